//! Benchmarks of the profile family: the outline of the MakeHuman body at
//! the default resolution, beside a naive rasteriser (every pixel centre of
//! every triangle's bounding box tested by barycentric signs, the coverage
//! step alone, same resolution); and the grid self-intersection test of a
//! 20k-point profile beside the all-pairs test.

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::mesh::Mesh;
use pdesculpt::profile::{outline_of_mesh, OutlineOptions, Profile, View};
use std::f64::consts::PI;
use std::hint::black_box;

/// Naive coverage raster of the projected triangles (baseline).
fn naive_raster(m: &Mesh, view: View, resolution: usize) -> usize {
    let p: Vec<[f64; 2]> = m.positions.iter().map(|&q| view.project(q)).collect();
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for q in &p {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    let h = (hi[0] - lo[0]).max(hi[1] - lo[1]) / resolution as f64;
    let nx = ((hi[0] - lo[0]) / h) as usize + 1;
    let ny = ((hi[1] - lo[1]) / h) as usize + 1;
    let mut grid = vec![false; nx * ny];
    let o = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    for t in &m.triangles {
        let [a, b, c] = [p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]];
        let i0 = ((a[0].min(b[0]).min(c[0]) - lo[0]) / h) as usize;
        let i1 = (((a[0].max(b[0]).max(c[0]) - lo[0]) / h) as usize).min(nx - 1);
        let j0 = ((a[1].min(b[1]).min(c[1]) - lo[1]) / h) as usize;
        let j1 = (((a[1].max(b[1]).max(c[1]) - lo[1]) / h) as usize).min(ny - 1);
        for j in j0..=j1 {
            for i in i0..=i1 {
                let q = [lo[0] + i as f64 * h, lo[1] + j as f64 * h];
                let (d0, d1, d2) = (o(a, b, q), o(b, c, q), o(c, a, q));
                let inside =
                    (d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0) || (d0 <= 0.0 && d1 <= 0.0 && d2 <= 0.0);
                if inside {
                    grid[j * nx + i] = true;
                }
            }
        }
    }
    grid.iter().filter(|&&b| b).count()
}

/// All-pairs self-intersection test (baseline): proper crossings only.
fn naive_crossings(p: &[[f64; 2]]) -> bool {
    let n = p.len();
    let o = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    for i in 0..n {
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            let (a, b, c, d) = (p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]);
            if o(a, b, c) * o(a, b, d) < 0.0 && o(c, d, a) * o(c, d, b) < 0.0 {
                return true;
            }
        }
    }
    false
}

fn bench(c: &mut Criterion) {
    let body = pdesculpt::makehuman::base_body()
        .expect("bundled body")
        .mesh;
    let opts = OutlineOptions::default();
    eprintln!(
        "body: {} vertices, {} triangles; resolution {}",
        body.positions.len(),
        body.triangles.len(),
        opts.resolution
    );
    let mut g = c.benchmark_group("profile_outline_makehuman");
    g.sample_size(20);
    g.bench_function("outline_of_mesh_front", |b| {
        b.iter(|| black_box(outline_of_mesh(&body, View::Front, &opts).expect("outline")))
    });
    g.bench_function("naive_raster_front", |b| {
        b.iter(|| black_box(naive_raster(&body, View::Front, opts.resolution)))
    });
    g.finish();

    let n = 20_000;
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / n as f64;
            let r = 1.0 + 0.1 * (7.0 * t).sin();
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    let mut g = c.benchmark_group("profile_validate_20k");
    g.sample_size(10);
    g.bench_function("profile_new_grid", |b| {
        b.iter(|| black_box(Profile::new(View::Front, pts.clone()).expect("simple")))
    });
    g.bench_function("all_pairs_baseline", |b| {
        b.iter(|| black_box(naive_crossings(&pts)))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
