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

use super::kernel::Segment;
use crate::mesh::{dot, norm, sub};

/// Kernel $h_s(d)$ at distance `d` (finite for every finite input; 0 when
/// $s^2d^2$ overflows).
fn kernel(d: f64, s: f64) -> f64 {
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
struct Node {
    centre: [f64; 3],
    radius: f64,
    pos: f64,
    neg: f64,
    s_min: f64,
    s_max: f64,
    /// Leaf: `Err(segment index)`; inner: `Ok([left, right])`.
    kids: Result<[usize; 2], usize>,
}

/// The hierarchy over a group's segments, each with its own kernel width.
#[derive(Clone, Debug)]
pub struct SegmentBvh {
    segments: Vec<(Segment, f64)>,
    nodes: Vec<Node>,
    total_mass: f64,
}

impl SegmentBvh {
    /// Builds the hierarchy over `(segment, s)` pairs (median splits along
    /// the longest axis of the midpoints' box).
    pub fn new(segments: Vec<(Segment, f64)>) -> SegmentBvh {
        let mut bvh = SegmentBvh {
            segments,
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
        let me = self.nodes.len();
        self.nodes.push(Node {
            centre,
            radius,
            pos,
            neg,
            s_min,
            s_max,
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
    /// what `leaf` returns. Returns the summed `(lo, hi)`.
    #[inline]
    fn walk(
        &self,
        x: [f64; 3],
        rho: f64,
        budget: f64,
        mut leaf: impl FnMut(&Node, usize, f64, f64) -> (f64, f64),
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
            let node = &self.nodes[stack[top]];
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
            if h - l <= per_mass * (node.pos + node.neg) {
                lo += l;
                hi += h;
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
        self.walk(x, rho, budget, |node, i, l, h| {
            let (seg, s) = &self.segments[i];
            let f = seg.field(x, *s);
            if rho == 0.0 {
                (f, f)
            } else {
                let d = (point_segment_distance(x, seg.p, seg.q) - rho).max(0.0);
                let slope = (node.pos + node.neg) * slope_bound(d, *s);
                ((f - rho * slope).max(l), (f + rho * slope).min(h))
            }
        })
    }

    /// The interaction list of the ball of radius `rho` around `x`: the
    /// segments to evaluate exactly at its points, and bounds `(lo, hi)`,
    /// valid on the whole ball, of the sum of all other segments, with
    /// `hi - lo <= budget`. [`Self::near_field`] of the list plus the
    /// midpoint of the bounds is then the field within `budget / 2`
    /// anywhere in the ball.
    pub fn near_list(
        &self,
        x: [f64; 3],
        rho: f64,
        budget: f64,
        near: &mut Vec<usize>,
    ) -> (f64, f64) {
        near.clear();
        self.walk(x, rho, budget, |_, i, _, _| {
            near.push(i);
            (0.0, 0.0)
        })
    }

    /// The exact field at `x` of the segments `list` (from
    /// [`Self::near_list`]).
    pub fn near_field(&self, list: &[usize], x: [f64; 3]) -> f64 {
        list.iter()
            .map(|&i| {
                let (seg, s) = &self.segments[i];
                seg.field(x, *s)
            })
            .sum()
    }

    /// The field at `x` within `budget / 2` (midpoint of [`Self::interval`]
    /// at radius 0).
    pub fn field(&self, x: [f64; 3], budget: f64) -> f64 {
        let (lo, hi) = self.interval(x, 0.0, budget);
        0.5 * (lo + hi)
    }
}
