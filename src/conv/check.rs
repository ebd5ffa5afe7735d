//! Checks of the conv family (none yet).

use crate::check::Check;

/// All checks of the conv family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
