//! 2-sided deformation patches (paper 000 eqs 4-9; sec 5.1 boundary curves).
//!
//! The patch is clamped at $u = 0, 1$ (eq 5) and closed (period 1) in $v$.
//! With the force series (eq 4), every Fourier mode $e^{i\omega v}$,
//! $\omega = 2n\pi$, of PDE (1) is the constant-coefficient ODE
//! $$a_1 w'''' - a_2\omega^2 w'' + a_3\omega^4 w = \sum_m p_m \sin m\pi u .$$
//!
//! **Exact** ([`Method::Exact`]): particular part
//! $\sum_m p_m \sin m\pi u / (a_1 (m\pi)^4 + a_2 (m\pi)^2\omega^2 + a_3\omega^4)$ plus a
//! homogeneous part fixed by the four clamped (or prescribed) boundary values.
//! For $\omega = 0$ the homogeneous space is the cubics. For $\omega > 0$ the
//! characteristic roots are $\pm\omega\alpha \pm \omega\sqrt{s}$ with
//! $q = \sqrt{a_3/a_1}$, $\alpha^2 = (2q + a_2/a_1)/4 > 0$ (ellipticity) and
//! $s = \alpha^2 - q$ (real distinct roots for $s > 0$, double for $s = 0$,
//! complex for $s < 0$). One basis covers every case continuously:
//! $e^{-A x} C(x),\ e^{-A x} S(x)$ at $x = u$ and $x = 1 - u$, $A = \omega\alpha$,
//! $C = \cosh(\sqrt{\sigma} x)$, $S = \sinh(\sqrt{\sigma}x)/\sqrt{\sigma}$,
//! $\sigma = \omega^2 s$ (entire in $\sigma$: $\cos$/$\sin$ for $\sigma < 0$, a
//! power series near $\sigma = 0$), decaying from each end so nothing overflows.
//!
//! **Paper** ([`Method::Paper`]): the printed basis (eq 7)
//! $B_m(u) = \sin m\pi u + m\pi\{-(u - 3u^2 + 2u^3) + [1-(-1)^m]u^2(u-1)\}$ with the
//! printed coefficients (eqs 8-9). $B_m$ satisfies eq 5 exactly (checked) and
//! eq 8's $c_m$ is exact for the mode $\omega = 0$; for $\omega > 0$ eq 9 is not
//! the residual minimiser. **LeastSquares** ([`Method::LeastSquares`]): the
//! same basis with the coefficients that minimise $\int_0^1 r^2\,du$ per mode.
//!
//! Non-zero boundary curves and tangents (sec 5.1, "not discussed" there):
//! [`Boundary`] gives $t(0,v)$, $t(1,v)$, $t_u(0,v)$, $t_u(1,v)$ as
//! [`Fourier3`] curves in $\theta = 2\pi v$; the exact solver matches them mode by mode.

use super::{check_forces, check_terms, quad, Force, Pde4Error, ShapeParams};
use crate::curve::Fourier3;
use crate::jet::{Jet, Real};
use crate::surface::{Domain, Surface};
use nalgebra::{DMatrix, DVector, Matrix4, Vector4};
use std::f64::consts::PI;

/// How the coefficients are found.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Exact solution of every Fourier mode.
    Exact,
    /// Printed basis (eq 7) and printed coefficients (eqs 8-9).
    Paper,
    /// Printed basis, residual-minimising coefficients.
    LeastSquares,
}

/// Below this `|sigma|` the homogeneous basis uses its power series.
const SERIES_SIGMA: f64 = 1e-3;

/// Boundary curves and u-tangents of a 2-sided patch (sec 5.1), as closed
/// curves in `theta = 2 pi v`.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Boundary {
    pub curve0: Fourier3,
    pub curve1: Fourier3,
    pub tangent0: Fourier3,
    pub tangent1: Fourier3,
}

impl Boundary {
    fn harmonics(&self) -> usize {
        [&self.curve0, &self.curve1, &self.tangent0, &self.tangent1]
            .iter()
            .map(|c| c.harmonics())
            .max()
            .unwrap_or(0)
    }
    fn is_finite(&self) -> bool {
        [&self.curve0, &self.curve1, &self.tangent0, &self.tangent1]
            .iter()
            .all(|c| c.is_finite())
    }
    /// `(t(0), t(1), t_u(0), t_u(1))` of harmonic `n`, component `k`, cos (`false`) or sin part.
    fn values(&self, n: usize, k: usize, sin: bool) -> [f64; 4] {
        let pick = |c: &Fourier3| {
            let (a, b) = c.harmonic(n, k);
            if sin {
                b
            } else {
                a
            }
        };
        [
            pick(&self.curve0),
            pick(&self.curve1),
            pick(&self.tangent0),
            pick(&self.tangent1),
        ]
    }
}

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

/// One component: modes `[0, cos 1, sin 1, cos 2, sin 2, ...]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Component {
    pub params: ShapeParams,
    modes: Vec<Mode>,
}

impl Component {
    /// Mode of index `j` (0: constant, `2n-1`: cos, `2n`: sin).
    pub fn mode(&self, j: usize) -> &Mode {
        &self.modes[j]
    }
    /// Number of modes `2N + 1`.
    pub fn mode_count(&self) -> usize {
        self.modes.len()
    }
    /// `t(u, v)`.
    pub fn eval<T: Real>(&self, u: T, v: T) -> T {
        let mut acc = self.modes[0].eval(u);
        for n in 1..=(self.modes.len() - 1) / 2 {
            let th = v * (2.0 * PI * n as f64);
            acc += self.modes[2 * n - 1].eval(u) * th.cos() + self.modes[2 * n].eval(u) * th.sin();
        }
        acc
    }
}

/// A 2-sided deformation (three components), a [`Surface`] closed in v
/// giving the displacement `(x, y, z)(u, v)`.
#[derive(Clone, Debug, PartialEq)]
pub struct TwoSided {
    pub m: usize,
    pub n: usize,
    pub method: Method,
    pub comps: [Component; 3],
    /// Eq 4 coefficients of the summed forces per component:
    /// `series[k][j][m-1]`, `j` the mode index as in [`Component::mode`].
    pub series: [Vec<Vec<f64>>; 3],
}

impl TwoSided {
    /// Solves the patch. `params[k]` are the shape parameters of component k.
    pub fn new(
        params: [ShapeParams; 3],
        forces: &[Force],
        m: usize,
        n: usize,
        method: Method,
        boundary: Option<&Boundary>,
    ) -> Result<Self, Pde4Error> {
        check_terms(m, n, 0)?;
        params.iter().try_for_each(ShapeParams::validate)?;
        if boundary.is_none() || !forces.is_empty() {
            check_forces(forces)?;
        }
        if let Some(b) = boundary {
            if method != Method::Exact {
                return Err(Pde4Error::Unsupported(
                    "non-zero boundary curves need method 'exact' (eqs 7-9 assume clamped zero boundaries)",
                ));
            }
            if !b.is_finite() {
                return Err(Pde4Error::NonFinite {
                    what: "boundary curve",
                    value: f64::NAN,
                });
            }
            if b.harmonics() > n {
                return Err(Pde4Error::BoundaryHarmonics {
                    got: b.harmonics(),
                    n,
                });
            }
        }
        let series: [Vec<Vec<f64>>; 3] = std::array::from_fn(|k| {
            let mut s = vec![vec![0.0; m]; 2 * n + 1];
            for f in forces {
                for mi in 1..=m {
                    let um = f.u_sine(mi) * f.p[k];
                    s[0][mi - 1] += um * f.v_fourier(0).0;
                    for ni in 1..=n {
                        let (c, si) = f.v_fourier(ni);
                        s[2 * ni - 1][mi - 1] += um * c;
                        s[2 * ni][mi - 1] += um * si;
                    }
                }
            }
            s
        });
        let mut comps = Vec::with_capacity(3);
        for k in 0..3 {
            let p = &params[k];
            let mut modes = Vec::with_capacity(2 * n + 1);
            for j in 0..=2 * n {
                let nn = j.div_ceil(2);
                let omega = 2.0 * PI * nn as f64;
                let f = &series[k][j];
                let mode = match method {
                    Method::Exact => {
                        let bc =
                            boundary.map_or([0.0; 4], |b| b.values(nn, k, j > 0 && j % 2 == 0));
                        Mode::exact(p, omega, f, bc)?
                    }
                    Method::Paper => {
                        let c: Vec<f64> = (1..=m)
                            .map(|mi| {
                                if nn == 0 {
                                    f[mi - 1] / (PI.powi(4) * (mi as f64).powi(4) * p.a1)
                                } else {
                                    -f[mi - 1] / printed_f(p, mi, nn)
                                }
                            })
                            .collect();
                        Mode::from_printed_basis(&c)
                    }
                    Method::LeastSquares => Mode::from_printed_basis(&least_squares(p, omega, f)?),
                };
                modes.push(mode);
            }
            comps.push(Component { params: *p, modes });
        }
        let comps: [Component; 3] = comps.try_into().map_err(|_| Pde4Error::Solve {
            system: "boundary components",
            reason: "not three components".into(),
        })?;
        Ok(TwoSided {
            m,
            n,
            method,
            comps,
            series,
        })
    }

    /// Eq 4 partial sum of the force of component `k` at `(u, v)`.
    pub fn force_series(&self, k: usize, u: f64, v: f64) -> f64 {
        let s = &self.series[k];
        let mut acc = 0.0;
        for (mi, &c) in s[0].iter().enumerate() {
            let su = (PI * (mi + 1) as f64 * u).sin();
            acc += su * c;
            for ni in 1..=self.n {
                let th = 2.0 * PI * ni as f64 * v;
                acc += su * (s[2 * ni - 1][mi] * th.cos() + s[2 * ni][mi] * th.sin());
            }
        }
        acc
    }

    /// Direct double sum at every grid point (the baseline of the fast [`Surface::grid`]).
    pub fn grid_naive(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let mut out = Vec::with_capacity(us.len() * vs.len());
        for &u in us {
            for &v in vs {
                out.push([
                    self.comps[0].eval(u, v),
                    self.comps[1].eval(u, v),
                    self.comps[2].eval(u, v),
                ]);
            }
        }
        out
    }
}

impl Surface for TwoSided {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        [
            self.comps[0].eval(u, v),
            self.comps[1].eval(u, v),
            self.comps[2].eval(u, v),
        ]
    }
    fn domain(&self) -> Domain {
        Domain {
            closed_v: true,
            ..Domain::UNIT
        }
    }
    /// Separable evaluation: every mode once per `u`, every harmonic once per `v`.
    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let nm = 2 * self.n + 1;
        let mut trig = vec![0.0; vs.len() * nm];
        for (iv, &v) in vs.iter().enumerate() {
            trig[iv * nm] = 1.0;
            for ni in 1..=self.n {
                let th = 2.0 * PI * ni as f64 * v;
                trig[iv * nm + 2 * ni - 1] = th.cos();
                trig[iv * nm + 2 * ni] = th.sin();
            }
        }
        let mut out = vec![[0.0; 3]; us.len() * vs.len()];
        let mut w = vec![0.0; nm];
        let mut sines = vec![0.0; self.m];
        for (iu, &u) in us.iter().enumerate() {
            for (i, s) in sines.iter_mut().enumerate() {
                *s = (PI * (i + 1) as f64 * u).sin();
            }
            for k in 0..3 {
                for j in 0..nm {
                    w[j] = self.comps[k].modes[j].eval_table(u, &sines);
                }
                for iv in 0..vs.len() {
                    let t = &trig[iv * nm..(iv + 1) * nm];
                    out[iu * vs.len() + iv][k] = w.iter().zip(t).map(|(a, b)| a * b).sum();
                }
            }
        }
        out
    }
}
