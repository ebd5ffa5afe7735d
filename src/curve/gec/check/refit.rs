//! Refit round trips (sample a GEC, fit it again) and FFT against least
//! squares on uniform samples.

use super::*;
use crate::check::Worst;

pub(super) fn refit_checks(tg: &Gec, out: &mut Vec<Check>) {
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
            let mut d = (a.0[0] - b.0[0]).abs().worst((a.0[1] - b.0[1]).abs());
            for n in 0..10 {
                for k in 0..2 {
                    d = d
                        .worst((a.1[n][k] - b.1[n][k]).abs())
                        .worst((a.2[n][k] - b.2[n][k]).abs());
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
