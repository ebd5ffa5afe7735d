//! Continuity checks: C2 joins of chains and grids, Fig 6b.

use super::*;
use crate::check::{worst, Worst};

/// C2 joins in u (chains) and v (splits).
pub(super) fn continuity_checks() -> Vec<Check> {
    let mut out = Vec::new();
    let chain = chain();
    let jumps = chain
        .as_ref()
        .map(|c| c.join_jumps(16))
        .unwrap_or([f64::NAN; 3]);
    for (i, what) in ["c0", "c1", "c2"].iter().enumerate() {
        out.push(ck(
            "eqs 23-25",
            &format!("ode6.continuity_u.{what}"),
            Kind::Continuity,
            jumps[i],
            tol::SOLVE,
            &format!("jump of d^{i}S/du^{i} across the joins of a 3-patch chain with different shape parameters per patch (paper case, fig 4c case, fig 6b case)"),
        ));
    }
    grid_checks(&mut out);
    let curves = BoundaryCurves::approach1(
        Curve::Fourier(test_curve(1.0, 0.0, 0.0)),
        Curve::Fourier(test_curve(0.6, 1.0, 1.0)),
        [1.0, 0.5, -1.0, 2.0],
    );
    fig6b_check(&curves, &mut out);
    grid_fast_path_check(curves, &mut out);
    out
}

/// A 3 x 2 grid of separately built patches (own Hermite constraint
/// curves each, see `grid_knots`): C2 across every u-join and v-join.
fn grid_checks(out: &mut Vec<Check>) {
    let grid = grid_3x2();
    let gj = grid.as_ref().map(|g| g.join_jumps(16));
    let rel = |f: fn(&GridJumps) -> (f64, f64)| match &gj {
        Ok(j) => {
            let (jump, mag) = f(j);
            if mag < GRID_MAGNITUDE_FLOOR {
                f64::INFINITY
            } else {
                jump / mag
            }
        }
        Err(_) => f64::NAN,
    };
    let mags = gj
        .as_ref()
        .map(|j| {
            format!(
                "|S_u^(j)| up to {:.2?}, |S_v^(j)| up to {:.2?}",
                j.u_magnitude, j.v_magnitude
            )
        })
        .unwrap_or_else(|e| format!("grid failed: {e}"));
    out.push(ck(
        "eqs 23-26",
        "ode6.continuity_grid_3x2",
        Kind::Continuity,
        gj.as_ref().map(|j| j.relative(GRID_MAGNITUDE_FLOOR)).unwrap_or(f64::NAN),
        tol::SOLVE,
        &format!("3 x 2 grid of separately built patches (each its own six quintic Hermite constraint curves; parameters per column: paper case, fig 4c case, fig 6b case): largest jump of d^jS/du^j (j <= 2) across the u-joins and d^jS/dv^j across the v-joins, relative to the derivative's magnitude there ({mags}; below {GRID_MAGNITUDE_FLOOR} the check fails as vacuous)"),
    ));
    for (i, what) in ["c0", "c1", "c2"].iter().enumerate() {
        let m = match i {
            0 => rel(|j| (j.v[0], j.v_magnitude[0])),
            1 => rel(|j| (j.v[1], j.v_magnitude[1])),
            _ => rel(|j| (j.v[2], j.v_magnitude[2])),
        };
        out.push(ck(
            "eq 26",
            &format!("ode6.continuity_v.{what}"),
            Kind::Continuity,
            m,
            tol::SOLVE,
            &format!("jump of d^{i}S/dv^{i} across the v-joins of the 3 x 2 grid (separate patches whose constraint curves meet C2 at the knot, equal shape parameters within a column), relative to |d^{i}S/dv^{i}| there"),
        ));
    }
}

/// Fig 6b: the same curves split at v = 0.4, different parameters.
fn fig6b_check(curves: &Result<BoundaryCurves, Ode6Error>, out: &mut Vec<Check>) {
    let split = |pa: Params, pb: Params| -> ([f64; 3], f64) {
        let (Ok(c), Ok(ba), Ok(bb)) = (curves.clone(), Basis::new(pa), Basis::new(pb)) else {
            return ([f64::NAN; 3], f64::NAN);
        };
        let (Ok(a), Ok(b)) = (
            Ode6Surface::new(ba, c.clone()).with_v_range(0.0, 0.4),
            Ode6Surface::new(bb, c).with_v_range(0.4, 1.0),
        ) else {
            return ([f64::NAN; 3], f64::NAN);
        };
        let size = (0..=20)
            .map(|i| crate::mesh::norm(a.point(i as f64 / 20.0, 0.4)))
            .fold(0.0, worst);
        (
            VSplit {
                below: &a,
                above: &b,
            }
            .join_jumps(20),
            size,
        )
    };
    let (fig6b, size) = split(Params::new(1.0, 1.0, 3.0), Params::new(0.1, 0.1, 3.0));
    let (same, _) = split(Params::new(1.0, 1.0, 3.0), Params::new(1.0, 1.0, 3.0));
    out.push(
        Check::paper_literal(FAMILY, PAPER, "eq 26, Fig 6b", "ode6.paper_literal.fig6b_v_join", fig6b[0] / size, tol::SOLVE, true).note(format!(
            "Fig 6b joins in v a patch with rho = eta = 1, lambda = 3 to one with rho = eta = 0.1, lambda = 3: xi differ, so even positions jump; measured: the position jump relative to max |S| on the join ({size:.3}), against the tolerance under which the continuity checks call a join continuous (equal parameters give {:.1e}); absolute jumps C0 {:.3e}, C1 {:.3e}, C2 {:.3e}",
            same[0], fig6b[0], fig6b[1], fig6b[2]
        )),
    );
}

/// The grid fast path equals point evaluation.
fn grid_fast_path_check(curves: Result<BoundaryCurves, Ode6Error>, out: &mut Vec<Check>) {
    let grid_err = match (curves, Basis::new(Params::new(1e-4, 3.0, 1e-4))) {
        (Ok(c), Ok(b)) => {
            let s = Ode6Surface::new(b, c).with_force(&Force::Sine {
                amp: [0.1, 0.2, 0.0],
                kappa: 2.0,
                phase: 0.0,
            });
            match s {
                Ok(s) => {
                    let us: Vec<f64> = (0..7).map(|i| i as f64 / 6.0).collect();
                    let vs: Vec<f64> = (0..9).map(|i| i as f64 / 9.0).collect();
                    let g = s.grid(&us, &vs);
                    let mut e = 0.0f64;
                    for (iu, &u) in us.iter().enumerate() {
                        for (iv, &v) in vs.iter().enumerate() {
                            e = e.worst(crate::mesh::dist(g[iu * vs.len() + iv], s.point(u, v)));
                        }
                    }
                    e
                }
                Err(_) => f64::NAN,
            }
        }
        _ => f64::NAN,
    };
    out.push(ck(
        "eq 19",
        "ode6.grid_equals_eval",
        Kind::Reference,
        grid_err,
        tol::ROUNDING * 100.0,
        "tensor-product grid evaluator against point evaluation",
    ));
}
