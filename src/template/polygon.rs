//! Closed planar polygons as the template layer sees them: validation
//! (closed, simple, counter-clockwise); the geometry itself (arc length,
//! points at arc length, distances) is `crate::polygon`.

use super::TemplateError;
pub use crate::polygon::{
    bbox, boundary_distance, cumulative, depth_span, hausdorff, point_at, seg_dist,
    self_intersection, signed_area2,
};

/// Validates a closed polygon (`what` names it in errors) and returns it
/// counter-clockwise, without a repeated closing point.
pub fn validated(what: &str, points: &[[f64; 2]]) -> Result<Vec<[f64; 2]>, TemplateError> {
    let mut p: Vec<[f64; 2]> = points.to_vec();
    if let Some(i) = p
        .iter()
        .position(|q| !q[0].is_finite() || !q[1].is_finite())
    {
        return Err(TemplateError::BadProfile {
            what: what.into(),
            problem: format!("point {i} is not finite"),
        });
    }
    if p.len() >= 2 && p[0] == p[p.len() - 1] {
        p.pop();
    }
    p.dedup();
    if p.len() < 3 {
        return Err(TemplateError::BadProfile {
            what: what.into(),
            problem: format!(
                "{} distinct points; a closed outline needs at least 3",
                p.len()
            ),
        });
    }
    let a2 = signed_area2(&p);
    let (lo, hi) = bbox(&p);
    let diam = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)).sqrt();
    if a2.abs() <= 1e-12 * diam * diam {
        return Err(TemplateError::BadProfile {
            what: what.into(),
            problem: "zero area".into(),
        });
    }
    if let Some((i, j)) = self_intersection(&p) {
        return Err(TemplateError::BadProfile {
            what: what.into(),
            problem: format!("self-intersecting (edges {i} and {j} cross)"),
        });
    }
    if a2 < 0.0 {
        p.reverse();
    }
    Ok(p)
}
