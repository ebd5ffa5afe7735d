//! The inside of a closed stroke on a part, mapped onto the unit square
//! (for the 4-sided sculpting force inside a curve of any simple shape,
//! paper 000 sec 5.1, [`super::Edit::ForceStroke`]; validated with the edit).
//!
//! # The map
//! The stroke is a closed polygon in the part's parameters `(u, theta)`.
//! It is scaled to its bounding box, `x = (u - u_a)/(u_b - u_a)`,
//! `y = (theta - theta_a)/(theta_b - theta_a)` (the affine map the
//! rectangle force uses), made counter-clockwise, and split into four sides
//! at four corner vertices: given by the user, or by default the vertices
//! extremal in the directions `(-1,-1), (1,-1), (1,1), (-1,1)` (a
//! rectangle's own corners). Side `k` goes onto side `k` of the unit square
//! by arc length, so every vertex `p_i` has an image `q_i` on the square's
//! boundary and the polygon goes onto the boundary one-to-one, piecewise
//! linearly. Inside, the map is the mean value interpolation of the `q_i`
//! (Floater 2003; Hormann and Floater 2006 for non-convex polygons):
//!
//! `phi(x) = sum_i w_i q_i / sum_i w_i`, `w_i = (tan(a_{i-1}/2) + tan(a_i/2)) / |p_i - x|`,
//!
//! `a_i` the signed angle at `x` between `p_i` and `p_{i+1}`. It is smooth
//! inside, interpolates the boundary (linearly along each edge), has
//! bounded derivatives up to the boundary and reproduces affine maps
//! (linear precision): a rectangle stroke gives exactly the rectangle
//! force's affine map. A mean value map onto a convex polygon is one-to-one
//! for a convex stroke; for a non-convex one it can fold, so every stroke
//! is checked at push time: the images of the cells of a
//! [`FOLD_GRID`]-square grid lying inside the stroke must all keep their
//! orientation ([`StrokeMap::folded_cells`]); a folding stroke is refused
//! ([`StrokeError::Folded`]). With the boundary going onto the square's
//! boundary once (degree one), a fold-free map is one-to-one.
//!
//! # Why C1 across the stroke
//! The force's pde4 patch `P` vanishes with its gradient on the square's
//! edges; the displacement is `P(phi(x))` inside and zero outside. On the
//! stroke `phi` lies on the square's boundary, so the displacement is zero
//! there, and its gradient `grad P(phi) . D phi` tends to zero because
//! `D phi` stays bounded: the edited part is C1 across the stroke
//! (checked in `verify` family `edit`, `force_stroke_*`).

use crate::polygon;
use std::f64::consts::PI;

/// Fewest distinct points of a stroke (one per corner).
pub const STROKE_POINTS_MIN: usize = 4;
/// Most points of a stroke.
pub const STROKE_POINTS_MAX: usize = 4096;
/// Largest gap between a stroke's last and first points, as a fraction of
/// its length, for the stroke to count as closed (the gap is then its
/// closing edge).
pub const CLOSE_GAP_MAX: f64 = 0.05;
/// Smallest stroke area as a fraction of its bounding box's area (below
/// this the stroke is a sliver with no inside to speak of).
pub const FILL_MIN: f64 = 0.02;
/// Grid cells per direction of the fold test.
pub const FOLD_GRID: usize = 64;
/// Points closer than this (relative to the bounding box) are one point.
const SAME_POINT: f64 = 1e-12;

/// Errors of a stroke.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StrokeError {
    #[error("the stroke has {count} distinct points; it needs at least {STROKE_POINTS_MIN} (one per corner)")]
    TooFewPoints { count: usize },
    #[error("the stroke has {count} points; at most {STROKE_POINTS_MAX}")]
    TooManyPoints { count: usize },
    #[error("stroke point {index} is not finite ({u}, {theta})")]
    NotFinite { index: usize, u: f64, theta: f64 },
    #[error("the stroke is open: the gap from its last point back to its first is {:.1}% of its length (a closed stroke ends where it starts, within {}%)", 100.0 * .gap / .length, 100.0 * CLOSE_GAP_MAX)]
    Open { gap: f64, length: f64 },
    #[error("the stroke crosses itself (edges {first} and {second})")]
    SelfIntersecting { first: usize, second: usize },
    #[error("the stroke is degenerate: it encloses {area:.3e} of its bounding box's {bbox:.3e} (below {FILL_MIN} of it)")]
    Degenerate { area: f64, bbox: f64 },
    #[error(
        "the stroke spans {span:.4} rad of angle: it must span less than the whole ring (2 pi)"
    )]
    TooWide { span: f64 },
    #[error("the stroke's u range [{lo:e}, {hi:e}] has no finite width (a stroke lies within its part's u range)")]
    UnboundedU { lo: f64, hi: f64 },
    #[error("corners {corners:?}: {message}")]
    BadCorners {
        corners: [usize; 4],
        message: String,
    },
    #[error("the map of the stroke's inside onto the square folds ({folded} of {cells} grid cells turn over): the stroke is too far from convex; draw a rounder stroke or choose other corners")]
    Folded { folded: usize, cells: usize },
}

/// A closed stroke's inside mapped onto the unit square.
#[derive(Clone, Debug, PartialEq)]
pub struct StrokeMap {
    /// Bounding box in `u`.
    pub u: [f64; 2],
    /// Bounding box in `theta` (the stroke's own angles, unwrapped).
    pub theta: [f64; 2],
    /// The polygon in box coordinates, counter-clockwise.
    pub poly: Vec<[f64; 2]>,
    /// The image of each vertex on the unit square's boundary.
    pub square: Vec<[f64; 2]>,
    /// The corner vertices (indices into `poly`), going onto `(0,0)`,
    /// `(1,0)`, `(1,1)`, `(0,1)`.
    pub corners: [usize; 4],
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn len(a: [f64; 2], b: [f64; 2]) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// The bounding box of a stroke whose points are finite and within the
/// counts, spanning less than a whole ring in angle, a finite positive
/// width in `u` and a positive one in angle.
fn bounds(stroke: &[[f64; 2]]) -> Result<([f64; 2], [f64; 2]), StrokeError> {
    if stroke.len() > STROKE_POINTS_MAX {
        return Err(StrokeError::TooManyPoints {
            count: stroke.len(),
        });
    }
    if let Some((i, p)) = stroke
        .iter()
        .enumerate()
        .find(|(_, p)| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(StrokeError::NotFinite {
            index: i,
            u: p[0],
            theta: p[1],
        });
    }
    if stroke.len() < STROKE_POINTS_MIN {
        return Err(StrokeError::TooFewPoints {
            count: stroke.len(),
        });
    }
    let (lo, hi) = polygon::bbox(stroke);
    if hi[1] - lo[1] >= 2.0 * PI {
        return Err(StrokeError::TooWide {
            span: hi[1] - lo[1],
        });
    }
    let ext = [hi[0] - lo[0], hi[1] - lo[1]];
    if !ext[0].is_finite() {
        return Err(StrokeError::UnboundedU {
            lo: lo[0],
            hi: hi[0],
        });
    }
    if !(ext[0] > 0.0 && ext[1] > 0.0) {
        return Err(StrokeError::Degenerate {
            area: 0.0,
            bbox: ext[0] * ext[1],
        });
    }
    Ok((lo, hi))
}

/// The stroke in box coordinates (`lo`, `ext`: its bounding box's corner
/// and extent) with repeated points dropped (keeping the first of a run)
/// and a last point that repeats the first; `index[k]` is the kept point
/// of stroke point `k`. Refused when open, with too few points left, or
/// crossing itself.
fn boxed_polygon(
    stroke: &[[f64; 2]],
    lo: [f64; 2],
    ext: [f64; 2],
) -> Result<(Vec<[f64; 2]>, Vec<usize>), StrokeError> {
    let boxed = |p: &[f64; 2]| [(p[0] - lo[0]) / ext[0], (p[1] - lo[1]) / ext[1]];
    let mut poly: Vec<[f64; 2]> = Vec::with_capacity(stroke.len());
    let mut index = Vec::with_capacity(stroke.len());
    for p in stroke {
        let q = boxed(p);
        if poly.last().is_some_and(|&l| len(l, q) <= SAME_POINT) {
            index.push(poly.len() - 1);
        } else {
            index.push(poly.len());
            poly.push(q);
        }
    }
    let length: f64 = (1..poly.len()).map(|i| len(poly[i - 1], poly[i])).sum();
    // closed: the last point repeats the first (then dropped), or ends
    // within the allowed gap of it (the gap is the closing edge)
    let gap = len(poly[poly.len() - 1], poly[0]);
    if poly.len() > 1 && gap <= SAME_POINT {
        poly.pop();
        let last = poly.len();
        index
            .iter_mut()
            .filter(|k| **k == last)
            .for_each(|k| *k = 0);
    } else if gap > CLOSE_GAP_MAX * (length + gap) {
        return Err(StrokeError::Open {
            gap,
            length: length + gap,
        });
    }
    if poly.len() < STROKE_POINTS_MIN {
        return Err(StrokeError::TooFewPoints { count: poly.len() });
    }
    if let Some((a, b, _)) = polygon::self_intersection(&poly) {
        return Err(StrokeError::SelfIntersecting {
            first: a,
            second: b,
        });
    }
    Ok((poly, index))
}

/// The default corners: the vertices extremal in the directions
/// `(-1,-1), (1,-1), (1,1), (-1,1)` (a rectangle's own corners).
fn extreme_corners(poly: &[[f64; 2]]) -> [usize; 4] {
    let dirs = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    dirs.map(|d| {
        let f = |k: usize| d[0] * poly[k][0] + d[1] * poly[k][1];
        (0..poly.len())
            .max_by(|&i, &j| f(i).total_cmp(&f(j)))
            .unwrap_or(0)
    })
}

/// Each vertex's image on the unit square's boundary: side `k` (from
/// corner `k` to corner `k + 1`) onto the square's side `k` by arc length.
fn square_images(poly: &[[f64; 2]], corners: [usize; 4]) -> Vec<[f64; 2]> {
    let n = poly.len();
    let square_corner = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let mut square = vec![[0.0; 2]; n];
    for k in 0..4 {
        let (a, b) = (corners[k], corners[(k + 1) % 4]);
        let count = (b + n - a) % n;
        let mut s = vec![0.0; count + 1];
        for j in 1..=count {
            s[j] = s[j - 1] + len(poly[(a + j - 1) % n], poly[(a + j) % n]);
        }
        let (c0, c1) = (square_corner[k], square_corner[(k + 1) % 4]);
        for j in 0..count {
            let t = s[j] / s[count];
            square[(a + j) % n] = [c0[0] + t * (c1[0] - c0[0]), c0[1] + t * (c1[1] - c0[1])];
        }
    }
    square
}

impl StrokeMap {
    /// The map of `stroke` (points `(u, theta)`, closed: the last point
    /// returns to the first within [`CLOSE_GAP_MAX`] of the length) with
    /// optional `corners` (four indices into `stroke`, in order along it).
    pub fn new(stroke: &[[f64; 2]], corners: Option<[usize; 4]>) -> Result<StrokeMap, StrokeError> {
        let (lo, hi) = bounds(stroke)?;
        let ext = [hi[0] - lo[0], hi[1] - lo[1]];
        let (mut poly, index) = boxed_polygon(stroke, lo, ext)?;
        let signed = polygon::signed_area(&poly);
        if signed.abs() < FILL_MIN {
            return Err(StrokeError::Degenerate {
                area: signed.abs() * ext[0] * ext[1],
                bbox: ext[0] * ext[1],
            });
        }
        let n = poly.len();
        let given = corners;
        let mut corners = match corners {
            Some(c) => {
                if c.iter().any(|&k| k >= stroke.len()) {
                    return Err(StrokeError::BadCorners {
                        corners: c,
                        message: format!(
                            "a corner index is past the stroke's {} points",
                            stroke.len()
                        ),
                    });
                }
                Some(c.map(|k| index[k]))
            }
            None => None,
        };
        if signed < 0.0 {
            poly.reverse();
            // the first corner stays first; the others now come in the
            // reverse order
            corners = corners.map(|c| [c[0], c[3], c[2], c[1]].map(|k| n - 1 - k));
        }
        let corners = corners.unwrap_or_else(|| extreme_corners(&poly));
        let off = |k: usize| (corners[k] + n - corners[0]) % n;
        if !(off(1) > 0 && off(2) > off(1) && off(3) > off(2)) {
            return Err(StrokeError::BadCorners {
                corners: given.unwrap_or(corners),
                message: match given {
                    Some(_) => "the corners must be four distinct stroke points in their order along the stroke".into(),
                    None => "the stroke has no four distinct extreme points to serve as corners; give \"corners\" (four stroke point indices in order along it)".into(),
                },
            });
        }
        let square = square_images(&poly, corners);
        let map = StrokeMap {
            u: [lo[0], hi[0]],
            theta: [lo[1], hi[1]],
            poly,
            square,
            corners,
        };
        let (folded, cells) = map.folded_cells(FOLD_GRID);
        if folded > 0 {
            return Err(StrokeError::Folded { folded, cells });
        }
        Ok(map)
    }

    /// Box coordinates of angle `theta` (any real: taken modulo `2 pi`
    /// after the stroke's smallest angle).
    pub fn y_of(&self, theta: f64) -> f64 {
        let t = self.theta[0] + (theta - self.theta[0]).rem_euclid(2.0 * PI);
        (t - self.theta[0]) / (self.theta[1] - self.theta[0])
    }

    /// Whether box point `x` is inside the polygon
    /// ([`polygon::point_in_polygon`]: even-odd; on the boundary, the
    /// left and bottom sides in, the right and top out).
    pub fn contains(&self, x: [f64; 2]) -> bool {
        polygon::point_in_polygon(&self.poly, x)
    }

    /// The mean value map of box point `x` (inside or on the polygon).
    pub fn map(&self, x: [f64; 2]) -> [f64; 2] {
        let (p, q) = (&self.poly, &self.square);
        let n = p.len();
        let d: Vec<[f64; 2]> = p.iter().map(|v| [v[0] - x[0], v[1] - x[1]]).collect();
        let r: Vec<f64> = d.iter().map(|v| v[0].hypot(v[1])).collect();
        if let Some(i) = (0..n).find(|&i| r[i] <= SAME_POINT) {
            return q[i];
        }
        // tan(a_i / 2), computed without cancellation on either side
        let mut t = vec![0.0; n];
        for i in 0..n {
            let j = (i + 1) % n;
            let (a, dd) = (cross(d[i], d[j]), d[i][0] * d[j][0] + d[i][1] * d[j][1]);
            let rr = r[i] * r[j];
            if dd < 0.0 && a.abs() <= SAME_POINT * rr {
                // on edge i
                let s = r[i] / (r[i] + r[j]);
                return [
                    q[i][0] + s * (q[j][0] - q[i][0]),
                    q[i][1] + s * (q[j][1] - q[i][1]),
                ];
            }
            t[i] = if dd >= 0.0 {
                a / (rr + dd)
            } else {
                (rr - dd) / a
            };
        }
        let (mut sw, mut sx, mut sy) = (0.0, 0.0, 0.0);
        for i in 0..n {
            let w = (t[(i + n - 1) % n] + t[i]) / r[i];
            sw += w;
            sx += w * q[i][0];
            sy += w * q[i][1];
        }
        [sx / sw, sy / sw]
    }

    /// The square coordinates of part point `(s, theta)`, `s` the box
    /// coordinate in `u`; `None` outside the stroke.
    pub fn local(&self, s: f64, theta: f64) -> Option<[f64; 2]> {
        let x = [s, self.y_of(theta)];
        self.contains(x).then(|| {
            let m = self.map(x);
            [m[0].clamp(0.0, 1.0), m[1].clamp(0.0, 1.0)]
        })
    }

    /// The fold test on a `grid`-square grid over the box: `(folded,
    /// cells)`, the cells whose four corners lie inside the stroke, and of
    /// them those whose image (two triangles) loses its orientation.
    pub fn folded_cells(&self, grid: usize) -> (usize, usize) {
        let h = 1.0 / grid as f64;
        let pts: Vec<Option<[f64; 2]>> = (0..=grid)
            .flat_map(|j| (0..=grid).map(move |i| [i as f64 * h, j as f64 * h]))
            .map(|x| self.contains(x).then(|| self.map(x)))
            .collect();
        let at = |i: usize, j: usize| pts[j * (grid + 1) + i];
        let (mut folded, mut cells) = (0, 0);
        for j in 0..grid {
            for i in 0..grid {
                let (Some(a), Some(b), Some(c), Some(d)) =
                    (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1))
                else {
                    continue;
                };
                cells += 1;
                let area = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
                    cross([q[0] - p[0], q[1] - p[1]], [r[0] - p[0], r[1] - p[1]])
                };
                if !(area(a, b, c) > 0.0 && area(a, c, d) > 0.0) {
                    folded += 1;
                }
            }
        }
        (folded, cells)
    }

    /// The Jacobian determinant of the map at box point `x` (central
    /// differences of step `h`).
    pub fn jacobian(&self, x: [f64; 2], h: f64) -> f64 {
        let f = |dx: f64, dy: f64| self.map([x[0] + dx, x[1] + dy]);
        let (a, b, c, d) = (f(h, 0.0), f(-h, 0.0), f(0.0, h), f(0.0, -h));
        let ju = [(a[0] - b[0]) / (2.0 * h), (a[1] - b[1]) / (2.0 * h)];
        let jv = [(c[0] - d[0]) / (2.0 * h), (c[1] - d[1]) / (2.0 * h)];
        cross(ju, jv)
    }
}
