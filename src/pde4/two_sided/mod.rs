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

use super::{check_forces, check_terms, Force, Pde4Error, ShapeParams};
use crate::curve::Fourier3;
use crate::jet::Real;
use crate::surface::{Domain, Surface};
use std::f64::consts::PI;

mod mode;
pub use mode::{basis_b, cubic_b, least_squares, printed_f, Mode};

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

#[cfg(test)]
mod tests {
    /// Each component holds `2N + 1` modes (constant, then a cos and a sin
    /// per harmonic), and every index below the count is a mode.
    #[test]
    fn a_component_counts_its_two_n_plus_one_modes() {
        let p = crate::pde4::samples::two_sided().expect("the sample patch solves");
        for c in &p.comps {
            assert_eq!(c.mode_count(), 2 * p.n + 1);
            let _ = c.mode(c.mode_count() - 1);
        }
    }
}
