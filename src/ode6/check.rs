//! Checks of the ode6 family (none yet).

use crate::check::Check;

/// All checks of the ode6 family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
