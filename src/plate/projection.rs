//! Projection onto the view plane (eq 13) and the local frame (eq 14).
//!
//! Eq 13 as printed reads
//! $\bar p_1 = -\frac{a p_x + b p_x + c p_z + d}{a^2+b^2+c^2}\,\mathbf n + \mathbf p$;
//! the second term must be $b\,p_y$ (orthogonal projection: the result lies
//! on the plane and $\mathbf p - \bar p_1 \parallel \mathbf n$). The corrected
//! form is [`project`], the printed one [`project_paper_literal`].
//! Eq 14 translates by the frame origin and rotates onto the unit vectors
//! $\mathbf v_x, \mathbf v_y, \mathbf v_z$ (a row vector times $\[T\]\[R\]$ gives
//! $((\bar p - \bar o)\cdot \mathbf v_x, (\bar p - \bar o)\cdot \mathbf v_y,
//! (\bar p - \bar o)\cdot \mathbf v_z)$); the $z'$ component is dropped.

use super::PlateError;
use crate::mesh::{dot, norm, scale, sub};
use crate::surface::cross;

/// The view plane $a x + b y + c z + d = 0$.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewPlane {
    /// $(a, b, c)$, not necessarily unit.
    pub normal: [f64; 3],
    pub d: f64,
}

impl ViewPlane {
    /// The plane with normal `normal` through `point`.
    pub fn through(point: [f64; 3], normal: [f64; 3]) -> Result<Self, PlateError> {
        let n = norm(normal);
        if !n.is_finite() || n < f64::EPSILON.sqrt() || point.iter().any(|c| !c.is_finite()) {
            return Err(PlateError::DegenerateProjection(format!(
                "view-plane normal {normal:?} is zero or not finite"
            )));
        }
        Ok(ViewPlane {
            normal,
            d: -dot(normal, point),
        })
    }
}

/// Eq 13, corrected: orthogonal projection of `p` onto the plane.
pub fn project(plane: &ViewPlane, p: [f64; 3]) -> [f64; 3] {
    let [a, b, c] = plane.normal;
    let t = (a * p[0] + b * p[1] + c * p[2] + plane.d) / (a * a + b * b + c * c);
    sub(p, scale(plane.normal, t))
}

/// Eq 13 exactly as printed (`b p_x` in place of `b p_y`); kept to measure
/// the erratum.
pub fn project_paper_literal(plane: &ViewPlane, p: [f64; 3]) -> [f64; 3] {
    let [a, b, c] = plane.normal;
    let t = (a * p[0] + b * p[0] + c * p[2] + plane.d) / (a * a + b * b + c * c);
    sub(p, scale(plane.normal, t))
}

/// The local frame of eq 14: origin and orthonormal axes, $\mathbf v_z$
/// along the plane normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalFrame {
    pub origin: [f64; 3],
    pub vx: [f64; 3],
    pub vy: [f64; 3],
    pub vz: [f64; 3],
}

impl LocalFrame {
    /// A right-handed frame at `origin` with $\mathbf v_z = \mathbf n/|\mathbf n|$.
    pub fn new(origin: [f64; 3], normal: [f64; 3]) -> Result<Self, PlateError> {
        let n = norm(normal);
        if !n.is_finite() || n < f64::EPSILON.sqrt() {
            return Err(PlateError::DegenerateProjection(format!(
                "frame normal {normal:?} is zero or not finite"
            )));
        }
        let vz = scale(normal, 1.0 / n);
        // the world axis least aligned with vz seeds vx
        let k = (0..3)
            .min_by(|&i, &j| vz[i].abs().total_cmp(&vz[j].abs()))
            .unwrap_or(0);
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let vx0 = sub(e, scale(vz, dot(e, vz)));
        let vx = scale(vx0, 1.0 / norm(vx0));
        let vy = cross(vz, vx);
        Ok(LocalFrame { origin, vx, vy, vz })
    }

    /// Eq 14: $\bar p' = \bar p_2 \[T\]\[R\]$, returning $(x', y', z')$.
    pub fn to_local(&self, p: [f64; 3]) -> [f64; 3] {
        let d = sub(p, self.origin);
        [dot(d, self.vx), dot(d, self.vy), dot(d, self.vz)]
    }

    /// Eq 14 written literally as the 4x4 homogeneous product (row vector
    /// times $\[T\]$ times $\[R\]$), for the check against [`Self::to_local`].
    pub fn to_local_matrix(&self, p: [f64; 3]) -> [f64; 3] {
        let o = self.origin;
        let t = [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [-o[0], -o[1], -o[2], 1.0],
        ];
        let (x, y, z) = (self.vx, self.vy, self.vz);
        let r = [
            [x[0], y[0], z[0], 0.0],
            [x[1], y[1], z[1], 0.0],
            [x[2], y[2], z[2], 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ];
        let row = [p[0], p[1], p[2], 1.0];
        let mul = |v: [f64; 4], m: [[f64; 4]; 4]| {
            let mut o = [0.0; 4];
            for j in 0..4 {
                o[j] = (0..4).map(|i| v[i] * m[i][j]).sum();
            }
            o
        };
        let out = mul(mul(row, t), r);
        [out[0], out[1], out[2]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_view_plane_needs_a_normal_and_a_finite_point() {
        assert!(ViewPlane::through([0.0; 3], [0.0, 0.0, 1.0]).is_ok());
        assert!(ViewPlane::through([0.0; 3], [0.0; 3]).is_err());
        assert!(ViewPlane::through([f64::NAN, 0.0, 0.0], [0.0, 0.0, 1.0]).is_err());
        assert!(ViewPlane::through([0.0; 3], [f64::INFINITY, 0.0, 0.0]).is_err());
    }

    /// A plane away from the origin: a point projects onto it along the
    /// normal (hand computed: the plane z = 2, and the plane of normal
    /// (1, 2, 3) through (1, 1, 1), where (2, 3, 4) lands at
    /// (2, 3, 4) - (14/14) (1, 2, 3)).
    #[test]
    fn a_point_projects_onto_a_plane_through_any_point() {
        let z2 = ViewPlane::through([5.0, -3.0, 2.0], [0.0, 0.0, 1.0]).expect("plane");
        let q = project(&z2, [1.0, 1.0, 5.0]);
        assert!(
            crate::mesh::dist(q, [1.0, 1.0, 2.0]) < crate::check::tol::ROUNDING,
            "{q:?}"
        );
        let tilted = ViewPlane::through([1.0; 3], [1.0, 2.0, 3.0]).expect("plane");
        let q = project(&tilted, [2.0, 3.0, 4.0]);
        assert!(
            crate::mesh::dist(q, [1.0, 1.0, 1.0]) < crate::check::tol::ROUNDING,
            "{q:?}"
        );
    }

    /// Eq 13 as printed reads `b p_x` for `b p_y`: through the origin with
    /// normal (1, 2, 3), (2, 3, 4) gets t = (2 + 4 + 12)/14 = 18/14, not
    /// the right 20/14 (hand computed).
    #[test]
    fn eq13_as_printed_uses_p_x_twice() {
        let plane = ViewPlane::through([0.0; 3], [1.0, 2.0, 3.0]).expect("plane");
        let q = project_paper_literal(&plane, [2.0, 3.0, 4.0]);
        let t = 18.0 / 14.0;
        let want = [2.0 - t, 3.0 - 2.0 * t, 4.0 - 3.0 * t];
        assert!(
            crate::mesh::dist(q, want) < crate::check::tol::ROUNDING,
            "{q:?}"
        );
    }
}
