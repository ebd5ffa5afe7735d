//! Residual checks: the forced ODE (eqs 24-29) from jets.

use super::*;
use crate::check::{worst, Worst};

/// The approach-1 curves of the forced surfaces.
fn curves() -> Result<BoundaryCurves, Ode6Error> {
    BoundaryCurves::approach1(
        Curve::Fourier(test_curve(1.0, 0.0, 0.0)),
        Curve::Fourier(test_curve(0.6, 1.0, 1.0)),
        [1.0, 0.5, -1.0, 2.0],
    )
}

/// Forced surfaces: residual of eq 2 and the constraints.
pub(super) fn force_checks() -> Vec<Check> {
    let forces = [
        Force::Polynomial {
            coef: vec![
                [1.0, 0.0, 2.0],
                [0.0, -3.0, 0.0],
                [0.5, 0.5, 0.5],
                [0.0, 0.0, -1.0],
                [0.2, 0.0, 0.0],
            ],
        },
        Force::Sine {
            amp: [0.0, 2.0, 1.0],
            kappa: 4.0,
            phase: 0.3,
        },
    ];
    let params = [
        Params::new(1.0, 3.0, 1.0),
        Params::new(1.0, 1.0, 3.0),
        Params::new(0.01, 1.0, 0.0),
        Params::new(1.0, 0.0, 0.0),
    ];
    let mut res = 0.0f64;
    let mut bnd = 0.0f64;
    for p in params {
        for f in &forces {
            let s = match (Basis::new(p), curves()) {
                (Ok(b), Ok(c)) => Ode6Surface::new(b, c).with_force(f),
                _ => Err(Ode6Error::AllZero),
            };
            let Ok(s) = s else {
                res = f64::NAN;
                continue;
            };
            for iu in 0..=6 {
                for iv in 0..4 {
                    let (u, v) = (iu as f64 / 6.0, iv as f64 / 4.0);
                    let pt = s.eval(Jet::<7, 1>::var_u(u), Jet::<7, 1>::constant(v));
                    let fu = f.eval(u);
                    for k in 0..3 {
                        let (a, b, c) = (
                            p.rho * pt[k].deriv(6, 0),
                            p.eta * pt[k].deriv(4, 0),
                            p.lambda * pt[k].deriv(2, 0),
                        );
                        let scale = a.abs() + b.abs() + c.abs() + fu[k].abs();
                        res = res.worst((a + b + c - fu[k]).abs() / scale.worst(1.0));
                    }
                }
            }
            for iv in 0..4 {
                let v = iv as f64 / 4.0;
                for (end, u) in [(0usize, 0.0), (3, 1.0)] {
                    let pt = s.eval(Jet::<3, 1>::var_u(u), Jet::<3, 1>::constant(v));
                    for i in 0..3 {
                        let c = s.curves.c(end + i, v);
                        for k in 0..3 {
                            bnd = bnd.worst((pt[k].deriv(i, 0) - c[k]).abs());
                        }
                    }
                }
            }
        }
    }
    let resonant_res = resonant_residual();
    let double = Basis::new(Params::new(1.0, 50.0, 625.0))
        .ok()
        .and_then(|b| curves().ok().map(|c| Ode6Surface::new(b, c)))
        .map(|s| {
            s.with_force(&Force::Sine {
                amp: [1.0, 0.0, 0.0],
                kappa: 5.0,
                phase: 0.0,
            })
        });
    let resonant = matches!(double, Some(Err(Ode6Error::Resonance { .. })));
    vec![
        ck("eq 2", "ode6.force_residual", Kind::Residual, res, tol::SOLVE, "rho S'''''' + eta S'''' + lambda S'' - F on forced surfaces (polynomial and sine F; 4 parameter sets incl. lambda = 0 and eta = lambda = 0), relative, jets"),
        ck("eq 1", "ode6.force_boundary", Kind::Boundary, bnd, tol::SOLVE, "forced surfaces still meet the six constraints (approach 1 curves)"),
        ck("eq 2", "ode6.force_resonant_residual", Kind::Residual, resonant_res, tol::SOLVE, "sine force at the simple resonance kappa^2 = -q_1 (rho = lambda = 1, eta = 3): u cos particular solution, relative residual of eq 2 (jets)"),
        ck("eq 2", "ode6.force_double_resonance_named_error", Kind::Residual, if resonant { 0.0 } else { 1.0 }, 0.0, "a sine force at the repeated root q = -25 (rho = 1, eta = 50, lambda = 625, kappa = 5) gives Ode6Error::Resonance"),
    ]
}

/// Simple resonance (kappa^2 = -q_1): the u cos particular solution, the
/// relative residual of eq 2 on the full forced surface (jets). The double
/// resonance (repeated root) is a named error, checked in [`force_checks`].
fn resonant_residual() -> f64 {
    let q1 = Params::new(1.0, 3.0, 1.0).q_roots()[0].0;
    match (Basis::new(Params::new(1.0, 3.0, 1.0)), curves()) {
        (Ok(b), Ok(c)) => {
            let f = Force::Sine {
                amp: [1.0, -0.5, 0.2],
                kappa: (-q1).sqrt(),
                phase: 0.4,
            };
            match Ode6Surface::new(b, c).with_force(&f) {
                Ok(s) => (0..=8)
                    .map(|i| {
                        let u = i as f64 / 8.0;
                        let pt = s.eval(Jet::<7, 1>::var_u(u), Jet::<7, 1>::constant(0.3));
                        let fu = f.eval(u);
                        (0..3)
                            .map(|k| {
                                let (a, b, c) = (
                                    pt[k].deriv(6, 0),
                                    3.0 * pt[k].deriv(4, 0),
                                    pt[k].deriv(2, 0),
                                );
                                (a + b + c - fu[k]).abs()
                                    / (a.abs() + b.abs() + c.abs() + fu[k].abs()).worst(1.0)
                            })
                            .fold(0.0, worst)
                    })
                    .fold(0.0, worst),
                Err(_) => f64::NAN,
            }
        }
        _ => f64::NAN,
    }
}
