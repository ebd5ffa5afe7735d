//! Skeleton extraction from the filtered polygon (paper 003, sec 3.2, Fig 2).
//!
//! 1. Constrained Delaunay triangulation (spade) of the polygon, its edges
//!    as constraints; only triangles inside the polygon are kept.
//! 2. Types by the number of external (polygon) edges: terminal (2),
//!    sleeve (1), junction (0).
//! 3. One circle per triangle: junction, the circumcircle; terminal, the
//!    incircle; sleeve, whichever of the circumcircle and the "edge-tangent"
//!    circle has the larger area of intersection with the polygon. The paper
//!    does not fix the edge-tangent circle further (it is tangent to the
//!    external edge and passes through the third vertex); we take the one
//!    whose diameter is the altitude from the third vertex onto the external
//!    edge's line (centre halfway between the two sides of the sleeve).
//! 4. Centres linked by triangle adjacency.
//! 5. Pruning: along each chain from a terminal triangle to the next
//!    junction (or to the middle of a chain that ends in another terminal),
//!    a centre is removed when its circle lies mostly
//!    inside the next kept circle: $|c_i - c_j| + \beta r_i \le r_j$ with
//!    $\beta$ = [`SkeletonOptions::overlap`] (0.5: the centre plus half the
//!    radius inside). Junction centres are never pruned. A run of pruned
//!    circles must lie mostly inside the next kept one as a whole, so a
//!    tapering run is not pruned away in a cascade; a terminal incircle
//!    smaller than [`SkeletonOptions::tiny`] times the next circle with its
//!    centre inside that circle is pruned too (our addition: ears of nearly
//!    collinear stroke points).

use super::stroke::distance_to_polygon;
use super::ConvError;
use crate::polygon::point_in_polygon;
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use std::collections::HashMap;

/// Triangle type by number of external edges.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum TriangleKind {
    Terminal,
    Sleeve,
    Junction,
}

/// Which circle a triangle uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum CircleKind {
    Circumcircle,
    Incircle,
    EdgeTangent,
}

/// A triangle of the CDT inside the polygon, with its circle.
#[derive(Clone, Debug, serde::Serialize)]
pub struct SkeletonTriangle {
    /// Polygon vertex indices.
    pub vertices: [usize; 3],
    pub kind: TriangleKind,
    pub circle: CircleKind,
    pub centre: [f64; 2],
    pub radius: f64,
    /// Adjacent inside triangles (across internal edges).
    pub neighbours: Vec<usize>,
}

/// Options of the skeleton extraction. Outside the crate, start from
/// [`SkeletonOptions::default`] and change fields with the `with_*`
/// setters (or by assignment).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
#[non_exhaustive]
pub struct SkeletonOptions {
    /// $\beta$ of the pruning criterion; 0 disables pruning (default 0.5).
    pub overlap: f64,
    /// A terminal circle smaller than `tiny` times the next circle is pruned
    /// too (ears of three nearly collinear stroke points; our addition;
    /// default 0.2).
    pub tiny: f64,
    /// Sample count per circle for the intersection area of sleeve circles
    /// (default 12).
    pub area_samples: usize,
}

setters!(SkeletonOptions {
    with_overlap: overlap: f64,
    with_tiny: tiny: f64,
    with_area_samples: area_samples: usize,
});

impl Default for SkeletonOptions {
    fn default() -> Self {
        SkeletonOptions {
            overlap: 0.5,
            tiny: 0.2,
            area_samples: 12,
        }
    }
}

/// The extracted skeleton: nodes (kept centres with radii) and the line
/// segments between them.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Skeleton {
    pub triangles: Vec<SkeletonTriangle>,
    /// Kept node per triangle (`None` if pruned).
    pub node_of_triangle: Vec<Option<usize>>,
    pub nodes: Vec<[f64; 2]>,
    pub radii: Vec<f64>,
    /// Node index pairs.
    pub edges: Vec<[usize; 2]>,
}

fn circumcircle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> ([f64; 2], f64) {
    let d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    let (a2, b2, c2) = (
        a[0] * a[0] + a[1] * a[1],
        b[0] * b[0] + b[1] * b[1],
        c[0] * c[0] + c[1] * c[1],
    );
    let ux = (a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d;
    let uy = (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d;
    let centre = [ux, uy];
    (centre, super::stroke::dist2(centre, a))
}

fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> ([f64; 2], f64) {
    use super::stroke::dist2;
    let (la, lb, lc) = (dist2(b, c), dist2(c, a), dist2(a, b));
    let p = la + lb + lc;
    let centre = [
        (la * a[0] + lb * b[0] + lc * c[0]) / p,
        (la * a[1] + lb * b[1] + lc * c[1]) / p,
    ];
    let area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs();
    (centre, 2.0 * area / p)
}

/// Circle tangent to the line `a`..`b` with the altitude from `c` as diameter.
fn edge_tangent_circle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> ([f64; 2], f64) {
    let e = [b[0] - a[0], b[1] - a[1]];
    let l2 = e[0] * e[0] + e[1] * e[1];
    let t = ((c[0] - a[0]) * e[0] + (c[1] - a[1]) * e[1]) / l2;
    let foot = [a[0] + t * e[0], a[1] + t * e[1]];
    let centre = [0.5 * (foot[0] + c[0]), 0.5 * (foot[1] + c[1])];
    (centre, 0.5 * super::stroke::dist2(foot, c))
}

/// Fraction-weighted area of the circle inside the polygon (polar midpoint
/// rule with `n` rings and `4n` sectors).
fn area_inside(centre: [f64; 2], r: f64, poly: &[[f64; 2]], n: usize) -> f64 {
    let (nr, nt) = (n.max(2), 4 * n.max(2));
    let mut a = 0.0;
    for i in 0..nr {
        let rho = r * (i as f64 + 0.5) / nr as f64;
        let cell = rho * (r / nr as f64) * (std::f64::consts::TAU / nt as f64);
        for j in 0..nt {
            let th = std::f64::consts::TAU * (j as f64 + 0.5) / nt as f64;
            let p = [centre[0] + rho * th.cos(), centre[1] + rho * th.sin()];
            if point_in_polygon(poly, p) {
                a += cell;
            }
        }
    }
    a
}

/// Extracts the skeleton of the counter-clockwise simple polygon `poly`.
pub fn extract(poly: &[[f64; 2]], opts: &SkeletonOptions) -> Result<Skeleton, ConvError> {
    let n = poly.len();
    if n < 3 {
        return Err(ConvError::TooShort {
            points: n,
            needed: 3,
        });
    }
    let all = triangulate(poly)?;
    let is_external = |a: usize, b: usize| (a + 1) % n == b || (b + 1) % n == a;
    let tris = inside_triangles(&all, poly);
    if tris.is_empty() {
        return Err(ConvError::Triangulation(
            "no triangle inside the stroke".into(),
        ));
    }
    // adjacency across internal edges
    let mut edge_faces: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (t, v) in tris.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (v[k], v[(k + 1) % 3]);
            if !is_external(a, b) {
                edge_faces.entry((a.min(b), a.max(b))).or_default().push(t);
            }
        }
    }
    let mut triangles = Vec::with_capacity(tris.len());
    for (t, v) in tris.iter().enumerate() {
        let ext: Vec<usize> = (0..3)
            .filter(|&k| is_external(v[k], v[(k + 1) % 3]))
            .collect();
        let (a, b, c) = (poly[v[0]], poly[v[1]], poly[v[2]]);
        let (kind, circle, centre, radius) = match ext.len() {
            0 => {
                let (c0, r0) = circumcircle(a, b, c);
                (TriangleKind::Junction, CircleKind::Circumcircle, c0, r0)
            }
            1 => {
                let k = ext[0];
                let (e0, e1, opp) = (poly[v[k]], poly[v[(k + 1) % 3]], poly[v[(k + 2) % 3]]);
                let (cc, rc) = circumcircle(a, b, c);
                let (ct, rt) = edge_tangent_circle(e0, e1, opp);
                let ac = area_inside(cc, rc, poly, opts.area_samples);
                let at = area_inside(ct, rt, poly, opts.area_samples);
                if ac >= at && point_in_polygon(poly, cc) {
                    (TriangleKind::Sleeve, CircleKind::Circumcircle, cc, rc)
                } else {
                    (TriangleKind::Sleeve, CircleKind::EdgeTangent, ct, rt)
                }
            }
            _ => {
                let (ci, ri) = incircle(a, b, c);
                (TriangleKind::Terminal, CircleKind::Incircle, ci, ri)
            }
        };
        let mut neighbours = Vec::new();
        for k in 0..3 {
            let (x, y) = (v[k], v[(k + 1) % 3]);
            if let Some(fs) = edge_faces.get(&(x.min(y), x.max(y))) {
                neighbours.extend(fs.iter().copied().filter(|&o| o != t));
            }
        }
        // a radius never reaches past the stroke
        let radius = radius.min(distance_to_polygon(centre, poly).max(radius * 0.25));
        triangles.push(SkeletonTriangle {
            vertices: *v,
            kind,
            circle,
            centre,
            radius,
            neighbours,
        });
    }
    Ok(prune_and_link(triangles, opts))
}

/// The constrained Delaunay triangulation of the polygon's vertices with
/// its edges as constraints, as triangles of polygon indices (every face,
/// inside or not).
fn triangulate(poly: &[[f64; 2]]) -> Result<Vec<[usize; 3]>, ConvError> {
    let n = poly.len();
    let mut cdt = ConstrainedDelaunayTriangulation::<Point2<f64>>::new();
    let mut index_of: HashMap<usize, usize> = HashMap::new();
    let mut handles = Vec::with_capacity(n);
    for (i, p) in poly.iter().enumerate() {
        let h = cdt
            .insert(Point2::new(p[0], p[1]))
            .map_err(|e| ConvError::insertion(i, e))?;
        index_of.insert(h.index(), i);
        handles.push(h);
    }
    if index_of.len() != n {
        return Err(ConvError::Triangulation(
            "duplicate vertices in the polygon".into(),
        ));
    }
    for i in 0..n {
        cdt.add_constraint(handles[i], handles[(i + 1) % n]);
    }
    let mut all: Vec<[usize; 3]> = Vec::new();
    for f in cdt.inner_faces() {
        let vs = f.vertices();
        let mut idx = [0usize; 3];
        for k in 0..3 {
            idx[k] = *index_of.get(&vs[k].fix().index()).ok_or_else(|| {
                ConvError::Triangulation("the triangulation added a vertex".into())
            })?;
        }
        all.push(idx);
    }
    Ok(all)
}

/// The triangles inside the counter-clockwise polygon: a triangle with a
/// polygon edge $i \to i+1$ is inside when its third vertex is on the left;
/// the others inherit the side of their neighbours across non-polygon
/// edges (robust for slivers along straight runs of the stroke, where a
/// centroid test is not).
fn inside_triangles(all: &[[usize; 3]], poly: &[[f64; 2]]) -> Vec<[usize; 3]> {
    let n = poly.len();
    let mut state: Vec<Option<bool>> = vec![None; all.len()];
    let mut edge_faces: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (t, v) in all.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (v[k], v[(k + 1) % 3]);
            edge_faces.entry((a.min(b), a.max(b))).or_default().push(t);
            let third = poly[v[(k + 2) % 3]];
            let (i, j) = if (a + 1) % n == b {
                (a, b)
            } else if (b + 1) % n == a {
                (b, a)
            } else {
                continue;
            };
            let (p, q) = (poly[i], poly[j]);
            let o = crate::polygon::orient(p, q, third);
            state[t] = Some(o > 0.0);
        }
    }
    let mut queue: Vec<usize> = (0..all.len()).filter(|&t| state[t].is_some()).collect();
    while let Some(t) = queue.pop() {
        let v = all[t];
        for k in 0..3 {
            let (a, b) = (v[k], v[(k + 1) % 3]);
            if (a + 1) % n == b || (b + 1) % n == a {
                continue;
            }
            for &o in &edge_faces[&(a.min(b), a.max(b))] {
                if state[o].is_none() {
                    state[o] = state[t];
                    queue.push(o);
                }
            }
        }
    }
    all.iter()
        .enumerate()
        .filter(|&(t, v)| {
            state[t].unwrap_or_else(|| {
                let c = [
                    (poly[v[0]][0] + poly[v[1]][0] + poly[v[2]][0]) / 3.0,
                    (poly[v[0]][1] + poly[v[1]][1] + poly[v[2]][1]) / 3.0,
                ];
                point_in_polygon(poly, c)
            })
        })
        .map(|(_, v)| *v)
        .collect()
}

fn mostly_inside(a: ([f64; 2], f64), b: ([f64; 2], f64), beta: f64) -> bool {
    beta > 0.0 && super::stroke::dist2(a.0, b.0) + beta * a.1 <= b.1
}

/// Sleeve circles smaller than this fraction of the largest circle are
/// slivers (see `prune_and_link`).
pub const SLIVER: f64 = 1e-9;

fn prune_and_link(triangles: Vec<SkeletonTriangle>, opts: &SkeletonOptions) -> Skeleton {
    let nt = triangles.len();
    let mut pruned = vec![false; nt];
    // chains from terminals
    for start in 0..nt {
        if triangles[start].kind == TriangleKind::Terminal {
            prune_chain(&triangles, start, opts, &mut pruned);
        }
    }
    // a sleeve sliver along a straight run of the stroke (its apex within
    // rounding of the external edge's line, which the uniform re-insertion
    // of points makes possible) has a zero-width tangent circle on the
    // stroke itself: it carries no thickness and gets no node; the linking
    // below walks through it like through a pruned triangle
    let rmax = triangles.iter().map(|t| t.radius).fold(0.0, f64::max);
    for (t, tri) in triangles.iter().enumerate() {
        if tri.kind == TriangleKind::Sleeve && (tri.radius.is_nan() || tri.radius <= SLIVER * rmax)
        {
            pruned[t] = true;
        }
    }
    // nodes
    let mut node_of_triangle = vec![None; nt];
    let mut nodes = Vec::new();
    let mut radii = Vec::new();
    for t in 0..nt {
        if !pruned[t] {
            node_of_triangle[t] = Some(nodes.len());
            nodes.push(triangles[t].centre);
            radii.push(triangles[t].radius);
        }
    }
    // link: a kept triangle connects to the nearest kept triangle along each
    // neighbour direction (walking through pruned ones)
    let edges = link(&triangles, &node_of_triangle);
    Skeleton {
        triangles,
        node_of_triangle,
        nodes,
        radii,
        edges,
    }
}

/// Prunes along the chain of sleeves from terminal triangle `start` (to a
/// junction, or to another terminal: then to the chain's middle): the
/// current end circle (and every circle it already absorbed) is pruned
/// when mostly inside the next one, so tapering runs are not pruned away
/// in a cascade.
fn prune_chain(
    triangles: &[SkeletonTriangle],
    start: usize,
    opts: &SkeletonOptions,
    pruned: &mut [bool],
) {
    let mut chain = vec![start];
    let mut prev = usize::MAX;
    let mut cur = start;
    loop {
        let next = triangles[cur]
            .neighbours
            .iter()
            .copied()
            .find(|&o| o != prev && !chain.contains(&o));
        match next {
            Some(o) => {
                chain.push(o);
                if triangles[o].kind != TriangleKind::Sleeve {
                    break;
                }
                prev = cur;
                cur = o;
            }
            None => break,
        }
    }
    let last = *chain.last().unwrap_or(&start);
    // a terminal-to-terminal chain is walked from each end to its middle
    let ends_in_junction = triangles[last].kind == TriangleKind::Junction;
    let walk = if ends_in_junction {
        chain.len().saturating_sub(1)
    } else {
        chain.len() / 2
    };
    let mut cluster: Vec<usize> = vec![chain[0]];
    for i in 0..walk {
        let t = chain[i];
        let next = chain[i + 1];
        let b = (triangles[next].centre, triangles[next].radius);
        let kept = chain.iter().filter(|&&c| !pruned[c]).count();
        let absorbed = cluster.iter().all(|&k| {
            let a = (triangles[k].centre, triangles[k].radius);
            mostly_inside(a, b, opts.overlap)
                || (triangles[k].kind == TriangleKind::Terminal
                    && a.1 < opts.tiny * b.1
                    && super::stroke::dist2(a.0, b.0) <= b.1)
        });
        if triangles[t].kind != TriangleKind::Junction
            && t != last
            && (ends_in_junction || kept > 2)
            && absorbed
        {
            pruned[t] = true;
            cluster.push(next);
        } else {
            cluster = vec![next];
        }
    }
}

/// The skeleton's edges: each kept triangle (`node_of_triangle`) linked to
/// the nearest kept triangle along each neighbour direction (walking
/// through pruned ones).
fn link(triangles: &[SkeletonTriangle], node_of_triangle: &[Option<usize>]) -> Vec<[usize; 2]> {
    let nt = triangles.len();
    let mut edges: Vec<[usize; 2]> = Vec::new();
    for t in 0..nt {
        let Some(a) = node_of_triangle[t] else {
            continue;
        };
        for &start in &triangles[t].neighbours {
            let mut seen = vec![t];
            let mut stack = vec![start];
            while let Some(u) = stack.pop() {
                if seen.contains(&u) {
                    continue;
                }
                seen.push(u);
                if let Some(b) = node_of_triangle[u] {
                    if a < b && !edges.contains(&[a, b]) {
                        edges.push([a, b]);
                    }
                    continue;
                }
                stack.extend(triangles[u].neighbours.iter().copied());
            }
        }
    }
    edges
}
