//! Curve networks (paper 004 secs 5, 6.3): solving and meshing a network
//! of C2 ODE patches against a baseline over the same curves, a bilinearly
//! blended **Coons patch** per patch (C0 across edges, no solve: each
//! patch is sampled straight from its four side polylines). Two networks:
//! the face network of the MakeHuman base (48 patches, 12 columns) and the
//! bundled quadruped (150 patches, 76 of them 3-sided). Both sides of a
//! pair sample `CELLS x CELLS` cells per patch; the Coons side includes
//! building the topology (it needs the sides' orientation), the ODE side
//! the whole `Network::build` (topology, lines, constraint curves, bases).

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::face::extract::{face_network, template, ROWS};
use pdesculpt::ode6::network::doc::{chord_params, DEFAULT_PARAMS};
use pdesculpt::ode6::network::topology::Side;
use pdesculpt::ode6::network::{samples, Network, NetworkDoc, Topology};
use std::hint::black_box;

/// Cells per patch side on both sides of every pair.
const CELLS: usize = 16;
/// Columns of the face network (the `--patches 48` default over 4 rows).
const FACE_COLUMNS: usize = 12;

/// A point of curve `c` at parameter `t` in `[0, 1]` (its params or chord
/// length), read from `from` to `to` when `along`, else backwards.
fn at(doc: &NetworkDoc, side: Side, t: f64, params: &[Vec<f64>]) -> [f64; 3] {
    let c = &doc.curves[side.curve];
    let t = if side.along { t } else { 1.0 - t };
    let ps = &params[side.curve];
    let k = ps.partition_point(|&x| x <= t).clamp(1, ps.len() - 1);
    let w = (t - ps[k - 1]) / (ps[k] - ps[k - 1]);
    let (a, b) = (c.points[k - 1], c.points[k]);
    [0, 1, 2].map(|i| a[i] + w * (b[i] - a[i]))
}

/// The baseline: one Coons patch per document patch, `(CELLS + 1)^2`
/// points each (a collapsed side reads its apex node).
fn coons(doc: &NetworkDoc) -> Vec<[f64; 3]> {
    let topo = Topology::new(doc).expect("topology");
    let params: Vec<Vec<f64>> = doc
        .curves
        .iter()
        .map(|c| {
            c.params
                .clone()
                .or_else(|| chord_params(&c.points))
                .expect("params")
        })
        .collect();
    let mut out = Vec::with_capacity(doc.patches.len() * (CELLS + 1) * (CELLS + 1));
    for s in &topo.sides {
        let corner = s.corners.map(|n| doc.nodes[n]);
        let u_side = |side: Option<Side>, v: f64, apex: [f64; 3]| {
            side.map_or(apex, |x| at(doc, x, v, &params))
        };
        for i in 0..=CELLS {
            let u = i as f64 / CELLS as f64;
            for j in 0..=CELLS {
                let v = j as f64 / CELLS as f64;
                let l = u_side(s.u0, v, corner[0]);
                let r = u_side(s.u1, v, corner[3]);
                let b = at(doc, s.v0, u, &params);
                let t = at(doc, s.v1, u, &params);
                out.push([0, 1, 2].map(|k| {
                    (1.0 - u) * l[k] + u * r[k] + (1.0 - v) * b[k] + v * t[k]
                        - ((1.0 - u) * (1.0 - v) * corner[0][k]
                            + (1.0 - u) * v * corner[1][k]
                            + u * v * corner[2][k]
                            + u * (1.0 - v) * corner[3][k])
                }));
            }
        }
    }
    out
}

fn bench(c: &mut Criterion) {
    let base = pdesculpt::makehuman::base_mesh().expect("base mesh");
    let t = template(FACE_COLUMNS).expect("face template");
    let face = face_network(&t, &base.positions, &[DEFAULT_PARAMS; FACE_COLUMNS]);
    assert_eq!(face.patches.len(), FACE_COLUMNS * ROWS);
    for (name, doc) in [("face_48", face), ("quadruped_150", samples::quadruped())] {
        let mut g = c.benchmark_group(format!("network/{name}"));
        g.sample_size(20);
        g.bench_function("ode6_c2_build_and_mesh", |b| {
            b.iter(|| {
                let net = Network::build(black_box(doc.clone())).expect("network");
                black_box(net.mesh(CELLS))
            })
        });
        g.bench_function("coons_c0_baseline", |b| {
            b.iter(|| black_box(coons(black_box(&doc))))
        });
        g.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
