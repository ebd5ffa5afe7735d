//! Measurements used by the checks and the tests: PDE residual, interpolation error, closed-v mismatch, basis residual, amplification, RK4, Lebesgue constants.

use super::*;
use crate::check::{worst, Worst};

/// Relative PDE residual max |w_u6 + a w_v6| / max(|w_u6|, |a w_v6|, 1) of
/// a surface over an 7 x 8 sample grid of its first patch range [0, 1].
pub fn pde_residual<S: Surface>(s: &S, a: f64, u_range: (f64, f64)) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 0..7 {
        let u = u_range.0 + (u_range.1 - u_range.0) * (0.03 + 0.94 * i as f64 / 6.0);
        for j in 0..8 {
            let v = 2.0 * PI * j as f64 / 8.0 + 0.1;
            let p = s.eval(Jet::<7, 1>::var_u(u), Jet::<7, 1>::constant(v));
            let pv = s.eval(Jet::<1, 7>::constant(u), Jet::<1, 7>::var_v(v));
            for k in 0..3 {
                let (du, dv) = (p[k].deriv(6, 0), a * pv[k].deriv(0, 6));
                worst = worst.worst((du + dv).abs() / du.abs().worst(dv.abs()).worst(1.0));
            }
        }
    }
    worst
}

/// Largest [`pde_residual`] over the pieces of a chain.
pub fn chain_residual(c: &Chain, a: f64) -> f64 {
    c.pieces
        .iter()
        .map(|p| pde_residual(&p.patch, a, (0.0, 1.0)))
        .fold(0.0, worst)
}

/// Largest distance, over 16 equally spaced `v`, from `at(v)` to the
/// section's curve (how far a surface passes from a section it must meet).
pub fn section_distance(s: &Section, at: impl Fn(f64) -> [f64; 3]) -> f64 {
    (0..16)
        .map(|j| {
            let v = 2.0 * PI * j as f64 / 16.0;
            crate::mesh::dist(at(v), s.curve.eval(v))
        })
        .fold(0.0, worst)
}

/// Max distance between the patch at local `nodes` and the curves there.
pub fn interpolation_error(p: &Patch, nodes: &[f64], curves: &[&Fourier3]) -> f64 {
    let mut worst: f64 = 0.0;
    for (&u, c) in nodes.iter().zip(curves) {
        for j in 0..16 {
            let v = 2.0 * PI * j as f64 / 16.0;
            let (a, b) = (p.point(u, v), c.eval(v));
            worst = worst.worst(crate::mesh::dist(a, b));
        }
    }
    worst
}

/// Mismatch of S and its u and v derivatives up to order 2 between v = 0
/// and v = 2 pi, over the u range.
pub fn closed_v_mismatch<S: Surface>(s: &S) -> f64 {
    let d = s.domain();
    let mut worst: f64 = 0.0;
    for i in 0..9 {
        let u = d.u.0 + (d.u.1 - d.u.0) * i as f64 / 8.0;
        let a = s.eval(Jet::<3, 3>::var_u(u), Jet::<3, 3>::var_v(d.v.0));
        let b = s.eval(Jet::<3, 3>::var_u(u), Jet::<3, 3>::var_v(d.v.1));
        for k in 0..3 {
            for p in 0..3 {
                for q in 0..3 - p {
                    let (x, y) = (a[k].deriv(p, q), b[k].deriv(p, q));
                    worst = worst.worst((x - y).abs() / x.abs().worst(1.0));
                }
            }
        }
    }
    worst
}

/// Max |phi^(6) - sigma q^6 phi| / max(|phi^(6)|, q^6, 1) of a basis over u in
/// [0, 1] (the stable basis functions are bounded by 1, so q^6 is the scale
/// of their sixth derivatives).
pub fn basis_ode_residual(b: &ModeBasis, sigma: f64, paper: bool) -> f64 {
    let q6 = b.q.powi(6) * sigma;
    let mut worst: f64 = 0.0;
    for i in 0..=10 {
        let u = Jet::<7, 1>::var_u(i as f64 / 10.0);
        let f = if paper { b.eval_paper(u) } else { b.eval(u) };
        for x in f {
            let (d6, d0) = (x.deriv(6, 0), x.value());
            worst = worst.worst((d6 - q6 * d0).abs() / d6.abs().worst(q6.abs()).worst(1.0));
        }
    }
    worst
}

/// Spectral radius of the 2x2 map (slope, curvature) at u = 0 -> at u = 1
/// of a method-2 patch with zero values (harmonic n, parameter a).
pub fn method2_amplification(a: f64, n: usize) -> Option<f64> {
    let s = ModeSolver::new(ModeBasis::new(a, n), method2_conditions(0.0)).ok()?;
    let b = s.basis.jet2(1.0);
    let mut t = [[0.0; 2]; 2];
    for (col, rhs) in [
        [0.0, 0.0, 0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
    ]
    .iter()
    .enumerate()
    {
        let c = s.solve(*rhs);
        for d in 0..2 {
            t[d][col] = (0..6).map(|j| c[j] * b[d + 1][j]).sum();
        }
    }
    let (tr, det) = (t[0][0] + t[1][1], t[0][0] * t[1][1] - t[0][1] * t[1][0]);
    let disc = tr * tr / 4.0 - det;
    Some(if disc >= 0.0 {
        (tr / 2.0).abs() + disc.sqrt()
    } else {
        det.abs().sqrt()
    })
}

/// Independent reference: integrate $A^{(6)} = a n^6 A$ as a first-order
/// system with classical RK4 (`steps` steps) from the closed form's value and
/// five derivatives at u = 0, and return max |A_rk4 - A_closed| over the
/// steps, relative to max(|A|, 1).
pub fn mode_vs_rk4(m: &Mode, a: f64, n: usize, steps: usize) -> f64 {
    let c = a * (n as f64).powi(6);
    let j0 = m.eval(Jet::<6, 1>::var_u(0.0));
    let mut y: [f64; 6] = std::array::from_fn(|d| j0.deriv(d, 0));
    let f = |y: &[f64; 6]| -> [f64; 6] { [y[1], y[2], y[3], y[4], y[5], c * y[0]] };
    let h = 1.0 / steps as f64;
    let mut worst: f64 = 0.0;
    for k in 1..=steps {
        let k1 = f(&y);
        let y2: [f64; 6] = std::array::from_fn(|i| y[i] + 0.5 * h * k1[i]);
        let k2 = f(&y2);
        let y3: [f64; 6] = std::array::from_fn(|i| y[i] + 0.5 * h * k2[i]);
        let k3 = f(&y3);
        let y4: [f64; 6] = std::array::from_fn(|i| y[i] + h * k3[i]);
        let k4 = f(&y4);
        y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        let exact = m.eval(k as f64 * h);
        worst = worst.worst((y[0] - exact).abs() / exact.abs().worst(1.0));
    }
    worst
}

/// Lebesgue constant of the six-point interpolation (101 samples).
pub fn lebesgue(b: ModeBasis) -> Option<f64> {
    let s = ModeSolver::new(b, method1_conditions(NODES_METHOD1)).ok()?;
    let cardinal: Vec<[f64; 6]> = (0..6)
        .map(|i| {
            let mut e = [0.0; 6];
            e[i] = 1.0;
            s.solve(e)
        })
        .collect();
    let mut best: f64 = 0.0;
    for k in 0..=100 {
        let phi: [f64; 6] = b.eval(k as f64 / 100.0);
        let sum: f64 = cardinal
            .iter()
            .map(|c| (0..6).map(|j| c[j] * phi[j]).sum::<f64>().abs())
            .sum();
        best = best.worst(sum);
    }
    Some(best)
}
