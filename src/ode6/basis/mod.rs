//! The complementary solution of eq 8 for every case of the shape
//! parameters, as the six basis functions $g_1..g_6$ of eq 19.
//!
//! The solution space of $\rho S^{(6)} + \eta S^{(4)} + \lambda S'' = 0$ is
//! spanned by $\{1, u\}$ and four functions built from the roots $q_{1,2}$ of
//! $\rho q^2 + \eta q + \lambda = 0$ ($q = r^2$). Each case gets a basis
//! $y_1..y_6$ that stays well conditioned as the case boundaries are approached
//! (repeated roots, a root tending to zero):
//!
//! | case | when | $y_3..y_6$ |
//! |---|---|---|
//! | `Series` | $\max\lvert q\rvert \le 4$ | Taylor series of the fundamental solutions at $u=0$ (all roots small: repeated, complex, $\lambda=0$, $\eta=\lambda=0$ alike) |
//! | `Separated` | real roots, $\lvert q_1-q_2\rvert \ge \max\lvert q\rvert/2$ | per root: $(\cos\omega u, \sin\omega u)$ ($q<-1$), $(e^{-\omega u}, e^{-\omega(1-u)})$ ($q>1$), $(F_2, F_3)$ series ($\lvert q\rvert\le1$) with $F_2 = \sum q^k u^{2k+2}/(2k+2)!$, $F_3 = \sum q^k u^{2k+3}/(2k+3)!$ |
//! | `CloseOscillatory` | real $q<0$ close (repeated: $\tau=0$) | $\cos\sigma u\,\{\cos\tau u, \sin\tau u/\tau\}$, $\sin\sigma u\,\{\ldots\}$ with $\sigma,\tau = (\omega_1\pm\omega_2)/2$ |
//! | `CloseGrowing` | real $q>0$ close | $e^{-\sigma u}\{\cosh\tau u, \sinh\tau u/\tau\}$ and the mirror in $1-u$ |
//! | `Complex` | $\eta^2 < 4\rho\lambda$, $r = \pm\alpha\pm i\beta$ | $\{\cosh\alpha u, \sinh\alpha u/\alpha\}\times\{\cos\beta u, \sin\beta u/\beta\}$ ($\alpha\le1$), else $e^{-\alpha u}\{\cos\beta u, \sin\beta u/\beta\}$ and the mirror |
//!
//! With the $6\times6$ matrix $M_{ik}$ of the boundary values (rows
//! $y_k(0), y_k'(0), y_k''(0), y_k(1), y_k'(1), y_k''(1)$) the basis functions
//! of eq 19 are $g_j(u) = \sum_k (M^{-1})_{kj} y_k(u)$, so that
//! $g_j^{(i)}(0)$ and $g_j^{(i)}(1)$ are the unit constraints. A singular $M$
//! (oscillatory roots at a "buckling" combination) is reported with its case.
//!
//! $\rho = 0$ makes the equation fourth order: four constants cannot meet
//! six constraints. [`Basis::new`] refuses it; [`Basis::reduced`] imposes the
//! positions and tangents $c_1, c_2, c_4, c_5$ only ($g_3 = g_6 = 0$), which
//! is the limit $\rho \to 0^+$ for $\eta > 0$: the curvature constraints are
//! then carried by an oscillation of wavelength $\sim\sqrt{\rho/\eta}$ whose
//! effect on the positions vanishes like $\sqrt{\rho/\eta}$ (non-uniformly:
//! larger near the singular frequencies; check `ode6.rho_to_zero_limit`).
//!
//! **Documented range** (swept by the property tests in `tests/it/ode6.rs`):
//! each of $\rho, \eta, \lambda$ is $0$ or $\pm 10^e$, $e \in [-3, 3]$, any
//! signs. There [`Basis::new`] returns a basis meeting eq 1 (to `1e-9`
//! scaled by the coefficient magnitude) and eq 8 (relative residual
//! `1e-9`), never NaN, or a named error ([`Ode6Error::RhoZero`],
//! [`Ode6Error::AllZero`], [`Ode6Error::Singular`] naming the root case).
//! Grids of patches with $\rho \in [10^{-2}, 10]$, $\eta \in [-30, 30]$,
//! $\lambda \in [-60, 60]$ per column are C2 across every join (relative
//! jumps below `1e-7`).

use super::Ode6Error;
use crate::check::{Measure, Worst};
use crate::jet::{Jet, Real};
use nalgebra::{DMatrix, SMatrix};

mod case_basis;
mod roots;
pub use roots::{classify, classify_closed, Params, RootCase};

/// Largest root magnitude handled by the Taylor series.
pub const Q_SERIES: f64 = 4.0;
/// Real roots closer than this fraction of the larger one use the
/// repeated-root-stable product form.
pub const SEPARATION: f64 = 0.5;
/// Smallest accepted reciprocal condition number of the column-equilibrated
/// boundary matrix.
pub const RCOND_MIN: f64 = 1e-11;
/// Largest relative residual accepted by [`Basis::with_case`].
pub const CASE_RESIDUAL_MAX: f64 = 1e-8;

/// The six basis functions `g_1..g_6` of eq 19 for one parameter set.
#[derive(Clone, Debug)]
pub struct Basis {
    pub params: Params,
    pub case: RootCase,
    /// 6 (eq 8), 4 (`rho = 0`) or 2 (`rho = eta = 0`).
    pub order: usize,
    /// `g_j(u) = sum_k coef[j][k] y_k(u)`.
    coef: [[f64; 6]; 6],
    /// Reciprocal condition number of the equilibrated boundary matrix.
    pub rcond: f64,
}

impl Basis {
    /// The basis for `rho != 0` (every sign and root case).
    pub fn new(params: Params) -> Result<Basis, Ode6Error> {
        params.validate()?;
        if params.rho == 0.0 {
            return Err(Ode6Error::RhoZero {
                eta: params.eta,
                lambda: params.lambda,
            });
        }
        let case = classify(&params);
        Basis::build(params, case, 6)
    }

    /// The same basis with the case forced (cross-checks between the series
    /// and the closed forms).
    /// A case that does not belong to `params` is refused (its functions
    /// would not solve eq 8).
    pub fn with_case(params: Params, case: RootCase) -> Result<Basis, Ode6Error> {
        params.validate()?;
        let b = Basis::build(params, case, 6)?;
        let res = b.residual_error(4);
        if res.is_finite() && res <= CASE_RESIDUAL_MAX {
            Ok(b)
        } else {
            Err(Ode6Error::WrongCase {
                case: b.case.name(),
                rho: params.rho,
                eta: params.eta,
                lambda: params.lambda,
                residual: res,
            })
        }
    }

    /// `rho = 0`: the fourth-order (or, with `eta = 0`, second-order)
    /// problem, imposing positions and tangents only (`g_3 = g_6 = 0`;
    /// with `eta = 0` also `g_2 = g_5 = 0`).
    pub fn reduced(params: Params) -> Result<Basis, Ode6Error> {
        params.validate()?;
        if params.rho != 0.0 {
            return Err(Ode6Error::ReducedNeedsRhoZero { rho: params.rho });
        }
        if params.eta == 0.0 {
            Basis::build(params, RootCase::SecondOrder, 2)
        } else {
            let q = -params.lambda / params.eta;
            Basis::build(params, RootCase::FourthOrder { q }, 4)
        }
    }

    fn build(params: Params, case: RootCase, order: usize) -> Result<Basis, Ode6Error> {
        let mut b = Basis {
            params,
            case,
            order,
            coef: [[0.0; 6]; 6],
            rcond: 0.0,
        };
        // Rows: the derivative orders imposed at each end.
        let per_end = order / 2;
        let n = order;
        let y0 = b.y(Jet::<3, 1>::var_u(0.0));
        let y1 = b.y(Jet::<3, 1>::var_u(1.0));
        let mut m = DMatrix::<f64>::zeros(n, n);
        for k in 0..n {
            for i in 0..per_end {
                m[(i, k)] = y0[k].deriv(i, 0);
                m[(per_end + i, k)] = y1[k].deriv(i, 0);
            }
        }
        // Equilibrate columns.
        let mut colscale = vec![1.0; n];
        for k in 0..n {
            let s = (0..n).map(|i| m[(i, k)].abs()).fold(0.0, f64::max);
            if !(s.is_finite() && s > 0.0) {
                return Err(b.singular(0.0));
            }
            colscale[k] = 1.0 / s;
            for i in 0..n {
                m[(i, k)] /= s;
            }
        }
        let norm1 = |a: &DMatrix<f64>| {
            (0..a.ncols())
                .map(|k| a.column(k).iter().map(|x| x.abs()).sum::<f64>())
                .fold(0.0, f64::max)
        };
        let inv = match m.clone().lu().try_inverse() {
            Some(inv) => inv,
            None => return Err(b.singular(0.0)),
        };
        let rcond = 1.0 / (norm1(&m) * norm1(&inv));
        b.rcond = rcond;
        if !(rcond.is_finite() && rcond >= RCOND_MIN) {
            return Err(b.singular(if rcond.is_finite() { rcond } else { 0.0 }));
        }
        // Constraint index j (0..6 in eq 1 numbering) for row r.
        let constraint = |r: usize| if r < per_end { r } else { 3 + r - per_end };
        for r in 0..n {
            let j = constraint(r);
            for k in 0..n {
                b.coef[j][k] = inv[(k, r)] * colscale[k];
            }
        }
        Ok(b)
    }

    fn singular(&self, rcond: f64) -> Ode6Error {
        Ode6Error::Singular {
            case: self.case.name(),
            rcond,
            rho: self.params.rho,
            eta: self.params.eta,
            lambda: self.params.lambda,
        }
    }

    /// The case basis `y_1..y_6` (unused entries zero for reduced orders).
    pub fn y<T: Real>(&self, u: T) -> [T; 6] {
        case_basis::case_basis(&self.case, u)
    }

    /// The basis functions `g_1..g_6` of eq 19 at `u` (generic: jets give
    /// their exact derivatives).
    pub fn g<T: Real>(&self, u: T) -> [T; 6] {
        let y = self.y(u);
        let mut g = [T::zero(); 6];
        for j in 0..6 {
            let mut acc = T::zero();
            for k in 0..self.order {
                acc += y[k] * self.coef[j][k];
            }
            g[j] = acc;
        }
        g
    }

    /// One scalar iso-parametric line: `sum_j g_j(u) c_j`.
    pub fn line<T: Real>(&self, u: T, c: &[f64; 6]) -> T {
        let g = self.g(u);
        let mut acc = T::zero();
        for j in 0..6 {
            acc += g[j] * c[j];
        }
        acc
    }

    /// The residual terms `(rho g^(6), eta g^(4), lambda g'')` of basis
    /// function `j` at `u` (jets).
    pub fn residual_terms(&self, j: usize, u: f64) -> [f64; 3] {
        let g = self.g(Jet::<7, 1>::var_u(u))[j];
        let Params { rho, eta, lambda } = self.params;
        [
            rho * g.deriv(6, 0),
            eta * g.deriv(4, 0),
            lambda * g.deriv(2, 0),
        ]
    }
}

/// The baseline the paper's closed form replaces: solve the 6x6 boundary
/// system for the constants of one iso-parametric line (one scalar
/// component) from scratch and evaluate it at `us`.
pub fn solve_line(params: Params, c: &[f64; 6], us: &[f64]) -> Result<Vec<f64>, Ode6Error> {
    params.validate()?;
    let case = classify(&params);
    let b = Basis {
        params,
        case,
        order: 6,
        coef: [[0.0; 6]; 6],
        rcond: 0.0,
    };
    let y0 = b.y(Jet::<3, 1>::var_u(0.0));
    let y1 = b.y(Jet::<3, 1>::var_u(1.0));
    let mut m = SMatrix::<f64, 6, 6>::zeros();
    for k in 0..6 {
        for i in 0..3 {
            m[(i, k)] = y0[k].deriv(i, 0);
            m[(3 + i, k)] = y1[k].deriv(i, 0);
        }
    }
    let rhs = nalgebra::Vector6::from_column_slice(c);
    let x = m.lu().solve(&rhs).ok_or_else(|| b.singular(0.0))?;
    Ok(us
        .iter()
        .map(|&u| {
            let y = b.y(u);
            (0..6).map(|k| x[k] * y[k]).sum()
        })
        .collect())
}

impl Basis {
    /// Largest error of `g_j^{(i)}` at `u = 0, 1` against the unit
    /// constraints (exact derivatives from jets), over the imposed ones.
    pub fn boundary_error(&self) -> f64 {
        let per_end = self.order / 2;
        let mut err = 0.0f64;
        for (end, u) in [(0usize, 0.0), (1, 1.0)] {
            let g = self.g(Jet::<3, 1>::var_u(u));
            for j in 0..6 {
                let imposed = j % 3 < per_end;
                if !imposed {
                    continue;
                }
                for i in 0..per_end {
                    let target = if 3 * end + i == j { 1.0 } else { 0.0 };
                    err = err.worst((g[j].deriv(i, 0) - target).abs());
                }
            }
        }
        err
    }

    /// Largest residual of eq 8 over the six basis functions at `n + 1`
    /// equally spaced `u`, relative to the largest of its three terms over
    /// those `u`.
    pub fn residual_error(&self, n: usize) -> f64 {
        let mut err = 0.0f64;
        for j in 0..6 {
            let terms: Vec<[f64; 3]> = (0..=n)
                .map(|i| self.residual_terms(j, i as f64 / n as f64))
                .collect();
            let scale = terms.iter().flatten().copied().max_abs();
            if scale == 0.0 {
                continue;
            }
            for t in &terms {
                err = err.worst((t[0] + t[1] + t[2]).abs() / scale);
            }
        }
        err
    }

    /// Largest `|coef|`: the amplification of rounding by the basis change.
    pub fn coef_magnitude(&self) -> f64 {
        self.coef.iter().flatten().fold(0.0, |a, b| a.max(b.abs()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `rcond` against the test's own condition number: the two inverses
    /// (LU here and there) agree to far better than this.
    const RCOND_REL: f64 = 1e-9;
    /// A coefficient moved by this ...
    const NUDGE: f64 = 1e-3;
    /// ... moves the boundary values by at least this (y_k and their
    /// derivatives at the ends are of order one after equilibration).
    const SEEN: f64 = 1e-6;

    /// Forcing a root case that does not belong to the parameters is
    /// refused (its functions would not solve eq 8).
    #[test]
    fn a_case_forced_on_other_parameters_is_refused() {
        let p = Params::new(1.0, 3.0, 1.0);
        let r = Basis::with_case(
            p,
            RootCase::Complex {
                alpha: 0.5,
                beta: 2.0,
            },
        );
        assert!(matches!(r, Err(Ode6Error::WrongCase { .. })), "{r:?}");
    }

    /// `rcond` is the reciprocal 1-norm condition number of the boundary
    /// matrix (rows: `y_k^{(i)}` at u = 0 and 1) with its columns scaled to
    /// a largest entry of 1, computed here from the case basis with
    /// nalgebra's own inverse and norms.
    #[test]
    fn rcond_is_the_reciprocal_condition_number_of_the_scaled_boundary_matrix() {
        for p in [Params::new(1.0, 3.0, 1.0), Params::new(-0.5, 2.0, 4.0)] {
            let b = Basis::new(p).expect("basis");
            let (y0, y1) = (b.y(Jet::<3, 1>::var_u(0.0)), b.y(Jet::<3, 1>::var_u(1.0)));
            let m = DMatrix::from_fn(6, 6, |r, k| {
                let col = |i: usize| {
                    if i < 3 {
                        y0[k].deriv(i, 0)
                    } else {
                        y1[k].deriv(i - 3, 0)
                    }
                };
                let s = (0..6).map(|i| col(i).abs()).fold(0.0, f64::max);
                col(r) / s
            });
            let inv = m.clone().try_inverse().expect("regular");
            let one = |a: &DMatrix<f64>| a.column_iter().map(|c| c.lp_norm(1)).fold(0.0, f64::max);
            let want = 1.0 / (one(&m) * one(&inv));
            assert!(
                (b.rcond - want).abs() <= RCOND_REL * want,
                "{p:?}: {} against {want}",
                b.rcond
            );
        }
    }

    /// The coefficient magnitude is the largest |coef| (the unit
    /// constraints make at least one coefficient of order one).
    #[test]
    fn the_coefficient_magnitude_is_the_largest_coefficient() {
        let b = Basis::new(Params::new(1.0, 3.0, 1.0)).expect("basis");
        let want = b.coef.iter().flatten().map(|c| c.abs()).fold(0.0, f64::max);
        assert!(want > 0.0);
        assert_eq!(b.coef_magnitude(), want);
    }

    /// The boundary error sees a basis whose coefficients are off: one
    /// coefficient moved by 1e-3 moves `g_j` or its derivatives at an end.
    #[test]
    fn the_boundary_error_sees_a_wrong_coefficient() {
        let b = Basis::new(Params::new(1.0, 3.0, 1.0)).expect("basis");
        assert_boundary_error_sees(&b, 0);
    }

    /// `b` meets its boundary conditions, and with `g_{j+1}`'s first
    /// coefficient nudged it does not.
    fn assert_boundary_error_sees(b: &Basis, j: usize) {
        assert!(
            b.boundary_error() <= crate::check::tol::SOLVE,
            "{}",
            b.boundary_error()
        );
        let mut off = b.clone();
        off.coef[j][0] += NUDGE;
        assert!(off.boundary_error() >= SEEN, "{}", off.boundary_error());
    }

    /// In the second-order basis (`rho = eta = 0`) the imposed functions are
    /// `g_1` and `g_4` (positions at `u = 0` and `u = 1`): a nudged `g_4` is
    /// seen. (Choosing the imposed ones by `j / 3` instead of `j % 3`, a
    /// mutant in sample ode6 4/24, checked `g_1..g_3` and missed it.)
    #[test]
    fn the_reduced_boundary_error_sees_the_far_end() {
        let b = Basis::reduced(Params::new(0.0, 0.0, 1.0)).expect("basis");
        assert_eq!(b.order, 2);
        assert_boundary_error_sees(&b, 3);
    }
}
