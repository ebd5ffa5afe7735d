//! The closed-body reconstruction of the bundled MakeHuman body
//! (`body::closed::reconstruct_closed`: layout from the mesh, traces,
//! 94 GEC section fits, six C2 PDE chains, the hips and shoulders
//! transitions, the mesh and its report against the skin), beside the
//! issue's baseline in the same run: one dense global solve, the torso's
//! `Chain::c2_global` through its 13 sections (per harmonic one dense
//! 24 x 24 system). Report the ratio.

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::body::closed::{reconstruct_closed, ClosedOptions};
use pdesculpt::character::part::build_part;
use pdesculpt::pde6::{Chain, Section};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let skin = pdesculpt::makehuman::base_body()
        .expect("bundled body")
        .mesh;
    let o = ClosedOptions::default();
    let body = reconstruct_closed(&skin, &o).expect("reconstructs");
    let torso = &body.specs[0];
    let part = build_part(torso).expect("torso builds");
    let sections: Vec<Section> = torso
        .sections
        .iter()
        .map(|s| Section {
            u: s.u,
            curve: part.section(s.u, 0),
        })
        .collect();
    let mut g = c.benchmark_group("body");
    g.bench_function("whole_body_reconstruction", |b| {
        b.iter(|| black_box(reconstruct_closed(&skin, &o).expect("reconstructs")))
    });
    g.bench_function("one_dense_global_solve_torso", |b| {
        b.iter(|| black_box(Chain::c2_global(o.a, &sections).expect("solves")))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
