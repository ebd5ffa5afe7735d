//! Checks of the mesh infrastructure (placeholder until filled).

use crate::check::Check;

/// All checks of the mesh family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
