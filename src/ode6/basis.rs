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
use crate::jet::{Jet, Real};
use nalgebra::{DMatrix, SMatrix};

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
/// Terms of the Taylor series of the fundamental solutions.
const N_SERIES: usize = 48;
/// Terms of the series of `F2`, `F3` (|q| <= 1, u in [0, 1]).
const N_F: usize = 16;

/// The shape control parameters of eq 2.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Params {
    pub rho: f64,
    pub eta: f64,
    pub lambda: f64,
}

impl Params {
    pub fn new(rho: f64, eta: f64, lambda: f64) -> Params {
        Params { rho, eta, lambda }
    }

    fn validate(&self) -> Result<(), Ode6Error> {
        for (name, value) in [
            ("rho", self.rho),
            ("eta", self.eta),
            ("lambda", self.lambda),
        ] {
            if !value.is_finite() {
                return Err(Ode6Error::NonFinite { name, value });
            }
        }
        if self.rho == 0.0 && self.eta == 0.0 && self.lambda == 0.0 {
            return Err(Ode6Error::AllZero);
        }
        Ok(())
    }

    /// Roots `q` of `rho q^2 + eta q + lambda = 0` (eqs 13-14) as
    /// `(re, im)` pairs, computed without cancellation; `rho != 0`.
    pub fn q_roots(&self) -> [(f64, f64); 2] {
        let (r, e, l) = (self.rho, self.eta, self.lambda);
        let disc = e * e - 4.0 * r * l;
        if disc >= 0.0 {
            let s = disc.sqrt();
            // t = rho q1 = -(e + sign(e) s)/2 (sign(0) = +1), q2 = lambda / t.
            let sgn = if e >= 0.0 { 1.0 } else { -1.0 };
            let t = -0.5 * (e + sgn * s);
            if t == 0.0 {
                return [(0.0, 0.0), (0.0, 0.0)];
            }
            let q1 = t / r;
            let q2 = l / t;
            [(q1, 0.0), (q2, 0.0)]
        } else {
            let a = -e / (2.0 * r);
            let b = (-disc).sqrt() / (2.0 * r.abs());
            [(a, b), (a, -b)]
        }
    }
}

/// Which basis represents the solution space (see the module doc).
#[derive(Clone, Debug, PartialEq)]
pub enum RootCase {
    /// Taylor series; `d[k][n]` is the n-th derivative at 0 of basis k.
    Series {
        coef: Vec<[f64; N_SERIES]>,
    },
    Separated {
        q1: f64,
        q2: f64,
    },
    CloseOscillatory {
        sigma: f64,
        tau: f64,
    },
    CloseGrowing {
        sigma: f64,
        tau: f64,
    },
    Complex {
        alpha: f64,
        beta: f64,
    },
    /// `rho = 0`, `eta != 0`: `{1, u}` and the pair of `q = -lambda/eta`.
    FourthOrder {
        q: f64,
    },
    /// `rho = eta = 0`: `{1, u}`.
    SecondOrder,
}

impl RootCase {
    /// A short name for messages.
    pub fn name(&self) -> String {
        match self {
            RootCase::Series { .. } => "small roots |q| <= 4 (Taylor series)".into(),
            RootCase::Separated { q1, q2 } => format!("distinct real roots q = {q1:.6e}, {q2:.6e}"),
            RootCase::CloseOscillatory { sigma, tau } => {
                format!("close/repeated negative roots (sigma = {sigma:.6e}, tau = {tau:.6e})")
            }
            RootCase::CloseGrowing { sigma, tau } => {
                format!("close/repeated positive roots (sigma = {sigma:.6e}, tau = {tau:.6e})")
            }
            RootCase::Complex { alpha, beta } => {
                format!("complex roots r = +-{alpha:.6e} +- {beta:.6e} i")
            }
            RootCase::FourthOrder { q } => format!("rho = 0, fourth order (q = {q:.6e})"),
            RootCase::SecondOrder => "rho = eta = 0, second order".into(),
        }
    }
}

/// `sin(b x)/b` (`x` at `b = 0`).
fn snc<T: Real>(b: f64, x: T) -> T {
    if b == 0.0 {
        x
    } else {
        (x * b).sin() / b
    }
}

/// `sinh(a x)/a` (`x` at `a = 0`).
fn shc<T: Real>(a: f64, x: T) -> T {
    if a == 0.0 {
        x
    } else {
        (x * a).sinh() / a
    }
}

/// The two basis functions contributed by one real root `q`.
fn pair<T: Real>(q: f64, u: T) -> [T; 2] {
    if q < -1.0 {
        let w = (-q).sqrt();
        [(u * w).cos(), (u * w).sin()]
    } else if q > 1.0 {
        let w = q.sqrt();
        [(u * (-w)).exp(), ((u - 1.0) * w).exp()]
    } else {
        series_f23(q, u)
    }
}

/// `F2(q, u)`, `F3(q, u)` by their series (entire in `q`).
fn series_f23<T: Real>(q: f64, u: T) -> [T; 2] {
    let u2 = u * u;
    // coefficients of (u^2)^k
    let mut f2 = T::zero();
    let mut f3 = T::zero();
    for k in (0..N_F).rev() {
        let qk = q.powi(k as i32);
        f2 = f2 * u2 + qk / crate::jet::factorial(2 * k + 2);
        f3 = f3 * u2 + qk / crate::jet::factorial(2 * k + 3);
    }
    [f2 * u2, f3 * u2 * u]
}

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
            Err(Ode6Error::BadData(format!(
                "case {} does not solve eq 8 for rho = {}, eta = {}, lambda = {} (relative residual {res:.2e})",
                b.case.name(),
                params.rho,
                params.eta,
                params.lambda
            )))
        }
    }

    /// `rho = 0`: the fourth-order (or, with `eta = 0`, second-order)
    /// problem, imposing positions and tangents only (`g_3 = g_6 = 0`;
    /// with `eta = 0` also `g_2 = g_5 = 0`).
    pub fn reduced(params: Params) -> Result<Basis, Ode6Error> {
        params.validate()?;
        if params.rho != 0.0 {
            return Err(Ode6Error::BadData(format!(
                "Basis::reduced needs rho = 0 (got rho = {})",
                params.rho
            )));
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
        let one = T::one();
        let z = T::zero();
        match &self.case {
            RootCase::Series { coef } => {
                let mut out = [z; 6];
                for k in 0..6 {
                    let mut acc = T::zero();
                    for n in (0..N_SERIES).rev() {
                        acc = acc * u + coef[k][n] / crate::jet::factorial(n);
                    }
                    out[k] = acc;
                }
                out
            }
            RootCase::Separated { q1, q2 } => {
                let [a, b] = pair(*q1, u);
                let [c, d] = pair(*q2, u);
                [one, u, a, b, c, d]
            }
            RootCase::CloseOscillatory { sigma, tau } => {
                let (cs, ss) = ((u * *sigma).cos(), (u * *sigma).sin());
                let (ct, st) = ((u * *tau).cos(), snc(*tau, u));
                [one, u, cs * ct, ss * ct, cs * st, ss * st]
            }
            RootCase::CloseGrowing { sigma, tau } => {
                let w = one - u;
                let e0 = (u * (-*sigma)).exp();
                let e1 = (w * (-*sigma)).exp();
                [
                    one,
                    u,
                    e0 * (u * *tau).cosh(),
                    e0 * shc(*tau, u),
                    e1 * (w * *tau).cosh(),
                    e1 * shc(*tau, w),
                ]
            }
            RootCase::Complex { alpha, beta } => {
                let (a, b) = (*alpha, *beta);
                if a <= 1.0 {
                    let (ch, sh) = ((u * a).cosh(), shc(a, u));
                    let (c, s) = ((u * b).cos(), snc(b, u));
                    [one, u, ch * c, ch * s, sh * c, sh * s]
                } else {
                    let w = one - u;
                    let e0 = (u * (-a)).exp();
                    let e1 = (w * (-a)).exp();
                    [
                        one,
                        u,
                        e0 * (u * b).cos(),
                        e0 * snc(b, u),
                        e1 * (w * b).cos(),
                        e1 * snc(b, w),
                    ]
                }
            }
            RootCase::FourthOrder { q } => {
                let [a, b] = pair(*q, u);
                [one, u, a, b, z, z]
            }
            RootCase::SecondOrder => [one, u, z, z, z, z],
        }
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

/// Chooses the case for `rho != 0`.
pub fn classify(p: &Params) -> RootCase {
    classify_with(p, true)
}

/// The closed-form case even for small roots (cross-checks the series).
pub fn classify_closed(p: &Params) -> RootCase {
    classify_with(p, false)
}

fn classify_with(p: &Params, allow_series: bool) -> RootCase {
    let [(a1, b1), (a2, _)] = p.q_roots();
    let qmax = a1.hypot(b1).max(a2.abs());
    if allow_series && qmax <= Q_SERIES {
        return RootCase::Series {
            coef: series_coefficients(p),
        };
    }
    if b1 != 0.0 {
        // r = alpha + i beta with r^2 = a + i b.
        let (a, b) = (a1, b1.abs());
        let m = a.hypot(b);
        let (alpha, beta) = if a >= 0.0 {
            let al = ((m + a) / 2.0).sqrt();
            (al, b / (2.0 * al))
        } else {
            let be = ((m - a) / 2.0).sqrt();
            (b / (2.0 * be), be)
        };
        return RootCase::Complex { alpha, beta };
    }
    let (q1, q2) = (a1, a2);
    let gap = (p.eta * p.eta - 4.0 * p.rho * p.lambda).max(0.0).sqrt() / p.rho.abs();
    if q1 * q2 <= 0.0 || gap >= SEPARATION * qmax {
        return RootCase::Separated { q1, q2 };
    }
    let (w1, w2) = (q1.abs().sqrt(), q2.abs().sqrt());
    let sigma = (w1 + w2) / 2.0;
    let tau = gap / (4.0 * sigma);
    if q1 < 0.0 {
        RootCase::CloseOscillatory { sigma, tau }
    } else {
        RootCase::CloseGrowing { sigma, tau }
    }
}

/// Derivatives at 0 of the fundamental solutions: `d[k][n]`, with
/// `rho d_{n+6} + eta d_{n+4} + lambda d_{n+2} = 0`.
fn series_coefficients(p: &Params) -> Vec<[f64; N_SERIES]> {
    (0..6)
        .map(|k| {
            let mut d = [0.0; N_SERIES];
            d[k] = 1.0;
            for m in 6..N_SERIES {
                d[m] = -(p.eta * d[m - 2] + p.lambda * d[m - 4]) / p.rho;
            }
            d
        })
        .collect()
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
                    err = err.max((g[j].deriv(i, 0) - target).abs());
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
            let scale = terms.iter().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
            if scale == 0.0 {
                continue;
            }
            for t in &terms {
                err = err.max((t[0] + t[1] + t[2]).abs() / scale);
            }
        }
        err
    }

    /// Largest `|coef|`: the amplification of rounding by the basis change.
    pub fn coef_magnitude(&self) -> f64 {
        self.coef.iter().flatten().fold(0.0, |a, b| a.max(b.abs()))
    }
}
