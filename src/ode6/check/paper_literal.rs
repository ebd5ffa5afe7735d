//! Paper-literal checks of paper 004: the printed forms built as printed.

use super::*;
use crate::check::{Measure, Worst};

/// Printed eqs 14-15, 20-22.
pub(super) fn paper_literal_checks() -> Vec<Check> {
    let (rho, eta, lambda) = (1.0, 3.0, 1.0);
    let lit = paper::xi_printed(rho, eta, lambda);
    let int = paper::xi_intended(rho, eta, lambda);
    let q = Params::new(rho, eta, lambda).q_roots();
    let intended_ok = (int[0] * int[0] + q[0].0)
        .abs()
        .worst((int[1] * int[1] + q[1].0).abs());
    let diff = (lit[0] - int[0]).abs().worst((lit[1] - int[1]).abs());
    let mut out = vec![
        ck("eqs 14-16", "ode6.xi_sqrt_restored", Kind::Reference, intended_ok, tol::ROUNDING, "xi_n^2 = -q_n with the square roots of eq 15 restored (rho = lambda = 1, eta = 3)"),
        Check::paper_literal(FAMILY, PAPER, "eq 15", "ode6.paper_literal.xi_eq15", diff, tol::SOLVE, true)
            .note("eq 15 as extracted (no square roots) against the intended xi (extraction loss, see ERRATA)"),
    ];
    // eq 14 as extracted, and with its minus and root restored, in eq 13
    let qp = paper::q_printed(rho, eta, lambda);
    let qr = paper::q_restored(rho, eta, lambda);
    let res = |q: [f64; 2]| {
        paper::eq13_residual(rho, eta, lambda, q[0])
            .worst(paper::eq13_residual(rho, eta, lambda, q[1]))
    };
    let ours = [q[0].0, q[1].0];
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 14", "ode6.paper_literal.q_eq14", res(qp), tol::SOLVE, true)
            .note(format!("eq 14 evaluated as extracted, eta(1 +- (1 - 4 rho lambda/eta^2))/(2 rho) = ({:.4}, {:.4}) at rho = lambda = 1, eta = 3: residual of eq 13 rho q^2 + eta q + lambda (extraction loss of the minus and the root)", qp[0], qp[1])),
    );
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 14", "ode6.paper_literal.q_eq14_restored", res(qr).worst((qr[0] - ours[0]).abs().worst((qr[1] - ours[1]).abs())), tol::ROUNDING, false)
            .note(format!("eq 14 with the leading minus and the square root restored, ({:.6}, {:.6}): residual of eq 13 and difference from the basis's own roots", qr[0], qr[1])),
    );
    eq20_restoration_checks(&mut out);
    out
}

/// The golden of `verify/ode6_eq20_40digits.py`: three parameter cases,
/// their roots and the exact coefficients of g_1..g_6 at 40 digits (rows
/// `A cos xi1 u, B sin xi1 u, C cos xi2 u, D sin xi2 u, E u, F`).
const EQ20_GOLDEN: &str = include_str!("../../../verify/golden/ode6_eq20_restored.json");

/// One case of the golden: `(rho, eta, lambda, xi1, xi2, exact)`.
type Eq20Case = (f64, f64, f64, f64, f64, [[f64; 6]; 6]);

fn eq20_cases() -> Vec<Eq20Case> {
    let golden: serde_json::Value = serde_json::from_str(EQ20_GOLDEN).unwrap_or_default();
    let f = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
    let Some(cases) = golden["cases"].as_array() else {
        return Vec::new();
    };
    cases
        .iter()
        .map(|c| {
            let exact = std::array::from_fn(|k| std::array::from_fn(|j| f(&c["exact"][k][j])));
            (
                f(&c["rho"]),
                f(&c["eta"]),
                f(&c["lambda"]),
                f(&c["xi1"]),
                f(&c["xi2"]),
                exact,
            )
        })
        .collect()
}

/// Largest difference of the printed `g_k` (k in `ks`, coefficients `c`)
/// from the project's basis in value, first and second derivative at 11 u,
/// relative to the largest |project's g_k^(d)| there; NaN when the basis
/// cannot be built.
fn printed_vs_basis(p: Params, x: (f64, f64), c: &[[f64; 6]; 6], ks: &[usize]) -> f64 {
    let Ok(b) = Basis::new(p) else {
        return f64::NAN;
    };
    let us: Vec<Jet<3, 1>> = (0..=10).map(|i| Jet::var_u(i as f64 / 10.0)).collect();
    let ours: Vec<[Jet<3, 1>; 6]> = us.iter().map(|&u| b.g(u)).collect();
    let mut err = 0.0f64;
    for &k in ks {
        for d in 0..3 {
            let scale = ours.iter().map(|g| g[k].deriv(d, 0)).max_abs();
            for (u, g) in us.iter().zip(&ours) {
                let printed = paper::g_from_coefficients(&c[k], x.0, x.1, *u).deriv(d, 0);
                err = err.worst((printed - g[k].deriv(d, 0)).abs() / scale);
            }
        }
    }
    err
}

/// Eqs 20-22 restored as `verify/ode6_eq20_40digits.py` finds (40 digits:
/// every gap a minus, "cos 2 xi2" as cos^2 xi2, a leading minus in d2, d4,
/// d10, inside e4's bracket and before g1, g2, g3, g6): the constants
/// against the exact coefficients they stand for (signed), the printed g_k
/// against the project's basis, and g_2's missing term.
fn eq20_restoration_checks(out: &mut Vec<Check>) {
    let cases = eq20_cases();
    let none = if cases.is_empty() { f64::NAN } else { 0.0 };
    let (mut consts, mut e22, mut g_ok, mut g2_d9) = (none, none, none, none);
    let mut g2_missing = if cases.is_empty() {
        f64::NAN
    } else {
        f64::INFINITY
    };
    for (rho, eta, lambda, x1, x2, g) in &cases {
        let (e, d) = paper::printed_constants(*x1, *x2);
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
        // each constant where it stands alone in a printed g_k (eq 20):
        // g1 = -d1 cos - d4 sin ..., g5 = d2 cos + d3 sin ..., g3 = -d5 cos
        // - d7 sin + d10 cos xi2 u, g6 = -d6 cos - d8 sin, g2's missing d9
        for (a, b) in [
            (-d[1], g[0][0]),
            (-d[4], g[0][1]),
            (d[2], g[4][0]),
            (d[3], g[4][1]),
            (-d[5], g[2][0]),
            (-d[7], g[2][1]),
            (d[10], g[2][2]),
            (-d[6], g[5][0]),
            (-d[8], g[5][1]),
            (d[9], g[1][2]),
        ] {
            consts = consts.worst(rel(a, b));
        }
        // eq 22: e9, e10 (sin xi2 u of g1, g5) and e11 (C = d1 (e11 + 1) of g1)
        for (a, b) in [
            (e[9], g[0][3]),
            (-e[10], g[4][3]),
            (d[1] * (e[11] + 1.0), g[0][2]),
        ] {
            e22 = e22.worst(rel(a, b));
        }
        let p = Params::new(*rho, *eta, *lambda);
        let printed = paper::g_printed_coefficients(*x1, *x2, false);
        let with_d9 = paper::g_printed_coefficients(*x1, *x2, true);
        g_ok = g_ok.worst(printed_vs_basis(p, (*x1, *x2), &printed, &[0, 2, 3, 4, 5]));
        g2_d9 = g2_d9.worst(printed_vs_basis(p, (*x1, *x2), &with_d9, &[1]));
        g2_missing = g2_missing.least(printed_vs_basis(p, (*x1, *x2), &printed, &[1]));
    }
    let n = cases.len();
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eqs 21, 22", "ode6.paper_literal.eq21_22_constants_restored", consts, tol::SOLVE, false)
            .note(format!("{n} parameter cases: d1..d10 of eq 21 as printed, restored (every gap a minus, cos^2 xi2 in e6, a leading minus in d2, d4, d10 and inside e4's bracket: verify/ode6_eq20_40digits.py), against the 40-digit exact coefficients each stands for in eq 20 (signed, relative): d1, d4 of g1, d2, d3 of g5, d5, d7, d10 of g3, d6, d8 of g6, and d9 = the cos xi2 u coefficient of g2 that eq 20 omits")),
    );
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 22", "ode6.paper_literal.eq22_e9_e10_e11_restored", e22, tol::SOLVE, false)
            .note(format!("{n} parameter cases: e9, e10 and (e11 + 1) d1 of eq 22 as printed (gaps restored as minus signs) against the 40-digit exact sin xi2 u coefficients of g1 and g5 (e9, -e10) and cos xi2 u of g1, signed, relative")),
    );
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 20", "ode6.paper_literal.g_eq20", g_ok, tol::SOLVE, false)
            .note(format!("{n} parameter cases: g1, g3, g4, g5, g6 of eq 20 as printed with the 40-digit restoration (one leading minus each on g1, g3, g6) against the project's basis (Basis::g, jets): value, first and second derivative at 11 u, relative to the basis's largest |g^(d)|")),
    );
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 20", "ode6.paper_literal.g2_missing_term", g2_missing, tol::DETECTED, true)
            .note(format!("{n} parameter cases: g2 of eq 20 as printed (restored, leading minus) has no cos xi2 u term: its difference from the project's basis g2 (value and two derivatives at 11 u, relative), smallest over the cases")),
    );
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 20", "ode6.paper_literal.g2_with_d9_term", g2_d9, tol::SOLVE, false)
            .note(format!("{n} parameter cases: the printed g2 plus the missing d9 cos xi2 u (d9 = (e11 + 1)(d1 + d2) as printed in eq 21) against the project's basis g2 (value and two derivatives at 11 u, relative)")),
    );
}
