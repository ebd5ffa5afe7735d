//! The simple-polygon test: one sweep over the edges sorted by their
//! smallest x, comparing only edges whose x-ranges overlap.

use super::{orient, segments_meet};

/// The first pair of edges `(a, b, at)` (`a < b`, smallest `a`, then
/// smallest `b`) of the closed polygon `p` that meet, with a point where
/// they meet. Non-adjacent edges meet when they share any point, proper
/// crossings and touching alike ([`super::segments_meet`]: a vertex on
/// another edge is not simple); adjacent edges meet when they fold back
/// onto each other (collinear, turning by 180 degrees at their shared
/// vertex). A repeated vertex is a self-intersection (its zero-length
/// edge's neighbours touch): drop repeats first ([`super::Outline`]
/// does). Points must be finite.
///
/// One sweep: edges sorted by their smallest x, each compared with the
/// later ones whose x-range begins before its own ends, which is near
/// linear for outlines (a vertical line meets few edges).
pub fn self_intersection(p: &[[f64; 2]]) -> Option<(usize, usize, [f64; 2])> {
    let n = p.len();
    if n < 3 {
        return None;
    }
    let mut found: Option<(usize, usize, [f64; 2])> = None;
    let mut keep = |a: usize, b: usize, at: [f64; 2]| {
        let (a, b) = (a.min(b), a.max(b));
        if found.is_none_or(|(fa, fb, _)| (a, b) < (fa, fb)) {
            found = Some((a, b, at));
        }
    };
    for i in 0..n {
        let (u, v, w) = (p[i], p[(i + 1) % n], p[(i + 2) % n]);
        let back = (u[0] - v[0]) * (w[0] - v[0]) + (u[1] - v[1]) * (w[1] - v[1]);
        if orient(u, v, w) == 0.0 && back > 0.0 {
            keep(i, (i + 1) % n, v);
        }
    }
    let mut edges: Vec<(f64, f64, usize)> = (0..n)
        .map(|i| {
            let (a, b) = (p[i][0], p[(i + 1) % n][0]);
            (a.min(b), a.max(b), i)
        })
        .collect();
    edges.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.2.cmp(&b.2)));
    for s in 0..n {
        let (_, hi, i) = edges[s];
        for &(lo2, _, j) in &edges[s + 1..] {
            if lo2 > hi {
                break;
            }
            if (i + 1) % n == j || (j + 1) % n == i {
                continue;
            }
            let (a, b) = (i.min(j), i.max(j));
            if let Some(at) = segments_meet(p[a], p[(a + 1) % n], p[b], p[(b + 1) % n]) {
                keep(a, b, at);
            }
        }
    }
    found
}

/// Whether the closed polygon is simple: no [`self_intersection`].
pub fn is_simple(p: &[[f64; 2]]) -> bool {
    self_intersection(p).is_none()
}
