//! Named test meshes of the mesh infrastructure (a torus and a reproducible
//! random source), shared by checks, tests and benches. Built here without
//! the `surface` layer above (`surface::samples::Torus` is the same torus as
//! a parametric surface; a test holds the two equal).

use super::Mesh;
use std::f64::consts::PI;

/// Deterministic pseudo-random numbers in [0, 1) (xorshift), so checks are
/// reproducible without a dependency.
pub fn lcg(seed: &mut u64) -> f64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// Major and minor radius of [`torus_mesh`].
pub const TORUS_RADII: (f64, f64) = (2.0, 0.5);

/// The torus about the y axis (radii [`TORUS_RADII`]) sampled on a closed
/// 2n x n parameter grid (`u` around the axis, `v` around the tube).
pub fn torus_mesh(n: usize) -> Mesh {
    let (big, small) = TORUS_RADII;
    let (nu, nv) = (2 * n.max(1), n.max(1));
    let mut pts = Vec::with_capacity(nu * nv);
    for iu in 0..nu {
        let a = (iu as f64 / nu as f64) * (2.0 * PI);
        for iv in 0..nv {
            let b = (iv as f64 / nv as f64) * (2.0 * PI);
            let r = b.cos() * small + big;
            pts.push([r * a.cos(), b.sin() * small, -(r * a.sin())]);
        }
    }
    Mesh::grid(pts, nu, nv, [true, true])
}
