//! A bounding-volume hierarchy over the segments of a component group and
//! provable bounds of their field on a point or a ball (issue 16; the field
//! of paper 003, sec 3.1).
//!
//! **Cluster bound.** Every segment's kernel $h_s(d) = 1/(1+s^2d^2)^2$
//! decreases with the distance $d$ and with $s$. A cluster of segments
//! inside the sphere $(c, R)$, with widths between $s_{min}$ and
//! $s_{max}$, positive mass $P = \sum \int (\lambda w)^+ dt$ and negative
//! mass $N = \sum \int (\lambda w)^- dt$, contributes to the field at every
//! point of the ball $(x, \rho)$ a value in
//! $$[P h_{s_{max}}(d_{max}) - N h_{s_{min}}(d_{min}),\;
//!   P h_{s_{min}}(d_{min}) - N h_{s_{max}}(d_{max})],$$
//! $d_{min} = \max(0, |x-c| - R - \rho)$, $d_{max} = |x-c| + R + \rho$: the
//! kernel at every point of every segment lies between its values at the
//! nearest and the farthest possible distance.
//!
//! **Segment bound.** One segment near the ball is evaluated exactly at the
//! centre (closed form, [`super::kernel`]) and bounded on the ball by its
//! gradient: $|\nabla F| \le \int |\lambda w|\,dt \cdot g(d)$ with
//! $g(d) = \max_{d' \ge d} |h'(d')|$, $|h'(d)| = 4s^2d/(1+s^2d^2)^3$ (largest
//! at $d^* = 1/(s\sqrt5)$), $d$ the distance from the ball to the segment.
//!
//! **Error budget.** [`SegmentBvh::interval`] accepts a cluster's interval
//! when its width is at most `budget` times the cluster's share
//! $(P+N)/M$ of the total mass $M$, else it opens the cluster. The widths
//! of the accepted clusters then sum to at most `budget`; at a point
//! ($\rho = 0$) the segments add no width, so the midpoint of the interval
//! is within `budget / 2` of the exact field.
//!
//! **Interaction lists.** [`SegmentBvh::near_list`] serves every point of
//! a ball at once: a cluster whose bound over the whole ball is within its
//! share adds its midpoint (a constant); otherwise, when all its segments
//! share one kernel width, its second-order expansion
//! ([`super::farfield::Moments`]) is evaluated at each point if its proven
//! error there is at most half its share; otherwise it is opened, and
//! leaf segments are evaluated exactly (one arctangent,
//! [`super::farfield::SegmentField`]). Every accepted cluster errs by at
//! most half its share, so the sum is within `budget / 2` of the field.
//!
//! **Frontiers.** The narrow-band octree asks these questions for nested
//! boxes. [`SegmentBvh::refine`] answers for a box starting from its
//! parent's [`Frontier`](super::frontier::Frontier) instead of the root: a cluster accepted for the
//! parent's ball is valid (and within its share) on every point of the
//! child box, so its bounds are inherited and never tested again; only the
//! nodes the parent left open (segments, and clusters whose expansion was
//! within half their share there) are tested on the child's ball. A
//! frontier is a cut of the tree, so the shares of its accepted clusters
//! and open nodes still sum to at most `budget`. An open cluster bounds the
//! field on a ball by its expansion at the centre, its error bound and
//! its gradient bound $(P+N)\,g(d_{min})$, like a segment. The bounds
//! therefore hold at every point of the box (not of the child's ball,
//! which may stick out of the parent's box), which is all the sampler
//! needs: it decides node values.

use super::farfield::{Moments, SegmentField};
use super::kernel::Segment;
use crate::mesh::{dot, norm, sub};

/// Kernel $h_s(d)$ at distance `d` (finite for every finite input; 0 when
/// $s^2d^2$ overflows).
pub(super) fn kernel(d: f64, s: f64) -> f64 {
    let a = 1.0 + (s * d) * (s * d);
    1.0 / (a * a)
}

/// $g(d) = \max_{d' \ge d} |h_s'(d')|$.
pub fn slope_bound(d: f64, s: f64) -> f64 {
    let d = d.max(1.0 / (s * 5f64.sqrt()));
    let a = 1.0 + (s * d) * (s * d);
    4.0 * s * s * d / (a * a * a)
}

/// $\int_0^l (\lambda w(t))^+ dt$ and $\int_0^l (\lambda w(t))^- dt$ of a
/// linearly weighted segment.
pub fn segment_masses(seg: &Segment) -> (f64, f64) {
    let l = seg.length();
    let (a, b) = (seg.lambda * seg.w0, seg.lambda * seg.w1);
    let pos = |a: f64, b: f64| -> f64 {
        if a >= 0.0 && b >= 0.0 {
            0.5 * l * (a + b)
        } else if a <= 0.0 && b <= 0.0 {
            0.0
        } else {
            let (p, n) = if a > 0.0 { (a, -b) } else { (b, -a) };
            0.5 * l * p * p / (p + n)
        }
    };
    (pos(a, b), pos(-a, -b))
}

/// Distance from `x` to the segment `p`..`q`.
pub fn point_segment_distance(x: [f64; 3], p: [f64; 3], q: [f64; 3]) -> f64 {
    let e = sub(q, p);
    let ee = dot(e, e);
    let d = sub(x, p);
    let t = if ee > 0.0 {
        (dot(d, e) / ee).clamp(0.0, 1.0)
    } else {
        0.0
    };
    norm([d[0] - t * e[0], d[1] - t * e[1], d[2] - t * e[2]])
}

#[derive(Clone, Debug)]
pub(super) struct Node {
    pub(super) centre: [f64; 3],
    pub(super) radius: f64,
    pub(super) pos: f64,
    pub(super) neg: f64,
    pub(super) s_min: f64,
    pub(super) s_max: f64,
    /// Moments about `centre` (for the expansion when `s_min == s_max`).
    pub(super) moments: Moments,
    /// Leaf: `Err(segment index)`; inner: `Ok([left, right])`.
    pub(super) kids: Result<[usize; 2], usize>,
}

/// What [`SegmentBvh::near_list`] hands back for a ball: the segments to
/// evaluate exactly and the clusters to evaluate by their expansion.
#[derive(Clone, Debug, Default)]
pub struct Interaction {
    pub segments: Vec<usize>,
    pub clusters: Vec<usize>,
}

/// The hierarchy over a group's segments, each with its own kernel width.
#[derive(Clone, Debug)]
pub struct SegmentBvh {
    pub(super) segments: Vec<(Segment, f64)>,
    pub(super) fields: Vec<SegmentField>,
    pub(super) nodes: Vec<Node>,
    pub(super) total_mass: f64,
}

impl SegmentBvh {
    /// Builds the hierarchy over `(segment, s)` pairs (median splits along
    /// the longest axis of the midpoints' box).
    pub fn new(segments: Vec<(Segment, f64)>) -> SegmentBvh {
        let fields = segments
            .iter()
            .map(|(g, s)| SegmentField::new(g, *s))
            .collect();
        let mut bvh = SegmentBvh {
            segments,
            fields,
            nodes: Vec::new(),
            total_mass: 0.0,
        };
        let mut idx: Vec<usize> = (0..bvh.segments.len()).collect();
        if !idx.is_empty() {
            bvh.build(&mut idx);
        }
        bvh.total_mass = bvh.nodes.first().map_or(0.0, |n| n.pos + n.neg);
        bvh
    }

    /// Number of segments.
    pub fn len(&self) -> usize {
        self.segments.len()
    }

    /// No segments.
    pub fn is_empty(&self) -> bool {
        self.segments.is_empty()
    }

    /// $M = \sum \int |\lambda w|\,dt$ over all segments.
    pub fn total_mass(&self) -> f64 {
        self.total_mass
    }

    fn build(&mut self, idx: &mut [usize]) -> usize {
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        let (mut pos, mut neg) = (0.0, 0.0);
        let (mut s_min, mut s_max) = (f64::INFINITY, 0.0f64);
        for &i in idx.iter() {
            let (seg, s) = &self.segments[i];
            for p in [seg.p, seg.q] {
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
            let (a, b) = segment_masses(seg);
            pos += a;
            neg += b;
            s_min = s_min.min(*s);
            s_max = s_max.max(*s);
        }
        let centre = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
        let mut radius: f64 = 0.0;
        for &i in idx.iter() {
            let seg = &self.segments[i].0;
            radius = radius.max(norm(sub(seg.p, centre)).max(norm(sub(seg.q, centre))));
        }
        let mut moments = Moments::default();
        for &i in idx.iter() {
            moments.add(&Moments::of_segment(&self.segments[i].0, centre));
        }
        let me = self.nodes.len();
        self.nodes.push(Node {
            centre,
            radius,
            pos,
            neg,
            s_min,
            s_max,
            moments,
            kids: Err(idx[0]),
        });
        if idx.len() > 1 {
            let mid = |i: usize, k: usize| {
                let seg = &self.segments[i].0;
                seg.p[k] + seg.q[k]
            };
            let axis = (0..3)
                .max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])))
                .unwrap_or(0);
            idx.sort_by(|&a, &b| mid(a, axis).total_cmp(&mid(b, axis)));
            let half = idx.len() / 2;
            let (l, r) = idx.split_at_mut(half);
            let left = self.build(l);
            let right = self.build(r);
            self.nodes[me].kids = Ok([left, right]);
        }
        me
    }

    /// Walks the hierarchy for the ball of radius `rho` around `x`: a
    /// cluster whose bounds are within its share of `budget` (or that cannot
    /// be split further) adds its bounds; a leaf segment that is not accepted
    /// is handed to `leaf` with its node and its own bounds `(l, h)`, and adds
    /// what `leaf` returns. Before a cluster is opened, `lump` may take it
    /// (node index, node, distance from `x` to its centre, its share of
    /// `budget`): then it adds nothing to the bounds. Returns the summed
    /// `(lo, hi)`.
    #[inline]
    fn walk(
        &self,
        x: [f64; 3],
        rho: f64,
        budget: f64,
        mut leaf: impl FnMut(&Node, usize, f64, f64) -> (f64, f64),
        mut lump: impl FnMut(usize, &Node, f64, f64) -> bool,
    ) -> (f64, f64) {
        if self.nodes.is_empty() {
            return (0.0, 0.0);
        }
        let per_mass = if self.total_mass > 0.0 {
            budget / self.total_mass
        } else {
            0.0
        };
        let (mut lo, mut hi) = (0.0, 0.0);
        let mut stack = [0usize; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let id = stack[top];
            let node = &self.nodes[id];
            let dc = norm(sub(x, node.centre));
            let dmin = (dc - node.radius - rho).max(0.0);
            let dmax = dc + node.radius + rho;
            let near = (
                node.pos * kernel(dmin, node.s_min),
                node.neg * kernel(dmin, node.s_min),
            );
            let far = (
                node.pos * kernel(dmax, node.s_max),
                node.neg * kernel(dmax, node.s_max),
            );
            let (l, h) = (far.0 - near.1, near.0 - far.1);
            let share = per_mass * (node.pos + node.neg);
            if h - l <= share {
                lo += l;
                hi += h;
                continue;
            }
            if lump(id, node, dc, share) {
                continue;
            }
            match node.kids {
                Ok([a, b]) if top + 2 <= stack.len() => {
                    stack[top] = a;
                    stack[top + 1] = b;
                    top += 2;
                }
                Ok(_) => {
                    lo += l;
                    hi += h;
                }
                Err(i) => {
                    let (dl, dh) = leaf(node, i, l, h);
                    lo += dl;
                    hi += dh;
                }
            }
        }
        (lo, hi)
    }

    /// Bounds `(lo, hi)` of the field on the ball of radius `rho` around
    /// `x`; accepted cluster approximations add at most `budget` to the
    /// width `hi - lo` (see the module doc).
    pub fn interval(&self, x: [f64; 3], rho: f64, budget: f64) -> (f64, f64) {
        let leaf = |node: &Node, i: usize, l: f64, h: f64| {
            let (seg, s) = &self.segments[i];
            let f = self.fields[i].value(x);
            if rho == 0.0 {
                (f, f)
            } else {
                let d = (point_segment_distance(x, seg.p, seg.q) - rho).max(0.0);
                let slope = (node.pos + node.neg) * slope_bound(d, *s);
                ((f - rho * slope).max(l), (f + rho * slope).min(h))
            }
        };
        self.walk(x, rho, budget, leaf, |_, _, _, _| false)
    }

    /// The interaction list of the ball of radius `rho` around `x`: the
    /// segments to evaluate exactly and the clusters to evaluate by their
    /// expansion at its points, and bounds `(lo, hi)`, valid on the whole
    /// ball, of the sum of all other segments. [`Self::near_field`] of the
    /// list plus the midpoint of the bounds is then the field within
    /// `budget / 2` anywhere in the ball (see the module doc).
    pub fn near_list(
        &self,
        x: [f64; 3],
        rho: f64,
        budget: f64,
        list: &mut Interaction,
    ) -> (f64, f64) {
        list.segments.clear();
        list.clusters.clear();
        let clusters = &mut list.clusters;
        let segments = &mut list.segments;
        self.walk(
            x,
            rho,
            budget,
            |_, i, _, _| {
                segments.push(i);
                (0.0, 0.0)
            },
            |id, node, dc, share| {
                let single = node.s_min == node.s_max;
                let dmin = (dc - node.radius - rho).max(0.0);
                let take = single && 2.0 * node.moments.error_bound(node.s_min, dmin) <= share;
                if take {
                    clusters.push(id);
                }
                take
            },
        )
    }

    /// The field at `x` of the interaction list `list` (from
    /// [`Self::near_list`]): exact segments plus cluster expansions.
    #[inline]
    pub fn near_field(&self, list: &Interaction, x: [f64; 3]) -> f64 {
        let mut f = 0.0;
        for &i in &list.segments {
            f += self.fields[i].value(x);
        }
        for &c in &list.clusters {
            let n = &self.nodes[c];
            f += n.moments.expansion(n.centre, n.s_min, x);
        }
        f
    }

    /// The field at `x` within `budget / 2` (midpoint of [`Self::interval`]
    /// at radius 0).
    pub fn field(&self, x: [f64; 3], budget: f64) -> f64 {
        let (lo, hi) = self.interval(x, 0.0, budget);
        0.5 * (lo + hi)
    }
}
