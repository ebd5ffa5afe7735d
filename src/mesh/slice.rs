//! Cross sections: a mesh cut by a plane, as polylines.
//!
//! Each triangle that straddles the plane contributes one segment; segments
//! are chained through the mesh edges they cross, so the chaining is exact
//! (no distance tolerance). A chain that returns to its start is closed; one
//! that ends at a mesh boundary is open.

use super::{dot, sub, Mesh};
use std::collections::HashMap;

/// A polyline of a cross section.
#[derive(Clone, Debug, PartialEq)]
pub struct Polyline {
    pub points: Vec<[f64; 3]>,
    pub closed: bool,
}

impl Polyline {
    /// Length (including the closing segment when closed).
    pub fn length(&self) -> f64 {
        let n = self.points.len();
        let segs = if self.closed { n } else { n.saturating_sub(1) };
        (0..segs)
            .map(|i| super::dist(self.points[i], self.points[(i + 1) % n]))
            .sum()
    }

    /// Centroid of the vertices.
    pub fn centroid(&self) -> [f64; 3] {
        let n = self.points.len().max(1) as f64;
        let mut c = [0.0; 3];
        for p in &self.points {
            for k in 0..3 {
                c[k] += p[k] / n;
            }
        }
        c
    }
}

/// Cuts `m` by the plane through `origin` with normal `normal`. Vertices
/// exactly on the plane are nudged to the positive side, so every crossing
/// is a proper edge crossing.
pub fn slice(m: &Mesh, origin: [f64; 3], normal: [f64; 3]) -> Vec<Polyline> {
    let d: Vec<f64> = m
        .positions
        .iter()
        .map(|p| {
            let s = dot(sub(*p, origin), normal);
            if s == 0.0 {
                f64::MIN_POSITIVE
            } else {
                s
            }
        })
        .collect();
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    // each crossing edge -> the (up to two) segments through it
    let mut segs: Vec<[(u32, u32); 2]> = Vec::new();
    let mut edge_segs: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for t in &m.triangles {
        let mut crossing = Vec::with_capacity(2);
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if (d[a as usize] > 0.0) != (d[b as usize] > 0.0) {
                crossing.push(key(a, b));
            }
        }
        if crossing.len() == 2 {
            let s = segs.len();
            segs.push([crossing[0], crossing[1]]);
            for e in crossing {
                edge_segs.entry(e).or_default().push(s);
            }
        }
    }
    let point = |e: (u32, u32)| {
        let (pa, pb) = (m.positions[e.0 as usize], m.positions[e.1 as usize]);
        let (da, db) = (d[e.0 as usize], d[e.1 as usize]);
        let t = da / (da - db);
        [
            pa[0] + t * (pb[0] - pa[0]),
            pa[1] + t * (pb[1] - pa[1]),
            pa[2] + t * (pb[2] - pa[2]),
        ]
    };
    let mut used = vec![false; segs.len()];
    let mut out = Vec::new();
    for start in 0..segs.len() {
        if used[start] {
            continue;
        }
        used[start] = true;
        // walk forward from segs[start][1], then backward from segs[start][0]
        let mut forward = vec![segs[start][0], segs[start][1]];
        let mut closed = false;
        for dir in 0..2 {
            loop {
                let end = *forward.last().unwrap_or(&segs[start][1]);
                let next = edge_segs
                    .get(&end)
                    .and_then(|v| v.iter().copied().find(|&s| !used[s]));
                match next {
                    Some(s) => {
                        used[s] = true;
                        let e = if segs[s][0] == end {
                            segs[s][1]
                        } else {
                            segs[s][0]
                        };
                        if e == forward[0] {
                            closed = true;
                            break;
                        }
                        forward.push(e);
                    }
                    None => break,
                }
            }
            if closed || dir == 1 {
                break;
            }
            forward.reverse();
        }
        out.push(Polyline {
            points: forward.into_iter().map(point).collect(),
            closed,
        });
    }
    out
}
