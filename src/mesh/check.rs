//! Checks of the mesh infrastructure against independent facts: brute-force
//! closest points, the exact area, volume and cross sections of a torus,
//! Euler characteristics, and lossless file round trips.

use super::io::{encode_obj, encode_ply, encode_stl, parse_obj, parse_ply, parse_stl};
use super::metrics::{closest_point_on_triangle, TriangleBvh};
use super::samples::{lcg, torus_mesh};
use super::{dist, slice, topology, Mesh};
use crate::check::Measure;
use crate::check::{least, Worst};
use crate::check::{tol, Check, Kind};
use std::f64::consts::PI;

/// All checks of the mesh family.
pub fn checks() -> Vec<Check> {
    let mut out = vec![bvh_check(), triangle_distance_check()];
    out.extend(torus_checks());
    out.push(round_trip_check());
    out
}

/// BVH closest points equal brute force over all triangles.
fn bvh_check() -> Check {
    let m = torus_mesh(24);
    let bvh = TriangleBvh::new(&m);
    let mut seed = 0x9e3779b97f4a7c15u64;
    let mut worst: f64 = 0.0;
    for _ in 0..200 {
        let p = [
            6.0 * lcg(&mut seed) - 3.0,
            2.0 * lcg(&mut seed) - 1.0,
            6.0 * lcg(&mut seed) - 3.0,
        ];
        let brute = (0..m.triangles.len())
            .map(|t| {
                let [a, b, c] = m.corners(t);
                dist(p, closest_point_on_triangle(p, a, b, c))
            })
            .fold(f64::INFINITY, least);
        let fast = bvh.closest(p).map_or(f64::INFINITY, |c| c.1);
        worst = worst.worst((fast - brute).abs());
    }
    Check::new(
        "mesh",
        "-",
        "closest point",
        "mesh.bvh-equals-brute-force",
        Kind::Reference,
        worst,
        tol::ROUNDING,
    )
    .note("BVH nearest distance vs. brute force over 1152 triangles at 200 random points")
}

/// The closest point on a triangle is a minimiser: no point of a dense
/// barycentric sampling is closer.
fn triangle_distance_check() -> Check {
    let mut seed = 12345u64;
    let mut worst: f64 = 0.0;
    for _ in 0..50 {
        let mut r = || 2.0 * lcg(&mut seed) - 1.0;
        let (a, b, c) = ([r(), r(), r()], [r(), r(), r()], [r(), r(), r()]);
        let p = [2.0 * r(), 2.0 * r(), 2.0 * r()];
        let d = dist(p, closest_point_on_triangle(p, a, b, c));
        let n = 60;
        let mut best = f64::INFINITY;
        for i in 0..=n {
            for j in 0..=(n - i) {
                let (s, t) = (i as f64 / n as f64, j as f64 / n as f64);
                let q = [
                    a[0] + s * (b[0] - a[0]) + t * (c[0] - a[0]),
                    a[1] + s * (b[1] - a[1]) + t * (c[1] - a[1]),
                    a[2] + s * (b[2] - a[2]) + t * (c[2] - a[2]),
                ];
                best = best.least(dist(p, q));
            }
        }
        // the closed form may only be better than the sampling
        worst = worst.worst(d - best);
    }
    Check::new(
        "mesh",
        "-",
        "closest point",
        "mesh.point-triangle-minimiser",
        Kind::Reference,
        worst.worst(0.0),
        tol::ROUNDING,
    )
    .note("Ericson's closed form never exceeds the minimum over a 1891-point barycentric sampling")
}

/// Topology, area, volume and cross sections of a tessellated torus against
/// the exact torus (second-order convergence of the polyhedral values).
fn torus_checks() -> Vec<Check> {
    let (big, small) = (2.0, 0.5);
    let m = torus_mesh(48);
    let r = topology::report(&m);
    let topo_err = (!r.watertight) as u32 as f64
        + (!r.manifold) as u32 as f64
        + (!r.oriented) as u32 as f64
        + (r.euler != 0) as u32 as f64
        + (m.positions.len() != 96 * 48) as u32 as f64;
    let exact_area = 4.0 * PI * PI * big * small;
    let exact_volume = 2.0 * PI * PI * big * small * small;
    // inscribed polyhedra: relative errors O(h^2); ratio of two refinements
    let coarse = torus_mesh(24);
    let err = |m: &Mesh| {
        (
            (m.area() - exact_area).abs() / exact_area,
            (m.signed_volume().abs() - exact_volume).abs() / exact_volume,
        )
    };
    let (ea1, ev1) = err(&coarse);
    let (ea2, ev2) = err(&m);
    let order_area = (ea1 / ea2).log2();
    let order_volume = (ev1 / ev2).log2();
    // y = 0 cross section: two circles of radii big +- small
    let loops = slice::slice(&m, [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let lengths: Vec<f64> = loops.iter().map(|l| l.length()).collect();
    let slice_err = if loops.len() == 2 && loops.iter().all(|l| l.closed) {
        let (lo, hi) = (lengths[0].least(lengths[1]), lengths[0].worst(lengths[1]));
        ((lo - 2.0 * PI * (big - small)).abs() / lo)
            .worst((hi - 2.0 * PI * (big + small)).abs() / hi)
    } else {
        f64::INFINITY
    };
    vec![
        Check::new("mesh", "-", "topology", "mesh.torus-topology", Kind::Reference, topo_err, 0.0)
            .note("tessellated torus: watertight, manifold, oriented, Euler characteristic 0, no duplicate seam vertices"),
        Check::new(
            "mesh",
            "-",
            "area, volume",
            "mesh.torus-area-volume-order",
            Kind::Reference,
            (order_area - 2.0).abs().worst((order_volume - 2.0).abs()),
            0.05,
        )
        .note(format!(
            "observed convergence orders of area ({order_area:.3}) and volume ({order_volume:.3}) to the exact torus are 2"
        )),
        Check::new(
            "mesh",
            "-",
            "slicing",
            "mesh.torus-cross-section",
            Kind::Reference,
            slice_err,
            // a 96-gon inscribed in a circle is short by pi^2/(6 96^2) = 1.8e-4
            5.0e-4,
        )
        .note("the y = 0 slice is two closed loops of lengths 2 pi (R -+ r)"),
    ]
}

/// OBJ, STL and PLY round trips keep positions (to f32) and triangles.
fn round_trip_check() -> Check {
    let m = torus_mesh(12);
    let mut worst: f64 = 0.0;
    let compare = |a: &Mesh, b: &Mesh| -> f64 {
        if a.triangles.len() != b.triangles.len() {
            return f64::INFINITY;
        }
        // compare triangle corners (STL re-indexes vertices)
        (0..a.triangles.len())
            .map(|t| {
                let (x, y) = (a.corners(t), b.corners(t));
                (0..3).map(|k| dist(x[k], y[k])).max_nan()
            })
            .max_nan()
    };
    match parse_obj(&encode_obj(&m), "roundtrip.obj") {
        Ok(b) => worst = worst.worst(compare(&m, &b)),
        Err(_) => worst = f64::INFINITY,
    }
    match parse_stl(&encode_stl(&m), "roundtrip.stl") {
        Ok(b) => worst = worst.worst(compare(&m, &b)),
        Err(_) => worst = f64::INFINITY,
    }
    match parse_ply(&encode_ply(&m), "roundtrip.ply") {
        Ok(b) => worst = worst.worst(compare(&m, &b)),
        Err(_) => worst = f64::INFINITY,
    }
    Check::new(
        "mesh",
        "-",
        "file formats",
        "mesh.file-round-trips",
        Kind::Reference,
        worst,
        // coordinates are stored as f32 in every format
        tol::scaled(f32::EPSILON as f64, 4.0),
    )
    .note("OBJ, binary STL and binary PLY written and read back: same triangles, corners equal to f32 rounding")
}
