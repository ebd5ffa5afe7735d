//! Polygonisation of implicit surfaces $\{x : f(x) = c\}$ sampled on a
//! regular grid (the paper 003 surfaces, Bloomenthal's polygoniser [4]).
//!
//! * [`marching_tetrahedra`]: every cube is split into the six Kuhn
//!   tetrahedra around its main diagonal (the same split in every cube, so
//!   faces match), the level set of the piecewise-linear interpolant is
//!   extracted per tetrahedron with vertices shared on grid edges. The
//!   result is the exact level set of a PL function on a simplicial complex:
//!   watertight and manifold. Orientation is combinatorial (from the
//!   tetrahedron's orientation and which vertices are inside), so it stays
//!   consistent even where triangles degenerate.
//! * [`surface_nets`]: naive surface nets, one vertex per sign-changing
//!   cube (mean of its edge crossings), one quad per sign-changing grid edge.
//!   Watertight and oriented; manifold except at ambiguous cube
//!   configurations (two sheets through one cube), which
//!   [`crate::mesh::topology::report`] counts.
//!
//! Inside is $f > c$ (convolution surfaces: field above threshold). Grid
//! nodes on the grid's boundary are treated as outside, so the output is
//! always closed.

use super::{Mesh, MeshError};
use std::collections::HashMap;

/// Largest number of grid nodes accepted.
pub const MAX_NODES: usize = 200_000_000;

/// A scalar field sampled on a regular grid.
#[derive(Clone, Debug)]
pub struct ScalarGrid {
    pub origin: [f64; 3],
    pub spacing: [f64; 3],
    pub dims: [usize; 3],
    /// x fastest, then y, then z.
    pub values: Vec<f64>,
}

impl ScalarGrid {
    /// Samples `f` on `dims` nodes spanning the box `lo`..`hi` (uses the
    /// available cores).
    pub fn sample<F: Fn([f64; 3]) -> f64 + Sync>(
        lo: [f64; 3],
        hi: [f64; 3],
        dims: [usize; 3],
        f: F,
    ) -> Result<ScalarGrid, MeshError> {
        if dims.iter().any(|&d| d < 3) {
            return Err(MeshError::Invalid(format!(
                "grid dimensions {dims:?}: at least 3 nodes per axis"
            )));
        }
        let total = dims[0].saturating_mul(dims[1]).saturating_mul(dims[2]);
        if total > MAX_NODES {
            return Err(MeshError::Invalid(format!(
                "grid of {total} nodes exceeds {MAX_NODES}"
            )));
        }
        if (0..3).any(|k| !(lo[k].is_finite() && hi[k].is_finite() && hi[k] > lo[k])) {
            return Err(MeshError::Invalid(format!("bad grid box {lo:?}..{hi:?}")));
        }
        let spacing = [
            (hi[0] - lo[0]) / (dims[0] - 1) as f64,
            (hi[1] - lo[1]) / (dims[1] - 1) as f64,
            (hi[2] - lo[2]) / (dims[2] - 1) as f64,
        ];
        let mut values = vec![0.0; total];
        let slab = dims[0] * dims[1];
        let threads = std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
            .min(dims[2]);
        let per = dims[2].div_ceil(threads);
        std::thread::scope(|scope| {
            for (c, chunk) in values.chunks_mut(per * slab).enumerate() {
                let f = &f;
                scope.spawn(move || {
                    for (n, v) in chunk.iter_mut().enumerate() {
                        let idx = c * per * slab + n;
                        let (i, j, k) = (idx % dims[0], (idx / dims[0]) % dims[1], idx / slab);
                        *v = f([
                            lo[0] + i as f64 * spacing[0],
                            lo[1] + j as f64 * spacing[1],
                            lo[2] + k as f64 * spacing[2],
                        ]);
                    }
                });
            }
        });
        if let Some(i) = values.iter().position(|v| !v.is_finite()) {
            return Err(MeshError::Invalid(format!(
                "field is not finite at grid node {i}"
            )));
        }
        Ok(ScalarGrid {
            origin: lo,
            spacing,
            dims,
            values,
        })
    }

    /// Linear index of node `(i, j, k)`.
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        i + self.dims[0] * (j + self.dims[1] * k)
    }

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

fn sq(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).powi(2)).sum()
}

/// Splits the quad `q` (cyclic, oriented) along its shorter diagonal.
fn push_quad(tris: &mut Vec<[u32; 3]>, pos: &[[f64; 3]], q: [u32; 4]) {
    let p = |i: usize| pos[q[i] as usize];
    if sq(p(0), p(2)) <= sq(p(1), p(3)) {
        tris.push([q[0], q[1], q[2]]);
        tris.push([q[0], q[2], q[3]]);
    } else {
        tris.push([q[0], q[1], q[3]]);
        tris.push([q[1], q[2], q[3]]);
    }
}

/// Corner offsets of the cube corner with bits (x, y, z).
const CORNER: [[usize; 3]; 8] = [
    [0, 0, 0],
    [1, 0, 0],
    [0, 1, 0],
    [1, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [0, 1, 1],
    [1, 1, 1],
];

/// The six Kuhn tetrahedra (corner bit indices) and their orientation sign.
fn kuhn_tets() -> [([usize; 4], f64); 6] {
    let perms = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let mut out = [([0usize; 4], 0.0); 6];
    for (t, p) in perms.iter().enumerate() {
        let c1 = 1 << p[0];
        let c2 = c1 | (1 << p[1]);
        let v = [0, c1, c2, 7];
        let f = |i: usize| CORNER[v[i]].map(|x| x as f64);
        let (a, b, c, d) = (f(0), f(1), f(2), f(3));
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let z = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
        let det = u[0] * (w[1] * z[2] - w[2] * z[1]) - u[1] * (w[0] * z[2] - w[2] * z[0])
            + u[2] * (w[0] * z[1] - w[1] * z[0]);
        out[t] = (v, det.signum());
    }
    out
}

/// Sign of the permutation `p` of 0..4.
fn parity(p: [usize; 4]) -> f64 {
    let mut s = 1.0;
    for i in 0..4 {
        for j in i + 1..4 {
            if p[i] > p[j] {
                s = -s;
            }
        }
    }
    s
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
    let n = tris.len();
    Mesh {
        positions,
        triangles: tris,
        tri_group: vec![0; n],
        groups: vec!["surface".into()],
    }
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
    for k in 1..d[2] - 1 {
        for j in 1..d[1] - 1 {
            for i in 1..d[0] - 1 {
                let n0 = grid.index(i, j, k);
                let c = [i, j, k];
                for a in 0..3 {
                    let mut c1 = c;
                    c1[a] += 1;
                    if c1[a] >= d[a] {
                        continue;
                    }
                    let n1 = grid.index(c1[0], c1[1], c1[2]);
                    let (in0, in1) = (vals[n0] > iso, vals[n1] > iso);
                    if in0 == in1 {
                        continue;
                    }
                    let (b, cc) = ((a + 1) % 3, (a + 2) % 3);
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
    let n = tris.len();
    Mesh {
        positions,
        triangles: tris,
        tri_group: vec![0; n],
        groups: vec!["surface".into()],
    }
}

/// Triangle shape statistics.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct TriangleQuality {
    pub triangles: usize,
    /// Smallest interior angle over all triangles (degrees).
    pub min_angle_deg: f64,
    /// Mean of the per-triangle smallest angle (degrees).
    pub mean_min_angle_deg: f64,
    /// Fraction of triangles whose smallest angle is below 10 degrees.
    pub frac_below_10deg: f64,
    /// Mean aspect ratio $\ell_{max}(a+b+c)/(4\sqrt3 A)$ (1 for an
    /// equilateral triangle; degenerate triangles excluded).
    pub mean_aspect: f64,
    /// Largest finite aspect ratio.
    pub max_aspect: f64,
    /// Triangles of zero area (aspect ratio infinite).
    pub degenerate: usize,
}

/// Angle statistics of `m`.
pub fn triangle_quality(m: &Mesh) -> TriangleQuality {
    let mut q = TriangleQuality {
        triangles: m.triangles.len(),
        min_angle_deg: 180.0,
        ..Default::default()
    };
    let mut below = 0usize;
    for t in &m.triangles {
        let p = t.map(|i| m.positions[i as usize]);
        let mut mn: f64 = 180.0;
        for c in 0..3 {
            let (a, b, o) = (p[(c + 1) % 3], p[(c + 2) % 3], p[c]);
            let u = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
            let v = [b[0] - o[0], b[1] - o[1], b[2] - o[2]];
            let nu = super::norm(u);
            let nv = super::norm(v);
            let ang = if nu > 0.0 && nv > 0.0 {
                (super::dot(u, v) / (nu * nv))
                    .clamp(-1.0, 1.0)
                    .acos()
                    .to_degrees()
            } else {
                0.0
            };
            mn = mn.min(ang);
        }
        q.min_angle_deg = q.min_angle_deg.min(mn);
        q.mean_min_angle_deg += mn;
        let l = [0, 1, 2].map(|c| {
            let (a, b) = (p[c], p[(c + 1) % 3]);
            super::norm([b[0] - a[0], b[1] - a[1], b[2] - a[2]])
        });
        let e1 = [p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]];
        let e2 = [p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]];
        let area = 0.5
            * super::norm([
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            ]);
        let lmax = l[0].max(l[1]).max(l[2]);
        if area > 1e-14 * lmax * lmax && area > 0.0 {
            let ar = lmax * (l[0] + l[1] + l[2]) / (4.0 * 3f64.sqrt() * area);
            q.mean_aspect += ar;
            q.max_aspect = q.max_aspect.max(ar);
        } else {
            q.degenerate += 1;
        }
        if mn < 10.0 {
            below += 1;
        }
    }
    if q.triangles > 0 {
        q.mean_min_angle_deg /= q.triangles as f64;
        q.frac_below_10deg = below as f64 / q.triangles as f64;
        let good = q.triangles - q.degenerate;
        if good > 0 {
            q.mean_aspect /= good as f64;
        }
    } else {
        q.min_angle_deg = 0.0;
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::topology::report;

    fn sphere_grid(n: usize) -> ScalarGrid {
        ScalarGrid::sample([-1.3; 3], [1.3; 3], [n; 3], |p| {
            1.0 - (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()
        })
        .expect("grid")
    }

    #[test]
    fn sphere_is_closed_manifold_oriented_outward() {
        let g = sphere_grid(20);
        for m in [marching_tetrahedra(&g, 0.0), surface_nets(&g, 0.0)] {
            let r = report(&m);
            assert!(r.watertight && r.manifold && r.oriented, "{r:?}");
            assert_eq!(r.euler, 2);
            let v = m.signed_volume();
            let exact = 4.0 / 3.0 * std::f64::consts::PI;
            assert!((v - exact).abs() / exact < 0.05, "volume {v}");
        }
    }

    #[test]
    fn quality_of_known_triangles() {
        let h = 3f64.sqrt() / 2.0;
        let m = Mesh {
            positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.5, h, 0.0], [2.0, 0.0, 0.0]],
            triangles: vec![[0, 1, 2], [0, 1, 3]],
            tri_group: vec![0, 0],
            groups: vec!["s".into()],
        };
        let q = triangle_quality(&m);
        assert_eq!(q.triangles, 2);
        assert_eq!(q.degenerate, 1);
        assert!((q.mean_aspect - 1.0).abs() < 1e-12, "{q:?}");
        assert!((q.max_aspect - 1.0).abs() < 1e-12);
        assert_eq!(q.min_angle_deg, 0.0);
        assert!((q.mean_min_angle_deg - 30.0).abs() < 1e-9);
        assert_eq!(q.frac_below_10deg, 0.5);
    }
}
