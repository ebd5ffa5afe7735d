//! The grid side of the narrow band ([`super::narrow`]): the grid, the
//! events the walkers record, their merge in traversal order and the
//! evaluation, once each, of the nodes deferred by the tasks (module doc
//! of [`super::narrow`], "Threads").

use super::bvh::{Interaction, SegmentBvh};
use crate::mesh::isosurface::ScalarGrid;

/// What [`super::narrow::sample`] did: node evaluations and boxes decided without them.
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
    /// Of `evaluated`: nodes on faces between tasks, evaluated after the
    /// merge (once each).
    pub shared_evaluated: usize,
    /// Nodes within the margin of $T$ given the reference's value after
    /// sampling (`BuiltModel::sample_group_fast`; 0 from [`super::narrow::sample`]).
    pub reference_nodes: usize,
    /// Nodes holding an evaluated value in the grid (counted in the grid,
    /// not by the walkers): equals `evaluated` when no node is evaluated
    /// twice.
    pub exact_nodes: usize,
}

impl NarrowStats {
    pub(super) fn add(&mut self, o: &NarrowStats) {
        self.evaluated += o.evaluated;
        self.boxes_skipped += o.boxes_skipped;
        self.boxes_tested += o.boxes_tested;
        self.segment_evaluations += o.segment_evaluations;
        self.cluster_evaluations += o.cluster_evaluations;
    }
}

/// Position of node `id` (x fastest, then y, then z) of the grid
/// `origin + (i, j, k) * spacing` with `dims` nodes: the arithmetic of
/// `ScalarGrid::sample`, so a value computed here is the reference's.
pub fn node_position(origin: [f64; 3], spacing: [f64; 3], dims: [usize; 3], id: usize) -> [f64; 3] {
    let ijk = [
        id % dims[0],
        (id / dims[0]) % dims[1],
        id / (dims[0] * dims[1]),
    ];
    [0, 1, 2].map(|a| origin[a] + ijk[a] as f64 * spacing[a])
}

/// A write of the sequential traversal (applied in order by [`merge`]).
#[derive(Clone, Copy, Debug)]
pub(super) enum Event {
    /// Every node of the box `lo..=hi` without a value gets `value`.
    Fill {
        lo: [u32; 3],
        hi: [u32; 3],
        value: f64,
    },
    /// Node `id` gets `value` unless it already has an exact one.
    Exact { id: usize, value: f64 },
    /// Node `id`, unless it already has an exact value, is evaluated after
    /// the merge with the walker's leaf context `leaf`.
    Deferred { id: usize, leaf: u32 },
    /// The events of task `index`.
    Task { index: usize },
}

pub(super) struct Grid<'a> {
    pub(super) bvh: &'a SegmentBvh,
    pub(super) threshold: f64,
    pub(super) budget: f64,
    pub(super) origin: [f64; 3],
    pub(super) spacing: [f64; 3],
    pub(super) dims: [usize; 3],
}

impl Grid<'_> {
    pub(super) fn at(&self, i: usize, j: usize, k: usize) -> [f64; 3] {
        [
            self.origin[0] + i as f64 * self.spacing[0],
            self.origin[1] + j as f64 * self.spacing[1],
            self.origin[2] + k as f64 * self.spacing[2],
        ]
    }

    pub(super) fn index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.dims[0] * (j + self.dims[1] * k)
    }
}

/// What a leaf's nodes are evaluated with: the midpoint of the bounds of
/// the clusters accepted for the whole leaf and the near interaction list.
#[derive(Clone, Debug, Default)]
pub(super) struct LeafContext {
    pub(super) far: f64,
    pub(super) near: Interaction,
}

/// The events and leaf contexts of one walker.
pub(super) struct Record<'r> {
    pub(super) events: &'r [Event],
    pub(super) leaves: &'r [LeafContext],
}

/// Applies `walker`'s events in order (tasks' events in place of their
/// markers); a deferred node that gets no earlier exact value is marked
/// exact and queued in `pending` with its leaf context.
fn merge<'r>(
    grid: &Grid,
    walker: &Record<'r>,
    tasks: &[Record<'r>],
    values: &mut [f64],
    exact: &mut [bool],
    pending: &mut Vec<(usize, &'r LeafContext)>,
) {
    for e in walker.events {
        match *e {
            Event::Fill { lo, hi, value } => {
                for k in lo[2] as usize..=hi[2] as usize {
                    for j in lo[1] as usize..=hi[1] as usize {
                        let row = grid.index(0, j, k);
                        for id in row + lo[0] as usize..=row + hi[0] as usize {
                            if !exact[id] && values[id].is_nan() {
                                values[id] = value;
                            }
                        }
                    }
                }
            }
            Event::Exact { id, value } => {
                if !exact[id] {
                    values[id] = value;
                    exact[id] = true;
                }
            }
            Event::Deferred { id, leaf } => {
                if !exact[id] {
                    exact[id] = true;
                    pending.push((id, &walker.leaves[leaf as usize]));
                }
            }
            Event::Task { index } => merge(grid, &tasks[index], &[], values, exact, pending),
        }
    }
}

/// Evaluates the `pending` nodes (once each) on up to `threads` threads
/// and stores them; returns the segment and cluster evaluations.
fn evaluate_pending(
    grid: &Grid,
    pending: &[(usize, &LeafContext)],
    values: &mut [f64],
    threads: usize,
) -> (usize, usize) {
    let node = |id: usize, c: &LeafContext| {
        let x = node_position(grid.origin, grid.spacing, grid.dims, id);
        c.far + grid.bvh.near_field(&c.near, x)
    };
    let mut out = vec![0.0; pending.len()];
    let per = pending.len().div_ceil(threads.max(1)).max(1);
    if threads <= 1 || pending.len() < 2 {
        for (o, &(id, c)) in out.iter_mut().zip(pending) {
            *o = node(id, c);
        }
    } else {
        std::thread::scope(|s| {
            for (chunk, part) in out.chunks_mut(per).zip(pending.chunks(per)) {
                s.spawn(move || {
                    for (o, &(id, c)) in chunk.iter_mut().zip(part) {
                        *o = node(id, c);
                    }
                });
            }
        });
    }
    let (mut segs, mut clusters) = (0, 0);
    for (&(id, c), v) in pending.iter().zip(out) {
        values[id] = v;
        segs += c.near.segments.len();
        clusters += c.near.clusters.len();
    }
    (segs, clusters)
}

/// Merges the walkers' records into the grid and evaluates the deferred
/// nodes.
pub(super) fn finish(
    grid: &Grid,
    top: &Record,
    tasks: &[Record],
    mut stats: NarrowStats,
    threads: usize,
) -> (ScalarGrid, NarrowStats) {
    let total = grid.dims[0] * grid.dims[1] * grid.dims[2];
    let mut values = vec![f64::NAN; total];
    let mut exact = vec![false; total];
    let mut pending = Vec::new();
    merge(grid, top, tasks, &mut values, &mut exact, &mut pending);
    let (segs, clusters) = evaluate_pending(grid, &pending, &mut values, threads);
    stats.nodes = total;
    stats.evaluated += pending.len();
    stats.shared_evaluated = pending.len();
    stats.segment_evaluations += segs;
    stats.cluster_evaluations += clusters;
    stats.exact_nodes = exact.iter().filter(|&&e| e).count();
    (
        ScalarGrid {
            origin: grid.origin,
            spacing: grid.spacing,
            dims: grid.dims,
            values,
        },
        stats,
    )
}
