//! Checks of the pde6 family: golden closed forms (SymPy/mpmath), PDE
//! residuals, interpolation (boundary) errors, C2 continuity across joins and
//! around the closed v direction, conditioning, and the paper-literal forms.

use super::mode::{
    method1_conditions, method2_conditions, paper_basis_condition, Mode, ModeBasis, ModeSolver,
    Regime, NODES_METHOD1,
};
use super::samples::{synthetic_sections, SIGNS};
use super::{Chain, Patch, Piece, Section, JOIN_SAMPLES};
use crate::check::Worst;
use crate::check::{tol, Check, Kind};
use crate::curve::Fourier3;
use crate::jet::Jet;
use crate::surface::Joined;
use crate::surface::Surface;
use serde::Deserialize;
use std::f64::consts::PI;
mod basis;
use basis::basis_checks;
mod chains;
use chains::chain_checks;
mod measure;
mod paper_literal;
mod printed;
mod printed_appendix;
mod printed_appendix_b;
mod printed_checks;
pub use measure::{
    basis_ode_residual, chain_residual, closed_v_mismatch, interpolation_error, lebesgue,
    method2_amplification, mode_vs_rk4, pde_residual, section_distance,
};
use paper_literal::printed_form_checks;
pub use paper_literal::{eq26_printed_interpolation_error, eq27_printed_interpolation_error};

const FAMILY: &str = "pde6";
const PAPER: &str = "002";
const GOLDEN: &str = include_str!("../../../verify/golden/pde6_closed_form.json");

/// Relative tolerance of PDE residuals: the sixth derivatives are sums of
/// terms of size $q^6 |A|$ that cancel, so rounding is amplified by ~1e3.
pub const RESIDUAL_TOL: f64 = 1e-9;
/// Relative tolerance of interpolation and continuity errors (the solves
/// have condition numbers up to ~1e7 in the documented range).
pub const SOLVE_TOL: f64 = 1e-8;
/// Largest condition number in the documented range (|a| <= 10, N <= 20).
pub const CONDITION_BOUND: f64 = 1e8;
/// Lebesgue constants: relative agreement with mpmath (101 samples both;
/// measured 2e-15).
pub const LEBESGUE_TOL: f64 = tol::ROUNDING;
/// RK4 with 2000 steps on q <= 4.5: global error ~ (q h)^4 q-growth, ~1e-10.
pub const RK4_TOL: f64 = 1e-8;
/// A slope jump smaller than this (relative) would make method 1 C1.
pub const JUMP_FLOOR: f64 = 1e-3;

#[derive(Deserialize)]
struct Golden {
    paper_pos_residual_q1_u05: Vec<f64>,
    cases: Vec<GoldenCase>,
    method2_d1: f64,
    method2_d2: f64,
    method2_amplification_quintic: f64,
    lebesgue: Vec<GoldenLebesgue>,
}

#[derive(Deserialize)]
struct GoldenCase {
    a: f64,
    n: usize,
    values: Vec<f64>,
    at: Vec<f64>,
    interp: Vec<Vec<f64>>,
    method2: Vec<Vec<f64>>,
}

#[derive(Deserialize)]
struct GoldenLebesgue {
    kind: String,
    q: f64,
    lebesgue: f64,
}

fn curves6(s: &[Section]) -> [&Fourier3; 6] {
    std::array::from_fn(|i| &s[i].curve)
}

fn golden_checks(out: &mut Vec<Check>) {
    let g: Golden =
        match crate::check::parse_golden(GOLDEN, FAMILY, PAPER, "golden", "pde6.golden_parse") {
            Ok(g) => g,
            Err(c) => {
                out.push(*c);
                return;
            }
        };
    let (mut e1, mut e2) = (0.0f64, 0.0f64);
    for c in &g.cases {
        let values: [f64; 6] = std::array::from_fn(|i| c.values[i]);
        let b = ModeBasis::new(c.a, c.n);
        let m1 = Mode::interpolate(c.a, c.n, values);
        let s2 = ModeSolver::new(b, method2_conditions(1.0));
        let m2 = s2.map(|s| {
            s.solve([
                values[0],
                values[1],
                values[2],
                values[3],
                g.method2_d1,
                g.method2_d2,
            ])
        });
        for (i, &u) in c.at.iter().enumerate() {
            for d in 0..3 {
                let e = m1.as_ref().map_or(f64::NAN, |m| {
                    let x = m.eval(Jet::<3, 1>::var_u(u)).deriv(d, 0);
                    (x - c.interp[i][d]).abs() / c.interp[i][d].abs().worst(1.0)
                });
                e1 = if e.is_nan() { f64::NAN } else { e1.worst(e) };
                let e = m2.as_ref().map_or(f64::NAN, |coef| {
                    let x = Mode {
                        basis: b,
                        coef: *coef,
                    }
                    .eval(Jet::<3, 1>::var_u(u))
                    .deriv(d, 0);
                    (x - c.method2[i][d]).abs() / c.method2[i][d].abs().worst(1.0)
                });
                e2 = if e.is_nan() { f64::NAN } else { e2.worst(e) };
            }
        }
    }
    out.push(
        Check::new(FAMILY, PAPER, "eqs 6-8, 21-23", "pde6.golden_method1_modes", Kind::Reference, e1, SOLVE_TOL)
            .note("six-point harmonic interpolants (value, slope, curvature) vs mpmath 40-digit solves, a in {-1,-0.5,0,1e-3,1,2}, n in {0,1,3,4,5,10,20}"),
    );
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "eqs 24-25, A34-A36",
            "pde6.golden_method2_modes",
            Kind::Reference,
            e2,
            SOLVE_TOL,
        )
        .note("method-2 harmonic functions (four values + slope, curvature at u = 1) vs mpmath"),
    );
    let mut el = 0.0f64;
    for l in &g.lebesgue {
        let b = ModeBasis {
            regime: match l.kind.as_str() {
                "neg" => super::Regime::Oscillatory,
                "pos" => super::Regime::Exponential,
                _ => super::Regime::Quintic,
            },
            q: l.q,
        };
        let m = lebesgue(b).map_or(f64::NAN, |x| crate::check::rel_err(x, l.lebesgue));
        el = if m.is_nan() { f64::NAN } else { el.worst(m) };
    }
    out.push(
        Check::new(FAMILY, PAPER, "eqs 21-23", "pde6.lebesgue_constants", Kind::Reference, el, LEBESGUE_TOL)
            .note("Lebesgue constants of the six-point interpolation for q in {1,5,10,20,40}, both signs, vs mpmath (intrinsic conditioning: <= 27 (a<0) / 102 (a>0) up to q = 20)"),
    );
    let amp = method2_amplification(0.0, 0).unwrap_or(f64::NAN);
    out.push(
        Check::new(FAMILY, PAPER, "eqs 24-27", "pde6.method2_amplification", Kind::Reference,
            crate::check::rel_err(amp, g.method2_amplification_quintic), tol::scaled(tol::ROUNDING, 1e3))
            .note(format!("spectral radius of the method-2 slope/curvature recursion per patch, quintic harmonic: {amp:.4} vs SymPy (13 + sqrt 165)/2; a = -0.5: n = 1 {:.2}, n = 5 {:.2}, n = 10 {:.2} (growth > 1: method 2 is unstable over long chains)",
                method2_amplification(-0.5, 1).unwrap_or(f64::NAN), method2_amplification(-0.5, 5).unwrap_or(f64::NAN), method2_amplification(-0.5, 10).unwrap_or(f64::NAN))),
    );
    // paper eq 7 basis: the residual numbers SymPy gives at q = 1, u = 0.5
    let b = ModeBasis {
        regime: super::Regime::Exponential,
        q: 1.0,
    };
    let f = b.eval_paper(Jet::<7, 1>::var_u(0.5));
    let rust: Vec<f64> = f.iter().map(|x| x.deriv(6, 0) - x.value()).collect();
    out.push(
        Check::new(FAMILY, PAPER, "eq 7", "pde6.paper_eq7_residual_vs_sympy", Kind::Reference,
            crate::check::max_abs_diff(&rust, &g.paper_pos_residual_q1_u05), tol::scaled(tol::ROUNDING, 1e3))
            .note("residual phi^(6) - q^6 phi of the printed a > 0 basis at q = 1, u = 0.5: jets vs SymPy"),
    );
}

/// All checks of the pde6 family.
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    golden_checks(&mut out);

    basis_checks(&mut out);
    chain_checks(&mut out);
    printed_form_checks(&mut out);
    printed_checks::printed_main_checks(&mut out);
    printed_appendix::printed_appendix_checks(&mut out);
    out
}
