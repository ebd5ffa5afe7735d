//! The shape parameters of eq 2, the roots $q_{1,2}$ of
//! $\rho q^2 + \eta q + \lambda = 0$ (eqs 13-14) and the choice of the
//! [`RootCase`] that represents the solution space (the table in
//! [`super`]'s module doc), with the Taylor coefficients of the series case.

use super::{Ode6Error, Q_SERIES, SEPARATION};

/// Terms of the Taylor series of the fundamental solutions.
pub(super) const N_SERIES: usize = 48;

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

    pub(super) fn validate(&self) -> Result<(), Ode6Error> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::tol;

    /// The case's imaginary part is below this fraction of its real part
    /// (a root this near the real axis: the branch without cancellation
    /// matters there; the roots built below are at 1e-7).
    const NEAR_AXIS: f64 = 1e-6;

    /// The complex case's square root `r = alpha + i beta` of `q = a + i b`
    /// takes the branch without cancellation: for `a > 0` and `b` about
    /// 1e-7 of it, the other branch's `m - a` (m = |q|, about 5e-15 a)
    /// keeps 1 or 2 of 16 digits and `alpha^2 - beta^2` misses `a` (a
    /// mutant swapping the branches survived every check: the cases the
    /// checks use have `b` comparable to `a`).
    #[test]
    fn a_complex_root_near_the_real_axis_keeps_its_digits() {
        let p = Params::new(1.0, -2.0, 1.0 + 1e-14);
        let [(a, b), _] = p.q_roots();
        assert!(a > 0.0 && b > 0.0 && b < NEAR_AXIS * a, "q = {a} + {b} i");
        let RootCase::Complex { alpha, beta } = classify_closed(&p) else {
            panic!("complex roots: {:?}", classify_closed(&p));
        };
        let re = alpha * alpha - beta * beta;
        let im = 2.0 * alpha * beta;
        assert!(
            (re - a).abs() <= tol::ROUNDING * a,
            "alpha^2 - beta^2 = {re}, a = {a}"
        );
        assert!(
            (im - b).abs() <= tol::ROUNDING * b,
            "2 alpha beta = {im}, b = {b}"
        );
    }
}
