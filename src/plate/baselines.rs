//! The baselines of the paper's comparisons (sec 5, Figs 11-12).
//!
//! * [`laplacian_deform`]: Laplacian surface editing in the style of
//!   Sorkine et al. 2004, linearised (differential coordinates kept, no
//!   implicit rotations $T_i$): the vertices outside the region are the
//!   anchors, the handle vertices are pulled by the displacement with weight
//!   $w_h$, and the region's displacement $\mathbf u$ minimises
//!   $\sum_i \|(L\mathbf u)_i\|^2 + w_h^2\sum_{h}\|\mathbf u_h - \mathbf d\|^2$
//!   (one sparse Cholesky, faer). Laplacian weights uniform or cotangent.
//! * [`delta_mush`]: Delta Mush (Mancewicz et al. 2014): smooth the rest
//!   region ($k$ Laplacian-smoothing steps of size $\lambda$, region border
//!   pinned), store the deltas to the rest pose in local frames, translate
//!   the moved vertices, smooth with the same $k, \lambda$ and add the
//!   deltas back.

use super::PlateError;
use crate::mesh::{add, dot, norm, scale, sub, Mesh};
use crate::surface::cross;
use faer::prelude::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::Side;

/// Laplacian weights.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Weights {
    Uniform,
    Cotangent,
}

/// Parameters of the Laplacian deformer.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct LaplacianParams {
    pub weights: Weights,
    /// Soft-constraint weight $w_h$ of the handle.
    pub handle_weight: f64,
}

impl Default for LaplacianParams {
    fn default() -> Self {
        LaplacianParams {
            weights: Weights::Cotangent,
            handle_weight: 10.0,
        }
    }
}

/// Parameters of Delta Mush.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct DeltaMushParams {
    /// Smoothing iterations $k$.
    pub iterations: usize,
    /// Step length $\lambda \in (0, 1]$.
    pub step: f64,
}

impl Default for DeltaMushParams {
    fn default() -> Self {
        DeltaMushParams {
            iterations: 40,
            step: 0.5,
        }
    }
}

/// Weighted vertex adjacency $(j, w_{ij})$ of a mesh.
pub fn adjacency(mesh: &Mesh, weights: Weights) -> Vec<Vec<(usize, f64)>> {
    let n = mesh.positions.len();
    let mut adj: Vec<Vec<(usize, f64)>> = vec![Vec::new(); n];
    let mut push = |i: usize, j: usize, w: f64| {
        if let Some(e) = adj[i].iter_mut().find(|e| e.0 == j) {
            e.1 += w;
        } else {
            adj[i].push((j, w));
        }
    };
    for t in &mesh.triangles {
        for k in 0..3 {
            let (i, j, o) = (
                t[k] as usize,
                t[(k + 1) % 3] as usize,
                t[(k + 2) % 3] as usize,
            );
            let w = match weights {
                Weights::Uniform => 0.5,
                Weights::Cotangent => {
                    let (a, b) = (
                        sub(mesh.positions[i], mesh.positions[o]),
                        sub(mesh.positions[j], mesh.positions[o]),
                    );
                    let c = norm(cross(a, b));
                    if c > 0.0 {
                        0.5 * dot(a, b) / c
                    } else {
                        0.0
                    }
                }
            };
            push(i, j, w);
            push(j, i, w);
        }
    }
    adj
}

fn check_region(mesh: &Mesh, region: &[u32]) -> Result<Vec<bool>, PlateError> {
    let n = mesh.positions.len();
    let mut sel = vec![false; n];
    for &v in region {
        let v = v as usize;
        if v >= n {
            return Err(PlateError::VertexOutOfBounds(v, n));
        }
        sel[v] = true;
    }
    Ok(sel)
}

/// The prefactored Laplacian (bi-Laplacian normal-equation) system of a
/// region: factor once, then each handle move is one sparse solve (the way
/// a libigl-style deformer works).
pub struct LaplacianSystem {
    llt: faer::sparse::linalg::solvers::Llt<usize, f64>,
    /// Mesh vertex of each unknown.
    pub cols: Vec<usize>,
    handle_cols: Vec<usize>,
    wh2: f64,
}

impl LaplacianSystem {
    /// Assembles and factors $L^\top L + w_h^2 S_h$ over the region.
    pub fn new(
        mesh: &Mesh,
        region: &[u32],
        handle: &[u32],
        params: &LaplacianParams,
    ) -> Result<Self, PlateError> {
        if !(params.handle_weight.is_finite() && params.handle_weight > 0.0) {
            return Err(PlateError::Parameter {
                name: "handle_weight",
                value: params.handle_weight,
                range: "> 0",
            });
        }
        let sel = check_region(mesh, region)?;
        let mut col = vec![usize::MAX; mesh.positions.len()];
        let mut cols = Vec::new();
        for (i, &s) in sel.iter().enumerate() {
            if s {
                col[i] = cols.len();
                cols.push(i);
            }
        }
        let m = cols.len();
        if m == 0 || handle.is_empty() {
            return Err(PlateError::TooFewVertices(m.min(handle.len()), 1));
        }
        let adj = adjacency(mesh, params.weights);
        let mut trip = Vec::new();
        for &i in &cols {
            let wsum: f64 = adj[i].iter().map(|e| e.1).sum();
            let mut row: Vec<(usize, f64)> = vec![(col[i], -wsum)];
            row.extend(
                adj[i]
                    .iter()
                    .filter(|e| col[e.0] != usize::MAX)
                    .map(|e| (col[e.0], e.1)),
            );
            for &(a, va) in &row {
                for &(b, vb) in &row {
                    trip.push(Triplet::new(a, b, va * vb));
                }
            }
        }
        let wh2 = params.handle_weight * params.handle_weight;
        let mut handle_cols = Vec::with_capacity(handle.len());
        for &h in handle {
            let c = *col.get(h as usize).unwrap_or(&usize::MAX);
            if c == usize::MAX {
                return Err(PlateError::VertexOutOfBounds(h as usize, m));
            }
            trip.push(Triplet::new(c, c, wh2));
            handle_cols.push(c);
        }
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(m, m, &trip)
            .map_err(PlateError::Matrix)?;
        let llt = a
            .sp_cholesky(Side::Lower)
            .map_err(|e| PlateError::cholesky("Laplacian normal equations", e))?;
        Ok(LaplacianSystem {
            llt,
            cols,
            handle_cols,
            wh2,
        })
    }

    /// Displacements of the region's vertices when the handle moves by `d`.
    pub fn solve(&self, d: [f64; 3]) -> faer::Mat<f64> {
        let mut rhs = faer::Mat::<f64>::zeros(self.cols.len(), 3);
        for &c in &self.handle_cols {
            for k in 0..3 {
                rhs[(c, k)] += self.wh2 * d[k];
            }
        }
        self.llt.solve_in_place(rhs.as_mut());
        rhs
    }
}

/// Laplacian deformer: displaces the region so that the handle vertices
/// move by `d` (softly) and the anchors outside the region stay.
pub fn laplacian_deform(
    mesh: &Mesh,
    region: &[u32],
    handle: &[u32],
    d: [f64; 3],
    params: &LaplacianParams,
) -> Result<Mesh, PlateError> {
    let sys = LaplacianSystem::new(mesh, region, handle, params)?;
    let u = sys.solve(d);
    let mut out = mesh.clone();
    for (c, &i) in sys.cols.iter().enumerate() {
        out.positions[i] = add(out.positions[i], [u[(c, 0)], u[(c, 1)], u[(c, 2)]]);
    }
    Ok(out)
}

/// `iterations` steps of uniform Laplacian smoothing of the `free` vertices.
fn smooth(p: &mut [[f64; 3]], adj: &[Vec<(usize, f64)>], free: &[usize], it: usize, step: f64) {
    let mut next = p.to_vec();
    for _ in 0..it {
        for &i in free {
            let n = adj[i].len() as f64;
            let mut avg = [0.0; 3];
            for &(j, _) in &adj[i] {
                avg = add(avg, scale(p[j], 1.0 / n));
            }
            next[i] = add(p[i], scale(sub(avg, p[i]), step));
        }
        for &i in free {
            p[i] = next[i];
        }
    }
}

fn frame(
    p: &[[f64; 3]],
    normals: &[[f64; 3]],
    adj: &[Vec<(usize, f64)>],
    i: usize,
) -> [[f64; 3]; 3] {
    let n = normals[i];
    let j = adj[i].first().map(|e| e.0).unwrap_or(i);
    let e = sub(p[j], p[i]);
    let t0 = sub(e, scale(n, dot(e, n)));
    let l = norm(t0);
    let t = if l > 0.0 {
        scale(t0, 1.0 / l)
    } else {
        [0.0; 3]
    };
    [t, cross(n, t), n]
}

/// Delta Mush: the vertices `moved` are translated by `d`, then the region
/// (its vertices with a neighbour outside it stay pinned) is smoothed and
/// the rest-pose deltas are restored.
pub fn delta_mush(
    mesh: &Mesh,
    region: &[u32],
    moved: &[u32],
    d: [f64; 3],
    params: &DeltaMushParams,
) -> Result<Mesh, PlateError> {
    if !(params.step.is_finite() && params.step > 0.0 && params.step <= 1.0) {
        return Err(PlateError::Parameter {
            name: "step",
            value: params.step,
            range: "(0, 1]",
        });
    }
    let sel = check_region(mesh, region)?;
    let adj = adjacency(mesh, Weights::Uniform);
    let free: Vec<usize> = (0..sel.len())
        .filter(|&i| sel[i] && !adj[i].is_empty() && adj[i].iter().all(|e| sel[e.0]))
        .collect();
    let rest = mesh.positions.clone();
    let mut s0 = rest.clone();
    smooth(&mut s0, &adj, &free, params.iterations, params.step);
    let smooth_mesh = |p: &[[f64; 3]]| {
        let mut m = mesh.clone();
        m.positions = p.to_vec();
        m.vertex_normals()
    };
    let n0 = smooth_mesh(&s0);
    let deltas: Vec<[f64; 3]> = free
        .iter()
        .map(|&i| {
            let f = frame(&s0, &n0, &adj, i);
            let dl = sub(rest[i], s0[i]);
            [dot(dl, f[0]), dot(dl, f[1]), dot(dl, f[2])]
        })
        .collect();
    let mut is_free = vec![false; sel.len()];
    for &i in &free {
        is_free[i] = true;
    }
    let mut p1 = rest;
    for &v in moved {
        let v = v as usize;
        if v >= p1.len() {
            return Err(PlateError::VertexOutOfBounds(v, p1.len()));
        }
        if is_free[v] {
            p1[v] = add(p1[v], d);
        }
    }
    smooth(&mut p1, &adj, &free, params.iterations, params.step);
    let n1 = smooth_mesh(&p1);
    let mut out = mesh.clone();
    out.positions = p1.clone();
    for (k, &i) in free.iter().enumerate() {
        let f = frame(&p1, &n1, &adj, i);
        let dl = deltas[k];
        out.positions[i] = add(
            p1[i],
            add(
                add(scale(f[0], dl[0]), scale(f[1], dl[1])),
                scale(f[2], dl[2]),
            ),
        );
    }
    Ok(out)
}
