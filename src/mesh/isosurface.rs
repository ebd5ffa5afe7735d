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

/// Field values and positions of grid nodes by integer coordinates, with
/// boundary nodes pushed below `iso` (consistent with [`inside_layer`]).
struct Sampler<'a> {
    grid: &'a ScalarGrid,
    iso: f64,
    below: f64,
}

impl<'a> Sampler<'a> {
    fn new(grid: &'a ScalarGrid, iso: f64) -> Self {
        Sampler {
            grid,
            iso,
            below: iso - iso.abs().max(1.0) * 1e-9,
        }
    }

    fn value(&self, c: [usize; 3]) -> f64 {
        let d = self.grid.dims;
        let v = self.grid.values[self.grid.index(c[0], c[1], c[2])];
        if (0..3).any(|a| c[a] == 0 || c[a] + 1 == d[a]) {
            v.min(self.below)
        } else {
            v
        }
    }

    fn position(&self, c: [usize; 3]) -> [f64; 3] {
        let (o, h) = (self.grid.origin, self.grid.spacing);
        [
            o[0] + c[0] as f64 * h[0],
            o[1] + c[1] as f64 * h[1],
            o[2] + c[2] as f64 * h[2],
        ]
    }

    /// Level crossing on the grid edge from node `lo` to `lo + dir`, where
    /// `dir` holds offset bits (x, y, z): linear interpolation of the values.
    #[inline(never)]
    fn crossing(&self, lo: [usize; 3], dir: usize) -> [f64; 3] {
        let hi = [
            lo[0] + (dir & 1),
            lo[1] + ((dir >> 1) & 1),
            lo[2] + (dir >> 2),
        ];
        let (va, vb) = (self.value(lo), self.value(hi));
        let t = ((self.iso - va) / (vb - va)).clamp(0.0, 1.0);
        let (pa, pb) = (self.position(lo), self.position(hi));
        [
            pa[0] + t * (pb[0] - pa[0]),
            pa[1] + t * (pb[1] - pa[1]),
            pa[2] + t * (pb[2] - pa[2]),
        ]
    }
}

/// Inside flags (`1` where `f > iso`) of the nodes of layer `k`; nodes on
/// the grid's boundary are outside (so the output is closed).
fn inside_layer(grid: &ScalarGrid, iso: f64, k: usize, out: &mut [u8]) {
    let d = grid.dims;
    out.fill(0);
    if k == 0 || k + 1 == d[2] {
        return;
    }
    for j in 1..d[1] - 1 {
        let r = d[0] * (j + d[1] * k);
        let (o, v) = (
            &mut out[d[0] * j + 1..d[0] * (j + 1) - 1],
            &grid.values[r + 1..r + d[0] - 1],
        );
        for (o, &v) in o.iter_mut().zip(v) {
            *o = u8::from(v > iso);
        }
    }
}

/// Calls `f(i, mask)` for the cubes `(i, j, k)` of a row that are neither
/// fully inside nor fully outside, `mask` holding bit `c` when cube corner
/// `c` is inside; `lower` and `upper` are the [`inside_layer`] flags of node
/// layers `k` and `k + 1`.
fn mixed_cubes_in_row(
    lower: &[u8],
    upper: &[u8],
    nx: usize,
    j: usize,
    mut f: impl FnMut(usize, u8),
) {
    let (a, b) = (
        &lower[nx * j..nx * (j + 1)],
        &lower[nx * (j + 1)..nx * (j + 2)],
    );
    let (c, e) = (
        &upper[nx * j..nx * (j + 1)],
        &upper[nx * (j + 1)..nx * (j + 2)],
    );
    // corners with x = 0 of the cube at i (bits 0, 2, 4, 6)
    let col = |i: usize| a[i] | (b[i] << 2) | (c[i] << 4) | (e[i] << 6);
    let mut left = col(0);
    for i in 0..nx - 1 {
        let right = col(i + 1);
        let mask = left | (right << 1);
        left = right;
        if mask != 0 && mask != 255 {
            f(i, mask);
        }
    }
}

/// A grid edge of a cube: its lower corner (bits x, y, z) and the offset
/// bits to its upper corner.
#[derive(Clone, Copy, Debug, Default)]
struct CubeEdge {
    corner: u8,
    dir: u8,
}

impl CubeEdge {
    fn between(a: usize, b: usize) -> CubeEdge {
        let (lo, hi) = (a.min(b), a.max(b));
        debug_assert_eq!(lo & hi, lo, "Kuhn edges join nested corners");
        CubeEdge {
            corner: lo as u8,
            dir: (lo ^ hi) as u8,
        }
    }
}

/// One output piece of a tetrahedron: a triangle (edges 0..3, reversed if
/// `flip`) or a quad (edges 0..4), with its crossing vertices created in
/// edge order.
#[derive(Clone, Copy, Debug, Default)]
struct TetPiece {
    quad: bool,
    flip: bool,
    edges: [CubeEdge; 4],
}

/// Marching-tetrahedra pieces of a cube for each of the 256 inside masks,
/// tetrahedron by tetrahedron.
struct MtCases {
    count: [u8; 256],
    pieces: [[TetPiece; 6]; 256],
}

fn mt_cases() -> &'static MtCases {
    static CASES: std::sync::OnceLock<MtCases> = std::sync::OnceLock::new();
    CASES.get_or_init(|| {
        let tets = kuhn_tets();
        let mut cases = MtCases {
            count: [0; 256],
            pieces: [[TetPiece::default(); 6]; 256],
        };
        for mask in 0..256usize {
            let inside = |c: usize| (mask >> c) & 1 == 1;
            let mut m = 0;
            for (tv, sign) in &tets {
                let ins: [bool; 4] = tv.map(inside);
                let count = ins.iter().filter(|&&b| b).count();
                let piece = match count {
                    1 | 3 => {
                        // the lone vertex differs from the other three
                        let lone_val = count == 1;
                        let a = (0..4).position(|x| ins[x] == lone_val).unwrap_or(0);
                        let mut rest: Vec<usize> = (0..4).filter(|&x| x != a).collect();
                        if sign * parity([a, rest[0], rest[1], rest[2]]) < 0.0 {
                            rest.swap(1, 2);
                        }
                        let e = |x: usize| CubeEdge::between(tv[a], tv[rest[x]]);
                        // normal points away from the lone vertex
                        TetPiece {
                            quad: false,
                            flip: !lone_val,
                            edges: [e(0), e(1), e(2), CubeEdge::default()],
                        }
                    }
                    2 => {
                        let ii: Vec<usize> = (0..4).filter(|&x| ins[x]).collect();
                        let mut oo: Vec<usize> = (0..4).filter(|&x| !ins[x]).collect();
                        if sign * parity([ii[0], ii[1], oo[0], oo[1]]) < 0.0 {
                            oo.swap(0, 1);
                        }
                        let (a, b, c, dd) = (tv[ii[0]], tv[ii[1]], tv[oo[0]], tv[oo[1]]);
                        let e = CubeEdge::between;
                        TetPiece {
                            quad: true,
                            flip: false,
                            edges: [e(a, c), e(a, dd), e(b, dd), e(b, c)],
                        }
                    }
                    _ => continue,
                };
                cases.pieces[mask][m] = piece;
                m += 1;
            }
            cases.count[mask] = m as u8;
        }
        cases
    })
}

/// Crossing vertices of marching tetrahedra, shared through the grid edge
/// they lie on. Edges are keyed by lower node and direction bits; only the
/// node layers `k` and `k + 1` of the current cube layer are live, stored in
/// two slabs indexed by layer parity.
struct SlabVertices<'a> {
    sampler: Sampler<'a>,
    slabs: [Vec<u32>; 2],
    touched: [Vec<usize>; 2],
    positions: Vec<[f64; 3]>,
}

impl SlabVertices<'_> {
    /// Forgets the vertices of the slab of layer `k` (before reusing it).
    fn clear_layer(&mut self, k: usize) {
        let p = k & 1;
        for &slot in &self.touched[p] {
            self.slabs[p][slot] = u32::MAX;
        }
        self.touched[p].clear();
    }

    /// The vertex on edge `e` of `cube`, created on first use.
    #[inline(always)]
    fn vertex(&mut self, cube: [usize; 3], e: CubeEdge) -> u32 {
        let c = e.corner as usize;
        let lo = [
            cube[0] + (c & 1),
            cube[1] + ((c >> 1) & 1),
            cube[2] + (c >> 2),
        ];
        let d = self.sampler.grid.dims;
        let p = lo[2] & 1;
        let slot = ((lo[0] + d[0] * lo[1]) << 3) | e.dir as usize;
        match self.slabs[p][slot] {
            u32::MAX => self.create(lo, e.dir as usize, slot),
            v => v,
        }
    }

    #[inline(always)]
    fn create(&mut self, lo: [usize; 3], dir: usize, slot: usize) -> u32 {
        let p = lo[2] & 1;
        let id = self.positions.len() as u32;
        self.positions.push(self.sampler.crossing(lo, dir));
        self.slabs[p][slot] = id;
        self.touched[p].push(slot);
        id
    }
}

/// Marching tetrahedra (Kuhn split) of `grid` at level `iso`.
pub fn marching_tetrahedra(grid: &ScalarGrid, iso: f64) -> Mesh {
    let d = grid.dims;
    let cases = mt_cases();
    let slab = d[0] * d[1];
    let mut ins = [vec![0u8; slab], vec![0u8; slab]];
    inside_layer(grid, iso, 0, &mut ins[0]);
    let mut ev = SlabVertices {
        sampler: Sampler::new(grid, iso),
        slabs: [vec![u32::MAX; slab << 3], vec![u32::MAX; slab << 3]],
        touched: [Vec::new(), Vec::new()],
        positions: Vec::new(),
    };
    let mut tris: Vec<[u32; 3]> = Vec::new();
    for k in 0..d[2] - 1 {
        // the slabs of layer k - 1 become those of layer k + 1
        ev.clear_layer(k + 1);
        inside_layer(grid, iso, k + 1, &mut ins[(k + 1) & 1]);
        let (lower, upper) = (&ins[k & 1], &ins[(k + 1) & 1]);
        for j in 0..d[1] - 1 {
            mixed_cubes_in_row(lower, upper, d[0], j, |i, mask| {
                let m = mask as usize;
                for p in &cases.pieces[m][..cases.count[m] as usize] {
                    let cube = [i, j, k];
                    if p.quad {
                        let q = p.edges.map(|e| ev.vertex(cube, e));
                        push_quad(&mut tris, &ev.positions, q);
                    } else {
                        let t = [0, 1, 2].map(|x| ev.vertex(cube, p.edges[x]));
                        tris.push(if p.flip { [t[0], t[2], t[1]] } else { t });
                    }
                }
            });
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

/// The twelve cube edges (corner bits).
const CUBE_EDGES: [[usize; 2]; 12] = [
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

/// Naive surface nets of `grid` at level `iso`.
///
/// One pass over the cubes: the vertex of cube `(i, j, k)` is placed, then
/// the quads dual to the sign-changing grid edges leaving node `(i, j, k)`
/// in +x, +y, +z are emitted (their four cubes precede it in scan order and
/// lie in cube layers `k - 1` and `k`).
pub fn surface_nets(grid: &ScalarGrid, iso: f64) -> Mesh {
    let d = grid.dims;
    // edge crossings, each shared by up to four cubes
    let slab = d[0] * d[1];
    let mut crossings = SlabVertices {
        sampler: Sampler::new(grid, iso),
        slabs: [vec![u32::MAX; slab << 3], vec![u32::MAX; slab << 3]],
        touched: [Vec::new(), Vec::new()],
        positions: Vec::new(),
    };
    let mut ins = [vec![0u8; d[0] * d[1]], vec![0u8; d[0] * d[1]]];
    inside_layer(grid, iso, 0, &mut ins[0]);
    // cube vertices of cube layers k - 1 and k, by layer parity
    let row = d[0] - 1;
    let layer = row * (d[1] - 1);
    let mut cube_vertex = vec![u32::MAX; 2 * layer];
    let mut positions: Vec<[f64; 3]> = Vec::new();
    let mut tris = Vec::new();
    for k in 0..d[2] - 1 {
        let cur = (k & 1) * layer;
        cube_vertex[cur..cur + layer].fill(u32::MAX);
        crossings.clear_layer(k + 1);
        inside_layer(grid, iso, k + 1, &mut ins[(k + 1) & 1]);
        let (lower, upper) = (&ins[k & 1], &ins[(k + 1) & 1]);
        for j in 0..d[1] - 1 {
            mixed_cubes_in_row(lower, upper, d[0], j, |i, mask| {
                let mut sum = [0.0; 3];
                let mut cnt = 0;
                for [a, b] in CUBE_EDGES {
                    if ((mask >> a) ^ (mask >> b)) & 1 == 1 {
                        let e = CubeEdge {
                            corner: a as u8,
                            dir: (a ^ b) as u8,
                        };
                        let v = crossings.vertex([i, j, k], e) as usize;
                        let p = crossings.positions[v];
                        for x in 0..3 {
                            sum[x] += p[x];
                        }
                        cnt += 1;
                    }
                }
                cube_vertex[cur + i + row * j] = positions.len() as u32;
                positions.push(sum.map(|x| x / cnt as f64));
                let c = [i, j, k];
                let in0 = mask & 1;
                for a in 0..3 {
                    let (b, cc) = ((a + 1) % 3, (a + 2) % 3);
                    // the edge from corner 0 to corner 1 << a of this cube
                    if (mask >> (1 << a)) & 1 == in0 || c[b] == 0 || c[cc] == 0 {
                        continue;
                    }
                    let offs = [(1, 1), (0, 1), (0, 0), (1, 0)];
                    let mut q = [0u32; 4];
                    let mut ok = true;
                    for (m, (ob, oc)) in offs.iter().enumerate() {
                        let mut cu = c;
                        cu[b] -= ob;
                        cu[cc] -= oc;
                        match cube_vertex[(cu[2] & 1) * layer + cu[0] + row * cu[1]] {
                            u32::MAX => ok = false,
                            v => q[m] = v,
                        }
                    }
                    if !ok {
                        continue;
                    }
                    if in0 == 0 {
                        q = [q[0], q[3], q[2], q[1]];
                    }
                    push_quad(&mut tris, &positions, q);
                }
            });
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

    /// Grids whose level sets touch the box, tie with the level at nodes
    /// (quantised values), have several components and uneven dimensions.
    fn awkward_grids() -> Vec<(ScalarGrid, f64)> {
        let wavy = |p: [f64; 3]| (3.0 * p[0]).sin() * (2.0 * p[1]).cos() + (4.0 * p[2]).sin();
        vec![
            (sphere_grid(20), 0.0),
            (sphere_grid(3), 0.0),
            (
                ScalarGrid::sample([-1.0, -1.5, -0.7], [1.2, 1.0, 0.9], [17, 23, 11], wavy)
                    .expect("grid"),
                0.3,
            ),
            (
                ScalarGrid::sample([-1.0; 3], [1.0; 3], [13, 9, 15], |p| {
                    (4.0 * wavy(p)).round() / 4.0
                })
                .expect("grid"),
                0.0,
            ),
            (
                ScalarGrid::sample([-2.0; 3], [2.0; 3], [10, 10, 10], |p| {
                    -1e4 * (p[0] * p[0] + p[1] * p[1] - p[2])
                })
                .expect("grid"),
                -2.5e3,
            ),
        ]
    }

    #[test]
    fn slab_polygonisers_match_the_hash_map_reference_exactly() {
        for (g, iso) in awkward_grids() {
            for (ours, theirs) in [
                (
                    marching_tetrahedra(&g, iso),
                    reference::marching_tetrahedra(&g, iso),
                ),
                (surface_nets(&g, iso), reference::surface_nets(&g, iso)),
            ] {
                assert!(!ours.triangles.is_empty() || g.dims[0] == 3);
                assert_eq!(ours.triangles, theirs.triangles, "dims {:?}", g.dims);
                assert_eq!(ours.positions, theirs.positions, "dims {:?}", g.dims);
            }
        }
    }

    #[test]
    fn awkward_grids_give_closed_oriented_surfaces() {
        for (g, iso) in awkward_grids() {
            let r = report(&marching_tetrahedra(&g, iso));
            assert!(r.watertight && r.manifold && r.oriented, "{r:?}");
            // surface nets: also where the level set is clipped by the box
            // (may be non-manifold at ambiguous cubes)
            let r = report(&surface_nets(&g, iso));
            assert!(r.watertight && r.oriented, "{:?} {r:?}", g.dims);
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

/// The straightforward hash-map implementations the polygonisers above
/// replaced, kept to check that the outputs are identical.
#[cfg(test)]
mod reference {
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
        let n = tris.len();
        Mesh {
            positions,
            triangles: tris,
            tri_group: vec![0; n],
            groups: vec!["surface".into()],
        }
    }
}
