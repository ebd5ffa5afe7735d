//! Benchmarks of the conv family: polygonisation throughput of marching
//! tetrahedra and surface nets (ours) against the fast-surface-nets crate on
//! the same sampled field, and the closed-form field against quadrature.

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::conv::model::{Component, Model};
use pdesculpt::conv::{kernel, shapes};
use pdesculpt::mesh::isosurface::{marching_tetrahedra, surface_nets, ScalarGrid};

fn polygonize(c: &mut Criterion) {
    let m = Model {
        components: vec![Component {
            name: "star".into(),
            stroke: shapes::star(5, 0.6, 1.6, 400),
            ..Default::default()
        }],
        ..Default::default()
    };
    let b = m.build().expect("build");
    for n in [48u32, 96] {
        let grid = ScalarGrid::sample([-2.2, -2.2, -1.2], [2.2, 2.2, 1.2], [n as usize; 3], |r| {
            b.group_field(0, r)
        })
        .expect("grid");
        // the same samples as a signed distance-like field (negative inside)
        let sdf: Vec<f32> = grid.values.iter().map(|v| (1.0 - v) as f32).collect();
        let mut g = c.benchmark_group(format!("conv_polygonize_{n}"));
        g.bench_function("marching_tetrahedra", |bch| {
            bch.iter(|| marching_tetrahedra(&grid, 1.0))
        });
        g.bench_function("surface_nets_ours", |bch| {
            bch.iter(|| surface_nets(&grid, 1.0))
        });
        g.bench_function("fast_surface_nets_crate", |bch| {
            use fast_surface_nets::ndshape::RuntimeShape;
            let shape = RuntimeShape::<u32, 3>::new([n, n, n]);
            let mut buf = fast_surface_nets::SurfaceNetsBuffer::default();
            bch.iter(|| {
                fast_surface_nets::surface_nets(&sdf, &shape, [0; 3], [n - 1; 3], &mut buf);
                buf.indices.len()
            })
        });
        g.finish();
    }
}

fn field(c: &mut Criterion) {
    let seg = kernel::Segment {
        p: [0.0; 3],
        q: [1.0, 0.2, 0.0],
        w0: 1.0,
        w1: 2.0,
        lambda: 1.0,
    };
    let mut g = c.benchmark_group("conv_field");
    g.bench_function("closed_form", |b| {
        b.iter(|| seg.field(std::hint::black_box([0.3, 0.4, -0.2]), 1.5))
    });
    g.bench_function("quadrature_1e-12", |b| {
        b.iter(|| {
            kernel::field_by_quadrature(&seg, std::hint::black_box([0.3, 0.4, -0.2]), 1.5, 1e-12)
        })
    });
    g.finish();
}

criterion_group!(benches, polygonize, field);
criterion_main!(benches);
