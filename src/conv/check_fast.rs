//! Checks of the fast conv pipeline (issue 16) against the brute-force
//! reference: the segment hierarchy's field bounds enclose the exact field,
//! its point values stay within the stated error budget, the narrow-band
//! surface of every bundled model lies within [`FAST_MESH_TOLERANCE`] of the
//! reference surface (relative to the model size) with the same topology,
//! an incremental rebuild equals a full one, and the option sweep's
//! near-circular ellipse is reconstructed (issue 16).

use super::frontier::Frontier;
use super::incremental::{MeshCache, SketchCache};
use super::kernel::total_field;
use super::model::{Component, Model, Polygonizer};
use super::sample::Sampler;
use super::samples::{Lcg, FIT_RMS_TOLERANCE};
use super::{shapes, sketch};
use crate::check::{tol, Check, Kind};
use crate::check::{worst, Worst};
use crate::mesh::topology::report;
use crate::mesh::{norm, sub, Mesh};

const FAMILY: &str = "conv";
const PAPER: &str = "003";

/// Largest distance between the narrow-band and the reference surfaces,
/// relative to the model size (bounding-box diagonal). The four bundled
/// models measure 0.9e-6 to 3.4e-6 (issue 31: within about 10x of what is
/// measured; issue 16's budget was 1e-3).
pub const FAST_MESH_TOLERANCE: f64 = 3e-5;
/// Resolution of the fast-against-reference comparison in `verify`.
pub const COMPARE_RESOLUTION: usize = 32;

const MODELS: [(&str, &str); 4] = [
    ("blob", include_str!("../../data/conv/blob.json")),
    ("star", include_str!("../../data/conv/star.json")),
    ("arm", include_str!("../../data/conv/arm.json")),
    ("teddy", include_str!("../../data/conv/teddy.json")),
];

/// Bounding-box diagonal of a mesh.
pub fn mesh_size(m: &Mesh) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &m.positions {
        for k in 0..3 {
            lo[k] = lo[k].least(p[k]);
            hi[k] = hi[k].worst(p[k]);
        }
    }
    norm(sub(hi, lo))
}

/// Distance between two meshes of the same grid and polygoniser: the
/// largest distance between corresponding vertices (an upper bound of the
/// Hausdorff distance of the two surfaces, whose triangles correspond), or
/// infinity when their vertex or triangle lists differ in structure.
pub fn corresponding_distance(a: &Mesh, b: &Mesh) -> f64 {
    if a.positions.len() != b.positions.len() || a.triangles != b.triangles {
        return f64::INFINITY;
    }
    a.positions
        .iter()
        .zip(&b.positions)
        .map(|(p, q)| norm(sub(*p, *q)))
        .fold(0.0, worst)
}

/// Fast against reference: (relative distance, same topology report, note).
pub fn compare_with_reference(m: &Model, resolution: usize) -> Result<(f64, bool, String), String> {
    let b = m.build().map_err(|e| e.to_string())?;
    let t = m.options.threshold;
    let method = Polygonizer::MarchingTetrahedra;
    let fast = b
        .polygonize_with(resolution, t, method, Sampler::NarrowBand)
        .map_err(|e| e.to_string())?;
    let refm = b
        .polygonize_with(resolution, t, method, Sampler::Reference)
        .map_err(|e| e.to_string())?;
    let d = corresponding_distance(&fast, &refm) / mesh_size(&refm);
    let (rf, rr) = (report(&fast), report(&refm));
    let same =
        rf.watertight == rr.watertight && rf.manifold == rr.manifold && rf.oriented == rr.oriented;
    Ok((
        d,
        same,
        format!(
            "{} / {} triangles; watertight {}, manifold {}, oriented {} (reference {}, {}, {})",
            fast.triangles.len(),
            refm.triangles.len(),
            rf.watertight,
            rf.manifold,
            rf.oriented,
            rr.watertight,
            rr.manifold,
            rr.oriented
        ),
    ))
}

fn mesh_checks(out: &mut Vec<Check>) {
    for (name, text) in MODELS {
        let (measured, note) = match Model::from_json(text)
            .map_err(|e| e.to_string())
            .and_then(|m| compare_with_reference(&m, COMPARE_RESOLUTION))
        {
            Ok((d, true, note)) => (d, note),
            Ok((_, false, note)) => (f64::INFINITY, format!("topology differs: {note}")),
            Err(e) => (f64::INFINITY, e),
        };
        out.push(
            Check::new(
                FAMILY,
                PAPER,
                "issue 16 narrow band",
                &format!("conv.fast.{name}_matches_reference"),
                Kind::Reference,
                measured,
                FAST_MESH_TOLERANCE,
            )
            .note(format!(
                "{name} at {COMPARE_RESOLUTION} cells: narrow-band + BVH surface against every node \
                 by every segment, max vertex distance / model size; {note}"
            )),
        );
    }
}

fn bound_checks(out: &mut Vec<Check>) {
    let Ok(m) = Model::from_json(MODELS[3].1) else {
        return;
    };
    let Ok(b) = m.build() else { return };
    let Ok(bvh) = b.group_bvh(0) else { return };
    let comps: Vec<_> = b.groups[0].iter().map(|&i| &b.components[i]).collect();
    let exact = |x: [f64; 3]| -> f64 {
        comps
            .iter()
            .map(|c| total_field(&c.segments, x, c.sketch.s))
            .sum()
    };
    let t = m.options.threshold;
    let mut rng = Lcg(16);
    let (mut violation, mut point_ratio) = (0.0f64, 0.0f64);
    let budget = 1e-3 * t;
    let mut near = super::bvh::Interaction::default();
    let mut near_f = super::bvh::Interaction::default();
    let mut stack = Vec::new();
    for _ in 0..200 {
        let c = [0, 1, 2].map(|_| rng.range(-3.0, 3.0));
        let rho = rng.range(0.0, 0.6);
        let (lo, hi) = bvh.interval(c, rho, 0.05 * t);
        let (nlo, nhi) = bvh.near_list(c, rho, budget, &mut near);
        // the same ball inside a parent ball of twice its radius: bounds
        // and lists from the parent's frontier (the octree's path)
        let off = [0, 1, 2].map(|_| rng.range(-0.5, 0.5) * rho);
        let parent = [0, 1, 2].map(|k| c[k] + off[k]);
        let (mut pf, mut cf) = (Frontier::default(), Frontier::default());
        bvh.refine(
            &bvh.root_frontier(),
            parent,
            2.0 * rho,
            0.05 * t,
            &mut pf,
            &mut stack,
        );
        let (clo, chi) = bvh.refine(&pf, c, rho, 0.05 * t, &mut cf, &mut stack);
        bvh.refine(
            &bvh.root_frontier(),
            parent,
            2.0 * rho,
            budget,
            &mut pf,
            &mut stack,
        );
        let (flo, fhi) = bvh.near_list_from(&pf, c, rho, budget, &mut near_f, &mut stack);
        for _ in 0..5 {
            // a point of the ball
            let dir = [0, 1, 2].map(|_| rng.range(-1.0, 1.0));
            let r = rho * rng.next_f64() / norm(dir).worst(1.0);
            let x = [0, 1, 2].map(|k| c[k] + r * dir[k]);
            let f = exact(x);
            violation = violation.worst((lo - f).worst(f - hi).worst(0.0) / t);
            violation = violation.worst((clo - f).worst(f - chi).worst(0.0) / t);
            let approx = 0.5 * (nlo + nhi) + bvh.near_field(&near, x);
            point_ratio = point_ratio.worst((approx - f).abs() / (0.5 * budget));
            let approx = 0.5 * (flo + fhi) + bvh.near_field(&near_f, x);
            point_ratio = point_ratio.worst((approx - f).abs() / (0.5 * budget));
        }
        let f = exact(c);
        point_ratio = point_ratio.worst((bvh.field(c, budget) - f).abs() / (0.5 * budget));
    }
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "issue 16 field bounds",
            "conv.fast.bounds_enclose_field",
            Kind::Reference,
            violation,
            tol::scaled(tol::ROUNDING, 100.0),
        )
        .note("teddy: 200 random balls, 5 points each: how far the exact field leaves the hierarchy's bound (/T), from the root and from the frontier of a parent ball of twice the radius"),
    );
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "issue 16 error budget",
            "conv.fast.point_error_within_budget",
            Kind::Reference,
            point_ratio,
            1.0 + tol::scaled(tol::ROUNDING, 1e6),
        )
        .note("teddy: |approximate - exact field| / (budget / 2) at points (budget 1e-3 T; interaction lists from the root and from a parent ball's frontier, and single points); must stay <= 1"),
    );
}

/// The one-arctangent segment field against the closed form, and the
/// cluster expansion's error against its proven bound (module doc of
/// [`super::farfield`]), on random segments, clusters and points.
fn farfield_checks(out: &mut Vec<Check>) {
    use super::farfield::{Moments, SegmentField};
    use super::kernel::Segment;
    let mut rng = Lcg(1616);
    let (mut kernel_err, mut bound_ratio) = (0.0f64, 0.0f64);
    for _ in 0..200 {
        let cluster: Vec<Segment> = (0..1 + (rng.next_f64() * 6.0) as usize)
            .map(|_| {
                let p = [0, 1, 2].map(|_| rng.range(-0.5, 0.5));
                let q = [0, 1, 2].map(|k| p[k] + rng.range(-0.4, 0.4));
                Segment {
                    p,
                    q,
                    w0: rng.range(-0.5, 2.0),
                    w1: rng.range(-0.5, 2.0),
                    lambda: rng.range(-1.0, 3.0),
                }
            })
            .collect();
        let s = rng.range(0.3, 4.0);
        let c = [0, 1, 2].map(|_| rng.range(-0.1, 0.1));
        let mut m = Moments::default();
        let mut radius = 0.0f64;
        for g in &cluster {
            m.add(&Moments::of_segment(g, c));
            radius = radius.worst(norm(sub(g.p, c))).worst(norm(sub(g.q, c)));
        }
        for _ in 0..5 {
            let dir = [0, 1, 2].map(|_| rng.range(-1.0, 1.0));
            let dist = rng.range(0.0, 6.0);
            let x = [0, 1, 2].map(|k| c[k] + dist * dir[k] / norm(dir).worst(1e-9));
            let mut exact = 0.0;
            let mut mass = 0.0;
            for g in &cluster {
                let f = g.field(x, s);
                exact += f;
                let own = g.lambda.abs() * (g.w0.abs() + g.w1.abs()) * g.length();
                mass += own;
                let diff = (SegmentField::new(g, s).value(x) - f).abs();
                kernel_err = kernel_err.worst(diff / own.worst(f64::MIN_POSITIVE));
            }
            let dmin = (norm(sub(x, c)) - radius).worst(0.0);
            let err = (m.expansion(c, s, x) - exact).abs();
            let bound = m.error_bound(s, dmin);
            bound_ratio = bound_ratio.worst(err / (bound + tol::ROUNDING * mass));
        }
    }
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "issue 16 one-arctangent field",
            "conv.fast.segment_field_matches_closed_form",
            Kind::Reference,
            kernel_err,
            tol::scaled(tol::ROUNDING, 100.0),
        )
        .note("1000 random segments and points: |one-atan2 field - closed form| / (|lambda| (|w0|+|w1|) l)"),
    );
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "issue 16 cluster expansion",
            "conv.fast.expansion_within_bound",
            Kind::Reference,
            bound_ratio,
            1.0,
        )
        .note("200 random clusters (1-6 signed segments), 5 points each at any distance: |second-order expansion - exact| / proven bound; must stay <= 1"),
    );
}

/// [`super::farfield::atan2_upper`] against [`f64::atan2`] on ratios
/// spread over 24 decades and both signs of `x`, plus the branch points.
fn atan2_checks(out: &mut Vec<Check>) {
    use super::farfield::atan2_upper;
    let mut rng = Lcg(0xa7a2);
    let mut worst = 0.0f64;
    let mut cases: Vec<(f64, f64)> = vec![(1.0, 0.0), (1.0, -0.0), (1.0, 1.0), (1.0, -1.0)];
    for t in [2.414_213_562_373_095, 0.66] {
        for f in [1.0 - 1e-15, 1.0, 1.0 + 1e-15] {
            cases.push((t * f, 1.0));
            cases.push((t * f, -1.0));
        }
    }
    for _ in 0..20_000 {
        let y = 10f64.powf(rng.range(-12.0, 12.0));
        let x = 10f64.powf(rng.range(-12.0, 12.0)) * if rng.next_f64() < 0.5 { -1.0 } else { 1.0 };
        cases.push((y, x));
    }
    for (y, x) in cases {
        let e = y.atan2(x);
        worst = worst.worst((atan2_upper(y, x) - e).abs() / (e.abs() * f64::EPSILON));
    }
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "issue 16 one-arctangent field",
            "conv.fast.atan2_matches_std",
            Kind::Reference,
            worst,
            ATAN2_ULPS,
        )
        .note("20 000 random (y > 0, x) over 24 decades and the branch points tan(3 pi/8), 0.66: |Cephes atan2 - std atan2| / (|atan2| eps)"),
    );
}

/// Largest accepted error of [`super::farfield::atan2_upper`], in units of
/// the result's relative rounding (`f64::EPSILON`).
pub const ATAN2_ULPS: f64 = 4.0;

fn incremental_checks(out: &mut Vec<Check>) {
    // two separate components (two groups): a body and an arm beside it
    let mut m = Model {
        components: vec![
            Component {
                name: "body".into(),
                stroke: shapes::ellipse(1.0, 1.6, 160),
                ..Default::default()
            },
            Component {
                name: "arm".into(),
                stroke: shapes::ellipse(1.2, 0.4, 160),
                translate: [4.0, 0.0, 0.0],
                ..Default::default()
            },
        ],
        ..Default::default()
    };
    let res = 24;
    let t = m.options.threshold;
    let method = Polygonizer::MarchingTetrahedra;
    let (mut sketches, mut meshes) = (SketchCache::default(), MeshCache::default());
    let run = |m: &Model, sk: &mut SketchCache, me: &mut MeshCache| -> Option<(Mesh, Mesh)> {
        let inc = me
            .polygonize(&m.build_cached(sk).ok()?, res, t, method)
            .ok()?;
        let full = m.build().ok()?.polygonize(res, t, method).ok()?;
        Some((inc, full))
    };
    let first = run(&m, &mut sketches, &mut meshes);
    // edit the last stroke: scale it by 1.1 about its first point
    if let Some(c) = m.components.last_mut() {
        let o = c.stroke[0];
        for p in &mut c.stroke {
            *p = [o[0] + 1.1 * (p[0] - o[0]), o[1] + 1.1 * (p[1] - o[1])];
        }
    }
    let before = (sketches.built, meshes.built);
    let second = run(&m, &mut sketches, &mut meshes);
    let (measured, note) = match (first, second) {
        (Some((a, b)), Some((c, d))) => (
            corresponding_distance(&a, &b).worst(corresponding_distance(&c, &d)),
            format!(
                "body and arm at {res} cells, the arm's stroke edited: {} sketch(es) and {} group mesh(es) rebuilt, {} and {} reused",
                sketches.built - before.0,
                meshes.built - before.1,
                sketches.reused,
                meshes.reused
            ),
        ),
        _ => (f64::INFINITY, "a build failed".into()),
    };
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "issue 16 incremental",
            "conv.fast.incremental_equals_full",
            Kind::Reference,
            measured,
            0.0,
        )
        .note(format!(
            "max vertex distance, incremental against full rebuild; {note}"
        )),
    );
}

fn regression_checks(out: &mut Vec<Check>) {
    let (st, o) = super::samples::near_circular_ellipse_case();
    let measured = sketch::build(&st, &o).map_or(f64::INFINITY, |sk| sk.fit.rms_rel_error);
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "sec 3.3 exact weights",
            "conv.weights.exact_nonnegative_round_stroke",
            Kind::Threshold,
            measured,
            FIT_RMS_TOLERANCE,
        )
        .note("issue 16's sweep case (near-circular ellipse, exact weights): RMS |F-T|/T after the fit; 0.868 when the 2x2 weights could change sign"),
    );
}

/// Projected gradient of $\min_{\lambda \ge 0} \|\mathbf F\lambda - T\|^2$
/// at the fitted `lambda` of a sketch, over $\max_i |(\mathbf F^T T)_i|$,
/// recomputed from the field matrix (independent of the solver's own test).
pub fn fit_kkt_residual(sk: &sketch::Sketch) -> f64 {
    use nalgebra::DVector;
    let pts: Vec<[f64; 3]> = sk.polygon.iter().map(|p| [p[0], p[1], 0.0]).collect();
    let f = super::fit::field_matrix(&sk.segments, &pts, sk.s);
    let x = DVector::from_column_slice(&sk.fit.lambda);
    let c = f.transpose() * DVector::from_element(pts.len(), sk.threshold);
    let g = f.transpose() * (&f * &x) - &c;
    let worst = (0..x.len())
        .map(|i| {
            if x[i] > 0.0 {
                g[i].abs()
            } else {
                (-g[i]).worst(0.0)
            }
        })
        .fold(0.0, worst);
    worst / c.amax().worst(f64::MIN_POSITIVE)
}

fn hildreth_checks(out: &mut Vec<Check>) {
    let built = Model::from_json(MODELS[3].1).and_then(|m| m.build());
    let (measured, note) = match built {
        Ok(b) => {
            let mut worst = 0.0f64;
            let mut notes = Vec::new();
            for c in &b.components {
                let f = &c.sketch.fit;
                let r = fit_kkt_residual(&c.sketch);
                worst = worst.worst(if f.converged { r } else { f64::INFINITY });
                notes.push(format!("{} {} sweeps {r:.1e}", c.name, f.iterations));
            }
            (worst, notes.join(", "))
        }
        Err(e) => (f64::INFINITY, e.to_string()),
    };
    out.push(
        Check::new(
            FAMILY,
            PAPER,
            "sec 3.3 Hildreth-d'Esopo",
            "conv.fit.hildreth_converges_teddy",
            Kind::Threshold,
            measured,
            super::fit::HILDRETH_KKT_STOP,
        )
        .note(format!(
            "teddy strokes: optimality (KKT) residual / max|F^T T| of the fitted lambda, infinite when the \
             solver hit its sweep cap (5 of 6 strokes before the subspace step, issue 16): {note}"
        )),
    );
}

/// The fast-pipeline checks (registered through `conv::check::checks`).
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    mesh_checks(&mut out);
    bound_checks(&mut out);
    farfield_checks(&mut out);
    atan2_checks(&mut out);
    incremental_checks(&mut out);
    regression_checks(&mut out);
    hildreth_checks(&mut out);
    out
}
