//! Checks of the pde6 family (none yet).

use crate::check::Check;

/// All checks of the pde6 family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
