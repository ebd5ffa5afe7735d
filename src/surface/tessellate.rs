//! Grid tessellation of any surface into a triangle mesh.

use super::{Domain, DynSurface};
use crate::mesh::Mesh;

/// Sampling density of a tessellation.
#[derive(Clone, Copy, Debug)]
pub struct Tessellation {
    /// Number of intervals in u (>= 1).
    pub nu: usize,
    /// Number of intervals in v (>= 1; >= 3 on a closed direction).
    pub nv: usize,
}

/// Parameter samples along one direction: `n + 1` values on an open
/// direction, `n` distinct values (the last one is the first) on a closed one.
fn samples(range: (f64, f64), n: usize, closed: bool) -> Vec<f64> {
    let count = if closed { n } else { n + 1 };
    (0..count)
        .map(|k| range.0 + (range.1 - range.0) * k as f64 / n as f64)
        .collect()
}

/// Tessellates `s` on a regular parameter grid: two triangles per cell,
/// oriented so that the triangle normal follows `S_u x S_v`. Closed
/// directions share their seam vertices.
pub fn tessellate<S: DynSurface + ?Sized>(s: &S, t: Tessellation) -> Mesh {
    let d = s.domain();
    let us = samples(d.u, t.nu.max(1), d.closed_u);
    let vs = samples(d.v, t.nv.max(1), d.closed_v);
    let pts = s.grid(&us, &vs);
    tessellate_grid(pts, us.len(), vs.len(), d)
}

/// Triangulates a row-major grid of points (`nu_pts x nv_pts`, index
/// `iu * nv_pts + iv`) with the closedness of `d`.
pub fn tessellate_grid(pts: Vec<[f64; 3]>, nu_pts: usize, nv_pts: usize, d: Domain) -> Mesh {
    Mesh::grid(pts, nu_pts, nv_pts, [d.closed_u, d.closed_v])
}
