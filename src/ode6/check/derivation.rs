//! Checks of paper 004's derivation, eqs 3, 9-13, 16-18 and 23-25 (issue
//! 17): the reduction to a fourth-order ODE, the characteristic equations,
//! the four roots, the solution forms of eqs 17-18, approach 1's constraints
//! and the Fig 6a u-join, each computed from the printed statement against
//! the project's basis (jets).
//!
//! The paper solves only $4\rho\lambda/\eta^2 < 1$ (with $\eta > 0$, so both
//! $q < 0$ and $\xi_{1,2} = \sqrt{-q_{1,2}}$ real); the cases below are in it.

use super::*;
use nalgebra::{Complex, DMatrix, DVector};

/// Parameter cases inside the paper's solved case.
const CASES: [(f64, f64, f64); 3] = [(1.0, 3.0, 1.0), (0.5, 4.0, 2.0), (1.0, 10.0, 5.0)];

/// Arbitrary constraint values of one scalar line.
const LINE: [f64; 6] = [0.7, -0.4, 1.3, -0.2, 0.9, 0.5];

fn worst(acc: f64, e: f64) -> f64 {
    if acc.is_nan() || e.is_nan() {
        f64::NAN
    } else {
        acc.max(e)
    }
}

/// $\xi_{1,2}$ of eq 15 with the extraction's minus and roots restored:
/// $\sqrt{\eta(1 \pm \sqrt{1 - 4\rho\lambda/\eta^2})/(2\rho)}$.
fn xi(p: &Params) -> [f64; 2] {
    let s = (1.0 - 4.0 * p.rho * p.lambda / (p.eta * p.eta)).sqrt();
    [1.0 + s, 1.0 - s].map(|t| (p.eta * t / (2.0 * p.rho)).sqrt())
}

/// Max relative residual of `(r4, r2, r0)`-weighted terms.
fn rel3(a: f64, b: f64, c: f64) -> f64 {
    (a + b + c).abs() / a.abs().max(b.abs()).max(c.abs()).max(f64::MIN_POSITIVE)
}

/// Least-squares fit of `f` by `funcs` on 4 + |funcs| points, error at 11
/// other points relative to max |f|.
fn span_error(funcs: &[Box<dyn Fn(f64) -> f64>], f: &dyn Fn(f64) -> f64) -> f64 {
    let m = funcs.len() + 4;
    let fit_u: Vec<f64> = (0..m).map(|i| (i as f64 + 0.5) / m as f64).collect();
    let a = DMatrix::from_fn(m, funcs.len(), |i, j| funcs[j](fit_u[i]));
    let b = DVector::from_fn(m, |i, _| f(fit_u[i]));
    let Ok(c) = a.clone().svd(true, true).solve(&b, 1e-14) else {
        return f64::NAN;
    };
    let test: Vec<f64> = (0..=10).map(|i| i as f64 / 10.0).collect();
    let scale = test
        .iter()
        .map(|&u| f(u).abs())
        .fold(0.0, f64::max)
        .max(1e-300);
    test.iter()
        .map(|&u| {
            let g: f64 = (0..funcs.len()).map(|j| c[j] * funcs[j](u)).sum();
            (g - f(u)).abs() / scale
        })
        .fold(0.0, worst)
}

fn trig(x: [f64; 2]) -> Vec<Box<dyn Fn(f64) -> f64>> {
    let mut v: Vec<Box<dyn Fn(f64) -> f64>> = Vec::new();
    for w in x {
        v.push(Box::new(move |u: f64| (w * u).cos()));
        v.push(Box::new(move |u: f64| (w * u).sin()));
    }
    v
}

pub(super) fn derivation_checks() -> Vec<Check> {
    let (mut e9, mut e10, mut e11, mut e12, mut e13, mut e16, mut e17, mut e18) = (
        0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64,
    );
    for (rho, eta, lambda) in CASES {
        let p = Params::new(rho, eta, lambda);
        let x = xi(&p);
        let Ok(b) = Basis::new(p) else {
            e10 = f64::NAN;
            continue;
        };
        // eq 9: for any function, eq 8's operator on S equals eq 10's on S'' (a
        // non-solution test function)
        for i in 0..=4 {
            let u = Jet::<7, 1>::var_u(0.1 + 0.2 * i as f64);
            let s = (u * 1.7).exp() + u * u * u * 0.3 + (u * 2.3).sin();
            let sbar = |d: usize| s.deriv(d + 2, 0);
            let eq8 = rho * s.deriv(6, 0) + eta * s.deriv(4, 0) + lambda * s.deriv(2, 0);
            let eq10 = rho * sbar(4) + eta * sbar(2) + lambda * sbar(0);
            e9 = worst(e9, (eq8 - eq10).abs() / eq8.abs().max(1.0));
        }
        // eq 10: S'' of the project's line solves it
        for i in 0..=10 {
            let s = b.line(Jet::<7, 1>::var_u(i as f64 / 10.0), &LINE);
            e10 = worst(
                e10,
                rel3(
                    rho * s.deriv(6, 0),
                    eta * s.deriv(4, 0),
                    lambda * s.deriv(2, 0),
                ),
            );
        }
        // eq 11: e^{ru}, r = +-i xi_k (cos and sin) substituted into eq 10
        for w in x {
            for i in 0..=4 {
                let u = Jet::<5, 1>::var_u(0.25 * i as f64);
                for f in [(u * w).cos(), (u * w).sin()] {
                    let (a, bb, c) = (rho * f.deriv(4, 0), eta * f.deriv(2, 0), lambda * f.value());
                    e11 = worst(
                        e11,
                        (a + bb + c).abs() / a.abs().max(bb.abs()).max(c.abs()).max(1.0),
                    );
                }
            }
        }
        // eqs 12, 13, 16: the quartic at the four roots of eq 16, the quadratic at q = r^2
        let qs = p.q_roots();
        for (k, w) in x.iter().enumerate() {
            for r in [Complex::new(0.0, *w), Complex::new(0.0, -*w)] {
                let (r2, r4) = (r * r, r * r * r * r);
                let res = (r4 * rho + r2 * eta + Complex::new(lambda, 0.0)).norm();
                e12 = worst(
                    e12,
                    res / (r4.norm() * rho).max(r2.norm() * eta).max(lambda.abs()),
                );
            }
            let q = -w * w;
            e13 = worst(e13, rel3(rho * q * q, eta * q, lambda));
            // the project's roots q (eqs 13-14, computed without cancellation)
            // give the same r = +-i xi_k (eq 16), xi_1 > xi_2
            let (qr, qi) = qs[k];
            let r_project = Complex::new(qr, qi).sqrt();
            e16 = worst(e16, (r_project - Complex::new(0.0, *w)).norm() / w);
        }
        // eqs 17, 18: the solution forms
        let bref = &b;
        let line = |d: usize| move |u: f64| bref.line(Jet::<3, 1>::var_u(u), &LINE).deriv(d, 0);
        e17 = worst(e17, span_error(&trig(x), &line(2)));
        let mut funcs = trig(x);
        funcs.push(Box::new(|u: f64| u));
        funcs.push(Box::new(|_| 1.0));
        e18 = worst(e18, span_error(&funcs, &line(0)));
    }
    let cases = "(rho, eta, lambda) in {(1,3,1), (0.5,4,2), (1,10,5)} (4 rho lambda / eta^2 < 1, the paper's case)";
    vec![
        ck("eq 9", "ode6.derivation.eq9_reduction", Kind::Residual, e9, tol::ROUNDING * 100.0, &format!("with S_bar = d2S/du2 (eq 9), eq 8's operator on S equals eq 10's on S_bar for a non-solution test function (jets), {cases}")),
        ck("eq 10", "ode6.derivation.eq10_fourth_order", Kind::Residual, e10, tol::SOLVE, &format!("rho S_bar'''' + eta S_bar'' + lambda S_bar = 0 for S_bar = S'' of a line of the project's basis, relative, {cases}")),
        ck("eq 11", "ode6.derivation.eq11_exponential_trial", Kind::Residual, e11, tol::ROUNDING * 100.0, &format!("S_bar = e^(r u) with r = +-i xi_k (cos xi_k u, sin xi_k u) solves eq 10 (jets), {cases}")),
        ck("eq 12", "ode6.derivation.eq12_quartic", Kind::Residual, e12, tol::ROUNDING * 10.0, "rho r^4 + eta r^2 + lambda = 0 at r = +-i xi_1, +-i xi_2 (complex), relative"),
        ck("eq 13", "ode6.derivation.eq13_quadratic", Kind::Residual, e13, tol::ROUNDING * 10.0, "rho q^2 + eta q + lambda = 0 at q = r^2 = -xi_k^2, relative"),
        ck("eq 16", "ode6.derivation.eq16_four_roots", Kind::Reference, e16, tol::ROUNDING * 10.0, "r_{1,2} = +-i xi_1, r_{3,4} = +-i xi_2 (xi from eq 15 restored) against sqrt of the project's roots q of eq 13 (Params::q_roots), relative"),
        ck("eq 17", "ode6.derivation.eq17_sbar_form", Kind::Reference, e17, tol::SOLVE, &format!("S'' of a project line is b1 cos xi1 u + b2 sin xi1 u + b3 cos xi2 u + b4 sin xi2 u: least-squares fit on 8 points, max error at 11 others relative to max |S''|, {cases}")),
        ck("eq 18", "ode6.derivation.eq18_s_form", Kind::Reference, e18, tol::SOLVE, "S of a project line is b1 cos xi1 u + ... + b4 sin xi2 u + b5 u + b6: least-squares fit on 10 points, error at 11 others relative to max |S|"),
    ]
}

/// Approach 1 (eq 3) and the Fig 6a construction (eqs 23-25).
pub(super) fn approach1_join_checks() -> Vec<Check> {
    let c = |s: f64, z: f64, ph: f64| Curve::Fourier(test_curve(s, z, ph));
    let w = [0.3, -0.2, 0.5, 0.4];
    let w56 = [-0.6, 0.8];
    let (pl, pr) = (Params::new(1.0, 3.0, 1.0), Params::new(0.5, 4.0, 2.0));
    let build = || -> Result<(Ode6Surface, Ode6Surface), Ode6Error> {
        let left = BoundaryCurves::approach1(c(1.0, 0.0, 0.0), c(0.7, 1.0, 0.5), w)?;
        let right = BoundaryCurves::approach1(
            c(0.7, 1.0, 0.5),
            c(1.2, 2.0, 1.0),
            [w[2], w[3], w56[0], w56[1]],
        )?;
        Ok((
            Ode6Surface::new(Basis::new(pl)?, left),
            Ode6Surface::new(Basis::new(pr)?, right),
        ))
    };
    let Ok((sl, sr)) = build() else {
        return vec![ck(
            "eqs 3, 23-25",
            "ode6.derivation.fig6a_build",
            Kind::Boundary,
            f64::NAN,
            tol::SOLVE,
            "approach 1 surfaces could not be built",
        )];
    };
    let curve = |s: f64, z: f64, ph: f64, v: f64| c(s, z, ph).eval(v);
    let d =
        |s: &Ode6Surface, u: f64, v: f64| s.eval(Jet::<3, 1>::var_u(u), Jet::<3, 1>::constant(v));
    let (mut e3, mut e24, mut e25, mut e23) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for j in 0..16 {
        let v = j as f64 / 16.0;
        let (c1, c4, c4h) = (
            curve(1.0, 0.0, 0.0, v),
            curve(0.7, 1.0, 0.5, v),
            curve(1.2, 2.0, 1.0, v),
        );
        let (l0, l1, r0, r1) = (
            d(&sl, 0.0, v),
            d(&sl, 1.0, v),
            d(&sr, 0.0, v),
            d(&sr, 1.0, v),
        );
        for k in 0..3 {
            // eq 3: c2 = w1 c1, c3 = w2 c1, c5 = w3 c4, c6 = w4 c4 (the left patch's S_u, S_uu)
            for (got, want) in [
                (l0[k].deriv(1, 0), w[0] * c1[k]),
                (l0[k].deriv(2, 0), w[1] * c1[k]),
                (l1[k].deriv(1, 0), w[2] * c4[k]),
                (l1[k].deriv(2, 0), w[3] * c4[k]),
            ] {
                e3 = worst(e3, (got - want).abs());
            }
            // eq 24: the left patch's six printed constraints
            for (got, want) in [
                (l0[k].value(), c1[k]),
                (l0[k].deriv(1, 0), w[0] * c1[k]),
                (l0[k].deriv(2, 0), w[1] * c1[k]),
                (l1[k].value(), c4[k]),
                (l1[k].deriv(1, 0), w[2] * c4[k]),
                (l1[k].deriv(2, 0), w[3] * c4[k]),
            ] {
                e24 = worst(e24, (got - want).abs());
            }
            // eq 25: the right patch's six printed constraints
            for (got, want) in [
                (r0[k].value(), c4[k]),
                (r0[k].deriv(1, 0), w[2] * c4[k]),
                (r0[k].deriv(2, 0), w[3] * c4[k]),
                (r1[k].value(), c4h[k]),
                (r1[k].deriv(1, 0), w56[0] * c4h[k]),
                (r1[k].deriv(2, 0), w56[1] * c4h[k]),
            ] {
                e25 = worst(e25, (got - want).abs());
            }
            // eq 23: S(1, v) = S^(0, v) and the first two u-derivatives
            for o in 0..3 {
                e23 = worst(
                    e23,
                    (l1[k].deriv(o, 0) - r0[k].deriv(o, 0)).abs()
                        / l1[k].deriv(o, 0).abs().max(1.0),
                );
            }
        }
    }
    let setup = "left patch (rho, eta, lambda) = (1, 3, 1) from c1, c4 with w1..w4 = (0.3, -0.2, 0.5, 0.4); right patch (0.5, 4, 2) from c4, c4_hat with (w3, w4, w5, w6); 16 v, jets";
    vec![
        ck("eq 3", "ode6.derivation.eq3_approach1", Kind::Boundary, e3, tol::SOLVE, &format!("approach 1 as printed: S_u(0,v) = w1 c1, S_uu(0,v) = w2 c1, S_u(1,v) = w3 c4, S_uu(1,v) = w4 c4; {setup}")),
        ck("eq 24", "ode6.derivation.eq24_fig6a_left", Kind::Boundary, e24, tol::SOLVE, &format!("the six printed constraints of the Fig 6a left patch; {setup}")),
        ck("eq 25", "ode6.derivation.eq25_fig6a_right", Kind::Boundary, e25, tol::SOLVE, &format!("the six printed constraints of the Fig 6a right patch; {setup}")),
        ck("eq 23", "ode6.derivation.eq23_u_join_c2", Kind::Continuity, e23, tol::SOLVE, &format!("eq 23: S^(0,v) = c4, S^_u(0,v) = c5, S^_uu(0,v) = c6 make S and S^ C2 across u = 1 / 0 (relative jumps of orders 0-2) with different shape parameters; {setup}")),
    ]
}
