//! The shape-parameter optimisation of sec 6.3: per column of patches, the
//! `(rho, eta, lambda)` that minimise the sum of squared distances between
//! the regenerated vertices and the input's.
//!
//! The ODE's solutions do not change when all three parameters are scaled
//! together, so `rho = 1` and the search is over `(eta, lambda)`: a coarse
//! grid over `[-ETA_MAX, ETA_MAX] x [-LAMBDA_MAX, LAMBDA_MAX]` (inside the
//! basis' documented range, `crate::ode6::basis`), then Nelder-Mead from
//! the best grid point. Parameter sets whose boundary system is singular
//! score infinity. The default parameters are a candidate too, so the
//! result is never worse than them.

use super::template::FaceTemplate;
use crate::ode6::network::doc::DEFAULT_PARAMS;
use crate::ode6::network::Network;
use crate::ode6::{Basis, Params};
use crate::surface::Surface;

/// Search box of `eta` and `lambda` (with `rho = 1`).
pub const ETA_MAX: f64 = 30.0;
pub const LAMBDA_MAX: f64 = 60.0;
/// Coarse grid per axis.
pub const GRID: usize = 9;
/// Nelder-Mead iterations after the grid.
pub const ITERATIONS: usize = 40;

/// The sum of squared vertex errors of column `i` with `params`.
pub fn column_cost(
    t: &FaceTemplate,
    net: &Network,
    pos: &[[f64; 3]],
    i: usize,
    params: Params,
) -> f64 {
    let Ok(basis) = Basis::new(params) else {
        return f64::INFINITY;
    };
    let surfaces: Vec<_> = (0..t.nv)
        .map(|j| {
            let mut s = net.patches[i * t.nv + j].clone();
            s.basis = basis.clone();
            s
        })
        .collect();
    let mut sum = 0.0;
    for p in t.vertices.iter().filter(|p| p.column == i) {
        let s = surfaces[p.row].point(p.u, p.v);
        let d = crate::vec3::dist(s, pos[p.vertex as usize]);
        sum += d * d;
    }
    if sum.is_finite() {
        sum
    } else {
        f64::INFINITY
    }
}

/// The optimised parameters of column `i`.
pub fn optimise_column(t: &FaceTemplate, net: &Network, pos: &[[f64; 3]], i: usize) -> Params {
    let cost = |x: [f64; 2]| {
        if x[0].abs() > ETA_MAX || x[1].abs() > LAMBDA_MAX {
            return f64::INFINITY;
        }
        column_cost(t, net, pos, i, Params::new(1.0, x[0], x[1]))
    };
    let d = DEFAULT_PARAMS;
    let mut best = ([d.eta / d.rho, d.lambda / d.rho], f64::INFINITY);
    best.1 = cost(best.0);
    for a in 0..GRID {
        for b in 0..GRID {
            let g = |k: usize, m: f64| m * (2.0 * k as f64 / (GRID - 1) as f64 - 1.0);
            let x = [g(a, ETA_MAX), g(b, LAMBDA_MAX)];
            let c = cost(x);
            if c < best.1 {
                best = (x, c);
            }
        }
    }
    let x = nelder_mead(&cost, best.0, [ETA_MAX / 8.0, LAMBDA_MAX / 8.0], ITERATIONS);
    let x = if cost(x) < best.1 { x } else { best.0 };
    Params::new(1.0, x[0], x[1])
}

/// Nelder-Mead in two variables (standard coefficients 1, 2, 0.5, 0.5).
fn nelder_mead(
    f: &dyn Fn([f64; 2]) -> f64,
    x0: [f64; 2],
    step: [f64; 2],
    iters: usize,
) -> [f64; 2] {
    let mut s = [x0, [x0[0] + step[0], x0[1]], [x0[0], x0[1] + step[1]]].map(|x| (x, f(x)));
    let lerp =
        |a: [f64; 2], b: [f64; 2], t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    for _ in 0..iters {
        s.sort_by(|a, b| a.1.total_cmp(&b.1));
        let c = lerp(s[0].0, s[1].0, 0.5);
        let r = lerp(c, s[2].0, -1.0);
        let fr = f(r);
        if fr < s[0].1 {
            let e = lerp(c, s[2].0, -2.0);
            let fe = f(e);
            s[2] = if fe < fr { (e, fe) } else { (r, fr) };
        } else if fr < s[1].1 {
            s[2] = (r, fr);
        } else {
            let k = lerp(c, s[2].0, 0.5);
            let fk = f(k);
            if fk < s[2].1 {
                s[2] = (k, fk);
            } else {
                for i in 1..3 {
                    let x = lerp(s[0].0, s[i].0, 0.5);
                    s[i] = (x, f(x));
                }
            }
        }
    }
    s.sort_by(|a, b| a.1.total_cmp(&b.1));
    s[0].0
}
