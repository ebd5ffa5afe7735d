//! Checks of the plate family (none yet).

use crate::check::Check;

/// All checks of the plate family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
