//! Expensive fixtures computed once per test process and shared by every
//! test that reads them (issue 30): the verify checks per family and the
//! closed body reconstructions. Under `cargo test` all tests of this binary
//! share one process, so a family's checks or a body are computed once
//! however many tests read them; a second test asking while the first
//! computes waits for it instead of computing again. Under
//! `cargo nextest` every test is its own process and pays for what it
//! reads, no more (a family test computes its family, not all of verify).
//!
//! A new test that needs a family's checks or a closed body takes them from
//! here; a new kind of expensive fixture gets its own function built like
//! these (docs/test-time.md, "Keeping a new test fast").

use pdesculpt::body::closed::{load_body, reconstruct_closed, ClosedBody, ClosedOptions};
use pdesculpt::check::Check;
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

/// One lazily computed value per key: the map hands out the key's slot
/// (made once and never freed, so values borrow for `'static`), the slot
/// computes once (concurrent callers of the same key wait).
struct Memo<T: 'static>(OnceLock<Mutex<HashMap<String, &'static OnceLock<T>>>>);

impl<T> Memo<T> {
    const fn new() -> Self {
        Memo(OnceLock::new())
    }
    fn get(&self, key: &str, compute: impl FnOnce() -> T) -> &'static T {
        let slot: &'static OnceLock<T> = self
            .0
            .get_or_init(Default::default)
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .entry(key.to_string())
            .or_insert_with(|| Box::leak(Box::new(OnceLock::new())));
        slot.get_or_init(compute)
    }
}

/// The checks of verify family `name` (`pdesculpt::verify::families`),
/// computed once per process.
pub fn family_checks(name: &str) -> &'static [Check] {
    static MEMO: Memo<Vec<Check>> = Memo::new();
    let f = pdesculpt::verify::families()
        .iter()
        .find(|f| f.name == name)
        .unwrap_or_else(|| panic!("no verify family {name}"));
    MEMO.get(name, || (f.checks)())
}

/// Every verify check, in registry order ([`family_checks`] of each family,
/// the families not computed yet on parallel threads, as `verify::run`).
pub fn all_checks() -> Vec<Check> {
    let families = pdesculpt::verify::families();
    std::thread::scope(|s| {
        for f in families {
            s.spawn(move || family_checks(f.name));
        }
    });
    families
        .iter()
        .flat_map(|f| family_checks(f.name).iter().cloned())
        .collect()
}

/// The closed reconstruction (default options) of the bundled body with
/// the morphs `morphs` (`NAME=WEIGHT`; none: the base body), once per
/// process.
pub fn closed_body(morphs: &[&str]) -> &'static ClosedBody {
    static MEMO: Memo<ClosedBody> = Memo::new();
    MEMO.get(&morphs.join("+"), || {
        let list: Vec<String> = morphs.iter().map(|m| m.to_string()).collect();
        let skin = load_body(None, &list).expect("bundled body");
        reconstruct_closed(&skin, &ClosedOptions::default())
            .unwrap_or_else(|e| panic!("{morphs:?}: {e}"))
    })
}
