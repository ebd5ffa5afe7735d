//! Rotation tolerance of the segmentation: the front outline is turned
//! upright about its principal axis before it is sliced, and everything
//! derived from it is turned back.
//!
//! The segmentation ([`super::segment`]) slices the outline horizontally, so
//! a drawing rotated by a few degrees puts one armpit higher than the other
//! and tilts every join. The outline's area moments about its centroid
//! `c`,
//!
//! $$ S = \int_\Omega (p - c)(p - c)^T \, dA, $$
//!
//! computed exactly for the polygon (Green's theorem), give the major axis
//! at angle `phi = atan2(2 S_xy, S_xx - S_yy) / 2` from the x axis. Its
//! **deviation** is `phi` reduced modulo 90 degrees into (-45, 45]: the
//! rotation from the nearest axis-aligned pose (a standing figure's major
//! axis is vertical, an animal's may be horizontal). Rules:
//! - anisotropy `(l1 - l2) / (l1 + l2)` of the eigenvalues below
//!   [`MIN_ANISOTROPY`]: the axis is not defined, no alignment;
//! - `|deviation|` below [`ROTATION_EPS_DEG`]: no alignment (an upright,
//!   mirror-symmetric drawing is derived bit for bit as before);
//! - otherwise the rotation is read again from the outline's thick core
//!   ([`core_axes`]: the area's moments weighted by the squared distance to
//!   the outline), so that a pose (one arm level, one hanging) is not read
//!   as a tilt; below [`CORE_EPS_DEG`] no alignment;
//! - `|deviation|` above [`MAX_ROTATION_DEG`]: an error naming the angle;
//! - otherwise the outline is rotated by `-deviation` about `c`, derived,
//!   and the derived section centres, frames and seam apexes are rotated
//!   back, so the model matches the drawing as drawn.
//!
//! Key cross-section sketches are horizontal slices of the figure in its
//! own (upright) frame: their height and centre are mapped with the outline.

use super::SketchError;

/// The rotation from the nearest axis-aligned pose of a major axis at
/// `major` radians: reduced modulo 90 degrees into (-45, 45].
pub fn deviation(major: f64) -> f64 {
    let q = std::f64::consts::FRAC_PI_2;
    let mut dev = major.rem_euclid(q);
    if dev > 0.5 * q {
        dev -= q;
    }
    dev
}

/// Largest accepted rotation from upright (degrees).
pub const MAX_ROTATION_DEG: f64 = 12.0;
/// Rotations below this (degrees) are not corrected.
pub const ROTATION_EPS_DEG: f64 = 1e-3;
/// Core-axis rotations below this (degrees) are not corrected: turning the
/// outline by less moves no point within half its height of the pivot by
/// more than the default flattening tolerance (1/1000 of the height), so
/// the rotation would change nothing the drawing says (2e-3 rad).
pub const CORE_EPS_DEG: f64 = 2.0e-3 * 180.0 / std::f64::consts::PI;
/// Below this eigenvalue anisotropy the principal axis is not used.
pub const MIN_ANISOTROPY: f64 = 0.2;

/// The principal axes of a simple polygon's area.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axes {
    pub centroid: [f64; 2],
    /// Angle of the major axis from the x axis (radians, in (-pi/2, pi/2]).
    pub major: f64,
    /// `(l1 - l2) / (l1 + l2)` of the second-moment eigenvalues, in [0, 1].
    pub anisotropy: f64,
}

/// Area, centroid and central second moments `[S_xx, S_yy, S_xy]` of a
/// simple polygon (either orientation).
pub fn moments(points: &[[f64; 2]]) -> (f64, [f64; 2], [f64; 3]) {
    let n = points.len();
    // shift to the vertex mean for accuracy
    let o = points
        .iter()
        .fold([0.0; 2], |a, p| [a[0] + p[0], a[1] + p[1]]);
    let o = [o[0] / n.max(1) as f64, o[1] / n.max(1) as f64];
    let (mut a2, mut cx, mut cy) = (0.0, 0.0, 0.0);
    let (mut ixx, mut iyy, mut ixy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let p = [points[i][0] - o[0], points[i][1] - o[1]];
        let q = [points[(i + 1) % n][0] - o[0], points[(i + 1) % n][1] - o[1]];
        let c = p[0] * q[1] - q[0] * p[1];
        a2 += c;
        cx += (p[0] + q[0]) * c;
        cy += (p[1] + q[1]) * c;
        iyy += (p[0] * p[0] + p[0] * q[0] + q[0] * q[0]) * c;
        ixx += (p[1] * p[1] + p[1] * q[1] + q[1] * q[1]) * c;
        ixy += (p[0] * q[1] + 2.0 * p[0] * p[1] + 2.0 * q[0] * q[1] + q[0] * p[1]) * c;
    }
    let area = 0.5 * a2;
    if area == 0.0 {
        return (0.0, o, [0.0; 3]);
    }
    let (cx, cy) = (cx / (3.0 * a2), cy / (3.0 * a2));
    // integrals of x^2, y^2, xy about o, then about the centroid
    let sxx = iyy / 12.0 - area * cx * cx;
    let syy = ixx / 12.0 - area * cy * cy;
    let sxy = ixy / 24.0 - area * cx * cy;
    let s = area.signum();
    (
        area.abs(),
        [o[0] + cx, o[1] + cy],
        [s * sxx, s * syy, s * sxy],
    )
}

/// The principal axes of a simple polygon.
pub fn axes(points: &[[f64; 2]]) -> Axes {
    let (_, c, [sxx, syy, sxy]) = moments(points);
    let major = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let half = 0.5 * (sxx - syy).hypot(2.0 * sxy);
    let mean = 0.5 * (sxx + syy);
    Axes {
        centroid: c,
        major,
        anisotropy: if mean > 0.0 { half / mean } else { 0.0 },
    }
}

/// A rotation of the drawing about `pivot` by `angle` (radians,
/// counter-clockwise) from its upright pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Alignment {
    pub pivot: [f64; 2],
    pub angle: f64,
}

impl Alignment {
    /// No rotation.
    pub fn identity() -> Alignment {
        Alignment {
            pivot: [0.0; 2],
            angle: 0.0,
        }
    }

    pub fn is_identity(&self) -> bool {
        self.angle == 0.0
    }

    fn rot(&self, p: [f64; 2], angle: f64) -> [f64; 2] {
        let (s, c) = angle.sin_cos();
        let d = [p[0] - self.pivot[0], p[1] - self.pivot[1]];
        [
            self.pivot[0] + c * d[0] - s * d[1],
            self.pivot[1] + s * d[0] + c * d[1],
        ]
    }

    /// A drawn point in the upright frame.
    pub fn to_upright(&self, p: [f64; 2]) -> [f64; 2] {
        self.rot(p, -self.angle)
    }

    /// An upright-frame point back in the drawing (z unchanged).
    pub fn point_back(&self, p: [f64; 3]) -> [f64; 3] {
        let q = self.rot([p[0], p[1]], self.angle);
        [q[0], q[1], p[2]]
    }

    /// An upright-frame direction back in the drawing.
    pub fn vector_back(&self, v: [f64; 3]) -> [f64; 3] {
        let (s, c) = self.angle.sin_cos();
        [c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]]
    }
}

/// Grid rows over the outline's height for [`core_axes`].
const CORE_ROWS: usize = 96;

/// The principal axes of the outline's **thick core**: the second moments
/// of the interior weighted by the squared distance to the outline,
/// sampled on a grid of [`CORE_ROWS`] rows (square cells). A tube of half
/// width `r` weighs `2 r^3 / 3` per unit length, so a part's share grows
/// with the cube of its thickness: an arm a fifth as thick as the torso
/// weighs 1/125 as much per unit length, and an asymmetric arm pose (one
/// arm level, the other hanging) no longer reads as a tilted figure. The
/// area's own axis ([`axes`]) turned such a drawing by 7 degrees (corpus
/// arms_apart), which put its feet at different heights and lost a leg.
pub fn core_axes(points: &[[f64; 2]]) -> Axes {
    let (lo, hi) = crate::polygon::bbox(points);
    let h = (hi[1] - lo[1]) / CORE_ROWS as f64;
    let cols = ((hi[0] - lo[0]) / h).ceil().max(1.0) as usize;
    let (mut w, mut m) = (0.0, [0.0; 2]);
    let mut pts = Vec::new();
    for i in 0..CORE_ROWS {
        for j in 0..cols {
            let q = [lo[0] + (j as f64 + 0.5) * h, lo[1] + (i as f64 + 0.5) * h];
            if crate::polygon::point_in_polygon(points, q) {
                let d = crate::polygon::boundary_distance(points, q);
                let wt = d * d;
                w += wt;
                m = [m[0] + wt * q[0], m[1] + wt * q[1]];
                pts.push((q, wt));
            }
        }
    }
    if !w.is_finite() || w <= 0.0 {
        return axes(points);
    }
    let c = [m[0] / w, m[1] / w];
    let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
    for (q, wt) in pts {
        let d = [q[0] - c[0], q[1] - c[1]];
        sxx += wt * d[0] * d[0];
        syy += wt * d[1] * d[1];
        sxy += wt * d[0] * d[1];
    }
    let half = 0.5 * (sxx - syy).hypot(2.0 * sxy);
    let mean = 0.5 * (sxx + syy);
    Axes {
        centroid: c,
        major: 0.5 * (2.0 * sxy).atan2(sxx - syy),
        anisotropy: if mean > 0.0 { half / mean } else { 0.0 },
    }
}

/// The rotation of a front outline from upright (see the module docs).
pub fn alignment(front: &[[f64; 2]]) -> Result<Alignment, SketchError> {
    let whole = axes(front);
    if whole.anisotropy.is_nan() || whole.anisotropy < MIN_ANISOTROPY {
        return Ok(Alignment::identity());
    }
    // an upright mirror-symmetric drawing: no rotation, bit for bit
    if deviation(whole.major).to_degrees().abs() < ROTATION_EPS_DEG {
        return Ok(Alignment::identity());
    }
    let ax = core_axes(front);
    let dev = deviation(ax.major);
    let deg = dev.to_degrees();
    if deg.abs() < CORE_EPS_DEG {
        return Ok(Alignment::identity());
    }
    if deg.abs() > MAX_ROTATION_DEG {
        return Err(SketchError::Segmentation(format!(
            "the front outline's principal axis is {deg:.1} degrees from upright (at most {MAX_ROTATION_DEG} is corrected): draw the figure upright"
        )));
    }
    Ok(Alignment {
        pivot: ax.centroid,
        angle: dev,
    })
}
