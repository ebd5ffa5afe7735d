//! Per-column cross-tangent scales of a child that turns back against its
//! parent (an arm hanging from the shoulders), [`column_scales`].

use super::part::PartSurface;
use super::transition::ChildTransition;
use crate::mesh::{add, dist, dot, norm, scale, sub};
use std::f64::consts::PI;

/// How strongly the per-column cross-tangent scale follows the column's
/// chord in a child that turns back against its parent
/// ([`column_scales`]). Measured on the closed body (README): crossing
/// triangle pairs of the base and the five checked morphs, 703 with one
/// scale, 249 at 3, 202 at 4.5, 169 at 6 (95 of them in the mitten hands,
/// which this does not touch); uncapped, 6 raised caucasian-female-young's
/// max 2.56 -> 3.06 %. With [`TURN_BACK_SCALE_MAX`] 6 leaves no shoulder
/// crossing on the base and the male bodies (at 4.5 the base kept a fold
/// at loop columns 2-3, rows 2-4, where the scale fell too slowly from the
/// back corner) and the error columns within 0.2 % of the height.
pub const TURN_BACK_EXPONENT: f64 = 6.0;

/// Largest per-column scale of a turning-back child, relative to its
/// `ell` ([`column_scales`]). At a cut the seam leaves the parent ring
/// along the parent's u-tangent, which is also the corner column's cross
/// tangent, so the corner column's first rows run along the seam; with the
/// corner's long chord the uncapped scale (up to 2.3 `ell`) pushed them
/// past the neighbouring arc column (caucasian-male-old: loop columns
/// 15-16, rows 0-1, at the front of the armpit).
pub const TURN_BACK_SCALE_MAX: f64 = 1.3;

/// Per loop vertex cross-tangent scales of a child that turns back against
/// its parent (an arm hanging from the shoulder: the parent's end tangent
/// points up, the child's ring lies below and outside the loop). With one
/// scale `ell` for every column, the columns at the loop's corners (the
/// cuts, where the parent's arc turns into a seam: the front and back of
/// the armpit) have chords to the child ring up to 1.7 times those under
/// the armpit, and their short Hermite tangents make them sweep flat across
/// the rising neighbours: the sheet folds through itself at rows 1-5
/// (`body::diagnose_self_crossings`). Here column i gets
/// `ell min((c_i / c_mean)^(TURN_BACK_EXPONENT g), TURN_BACK_SCALE_MAX)`, `c_i` its chord
/// `|Q(theta_i) - L_i|`, `c_mean` the loop's mean chord, `g = max(0, -cos)` of the angle between the parent's end
/// direction and the loop-centroid-to-ring-centre direction: 0 for a child
/// that continues the parent (legs, a head, every sketch transition: the
/// scales are then `ell`, unchanged), growing as the child turns back. The
/// cross tangents stay parallel to the parts' u-tangents, so the joins stay
/// C1 with the column's scale (measured with it) and the seams G1 (both
/// sides' tangents are still opposite modulo the seam's).
pub fn column_scales(
    ct: &ChildTransition,
    parent: &PartSurface,
    pts: &[[f64; 3]],
    ring: &crate::curve::Fourier3,
) -> Vec<f64> {
    let n = pts.len();
    let axis = scale(parent.section(ct.parent_u, 1).c0, ct.sgn);
    let towards = sub(ring.c0, centroid(pts));
    let c = dot(axis, towards) / (norm(axis) * norm(towards)).max(f64::MIN_POSITIVE);
    let g = (-c).max(0.0);
    if n == 0 || g <= 0.0 || !g.is_finite() {
        return Vec::new();
    }
    let chords: Vec<f64> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let th = ct.theta0 + ct.sigma * 2.0 * PI * i as f64 / n as f64;
            dist(*p, ring.eval(th))
        })
        .collect();
    let mean = chords.iter().sum::<f64>() / n as f64;
    if !(mean.is_finite() && mean > 0.0) {
        return Vec::new();
    }
    chords
        .iter()
        .map(|c| {
            ct.ell
                * (c / mean)
                    .max(f64::MIN_POSITIVE)
                    .powf(TURN_BACK_EXPONENT * g)
                    .min(TURN_BACK_SCALE_MAX)
        })
        .collect()
}

pub(super) fn centroid(p: &[[f64; 3]]) -> [f64; 3] {
    let s = p.iter().fold([0.0; 3], |a, b| add(a, *b));
    scale(s, 1.0 / p.len().max(1) as f64)
}
