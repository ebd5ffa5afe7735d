//! The checks of the body reconstruction: family `body` in
//! [`crate::verify`]; the check names keep their `pde6.body_*` prefix (the
//! surfaces are pde6 chains, and scripts filter on those names).

use crate::check::Check;

mod closed;
mod parts;

pub use closed::morph_closed_checks;
pub use parts::{ROUGHNESS_RATIO_MAX, SLIP_MAX_DEG};

/// The checks of family `body` in `verify`: the base body (the checked
/// morphs are `pdesculpt study bodies`, [`morph_closed_checks`]).
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    parts::body_smoothness_checks(&mut out);
    closed::body_closed_checks(&mut out);
    closed::body_cavity_checks(&mut out);
    out
}
