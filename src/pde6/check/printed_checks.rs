//! Checks of paper 002 eqs 3-6, 9-24, 27 built as printed (issue 17): the
//! printed series, derivative formulas and linear systems against the
//! project's closed form (jets), on the method-2 chain through the 12
//! synthetic sections in the paper's Fig 4 layout ([`paper_layout_sections`]).

use super::printed::*;
use super::*;
use crate::check::{worst, Worst};

/// u samples on a patch (local parameter).
const US: [f64; 9] = [0.0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0];

/// |x - y| / max(|y|, 1); NaN stays NaN.
pub(super) fn rel(x: f64, y: f64) -> f64 {
    (x - y).abs() / y.abs().worst(1.0)
}

/// A patch's point from the printed series (eqs 3-5 / 14): x = A_x0 +
/// sum(A_xn cos nv + B_xn sin nv), y = A_y0 + sum(A_yn sin nv + B_yn cos nv),
/// z = A_z0, each function from the project's closed form.
pub fn printed_series_point(p: &Patch, u: f64, v: f64) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (role, n, k, b, c) in functions(p) {
        let f = project_function(&b, &c, u, 0);
        let (cn, sn) = ((n as f64 * v).cos(), (n as f64 * v).sin());
        out[k] += match (role, k) {
            (Role::W0, _) => f,
            (Role::A, 0) | (Role::B, 1) => f * cn,
            _ => f * sn,
        };
    }
    out
}

/// Max over pieces, u samples and 16 v of the printed series against the
/// patch's own evaluation, coordinate `k` (or all for `None`).
fn series_error(pieces: &[&Piece], k: Option<usize>) -> f64 {
    let mut e = 0.0f64;
    for piece in pieces {
        for &u in &US {
            for j in 0..16 {
                let v = 2.0 * PI * j as f64 / 16.0 + 0.05;
                let (a, b) = (
                    printed_series_point(&piece.patch, u, v),
                    piece.patch.eval(u, v),
                );
                for kk in 0..3 {
                    if k.is_none_or(|k| k == kk) {
                        e = worst(e, rel(a[kk], b[kk]));
                    }
                }
            }
        }
    }
    e
}

/// The section's coefficient the paper calls a_wn / b_wn / a_w0 (eq 9).
fn curve_coef(c: &Fourier3, role: Role, n: usize, k: usize) -> f64 {
    let (cn, sn) = c.harmonic(n, k);
    match (role, k) {
        (Role::W0, _) => cn,
        (Role::A, 0) | (Role::B, 1) => cn,
        _ => sn,
    }
}

/// Eq 9 as printed for one curve.
fn eq9_point(c: &Fourier3, v: f64) -> [f64; 3] {
    let mut p = [c.c0[0], c.c0[1], c.c0[2]];
    for n in 1..=c.harmonics() {
        let (cn, sn) = ((n as f64 * v).cos(), (n as f64 * v).sin());
        p[0] += curve_coef(c, Role::A, n, 0) * cn + curve_coef(c, Role::B, n, 0) * sn;
        p[1] += curve_coef(c, Role::A, n, 1) * sn + curve_coef(c, Role::B, n, 1) * cn;
    }
    p
}

/// Max error of the printed derivative formulas (eqs 10-13) over the
/// functions of `role`s of the pieces: `d` = 1 or 2.
fn derivative_error(pieces: &[&Piece], roles: &[Role], d: usize, b_as_printed: bool) -> f64 {
    let mut e = 0.0f64;
    for piece in pieces {
        for (role, _, _, b, c) in functions(&piece.patch) {
            if !roles.contains(&role) {
                continue;
            }
            let Some(pc) = to_paper_basis(&b, &c) else {
                return f64::NAN;
            };
            let (q1, q2) = q12(&b);
            for &u in &US {
                let printed = match (role, d) {
                    (Role::W0, 1) => eq10(&pc, u),
                    (Role::W0, _) => eq12(&pc, u),
                    (r, 1) => eq11(&pc, q1, q2, u, b_as_printed && r == Role::B),
                    _ => eq13(&pc, q1, q2, u),
                };
                e = worst(e, rel(printed, project_function(&b, &c, u, d)));
            }
        }
    }
    e
}

/// Max error of the node conditions of eqs 16-18 (A31-A33): the functions of
/// `role` at `nodes` against the curves' coefficients.
pub(super) fn node_error(p: &Patch, nodes: &[f64], curves: &[&Fourier3], role: Role) -> f64 {
    let mut e = 0.0f64;
    for (r, n, k, b, c) in functions(p) {
        if r != role {
            continue;
        }
        for (&u, curve) in nodes.iter().zip(curves) {
            e = worst(
                e,
                rel(
                    project_function(&b, &c, u, 0),
                    curve_coef(curve, role, n, k),
                ),
            );
        }
    }
    e
}

/// Max error of the function solved from printed rows (eqs 21-23, A34-A36
/// with A27-A29) against the project's function, values and two
/// derivatives at the u samples.
pub(super) fn solved_rows_error(
    p: &Patch,
    role: Role,
    rows: impl Fn(&FnBasis) -> [[f64; 6]; 6],
    rhs: impl Fn(usize, usize) -> [f64; 6],
) -> f64 {
    let mut e = 0.0f64;
    for (r, n, k, b, c) in functions(p) {
        if r != role {
            continue;
        }
        let Some(pc) = solve_rows(rows(&b), rhs(n, k)) else {
            return f64::NAN;
        };
        for &u in &US {
            for d in 0..3 {
                e = worst(
                    e,
                    rel(
                        paper_function(&b, &pc, u, d),
                        project_function(&b, &c, u, d),
                    ),
                );
            }
        }
    }
    e
}

pub(super) fn printed_main_checks(out: &mut Vec<Check>) {
    let (name, a) = SIGNS[0];
    let sec = paper_layout_sections();
    let chain = match Chain::method2(a, &sec, 3) {
        Ok(c) if c.pieces.len() == 3 => c,
        _ => {
            out.push(Check::new(
                FAMILY,
                PAPER,
                "eqs 3-27",
                "pde6.printed.chain",
                Kind::Residual,
                f64::NAN,
                SOLVE_TOL,
            ));
            return;
        }
    };
    let layout = format!("method-2 chain, a = {a}, 12 synthetic sections with 6 harmonics in the paper's layout (P2 on C1-C4, P1 on C4-C9, P3 on C9-C12, unit local parameters)");

    series_checks(&chain, &sec, &layout, out);
    group_and_system_checks(&chain, &sec, a, out);
    derivative_checks(&chain, out);
    join_checks(&chain, &sec, name, &layout, out);
}

/// Eq 9's curves (the chain passes through them), the series of eqs 3-5
/// and 14, and eq 15: patch 1 through C4-C9.
fn series_checks(chain: &Chain, sec: &[Section], layout: &str, out: &mut Vec<Check>) {
    let (p2, p1, p3) = (&chain.pieces[0], &chain.pieces[1], &chain.pieces[2]);
    let all = [p2, p1, p3];
    // eq 9: the printed curves, and the chain passes through them
    let mut e9 = 0.0f64;
    for s in sec {
        for j in 0..16 {
            let v = 2.0 * PI * j as f64 / 16.0 + 0.05;
            let (a, b) = (eq9_point(&s.curve, v), chain.point(s.u, v));
            e9 = worst(
                e9,
                crate::mesh::dist(a, b) / crate::mesh::norm(a).worst(1.0),
            );
        }
    }
    out.push(Check::new(FAMILY, PAPER, "eq 9", "pde6.printed.eq9_curves", Kind::Residual, e9, tol::scaled(tol::ROUNDING, 10.0))
        .note(format!("the 12 curves C_i as printed (x = a_x0 + sum(a_xn cos nv + b_xn sin nv), y = a_y0 + sum(a_yn sin nv + b_yn cos nv), z = z_c) from the sections' coefficients against the project's chain at the section's u (it must pass through them), 16 v each, relative; {layout}")));
    // eqs 3, 4, 5, 14: the printed series
    for (eq, k, what) in [
        ("eq 3", Some(0), "x"),
        ("eq 4", Some(1), "y"),
        ("eq 5", Some(2), "z"),
    ] {
        out.push(Check::new(FAMILY, PAPER, eq, &format!("pde6.printed.eq{}_series_{what}", &eq[3..]), Kind::Residual, series_error(&all, k), tol::scaled(tol::ROUNDING, 10.0))
            .note(format!("{what} of eq {} built as printed from the harmonic functions (A_yn with sin nv, B_yn with cos nv for y) against the patch evaluation, all three patches of the {layout}", &eq[3..])));
    }
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq 14",
            "pde6.printed.eq14_patch1_series",
            Kind::Residual,
            series_error(&[p1], None),
            tol::scaled(tol::ROUNDING, 10.0),
        )
        .note("x^P1, y^P1, z^P1 of eq 14 built as printed against patch 1's evaluation"),
    );
    // eq 15: patch 1 through C4-C9 at u = 0.2 i (printed series)
    let mut e15 = 0.0f64;
    for i in 0..6 {
        for j in 0..16 {
            let v = 2.0 * PI * j as f64 / 16.0 + 0.05;
            let (a, b) = (
                printed_series_point(&p1.patch, 0.2 * i as f64, v),
                sec[3 + i].curve.eval(v),
            );
            e15 = worst(e15, crate::mesh::dist(a, b));
        }
    }
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq 15",
            "pde6.printed.eq15_patch1_through_c4_c9",
            Kind::Boundary,
            e15,
            SOLVE_TOL,
        )
        .note("the printed series of patch 1 at u = 0.2 i against C_{i+4}(v), i = 0..5, 16 v"),
    );
}

/// Eqs 16-18 (the three groups), 6 and A7 (the quintic form), 19 and 21
/// (patch 1's monomial system), 22-23 (the a < 0 systems) and eq 20 as
/// printed.
fn group_and_system_checks(chain: &Chain, sec: &[Section], a: f64, out: &mut Vec<Check>) {
    let (p2, p1, p3) = (&chain.pieces[0], &chain.pieces[1], &chain.pieces[2]);
    let all = [p2, p1, p3];
    let tol = PRINTED_TOL;
    // eqs 16-18: the three groups
    let curves: Vec<&Fourier3> = sec[3..9].iter().map(|s| &s.curve).collect();
    for (eq, role, what) in [
        ("eq 16", Role::W0, "a_w0"),
        ("eq 17", Role::A, "A_wn"),
        ("eq 18", Role::B, "B_wn"),
    ] {
        out.push(Check::new(FAMILY, PAPER, eq, &format!("pde6.printed.eq{}_group_{}", &eq[3..], what.to_lowercase()), Kind::Boundary, node_error(&p1.patch, &NODES_METHOD1, &curves, role), SOLVE_TOL)
            .note(format!("{eq}: patch 1's {what} functions at u = 0.2 i equal the curves' coefficients (x and y; z for n = 0)")));
    }
    // eqs 6, A7: the quintic form (Taylor coefficients at 0 reproduce the function)
    let mut e6 = 0.0f64;
    for piece in all {
        for (r, _, _, b, c) in functions(&piece.patch) {
            if r != Role::W0 {
                continue;
            }
            let j = {
                let p = b.project.eval(Jet::<6, 1>::var_u(0.0));
                let f: Vec<f64> = (0..6)
                    .map(|d| {
                        (0..6).map(|i| p[i].deriv(d, 0) * c[i]).sum::<f64>()
                            / crate::jet::factorial(d)
                    })
                    .collect();
                f
            };
            for &u in &US {
                let poly: f64 = (0..6).map(|d| j[d] * u.powi(d as i32)).sum();
                e6 = worst(e6, rel(poly, project_function(&b, &c, u, 0)));
            }
        }
    }
    out.push(Check::new(FAMILY, PAPER, "eqs 6, A7", "pde6.printed.eq6_quintic", Kind::Residual, e6, tol::scaled(tol::ROUNDING, 100.0))
        .note("A_w0 = a0 + a1 u + ... + a5 u^5 (eq 6, the same printed solution as A7): the quintic with the Taylor coefficients at u = 0 (jets) reproduces every n = 0 function of the three patches"));
    // eqs 19, 21: the monomial system of patch 1 as printed
    let e21 = solved_rows_error(
        &p1.patch,
        Role::W0,
        |_| std::array::from_fn(eq21_row),
        |n, k| std::array::from_fn(|i| curve_coef(curves[i], Role::W0, n, k)),
    );
    out.push(Check::new(FAMILY, PAPER, "eqs 19, 21", "pde6.printed.eq21_monomial_system", Kind::Reference, e21, tol)
        .note("eq 21's rows (1, 0.2i, 0.04i^2, 0.008i^3, 0.0016i^4, 0.00032i^5) solved for the curves' a_w0, the quintic of eq 19 against patch 1's A_w0: value, slope, curvature"));
    // eqs 22, 23: the printed a < 0 systems
    for (eq, role, what) in [("eq 22", Role::A, "a_wn"), ("eq 23", Role::B, "b_wn")] {
        let e = solved_rows_error(
            &p1.patch,
            role,
            |b| {
                let (q1, q2) = q12(b);
                std::array::from_fn(|i| eq22_row(i, q1, q2))
            },
            |n, k| std::array::from_fn(|i| curve_coef(curves[i], role, n, k)),
        );
        out.push(Check::new(FAMILY, PAPER, eq, &format!("pde6.printed.eq{}_system_{what}", &eq[3..]), Kind::Reference, e, tol)
            .note(format!("{eq}'s rows as printed (minus of e^(-0.2 i q1n) restored) solved for the curves' {what}, the eq 8 function against patch 1's (project basis): value, slope, curvature, n = 1..6")));
    }
    // eq 20 as printed: the a > 0 triple-root form for the a < 0 patch
    let mut e20 = 0.0f64;
    for n in 1..=6 {
        let b = ModeBasis {
            regime: crate::pde6::Regime::Exponential,
            q: n as f64 * a.abs().powf(1.0 / 6.0),
        };
        e20 = worst(e20, basis_ode_residual(&b, -1.0, true));
    }
    out.push(Check::paper_literal(FAMILY, PAPER, "eq 20", "pde6.paper_literal.eq20_prints_eq7_form", e20, RESIDUAL_TOL, true)
        .note(format!("eq 20 prints A_wn^P1 = (a0 + a1 u + a2 u^2) e^(q0n u) + (a3 + a4 u + a5 u^2) e^(-q0n u) (eq 7's a > 0 form) while eqs 22-23 solve eq 8's a < 0 form: its relative ODE residual A^(6) - a n^6 A at a = {a}, n = 1..6")));
}

/// Eqs 10-13: the printed derivatives against jets, and against SymPy.
fn derivative_checks(chain: &Chain, out: &mut Vec<Check>) {
    let all = [&chain.pieces[0], &chain.pieces[1], &chain.pieces[2]];
    let tol = PRINTED_TOL;
    // eqs 10-13: printed derivatives against jets
    let e10 = derivative_error(&all, &[Role::W0], 1, false);
    let e11 = derivative_error(&all, &[Role::A, Role::B], 1, false);
    let e11b = derivative_error(&all, &[Role::B], 1, true);
    let e12 = derivative_error(&all, &[Role::W0], 2, false);
    let e13 = derivative_error(&all, &[Role::A, Role::B], 2, false);
    let basis = "each function of the three patches converted to the paper's basis (eq 6 monomials, eq 8 with signs restored), the printed formula at 9 u against the jet derivative of the project's closed form";
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq 10",
            "pde6.printed.eq10_slope_a_w0",
            Kind::Reference,
            e10,
            tol,
        )
        .note(format!("eq 10 as printed, dA_w0/du: {basis}")),
    );
    out.push(Check::new(FAMILY, PAPER, "eq 11", "pde6.printed.eq11_slope_a_b_wn", Kind::Reference, e11, tol)
        .note(format!("eq 11, dA_wn/du and dB_wn/du, every minus sign restored and the B line's cos(q2n u) read as cos(2 q2n u) like the A line: {basis}")));
    out.push(Check::paper_literal(FAMILY, PAPER, "eq 11", "pde6.paper_literal.eq11_b_cos_argument", e11b, tol, true)
        .note("eq 11's dB_wn/du with the printed 2 b_wn,1 q2n cos(q2n u) (the A line has cos(2 q2n u)): max relative error against the jets of B_wn (misprint, ERRATA)"));
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq 12",
            "pde6.printed.eq12_curvature_a_w0",
            Kind::Reference,
            e12,
            tol,
        )
        .note(format!("eq 12 as printed, d2A_w0/du2: {basis}")),
    );
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq 13",
            "pde6.printed.eq13_curvature_a_b_wn",
            Kind::Reference,
            e13,
            tol,
        )
        .note(format!(
            "eq 13 as printed (every minus sign restored), d2A_wn/du2 and d2B_wn/du2: {basis}"
        )),
    );
    out.push(Check::new(FAMILY, PAPER, "eqs 11, 13", "pde6.printed.eq11_eq13_vs_sympy", Kind::Reference, eq11_13_vs_sympy(), tol::scaled(tol::ROUNDING, 10.0))
        .note("eqs 11 and 13 as printed (minus signs restored) for each of the six eq 8 basis functions against SymPy's derivatives at (q, u) = (1.3, 0.4), (4.7, 0.85), (2.2, 1) (verify/printed_forms.py, which also proves the restored formulas equal the derivatives symbolically)"));
}

/// Eq 24 (C2 across the joins in the printed local parameters) and eq 27
/// (patch 3 as printed, z constant).
fn join_checks(chain: &Chain, sec: &[Section], name: &str, layout: &str, out: &mut Vec<Check>) {
    let (p2, p1, p3) = (&chain.pieces[0], &chain.pieces[1], &chain.pieces[2]);
    // eq 24: C2 across the joins in the printed local parameters
    let mut e24 = 0.0f64;
    for (lo, hi) in [(p2, p1), (p1, p3)] {
        for d in 1..=2 {
            let (s_lo, s_hi) = (lo.patch.section(1.0, d), hi.patch.section(0.0, d));
            for j in 0..16 {
                let v = 2.0 * PI * j as f64 / 16.0 + 0.05;
                let (x, y) = (s_lo.eval(v), s_hi.eval(v));
                for k in 0..3 {
                    e24 = worst(e24, rel(x[k], y[k]));
                }
            }
        }
    }
    out.push(Check::new(FAMILY, PAPER, "eq 24", &format!("pde6.printed.eq24_c2_local_{name}"), Kind::Continuity, e24, SOLVE_TOL)
        .note(format!("eq 24: dw^P2(1, v)/du = dw^P1(0, v)/du and the same for d2/du2 (and P3(0) against P1(1)), in each patch's own unit parameter, 16 v, {layout}")));
    // eq 27: patch 3 as printed (z constant)
    let e27 = eq27_printed_interpolation_error(p3, sec);
    out.push(Check::paper_literal(FAMILY, PAPER, "eq 27", &format!("pde6.paper_literal.eq27_constant_z_{name}"), e27, SOLVE_TOL, true)
        .note("eq 27 built as printed for patch 3: z^P3(u, v) = A_z0^P3(0) constant; max distance to the sections C9-C12 it must pass through (the corrected A_z0^P3(u) passes: pde6.method2_interpolates_*)"));
}

/// SymPy's derivatives of the eq 8 basis (`verify/printed_forms.py`).
const PRINTED_GOLDEN: &str = include_str!("../../../verify/golden/printed_forms.json");

/// Eqs 11 and 13 as printed (restored) for each unit coefficient vector
/// against SymPy's derivatives of the eq 8 basis functions; NaN when the
/// golden is missing or malformed.
fn eq11_13_vs_sympy() -> f64 {
    let g: serde_json::Value = serde_json::from_str(PRINTED_GOLDEN).unwrap_or_default();
    let Some(samples) = g["pde6_basis_derivatives"].as_array() else {
        return f64::NAN;
    };
    let mut e = if samples.is_empty() { f64::NAN } else { 0.0f64 };
    for smp in samples {
        let (q, u) = (
            smp["q"].as_f64().unwrap_or(f64::NAN),
            smp["u"].as_f64().unwrap_or(f64::NAN),
        );
        let (q1, q2) = (0.5 * 3f64.sqrt() * q, 0.5 * q);
        for j in 0..6 {
            let mut c = [0.0; 6];
            c[j] = 1.0;
            let d1 = smp["d1"][j].as_f64().unwrap_or(f64::NAN);
            let d2 = smp["d2"][j].as_f64().unwrap_or(f64::NAN);
            e = worst(e, rel(eq11(&c, q1, q2, u, false), d1));
            e = worst(e, rel(eq13(&c, q1, q2, u), d2));
        }
    }
    e
}

/// Tolerance of the printed-formula comparisons: the conversion to the
/// paper's basis (exponentials centred at u = 0, condition up to ~1e4 at
/// q = 5.3) and its derivatives lose a few digits.
pub const PRINTED_TOL: f64 = 1e-9;
