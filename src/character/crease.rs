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
use std::collections::HashMap;

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

/// The triangles on each undirected edge `(low, high)` of `m`, in triangle
/// order.
pub fn edge_triangles(m: &Mesh) -> HashMap<(u32, u32), Vec<usize>> {
    let mut edges: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (t, tr) in m.triangles.iter().enumerate() {
        for e in 0..3 {
            let (a, b) = (tr[e], tr[(e + 1) % 3]);
            edges.entry((a.min(b), a.max(b))).or_default().push(t);
        }
    }
    edges
}

/// Crease reports of every group of `m` (edges shared by exactly two
/// triangles; the angle of a consistently oriented pair is the angle
/// between their normals).
pub fn creases(m: &Mesh) -> Vec<CreaseReport> {
    let edges = edge_triangles(m);
    // in edge order, not the map's (seeded per map): the creased length is
    // a sum and the maximum's place a first-found, so the report would
    // otherwise change in its last bits from run to run
    let mut edges: Vec<((u32, u32), Vec<usize>)> = edges.into_iter().collect();
    edges.sort_unstable_by_key(|e| e.0);
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
    for &((a, b), ref ts) in &edges {
        let [t0, t1] = ts[..] else { continue };
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
