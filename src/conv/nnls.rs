//! The non-negative least-squares solvers of the global interpolation
//! (paper 003, sec 3.3; [`super::fit::global_fit`]):
//! $\min_{x \ge 0} \|Ax - b\|^2$ by Hildreth-d'Esopo on the normal
//! equations, Lawson-Hanson's active set, or a projected
//! Levenberg-Marquardt. Every iteration cap and tolerance is a named
//! constant; a solver that stops at a cap says so (`converged = false`,
//! reported in [`super::fit::FitReport`]).

use nalgebra::{DMatrix, DVector};

/// Lawson-Hanson: a dual variable $w_i = (A^T(b - Ax))_i$ above
/// `LH_DUAL_TOL` $\|A\|\,\max(1, \|b\|)$ still lowers the residual.
pub const LH_DUAL_TOL: f64 = 1e-12;
/// Lawson-Hanson: relative singular-value cut-off of the passive-set
/// least-squares solve.
pub const LH_SVD_EPS: f64 = 1e-14;
/// Lawson-Hanson: a passive variable at or below this value after a step
/// is set to 0 and made active.
pub const LH_ZERO: f64 = 1e-15;
/// Lawson-Hanson outer-loop cap: `LH_OUTER_PER_VARIABLE n + LH_EXTRA_ITERATIONS`
/// (Lawson and Hanson observed about n/2 outer iterations).
pub const LH_OUTER_PER_VARIABLE: usize = 3;
/// See [`LH_OUTER_PER_VARIABLE`].
pub const LH_EXTRA_ITERATIONS: usize = 10;
/// Lawson-Hanson inner-loop cap over the whole solve:
/// `LH_INNER_PER_VARIABLE n + LH_INNER_EXTRA` least-squares solves.
pub const LH_INNER_PER_VARIABLE: usize = 10;
/// See [`LH_INNER_PER_VARIABLE`].
pub const LH_INNER_EXTRA: usize = 100;
/// Projected Levenberg-Marquardt: initial damping (relative to the
/// diagonal of $A^TA$).
pub const LM_MU_START: f64 = 1e-3;
/// Damping divisor after an accepted step.
pub const LM_MU_DOWN: f64 = 3.0;
/// Damping factor after a rejected step.
pub const LM_MU_UP: f64 = 4.0;
/// Damping factor when the damped matrix is not positive definite.
pub const LM_MU_UP_SINGULAR: f64 = 10.0;
/// Smallest damping.
pub const LM_MU_MIN: f64 = 1e-12;
/// Damping beyond which no descent step is left: the iterate is
/// stationary within rounding (reported as converged).
pub const LM_MU_MAX: f64 = 1e12;

/// Maximum coordinate-descent sweeps of Hildreth-d'Esopo.
pub const HILDRETH_MAX_SWEEPS: usize = 20_000;
/// Relative change at which the iterative solvers stop.
pub const SOLVER_STOP: f64 = 1e-12;

/// Hildreth-d'Esopo stops when the optimality (Karush-Kuhn-Tucker)
/// residual of $\min_{x \ge 0} \frac12 x^TQx - c^Tx$, the projected
/// gradient, is below this fraction of $\max_i |c_i|$.
pub const HILDRETH_KKT_STOP: f64 = 1e-9;

/// The projected gradient's largest entry: $|g_i|$ where $x_i > 0$,
/// $\max(0, -g_i)$ where $x_i = 0$, $g = Qx - c$.
pub(crate) fn kkt_residual(q: &DMatrix<f64>, c: &DVector<f64>, x: &DVector<f64>) -> f64 {
    let g = q * x - c;
    (0..x.len())
        .map(|i| {
            if x[i] > 0.0 {
                g[i].abs()
            } else {
                (-g[i]).max(0.0)
            }
        })
        .fold(0.0, f64::max)
}

/// Coordinate-descent sweeps between two subspace steps of Hildreth-d'Esopo.
pub const HILDRETH_SWEEPS_PER_STEP: usize = 4;

/// Cyclic projected coordinate descent with subspace steps; (sweeps,
/// converged).
///
/// **Why plain coordinate descent stalls.** On the normal equations
/// $Q = \mathbf F^T\mathbf F$ of a sketch, neighbouring segments have
/// nearly equal field columns: $Q$ of the teddy's strokes has a condition
/// number of $10^9$ to $3\cdot10^{12}$ (that of its block on the positive
/// $\lambda_i$ up to $2\cdot10^8$). Cyclic coordinate descent (Gauss-Seidel)
/// reduces the error in the slowest eigendirection by a factor of about
/// $1 - 1/\kappa$ per sweep, so after its cap of 20,000 sweeps the
/// optimality residual of 5 of the 6 distinct teddy strokes was still
/// $10^{-6}$ of $\max_i c_i$, 1000 times the stopping rule (issue 16).
///
/// **The fix.** Coordinate descent finds *which* $\lambda_i$ are zero in a
/// few sweeps even when it converges slowly on the others. After every
/// [`HILDRETH_SWEEPS_PER_STEP`] sweeps the free block is solved exactly
/// (Cholesky of $Q_{FF}$, $F = \{i : x_i > 0\}$, $x_A = 0$); the step
/// $x \to z$ is taken as far as it stays feasible, $x + \alpha(z - x)$
/// with the largest $\alpha \le 1$ keeping $x \ge 0$, which never raises the
/// convex objective (it moves toward the minimum of the objective on the
/// face). The sweeps then release the variables whose gradient points
/// inward. Stop: the projected gradient (the Karush-Kuhn-Tucker residual)
/// below [`HILDRETH_KKT_STOP`] $\max_i |c_i|$, computed afresh.
pub(crate) fn hildreth(q: &DMatrix<f64>, c: &DVector<f64>, x: &mut DVector<f64>) -> (usize, bool) {
    let n = c.len();
    let cmax = c.amax().max(f64::MIN_POSITIVE);
    // the gradient Qx - c, updated by a column of the symmetric Q whenever
    // one coordinate moves (recomputed after every subspace step)
    let mut grad = q * &*x - c;
    for sweep in 0..HILDRETH_MAX_SWEEPS {
        for i in 0..n {
            if q[(i, i)] <= 0.0 {
                continue;
            }
            let new = (x[i] - grad[i] / q[(i, i)]).max(0.0);
            let delta = new - x[i];
            if delta != 0.0 {
                grad.axpy(delta, &q.column(i), 1.0);
            }
            x[i] = new;
        }
        if sweep % HILDRETH_SWEEPS_PER_STEP == HILDRETH_SWEEPS_PER_STEP - 1 {
            subspace_step(q, c, x);
            grad = q * &*x - c;
            if kkt_residual(q, c, x) <= HILDRETH_KKT_STOP * cmax {
                return (sweep + 1, true);
            }
        }
    }
    (HILDRETH_MAX_SWEEPS, false)
}

/// The exact minimiser on the face of the free variables ($x_i > 0$): when
/// it is infeasible, the step toward it stops where the first variable
/// reaches 0, that variable leaves the free set and the smaller face is
/// solved again (the inner loop of Lawson-Hanson; the free set shrinks, so
/// it ends). Leaves `x` as it is when a block $Q_{FF}$ is not numerically
/// positive definite.
fn subspace_step(q: &DMatrix<f64>, c: &DVector<f64>, x: &mut DVector<f64>) {
    let mut free: Vec<usize> = (0..x.len()).filter(|&i| x[i] > 0.0).collect();
    while !free.is_empty() {
        let qf = DMatrix::from_fn(free.len(), free.len(), |a, b| q[(free[a], free[b])]);
        let cf = DVector::from_fn(free.len(), |a, _| c[free[a]]);
        let Some(chol) = qf.cholesky() else {
            return;
        };
        let z = chol.solve(&cf);
        if z.iter().any(|v| !v.is_finite()) {
            return;
        }
        let mut alpha: f64 = 1.0;
        let mut blocking = None;
        for (a, &i) in free.iter().enumerate() {
            // t = x / (x - z) lies in (0, 1] when z <= 0 < x
            if z[a] <= 0.0 {
                let t = x[i] / (x[i] - z[a]);
                if blocking.is_none() || t < alpha {
                    alpha = t;
                    blocking = Some(a);
                }
            }
        }
        for (a, &i) in free.iter().enumerate() {
            x[i] = (x[i] + alpha * (z[a] - x[i])).max(0.0);
        }
        let Some(a) = blocking else {
            return;
        };
        // the variable that bounds the step lands on its bound exactly
        x[free[a]] = 0.0;
        free.retain(|&i| x[i] > 0.0);
    }
}

/// Lawson-Hanson NNLS (active set); (solution, inner iterations,
/// converged). Not converged: an iteration cap was hit (see
/// [`LH_OUTER_PER_VARIABLE`], [`LH_INNER_PER_VARIABLE`]).
pub(crate) fn lawson_hanson(a: &DMatrix<f64>, b: &DVector<f64>) -> (DVector<f64>, usize, bool) {
    let n = a.ncols();
    let mut x = DVector::zeros(n);
    let mut passive = vec![false; n];
    let tol = LH_DUAL_TOL * a.norm() * b.norm().max(1.0);
    let mut iters = 0;
    let mut converged = false;
    let ls = |passive: &[bool]| -> DVector<f64> {
        let cols: Vec<usize> = (0..n).filter(|&i| passive[i]).collect();
        let sub = DMatrix::from_fn(a.nrows(), cols.len(), |r, c| a[(r, cols[c])]);
        let sol = sub
            .svd(true, true)
            .solve(b, LH_SVD_EPS)
            .unwrap_or_else(|_| DVector::zeros(cols.len()));
        let mut z = DVector::zeros(n);
        for (k, &i) in cols.iter().enumerate() {
            z[i] = sol[k];
        }
        z
    };
    'outer: for _ in 0..LH_OUTER_PER_VARIABLE * n + LH_EXTRA_ITERATIONS {
        let w = a.transpose() * (b - a * &x);
        let cand = (0..n)
            .filter(|&i| !passive[i] && w[i] > tol)
            .max_by(|&i, &j| w[i].total_cmp(&w[j]));
        let Some(t) = cand else {
            converged = true;
            break;
        };
        passive[t] = true;
        loop {
            iters += 1;
            let z = ls(&passive);
            if (0..n).all(|i| !passive[i] || z[i] > 0.0) {
                x = z;
                break;
            }
            let mut alpha = f64::INFINITY;
            for i in 0..n {
                if passive[i] && z[i] <= 0.0 {
                    alpha = alpha.min(x[i] / (x[i] - z[i]));
                }
            }
            x = &x + (&z - &x) * alpha;
            for i in 0..n {
                if passive[i] && x[i] <= LH_ZERO {
                    passive[i] = false;
                    x[i] = 0.0;
                }
            }
            if iters > LH_INNER_PER_VARIABLE * n + LH_INNER_EXTRA {
                // the inner loop's cap: reported as not converged
                break 'outer;
            }
        }
    }
    (x, iters, converged)
}

/// Largest iteration count of the projected Levenberg-Marquardt solver.
pub const LM_MAX_ITERATIONS: usize = 500;

/// Projected Levenberg-Marquardt from `x`; (iterations, converged).
pub(crate) fn projected_lm(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
    x: &mut DVector<f64>,
) -> (usize, bool) {
    let jtj = a.transpose() * a;
    let cost = |x: &DVector<f64>| (a * x - b).norm_squared();
    let mut mu = LM_MU_START;
    let mut c = cost(x);
    let n = x.len();
    for it in 0..LM_MAX_ITERATIONS {
        let g = a.transpose() * (a * &*x - b);
        let mut m = jtj.clone();
        for i in 0..n {
            m[(i, i)] += mu * jtj[(i, i)].max(f64::MIN_POSITIVE);
        }
        let Some(chol) = m.cholesky() else {
            mu *= LM_MU_UP_SINGULAR;
            continue;
        };
        let d = chol.solve(&(-g));
        let trial = (&*x + d).map(|v| v.max(0.0));
        let ct = cost(&trial);
        if ct < c {
            let done = (c - ct) <= SOLVER_STOP * c;
            *x = trial;
            c = ct;
            mu = (mu / LM_MU_DOWN).max(LM_MU_MIN);
            if done {
                return (it + 1, true);
            }
        } else {
            mu *= LM_MU_UP;
            if mu > LM_MU_MAX {
                // no descent step left: stationary within rounding
                return (it + 1, true);
            }
        }
    }
    (LM_MAX_ITERATIONS, false)
}
