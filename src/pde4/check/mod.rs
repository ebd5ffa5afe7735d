//! Checks of the pde4 family (paper 000 eqs 1-15, appendices A, B; classical
//! clamped-plate values from Timoshenko & Woinowsky-Krieger, *Theory of Plates
//! and Shells*, 2nd ed., tables 35 and 40 area; 0.00126532 from Taylor &
//! Govindjee's 2004 high-precision clamped-square solution). The sinusoidally
//! loaded clamped plates have no trusted published value at hand: they are
//! checked against the independent finite-difference solver [`super::fd`],
//! itself checked against the published uniform-load value.

use super::force::{printed_four_sided, printed_two_sided};
use super::four_sided::{self, FourSided};
use super::samples::{mixed_shapes, root_cases, sample_boundary, sample_forces, SINE_LOAD};
use super::two_sided::{self, basis_b, Boundary, Mode, TwoSided};
use super::{Force, ForceKind, ShapeParams};
use crate::check::{tol, Check, Kind};
use crate::jet::Jet;
use crate::surface::Surface;
use serde_json::Value;
use std::f64::consts::PI;
mod appendix;
mod forces;
use forces::force_checks;
mod two_sided_patch;
use two_sided_patch::two_sided_checks;
pub use two_sided_patch::{two_sided_boundary, two_sided_residual};
mod four_sided_patch;
mod paper_literal;
use four_sided_patch::four_sided_checks;
pub use four_sided_patch::plate_centre;
use paper_literal::printed_statement_checks;
pub use paper_literal::{printed_area_profile, printed_line_profile};

const F: &str = "pde4";
const P: &str = "000";
/// The golden file of `verify/pde4_derive.py`.
pub const GOLDEN: &str = include_str!("../../../verify/golden/pde4_derive.json");

/// Clamped square plate, uniform load: `w_max = 0.00126 q a^4 / D` (Timoshenko table 35).
pub const PLATE_SQUARE_UNIFORM: f64 = 0.00126;
/// Same, to six digits (Taylor & Govindjee 2004).
pub const PLATE_SQUARE_UNIFORM_PRECISE: f64 = 0.001_265_32;
/// Clamped rectangle `b/a = 1.5`, uniform load: `0.00220 q a^4 / D` (table 35).
pub const PLATE_RECT_15_UNIFORM: f64 = 0.00220;
/// Clamped rectangle `b/a = 2`, uniform load: `0.00254 q a^4 / D` (table 35).
pub const PLATE_RECT_2_UNIFORM: f64 = 0.00254;
/// Clamped square, central concentrated load: `0.00560 P a^2 / D`.
pub const PLATE_SQUARE_POINT: f64 = 0.00560;
/// Coarse grid of the Richardson-extrapolated finite-difference reference
/// ([`super::fd`]; the fine grid is twice as dense).
pub const FD_GRID: usize = 40;
/// Terms per direction of the Galerkin plate checks.
pub const PLATE_TERMS: usize = 16;
/// Eq 4 / eq 11 partial sums of an area force at 64 terms, sampled inside the
/// support: the sine bump has a kink at its edges, so the sums converge like 1/M.
pub const SERIES_TOL: f64 = 2e-3;

/// `|a - b| / |b|` (true relative error; the plate values are ~1e-3).
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn arr(v: &Value) -> Vec<f64> {
    v.as_array()
        .map(|a| a.iter().filter_map(Value::as_f64).collect())
        .unwrap_or_default()
}

fn golden() -> Value {
    serde_json::from_str(GOLDEN).unwrap_or(Value::Null)
}

/// All checks of the pde4 family.
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    force_checks(&mut out);
    appendix::appendix_checks(&mut out);
    two_sided_checks(&mut out);
    four_sided_checks(&mut out);
    printed_statement_checks(&mut out);
    out
}
