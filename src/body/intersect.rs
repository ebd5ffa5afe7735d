//! Self-intersections of a closed mesh: every pair of triangles that share
//! no vertex and cross each other (an edge of one passes through the
//! other). Candidate pairs come from a uniform grid over the triangles'
//! bounding boxes (cell = twice the mean edge length), so the cost is
//! linear in the triangles for a mesh of even density.
//!
//! The test is Moller-Trumbore's segment-triangle intersection on the six
//! edges of a pair (two non-coplanar triangles intersect if and only if an
//! edge of one meets the other); coplanar overlaps are not counted.

use super::sites::group_of;
use crate::mesh::{dot, sub, Mesh};
use crate::vec3::cross;
use std::collections::HashMap;

/// Self-intersections found.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct Intersections {
    /// Crossing triangle pairs.
    pub pairs: usize,
    /// Crossing pairs per pair of groups (`"a/b"`, names sorted), largest first.
    pub by_groups: Vec<(String, usize)>,
    /// One crossing point per group pair (the first found).
    pub example: Option<[f64; 3]>,
}

/// Where segment `p`-`q` crosses triangle `t` strictly inside (barycentric
/// and segment parameters away from the ends by `eps`).
pub fn segment_hits_triangle(
    p: [f64; 3],
    q: [f64; 3],
    t: [[f64; 3]; 3],
    eps: f64,
) -> Option<[f64; 3]> {
    let d = sub(q, p);
    let e1 = sub(t[1], t[0]);
    let e2 = sub(t[2], t[0]);
    let h = cross(d, e2);
    let a = dot(e1, h);
    let scale = (dot(d, d) * dot(e1, e1).max(dot(e2, e2))).max(f64::MIN_POSITIVE);
    if a.abs() <= 1e-12 * scale {
        return None;
    }
    let f = 1.0 / a;
    let s = sub(p, t[0]);
    let u = f * dot(s, h);
    if u < eps || u > 1.0 - eps {
        return None;
    }
    let qv = cross(s, e1);
    let v = f * dot(d, qv);
    if v < eps || u + v > 1.0 - eps {
        return None;
    }
    let w = f * dot(e2, qv);
    if w < eps || w > 1.0 - eps {
        return None;
    }
    Some([p[0] + w * d[0], p[1] + w * d[1], p[2] + w * d[2]])
}

/// Whether triangles `a` and `b` cross (an edge of one through the other).
pub fn triangles_cross(a: [[f64; 3]; 3], b: [[f64; 3]; 3], eps: f64) -> Option<[f64; 3]> {
    for (x, y) in [(a, b), (b, a)] {
        for k in 0..3 {
            if let Some(p) = segment_hits_triangle(x[k], x[(k + 1) % 3], y, eps) {
                return Some(p);
            }
        }
    }
    None
}

/// Parameter margin of [`triangles_cross`]: touching at an edge or a corner
/// within this fraction is not a crossing.
pub const CROSS_EPS: f64 = 1e-9;

/// Crossing pairs (`pde6 body --morph NAME=1 --json`, release) of the
/// checked closed bodies that do NOT reach the target of 0: the
/// known state, a regression bound per body, not a target. Every checked
/// body not listed (`"base"` and the morph names of
/// [`crate::body::closed::CHECKED_MORPHS`] without `=1`) is held to 0:
/// base, caucasian-male-child, universal-male maxweight,
/// stomach-pregnant-incr, african-male-young, caucasian-male-young and
/// caucasian-male-old (95 and 46 inside the mitten hands before the hands got
/// a thumb, a straight palm trace and their own chains: README, The hands),
/// and, since the shoulders' cuts are measured per body (`body::closed`),
/// universal-female maxweight (was 70). Left: caucasian-female-young inside
/// the head (the head trace takes the mouth bag's loop at the chin; its
/// armpits are at 0, were 32).
pub const KNOWN_CROSSINGS: &[(&str, usize)] = &[("caucasian-female-young", 26)];

/// The known crossing pairs of a checked body ([`KNOWN_CROSSINGS`]; 0, the
/// target, for a body not listed).
pub fn known_crossings(body: &str) -> usize {
    KNOWN_CROSSINGS
        .iter()
        .find(|(b, _)| *b == body)
        .map_or(0, |(_, n)| *n)
}

/// A triangle whose bounding box spans more grid cells than this along an
/// axis is not put in the grid but tested against every other triangle: one
/// long sliver (or a spike of a failed reconstruction) would otherwise visit
/// up to (extent / cell)^3 cells.
pub const GRID_SPAN_MAX: i64 = 16;

/// A crossing pair of triangles and a point where they cross.
pub type CrossingPair = (usize, usize, [f64; 3]);

/// Every crossing pair `(t, s, point)` of triangles of `m` that share no
/// vertex (`t < s` for the grid's triangles), in the order found.
pub fn crossing_pairs(m: &Mesh) -> Vec<CrossingPair> {
    let n = m.triangles.len();
    if n == 0 {
        return Vec::new();
    }
    let mut edge_sum = 0.0;
    for t in 0..n {
        let c = m.corners(t);
        for k in 0..3 {
            edge_sum += crate::mesh::dist(c[k], c[(k + 1) % 3]);
        }
    }
    let cell = (2.0 * edge_sum / (3 * n) as f64).max(f64::MIN_POSITIVE);
    let key = |p: [f64; 3]| p.map(|x| (x / cell).floor() as i64);
    let boxes: Vec<([i64; 3], [i64; 3])> = (0..n)
        .map(|t| {
            let c = m.corners(t);
            let lo = std::array::from_fn(|k| c[0][k].min(c[1][k]).min(c[2][k]));
            let hi = std::array::from_fn(|k| c[0][k].max(c[1][k]).max(c[2][k]));
            (key(lo), key(hi))
        })
        .collect();
    let big: Vec<bool> = boxes
        .iter()
        .map(|(lo, hi)| (0..3).any(|k| hi[k].saturating_sub(lo[k]) > GRID_SPAN_MAX))
        .collect();
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
    for (t, (lo, hi)) in boxes.iter().enumerate().filter(|(t, _)| !big[*t]) {
        for i in lo[0]..=hi[0] {
            for j in lo[1]..=hi[1] {
                for k in lo[2]..=hi[2] {
                    grid.entry([i, j, k]).or_default().push(t as u32);
                }
            }
        }
    }
    let mut out = Vec::new();
    let mut test = |t: usize, s: usize| {
        let (tv, sv) = (m.triangles[t], m.triangles[s]);
        if tv.iter().any(|v| sv.contains(v)) {
            return;
        }
        if let Some(p) = triangles_cross(m.corners(t), m.corners(s), CROSS_EPS) {
            out.push((t, s, p));
        }
    };
    let mut cand = Vec::new();
    for (t, (lo, hi)) in boxes.iter().enumerate() {
        if big[t] {
            // against every triangle after it, and every grid one before it
            for s in (0..n).filter(|&s| s > t || !big[s]) {
                if s != t {
                    test(t, s);
                }
            }
            continue;
        }
        cand.clear();
        for i in lo[0]..=hi[0] {
            for j in lo[1]..=hi[1] {
                for k in lo[2]..=hi[2] {
                    if let Some(v) = grid.get(&[i, j, k]) {
                        cand.extend(v.iter().copied().filter(|&s| s as usize > t));
                    }
                }
            }
        }
        cand.sort_unstable();
        cand.dedup();
        for &s in &cand {
            test(t, s as usize);
        }
    }
    out
}

/// Every crossing pair of triangles of `m` that share no vertex.
pub fn self_intersections(m: &Mesh) -> Intersections {
    intersections_of(m, &crossing_pairs(m))
}

/// [`self_intersections`] from the [`crossing_pairs`] of `m` found before
/// (the shoulder-cut search has them for the model it keeps).
pub fn intersections_of(m: &Mesh, pairs: &[CrossingPair]) -> Intersections {
    let mut out = Intersections::default();
    let mut groups: HashMap<String, usize> = HashMap::new();
    for &(t, s, p) in pairs {
        out.pairs += 1;
        out.example.get_or_insert(p);
        let (mut a, mut b) = (group_of(m, t), group_of(m, s));
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        *groups.entry(format!("{a}/{b}")).or_default() += 1;
    }
    out.by_groups = groups.into_iter().collect();
    out.by_groups
        .sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    out
}
