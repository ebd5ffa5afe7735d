//! How well a surface follows its stroke (paper 003, sec 5: "after global
//! interpolation, fit the given silhouette curve").
//!
//! The mesh is projected orthogonally onto the stroke's plane and
//! rasterised (a pixel is covered when its centre lies in a projected
//! triangle); the outline of the covered region is compared with the
//! stroke polygon both ways. Distances are relative to the stroke's size
//! (bounding-box diagonal); the pixel size (also reported) bounds the
//! resolution of the measurement.

use super::stroke::{dist2, distance_to_polygon};
use crate::mesh::Mesh;
use crate::polygon::point_in_polygon;

/// Silhouette-following error.
#[derive(Clone, Copy, Debug, Default, serde::Serialize)]
pub struct SilhouetteError {
    /// Max over outline pixels and stroke points of the distance to the
    /// other curve, / stroke size.
    pub max_rel: f64,
    /// Mean of the same distances, / stroke size.
    pub mean_rel: f64,
    /// Pixel size / stroke size.
    pub pixel_rel: f64,
}

/// Raster size of the measurement (pixels along the longer side).
pub const RASTER: usize = 400;

/// Compares the projection of `mesh` onto the plane through `origin` spanned
/// by the orthonormal `e1`, `e2` with the closed `stroke` (plane coordinates).
pub fn silhouette_error(
    mesh: &Mesh,
    origin: [f64; 3],
    e1: [f64; 3],
    e2: [f64; 3],
    stroke: &[[f64; 2]],
) -> SilhouetteError {
    silhouette_error_union(mesh, origin, e1, e2, &[stroke])
}

/// As [`silhouette_error`] for merged components sketched in one plane:
/// the outline is compared with the boundary of the union of the closed
/// `strokes` (outline pixels to the nearest stroke; stroke points inside
/// another stroke are not on the union's boundary and are skipped). The
/// size is the diagonal of all strokes' bounding box.
pub fn silhouette_error_union(
    mesh: &Mesh,
    origin: [f64; 3],
    e1: [f64; 3],
    e2: [f64; 3],
    strokes: &[&[[f64; 2]]],
) -> SilhouetteError {
    let proj: Vec<[f64; 2]> = mesh
        .positions
        .iter()
        .map(|p| {
            let d = [p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]];
            [crate::mesh::dot(d, e1), crate::mesh::dot(d, e2)]
        })
        .collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in strokes.iter().flat_map(|s| s.iter()).chain(proj.iter()) {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let (mut slo, mut shi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in strokes.iter().flat_map(|s| s.iter()) {
        for k in 0..2 {
            slo[k] = slo[k].min(p[k]);
            shi[k] = shi[k].max(p[k]);
        }
    }
    let size = dist2(slo, shi);
    let pad = 0.05 * size;
    lo = [lo[0] - pad, lo[1] - pad];
    hi = [hi[0] + pad, hi[1] + pad];
    let (outline, px) = outline_pixels(&proj, &mesh.triangles, lo, hi);
    if outline.is_empty() || size <= 0.0 {
        return SilhouetteError {
            max_rel: f64::INFINITY,
            mean_rel: f64::INFINITY,
            pixel_rel: px / size,
        };
    }
    let mut dists: Vec<f64> = outline
        .iter()
        .map(|&p| {
            strokes
                .iter()
                .map(|s| distance_to_polygon(p, s))
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    for (i, st) in strokes.iter().enumerate() {
        for &s in st.iter() {
            let covered = strokes
                .iter()
                .enumerate()
                .any(|(j, o)| j != i && point_in_polygon(o, s));
            if covered {
                continue;
            }
            dists.push(
                outline
                    .iter()
                    .map(|&o| dist2(o, s))
                    .fold(f64::INFINITY, f64::min),
            );
        }
    }
    let max = dists.iter().copied().fold(0.0, f64::max);
    let mean = dists.iter().sum::<f64>() / dists.len() as f64;
    SilhouetteError {
        max_rel: max / size,
        mean_rel: mean / size,
        pixel_rel: px / size,
    }
}

/// The outline pixels (pixel centres, plane coordinates) of the projected
/// mesh `proj` with `triangles`, rasterised over the box `lo`..`hi` at
/// [`RASTER`] pixels along its longer side: covered pixels with an
/// uncovered or missing 4-neighbour. Also returns the pixel size.
fn outline_pixels(
    proj: &[[f64; 2]],
    triangles: &[[u32; 3]],
    lo: [f64; 2],
    hi: [f64; 2],
) -> (Vec<[f64; 2]>, f64) {
    let px = ((hi[0] - lo[0]).max(hi[1] - lo[1])) / RASTER as f64;
    let (w, h) = (
        ((hi[0] - lo[0]) / px).ceil() as usize + 1,
        ((hi[1] - lo[1]) / px).ceil() as usize + 1,
    );
    let mut cov = vec![false; w * h];
    for t in triangles {
        let [a, b, c] = t.map(|i| proj[i as usize]);
        let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if area.abs() <= 0.0 {
            continue;
        }
        let x0 = ((a[0].min(b[0]).min(c[0]) - lo[0]) / px).floor().max(0.0) as usize;
        let x1 = (((a[0].max(b[0]).max(c[0]) - lo[0]) / px).ceil() as usize).min(w - 1);
        let y0 = ((a[1].min(b[1]).min(c[1]) - lo[1]) / px).floor().max(0.0) as usize;
        let y1 = (((a[1].max(b[1]).max(c[1]) - lo[1]) / px).ceil() as usize).min(h - 1);
        for y in y0..=y1 {
            for x in x0..=x1 {
                let p = [lo[0] + (x as f64 + 0.5) * px, lo[1] + (y as f64 + 0.5) * px];
                let e = |u: [f64; 2], v: [f64; 2]| {
                    ((v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0])) * area.signum()
                };
                if e(a, b) >= 0.0 && e(b, c) >= 0.0 && e(c, a) >= 0.0 {
                    cov[x + w * y] = true;
                }
            }
        }
    }
    let mut outline = Vec::new();
    for y in 0..h {
        for x in 0..w {
            if !cov[x + w * y] {
                continue;
            }
            let edge = x == 0
                || y == 0
                || x + 1 == w
                || y + 1 == h
                || !cov[x - 1 + w * y]
                || !cov[x + 1 + w * y]
                || !cov[x + w * (y - 1)]
                || !cov[x + w * (y + 1)];
            if edge {
                outline.push([lo[0] + (x as f64 + 0.5) * px, lo[1] + (y as f64 + 0.5) * px]);
            }
        }
    }
    (outline, px)
}
