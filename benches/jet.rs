//! Jets against finite differences: all derivatives up to (6, 6) of a closed
//! form, by one jet evaluation and by nested central differences of the
//! f64 evaluation (the naive baseline, which is also far less accurate).

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::jet::{check::golden_function, Jet6x6};
use std::hint::black_box;

fn f(u: f64, v: f64) -> f64 {
    golden_function("exp_sin_quotient", u, v).unwrap_or(0.0)
}

/// d^(i+j) f / du^i dv^j by nested central differences with step h.
fn fd(i: usize, j: usize, u: f64, v: f64, h: f64) -> f64 {
    if i > 0 {
        (fd(i - 1, j, u + h, v, h) - fd(i - 1, j, u - h, v, h)) / (2.0 * h)
    } else if j > 0 {
        (fd(0, j - 1, u, v + h, h) - fd(0, j - 1, u, v - h, h)) / (2.0 * h)
    } else {
        f(u, v)
    }
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("derivatives_to_6x6");
    g.bench_function("jet", |b| {
        b.iter(|| {
            let j = golden_function(
                "exp_sin_quotient",
                Jet6x6::var_u(black_box(0.3)),
                Jet6x6::var_v(black_box(0.7)),
            );
            black_box(j)
        })
    });
    g.bench_function("finite_differences", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for i in 0..=6 {
                for j in 0..=6 {
                    s += fd(i, j, black_box(0.3), black_box(0.7), 1e-2);
                }
            }
            black_box(s)
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
