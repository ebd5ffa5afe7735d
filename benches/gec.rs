//! Fitting 4096 points of a closed section with J = 10 terms, three ways in
//! one group: Householder QR of the 4096 x 21 design matrix (the baseline,
//! the library default), Cholesky of the normal equations, and the FFT path
//! (uniform resampling in the parameter, then a 4096-point FFT truncated to
//! J harmonics; `fft_direct` skips the resampling because the samples are
//! already uniform in the parameter). Validation, plane fitting and
//! parameterisation are done once outside the timed loop; the ErM / ErA
//! evaluation (which dominates a full `fit`) is not timed.
//!
//! `nice cargo bench --bench gec -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::curve::gec::fit::{
    dft_coefficients, parameters, resample_uniform, section, solve, FrameChoice, Param,
    PLANARITY_TOL,
};
use pdesculpt::curve::gec::{Frame, Gec, Solver};
use std::hint::black_box;

const M: usize = 4096;
const J: usize = 10;

/// A bumpy 10-harmonic section in a tilted plane.
fn section_points() -> Vec<[f64; 3]> {
    let frame =
        Frame::from_normal([0.3, 2.0, -0.1], [0.1, 1.0, 0.2], [1.0, 0.0, 0.0]).expect("frame");
    let x: Vec<[f64; 2]> = (1..=J)
        .map(|n| {
            let w = 0.08 / n as f64;
            if n == 1 {
                [1.3, 0.05]
            } else {
                [w, -0.5 * w]
            }
        })
        .collect();
    let y: Vec<[f64; 2]> = (1..=J)
        .map(|n| {
            let w = 0.06 / n as f64;
            if n == 1 {
                [0.9, -0.04]
            } else {
                [0.5 * w, w]
            }
        })
        .collect();
    Gec::new(frame, [0.02, -0.01], x, y).expect("gec").sample(M)
}

fn fits(c: &mut Criterion) {
    let pts = section_points();
    let sec = section(&pts, FrameChoice::Auto, PLANARITY_TOL, 2 * J + 1).expect("section");
    let thetas = parameters(&sec.points, Param::Uniform, None);
    let mut g = c.benchmark_group("gec_fit_4096_J10");
    g.bench_function("qr_baseline", |b| {
        b.iter(|| solve(black_box(&sec.points), &thetas, J, Solver::Qr).expect("qr"))
    });
    g.bench_function("normal_equations", |b| {
        b.iter(|| {
            solve(black_box(&sec.points), &thetas, J, Solver::NormalEquations).expect("normal")
        })
    });
    g.bench_function("fft_resample", |b| {
        b.iter(|| {
            let (t0, uni) = resample_uniform(black_box(&sec.points), &thetas, M).expect("uni");
            dft_coefficients(&uni, t0, J).expect("fft")
        })
    });
    g.bench_function("fft_direct", |b| {
        b.iter(|| dft_coefficients(black_box(&sec.points), thetas[0], J).expect("fft"))
    });
    g.finish();
}

criterion_group!(benches, fits);
criterion_main!(benches);
