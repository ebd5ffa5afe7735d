//! Checks of the jet arithmetic against SymPy goldens and identities.

use super::{Jet6x6, Real};
use crate::check::Worst;
use crate::check::{tol, Check, Kind};
use serde::Deserialize;

const GOLDEN: &str = include_str!("../../verify/golden/jet.json");

#[derive(Deserialize)]
struct Golden {
    order: usize,
    functions: Vec<GoldenFn>,
}

#[derive(Deserialize)]
struct GoldenFn {
    name: String,
    u0: f64,
    v0: f64,
    derivatives: Vec<Vec<f64>>,
}

/// The closed forms of `verify/jet_golden.py`, written once generically.
pub fn golden_function<T: Real>(name: &str, u: T, v: T) -> Option<T> {
    Some(match name {
        "exp_sin_quotient" => (u.sin() * v).exp() / (u * u * v + 1.0),
        "atan2_sqrt_log" => v.atan2(u) * (u + 2.0).sqrt() + (u * v + 1.0).ln(),
        "atan2_steep" => v.atan2(u),
        "hyperbolic_tan" => (u - v).sinh() * (u * v * 2.0).cosh() + (u / 2.0).tan(),
        "powers_atan" => u.powi(5) * v.powi(-2) + (u * v).atan() * (u + v).powf(1.5),
        "cos_sincos" => {
            let (s, c) = (u * v).sin_cos();
            u.cos() * v + s * c
        }
        _ => return None,
    })
}

/// Largest relative deviation (scaled by `max(1, |golden|)`) over all mixed
/// derivatives up to order 6 in each variable; `None` for an unknown name.
pub fn golden_deviation(name: &str) -> Option<f64> {
    let g: Golden = serde_json::from_str(GOLDEN).ok()?;
    let f = g.functions.iter().find(|f| f.name == name)?;
    let jet = golden_function(name, Jet6x6::var_u(f.u0), Jet6x6::var_v(f.v0))?;
    let mut worst: f64 = 0.0;
    for i in 0..=g.order {
        for j in 0..=g.order {
            let want = f.derivatives[i][j];
            let got = jet.deriv(i, j);
            worst = worst.worst((got - want).abs() / want.abs().worst(1.0));
        }
    }
    Some(worst)
}

/// All checks of the jet family.
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    let g: Golden = match serde_json::from_str(GOLDEN) {
        Ok(g) => g,
        Err(e) => {
            return vec![Check::new(
                "jet",
                "-",
                "-",
                "jet.golden-parse",
                Kind::Reference,
                f64::NAN,
                0.0,
            )
            .note(format!("verify/golden/jet.json did not parse: {e}"))]
        }
    };
    for f in &g.functions {
        let dev = golden_deviation(&f.name).unwrap_or(f64::NAN);
        // High-order derivatives of these functions reach 1e4..1e6; the
        // recurrences lose a few digits per order.
        out.push(
            Check::new(
                "jet",
                "-",
                "Taylor arithmetic",
                &format!("jet.sympy.{}", f.name),
                Kind::Reference,
                dev,
                tol::ROUNDING,
            )
            .note("all d^(i+j)/du^i dv^j, i,j <= 6, against SymPy (verify/jet_golden.py)"),
        );
    }
    out.push(identity_check());
    out.push(f64_path_check(&g));
    out
}

/// The `f64` side of [`Real`] (what every fast evaluation runs) against
/// the same SymPy goldens: each golden function evaluated with `T = f64`,
/// and a generic expression through `Real::cst`, `one`, `zero` and
/// `recip` whose value is known in closed form.
fn f64_path_check(g: &Golden) -> Check {
    fn generic<T: Real>(u: T) -> T {
        // (u + 1/2) * 1/(u + 1) + 0 at u: a constant, the unit, the zero
        // and the reciprocal of the generic code paths
        (u + T::cst(0.5)) * (u + T::one()).recip() + T::zero()
    }
    let mut worst: f64 = 0.0;
    for f in &g.functions {
        let want = f.derivatives.first().and_then(|r| r.first()).copied();
        let got = golden_function::<f64>(&f.name, f.u0, f.v0);
        worst = match (want, got) {
            (Some(w), Some(x)) => worst.worst((x - w).abs() / w.abs().worst(1.0)),
            _ => f64::NAN,
        };
    }
    let u = 0.37;
    worst = worst.worst((generic(u) - (u + 0.5) / (u + 1.0)).abs());
    worst = worst.worst((generic(Jet6x6::var_u(u)).value() - generic(u)).abs());
    Check::new(
        "jet",
        "-",
        "Taylor arithmetic",
        "jet.f64_path",
        Kind::Reference,
        worst,
        tol::ROUNDING,
    )
    .note("the golden functions evaluated in f64 against SymPy's values, and (u + cst 1/2) recip(u + one) + zero in f64 against its closed form and the jet's value")
}

/// sin^2 + cos^2 = 1 and exp(ln x) = x hold as jets, and `Sum` adds: every
/// derivative of each identity is zero.
fn identity_check() -> Check {
    let u = Jet6x6::var_u(0.37);
    let v = Jet6x6::var_v(1.9);
    let x = u * v + u.sin() * 0.5 + 2.0;
    let one = x.sin() * x.sin() + x.cos() * x.cos();
    let back = x.ln().exp();
    // `Sum` over jets adds them term by term
    let summed: Jet6x6 = [x, one, back].into_iter().sum();
    let added = x + one + back;
    let mut worst: f64 = (one.value() - 1.0).abs();
    for i in 0..7 {
        for j in 0..7 {
            if i + j > 0 {
                worst = worst.worst(one.deriv(i, j).abs());
            }
            let rel = (back.deriv(i, j) - x.deriv(i, j)).abs() / x.deriv(i, j).abs().worst(1.0);
            worst = worst.worst(rel);
            worst = worst.worst((summed.deriv(i, j) - added.deriv(i, j)).abs());
        }
    }
    Check::new(
        "jet",
        "-",
        "identities",
        "jet.identities",
        Kind::Reference,
        worst,
        tol::SOLVE,
    )
    .note("sin^2+cos^2-1, exp(ln x)-x and a Sum of jets minus the same jets added vanish in every derivative up to (6,6)")
}
