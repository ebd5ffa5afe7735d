//! The property-testing harness (`pdesculpt::harness`) on the kit's own
//! families: each family passes every property that applies to it, on
//! inputs drawn by the harness's strategies.

use crate::strategies::config;
use pdesculpt::check::tol;
use pdesculpt::curve::gec::{self, FitOptions};
use pdesculpt::harness::properties::{
    boundary_gap, derivatives_vs_finite_differences, interior_points, joins_within, residual,
    within,
};
use pdesculpt::harness::strategies::{
    gec_section, ode6_shape, pde4_force, pde4_shape, pde6_shape, ring_curve,
};
use pdesculpt::ode6::{Basis, BoundaryCurves, Curve, Ode6Surface};
use pdesculpt::pde4::two_sided::Method;
use pdesculpt::pde4::TwoSided;
use pdesculpt::pde6::{Chain, Section};
use pdesculpt::surface::check::FD_TOL;
use proptest::prelude::*;

/// Points on a GEC sampled for a refit: enough for J = 4 (2J + 1 = 9).
const REFIT_POINTS: usize = 120;

proptest! {
    #![proptest_config(config(8))]

    /// pde4 (paper 000 eqs 1, 4, 5): a clamped 2-sided patch under a random
    /// force solves eq 1 against its force series and vanishes with its
    /// u-derivative at u = 0, 1.
    #[test]
    fn pde4_two_sided_meets_the_harness(shape in pde4_shape(), force in pde4_force()) {
        let t = TwoSided::new([shape; 3], &[force], 8, 6, Method::Exact, None)
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        let r = residual(&t, &interior_points(&t, 4), |d, u, v| {
            let (a, b, c) = (d.get(4, 0), d.get(2, 2), d.get(0, 4));
            let f: [f64; 3] = std::array::from_fn(|k| t.force_series(k, u, v));
            let res = std::array::from_fn(|k| shape.a1 * a[k] + shape.a2 * b[k] + shape.a3 * c[k] - f[k]);
            let scale = (0..3).map(|k| (shape.a1 * a[k]).abs().max((shape.a3 * c[k]).abs()).max(f[k].abs())).fold(0.0, f64::max);
            (res, scale)
        });
        within("eq 1 residual", r, tol::SOLVE)?;
        for u in [0.0, 1.0] {
            within("clamped position", boundary_gap(&t, u, 0, |_| [0.0; 3], 32), tol::SOLVE)?;
            within("clamped slope", boundary_gap(&t, u, 1, |_| [0.0; 3], 32), tol::SOLVE)?;
        }
        within("jets vs finite differences", derivatives_vs_finite_differences(&t), FD_TOL)?;
    }

    /// pde6 (paper 002 eqs 2, 24-27): the global C2 chain through seven
    /// random sections passes through them, is C2 at its joins and solves
    /// eq 2 on each patch.
    #[test]
    fn pde6_chain_meets_the_harness(
        a in pde6_shape(),
        curves in prop::collection::vec(ring_curve(2, 0.0), 7),
    ) {
        let sections: Vec<Section> = curves
            .into_iter()
            .enumerate()
            .map(|(i, mut c)| { c.c0[1] = 0.5 * i as f64; Section { u: i as f64 / 3.0, curve: c } })
            .collect();
        let chain = Chain::c2_global(a, &sections).map_err(|e| TestCaseError::fail(e.to_string()))?;
        for s in &sections {
            within("section interpolated", boundary_gap(&chain, s.u, 0, |v| s.curve.eval(v), 32), tol::SOLVE)?;
        }
        let jumps = joins_within(&chain, &chain.joins(), 2, 16);
        within("C0 at the joins", jumps[0], tol::JOIN)?;
        within("C1 at the joins", jumps[1], tol::JOIN)?;
        within("C2 at the joins", jumps[2], tol::JOIN)?;
        let r = residual(&chain, &interior_points(&chain, 4), |d, u, _| {
            let l6 = chain.pieces[chain.piece_at(u)].length.powi(6);
            let (w_u6, w_v6) = (d.get(6, 0), d.get(0, 6));
            let res = std::array::from_fn(|k| l6 * w_u6[k] + a * w_v6[k]);
            let scale = (0..3).map(|k| (l6 * w_u6[k]).abs().max((a * w_v6[k]).abs())).fold(0.0, f64::max);
            (res, scale)
        });
        within("eq 2 residual", r, tol::SOLVE)?;
        within("jets vs finite differences", derivatives_vs_finite_differences(&chain), FD_TOL)?;
    }

    /// ode6 (paper 004 eqs 1, 2): a patch meets its six constraint curves
    /// (position, first and second u-derivative at both ends) and every line
    /// solves eq 2.
    #[test]
    fn ode6_patch_meets_the_harness(
        params in ode6_shape(),
        curves in prop::collection::vec(ring_curve(2, 0.0), 6),
    ) {
        let c: [Curve; 6] = std::array::from_fn(|j| Curve::Fourier(curves[j].clone()));
        let s = Ode6Surface::new(
            Basis::new(params).map_err(|e| TestCaseError::fail(e.to_string()))?,
            BoundaryCurves::direct(c).map_err(|e| TestCaseError::fail(e.to_string()))?,
        );
        let scale = Basis::new(params).map(|b| b.coef_magnitude()).unwrap_or(1.0);
        for (j, (u, order)) in [(0.0, 0), (0.0, 1), (0.0, 2), (1.0, 0), (1.0, 1), (1.0, 2)].into_iter().enumerate() {
            let curve = &curves[j];
            let gap = boundary_gap(&s, u, order, |v| curve.eval(std::f64::consts::TAU * v), 32);
            within("eq 1 constraint", gap, tol::scaled(tol::SOLVE, scale))?;
        }
        let (rho, eta, lambda) = (params.rho, params.eta, params.lambda);
        let r = residual(&s, &interior_points(&s, 4), |d, _, _| {
            let (d6, d4, d2) = (d.get(6, 0), d.get(4, 0), d.get(2, 0));
            let res = std::array::from_fn(|k| rho * d6[k] + eta * d4[k] + lambda * d2[k]);
            let scale = (0..3).map(|k| (rho * d6[k]).abs().max((eta * d4[k]).abs()).max((lambda * d2[k]).abs())).fold(0.0, f64::max);
            (res, scale)
        });
        within("eq 2 residual", r, tol::SOLVE)?;
        within("jets vs finite differences", derivatives_vs_finite_differences(&s), FD_TOL)?;
    }

    /// GEC sections (paper 000 eq 16, 002 eq 1): sampled and refitted with
    /// their own number of terms, the fit reproduces the curve.
    #[test]
    fn gec_sections_refit_to_themselves(g in gec_section(4)) {
        let points = g.sample(REFIT_POINTS);
        let fit = gec::fit(&points, &FitOptions::new(g.terms()))
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        within("refit ErM / size", fit.errors.erm_rel, tol::SOLVE)?;
    }
}
