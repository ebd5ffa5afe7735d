//! Checks of the surface infrastructure: jet derivatives of a surface
//! against finite differences, and seam sharing in tessellation.

use super::{tessellate, Revolution, Surface, Tessellation};
use crate::check::{Check, Kind};
use crate::mesh::topology;

/// Step and tolerance of the central-difference comparison: the truncation
/// error is O(h^2) times the third derivative (here below 1e3).
const FD_STEP: f64 = 1e-4;
const FD_TOL: f64 = 1e-5;

/// All checks of the surface family.
pub fn checks() -> Vec<Check> {
    let s = Revolution { r0: 1.0, r1: 0.3 };
    let mut worst: f64 = 0.0;
    for &(u, v) in &[(0.2, 0.1), (0.5, 0.7), (0.9, 0.35)] {
        for (i, j) in [(1, 0), (0, 1), (2, 0), (1, 1), (0, 2)] {
            let d = s.derivative(u, v, i, j);
            let fd = central(&s, u, v, i, j);
            for k in 0..3 {
                worst = worst.max((d[k] - fd[k]).abs() / d[k].abs().max(1.0));
            }
        }
    }
    let m = tessellate(&s, Tessellation { nu: 10, nv: 16 });
    let r = topology::report(&m);
    // open in u (two boundary loops of 16 edges), closed in v: 11 x 16 vertices
    let seam_err = (m.positions.len() as f64 - 176.0).abs()
        + (r.boundary_edges as f64 - 32.0).abs()
        + (!r.oriented) as u32 as f64
        + (r.nonmanifold_edges as f64);
    vec![
        Check::new(
            "surface",
            "-",
            "derivatives",
            "surface.jet-vs-finite-differences",
            Kind::Reference,
            worst,
            FD_TOL,
        )
        .note("S_u, S_v, S_uu, S_uv, S_vv of a surface of revolution: jets vs central differences (h = 1e-4)"),
        Check::new(
            "surface",
            "-",
            "tessellation",
            "surface.closed-seam-shared",
            Kind::Reference,
            seam_err,
            0.0,
        )
        .note("a tube closed in v tessellates with shared seam vertices: 11x16 vertices, only the two end loops are boundary"),
    ]
}

fn central<S: Surface>(s: &S, u: f64, v: f64, i: usize, j: usize) -> [f64; 3] {
    let h = FD_STEP;
    let f = |du: f64, dv: f64| s.point(u + du, v + dv);
    let comb = |terms: &[(f64, f64, f64)], div: f64| {
        let mut out = [0.0; 3];
        for &(du, dv, w) in terms {
            let p = f(du, dv);
            for k in 0..3 {
                out[k] += w * p[k] / div;
            }
        }
        out
    };
    match (i, j) {
        (1, 0) => comb(&[(h, 0.0, 1.0), (-h, 0.0, -1.0)], 2.0 * h),
        (0, 1) => comb(&[(0.0, h, 1.0), (0.0, -h, -1.0)], 2.0 * h),
        (2, 0) => comb(&[(h, 0.0, 1.0), (0.0, 0.0, -2.0), (-h, 0.0, 1.0)], h * h),
        (0, 2) => comb(&[(0.0, h, 1.0), (0.0, 0.0, -2.0), (0.0, -h, 1.0)], h * h),
        _ => comb(
            &[(h, h, 1.0), (h, -h, -1.0), (-h, h, -1.0), (-h, -h, 1.0)],
            4.0 * h * h,
        ),
    }
}
