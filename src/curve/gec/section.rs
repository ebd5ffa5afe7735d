//! Validation of a closed planar polyline before a GEC fit: finite
//! coordinates in a supported scale range, no repeated or closing-copy
//! points, closed (no opening gap), planar within a tolerance, enclosing an
//! area; the plane is fitted (Newell's normal, area centroid) or given.

use super::{Frame, GecError};
use crate::mesh::{dist, norm};
use crate::vec3::bounds;

/// The plane the curve is placed in.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum FrameChoice {
    /// Fitted (Newell normal, area centroid).
    #[default]
    Auto,
    /// Given: points are projected onto it (still checked for planarity).
    Given(Frame),
}

/// Two points closer than this times the polyline's diameter are "repeated".
pub const REPEAT_TOL: f64 = 1e-12;
/// Default planarity tolerance (relative to the diameter).
pub const PLANARITY_TOL: f64 = 1e-6;

/// A validated closed polyline in its plane.
#[derive(Clone, Debug)]
pub struct Section {
    pub frame: Frame,
    pub points: Vec<[f64; 2]>,
    pub off_plane: f64,
    pub diameter: f64,
}

fn diameter(points: &[[f64; 3]]) -> f64 {
    let (lo, hi) = bounds(points).unwrap_or(([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]));
    dist(lo, hi)
}

/// Smallest and largest diameter (and largest coordinate magnitude) of a
/// point set the fit accepts: outside, squared distances underflow or
/// overflow and the repeated-point, planarity and least-squares tests would
/// give false answers.
pub const SCALE_RANGE: (f64, f64) = (1e-100, 1e100);

/// Refuses points whose diameter or coordinates lie outside
/// [`SCALE_RANGE`] (a clear error instead of a false "coincide" or a
/// non-finite fit).
pub fn check_scale(points: &[[f64; 3]]) -> Result<(), GecError> {
    let (lo, hi) = SCALE_RANGE;
    if let Some(i) = points.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
        return Err(GecError::NonFinite {
            index: i,
            point: points[i],
        });
    }
    let big = points.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    let span = bounds(points).map_or(f64::NEG_INFINITY, |(a, b)| {
        (b[0] - a[0]).max(b[1] - a[1]).max(b[2] - a[2])
    });
    if points.len() > 1 && !(span >= lo && big <= hi) {
        return Err(GecError::InvalidParameter(format!(
            "the points span {span:.3e} with coordinates up to {big:.3e}; the fit supports spans of at least {lo:e} and coordinates up to {hi:e} (rescale the input)"
        )));
    }
    Ok(())
}

/// Signed area and area centroid of a closed planar polygon.
pub fn polygon_area_centroid(p: &[[f64; 2]]) -> (f64, [f64; 2]) {
    let n = p.len();
    let (mut a, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let (q, r) = (p[i], p[(i + 1) % n]);
        let c = q[0] * r[1] - r[0] * q[1];
        a += c;
        cx += (q[0] + r[0]) * c;
        cy += (q[1] + r[1]) * c;
    }
    a *= 0.5;
    if a == 0.0 {
        return (0.0, [0.0; 2]);
    }
    (a, [cx / (6.0 * a), cy / (6.0 * a)])
}

/// Validates a closed polyline (finite, no repeated consecutive points, at
/// least `min_points`), fits or applies the frame, projects the points.
pub fn section(
    points: &[[f64; 3]],
    frame: FrameChoice,
    planarity_tol: f64,
    min_points: usize,
) -> Result<Section, GecError> {
    if !(planarity_tol.is_finite() && planarity_tol >= 0.0) {
        return Err(GecError::InvalidParameter(format!(
            "planarity tolerance {planarity_tol}"
        )));
    }
    if let Some((i, p)) = points
        .iter()
        .enumerate()
        .find(|(_, p)| !p.iter().all(|x| x.is_finite()))
    {
        return Err(GecError::NonFinite {
            index: i,
            point: *p,
        });
    }
    let n = points.len();
    if n < min_points.max(3) {
        return Err(GecError::Degenerate(format!(
            "{n} points, at least {} needed",
            min_points.max(3)
        )));
    }
    let diam = diameter(points);
    if diam.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) || !diam.is_finite() {
        return Err(GecError::Degenerate("all points coincide".into()));
    }
    for i in 0..n {
        let j = (i + 1) % n;
        if dist(points[i], points[j]) <= REPEAT_TOL * diam {
            return Err(GecError::RepeatedPoint {
                first: i.min(j),
                second: i.max(j),
            });
        }
    }
    let frame = match frame {
        FrameChoice::Given(f) => Frame::new(f.origin, f.e1, f.e2)?,
        FrameChoice::Auto => {
            // Newell's normal (oriented: counter-clockwise about it)
            let mut nrm = [0.0; 3];
            let mut mean = [0.0; 3];
            for i in 0..n {
                let (a, b) = (points[i], points[(i + 1) % n]);
                nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
                nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
                nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
                for k in 0..3 {
                    mean[k] += a[k] / n as f64;
                }
            }
            if norm(nrm) <= REPEAT_TOL * diam * diam {
                return Err(GecError::Degenerate("the polygon encloses no area".into()));
            }
            let f0 = Frame::from_normal(mean, nrm, [1.0, 0.0, 0.0])?;
            let p2: Vec<[f64; 2]> = points.iter().map(|p| f0.project(*p).0).collect();
            let (_, c) = polygon_area_centroid(&p2);
            let o = f0.place(c[0], c[1]);
            Frame { origin: o, ..f0 }
        }
    };
    let mut off = 0.0f64;
    let plane: Vec<[f64; 2]> = points
        .iter()
        .map(|p| {
            let (q, d) = frame.project(*p);
            off = off.max(d.abs());
            q
        })
        .collect();
    if off > planarity_tol * diam {
        return Err(GecError::NotPlanar {
            deviation: off,
            tolerance: planarity_tol * diam,
        });
    }
    let (area, _) = polygon_area_centroid(&plane);
    if area.abs() <= REPEAT_TOL * diam * diam {
        return Err(GecError::Degenerate(
            "the polygon encloses no area in its plane".into(),
        ));
    }
    Ok(Section {
        frame,
        points: plane,
        off_plane: off,
        diameter: diam,
    })
}

/// A closing gap longer than this many median segments (and longer than
/// every other segment) marks a polyline as open; see [`check_closed`].
pub const OPEN_GAP_FACTOR: f64 = 10.0;

/// Drops a closing copy of the first point (last point within
/// [`REPEAT_TOL`] times the diameter of the first), the usual way files
/// write a closed polyline. Returns whether a point was dropped.
pub fn strip_closing_copy(points: &mut Vec<[f64; 3]>) -> bool {
    if points.len() < 2 {
        return false;
    }
    let diam = diameter(points);
    let (first, last) = (points[0], points[points.len() - 1]);
    if diam.is_finite() && dist(first, last) <= REPEAT_TOL * diam {
        points.pop();
        return true;
    }
    false
}

/// The first pair `(i, j)`, `i < j`, of points closer than [`REPEAT_TOL`]
/// times the diameter, consecutive or not (sort by x, then scan the window
/// of equal-enough x: O(n log n) for generic data). Non-finite points are
/// skipped (they are reported by [`fit`]).
pub fn repeated_points(points: &[[f64; 3]]) -> Option<(usize, usize)> {
    let finite: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].iter().all(|v| v.is_finite()))
        .collect();
    let sel: Vec<[f64; 3]> = finite.iter().map(|&i| points[i]).collect();
    let tol = REPEAT_TOL * diameter(&sel);
    if !tol.is_finite() {
        return None;
    }
    let mut order = finite;
    order.sort_by(|&a, &b| points[a][0].total_cmp(&points[b][0]));
    let mut best: Option<(usize, usize)> = None;
    for (k, &i) in order.iter().enumerate() {
        for &j in &order[k + 1..] {
            if points[j][0] - points[i][0] > tol {
                break;
            }
            if dist(points[i], points[j]) <= tol {
                let pair = (i.min(j), i.max(j));
                if best.is_none_or(|b| pair < b) {
                    best = Some(pair);
                }
            }
        }
    }
    best
}

/// Rejects a polyline that looks open: with $g$ the gap from the last point
/// back to the first and $\tilde s$ the median of the other segments, the
/// polyline is open when $g > $ [`OPEN_GAP_FACTOR`] $\tilde s$ **and** $g$
/// exceeds every other segment. (A uniformly sampled arc missing more than
/// about ten sample steps is open; a closed curve sampled densely on one
/// side and sparsely on the other is not, because its closing segment is no
/// longer than the sparse ones.) Needs at least 3 points.
pub fn check_closed(points: &[[f64; 3]]) -> Result<(), GecError> {
    let n = points.len();
    if n < 3 {
        return Ok(());
    }
    let mut segs: Vec<f64> = (0..n - 1).map(|i| dist(points[i], points[i + 1])).collect();
    let gap = dist(points[n - 1], points[0]);
    let longest = segs.iter().copied().fold(0.0, f64::max);
    segs.sort_by(f64::total_cmp);
    let median = segs[segs.len() / 2];
    if !(gap.is_finite() && median.is_finite()) {
        return Ok(());
    }
    if gap > OPEN_GAP_FACTOR * median && gap > longest {
        return Err(GecError::OpenPolyline {
            gap,
            median,
            ratio: if median > 0.0 {
                gap / median
            } else {
                f64::INFINITY
            },
        });
    }
    Ok(())
}
