//! Distances between points and meshes, and between meshes.
//!
//! [`closest_point_on_triangle`] is the region-based algorithm of Ericson,
//! *Real-Time Collision Detection* (2005), sec. 5.1.5. [`TriangleBvh`] is a
//! median-split bounding-volume hierarchy with best-first nearest queries.
//! [`distance_stats`] samples one mesh (its vertices and triangle centroids)
//! against the other; [`hausdorff`] takes the larger of both directions.

use super::{add, dot, scale, sub, Mesh};
use crate::check::Measure;
use serde::Serialize;

/// Closest point to `p` on the triangle `(a, b, c)`.
pub fn closest_point_on_triangle(p: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    let ab = sub(b, a);
    let ac = sub(c, a);
    let ap = sub(p, a);
    let d1 = dot(ab, ap);
    let d2 = dot(ac, ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = sub(p, b);
    let d3 = dot(ab, bp);
    let d4 = dot(ac, bp);
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return add(a, scale(ab, v));
    }
    let cp = sub(p, c);
    let d5 = dot(ab, cp);
    let d6 = dot(ac, cp);
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return add(a, scale(ac, w));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return add(b, scale(sub(c, b), w));
    }
    let denom = 1.0 / (va + vb + vc);
    let v = vb * denom;
    let w = vc * denom;
    add(a, add(scale(ab, v), scale(ac, w)))
}

#[derive(Clone, Copy, Debug)]
struct Aabb {
    lo: [f64; 3],
    hi: [f64; 3],
}

impl Aabb {
    fn empty() -> Self {
        Aabb {
            lo: [f64::INFINITY; 3],
            hi: [f64::NEG_INFINITY; 3],
        }
    }
    fn grow(&mut self, p: [f64; 3]) {
        for k in 0..3 {
            self.lo[k] = self.lo[k].min(p[k]);
            self.hi[k] = self.hi[k].max(p[k]);
        }
    }
    fn dist2(&self, p: [f64; 3]) -> f64 {
        let mut s = 0.0;
        for k in 0..3 {
            let d = (self.lo[k] - p[k]).max(0.0).max(p[k] - self.hi[k]);
            s += d * d;
        }
        s
    }
}

enum Node {
    Leaf {
        bbox: Aabb,
        tris: Vec<u32>,
    },
    Inner {
        bbox: Aabb,
        children: Box<[Node; 2]>,
    },
}

impl Node {
    fn bbox(&self) -> &Aabb {
        match self {
            Node::Leaf { bbox, .. } | Node::Inner { bbox, .. } => bbox,
        }
    }
}

/// Bounding-volume hierarchy over a mesh's triangles for closest-point
/// queries.
pub struct TriangleBvh<'a> {
    mesh: &'a Mesh,
    root: Option<Node>,
}

const LEAF_SIZE: usize = 8;

impl<'a> TriangleBvh<'a> {
    /// Builds the hierarchy (median split along the longest axis).
    pub fn new(mesh: &'a Mesh) -> Self {
        let tris: Vec<u32> = (0..mesh.triangles.len() as u32).collect();
        let centroids: Vec<[f64; 3]> = (0..mesh.triangles.len())
            .map(|t| {
                let [a, b, c] = mesh.corners(t);
                scale(add(add(a, b), c), 1.0 / 3.0)
            })
            .collect();
        let root = if tris.is_empty() {
            None
        } else {
            Some(build(mesh, &centroids, tris))
        };
        TriangleBvh { mesh, root }
    }

    /// The closest point on the mesh to `p`, its distance and the triangle;
    /// `None` for a mesh without triangles.
    pub fn closest(&self, p: [f64; 3]) -> Option<([f64; 3], f64, usize)> {
        let root = self.root.as_ref()?;
        let mut best = (p, f64::INFINITY, 0usize);
        let mut stack: Vec<&Node> = vec![root];
        while let Some(node) = stack.pop() {
            if node.bbox().dist2(p) >= best.1 {
                continue;
            }
            match node {
                Node::Leaf { tris, .. } => {
                    for &t in tris {
                        let [a, b, c] = self.mesh.corners(t as usize);
                        let q = closest_point_on_triangle(p, a, b, c);
                        let d2 = dot(sub(q, p), sub(q, p));
                        if d2 < best.1 {
                            best = (q, d2, t as usize);
                        }
                    }
                }
                Node::Inner { children, .. } => {
                    let (l, r) = (&children[0], &children[1]);
                    // visit the nearer child first (pushed last)
                    if l.bbox().dist2(p) < r.bbox().dist2(p) {
                        stack.push(r);
                        stack.push(l);
                    } else {
                        stack.push(l);
                        stack.push(r);
                    }
                }
            }
        }
        Some((best.0, best.1.sqrt(), best.2))
    }
}

fn build(mesh: &Mesh, centroids: &[[f64; 3]], mut tris: Vec<u32>) -> Node {
    let mut bbox = Aabb::empty();
    for &t in &tris {
        for p in mesh.corners(t as usize) {
            bbox.grow(p);
        }
    }
    if tris.len() <= LEAF_SIZE {
        return Node::Leaf { bbox, tris };
    }
    let ext = sub(bbox.hi, bbox.lo);
    let axis = if ext[0] >= ext[1] && ext[0] >= ext[2] {
        0
    } else if ext[1] >= ext[2] {
        1
    } else {
        2
    };
    let mid = tris.len() / 2;
    tris.select_nth_unstable_by(mid, |&a, &b| {
        centroids[a as usize][axis].total_cmp(&centroids[b as usize][axis])
    });
    let right = tris.split_off(mid);
    Node::Inner {
        bbox,
        children: Box::new([build(mesh, centroids, tris), build(mesh, centroids, right)]),
    }
}

/// Distance statistics of sample points against a mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct DistanceStats {
    pub samples: usize,
    pub rms: f64,
    pub mean: f64,
    pub max: f64,
}

/// Distances from `points` to the mesh `to`.
pub fn point_distances(points: &[[f64; 3]], to: &Mesh) -> Vec<f64> {
    let bvh = TriangleBvh::new(to);
    points
        .iter()
        .map(|&p| bvh.closest(p).map_or(f64::INFINITY, |c| c.1))
        .collect()
}

/// Sample points of a mesh: its vertices and its triangle centroids.
pub fn sample_points(m: &Mesh) -> Vec<[f64; 3]> {
    let mut pts = m.positions.clone();
    for t in 0..m.triangles.len() {
        let [a, b, c] = m.corners(t);
        pts.push(scale(add(add(a, b), c), 1.0 / 3.0));
    }
    pts
}

/// One-sided distances from `from` (vertices and triangle centroids) to `to`.
pub fn distance_stats(from: &Mesh, to: &Mesh) -> DistanceStats {
    stats(&point_distances(&sample_points(from), to))
}

/// RMS, mean and max of a list of distances.
pub fn stats(d: &[f64]) -> DistanceStats {
    let n = d.len().max(1) as f64;
    DistanceStats {
        samples: d.len(),
        rms: (d.iter().map(|x| x * x).sum::<f64>() / n).sqrt(),
        mean: d.iter().sum::<f64>() / n,
        max: d.iter().copied().max_nan(),
    }
}

/// Symmetric Hausdorff distance (sampled at vertices and centroids).
pub fn hausdorff(a: &Mesh, b: &Mesh) -> f64 {
    distance_stats(a, b).max.max(distance_stats(b, a).max)
}
