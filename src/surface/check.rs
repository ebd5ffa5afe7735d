//! Checks of the surface infrastructure (placeholder until filled).

use crate::check::Check;

/// All checks of the surface family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
