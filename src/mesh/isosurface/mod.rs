//! Polygonisation of implicit surfaces $\{x : f(x) = c\}$ sampled on a
//! regular grid (the paper 003 surfaces, Bloomenthal's polygoniser [4]).
//!
//! * [`marching_tetrahedra`]: every cube is split into the six Kuhn
//!   tetrahedra around its main diagonal (the same split in every cube, so
//!   faces match), the level set of the piecewise-linear interpolant is
//!   extracted per tetrahedron with vertices shared on grid edges. The
//!   result is the exact level set of a PL function on a simplicial complex:
//!   watertight and manifold. Orientation is combinatorial (from the
//!   tetrahedron's orientation and which vertices are inside), so it stays
//!   consistent even where triangles degenerate.
//! * [`surface_nets`]: naive surface nets, one vertex per sign-changing
//!   cube (mean of its edge crossings), one quad per sign-changing grid edge.
//!   Watertight and oriented; manifold except at ambiguous cube
//!   configurations (two sheets through one cube), which
//!   [`crate::mesh::topology::report`] counts.
//!
//! Inside is $f > c$ (convolution surfaces: field above threshold). Grid
//! nodes on the grid's boundary are treated as outside, so the output is
//! always closed.

use super::{Mesh, MeshError};

/// Largest number of grid nodes accepted.
pub const MAX_NODES: usize = 200_000_000;

/// A scalar field sampled on a regular grid.
#[derive(Clone, Debug)]
pub struct ScalarGrid {
    pub origin: [f64; 3],
    pub spacing: [f64; 3],
    pub dims: [usize; 3],
    /// x fastest, then y, then z.
    pub values: Vec<f64>,
}

impl ScalarGrid {
    /// Samples `f` on `dims` nodes spanning the box `lo`..`hi` (uses the
    /// available cores).
    pub fn sample<F: Fn([f64; 3]) -> f64 + Sync>(
        lo: [f64; 3],
        hi: [f64; 3],
        dims: [usize; 3],
        f: F,
    ) -> Result<ScalarGrid, MeshError> {
        if dims.iter().any(|&d| d < 3) {
            return Err(MeshError::Invalid(format!(
                "grid dimensions {dims:?}: at least 3 nodes per axis"
            )));
        }
        let total = dims[0].saturating_mul(dims[1]).saturating_mul(dims[2]);
        if total > MAX_NODES {
            return Err(MeshError::Invalid(format!(
                "grid of {total} nodes exceeds {MAX_NODES}"
            )));
        }
        if (0..3).any(|k| !(lo[k].is_finite() && hi[k].is_finite() && hi[k] > lo[k])) {
            return Err(MeshError::Invalid(format!("bad grid box {lo:?}..{hi:?}")));
        }
        let spacing = [
            (hi[0] - lo[0]) / (dims[0] - 1) as f64,
            (hi[1] - lo[1]) / (dims[1] - 1) as f64,
            (hi[2] - lo[2]) / (dims[2] - 1) as f64,
        ];
        let mut values = vec![0.0; total];
        let slab = dims[0] * dims[1];
        let threads = std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
            .min(dims[2]);
        let per = dims[2].div_ceil(threads);
        std::thread::scope(|scope| {
            for (c, chunk) in values.chunks_mut(per * slab).enumerate() {
                let f = &f;
                scope.spawn(move || {
                    for (n, v) in chunk.iter_mut().enumerate() {
                        let idx = c * per * slab + n;
                        let (i, j, k) = (idx % dims[0], (idx / dims[0]) % dims[1], idx / slab);
                        *v = f([
                            lo[0] + i as f64 * spacing[0],
                            lo[1] + j as f64 * spacing[1],
                            lo[2] + k as f64 * spacing[2],
                        ]);
                    }
                });
            }
        });
        if let Some(i) = values.iter().position(|v| !v.is_finite()) {
            return Err(MeshError::Invalid(format!(
                "field is not finite at grid node {i}"
            )));
        }
        Ok(ScalarGrid {
            origin: lo,
            spacing,
            dims,
            values,
        })
    }

    /// Linear index of node `(i, j, k)`.
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.dims[0] * (j + self.dims[1] * k)
    }
}

pub(super) fn sq(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).powi(2)).sum()
}

/// Splits the quad `q` (cyclic, oriented) along its shorter diagonal.
pub(super) fn push_quad(tris: &mut Vec<[u32; 3]>, pos: &[[f64; 3]], q: [u32; 4]) {
    let p = |i: usize| pos[q[i] as usize];
    if sq(p(0), p(2)) <= sq(p(1), p(3)) {
        tris.push([q[0], q[1], q[2]]);
        tris.push([q[0], q[2], q[3]]);
    } else {
        tris.push([q[0], q[1], q[3]]);
        tris.push([q[1], q[2], q[3]]);
    }
}

mod polygonize;
mod quality;
mod scan;

pub use polygonize::{marching_tetrahedra, surface_nets};
pub use quality::{smallest_angles_deg, triangle_quality, TriangleQuality};

#[cfg(test)]
mod reference;
#[cfg(test)]
mod tests;
