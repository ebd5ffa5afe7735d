//! The case bases $y_1..y_6$ of the table in [`super`]'s module doc:
//! the elementary functions of each root case, generic over [`Real`] so
//! that jets give their exact derivatives.

use super::roots::{RootCase, N_SERIES};
use crate::jet::Real;

/// Terms of the series of `F2`, `F3` (|q| <= 1, u in [0, 1]).
const N_F: usize = 16;

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

/// The case basis `y_1..y_6` of `case` (unused entries zero for reduced
/// orders).
pub(super) fn case_basis<T: Real>(case: &RootCase, u: T) -> [T; 6] {
    let one = T::one();
    let z = T::zero();
    match case {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The series of `F2(q, u) = sum q^k u^(2k+2) / (2k+2)!` and `F3(q, u) =
    /// sum q^k u^(2k+3) / (2k+3)!` against their closed forms: with `s =
    /// sqrt(|q|)`, `(cosh su - 1) / q` and `(sinh su - su) / (q s)` for `q >
    /// 0`, `(cos su - 1) / q` and `(su - sin su) / s^3` for `q < 0`.
    #[test]
    fn the_f2_f3_series_match_their_closed_forms() {
        for q in [0.5f64, -0.5, 2.0] {
            let s = q.abs().sqrt();
            for u in [0.25f64, 0.7, 1.0] {
                let [f2, f3] = series_f23(q, u);
                let (w2, w3) = if q > 0.0 {
                    (
                        ((s * u).cosh() - 1.0) / q,
                        ((s * u).sinh() - s * u) / (q * s),
                    )
                } else {
                    (
                        ((s * u).cos() - 1.0) / q,
                        (s * u - (s * u).sin()) / s.powi(3),
                    )
                };
                let tol = crate::check::tol::SOLVE;
                assert!((f2 - w2).abs() <= tol, "F2({q}, {u}): {f2} against {w2}");
                assert!((f3 - w3).abs() <= tol, "F3({q}, {u}): {f3} against {w3}");
            }
        }
    }
    /// The close-root cases divide their second function by the half gap
    /// `tau` (`sin(tau u)/tau`, `sinh(tau u)/tau`), so as the two roots meet
    /// the basis tends to the double root's `{cos, sin}(sigma u) u`, not to
    /// zero: at `tau = 0.3` the functions are exactly that quotient, at
    /// `tau = 1e-10` the limit to rounding.
    #[test]
    fn the_close_cases_tend_to_the_double_roots_basis() {
        let sigma = 1.5;
        let tol = crate::check::tol::ROUNDING;
        for u in [0.25f64, 0.7, 1.0] {
            let (c, s) = ((sigma * u).cos(), (sigma * u).sin());
            let tau = 0.3;
            let b = case_basis(&RootCase::CloseOscillatory { sigma, tau }, u);
            let st = (tau * u).sin() / tau;
            assert!((b[4] - c * st).abs() <= tol, "{b:?}");
            assert!((b[5] - s * st).abs() <= tol, "{b:?}");
            let g = case_basis(&RootCase::CloseGrowing { sigma, tau }, u);
            let e0 = (-sigma * u).exp();
            assert!((g[3] - e0 * (tau * u).sinh() / tau).abs() <= tol, "{g:?}");
            let tau = 1e-10;
            let b = case_basis(&RootCase::CloseOscillatory { sigma, tau }, u);
            assert!(
                (b[4] - c * u).abs() <= tol && (b[5] - s * u).abs() <= tol,
                "{b:?}"
            );
            let g = case_basis(&RootCase::CloseGrowing { sigma, tau }, u);
            assert!((g[3] - e0 * u).abs() <= tol, "{g:?}");
        }
    }
}
