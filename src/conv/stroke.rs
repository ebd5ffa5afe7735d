//! Filtering a sketched silhouette stroke (paper 003, sec 3.2).
//!
//! The sampled closed stroke is simplified by Douglas-Peucker (tolerance a
//! fraction of the bounding-box diagonal), then points are re-inserted on
//! every edge longer than the target spacing so the polygon is roughly
//! uniformly sampled (the paper's Fig 2a). Self-intersecting results are
//! rejected with [`ConvError::SelfIntersecting`]; the orientation is
//! normalised to counter-clockwise.

use super::ConvError;
use crate::polygon::{self_intersection, signed_area};

/// Options of the stroke filter: `StrokeOptions::default()` or
/// [`StrokeOptions::new`].
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
#[non_exhaustive]
pub struct StrokeOptions {
    /// Douglas-Peucker tolerance as a fraction of the bounding-box diagonal.
    pub dp_tolerance: f64,
    /// Target spacing of the re-inserted points as a fraction of the
    /// perimeter (edges longer than this are subdivided uniformly).
    pub spacing: f64,
}

impl Default for StrokeOptions {
    fn default() -> Self {
        StrokeOptions {
            dp_tolerance: 0.004,
            spacing: 1.0 / 64.0,
        }
    }
}

impl StrokeOptions {
    /// The Douglas-Peucker tolerance and the re-inserted points' spacing
    /// (fractions of the diagonal and of the perimeter).
    pub fn new(dp_tolerance: f64, spacing: f64) -> StrokeOptions {
        StrokeOptions {
            dp_tolerance,
            spacing,
        }
    }
}

/// Smallest number of distinct points a stroke needs.
pub const MIN_POINTS: usize = 4;
/// Largest absolute stroke coordinate (screen units): beyond it squared
/// distances lose the sketch's detail long before they overflow.
pub const MAX_COORDINATE: f64 = 1e6;
/// Smallest stroke size (bounding-box diagonal).
pub const MIN_SIZE: f64 = 1e-6;
/// Points closer than this fraction of the diagonal are merged.
const DUPLICATE_FRACTION: f64 = 1e-9;

/// Perimeter of the closed polygon.
pub fn perimeter(pts: &[[f64; 2]]) -> f64 {
    let n = pts.len();
    (0..n).map(|i| dist2(pts[i], pts[(i + 1) % n])).sum()
}

pub(crate) fn dist2(a: [f64; 2], b: [f64; 2]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// Distance from `p` to the segment `a`..`b`.
pub fn point_segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let e = [b[0] - a[0], b[1] - a[1]];
    let l2 = e[0] * e[0] + e[1] * e[1];
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * e[0] + (p[1] - a[1]) * e[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist2(p, [a[0] + t * e[0], a[1] + t * e[1]])
}

/// Distance from `p` to the closed polygon's boundary.
pub fn distance_to_polygon(p: [f64; 2], poly: &[[f64; 2]]) -> f64 {
    let n = poly.len();
    (0..n)
        .map(|i| point_segment_distance(p, poly[i], poly[(i + 1) % n]))
        .fold(f64::INFINITY, f64::min)
}

fn douglas_peucker(pts: &[[f64; 2]], eps: f64, keep: &mut [bool], i0: usize, i1: usize) {
    if i1 <= i0 + 1 {
        return;
    }
    let (mut best, mut bi) = (-1.0, i0);
    for i in i0 + 1..i1 {
        let d = point_segment_distance(pts[i], pts[i0], pts[i1]);
        if d > best {
            best = d;
            bi = i;
        }
    }
    if best > eps {
        keep[bi] = true;
        douglas_peucker(pts, eps, keep, i0, bi);
        douglas_peucker(pts, eps, keep, bi, i1);
    }
}

/// Filters a sampled closed stroke: validation, Douglas-Peucker,
/// re-inserted points, self-intersection rejection, counter-clockwise
/// orientation.
pub fn filter_stroke(raw: &[[f64; 2]], opts: &StrokeOptions) -> Result<Vec<[f64; 2]>, ConvError> {
    check_input(raw, opts)?;
    // hypot: the squares of a tiny stroke's extent underflow
    let diag = crate::polygon::diagonal(raw);
    if diag > 0.0 && diag < MIN_SIZE {
        return Err(ConvError::TooSmall {
            size: diag,
            limit: MIN_SIZE,
        });
    }
    // drop consecutive duplicates (and a closing repeat of the first point)
    let mut pts: Vec<[f64; 2]> = Vec::with_capacity(raw.len());
    for &p in raw {
        if pts
            .last()
            .is_none_or(|&q| dist2(p, q) > DUPLICATE_FRACTION * diag)
        {
            pts.push(p);
        }
    }
    while pts.len() > 1 && dist2(pts[0], pts[pts.len() - 1]) <= DUPLICATE_FRACTION * diag {
        pts.pop();
    }
    if pts.len() < MIN_POINTS || diag <= 0.0 {
        return Err(ConvError::TooShort {
            points: pts.len(),
            needed: MIN_POINTS,
        });
    }
    let area = signed_area(&pts).abs();
    if area <= 1e-6 * diag * diag {
        return Err(ConvError::ZeroArea { area });
    }
    // Douglas-Peucker on the closed polygon: split at point 0 and the point
    // farthest from it.
    let n = pts.len();
    let far = (1..n)
        .max_by(|&a, &b| dist2(pts[0], pts[a]).total_cmp(&dist2(pts[0], pts[b])))
        .unwrap_or(n / 2);
    let mut ext = pts.clone();
    ext.push(pts[0]);
    let mut keep = vec![false; n + 1];
    keep[0] = true;
    keep[far] = true;
    keep[n] = true;
    let eps = opts.dp_tolerance * diag;
    douglas_peucker(&ext, eps, &mut keep, 0, far);
    douglas_peucker(&ext, eps, &mut keep, far, n);
    let simplified: Vec<[f64; 2]> = (0..n).filter(|&i| keep[i]).map(|i| pts[i]).collect();
    // re-inserted points for uniform spacing
    let h = opts.spacing * perimeter(&simplified);
    let m = simplified.len();
    let mut out = Vec::new();
    for i in 0..m {
        let (a, b) = (simplified[i], simplified[(i + 1) % m]);
        let k = (dist2(a, b) / h).ceil().max(1.0) as usize;
        for j in 0..k {
            let t = j as f64 / k as f64;
            out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
    }
    if out.len() < MIN_POINTS {
        return Err(ConvError::TooShort {
            points: out.len(),
            needed: MIN_POINTS,
        });
    }
    if let Some((i, j, _)) = self_intersection(&out) {
        return Err(ConvError::SelfIntersecting {
            edge_a: i,
            edge_b: j,
        });
    }
    if signed_area(&out) < 0.0 {
        out.reverse();
    }
    Ok(out)
}

/// The options' ranges and every raw point finite and within
/// [`MAX_COORDINATE`].
fn check_input(raw: &[[f64; 2]], opts: &StrokeOptions) -> Result<(), ConvError> {
    if !(opts.dp_tolerance >= 0.0 && opts.dp_tolerance < 0.5) {
        return Err(ConvError::Parameter(format!(
            "dp_tolerance {} outside [0, 0.5)",
            opts.dp_tolerance
        )));
    }
    if !(opts.spacing > 1e-4 && opts.spacing <= 0.25) {
        return Err(ConvError::Parameter(format!(
            "spacing {} outside (1e-4, 0.25]",
            opts.spacing
        )));
    }
    for (i, p) in raw.iter().enumerate() {
        if !p[0].is_finite() || !p[1].is_finite() {
            return Err(ConvError::NonFinite { index: i });
        }
        if let Some(&value) = p.iter().find(|v| v.abs() > MAX_COORDINATE) {
            return Err(ConvError::OutOfRange {
                index: i,
                value,
                limit: MAX_COORDINATE,
            });
        }
    }
    Ok(())
}
