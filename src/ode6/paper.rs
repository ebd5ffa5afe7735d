//! The printed forms of paper 004, literally, for the paper-literal checks.
//!
//! Eqs 14-15 as extracted read `q_{1,2} = η(1 ± 1 4ρλ/η²)/(2ρ)` and
//! `ξ_{1,2} = η(1 ± 1 4ρλ/η²)/(2ρ)` (identical texts: the minus sign and both
//! square roots are lost in the extraction). The intended forms are
//! $q_{1,2} = -\eta(1 \pm \sqrt{1 - 4\rho\lambda/\eta^2})/(2\rho)$ and
//! $\xi_{1,2} = \sqrt{\eta(1 \pm \sqrt{1 - 4\rho\lambda/\eta^2})/(2\rho)}$,
//! so that $r = \pm i\xi$ and $q = -\xi^2$ (eq 16).

use crate::jet::Real;

/// `q_{1,2}` of eq 14 exactly as extracted, `η(1 ± 1 4ρλ/η²)/(2ρ)`, with
/// the lost minus read as `1 - 4ρλ/η²` under no root and no leading minus
/// (the same reading as [`xi_printed`]; the texts of eqs 14 and 15 are
/// identical).
pub fn q_printed(rho: f64, eta: f64, lambda: f64) -> [f64; 2] {
    xi_printed(rho, eta, lambda)
}

/// `q_{1,2}` of eq 14 with the leading minus and the square root restored:
/// `-η(1 ± sqrt(1 - 4ρλ/η²))/(2ρ)`.
pub fn q_restored(rho: f64, eta: f64, lambda: f64) -> [f64; 2] {
    let t = (1.0 - 4.0 * rho * lambda / (eta * eta)).sqrt();
    [
        -eta * (1.0 + t) / (2.0 * rho),
        -eta * (1.0 - t) / (2.0 * rho),
    ]
}

/// Residual `|ρq² + ηq + λ|` of eq 13 at `q`, relative to `max(|λ|, 1)`.
pub fn eq13_residual(rho: f64, eta: f64, lambda: f64, q: f64) -> f64 {
    (rho * q * q + eta * q + lambda).abs() / lambda.abs().max(1.0)
}

/// `ξ_{1,2}` of eq 15 read literally (no square roots, "1 4ρλ" as `1 - 4ρλ`
/// under no root): `η(1 ± (1 - 4ρλ/η²))/(2ρ)`.
pub fn xi_printed(rho: f64, eta: f64, lambda: f64) -> [f64; 2] {
    let t = 1.0 - 4.0 * rho * lambda / (eta * eta);
    [eta * (1.0 + t) / (2.0 * rho), eta * (1.0 - t) / (2.0 * rho)]
}

/// `ξ_{1,2}` of eq 15 with the square roots restored.
pub fn xi_intended(rho: f64, eta: f64, lambda: f64) -> [f64; 2] {
    let t = (1.0 - 4.0 * rho * lambda / (eta * eta)).sqrt();
    [
        (eta * (1.0 + t) / (2.0 * rho)).sqrt(),
        (eta * (1.0 - t) / (2.0 * rho)).sqrt(),
    ]
}

/// The constants `e_1..e_13` and `d_1..d_10` of eqs 21-22 as printed,
/// restored as `verify/ode6_eq20_40digits.py` finds (40 digits, the fewest
/// signs, unique): a minus in every gap the extraction left between two
/// terms, "cos 2 ξ2" of `e_6` read as `cos²ξ2`, and a leading minus in `d_2`,
/// `d_4`, `d_10` and inside `e_4`'s bracket. Nothing else is changed
/// (index 0 unused). `d_9` is as printed.
pub fn printed_constants(x1: f64, x2: f64) -> ([f64; 14], [f64; 11]) {
    let (c1, s1, c2, s2) = (x1.cos(), x1.sin(), x2.cos(), x2.sin());
    let mut e = [0.0; 14];
    e[1] = x1 * (c1 - 1.0) + x1 * x1 * s1 * (1.0 - c2) / (x2 * s2);
    e[2] = s1 - x1 + x1 * x1 * s1 * (1.0 / s2 - 1.0 / x2) / x2;
    e[3] = c1 - 1.0
        + x1 * x1 * (1.0 - c2) / (x2 * x2)
        + x1 * x1 * (c2 - c1) * (1.0 / x2 - 1.0 / s2) / x2;
    e[4] = x1 * (-s1 + x1 * s2 / x2) + x1 * x1 * (c2 - c1) * (c2 - 1.0) / (x2 * s2);
    e[5] = (1.0 / x2 - c2 / s2) / x2;
    e[6] = (s2 + c2 * c2 / s2 - c2 / s2) / x2;
    e[7] = (1.0 / s2 - 1.0 / x2) / x2;
    e[8] = (1.0 - c2) / (x2 * s2);
    e[11] = x1 * x1 / (x2 * x2) - 1.0;
    e[12] = c2 / (x2 * s2);
    e[13] = 1.0 / (x2 * s2);
    let den = e[1] * e[3] - e[2] * e[4];
    let mut d = [0.0; 11];
    d[1] = e[1] / den;
    d[2] = -e[2] / den;
    d[3] = e[3] / den;
    d[4] = -e[4] / den;
    d[5] = d[1] * e[5] + d[2] * e[6];
    d[6] = d[1] * e[7] + d[2] * e[8];
    d[7] = d[4] * e[5] + d[3] * e[6];
    d[8] = d[4] * e[7] + d[3] * e[8];
    d[9] = (e[11] + 1.0) * (d[1] + d[2]);
    d[10] = -1.0 / (x2 * x2) + (e[11] + 1.0) * d[5];
    e[9] = x1 * x1 * (d[4] * s1 - d[1] * (c2 - c1)) / (x2 * x2 * s2);
    e[10] = x1 * x1 * (d[3] * s1 - d[2] * (c2 - c1)) / (x2 * x2 * s2);
    (e, d)
}

/// The coefficients `(A, B, C, D, E, F)` of `g_1..g_6` of eq 20,
/// `g = A cos ξ1u + B sin ξ1u + C cos ξ2u + D sin ξ2u + E u + F`, built from
/// [`printed_constants`] term by term as printed, with the restoration of
/// [`printed_constants`] and a leading minus on `g_1`, `g_2`, `g_3`, `g_6`.
/// `g_2` is as printed: it has no `cos ξ2u` term (`C = 0`); with
/// `with_d9` its missing term `d_9 cos ξ2u` is added.
pub fn g_printed_coefficients(x1: f64, x2: f64, with_d9: bool) -> [[f64; 6]; 6] {
    let (e, d) = printed_constants(x1, x2);
    let e11p = e[11] + 1.0;
    let (d12, d34, e910) = (d[1] + d[2], d[3] + d[4], e[9] + e[10]);
    let (e3d, e6d) = (e[5] * e[9] + e[6] * e[10], e[7] * e[9] + e[8] * e[10]);
    [
        [
            -d[1],
            -d[4],
            d[1] * e11p,
            e[9],
            -(x2 * e[9] - x1 * d[4]),
            -(e[11] * d[1] - 1.0),
        ],
        [
            -d12,
            -d34,
            if with_d9 { d[9] } else { 0.0 },
            e910,
            -(x2 * e910 - x1 * d34 - 1.0),
            -e[11] * d12,
        ],
        [
            -d[5],
            -d[7],
            d[10],
            e3d + e[12] / x2,
            -(x2 * e3d - x1 * d[7] + e[12]),
            -(e[11] * d[5] - 1.0 / (x2 * x2)),
        ],
        [
            d[1],
            d[4],
            -d[1] * e11p,
            -e[9],
            x2 * e[9] - x1 * d[4],
            e[11] * d[1],
        ],
        [
            d[2],
            d[3],
            -d[2] * e11p,
            -e[10],
            x2 * e[10] - x1 * d[3],
            e[11] * d[2],
        ],
        [
            -d[6],
            -d[8],
            d[6] * e11p,
            e6d - e[13] / x2,
            -(x2 * e6d - x1 * d[8] - e[13]),
            -e[11] * d[6],
        ],
    ]
}

/// `g_k(t)` from its coefficients `(A, B, C, D, E, F)` (any [`Real`]).
pub fn g_from_coefficients<T: Real>(c: &[f64; 6], x1: f64, x2: f64, t: T) -> T {
    (t * x1).cos() * c[0]
        + (t * x1).sin() * c[1]
        + (t * x2).cos() * c[2]
        + (t * x2).sin() * c[3]
        + t * c[4]
        + c[5]
}
