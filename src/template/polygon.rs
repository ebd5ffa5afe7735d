//! Closed planar polygons as the template layer sees them: validation
//! ([`crate::polygon::Outline`]: closed, simple, counter-clockwise) with
//! the template's error; the geometry itself is `crate::polygon`.

use super::TemplateError;
pub use crate::polygon::{
    bbox, boundary_distance, cumulative, depth_span, hausdorff, point_at, seg_dist,
    self_intersection, signed_area,
};
use crate::polygon::{Orientation, Outline};

/// Validates a closed polygon (`what` names it in errors) and returns it
/// counter-clockwise, without repeated points nor a closing copy
/// ([`crate::polygon::Outline::new`]). A clockwise polygon is reversed
/// whole, its last point first (where `Outline` keeps the first point
/// first): the template's fits start their arc length there, and the
/// bundled study's values (female -> pregnant, up to 1.6 % of its profile
/// errors) were measured with that start.
pub fn validated(what: &str, points: &[[f64; 2]]) -> Result<Vec<[f64; 2]>, TemplateError> {
    let o = Outline::new(points.to_vec()).map_err(|e| TemplateError::BadProfile {
        what: what.into(),
        problem: e.to_string(),
    })?;
    let cw = o.given_orientation() == Orientation::Clockwise;
    let mut p = o.into_points();
    if cw {
        p.rotate_left(1);
    }
    Ok(p)
}
