//! The length-based mapping onto the unit disk (eq 16, sec 4.3).
//!
//! With boundary vertices $A_1\dots A_M$ and the centroid $C$ of the region,
//! an interior vertex $B_j$ is sent along the ray $C B_j$ to the boundary
//! point $D_j$ on edge $A_iA_{i+1}$; $D_j$ goes to the unit-circle point at
//! angle $2\pi L_{A_1D_j}/L_{sum}$ and $B_j$ to
//! $\tilde B_j = \rho_j \tilde D_j$ with $\rho_j = |CB_j|/|CD_j|$.
//!
//! The paper writes eq 16 componentwise,
//! $u_{\tilde B} = u_{\tilde D}(x'_B - x'_C)/(x'_D - x'_C)$ (and $v$ with $y'$);
//! both ratios equal $\rho_j$ because $B_j$ lies on segment $CD_j$, but each is
//! $0/0$ when $B_j$ is straight above or beside $C$. [`DiskMapping::map_point`] uses the
//! radial ratio; [`eq16_paper_literal`] keeps the printed form.

use super::PlateError;
use crate::polygon::{point_in_polygon as inside, signed_area};

/// Relative snapping of a ray's edge parameter at polygon vertices.
const VERTEX_SNAP: f64 = 1e-9;

/// Result of the mapping for one point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiskPoint {
    pub u: f64,
    pub v: f64,
    /// $\rho = |CB|/|CD|$ (1 on the boundary, may exceed 1 for a point
    /// outside the boundary curve).
    pub rho: f64,
}

/// The boundary polygon with cumulative arc lengths and the centroid.
#[derive(Clone, Debug)]
pub struct DiskMapping {
    pub polygon: Vec<[f64; 2]>,
    /// $L_{A_1A_k}$ for k = 1..M (first is 0).
    pub cumulative: Vec<f64>,
    pub l_sum: f64,
    pub centroid: [f64; 2],
    /// Number of mapped points whose ray from C crossed the boundary more
    /// than once (region not star-shaped about C: eq 16 is not one-to-one).
    pub non_star_rays: usize,
}

impl DiskMapping {
    /// Prepares the mapping for boundary `polygon` (counter-clockwise) and
    /// the region centroid.
    pub fn new(polygon: Vec<[f64; 2]>, centroid: [f64; 2]) -> Result<Self, PlateError> {
        if polygon.len() < 3 || signed_area(&polygon).abs() <= 0.0 {
            return Err(PlateError::DegenerateProjection(
                "boundary polygon has no area".into(),
            ));
        }
        if !inside(&polygon, centroid) {
            return Err(PlateError::CentroidOutside);
        }
        let m = polygon.len();
        let mut cumulative = Vec::with_capacity(m);
        let mut acc = 0.0;
        for i in 0..m {
            cumulative.push(acc);
            let (a, b) = (polygon[i], polygon[(i + 1) % m]);
            acc += (b[0] - a[0]).hypot(b[1] - a[1]);
        }
        Ok(DiskMapping {
            polygon,
            cumulative,
            l_sum: acc,
            centroid,
            non_star_rays: 0,
        })
    }

    /// Maps one point (eq 16). Boundary vertex `k` may be given directly.
    pub fn map_point(&mut self, p: [f64; 2], boundary_vertex: Option<usize>) -> DiskPoint {
        let two_pi = std::f64::consts::TAU;
        if let Some(k) = boundary_vertex {
            let th = two_pi * self.cumulative[k] / self.l_sum;
            return DiskPoint {
                u: th.cos(),
                v: th.sin(),
                rho: 1.0,
            };
        }
        let c = self.centroid;
        let dir = [p[0] - c[0], p[1] - c[1]];
        let len_b = dir[0].hypot(dir[1]);
        if len_b <= f64::EPSILON * self.l_sum {
            return DiskPoint {
                u: 0.0,
                v: 0.0,
                rho: 0.0,
            };
        }
        // all crossings of the ray C + t dir (t > 0) with the polygon edges
        let m = self.polygon.len();
        let mut best: Option<(f64, usize, f64)> = None; // (t, edge, s)
        let mut hits: Vec<f64> = Vec::new();
        for i in 0..m {
            let (a, b) = (self.polygon[i], self.polygon[(i + 1) % m]);
            let Some((t, s)) = crate::polygon::line_segment_params(c, dir, a, b) else {
                continue;
            };
            // a ray through a polygon vertex must hit one of its two edges
            // despite rounding
            if t > 0.0 && (-VERTEX_SNAP..=1.0 + VERTEX_SNAP).contains(&s) {
                hits.push(t);
                // D_j: the first crossing at or beyond B (t >= 1)
                let key = if t >= 1.0 - VERTEX_SNAP {
                    t
                } else {
                    f64::INFINITY
                };
                if best.is_none_or(|(bt, _, _)| key < bt) {
                    best = Some((key, i, s.clamp(0.0, 1.0)));
                }
            }
        }
        hits.sort_by(f64::total_cmp);
        hits.dedup_by(|a, b| (*a - *b).abs() <= VERTEX_SNAP * b.abs().max(1.0));
        if hits.len() > 1 {
            self.non_star_rays += 1;
        }
        let Some((t, i, s)) = best.filter(|b| b.0.is_finite()) else {
            // outside the boundary curve: no deformation
            return DiskPoint {
                u: 0.0,
                v: 0.0,
                rho: f64::INFINITY,
            };
        };
        let (a, b) = (self.polygon[i], self.polygon[(i + 1) % m]);
        let len_e = (b[0] - a[0]).hypot(b[1] - a[1]);
        let th = two_pi * (self.cumulative[i] + s * len_e) / self.l_sum;
        let rho = 1.0 / t;
        DiskPoint {
            u: rho * th.cos(),
            v: rho * th.sin(),
            rho,
        }
    }
}

/// Eq 16 as printed: componentwise ratios (0/0 when $x'_B = x'_C$ or
/// $y'_B = y'_C$).
pub fn eq16_paper_literal(b: [f64; 2], c: [f64; 2], d: [f64; 2], d_tilde: [f64; 2]) -> [f64; 2] {
    [
        d_tilde[0] * (b[0] - c[0]) / (d[0] - c[0]),
        d_tilde[1] * (b[1] - c[1]) / (d[1] - c[1]),
    ]
}

/// Beyond the paper: a harmonic (Tutte) disk mapping. The boundary loop
/// goes to the unit circle by the same arc-length rule as eq 16; every
/// other vertex is the average of its neighbours in `triangles` (uniform
/// weights, one sparse Cholesky solve). By Tutte's theorem the map of a
/// disk-like triangulation onto the convex disk is one-to-one, so it needs
/// neither a star-shaped region nor a centroid inside it, and it has no
/// creases along the rays through boundary corners that eq 16 produces.
/// Vertices in no triangle connected to the boundary get $\rho = \infty$
/// (no deformation).
pub fn harmonic_disk(
    n_points: usize,
    triangles: &[[usize; 3]],
    boundary_loop: &[usize],
    points: &[[f64; 2]],
) -> Result<Vec<DiskPoint>, PlateError> {
    use faer::prelude::Solve;
    use faer::sparse::{SparseColMat, Triplet};
    let m = boundary_loop.len();
    if m < 3 {
        return Err(PlateError::BoundaryNotClosed {
            alpha0: f64::NAN,
            reason: "boundary loop has fewer than 3 vertices".into(),
        });
    }
    let mut out = vec![
        DiskPoint {
            u: 0.0,
            v: 0.0,
            rho: f64::INFINITY
        };
        n_points
    ];
    // arc-length positions on the circle
    let mut acc = vec![0.0; m];
    let mut total = 0.0;
    for k in 0..m {
        acc[k] = total;
        let (a, b) = (points[boundary_loop[k]], points[boundary_loop[(k + 1) % m]]);
        total += (b[0] - a[0]).hypot(b[1] - a[1]);
    }
    let mut on_boundary = vec![false; n_points];
    for k in 0..m {
        let th = std::f64::consts::TAU * acc[k] / total;
        out[boundary_loop[k]] = DiskPoint {
            u: th.cos(),
            v: th.sin(),
            rho: 1.0,
        };
        on_boundary[boundary_loop[k]] = true;
    }
    let nbrs = neighbours(n_points, triangles);
    // interior vertices reachable from the boundary
    let reach = reachable(&nbrs, &on_boundary, boundary_loop);
    let mut col = vec![usize::MAX; n_points];
    let mut unknown = Vec::new();
    for v in 0..n_points {
        if reach[v] && !on_boundary[v] {
            col[v] = unknown.len();
            unknown.push(v);
        }
    }
    if unknown.is_empty() {
        return Ok(out);
    }
    let n = unknown.len();
    let mut trip = Vec::new();
    let mut rhs = faer::Mat::<f64>::zeros(n, 2);
    for (r, &v) in unknown.iter().enumerate() {
        trip.push(Triplet::new(r, r, nbrs[v].len() as f64));
        for &w in &nbrs[v] {
            if on_boundary[w] {
                rhs[(r, 0)] += out[w].u;
                rhs[(r, 1)] += out[w].v;
            } else {
                trip.push(Triplet::new(r, col[w], -1.0));
            }
        }
    }
    let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &trip)
        .map_err(PlateError::Matrix)?;
    let llt = a
        .sp_cholesky(faer::Side::Lower)
        .map_err(|e| PlateError::cholesky("harmonic mapping", e))?;
    llt.solve_in_place(rhs.as_mut());
    for (r, &v) in unknown.iter().enumerate() {
        let (u, w) = (rhs[(r, 0)], rhs[(r, 1)]);
        out[v] = DiskPoint {
            u,
            v: w,
            rho: u.hypot(w),
        };
    }
    Ok(out)
}

/// Each vertex's neighbours along the triangles' edges.
fn neighbours(n_points: usize, triangles: &[[usize; 3]]) -> Vec<Vec<usize>> {
    let mut nbrs: Vec<Vec<usize>> = vec![Vec::new(); n_points];
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if !nbrs[a].contains(&b) {
                nbrs[a].push(b);
                nbrs[b].push(a);
            }
        }
    }
    nbrs
}

/// The vertices connected to the boundary loop (the boundary included).
fn reachable(nbrs: &[Vec<usize>], on_boundary: &[bool], boundary_loop: &[usize]) -> Vec<bool> {
    let mut reach = on_boundary.to_vec();
    let mut stack: Vec<usize> = boundary_loop.to_vec();
    while let Some(v) = stack.pop() {
        for &w in &nbrs[v] {
            if !reach[w] {
                reach[w] = true;
                stack.push(w);
            }
        }
    }
    reach
}

#[cfg(test)]
mod tests {
    //! The mapping against hand-computed values, here so that the mutation
    //! oracle (the library's unit tests plus `verify`) sees them.
    use super::*;

    const TOL: f64 = crate::check::tol::ROUNDING;

    /// Each edge once, both ways: two triangles sharing the edge 1-2 (a
    /// mutation sample found the interior of the harmonic map untested
    /// where the mean of the boundary is the origin, so neighbours that
    /// were never added passed).
    #[test]
    fn neighbours_are_the_edges_both_ways_once() {
        let mut n = neighbours(4, &[[0, 1, 2], [2, 1, 3]]);
        for l in &mut n {
            l.sort_unstable();
        }
        assert_eq!(
            n,
            vec![vec![1, 2], vec![0, 2, 3], vec![0, 1, 3], vec![1, 2]]
        );
    }

    fn square() -> DiskMapping {
        // side 2, so that an edge parameter and an arc length differ
        let poly = vec![[1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0]];
        DiskMapping::new(poly, [0.0, 0.0]).expect("square")
    }

    #[test]
    fn eq16_sends_a_point_along_its_ray_by_arc_length() {
        let mut m = square();
        // the ray from C through B = (0.5, 0.2) leaves at D = (1, 0.4),
        // 1.4 along the first edge of a boundary 8 long: angle 2 pi 1.4/8;
        // |CB|/|CD| = 1/2
        let p = m.map_point([0.5, 0.2], None);
        let th = std::f64::consts::TAU * 1.4 / 8.0;
        assert!((p.rho - 0.5).abs() <= TOL, "{p:?}");
        assert!((p.u - 0.5 * th.cos()).abs() <= TOL, "{p:?}");
        assert!((p.v - 0.5 * th.sin()).abs() <= TOL, "{p:?}");
        // boundary vertex 2 is half way round
        let q = m.map_point([-1.0, 1.0], Some(2));
        assert!((q.u + 1.0).abs() <= TOL && q.v.abs() <= TOL, "{q:?}");
    }

    /// A ray that leaves the boundary, re-enters it and leaves again (a
    /// notch cut into the top edge of a square) is counted as a non-star
    /// ray, its three crossings kept apart although they lie within one
    /// ray length of each other; a convex boundary has none.
    #[test]
    fn a_ray_crossing_a_notch_is_counted_as_not_star_shaped() {
        let notched = vec![
            [2.0, -2.0],
            [2.0, 2.0],
            [1.5, 2.0],
            [1.0, 0.3],
            [0.5, 2.0],
            [-2.0, 2.0],
            [-2.0, -2.0],
        ];
        let mut m = DiskMapping::new(notched, [0.0, 0.0]).expect("notched");
        // the ray y = x / 2 crosses the notch at x = 0.95 and 1.07 and the
        // right edge at x = 2: t = 0.53, 0.59, 1.11 for B at x = 1.8
        let p = m.map_point([1.8, 0.9], None);
        assert_eq!(m.non_star_rays, 1, "{p:?}");
        assert!((p.rho - 0.9).abs() <= TOL, "{p:?}");
        let mut sq = square();
        for q in [[0.5, 0.2], [-0.3, 0.9], [0.99, -0.99]] {
            sq.map_point(q, None);
        }
        assert_eq!(sq.non_star_rays, 0);
    }

    #[test]
    fn the_harmonic_disk_puts_the_boundary_by_arc_length_and_the_centre_at_the_mean() {
        // a unit square away from the origin, fanned around its centre
        let points = [[1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0], [1.5, 1.5]];
        let tris = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]];
        let d = harmonic_disk(5, &tris, &[0, 1, 2, 3], &points).expect("disk");
        for (k, p) in d.iter().take(4).enumerate() {
            let th = std::f64::consts::FRAC_PI_2 * k as f64;
            assert!(
                (p.u - th.cos()).abs() <= TOL && (p.v - th.sin()).abs() <= TOL,
                "{k}: {p:?}"
            );
        }
        assert!(d[4].u.abs() <= TOL && d[4].v.abs() <= TOL, "{:?}", d[4]);
    }
}
