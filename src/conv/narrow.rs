//! Narrow-band sampling of a group's field (issue 16): only the grid cells
//! that can hold the surface $F = T$ are sampled.
//!
//! An octree over the grid's cells: for a box of cells, the field on the
//! ball around it is bounded by [`SegmentBvh::interval`]. When the bound
//! lies entirely above or entirely below $T$ (beyond the accepted
//! approximation error), no point of the box is on the surface: its nodes
//! that no other cell needs are filled with that bound (a value on the
//! proven side of $T$) and the box is done. Otherwise it is split in up to
//! eight; a box of at most [`LEAF_CELLS`] cells per side has all its nodes
//! evaluated (within `budget / 2`, see [`super::bvh`]). Every cell that
//! crosses $T$ therefore has exact corners, and every other cell has all
//! corners on one side of $T$, so both polygonisers see the same crossing
//! cells as with the field sampled everywhere. The work grows with the
//! surface area, not the volume.

use super::bvh::{Interaction, SegmentBvh};
use crate::mesh::isosurface::ScalarGrid;

/// Cells per side of an octree leaf (evaluated node by node).
pub const LEAF_CELLS: usize = 2;
/// Default accepted error of a node value, as a fraction of $T$: the
/// midpoint of the field's bound is within half of it.
pub const FIELD_TOLERANCE: f64 = 1e-4;

/// What [`sample`] did: node evaluations and boxes decided without them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct NarrowStats {
    pub nodes: usize,
    pub evaluated: usize,
    pub boxes_skipped: usize,
    pub boxes_tested: usize,
    /// Exact segment evaluations (the segments near a leaf times its
    /// nodes evaluated).
    pub segment_evaluations: usize,
    /// Cluster expansions evaluated (the clusters near a leaf times its
    /// nodes evaluated).
    pub cluster_evaluations: usize,
}

struct Band<'a> {
    bvh: &'a SegmentBvh,
    threshold: f64,
    budget: f64,
    origin: [f64; 3],
    spacing: [f64; 3],
    dims: [usize; 3],
    values: Vec<f64>,
    exact: Vec<bool>,
    stats: NarrowStats,
    near: Interaction,
}

impl Band<'_> {
    fn at(&self, i: usize, j: usize, k: usize) -> [f64; 3] {
        [
            self.origin[0] + i as f64 * self.spacing[0],
            self.origin[1] + j as f64 * self.spacing[1],
            self.origin[2] + k as f64 * self.spacing[2],
        ]
    }

    fn index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.dims[0] * (j + self.dims[1] * k)
    }

    /// Cells `lo..hi` (per axis), nodes `lo..=hi`.
    fn visit(&mut self, lo: [usize; 3], hi: [usize; 3]) {
        let n = [0, 1, 2].map(|k| hi[k] - lo[k]);
        let a = self.at(lo[0], lo[1], lo[2]);
        let b = self.at(hi[0], hi[1], hi[2]);
        let centre = [0, 1, 2].map(|k| 0.5 * (a[k] + b[k]));
        let rho = 0.5 * crate::mesh::norm(crate::mesh::sub(b, a));
        if n.iter().all(|&c| c <= LEAF_CELLS) {
            let mut near = std::mem::take(&mut self.near);
            let (flo, fhi) = self.bvh.near_list(centre, rho, self.budget, &mut near);
            let far = 0.5 * (flo + fhi);
            for k in lo[2]..=hi[2] {
                for j in lo[1]..=hi[1] {
                    for i in lo[0]..=hi[0] {
                        let id = self.index(i, j, k);
                        if !self.exact[id] {
                            self.values[id] = far + self.bvh.near_field(&near, self.at(i, j, k));
                            self.exact[id] = true;
                            self.stats.evaluated += 1;
                            self.stats.segment_evaluations += near.segments.len();
                            self.stats.cluster_evaluations += near.clusters.len();
                        }
                    }
                }
            }
            self.near = near;
            return;
        }
        let (flo, fhi) = self.bvh.interval(centre, rho, self.budget);
        self.stats.boxes_tested += 1;
        let fill = if flo > self.threshold {
            Some(flo)
        } else if fhi < self.threshold {
            Some(fhi)
        } else {
            None
        };
        if let Some(v) = fill {
            self.stats.boxes_skipped += 1;
            for k in lo[2]..=hi[2] {
                for j in lo[1]..=hi[1] {
                    let row = self.index(0, j, k);
                    for id in row + lo[0]..=row + hi[0] {
                        if !self.exact[id] && self.values[id].is_nan() {
                            self.values[id] = v;
                        }
                    }
                }
            }
            return;
        }
        let mid = [0, 1, 2].map(|k| lo[k] + n[k] / 2);
        for cz in 0..2 {
            for cy in 0..2 {
                for cx in 0..2 {
                    let c = [cx, cy, cz];
                    let mut l = [0; 3];
                    let mut h = [0; 3];
                    let mut empty = false;
                    for k in 0..3 {
                        if n[k] <= 1 {
                            // not split along this axis: only the first child
                            empty |= c[k] == 1;
                            l[k] = lo[k];
                            h[k] = hi[k];
                        } else if c[k] == 0 {
                            l[k] = lo[k];
                            h[k] = mid[k];
                        } else {
                            l[k] = mid[k];
                            h[k] = hi[k];
                        }
                    }
                    if !empty {
                        self.visit(l, h);
                    }
                }
            }
        }
    }
}

/// Samples the field of `bvh` on the grid `origin + (i, j, k) * spacing`,
/// `dims` nodes, exactly (within `budget / 2`) at the corners of every cell
/// the surface $F = T$ may cross; every other node gets a value on its
/// proven side of $T$.
pub fn sample(
    bvh: &SegmentBvh,
    threshold: f64,
    budget: f64,
    origin: [f64; 3],
    spacing: [f64; 3],
    dims: [usize; 3],
) -> (ScalarGrid, NarrowStats) {
    let total = dims[0] * dims[1] * dims[2];
    let mut band = Band {
        bvh,
        threshold,
        budget,
        origin,
        spacing,
        dims,
        values: vec![f64::NAN; total],
        exact: vec![false; total],
        stats: NarrowStats {
            nodes: total,
            ..Default::default()
        },
        near: Interaction::default(),
    };
    band.visit([0; 3], [dims[0] - 1, dims[1] - 1, dims[2] - 1]);
    let stats = band.stats;
    (
        ScalarGrid {
            origin,
            spacing,
            dims,
            values: band.values,
        },
        stats,
    )
}
