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
//!
//! Each box starts from its parent's [`Frontier`] (clusters accepted for
//! the parent stay accepted, see [`super::bvh`]), so a box tests only what
//! its parent left open.
//!
//! **Threads, deterministically, each node once.** The octree is refined
//! in order down to depth [`TASK_DEPTH`]; every box there that needs
//! refining becomes a task, and the tasks run on up to [`MAX_THREADS`]
//! threads (`std::thread::scope`). A box records what it writes as events
//! (fill a box of nodes, set a node exactly) instead of writing the grid;
//! the events are then applied in the order of the sequential traversal,
//! with its rules (the first leaf of the traversal to reach a node gives
//! its value, a fill only reaches a node that has no value yet).
//!
//! A node inside a task's box belongs to that task alone and is evaluated
//! there. A node on a face of a task's box inside the grid may also be
//! reached by the neighbouring task, so the task does not evaluate it: it
//! records a *deferred* event naming the node and its leaf's interaction
//! list (`narrow_merge::LeafContext`). The merge keeps, for every node, the first
//! event in traversal order, exact or deferred, and the deferred nodes it
//! keeps are then evaluated once each (in parallel) with their first
//! leaf's list: the same arithmetic as [`sample_sequential`], the single
//! traversal that evaluates every node where it first reaches it. The grid
//! is therefore the same bit for bit for any number of threads and equal
//! to the sequential one, and every band node is evaluated exactly once
//! ([`NarrowStats::evaluated`] equals [`NarrowStats::exact_nodes`]; test
//! `narrow_band_is_identical_for_any_thread_count`).

use super::bvh::{Interaction, SegmentBvh};
use super::frontier::Frontier;
pub use super::narrow_merge::NarrowStats;
use super::narrow_merge::{finish, Event, Grid, LeafContext, Record};
use crate::mesh::isosurface::ScalarGrid;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Cells per side of an octree leaf (evaluated node by node).
pub const LEAF_CELLS: usize = 2;
/// Default accepted error of a node value, as a fraction of $T$: the
/// midpoint of the field's bound is within half of it.
pub const FIELD_TOLERANCE: f64 = 1e-4;
/// Octree depth whose boxes are the parallel tasks (at most $8^2$ tasks).
pub const TASK_DEPTH: usize = 2;
/// Most threads [`sample`] uses.
pub const MAX_THREADS: usize = 8;

/// A box left to a task: cells `lo..hi`, its depth and its frontier.
struct Task {
    lo: [usize; 3],
    hi: [usize; 3],
    depth: usize,
    frontier: Frontier,
}

/// One traversal (the top levels, or one task) and its scratch.
struct Walker<'a, 'g> {
    grid: &'a Grid<'g>,
    /// Emit a task instead of refining a box at this depth (top levels).
    split_at: Option<usize>,
    tasks: Vec<Task>,
    events: Vec<Event>,
    /// Contexts of the leaves with deferred nodes.
    leaves: Vec<LeafContext>,
    stats: NarrowStats,
    /// Per axis, whether the low / high face of `seen_lo..` is shared with
    /// other walkers (its nodes are deferred).
    shared_lo: [bool; 3],
    shared_hi: [bool; 3],
    /// Nodes of the box `seen_lo..` this walker has already evaluated.
    seen: Vec<bool>,
    seen_lo: [usize; 3],
    seen_dims: [usize; 3],
    /// Frontiers by depth (reused).
    pool: Vec<Frontier>,
    stack: Vec<usize>,
    near: Interaction,
}

impl<'a, 'g> Walker<'a, 'g> {
    /// A walker over the nodes `lo..=hi`; with `share`, the nodes on the
    /// faces of that box inside the grid are deferred (a task), and with
    /// `split_at` every node is (the top levels, whose leaves may touch any
    /// task).
    fn new(
        grid: &'a Grid<'g>,
        lo: [usize; 3],
        hi: [usize; 3],
        split_at: Option<usize>,
        share: bool,
    ) -> Self {
        let seen_dims = [0, 1, 2].map(|k| hi[k] - lo[k] + 1);
        Walker {
            grid,
            split_at,
            tasks: Vec::new(),
            events: Vec::new(),
            leaves: Vec::new(),
            stats: NarrowStats::default(),
            shared_lo: [0, 1, 2].map(|k| share && lo[k] > 0),
            shared_hi: [0, 1, 2].map(|k| share && hi[k] + 1 < grid.dims[k]),
            seen: vec![false; seen_dims[0] * seen_dims[1] * seen_dims[2]],
            seen_lo: lo,
            seen_dims,
            pool: Vec::new(),
            stack: Vec::new(),
            near: Interaction::default(),
        }
    }

    /// Visits the children of the box `lo..hi` (at `depth`) in order.
    fn children(&mut self, lo: [usize; 3], hi: [usize; 3], depth: usize, from: &Frontier) {
        let n = [0, 1, 2].map(|k| hi[k] - lo[k]);
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
                        self.visit(l, h, depth + 1, from);
                    }
                }
            }
        }
    }

    /// Cells `lo..hi` (per axis), nodes `lo..=hi`, at octree `depth`,
    /// inside the box whose frontier is `from`.
    fn visit(&mut self, lo: [usize; 3], hi: [usize; 3], depth: usize, from: &Frontier) {
        let g = self.grid;
        let n = [0, 1, 2].map(|k| hi[k] - lo[k]);
        let a = g.at(lo[0], lo[1], lo[2]);
        let b = g.at(hi[0], hi[1], hi[2]);
        let centre = [0, 1, 2].map(|k| 0.5 * (a[k] + b[k]));
        let rho = 0.5 * crate::mesh::norm(crate::mesh::sub(b, a));
        if n.iter().all(|&c| c <= LEAF_CELLS) {
            self.leaf(lo, hi, centre, rho, from);
            return;
        }
        let mut to = self.pool.pop().unwrap_or_default();
        let (flo, fhi) = g
            .bvh
            .refine(from, centre, rho, g.budget, &mut to, &mut self.stack);
        self.stats.boxes_tested += 1;
        let fill = if flo > g.threshold {
            Some(flo)
        } else if fhi < g.threshold {
            Some(fhi)
        } else {
            None
        };
        if let Some(value) = fill {
            self.stats.boxes_skipped += 1;
            self.events.push(Event::Fill {
                lo: lo.map(|v| v as u32),
                hi: hi.map(|v| v as u32),
                value,
            });
        } else if self.split_at == Some(depth) {
            self.events.push(Event::Task {
                index: self.tasks.len(),
            });
            self.tasks.push(Task {
                lo,
                hi,
                depth,
                frontier: to.clone(),
            });
        } else {
            self.children(lo, hi, depth, &to);
        }
        self.pool.push(to);
    }

    fn leaf(
        &mut self,
        lo: [usize; 3],
        hi: [usize; 3],
        centre: [f64; 3],
        rho: f64,
        from: &Frontier,
    ) {
        let g = self.grid;
        let mut near = std::mem::take(&mut self.near);
        let (flo, fhi) =
            g.bvh
                .near_list_from(from, centre, rho, g.budget, &mut near, &mut self.stack);
        let far = 0.5 * (flo + fhi);
        let mut deferred = false;
        for k in lo[2]..=hi[2] {
            for j in lo[1]..=hi[1] {
                for i in lo[0]..=hi[0] {
                    let s = [i, j, k];
                    let local = (s[0] - self.seen_lo[0])
                        + self.seen_dims[0]
                            * ((s[1] - self.seen_lo[1])
                                + self.seen_dims[1] * (s[2] - self.seen_lo[2]));
                    if self.seen[local] {
                        continue;
                    }
                    self.seen[local] = true;
                    let id = g.index(i, j, k);
                    let shared = self.split_at.is_some()
                        || (0..3).any(|a| {
                            (self.shared_lo[a] && s[a] == self.seen_lo[a])
                                || (self.shared_hi[a]
                                    && s[a] + 1 == self.seen_lo[a] + self.seen_dims[a])
                        });
                    if shared {
                        deferred = true;
                        let leaf = self.leaves.len() as u32;
                        self.events.push(Event::Deferred { id, leaf });
                        continue;
                    }
                    let value = far + g.bvh.near_field(&near, g.at(i, j, k));
                    self.events.push(Event::Exact { id, value });
                    self.stats.evaluated += 1;
                    self.stats.segment_evaluations += near.segments.len();
                    self.stats.cluster_evaluations += near.clusters.len();
                }
            }
        }
        if deferred {
            self.leaves.push(LeafContext {
                far,
                near: near.clone(),
            });
        }
        self.near = near;
    }
}

/// Samples the field of `bvh` on the grid `origin + (i, j, k) * spacing`,
/// `dims` nodes, exactly (within `budget / 2`) at the corners of every cell
/// the surface $F = T$ may cross; every other node gets a value on its
/// proven side of $T$. Uses the available cores (at most [`MAX_THREADS`]);
/// the result does not depend on their number.
pub fn sample(
    bvh: &SegmentBvh,
    threshold: f64,
    budget: f64,
    origin: [f64; 3],
    spacing: [f64; 3],
    dims: [usize; 3],
) -> (ScalarGrid, NarrowStats) {
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(MAX_THREADS);
    sample_with_threads(bvh, threshold, budget, origin, spacing, dims, threads)
}

/// [`sample`] on `threads` threads (at least one).
pub fn sample_with_threads(
    bvh: &SegmentBvh,
    threshold: f64,
    budget: f64,
    origin: [f64; 3],
    spacing: [f64; 3],
    dims: [usize; 3],
    threads: usize,
) -> (ScalarGrid, NarrowStats) {
    let grid = Grid {
        bvh,
        threshold,
        budget,
        origin,
        spacing,
        dims,
    };
    let top_hi = [dims[0] - 1, dims[1] - 1, dims[2] - 1];
    let mut top = Walker::new(&grid, [0; 3], top_hi, Some(TASK_DEPTH), false);
    top.visit([0; 3], top_hi, 0, &bvh.root_frontier());
    let tasks = std::mem::take(&mut top.tasks);
    let next = AtomicUsize::new(0);
    let run = || {
        let mut done: Vec<Done> = Vec::new();
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(t) = tasks.get(i) else { break };
            let mut w = Walker::new(&grid, t.lo, t.hi, None, true);
            w.children(t.lo, t.hi, t.depth, &t.frontier);
            done.push((i, w.events, w.leaves, w.stats));
        }
        done
    };
    let threads = threads.max(1);
    let task_threads = threads.min(tasks.len().max(1));
    let mut results: Vec<Done> = if task_threads == 1 {
        run()
    } else {
        std::thread::scope(|s| {
            let handles: Vec<_> = (0..task_threads).map(|_| s.spawn(run)).collect();
            handles
                .into_iter()
                .flat_map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
                .collect()
        })
    };
    results.sort_by_key(|r| r.0);
    let mut stats = top.stats;
    let records: Vec<Record> = results
        .iter()
        .map(|(_, events, leaves, st)| {
            stats.add(st);
            Record { events, leaves }
        })
        .collect();
    let top_record = Record {
        events: &top.events,
        leaves: &top.leaves,
    };
    finish(&grid, &top_record, &records, stats, threads)
}

/// A finished task: its index, events, leaf contexts and counts.
type Done = (usize, Vec<Event>, Vec<LeafContext>, NarrowStats);

/// The reference traversal for [`sample_with_threads`]: one walker over
/// the whole octree, no tasks, every node evaluated where the traversal
/// first reaches it. Same grid, bit for bit.
pub fn sample_sequential(
    bvh: &SegmentBvh,
    threshold: f64,
    budget: f64,
    origin: [f64; 3],
    spacing: [f64; 3],
    dims: [usize; 3],
) -> (ScalarGrid, NarrowStats) {
    let grid = Grid {
        bvh,
        threshold,
        budget,
        origin,
        spacing,
        dims,
    };
    let top_hi = [dims[0] - 1, dims[1] - 1, dims[2] - 1];
    let mut w = Walker::new(&grid, [0; 3], top_hi, None, false);
    w.visit([0; 3], top_hi, 0, &bvh.root_frontier());
    let record = Record {
        events: &w.events,
        leaves: &w.leaves,
    };
    finish(&grid, &record, &[], w.stats, 1)
}
