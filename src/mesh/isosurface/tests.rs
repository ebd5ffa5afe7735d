//! Unit tests of the polygonisers.

use super::*;
use crate::check::tol;
use crate::mesh::topology::report;

/// The unit sphere polygonised on a 20-cell grid: relative volume error
/// (discretisation, not rounding).
const SPHERE_VOLUME_REL_MAX: f64 = 0.05;

fn sphere_grid(n: usize) -> ScalarGrid {
    ScalarGrid::sample([-1.3; 3], [1.3; 3], [n; 3], |p| {
        1.0 - (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()
    })
    .expect("grid")
}

#[test]
fn sphere_is_closed_manifold_oriented_outward() {
    let g = sphere_grid(20);
    for m in [marching_tetrahedra(&g, 0.0), surface_nets(&g, 0.0)] {
        let r = report(&m);
        assert!(r.watertight && r.manifold && r.oriented, "{r:?}");
        assert_eq!(r.euler, 2);
        let v = m.signed_volume();
        let exact = 4.0 / 3.0 * std::f64::consts::PI;
        assert!(
            (v - exact).abs() / exact < SPHERE_VOLUME_REL_MAX,
            "volume {v}"
        );
    }
}

/// Grids whose level sets touch the box, tie with the level at nodes
/// (quantised values), have several components and uneven dimensions.
fn awkward_grids() -> Vec<(ScalarGrid, f64)> {
    let wavy = |p: [f64; 3]| (3.0 * p[0]).sin() * (2.0 * p[1]).cos() + (4.0 * p[2]).sin();
    vec![
        (sphere_grid(20), 0.0),
        (sphere_grid(3), 0.0),
        (
            ScalarGrid::sample([-1.0, -1.5, -0.7], [1.2, 1.0, 0.9], [17, 23, 11], wavy)
                .expect("grid"),
            0.3,
        ),
        (
            ScalarGrid::sample([-1.0; 3], [1.0; 3], [13, 9, 15], |p| {
                (4.0 * wavy(p)).round() / 4.0
            })
            .expect("grid"),
            0.0,
        ),
        (
            ScalarGrid::sample([-2.0; 3], [2.0; 3], [10, 10, 10], |p| {
                -1e4 * (p[0] * p[0] + p[1] * p[1] - p[2])
            })
            .expect("grid"),
            -2.5e3,
        ),
    ]
}

#[test]
fn slab_polygonisers_match_the_hash_map_reference_exactly() {
    for (g, iso) in awkward_grids() {
        for (ours, theirs) in [
            (
                marching_tetrahedra(&g, iso),
                reference::marching_tetrahedra(&g, iso),
            ),
            (surface_nets(&g, iso), reference::surface_nets(&g, iso)),
        ] {
            assert!(!ours.triangles.is_empty() || g.dims[0] == 3);
            assert_eq!(ours.triangles, theirs.triangles, "dims {:?}", g.dims);
            assert_eq!(ours.positions, theirs.positions, "dims {:?}", g.dims);
        }
    }
}

#[test]
fn awkward_grids_give_closed_oriented_surfaces() {
    for (g, iso) in awkward_grids() {
        let r = report(&marching_tetrahedra(&g, iso));
        assert!(r.watertight && r.manifold && r.oriented, "{r:?}");
        // surface nets: also where the level set is clipped by the box
        // (may be non-manifold at ambiguous cubes)
        let r = report(&surface_nets(&g, iso));
        assert!(r.watertight && r.oriented, "{:?} {r:?}", g.dims);
    }
}

#[test]
fn quality_of_known_triangles() {
    let h = 3f64.sqrt() / 2.0;
    let m = Mesh {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.5, h, 0.0], [2.0, 0.0, 0.0]],
        triangles: vec![[0, 1, 2], [0, 1, 3]],
        tri_group: vec![0, 0],
        groups: vec!["s".into()],
    };
    let q = triangle_quality(&m);
    assert_eq!(q.triangles, 2);
    assert_eq!(q.degenerate, 1);
    assert!((q.mean_aspect - 1.0).abs() < tol::ROUNDING, "{q:?}");
    assert!((q.max_aspect - 1.0).abs() < tol::ROUNDING);
    assert_eq!(q.min_angle_deg, 0.0);
    assert!((q.mean_min_angle_deg - 30.0).abs() < tol::SOLVE);
    assert_eq!(q.frac_below_10deg, 0.5);
}
