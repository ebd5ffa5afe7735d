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
    MEMO.get(name, || f.run())
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

/// `f` of every input, in input order, on at most as many threads as the
/// machine has cores (a test over several expensive inputs, e.g. several
/// bodies, runs them side by side instead of in a row; the inputs and
/// what is checked of each are unchanged).
pub fn parallel_map<T: Sync, R: Send>(inputs: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let next = AtomicUsize::new(0);
    let done = Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..threads.min(inputs.len()) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(x) = inputs.get(i) else { break };
                let r = f(x);
                done.lock().unwrap_or_else(|e| e.into_inner()).push((i, r));
            });
        }
    });
    let mut done = done.into_inner().unwrap_or_else(|e| e.into_inner());
    done.sort_by_key(|(i, _)| *i);
    assert_eq!(
        done.len(),
        inputs.len(),
        "a thread of parallel_map panicked"
    );
    done.into_iter().map(|(_, r)| r).collect()
}
