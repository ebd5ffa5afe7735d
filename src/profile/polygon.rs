//! [`Profile`]: a validated simple closed polygon in one view.

use super::grid::{len, point_segment};
use super::{ProfileError, View};
use crate::polygon::{Outline, OutlineError};
use serde::{Deserialize, Serialize};

/// A simple closed polygon, counter-clockwise in (horizontal, vertical)
/// profile coordinates of its [`View`], without a repeated closing point.
///
/// Serialises as `{"view": "front", "points": [[h, v], ...]}` (the JSON
/// input format); deserialising validates with [`Profile::new`], so a
/// document embedding a profile cannot hold an invalid one.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "ProfileJson", into = "ProfileJson")]
pub struct Profile {
    view: View,
    outline: Outline,
}

impl Profile {
    /// Validates and normalises a closed polygon ([`Outline::new`]: every
    /// coordinate finite, repeats within [`crate::polygon::DUPLICATE_REL`] of the diagonal
    /// dropped, at least 3 points, not on one line, simple, turned
    /// counter-clockwise keeping the first point first); its errors become
    /// [`ProfileError::NonFinite`], [`ProfileError::TooFewPoints`],
    /// [`ProfileError::ZeroArea`] and [`ProfileError::SelfIntersecting`]
    /// (segment `k` is the edge from input point `k` to the next kept one).
    pub fn new(view: View, points: Vec<[f64; 2]>) -> Result<Profile, ProfileError> {
        Ok(Profile::of(view, Outline::new(points)?))
    }

    /// A profile of an outline validated already.
    pub fn of(view: View, outline: Outline) -> Profile {
        Profile { view, outline }
    }

    /// The validated outline.
    pub fn outline(&self) -> &Outline {
        &self.outline
    }

    /// The view the profile is drawn in.
    pub fn view(&self) -> View {
        self.view
    }

    /// The vertices, counter-clockwise, first not repeated at the end.
    pub fn points(&self) -> &[[f64; 2]] {
        self.outline.points()
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.outline.len()
    }

    /// Always false (a profile has at least 3 points).
    pub fn is_empty(&self) -> bool {
        self.outline.is_empty()
    }

    /// Edge `i`: from vertex `i` to vertex `i + 1` (mod n).
    pub fn edge(&self, i: usize) -> [[f64; 2]; 2] {
        let p = self.points();
        let n = p.len();
        [p[i % n], p[(i + 1) % n]]
    }

    /// Enclosed area (positive).
    pub fn area(&self) -> f64 {
        self.outline.area()
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
        let o = self.points()[0];
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
        self.outline.bbox()
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

    /// Whether `p` is inside ([`crate::polygon::point_in_polygon`]: even-odd,
    /// points on the left and bottom of the boundary in, right and top out).
    pub fn contains(&self, p: [f64; 2]) -> bool {
        crate::polygon::point_in_polygon(self.points(), p)
    }

    /// Distance from `p` to the boundary (exact, linear time; for many
    /// queries build a [`super::ProfileIndex`]).
    pub fn distance(&self, p: [f64; 2]) -> f64 {
        boundary_distance(self.points(), p)
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
            .points()
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

    /// The profile scaled by `scale` and shifted by `shift` without a second
    /// validation ([`Outline::placed`]); `None` for a scale that is not
    /// finite and positive or a non-finite result.
    pub fn placed(&self, scale: f64, shift: [f64; 2]) -> Option<Profile> {
        let outline = self.outline.placed(scale, shift)?;
        Some(Profile::of(self.view, outline))
    }

    /// The same polygon in another view (coordinates unchanged).
    pub fn with_view(&self, view: View) -> Profile {
        Profile {
            view,
            outline: self.outline.clone(),
        }
    }
}

/// Distance from `p` to the boundary of the closed polygon `points` (exact,
/// linear time; infinite for no points).
pub fn boundary_distance(points: &[[f64; 2]], p: [f64; 2]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| point_segment(p, points[i], points[(i + 1) % n]).0)
        .fold(f64::INFINITY, f64::min)
}

impl From<OutlineError> for ProfileError {
    fn from(e: OutlineError) -> ProfileError {
        match e {
            OutlineError::NonFinite { index } => ProfileError::NonFinite { index },
            OutlineError::TooFewPoints { count } => ProfileError::TooFewPoints { count },
            OutlineError::ZeroArea => ProfileError::ZeroArea,
            OutlineError::SelfIntersecting { a, b, at } => {
                ProfileError::SelfIntersecting { a, b, at }
            }
        }
    }
}

/// The serde form of a [`Profile`] (validated on deserialisation).
#[derive(Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ProfileJson {
    pub(super) view: View,
    pub(super) points: Vec<[f64; 2]>,
}

impl TryFrom<ProfileJson> for Profile {
    type Error = ProfileError;
    fn try_from(j: ProfileJson) -> Result<Profile, ProfileError> {
        Profile::new(j.view, j.points)
    }
}

impl From<Profile> for ProfileJson {
    fn from(p: Profile) -> ProfileJson {
        ProfileJson {
            view: p.view(),
            points: p.points().to_vec(),
        }
    }
}
