//! The face template: which vertices of the MakeHuman base topology make
//! the face region, their `(u, v)`, and the material points the curve
//! network is sampled at. Computed once from the bundled base mesh; since
//! every accepted input has the same vertices and triangles, the template
//! applies to any of them (its points are barycentric combinations of
//! vertex indices, so the network moves with the expression).
//!
//! **Region.** The base faces `+z`. A body vertex belongs to the face when
//! (1) its front projection `(x, y)` lies in the window `|x| <= a`,
//! `y_lo(x) <= y <= y_hi` with `y_lo(x) = y_chin + (y_jaw - y_chin)(x/a)^2`
//! ([`Window`]), (2) it is the frontmost surface point over its `(x, y)`
//! (no skin in front of it), (3) its normal faces forward (`n_z > 0`), and
//! (4) it is connected through such vertices to the tip of the nose. (4)
//! drops the back walls of the eye sockets, visible through the openings
//! but reached from the face only over the hidden inner side of the lids.
//!
//! **Parameters.** `nu` columns of equal width `2a/nu` in `x` and `nv`
//! rows of equal height in `w = (y - y_lo(x)) / (y_hi - y_lo(x))`: a
//! vertex in column `i`, row `j` has `u = (x + a)/(2a) nu - i`, `v = w nv -
//! j`. The curves are the column lines `x = x_i`, sampled at `w = k/(nv
//! m)` on the frontmost region triangle over the point (none over the eye
//! openings: such samples are skipped and the curve's spline bridges the
//! opening; a node there slides along its column to the nearest covered
//! point). Cross derivatives along a column come from the points at
//! `x_i +- h` with the same `w`, `h = 2a/(2 nu)` (half a column; one-sided
//! `x_i, x_i + h, x_i + 2h` on the outer columns).

use super::FaceError;
use crate::mesh::Mesh;
use std::collections::VecDeque;

/// The face window in the base's front projection (decimetres). Chosen by
/// looking at the base head's front view (brow to chin, cheek to cheek,
/// inside the part of the head that faces the viewer), not tuned to any
/// error: `a` half width, `y_hi` the forehead line, `y_chin` the chin on
/// the midline, `y_jaw` the lower edge at `|x| = a`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Window {
    pub a: f64,
    pub y_hi: f64,
    pub y_chin: f64,
    pub y_jaw: f64,
}

/// The window of the bundled base (see [`Window`]).
pub const BASE_WINDOW: Window = Window {
    a: 0.56,
    y_hi: 7.55,
    y_chin: 6.30,
    y_jaw: 6.72,
};

impl Window {
    pub fn y_lo(&self, x: f64) -> f64 {
        let s = x / self.a;
        self.y_chin + (self.y_jaw - self.y_chin) * s * s
    }

    /// `(x, y)` to the window's unit square `(s, w)`, `s = (x + a)/(2a)`.
    pub fn unit(&self, x: f64, y: f64) -> (f64, f64) {
        let lo = self.y_lo(x);
        ((x + self.a) / (2.0 * self.a), (y - lo) / (self.y_hi - lo))
    }

    /// The inverse of [`Window::unit`].
    pub fn point(&self, s: f64, w: f64) -> (f64, f64) {
        let x = -self.a + 2.0 * self.a * s;
        let lo = self.y_lo(x);
        (x, lo + w * (self.y_hi - lo))
    }
}

/// How far (dm) the sampled region reaches beyond the window, so that
/// the curves on the window's edge and their one-sided derivative points
/// lie on covered triangles.
pub const MARGIN: f64 = 0.08;

/// A point of the surface as a barycentric combination of three vertices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub tri: [u32; 3],
    pub w: [f64; 3],
}

impl Material {
    pub fn eval(&self, p: &[[f64; 3]]) -> [f64; 3] {
        std::array::from_fn(|k| (0..3).map(|i| self.w[i] * p[self.tri[i] as usize][k]).sum())
    }
}

/// Frontmost-point queries over the body triangles' front projection.
pub struct Front<'a> {
    mesh: &'a Mesh,
    tris: Vec<u32>,
    lo: [f64; 2],
    cell: f64,
    dims: [usize; 2],
    cells: Vec<Vec<u32>>,
}

impl<'a> Front<'a> {
    /// Buckets the triangles `tris` of `mesh` in a grid of `cell`-sized squares.
    pub fn new(mesh: &'a Mesh, tris: Vec<u32>, cell: f64) -> Front<'a> {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for &t in &tris {
            for &i in &mesh.triangles[t as usize] {
                let p = mesh.positions[i as usize];
                for k in 0..2 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
        let dims = [0, 1].map(|k| (((hi[k] - lo[k]) / cell).ceil() as usize).clamp(1, 4096));
        let mut f = Front {
            mesh,
            tris: Vec::new(),
            lo,
            cell,
            dims,
            cells: vec![Vec::new(); dims[0] * dims[1]],
        };
        for &t in &tris {
            let ps = mesh.triangles[t as usize].map(|i| mesh.positions[i as usize]);
            let (a, b) = (
                f.index(
                    ps.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min),
                    ps.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min),
                ),
                f.index(
                    ps.iter().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max),
                    ps.iter().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max),
                ),
            );
            for ix in a[0]..=b[0] {
                for iy in a[1]..=b[1] {
                    f.cells[ix * dims[1] + iy].push(t);
                }
            }
        }
        f.tris = tris;
        f
    }

    fn index(&self, x: f64, y: f64) -> [usize; 2] {
        let c = |v: f64, k: usize| {
            (((v - self.lo[k]) / self.cell).floor().max(0.0) as usize).min(self.dims[k] - 1)
        };
        [c(x, 0), c(y, 1)]
    }

    /// The frontmost (largest `z`) triangle over `(x, y)`: its index, the
    /// barycentric weights and `z`.
    pub fn hit(&self, x: f64, y: f64) -> Option<(u32, [f64; 3], f64)> {
        let [ix, iy] = self.index(x, y);
        let mut best: Option<(u32, [f64; 3], f64)> = None;
        for &t in &self.cells[ix * self.dims[1] + iy] {
            let ps = self.mesh.triangles[t as usize].map(|i| self.mesh.positions[i as usize]);
            let Some(w) = barycentric(ps, x, y) else {
                continue;
            };
            let z = w[0] * ps[0][2] + w[1] * ps[1][2] + w[2] * ps[2][2];
            if best.is_none_or(|b| z > b.2) {
                best = Some((t, w, z));
            }
        }
        best
    }
}

/// Barycentric weights of `(x, y)` in the projected triangle (`None`
/// outside or degenerate; edges count as inside).
fn barycentric(p: [[f64; 3]; 3], x: f64, y: f64) -> Option<[f64; 3]> {
    let d = (p[1][1] - p[2][1]) * (p[0][0] - p[2][0]) + (p[2][0] - p[1][0]) * (p[0][1] - p[2][1]);
    if d.abs() < 1e-300 {
        return None;
    }
    let a = ((p[1][1] - p[2][1]) * (x - p[2][0]) + (p[2][0] - p[1][0]) * (y - p[2][1])) / d;
    let b = ((p[2][1] - p[0][1]) * (x - p[2][0]) + (p[0][0] - p[2][0]) * (y - p[2][1])) / d;
    let c = 1.0 - a - b;
    let eps = -1e-12;
    (a >= eps && b >= eps && c >= eps).then_some([a, b, c])
}

/// The face region of a mesh (the base): per vertex, whether it is in it.
pub fn face_region(m: &Mesh, body: &[bool], win: &Window) -> Result<Vec<bool>, FaceError> {
    let n = m.positions.len();
    let normals = m.vertex_normals();
    let low = win.y_chin - 0.5 * (win.y_hi - win.y_chin);
    let head: Vec<u32> = (0..m.triangles.len() as u32)
        .filter(|&t| {
            body[t as usize]
                && m.triangles[t as usize]
                    .iter()
                    .all(|&i| m.positions[i as usize][1] > low)
        })
        .collect();
    let front = Front::new(m, head.clone(), 0.05);
    let inside = |p: [f64; 3]| {
        let (s, w) = win.unit(p[0], p[1]);
        (0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&w)
    };
    let mut cand = vec![false; n];
    for &t in &head {
        for &i in &m.triangles[t as usize] {
            let i = i as usize;
            let p = m.positions[i];
            if cand[i] || !inside(p) || normals[i][2] <= 0.0 {
                continue;
            }
            let visible = front.hit(p[0], p[1]).is_some_and(|h| p[2] >= h.2 - 1e-9);
            cand[i] = visible;
        }
    }
    // connected to the nose tip (the frontmost candidate)
    let tip = (0..n)
        .filter(|&i| cand[i])
        .max_by(|&a, &b| m.positions[a][2].total_cmp(&m.positions[b][2]))
        .ok_or(FaceError::Template("no face region in the window".into()))?;
    let mut adj = vec![Vec::new(); n];
    for &t in &head {
        let tri = m.triangles[t as usize];
        for k in 0..3 {
            let (a, b) = (tri[k] as usize, tri[(k + 1) % 3] as usize);
            adj[a].push(b);
            adj[b].push(a);
        }
    }
    let mut region = vec![false; n];
    region[tip] = true;
    let mut queue = VecDeque::from([tip]);
    while let Some(i) = queue.pop_front() {
        for &j in &adj[i] {
            if cand[j] && !region[j] {
                region[j] = true;
                queue.push_back(j);
            }
        }
    }
    Ok(region)
}

/// One sample of a column curve: its parameter `w` along the column, its
/// point, and the three points and weights of its cross derivatives.
#[derive(Clone, Debug)]
pub struct Sample {
    pub w: f64,
    pub point: Material,
    pub stencil: [Material; 3],
    /// Weights of the stencil points in `S_u` and in `S_uu` (per unit `u`).
    pub first: [f64; 3],
    pub second: [f64; 3],
}

/// A face-region vertex and where it sits in the network.
#[derive(Clone, Copy, Debug)]
pub struct Placed {
    pub vertex: u32,
    pub column: usize,
    pub row: usize,
    pub u: f64,
    pub v: f64,
}

/// The face template for `nu` columns and `nv` rows (see the module doc).
#[derive(Clone, Debug)]
pub struct FaceTemplate {
    pub window: Window,
    pub nu: usize,
    pub nv: usize,
    /// Samples per row along a column.
    pub per_row: usize,
    pub vertices: Vec<Placed>,
    /// `columns[i]`: the samples of column line `i`, `i = 0..=nu`, by `w`;
    /// the nodes are the samples with `w = j / nv`.
    pub columns: Vec<Vec<Sample>>,
    /// Highest vertex of the body and lowest face vertex (head height).
    pub top: u32,
    pub chin: u32,
}

impl FaceTemplate {
    /// The template of `base` (the full MakeHuman mesh, groups included;
    /// `body[t]` marks the skin triangles).
    pub fn new(
        base: &Mesh,
        body: &[bool],
        win: Window,
        (nu, nv, per_row): (usize, usize, usize),
    ) -> Result<FaceTemplate, FaceError> {
        // the region over a slightly larger window: triangles across the
        // window's edge are covered, so the outer columns can be sampled
        let d = MARGIN;
        let wide = Window {
            a: win.a + d,
            y_hi: win.y_hi + d,
            y_chin: win.y_chin - d,
            y_jaw: win.y_jaw - d,
        };
        let region = face_region(base, body, &wide)?;
        let tris: Vec<u32> = (0..base.triangles.len() as u32)
            .filter(|&t| {
                base.triangles[t as usize]
                    .iter()
                    .all(|&i| region[i as usize])
            })
            .collect();
        let front = Front::new(base, tris, 0.05);
        let covered = |s: f64, w: f64| {
            let (x, y) = win.point(s, w);
            front.hit(x, y).map(|(t, w, _)| Material {
                tri: base.triangles[t as usize],
                w,
            })
        };
        let h = 0.5 / nu as f64;
        let mut columns = Vec::with_capacity(nu + 1);
        for i in 0..=nu {
            let s = i as f64 / nu as f64;
            let (offsets, first, second) = stencil(i, nu, h);
            let at = |w: f64| -> Option<(Material, [Material; 3])> {
                let p = covered(s, w)?;
                let st = [
                    covered(s + offsets[0], w)?,
                    covered(s + offsets[1], w)?,
                    covered(s + offsets[2], w)?,
                ];
                Some((p, st))
            };
            let total = nv * per_row;
            let mut col = Vec::new();
            for k in 0..=total {
                let w = k as f64 / total as f64;
                let found = if k % per_row == 0 {
                    // a node: the nearest covered point along the column
                    let step = 1.0 / (8 * total) as f64;
                    (0..8 * total).find_map(|d| {
                        let d = d as f64 * step;
                        [w + d, w - d]
                            .into_iter()
                            .filter(|x| (0.0..=1.0).contains(x))
                            .find_map(at)
                    })
                } else {
                    at(w)
                };
                match found {
                    Some((point, stencil)) => col.push(Sample {
                        w,
                        point,
                        stencil,
                        first,
                        second,
                    }),
                    None if k % per_row == 0 => {
                        return Err(FaceError::Template(format!(
                            "column {i} has no face point near node {}",
                            k / per_row
                        )))
                    }
                    None => {}
                }
            }
            columns.push(col);
        }
        let vertices = place(base, &region, &win, nu, nv);
        let (top, chin) = top_and_chin(base, body, &vertices);
        Ok(FaceTemplate {
            window: win,
            nu,
            nv,
            per_row,
            vertices,
            columns,
            top,
            chin,
        })
    }
}

/// The highest body vertex (the top of the head) and the lowest placed
/// face vertex (the chin): the head height the errors are measured over.
fn top_and_chin(base: &Mesh, body: &[bool], vertices: &[Placed]) -> (u32, u32) {
    let mut on_body = vec![false; base.positions.len()];
    for (t, _) in base.triangles.iter().zip(body).filter(|(_, b)| **b) {
        for &i in t {
            on_body[i as usize] = true;
        }
    }
    let top = (0..base.positions.len())
        .filter(|&i| on_body[i])
        .max_by(|&a, &b| base.positions[a][1].total_cmp(&base.positions[b][1]))
        .unwrap_or(0) as u32;
    let chin = vertices
        .iter()
        .min_by(|a, b| {
            base.positions[a.vertex as usize][1].total_cmp(&base.positions[b.vertex as usize][1])
        })
        .map_or(0, |p| p.vertex);
    (top, chin)
}

/// Every region vertex inside the window with its patch (column, row)
/// and its `(u, v)` in that patch.
fn place(base: &Mesh, region: &[bool], win: &Window, nu: usize, nv: usize) -> Vec<Placed> {
    let mut vertices = Vec::new();
    for (i, &r) in region.iter().enumerate() {
        let p = base.positions[i];
        let (s, w) = win.unit(p[0], p[1]);
        if !r || !(0.0..=1.0).contains(&s) || !(0.0..=1.0).contains(&w) {
            continue;
        }
        let (cu, cv) = (s * nu as f64, w * nv as f64);
        let (column, row) = (
            (cu.floor() as usize).min(nu - 1),
            (cv.floor() as usize).min(nv - 1),
        );
        vertices.push(Placed {
            vertex: i as u32,
            column,
            row,
            u: cu - column as f64,
            v: cv - row as f64,
        });
    }
    vertices
}

/// Offsets in `s` of the three stencil points of column `i` and their
/// weights in `S_u`, `S_uu` per unit of `u` (one column = `1/nu` in `s`,
/// spacing `h`): central on inner columns, one-sided on the outer two.
pub fn stencil(i: usize, nu: usize, h: f64) -> ([f64; 3], [f64; 3], [f64; 3]) {
    // derivatives in s times (1/nu)^k: per unit of u
    let du = 1.0 / nu as f64;
    let (a, b) = (du / h, (du / h) * (du / h));
    if i == 0 {
        (
            [0.0, h, 2.0 * h],
            [-1.5 * a, 2.0 * a, -0.5 * a],
            [b, -2.0 * b, b],
        )
    } else if i == nu {
        (
            [0.0, -h, -2.0 * h],
            [1.5 * a, -2.0 * a, 0.5 * a],
            [b, -2.0 * b, b],
        )
    } else {
        ([-h, 0.0, h], [-0.5 * a, 0.0, 0.5 * a], [b, -2.0 * b, b])
    }
}
