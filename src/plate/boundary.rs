//! Boundary extraction by an alpha shape on a Delaunay triangulation (eq 15,
//! sec 4.2).
//!
//! The Delaunay triangulation (dual of the Voronoi cells $V_i$ of eq 15) of
//! the projected points is built with spade. With $d_P$ the smallest distance
//! between two points (always a Delaunay edge) and $\alpha = d_P\alpha_0$,
//! every triangle with an edge longer than $2\alpha$ is removed; the boundary
//! is the set of edges of the remaining triangles that bound only one of
//! them (the boundary of the alpha complex; the paper's empty-circle test on
//! these edges selects the same edges on the paper's uniform meshes). The
//! edges are chained into loops; the loop of largest area, oriented
//! counter-clockwise, is the boundary curve $A_1 \dots A_M$.

use super::PlateError;
use crate::polygon::signed_area;
use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation};
use std::collections::HashMap;

/// The paper's threshold $\alpha_0$ (sec 5).
pub const ALPHA0_DEFAULT: f64 = 0.86;

#[derive(Clone, Copy, Debug)]
struct Site {
    p: [f64; 2],
    index: usize,
}

impl HasPosition for Site {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        Point2::new(self.p[0], self.p[1])
    }
}

/// The extracted boundary curve.
#[derive(Clone, Debug, PartialEq)]
pub struct Boundary {
    /// Indices (into the input points) of $A_1 \dots A_M$, counter-clockwise.
    pub loop_indices: Vec<usize>,
    /// $d_P$, the smallest distance between two points.
    pub d_p: f64,
    /// $\alpha = d_P \alpha_0$.
    pub alpha: f64,
    /// Further (smaller) loops of the alpha shape: holes or islands.
    pub extra_loops: usize,
    /// Triangles of the alpha complex (indices into the input points).
    pub triangles: Vec<[usize; 3]>,
}

/// The boundary of the region's own mesh triangles (an alternative to the
/// alpha shape that does not depend on uniform vertex spacing):
/// `triangles` index `points`; each is oriented counter-clockwise in the
/// plane and zero-area ones are dropped.
pub fn mesh_edge_boundary(
    points: &[[f64; 2]],
    triangles: &[[usize; 3]],
) -> Result<Boundary, PlateError> {
    let mut tris = Vec::new();
    for t in triangles {
        let (a, b, c) = (points[t[0]], points[t[1]], points[t[2]]);
        let s = crate::polygon::orient(a, b, c);
        if s > 0.0 {
            tris.push(*t);
        } else if s < 0.0 {
            tris.push([t[0], t[2], t[1]]);
        }
    }
    if tris.is_empty() {
        return Err(PlateError::BoundaryNotClosed {
            alpha0: f64::NAN,
            reason: "the region contains no mesh triangle".into(),
        });
    }
    boundary_of_triangles(points, tris, f64::NAN, f64::NAN, f64::NAN)
}

/// Extracts the alpha-shape boundary of `points` (eq 15).
pub fn alpha_shape(points: &[[f64; 2]], alpha0: f64) -> Result<Boundary, PlateError> {
    if !(alpha0.is_finite() && alpha0 > 0.5) {
        return Err(PlateError::Parameter {
            name: "alpha0",
            value: alpha0,
            range: "> 0.5 (2 alpha must exceed the closest distance)",
        });
    }
    if points.len() < 3 {
        return Err(PlateError::TooFewVertices(points.len(), 3));
    }
    if let Some(i) = points
        .iter()
        .position(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(PlateError::NonFinite(i));
    }
    let sites: Vec<Site> = points
        .iter()
        .enumerate()
        .map(|(index, &p)| Site { p, index })
        .collect();
    let dt = DelaunayTriangulation::<Site>::bulk_load(sites).map_err(PlateError::Insertion)?;
    if dt.num_vertices() != points.len() {
        return Err(PlateError::DegenerateProjection(format!(
            "{} region vertices project onto the same points as others",
            points.len() - dt.num_vertices()
        )));
    }
    if dt.num_inner_faces() == 0 {
        return Err(PlateError::DegenerateProjection(
            "all region vertices project onto one line".into(),
        ));
    }
    let d = |a: usize, b: usize| {
        let (p, q) = (points[a], points[b]);
        (p[0] - q[0]).hypot(p[1] - q[1])
    };
    let d_p = dt
        .undirected_edges()
        .map(|e| {
            let [a, b] = e.vertices();
            d(a.data().index, b.data().index)
        })
        .fold(f64::INFINITY, f64::min);
    let alpha = d_p * alpha0;
    let mut triangles = Vec::new();
    for f in dt.inner_faces() {
        let v = f.vertices().map(|h| h.data().index);
        if (0..3).any(|k| d(v[k], v[(k + 1) % 3]) > 2.0 * alpha) {
            continue;
        }
        triangles.push(v);
    }
    if triangles.is_empty() {
        return Err(PlateError::BoundaryNotClosed {
            alpha0,
            reason: "no triangle survives the 2 alpha edge test (non-uniform vertex spacing? try the mesh-edge boundary)".into(),
        });
    }
    boundary_of_triangles(points, triangles, d_p, alpha, alpha0)
}

/// The outer boundary loop of a set of counter-clockwise triangles over
/// `points` (the chaining step shared by the alpha shape and the mesh-edge
/// boundary).
pub fn boundary_of_triangles(
    points: &[[f64; 2]],
    triangles: Vec<[usize; 3]>,
    d_p: f64,
    alpha: f64,
    alpha0: f64,
) -> Result<Boundary, PlateError> {
    let mut edge_count: HashMap<(usize, usize), (usize, [usize; 2])> = HashMap::new();
    for v in &triangles {
        for k in 0..3 {
            let (a, b) = (v[k], v[(k + 1) % 3]);
            let e = edge_count
                .entry((a.min(b), a.max(b)))
                .or_insert((0, [a, b]));
            e.0 += 1;
            e.1 = [a, b];
        }
    }
    // directed boundary edges (spade faces are counter-clockwise)
    let mut next: HashMap<usize, usize> = HashMap::new();
    for (_, (count, [a, b])) in edge_count.iter() {
        if *count == 1 && next.insert(*a, *b).is_some() {
            return Err(PlateError::BoundaryNotClosed {
                alpha0,
                reason: format!("boundary is pinched at vertex {a}"),
            });
        }
    }
    let mut loops: Vec<Vec<usize>> = Vec::new();
    let mut seen: HashMap<usize, bool> = HashMap::new();
    let mut starts: Vec<usize> = next.keys().copied().collect();
    starts.sort_unstable();
    for s in starts {
        if seen.contains_key(&s) {
            continue;
        }
        let mut lp = vec![s];
        seen.insert(s, true);
        let mut cur = s;
        loop {
            let Some(&n) = next.get(&cur) else {
                return Err(PlateError::BoundaryNotClosed {
                    alpha0,
                    reason: format!("boundary chain stops at vertex {cur}"),
                });
            };
            if n == s {
                break;
            }
            if seen.insert(n, true).is_some() || lp.len() > next.len() {
                return Err(PlateError::BoundaryNotClosed {
                    alpha0,
                    reason: format!("boundary chain revisits vertex {n}"),
                });
            }
            lp.push(n);
            cur = n;
        }
        loops.push(lp);
    }
    let area = |lp: &Vec<usize>| signed_area(&lp.iter().map(|&i| points[i]).collect::<Vec<_>>());
    let best = (0..loops.len())
        .max_by(|&i, &j| area(&loops[i]).abs().total_cmp(&area(&loops[j]).abs()))
        .ok_or(PlateError::BoundaryNotClosed {
            alpha0,
            reason: "no boundary loop".into(),
        })?;
    let mut loop_indices = loops[best].clone();
    if loop_indices.len() < 3 {
        return Err(PlateError::BoundaryNotClosed {
            alpha0,
            reason: "boundary loop has fewer than 3 vertices".into(),
        });
    }
    if area(&loop_indices) < 0.0 {
        loop_indices.reverse();
    }
    Ok(Boundary {
        loop_indices,
        d_p,
        alpha,
        extra_loops: loops.len() - 1,
        triangles,
    })
}
