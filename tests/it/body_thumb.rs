//! The closed body's hands (issue 15, build item 1): each hand is a mitten
//! and a thumb joined to the arm by a wrist transition; the skin's thumb
//! lies on the reconstruction and the web between thumb and index finger
//! stays open (a mitten of convex hulls would fill it).

use pdesculpt::body::closed::{
    load_body, reconstruct_closed, ClosedOptions, JOIN_C1_MAX, THUMB_SKIN_MAX_REL,
};
use pdesculpt::body::hand::winding_number;
use pdesculpt::check::tol;

#[test]
fn the_base_body_has_a_thumb_on_each_hand_and_an_open_web() {
    let b = crate::shared::closed_body(&[]);
    let r = &b.report;
    for side in ["l", "r"] {
        for part in [format!("thumb_{side}"), format!("hand_{side}")] {
            assert!(b.specs.iter().any(|p| p.name == part), "no part {part}");
        }
        let wrist = format!("wrist_{side}");
        let t = b.transitions.iter().find(|t| t.name == wrist).unwrap();
        assert_eq!(t.parent, format!("arm_{side}"));
        assert_eq!(
            t.children,
            [format!("hand_{side}"), format!("thumb_{side}")]
        );
        // the report's joins cover the wrist: both parts of both children
        let joins: Vec<_> = r.joins.iter().filter(|j| j.transition == wrist).collect();
        assert_eq!(joins.len(), 4, "{wrist}");
        for j in joins {
            assert!(j.c1 <= JOIN_C1_MAX && j.samples > 0, "{wrist}: {j:?}");
        }
    }
    assert_eq!(r.hands.len(), 2);
    for h in &r.hands {
        assert!(h.thumb_vertices >= 50, "{h:?}");
        assert!(h.thumb_skin_to_recon_max_rel <= THUMB_SKIN_MAX_REL, "{h:?}");
        assert!(h.web_points >= 2, "{h:?}");
        assert_eq!(h.web_points_inside, 0, "{h:?}");
    }
    assert_eq!(r.self_intersections.pairs, 0, "{:?}", r.self_intersections);
}

/// The web check sees a mitten: the web points are the middles of the gaps
/// between two loops of one plane, so the convex hull of those loops (a
/// mitten section) holds them, and a closed hull surface encloses them.
#[test]
fn a_convex_hull_mitten_fills_the_web() {
    use pdesculpt::profile::shapes::convex_hull;
    // two unit squares 0.5 apart in the plane z = 0: the middle of their
    // gap is inside the hull of both
    let sq = |x0: f64| vec![[x0, 0.0], [x0 + 1.0, 0.0], [x0 + 1.0, 1.0], [x0, 1.0]];
    let pts: Vec<[f64; 2]> = sq(0.0).into_iter().chain(sq(1.5)).collect();
    let hull = convex_hull(&pts);
    let inside = |p: [f64; 2]| {
        let n = hull.len();
        (0..n).all(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= -1e-12
        })
    };
    assert!(inside([1.25, 0.5]));
    // the winding number tells inside from outside on a closed mesh
    let cube = pdesculpt::profile::shapes::box_mesh([0.0; 3], [1.0; 3]);
    assert!((winding_number(&cube, [0.5, 0.5, 0.5]).abs() - 1.0).abs() < tol::SOLVE);
    assert!(winding_number(&cube, [1.5, 0.5, 0.5]).abs() < tol::SOLVE);
}

/// Without thumbs (`ClosedOptions::thumbs` off, the path a mesh whose
/// hands show no separate thumb takes) each arm is one chain ending in a
/// mitten: still one watertight, manifold, oriented body, C1 at the joins,
/// no wrist, and the report names both arms as thumbless.
#[test]
fn without_thumbs_each_arm_ends_in_a_mitten_and_the_report_says_so() {
    let skin = load_body(None, &[]).unwrap();
    let o = ClosedOptions::default().with_thumbs(false);
    let b = reconstruct_closed(&skin, &o).unwrap();
    let r = &b.report;
    let t = &r.topology;
    assert!(t.watertight && t.manifold && t.oriented, "{t:?}");
    assert!(r.max_join[1] <= JOIN_C1_MAX, "C1 {}", r.max_join[1]);
    assert!(b.transitions.iter().all(|t| !t.name.starts_with("wrist")));
    assert!(b
        .specs
        .iter()
        .all(|p| !p.name.starts_with("thumb") && !p.name.starts_with("hand")));
    let arm = b.specs.iter().find(|p| p.name == "arm_l").unwrap();
    assert!(arm.closed_end, "the arm ends in a mitten tip");
    assert!(r.hands.is_empty());
    assert_eq!(r.thumbless.len(), 2, "{:?}", r.thumbless);
    assert!(r.thumbless[0].starts_with("arm_l: ") && r.thumbless[0].contains("thumbs off"));
}
