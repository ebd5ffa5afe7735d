//! One check per numbered equation of paper 001's model (eqs 2, 5, 6, 8-11):
//! the printed operator against an independent 13-point finite-difference
//! biharmonic (also applied to the implementation's eq 12), the printed PDE,
//! boundary and printed derivatives measured with jets on the
//! implementation, and the assumed form and its constant against an
//! independent Morley finite-element solve of the clamped disk.

use super::*;
use crate::check::{Measure, Worst};

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
    // eqs 2 and 6 define the operator; the plate code has no operator of its
    // own (its deformation is the closed form eq 12), so the check holds the
    // printed operator (jets) against the 13-point stencil on a test field
    // and applies the stencil to the implementation's eq 12, D nabla^4 xi = q
    let op = pts
        .iter()
        .map(|&(u, v)| {
            let a = printed_biharmonic(test_field, u, v);
            let b = stencil_biharmonic(test_field, u, v);
            let ours = d * stencil_biharmonic(disk, u, v);
            ((a - b).abs() / a.abs().worst(1.0)).worst((ours - q).abs() / q)
        })
        .max_nan();
    for (eq, name, vars) in [
        ("eq 2", "plate.eq2.biharmonic_operator", "x, y"),
        ("eq 6", "plate.eq6.biharmonic_operator", "u, v"),
    ] {
        out.push(
            Check::new(F, P, eq, name, Kind::Reference, op, STENCIL_TOL)
                .note(format!("the printed nabla^4 = d4/d{vars}^4 terms (f_4,0 + 2 f_2,2 + f_0,4 from jets) against the 13-point finite-difference biharmonic (h = 1e-2) of sin(1.3u)cos(0.7v) + u^2v^2/2, and the stencil applied to the implementation's disk_solution (eq 12, q = 3.7, D = 0.9): D nabla^4 xi against q, 4 points, relative (the operator has no code of its own)")),
        );
    }
    // eq 5: D_xi nabla^4 xi = q_xi, per coordinate with its own D and q
    let mut res5 = 0.0f64;
    for (qx, dx) in [(1.0, 2.0), (-0.4, 0.3), (2.5, 1.1)] {
        for &(u, v) in &pts {
            let r = (dx * printed_biharmonic(|u, v| disk_solution(qx, dx, u, v), u, v) - qx).abs()
                / qx.abs();
            res5 = res5.worst(r);
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
        .max_nan();
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
    // eqs 9, 11: the assumed form and its constant against an independent
    // numerical solve of the clamped unit disk (Morley elements)
    let (shape, centre) = morley_disk(q, d).unwrap_or((f64::NAN, f64::NAN));
    out.push(
        Check::new(F, P, "eq 9", "plate.eq9.assumed_form", Kind::Reference, shape, MORLEY_DISK_TOL)
            .note(format!("the shape of the implementation's xi (disk_solution, eq 9's m (u^2+v^2-1)^2 with eq 11's m) against the Morley finite-element solution of D nabla^4 w = q, w = dw/dn = 0 on the unit circle ({MORLEY_DISK_RINGS} rings, q = 3.7, D = 0.9): max |xi/xi(0) - w/w(0)| over the mesh vertices")),
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
                .worst((w.deriv(0, 1) - 4.0 * m * v * s).abs())
                / m
        })
        .max_nan();
    out.push(
        Check::paper_literal(F, P, "eq 10", "plate.eq10.printed_derivatives", d10, tol::ROUNDING, false)
            .note("the printed xi_u = 4 m u (u^2+v^2-1), xi_v = 4 m v (u^2+v^2-1) against jet derivatives of the implementation's eq 12, inside and on the circle (relative to m)"),
    );
    out.push(
        Check::new(F, P, "eq 11", "plate.eq11.printed_constant", Kind::Reference, centre, MORLEY_DISK_TOL)
            .note(format!("the implementation's centre deflection xi(0, 0) = m (eq 11's q/(64 D) inside disk_solution) against the Morley finite-element centre deflection of the clamped unit disk ({MORLEY_DISK_RINGS} rings, q = 3.7, D = 0.9), relative")),
    );
}

/// Rings of the Morley disk mesh of the eq 9 and eq 11 checks (raw centre
/// error 0.36 % at 24 rings, 0.09 % at 48: order 2).
const MORLEY_DISK_RINGS: usize = 24;
/// Bound on the eq 9 / eq 11 comparisons with the Morley solution at
/// [`MORLEY_DISK_RINGS`]: the discretisation error there (0.36 % at the
/// centre, order 2) with a factor 2 for the shape's worst vertex.
const MORLEY_DISK_TOL: f64 = 1e-2;

/// The implementation's eq 12 on the clamped unit disk against the Morley
/// solution with the same `q` and `D`: (max shape error relative to the
/// centre value, relative centre error).
fn morley_disk(q: f64, d: f64) -> Result<(f64, f64), PlateError> {
    let (pts, tris) = ellipse_mesh(1.0, 1.0, MORLEY_DISK_RINGS)?;
    let w = solve_clamped(&pts, &tris, &vec![q; pts.len()], d)?.w;
    let ours: Vec<f64> = pts
        .iter()
        .map(|p| disk_solution(q, d, p[0], p[1]))
        .collect();
    let shape = pts
        .iter()
        .enumerate()
        .map(|(i, _)| (ours[i] / ours[0] - w[i] / w[0]).abs())
        .max_nan();
    Ok((shape, (ours[0] - w[0]).abs() / w[0].abs()))
}
