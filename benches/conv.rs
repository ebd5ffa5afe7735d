//! Benchmarks of the conv family: the whole teddy build (fit + sample +
//! polygonise) with the narrow-band sampler against the brute-force
//! sampler at 96 and 160 cells; polygonisation throughput of marching
//! tetrahedra and surface nets (ours) against the fast-surface-nets crate on
//! the same sampled field; and the closed-form field against quadrature.
//!
//! Run one group: `cargo bench --bench conv -- conv_teddy --warm-up-time 1
//! --measurement-time 3`. The brute-force build at 160 cells takes 15-120 s
//! (idle to loaded machine), too long for criterion's ten samples: with
//! `CONV_BRUTE_160=1` the 160-cell group times one build of each sampler
//! in the same process and prints the ratio instead.

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::conv::model::{Component, Model, Polygonizer};
use pdesculpt::conv::sample::Sampler;
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

fn teddy(c: &mut Criterion) {
    let text = include_str!("../data/conv/teddy.json");
    let m = Model::from_json(text).expect("teddy");
    let t = m.options.threshold;
    let build = |res: usize, sampler: Sampler| {
        let b = m.build().expect("build");
        b.polygonize_with(res, t, Polygonizer::MarchingTetrahedra, sampler)
            .expect("mesh")
            .triangles
            .len()
    };
    for res in [96usize, 160] {
        let mut g = c.benchmark_group(format!("conv_teddy_{res}"));
        g.sample_size(10);
        g.bench_function("narrow_band", |b| {
            b.iter(|| build(res, Sampler::NarrowBand))
        });
        if res == 96 {
            g.bench_function("brute_force", |b| b.iter(|| build(res, Sampler::Reference)));
        }
        g.finish();
    }
    if std::env::var_os("CONV_BRUTE_160").is_some() {
        let time = |sampler: Sampler| {
            let t0 = std::time::Instant::now();
            let n = build(160, sampler);
            (t0.elapsed().as_secs_f64(), n)
        };
        let (fast, nf) = time(Sampler::NarrowBand);
        let (brute, nb) = time(Sampler::Reference);
        println!(
            "conv_teddy_160 one build each: narrow_band {fast:.3} s ({nf} triangles), \
             brute_force {brute:.2} s ({nb} triangles), ratio {:.1}x",
            brute / fast
        );
    }
    let mut g = c.benchmark_group("conv_teddy_fit_only");
    g.sample_size(10);
    g.bench_function("build", |b| {
        b.iter(|| m.build().expect("build").groups.len())
    });
    g.finish();
}

criterion_group!(benches, teddy, polygonize, field);
criterion_main!(benches);
