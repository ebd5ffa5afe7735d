//! Issue 35, drawings: every finding of the bad-input probe on SVG loading,
//! reduced to its input, with the clear error expected (or the correct
//! result) and no file read that the user did not name.

use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
use crate::fuzz_harness::guarded;
use kurbo::{BezPath, Point};
use pdesculpt::profile::{estimate_points, parse_svg, ProfileError, View};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::time::Duration;

/// Per-case limit of the cases that used to hang (debug build, busy
/// machine); they now fail in milliseconds.
const LIMIT: Duration = Duration::from_secs(30);

fn svg(body: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink">{body}</svg>"#
    )
}

/// Flattening tolerance of the drawings that read (model units).
const FLATTEN: f64 = 1e-3;
/// The blob's two cubics have 7 distinct control points: a flattened
/// outline has more points than that.
const BLOB_CONTROL_POINTS: usize = 8;

const BLOB: &str = r#"<path id="o" d="M 0 0 C 0.3 -0.5 0.7 -0.5 1 0 C 0.7 0.5 0.3 0.5 0 0 Z"/>"#;

fn cubic(size: &str) -> String {
    svg(&format!(
        r#"<path id="o" d="M 0 0 C {size} 0 {size} {size} 0 {size} Z"/>"#
    ))
}

/// Parses on a guarded thread: a hang or a panic fails the test by name.
fn parse(text: String, tolerance: f64) -> Result<usize, String> {
    guarded(LIMIT, move || {
        parse_svg(&text, View::Front, tolerance)
            .map(|s| s.outline.points().len())
            .map_err(|e| e.to_string())
    })
    .unwrap_or_else(|what| panic!("parse_svg: {what}"))
}

#[test]
fn tolerance_1e_300_is_refused_by_the_point_budget_not_a_capacity_overflow() {
    let e = parse(svg(BLOB), 1e-300).expect_err("refused");
    assert!(
        e.contains("would give about") && e.contains("raise the tolerance"),
        "{e}"
    );
    // the same drawing at an ordinary tolerance reads
    assert!(parse(svg(BLOB), FLATTEN).expect("reads") > BLOB_CONTROL_POINTS);
}

#[test]
fn huge_cubics_and_arcs_are_refused_before_flattening() {
    for size in ["1e30", "1e12", "1e11"] {
        let e = parse(cubic(size), 2e-3).expect_err(size);
        assert!(e.contains("beyond the drawing range"), "{size}: {e}");
    }
    // usvg (f32) collapses this arc: refused by the drawing's size either
    // way, never flattened into gigabytes
    let arc = svg(r#"<path id="o" d="M 0 0 A 1e30 1e30 0 1 1 1 0 Z"/>"#);
    let e = parse(arc, 2e-3).expect_err("arc");
    assert!(
        e.contains("beyond the drawing range") || e.contains("outside the range 1e-5 to 100000"),
        "{e}"
    );
    // inside the range but too fine for the budget
    let e = parse(cubic("1e4"), 1e-7).expect_err("budget");
    assert!(e.contains("over the limit of 200000"), "{e}");
}

#[test]
fn four_hundred_circles_are_refused_before_any_is_flattened() {
    let big: String = (0..400)
        .map(|i| format!(r#"<circle cx="{i}" cy="0" r="1e9"/>"#))
        .collect();
    let e = parse(svg(&big), 2e-3).expect_err("r = 1e9");
    assert!(e.contains("beyond the drawing range"), "{e}");
    let fine: String = (0..400)
        .map(|i| format!(r#"<circle cx="{}" cy="0" r="1"/>"#, 3 * i))
        .collect();
    let e = parse(svg(&fine), 1e-7).expect_err("budget");
    assert!(e.contains("over the limit"), "{e}");
}

#[test]
fn too_many_shapes_are_refused_by_count() {
    let many: String = (0..10_001)
        .map(|i| format!(r#"<rect x="{i}" y="0" width="0.5" height="0.5"/>"#))
        .collect();
    let e = parse(svg(&many), 2e-3).expect_err("shapes");
    assert!(e.contains("shapes of the SVG drawing = 10001"), "{e}");
}

#[cfg(unix)]
#[test]
fn image_references_are_never_opened_fifo_device_or_file() {
    let d = tmpdir("harden-image");
    let fifo = d.join("fifo");
    let _ = std::fs::remove_file(&fifo);
    let c = std::ffi::CString::new(fifo.to_str().expect("utf8")).expect("c");
    // SAFETY: a valid NUL-terminated path
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    for href in [fifo.to_str().expect("utf8"), "/dev/zero", "/etc/passwd"] {
        let text = svg(&format!(
            r#"<image xlink:href="{href}" width="1" height="1"/>{BLOB}"#
        ));
        // opening the FIFO would block forever, reading /dev/zero would not end
        let n = parse(text, FLATTEN).expect("the outline reads; the image is ignored");
        assert!(n > BLOB_CONTROL_POINTS, "{href}");
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn non_finite_and_overflowing_numbers_are_named_with_their_element() {
    let cases = [
        (
            r#"<path id="o" d="M 0 0 L NaN 1 L 1 1 Z"/>"#,
            "<path id=\"o\">: attribute d holds \"NaN\"",
        ),
        (
            r#"<path id="o" d="M 0 0 L 1e39 1 L 1 1 Z"/>"#,
            "holds \"1e39\", beyond the 32-bit float range",
        ),
        (
            r#"<g id="g" transform="scale(NaN)">{BLOB}</g>"#,
            "<g id=\"g\">: attribute transform holds \"NaN\"",
        ),
        (
            r#"<g transform="scale(1e20)"><g transform="scale(1e20)">{BLOB}</g></g>"#,
            "may scale coordinates past the 32-bit float range",
        ),
    ];
    for (body, needle) in cases {
        let e = parse(svg(&body.replace("{BLOB}", BLOB)), FLATTEN).expect_err(body);
        assert!(e.contains(needle), "{body}: {e}");
    }
}

#[test]
fn a_closed_path_named_cut_is_refused_not_used_as_a_cut() {
    let text = svg(&format!(
        r#"{BLOB}<path id="cut_x" d="M 0.2 -1 L 0.8 -1 L 0.5 1 Z"/>"#
    ));
    match parse_svg(&text, View::Front, FLATTEN) {
        Err(ProfileError::ClosedCut { id }) => assert_eq!(id, "cut_x"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_drawing_of_1e30_is_refused_by_its_size_not_a_condition_number() {
    let d = tmpdir("harden-size");
    let json = d.join("huge.json");
    std::fs::write(&json, "[[0, 0], [1e30, 0], [1e30, 2e30], [0, 2e30]]").expect("write");
    let out_path = d.join("o.obj");
    let out = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        json.to_str().expect("utf8"),
        "-o",
        out_path.to_str().expect("utf8"),
    ]);
    assert_clear_error(&out, "the drawing is 2e30 model units across");
    assert!(!out_path.exists());
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
/// Issue 28: each view is placed by its own outline (feet at y = 0), so a
/// side view drawn anywhere on its page builds (it used to be refused).
fn a_side_view_drawn_5_m_above_the_front_is_placed_by_its_own_outline() {
    let d = tmpdir("harden-side");
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/data/sketch/");
    let side = std::fs::read_to_string(format!("{data}male_side.svg")).expect("side");
    let side = side
        .replacen("<path", r#"<g transform="translate(0,-5)"><path"#, 1)
        .replace("</svg>", "</g></svg>");
    let sp = d.join("side.svg");
    std::fs::write(&sp, side).expect("write");
    let out_path = d.join("o.obj");
    let out = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        &format!("{data}male_front.svg"),
        "--side",
        sp.to_str().expect("utf8"),
        "-o",
        out_path.to_str().expect("utf8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out_path.exists());
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn profile_extract_of_a_1e37_cube_writes_no_svg_its_check_would_refuse() {
    let d = tmpdir("harden-extract");
    let mut obj = String::new();
    for x in [0.0, 1e37] {
        for y in [0.0, 1e37] {
            for z in [0.0, 1e37] {
                obj += &format!("v {x:e} {y:e} {z:e}\n");
            }
        }
    }
    obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    let m = d.join("cube.obj");
    std::fs::write(&m, obj).expect("write");
    let svg_path = d.join("cube.svg");
    let out = pdesculpt(&[
        "profile",
        "extract",
        m.to_str().expect("utf8"),
        "--view",
        "front",
        "-o",
        svg_path.to_str().expect("utf8"),
    ]);
    assert_clear_error(&out, "outside the range");
    assert!(!svg_path.exists());
    let _ = std::fs::remove_dir_all(&d);
}

/// Points kurbo emits for `b` at `tolerance`.
fn flattened(b: &BezPath, tolerance: f64) -> f64 {
    let mut n = 0.0;
    kurbo::flatten(b.iter(), tolerance, |_| n += 1.0);
    n
}

#[test]
fn the_point_estimate_bounds_kurbos_flattening() {
    let coord = || prop_oneof![-1e3f64..1e3, -1.0f64..1.0, Just(0.0)];
    let curve = (
        proptest::collection::vec((coord(), coord()), 4),
        prop_oneof![Just(1e-6), Just(1e-3), Just(0.1), 1e-5f64..1.0],
        any::<bool>(),
    );
    let mut runner = TestRunner::new_with_rng(
        Config {
            cases: 400,
            failure_persistence: None,
            ..Config::default()
        },
        TestRng::from_seed(RngAlgorithm::ChaCha, &[35; 32]),
    );
    runner
        .run(&curve, |(p, tol, quad)| {
            let pt = |i: usize| Point::new(p[i].0, p[i].1);
            let mut b = BezPath::new();
            b.move_to(pt(0));
            if quad {
                b.quad_to(pt(1), pt(2));
            } else {
                b.curve_to(pt(1), pt(2), pt(3));
            }
            b.close_path();
            let (est, got) = (estimate_points(&b, tol), flattened(&b, tol));
            prop_assert!(got <= est, "kurbo {got} > estimate {est}");
            Ok(())
        })
        .expect("the estimate is an upper bound");
    // extreme curves: cusps, loops, one long control arm
    for p in [
        [(0.0, 0.0), (1e3, 0.0), (0.0, 0.0), (1e3, 0.0)],
        [(0.0, 0.0), (1e3, 1e3), (-1e3, 1e3), (1.0, 0.0)],
        [(0.0, 0.0), (0.0, 0.0), (0.0, 0.0), (1e-3, 0.0)],
    ] {
        let pt = |i: usize| Point::new(p[i].0, p[i].1);
        let mut b = BezPath::new();
        b.move_to(pt(0));
        b.curve_to(pt(1), pt(2), pt(3));
        for tol in [1e-9, 1e-4, 1.0] {
            assert!(
                flattened(&b, tol) <= estimate_points(&b, tol),
                "{p:?} {tol}"
            );
        }
    }
}
