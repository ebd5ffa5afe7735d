//! Checks of the gec family (none yet).

use crate::check::Check;

/// All checks of the gec family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
