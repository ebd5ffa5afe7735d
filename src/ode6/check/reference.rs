//! Reference checks: series solutions and difference formulas against the exact basis.

use super::*;
use crate::check::Worst;

/// The series and the closed forms agree where both apply.
pub(super) fn series_checks() -> Vec<Check> {
    let mut worst = 0.0f64;
    for p in [
        Params::new(1.0, 3.0, 1.0),
        Params::new(1.0, 1.0, 3.0),
        Params::new(1.0, 2.0, 1.0),
        Params::new(1.0, -2.5, 1.5),
        Params::new(1.0, 0.5, -2.0),
    ] {
        let (Ok(a), Ok(b)) = (Basis::new(p), Basis::with_case(p, classify_closed(&p))) else {
            worst = f64::NAN;
            continue;
        };
        for i in 0..=10 {
            let u = i as f64 / 10.0;
            let (ga, gb) = (a.g(u), b.g(u));
            for j in 0..6 {
                worst = worst.worst((ga[j] - gb[j]).abs());
            }
        }
    }
    vec![ck(
        "eq 19",
        "ode6.series_vs_closed_form",
        Kind::Reference,
        worst,
        tol::SOLVE,
        "Taylor-series basis against the closed-form case bases for |q| <= 4 (distinct, complex, repeated, growing, mixed roots)",
    )]
}

/// Approach 2: what eqs 4-7 and the three-point formulas differentiate.
pub(super) fn difference_checks() -> Vec<Check> {
    // f(u) = exp(u) + sin(3u) on both ends, control curves close to the ends.
    let f = |u: f64| u.exp() + (3.0 * u).sin();
    let (f1, f2) = (
        |u: f64| u.exp() + 3.0 * (3.0 * u).cos(),
        |u: f64| u.exp() - 9.0 * (3.0 * u).sin(),
    );
    let err_at = |h: f64, formula: DiffFormula, ratio: f64| -> [f64; 4] {
        let a = Approach2 {
            u2: h,
            u3: ratio * h,
            u5: 1.0 - ratio * h,
            u6: 1.0 - h,
            formula,
        };
        let Ok(d) = a.derivatives([f(0.0), f(a.u2), f(a.u3), f(a.u5), f(a.u6), f(1.0)]) else {
            return [f64::NAN; 4];
        };
        [
            (d[0] - f1(0.0)).abs(),
            (d[1] - f2(0.0)).abs(),
            (d[2] - f1(1.0)).abs(),
            (d[3] - f2(1.0)).abs(),
        ]
    };
    let order = |e1: f64, e2: f64| (e1 / e2).log2();
    let c = err_at(1e-2, DiffFormula::ThreePoint, 3.0);
    let c2 = err_at(5e-3, DiffFormula::ThreePoint, 3.0);
    let p = err_at(1e-3, DiffFormula::Printed, 3.0);
    let p_eq = err_at(1e-3, DiffFormula::Printed, 2.0);
    // Exactness on a quadratic.
    let quad = |u: f64| 2.0 - u + 1.5 * u * u;
    let a = Approach2 {
        u2: 0.1,
        u3: 0.25,
        u5: 0.8,
        u6: 0.9,
        formula: DiffFormula::ThreePoint,
    };
    let exact = a
        .derivatives([
            quad(0.0),
            quad(0.1),
            quad(0.25),
            quad(0.8),
            quad(0.9),
            quad(1.0),
        ])
        .map(|d| {
            (d[0] + 1.0)
                .abs()
                .worst((d[1] - 3.0).abs())
                .worst((d[2] - 2.0).abs())
                .worst((d[3] - 3.0).abs())
        })
        .unwrap_or(f64::NAN);
    vec![
        ck("eqs 3-7", "ode6.three_point_exact_on_quadratics", Kind::Reference, exact, tol::ROUNDING * 100.0, "three-point first and second derivatives of 2 - u + 1.5 u^2 at both ends (u2, u3, u5, u6 = 0.1, 0.25, 0.8, 0.9)"),
        ck(
            "eqs 3-7",
            "ode6.three_point_first_derivative_order2",
            Kind::Reference,
            (2.0 - order(c[0], c2[0]).least(order(c[2], c2[2]))).worst(0.0),
            0.1,
            "observed order of the three-point first derivatives (h = 1e-2, 5e-3) is 2: measured 2 - order",
        ),
        Check::paper_literal(FAMILY, PAPER, "eq 5", "ode6.paper_literal.c3_eq5", p[1].worst(p[3]), 0.5, true).note(format!(
            "printed c3, c6 with u3 = 3 u2 (h = 1e-3) converge to u3/(2 u2) f'' = 1.5 f'', not f'': errors {:.3}, {:.3}",
            p[1], p[3]
        )),
        Check::paper_literal(FAMILY, PAPER, "eq 5", "ode6.paper_literal.c3_eq5_equal_spacing", p_eq[1].worst(p_eq[3]), 0.05, false)
            .note("printed c3, c6 with u3 = 2 u2 (equal spacing) are first-order second derivatives (h = 1e-3)"),
        Check::paper_literal(FAMILY, PAPER, "eq 7", "ode6.paper_literal.c6_eq7", p[3], 0.5, true).note(format!(
            "printed c6 alone (the mirror of eq 5) with 1 - u5 = 3 (1 - u6) (h = 1e-3): error {:.3} in f''(1), converges to 1.5 f''",
            p[3]
        )),
        Check::paper_literal(FAMILY, PAPER, "eq 7", "ode6.paper_literal.c6_eq7_equal_spacing", p_eq[3], 0.05, false)
            .note("printed c6 with 1 - u5 = 2 (1 - u6) (equal spacing) is a first-order second derivative (h = 1e-3)"),
        Check::paper_literal(FAMILY, PAPER, "eqs 4, 6", "ode6.paper_literal.c2_eq4", p[0].worst(p[2]), 0.05, false)
            .note("printed c2, c5 are first-order one-sided first derivatives (h = 1e-3)"),
    ]
}
