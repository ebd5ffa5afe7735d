//! Checks of the gec family: golden values from `verify/gec_golden.py`,
//! refit round trips, FFT against least squares, transforms against
//! transformed points, and the paper-literal forms of 000 eq 16 and 002 eq 1.

mod correction;

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
    let n = a.terms().max(b.terms());
    let (fa, fb) = (
        a.to_fourier3().with_harmonics(n),
        b.to_fourier3().with_harmonics(n),
    );
    let mut d: f64 = 0.0;
    for k in 0..3 {
        d = d.max((fa.c0[k] - fb.c0[k]).abs());
        for i in 0..n {
            d = d.max((fa.cos[i][k] - fb.cos[i][k]).abs());
            d = d.max((fa.sin[i][k] - fb.sin[i][k]).abs());
        }
    }
    d
}

fn max_diff3(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    a.iter()
        .zip(b)
        .flat_map(|(p, q)| (0..3).map(move |k| (p[k] - q[k]).abs()))
        .fold(0.0, f64::max)
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
    // derivatives via jets vs sympy
    let mut d: f64 = 0.0;
    for (k, want) in g.derivs_xy.iter().enumerate() {
        let got = gec.derivative(g.theta, k);
        d = d
            .max((got[0] - want[0]).abs())
            .max((got[1] - want[1]).abs());
        d = d.max(if k == 0 {
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
        .max((t[1] - g.derivs_xy[1][1]).abs());
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
        .max((cen[1] - g.centroid_xy[1]).abs());
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
            d0 = d0.max((p[i] - e[i]).abs());
            d2 = d2.max((q[i] - e[i]).abs());
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

    refit_checks(&tg, &mut out);
    transform_checks(&tg, &mut out);
    metric_checks(&mut out);
    correction::correction_checks(&mut out);
    out
}

fn refit_checks(tg: &Gec, out: &mut Vec<Check>) {
    let pts = tg.sample(64);
    let base = FitOptions {
        param: Param::Uniform,
        theta0: Some(0.0),
        ..FitOptions::new(3)
    };
    for (solver, name) in [
        (Solver::Qr, "gec.refit_qr"),
        (Solver::NormalEquations, "gec.refit_normal_equations"),
    ] {
        let d =
            fit(&pts, &FitOptions { solver, ..base }).map_or(f64::NAN, |r| coeff_diff(tg, &r.gec));
        out.push(c("002 eq 1", name, Kind::Reference, d, tol::SOLVE,
            "a tilted GEC sampled at 64 points and refitted (J=3, auto frame) reproduces its coefficients"));
    }
    let d = fit_fft(&pts, &base, 64).map_or(f64::NAN, |r| coeff_diff(tg, &r.gec));
    out.push(c(
        "002 eq 1",
        "gec.refit_fft",
        Kind::Reference,
        d,
        tol::SOLVE,
        "same round trip through the FFT path",
    ));
    // FFT == least squares on uniform samples of a non-GEC curve (superellipse)
    let m = 96;
    let t0 = 0.3;
    let p: Vec<[f64; 2]> = (0..m)
        .map(|k| {
            let t: f64 = t0 + 2.0 * PI * k as f64 / m as f64;
            let (s, co) = t.sin_cos();
            [
                1.5 * co.signum() * co.abs().powf(0.6),
                s.signum() * s.abs().powf(0.6),
            ]
        })
        .collect();
    let th: Vec<f64> = (0..m)
        .map(|k| t0 + 2.0 * PI * k as f64 / m as f64)
        .collect();
    let d = match (solve(&p, &th, 10, Solver::Qr), dft_coefficients(&p, t0, 10)) {
        (Ok(a), Ok(b)) => {
            let mut d = (a.0[0] - b.0[0]).abs().max((a.0[1] - b.0[1]).abs());
            for n in 0..10 {
                for k in 0..2 {
                    d = d
                        .max((a.1[n][k] - b.1[n][k]).abs())
                        .max((a.2[n][k] - b.2[n][k]).abs());
                }
            }
            d
        }
        _ => f64::NAN,
    };
    out.push(c(
        "002 eq 1",
        "gec.fft_equals_lsq",
        Kind::Reference,
        d,
        tol::SOLVE,
        "truncated DFT equals QR least squares on 96 uniform samples of a superellipse, J=10",
    ));
}

fn transform_checks(tg: &Gec, out: &mut Vec<Check>) {
    let th: Vec<f64> = (0..37).map(|k| 0.17 * k as f64).collect();
    let f = tg.frame;
    let plane = |g: &Gec| -> Vec<[f64; 2]> { th.iter().map(|t| g.eval_plane(*t)).collect() };
    let p0 = plane(tg);
    let lift =
        |p: &[[f64; 2]]| -> Vec<[f64; 3]> { p.iter().map(|q| f.place(q[0], q[1])).collect() };
    let space = |g: &Gec| -> Vec<[f64; 3]> { th.iter().map(|t| g.eval(*t)).collect() };
    // scale
    let cc = [0.2, -0.1];
    let want: Vec<[f64; 2]> = p0
        .iter()
        .map(|q| [cc[0] + 1.3 * (q[0] - cc[0]), cc[1] + 0.7 * (q[1] - cc[1])])
        .collect();
    out.push(c(
        "000 sec 5.2",
        "gec.transform_scale",
        Kind::Residual,
        max_diff3(&space(&tg.scaled(1.3, 0.7, cc)), &lift(&want)),
        tol::ROUNDING,
        "per-axis scaling of coefficients equals scaled points",
    ));
    // rotate
    let (s, co) = 0.9f64.sin_cos();
    let want: Vec<[f64; 2]> = p0
        .iter()
        .map(|q| {
            let d = [q[0] - cc[0], q[1] - cc[1]];
            [cc[0] + co * d[0] - s * d[1], cc[1] + s * d[0] + co * d[1]]
        })
        .collect();
    out.push(c(
        "000 sec 5.2",
        "gec.transform_rotate",
        Kind::Residual,
        max_diff3(&space(&tg.rotated(0.9, cc)), &lift(&want)),
        tol::ROUNDING,
        "in-plane rotation of coefficient pairs equals rotated points",
    ));
    // translate
    let dvec = [0.5, -1.0, 2.0];
    let want: Vec<[f64; 3]> = space(tg)
        .iter()
        .map(|p| [p[0] + dvec[0], p[1] + dvec[1], p[2] + dvec[2]])
        .collect();
    out.push(c(
        "000 sec 5.2",
        "gec.transform_translate",
        Kind::Residual,
        max_diff3(&space(&tg.translated(dvec)), &want),
        tol::ROUNDING,
        "translation equals translated points",
    ));
    // bump
    let (h, tc, sig) = (0.2, 1.1, 0.35);
    let d = match tg.with_bump(h, tc, sig) {
        Ok(b) => {
            let gs: Vec<f64> = (1..=tg.terms())
                .map(|n| (-(n as f64 * sig).powi(2) / 2.0).exp())
                .collect();
            let nb = 1.0 + 2.0 * gs.iter().sum::<f64>();
            let want: Vec<[f64; 2]> = th
                .iter()
                .zip(&p0)
                .map(|(t, q)| {
                    let prof = (1.0
                        + 2.0
                            * gs.iter()
                                .enumerate()
                                .map(|(i, g)| g * ((i + 1) as f64 * (t - tc)).cos())
                                .sum::<f64>())
                        / nb;
                    [q[0] + h * prof * tc.cos(), q[1] + h * prof * tc.sin()]
                })
                .collect();
            let peak = b.eval_plane(tc);
            let base = tg.eval_plane(tc);
            let dpeak = ((peak[0] - base[0]).hypot(peak[1] - base[1]) - h).abs();
            max_diff3(&space(&b), &lift(&want)).max(dpeak)
        }
        Err(_) => f64::NAN,
    };
    out.push(c(
        "000 sec 5.2",
        "gec.transform_bump",
        Kind::Residual,
        d,
        tol::ROUNDING,
        "local bump in coefficient space equals displaced points; peak height h at theta_c",
    ));
    // bend: a chain of sections perpendicular to the direction
    let d = match Bend::new([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], 0.4) {
        Ok(bend) => (0..5)
            .map(|i| {
                let sec = Gec::new(
                    Frame::z_plane(0.5 * i as f64),
                    [0.1, 0.0],
                    tg.x.clone(),
                    tg.y.clone(),
                );
                match sec {
                    Ok(sec) => {
                        let moved = bend.apply_gec(&sec);
                        let want: Vec<[f64; 3]> =
                            space(&sec).iter().map(|p| bend.apply(*p)).collect();
                        max_diff3(&space(&moved), &want)
                    }
                    Err(_) => f64::NAN,
                }
            })
            .fold(0.0, f64::max),
        Err(_) => f64::NAN,
    };
    out.push(c(
        "000 sec 5.2",
        "gec.transform_bend_chain",
        Kind::Residual,
        d,
        tol::ROUNDING,
        "bending a chain of z-plane sections equals the bend deformer applied to their points",
    ));
}

fn metric_checks(out: &mut Vec<Check>) {
    // ErM/ErA of the unit circle against points on the circle of radius 1.1
    let circle = Gec::ellipse(Frame::z_plane(0.0), [0.0, 0.0], 1.0, 1.0);
    let pts: Vec<[f64; 2]> = (0..50)
        .map(|k| {
            let t = 0.1 + 2.0 * PI * k as f64 / 50.0;
            [1.1 * t.cos(), 1.1 * t.sin()]
        })
        .collect();
    let e = metrics::errors(&circle, &pts);
    out.push(c(
        "002 Table 1",
        "gec.metrics_circle",
        Kind::Reference,
        (e.erm - 0.1).abs().max((e.era - 0.1).abs()),
        tol::SOLVE,
        "ErM = ErA = 0.1 for points on a circle of radius 1.1 against the unit circle",
    ));
    // an ellipse: distance from (0, 2) to ellipse a=2, b=1 is 1 (closest point (0,1))
    let ell = Gec::ellipse(Frame::z_plane(0.0), [0.0, 0.0], 2.0, 1.0);
    let s = metrics::Sampled::new(&ell);
    let (d, _) = s.closest([0.0, 2.0]);
    let (d2, _) = s.closest([3.0, 0.0]);
    out.push(c(
        "002 Table 1",
        "gec.metrics_ellipse_distance",
        Kind::Reference,
        (d - 1.0).abs().max((d2 - 1.0).abs()),
        tol::SOLVE,
        "point-to-curve distance with Newton polish on an ellipse (exact 1, 1)",
    ));
}
