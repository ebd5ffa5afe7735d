//! Benchmarks of the pde4 family: separable (tensor-product) grid evaluation
//! vs the direct double sum, M = N = 32 on a 256 x 256 grid, in the same run.

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::pde4::four_sided::{self, FourSided};
use pdesculpt::pde4::samples::sample_forces;
use pdesculpt::pde4::two_sided::{self, TwoSided};
use pdesculpt::pde4::ShapeParams;
use pdesculpt::surface::Surface;
use std::hint::black_box;
use std::time::Duration;

const TERMS: usize = 32;
const GRID: usize = 256;

fn grid_axis(closed: bool) -> Vec<f64> {
    let d = if closed { GRID } else { GRID - 1 } as f64;
    (0..GRID).map(|i| i as f64 / d).collect()
}

fn bench(c: &mut Criterion) {
    let forces = sample_forces();
    let (us, vs) = (grid_axis(false), grid_axis(true));
    let two = TwoSided::new(
        [ShapeParams::PLATE; 3],
        &forces,
        TERMS,
        TERMS,
        two_sided::Method::Exact,
        None,
    )
    .expect("two-sided");
    let four = FourSided::new(
        [ShapeParams::PLATE; 3],
        &forces,
        TERMS,
        TERMS,
        four_sided::Method::Galerkin,
    )
    .expect("four-sided");
    let mut g = c.benchmark_group("pde4_grid_256_M32_N32");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(8))
        .warm_up_time(Duration::from_secs(1));
    g.bench_function("two_sided_separable", |b| {
        b.iter(|| black_box(two.grid(black_box(&us), black_box(&vs))))
    });
    g.bench_function("two_sided_naive_double_sum", |b| {
        b.iter(|| black_box(two.grid_naive(black_box(&us), black_box(&vs))))
    });
    g.bench_function("four_sided_separable", |b| {
        b.iter(|| black_box(four.grid(black_box(&us), black_box(&us))))
    });
    g.bench_function("four_sided_naive_double_sum", |b| {
        b.iter(|| black_box(four.grid_naive(black_box(&us), black_box(&us))))
    });
    g.finish();
    let mut s = c.benchmark_group("pde4_solve_M16_N16");
    s.sample_size(10)
        .measurement_time(Duration::from_secs(4))
        .warm_up_time(Duration::from_secs(1));
    s.bench_function("four_sided_galerkin_solve", |b| {
        b.iter(|| {
            black_box(FourSided::new(
                [ShapeParams::PLATE; 3],
                &forces,
                16,
                16,
                four_sided::Method::Galerkin,
            ))
        })
    });
    s.bench_function("two_sided_exact_solve", |b| {
        b.iter(|| {
            black_box(TwoSided::new(
                [ShapeParams::PLATE; 3],
                &forces,
                16,
                16,
                two_sided::Method::Exact,
                None,
            ))
        })
    });
    s.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
