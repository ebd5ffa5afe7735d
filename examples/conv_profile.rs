//! Where the time of a teddy build goes (issue 16): fit, sampling (narrow
//! band) and polygonisation, timed with `std::time` per stage. Not a
//! benchmark (no baseline); the criterion bench is `benches/conv.rs`.
//!
//! `cargo run --release --example conv_profile -- [RESOLUTION...]`

use pdesculpt::conv::model::Model;
use pdesculpt::conv::narrow::FIELD_TOLERANCE;
use pdesculpt::mesh::isosurface::marching_tetrahedra;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let text = include_str!("../data/conv/teddy.json");
    let m = Model::from_json(text)?;
    let t = m.options.threshold;
    let res: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse())
        .collect::<Result<_, _>>()?;
    let res = if res.is_empty() { vec![96, 160] } else { res };
    let t0 = Instant::now();
    let b = m.build()?;
    let fit = t0.elapsed().as_secs_f64();
    println!("build (skeleton + weights + fit): {:.1} ms", 1e3 * fit);
    for c in &b.components {
        println!(
            "  {:8} {:4} segments, fit {:.1} ms, {} sweeps, converged {}, max rel err {:.2e}",
            c.name,
            c.segments.len(),
            1e3 * c.sketch.fit.seconds,
            c.sketch.fit.iterations,
            c.sketch.fit.converged,
            c.sketch.fit.max_rel_error
        );
    }
    if std::env::var("CONV_DIAG").is_ok() {
        use nalgebra::DVector;
        for c in &b.components {
            let sk = &c.sketch;
            let pts: Vec<[f64; 3]> = sk.polygon.iter().map(|p| [p[0], p[1], 0.0]).collect();
            let f = pdesculpt::conv::fit::field_matrix(&sk.segments, &pts, sk.s);
            let q = f.transpose() * &f;
            let cv = f.transpose() * DVector::from_element(pts.len(), t);
            let x = DVector::from_vec(sk.fit.lambda.clone());
            let g = &q * &x - &cv;
            let ev = q.clone().symmetric_eigenvalues();
            let free: Vec<usize> = (0..x.len()).filter(|&i| x[i] > 0.0).collect();
            let qf =
                nalgebra::DMatrix::from_fn(free.len(), free.len(), |a, bb| q[(free[a], free[bb])]);
            let evf = qf.symmetric_eigenvalues();
            let kkt = (0..x.len())
                .map(|i| {
                    if x[i] > 0.0 {
                        g[i].abs()
                    } else {
                        (-g[i]).max(0.0)
                    }
                })
                .fold(0.0, f64::max);
            println!("  {:8} n {} free {} cond(Q) {:.2e} cond(Q_FF) {:.2e} kkt/cmax {:.2e} max lambda {:.2e} diag range {:.2e}..{:.2e}",
                c.name, x.len(), free.len(),
                ev.max() / ev.min().abs().max(1e-300), evf.max() / evf.min().abs().max(1e-300),
                kkt / cv.amax(), x.max(), q.diagonal().min(), q.diagonal().max());
        }
    }
    for &r in &res {
        let (mut ts, mut tp) = (0.0, 0.0);
        for g in 0..b.groups.len() {
            let t1 = Instant::now();
            let Some((grid, st)) = b.sample_group_fast(g, r, t, FIELD_TOLERANCE)? else {
                continue;
            };
            let t2 = Instant::now();
            let mesh = marching_tetrahedra(&grid, t);
            let t3 = Instant::now();
            ts += (t2 - t1).as_secs_f64();
            tp += (t3 - t2).as_secs_f64();
            println!(
                "  res {r} group {g}: sample {:.1} ms ({} nodes, {} evaluated, {:.1} segments + {:.1} clusters per evaluation, {} boxes tested), polygonise {:.1} ms, {} triangles",
                1e3 * (t2 - t1).as_secs_f64(),
                st.nodes,
                st.evaluated,
                st.segment_evaluations as f64 / st.evaluated.max(1) as f64,
                st.cluster_evaluations as f64 / st.evaluated.max(1) as f64,
                st.boxes_tested,
                1e3 * (t3 - t2).as_secs_f64(),
                mesh.triangles.len()
            );
        }
        println!(
            "res {r}: fit {:.1} ms + sample {:.1} ms + polygonise {:.1} ms",
            1e3 * fit,
            1e3 * ts,
            1e3 * tp
        );
    }
    Ok(())
}
