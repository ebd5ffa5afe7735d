//! Benchmark of template fitting (000 sec 4.2.1, low level): the MakeHuman
//! base (every `v` of the base OBJ, 13k+ vertices) fitted to the front
//! profile of the `male->boy` target, beside the same fit with a dense
//! thin-plate solve on *all* outline points as centres (baseline).
//!
//! What is timed: the whole low level of [`fit`] (sketch validation,
//! landmarks on both outlines, the Umeyama similarity, arc-length
//! correspondence, the dense thin-plate LU solve with its residual, and the
//! warp of every template vertex), and the fit's self-check: the template's
//! outline and the fitted mesh's outline extracted (`mesh_outline`) and
//! measured against the sketch, plus any correction pass. Not timed: the
//! target's outline (the sketch), and the condition number (off in both).

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::template::measure::mesh_outline;
use pdesculpt::template::study::{makehuman_template, CASES};
use pdesculpt::template::{fit, FitOptions, Sketch, View};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let template = makehuman_template(&[]).expect("bundled template");
    let case = CASES
        .iter()
        .find(|c| c.name == "male->boy")
        .expect("study case");
    let ts: Vec<_> = case
        .target
        .iter()
        .map(|n| (pdesculpt::makehuman::target(n).expect("target"), 1.0))
        .collect();
    let target = pdesculpt::makehuman::body(&ts).expect("target body").mesh;
    let sketch = Sketch {
        front: mesh_outline(&target, View::Front).expect("target outline"),
        ..Default::default()
    };
    let t_front = mesh_outline(&template.skin, View::Front).expect("template outline");
    let mut ours = FitOptions::default();
    ours.condition = false;
    let mut dense = ours.clone();
    dense.front_centres = t_front.len();
    eprintln!(
        "template: {} vertices (skin {}); template outline {} points, sketch {} points; \
         centres: ours {}, baseline {}",
        template.mesh.positions.len(),
        template.skin.positions.len(),
        t_front.len(),
        sketch.front.len(),
        ours.front_centres,
        dense.front_centres
    );
    let mut g = c.benchmark_group("template_low_makehuman");
    g.sample_size(10);
    g.bench_function("fit_low_400_centres", |b| {
        b.iter(|| black_box(fit(&template, &sketch, &ours, &mesh_outline).expect("fit")))
    });
    g.bench_function("fit_low_all_outline_centres", |b| {
        b.iter(|| black_box(fit(&template, &sketch, &dense, &mesh_outline).expect("fit")))
    });
    g.finish();
    // centre-count sweep (same fit), to see where the time goes
    let mut g = c.benchmark_group("template_low_makehuman_centres");
    g.sample_size(10);
    for n in [200, 399, 486, 800] {
        let mut o = ours.clone();
        o.front_centres = n;
        let r = fit(&template, &sketch, &o, &mesh_outline).expect("fit");
        eprintln!("{n} requested: {:?}", r.levels[0].0);
        g.bench_function(format!("fit_low_{n}"), |b| {
            b.iter(|| black_box(fit(&template, &sketch, &o, &mesh_outline).expect("fit")))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
