//! Boundary checks: GEC boundary curves (approach 1) and degenerate parameter limits.

use super::*;
use crate::check::{worst, Worst};

/// Largest error of a patch from GEC boundary curves (approach 1) against
/// the GECs evaluated by [`Gec::eval_v`] itself: positions, u-derivatives
/// `w c` and v-derivatives of the boundaries, at 24 v (jets).
pub fn gec_boundary_error(p: Params, w: [f64; 4]) -> Result<f64, Ode6Error> {
    let (ga, gb) = test_gecs();
    let s = Ode6Surface::new(
        Basis::new(p)?,
        BoundaryCurves::approach1(Curve::from_gec(&ga)?, Curve::from_gec(&gb)?, w)?,
    );
    let mut err = 0.0f64;
    for i in 0..24 {
        let v = i as f64 / 24.0;
        for (g, u, scale) in [(&ga, 0.0, [1.0, w[0], w[1]]), (&gb, 1.0, [1.0, w[2], w[3]])] {
            let pt = s.eval(Jet::<3, 3>::var_u(u), Jet::<3, 3>::var_v(v));
            let gv = g.eval_v(Jet::<1, 3>::var_v(v));
            for k in 0..3 {
                for (du, sc) in scale.iter().enumerate() {
                    for dv in 0..3 {
                        err = err.worst((pt[k].deriv(du, dv) - sc * gv[k].deriv(0, dv)).abs());
                    }
                }
            }
        }
    }
    Ok(err)
}

pub(super) fn gec_check() -> Check {
    let cases = [
        (Params::new(1.0, 3.0, 1.0), [1.0, 0.5, -1.0, 2.0]),
        (Params::new(1.0, 1.0, 3.0), [0.0, 3.0, 0.0, -3.0]),
        (Params::new(1e-4, 3.0, 1e-4), [2.0, 0.0, 1.0, 0.0]),
    ];
    let err = cases
        .iter()
        .map(|(p, w)| gec_boundary_error(*p, *w).unwrap_or(f64::NAN))
        .fold(
            0.0f64,
            |a, b| if b.is_nan() { f64::NAN } else { a.worst(b) },
        );
    ck(
        "eq 1",
        "ode6.boundary.gec_curves",
        Kind::Boundary,
        err,
        tol::SOLVE,
        "approach 1 from two GECs in tilted frames (crate::curve::gec): S, S_u, S_uu at u = 0, 1 and their v-derivatives up to 2 against w * Gec::eval_v (3 parameter cases, 24 v, jets)",
    )
}

/// rho = 0, the singular system, bad input: named errors and the limit.
pub(super) fn degenerate_checks(golden: &serde_json::Value) -> Vec<Check> {
    let mut out = Vec::new();
    let s = &golden["singular"];
    let p = Params::new(
        s["rho"].as_f64().unwrap_or(f64::NAN),
        s["eta"].as_f64().unwrap_or(f64::NAN),
        s["lambda"].as_f64().unwrap_or(f64::NAN),
    );
    let singular_named = matches!(Basis::new(p), Err(Ode6Error::Singular { .. }));
    out.push(ck(
        "eq 1",
        "ode6.singular_system_named_error",
        Kind::Boundary,
        if singular_named { 0.0 } else { 1.0 },
        0.0,
        "parameters where the 6x6 boundary system is singular (a zero of its determinant found by verify/ode6_golden.py) give Ode6Error::Singular",
    ));
    let rho0 = matches!(
        Basis::new(Params::new(0.0, 1.0, 1.0)),
        Err(Ode6Error::RhoZero { .. })
    );
    let bad = [
        Params::new(f64::NAN, 1.0, 1.0),
        Params::new(1.0, f64::INFINITY, 1.0),
        Params::new(0.0, 0.0, 0.0),
    ]
    .iter()
    .all(|p| Basis::new(*p).is_err());
    out.push(ck(
        "eq 2",
        "ode6.degenerate_parameters_named_error",
        Kind::Boundary,
        if rho0 && bad { 0.0 } else { 1.0 },
        0.0,
        "rho = 0 gives Ode6Error::RhoZero; NaN, infinite and all-zero parameters give named errors",
    ));
    // Reduced rho = 0 problems: boundary + residual of the fourth/second-order equation.
    let mut worst_b = 0.0f64;
    let mut worst_r = 0.0f64;
    for p in [
        Params::new(0.0, 1.0, 1.0),
        Params::new(0.0, 1.0, -30.0),
        Params::new(0.0, 0.01, 3.0),
        Params::new(0.0, 1.0, 0.0),
        Params::new(0.0, 0.0, 2.0),
    ] {
        match Basis::reduced(p) {
            Ok(b) => {
                worst_b = worst_b.worst(b.boundary_error());
                worst_r = worst_r.worst(b.residual_error(8));
            }
            Err(_) => worst_b = f64::NAN,
        }
    }
    out.push(ck(
        "eq 1",
        "ode6.boundary.rho_zero_reduced",
        Kind::Boundary,
        worst_b,
        tol::SOLVE,
        "rho = 0: positions and tangents met (4 constraints; eta = 0: positions only)",
    ));
    out.push(ck(
        "eq 8",
        "ode6.residual.rho_zero_reduced",
        Kind::Residual,
        worst_r,
        tol::SOLVE,
        "rho = 0: residual of eta S'''' + lambda S'' = 0 (jets)",
    ));
    out.push(rho_limit_check());
    out
}

/// The limit rho -> 0+: the positions approach the reduced solution like
/// sqrt(rho / eta).
fn rho_limit_check() -> Check {
    let c = [1.0, -0.5, 3.0, 0.2, 0.7, -2.0];
    let dist_to_reduced = |rho: f64| match (
        Basis::new(Params::new(rho, 1.0, 1.0)),
        Basis::reduced(Params::new(0.0, 1.0, 1.0)),
    ) {
        (Ok(a), Ok(b)) => (0..=40)
            .map(|i| {
                let u = i as f64 / 40.0;
                (a.line(u, &c) - b.line(u, &c)).abs()
            })
            .fold(0.0, worst),
        _ => f64::NAN,
    };
    let ratios: Vec<f64> = (6..=12)
        .map(|k| dist_to_reduced(10f64.powi(-k)) / 10f64.powi(-k).sqrt())
        .collect();
    let worst = ratios.iter().fold(
        0.0f64,
        |a, b| if b.is_nan() { f64::NAN } else { a.worst(*b) },
    );
    ck(
        "eq 2",
        "ode6.rho_to_zero_limit",
        Kind::Reference,
        worst,
        RHO_LIMIT_CONST,
        &format!(
            "rho -> 0+ (eta = lambda = 1, c3 = 3, c6 = -2): max distance of the positions to the reduced rho = 0 solution over sqrt(rho/eta), rho = 1e-6..1e-12 ({}); not uniform: it peaks where omega = sqrt(eta/rho) nears a singular system",
            ratios.iter().map(|r| format!("{r:.2}")).collect::<Vec<_>>().join(", ")
        ),
    )
}
