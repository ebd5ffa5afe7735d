//! Landmarks on an outline and the arc-length correspondence between two
//! outlines (000 sec 4.2.1: the template's primary profile is mapped onto the
//! sketched one).
//!
//! Each outline is read in its own upright frame: origin at its area
//! centroid, "up" the principal axis of its area (the body's long axis) with
//! the sign nearer +y, so landmark detection commutes with rotations of the
//! sketch by less than 45 degrees (a sketch is drawn upright). Landmarks are
//! found in counter-clockwise order:
//!
//! | scheme | landmarks |
//! |---|---|
//! | [`Scheme::Human`] (front) | top of head, left hand, left armpit, left foot, crotch, right foot, right armpit, right hand |
//! | [`Scheme::Side`] | top of head, heel (extreme towards back-down), toe (extreme towards front-down) |
//! | [`Scheme::Extremes`] | top, left, bottom, right (support points) |
//!
//! Armpits and the crotch are concave extremes: the highest point of the arc
//! between hand and foot (between the feet), which must lie strictly inside
//! that arc; otherwise the outline has no such landmark and detection fails
//! with an error naming it. Between consecutive landmarks points correspond
//! by arc-length fraction.

use super::polygon::{cumulative, point_at};
use super::TemplateError;

/// Which landmarks to look for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Scheme {
    Human,
    Side,
    Extremes,
}

impl Scheme {
    /// Landmark names, in counter-clockwise order.
    pub fn names(self) -> &'static [&'static str] {
        match self {
            Scheme::Human => &[
                "top of head",
                "left hand",
                "left armpit",
                "left foot",
                "crotch",
                "right foot",
                "right armpit",
                "right hand",
            ],
            Scheme::Side => &["top of head", "heel", "toe"],
            Scheme::Extremes => &["top", "left", "bottom", "right"],
        }
    }
}

/// A 2D similarity `x -> s R x + t`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Similarity {
    pub scale: f64,
    /// Rotation angle (radians, counter-clockwise).
    pub angle: f64,
    pub translation: [f64; 2],
}

impl Similarity {
    pub fn identity() -> Self {
        Similarity {
            scale: 1.0,
            angle: 0.0,
            translation: [0.0; 2],
        }
    }

    pub fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.angle.sin_cos();
        [
            self.scale * (c * p[0] - s * p[1]) + self.translation[0],
            self.scale * (s * p[0] + c * p[1]) + self.translation[1],
        ]
    }

    /// The least-squares similarity taking `a[i]` to `b[i]` (Umeyama 1991).
    pub fn fit(a: &[[f64; 2]], b: &[[f64; 2]]) -> Self {
        let n = a.len() as f64;
        let mean = |p: &[[f64; 2]]| {
            let mut m = [0.0; 2];
            for q in p {
                m[0] += q[0] / n;
                m[1] += q[1] / n;
            }
            m
        };
        let (ma, mb) = (mean(a), mean(b));
        let (mut sxx, mut sxy, mut va) = (0.0, 0.0, 0.0);
        for (p, q) in a.iter().zip(b) {
            let u = [p[0] - ma[0], p[1] - ma[1]];
            let v = [q[0] - mb[0], q[1] - mb[1]];
            sxx += u[0] * v[0] + u[1] * v[1];
            sxy += u[0] * v[1] - u[1] * v[0];
            va += u[0] * u[0] + u[1] * u[1];
        }
        let angle = sxy.atan2(sxx);
        let scale = (sxx * sxx + sxy * sxy).sqrt() / va.max(1e-300);
        let mut t = Similarity {
            scale,
            angle,
            translation: [0.0; 2],
        };
        let r = t.apply(ma);
        t.translation = [mb[0] - r[0], mb[1] - r[1]];
        t
    }
}

/// The upright frame of a counter-clockwise polygon: centroid and angle of
/// "up" measured from +y.
pub fn upright_frame(p: &[[f64; 2]]) -> ([f64; 2], f64) {
    let n = p.len();
    // the centroid's own cross terms (their sum is twice the area)
    let w: Vec<f64> = (0..n)
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % n]);
            a[0] * b[1] - a[1] * b[0]
        })
        .collect();
    let a2: f64 = w.iter().sum();
    let mut c = [0.0; 2];
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        c[0] += (a[0] + b[0]) * w[i] / (3.0 * a2);
        c[1] += (a[1] + b[1]) * w[i] / (3.0 * a2);
    }
    // second moments of area about the centroid
    let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let a = [p[i][0] - c[0], p[i][1] - c[1]];
        let b = [p[(i + 1) % n][0] - c[0], p[(i + 1) % n][1] - c[1]];
        let w = a[0] * b[1] - a[1] * b[0];
        sxx += (a[0] * a[0] + a[0] * b[0] + b[0] * b[0]) * w / 12.0;
        syy += (a[1] * a[1] + a[1] * b[1] + b[1] * b[1]) * w / 12.0;
        sxy += (a[0] * b[1] + 2.0 * a[0] * a[1] + 2.0 * b[0] * b[1] + b[0] * a[1]) * w / 24.0;
    }
    // a principal axis, as an angle from +x
    let theta = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    // the principal axis nearer +y, as an angle from +y in (-pi/2, pi/2]
    let norm = |mut a: f64| {
        use std::f64::consts::PI;
        while a > PI / 2.0 {
            a -= PI;
        }
        while a <= -PI / 2.0 {
            a += PI;
        }
        a
    };
    let u1 = norm(theta - std::f64::consts::FRAC_PI_2);
    let u2 = norm(theta);
    let up = if u1.abs() <= u2.abs() { u1 } else { u2 };
    (c, up)
}

/// Landmarks of a counter-clockwise polygon: vertex indices in
/// counter-clockwise order starting at the top. `what` names the outline in
/// errors.
pub fn find(p: &[[f64; 2]], scheme: Scheme, what: &str) -> Result<Vec<usize>, TemplateError> {
    let (c, up) = upright_frame(p);
    let (s, co) = (-up).sin_cos();
    let uv: Vec<[f64; 2]> = p
        .iter()
        .map(|q| {
            let d = [q[0] - c[0], q[1] - c[1]];
            [co * d[0] - s * d[1], s * d[0] + co * d[1]]
        })
        .collect();
    let n = p.len();
    let argmax = |from: usize, len: usize, f: &dyn Fn([f64; 2]) -> f64| {
        (0..=len)
            .map(|k| (from + k) % n)
            .max_by(|&a, &b| f(uv[a]).total_cmp(&f(uv[b])))
            .unwrap_or(from)
    };
    let fwd = |a: usize, b: usize| (b + n - a) % n;
    let missing = |name: &str, why: &str| TemplateError::Landmark {
        outline: what.into(),
        landmark: name.into(),
        problem: why.into(),
    };
    let top = argmax(0, n - 1, &|q| q[1]);
    let marks = match scheme {
        Scheme::Extremes => {
            let left = argmax(0, n - 1, &|q| -q[0]);
            let bottom = argmax(0, n - 1, &|q| -q[1]);
            let right = argmax(0, n - 1, &|q| q[0]);
            vec![top, left, bottom, right]
        }
        Scheme::Side => {
            let heel = argmax(0, n - 1, &|q| -q[0] - q[1]);
            let toe = argmax(0, n - 1, &|q| q[0] - q[1]);
            vec![top, heel, toe]
        }
        Scheme::Human => {
            let left = argmax(0, n - 1, &|q| -q[0]);
            let right = argmax(0, n - 1, &|q| q[0]);
            if fwd(top, left) >= fwd(top, right) {
                return Err(missing("left hand", "the leftmost point does not come before the rightmost going counter-clockwise from the top"));
            }
            let utop = uv[top][0];
            let bottom_len = fwd(left, right);
            let lfoot = argmax(left, bottom_len, &|q| {
                if q[0] < utop {
                    -q[1]
                } else {
                    f64::NEG_INFINITY
                }
            });
            let rfoot = argmax(left, bottom_len, &|q| {
                if q[0] > utop {
                    -q[1]
                } else {
                    f64::NEG_INFINITY
                }
            });
            if fwd(left, lfoot) >= fwd(left, rfoot) {
                return Err(missing(
                    "left foot",
                    "no lowest point left of the head before the right foot",
                ));
            }
            let interior = |name: &str, a: usize, b: usize| -> Result<usize, TemplateError> {
                let len = fwd(a, b);
                let k = argmax(a, len, &|q| q[1]);
                if k == a || k == b || len < 2 {
                    return Err(missing(name, "the outline has no concave extreme (highest point) strictly inside that arc"));
                }
                Ok(k)
            };
            let larm = interior("left armpit", left, lfoot)?;
            let crotch = interior("crotch", lfoot, rfoot)?;
            let rarm = interior("right armpit", rfoot, right)?;
            vec![top, left, larm, lfoot, crotch, rfoot, rarm, right]
        }
    };
    // strictly increasing counter-clockwise from the top
    for w in marks.windows(2) {
        if fwd(top, w[1]) <= fwd(top, w[0]) {
            let names = scheme.names();
            let k = marks.iter().position(|&m| m == w[1]).unwrap_or(0);
            return Err(missing(names[k], "out of counter-clockwise order"));
        }
    }
    Ok(marks)
}

/// Corresponding points: `count` points on `a` and their partners on `b`,
/// spread over the arcs between consecutive landmarks in proportion to the
/// arcs' lengths on `a`, by equal arc-length fractions within each arc.
/// Landmarks themselves are included.
pub fn correspond(
    a: &[[f64; 2]],
    la: &[usize],
    b: &[[f64; 2]],
    lb: &[usize],
    count: usize,
) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let (ca, cb) = (cumulative(a), cumulative(b));
    let (pa, pb) = (ca[a.len()], cb[b.len()]);
    let k = la.len();
    let arc = |cum: &[f64], per: f64, i: usize, j: usize| {
        let (s, e) = (cum[i], cum[j]);
        let len = if e > s { e - s } else { e + per - s };
        (s, len)
    };
    let mut out_a = Vec::with_capacity(count + k);
    let mut out_b = Vec::with_capacity(count + k);
    for m in 0..k {
        let (sa, lena) = arc(&ca, pa, la[m], la[(m + 1) % k]);
        let (sb, lenb) = arc(&cb, pb, lb[m], lb[(m + 1) % k]);
        let pts = ((count as f64 * lena / pa).round() as usize).max(1);
        for q in 0..pts {
            let f = q as f64 / pts as f64;
            out_a.push(point_at(a, &ca, sa + f * lena));
            out_b.push(point_at(b, &cb, sb + f * lenb));
        }
    }
    (out_a, out_b)
}

/// The arc-length fractions of the arcs between consecutive landmarks.
pub fn arc_fractions(p: &[[f64; 2]], marks: &[usize]) -> Vec<f64> {
    let cum = cumulative(p);
    let per = cum[p.len()];
    let k = marks.len();
    (0..k)
        .map(|m| {
            let (s, e) = (cum[marks[m]], cum[marks[(m + 1) % k]]);
            (if e > s { e - s } else { e + per - s }) / per
        })
        .collect()
}

/// Rows (heights) on which [`face_marks`] reads an outline's depth span.
pub const FACE_ROWS: usize = 1024;
/// Heights (fractions of the outline's height from its lowest point)
/// searched for the neck, the narrowest depth span of the upper body.
pub const NECK_BAND: (f64, f64) = (0.75, 0.95);
/// Half-width (fraction of the height) of the window over which the chin's
/// underside is found as the front's largest change in depth.
pub const CHIN_WINDOW: f64 = 0.005;
/// The chin is searched from this far (fraction of the height) below the
/// neck up to [`NOSE_CLEAR`] below the nose tip (the nose's own underside
/// is a shallow stretch too).
pub const CHIN_BELOW_NECK: f64 = 0.02;
/// See [`CHIN_BELOW_NECK`].
pub const NOSE_CLEAR: f64 = 0.015;

/// Landmarks of a side outline's head (issue 12, "jaw"): heights in model
/// units. The side outline of a human is read by rows: its front (largest
/// depth) and back at each height.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct FaceMarks {
    /// The narrowest depth span in [`NECK_BAND`].
    pub neck: f64,
    /// The front-most point above the neck.
    pub nose: f64,
    /// The chin's underside: between the neck and the nose, the height
    /// where the front moves most in depth within [`CHIN_WINDOW`] (the
    /// shallow stretch from the chin's front back to the throat).
    pub chin: f64,
    /// The outline's highest point (top of the head).
    pub top: f64,
    /// The outline's lowest point.
    pub bottom: f64,
}

/// [`FaceMarks`] of the closed side outline `p` (depth, height); `what`
/// names it in errors.
pub fn face_marks(p: &[[f64; 2]], what: &str) -> Result<FaceMarks, TemplateError> {
    let missing = |name: &str, why: &str| TemplateError::Landmark {
        outline: what.into(),
        landmark: name.into(),
        problem: why.into(),
    };
    let (lo, hi) = super::polygon::bbox(p);
    let h = hi[1] - lo[1];
    if !(h.is_finite() && h > 0.0) {
        return Err(missing("neck", "the outline has no height"));
    }
    let n = FACE_ROWS;
    let y = |r: usize| lo[1] + h * r as f64 / (n - 1) as f64;
    let rows: Vec<Option<(f64, f64)>> = (0..n)
        .map(|r| super::polygon::depth_span(p, y(r)))
        .collect();
    let row = |f: f64| ((f * (n - 1) as f64).round() as usize).min(n - 1);
    let width = |r: usize| rows[r].map_or(f64::INFINITY, |(b, f)| f - b);
    let neck = (row(NECK_BAND.0)..=row(NECK_BAND.1))
        .min_by(|&a, &b| width(a).total_cmp(&width(b)))
        .filter(|&r| width(r).is_finite())
        .ok_or_else(|| missing("neck", "the outline does not cross the neck's heights"))?;
    let front = |r: usize| rows[r].map_or(f64::NEG_INFINITY, |s| s.1);
    let nose = (neck..n)
        .max_by(|&a, &b| front(a).total_cmp(&front(b)))
        .unwrap_or(neck);
    let w = row(CHIN_WINDOW).max(1);
    let (from, to) = (
        neck.saturating_sub(row(CHIN_BELOW_NECK)).max(w),
        nose.saturating_sub(row(NOSE_CLEAR)).min(n - 1 - w),
    );
    if from >= to {
        return Err(missing(
            "chin",
            "the nose tip is not far enough above the neck for a chin between them",
        ));
    }
    let jump = |r: usize| front(r + w) - front(r - w);
    let chin = (from..to)
        .max_by(|&a, &b| jump(a).total_cmp(&jump(b)))
        .filter(|&r| jump(r).is_finite() && jump(r) > 0.0)
        .ok_or_else(|| {
            missing(
                "chin",
                "the front does not step forward anywhere between the neck and the nose",
            )
        })?;
    Ok(FaceMarks {
        neck: y(neck),
        nose: y(nose),
        chin: y(chin),
        top: hi[1],
        bottom: lo[1],
    })
}
