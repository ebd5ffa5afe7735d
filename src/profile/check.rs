//! Checks of the profile family: mesh outlines against exact outlines,
//! SVG curve flattening against an exact circle, distances against closed
//! forms. They measure and report; the tests assert on them.

use super::shapes::{box_mesh, convex_hull, cylinder, sphere, torus};
use super::{outline_of_mesh, parse_svg, profile_distance, OutlineOptions, Profile, View};
use crate::check::{tol, Check, Kind};
use crate::check::{worst, Worst};
use crate::mesh::Mesh;

const F: &str = "profile";
const P: &str = "000";

/// Resolution of the outline checks (pixels along the larger extent).
pub const CHECK_RESOLUTION: usize = 400;
/// Outline accuracy at sharp corners, in pixels (a corner between grid
/// lines is cut by a chord: at most h / sqrt(2), plus rounding).
pub const CORNER_PX: f64 = 0.75;
/// Outline accuracy of an axis-aligned box, whose corners fall on grid
/// lines so the scanline outline is exact up to coordinate rounding
/// (measured 1e-6 px; ten times that). A corner cut by a chord, as on the
/// turned box, is [`CORNER_PX`].
pub const GRID_ALIGNED_PX: f64 = 1e-5;
/// Outline accuracy on smooth outlines, in pixels (Douglas-Peucker 0.25 px
/// plus the chord sagitta).
pub const SMOOTH_PX: f64 = 0.35;
/// Relative rounding of coordinates read back from SVG (usvg parses and
/// transforms in f32: about 6e-8 relative, with margin for transforms).
pub const SVG_ROUNDING: f64 = 1e-6;
/// usvg turns elliptic arcs (the `A` path command, rounded `rect`
/// corners) into cubic Béziers before we see them,
/// with a radial error up to about this fraction of the radius (kurbo's
/// arc approximation, at least 4 cubics per turn: 2.7e-4, plus margin).
/// Flattening adds at most the requested tolerance on top. (`circle` and
/// `ellipse` elements are flattened from their exact conic instead.)
pub const USVG_ARC_REL: f64 = 3e-4;
/// Flattening tolerance of the SVG circle check (model units, radius 50).
pub const FLATTEN_TOL: f64 = 0.01;

/// Hausdorff distance between the outline of `m` in `view` and the exact
/// outline `exact`, in pixels of the check resolution.
pub fn outline_error_px(m: &Mesh, view: View, exact: &[[f64; 2]], resolution: usize) -> f64 {
    let opts = OutlineOptions {
        resolution,
        ..OutlineOptions::default()
    };
    let (Ok(got), Ok(want)) = (
        outline_of_mesh(m, view, &opts),
        Profile::new(view, exact.to_vec()),
    ) else {
        return f64::NAN;
    };
    let extent = want.width().worst(want.height());
    profile_distance(&got, &want).max / (extent / resolution as f64)
}

/// Exact outline of a convex mesh: the hull of its projected vertices.
pub fn hull_outline(m: &Mesh, view: View) -> Vec<[f64; 2]> {
    let p: Vec<[f64; 2]> = m.positions.iter().map(|&q| view.project(q)).collect();
    convex_hull(&p)
}

/// A cross of two boxes (non-convex) and its exact front outline.
pub fn cross() -> (Mesh, Vec<[f64; 2]>) {
    let mut m = box_mesh([-3.0, -0.5, -0.5], [3.0, 0.5, 0.5]);
    m.append(&box_mesh([-0.5, -3.0, -0.4], [0.5, 3.0, 0.4]));
    let exact = vec![
        [0.5, -3.0],
        [0.5, -0.5],
        [3.0, -0.5],
        [3.0, 0.5],
        [0.5, 0.5],
        [0.5, 3.0],
        [-0.5, 3.0],
        [-0.5, 0.5],
        [-3.0, 0.5],
        [-3.0, -0.5],
        [-0.5, -0.5],
        [-0.5, -3.0],
    ];
    (m, exact)
}

/// Every check of the family.
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    let r = CHECK_RESOLUTION;
    // box: a rotated-free axis-aligned box has a rectangular outline
    let b = box_mesh([-0.3, 0.1, -0.2], [0.7, 1.9, 0.45]);
    for (view, name, exact) in [
        (
            View::Front,
            "box-front",
            vec![[-0.3, 0.1], [0.7, 0.1], [0.7, 1.9], [-0.3, 1.9]],
        ),
        (
            View::Side,
            "box-side",
            vec![[-0.2, 0.1], [0.45, 0.1], [0.45, 1.9], [-0.2, 1.9]],
        ),
        (
            View::Top,
            "box-top",
            vec![[-0.3, -0.2], [0.7, -0.2], [0.7, 0.45], [-0.3, 0.45]],
        ),
    ] {
        out.push(
            Check::new(
                F,
                P,
                "outline",
                &format!("profile.outline-{name}"),
                Kind::Reference,
                outline_error_px(&b, view, &exact, r),
                GRID_ALIGNED_PX,
            )
            .note("Hausdorff distance (pixels) from the mesh outline to the exact rectangle (corners on grid lines: exact up to coordinate rounding)"),
        );
    }
    // the same box turned by 0.4 rad about z: its front outline is the
    // rotated rectangle, with corners off the grid lines (the axis-aligned
    // box's extreme corners fall on grid lines, so it measures ~0)
    let (c, s) = (0.4f64.cos(), 0.4f64.sin());
    let rot = |p: [f64; 3]| [c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]];
    let mut turned = b.clone();
    turned.map_positions(rot);
    let exact: Vec<[f64; 2]> = [[-0.3, 0.1], [0.7, 0.1], [0.7, 1.9], [-0.3, 1.9]]
        .iter()
        .map(|p| View::Front.project(rot([p[0], p[1], 0.0])))
        .collect();
    out.push(
        Check::new(F, P, "outline", "profile.outline-turned-box-front", Kind::Reference, outline_error_px(&turned, View::Front, &exact, r), CORNER_PX)
            .note("Hausdorff distance (pixels) from the front outline of a box turned 0.4 rad about z to the exact rotated rectangle"),
    );
    let s = sphere([0.1, 0.2, -0.3], 1.0, 96);
    out.push(
        Check::new(F, P, "outline", "profile.outline-sphere-front", Kind::Reference, outline_error_px(&s, View::Front, &hull_outline(&s, View::Front), r), SMOOTH_PX)
            .note("Hausdorff distance (pixels) from the outline of a UV sphere to the convex hull of its projected vertices"),
    );
    let c = cylinder(0.4, -1.0, 1.0, 64);
    out.push(
        Check::new(F, P, "outline", "profile.outline-cylinder-side", Kind::Reference, outline_error_px(&c, View::Side, &[[-0.4, -1.0], [0.4, -1.0], [0.4, 1.0], [-0.4, 1.0]], r), GRID_ALIGNED_PX)
            .note("Hausdorff distance (pixels) from the side outline of a cylinder to the exact rectangle (corners on grid lines: exact up to coordinate rounding)"),
    );
    let t = torus(1.0, 0.3, 64);
    out.push(
        Check::new(F, P, "outline", "profile.outline-torus-top", Kind::Reference, outline_error_px(&t, View::Top, &hull_outline(&t, View::Top), r), SMOOTH_PX)
            .note("Hausdorff distance (pixels) from the top outline of a torus (its hole excluded) to the hull of its vertices"),
    );
    let (m, exact) = cross();
    out.push(
        Check::new(F, P, "outline", "profile.outline-cross-front", Kind::Reference, outline_error_px(&m, View::Front, &exact, r), CORNER_PX)
            .note("Hausdorff distance (pixels) from the outline of two crossed boxes (non-convex, 12 corners) to the exact cross"),
    );
    out.push(svg_circle_check());
    out.push(distance_check());
    out
}

/// An SVG `<circle>` of radius 50 flattened with [`FLATTEN_TOL`]: largest
/// deviation of the polygon (vertices and edge midpoints) from the exact
/// circle, over `FLATTEN_TOL` plus f32 rounding (passes at <= 1).
fn svg_circle_check() -> Check {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg"><circle cx="10" cy="-20" r="50"/></svg>"#;
    let measured = match parse_svg(svg, View::Front, FLATTEN_TOL) {
        Ok(s) => {
            let p = s.outline.points();
            let n = p.len();
            let dev = |q: [f64; 2]| ((q[0] - 10.0).hypot(q[1] - 20.0) - 50.0).abs();
            (0..n)
                .flat_map(|i| {
                    let (a, b) = (p[i], p[(i + 1) % n]);
                    [dev(a), dev([0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])])]
                })
                .fold(0.0, worst)
                / (FLATTEN_TOL + SVG_ROUNDING * 100.0)
        }
        Err(_) => f64::NAN,
    };
    Check::new(F, P, "svg", "profile.svg-circle-flatten", Kind::Reference, measured, 1.0)
        .note("largest distance of the flattened SVG circle from the exact circle, in units of the flattening tolerance (plus f32 rounding)")
}

/// Two concentric squares of half-sides 1 and 1.25: Hausdorff distance
/// 0.25 * sqrt(2) (corner to corner), relative error against it.
fn distance_check() -> Check {
    let sq = |s: f64| vec![[-s, -s], [s, -s], [s, s], [-s, s]];
    let measured = match (
        Profile::new(View::Front, sq(1.0)),
        Profile::new(View::Front, sq(1.25)),
    ) {
        (Ok(a), Ok(b)) => {
            let d = profile_distance(&a, &b);
            (d.max - 0.25 * 2f64.sqrt()).abs() / (0.25 * 2f64.sqrt())
        }
        _ => f64::NAN,
    };
    Check::new(
        F,
        P,
        "distance",
        "profile.distance-squares",
        Kind::Reference,
        measured,
        tol::ROUNDING,
    )
    .note("relative error of the Hausdorff distance between concentric squares against 0.25 sqrt 2")
}
