//! Where a GEC lives: a [`Frame`] (origin and orthonormal in-plane axes)
//! places the papers' plane curve in any plane (paper 000 sec 4.1.3).

use super::GecError;
use crate::jet::Real;
use crate::mesh::{dot, norm, scale, sub};
use crate::surface::cross;

/// Where a GEC lives in space: origin and two orthonormal in-plane axes.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Frame {
    pub origin: [f64; 3],
    pub e1: [f64; 3],
    pub e2: [f64; 3],
}

/// Orthonormality tolerance of [`Frame::new`].
pub const FRAME_TOL: f64 = 1e-9;

impl Frame {
    /// The papers' placement: the plane $z = z_c$ with axes X and Y.
    pub fn z_plane(z_c: f64) -> Frame {
        Frame {
            origin: [0.0, 0.0, z_c],
            e1: [1.0, 0.0, 0.0],
            e2: [0.0, 1.0, 0.0],
        }
    }

    /// A frame from origin and axes (checked finite and orthonormal).
    pub fn new(origin: [f64; 3], e1: [f64; 3], e2: [f64; 3]) -> Result<Frame, GecError> {
        let all = origin.iter().chain(&e1).chain(&e2);
        if !all.clone().all(|x| x.is_finite()) {
            return Err(GecError::InvalidFrame("non-finite component".into()));
        }
        let err = (norm(e1) - 1.0)
            .abs()
            .max((norm(e2) - 1.0).abs())
            .max(dot(e1, e2).abs());
        if err > FRAME_TOL {
            return Err(GecError::InvalidFrame(format!(
                "axes not orthonormal (error {err:.3e})"
            )));
        }
        Ok(Frame { origin, e1, e2 })
    }

    /// A frame in the plane through `origin` with normal `normal`; `e1` is the
    /// projection of `hint` (or of a coordinate axis if `hint` is nearly
    /// parallel to the normal), `e2 = normal x e1`.
    pub fn from_normal(
        origin: [f64; 3],
        normal: [f64; 3],
        hint: [f64; 3],
    ) -> Result<Frame, GecError> {
        let nn = norm(normal);
        if !(nn.is_finite() && nn > 0.0) {
            return Err(GecError::InvalidFrame("zero or non-finite normal".into()));
        }
        let n = scale(normal, 1.0 / nn);
        let candidates = [hint, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]];
        for h in candidates {
            let p = sub(h, scale(n, dot(h, n)));
            let pn = norm(p);
            if pn.is_finite() && pn > 0.3 * norm(h).max(f64::MIN_POSITIVE) {
                let e1 = scale(p, 1.0 / pn);
                let e2 = cross(n, e1);
                return Frame::new(origin, e1, e2);
            }
        }
        Err(GecError::InvalidFrame("no in-plane axis found".into()))
    }

    /// Unit normal `e1 x e2`.
    pub fn normal(&self) -> [f64; 3] {
        cross(self.e1, self.e2)
    }

    /// Space point of in-plane coordinates `(x, y)` (generic).
    pub fn place<T: Real>(&self, x: T, y: T) -> [T; 3] {
        let mut p = [T::cst(0.0); 3];
        for k in 0..3 {
            p[k] = x * self.e1[k] + y * self.e2[k] + self.origin[k];
        }
        p
    }

    /// In-plane coordinates of a space point (orthogonal projection) and its
    /// signed distance from the plane.
    pub fn project(&self, p: [f64; 3]) -> ([f64; 2], f64) {
        let d = sub(p, self.origin);
        ([dot(d, self.e1), dot(d, self.e2)], dot(d, self.normal()))
    }
}
