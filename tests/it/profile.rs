//! Profiles: validation, SVG/JSON input and output, mesh outlines, the CLI.

use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
use pdesculpt::check::tol;
use pdesculpt::profile::check::{
    cross, hull_outline, outline_error_px, CHECK_RESOLUTION, CORNER_PX, SMOOTH_PX, SVG_ROUNDING,
    USVG_ARC_REL,
};
use pdesculpt::profile::shapes::{box_mesh, sphere, torus};
use pdesculpt::profile::{
    outline_of_mesh, parse_json, parse_svg, profile_distance, to_json, to_svg, OutlineOptions,
    Profile, ProfileError, View,
};
use proptest::prelude::*;
use std::f64::consts::PI;

fn square(s: f64) -> Vec<[f64; 2]> {
    vec![[0.0, 0.0], [s, 0.0], [s, s], [0.0, s]]
}

fn data(name: &str) -> String {
    format!("{}/tests/data/profile/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn the_family_checks_pass() {
    let cs = crate::shared::family_checks("profile");
    assert!(cs.len() >= 8);
    for c in cs {
        assert!(
            c.passed,
            "{}: measured {} > {} ({})",
            c.name, c.measured, c.tolerance, c.note
        );
    }
}

#[test]
fn views_project_to_their_axes() {
    let p = [1.0, 2.0, 3.0];
    assert_eq!(View::Front.project(p), [1.0, 2.0]);
    assert_eq!(View::Side.project(p), [3.0, 2.0]);
    assert_eq!(View::Top.project(p), [1.0, 3.0]);
    assert_eq!(View::Side.axes(), (2, 1));
    assert_eq!("Front".parse::<View>().ok(), Some(View::Front));
    assert!(matches!(
        "back".parse::<View>(),
        Err(pdesculpt::polygon::UnknownView { .. })
    ));
    assert_eq!(
        serde_json::to_string(&View::Top).ok().as_deref(),
        Some("\"top\"")
    );
}

#[test]
fn validation_errors_name_the_problem() {
    let mut p = square(1.0);
    p[2][1] = f64::NAN;
    assert!(matches!(
        Profile::new(View::Front, p),
        Err(ProfileError::NonFinite { index: 2 })
    ));
    assert!(matches!(
        Profile::new(
            View::Front,
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 0.0]]
        ),
        Err(ProfileError::TooFewPoints { count: 2 })
    ));
    assert!(matches!(
        Profile::new(
            View::Front,
            vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]
        ),
        Err(ProfileError::ZeroArea)
    ));
    // bow tie: edge 0 ((0,0)-(1,1)) crosses edge 2 ((1,0)-(0,1)) at (0.5, 0.5)
    match Profile::new(
        View::Front,
        vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]],
    ) {
        Err(ProfileError::SelfIntersecting { a, b, at }) => {
            assert_eq!((a, b), (0, 2));
            assert!((at[0] - 0.5).abs() <= tol::ROUNDING && (at[1] - 0.5).abs() <= tol::ROUNDING);
        }
        other => panic!("expected a self-intersection, got {other:?}"),
    }
    // a spike folding back onto its own edge
    assert!(matches!(
        Profile::new(
            View::Front,
            vec![[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
        ),
        Err(ProfileError::SelfIntersecting { .. })
    ));
    // touching at a vertex (figure eight through a shared point)
    assert!(matches!(
        Profile::new(
            View::Front,
            vec![
                [0.0, 0.0],
                [1.0, 1.0],
                [2.0, 0.0],
                [2.0, 2.0],
                [1.0, 1.0],
                [0.0, 2.0]
            ]
        ),
        Err(ProfileError::SelfIntersecting { .. })
    ));
    // indices refer to the input, duplicates included
    match Profile::new(
        View::Front,
        vec![[0.0, 0.0], [0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]],
    ) {
        Err(ProfileError::SelfIntersecting { a, b, .. }) => assert_eq!((a, b), (0, 3)),
        other => panic!("expected a self-intersection, got {other:?}"),
    }
    let msg = Profile::new(
        View::Front,
        vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]],
    )
    .err()
    .map(|e| e.to_string())
    .unwrap_or_default();
    assert!(
        msg.contains("segment 0") && msg.contains("segment 2"),
        "{msg}"
    );
}

#[test]
fn profiles_are_counter_clockwise_without_closing_copy() {
    let mut cw = square(2.0);
    cw.reverse();
    cw.push(cw[0]);
    let p = Profile::new(View::Side, cw.clone()).expect("valid");
    assert_eq!(p.len(), 4);
    assert_eq!(p.points()[0], cw[0], "first input point stays first");
    assert!((p.area() - 4.0).abs() <= tol::ROUNDING);
    assert!((p.perimeter() - 8.0).abs() <= tol::ROUNDING);
    assert_eq!(p.bbox(), ([0.0, 0.0], [2.0, 2.0]));
    assert_eq!((p.width(), p.height()), (2.0, 2.0));
    assert!(p.contains([1.0, 1.5]) && !p.contains([2.5, 1.0]));
    assert!((p.distance([1.0, 1.5]) - 0.5).abs() <= tol::ROUNDING);
    assert!((p.distance([3.0, 3.0]) - 2f64.sqrt()).abs() <= tol::ROUNDING);
    let r = p.resample_arclength(8);
    assert_eq!(r.len(), 8);
    for w in r.windows(2) {
        let d = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        assert!((d - 1.0).abs() <= tol::ROUNDING, "spacing {d}");
    }
    let t = p
        .transformed(2.0, PI / 2.0, [1.0, -1.0])
        .expect("similarity");
    assert!((t.area() - 16.0).abs() <= tol::scaled(tol::ROUNDING, 16.0));
    assert!((t.perimeter() - 16.0).abs() <= tol::scaled(tol::ROUNDING, 16.0));
    assert!(p.transformed(0.0, 0.0, [0.0, 0.0]).is_err());
    assert!(p
        .transformed(-1.0, 0.0, [0.0, 0.0])
        .is_ok_and(|q| q.area() > 0.0));
}

#[test]
fn distance_is_symmetric_and_zero_on_itself() {
    let a = Profile::new(View::Front, square(1.0)).expect("a");
    let b = a.transformed(1.0, 0.0, [0.1, 0.0]).expect("b");
    let d0 = profile_distance(&a, &a);
    assert!(d0.max <= tol::ROUNDING && d0.rms <= tol::ROUNDING);
    let (dab, dba) = (profile_distance(&a, &b), profile_distance(&b, &a));
    assert!((dab.max - 0.1).abs() <= tol::ROUNDING);
    assert!((dab.max - dba.max).abs() <= tol::ROUNDING);
    assert!((dab.rms - dba.rms).abs() <= tol::SOLVE);
    assert!((dab.max_rel - dab.max / b.height()).abs() <= tol::ROUNDING);
    assert!(dab.rms > 0.0 && dab.rms < dab.max);
}

#[test]
fn self_intersection_test_is_fast_on_100k_points() {
    // correctness at scale (timing is the bench's business): a 100k-gon is
    // accepted, and the same with one far vertex pulled across is rejected
    let n = 100_000;
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / n as f64;
            let r = 1.0 + 0.1 * (7.0 * t).sin();
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    assert_eq!(
        Profile::new(View::Front, pts.clone())
            .expect("simple")
            .len(),
        n
    );
    let mut bad = pts;
    bad[n / 2] = [1.5, 0.0];
    assert!(matches!(
        Profile::new(View::Front, bad),
        Err(ProfileError::SelfIntersecting { .. })
    ));
}

/// A star-shaped polygon around the origin: sorted angles, radii in [0.2, 1].
fn star() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec((0.5f64..1.5, 0.2f64..1.0), 3..300).prop_map(|v| {
        let total: f64 = v.iter().map(|x| x.0).sum();
        let mut t = 0.0;
        v.iter()
            .map(|&(dt, r)| {
                t += dt;
                let a = 2.0 * PI * t / total;
                [r * a.cos(), r * a.sin()]
            })
            .collect()
    })
}

proptest! {
    #![proptest_config(crate::strategies::config(64))]

    #[test]
    fn star_shaped_polygons_are_accepted(pts in star(), reverse in any::<bool>()) {
        let mut p = pts.clone();
        if reverse { p.reverse(); }
        let prof = Profile::new(View::Front, p).expect("star-shaped is simple");
        prop_assert_eq!(prof.len(), pts.len());
        prop_assert!(prof.area() > 0.0);
        prop_assert!(prof.contains([0.0, 0.0]));
    }

    #[test]
    fn swapping_two_non_adjacent_vertices_is_rejected(
        n in 5usize..200, i in 0usize..1000, gap in 2usize..1000, jitter in 0.0f64..0.5,
    ) {
        // points in convex position (on an ellipse): only the cyclic order
        // (or its reverse) is simple, so a swap of two non-adjacent vertices
        // makes edges cross
        let mut p: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let t = 2.0 * PI * (k as f64 + jitter) / n as f64;
                [2.0 * t.cos(), t.sin()]
            })
            .collect();
        let i = i % n;
        let j = (i + 2 + gap % (n - 3)) % n;
        p.swap(i, j);
        let r = Profile::new(View::Front, p);
        prop_assert!(matches!(r, Err(ProfileError::SelfIntersecting { .. })), "{:?}", r.map(|q| q.len()));
    }
}

const CIRCLE_SVG: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10" width="100mm" height="100mm">
  <g transform="translate(100, 200) scale(2)">
    <circle id="body" cx="0" cy="0" r="10" fill="none" stroke="black"/>
  </g>
  <polyline id="cut1" points="80,200 120,200" stroke="red"/>
</svg>"#;

/// Top view: svg y is model z unflipped, so the circle (svg y in 180..=220)
/// stays above this; a flipped axis would put it at -220..=-180.
const TOP_VIEW_Z_FLOOR: f64 = 150.0;

#[test]
fn svg_applies_transforms_flattens_curves_and_reads_cuts() {
    let tol_model = 1e-3;
    let s = parse_svg(CIRCLE_SVG, View::Front, tol_model).expect("valid sketch");
    // circle of radius 20 centred at svg (100, 200) = model (100, -200)
    let n = s.outline.len();
    assert!(n > 16);
    let pts = s.outline.points();
    for i in 0..n {
        let (a, b) = (pts[i], pts[(i + 1) % n]);
        let mid = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
        for q in [a, mid] {
            let dev = ((q[0] - 100.0).hypot(q[1] + 200.0) - 20.0).abs();
            assert!(
                dev <= tol_model + USVG_ARC_REL * 20.0 + SVG_ROUNDING * 200.0,
                "deviation {dev}"
            );
        }
    }
    assert!(
        (s.outline.area() - PI * 400.0).abs()
            <= 2.0 * PI * 20.0 * (tol_model + USVG_ARC_REL * 20.0)
    );
    assert_eq!(s.cuts.len(), 1);
    assert_eq!(s.cuts[0].id, "cut1");
    assert_eq!(s.cuts[0].points, vec![[80.0, -200.0], [120.0, -200.0]]);
    // top view: svg y is model z, unflipped
    let t = parse_svg(CIRCLE_SVG, View::Top, tol_model).expect("valid");
    assert!(t.outline.points().iter().all(|p| p[1] > TOP_VIEW_Z_FLOOR));
}

#[test]
fn svg_arcs_and_ellipses_are_flattened_within_tolerance() {
    let tol_model = 1e-4;
    // a circle of radius 30 centred at (0, 0) as two `A` arcs: usvg's cubic
    // approximation adds up to USVG_ARC_REL * r
    let arcs = r#"<svg xmlns="http://www.w3.org/2000/svg"><path id="o" d="M 30 0 A 30 30 0 0 1 -30 0 A 30 30 0 0 1 30 0 Z"/></svg>"#;
    // an ellipse without id, rotated: exact conic
    let ell = r#"<svg xmlns="http://www.w3.org/2000/svg"><ellipse cx="0" cy="0" rx="30" ry="10" transform="rotate(30)"/></svg>"#;
    let s = parse_svg(arcs, View::Front, tol_model).expect("arcs");
    let worst = s
        .outline
        .points()
        .iter()
        .map(|p| (p[0].hypot(p[1]) - 30.0).abs())
        .fold(0.0, f64::max);
    assert!(
        worst <= tol_model + USVG_ARC_REL * 30.0,
        "arc deviation {worst}"
    );
    let e = parse_svg(ell, View::Front, tol_model).expect("ellipse");
    let (c, s30) = ((PI / 6.0).cos(), (PI / 6.0).sin());
    let n = e.outline.len();
    let pts = e.outline.points();
    for i in 0..n {
        let (a, b) = (pts[i], pts[(i + 1) % n]);
        for q in [a, [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]] {
            // back to the ellipse's frame (model y = -svg y)
            let (x, y) = (q[0], -q[1]);
            let (u, v) = (c * x + s30 * y, -s30 * x + c * y);
            let level = ((u / 30.0).powi(2) + (v / 10.0).powi(2)).sqrt();
            // distance to the ellipse is at most (level - 1) * 30 in the
            // outward direction and (1 - level) * 10 inward
            let dev = if level > 1.0 {
                (level - 1.0) * 30.0
            } else {
                (1.0 - level) * 10.0
            };
            assert!(
                dev <= tol_model + SVG_ROUNDING * 30.0,
                "ellipse deviation {dev}"
            );
        }
    }
}

#[test]
fn svg_rect_and_file_with_groups() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg"><rect id="r" x="1" y="2" width="3" height="4" transform="rotate(90)"/></svg>"#;
    let s = parse_svg(svg, View::Side, 1e-3).expect("rect");
    assert_eq!(s.outline.len(), 4);
    assert!((s.outline.area() - 12.0).abs() <= SVG_ROUNDING * 12.0);
    // rotate(90): (x, y) -> (-y, x); model v = -svg y
    let (lo, hi) = s.outline.bbox();
    for (got, want) in [(lo, [-6.0, -4.0]), (hi, [-2.0, -1.0])] {
        assert!(
            (got[0] - want[0]).abs() <= SVG_ROUNDING * 10.0
                && (got[1] - want[1]).abs() <= SVG_ROUNDING * 10.0,
            "{got:?} vs {want:?}"
        );
    }
    let f =
        pdesculpt::profile::read_svg(std::path::Path::new(&data("figure.svg")), View::Front, 1e-3)
            .expect("figure");
    let (lo, hi) = f.outline.bbox();
    assert!(
        (lo[1] - 10.0).abs() <= SVG_ROUNDING * 200.0,
        "translated group: {lo:?}"
    );
    // the quadratic's apex: svg y -140 - 15, translated by -10
    assert!((hi[1] - 165.0).abs() <= SVG_ROUNDING * 200.0, "{hi:?}");
    assert_eq!(f.cuts.len(), 1);
    assert!(f.cuts[0]
        .points
        .iter()
        .all(|p| (p[1] - 130.0).abs() <= SVG_ROUNDING * 200.0));
}

#[test]
fn svg_errors_are_clear() {
    let wrap = |body: &str| format!(r#"<svg xmlns="http://www.w3.org/2000/svg">{body}</svg>"#);
    assert!(matches!(
        parse_svg(&wrap(""), View::Front, 1e-3),
        Err(ProfileError::NoOutline)
    ));
    match parse_svg(
        &wrap(r#"<path id="arm" d="M 0 0 L 1 0 L 1 1"/>"#),
        View::Front,
        1e-3,
    ) {
        Err(ProfileError::OpenPath { id }) => assert_eq!(id, "arm"),
        other => panic!("expected an open path, got {other:?}"),
    }
    match parse_svg(
        &wrap(r#"<rect id="a" width="1" height="1"/><circle id="b" r="1"/>"#),
        View::Front,
        1e-3,
    ) {
        Err(ProfileError::SeveralOutlines { ids }) => assert_eq!(ids, vec!["a", "b"]),
        other => panic!("expected several outlines, got {other:?}"),
    }
    let bow = std::fs::read_to_string(data("crossing.svg")).expect("read");
    match parse_svg(&bow, View::Front, 1e-3) {
        Err(ProfileError::SelfIntersecting { at, .. }) => {
            assert!(
                at[0].abs() <= SVG_ROUNDING && at[1].abs() <= SVG_ROUNDING,
                "{at:?}"
            )
        }
        other => panic!("expected a self-intersection, got {other:?}"),
    }
    assert!(matches!(
        parse_svg("<svg", View::Front, 1e-3),
        Err(ProfileError::Svg { .. })
    ));
    assert!(matches!(
        parse_svg(CIRCLE_SVG, View::Front, 0.0),
        Err(ProfileError::InvalidParameter { .. })
    ));
}

#[test]
fn svg_and_json_round_trip() {
    for view in View::ALL {
        let p = Profile::new(
            view,
            vec![
                [0.1, 1.7],
                [-0.3, 0.2],
                [0.4, -0.25],
                [0.9, 0.6],
                [0.3, 0.8],
            ],
        )
        .expect("valid");
        let back = parse_svg(&to_svg(&[&p]), view, 1e-3)
            .expect("reads back")
            .outline;
        assert_eq!(back.len(), p.len(), "{view}");
        for (a, b) in p.points().iter().zip(back.points()) {
            assert!(
                (a[0] - b[0]).abs() <= SVG_ROUNDING && (a[1] - b[1]).abs() <= SVG_ROUNDING,
                "{view}: {a:?} vs {b:?}"
            );
        }
        let j = parse_json(&to_json(&p)).expect("json reads back");
        assert_eq!(j, p);
        let embedded: Profile =
            serde_json::from_str(&serde_json::to_string(&p).expect("ser")).expect("de");
        assert_eq!(embedded, p);
    }
    assert!(matches!(
        parse_json(r#"{"view": "front", "points": [[0,0],[1,0],[0,1]], "extra": 1}"#),
        Err(ProfileError::Json { .. })
    ));
    assert!(matches!(
        parse_json(r#"{"view": "back", "points": [[0,0],[1,0],[0,1]]}"#),
        Err(ProfileError::Json { .. })
    ));
    // deserialising validates
    let bow = r#"{"view": "side", "points": [[0,0],[1,1],[1,0],[0,1]]}"#;
    let e = serde_json::from_str::<Profile>(bow)
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(e.contains("intersects itself"), "{e}");
    assert!(matches!(
        parse_json(bow),
        Err(ProfileError::SelfIntersecting { .. })
    ));
}

#[test]
fn outlines_of_known_meshes_match_exact_outlines() {
    let r = CHECK_RESOLUTION;
    let b = box_mesh([0.0, 0.0, 0.0], [2.0, 1.0, 0.5]);
    let rect = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
    assert!(outline_error_px(&b, View::Front, &rect, r) <= CORNER_PX);
    let s = sphere([0.0; 3], 1.0, 64);
    for v in View::ALL {
        assert!(
            outline_error_px(&s, v, &hull_outline(&s, v), r) <= SMOOTH_PX,
            "{v}"
        );
    }
    let t = torus(1.0, 0.25, 48);
    assert!(outline_error_px(&t, View::Top, &hull_outline(&t, View::Top), r) <= SMOOTH_PX);
    let (m, exact) = cross();
    assert!(outline_error_px(&m, View::Front, &exact, r) <= CORNER_PX);
}

#[test]
fn outline_errors() {
    let b = box_mesh([0.0; 3], [1.0; 3]);
    let bad = |resolution| OutlineOptions::default().resolution(resolution);
    assert!(matches!(
        outline_of_mesh(&b, View::Front, &bad(0)),
        Err(ProfileError::InvalidParameter { .. })
    ));
    assert!(matches!(
        outline_of_mesh(
            &b,
            View::Front,
            &bad(pdesculpt::profile::MAX_RESOLUTION + 1)
        ),
        Err(ProfileError::InvalidParameter { .. })
    ));
    let empty = pdesculpt::mesh::Mesh::new(vec![[0.0; 3]], vec![]);
    assert!(outline_of_mesh(&empty, View::Front, &OutlineOptions::default()).is_err());
    // two separate boxes of equal size
    let mut two = box_mesh([0.0; 3], [1.0; 3]);
    two.append(&box_mesh([3.0, 0.0, 0.0], [4.0, 1.0, 1.0]));
    assert!(matches!(
        outline_of_mesh(&two, View::Front, &OutlineOptions::default()),
        Err(ProfileError::Disconnected { count: 2, .. })
    ));
    // a flat square seen edge-on
    let flat = pdesculpt::mesh::Mesh::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    assert!(matches!(
        outline_of_mesh(&flat, View::Side, &OutlineOptions::default()),
        Err(ProfileError::ZeroArea)
    ));
}

#[test]
fn makehuman_body_outline_is_one_simple_polygon_of_the_body_height() {
    let body = pdesculpt::makehuman::base_body()
        .expect("bundled body")
        .mesh;
    let (lo, hi) = body.bbox();
    let opts = OutlineOptions::default();
    for view in [View::Front, View::Side] {
        let p = outline_of_mesh(&body, view, &opts).expect("outline");
        let (_, v) = view.axes();
        let (hl, vl) = (view.axes().0, v);
        let extent = (hi[hl] - lo[hl]).max(hi[vl] - lo[vl]);
        let px = extent / opts.resolution as f64;
        assert!(
            (p.height() - (hi[v] - lo[v])).abs() <= px,
            "{view}: height {} vs {}",
            p.height(),
            hi[v] - lo[v]
        );
        // re-validating the points gives the same polygon: simple, closed
        assert_eq!(Profile::new(view, p.points().to_vec()).expect("simple"), p);
        assert!(p.len() > 100);
    }
}

/// OBJ lines of a 1 x 2 x 1 box at x from `x0`, its vertices numbered
/// from `first + 1` (boxes written one after another in one file).
fn box_obj(x0: f64, first: usize) -> String {
    let mut s = String::new();
    for (x, y, z) in [
        (0, 0, 0),
        (1, 0, 0),
        (1, 2, 0),
        (0, 2, 0),
        (0, 0, 1),
        (1, 0, 1),
        (1, 2, 1),
        (0, 2, 1),
    ] {
        s += &format!("v {} {y} {z}\n", x0 + x as f64);
    }
    for f in [
        [1, 3, 2],
        [1, 4, 3],
        [5, 6, 7],
        [5, 7, 8],
        [1, 2, 6],
        [1, 6, 5],
        [4, 8, 7],
        [4, 7, 3],
        [1, 5, 8],
        [1, 8, 4],
        [2, 3, 7],
        [2, 7, 6],
    ] {
        s += &format!("f {} {} {}\n", f[0] + first, f[1] + first, f[2] + first);
    }
    s
}

/// `pdesculpt --json profile extract MESH --view front -o SVG
/// --resolution 200 EXTRA...`, which must succeed: its JSON report and
/// its stderr.
fn extract_front(mesh: &str, svg: &str, extra: &[&str]) -> (serde_json::Value, String) {
    let mut args = vec![
        "--json",
        "profile",
        "extract",
        mesh,
        "--view",
        "front",
        "-o",
        svg,
        "--resolution",
        "200",
    ];
    args.extend_from_slice(extra);
    let out = pdesculpt(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    (v, String::from_utf8_lossy(&out.stderr).into_owned())
}

#[test]
fn cli_extract_and_check() {
    let d = tmpdir("profile");
    let obj = d.join("box.obj");
    std::fs::write(&obj, box_obj(0.0, 0)).expect("write");
    let svg = d.join("front.svg");
    let (o, s) = (obj.to_str().expect("utf8"), svg.to_str().expect("utf8"));
    let (v, _) = extract_front(o, s, &[]);
    let px = 2.0 / 200.0;
    assert!((v["height"].as_f64().unwrap_or(0.0) - 2.0).abs() <= px);
    assert!((v["width"].as_f64().unwrap_or(0.0) - 1.0).abs() <= px);
    assert!(v["points"].as_u64().unwrap_or(0) >= 4);
    let out = pdesculpt(&["--json", "profile", "check", s, "--view", "front"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let c: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    assert!(
        (c["area"].as_f64().unwrap_or(0.0) - v["area"].as_f64().unwrap_or(1.0)).abs()
            <= SVG_ROUNDING
    );

    let never = d.join("never.svg");
    let n = never.to_str().expect("utf8");
    assert_clear_error(
        &pdesculpt(&[
            "profile",
            "extract",
            "/no/such.obj",
            "--view",
            "front",
            "-o",
            n,
        ]),
        "/no/such.obj",
    );
    assert_clear_error(
        &pdesculpt(&["profile", "extract", o, "--view", "back", "-o", n]),
        "unknown view",
    );
    assert_clear_error(
        &pdesculpt(&[
            "profile",
            "extract",
            o,
            "--view",
            "front",
            "-o",
            n,
            "--resolution",
            "0",
        ]),
        "resolution",
    );
    assert_clear_error(
        &pdesculpt(&[
            "profile",
            "extract",
            o,
            "--view",
            "front",
            "-o",
            n,
            "--resolution",
            "100000",
        ]),
        "resolution",
    );
    let empty = d.join("empty.obj");
    std::fs::write(&empty, "v 0 0 0\nv 1 0 0\nv 0 1 0\n").expect("write");
    assert_clear_error(
        &pdesculpt(&[
            "profile",
            "extract",
            empty.to_str().expect("utf8"),
            "--view",
            "front",
            "-o",
            n,
        ]),
        "no triangles",
    );
    assert!(!never.exists(), "no output on failure");
    assert_clear_error(
        &pdesculpt(&["profile", "check", &data("crossing.svg"), "--view", "front"]),
        "intersects itself",
    );
    std::fs::remove_dir_all(&d).ok();
}

/// `profile extract --group` outlines only the named OBJ groups (MakeHuman's
/// base mesh hides a skirt and tights in helper groups); without it a
/// mesh of several groups is outlined whole, with a note naming them.
#[test]
fn cli_extract_outlines_only_the_named_groups() {
    let d = tmpdir("profile-groups");
    let obj = d.join("two.obj");
    std::fs::write(
        &obj,
        format!("g body\n{}g helper\n{}", box_obj(0.0, 0), box_obj(0.5, 8)),
    )
    .expect("write");
    let o = obj.to_str().expect("utf8");
    let svg = d.join("front.svg");
    let s = svg.to_str().expect("utf8");
    let width = |extra: &[&str]| {
        let (v, stderr) = extract_front(o, s, extra);
        (v["width"].as_f64().unwrap_or(0.0), stderr)
    };
    // the outer outline of both boxes spans x 0..1.5; the body alone 0..1
    let px = 1.5 / 200.0;
    let (all, note) = width(&[]);
    assert!((all - 1.5).abs() <= px, "all groups: width {all}");
    assert!(
        note.contains("--group") && note.contains("helper"),
        "{note}"
    );
    let (body, quiet) = width(&["--group", "body"]);
    assert!((body - 1.0).abs() <= px, "body: width {body}");
    assert!(!quiet.contains("--group"), "{quiet}");
    let never = d.join("never.svg");
    let n = never.to_str().expect("utf8");
    assert_clear_error(
        &pdesculpt(&[
            "profile", "extract", o, "--view", "front", "-o", n, "--group", "bdy",
        ]),
        "no group 'bdy'",
    );
    assert!(!never.exists(), "no output on failure");
    std::fs::remove_dir_all(&d).ok();
}
