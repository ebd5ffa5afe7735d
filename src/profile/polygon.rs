//! [`Profile`]: a validated simple closed polygon in one view.

use super::grid::{first_self_intersection, len, point_segment};
use super::{ProfileError, View};
use serde::{Deserialize, Serialize};

/// Consecutive points closer than this fraction of the bounding-box
/// diagonal are one point (the later copy is dropped).
pub const DUPLICATE_REL: f64 = 1e-12;

/// A simple closed polygon, counter-clockwise in (horizontal, vertical)
/// profile coordinates of its [`View`], without a repeated closing point.
///
/// Serialises as `{"view": "front", "points": [[h, v], ...]}` (the JSON
/// input format); deserialising validates with [`Profile::new`], so a
/// document embedding a profile cannot hold an invalid one.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    try_from = "super::json::ProfileJson",
    into = "super::json::ProfileJson"
)]
pub struct Profile {
    view: View,
    points: Vec<[f64; 2]>,
}

impl Profile {
    /// Validates and normalises a closed polygon: every coordinate finite
    /// ([`ProfileError::NonFinite`] names the first bad index), consecutive
    /// duplicates dropped (within [`DUPLICATE_REL`] of the bounding-box
    /// diagonal, the closing copy included), at least 3 points left
    /// ([`ProfileError::TooFewPoints`]), not all on one line
    /// ([`ProfileError::ZeroArea`]), no two edges meeting except neighbours
    /// at their shared vertex ([`ProfileError::SelfIntersecting`]: segment
    /// `k` is the edge from input point `k` to the next kept point; a grid
    /// keeps this near-linear), then reoriented counter-clockwise (reversed and
    /// rotated so that the first input point stays first).
    pub fn new(view: View, points: Vec<[f64; 2]>) -> Result<Profile, ProfileError> {
        if let Some(index) = points
            .iter()
            .position(|p| !(p[0].is_finite() && p[1].is_finite()))
        {
            return Err(ProfileError::NonFinite { index });
        }
        let diag = bbox_of(&points).map_or(0.0, |(lo, hi)| len(lo, hi));
        let eps = DUPLICATE_REL * diag;
        let mut pts: Vec<[f64; 2]> = Vec::with_capacity(points.len());
        let mut orig: Vec<usize> = Vec::with_capacity(points.len());
        for (i, p) in points.into_iter().enumerate() {
            if pts.last().is_none_or(|&q| len(p, q) > eps) {
                pts.push(p);
                orig.push(i);
            }
        }
        while pts.len() > 1 && len(pts[0], pts[pts.len() - 1]) <= eps {
            pts.pop();
            orig.pop();
        }
        if pts.len() < 3 {
            return Err(ProfileError::TooFewPoints { count: pts.len() });
        }
        if collinear(&pts, diag) {
            return Err(ProfileError::ZeroArea);
        }
        if let Some((a, b, at)) = first_self_intersection(&pts) {
            return Err(ProfileError::SelfIntersecting {
                a: orig[a],
                b: orig[b],
                at,
            });
        }
        // a simple polygon that is not collinear has a non-zero area
        if signed_area(&pts) < 0.0 {
            pts[1..].reverse();
        }
        Ok(Profile { view, points: pts })
    }

    /// The view the profile is drawn in.
    pub fn view(&self) -> View {
        self.view
    }

    /// The vertices, counter-clockwise, first not repeated at the end.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Always false (a profile has at least 3 points).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Edge `i`: from vertex `i` to vertex `i + 1` (mod n).
    pub fn edge(&self, i: usize) -> [[f64; 2]; 2] {
        let n = self.points.len();
        [self.points[i % n], self.points[(i + 1) % n]]
    }

    /// Enclosed area (positive).
    pub fn area(&self) -> f64 {
        signed_area(&self.points)
    }

    /// Length of the closed boundary.
    pub fn perimeter(&self) -> f64 {
        (0..self.len())
            .map(|i| {
                let [p, q] = self.edge(i);
                len(p, q)
            })
            .sum()
    }

    /// Area centroid.
    pub fn centroid(&self) -> [f64; 2] {
        let (mut cx, mut cy, mut a2) = (0.0, 0.0, 0.0);
        let o = self.points[0];
        for i in 0..self.len() {
            let [p, q] = self.edge(i);
            let (p, q) = ([p[0] - o[0], p[1] - o[1]], [q[0] - o[0], q[1] - o[1]]);
            let c = p[0] * q[1] - q[0] * p[1];
            a2 += c;
            cx += (p[0] + q[0]) * c;
            cy += (p[1] + q[1]) * c;
        }
        [o[0] + cx / (3.0 * a2), o[1] + cy / (3.0 * a2)]
    }

    /// Axis-aligned bounding box (min, max).
    pub fn bbox(&self) -> ([f64; 2], [f64; 2]) {
        bbox_of(&self.points).unwrap_or(([0.0; 2], [0.0; 2]))
    }

    /// Horizontal extent.
    pub fn width(&self) -> f64 {
        let (lo, hi) = self.bbox();
        hi[0] - lo[0]
    }

    /// Vertical extent.
    pub fn height(&self) -> f64 {
        let (lo, hi) = self.bbox();
        hi[1] - lo[1]
    }

    /// Whether `p` is inside (even-odd rule; points on the boundary may go
    /// either way).
    pub fn contains(&self, p: [f64; 2]) -> bool {
        contains_point(&self.points, p)
    }

    /// Distance from `p` to the boundary (exact, linear time; for many
    /// queries build a [`super::ProfileIndex`]).
    pub fn distance(&self, p: [f64; 2]) -> f64 {
        boundary_distance(&self.points, p)
    }

    /// The point at arc length `s` from vertex 0 along the boundary
    /// (counter-clockwise; `s` taken modulo the perimeter).
    pub fn point_at_arclength(&self, s: f64) -> [f64; 2] {
        self.resample_at(&[s])[0]
    }

    /// `n` points equally spaced by arc length, starting at vertex 0,
    /// counter-clockwise (no closing copy). Returns points rather than a
    /// profile: a coarse resampling of a concave outline may cross itself.
    pub fn resample_arclength(&self, n: usize) -> Vec<[f64; 2]> {
        let per = self.perimeter();
        let s: Vec<f64> = (0..n).map(|k| per * k as f64 / n as f64).collect();
        self.resample_at(&s)
    }

    /// Points at the given arc lengths (each taken modulo the perimeter;
    /// fastest when sorted).
    pub fn resample_at(&self, s: &[f64]) -> Vec<[f64; 2]> {
        let n = self.len();
        let mut cum = Vec::with_capacity(n + 1);
        cum.push(0.0);
        for i in 0..n {
            let [p, q] = self.edge(i);
            cum.push(cum[i] + len(p, q));
        }
        let per = cum[n];
        s.iter()
            .map(|&s| {
                let s = s.rem_euclid(per);
                let i = match cum.binary_search_by(|c| c.total_cmp(&s)) {
                    Ok(i) => i.min(n - 1),
                    Err(i) => (i - 1).min(n - 1),
                };
                let [p, q] = self.edge(i);
                let l = cum[i + 1] - cum[i];
                let t = if l > 0.0 { (s - cum[i]) / l } else { 0.0 };
                [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]
            })
            .collect()
    }

    /// The similarity transform `x -> scale * R(rotation) x + translation`
    /// of the profile (same view). A negative scale is a point reflection
    /// (rotation by pi). Errors on a zero or non-finite scale, rotation or
    /// translation.
    pub fn transformed(
        &self,
        scale: f64,
        rotation_rad: f64,
        translation: [f64; 2],
    ) -> Result<Profile, ProfileError> {
        let valid = scale.is_finite()
            && scale != 0.0
            && rotation_rad.is_finite()
            && translation.iter().all(|t| t.is_finite());
        if !valid {
            return Err(ProfileError::InvalidParameter {
                message: format!(
                    "similarity transform needs a finite non-zero scale and finite rotation and translation, got scale {scale}, rotation {rotation_rad}, translation {translation:?}"
                ),
            });
        }
        let (s, c) = rotation_rad.sin_cos();
        let pts = self
            .points
            .iter()
            .map(|p| {
                [
                    scale * (c * p[0] - s * p[1]) + translation[0],
                    scale * (s * p[0] + c * p[1]) + translation[1],
                ]
            })
            .collect();
        Profile::new(self.view, pts)
    }

    /// The same polygon in another view (coordinates unchanged).
    pub fn with_view(&self, view: View) -> Profile {
        Profile {
            view,
            points: self.points.clone(),
        }
    }
}

/// Signed area of a closed polygon (positive when counter-clockwise),
/// computed relative to the first point to limit cancellation.
pub(crate) fn signed_area(pts: &[[f64; 2]]) -> f64 {
    let n = pts.len();
    if n < 3 {
        return 0.0;
    }
    let o = pts[0];
    let mut a = 0.0;
    for i in 1..n - 1 {
        let (p, q) = (pts[i], pts[i + 1]);
        a += (p[0] - o[0]) * (q[1] - o[1]) - (q[0] - o[0]) * (p[1] - o[1]);
    }
    0.5 * a
}

/// Whether every point lies within `DUPLICATE_REL * diag` of the line
/// through the first point and the point farthest from it.
fn collinear(pts: &[[f64; 2]], diag: f64) -> bool {
    let o = pts[0];
    let far = pts
        .iter()
        .copied()
        .max_by(|a, b| len(o, *a).total_cmp(&len(o, *b)))
        .unwrap_or(o);
    let l = len(o, far);
    if l == 0.0 {
        return true;
    }
    pts.iter()
        .all(|&p| (super::grid::orient(o, far, p) / l).abs() <= DUPLICATE_REL * diag)
}

/// Bounding box of finite points; `None` when empty.
pub(crate) fn bbox_of(pts: &[[f64; 2]]) -> Option<([f64; 2], [f64; 2])> {
    let first = *pts.first()?;
    let mut lo = first;
    let mut hi = first;
    for p in pts {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    Some((lo, hi))
}

/// Whether `p` is inside the closed polygon `points` (even-odd rule, the
/// closing edge implicit; points on the boundary may go either way). For
/// any polygon, simple or not ([`Profile::contains`] on a validated one).
pub fn contains_point(points: &[[f64; 2]], p: [f64; 2]) -> bool {
    let n = points.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (points[i], points[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Distance from `p` to the boundary of the closed polygon `points` (exact,
/// linear time; infinite for no points).
pub fn boundary_distance(points: &[[f64; 2]], p: [f64; 2]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| point_segment(p, points[i], points[(i + 1) % n]).0)
        .fold(f64::INFINITY, f64::min)
}
