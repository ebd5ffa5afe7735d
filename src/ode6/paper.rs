//! The printed forms of paper 004, literally, for the paper-literal checks.
//!
//! Eqs 14-15 as extracted read `q_{1,2} = η(1 ± 1 4ρλ/η²)/(2ρ)` and
//! `ξ_{1,2} = η(1 ± 1 4ρλ/η²)/(2ρ)` (identical texts: the minus sign and both
//! square roots are lost in the extraction). The intended forms are
//! $q_{1,2} = -\eta(1 \pm \sqrt{1 - 4\rho\lambda/\eta^2})/(2\rho)$ and
//! $\xi_{1,2} = \sqrt{\eta(1 \pm \sqrt{1 - 4\rho\lambda/\eta^2})/(2\rho)}$,
//! so that $r = \pm i\xi$ and $q = -\xi^2$ (eq 16).

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

/// Sign choices for the places where the extraction of eqs 20-22 lost a
/// sign that cannot be inferred: the leading sign of `e_4`'s bracket, of
/// `e_6`, of the `1/ξ2²` term of `d_10`, and of every `g_k`'s first term.
#[derive(Clone, Copy, Debug)]
pub struct PrintedSigns {
    pub e4: f64,
    pub e6: f64,
    pub d10: f64,
    pub lead: f64,
}

/// The constants `e_1..e_13` and `d_1..d_10` of eqs 21-22 as printed, the
/// lost minus signs restored between adjacent terms (index 0 unused).
pub fn printed_constants(x1: f64, x2: f64, s: PrintedSigns) -> ([f64; 14], [f64; 11]) {
    let (c1, s1, c2, s2) = (x1.cos(), x1.sin(), x2.cos(), x2.sin());
    let mut e = [0.0; 14];
    e[1] = x1 * (c1 - 1.0) + x1 * x1 * s1 * (1.0 - c2) / (x2 * s2);
    e[2] = s1 - x1 + x1 * x1 * s1 * (1.0 / s2 - 1.0 / x2) / x2;
    e[3] = c1 - 1.0
        + x1 * x1 * (1.0 - c2) / (x2 * x2)
        + x1 * x1 * (c2 - c1) * (1.0 / x2 - 1.0 / s2) / x2;
    e[4] = x1 * (s.e4 * s1 + x1 * s2 / x2) + x1 * x1 * (c2 - c1) * (c2 - 1.0) / (x2 * s2);
    e[5] = (1.0 / x2 - c2 / s2) / x2;
    e[6] = (s.e6 * s2 + c2 * c2 / s2 - c2 / s2) / x2;
    e[7] = (1.0 / s2 - 1.0 / x2) / x2;
    e[8] = (1.0 - c2) / (x2 * s2);
    e[11] = x1 * x1 / (x2 * x2) - 1.0;
    e[12] = c2 / (x2 * s2);
    e[13] = 1.0 / (x2 * s2);
    let den = e[1] * e[3] - e[2] * e[4];
    let mut d = [0.0; 11];
    d[1] = e[1] / den;
    d[2] = e[2] / den;
    d[3] = e[3] / den;
    d[4] = e[4] / den;
    d[5] = d[1] * e[5] + d[2] * e[6];
    d[6] = d[1] * e[7] + d[2] * e[8];
    d[7] = d[4] * e[5] + d[3] * e[6];
    d[8] = d[4] * e[7] + d[3] * e[8];
    d[10] = s.d10 / (x2 * x2) + (e[11] + 1.0) * d[5];
    e[9] = x1 * x1 * (d[4] * s1 - d[1] * (c2 - c1)) / (x2 * x2 * s2);
    e[10] = x1 * x1 * (d[3] * s1 - d[2] * (c2 - c1)) / (x2 * x2 * s2);
    (e, d)
}

/// The basis functions `g_1..g_6` of eq 20 with the constants of eqs 21-22
/// exactly as printed, the lost minus signs restored between adjacent terms.
pub fn g_printed(x1: f64, x2: f64, s: PrintedSigns, t: f64) -> [f64; 6] {
    let (e, d) = printed_constants(x1, x2, s);
    let (ca, sa, cb, sb) = (
        (x1 * t).cos(),
        (x1 * t).sin(),
        (x2 * t).cos(),
        (x2 * t).sin(),
    );
    let l = s.lead;
    [
        l * d[1] * ca - d[4] * sa + d[1] * (e[11] + 1.0) * cb + e[9] * sb
            - (x2 * e[9] - x1 * d[4]) * t
            - (e[11] * d[1] - 1.0),
        l * (d[1] + d[2]) * ca - (d[3] + d[4]) * sa + (e[9] + e[10]) * sb
            - (x2 * (e[9] + e[10]) - x1 * (d[3] + d[4]) - 1.0) * t
            - e[11] * (d[1] + d[2]),
        l * d[5] * ca - d[7] * sa + d[10] * cb + (e[5] * e[9] + e[6] * e[10] + e[12] / x2) * sb
            - (x2 * (e[5] * e[9] + e[6] * e[10]) - x1 * d[7] + e[12]) * t
            - (e[11] * d[5] - 1.0 / (x2 * x2)),
        l * d[1] * ca + d[4] * sa - d[1] * (e[11] + 1.0) * cb - e[9] * sb
            + (x2 * e[9] - x1 * d[4]) * t
            + e[11] * d[1],
        l * d[2] * ca + d[3] * sa - d[2] * (e[11] + 1.0) * cb - e[10] * sb
            + (x2 * e[10] - x1 * d[3]) * t
            + e[11] * d[2],
        l * d[6] * ca - d[8] * sa
            + d[6] * (e[11] + 1.0) * cb
            + (e[7] * e[9] + e[8] * e[10] - e[13] / x2) * sb
            - (x2 * (e[7] * e[9] + e[8] * e[10]) - x1 * d[8] - e[13]) * t
            - e[11] * d[6],
    ]
}

/// Smallest, over every sign choice and both orderings of `ξ1, ξ2`, of the
/// largest error of the printed `g_k` (k = 0..6) in the six constraints of
/// eq 1 (derivatives by central differences of step `h`).
pub fn g_printed_best_boundary_error(x1: f64, x2: f64, k: usize) -> f64 {
    let h = 1e-4;
    let mut best = f64::INFINITY;
    for bits in 0..16u32 {
        let sg = |b: u32| if bits & (1 << b) != 0 { -1.0 } else { 1.0 };
        let s = PrintedSigns {
            e4: sg(0),
            e6: sg(1),
            d10: sg(2),
            lead: sg(3),
        };
        for (a, b) in [(x1, x2), (x2, x1)] {
            let g = |t: f64| g_printed(a, b, s, t)[k];
            let mut err = 0.0f64;
            for (end, t) in [(0usize, 0.0), (1, 1.0)] {
                let vals = [
                    g(t),
                    (g(t + h) - g(t - h)) / (2.0 * h),
                    (g(t + h) - 2.0 * g(t) + g(t - h)) / (h * h),
                ];
                for (i, v) in vals.iter().enumerate() {
                    let target = if 3 * end + i == k { 1.0 } else { 0.0 };
                    err = err.max((v - target).abs());
                }
            }
            if err.is_finite() {
                best = best.min(err);
            }
        }
    }
    best
}
