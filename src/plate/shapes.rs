//! Test regions and the paper's comparisons (Figs 11-12): a flat sheet, a
//! region of it shaped as a square, rectangle, triangle, pentagram or
//! circle, pushed along its normal by our method (eq 12 through the whole
//! pipeline), Delta Mush and the Laplacian deformer, each compared with the
//! finite-element ground truth ([`super::reference`]) on the same vertices.
//! The baselines' amplitudes are set by their handles, so shapes are
//! compared after normalising every deflection field to a unit peak; our
//! method's absolute amplitude ratio to the ground truth is reported too.

use super::baselines::{delta_mush, laplacian_deform, DeltaMushParams, LaplacianParams};
use super::deformer::{Direction, MappingMethod, PlateDeformer, RegionOptions};
pub use super::delaunay::delaunay;
use super::reference::solve_clamped;
use super::PlateError;
use crate::mesh::Mesh;
use crate::polygon::point_in_polygon as inside;

/// Region shapes of the comparisons.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Shape {
    Square,
    Rectangle,
    Triangle,
    Pentagram,
    Circle,
}

impl Shape {
    pub const ALL: [Shape; 5] = [
        Shape::Square,
        Shape::Rectangle,
        Shape::Triangle,
        Shape::Pentagram,
        Shape::Circle,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Shape::Square => "square",
            Shape::Rectangle => "rectangle",
            Shape::Triangle => "triangle",
            Shape::Pentagram => "pentagram",
            Shape::Circle => "circle",
        }
    }

    pub fn parse(s: &str) -> Option<Shape> {
        Shape::ALL.into_iter().find(|x| x.name() == s)
    }

    /// The boundary polygon (counter-clockwise, centred at the origin).
    pub fn polygon(self) -> Vec<[f64; 2]> {
        let reg = |n: usize, r: f64, phase: f64| -> Vec<[f64; 2]> {
            (0..n)
                .map(|i| {
                    let t = phase + std::f64::consts::TAU * i as f64 / n as f64;
                    [r * t.cos(), r * t.sin()]
                })
                .collect()
        };
        match self {
            Shape::Square => vec![[-0.8, -0.8], [0.8, -0.8], [0.8, 0.8], [-0.8, 0.8]],
            Shape::Rectangle => vec![[-1.0, -0.5], [1.0, -0.5], [1.0, 0.5], [-1.0, 0.5]],
            Shape::Triangle => reg(3, 1.0, std::f64::consts::FRAC_PI_2),
            Shape::Circle => reg(128, 1.0, 0.0),
            Shape::Pentagram => {
                let inner = (18f64.to_radians().sin()) / (54f64.to_radians().sin());
                (0..10)
                    .map(|i| {
                        let r = if i % 2 == 0 { 1.0 } else { inner };
                        let t = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * i as f64 / 5.0;
                        [r * t.cos(), r * t.sin()]
                    })
                    .collect()
            }
        }
    }
}

/// A flat sheet in the plane z = 0: an `n` x `n` grid over
/// $[-1.25, 1.25]^2$ (union-jack triangles).
pub fn sheet(n: usize) -> Mesh {
    let (pts, tris) = super::reference::rectangle_mesh(2.5, 2.5, n, n);
    Mesh::new(
        pts.iter().map(|p| [p[0], p[1], 0.0]).collect(),
        tris.iter().map(|t| t.map(|v| v as u32)).collect(),
    )
}

/// The sheet vertices inside (or within 1e-9 of) `polygon`.
pub fn region_in_polygon(mesh: &Mesh, polygon: &[[f64; 2]]) -> Vec<u32> {
    let eps = 1e-9;
    (0..mesh.positions.len() as u32)
        .filter(|&i| {
            let p = mesh.positions[i as usize];
            [[0.0, 0.0], [eps, 0.0], [-eps, 0.0], [0.0, eps], [0.0, -eps]]
                .iter()
                .any(|o| inside(polygon, [p[0] + o[0], p[1] + o[1]]))
        })
        .collect()
}

/// Error of one method against the ground truth.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MethodError {
    pub method: &'static str,
    /// RMS over the region of (normalised deflection - normalised truth).
    pub rms: f64,
    /// Max over the region of the same.
    pub max: f64,
}

/// One comparison: deflection fields on the region vertices.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Comparison {
    pub shape: Shape,
    pub grid: usize,
    /// Region vertex indices into the sheet.
    pub region: Vec<u32>,
    /// Sheet positions of the region vertices.
    pub xy: Vec<[f64; 2]>,
    /// Normalised (unit peak) deflections: truth, ours (eq 16 mapping),
    /// ours with the harmonic mapping, Delta Mush, Laplacian.
    pub truth: Vec<f64>,
    pub ours: Vec<f64>,
    pub ours_harmonic: Vec<f64>,
    pub delta_mush: Vec<f64>,
    pub laplacian: Vec<f64>,
    pub errors: Vec<MethodError>,
    /// Our peak deflection over the ground truth's, same q and D.
    pub amplitude_ratio: f64,
    pub delta_mush_params: DeltaMushParams,
    pub laplacian_params: LaplacianParams,
}

fn normalise(w: &[f64]) -> Vec<f64> {
    let peak = w.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if peak > 0.0 {
        w.iter().map(|x| x / peak).collect()
    } else {
        w.to_vec()
    }
}

fn errors(method: &'static str, w: &[f64], truth: &[f64]) -> MethodError {
    let n = w.len().max(1) as f64;
    let d: Vec<f64> = w.iter().zip(truth).map(|(a, b)| a - b).collect();
    MethodError {
        method,
        rms: (d.iter().map(|x| x * x).sum::<f64>() / n).sqrt(),
        max: d.iter().fold(0.0, |m, x| m.max(x.abs())),
    }
}

/// Grid cells per side of the comparison sheet of `pdesculpt plate compare`.
pub const COMPARE_GRID_DEFAULT: usize = 60;

/// Runs the comparison of Figs 11-12 on a `grid` x `grid` sheet.
pub fn compare(
    shape: Shape,
    grid: usize,
    dm: &DeltaMushParams,
    lap: &LaplacianParams,
) -> Result<Comparison, PlateError> {
    if !(8..=400).contains(&grid) {
        return Err(PlateError::Parameter {
            name: "grid",
            value: grid as f64,
            range: "8..=400",
        });
    }
    let mesh = sheet(grid);
    let region = region_in_polygon(&mesh, &shape.polygon());
    let opts = RegionOptions {
        view: Some([0.0, 0.0, 1.0]),
        ..RegionOptions::default()
    };
    let plate = PlateDeformer::new(&mesh, &region, &opts)?;
    let d = [0.0, 0.0, 1.0];
    let ours_mesh = plate.deform(&mesh, d, 1.0, Direction::Normal)?;
    // ground truth on the region's triangles, same q = 1 and D
    let (xy, tris) = region_triangles(&mesh, plate.region());
    let gt = solve_clamped(&xy, &tris, &vec![1.0; xy.len()], plate.rigidity())?;
    let z = |m: &Mesh| -> Vec<f64> {
        plate
            .region()
            .iter()
            .map(|&v| m.positions[v as usize][2])
            .collect()
    };
    let ours_raw = z(&ours_mesh);
    let gt_peak = gt.w.iter().fold(0.0f64, |m, x| m.max(*x));
    let ours_peak = ours_raw.iter().fold(0.0f64, |m, x| m.max(*x));
    let handle = centre_handle(plate.region(), &xy, plate.boundary().d_p);
    let harm = PlateDeformer::new(
        &mesh,
        &region,
        &RegionOptions {
            mapping: MappingMethod::Harmonic,
            ..opts
        },
    )?;
    let harm_mesh = harm.deform(&mesh, d, 1.0, Direction::Normal)?;
    let lap_mesh = laplacian_deform(&mesh, plate.region(), &handle, [0.0, 0.0, 1.0], lap)?;
    let dm_mesh = delta_mush(&mesh, plate.region(), plate.region(), [0.0, 0.0, 1.0], dm)?;
    let truth = normalise(&gt.w);
    let ours = normalise(&ours_raw);
    let ours_harmonic = normalise(&z(&harm_mesh));
    let delta = normalise(&z(&dm_mesh));
    let lapz = normalise(&z(&lap_mesh));
    let errors = vec![
        errors("ours", &ours, &truth),
        errors("ours_harmonic", &ours_harmonic, &truth),
        errors("delta_mush", &delta, &truth),
        errors("laplacian", &lapz, &truth),
    ];
    Ok(Comparison {
        shape,
        grid,
        region: plate.region().to_vec(),
        xy,
        truth,
        ours,
        ours_harmonic,
        delta_mush: delta,
        laplacian: lapz,
        errors,
        amplitude_ratio: if gt_peak > 0.0 {
            ours_peak / gt_peak
        } else {
            f64::NAN
        },
        delta_mush_params: *dm,
        laplacian_params: *lap,
    })
}

/// The region's planar mesh: its vertices' (x, y) in region order and the
/// triangles of `mesh` inside it, indexed in that order.
fn region_triangles(mesh: &Mesh, region: &[u32]) -> (Vec<[f64; 2]>, Vec<[usize; 3]>) {
    let mut local = vec![usize::MAX; mesh.positions.len()];
    for (k, &v) in region.iter().enumerate() {
        local[v as usize] = k;
    }
    let xy: Vec<[f64; 2]> = region
        .iter()
        .map(|&v| {
            let p = mesh.positions[v as usize];
            [p[0], p[1]]
        })
        .collect();
    let tris: Vec<[usize; 3]> = mesh
        .triangles
        .iter()
        .filter_map(|t| {
            let l = t.map(|v| local[v as usize]);
            l.iter().all(|&x| x != usize::MAX).then_some(l)
        })
        .collect();
    (xy, tris)
}

/// The baselines' handle: the region vertices (planar positions `xy`)
/// within 1.5 `d_p` of their centroid, or the region's first vertex.
fn centre_handle(region: &[u32], xy: &[[f64; 2]], d_p: f64) -> Vec<u32> {
    let c = d_p;
    let centre = {
        let n = xy.len() as f64;
        xy.iter()
            .fold([0.0, 0.0], |a, p| [a[0] + p[0] / n, a[1] + p[1] / n])
    };
    let mut handle: Vec<u32> = region
        .iter()
        .zip(xy)
        .filter(|(_, p)| (p[0] - centre[0]).hypot(p[1] - centre[1]) <= 1.5 * c)
        .map(|(&v, _)| v)
        .collect();
    if handle.is_empty() {
        handle.push(region[0]);
    }
    handle
}
