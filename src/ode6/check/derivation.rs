//! Checks of paper 004's derivation, eqs 3, 9-13, 16-18 and 23-25 (issue
//! 17): the reduction to a fourth-order ODE, the characteristic equations,
//! the four roots, the solution forms of eqs 17-18, approach 1's constraints
//! and the Fig 6a u-join, each computed from the printed statement against
//! the project's basis (jets).
//!
//! The paper solves only $4\rho\lambda/\eta^2 < 1$ (with $\eta > 0$, so both
//! $q < 0$ and $\xi_{1,2} = \sqrt{-q_{1,2}}$ real); the cases below are in it.

use super::*;
use crate::check::{worst, Worst};
use nalgebra::{Complex, DMatrix, DVector};

/// Parameter cases inside the paper's solved case.
const CASES: [(f64, f64, f64); 3] = [(1.0, 3.0, 1.0), (0.5, 4.0, 2.0), (1.0, 10.0, 5.0)];

/// Central-difference step of the eq 9 check: truncation h^2 |S''''|/12
/// and rounding 4 eps |S| / h^2 balance near 1e-4 (both about 1e-8 here).
const FD_STEP: f64 = 1e-4;
/// Bound on the eq 9 check: ten times the two error sources of
/// [`FD_STEP`] for |S| and |S''''| up to 1e2 on these lines.
const FD_TOL: f64 = 1e-6;

/// Arbitrary constraint values of one scalar line.
const LINE: [f64; 6] = [0.7, -0.4, 1.3, -0.2, 0.9, 0.5];

/// $\xi_{1,2}$ of eq 15 with the extraction's minus and roots restored:
/// $\sqrt{\eta(1 \pm \sqrt{1 - 4\rho\lambda/\eta^2})/(2\rho)}$.
fn xi(p: &Params) -> [f64; 2] {
    let s = (1.0 - 4.0 * p.rho * p.lambda / (p.eta * p.eta)).sqrt();
    [1.0 + s, 1.0 - s].map(|t| (p.eta * t / (2.0 * p.rho)).sqrt())
}

/// Max relative residual of `(r4, r2, r0)`-weighted terms.
fn rel3(a: f64, b: f64, c: f64) -> f64 {
    (a + b + c).abs()
        / a.abs()
            .worst(b.abs())
            .worst(c.abs())
            .worst(f64::MIN_POSITIVE)
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
        .fold(0.0, worst)
        .worst(1e-300);
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

/// SymPy's xi for three cases (`verify/printed_forms.py`).
const PRINTED_GOLDEN: &str = include_str!("../../../verify/golden/printed_forms.json");

/// xi of eq 15 (restored) against SymPy's roots of the quartic (eq 16).
fn xi_vs_sympy() -> f64 {
    let g: serde_json::Value = serde_json::from_str(PRINTED_GOLDEN).unwrap_or_default();
    let Some(cases) = g["ode6_xi"].as_array() else {
        return f64::NAN;
    };
    let mut e = if cases.is_empty() { f64::NAN } else { 0.0f64 };
    for c in cases {
        let f = |k: &str| c[k].as_f64().unwrap_or(f64::NAN);
        let x = xi(&Params::new(f("rho"), f("eta"), f("lambda")));
        for k in 0..2 {
            let want = c["xi"][k].as_f64().unwrap_or(f64::NAN);
            e = worst(e, (x[k] - want).abs() / want);
        }
    }
    e
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
        // eq 9 (S_bar = S'') has no code of its own: the S_bar that eq 10's
        // check feeds is the jets' S'' of the project's line; here it is
        // held against central second differences of the line's f64
        // evaluation (the path surfaces are built with)
        for i in 1..=9 {
            let u = i as f64 / 10.0;
            let f = |t: f64| b.line(t, &LINE);
            let h = FD_STEP;
            let fd = (f(u + h) - 2.0 * f(u) + f(u - h)) / (h * h);
            let jet = b.line(Jet::<3, 1>::var_u(u), &LINE).deriv(2, 0);
            e9 = e9.worst((fd - jet).abs() / jet.abs().worst(1.0));
        }
        // eq 10: S'' of the project's line solves it
        for i in 0..=10 {
            let s = b.line(Jet::<7, 1>::var_u(i as f64 / 10.0), &LINE);
            e10 = e10.worst(rel3(
                rho * s.deriv(6, 0),
                eta * s.deriv(4, 0),
                lambda * s.deriv(2, 0),
            ));
        }
        // eq 11: the project's case functions y1..y4 (one pair per root q_k:
        // cos, sin xi_k u, or the series F2, F3 for |q| <= 1) are the trial
        // solutions of eq 10: y'' substituted into it (jets)
        for i in 0..=4 {
            let y = b.y(Jet::<7, 1>::var_u(0.25 * i as f64));
            for f in &y[..4] {
                e11 = e11.worst(rel3(
                    rho * f.deriv(6, 0),
                    eta * f.deriv(4, 0),
                    lambda * f.deriv(2, 0),
                ));
            }
        }
        // eqs 12, 13: the project's roots q_k (Params::q_roots) in the
        // quadratic, and r = +-sqrt(q_k) in the quartic (complex)
        let qs = p.q_roots();
        for (qr, qi) in qs {
            let q = Complex::new(qr, qi);
            let res = (q * q * rho + q * eta + Complex::new(lambda, 0.0)).norm();
            e13 = e13.worst(
                res / (q.norm_sqr() * rho)
                    .worst(q.norm() * eta)
                    .worst(lambda.abs()),
            );
            for r in [q.sqrt(), -q.sqrt()] {
                let (r2, r4) = (r * r, r * r * r * r);
                let res = (r4 * rho + r2 * eta + Complex::new(lambda, 0.0)).norm();
                e12 = e12.worst(res / (r4.norm() * rho).worst(r2.norm() * eta).worst(lambda.abs()));
            }
        }
        for (k, w) in x.iter().enumerate() {
            // the project's roots q (eqs 13-14, computed without cancellation)
            // give the same r = +-i xi_k (eq 16), xi_1 > xi_2
            let (qr, qi) = qs[k];
            let r_project = Complex::new(qr, qi).sqrt();
            e16 = e16.worst((r_project - Complex::new(0.0, *w)).norm() / w);
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
        ck("eq 9", "ode6.derivation.eq9_reduction", Kind::Residual, e9, FD_TOL, &format!("eq 9 (S_bar = S'') is a substitution with no code of its own: the S_bar the eq 10 check feeds (jets' S'' of the project's line) against central second differences (h = 1e-4) of the line's f64 evaluation at 9 u, relative, {cases}")),
        ck("eq 10", "ode6.derivation.eq10_fourth_order", Kind::Residual, e10, tol::SOLVE, &format!("rho S_bar'''' + eta S_bar'' + lambda S_bar = 0 for S_bar = S'' of a line of the project's basis, relative, {cases}")),
        ck("eq 11", "ode6.derivation.eq11_exponential_trial", Kind::Residual, e11, tol::SOLVE, &format!("the project's case functions y1..y4 (Basis::y: cos, sin xi_k u per root, or the series F2, F3 for |q| <= 1), the trial solutions S_bar = e^(r u) of eq 11, substituted as S_bar = y'' into eq 10 (jets), relative, {cases}")),
        ck("eq 12", "ode6.derivation.eq12_quartic", Kind::Residual, e12, tol::ROUNDING * 10.0, &format!("rho r^4 + eta r^2 + lambda = 0 at r = +-sqrt(q_k) of the project's roots (Params::q_roots, complex), relative, {cases}")),
        ck("eq 13", "ode6.derivation.eq13_quadratic", Kind::Residual, e13, tol::ROUNDING * 10.0, &format!("rho q^2 + eta q + lambda = 0 at the project's roots q_k (Params::q_roots), relative, {cases}")),
        ck("eq 16", "ode6.derivation.eq16_four_roots", Kind::Reference, e16, tol::ROUNDING * 10.0, "r_{1,2} = +-i xi_1, r_{3,4} = +-i xi_2 (xi from eq 15 restored) against sqrt of the project's roots q of eq 13 (Params::q_roots), relative"),
        ck("eqs 15, 16", "ode6.derivation.xi_vs_sympy", Kind::Reference, xi_vs_sympy(), tol::ROUNDING, "xi_{1,2} of eq 15 (minus and roots restored) against SymPy's roots +-i xi of the quartic (verify/printed_forms.py, 30 digits), three cases"),
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
                        / l1[k].deriv(o, 0).abs().worst(1.0),
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
