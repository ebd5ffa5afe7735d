//! Checks of paper 002 appendix A (A1-A4, A6-A16: substitution, harmonic
//! ODEs, characteristic roots) and, through [`super::printed_appendix_b`],
//! appendix B (A17-A36: the method-2 conditions of patch 2, written out, and
//! its linear systems), each built as printed (signs restored, see
//! [`super::printed`]) against the project.
//!
//! Numbering of the appendix (the extraction carries no labels; fixed from
//! the text's own references "(A11)", "(A17)-(A36)"): A1-A3 substitution of
//! eqs 3-5 into eq 2; A4-A6 the harmonic ODEs; A7 the quintic; A8 the
//! characteristic equation; a > 0: A9 $r^3 = \pm n^3\sqrt a$, A10 the
//! printed triple root $r_{1,2,3} = q_{0n}$, A11 $q_{0n} = n|a|^{1/6}$, A12
//! $r_{4,5,6} = -q_{0n}$ and the basis; a < 0: A13 $r^3 = \pm i n^3\sqrt{|a|}$,
//! A14 $r_{1,2,3}$, A15 $q_{1n}, q_{2n}$, A16 $r_{4,5,6}$ and the basis;
//! A17-A18 the equalised C2 conditions, A19-A26 the derivatives at the ends,
//! A27-A29 the substituted conditions, A30-A33 patch 2 through C1-C4,
//! A34-A36 its systems.

use super::printed::*;
use super::printed_appendix_b::appendix_b_checks;
use super::printed_checks::rel;
use super::*;
use crate::check::{worst, Worst};
use crate::jet::Real;
use nalgebra::Complex;

/// Polynomial coefficient functions of a test surface that does not solve
/// eq 2 (degree 7, so every sixth derivative is non-zero).
fn test_poly(n: usize, which: usize) -> [f64; 8] {
    std::array::from_fn(|k| (1.3 * (n * 8 + k) as f64 + 0.7 * which as f64).sin() * 0.5)
}

fn poly<T: Real>(c: &[f64; 8], u: T) -> T {
    let mut acc = T::cst(c[7]);
    for k in (0..7).rev() {
        acc = acc * u + c[k];
    }
    acc
}

const TEST_N: usize = 4;

/// The test series: x (`y_form = false`, eq 3 form) or y (eq 4 form:
/// P_n sin nv + Q_n cos nv) with P_n = test_poly(n, 0), Q_n = test_poly(n, 1).
fn test_series<T: Real>(u: T, v: T, y_form: bool) -> T {
    let mut s = poly(&test_poly(0, 0), u);
    for n in 1..=TEST_N {
        let (c, si) = ((v * n as f64).cos(), (v * n as f64).sin());
        let (p, q) = (poly(&test_poly(n, 0), u), poly(&test_poly(n, 1), u));
        s += if y_form {
            p * si + q * c
        } else {
            p * c + q * si
        };
    }
    s
}

/// Max relative difference between the printed left side of A1/A2 and the
/// operator $w_{u^6} + a w_{v^6}$ of eq 2 applied to the test series.
/// `printed_a2`: A2 exactly as printed ($A_{yn}$ with cos nv, $B_{yn}$ with
/// $\sin n\pi$ in the sixth-derivative sum and with sin nv in the other).
fn substitution_error(a: f64, y_form: bool, printed_a2: bool) -> f64 {
    let mut e = 0.0f64;
    for i in 0..5 {
        let u = 0.1 + 0.2 * i as f64;
        for j in 0..8 {
            let v = 2.0 * PI * j as f64 / 8.0 + 0.1;
            let op = test_series(Jet::<7, 1>::var_u(u), Jet::<7, 1>::constant(v), y_form)
                .deriv(6, 0)
                + a * test_series(Jet::<1, 7>::constant(u), Jet::<1, 7>::var_v(v), y_form)
                    .deriv(0, 6);
            let d6 = |n: usize, w: usize| poly(&test_poly(n, w), Jet::<7, 1>::var_u(u)).deriv(6, 0);
            let d0 = |n: usize, w: usize| poly(&test_poly(n, w), u);
            let mut lhs = d6(0, 0);
            for n in 1..=TEST_N {
                let nf = n as f64;
                let (c, s) = ((nf * v).cos(), (nf * v).sin());
                let n6 = a * nf.powi(6);
                lhs += if printed_a2 {
                    d6(n, 0) * c + d6(n, 1) * (nf * PI).sin() - n6 * (d0(n, 0) * c + d0(n, 1) * s)
                } else if y_form {
                    d6(n, 0) * s + d6(n, 1) * c - n6 * (d0(n, 0) * s + d0(n, 1) * c)
                } else {
                    d6(n, 0) * c + d6(n, 1) * s - n6 * (d0(n, 0) * c + d0(n, 1) * s)
                };
            }
            e = worst(e, (lhs - op).abs() / op.abs().worst(1.0));
        }
    }
    e
}

/// The six roots of $r^6 = a n^6$ as the paper prints them for a < 0 (A14,
/// A16, signs and roots restored: $\pm q_1 + iq_2$, $-2iq_2$ and conjugates)
/// or as they are for a > 0 ($\pm q$, $q(\pm\frac12 \pm i\frac{\sqrt3}2)$).
fn roots(a: f64, n: usize) -> [Complex<f64>; 6] {
    let b = FnBasis {
        project: ModeBasis::new(a, n),
        printed: printed_basis(a, n),
    };
    let (q1, q2) = q12(&b);
    let c = Complex::new;
    if a < 0.0 {
        [
            c(q1, q2),
            c(-q1, q2),
            c(0.0, -2.0 * q2),
            c(q1, -q2),
            c(-q1, -q2),
            c(0.0, 2.0 * q2),
        ]
    } else {
        let q = b.printed.q;
        let (h, s) = (0.5 * q, 0.5 * 3f64.sqrt() * q);
        [
            c(q, 0.0),
            c(-h, s),
            c(-h, -s),
            c(-q, 0.0),
            c(h, s),
            c(h, -s),
        ]
    }
}

fn root_checks(out: &mut Vec<Check>) {
    let (mut e8, mut e9, mut e11, mut e10, mut e13, mut e14) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for n in 1..=6 {
        for a in [-0.5, 0.8, -3.0, 2.0] {
            let nf = n as f64;
            let an6 = a * nf.powi(6);
            let r = roots(a, n);
            for z in r {
                e8 = worst(e8, (z.powi(6) - an6).norm() / an6.abs());
            }
            let c3 = nf.powi(3) * a.abs().sqrt();
            if a > 0.0 {
                // A9: the first three cube to +n^3 sqrt a, the last three to -
                for (i, z) in r.iter().enumerate() {
                    let target = if i < 3 { c3 } else { -c3 };
                    e9 = worst(e9, (z.powi(3) - target).norm() / c3);
                }
                let q0 = nf * a.abs().powf(1.0 / 6.0);
                // A11 as printed against the printed roots and the
                // project's exponent (ModeBasis::new)
                let ours = ModeBasis::new(a, n).q;
                e11 = worst(
                    e11,
                    rel(r[0].re, q0)
                        .worst(rel(-r[3].re, q0))
                        .worst(rel(ours, q0)),
                );
                for z in &r[..3] {
                    e10 = e10.worst((z - q0).norm() / q0);
                }
            } else {
                for (i, z) in r.iter().enumerate() {
                    let target = Complex::new(0.0, if i < 3 { c3 } else { -c3 });
                    e13 = worst(e13, (z.powi(3) - target).norm() / c3);
                }
                let b = ModeBasis::new(a, n);
                // the printed roots are the exponents of the eq 8 basis: e^{r u}
                // real/imag parts against eval_paper at u = 0.3
                let u = 0.3;
                let p = b.eval_paper(u);
                let ez = |z: Complex<f64>| (z * u).exp();
                let want = [
                    ez(r[5]).re,
                    ez(r[5]).im,
                    ez(r[0]).re,
                    ez(r[0]).im,
                    ez(r[4]).re,
                    -ez(r[4]).im,
                ];
                for j in 0..6 {
                    e14 = worst(e14, rel(want[j], p[j]));
                }
            }
        }
    }
    let cases = "a in {-3, -0.5, 0.8, 2}, n = 1..6";
    out.push(Check::new(FAMILY, PAPER, "eq A8", "pde6.printed.a8_characteristic_roots", Kind::Residual, e8, tol::scaled(tol::ROUNDING, 10.0))
        .note(format!("|r^6 - a n^6| / |a n^6| of the six roots (a < 0: as printed in A14/A16 with signs restored; a > 0: the corrected roots), {cases}")));
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq A9",
            "pde6.printed.a9_cubes_pos",
            Kind::Residual,
            e9,
            tol::scaled(tol::ROUNDING, 10.0),
        )
        .note("a > 0: the roots cube to +n^3 sqrt(a) (three) and -n^3 sqrt(a) (three), relative"),
    );
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq A11",
            "pde6.printed.a11_q0n",
            Kind::Residual,
            e11,
            tol::scaled(tol::ROUNDING, 10.0),
        )
        .note("a > 0: the real roots are +-q0n with q0n = n |a|^(1/6) as printed, and the project's exponent q (ModeBasis::new) is that q0n, relative"),
    );
    out.push(Check::paper_literal(FAMILY, PAPER, "eqs A10, A12", "pde6.paper_literal.a10_a12_triple_root", e10, tol::ROUNDING, true)
        .note("A10/A12 print r_{1,2,3} = q0n (and r_{4,5,6} = -q0n) as triple roots: max |r_k - q0n| / q0n over the three distinct cube roots of n^3 sqrt(a) (sqrt 3; misprint, ERRATA eq 7)"));
    out.push(Check::new(FAMILY, PAPER, "eq A13", "pde6.printed.a13_cubes_neg", Kind::Residual, e13, tol::scaled(tol::ROUNDING, 10.0))
        .note("a < 0: the printed roots (signs restored) cube to +i n^3 sqrt|a| (r1-r3) and -i n^3 sqrt|a| (r4-r6)"));
    out.push(Check::new(FAMILY, PAPER, "eqs A14, A15, A16", "pde6.printed.a14_a16_roots_are_basis_exponents", Kind::Residual, e14, tol::scaled(tol::ROUNDING, 10.0))
        .note("a < 0: r = q1n + i q2n, -q1n + i q2n, -2 i q2n and conjugates with q1n = sqrt3/2 n|a|^(1/6), q2n = n|a|^(1/6)/2 (A15): e^(r u) (real, imaginary parts) are the six eq 8 / A16 basis functions at u = 0.3"));
}

fn substitution_checks(out: &mut Vec<Check>) {
    let a = -0.5;
    let what = "the left side of the printed equation for a series with degree-7 polynomial coefficient functions (not a solution, n <= 4) against w_u6 + a w_v6 from jets, a = -0.5";
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq A1",
            "pde6.printed.a1_substitution_x",
            Kind::Residual,
            substitution_error(a, false, false),
            tol::scaled(tol::ROUNDING, 1e3),
        )
        .note(format!("A1 (x, eq 3 into eq 2): {what}")),
    );
    out.push(Check::new(FAMILY, PAPER, "eq A2", "pde6.printed.a2_substitution_y", Kind::Residual, substitution_error(a, true, false), tol::scaled(tol::ROUNDING, 1e3))
        .note(format!("A2 (y, eq 4 into eq 2) read with sin nv for sin n pi and A_yn with sin nv as in eq 4: {what}")));
    out.push(Check::paper_literal(FAMILY, PAPER, "eq A2", "pde6.paper_literal.a2_sin_n_pi", substitution_error(a, true, true), tol::scaled(tol::ROUNDING, 1e3), true)
        .note("A2 exactly as printed (B_yn^(6) sin n pi, A_yn paired with cos nv) for the eq 4 series: relative difference from w_u6 + a w_v6 (ERRATA)"));
    // A3: z = A_z0(u) (eq 5): on the project's patches (sections with a
    // v-constant z) z has no v dependence and eq 2 reduces to A_z0^(6) = 0
    let sec = paper_layout_sections();
    let e3 = Chain::method2(a, &sec, 3).map_or(f64::NAN, |chain| {
        let mut e = 0.0f64;
        for piece in &chain.pieces {
            for i in 0..5 {
                let (u, v) = (0.1 + 0.2 * i as f64, 0.3 + 0.9 * i as f64);
                let zu = piece
                    .patch
                    .eval(Jet::<7, 1>::var_u(u), Jet::<7, 1>::constant(v))[2];
                let zv = piece
                    .patch
                    .eval(Jet::<1, 7>::constant(u), Jet::<1, 7>::var_v(v))[2];
                let scale = zu.value().abs().worst(1.0);
                for d in 1..=6 {
                    e = worst(e, zv.deriv(0, d).abs() / scale);
                }
                e = worst(e, (zu.deriv(6, 0) + a * zv.deriv(0, 6)).abs() / scale);
            }
        }
        e
    });
    out.push(Check::new(FAMILY, PAPER, "eq A3", "pde6.printed.a3_substitution_z", Kind::Residual, e3, tol::scaled(tol::ROUNDING, 10.0))
        .note("A3: z = A_z0(u) (eq 5) on the project's three patches of the paper-layout method-2 chain (a = -0.5, sections with v-constant z): dz/dv^d (d = 1..6) vanish and z_u6 + a z_v6 = A_z0^(6) = 0, jets, 5 points per patch, relative to max(|z|, 1)"));
}

/// Relative ODE residual of the functions of `role` in the pieces.
fn ode_error(pieces: &[&Piece], a: f64, role: Role) -> f64 {
    let mut e = 0.0f64;
    for piece in pieces {
        for (r, n, _, b, c) in functions(&piece.patch) {
            if r != role {
                continue;
            }
            let an6 = a * (n as f64).powi(6);
            for i in 0..=8 {
                let u = i as f64 / 8.0;
                let (d6, d0) = (
                    project_function(&b, &c, u, 6),
                    project_function(&b, &c, u, 0),
                );
                let scale = d6
                    .abs()
                    .worst((an6 * d0).abs())
                    .worst(b.project.q.powi(6))
                    .worst(1.0);
                e = worst(e, (d6 - an6 * d0).abs() / scale);
            }
        }
    }
    e
}

pub(super) fn printed_appendix_checks(out: &mut Vec<Check>) {
    substitution_checks(out);
    root_checks(out);
    let a = SIGNS[0].1;
    let sec = paper_layout_sections();
    let Ok(chain) = Chain::method2(a, &sec, 3) else {
        out.push(Check::new(
            FAMILY,
            PAPER,
            "eqs A4-A36",
            "pde6.printed.appendix_chain",
            Kind::Residual,
            f64::NAN,
            SOLVE_TOL,
        ));
        return;
    };
    let pieces: Vec<&Piece> = chain.pieces.iter().collect();
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eq A4",
            "pde6.printed.a4_quintic_ode",
            Kind::Residual,
            ode_error(&pieces, 0.0, Role::W0),
            RESIDUAL_TOL,
        )
        .note("A4: A_w0^(6) = 0 for every n = 0 function of the three patches (jets), relative"),
    );
    out.push(Check::new(FAMILY, PAPER, "eq A6", "pde6.printed.a6_b_wn_ode", Kind::Residual, ode_error(&pieces, a, Role::B), RESIDUAL_TOL)
        .note("A6: B_wn^(6) - a n^6 B_wn = 0 for every B_wn (x: sin nv, y: cos nv) of the three patches, a = -0.5, jets, relative to max(|B^(6)|, q^6, 1)"));
    if let [p2, p1, _] = pieces[..] {
        appendix_b_checks(out, p2, p1, &sec);
    }
}
