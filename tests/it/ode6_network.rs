//! Curve networks of ODE patches (paper 004 secs 5, 6.2): C2 across every
//! edge, 3-sided patches, bundled networks and refused documents.

use pdesculpt::check::tol;
use pdesculpt::ode6::network::samples;
use pdesculpt::ode6::network::solve::stencil;
use pdesculpt::ode6::network::{Network, NetworkDoc, NetworkError};
use pdesculpt::ode6::Params;

/// The C2 bound of issue 32: relative jumps across every edge.
const C2_RELATIVE: f64 = 1e-9;
/// The golden weights of verify/ode6_network.py.
const GOLDEN: &str = include_str!("../../verify/golden/ode6_network.json");

/// Two documents equal up to the last bit of a JSON float round trip
/// (serde_json's default parser may round the last digit).
fn same(a: &NetworkDoc, b: &NetworkDoc) -> bool {
    fn eq(x: &serde_json::Value, y: &serde_json::Value) -> bool {
        use serde_json::Value as V;
        match (x, y) {
            (V::Number(p), V::Number(q)) => {
                let (p, q) = (
                    p.as_f64().unwrap_or(f64::NAN),
                    q.as_f64().unwrap_or(f64::NAN),
                );
                (p - q).abs() <= tol::ROUNDING * p.abs().max(q.abs()).max(1.0)
            }
            (V::Array(p), V::Array(q)) => {
                p.len() == q.len() && p.iter().zip(q).all(|(a, b)| eq(a, b))
            }
            (V::Object(p), V::Object(q)) => {
                p.len() == q.len() && p.iter().all(|(k, a)| q.get(k).is_some_and(|b| eq(a, b)))
            }
            _ => x == y,
        }
    }
    let v = |d: &NetworkDoc| serde_json::to_value(d).unwrap_or_default();
    eq(&v(a), &v(b))
}

fn build(doc: NetworkDoc) -> Network {
    Network::build(doc).expect("network builds")
}

fn assert_c2(name: &str, r: &pdesculpt::ode6::network::NetworkReport) {
    for m in [r.max_relative_u_edges, r.max_relative_v_edges] {
        for x in m {
            assert!(x <= C2_RELATIVE, "{name}: {m:?}");
        }
    }
}

#[test]
fn wavy_grid_is_c2_across_every_edge_with_parameters_per_column() {
    let params = [
        Params::new(1.0, 3.0, 1.0),
        Params::new(0.1, 0.1, 3.0),
        Params::new(1.0, -2.0, 5.0),
    ];
    let net = build(samples::wavy_grid(3, 3, &params));
    let r = net.report(8);
    assert_eq!((r.u_edges, r.v_edges), (6, 6), "{r:?}");
    assert_c2("wavy", &r);
    assert!(r.residual <= tol::SOLVE, "{}", r.residual);
    assert!(
        r.u_side_interpolation <= tol::SOLVE,
        "{}",
        r.u_side_interpolation
    );
}

#[test]
fn bundled_networks_are_c2_across_every_edge_and_match_their_files() {
    for (name, doc) in samples::bundled() {
        let path = format!("{}/data/network/{name}.json", env!("CARGO_MANIFEST_DIR"));
        if std::env::var_os("PDESCULPT_WRITE_NETWORKS").is_some() {
            std::fs::write(&path, doc.to_json()).expect("write network");
        }
        let text = std::fs::read_to_string(&path).expect("bundled network file");
        let file = NetworkDoc::from_json(&text).expect("bundled network parses");
        assert!(
            same(&file, &doc),
            "{path} differs from its generator (PDESCULPT_WRITE_NETWORKS=1)"
        );
        let net = build(doc);
        let r = net.report(2);
        assert_c2(name, &r);
        assert!(r.three_sided > 0, "{name} has fans");
        assert!(r.apex_interpolation <= tol::SOLVE, "{name}");
        assert!(r.u_side_interpolation <= tol::SOLVE, "{name}");
        assert!(r.residual <= tol::SOLVE, "{name}: {}", r.residual);
    }
}

#[test]
fn stencils_are_the_sympy_derivation() {
    let g: serde_json::Value = serde_json::from_str(GOLDEN).expect("golden");
    let get = |name: &str, k: &str| -> Vec<f64> {
        g["stencils"][name][k]
            .as_array()
            .expect("weights")
            .iter()
            .map(|x| x.as_f64().expect("number"))
            .collect()
    };
    // strip of 5 sections: first, an inner one, the last
    for (name, k, order) in [
        ("first", 0, [0, 1, 2]),
        ("central", 2, [1, 2, 3]),
        ("last", 4, [4, 3, 2]),
    ] {
        let st = stencil(k, 5, false);
        let (d1, d2) = (get(name, "first"), get(name, "second"));
        for (i, sec) in order.iter().enumerate() {
            let (w1, w2) = st
                .iter()
                .filter(|s| s.0 == *sec)
                .fold((0.0, 0.0), |a, s| (a.0 + s.1, a.1 + s.2));
            assert!((w1 - d1[i]).abs() <= tol::ROUNDING, "{name} first {sec}");
            assert!((w2 - d2[i]).abs() <= tol::ROUNDING, "{name} second {sec}");
        }
    }
    // the face's column stencils (half a column apart)
    let (_, f1, f2) = pdesculpt::face::template::stencil(3, 12, 0.5 / 12.0);
    let col = |k: &str| -> Vec<f64> {
        g["face_columns"]["central"][k]
            .as_array()
            .expect("weights")
            .iter()
            .map(|x| x.as_f64().expect("number"))
            .collect()
    };
    for i in 0..3 {
        assert!((f1[i] - col("first")[i]).abs() <= tol::ROUNDING);
        assert!((f2[i] - col("second")[i]).abs() <= tol::ROUNDING);
    }
    assert_eq!(g["three_sided"]["c2_matches_polar_radius"], true);
}

#[test]
fn a_three_sided_fan_meets_its_apex_and_far_sides_exactly() {
    let net = build(samples::vase());
    let r = net.report(4);
    assert_eq!(r.three_sided, 4);
    assert!(
        r.apex_interpolation <= tol::ROUNDING,
        "{}",
        r.apex_interpolation
    );
    assert!(
        r.u_side_interpolation <= tol::SOLVE,
        "{}",
        r.u_side_interpolation
    );
    // the sides from the apex are ODE lines: near the sampled curves, not on them
    assert!(r.max_side_relative > 0.0 && r.max_side_relative.is_finite());
}

fn refused(doc: NetworkDoc) -> NetworkError {
    Network::build(doc).expect_err("refused")
}

#[test]
fn patches_of_two_or_five_sides_are_refused_by_name() {
    for n in [2usize, 5] {
        let mut doc = samples::wavy_grid(1, 1, &[]);
        let c = doc.patches[0].curves[0];
        doc.patches[0].curves.resize(n, c);
        match refused(doc) {
            NetworkError::Sides { patch: 0, sides } => assert_eq!(sides, n),
            other => panic!("{n} sides: {other:?}"),
        }
    }
}

#[test]
fn curves_that_miss_their_nodes_and_nan_are_refused() {
    let mut doc = samples::wavy_grid(2, 2, &[]);
    doc.curves[1].points[0][2] += 0.01;
    assert!(matches!(
        refused(doc),
        NetworkError::CurveOffNode { curve: 1, .. }
    ));
    let mut doc = samples::wavy_grid(2, 2, &[]);
    doc.curves[0].points[3][1] = f64::NAN;
    assert!(matches!(refused(doc), NetworkError::NonFinite { .. }));
    let mut doc = samples::wavy_grid(2, 2, &[]);
    doc.nodes[0][0] = f64::INFINITY;
    assert!(matches!(refused(doc), NetworkError::NonFinite { .. }));
    let mut doc = samples::wavy_grid(2, 2, &[]);
    doc.patches[0].params.eta = f64::NAN;
    assert!(matches!(
        refused(doc),
        NetworkError::Params { patch: 0, .. }
    ));
    // sides that do not close a loop
    let mut doc = samples::wavy_grid(2, 2, &[]);
    doc.patches[0].curves.swap(0, 1);
    assert!(matches!(
        refused(doc),
        NetworkError::OpenBoundary { patch: 0 }
    ));
}

/// Counts and coordinates are bounded before any solve: a curve of 400,000
/// points once reached the periodic spline's dense LU (a 1.3 TB
/// allocation, an abort), a node at 1e300 was reported "inf away".
#[test]
fn huge_counts_and_far_coordinates_are_refused_before_the_solve() {
    use pdesculpt::limits::{MODEL_COORD, NETWORK_CURVE_POINTS};
    let mut doc = samples::wavy_grid(2, 2, &[]);
    let p = doc.curves[0].points[1];
    let too_many = NETWORK_CURVE_POINTS.max as usize + 1;
    doc.curves[0]
        .points
        .splice(1..2, std::iter::repeat_n(p, too_many));
    match refused(doc) {
        NetworkError::Limit(e) => assert!(e.to_string().contains("curves[0].points"), "{e}"),
        other => panic!("{other:?}"),
    }
    let mut doc = samples::wavy_grid(2, 2, &[]);
    doc.nodes[0][0] = 1e300;
    match refused(doc) {
        NetworkError::Coordinate { value, max, .. } => {
            assert_eq!((value, max), (1e300, MODEL_COORD))
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn joins_that_cannot_be_c2_are_refused_by_name() {
    // unequal parameters across a v-edge (eq 26)
    let mut doc = samples::wavy_grid(1, 2, &[]);
    doc.patches[1].params = Params::new(1.0, 1.0, 3.0);
    assert!(matches!(refused(doc), NetworkError::VParams { .. }));
    // a patch rotated by a quarter turn: its u-side meets a v-side
    let mut doc = samples::wavy_grid(2, 1, &[]);
    doc.patches[1].curves.rotate_left(1);
    assert!(matches!(refused(doc), NetworkError::Join { .. }));
}

#[test]
fn documents_are_versioned_and_strict() {
    let doc = samples::wavy_grid(1, 1, &[]);
    let text = doc.to_json();
    assert!(same(
        &NetworkDoc::from_json(&text).expect("round trip"),
        &doc
    ));
    let bad = text.replacen("\"version\": 1", "\"version\": 2", 1);
    assert!(matches!(
        NetworkDoc::from_json(&bad),
        Err(NetworkError::Version { found: 2, .. })
    ));
    let bad = text.replacen("\"version\": 1", "\"version\": 1, \"colour\": 3", 1);
    assert!(matches!(
        NetworkDoc::from_json(&bad),
        Err(NetworkError::Json { .. })
    ));
}

#[test]
fn cli_network_writes_a_mesh_and_a_report_and_refuses_bad_input_without_a_file() {
    use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
    let d = tmpdir("ode6-network");
    let out = d.join("vase.glb");
    let net = format!("{}/data/network/vase.json", env!("CARGO_MANIFEST_DIR"));
    let o = pdesculpt(&[
        "--json",
        "ode6",
        "network",
        &net,
        "-o",
        out.to_str().expect("path"),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    assert_eq!(v["report"]["patches"], 24);
    // one node per patch (issue 34's part layout), named after the patch
    let g = crate::gltf::glb_json(&std::fs::read(&out).expect("glb"));
    let nodes = g["nodes"].as_array().expect("nodes");
    let named = |n: &str| nodes.iter().any(|x| x["name"].as_str() == Some(n));
    assert_eq!(nodes.iter().filter(|x| x.get("mesh").is_some()).count(), 24);
    assert!(named("vase.0.0"), "{nodes:?}");
    let mut doc = samples::wavy_grid(1, 1, &[]);
    let c0 = doc.patches[0].curves[0];
    doc.patches[0].curves.push(c0);
    let bad = d.join("five.json");
    std::fs::write(&bad, doc.to_json()).expect("write");
    let out = d.join("five.obj");
    let o = pdesculpt(&[
        "ode6",
        "network",
        bad.to_str().expect("p"),
        "-o",
        out.to_str().expect("p"),
    ]);
    assert_clear_error(&o, "5 sides");
    assert!(!out.exists());
}

#[test]
fn cli_network_names_each_bad_document_and_writes_nothing() {
    use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
    let d = tmpdir("ode6-network-bad");
    let good = samples::wavy_grid(2, 1, &[]);
    let mut two = good.clone();
    two.patches[0].curves.truncate(2);
    let mut off = good.clone();
    off.curves[0].points[0][2] += 0.5;
    let text = good.to_json();
    let first = text.find("\"points\"").expect("points");
    let digit = first
        + text[first..]
            .find(|c: char| c.is_ascii_digit())
            .expect("digit");
    let mut huge = text.clone();
    huge.insert_str(digit, "1e999");
    huge.remove(digit + 5);
    let unknown = text.replacen("\"version\": 1", "\"version\": 1, \"colour\": 3", 1);
    for (name, body, needle) in [
        ("two", two.to_json(), "2 sides"),
        ("off", off.to_json(), "does not meet its node"),
        ("huge", huge, "number out of range"),
        ("unknown", unknown, "unknown field"),
    ] {
        let input = d.join(format!("{name}.json"));
        std::fs::write(&input, body).expect("write");
        let out = d.join(format!("{name}.glb"));
        let o = pdesculpt(&[
            "ode6",
            "network",
            input.to_str().expect("p"),
            "-o",
            out.to_str().expect("p"),
        ]);
        assert_clear_error(&o, needle);
        assert!(!out.exists(), "{name}");
    }
}
