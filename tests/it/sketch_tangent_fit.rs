//! The sketched transitions' tangent factors (and late depth blends)
//! fitted to the drawing (`sketch::tangent_fit`), on the corpus's
//! arms_apart (its two arms at different angles): with the derived
//! factors its model missed the drawn front by 1.00 % of the height,
//! with the fitted ones 0.74 %; and on chubby's square shoulders. (The test
//! first used the cartoon with a head half the height, 1.66 % with the
//! derived factors; since the arms' chains run along their rims and a
//! guarded end leaves along its chord, docs/drawing-corpus.md nineteenth
//! and twentieth measurements, its derived factors are already the best
//! and the fit keeps them.)

use crate::sketch_draw::{build, shoulders};
use pdesculpt::character::assembly::{transition_points, BlendTry, Resolution};
use pdesculpt::pipeline::Built;
use pdesculpt::sketch::quality::ViewQuality;
use std::path::PathBuf;

/// The whole-model front profile error bound, relative to the height:
/// between the fitted factors' 0.74 % and the derived ones' 1.00 %, so
/// the test fails if the fit does not act.
const FITTED_FRONT_MAX: f64 = 0.0085;
/// How far (relative to the height) a point the fit measures may lie from
/// the mesh vertex it stands for: the same evaluation, so rounding only.
const SAME_POINT: f64 = 1e-12;

fn corpus(name: &str) -> Built {
    let data = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/sketch/corpus");
    build(
        &data.join(format!("{name}_front.svg")),
        &data.join(format!("{name}_side.svg")),
        None,
    )
    .unwrap_or_else(|e| panic!("{name} builds: {e}"))
}

/// The whole model's profile error in `view` ("front", "side").
fn whole_view<'a>(b: &'a Built, view: &str) -> &'a ViewQuality {
    b.report
        .quality
        .whole
        .views
        .iter()
        .find(|v| v.view == view)
        .unwrap_or_else(|| panic!("no {view} view"))
}

/// The fit takes the shoulders' factors off the derived ones (arms 0.7,
/// head 1) and the model follows the drawn front closer than with them.
#[test]
fn a_drawings_shoulders_follow_its_drawn_front_with_fitted_tangents() {
    let b = corpus("arms_apart");
    let shoulders = shoulders(&b);
    let derived = [0.7, 1.0, 0.7];
    let fitted: Vec<f64> = (0..3).map(|c| shoulders.child_scale(c)).collect();
    assert_ne!(fitted, derived, "the fit kept every derived factor");
    let front = whole_view(&b, "front");
    assert!(
        front.max_rel <= FITTED_FRONT_MAX,
        "front profile error {:.2} % of the height (factors {fitted:?})",
        100.0 * front.max_rel
    );
}

/// The side-view bound of issue 28 (relative to the height). The corpus's
/// chubby figure has square shoulders in its side view; with the plain
/// blend the head's transition cut the back's corner, 3.00 % of the height
/// inside the drawing, with the fitted late depth blend 1.74 %.
const SQUARE_SIDE_MAX: f64 = 0.02;

/// The fit starts the head's depth blend late on the side of the back
/// (its loop's -z side) and the model follows the drawn square shoulders.
#[test]
fn square_shoulders_are_followed_by_a_late_depth_blend() {
    let b = corpus("chubby");
    let shoulders = shoulders(&b);
    let head = shoulders
        .children
        .iter()
        .position(|c| c == "head")
        .expect("the head is a child");
    let rise = shoulders.child_rises.get(head).copied().unwrap_or([0.0; 2]);
    assert!(rise[0] > 0.0, "the head's back blends as before: {rise:?}");
    let side = whole_view(&b, "side");
    assert!(
        side.max_rel <= SQUARE_SIDE_MAX,
        "side profile error {:.2} % of the height (rises {:?})",
        100.0 * side.max_rel,
        shoulders.child_rises
    );
}

/// What the fit measures is what the mesh holds: every point
/// `transition_points` gives at the document's factors is a vertex of the
/// built mesh.
#[test]
fn the_fitted_points_are_the_meshs_vertices() {
    let b = corpus("cartoon_head_half");
    let h = b.report.height;
    let rows = Resolution::default().transition_rows;
    let verts = &b.model.mesh.positions;
    for t in b.doc.transitions() {
        for c in 0..t.children.len() {
            let pts = transition_points(t, &b.model.parts, c, rows, &[BlendTry::document(t, c)])
                .expect("planned");
            for p in &pts[0] {
                let d = verts
                    .iter()
                    .map(|v| pdesculpt::mesh::dist(*v, *p))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    d <= SAME_POINT * h,
                    "{} child {c}: a point {:.3e} of the height from the mesh",
                    t.name,
                    d / h
                );
            }
        }
    }
}
