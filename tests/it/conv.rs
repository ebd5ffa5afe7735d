//! Integration tests of the conv family (paper 003).

use pdesculpt::check::tol;
use pdesculpt::conv::model::{Component, Model, Polygonizer};
use pdesculpt::conv::{kernel, shapes, sketch, stroke, ConvError};
use pdesculpt::mesh::topology::report;
use proptest::prelude::*;

/// Relative rounding of a few f64 operations (an exact split or a sum).
const FEW_OPS: f64 = 1e-15;
/// Volumes at 32 and 48 cells within this fraction of the finest mesh's.
const VOLUME_CONVERGENCE: f64 = 0.1;
/// Over the whole option sweep the fit's relative RMS only guards against
/// blow-up (the default options meet `FIT_RMS_TOLERANCE`, 0.15).
const FIT_BLOWUP: f64 = 0.5;

#[test]
fn checks_pass() {
    for c in crate::shared::family_checks("conv") {
        assert!(
            c.passed,
            "{} measured {} tol {}: {}",
            c.name, c.measured, c.tolerance, c.note
        );
    }
}

#[test]
fn bundled_models_build_closed_meshes() {
    for f in ["blob", "star", "arm", "teddy"] {
        let path = format!("{}/data/conv/{f}.json", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).expect("model file");
        let m = Model::from_json(&text).expect("parse");
        let b = m.build().expect("build");
        let mesh = b
            .polygonize(24, m.options.threshold, Polygonizer::MarchingTetrahedra)
            .expect("mesh");
        let r = report(&mesh);
        assert!(r.watertight && r.manifold && r.oriented, "{f}: {r:?}");
    }
}

#[test]
fn bad_strokes_are_rejected() {
    let o = stroke::StrokeOptions::default();
    // a figure eight with unequal lobes (equal lobes have zero signed area)
    let eight: Vec<[f64; 2]> = shapes::figure_eight(200)
        .into_iter()
        .map(|p| {
            if p[0] > 0.0 {
                [2.0 * p[0], 2.0 * p[1]]
            } else {
                p
            }
        })
        .collect();
    assert!(matches!(
        stroke::filter_stroke(&eight, &o),
        Err(ConvError::SelfIntersecting { .. })
    ));
    assert!(matches!(
        stroke::filter_stroke(&[[0.0, 0.0], [1.0, 0.0]], &o),
        Err(ConvError::TooShort { .. })
    ));
    let line: Vec<[f64; 2]> = (0..20).map(|i| [i as f64, 0.0]).collect();
    assert!(matches!(
        stroke::filter_stroke(&line, &o),
        Err(ConvError::ZeroArea { .. })
    ));
    let mut nan = shapes::ellipse(1.0, 1.0, 50);
    nan[3][1] = f64::NAN;
    assert!(matches!(
        stroke::filter_stroke(&nan, &o),
        Err(ConvError::NonFinite { index: 3 })
    ));
    assert!(Model::from_json("{\"components\": 3}").is_err());
}

#[test]
fn cli_field_matches_library() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_pdesculpt"))
        .args([
            "--json",
            "conv",
            "field",
            "--segment",
            "0,0,0,1,0,0",
            "--weights",
            "1,2",
            "--s",
            "1.5",
            "--at",
            "0.3,0.4,-0.2",
        ])
        .output()
        .expect("run");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    let seg = kernel::Segment {
        p: [0.0; 3],
        q: [1.0, 0.0, 0.0],
        w0: 1.0,
        w1: 2.0,
        lambda: 1.0,
    };
    let f = seg.field([0.3, 0.4, -0.2], 1.5);
    assert!((v["field"].as_f64().unwrap_or(f64::NAN) - f).abs() <= FEW_OPS * f.abs());
}

proptest! {
    #![proptest_config(crate::strategies::config(24))]
    #[test]
    fn ellipses_and_stars_build_finite_closed_surfaces(a in 0.5f64..3.0, b in 0.3f64..2.0, arms in 3usize..7, star in any::<bool>()) {
        let st = if star { shapes::star(arms, 0.5 * b.min(a), a.max(b) + 0.5, 300) } else { shapes::ellipse(a, b, 200) };
        let sk = sketch::build(&st, &Default::default()).expect("build");
        prop_assert!(sk.segments.iter().all(|s| s.w0.is_finite() && s.w1.is_finite() && s.lambda.is_finite() && s.lambda >= 0.0));
        prop_assert!(sk.fit.rms_rel_error.is_finite() && sk.fit.rms_rel_error < pdesculpt::conv::check::FIT_RMS_TOLERANCE);
        let m = Model { components: vec![Component { name: "c".into(), stroke: st, ..Default::default() }], ..Default::default() };
        let mesh = m.build().expect("b").polygonize(16, 1.0, Polygonizer::MarchingTetrahedra).expect("mesh");
        prop_assert!(mesh.positions.iter().all(|p| p.iter().all(|x| x.is_finite())));
        let r = report(&mesh);
        prop_assert!(r.watertight && r.manifold && r.oriented);
    }

    #[test]
    fn field_matches_quadrature(seed in any::<u64>()) {
        let mut rng = pdesculpt::conv::check::Lcg(seed);
        let (seg, r, s) = pdesculpt::conv::check::random_case(&mut rng);
        let f = seg.field(r, s);
        let q = kernel::field_by_quadrature(&seg, r, s, 1e-14 * f.abs());
        prop_assert!(f.is_finite() && (f - q).abs() <= pdesculpt::check::tol::QUADRATURE * q.abs());
    }
}

// ---- strokes -------------------------------------------------------------

#[test]
fn orientation_is_normalised_to_counter_clockwise() {
    let o = stroke::StrokeOptions::default();
    let ccw = shapes::star(5, 0.6, 1.6, 300);
    let mut cw = ccw.clone();
    cw.reverse();
    for raw in [ccw, cw] {
        let p = stroke::filter_stroke(&raw, &o).expect("filter");
        assert!(pdesculpt::polygon::signed_area(&p) > 0.0);
        assert!(pdesculpt::polygon::is_simple(&p));
    }
}

/// A closed stroke with a self-intersection (a bow tie with unequal lobes).
fn bow_tie() -> Vec<[f64; 2]> {
    shapes::figure_eight(200)
        .into_iter()
        .map(|p| {
            if p[0] > 0.0 {
                [2.0 * p[0], 2.0 * p[1]]
            } else {
                p
            }
        })
        .collect()
}

#[test]
fn self_intersection_error_is_clear() {
    let e = sketch::build(&bow_tie(), &Default::default()).expect_err("must fail");
    assert!(e.to_string().contains("intersects itself"), "{e}");
    let e = stroke::filter_stroke(&[[0.0, 0.0], [1.0, 0.0]], &Default::default())
        .expect_err("too short");
    assert!(e.to_string().contains("too short"), "{e}");
}

// ---- skeleton circle rules ----------------------------------------------

fn line_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let e = [b[0] - a[0], b[1] - a[1]];
    ((p[0] - a[0]) * e[1] - (p[1] - a[1]) * e[0]).abs() / e[0].hypot(e[1])
}

fn d2(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Every triangle's circle follows the paper's rule for its type:
/// junction = circumcircle, terminal = incircle, sleeve = circumcircle or
/// the edge-tangent circle (centre halfway up the altitude onto the
/// external edge); kinds match the number of external edges; radii never
/// exceed the circle's and stay positive.
fn assert_circle_rules(poly: &[[f64; 2]]) {
    use pdesculpt::conv::skeleton::{extract, CircleKind, TriangleKind};
    let sk = extract(poly, &Default::default()).expect("skeleton");
    let n = poly.len();
    let ext = |a: usize, b: usize| (a + 1) % n == b || (b + 1) % n == a;
    let scale = stroke::perimeter(poly);
    let tol = 1e-9 * scale;
    // nodes have positive radii; zero-radius slivers have no node
    assert!(sk.radii.iter().all(|&r| r > 0.0 && r.is_finite()));
    for (t, node) in sk.triangles.iter().zip(&sk.node_of_triangle) {
        assert!(t.radius > 0.0 || node.is_none());
    }
    for t in &sk.triangles {
        let v = t.vertices.map(|i| poly[i]);
        let next = |k: usize| t.vertices[(k + 1) % 3];
        let ext_edges: Vec<usize> = (0..3).filter(|&k| ext(t.vertices[k], next(k))).collect();
        let expect_kind = match ext_edges.len() {
            0 => TriangleKind::Junction,
            1 => TriangleKind::Sleeve,
            _ => TriangleKind::Terminal,
        };
        assert_eq!(t.kind, expect_kind);
        assert!(t.radius >= 0.0 && t.radius.is_finite());
        let c = t.centre;
        let circ = [d2(c, v[0]), d2(c, v[1]), d2(c, v[2])];
        let is_circum = (circ[0] - circ[1]).abs() <= tol && (circ[1] - circ[2]).abs() <= tol;
        match (t.kind, t.circle) {
            (TriangleKind::Junction, CircleKind::Circumcircle) => {
                assert!(is_circum, "{circ:?}");
                assert!(t.radius <= circ[0] + tol);
            }
            (TriangleKind::Terminal, CircleKind::Incircle) => {
                let d = [0, 1, 2].map(|k| line_distance(c, v[k], v[(k + 1) % 3]));
                assert!(
                    (d[0] - d[1]).abs() <= tol && (d[1] - d[2]).abs() <= tol,
                    "{d:?}"
                );
                assert!(t.radius <= d[0] + tol);
            }
            (TriangleKind::Sleeve, CircleKind::Circumcircle) => {
                assert!(is_circum);
                assert!(pdesculpt::polygon::point_in_polygon(poly, c));
            }
            (TriangleKind::Sleeve, CircleKind::EdgeTangent) => {
                let k = ext_edges[0];
                let (a, b, opp) = (v[k], v[(k + 1) % 3], v[(k + 2) % 3]);
                let h = line_distance(opp, a, b);
                assert!((line_distance(c, a, b) - 0.5 * h).abs() <= tol);
                assert!((d2(c, opp) - 0.5 * h).abs() <= tol);
                assert!(t.radius <= h / 2.0 + tol);
            }
            other => panic!("circle rule violated: {other:?}"),
        }
    }
    // the skeleton links kept centres; every edge joins two distinct nodes
    for e in &sk.edges {
        assert!(e[0] != e[1] && e[0] < sk.nodes.len() && e[1] < sk.nodes.len());
    }
}

#[test]
fn skeleton_circles_follow_the_paper_rules() {
    let o = stroke::StrokeOptions::default();
    for raw in [
        shapes::star(5, 0.6, 1.6, 400),
        shapes::ellipse(2.0, 1.0, 300),
        shapes::folding(1.5, 0.4, 4.0, 400),
        shapes::figure(500),
    ] {
        assert_circle_rules(&stroke::filter_stroke(&raw, &o).expect("filter"));
    }
}

// ---- weights --------------------------------------------------------------

#[test]
fn weight_options_have_the_paper_defaults_and_divide_at_joints() {
    use pdesculpt::conv::fit::{weights, RawSegment, Solver, WeightMode};
    let d = sketch::ConvOptions::default();
    assert_eq!(d.radius_factor, 0.8);
    assert_eq!(d.weights, WeightMode::Paper);
    assert!(d.divide_at_joints);
    assert_eq!(d.solver, Solver::HildrethDEsopo);
    assert_eq!(d.threshold, 1.0);
    // an empty options object in a model file means the defaults
    let m = Model::from_json(
        r#"{"options": {}, "components": [{"name": "a", "stroke": [[0,0],[1,0],[1,1],[0,1]]}]}"#,
    )
    .expect("parse");
    assert_eq!(m.options, d);
    let raw = RawSegment {
        p: [0.0; 3],
        q: [1.0, 0.0, 0.0],
        rp: 0.4,
        rq: 0.3,
        degree: [3, 2],
    };
    for mode in [WeightMode::Paper, WeightMode::Exact] {
        let whole = weights(&[raw], [0.0, 0.0, 1.0], 1.0, 2.0, mode, false).expect("w")[0];
        let split = weights(&[raw], [0.0, 0.0, 1.0], 1.0, 2.0, mode, true).expect("w")[0];
        assert!((split.w0 - whole.w0 / 3.0).abs() <= FEW_OPS * whole.w0.abs());
        assert!((split.w1 - whole.w1 / 2.0).abs() <= FEW_OPS * whole.w1.abs());
        // the isolated segment meets the threshold where the options say
        let at = |x: [f64; 3]| whole.field(x, 2.0);
        match mode {
            WeightMode::Exact => {
                assert!((at([0.0, 0.0, 0.4]) - 1.0).abs() < tol::ROUNDING);
                assert!((at([1.0, 0.0, 0.3]) - 1.0).abs() < tol::ROUNDING);
            }
            WeightMode::Paper => assert!((at([0.5, 0.0, 0.35]) - 1.0).abs() < tol::ROUNDING),
        }
    }
    // the radius factor scales the skeleton radii into the weights
    let o = sketch::ConvOptions::default().with_radius_factor(1.0);
    let st = shapes::ellipse(2.0, 1.0, 200);
    let a = sketch::build(&st, &Default::default()).expect("0.8");
    let b = sketch::build(&st, &o).expect("1.0");
    let fat = |k: &sketch::Sketch| k.field([0.0, 0.0, 0.9]);
    assert!(fat(&b) > 0.0 && fat(&a) > 0.0);
}

// ---- modeling operations and the model file -------------------------------

fn comp(name: &str, stroke: Vec<[f64; 2]>) -> Component {
    Component {
        name: name.into(),
        stroke,
        ..Default::default()
    }
}

#[test]
fn translate_rotate_copy_move_the_segments_rigidly() {
    use pdesculpt::conv::model::Rotation;
    let st = shapes::star(5, 0.6, 1.6, 300);
    let base = Model {
        components: vec![comp("a", st.clone())],
        ..Default::default()
    };
    let b0 = base.build().expect("base");
    let s0 = &b0.components[0].segments;
    // translate
    let mut m = base.clone();
    m.components[0].translate = [0.5, -1.0, 2.0];
    let b = m.build().expect("translate");
    for (x, y) in s0.iter().zip(&b.components[0].segments) {
        for k in 0..3 {
            assert!((y.p[k] - x.p[k] - m.components[0].translate[k]).abs() < tol::ROUNDING);
        }
        assert_eq!(x.lambda, y.lambda);
    }
    // rotate: the field is carried along (F_rot(R x) = F(x))
    let mut m = base.clone();
    m.components[0].rotate = Some(Rotation {
        axis: [0.0, 1.0, 0.0],
        degrees: 90.0,
    });
    let b = m.build().expect("rotate");
    let cen = {
        let n = s0.len() as f64;
        let mut c = [0.0; 3];
        for s in s0 {
            for k in 0..3 {
                c[k] += 0.5 * (s.p[k] + s.q[k]) / n;
            }
        }
        c
    };
    // 90 degrees about +y: (x, y, z) -> (z, y, -x) about the centroid
    let rot = |p: [f64; 3]| {
        let d = [p[0] - cen[0], p[1] - cen[1], p[2] - cen[2]];
        [cen[0] + d[2], cen[1] + d[1], cen[2] - d[0]]
    };
    for x in [[0.3, 0.2, 0.1], [1.0, -0.5, 0.4], [-0.7, 0.9, -0.2]] {
        let f0 = b0.group_field(0, x);
        let f1 = b.group_field(0, rot(x));
        assert!(
            (f0 - f1).abs() <= tol::ROUNDING * f0.abs().max(1.0),
            "{f0} {f1}"
        );
    }
    // copy: the same stroke and plane, then its own translation
    let mut m = base.clone();
    m.components.push(Component {
        name: "b".into(),
        copy_of: Some("a".into()),
        translate: [4.0, 0.0, 0.0],
        ..Default::default()
    });
    let b = m.build().expect("copy");
    assert_eq!(b.groups.len(), 2);
    for (x, y) in b.components[0]
        .segments
        .iter()
        .zip(&b.components[1].segments)
    {
        assert!(
            (y.p[0] - x.p[0] - 4.0).abs() < tol::ROUNDING
                && (y.q[1] - x.q[1]).abs() < tol::ROUNDING
        );
    }
    assert_eq!(b.components[0].depth, b.components[1].depth);
    // a copy of a copy is refused, as is a copy of an unknown component
    let mut bad = m.clone();
    bad.components.push(Component {
        name: "c".into(),
        copy_of: Some("b".into()),
        ..Default::default()
    });
    assert!(bad
        .build()
        .expect_err("copy of copy")
        .to_string()
        .contains("itself a copy"));
    bad.components[2].copy_of = Some("zz".into());
    assert!(bad
        .build()
        .expect_err("unknown")
        .to_string()
        .contains("unknown component"));
}

#[test]
fn merge_sums_fields_and_carve_negates_lambda() {
    use pdesculpt::conv::model::Operation;
    let body = shapes::ellipse(1.2, 1.6, 200);
    let hole: Vec<[f64; 2]> = shapes::ellipse(0.3, 0.3, 80)
        .into_iter()
        .map(|p| [p[0], p[1] + 0.2])
        .collect();
    let mut m = Model {
        components: vec![comp("body", body), comp("hole", hole)],
        ..Default::default()
    };
    m.components[1].depth = Some(0.6);
    let sep = m.build().expect("separate");
    assert_eq!(sep.groups.len(), 2);
    m.operations = vec![Operation::Merge {
        a: "body".into(),
        b: "hole".into(),
    }];
    let merged = m.build().expect("merge");
    assert_eq!(merged.groups.len(), 1);
    let x = [0.1, 0.3, 0.4];
    let sum = sep.group_field(0, x) + sep.group_field(1, x);
    assert!((merged.group_field(0, x) - sum).abs() <= tol::ROUNDING * sum);
    m.operations = vec![Operation::Carve {
        target: "body".into(),
        tool: "hole".into(),
    }];
    let carved = m.build().expect("carve");
    assert_eq!(carved.groups.len(), 1);
    for (x, y) in sep.components[1]
        .segments
        .iter()
        .zip(&carved.components[1].segments)
    {
        assert_eq!(y.lambda, -x.lambda);
    }
    let diff = sep.group_field(0, x) - sep.group_field(1, x);
    assert!((carved.group_field(0, x) - diff).abs() <= tol::ROUNDING * sum);
    // the carved mesh is still closed and has less volume
    let v = |b: &pdesculpt::conv::model::BuiltModel| {
        let mesh = b
            .polygonize(24, 1.0, Polygonizer::MarchingTetrahedra)
            .expect("mesh");
        let r = report(&mesh);
        assert!(r.watertight && r.manifold && r.oriented, "{r:?}");
        mesh.signed_volume()
    };
    let (vm, vc) = (v(&merged), v(&carved));
    assert!(vc < vm, "carved {vc} merged {vm}");
    // operations naming unknown components are refused
    m.operations = vec![Operation::Merge {
        a: "body".into(),
        b: "nope".into(),
    }];
    assert!(m
        .build()
        .expect_err("unknown")
        .to_string()
        .contains("unknown component"));
}

#[test]
fn depth_from_the_first_stroke_point_lies_on_the_surface() {
    use pdesculpt::conv::model::View;
    // a side-view stroke whose first point looks at the body: its plane
    // goes where the ray along +x through that point meets the body surface
    let knob: Vec<[f64; 2]> = shapes::ellipse(0.3, 0.3, 80)
        .into_iter()
        .map(|p| [p[0] - 0.3, p[1]])
        .collect();
    let m = Model {
        components: vec![
            comp("body", shapes::ellipse(1.2, 1.6, 200)),
            Component {
                view: View::Side,
                ..comp("knob", knob)
            },
        ],
        ..Default::default()
    };
    let b = m.build().expect("build");
    let knob = &b.components[1];
    let comps = vec![&b.components[0]];
    let p0 = knob.sketch.polygon[0];
    let f = knob.frame;
    let hit = [0, 1, 2].map(|k| f[0][k] * p0[0] + f[1][k] * p0[1] + f[2][k] * knob.depth);
    let field = pdesculpt::conv::model::components_field(&comps, hit);
    // the plane lies where the ray meets the body (1.2 from its axis at
    // the middle), well away from depth 0
    let least_depth = 0.5;
    assert!(knob.depth > least_depth, "depth {}", knob.depth);
    assert!(
        (field - m.options.threshold).abs() < tol::SOLVE,
        "field {field} at depth {}",
        knob.depth
    );
    // a ray that misses everything leaves the plane at depth 0 ("in the air")
    let far: Vec<[f64; 2]> = shapes::ellipse(0.3, 0.3, 80)
        .into_iter()
        .map(|p| [p[0] + 5.0, p[1]])
        .collect();
    let m2 = Model {
        components: vec![
            comp("body", shapes::ellipse(1.2, 1.6, 200)),
            Component {
                view: View::Side,
                ..comp("far", far)
            },
        ],
        ..Default::default()
    };
    assert_eq!(m2.build().expect("build").components[1].depth, 0.0);
    // the bundled teddy's side-view tail takes its depth from the body
    let path = format!("{}/data/conv/teddy.json", env!("CARGO_MANIFEST_DIR"));
    let t = Model::from_json(&std::fs::read_to_string(path).expect("read")).expect("parse");
    let tb = t.build().expect("teddy");
    let i = tb
        .components
        .iter()
        .position(|c| c.name == "tail")
        .expect("tail");
    let tail = &tb.components[i];
    let (p0, f) = (tail.sketch.polygon[0], tail.frame);
    let hit = [0, 1, 2].map(|k| f[0][k] * p0[0] + f[1][k] * p0[1] + f[2][k] * tail.depth);
    let comps: Vec<_> = tb.components[..i].iter().collect();
    let field = pdesculpt::conv::model::components_field(&comps, hit);
    assert!(t.components[i].depth.is_none() && tail.depth > 0.0);
    assert!(
        (field - t.options.threshold).abs() < tol::SOLVE,
        "tail field {field}"
    );
}

#[test]
fn model_file_round_trips_and_rebuilds_at_any_resolution() {
    let path = format!("{}/data/conv/star.json", env!("CARGO_MANIFEST_DIR"));
    let m = Model::from_json(&std::fs::read_to_string(path).expect("read")).expect("parse");
    let again = Model::from_json(&m.to_json()).expect("re-parse");
    assert_eq!(m, again);
    let b = again.build().expect("build");
    let mut vols = Vec::new();
    for res in [16, 32, 48] {
        for method in [Polygonizer::MarchingTetrahedra, Polygonizer::SurfaceNets] {
            let mesh = b
                .polygonize(res, m.options.threshold, method)
                .expect("mesh");
            let r = report(&mesh);
            // surface nets: closed (no boundary edges) but not manifold at
            // ambiguous cubes (documented in mesh::isosurface)
            assert_eq!(r.boundary_edges, 0, "{res} {method:?} {r:?}");
            if method == Polygonizer::MarchingTetrahedra {
                assert!(r.watertight && r.manifold && r.oriented, "{res} {r:?}");
            }
            vols.push((res, mesh.signed_volume()));
        }
    }
    // the same file at 32 and 48 cells: volumes within 10 % of the finest
    // marching-tetrahedra mesh (16 cells is coarse for the star's arms)
    let fine = vols[vols.len() - 2].1;
    for (res, v) in &vols {
        assert!(*v > 0.0, "{vols:?}");
        if *res >= 32 {
            assert!((v - fine).abs() / fine < VOLUME_CONVERGENCE, "{vols:?}");
        }
    }
    for res in [0, 3, 513] {
        assert!(b
            .polygonize(res, 1.0, Polygonizer::MarchingTetrahedra)
            .is_err());
    }
}

// ---- the CLI on bad input --------------------------------------------------

fn model_with_stroke(stroke: &str) -> String {
    format!(r#"{{"components": [{{"name": "c", "stroke": {stroke}}}]}}"#)
}

/// Runs `conv build MODEL -o OUT --resolution RES` and asserts a clear
/// error containing `needle`, with no `out` written.
fn assert_build_refused(model: &std::path::Path, out: &std::path::Path, res: &str, needle: &str) {
    use crate::cli::{assert_clear_error, pdesculpt};
    let o = pdesculpt(&[
        "conv",
        "build",
        model.to_str().expect("utf8"),
        "-o",
        out.to_str().expect("utf8"),
        "--resolution",
        res,
    ]);
    assert_clear_error(&o, needle);
    assert!(
        !out.exists(),
        "{}: an output file was written",
        model.display()
    );
}

#[test]
fn cli_build_rejects_bad_strokes_clearly_without_writing() {
    use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
    let d = tmpdir("conv-bad");
    let eight: Vec<String> = bow_tie()
        .iter()
        .map(|p| format!("[{},{}]", p[0], p[1]))
        .collect();
    let cases = [
        ("selfx", model_with_stroke(&format!("[{}]", eight.join(","))), "intersects itself"),
        ("short", model_with_stroke("[[0,0],[1,0],[0,1]]"), "too short"),
        (
            "flat",
            model_with_stroke("[[0,0],[1,0],[2,0],[3,0],[4,0],[5,0]]"),
            "no area",
        ),
        ("nan", model_with_stroke("[[0,0],[1,0],[NaN,1],[0,1]]"), "model file"),
        ("inf", model_with_stroke("[[0,0],[1,0],[1e999,1],[0,1]]"), "model file"),
        ("nulls", model_with_stroke("[[0,0],[1,0],[null,1],[0,1]]"), "model file"),
        ("empty", r#"{"components": []}"#.to_string(), "no components"),
        (
            "badopt",
            r#"{"options": {"threshold": -1}, "components": [{"name": "c", "stroke": [[0,0],[1,0],[1,1],[0,1]]}]}"#
                .to_string(),
            "threshold",
        ),
    ];
    for (name, text, needle) in cases {
        let model = d.join(format!("{name}.json"));
        std::fs::write(&model, text).expect("write");
        assert_build_refused(&model, &d.join(format!("{name}.obj")), "16", needle);
    }
    // bad resolution and polygonizer
    let model = d.join("ok.json");
    std::fs::write(&model, model_with_stroke("[[0,0],[1,0],[1,1],[0,1]]")).expect("write");
    let o = d.join("ok.obj");
    for (flag, val, needle) in [
        ("--resolution", "2", "resolution"),
        ("--polygonizer", "xx", "polygonizer"),
        ("--sampler", "xx", "sampler"),
    ] {
        let out = pdesculpt(&[
            "conv",
            "build",
            model.to_str().expect("utf8"),
            "-o",
            o.to_str().expect("utf8"),
            flag,
            val,
        ]);
        assert_clear_error(&out, needle);
        assert!(!o.exists());
    }
    // conv field: NaN and degenerate segments
    for (args, needle) in [
        (
            vec![
                "--segment",
                "0,0,0,0,0,0",
                "--weights",
                "1,1",
                "--s",
                "1",
                "--at",
                "1,0,0",
            ],
            "coincide",
        ),
        (
            vec![
                "--segment",
                "0,0,0,1,0,0",
                "--weights",
                "1,NaN",
                "--s",
                "1",
                "--at",
                "1,0,0",
            ],
            "not finite",
        ),
        (
            vec![
                "--segment",
                "0,0,0,1,0,0",
                "--weights",
                "1,1",
                "--s",
                "0",
                "--at",
                "1,0,0",
            ],
            "--s",
        ),
        (
            vec![
                "--segment",
                "0,0,0,1,0",
                "--weights",
                "1,1",
                "--s",
                "1",
                "--at",
                "1,0,0",
            ],
            "--segment",
        ),
    ] {
        let mut a = vec!["conv", "field"];
        a.extend(args);
        assert_clear_error(&pdesculpt(&a), needle);
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// A rotation axis whose length overflows, (1e300, 1e300, 0), divided the
/// axis by an infinite norm, so the "rotation" scaled the component by
/// cos(angle) and the build said "the surface is empty at this
/// resolution"; it is now refused as a bad rotation.
#[test]
fn rotation_axis_of_overflowing_length_is_refused() {
    use pdesculpt::conv::model::Rotation;
    let mut m = Model::from_json(&model_with_stroke("[[0,0],[1,0],[1,1],[0,1]]")).expect("model");
    m.components[0].rotate = Some(Rotation {
        axis: [1e300, 1e300, 0.0],
        degrees: 90.0,
    });
    let e = m.build().expect_err("an overflowing axis");
    assert!(e.to_string().contains("bad rotation"), "{e}");
}

/// An option far out of range was printed in full ("radius_factor must
/// lie in (0, 2], got = 1000...000", 301 digits); it reads "got 1e300".
#[test]
fn option_out_of_range_is_printed_short() {
    use pdesculpt::conv::sketch::ConvOptions;
    for (o, needle) in [
        (
            ConvOptions::default().with_radius_factor(1e300),
            "radius_factor must lie in (0, 2], got 1e300",
        ),
        (
            ConvOptions::default().with_threshold(-1.0),
            "threshold must be positive and finite, got -1.0",
        ),
    ] {
        let e = o.validate().expect_err("out of range").to_string();
        assert!(e.contains(needle), "{e}");
    }
}

/// Every input path of `conv build` refuses out-of-range or malformed
/// input clearly, before writing: duplicate component names (operations
/// and copies would pick one silently), stroke coordinates beyond
/// MAX_COORDINATE (squared distances overflowed: "1 distinct points" for a
/// 4-point square), strokes below MIN_SIZE, translations and depths beyond
/// MAX_TRANSLATION (1e300 said "does not close"),
/// too many components, truncated and non-UTF-8 files, a missing file, a
/// directory, and resolutions out of range.
#[test]
fn cli_build_refuses_out_of_range_models_clearly() {
    use crate::cli::tmpdir;
    use pdesculpt::conv::model::MAX_COMPONENTS;
    let d = tmpdir("conv-range");
    let square = |s: f64| format!("[[0,0],[{s:e},0],[{s:e},{s:e}],[0,{s:e}]]");
    let comp = |name: &str, extra: &str| {
        format!(r#"{{"name": "{name}", "stroke": [[0,0],[1,0],[1,1],[0,1]]{extra}}}"#)
    };
    let many: Vec<String> = (0..=MAX_COMPONENTS)
        .map(|i| comp(&format!("c{i}"), ""))
        .collect();
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "dup",
            format!(
                r#"{{"components": [{}, {}]}}"#,
                comp("c", ""),
                comp("c", "")
            )
            .into_bytes(),
            "both named",
        ),
        (
            "huge",
            model_with_stroke(&square(1e300)).into_bytes(),
            "scale the sketch down",
        ),
        (
            "tiny",
            model_with_stroke(&square(1e-300)).into_bytes(),
            "scale the sketch up",
        ),
        (
            "far",
            format!(
                r#"{{"components": [{}]}}"#,
                comp("c", r#", "translate": [1e300, 0, 0]"#)
            )
            .into_bytes(),
            "nearer the origin",
        ),
        (
            "deep",
            format!(
                r#"{{"components": [{}]}}"#,
                comp("c", r#", "depth": -1e13"#)
            )
            .into_bytes(),
            "nearer the origin",
        ),
        (
            "many",
            format!(r#"{{"components": [{}]}}"#, many.join(",")).into_bytes(),
            "at most",
        ),
        (
            "trunc",
            br#"{"components": [{"name": "c", "stroke": [[0,0],[1,0]"#.to_vec(),
            "EOF",
        ),
        ("binary", vec![0xff, 0xfe, 0x00, 0x7b], "UTF-8"),
    ];
    for (name, bytes, needle) in cases {
        let model = d.join(format!("{name}.json"));
        std::fs::write(&model, bytes).expect("write");
        assert_build_refused(&model, &d.join(format!("{name}.obj")), "16", needle);
    }
    let ok = d.join("ok.json");
    std::fs::write(&ok, model_with_stroke(&square(1.0))).expect("write");
    let o = d.join("ok.obj");
    let missing = d.join("missing.json");
    for (model, res, needle) in [
        (&missing, "16", "No such file"),
        (&d, "16", "a directory, not a regular file"),
        (&ok, "100000", "resolution"),
        (&ok, "3", "resolution"),
    ] {
        assert_build_refused(model, &o, res, needle);
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// Issue 16: Hildreth-d'Esopo ran into its 20,000-sweep cap on 5 of the 6
/// distinct teddy strokes (normal equations with condition numbers up to
/// 3e12). With the subspace step every stroke converges, its optimality
/// residual recomputed from the field matrix is below the stopping rule,
/// and the fit is as good as Lawson-Hanson's exact NNLS.
#[test]
fn hildreth_converges_on_every_teddy_stroke() {
    use pdesculpt::conv::check_fast::fit_kkt_residual;
    use pdesculpt::conv::fit::{Solver, HILDRETH_KKT_STOP, HILDRETH_MAX_SWEEPS};
    let m = Model::from_json(include_str!("../../data/conv/teddy.json")).expect("teddy");
    let b = m.build().expect("build");
    for c in &b.components {
        let f = &c.sketch.fit;
        assert_eq!(f.solver, Solver::HildrethDEsopo);
        assert!(
            f.converged && f.iterations < HILDRETH_MAX_SWEEPS,
            "{}: {} sweeps, converged {}",
            c.name,
            f.iterations,
            f.converged
        );
        let kkt = fit_kkt_residual(&c.sketch);
        assert!(kkt <= HILDRETH_KKT_STOP, "{}: KKT residual {kkt:e}", c.name);
    }
    // the same optimum as the exact active-set solver
    let mut lh = m.clone();
    lh.options.solver = Solver::LawsonHanson;
    let b2 = lh.build().expect("build (Lawson-Hanson)");
    for (c, d) in b.components.iter().zip(&b2.components) {
        let (h, l) = (c.sketch.fit.rms_rel_error, d.sketch.fit.rms_rel_error);
        assert!(
            h <= l * (1.0 + pdesculpt::conv::check::SOLVER_SLACK),
            "{}: Hildreth rms {h:e} above Lawson-Hanson {l:e}",
            c.name
        );
    }
}

/// `conv build --sampler fast|reference`: both samplers write the same
/// surface (corresponding vertices within the fast-against-reference
/// tolerance of the model size) with the same topology report.
#[test]
fn cli_build_sampler_flag_fast_matches_reference() {
    use crate::cli::{pdesculpt, tmpdir};
    use pdesculpt::conv::check_fast::{corresponding_distance, mesh_size, FAST_MESH_TOLERANCE};
    let d = tmpdir("conv-sampler");
    let mut outputs = Vec::new();
    for sampler in ["fast", "reference"] {
        let o = d.join(format!("{sampler}.obj"));
        let out = pdesculpt(&[
            "--json",
            "conv",
            "build",
            concat!(env!("CARGO_MANIFEST_DIR"), "/data/conv/blob.json"),
            "-o",
            o.to_str().expect("utf8"),
            "--resolution",
            "24",
            "--sampler",
            sampler,
        ]);
        assert!(
            out.status.success(),
            "{sampler}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
        assert_eq!(v["sampler"], sampler);
        let mesh = pdesculpt::mesh::io::read(&o).expect("read the written mesh");
        outputs.push((v["topology"].clone(), mesh));
    }
    let (fast, reference) = (&outputs[0], &outputs[1]);
    assert_eq!(fast.0, reference.0, "topology reports differ");
    assert_eq!(fast.0["watertight"], true);
    let dist = corresponding_distance(&fast.1, &reference.1) / mesh_size(&reference.1);
    assert!(
        dist <= FAST_MESH_TOLERANCE,
        "fast and reference meshes {dist:e} apart (relative)"
    );
    let _ = std::fs::remove_dir_all(&d);
}

// ---- proptests over the documented parameter ranges -------------------------

proptest! {
    #![proptest_config(crate::strategies::config(24))]

    /// Stroke filter: any tolerance / spacing in range keeps the polygon
    /// simple, counter-clockwise, finite and within the DP tolerance of the
    /// raw stroke.
    #[test]
    fn stroke_filter_sweeps_its_options(
        dp in 0.0f64..0.05, spacing in 0.005f64..0.1, a in 0.5f64..3.0, b in 0.3f64..2.0,
        arms in 3usize..8, reverse in any::<bool>(), star in any::<bool>(),
    ) {
        let mut raw = if star { shapes::star(arms, 0.5 * a.min(b), a.max(b) + 0.5, 300) } else { shapes::ellipse(a, b, 200) };
        if reverse { raw.reverse(); }
        let o = stroke::StrokeOptions::new(dp, spacing);
        let p = stroke::filter_stroke(&raw, &o).expect("filter");
        prop_assert!(p.iter().all(|q| q[0].is_finite() && q[1].is_finite()));
        prop_assert!(pdesculpt::polygon::signed_area(&p) > 0.0);
        prop_assert!(pdesculpt::polygon::is_simple(&p));
        let diag = {
            let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
            for q in &raw { for k in 0..2 { lo[k] = lo[k].min(q[k]); hi[k] = hi[k].max(q[k]); } }
            d2(lo, hi)
        };
        for q in &raw {
            prop_assert!(stroke::distance_to_polygon(*q, &p) <= dp * diag * (1.0 + tol::SOLVE) + tol::ROUNDING);
        }
        let h = spacing * stroke::perimeter(&p);
        prop_assert!((0..p.len()).all(|i| d2(p[i], p[(i + 1) % p.len()]) <= h * (1.0 + tol::SOLVE) + tol::ROUNDING || dp == 0.0));
        assert_circle_rules(&p);
    }

    /// The whole reconstruction over the documented option ranges: it
    /// either builds (finite weights, lambda >= 0, fit error finite, the
    /// fitted field near T at the silhouette points) or fails with an error,
    /// never a panic or a NaN.
    #[test]
    fn reconstruction_sweeps_its_options(
        threshold in 0.5f64..2.0, s_scale in 0.5f64..2.0, radius_factor in 0.5f64..1.0,
        overlap in 0.0f64..1.0, exact in any::<bool>(), divide in any::<bool>(), solver in 0usize..3,
        a in 0.6f64..2.5, b in 0.4f64..1.5, arms in 3usize..7, star in any::<bool>(),
    ) {
        use pdesculpt::conv::fit::{Solver, WeightMode};
        let st = if star { shapes::star(arms, 0.5 * a.min(b), a.max(b) + 0.5, 300) } else { shapes::ellipse(a, b, 200) };
        let mut o = sketch::ConvOptions::default()
            .with_threshold(threshold).with_s_scale(s_scale).with_radius_factor(radius_factor)
            .with_divide_at_joints(divide)
            .with_weights(if exact { WeightMode::Exact } else { WeightMode::Paper })
            .with_solver([Solver::HildrethDEsopo, Solver::LawsonHanson, Solver::ProjectedLm][solver]);
        o.skeleton.overlap = overlap;
        let sk = match sketch::build(&st, &o) {
            Ok(sk) => sk,
            // exact weights can all go negative (round strokes, small s):
            // the fit then switches every segment off, reported as an error
            Err(e) if exact => {
                prop_assert!(e.to_string().contains("switched every segment off"), "{e}");
                return Ok(());
            }
            Err(e) => return Err(TestCaseError::fail(format!("build: {e}"))),
        };
        prop_assert!(sk.s.is_finite() && sk.s > 0.0);
        prop_assert!(sk.segments.iter().all(|s| s.w0.is_finite() && s.w1.is_finite() && s.lambda.is_finite() && s.lambda >= 0.0));
        prop_assert!(sk.fit.rms_rel_error.is_finite());
        // FIT_RMS_TOLERANCE (0.15) holds for the default options (see
        // ellipses_and_stars_build_finite_closed_surfaces) but not over the
        // whole sweep: small stars without division at joints reach ~0.19.
        // Exact weights are kept non-negative since issue 16 (before, a
        // near-circular ellipse reached 0.868: see
        // near_circular_ellipse_with_exact_weights_is_reconstructed).
        // Here: a bound against blow-up only.
        prop_assert!(sk.fit.rms_rel_error < FIT_BLOWUP, "rms {}", sk.fit.rms_rel_error);
        for p in sk.polygon.iter().step_by(7) {
            prop_assert!(sk.field([p[0], p[1], 0.0]).is_finite());
        }
    }

    /// Random garbage strokes: an error or a finite sketch, never a panic.
    #[test]
    fn random_strokes_never_panic(pts in prop::collection::vec((-2.0f64..2.0, -2.0f64..2.0), 0..40)) {
        let raw: Vec<[f64; 2]> = pts.into_iter().map(|(x, y)| [x, y]).collect();
        if let Ok(sk) = sketch::build(&raw, &Default::default()) {
            prop_assert!(sk.segments.iter().all(|s| s.w0.is_finite() && s.w1.is_finite() && s.lambda.is_finite()));
        }
    }
}

/// A stroke filter setting found by the option sweep: the uniform
/// re-insertion of points puts three stroke points within rounding of one
/// line, and the CDT makes a sleeve sliver of them whose tangent circle has
/// radius 0. It must not become a skeleton node.
#[test]
fn sliver_sleeves_get_no_node() {
    use pdesculpt::conv::skeleton::extract;
    let raw = shapes::ellipse(1.992807772364267, 0.5693002556800587, 200);
    let o = stroke::StrokeOptions::new(0.01737680236299407, 0.01355085684409124);
    let p = stroke::filter_stroke(&raw, &o).expect("filter");
    let sk = extract(&p, &Default::default()).expect("skeleton");
    let slivers: Vec<usize> = (0..sk.triangles.len())
        .filter(|&i| sk.triangles[i].radius == 0.0)
        .collect();
    assert!(!slivers.is_empty(), "the case still makes a sliver");
    for i in slivers {
        assert!(sk.node_of_triangle[i].is_none());
    }
    assert!(sk.radii.iter().all(|&r| r > 0.0 && r.is_finite()));
    assert_circle_rules(&p);
    let built = sketch::build(&raw, &Default::default()).expect("build");
    assert!(built.fit.rms_rel_error.is_finite());
}

/// The option sweep's failing case of issue 16: a near-circular ellipse
/// with exact 2x2 weights, division at joints and Hildreth-d'Esopo.
#[test]
fn near_circular_ellipse_with_exact_weights_is_reconstructed() {
    let (st, o) = pdesculpt::conv::samples::near_circular_ellipse_case();
    let sk = sketch::build(&st, &o).expect("build");
    // before the fix: rms 0.868 (exact 2x2 weights of opposite signs)
    assert!(
        sk.segments.iter().all(|s| s.w0 >= 0.0 && s.w1 >= 0.0),
        "a negative weight"
    );
    assert!(
        sk.fit.rms_rel_error < pdesculpt::conv::check::FIT_RMS_TOLERANCE,
        "rms {}",
        sk.fit.rms_rel_error
    );
}

proptest! {
    #![proptest_config(crate::strategies::config(6))]

    /// Random two- or three-component models (ellipses and stars, some
    /// merged, one possibly carving): the narrow-band surface matches the
    /// brute-force reference within FAST_MESH_TOLERANCE of the model size,
    /// with the same topology report.
    #[test]
    fn narrow_band_matches_reference_on_random_models(
        parts in prop::collection::vec((0.4f64..1.5, 0.3f64..1.2, 3usize..6, any::<bool>(), -1.5f64..1.5, -1.0f64..1.0, -0.5f64..0.5), 2..4),
        merge in any::<bool>(), carve in any::<bool>(),
    ) {
        use pdesculpt::conv::check_fast::{compare_with_reference, FAST_MESH_TOLERANCE};
        use pdesculpt::conv::model::Operation;
        let components: Vec<Component> = parts.iter().enumerate().map(|(i, &(a, b, arms, star, x, y, z))| Component {
            name: format!("c{i}"),
            stroke: if star { shapes::star(arms, 0.5 * a.min(b), a.max(b) + 0.4, 200) } else { shapes::ellipse(a, b, 120) },
            depth: Some(z),
            translate: [2.0 * x, y, 0.0],
            ..Default::default()
        }).collect();
        let n = components.len();
        let mut operations = Vec::new();
        if merge {
            operations.push(Operation::Merge { a: "c0".into(), b: "c1".into() });
        }
        if carve && n > 2 {
            operations.push(Operation::Carve { target: "c0".into(), tool: format!("c{}", n - 1) });
        }
        let m = Model { components, operations, ..Default::default() };
        match compare_with_reference(&m, 20) {
            Ok((d, same, note)) => {
                prop_assert!(same, "{note}");
                prop_assert!(d <= FAST_MESH_TOLERANCE, "distance {d}: {note}");
            }
            // a carve can remove a whole surface: the same error both ways
            Err(e) => prop_assert!(e.contains("no surface") || e.contains("empty"), "{e}"),
        }
    }
}

/// Issue 16, parallel narrow band: the teddy's grid is the same, bit for
/// bit, on 1, 2 and 3 threads (tasks merged in the sequential order) and
/// equals what the single sequential traversal (no tasks) gives; every band
/// node is evaluated exactly once (the walkers' count equals the count of
/// evaluated nodes in the grid), the nodes shared between tasks among
/// them. `sample_group_fast` returns the same grid except at the nodes near
/// $T$, which hold the reference's value.
#[test]
fn narrow_band_is_identical_for_any_thread_count() {
    use pdesculpt::conv::narrow::{sample_sequential, sample_with_threads, FIELD_TOLERANCE};
    use pdesculpt::conv::sample::node_position;
    let m = Model::from_json(include_str!("../../data/conv/teddy.json")).expect("teddy");
    let b = m.build().expect("build");
    let t = m.options.threshold;
    let (grid, stats) = b
        .sample_group_fast(0, 40, t, FIELD_TOLERANCE)
        .expect("sample")
        .expect("a surface");
    let bvh = b.group_bvh(0).expect("bvh");
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let run = |threads: usize| {
        sample_with_threads(
            &bvh,
            t,
            FIELD_TOLERANCE * t,
            grid.origin,
            grid.spacing,
            grid.dims,
            threads,
        )
    };
    let (one, st1) = run(1);
    assert!(one.values.iter().all(|v| v.is_finite()));
    for threads in [2, 3] {
        let (g, st) = run(threads);
        assert_eq!(st, st1, "{threads} threads");
        assert_eq!(bits(&g.values), bits(&one.values), "{threads} threads");
    }
    let (seq, st) = sample_sequential(
        &bvh,
        t,
        FIELD_TOLERANCE * t,
        grid.origin,
        grid.spacing,
        grid.dims,
    );
    assert_eq!(bits(&seq.values), bits(&one.values), "sequential");
    assert_eq!(st.shared_evaluated, 0, "no tasks, nothing deferred");
    // each band node once: with tasks, and without
    assert_eq!(st1.evaluated, st1.exact_nodes, "{st1:?}");
    assert_eq!(st.evaluated, st.exact_nodes, "{st:?}");
    assert_eq!(st1.exact_nodes, st.exact_nodes);
    assert_eq!(st1.segment_evaluations, st.segment_evaluations);
    assert!(st1.shared_evaluated > 0, "tasks share faces: {st1:?}");
    // sample_group_fast: the same, but the nodes near T are the reference's
    assert_eq!(stats.evaluated, st1.evaluated);
    let mut settled = 0;
    for (id, (&fast, &raw)) in grid.values.iter().zip(&one.values).enumerate() {
        if (raw - t).abs() <= FIELD_TOLERANCE * t {
            settled += 1;
            let x = node_position(grid.origin, grid.spacing, grid.dims, id);
            assert_eq!(fast.to_bits(), b.group_field(0, x).to_bits(), "node {id}");
        } else {
            assert_eq!(fast.to_bits(), raw.to_bits(), "node {id}");
        }
    }
    assert_eq!(settled, stats.reference_nodes);
}

/// Issue 16, the 4-triangle difference at 160 cells: one node within
/// 1e-6 T of T fell on the other side. Every node of the shell
/// |F - T| <= SIDE_SHELL T is now on the reference's side (some nodes near
/// T get the reference's value); outside the shell the error bound keeps
/// the sides.
#[test]
fn teddy_sides_match_reference_at_160() {
    use pdesculpt::conv::check_sides::{compare_sides, SIDES_RESOLUTION};
    let m = Model::from_json(include_str!("../../data/conv/teddy.json")).expect("teddy");
    let s = compare_sides(&m, SIDES_RESOLUTION).expect("compare");
    assert!(s.shell > 0 && s.settled > 0, "{s:?}");
    assert_eq!(s.differ, 0, "{s:?}");
}

/// Issue 16, per-component reuse: after one stroke of a two-group model
/// changes, only its sketch and its group's mesh are rebuilt, and the
/// result equals a full rebuild.
#[test]
fn incremental_rebuild_equals_full_build() {
    use pdesculpt::conv::check_fast::corresponding_distance;
    use pdesculpt::conv::incremental::{MeshCache, SketchCache};
    let mut m = Model {
        components: vec![
            Component {
                name: "a".into(),
                stroke: shapes::ellipse(1.0, 1.5, 120),
                ..Default::default()
            },
            Component {
                name: "b".into(),
                stroke: shapes::star(5, 0.5, 1.2, 200),
                translate: [4.0, 0.0, 0.0],
                ..Default::default()
            },
        ],
        ..Default::default()
    };
    let (mut sk, mut me) = (SketchCache::default(), MeshCache::default());
    let mt = Polygonizer::MarchingTetrahedra;
    me.polygonize(&m.build_cached(&mut sk).expect("build"), 20, 1.0, mt)
        .expect("mesh");
    assert_eq!((sk.built, me.built), (2, 2));
    m.components[1].stroke = shapes::star(5, 0.5, 1.3, 200);
    let inc = me
        .polygonize(&m.build_cached(&mut sk).expect("build"), 20, 1.0, mt)
        .expect("mesh");
    assert_eq!((sk.built, sk.reused, me.built, me.reused), (3, 1, 3, 1));
    let full = m.build().expect("b").polygonize(20, 1.0, mt).expect("mesh");
    assert_eq!(corresponding_distance(&inc, &full), 0.0);
}

/// Issue 18: unknown keys in model files and options are errors.
#[test]
fn unknown_keys_are_rejected() {
    let ok = r#"{"components":[{"name":"a","stroke":[[0,0],[1,0],[1,1],[0,1]]}]}"#;
    assert!(Model::from_json(ok).is_ok());
    for bad in [
        r#"{"components":[{"name":"a","stroke":[[0,0],[1,0],[1,1],[0,1]]}],"colour":1}"#,
        r#"{"components":[{"name":"a","strok":[[0,0],[1,0],[1,1],[0,1]]}]}"#,
        r#"{"options":{"treshold":1},"components":[{"name":"a","stroke":[[0,0],[1,0],[1,1],[0,1]]}]}"#,
        r#"{"options":{"skeleton":{"overlapp":0.5}},"components":[{"name":"a","stroke":[[0,0],[1,0],[1,1],[0,1]]}]}"#,
    ] {
        let e = Model::from_json(bad).expect_err(bad);
        assert!(e.to_string().contains("unknown field"), "{e}");
    }
}

/// Issue 18: skeleton and stroke options are checked against their
/// documented ranges before any work.
#[test]
fn out_of_range_options_are_rejected_before_work() {
    let mut o = sketch::ConvOptions::default();
    o.skeleton.area_samples = usize::MAX;
    let e = sketch::build(&shapes::ellipse(1.0, 0.5, 50), &o).expect_err("area_samples");
    assert!(e.to_string().contains("area_samples"), "{e}");
    let mut o = sketch::ConvOptions::default();
    o.skeleton.overlap = f64::NAN;
    assert!(o.validate().is_err());
    let mut o = sketch::ConvOptions::default();
    o.stroke.spacing = 1e-9;
    assert!(o
        .validate()
        .expect_err("spacing")
        .to_string()
        .contains("spacing"));
}

/// Issue 18: a model shifted by 1e9 is refused before a mesh file would
/// round its shape away; the fit reports whether its solver converged.
#[test]
fn far_shifted_model_is_refused_for_output() {
    use pdesculpt::conv::sample::check_f32_output;
    let mut m = Model {
        components: vec![Component {
            name: "a".into(),
            stroke: shapes::ellipse(1.0, 0.6, 100),
            ..Default::default()
        }],
        ..Default::default()
    };
    let near = m.build().expect("b");
    let mesh = near
        .polygonize(16, 1.0, Polygonizer::MarchingTetrahedra)
        .expect("mesh");
    assert!(check_f32_output(&mesh).is_ok());
    let fit = &near.components[0].sketch.fit;
    assert!(fit.converged || fit.iterations > 0);
    m.components[0].translate = [1e9, 0.0, 0.0];
    let far = m
        .build()
        .expect("b")
        .polygonize(16, 1.0, Polygonizer::MarchingTetrahedra)
        .expect("mesh");
    let e = check_f32_output(&far).expect_err("1e9");
    assert!(e.to_string().contains("f32"), "{e}");
}
