//! The straightforward hash-map implementations the polygonisers
//! replaced, kept to check that the outputs are identical.

use super::scan::*;
use super::*;
use std::collections::HashMap;

impl ScalarGrid {
    fn coords(&self, n: usize) -> [usize; 3] {
        let d = self.dims;
        [n % d[0], (n / d[0]) % d[1], n / (d[0] * d[1])]
    }

    fn position(&self, n: usize) -> [f64; 3] {
        let c = self.coords(n);
        [
            self.origin[0] + c[0] as f64 * self.spacing[0],
            self.origin[1] + c[1] as f64 * self.spacing[1],
            self.origin[2] + c[2] as f64 * self.spacing[2],
        ]
    }

    fn on_boundary(&self, n: usize) -> bool {
        let c = self.coords(n);
        (0..3).any(|k| c[k] == 0 || c[k] + 1 == self.dims[k])
    }

    /// Values with boundary nodes pushed below `iso`.
    fn effective(&self, iso: f64) -> Vec<f64> {
        let below = iso - iso.abs().max(1.0) * 1e-9;
        self.values
            .iter()
            .enumerate()
            .map(|(n, &v)| if self.on_boundary(n) { v.min(below) } else { v })
            .collect()
    }
}

/// Edge-vertex cache shared by both polygonisers.
struct EdgeVertices<'a> {
    grid: &'a ScalarGrid,
    vals: &'a [f64],
    iso: f64,
    map: HashMap<(usize, usize), u32>,
    positions: Vec<[f64; 3]>,
}

impl EdgeVertices<'_> {
    fn crossing(&self, a: usize, b: usize) -> [f64; 3] {
        let (va, vb) = (self.vals[a], self.vals[b]);
        let t = ((self.iso - va) / (vb - va)).clamp(0.0, 1.0);
        let (pa, pb) = (self.grid.position(a), self.grid.position(b));
        [
            pa[0] + t * (pb[0] - pa[0]),
            pa[1] + t * (pb[1] - pa[1]),
            pa[2] + t * (pb[2] - pa[2]),
        ]
    }
    fn vertex(&mut self, a: usize, b: usize) -> u32 {
        let key = (a.min(b), a.max(b));
        if let Some(&v) = self.map.get(&key) {
            return v;
        }
        let p = self.crossing(key.0, key.1);
        let id = self.positions.len() as u32;
        self.positions.push(p);
        self.map.insert(key, id);
        id
    }
}

/// Marching tetrahedra (Kuhn split) of `grid` at level `iso`.
pub fn marching_tetrahedra(grid: &ScalarGrid, iso: f64) -> Mesh {
    let vals = grid.effective(iso);
    let mut ev = EdgeVertices {
        grid,
        vals: &vals,
        iso,
        map: HashMap::new(),
        positions: Vec::new(),
    };
    let tets = kuhn_tets();
    let mut tris: Vec<[u32; 3]> = Vec::new();
    let d = grid.dims;
    for k in 0..d[2] - 1 {
        for j in 0..d[1] - 1 {
            for i in 0..d[0] - 1 {
                let node =
                    |c: usize| grid.index(i + CORNER[c][0], j + CORNER[c][1], k + CORNER[c][2]);
                let inside: Vec<bool> = (0..8).map(|c| vals[node(c)] > iso).collect();
                if inside.iter().all(|&b| b) || inside.iter().all(|&b| !b) {
                    continue;
                }
                for (tv, sign) in &tets {
                    let n: [usize; 4] = tv.map(node);
                    let ins: [bool; 4] = tv.map(|c| inside[c]);
                    let count = ins.iter().filter(|&&b| b).count();
                    match count {
                        1 | 3 => {
                            // the lone vertex differs from the other three
                            let lone_val = count == 1;
                            let a = (0..4).position(|x| ins[x] == lone_val).unwrap_or(0);
                            let mut rest: Vec<usize> = (0..4).filter(|&x| x != a).collect();
                            let mut perm = [a, rest[0], rest[1], rest[2]];
                            if sign * parity(perm) < 0.0 {
                                rest.swap(1, 2);
                                perm = [a, rest[0], rest[1], rest[2]];
                            }
                            let t = [
                                ev.vertex(n[perm[0]], n[perm[1]]),
                                ev.vertex(n[perm[0]], n[perm[2]]),
                                ev.vertex(n[perm[0]], n[perm[3]]),
                            ];
                            // normal points away from the lone vertex
                            if lone_val {
                                tris.push(t);
                            } else {
                                tris.push([t[0], t[2], t[1]]);
                            }
                        }
                        2 => {
                            let ii: Vec<usize> = (0..4).filter(|&x| ins[x]).collect();
                            let mut oo: Vec<usize> = (0..4).filter(|&x| !ins[x]).collect();
                            if sign * parity([ii[0], ii[1], oo[0], oo[1]]) < 0.0 {
                                oo.swap(0, 1);
                            }
                            let (a, b, c, dd) = (n[ii[0]], n[ii[1]], n[oo[0]], n[oo[1]]);
                            let q = [
                                ev.vertex(a, c),
                                ev.vertex(a, dd),
                                ev.vertex(b, dd),
                                ev.vertex(b, c),
                            ];
                            push_quad(&mut tris, &ev.positions, q);
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    let positions = ev.positions;
    Mesh::with_group(positions, tris, "surface")
}

/// Naive surface nets of `grid` at level `iso`.
pub fn surface_nets(grid: &ScalarGrid, iso: f64) -> Mesh {
    let vals = grid.effective(iso);
    let d = grid.dims;
    let cube = |i: usize, j: usize, k: usize| i + (d[0] - 1) * (j + (d[1] - 1) * k);
    let ev = EdgeVertices {
        grid,
        vals: &vals,
        iso,
        map: HashMap::new(),
        positions: Vec::new(),
    };
    let mut cube_vertex: HashMap<usize, u32> = HashMap::new();
    let mut positions: Vec<[f64; 3]> = Vec::new();
    const EDGES: [[usize; 2]; 12] = [
        [0, 1],
        [2, 3],
        [4, 5],
        [6, 7],
        [0, 2],
        [1, 3],
        [4, 6],
        [5, 7],
        [0, 4],
        [1, 5],
        [2, 6],
        [3, 7],
    ];
    for k in 0..d[2] - 1 {
        for j in 0..d[1] - 1 {
            for i in 0..d[0] - 1 {
                let node =
                    |c: usize| grid.index(i + CORNER[c][0], j + CORNER[c][1], k + CORNER[c][2]);
                let mut sum = [0.0; 3];
                let mut cnt = 0;
                for e in EDGES {
                    let (a, b) = (node(e[0]), node(e[1]));
                    if (vals[a] > iso) != (vals[b] > iso) {
                        let p = ev.crossing(a, b);
                        for x in 0..3 {
                            sum[x] += p[x];
                        }
                        cnt += 1;
                    }
                }
                if cnt > 0 {
                    cube_vertex.insert(cube(i, j, k), positions.len() as u32);
                    positions.push(sum.map(|x| x / cnt as f64));
                }
            }
        }
    }
    let mut tris = Vec::new();
    // (nodes from 0: the edge along axis a needs only c[b], c[cc] >= 1;
    // starting every axis at 1 left holes where the surface is clipped)
    for k in 0..d[2] - 1 {
        for j in 0..d[1] - 1 {
            for i in 0..d[0] - 1 {
                let n0 = grid.index(i, j, k);
                let c = [i, j, k];
                for a in 0..3 {
                    let mut c1 = c;
                    c1[a] += 1;
                    let (b, cc) = ((a + 1) % 3, (a + 2) % 3);
                    if c1[a] >= d[a] || c[b] == 0 || c[cc] == 0 {
                        continue;
                    }
                    let n1 = grid.index(c1[0], c1[1], c1[2]);
                    let (in0, in1) = (vals[n0] > iso, vals[n1] > iso);
                    if in0 == in1 {
                        continue;
                    }
                    let offs = [(1, 1), (0, 1), (0, 0), (1, 0)];
                    let mut q = [0u32; 4];
                    let mut ok = true;
                    for (m, (ob, oc)) in offs.iter().enumerate() {
                        let mut cu = c;
                        cu[b] -= ob;
                        cu[cc] -= oc;
                        match cube_vertex.get(&cube(cu[0], cu[1], cu[2])) {
                            Some(&v) => q[m] = v,
                            None => ok = false,
                        }
                    }
                    if !ok {
                        continue;
                    }
                    if !in0 {
                        q = [q[0], q[3], q[2], q[1]];
                    }
                    push_quad(&mut tris, &positions, q);
                }
            }
        }
    }
    Mesh::with_group(positions, tris, "surface")
}
