//! Checks of the ode6 family: bases for every parameter case against an
//! independent 60-digit matrix-exponential solution, boundary constraints
//! and ODE residuals per case, the named errors, the printed forms, the
//! difference formulas, sculpting forces, and C2 joins in u and v.

use super::basis::{classify_closed, Basis, Params};
use super::boundary::{Approach2, BoundaryCurves, Curve, DiffFormula};
use super::force::Force;
use super::paper;
use super::samples::{chain, grid_3x2, grid_knots, test_curve, test_gecs};
use super::surface::{Grid, GridJumps, Ode6Surface, VSplit};
use super::Ode6Error;
use crate::check::Worst;
use crate::check::{tol, Check, Kind};
use crate::jet::Jet;
use crate::surface::{Joined, Surface};
mod boundary;
pub use boundary::gec_boundary_error;
use boundary::{degenerate_checks, gec_check};
mod reference;
use reference::{difference_checks, series_checks};
mod paper_literal;
use paper_literal::paper_literal_checks;
mod residual;
use residual::force_checks;
mod continuity;
mod derivation;
mod network;
use continuity::continuity_checks;
pub use network::NETWORK_C2;

const FAMILY: &str = "ode6";
const PAPER: &str = "004";
/// The verify script's goldens.
pub const GOLDEN: &str = include_str!("../../../verify/golden/ode6_basis.json");
/// Bound on `distance / sqrt(rho/eta)` of the `rho -> 0+` limit check
/// (positions converge like `sqrt(rho/eta)`).
pub const RHO_LIMIT_CONST: f64 = 10.0;

fn ck(eq: &str, name: &str, kind: Kind, measured: f64, tolerance: f64, note: &str) -> Check {
    Check::new(FAMILY, PAPER, eq, name, kind, measured, tolerance).note(note)
}

/// The named parameter cases of the golden file.
pub fn golden_cases() -> Vec<(String, Params)> {
    let v: serde_json::Value = serde_json::from_str(GOLDEN).unwrap_or_default();
    v["cases"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|c| {
                    let f = |k: &str| c[k].as_f64().unwrap_or(f64::NAN);
                    (
                        c["name"].as_str().unwrap_or("?").to_string(),
                        Params::new(f("rho"), f("eta"), f("lambda")),
                    )
                })
                .collect()
        })
        .unwrap_or_default()
}

/// Largest error of the Rust basis against the golden `g_j^{(d)}(u)`,
/// relative to the largest golden magnitude of that `(j, d)`.
fn golden_error(b: &Basis, case: &serde_json::Value) -> f64 {
    let us: Vec<f64> = case["us"]
        .as_array()
        .map(|a| a.iter().filter_map(|x| x.as_f64()).collect())
        .unwrap_or_default();
    if us.is_empty() {
        return f64::NAN;
    }
    let g = &case["g"];
    let mut err = 0.0f64;
    for j in 0..6 {
        for d in 0..3 {
            let gold: Vec<f64> = (0..us.len())
                .map(|i| g[i][j][d].as_f64().unwrap_or(f64::NAN))
                .collect();
            let scale = gold.iter().fold(1.0f64, |a, b| a.worst(b.abs()));
            for (i, &u) in us.iter().enumerate() {
                let ours = b.g(Jet::<3, 1>::var_u(u))[j].deriv(d, 0);
                err = err.worst((ours - gold[i]).abs() / scale);
            }
        }
    }
    err
}

/// Smallest derivative magnitude at the grid's joins for its continuity
/// check to count (below it the check fails as vacuous).
pub const GRID_MAGNITUDE_FLOOR: f64 = 0.1;

/// All checks of the ode6 family.
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    let golden: serde_json::Value = serde_json::from_str(GOLDEN).unwrap_or_default();
    let empty = Vec::new();
    let cases = golden["cases"].as_array().unwrap_or(&empty);
    out.push(ck(
        "eq 19",
        "ode6.golden_cases_present",
        Kind::Reference,
        if cases.len() >= 15 { 0.0 } else { 1.0 },
        0.0,
        "the golden file holds the parameter cases (every root case)",
    ));
    for case in cases {
        let name = case["name"].as_str().unwrap_or("?");
        let f = |k: &str| case[k].as_f64().unwrap_or(f64::NAN);
        let p = Params::new(f("rho"), f("eta"), f("lambda"));
        match Basis::new(p) {
            Ok(b) => {
                let cname = b.case.name();
                let amp = b.coef_magnitude();
                out.push(ck(
                    "eqs 8-19",
                    &format!("ode6.golden.{name}"),
                    Kind::Reference,
                    golden_error(&b, case),
                    tol::SOLVE,
                    &format!("g_j, g_j', g_j'' at 6 u against the 60-digit companion-matrix exponential (verify/ode6_golden.py); case: {cname}"),
                ));
                out.push(ck(
                    "eq 1",
                    &format!("ode6.boundary.{name}"),
                    Kind::Boundary,
                    b.boundary_error(),
                    tol::scaled(tol::SOLVE, amp * 1e-3),
                    &format!("g_j^(i)(0), g_j^(i)(1) against the unit constraints (jets); coefficient magnitude {amp:.1e}"),
                ));
                // C2 across the joins of a 2 x 2 grid whose columns both use
                // this case (separate patches, Hermite constraint curves).
                let knots: Vec<_> = grid_knots().into_iter().take(3).collect();
                let rel = Grid::from_knots(&knots, vec![b.clone(), b.clone()])
                    .map(|g| g.join_jumps(8).relative(GRID_MAGNITUDE_FLOOR))
                    .unwrap_or(f64::NAN);
                out.push(ck(
                    "eqs 23-26",
                    &format!("ode6.continuity.{name}"),
                    Kind::Continuity,
                    rel,
                    tol::scaled(tol::SOLVE, amp * 1e-3),
                    "2 x 2 grid, both columns this case: largest jump of d^jS/du^j, d^jS/dv^j (j <= 2) across the u- and v-joins relative to the derivative's magnitude there (fails below magnitude 0.1 as vacuous)",
                ));
                out.push(ck(
                    "eq 8",
                    &format!("ode6.residual.{name}"),
                    Kind::Residual,
                    b.residual_error(8),
                    tol::SOLVE,
                    "|rho g'''''' + eta g'''' + lambda g''| / (sum of the three magnitudes) at 9 u (jets)",
                ));
            }
            Err(e) => out.push(ck(
                "eqs 8-19",
                &format!("ode6.golden.{name}"),
                Kind::Reference,
                f64::NAN,
                tol::SOLVE,
                &format!("basis failed: {e}"),
            )),
        }
    }
    out.extend(series_checks());
    out.extend(degenerate_checks(&golden));
    out.extend(paper_literal_checks());
    out.extend(difference_checks());
    out.extend(force_checks());
    out.extend(continuity_checks());
    out.extend(derivation::derivation_checks());
    out.extend(derivation::approach1_join_checks());
    out.push(gec_check());
    out.extend(network::network_checks());
    out
}
