//! Shape manipulation in coefficient space (paper 000 sec 5.2, "GEC-driven
//! shape manipulation": change size or shape of the GECs, or apply
//! geometric transformations).
//!
//! Every operation maps coefficients to coefficients and is exact: the
//! transformed curve equals the transformed points at every $\theta$
//! (checked in [`super::check`]).
//!
//! * translate: $\mathbf{o} \mathrel{+}= \mathbf{d}$;
//! * scale per in-plane axis about an in-plane point $\mathbf{c}$:
//!   $x_0 \to c_x + s_x(x_0 - c_x)$, $(a_{xn}, b_{xn}) \to s_x (a_{xn},
//!   b_{xn})$, and the same for $y$ with $s_y$;
//! * rotate in plane by $\varphi$ about $\mathbf{c}$: with the harmonic-$n$
//!   cos and sin parts $C_n = (a_{xn}, b_{yn})$, $S_n = (b_{xn}, a_{yn})$,
//!   $C_n \to R_\varphi C_n$, $S_n \to R_\varphi S_n$ (the (sin, cos)
//!   ordering of $y$ makes this a mixing of $a_{xn}$ with $b_{yn}$ and
//!   $b_{xn}$ with $a_{yn}$);
//! * bend a chain of sections: the classic bend deformer along a direction
//!   $\mathbf{d}$ about an axis $\mathbf{k}$ with curvature $\kappa$; a
//!   section whose centre lies at $s = (\mathbf{c} - \mathbf{p}) \cdot
//!   \mathbf{d}$ is moved rigidly by the deformer's motion at $s$ (rotation
//!   by $\kappa s$ about $\mathbf{k}$): exact for sections perpendicular to
//!   $\mathbf{d}$;
//! * local bump: a displacement $h\, b(\theta)\, \mathbf{u}$ along the
//!   in-plane direction $\mathbf{u} = (\cos\theta_c, \sin\theta_c)$ with the
//!   band-limited profile $b(\theta) = \frac{1 + 2\sum_{n=1}^{J} g_n
//!   \cos n(\theta - \theta_c)}{1 + 2 \sum_{n=1}^{J} g_n}$, $g_n =
//!   e^{-(n\sigma)^2/2}$, so $b(\theta_c) = 1$ and the bump stays inside the
//!   J-term space.

use super::{Frame, Gec, GecError};
use crate::mesh::{add, dot, norm, scale, sub};
use crate::surface::cross;

impl Gec {
    /// Translated by `d` in space.
    pub fn translated(&self, d: [f64; 3]) -> Gec {
        let mut g = self.clone();
        g.frame.origin = add(g.frame.origin, d);
        g
    }

    /// Scaled by `(sx, sy)` along the frame axes about in-plane point `c`.
    pub fn scaled(&self, sx: f64, sy: f64, c: [f64; 2]) -> Gec {
        let mut g = self.clone();
        g.centre = [
            c[0] + sx * (g.centre[0] - c[0]),
            c[1] + sy * (g.centre[1] - c[1]),
        ];
        for p in &mut g.x {
            *p = [sx * p[0], sx * p[1]];
        }
        for p in &mut g.y {
            *p = [sy * p[0], sy * p[1]];
        }
        g
    }

    /// Rotated in its plane by `phi` (counter-clockwise) about in-plane `c`.
    pub fn rotated(&self, phi: f64, c: [f64; 2]) -> Gec {
        let (s, co) = phi.sin_cos();
        let rot = |v: [f64; 2]| [co * v[0] - s * v[1], s * v[0] + co * v[1]];
        let mut g = self.clone();
        let d = rot([g.centre[0] - c[0], g.centre[1] - c[1]]);
        g.centre = [c[0] + d[0], c[1] + d[1]];
        for (px, py) in g.x.iter_mut().zip(g.y.iter_mut()) {
            let cn = rot([px[0], py[1]]);
            let sn = rot([px[1], py[0]]);
            *px = [cn[0], sn[0]];
            *py = [sn[1], cn[1]];
        }
        g
    }

    /// With a local bump of height `h` at angle `theta_c` of width `sigma`
    /// (see the module doc).
    pub fn with_bump(&self, h: f64, theta_c: f64, sigma: f64) -> Result<Gec, GecError> {
        if !(h.is_finite() && theta_c.is_finite() && sigma.is_finite() && sigma > 0.0) {
            return Err(GecError::InvalidParameter(format!(
                "bump needs finite h, theta_c and sigma > 0 (got {h}, {theta_c}, {sigma})"
            )));
        }
        let j = self.terms();
        let g: Vec<f64> = (1..=j)
            .map(|n| (-(n as f64 * sigma).powi(2) / 2.0).exp())
            .collect();
        let norm_b = 1.0 + 2.0 * g.iter().sum::<f64>();
        let u = [theta_c.cos(), theta_c.sin()];
        let mut out = self.clone();
        out.centre[0] += h * u[0] / norm_b;
        out.centre[1] += h * u[1] / norm_b;
        for n in 1..=j {
            let w = h * 2.0 * g[n - 1] / norm_b;
            let (sn, cn) = (n as f64 * theta_c).sin_cos();
            out.x[n - 1][0] += w * u[0] * cn;
            out.x[n - 1][1] += w * u[0] * sn;
            out.y[n - 1][0] += w * u[1] * sn;
            out.y[n - 1][1] += w * u[1] * cn;
        }
        Ok(out)
    }

    /// Moved rigidly: `p -> R (p - pivot) + pivot + t` with the rotation
    /// about unit `axis` by `angle`.
    pub fn rigid(&self, pivot: [f64; 3], axis: [f64; 3], angle: f64, t: [f64; 3]) -> Gec {
        let r = |v: [f64; 3]| rotate(v, axis, angle);
        let f = &self.frame;
        let frame = Frame {
            origin: add(add(r(sub(f.origin, pivot)), pivot), t),
            e1: r(f.e1),
            e2: r(f.e2),
        };
        Gec {
            frame,
            ..self.clone()
        }
    }
}

/// Rodrigues rotation of `v` about unit `axis` by `angle`.
pub fn rotate(v: [f64; 3], axis: [f64; 3], angle: f64) -> [f64; 3] {
    let (s, c) = angle.sin_cos();
    let kxv = cross(axis, v);
    let kdv = dot(axis, v);
    let mut out = [0.0; 3];
    for i in 0..3 {
        out[i] = v[i] * c + kxv[i] * s + axis[i] * kdv * (1.0 - c);
    }
    out
}

/// A bend deformer: points along `direction` from `pivot` bend towards
/// `axis x direction` on a circle of curvature `kappa`.
#[derive(Clone, Copy, Debug)]
pub struct Bend {
    pub pivot: [f64; 3],
    pub direction: [f64; 3],
    pub axis: [f64; 3],
    pub kappa: f64,
}

impl Bend {
    /// Checks the directions (unit, orthogonal) and the curvature.
    pub fn new(
        pivot: [f64; 3],
        direction: [f64; 3],
        axis: [f64; 3],
        kappa: f64,
    ) -> Result<Bend, GecError> {
        let (nd, na) = (norm(direction), norm(axis));
        if !(nd > 0.0 && na > 0.0 && kappa.is_finite() && pivot.iter().all(|v| v.is_finite())) {
            return Err(GecError::InvalidParameter(
                "bend needs finite pivot, non-zero direction and axis, finite curvature".into(),
            ));
        }
        let d = scale(direction, 1.0 / nd);
        let a = sub(scale(axis, 1.0 / na), scale(d, dot(axis, d) / na));
        let an = norm(a);
        if an < 1e-6 {
            return Err(GecError::InvalidParameter(
                "bend axis parallel to the direction".into(),
            ));
        }
        Ok(Bend {
            pivot,
            direction: d,
            axis: scale(a, 1.0 / an),
            kappa,
        })
    }

    /// The rigid motion at arc position `s`: `(angle, translation of the
    /// centre-line point)` so that `p -> rotate(p - c(s)) + c'(s)`.
    fn at(&self, s: f64) -> ([f64; 3], [f64; 3], f64) {
        let m = cross(self.axis, self.direction);
        let phi = self.kappa * s;
        let line = add(self.pivot, scale(self.direction, s));
        let arc = if self.kappa.abs() < 1e-12 {
            line
        } else {
            let r = 1.0 / self.kappa;
            add(
                self.pivot,
                add(
                    scale(self.direction, r * phi.sin()),
                    scale(m, r * (1.0 - phi.cos())),
                ),
            )
        };
        (line, arc, phi)
    }

    /// The deformer applied to a point.
    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        let s = dot(sub(p, self.pivot), self.direction);
        let (line, arc, phi) = self.at(s);
        add(arc, rotate(sub(p, line), self.axis, phi))
    }

    /// The deformer applied to a section (rigidly, at its centre's `s`).
    pub fn apply_gec(&self, g: &Gec) -> Gec {
        let c = g.frame.place(g.centre[0], g.centre[1]);
        let s = dot(sub(c, self.pivot), self.direction);
        let (line, arc, phi) = self.at(s);
        let r = |v: [f64; 3]| rotate(v, self.axis, phi);
        let f = &g.frame;
        Gec {
            frame: Frame {
                origin: add(arc, r(sub(f.origin, line))),
                e1: r(f.e1),
                e2: r(f.e2),
            },
            ..g.clone()
        }
    }

    /// Bends a chain of sections.
    pub fn apply_chain(&self, chain: &[Gec]) -> Vec<Gec> {
        chain.iter().map(|g| self.apply_gec(g)).collect()
    }
}
