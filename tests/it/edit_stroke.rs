//! The 4-sided force inside a closed stroke (`force_stroke`, paper 000 sec
//! 5.1): the map, its checks, bad strokes, the minimum force size, the CLI.

use super::edit::{female, low};
use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
use pdesculpt::character::log::Edit;
use pdesculpt::check::tol;
use pdesculpt::edit::check::sample_force_region;
use pdesculpt::edit::check_stroke::{
    rectangle_difference, rectangle_stroke, sample_force_stroke, sample_stroke, stroke_measures,
    C1_ORDER_TOL,
};
use pdesculpt::edit::force4::{THETA_SPAN_MIN, U_SPAN_MIN_FRACTION};
use pdesculpt::edit::stroke::{StrokeError, StrokeMap, FOLD_GRID};
use pdesculpt::pde4::{Force, ForceKind};
use pdesculpt::pipeline::build_document;
use std::f64::consts::PI;
use std::path::Path;

fn uniform() -> Force {
    Force {
        kind: ForceKind::Uniform,
        p: [0.0, 0.0, 1.0],
    }
}

fn stroke_edit(part: &str, stroke: Vec<[f64; 2]>, corners: Option<[usize; 4]>) -> Edit {
    Edit::ForceStroke {
        part: part.into(),
        stroke,
        corners,
        force: uniform(),
        a: 1.0,
    }
}

#[test]
fn the_stroke_force_is_c0_and_c1_on_its_stroke_zero_outside_and_one_to_one() {
    let d = female();
    let e = sample_force_stroke(&d.parts()[0], 0.8, [0.0, 0.0, 5.0]);
    let m = stroke_measures(&e).expect("the sample stroke force evaluates");
    assert!(m.c0 <= tol::ROUNDING, "{m:?}");
    assert!((m.order - 1.0).abs() <= C1_ORDER_TOL, "{m:?}");
    assert_eq!(m.outside, 0.0, "{m:?}");
    assert_eq!(m.folded + m.negative_jacobians, 0, "{m:?}");
    assert!(m.min_jacobian > 0.0, "{m:?}");
}

#[test]
fn a_rectangle_stroke_reproduces_the_rectangle_force() {
    let d = female();
    let r = sample_force_region(&d.parts()[0], 0.2, [0.0, 0.0, 5.0]);
    assert!(rectangle_difference(&r) <= tol::ROUNDING);
    // the same rectangle drawn clockwise, corners found by default: the
    // same map (the first corner stays at the rectangle's (u_a, theta_a))
    let Edit::ForceRegion { u, theta, .. } = r else {
        unreachable!()
    };
    let (mut pts, _) = rectangle_stroke(u, theta, 8);
    pts.reverse();
    let map = StrokeMap::new(&pts, None).expect("a rectangle is a stroke");
    for (x, want) in [
        ([0.25, 0.5], [0.25, 0.5]),
        ([0.9, 0.1], [0.9, 0.1]),
        ([0.5, 0.999], [0.5, 0.999]),
    ] {
        let got = map.map(x);
        assert!(
            (got[0] - want[0]).abs() + (got[1] - want[1]).abs() <= tol::ROUNDING,
            "{got:?}"
        );
    }
}

#[test]
fn a_stroke_across_theta_zero_maps_the_angles_modulo_the_ring() {
    let d = female();
    let torso = &d.parts()[0];
    let e = sample_force_stroke(torso, 0.1, [0.0, 0.0, 5.0]);
    let m = stroke_measures(&e).expect("evaluates");
    assert_eq!(m.outside, 0.0);
    let map = StrokeMap::new(&sample_stroke(torso, 0.1), None).expect("valid");
    assert!(map.theta[0] < 0.0);
    assert!((map.y_of(0.05) - map.y_of(0.05 + 2.0 * PI)).abs() <= tol::ROUNDING);
    assert!((map.y_of(-0.05) - map.y_of(2.0 * PI - 0.05)).abs() <= tol::ROUNDING);
}

#[test]
fn bad_strokes_get_named_errors() {
    let sq = |k: usize| -> Vec<[f64; 2]> {
        let c = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
        c[..k].to_vec()
    };
    let err = |p: &[[f64; 2]], c: Option<[usize; 4]>| StrokeMap::new(p, c).expect_err("bad");
    assert!(matches!(
        err(&sq(3), None),
        StrokeError::TooFewPoints { .. }
    ));
    // four distinct points but not closed: the gap is a quarter
    assert!(matches!(err(&sq(4), None), StrokeError::Open { .. }));
    let bow = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]];
    assert!(matches!(
        err(&bow, None),
        StrokeError::SelfIntersecting { .. }
    ));
    let line = [
        [0.0, 0.0],
        [0.5, 0.5],
        [1.0, 1.0],
        [0.5, 0.5001],
        [0.0, 0.0],
    ];
    assert!(matches!(err(&line, None), StrokeError::Degenerate { .. }));
    let mut nan = sq(5);
    nan[2][1] = f64::NAN;
    assert!(matches!(
        err(&nan, None),
        StrokeError::NotFinite { index: 2, .. }
    ));
    let wide = [[0.0, 0.0], [1.0, 0.0], [1.0, 7.0], [0.0, 7.0], [0.0, 0.0]];
    assert!(matches!(err(&wide, None), StrokeError::TooWide { .. }));
    assert!(matches!(
        err(&sq(5), Some([0, 2, 1, 3])),
        StrokeError::BadCorners { .. }
    ));
    assert!(matches!(
        err(&sq(5), Some([0, 1, 2, 9])),
        StrokeError::BadCorners { .. }
    ));
    // an annulus sector of 1.95 pi (a C almost closed on itself): the mean
    // value map folds, and the stroke is refused
    let n = 40;
    let arc = |r: f64, k: usize, dir: f64| {
        let t = dir * (-0.975 * PI + 1.95 * PI * k as f64 / n as f64);
        [r * t.cos(), r * t.sin()]
    };
    let mut c_shape: Vec<[f64; 2]> = (0..=n).map(|k| arc(1.0, k, 1.0)).collect();
    c_shape.extend((0..=n).map(|k| arc(0.5, k, -1.0)));
    c_shape.push(c_shape[0]);
    match err(&c_shape, None) {
        StrokeError::Folded { folded, cells } => assert!(folded > 0 && cells > FOLD_GRID),
        other => panic!("{other}"),
    }
    // a wobbly but round hand-drawn stroke, not quite closed, is accepted
    let hand: Vec<[f64; 2]> = (0..=60)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / 62.0;
            let r = 1.0 + 0.05 * (7.0 * t).sin();
            [r * t.cos(), 0.5 * r * t.sin()]
        })
        .collect();
    StrokeMap::new(&hand, None).expect("a round stroke with a small gap is closed");
}

#[test]
fn stroke_edits_are_validated_against_the_part_and_leave_the_document_unchanged() {
    let mut d = female();
    let torso = d.parts()[0].clone();
    let (u0, u1) = (
        torso.sections[0].u,
        torso.sections[torso.sections.len() - 1].u,
    );
    let before = d.clone();
    let rect = |u: [f64; 2], th: [f64; 2]| rectangle_stroke(u, th, 4);
    let mid = [u0 + 0.3 * (u1 - u0), u0 + 0.6 * (u1 - u0)];
    let tiny_u = [mid[0], mid[0] + 0.5 * U_SPAN_MIN_FRACTION * (u1 - u0)];
    let bad = [
        (
            stroke_edit("torso", rect([u0 - 1.0, mid[1]], [0.0, 1.0]).0, None),
            "outside the part's u range",
        ),
        (
            stroke_edit("tail", rect(mid, [0.0, 1.0]).0, None),
            "unknown part 'tail'",
        ),
        (
            stroke_edit("torso", rect(tiny_u, [0.0, 1.0]).0, None),
            "narrower than the smallest force",
        ),
        (
            stroke_edit("torso", rect(mid, [0.0, 0.5 * THETA_SPAN_MIN]).0, None),
            "the stroke's angle span",
        ),
        (
            stroke_edit("torso", vec![[mid[0], 0.0]; 3], None),
            "stroke: the stroke has",
        ),
        (
            stroke_edit("torso", rect(mid, [0.0, f64::NAN]).0, None),
            "not finite",
        ),
    ];
    for (e, needle) in bad {
        let err = d.push_edit(e.clone()).expect_err(needle);
        assert!(err.to_string().contains(needle), "{needle}: {err}");
        assert_eq!(d, before, "{e:?} changed the document");
    }
    let base = build_document(&d, Path::new("."), low(), false).expect("builds");
    d.push_edit(sample_force_stroke(&torso, 0.8, [0.0, 0.0, 5.0]))
        .expect("the sample stroke force is valid");
    let b = build_document(&d, Path::new("."), low(), false).expect("builds");
    let t = &b.report.topology;
    assert!(t.watertight && t.manifold && t.oriented, "{t:?}");
    let moved = (0..base.model.mesh.positions.len())
        .filter(|&i| base.model.mesh.positions[i] != b.model.mesh.positions[i])
        .count();
    assert!(moved > 0, "the force moves the torso");
    assert!(moved * 4 < base.model.mesh.positions.len(), "{moved} moved");
}

#[test]
fn force_regions_below_the_minimum_size_are_refused() {
    let mut d = female();
    let torso = d.parts()[0].clone();
    let (u0, u1) = (
        torso.sections[0].u,
        torso.sections[torso.sections.len() - 1].u,
    );
    let before = d.clone();
    let region = |u: [f64; 2], theta: [f64; 2]| Edit::ForceRegion {
        part: "torso".into(),
        u,
        theta,
        force: uniform(),
        a: 1.0,
    };
    let mid = [u0 + 0.3 * (u1 - u0), u0 + 0.6 * (u1 - u0)];
    let bad = [
        (region(mid, [1.0, 1.0 + 1e-10]), "theta[1] - theta[0]"),
        (
            region([mid[0], mid[0] + 1e-10], [1.0, 2.0]),
            "narrower than the smallest force",
        ),
        (
            Edit::Force {
                part: "torso".into(),
                u: [mid[0], mid[0] + 1e-10],
                force: uniform(),
                a: 1.0,
            },
            "narrower than the smallest force",
        ),
    ];
    for (e, needle) in bad {
        let err = d.push_edit(e.clone()).expect_err(needle);
        assert!(err.to_string().contains(needle), "{needle}: {err}");
        assert_eq!(d, before);
    }
    // just above the minimum is accepted
    let w = 1.01 * U_SPAN_MIN_FRACTION * (u1 - u0);
    d.push_edit(region(
        [mid[0], mid[0] + w],
        [1.0, 1.0 + 1.01 * THETA_SPAN_MIN],
    ))
    .expect("the smallest force");
}

#[test]
fn cli_force_stroke_edits_and_bad_strokes_leave_the_file_unchanged() {
    let dir = tmpdir("edit-stroke-cli");
    let doc = dir.join("char.json");
    let d = female();
    d.save(&doc).expect("saves");
    let docs = doc.to_str().unwrap();
    let op = dir.join("op.json");
    let ops = op.to_str().unwrap();
    let e = sample_force_stroke(&d.parts()[0], 0.8, [0.0, 0.0, 5.0]);
    std::fs::write(&op, serde_json::to_string(&e).unwrap()).unwrap();
    let o = pdesculpt(&["character", "edit", docs, "--op", ops]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = pdesculpt(&["character", "log", docs]);
    let log = String::from_utf8_lossy(&o.stdout);
    assert!(log.contains("inside a stroke of 97 points"), "{log}");
    let before = std::fs::read(&doc).expect("reads");
    let bad = [
        (
            r#"{"op": "force_stroke", "part": "torso", "stroke": [[1.0, 0.0], [1.1, 0.0], [1.1, 1.0]], "force": {"type": "uniform", "p": [0.0, 0.0, 1.0]}}"#,
            "at least 4",
        ),
        (
            r#"{"op": "force_stroke", "part": "torso", "stroke": [[1.0, 0.0], [1.1, 1.0], [1.1, 0.0], [1.0, 1.0], [1.0, 0.0]], "force": {"type": "uniform", "p": [0.0, 0.0, 1.0]}}"#,
            "crosses itself",
        ),
        (
            r#"{"op": "force_stroke", "part": "torso", "stroke": [[1.0, 0.0], [1.1, 0.0], [1.1, 1.0], [1.0, 1.0]], "force": {"type": "uniform", "p": [0.0, 0.0, 1.0]}}"#,
            "the stroke is open",
        ),
        (
            r#"{"op": "force_stroke", "part": "torso", "stroke": [[1.0, 0.0], [1.1, 0.0], [1.1, 1.0], [1.0, 1.0], [1.0, 0.0]], "force": {"type": "uniform", "p": [0.0, 0.0, 1.0]}, "corners": [0, 1, 2]}"#,
            "not an edit",
        ),
    ];
    for (text, needle) in bad {
        std::fs::write(&op, text).unwrap();
        let o = pdesculpt(&["character", "edit", docs, "--op", ops]);
        assert_clear_error(&o, needle);
        assert_eq!(std::fs::read(&doc).expect("reads"), before, "{text}");
    }
}

/// The sample stroke on the front of the torso drawn in the front view
/// (its surface points projected), and the stroke itself.
fn drawn_front(
    d: &pdesculpt::character::doc::CharacterDoc,
) -> (pdesculpt::sasm::Stroke, Vec<[f64; 2]>) {
    use pdesculpt::profile::View;
    let spec = &d.parts()[0];
    let surf = pdesculpt::character::part::build_part(spec).expect("builds");
    let um = 0.5 * (surf.u0 + surf.u1);
    let front = (0..360)
        .map(|k| 2.0 * PI * k as f64 / 360.0)
        .max_by(|a, b| surf.point(um, *a)[2].total_cmp(&surf.point(um, *b)[2]))
        .unwrap();
    let stroke = sample_stroke(spec, front);
    let points = stroke
        .iter()
        .map(|q| View::Front.project(surf.point(q[0], q[1])))
        .collect();
    (
        pdesculpt::sasm::Stroke {
            view: View::Front,
            points,
        },
        stroke,
    )
}

#[test]
fn a_stroke_drawn_in_a_view_is_projected_onto_the_part() {
    use pdesculpt::pipeline::project_force_stroke;
    let d = female();
    let (drawn, want) = drawn_front(&d);
    let mut e = stroke_edit("torso", Vec::new(), None);
    project_force_stroke(&d, &mut e, &drawn).expect("projects");
    let Edit::ForceStroke { stroke, .. } = &e else {
        unreachable!()
    };
    assert_eq!(stroke.len(), want.len());
    for (g, w) in stroke.iter().zip(&want) {
        let dt = (g[1] - w[1] + PI).rem_euclid(2.0 * PI) - PI;
        assert!(
            (g[0] - w[0]).abs() + dt.abs() <= tol::DETECTED,
            "{g:?} vs {w:?}"
        );
    }
    let mut d2 = d.clone();
    d2.push_edit(e)
        .expect("the projected stroke is a valid force stroke");
}

#[test]
fn cli_edit_projects_a_drawn_stroke_and_refuses_one_that_misses() {
    let dir = tmpdir("edit-stroke-drawn");
    let doc = dir.join("char.json");
    let d = female();
    d.save(&doc).expect("saves");
    let (drawn, _) = drawn_front(&d);
    let (op, st) = (dir.join("op.json"), dir.join("drawn.json"));
    std::fs::write(
        &op,
        r#"{"op": "force_stroke", "part": "torso", "stroke": [], "force": {"type": "uniform", "p": [0.0, 0.0, 0.5]}}"#,
    )
    .unwrap();
    let mut far = drawn.clone();
    far.points.iter_mut().for_each(|p| p[0] += 10.0);
    std::fs::write(&st, serde_json::to_string(&far).unwrap()).unwrap();
    let args = |s: &Path| {
        vec![
            "character".to_string(),
            "edit".into(),
            doc.to_str().unwrap().into(),
            "--op".into(),
            op.to_str().unwrap().into(),
            "--drawn".into(),
            s.to_str().unwrap().into(),
        ]
    };
    let before = std::fs::read(&doc).unwrap();
    let a = args(&st);
    let o = pdesculpt(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_clear_error(&o, "force stroke");
    assert_eq!(std::fs::read(&doc).unwrap(), before);
    std::fs::write(&st, serde_json::to_string(&drawn).unwrap()).unwrap();
    let o = pdesculpt(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = pdesculpt(&["character", "log", doc.to_str().unwrap()]);
    let log = String::from_utf8_lossy(&o.stdout);
    assert!(log.contains("inside a stroke of 97 points"), "{log}");
}

#[test]
fn a_stroke_whose_u_width_overflows_is_refused_by_name() {
    // finite points whose u width overflows to infinity: the box scaling
    // made NaN of them and the error blamed the corners
    let mut s = sample_stroke(&female().parts()[0], 0.8);
    s[3][0] = 1e308;
    s[10][0] = -1e308;
    let err = StrokeMap::new(&s, None).expect_err("an unbounded stroke");
    assert!(matches!(err, StrokeError::UnboundedU { .. }), "{err}");
    assert!(err.to_string().contains("no finite width"), "{err}");
}

#[test]
fn a_drawn_stroke_over_the_point_limit_is_refused_before_it_is_projected() {
    use pdesculpt::edit::stroke::STROKE_POINTS_MAX;
    use pdesculpt::pipeline::project_force_stroke;
    let d = female();
    // every point misses the part: projected first, the error would name
    // a miss (after casting a ray for each of them)
    let drawn = pdesculpt::sasm::Stroke {
        view: pdesculpt::profile::View::Front,
        points: vec![[10.0, 10.0]; STROKE_POINTS_MAX + 1],
    };
    let mut e = stroke_edit("torso", Vec::new(), None);
    let err = project_force_stroke(&d, &mut e, &drawn).expect_err("too many points");
    assert!(
        err.to_string()
            .contains(&format!("at most {STROKE_POINTS_MAX}")),
        "{err}"
    );
    assert_eq!(e, stroke_edit("torso", Vec::new(), None));
}
