//! 4-sided deformation patches (paper 000 eqs 10-15).
//!
//! All four edges clamped (eqs 5, 10). The printed solution (eq 13) is
//! $$t(u,v) = \sum_{m,n} d_{mn}\,B_m(u)\,\psi_n(v),\qquad
//!   \psi_n(v) = v(1-v)\sin n\pi v,$$
//! with $B_m$ the clamped basis of eq 7 (eq 13's cubic is the same
//! polynomial, checked in `verify/pde4_derive.py`) and the printed
//! coefficients (eqs 14-15) $d_{mn} = n^2 p_{mn} / (m\pi^2\bar d_{mn})$,
//! $\bar d_{mn} = 2m^3a_1 + 6n^4(-m\pi^2/12 + 1/m)a_3$ — no $a_2$, no coupling.
//!
//! The Ritz-Galerkin solution ([`Method::Galerkin`]) uses the same basis with
//! all modes coupled: with the energy form
//! $a(w,\phi) = \int\!\!\int a_1 w_{uu}\phi_{uu} + a_2 w_{uv}\phi_{uv} + a_3 w_{vv}\phi_{vv}$
//! (equal to $\int\!\!\int L[w]\phi$ for clamped functions) the stiffness matrix is
//! $K = a_1 A^u_2\otimes A^v_0 + a_2 A^u_1\otimes A^v_1 + a_3 A^u_0\otimes A^v_2$,
//! $A_k^{ij} = \int \phi_i^{(k)}\phi_j^{(k)}$ (Gauss-Legendre), and the load
//! $F_{mn} = \int\!\!\int P\,B_m\psi_n$ is taken from the force itself (point
//! values for the delta parts). $K$ is symmetric positive definite for an
//! elliptic operator; it is solved densely (Cholesky).

use super::two_sided::basis_b;
use super::{check_forces, check_terms, quad, Force, ForceKind, Pde4Error, ShapeParams};
use crate::jet::{Jet, Real};
use crate::surface::{Domain, Surface};
use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// How the coefficients `d_mn` are found.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Printed eqs 14-15 with the exact eq 11 force coefficients.
    Paper,
    /// Coupled Ritz-Galerkin in the eq 13 basis.
    Galerkin,
}

/// Gauss-Legendre points per panel.
const QUAD_ORDER: usize = 10;

/// `psi_n(v) = v (1 - v) sin n pi v` (eq 13).
pub fn basis_psi<T: Real>(n: usize, v: T) -> T {
    v * (-v + 1.0) * (v * (PI * n as f64)).sin()
}

/// A 4-sided deformation: the displacement `sum d_mn B_m(u) psi_n(v)` per component.
#[derive(Clone, Debug, PartialEq)]
pub struct FourSided {
    pub m: usize,
    pub n: usize,
    pub method: Method,
    pub params: [ShapeParams; 3],
    /// `d[k][(m-1) * N + (n-1)]`.
    pub d: [Vec<f64>; 3],
}

/// `A_k[i][j] = int phi_i^(k) phi_j^(k)` for k = 0, 1, 2.
fn gram(count: usize, f: impl Fn(usize, Jet<3, 1>) -> Jet<3, 1>) -> [DMatrix<f64>; 3] {
    let (xs, ws) = quad::composite(0.0, 1.0, count + 4, QUAD_ORDER);
    let mut vals = vec![[0.0; 3]; xs.len() * count];
    for (q, &x) in xs.iter().enumerate() {
        for i in 0..count {
            let j = f(i + 1, Jet::<3, 1>::var_u(x));
            vals[q * count + i] = [j.deriv(0, 0), j.deriv(1, 0), j.deriv(2, 0)];
        }
    }
    std::array::from_fn(|k| {
        let mut a = DMatrix::zeros(count, count);
        for (q, &w) in ws.iter().enumerate() {
            let row = &vals[q * count..(q + 1) * count];
            for i in 0..count {
                for j in 0..count {
                    a[(i, j)] += w * row[i][k] * row[j][k];
                }
            }
        }
        a
    })
}

/// `int_lo^hi prof(x) phi_i(x) dx` for `i = 1..=count`.
fn load(
    count: usize,
    lo: f64,
    hi: f64,
    prof: impl Fn(f64) -> f64,
    phi: impl Fn(usize, f64) -> f64,
) -> Vec<f64> {
    let (xs, ws) = quad::composite(lo, hi, count + 4, QUAD_ORDER);
    (1..=count)
        .map(|i| {
            xs.iter()
                .zip(&ws)
                .map(|(&x, &w)| w * prof(x) * phi(i, x))
                .sum()
        })
        .collect()
}

fn bump(a: f64, b: f64) -> impl Fn(f64) -> f64 {
    move |x| super::force::bump(a, b, x)
}

/// `(int f B_m du, int g psi_n dv)` of one force (unit magnitude).
pub fn load_vectors(f: &Force, m: usize, n: usize) -> (Vec<f64>, Vec<f64>) {
    let pb = |i: usize, x: f64| basis_b(i, x);
    let pp = |i: usize, x: f64| basis_psi(i, x);
    let point = |count: usize, x: f64, phi: &dyn Fn(usize, f64) -> f64| {
        (1..=count).map(|i| phi(i, x)).collect::<Vec<_>>()
    };
    match f.kind {
        ForceKind::Concentrated { u0, v0 } => (point(m, u0, &pb), point(n, v0, &pp)),
        ForceKind::Line { u0, u1, v0 } => (load(m, u0, u1, bump(u0, u1), pb), point(n, v0, &pp)),
        ForceKind::Area { u0, u1, v0, v1 } => (
            load(m, u0, u1, bump(u0, u1), pb),
            load(n, v0, v1, bump(v0, v1), pp),
        ),
        ForceKind::Uniform => (
            load(m, 0.0, 1.0, |_| 1.0, pb),
            load(n, 0.0, 1.0, |_| 1.0, pp),
        ),
    }
}

/// Eq 15 as printed: `dbar_mn = 2 m^3 a1 + 6 n^4 (-m pi^2 / 12 + 1/m) a3`.
pub fn printed_dbar(p: &ShapeParams, m: usize, n: usize) -> f64 {
    let (m, n) = (m as f64, n as f64);
    2.0 * m.powi(3) * p.a1 + 6.0 * n.powi(4) * (-m * PI * PI / 12.0 + 1.0 / m) * p.a3
}

impl FourSided {
    /// Solves the patch with `M x N` terms.
    pub fn new(
        params: [ShapeParams; 3],
        forces: &[Force],
        m: usize,
        n: usize,
        method: Method,
    ) -> Result<Self, Pde4Error> {
        check_terms(m, n, 1)?;
        if method == Method::Galerkin {
            super::check_galerkin_cost(m, n)?;
        }
        params.iter().try_for_each(ShapeParams::validate)?;
        check_forces(forces)?;
        let d = match method {
            Method::Paper => std::array::from_fn(|k| {
                let p = &params[k];
                let mut d = vec![0.0; m * n];
                for mi in 1..=m {
                    for ni in 1..=n {
                        let pmn: f64 = forces.iter().map(|f| f.p[k] * f.four_sided(mi, ni)).sum();
                        d[(mi - 1) * n + ni - 1] = (ni * ni) as f64 * pmn
                            / (mi as f64 * PI * PI * printed_dbar(p, mi, ni));
                    }
                }
                d
            }),
            Method::Galerkin => {
                let au = gram(m, basis_b);
                let av = gram(n, basis_psi);
                let loads: Vec<(Vec<f64>, Vec<f64>)> =
                    forces.iter().map(|f| load_vectors(f, m, n)).collect();
                let mut out: Vec<Vec<f64>> = Vec::with_capacity(3);
                // factorisations reused between components with equal parameters
                let mut factors: Vec<(ShapeParams, nalgebra::Cholesky<f64, nalgebra::Dyn>)> =
                    Vec::new();
                for k in 0..3 {
                    let p = &params[k];
                    let mut rhs = DVector::zeros(m * n);
                    for (f, (lu, lv)) in forces.iter().zip(&loads) {
                        if f.p[k] == 0.0 {
                            continue;
                        }
                        for i in 0..m {
                            for j in 0..n {
                                rhs[i * n + j] += f.p[k] * lu[i] * lv[j];
                            }
                        }
                    }
                    if rhs.iter().all(|x| *x == 0.0) {
                        out.push(vec![0.0; m * n]);
                        continue;
                    }
                    if !factors.iter().any(|(q, _)| q == p) {
                        let mut kmat = DMatrix::zeros(m * n, m * n);
                        for i in 0..m {
                            for j in 0..n {
                                for a in 0..m {
                                    for b in 0..n {
                                        kmat[(i * n + j, a * n + b)] =
                                            p.a1 * au[2][(i, a)] * av[0][(j, b)]
                                                + p.a2 * au[1][(i, a)] * av[1][(j, b)]
                                                + p.a3 * au[0][(i, a)] * av[2][(j, b)];
                                    }
                                }
                            }
                        }
                        let chol = kmat.cholesky().ok_or_else(|| Pde4Error::Solve {
                            system: "Galerkin stiffness matrix",
                            reason: format!("not positive definite (M = {m}, N = {n})"),
                        })?;
                        factors.push((*p, chol));
                    }
                    let chol = factors
                        .iter()
                        .find(|(q, _)| q == p)
                        .map(|(_, c)| c)
                        .ok_or_else(|| Pde4Error::Solve {
                            system: "Galerkin stiffness matrix",
                            reason: "missing factorisation".into(),
                        })?;
                    out.push(chol.solve(&rhs).iter().copied().collect());
                }
                let mut it = out.into_iter();
                std::array::from_fn(|_| it.next().unwrap_or_default())
            }
        };
        Ok(FourSided {
            m,
            n,
            method,
            params,
            d,
        })
    }

    /// Component `k` at `(u, v)`.
    pub fn component<T: Real>(&self, k: usize, u: T, v: T) -> T {
        let bu: Vec<T> = (1..=self.m).map(|i| basis_b(i, u)).collect();
        let mut acc = T::zero();
        for nj in 1..=self.n {
            let pv = basis_psi(nj, v);
            let mut s = T::zero();
            for (mi, b) in bu.iter().enumerate() {
                let c = self.d[k][mi * self.n + nj - 1];
                if c != 0.0 {
                    s += *b * c;
                }
            }
            acc += s * pv;
        }
        acc
    }

    /// Direct double sum at every grid point (baseline of [`Surface::grid`]).
    pub fn grid_naive(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let mut out = Vec::with_capacity(us.len() * vs.len());
        for &u in us {
            for &v in vs {
                out.push(Surface::eval(self, u, v));
            }
        }
        out
    }
}

impl Surface for FourSided {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        [
            self.component(0, u, v),
            self.component(1, u, v),
            self.component(2, u, v),
        ]
    }
    fn domain(&self) -> Domain {
        Domain::UNIT
    }
    /// Separable evaluation `Phi D Psi^T`.
    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let (m, n) = (self.m, self.n);
        let phi: Vec<f64> = us
            .iter()
            .flat_map(|&u| (1..=m).map(move |i| basis_b(i, u)))
            .collect();
        let psi: Vec<f64> = vs
            .iter()
            .flat_map(|&v| (1..=n).map(move |j| basis_psi(j, v)))
            .collect();
        let mut out = vec![[0.0; 3]; us.len() * vs.len()];
        let mut row = vec![0.0; n];
        for iu in 0..us.len() {
            let ph = &phi[iu * m..(iu + 1) * m];
            for k in 0..3 {
                row.iter_mut().for_each(|r| *r = 0.0);
                for (i, &p) in ph.iter().enumerate() {
                    let drow = &self.d[k][i * n..(i + 1) * n];
                    for j in 0..n {
                        row[j] += p * drow[j];
                    }
                }
                for iv in 0..vs.len() {
                    let ps = &psi[iv * n..(iv + 1) * n];
                    out[iu * vs.len() + iv][k] = row.iter().zip(ps).map(|(a, b)| a * b).sum();
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Gram matrices' quadrature is converged: against four times as
    /// many panels, every entry of `A_0`, `A_1`, `A_2` agrees to
    /// `tol::SOLVE` of the largest, for 6 modes (the fewest panels) and 16
    /// (the plate tables' count). With `count - 4` panels instead of
    /// `count + 4` (a mutant that the plate tables' 4 digits did not see:
    /// docs/verification.md, pde4 5/69) 6 modes get 2 panels.
    #[test]
    fn the_gram_quadrature_is_converged() {
        for count in [6, 16] {
            let got = gram(count, basis_psi);
            let (xs, ws) = quad::composite(0.0, 1.0, 4 * (count + 4), QUAD_ORDER);
            for (k, a) in got.iter().enumerate() {
                let mut want = DMatrix::<f64>::zeros(count, count);
                for (&x, &w) in xs.iter().zip(&ws) {
                    let d: Vec<f64> = (0..count)
                        .map(|i| basis_psi(i + 1, Jet::<3, 1>::var_u(x)).deriv(k, 0))
                        .collect();
                    for i in 0..count {
                        for j in 0..count {
                            want[(i, j)] += w * d[i] * d[j];
                        }
                    }
                }
                let err = (a - &want).amax() / want.amax();
                assert!(
                    err < crate::check::tol::SOLVE,
                    "{count} modes, A_{k}: {err:e}"
                );
            }
        }
    }
}
