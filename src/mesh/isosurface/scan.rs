//! The scanning machinery shared by both polygonisers: cube corners, the
//! Kuhn split, the boundary-aware sampler, inside flags per layer, mixed
//! cubes per row, and vertex sharing per slab.

use super::*;

/// Corner offsets of the cube corner with bits (x, y, z).
pub(super) const CORNER: [[usize; 3]; 8] = [
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
pub(super) fn kuhn_tets() -> [([usize; 4], f64); 6] {
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
pub(super) fn parity(p: [usize; 4]) -> f64 {
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
pub(super) struct Sampler<'a> {
    pub(super) grid: &'a ScalarGrid,
    pub(super) iso: f64,
    pub(super) below: f64,
}

impl<'a> Sampler<'a> {
    pub(super) fn new(grid: &'a ScalarGrid, iso: f64) -> Self {
        Sampler {
            grid,
            iso,
            below: iso - iso.abs().max(1.0) * 1e-9,
        }
    }

    pub(super) fn value(&self, c: [usize; 3]) -> f64 {
        let d = self.grid.dims;
        let v = self.grid.values[self.grid.index(c[0], c[1], c[2])];
        if (0..3).any(|a| c[a] == 0 || c[a] + 1 == d[a]) {
            v.min(self.below)
        } else {
            v
        }
    }

    pub(super) fn position(&self, c: [usize; 3]) -> [f64; 3] {
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
    pub(super) fn crossing(&self, lo: [usize; 3], dir: usize) -> [f64; 3] {
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
pub(super) fn inside_layer(grid: &ScalarGrid, iso: f64, k: usize, out: &mut [u8]) {
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
pub(super) fn mixed_cubes_in_row(
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
pub(super) struct CubeEdge {
    pub(super) corner: u8,
    pub(super) dir: u8,
}

impl CubeEdge {
    pub(super) fn between(a: usize, b: usize) -> CubeEdge {
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
pub(super) struct TetPiece {
    pub(super) quad: bool,
    pub(super) flip: bool,
    pub(super) edges: [CubeEdge; 4],
}

/// Marching-tetrahedra pieces of a cube for each of the 256 inside masks,
/// tetrahedron by tetrahedron.
pub(super) struct MtCases {
    pub(super) count: [u8; 256],
    pub(super) pieces: [[TetPiece; 6]; 256],
}

pub(super) fn mt_cases() -> &'static MtCases {
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
pub(super) struct SlabVertices<'a> {
    pub(super) sampler: Sampler<'a>,
    pub(super) slabs: [Vec<u32>; 2],
    pub(super) touched: [Vec<usize>; 2],
    pub(super) positions: Vec<[f64; 3]>,
}

impl SlabVertices<'_> {
    /// Forgets the vertices of the slab of layer `k` (before reusing it).
    pub(super) fn clear_layer(&mut self, k: usize) {
        let p = k & 1;
        for &slot in &self.touched[p] {
            self.slabs[p][slot] = u32::MAX;
        }
        self.touched[p].clear();
    }

    /// The vertex on edge `e` of `cube`, created on first use.
    #[inline(always)]
    pub(super) fn vertex(&mut self, cube: [usize; 3], e: CubeEdge) -> u32 {
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
    pub(super) fn create(&mut self, lo: [usize; 3], dir: usize, slot: usize) -> u32 {
        let p = lo[2] & 1;
        let id = self.positions.len() as u32;
        self.positions.push(self.sampler.crossing(lo, dir));
        self.slabs[p][slot] = id;
        self.touched[p].push(slot);
        id
    }
}
