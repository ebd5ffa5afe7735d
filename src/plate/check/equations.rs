//! One check per numbered equation of paper 001's model (eqs 2, 5, 6, 8-11):
//! the printed operator against an independent 13-point finite-difference
//! biharmonic, the printed PDE, boundary, assumed form, printed derivatives
//! and the printed constant, each built as printed and measured with jets.

use super::*;

/// Step of the 13-point biharmonic stencil; its truncation error is
/// O(h^2) times sixth derivatives (below 1e3 here) and its rounding
/// eps |f| / h^4.
const STENCIL_STEP: f64 = 1e-2;
/// Tolerance of the stencil comparison (relative, the larger of the two
/// error sources above at STENCIL_STEP).
const STENCIL_TOL: f64 = 1e-4;

/// A smooth non-polynomial test field with non-zero mixed derivatives.
fn test_field<T: crate::jet::Real>(u: T, v: T) -> T {
    (u * 1.3).sin() * (v * 0.7).cos() + u * u * v * v * 0.5
}

/// Eq 2 / eq 6 as printed: `f_uuuu + 2 f_uuvv + f_vvvv` from jets.
fn printed_biharmonic(f: impl Fn(Jet4x4, Jet4x4) -> Jet4x4, u: f64, v: f64) -> f64 {
    let w = f(Jet4x4::var_u(u), Jet4x4::var_v(v));
    w.deriv(4, 0) + 2.0 * w.deriv(2, 2) + w.deriv(0, 4)
}

/// The classical 13-point stencil of the biharmonic operator.
fn stencil_biharmonic(f: impl Fn(f64, f64) -> f64, u: f64, v: f64) -> f64 {
    let h = STENCIL_STEP;
    let p = |i: f64, j: f64| f(u + i * h, v + j * h);
    let s = 20.0 * p(0.0, 0.0) - 8.0 * (p(1.0, 0.0) + p(-1.0, 0.0) + p(0.0, 1.0) + p(0.0, -1.0))
        + 2.0 * (p(1.0, 1.0) + p(1.0, -1.0) + p(-1.0, 1.0) + p(-1.0, -1.0))
        + p(2.0, 0.0)
        + p(-2.0, 0.0)
        + p(0.0, 2.0)
        + p(0.0, -2.0);
    s / h.powi(4)
}

pub(super) fn equation_checks(out: &mut Vec<Check>) {
    let pts = [(0.1, 0.2), (-0.3, 0.4), (0.5, -0.25), (0.0, 0.0)];
    let (q, d) = (3.7, 0.9);
    let disk = |u: f64, v: f64| disk_solution(q, d, u, v);
    // eqs 2 and 6: the printed operator vs the stencil, x-y and u-v names
    let op = pts
        .iter()
        .map(|&(u, v)| {
            let a = printed_biharmonic(test_field, u, v);
            let b = stencil_biharmonic(test_field, u, v);
            (a - b).abs() / a.abs().max(1.0)
        })
        .fold(0.0, f64::max);
    for (eq, name, vars) in [
        ("eq 2", "plate.eq2.biharmonic_operator", "x, y"),
        ("eq 6", "plate.eq6.biharmonic_operator", "u, v"),
    ] {
        out.push(
            Check::new(F, P, eq, name, Kind::Reference, op, STENCIL_TOL)
                .note(format!("the printed nabla^4 = d4/d{vars}^4 terms (f_4,0 + 2 f_2,2 + f_0,4 from jets) against the 13-point finite-difference biharmonic (h = 1e-2) of sin(1.3u)cos(0.7v) + u^2v^2/2 at 4 points, relative")),
        );
    }
    // eq 5: D_xi nabla^4 xi = q_xi, per coordinate with its own D and q
    let mut res5 = 0.0f64;
    for (qx, dx) in [(1.0, 2.0), (-0.4, 0.3), (2.5, 1.1)] {
        for &(u, v) in &pts {
            let r = (dx * printed_biharmonic(|u, v| disk_solution(qx, dx, u, v), u, v) - qx).abs()
                / qx.abs();
            res5 = res5.max(r);
        }
    }
    out.push(
        Check::new(F, P, "eq 5", "plate.eq5.per_coordinate_residual", Kind::Residual, res5, tol::ROUNDING)
            .note("|D_xi nabla^4 xi - q_xi| / |q_xi| of eq 12 for three coordinates with different D_xi and q_xi (one negative), 4 points, jets"),
    );
    // eq 8: the boundary circle; the deformation vanishes there
    let b8 = (0..32)
        .map(|k| {
            let t = 2.0 * std::f64::consts::PI * k as f64 / 32.0;
            let (u, v) = (t.cos(), t.sin());
            (u * u + v * v - 1.0).abs() + disk(u, v).abs() / (q / d)
        })
        .fold(0.0, f64::max);
    out.push(
        Check::new(
            F,
            P,
            "eq 8",
            "plate.eq8.boundary_circle",
            Kind::Boundary,
            b8,
            tol::ROUNDING,
        )
        .note("32 points of u^2 + v^2 - 1 = 0: the circle residual plus |xi| / (q/D) there"),
    );
    // eq 9: the solution has the assumed form m (u^2+v^2-1)^2 with one m
    let ms: Vec<f64> = pts
        .iter()
        .map(|&(u, v)| disk(u, v) / (u * u + v * v - 1.0).powi(2))
        .collect();
    let spread = ms.iter().fold(0.0f64, |a, m| a.max((m - ms[0]).abs())) / ms[0].abs();
    out.push(
        Check::new(
            F,
            P,
            "eq 9",
            "plate.eq9.assumed_form",
            Kind::Reference,
            spread,
            tol::ROUNDING,
        )
        .note("xi / (u^2+v^2-1)^2 is one constant m at 4 interior points (relative spread)"),
    );
    // eq 10: the printed first derivatives against jets
    let m = q / (64.0 * d);
    let d10 = pts
        .iter()
        .chain(&[(0.6, 0.8), (-1.0, 0.0)])
        .map(|&(u, v)| {
            let w = disk_solution(q, d, Jet4x4::var_u(u), Jet4x4::var_v(v));
            let s = u * u + v * v - 1.0;
            (w.deriv(1, 0) - 4.0 * m * u * s)
                .abs()
                .max((w.deriv(0, 1) - 4.0 * m * v * s).abs())
                / m
        })
        .fold(0.0, f64::max);
    out.push(
        Check::paper_literal(F, P, "eq 10", "plate.eq10.printed_derivatives", d10, tol::ROUNDING, false)
            .note("the printed xi_u = 4 m u (u^2+v^2-1), xi_v = 4 m v (u^2+v^2-1) against jet derivatives of eq 9, inside and on the circle (relative to m)"),
    );
    // eq 11: m solved from eq 9 in eq 5 (nabla^4 of the form by jets) vs printed q/(64 D)
    let unit = printed_biharmonic(
        |u, v| {
            let s = u * u + v * v - 1.0;
            s * s
        },
        0.2,
        0.3,
    );
    let m_solved = q / (d * unit);
    out.push(
        Check::paper_literal(F, P, "eq 11", "plate.eq11.printed_constant", rel_err(m_solved, m) / m.abs().min(1.0), tol::ROUNDING, false)
            .note(format!("m solved from D nabla^4 [m (u^2+v^2-1)^2] = q with nabla^4 from jets ({unit}) against the printed q/(64 D)")),
    );
}
