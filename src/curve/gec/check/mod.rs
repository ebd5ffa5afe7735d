//! Checks of the gec family: golden values from `verify/gec_golden.py`,
//! refit round trips, FFT against least squares, transforms against
//! transformed points, and the paper-literal forms of 000 eq 16 and 002 eq 1.

use crate::check::{worst, Worst};
mod correction;
mod metric;
mod refit;
mod transform;

use super::fit::{dft_coefficients, solve};
use super::samples::tilted_gec;
use super::transform::Bend;
use super::{fit, fit_fft, metrics, FitOptions, Frame, Gec, Param, Solver};
use crate::check::{tol, Check, Kind};
use std::f64::consts::PI;

const FAMILY: &str = "gec";
const GOLDEN: &str = include_str!("../../../../verify/golden/gec_golden.json");
/// Nodes of the checked arc-length quadrature.
const ARC_NODES: usize = 512;

#[derive(serde::Deserialize)]
struct Golden {
    centre: [f64; 2],
    x: Vec<[f64; 2]>,
    y: Vec<[f64; 2]>,
    z_c: f64,
    theta: f64,
    derivs_xy: Vec<[f64; 2]>,
    area: f64,
    centroid_xy: [f64; 2],
    arc_length: f64,
}

fn golden() -> Option<(Golden, Gec)> {
    let g: Golden = serde_json::from_str(GOLDEN).ok()?;
    let gec = Gec::new(Frame::z_plane(g.z_c), g.centre, g.x.clone(), g.y.clone()).ok()?;
    Some((g, gec))
}

/// Largest difference of the space Fourier coefficients (frame-independent).
pub fn coeff_diff(a: &Gec, b: &Gec) -> f64 {
    let n = usize::max(a.terms(), b.terms());
    let (fa, fb) = (
        a.to_fourier3().with_harmonics(n),
        b.to_fourier3().with_harmonics(n),
    );
    let mut d: f64 = 0.0;
    for k in 0..3 {
        d = d.worst((fa.c0[k] - fb.c0[k]).abs());
        for i in 0..n {
            d = d.worst((fa.cos[i][k] - fb.cos[i][k]).abs());
            d = d.worst((fa.sin[i][k] - fb.sin[i][k]).abs());
        }
    }
    d
}

fn max_diff3(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    a.iter()
        .zip(b)
        .flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs()))
        .fold(0.0, worst)
}

fn c(eq: &str, name: &str, kind: Kind, measured: f64, tol: f64, note: &str) -> Check {
    let paper = if eq.starts_with("002") { "002" } else { "000" };
    let eq = eq.trim_start_matches("002 ").trim_start_matches("000 ");
    Check::new(FAMILY, paper, eq, name, kind, measured, tol).note(note)
}

/// All checks of the gec family.
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    let Some((g, gec)) = golden() else {
        out.push(c(
            "000 eq 16",
            "gec.golden_parse",
            Kind::Reference,
            f64::NAN,
            0.0,
            "golden JSON did not parse",
        ));
        return out;
    };
    golden_checks(&g, &gec, &mut out);
    paper_literal_checks(&g, &gec, &mut out);

    // conversion to Fourier3
    let tg = tilted_gec();
    let f3 = tg.to_fourier3();
    let th: Vec<f64> = (0..40).map(|k| 0.17 * k as f64).collect();
    let a: Vec<[f64; 3]> = th.iter().map(|t| tg.eval(*t)).collect();
    let b: Vec<[f64; 3]> = th.iter().map(|t| f3.eval(*t)).collect();
    out.push(c(
        "000 eq 16",
        "gec.to_fourier3",
        Kind::Reference,
        max_diff3(&a, &b),
        tol::ROUNDING,
        "Fourier3 from a tilted GEC evaluates to the same points",
    ));

    refit::refit_checks(&tg, &mut out);
    transform::transform_checks(&tg, &mut out);
    metric::metric_checks(&mut out);
    correction::correction_checks(&mut out);
    out
}

/// Eq 16 against the SymPy golden: derivatives, tangent, area, centroid,
/// arc length.
fn golden_checks(g: &Golden, gec: &Gec, out: &mut Vec<Check>) {
    // derivatives via jets vs sympy
    let mut d: f64 = 0.0;
    for (k, want) in g.derivs_xy.iter().enumerate() {
        let got = gec.derivative(g.theta, k);
        d = d
            .worst((got[0] - want[0]).abs())
            .worst((got[1] - want[1]).abs());
        d = d.worst(if k == 0 {
            (got[2] - g.z_c).abs()
        } else {
            got[2].abs()
        });
    }
    out.push(c(
        "000 eq 16",
        "gec.derivatives_golden",
        Kind::Reference,
        d,
        tol::ROUNDING,
        "d^k P/dtheta^k (k=0..3) by jets vs SymPy",
    ));
    let t = gec.tangent_plane(g.theta);
    let dt = (t[0] - g.derivs_xy[1][0])
        .abs()
        .worst((t[1] - g.derivs_xy[1][1]).abs());
    out.push(c(
        "000 eq 16",
        "gec.tangent_fast_path",
        Kind::Reference,
        dt,
        tol::ROUNDING,
        "plain-f64 tangent vs SymPy derivative",
    ));
    out.push(c(
        "000 eq 16",
        "gec.area_closed_form",
        Kind::Reference,
        (gec.area() - g.area).abs(),
        tol::ROUNDING,
        "pi sum n (a_x a_y - b_x b_y) vs SymPy Green integral",
    ));
    let cen = gec.centroid();
    let dc = (cen[0] - g.centroid_xy[0])
        .abs()
        .worst((cen[1] - g.centroid_xy[1]).abs());
    out.push(c(
        "000 eq 16",
        "gec.centroid",
        Kind::Reference,
        dc,
        tol::ROUNDING,
        "trapezoidal Green centroid vs SymPy",
    ));
    out.push(c(
        "000 eq 16",
        "gec.arc_length",
        Kind::Reference,
        (gec.arc_length_with(ARC_NODES) - g.arc_length).abs() / g.arc_length,
        tol::QUADRATURE,
        "periodic trapezoid vs mpmath quad (relative)",
    ));
}

/// The printed forms of 000 eq 16 and 002 eq 1 equal `Gec::eval`.
fn paper_literal_checks(g: &Golden, gec: &Gec, out: &mut Vec<Check>) {
    // paper-literal forms (they agree: the two papers' forms are one family)
    let (xs, ys) = gec.to_paper_000();
    let [ax, bx, ay, by] = gec.to_paper_002();
    let (mut d0, mut d2): (f64, f64) = (0.0, 0.0);
    for k in 0..50 {
        let v = k as f64 / 50.0;
        let e = gec.eval_v(v);
        let p = super::paper_000_literal(&xs, &ys, g.z_c, v);
        let q = super::paper_002_literal(&ax, &bx, &ay, &by, g.z_c, 2.0 * PI * v);
        for i in 0..3 {
            d0 = d0.worst((p[i] - e[i]).abs());
            d2 = d2.worst((q[i] - e[i]).abs());
        }
    }
    out.push(
        Check::paper_literal(
            FAMILY,
            "000",
            "eq 16",
            "gec.paper_000_literal",
            d0,
            tol::ROUNDING,
            false,
        )
        .note("printed eq 16 (v in [0,1], x (cos,sin), y (sin,cos)) equals Gec::eval_v"),
    );
    out.push(
        Check::paper_literal(
            FAMILY,
            "002",
            "eq 1",
            "gec.paper_002_literal",
            d2,
            tol::ROUNDING,
            false,
        )
        .note("printed eq 1 (v in [0,2pi]) equals Gec::eval"),
    );
}
