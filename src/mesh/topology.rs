//! Watertightness, manifoldness and consistent orientation.

use super::Mesh;
use serde::Serialize;
use std::collections::HashMap;

/// Topological facts about a triangle mesh.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct TopologyReport {
    pub vertices: usize,
    pub triangles: usize,
    /// Undirected edges used by exactly one triangle.
    pub boundary_edges: usize,
    /// Undirected edges used by more than two triangles.
    pub nonmanifold_edges: usize,
    /// Interior edges whose two triangles traverse it in the same direction.
    pub misoriented_edges: usize,
    /// Vertices whose incident triangles form more than one fan.
    pub nonmanifold_vertices: usize,
    /// Triangles with a repeated vertex index.
    pub degenerate_triangles: usize,
    /// Every edge has exactly two triangles.
    pub watertight: bool,
    /// Edge- and vertex-manifold.
    pub manifold: bool,
    /// Every interior edge is traversed once in each direction.
    pub oriented: bool,
    /// Euler characteristic V - E + F (over referenced vertices).
    pub euler: i64,
}

/// Computes the [`TopologyReport`] of `m`.
pub fn report(m: &Mesh) -> TopologyReport {
    // directed edge -> count, undirected edge -> count
    let mut undirected: HashMap<(u32, u32), (u32, u32)> = HashMap::new(); // (forward, backward)
    let mut r = TopologyReport {
        vertices: m.positions.len(),
        triangles: m.triangles.len(),
        ..Default::default()
    };
    let mut used = vec![false; m.positions.len()];
    for t in &m.triangles {
        if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            r.degenerate_triangles += 1;
        }
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            used[a as usize] = true;
            let e = undirected.entry((a.min(b), a.max(b))).or_insert((0, 0));
            if a < b {
                e.0 += 1;
            } else {
                e.1 += 1;
            }
        }
    }
    for &(f, b) in undirected.values() {
        match f + b {
            1 => r.boundary_edges += 1,
            2 => {
                if f != 1 {
                    r.misoriented_edges += 1
                }
            }
            _ => r.nonmanifold_edges += 1,
        }
    }
    r.nonmanifold_vertices = count_nonmanifold_vertices(m);
    r.watertight = r.boundary_edges == 0 && r.nonmanifold_edges == 0;
    r.manifold = r.nonmanifold_edges == 0 && r.nonmanifold_vertices == 0;
    r.oriented = r.misoriented_edges == 0 && r.nonmanifold_edges == 0;
    let v = used.iter().filter(|&&u| u).count() as i64;
    r.euler = v - undirected.len() as i64 + m.triangles.len() as i64;
    r
}

/// Vertices whose triangle fan is not connected through shared edges.
fn count_nonmanifold_vertices(m: &Mesh) -> usize {
    let mut incident: Vec<Vec<u32>> = vec![Vec::new(); m.positions.len()];
    for (ti, t) in m.triangles.iter().enumerate() {
        for &v in t {
            incident[v as usize].push(ti as u32);
        }
    }
    let mut bad = 0;
    for (v, tris) in incident.iter().enumerate() {
        if tris.len() <= 1 {
            continue;
        }
        // union-find over the incident triangles, joined when they share an
        // edge through v
        let mut parent: Vec<usize> = (0..tris.len()).collect();
        fn find(p: &mut [usize], x: usize) -> usize {
            let mut r = x;
            while p[r] != r {
                r = p[r];
            }
            let mut y = x;
            while p[y] != r {
                let n = p[y];
                p[y] = r;
                y = n;
            }
            r
        }
        let others: Vec<[u32; 2]> = tris
            .iter()
            .map(|&t| {
                let tri = m.triangles[t as usize];
                let k = tri.iter().position(|&x| x as usize == v).unwrap_or(0);
                [tri[(k + 1) % 3], tri[(k + 2) % 3]]
            })
            .collect();
        for a in 0..tris.len() {
            for b in (a + 1)..tris.len() {
                if others[a].iter().any(|x| others[b].contains(x)) {
                    let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
                    parent[ra] = rb;
                }
            }
        }
        let roots = (0..tris.len())
            .filter(|&i| find(&mut parent, i) == i)
            .count();
        if roots > 1 {
            bad += 1;
        }
    }
    bad
}
