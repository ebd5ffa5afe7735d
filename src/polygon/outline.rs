//! [`Outline`]: a closed polygon validated once, where it enters the
//! program, and carried validated from then on.

use super::{bbox, orient, self_intersection, signed_area, Orientation};
use std::fmt;

/// Consecutive points closer than this fraction of the bounding-box
/// diagonal are one point (the later copy is dropped); points within it of
/// one line make a zero-area outline.
pub const DUPLICATE_REL: f64 = 1e-12;

/// Why a closed polygon is not a valid outline. Indices are those of the
/// points as given (repeats included).
#[derive(Clone, Debug, PartialEq)]
pub enum OutlineError {
    /// Point `index` has a coordinate that is infinite or not a number.
    NonFinite { index: usize },
    /// Fewer than 3 distinct points (`count` after dropping repeats).
    TooFewPoints { count: usize },
    /// Every point on one line (within [`DUPLICATE_REL`] of the diagonal).
    ZeroArea,
    /// Edges `a` and `b` (edge `k` from given point `k` to the next
    /// distinct one) meet at `at` ([`super::self_intersection`]).
    SelfIntersecting { a: usize, b: usize, at: [f64; 2] },
}

impl fmt::Display for OutlineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OutlineError::NonFinite { index } => {
                write!(f, "point {index} has a non-finite coordinate")
            }
            OutlineError::TooFewPoints { count } => {
                write!(f, "needs at least 3 distinct points, got {count}")
            }
            OutlineError::ZeroArea => f.write_str("zero area (all points on a line)"),
            OutlineError::SelfIntersecting { a, b, at } => write!(
                f,
                "intersects itself: segment {a} crosses segment {b} near ({:.6}, {:.6})",
                at[0], at[1]
            ),
        }
    }
}

impl std::error::Error for OutlineError {}

/// A simple closed polygon with a non-zero area, counter-clockwise,
/// without repeated points (nor a closing copy of the first). Made only
/// by [`Outline::new`], so holding one is proof of the checks. It records
/// the orientation the points were given in; two outlines are equal when
/// their points are, however they were given.
#[derive(Clone, Debug)]
pub struct Outline {
    points: Vec<[f64; 2]>,
    given: Orientation,
}

impl PartialEq for Outline {
    fn eq(&self, other: &Outline) -> bool {
        self.points == other.points
    }
}

impl Outline {
    /// Validates and normalises a closed polygon: every coordinate finite
    /// (the first bad index is named), consecutive repeats dropped (within
    /// [`DUPLICATE_REL`] of the bounding-box diagonal, the closing copy
    /// included), at least 3 points left, not all on one line, no two
    /// edges meeting except neighbours at their shared vertex (touching is
    /// a self-intersection: [`super::self_intersection`]), then turned
    /// counter-clockwise: a clockwise polygon is reversed keeping its first
    /// point first.
    pub fn new(points: Vec<[f64; 2]>) -> Result<Outline, OutlineError> {
        if let Some(index) = points
            .iter()
            .position(|p| !(p[0].is_finite() && p[1].is_finite()))
        {
            return Err(OutlineError::NonFinite { index });
        }
        let diag = super::diagonal(&points);
        let eps = DUPLICATE_REL * diag;
        let len = |p: [f64; 2], q: [f64; 2]| (q[0] - p[0]).hypot(q[1] - p[1]);
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
            return Err(OutlineError::TooFewPoints { count: pts.len() });
        }
        if collinear(&pts, diag) {
            return Err(OutlineError::ZeroArea);
        }
        if let Some((a, b, at)) = self_intersection(&pts) {
            return Err(OutlineError::SelfIntersecting {
                a: orig[a],
                b: orig[b],
                at,
            });
        }
        // a simple polygon not on one line has a non-zero area
        let given = if signed_area(&pts) < 0.0 {
            pts[1..].reverse();
            Orientation::Clockwise
        } else {
            Orientation::CounterClockwise
        };
        Ok(Outline { points: pts, given })
    }

    /// The vertices, counter-clockwise, the first not repeated at the end.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// The orientation the points were given in (the outline itself is
    /// counter-clockwise).
    pub fn given_orientation(&self) -> Orientation {
        self.given
    }

    /// The vertices, given up.
    pub fn into_points(self) -> Vec<[f64; 2]> {
        self.points
    }

    /// Number of vertices (at least 3).
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Always false (an outline has at least 3 points).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Enclosed area (positive).
    pub fn area(&self) -> f64 {
        signed_area(&self.points)
    }

    /// Axis-aligned bounds (min, max).
    pub fn bbox(&self) -> ([f64; 2], [f64; 2]) {
        bbox(&self.points)
    }

    /// The outline scaled by `scale` about the origin, then shifted by
    /// `shift` (`scale * p + shift` per coordinate), without validating it
    /// again: such a map keeps an outline simple and counter-clockwise
    /// (up to the rounding of each coordinate). `None` when `scale` is not
    /// finite and positive or a moved point is not finite.
    pub fn placed(&self, scale: f64, shift: [f64; 2]) -> Option<Outline> {
        self.mapped(scale, |p| {
            [scale * p[0] + shift[0], scale * p[1] + shift[1]]
        })
    }

    /// The outline scaled by `scale` about the origin (`scale * p`), as
    /// [`Outline::placed`] without a shift.
    pub fn scaled(&self, scale: f64) -> Option<Outline> {
        self.mapped(scale, |p| [scale * p[0], scale * p[1]])
    }

    fn mapped(&self, scale: f64, f: impl Fn(&[f64; 2]) -> [f64; 2]) -> Option<Outline> {
        if !(scale.is_finite() && scale > 0.0) {
            return None;
        }
        let points: Vec<[f64; 2]> = self.points.iter().map(f).collect();
        let finite = points.iter().flatten().all(|x| x.is_finite());
        finite.then_some(Outline {
            points,
            given: self.given,
        })
    }
}

/// Checks a closed polygon as [`Outline::new`] does, keeping nothing.
pub fn validate(points: &[[f64; 2]]) -> Result<(), OutlineError> {
    Outline::new(points.to_vec()).map(|_| ())
}

/// Whether every point lies within `DUPLICATE_REL * diag` of the line
/// through the first point and the point farthest from it.
fn collinear(pts: &[[f64; 2]], diag: f64) -> bool {
    let o = pts[0];
    let len = |q: [f64; 2]| (q[0] - o[0]).hypot(q[1] - o[1]);
    let far = pts
        .iter()
        .copied()
        .max_by(|a, b| len(*a).total_cmp(&len(*b)))
        .unwrap_or(o);
    let l = len(far);
    if l == 0.0 {
        return true;
    }
    pts.iter()
        .all(|&p| (orient(o, far, p) / l).abs() <= DUPLICATE_REL * diag)
}
