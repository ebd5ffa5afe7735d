//! Integration tests of the conv family (paper 003).

use pdesculpt::conv::model::{Component, Model, Polygonizer};
use pdesculpt::conv::{kernel, shapes, sketch, stroke, ConvError};
use pdesculpt::mesh::topology::report;
use proptest::prelude::*;

#[test]
fn checks_pass() {
    for c in pdesculpt::conv::check::checks() {
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
    assert!((v["field"].as_f64().unwrap_or(f64::NAN) - f).abs() <= 1e-15 * f.abs());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
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
