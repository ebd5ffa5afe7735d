//! Benchmarks of the plate family (paper 001): one cursor move on a
//! ~100k-vertex region with the precomputed plate deformer, against
//! re-solving a sparse bi-Laplacian system on the same region (prefactored
//! faer Cholesky, the libigl-style per-move cost; and factor + solve), and
//! against a plain copy of the region's vertex buffer (memory-bound limit).

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::plate::baselines::{LaplacianParams, LaplacianSystem};
use pdesculpt::plate::shapes::{region_in_polygon, sheet};
use pdesculpt::plate::{Direction, PlateDeformer, RegionOptions};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let mesh = sheet(330);
    let poly = [[-1.2, -1.2], [1.2, -1.2], [1.2, 1.2], [-1.2, 1.2]];
    let region = region_in_polygon(&mesh, &poly);
    let opts = RegionOptions::default().with_view(Some([0.0, 0.0, 1.0]));
    let t = std::time::Instant::now();
    let plate = PlateDeformer::new(&mesh, &region, &opts).expect("region prepares");
    eprintln!(
        "region: {} vertices, {} boundary vertices, precompute {:.3} s",
        plate.region().len(),
        plate.boundary().loop_indices.len(),
        t.elapsed().as_secs_f64()
    );
    let handle: Vec<u32> = plate
        .region()
        .iter()
        .copied()
        .filter(|&v| {
            let p = mesh.positions[v as usize];
            p[0].hypot(p[1]) < 0.02
        })
        .collect();
    let t = std::time::Instant::now();
    let sys = LaplacianSystem::new(&mesh, plate.region(), &handle, &LaplacianParams::default())
        .expect("system factors");
    eprintln!(
        "bi-Laplacian factorisation {:.3} s",
        t.elapsed().as_secs_f64()
    );

    let mut g = c.benchmark_group("plate_move_100k");
    g.sample_size(20);
    let mut positions = mesh.positions.clone();
    let mut k = 0.0;
    g.bench_function("plate_update", |b| {
        b.iter(|| {
            k += 1e-3;
            let f = plate.force([0.0, 0.0, k], 70.0, Direction::Cursor);
            plate.apply(&mut positions, f).expect("buffer fits");
            black_box(&positions);
        })
    });
    let src = plate.rest().to_vec();
    let mut dst = vec![[0.0; 3]; src.len()];
    g.bench_function("buffer_copy", |b| {
        b.iter(|| {
            dst.copy_from_slice(black_box(&src));
            black_box(&dst);
        })
    });
    g.bench_function("bilaplacian_prefactored_solve", |b| {
        b.iter(|| black_box(sys.solve([0.0, 0.0, 1.0])))
    });
    g.sample_size(10);
    g.bench_function("bilaplacian_factor_and_solve", |b| {
        b.iter(|| {
            let s =
                LaplacianSystem::new(&mesh, plate.region(), &handle, &LaplacianParams::default())
                    .expect("system factors");
            black_box(s.solve([0.0, 0.0, 1.0]))
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
