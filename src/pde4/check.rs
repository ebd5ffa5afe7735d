//! Checks of the pde4 family (none yet).

use crate::check::Check;

/// All checks of the pde4 family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
