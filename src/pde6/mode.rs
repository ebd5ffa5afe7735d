//! One harmonic of the closed form: the six functions that solve
//! $A^{(6)}(u) = a n^6 A(u)$ (paper 002 eqs 6-8, appendix A), in an
//! end-centred basis, and the $6\times 6$ interpolation solves (eqs 21-23,
//! 24-25, A34-A36).
//!
//! With $q = n |a|^{1/6}$ the roots of $r^6 = a n^6$ are (derived in
//! `verify/pde6_closed_form.py`):
//!
//! * $a < 0$: $\pm i q$ and $q(\pm\tfrac{\sqrt3}{2} \pm \tfrac i2)$ (paper eq 8
//!   with $q_{1n} = \tfrac{\sqrt3}{2} q$, $q_{2n} = \tfrac q2$);
//! * $a > 0$: $\pm q$ and $q(\pm\tfrac12 \pm i\tfrac{\sqrt3}{2})$ — six simple
//!   roots, *not* the triple roots $\pm q_{0n}$ of paper eq 7 (ERRATA);
//! * $a = 0$ or $n = 0$: $r = 0$ six times, the quintic of eq 6.
//!
//! Each growing exponential is centred at the end it grows towards
//! ($e^{s(u-1)}$ instead of $e^{su}$), so every basis function is bounded by 1
//! on $[0, 1]$ and the interpolation matrices stay well conditioned; for the
//! quintic the basis is $(2u-1)^k$.

use super::Pde6Error;
use crate::jet::{Jet, Real};
use nalgebra::{Matrix6, Vector6};

/// Which closed form a harmonic takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Regime {
    /// $a = 0$ or $n = 0$: quintic polynomial (eq 6).
    Quintic,
    /// $a < 0$: two oscillating and four exponentially damped/grown waves (eq 8).
    Oscillatory,
    /// $a > 0$: real exponentials $e^{\pm q u}$ and damped waves (eq 7 corrected).
    Exponential,
}

/// The six basis functions of one harmonic.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModeBasis {
    pub regime: Regime,
    /// $q = n |a|^{1/6}$ (0 for the quintic).
    pub q: f64,
}

const HALF_SQRT3: f64 = 0.866_025_403_784_438_6;

/// Below this q the series basis ([`ModeBasis::eval_series`]) is used.
pub const Q_SERIES: f64 = 4.0;
/// Terms of the series basis.
pub const SERIES_TERMS: usize = 7;

impl ModeBasis {
    /// The basis of harmonic `n` for the PDE parameter `a`.
    pub fn new(a: f64, n: usize) -> ModeBasis {
        if a == 0.0 || n == 0 {
            return ModeBasis {
                regime: Regime::Quintic,
                q: 0.0,
            };
        }
        let q = n as f64 * a.abs().powf(1.0 / 6.0);
        let regime = if a < 0.0 {
            Regime::Oscillatory
        } else {
            Regime::Exponential
        };
        ModeBasis { regime, q }
    }

    /// The six basis functions at `u` (jets give their derivatives).
    pub fn eval<T: Real>(&self, u: T) -> [T; 6] {
        let q = self.q;
        if self.regime == Regime::Quintic || q <= Q_SERIES {
            return self.eval_series(u);
        }
        match self.regime {
            Regime::Quintic => self.eval_series(u),
            Regime::Oscillatory => {
                let (s, h) = (HALF_SQRT3 * q, 0.5 * q);
                let w = u - 1.0;
                let (e0, e1) = ((u * -s).exp(), (w * s).exp());
                [
                    (u * q).cos(),
                    (u * q).sin(),
                    e0 * (u * h).cos(),
                    e0 * (u * h).sin(),
                    e1 * (w * h).cos(),
                    e1 * (w * h).sin(),
                ]
            }
            Regime::Exponential => {
                let (s, h) = (0.5 * q, HALF_SQRT3 * q);
                let w = u - 1.0;
                let (e0, e1) = ((u * -s).exp(), (w * s).exp());
                [
                    (u * -q).exp(),
                    (w * q).exp(),
                    e0 * (u * h).cos(),
                    e0 * (u * h).sin(),
                    e1 * (w * h).cos(),
                    e1 * (w * h).sin(),
                ]
            }
        }
    }

    /// The series basis for small q: the fundamental system at u = 1/2,
    /// $\phi_k(u) = \sum_{m \ge 0} \sigma^m (q/2)^{6m} \frac{k!}{(k+6m)!} (2u-1)^{k+6m}$
    /// with $\sigma = \operatorname{sign} a$; it solves $\phi^{(6)} = \sigma q^6
    /// \phi$ term by term, is $(2u-1)^k$ for q = 0, and stays well conditioned
    /// as $q \to 0$ where the exponential basis degenerates.
    /// [`SERIES_TERMS`] terms: the first omitted one is below $10^{-30}$ for
    /// $q \le$ [`Q_SERIES`].
    pub fn eval_series<T: Real>(&self, u: T) -> [T; 6] {
        let sigma = match self.regime {
            Regime::Quintic => 0.0,
            Regime::Oscillatory => -1.0,
            Regime::Exponential => 1.0,
        };
        let s = u * 2.0 - 1.0;
        let s2 = s * s;
        let s6 = s2 * s2 * s2;
        let pow: [T; 6] = [T::one(), s, s2, s2 * s, s2 * s2, s2 * s2 * s];
        let h6 = (0.5 * self.q).powi(6) * sigma;
        std::array::from_fn(|k| {
            let mut acc = pow[k];
            if h6 != 0.0 {
                let mut term = pow[k];
                let mut c = 1.0;
                for m in 1..SERIES_TERMS {
                    // c_m = c_{m-1} h6 k!... : ratio (k+6m-6)! / (k+6m)!
                    let mut r = h6;
                    for j in (k + 6 * m - 5)..=(k + 6 * m) {
                        r /= j as f64;
                    }
                    c *= r;
                    term *= s6;
                    acc += term * c;
                }
            }
            acc
        })
    }

    /// The basis as printed in appendix A (eq 6, eq 7 and eq 8 with the lost
    /// minus signs restored): exponentials centred at $u = 0$. For
    /// $a > 0$ this is the (wrong) triple-root form of eq 7, kept to measure
    /// the erratum; for $a < 0$ it spans the same space as [`ModeBasis::eval`]
    /// and serves the conditioning comparison.
    pub fn eval_paper<T: Real>(&self, u: T) -> [T; 6] {
        let q = self.q;
        match self.regime {
            Regime::Quintic => {
                let u2 = u * u;
                [T::one(), u, u2, u2 * u, u2 * u2, u2 * u2 * u]
            }
            Regime::Oscillatory => {
                let (q1, q2) = (HALF_SQRT3 * q, 0.5 * q);
                let (ep, em) = ((u * q1).exp(), (u * -q1).exp());
                let (c, s) = ((u * q2).cos(), (u * q2).sin());
                [
                    (u * (2.0 * q2)).cos(),
                    (u * (2.0 * q2)).sin(),
                    ep * c,
                    ep * s,
                    em * c,
                    em * s,
                ]
            }
            Regime::Exponential => {
                let (ep, em) = ((u * q).exp(), (u * -q).exp());
                [ep, u * ep, u * u * ep, em, u * em, u * u * em]
            }
        }
    }

    /// Values of $\partial^d$ of the six basis functions at `u`, d = 0, 1, 2.
    pub fn jet2(&self, u: f64) -> [[f64; 6]; 3] {
        let b = self.eval(Jet::<3, 1>::var_u(u));
        let mut out = [[0.0; 6]; 3];
        for j in 0..6 {
            for (d, row) in out.iter_mut().enumerate() {
                row[j] = b[j].deriv(d, 0);
            }
        }
        out
    }
}

/// One linear condition on a harmonic function $A(u)$ on $[0, 1]$.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Condition {
    /// $A(u)$ at `u`.
    Value(f64),
    /// $A'(u)$.
    Slope(f64),
    /// $A''(u)$.
    Curvature(f64),
}

impl Condition {
    fn row(&self, b: &ModeBasis) -> [f64; 6] {
        match *self {
            Condition::Value(u) => b.jet2(u)[0],
            Condition::Slope(u) => b.jet2(u)[1],
            Condition::Curvature(u) => b.jet2(u)[2],
        }
    }
}

/// The six interpolation nodes of one patch, u = 0, 0.2, ..., 1 (eq 15).
pub const NODES_METHOD1: [f64; 6] = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0];

/// The six conditions of a patch through six curves at `nodes`.
pub fn method1_conditions(nodes: [f64; 6]) -> [Condition; 6] {
    nodes.map(Condition::Value)
}

/// Method 2 (eqs 24-25): four curves at u = 0, 1/3, 2/3, 1 and the slope and
/// curvature carried over at `u = join` (0 or 1).
pub fn method2_conditions(join: f64) -> [Condition; 6] {
    [
        Condition::Value(0.0),
        Condition::Value(1.0 / 3.0),
        Condition::Value(2.0 / 3.0),
        Condition::Value(1.0),
        Condition::Slope(join),
        Condition::Curvature(join),
    ]
}

/// A factorised $6\times6$ interpolation problem of one harmonic: the basis,
/// the conditions, and the inverse of the (column-equilibrated) matrix.
#[derive(Clone, Debug)]
pub struct ModeSolver {
    pub basis: ModeBasis,
    pub conditions: [Condition; 6],
    matrix: Matrix6<f64>,
    inverse: Matrix6<f64>,
    /// 1-norm condition number of the matrix.
    pub condition_number: f64,
}

fn norm1(m: &Matrix6<f64>) -> f64 {
    (0..6)
        .map(|j| (0..6).map(|i| m[(i, j)].abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

/// Matrix of `conditions` applied to a basis given as rows of values.
fn assemble(rows: impl Fn(&Condition) -> [f64; 6], conditions: &[Condition; 6]) -> Matrix6<f64> {
    let mut m = Matrix6::zeros();
    for (i, c) in conditions.iter().enumerate() {
        let r = rows(c);
        for j in 0..6 {
            m[(i, j)] = r[j];
        }
    }
    m
}

/// 1-norm condition number of the interpolation matrix in the paper's
/// basis (exponentials centred at u = 0), for the conditioning comparison.
pub fn paper_basis_condition(basis: &ModeBasis, conditions: &[Condition; 6]) -> f64 {
    let m = assemble(
        |c| {
            let (u, d) = match *c {
                Condition::Value(u) => (u, 0),
                Condition::Slope(u) => (u, 1),
                Condition::Curvature(u) => (u, 2),
            };
            basis
                .eval_paper(Jet::<3, 1>::var_u(u))
                .map(|x| x.deriv(d, 0))
        },
        conditions,
    );
    match m.try_inverse() {
        Some(inv) => norm1(&m) * norm1(&inv),
        None => f64::INFINITY,
    }
}

impl ModeSolver {
    /// Factorises the problem; errors when the matrix is singular or the
    /// parameters are not finite.
    pub fn new(basis: ModeBasis, conditions: [Condition; 6]) -> Result<ModeSolver, Pde6Error> {
        if !basis.q.is_finite() {
            return Err(Pde6Error::NotFinite("PDE parameter a".into()));
        }
        let matrix = assemble(|c| c.row(&basis), &conditions);
        let inverse = matrix
            .full_piv_lu()
            .try_inverse()
            .ok_or(Pde6Error::Singular { q: basis.q })?;
        let condition_number = norm1(&matrix) * norm1(&inverse);
        if !condition_number.is_finite() || condition_number > MAX_CONDITION {
            return Err(Pde6Error::IllConditioned {
                q: basis.q,
                condition: condition_number,
            });
        }
        Ok(ModeSolver {
            basis,
            conditions,
            matrix,
            inverse,
            condition_number,
        })
    }

    /// Coefficients of the function that meets the six right-hand sides
    /// (one step of iterative refinement).
    pub fn solve(&self, rhs: [f64; 6]) -> [f64; 6] {
        let b = Vector6::from(rhs);
        let mut x = self.inverse * b;
        let r = b - self.matrix * x;
        x += self.inverse * r;
        x.into()
    }

    /// Max |M x - b| relative to max(|b|, 1): the solve residual.
    pub fn residual(&self, coef: [f64; 6], rhs: [f64; 6]) -> f64 {
        let r = self.matrix * Vector6::from(coef) - Vector6::from(rhs);
        r.amax() / Vector6::from(rhs).amax().max(1.0)
    }
}

/// Interpolation matrices with a larger 1-norm condition number are refused.
pub const MAX_CONDITION: f64 = 1e12;

/// A single harmonic function $A(u) = \sum_j c_j \phi_j(u)$.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mode {
    pub basis: ModeBasis,
    pub coef: [f64; 6],
}

impl Mode {
    /// The harmonic-n function for parameter `a` that takes `values` at
    /// u = 0, 0.2, ..., 1 (the `pde6 mode` command).
    pub fn interpolate(a: f64, n: usize, values: [f64; 6]) -> Result<Mode, Pde6Error> {
        super::validate_a(a)?;
        if values.iter().any(|x| !x.is_finite()) {
            return Err(Pde6Error::NotFinite("mode values".into()));
        }
        let s = ModeSolver::new(ModeBasis::new(a, n), method1_conditions(NODES_METHOD1))?;
        Ok(Mode {
            basis: s.basis,
            coef: s.solve(values),
        })
    }

    /// $A(u)$ (generic).
    pub fn eval<T: Real>(&self, u: T) -> T {
        let b = self.basis.eval(u);
        let mut s = T::zero();
        for j in 0..6 {
            s += b[j] * self.coef[j];
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series basis is the fundamental system at u = 1/2 (its doc):
    /// there phi_0 = 1 and phi_1..phi_5 = 0, in every regime. Any basis of
    /// the solution space solves the same conditions, so the mode checks
    /// could not see the expansion point move (a mutation sample:
    /// `2u - 1` -> `2u + 1`, the system at u = -1/2, survived them).
    #[test]
    fn the_series_basis_is_the_fundamental_system_at_one_half() {
        for a in [1e-3, -1e-3, 0.0] {
            let b = ModeBasis::new(a, 1);
            assert!(b.q < Q_SERIES, "{b:?}");
            let phi = b.eval_series(0.5);
            assert_eq!(phi[0], 1.0, "a = {a}: {phi:?}");
            for (k, v) in phi.iter().enumerate().skip(1) {
                assert_eq!(*v, 0.0, "a = {a}: phi_{k} = {v}");
            }
        }
    }
}
