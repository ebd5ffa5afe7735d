//! Frontiers of the segment hierarchy for nested boxes (issue 16; the
//! module doc of [`super::bvh`], "Frontiers"): a box starts from its
//! parent's frontier, inherits the clusters accepted there and tests only
//! the nodes left open.

use super::bvh::{kernel, point_segment_distance, slope_bound, Interaction, Node, SegmentBvh};
use crate::mesh::{norm, sub};

/// What [`SegmentBvh::refine`] leaves for the boxes inside a box: summed
/// bounds of the clusters accepted there and the nodes still open.
#[derive(Clone, Debug, Default)]
pub struct Frontier {
    pub lo: f64,
    pub hi: f64,
    pub open: Vec<usize>,
}

impl SegmentBvh {
    /// The frontier of the whole domain: nothing accepted, the root open.
    pub fn root_frontier(&self) -> Frontier {
        Frontier {
            lo: 0.0,
            hi: 0.0,
            open: if self.nodes.is_empty() {
                vec![]
            } else {
                vec![0]
            },
        }
    }

    /// The cluster bound of `node` on the ball `(x, rho)`: (distance from
    /// `x` to its centre, lo, hi, its share of the budget).
    #[inline]
    pub(super) fn bound(
        &self,
        node: &Node,
        x: [f64; 3],
        rho: f64,
        per_mass: f64,
    ) -> (f64, f64, f64, f64) {
        let dc = norm(sub(x, node.centre));
        let dmin = (dc - node.radius - rho).max(0.0);
        let dmax = dc + node.radius + rho;
        let (kn, kf) = (kernel(dmin, node.s_min), kernel(dmax, node.s_max));
        let l = node.pos * kf - node.neg * kn;
        let h = node.pos * kn - node.neg * kf;
        (dc, l, h, per_mass * (node.pos + node.neg))
    }

    pub(super) fn per_mass(&self, budget: f64) -> f64 {
        if self.total_mass > 0.0 {
            budget / self.total_mass
        } else {
            0.0
        }
    }

    /// Whether `node` (of one kernel width) is evaluated by its expansion
    /// everywhere at least `dmin` from its ball: its error there is at
    /// most half its `share`.
    #[inline]
    pub(super) fn lumpable(node: &Node, dmin: f64, share: f64) -> bool {
        node.s_min == node.s_max && 2.0 * node.moments.error_bound(node.s_min, dmin) <= share
    }

    /// Bounds `(lo, hi)` of the field on the points of a box inside the
    /// ball `(x, rho)`, starting from the frontier `from` of a box that
    /// holds it; `to` becomes this box's frontier (for its sub-boxes).
    /// `stack` is scratch. Accepted approximations add at most `budget` to
    /// the width (module doc).
    pub fn refine(
        &self,
        from: &Frontier,
        x: [f64; 3],
        rho: f64,
        budget: f64,
        to: &mut Frontier,
        stack: &mut Vec<usize>,
    ) -> (f64, f64) {
        let per_mass = self.per_mass(budget);
        to.lo = from.lo;
        to.hi = from.hi;
        to.open.clear();
        let (mut lo, mut hi) = (0.0, 0.0);
        stack.clear();
        stack.extend(from.open.iter().rev());
        while let Some(id) = stack.pop() {
            let node = &self.nodes[id];
            let (dc, l, h, share) = self.bound(node, x, rho, per_mass);
            if h - l <= share {
                to.lo += l;
                to.hi += h;
                continue;
            }
            let dmin = (dc - node.radius - rho).max(0.0);
            let (f, err, s) = if Self::lumpable(node, dmin, share) {
                let f = node.moments.expansion(node.centre, node.s_min, x);
                (f, node.moments.error_bound(node.s_min, dmin), node.s_min)
            } else {
                match node.kids {
                    Ok([a, b]) => {
                        stack.push(b);
                        stack.push(a);
                        continue;
                    }
                    Err(i) => {
                        let (seg, s) = &self.segments[i];
                        let f = self.fields[i].value(x);
                        let d = (point_segment_distance(x, seg.p, seg.q) - rho).max(0.0);
                        let slope = rho * (node.pos + node.neg) * slope_bound(d, *s);
                        to.open.push(id);
                        lo += (f - slope).max(l);
                        hi += (f + slope).min(h);
                        continue;
                    }
                }
            };
            to.open.push(id);
            let slope = rho * (node.pos + node.neg) * slope_bound(dmin, s);
            lo += (f - err - slope).max(l);
            hi += (f + err + slope).min(h);
        }
        (to.lo + lo, to.hi + hi)
    }

    /// [`Self::near_list`] for the points of a box inside the ball
    /// `(x, rho)`, starting from the frontier `from` of a box that holds
    /// it. Returns the bounds of everything not in `list`; their midpoint
    /// plus [`Self::near_field`] is within `budget / 2` of the field.
    pub fn near_list_from(
        &self,
        from: &Frontier,
        x: [f64; 3],
        rho: f64,
        budget: f64,
        list: &mut Interaction,
        stack: &mut Vec<usize>,
    ) -> (f64, f64) {
        let per_mass = self.per_mass(budget);
        list.segments.clear();
        list.clusters.clear();
        let (mut lo, mut hi) = (from.lo, from.hi);
        stack.clear();
        stack.extend(from.open.iter().rev());
        while let Some(id) = stack.pop() {
            let node = &self.nodes[id];
            let (dc, l, h, share) = self.bound(node, x, rho, per_mass);
            if h - l <= share {
                lo += l;
                hi += h;
            } else if Self::lumpable(node, (dc - node.radius - rho).max(0.0), share) {
                list.clusters.push(id);
            } else {
                match node.kids {
                    Ok([a, b]) => {
                        stack.push(b);
                        stack.push(a);
                    }
                    Err(i) => list.segments.push(i),
                }
            }
        }
        (lo, hi)
    }
}
