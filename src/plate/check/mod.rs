//! Checks of the plate family (paper 001). They measure and report; the
//! tests assert on them.

use super::deformer::{Direction, PlateDeformer, RegionOptions};
use super::mapping::eq16_paper_literal;
use super::projection::{project, project_paper_literal, LocalFrame, ViewPlane};
use super::reference::{ellipse_mesh, rectangle_mesh, solve_clamped, CLAMPED_RECTANGLE};
use super::shapes::{region_in_polygon, sheet, Shape};
use super::{disk_profile, disk_solution, Material, PlateError};
use crate::check::{max_abs_diff, rel_err, tol, Check, Kind};
use crate::check::{worst, Worst};
use crate::jet::Jet4x4;
mod equations;
mod projection;
mod reference;
use equations::equation_checks;
use projection::projection_checks;
pub use projection::{square_slope_jump, SLOPE_JUMP_TOL};
use reference::reference_checks;
pub use reference::{
    ellipse_centre, observed_order, pipeline_circle, rectangle_centre, ORDER_TOL, PIPELINE_GRID,
    PIPELINE_ORDER1_FACTOR, REFERENCE_CELLS, REFERENCE_RINGS_CIRCLE, REFERENCE_RINGS_ELLIPSE,
};
use serde::Deserialize;

const F: &str = "plate";
const P: &str = "001";

#[derive(Deserialize)]
struct Sample {
    u: f64,
    v: f64,
    w: f64,
}
#[derive(Deserialize)]
pub(super) struct Eq13 {
    plane: [f64; 4],
    p: [f64; 3],
    correct: [f64; 3],
    printed: [f64; 3],
}
#[derive(Deserialize)]
struct Golden {
    rigidity_default: f64,
    eq12_samples: Vec<Sample>,
    eq13_case: Eq13,
    ellipse_centre_a1_b0p5: f64,
}

fn golden() -> Golden {
    serde_json::from_str(include_str!("../../../verify/golden/plate_model.json"))
        .expect("committed golden JSON parses")
}

/// All checks of the plate family.
pub fn checks() -> Vec<Check> {
    let g = golden();
    let mut out = Vec::new();
    let mat = Material::default();
    let d = mat.rigidity().unwrap_or(f64::NAN);
    out.push(
        Check::new(
            F,
            P,
            "eq 3",
            "plate.rigidity.default",
            Kind::Reference,
            rel_err(d, g.rigidity_default),
            tol::ROUNDING,
        )
        .note("D = E h^3/(12(1-mu^2)) with E=1e6, mu=0.5, h=0.1 against SymPy (111.11)"),
    );
    // eq 12: golden samples, biharmonic residual, C1 on the unit circle
    let err = g
        .eq12_samples
        .iter()
        .map(|s| (disk_solution(1.0, 1.0, s.u, s.v) - s.w).abs())
        .fold(0.0, worst);
    out.push(
        Check::new(
            F,
            P,
            "eq 12",
            "plate.eq12.golden",
            Kind::Reference,
            err,
            tol::ROUNDING,
        )
        .note("q/(64D)(u^2+v^2-1)^2 at 5 points against SymPy"),
    );
    let (q, dd) = (3.7, d);
    let mut res: f64 = 0.0;
    let mut bc: f64 = 0.0;
    for k in 0..16 {
        let t = k as f64 * 0.39;
        let (u0, v0) = (0.6 * t.cos() * (k as f64 / 16.0), 0.6 * t.sin());
        let w = disk_solution(q, dd, Jet4x4::var_u(u0), Jet4x4::var_v(v0));
        let bl = w.deriv(4, 0) + 2.0 * w.deriv(2, 2) + w.deriv(0, 4);
        res = res.worst((dd * bl - q).abs() / q);
        let (uc, vc) = (t.cos(), t.sin());
        let wb = disk_solution(q, dd, Jet4x4::var_u(uc), Jet4x4::var_v(vc));
        bc = bc
            .worst(wb.value().abs())
            .worst(wb.deriv(1, 0).abs())
            .worst(wb.deriv(0, 1).abs());
    }
    out.push(
        Check::new(
            F,
            P,
            "eq 1, 12",
            "plate.eq12.biharmonic_residual",
            Kind::Residual,
            res,
            tol::ROUNDING,
        )
        .note("|D lap^2 xi - q|/q of eq 12 at 16 interior points, derivatives from jets"),
    );
    out.push(
        Check::new(
            F,
            P,
            "eq 7, 12",
            "plate.eq12.c1_boundary",
            Kind::Boundary,
            bc / (q / dd),
            tol::ROUNDING,
        )
        .note("max |xi|, |xi_u|, |xi_v| on the unit circle (16 points, jets), relative to q/D"),
    );
    projection_checks(&mut out, &g.eq13_case);
    reference_checks(&mut out, g.ellipse_centre_a1_b0p5);
    equation_checks(&mut out);
    out
}
