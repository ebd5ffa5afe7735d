//! One Fourier mode of a 2-sided patch: the ODE
//! $a_1 w'''' - a_2\omega^2 w'' + a_3\omega^4 w = \sum_m p_m \sin m\pi u$
//! solved exactly (particular sines plus the homogeneous basis of
//! [`super`]'s module doc, fixed by four boundary values), or in the printed
//! basis $B_m$ of eq 7 with the printed (eqs 8-9) or residual-minimising
//! coefficients.

use crate::jet::{Jet, Real};
use crate::pde4::{quad, Pde4Error, ShapeParams};
use nalgebra::{DMatrix, DVector, Matrix4, Vector4};
use std::f64::consts::PI;

/// Below this `|sigma|` the homogeneous basis uses its power series.
const SERIES_SIGMA: f64 = 1e-3;

/// Homogeneous part of one mode.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Hom {
    /// `h0 + h1 u + h2 u^2 + h3 u^3`.
    Cubic,
    /// Exponential basis with `A = omega alpha`, `sigma = omega^2 s`.
    Exp { a: f64, sigma: f64 },
}

/// `(e^{-A x} C(x), e^{-A x} S(x))`.
fn ecs<T: Real>(a: f64, sigma: f64, x: T) -> (T, T) {
    if sigma.abs() < SERIES_SIGMA {
        let e = (x * (-a)).exp();
        let x2 = x * x;
        // C = sum sigma^k x^{2k}/(2k)!, S = sum sigma^k x^{2k+1}/(2k+1)!
        let (mut c, mut s) = (T::zero(), T::zero());
        let mut pw = T::one();
        let mut sk = 1.0;
        let mut fact_even = 1.0;
        let mut fact_odd = 1.0;
        for k in 0..9 {
            if k > 0 {
                fact_even *= ((2 * k - 1) * (2 * k)) as f64;
                fact_odd *= ((2 * k) * (2 * k + 1)) as f64;
                pw *= x2;
                sk *= sigma;
            }
            c += pw * (sk / fact_even);
            s += pw * x * (sk / fact_odd);
        }
        (e * c, e * s)
    } else if sigma > 0.0 {
        let g = sigma.sqrt();
        let e1 = (x * (g - a)).exp();
        let e2 = (x * (-(a + g))).exp();
        ((e1 + e2) * 0.5, (e1 - e2) / (2.0 * g))
    } else {
        let b = (-sigma).sqrt();
        let e = (x * (-a)).exp();
        (e * (x * b).cos(), e * (x * b).sin() / b)
    }
}

impl Hom {
    fn basis<T: Real>(&self, u: T) -> [T; 4] {
        match *self {
            Hom::Cubic => [T::one(), u, u * u, u * u * u],
            Hom::Exp { a, sigma } => {
                let (c0, s0) = ecs(a, sigma, u);
                let (c1, s1) = ecs(a, sigma, -u + 1.0);
                [c0, s0, c1, s1]
            }
        }
    }
}

/// One Fourier mode `w(u)`: `sum_m sines[m-1] sin m pi u + sum_j h[j] basis_j(u)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Mode {
    sines: Vec<f64>,
    hom: Hom,
    h: [f64; 4],
}

impl Mode {
    /// `w(u)`.
    pub fn eval<T: Real>(&self, u: T) -> T {
        let mut acc = T::zero();
        for (i, &c) in self.sines.iter().enumerate() {
            if c != 0.0 {
                acc += (u * (PI * (i + 1) as f64)).sin() * c;
            }
        }
        let b = self.hom.basis(u);
        for j in 0..4 {
            acc += b[j] * self.h[j];
        }
        acc
    }

    /// `w(u)` in f64 from a table `sines[m-1] = sin(m pi u)` (fast grids).
    pub fn eval_table(&self, u: f64, sines: &[f64]) -> f64 {
        let mut acc: f64 = self.sines.iter().zip(sines).map(|(c, s)| c * s).sum();
        let b = self.hom.basis(u);
        for j in 0..4 {
            acc += b[j] * self.h[j];
        }
        acc
    }

    /// Exact clamped mode: `a1 w'''' - a2 w^2 w'' + a3 w^4 w = sum f_m sin m pi u`,
    /// `(w(0), w(1), w'(0), w'(1)) = bc`.
    pub fn exact(p: &ShapeParams, omega: f64, f: &[f64], bc: [f64; 4]) -> Result<Mode, Pde4Error> {
        let sines: Vec<f64> = f
            .iter()
            .enumerate()
            .map(|(i, &fm)| fm / p.symbol(PI * (i + 1) as f64, omega))
            .collect();
        let hom = if omega == 0.0 {
            Hom::Cubic
        } else {
            let q = (p.a3 / p.a1).sqrt();
            let alpha2 = 0.25 * (2.0 * q + p.a2 / p.a1);
            Hom::Exp {
                a: omega * alpha2.sqrt(),
                sigma: omega * omega * (alpha2 - q),
            }
        };
        let part = Mode {
            sines,
            hom,
            h: [0.0; 4],
        };
        let d0 = part.eval(Jet::<2, 1>::var_u(0.0)).c[1][0];
        let d1 = part.eval(Jet::<2, 1>::var_u(1.0)).c[1][0];
        let rhs = Vector4::new(bc[0], bc[1], bc[2] - d0, bc[3] - d1);
        let b0 = hom.basis(Jet::<2, 1>::var_u(0.0));
        let b1 = hom.basis(Jet::<2, 1>::var_u(1.0));
        let mut a = Matrix4::zeros();
        for j in 0..4 {
            a[(0, j)] = b0[j].c[0][0];
            a[(1, j)] = b1[j].c[0][0];
            a[(2, j)] = b0[j].c[1][0];
            a[(3, j)] = b1[j].c[1][0];
        }
        let sol = a.lu().solve(&rhs).ok_or_else(|| Pde4Error::Solve {
            system: "boundary system",
            reason: format!("singular for mode omega = {omega}"),
        })?;
        Ok(Mode {
            h: [sol[0], sol[1], sol[2], sol[3]],
            ..part
        })
    }

    /// Printed-basis mode with coefficients `c_m` of `B_m` (eq 7).
    pub fn from_printed_basis(c: &[f64]) -> Mode {
        let mut h = [0.0; 4];
        for (i, &cm) in c.iter().enumerate() {
            let k = cubic_b(i + 1);
            for j in 0..4 {
                h[j] += cm * k[j];
            }
        }
        Mode {
            sines: c.to_vec(),
            hom: Hom::Cubic,
            h,
        }
    }
}

/// Cubic part of eq 7's `B_m` (= eq 13's): `m pi (-u + (2+s) u^2 - (1+s) u^3)`, `s = (-1)^m`.
pub fn cubic_b(m: usize) -> [f64; 4] {
    let s = if m % 2 == 0 { 1.0 } else { -1.0 };
    let k = PI * m as f64;
    [0.0, -k, k * (2.0 + s), -k * (1.0 + s)]
}

/// Eq 7's basis function `B_m(u)`.
pub fn basis_b<T: Real>(m: usize, u: T) -> T {
    let c = cubic_b(m);
    (u * (PI * m as f64)).sin() + u * c[1] + u * u * c[2] + u * u * u * c[3]
}

/// Eq 9 as printed: `f_mn = pi^4 [4 m^2 n^2 (a2 + pi^2 n^2 a3 / 3) - (m^4 a1 + 4 m^2 n^2 a2 + 16 n^4 a3)]`.
pub fn printed_f(p: &ShapeParams, m: usize, n: usize) -> f64 {
    let (m, n) = (m as f64, n as f64);
    PI.powi(4)
        * (4.0 * m * m * n * n * (p.a2 + PI * PI * n * n * p.a3 / 3.0)
            - (m.powi(4) * p.a1 + 4.0 * m * m * n * n * p.a2 + 16.0 * n.powi(4) * p.a3))
}

/// Residual-minimising coefficients of `B_1..B_M` for one mode.
pub fn least_squares(p: &ShapeParams, omega: f64, f: &[f64]) -> Result<Vec<f64>, Pde4Error> {
    let m = f.len();
    let (xs, ws) = quad::composite(0.0, 1.0, m + 4, 10);
    let mut a = DMatrix::zeros(xs.len(), m);
    let mut b = DVector::zeros(xs.len());
    for (q, (&x, &w)) in xs.iter().zip(&ws).enumerate() {
        let sw = w.sqrt();
        for i in 0..m {
            let j = basis_b(i + 1, Jet::<5, 1>::var_u(x));
            let l = p.a1 * j.deriv(4, 0) - p.a2 * omega * omega * j.deriv(2, 0)
                + p.a3 * omega.powi(4) * j.value();
            a[(q, i)] = l * sw;
            b[q] += f[i] * (PI * (i + 1) as f64 * x).sin() * sw;
        }
    }
    let svd = a.svd(true, true);
    let c = svd.solve(&b, 1e-14).map_err(|e| Pde4Error::Solve {
        system: "least squares",
        reason: e.to_string(),
    })?;
    Ok(c.iter().copied().collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Below [`SERIES_SIGMA`] the power series gives the closed forms
    /// `e^{-A x} cosh(g x)`, `e^{-A x} sinh(g x) / g` (sigma = g^2 > 0) and
    /// `e^{-A x} cos(b x)`, `e^{-A x} sin(b x) / b` (sigma = -b^2), to
    /// rounding; the branch the modes of small `omega^2 s` take.
    #[test]
    fn the_series_branch_matches_the_closed_forms() {
        let a = 0.7;
        for sigma in [0.9 * SERIES_SIGMA, 0.3 * SERIES_SIGMA, -0.5 * SERIES_SIGMA] {
            for x in [0.0, 0.25, 0.6, 1.0] {
                let (c, s) = ecs(a, sigma, x);
                let e = (-a * x).exp();
                let (cw, sw) = if sigma > 0.0 {
                    let g = sigma.sqrt();
                    (e * (g * x).cosh(), e * (g * x).sinh() / g)
                } else {
                    let b = (-sigma).sqrt();
                    (e * (b * x).cos(), e * (b * x).sin() / b)
                };
                let tol = 10.0 * crate::check::tol::ROUNDING;
                assert!(
                    (c - cw).abs() <= tol,
                    "C: sigma {sigma}, x {x}: {c} against {cw}"
                );
                assert!(
                    (s - sw).abs() <= tol,
                    "S: sigma {sigma}, x {x}: {s} against {sw}"
                );
            }
        }
    }
}
