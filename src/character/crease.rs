//! The crease metric: the largest dihedral angle between adjacent triangles
//! of a mesh group (the angle between their unit normals), inside the group
//! and along its border with other groups.
//!
//! A smooth surface sampled at spacing `h` with principal curvature `k`
//! turns by about `k h` between neighbouring triangles; a crease (a
//! tangent-plane jump along a curve) turns by its jump angle at every
//! resolution. A transition's value is read against the parts' own (the
//! largest of any part's interior edges): a transition that is G1 and no
//! more curved than the parts stays at or below the parts' level.

use crate::mesh::{dot, norm, scale, Mesh};
use serde::Serialize;

/// The largest dihedral angles of one group.
#[derive(Clone, Debug, Serialize)]
pub struct CreaseReport {
    pub group: String,
    /// Largest angle (degrees) over edges with both triangles in the group.
    pub interior_deg: f64,
    /// Midpoint of that edge.
    pub interior_at: [f64; 3],
    /// Largest angle (degrees) over edges between the group and another.
    pub border_deg: f64,
    /// Total length of the group's interior edges turning by more than
    /// [`CREASE_DEG`] (model units): how much of it is creased, where the
    /// maximum alone is set by one sliver at a seam's corner.
    pub creased_length: f64,
}

/// The dihedral angle above which an edge counts as creased (degrees).
pub const CREASE_DEG: f64 = 30.0;

fn unit_normal(m: &Mesh, t: usize) -> [f64; 3] {
    let n = m.face_normal_area(t);
    scale(n, 1.0 / norm(n).max(f64::MIN_POSITIVE))
}

/// The triangles on each undirected edge `(low, high)` of a mesh, in
/// triangle order, the edges sorted (a sorted list grouped by edge, not a
/// hash map of vectors: a tenth of the sketch build's time went to
/// building that map, three times a build, and every caller wants the
/// edges in order anyway).
pub struct EdgeTriangles {
    keys: Vec<(u32, u32)>,
    start: Vec<u32>,
    tris: Vec<u32>,
}

impl EdgeTriangles {
    /// The edges in order, each with its triangles.
    pub fn iter(&self) -> impl Iterator<Item = ((u32, u32), &[u32])> + '_ {
        self.keys.iter().enumerate().map(|(i, &k)| {
            (
                k,
                &self.tris[self.start[i] as usize..self.start[i + 1] as usize],
            )
        })
    }

    /// The triangles on edge `(low, high)` (none when it is not an edge).
    pub fn get(&self, e: (u32, u32)) -> &[u32] {
        match self.keys.binary_search(&e) {
            Ok(i) => &self.tris[self.start[i] as usize..self.start[i + 1] as usize],
            Err(_) => &[],
        }
    }
}

/// The triangles on each undirected edge of `m` ([`EdgeTriangles`]).
pub fn edge_triangles(m: &Mesh) -> EdgeTriangles {
    let mut all: Vec<(u64, u32)> = Vec::with_capacity(3 * m.triangles.len());
    for (t, tr) in m.triangles.iter().enumerate() {
        for e in 0..3 {
            let (a, b) = (tr[e], tr[(e + 1) % 3]);
            all.push((((a.min(b) as u64) << 32) | a.max(b) as u64, t as u32));
        }
    }
    all.sort_unstable();
    let mut out = EdgeTriangles {
        keys: Vec::new(),
        start: Vec::new(),
        tris: Vec::with_capacity(all.len()),
    };
    for (i, &(k, t)) in all.iter().enumerate() {
        // a new edge: its key and where its triangles start
        if i == 0 || all[i - 1].0 != k {
            out.keys.push(((k >> 32) as u32, k as u32));
            out.start.push(out.tris.len() as u32);
        }
        out.tris.push(t);
    }
    out.start.push(out.tris.len() as u32);
    out
}

/// Crease reports of every group of `m` (edges shared by exactly two
/// triangles; the angle of a consistently oriented pair is the angle
/// between their normals).
pub fn creases(m: &Mesh) -> Vec<CreaseReport> {
    // in edge order: the creased length is a sum and the maximum's place
    // a first-found, so the report must not depend on a map's order
    let edges = edge_triangles(m);
    let normals: Vec<[f64; 3]> = (0..m.triangles.len()).map(|t| unit_normal(m, t)).collect();
    let mut out: Vec<CreaseReport> = m
        .groups
        .iter()
        .map(|g| CreaseReport {
            group: g.clone(),
            interior_deg: 0.0,
            interior_at: [0.0; 3],
            border_deg: 0.0,
            creased_length: 0.0,
        })
        .collect();
    for ((a, b), ts) in edges.iter() {
        let [t0, t1] = ts[..] else { continue };
        let (t0, t1) = (t0 as usize, t1 as usize);
        let ang = dot(normals[t0], normals[t1])
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees();
        let (g0, g1) = (m.tri_group[t0] as usize, m.tri_group[t1] as usize);
        if g0 == g1 {
            let r = &mut out[g0];
            if ang > CREASE_DEG {
                r.creased_length +=
                    crate::mesh::dist(m.positions[a as usize], m.positions[b as usize]);
            }
            if ang > r.interior_deg {
                r.interior_deg = ang;
                let (pa, pb) = (m.positions[a as usize], m.positions[b as usize]);
                r.interior_at = scale(crate::mesh::add(pa, pb), 0.5);
            }
        } else {
            for g in [g0, g1] {
                out[g].border_deg = out[g].border_deg.max(ang);
            }
        }
    }
    out
}
