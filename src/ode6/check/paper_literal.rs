//! Paper-literal checks of paper 004: the printed forms built as printed.

use super::*;

/// Printed eqs 14-15, 20-22.
pub(super) fn paper_literal_checks() -> Vec<Check> {
    let (rho, eta, lambda) = (1.0, 3.0, 1.0);
    let lit = paper::xi_printed(rho, eta, lambda);
    let int = paper::xi_intended(rho, eta, lambda);
    let q = Params::new(rho, eta, lambda).q_roots();
    let intended_ok = (int[0] * int[0] + q[0].0)
        .abs()
        .max((int[1] * int[1] + q[1].0).abs());
    let diff = (lit[0] - int[0]).abs().max((lit[1] - int[1]).abs());
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
            .max(paper::eq13_residual(rho, eta, lambda, q[1]))
    };
    let ours = [q[0].0, q[1].0];
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 14", "ode6.paper_literal.q_eq14", res(qp), tol::SOLVE, true)
            .note(format!("eq 14 evaluated as extracted, eta(1 +- (1 - 4 rho lambda/eta^2))/(2 rho) = ({:.4}, {:.4}) at rho = lambda = 1, eta = 3: residual of eq 13 rho q^2 + eta q + lambda (extraction loss of the minus and the root)", qp[0], qp[1])),
    );
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 14", "ode6.paper_literal.q_eq14_restored", res(qr).max((qr[0] - ours[0]).abs().max((qr[1] - ours[1]).abs())), tol::ROUNDING, false)
            .note(format!("eq 14 with the leading minus and the square root restored, ({:.6}, {:.6}): residual of eq 13 and difference from the basis's own roots", qr[0], qr[1])),
    );
    let mut worst_printed = f64::INFINITY;
    let mut best_printed = 0.0f64;
    for k in 0..6 {
        let e = paper::g_printed_best_boundary_error(int[0], int[1], k);
        worst_printed = worst_printed.min(e);
        best_printed = best_printed.max(e);
    }
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eqs 20-22", "ode6.paper_literal.g_eq20", worst_printed, 1e-3, true).note(format!(
            "printed g_1..g_6 (lost minus signs restored, all 16 sign choices, both xi orders) at rho = lambda = 1, eta = 3: smallest constraint error over k {worst_printed:.3} (largest {best_printed:.3})"
        )),
    );
    out
}
