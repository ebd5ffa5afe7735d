//! The `sketch` family's checks and the profile error measure.

use super::input::Outline;
use super::report::ProfileErrorReport;
use crate::check::Check;
use crate::mesh::Mesh;

/// Profile error per given view (filled once the profile module lands).
pub fn profile_errors(
    _mesh: &Mesh,
    _front: &Outline,
    _side: Option<&Outline>,
    _height: f64,
) -> Vec<ProfileErrorReport> {
    Vec::new()
}

/// Every check of the family.
pub fn checks() -> Vec<Check> {
    Vec::new()
}
