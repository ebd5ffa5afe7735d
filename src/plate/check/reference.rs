//! Reference checks of the plate family: the independent Morley solver
//! against plate theory (disk, ellipse, rectangles, convergence order) and
//! the whole pipeline (projection, alpha shape, eq 16, eq 12) on a circular
//! region, where eq 12 is the exact clamped plate.

use super::*;
use crate::check::{worst, Worst};

/// Mesh resolution of the reference-solver checks: cells across the shorter
/// side of the square/rectangle. The errors are raw (no extrapolation); the
/// Morley centre deflection converges as $O(h^2)$ (measured order 1.95 on
/// 16, 32, 64 cells). Raw error of the clamped square against 0.00126532:
/// 20.5 % (8 cells), 5.6 % (16), 1.44 % (32), 0.64 % (48), 0.36 % (64),
/// 0.16 % (96), 0.09 % (128); b/a = 1.5 against 0.00220: 0.39 % (48),
/// 0.15 % (64); b/a = 2 against 0.00254: 0.28 % (48), 0.04 % (64).
pub const REFERENCE_CELLS: usize = 64;
/// Rings of the disk mesh (raw error 1.44 % at 12 rings, 0.36 % at 24,
/// 0.09 % at 48).
pub const REFERENCE_RINGS_CIRCLE: usize = 32;
/// Rings of the 2:1 ellipse mesh (raw error 4.2 % at 12 rings, 1.07 % at
/// 24, 0.27 % at 48).
pub const REFERENCE_RINGS_ELLIPSE: usize = 48;
/// Tolerance on the measured convergence order of the reference solver
/// (expected 2 for Morley vertex deflections).
pub const ORDER_TOL: f64 = 0.25;
/// Grid cells per side of the sheet in the pipeline check.
pub const PIPELINE_GRID: usize = 60;
/// The pipeline on a staircase region is first order in the grid spacing h
/// (the boundary polygon D_j of eq 16 is the staircase): the tolerance on
/// the normalised profile error is this factor times h.
pub const PIPELINE_ORDER1_FACTOR: f64 = 1.5;

/// Centre deflection of the Morley solution ($q = D = 1$) on the rectangle
/// $a \times b$ with `n` cells across the side `a`.
pub fn rectangle_centre(a: f64, b: f64, n: usize) -> Result<f64, PlateError> {
    let ny = ((n as f64) * b / a).round() as usize;
    let (pts, tris) = rectangle_mesh(a, b, n, usize::max(ny, 2) & !1);
    let s = solve_clamped(&pts, &tris, &vec![1.0; pts.len()], 1.0)?;
    let c = pts
        .iter()
        .position(|p| p[0].abs() < 1e-12 && p[1].abs() < 1e-12)
        .ok_or_else(|| PlateError::Solve("no centre vertex".into()))?;
    Ok(s.w[c])
}

/// Centre deflection of the Morley solution ($q = D = 1$) on the ellipse.
pub fn ellipse_centre(a: f64, b: f64, rings: usize) -> Result<f64, PlateError> {
    let (pts, tris) = ellipse_mesh(a, b, rings)?;
    let s = solve_clamped(&pts, &tris, &vec![1.0; pts.len()], 1.0)?;
    Ok(s.w[0])
}

/// Observed order from three centre deflections at h, h/2, h/4.
pub fn observed_order(w: [f64; 3]) -> f64 {
    ((w[0] - w[1]) / (w[1] - w[2])).abs().log2()
}

/// The reference-solver and pipeline checks (`ellipse_golden`: the exact
/// centre deflection of the clamped 2:1 ellipse, SymPy).
pub(super) fn reference_checks(out: &mut Vec<Check>, ellipse_golden: f64) {
    // reference solver against plate theory: raw (unextrapolated) errors
    let circ = ellipse_centre(1.0, 1.0, REFERENCE_RINGS_CIRCLE).unwrap_or(f64::NAN);
    out.push(Check::new(F, P, "eq 1, 4", "plate.reference.circle", Kind::Reference,
        (circ - 1.0 / 64.0).abs() * 64.0, tol::PLATE_THEORY)
        .note(format!("raw Morley FE centre deflection ({REFERENCE_RINGS_CIRCLE} rings, no extrapolation) of the clamped unit disk vs exact q a^4/(64 D); order 2 (0.36 % at 24 rings, 0.09 % at 48)")));
    let ell = ellipse_centre(1.0, 0.5, REFERENCE_RINGS_ELLIPSE).unwrap_or(f64::NAN);
    out.push(Check::new(F, P, "eq 1, 4", "plate.reference.ellipse", Kind::Reference,
        (ell - ellipse_golden).abs() / ellipse_golden, tol::PLATE_THEORY)
        .note(format!("raw Morley FE centre deflection ({REFERENCE_RINGS_ELLIPSE} rings, no extrapolation) of the clamped 2:1 ellipse vs the exact solution (SymPy); order 2")));
    for (ratio, alpha, source) in CLAMPED_RECTANGLE {
        let w = rectangle_centre(1.0, ratio, REFERENCE_CELLS).unwrap_or(f64::NAN);
        out.push(Check::new(F, P, "eq 1, 4", &format!("plate.reference.rectangle_{ratio:.1}"), Kind::Reference,
            (w - alpha).abs() / alpha, tol::PLATE_THEORY)
            .note(format!("raw Morley FE w_max ({REFERENCE_CELLS} cells across a, no extrapolation) of the clamped {ratio}:1 rectangle vs alpha = {alpha} ({source})")));
    }
    let ws = [16, 32, 64].map(|k| rectangle_centre(1.0, 1.0, k).unwrap_or(f64::NAN));
    out.push(
        Check::new(
            F,
            P,
            "eq 1, 4",
            "plate.reference.convergence_order",
            Kind::Reference,
            (observed_order(ws) - 2.0).abs(),
            ORDER_TOL,
        )
        .note("|p - 2|, p the observed order of the square's centre deflection on 16, 32, 64 cells (1.95; 1.85 on 8, 16, 32; 1.98 on 32, 64, 128)"),
    );
    // the whole pipeline on a circular region: eq 12 is then the exact plate
    let (pipe, bnd) = pipeline_circle().unwrap_or((f64::NAN, f64::NAN));
    let h = 2.5 / PIPELINE_GRID as f64;
    out.push(Check::new(F, P, "eq 12-16", "plate.pipeline.circle_exact", Kind::Reference, pipe, PIPELINE_ORDER1_FACTOR * h)
        .note("circular region of a 61x61 sheet (h = 0.042): max |ours - (1-r^2)^2| (unit peak) through projection, alpha shape, eq 16, eq 12; tolerance 1.5 h"));
    out.push(
        Check::new(
            F,
            P,
            "eq 7",
            "plate.pipeline.boundary_fixed",
            Kind::Boundary,
            bnd,
            tol::ROUNDING,
        )
        .note("displacement of the alpha-shape boundary vertices after a cursor move"),
    );
}

/// Max error of the normalised pipeline deflection against the exact
/// circular plate, and the displacement of the boundary vertices.
pub fn pipeline_circle() -> Result<(f64, f64), PlateError> {
    let mesh = sheet(PIPELINE_GRID);
    let region = region_in_polygon(&mesh, &Shape::Circle.polygon());
    let opts = RegionOptions {
        view: Some([0.0, 0.0, 1.0]),
        ..RegionOptions::default()
    };
    let p = PlateDeformer::new(&mesh, &region, &opts)?;
    let m = p.deform(&mesh, [0.0, 0.0, 1.0], 50.0, Direction::Cursor)?;
    let z: Vec<f64> = p
        .region()
        .iter()
        .map(|&v| m.positions[v as usize][2])
        .collect();
    let peak = z.iter().fold(0.0f64, |a, b| a.worst(*b));
    // the region's boundary radius (outermost vertices)
    let rmax = p.local().iter().map(|q| q[0].hypot(q[1])).fold(0.0, worst);
    let mut err: f64 = 0.0;
    for (k, q) in p.local().iter().enumerate() {
        let r = q[0].hypot(q[1]) / rmax;
        err = err.worst((z[k] / peak - 64.0 * disk_profile(r)).abs());
    }
    let bnd = p
        .boundary()
        .loop_indices
        .iter()
        .map(|&i| (m.positions[p.region()[i] as usize][2]).abs())
        .fold(0.0, worst);
    Ok((err, bnd))
}
