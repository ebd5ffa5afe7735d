//! ODE6 surfaces: the precomputed basis g_1..g_6 (one 6x6 inverse per
//! parameter set, then a tensor product) against solving the 6x6 boundary
//! system for every iso-parametric line and coordinate (the baseline the
//! closed form replaces), on the same 65 x 128 grid of the paper case
//! (rho = lambda = 1, eta = 3) and the Fig 4c case (rho = lambda = 1e-4).

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::ode6::basis::solve_line;
use pdesculpt::ode6::samples::test_curve;
use pdesculpt::ode6::{Basis, BoundaryCurves, Curve, Ode6Surface, Params};
use pdesculpt::surface::{tessellate, Surface, Tessellation};
use std::hint::black_box;

const NU: usize = 64;
const NV: usize = 128;

fn curves() -> BoundaryCurves {
    BoundaryCurves::approach1(
        Curve::Fourier(test_curve(1.0, 0.0, 0.0)),
        Curve::Fourier(test_curve(0.6, 1.0, 1.0)),
        [1.0, 0.5, -1.0, 2.0],
    )
    .expect("curves")
}

/// The baseline: per v sample and coordinate, build and solve the 6x6
/// system and evaluate the line at every u.
fn per_line(p: Params, bc: &BoundaryCurves, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
    let mut out = vec![[0.0; 3]; us.len() * vs.len()];
    for (iv, &v) in vs.iter().enumerate() {
        let c: Vec<[f64; 3]> = (0..6).map(|j| bc.c(j, v)).collect();
        for k in 0..3 {
            let cj = [c[0][k], c[1][k], c[2][k], c[3][k], c[4][k], c[5][k]];
            let line = solve_line(p, &cj, us).expect("solve");
            for (iu, x) in line.into_iter().enumerate() {
                out[iu * vs.len() + iv][k] = x;
            }
        }
    }
    out
}

fn bench(c: &mut Criterion) {
    let us: Vec<f64> = (0..=NU).map(|i| i as f64 / NU as f64).collect();
    let vs: Vec<f64> = (0..NV).map(|i| i as f64 / NV as f64).collect();
    for (name, p) in [
        ("paper_rho1_eta3_lambda1", Params::new(1.0, 3.0, 1.0)),
        ("fig4c_rho_lambda_1e-4", Params::new(1e-4, 3.0, 1e-4)),
    ] {
        let mut g = c.benchmark_group(format!("ode6_grid_65x128/{name}"));
        let bc = curves();
        g.bench_function("basis_precomputed_grid", |b| {
            b.iter(|| {
                let s = Ode6Surface::new(Basis::new(black_box(p)).expect("basis"), bc.clone());
                black_box(s.grid(&us, &vs))
            })
        });
        g.bench_function("basis_precomputed_tessellate", |b| {
            b.iter(|| {
                let s = Ode6Surface::new(Basis::new(black_box(p)).expect("basis"), bc.clone());
                black_box(tessellate(&s, Tessellation { nu: NU, nv: NV }))
            })
        });
        g.bench_function("solve_6x6_per_line", |b| {
            b.iter(|| black_box(per_line(black_box(p), &bc, &us, &vs)))
        });
        g.finish();
    }
    let mut g = c.benchmark_group("ode6_basis_construction");
    g.bench_function("series_case", |b| {
        b.iter(|| black_box(Basis::new(black_box(Params::new(1.0, 3.0, 1.0)))))
    });
    g.bench_function("closed_form_case", |b| {
        b.iter(|| black_box(Basis::new(black_box(Params::new(1e-4, 3.0, 1e-4)))))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
