//! Weights and global interpolation (paper 003, sec 3.3, Figs 3-5).
//!
//! **Weights.** For a segment from $p$ to $q$ with radii $R_p, R_q$ (already
//! multiplied by the radius factor 0.8), $r_p = p + R_p n$, $r_q = q + R_q n$
//! ($n$ the stroke plane's normal) and $A = F_1 - F_t/l$, $B = F_t/l$, the
//! conditions $F(r_p) = F(r_q) = T$ read $w_0 A(r_p) + w_1 B(r_p) = T$ and
//! $w_0 A(r_q) + w_1 B(r_q) = T$. The paper drops the small cross terms:
//! $w_0 = T/A(r_p)$, $w_1 = T/B(r_q)$ ([`WeightMode::Paper`], default), then
//! scales both by $\kappa = T / (w_0 A(r_{mid}) + w_1 B(r_{mid}))$ with
//! $r_{mid}$ at $(R_p+R_q)/2$ above $(p+q)/2$. [`WeightMode::Exact`] solves
//! the 2x2 system instead (no $\kappa$), with both weights kept
//! non-negative ([`nonnegative_endpoint_weights`]: on short segments the
//! system is nearly singular and its plain solution changes sign). Finally the weight at each
//! skeletal endpoint is divided by the number of segments meeting there.
//! The printed weight equations omit the $1/l$ of $F_t$ (ERRATA.md).
//!
//! **Global interpolation.** $\min_{\Lambda\ge 0}\|\mathbf F\Lambda - \mathbf T\|^2$,
//! $\mathbf F_{ji}$ the field of segment $i$ (its weights, $\lambda = 1$) at
//! silhouette point $r_j$. Three solvers: Hildreth-d'Esopo (cyclic
//! coordinate descent on the normal equations with projection onto
//! $\lambda_i \ge 0$ — d'Esopo's coordinate-wise scheme for bound
//! constraints, which is what Hildreth's row-action method reduces to when
//! every constraint involves one variable), Lawson-Hanson NNLS (active set,
//! exact), and a projected Levenberg-Marquardt. The paper asks $\Lambda > 0$;
//! all three return $\Lambda \ge 0$ (a zero switches a segment off).

use super::kernel::Segment;
use super::ConvError;
use nalgebra::{DMatrix, DVector};

/// How the per-segment weights are set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum WeightMode {
    /// The paper's decoupled approximation plus the midpoint scale $\kappa$.
    Paper,
    /// The exact 2x2 solve of both endpoint conditions, weights $\ge 0$.
    Exact,
}

/// Global interpolation solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Solver {
    /// No global interpolation ($\lambda_i = 1$, Fig 4a).
    None,
    HildrethDEsopo,
    LawsonHanson,
    ProjectedLm,
}

/// Radii-carrying skeleton segment in the plane (before weights).
#[derive(Clone, Copy, Debug)]
pub struct RawSegment {
    pub p: [f64; 3],
    pub q: [f64; 3],
    pub rp: f64,
    pub rq: f64,
    /// Number of segments meeting at `p` and at `q`.
    pub degree: [usize; 2],
}

fn ab(seg: &Segment, r: [f64; 3], s: f64) -> (f64, f64) {
    let (f1, ft) = seg.basis(r, s);
    let l = seg.length();
    (f1 - ft / l, ft / l)
}

fn offset(x: [f64; 3], n: [f64; 3], d: f64) -> [f64; 3] {
    [x[0] + d * n[0], x[1] + d * n[1], x[2] + d * n[2]]
}

/// The field of a segment as the paper's weight equations print it,
/// $w_0(F_1 - F_t) + w_1 F_t$ (no $1/l$): kept for the paper-literal check.
pub fn paper_literal_field(seg: &Segment, r: [f64; 3], s: f64) -> f64 {
    let (f1, ft) = seg.basis(r, s);
    seg.w0 * (f1 - ft) + seg.w1 * ft
}

/// Weights of one isolated segment (before the division at joints).
pub fn segment_weights(
    raw: &RawSegment,
    normal: [f64; 3],
    threshold: f64,
    s: f64,
    mode: WeightMode,
) -> Result<Segment, ConvError> {
    let mut seg = Segment {
        p: raw.p,
        q: raw.q,
        w0: 1.0,
        w1: 1.0,
        lambda: 1.0,
    };
    let rp = offset(raw.p, normal, raw.rp);
    let rq = offset(raw.q, normal, raw.rq);
    let (ap, bp) = ab(&seg, rp, s);
    let (aq, bq) = ab(&seg, rq, s);
    match mode {
        WeightMode::Paper => {
            seg.w0 = threshold / ap;
            seg.w1 = threshold / bq;
            let mid = offset(
                [
                    0.5 * (raw.p[0] + raw.q[0]),
                    0.5 * (raw.p[1] + raw.q[1]),
                    0.5 * (raw.p[2] + raw.q[2]),
                ],
                normal,
                0.5 * (raw.rp + raw.rq),
            );
            let (am, bm) = ab(&seg, mid, s);
            let kappa = threshold / (seg.w0 * am + seg.w1 * bm);
            seg.w0 *= kappa;
            seg.w1 *= kappa;
        }
        WeightMode::Exact => {
            let [w0, w1] = nonnegative_endpoint_weights([[ap, bp], [aq, bq]], threshold);
            seg.w0 = w0;
            seg.w1 = w1;
        }
    }
    if !(seg.w0.is_finite() && seg.w1.is_finite()) {
        return Err(ConvError::Numerical(format!(
            "non-finite weights for the segment {:?}-{:?}",
            raw.p, raw.q
        )));
    }
    Ok(seg)
}

/// The exact endpoint weights: $\min_{w \ge 0} \|M w - T\mathbf 1\|$ for
/// the 2x2 system $M = [[A(r_p), B(r_p)], [A(r_q), B(r_q)]]$ of both
/// endpoint conditions.
///
/// The unconstrained solve is the answer when both weights come out
/// non-negative. On a segment that is short against its radius (or under
/// a wide kernel, small $s$) the two rows are nearly equal, the system is
/// nearly singular and its solution is a large positive weight at one end
/// and a large negative one at the other: a kernel weight that changes sign
/// along the segment, so its field is negative on one side. The global fit
/// ($\lambda \ge 0$) cannot undo that, and a near-circular stroke was
/// reconstructed with an RMS error of 87 % of $T$ (issue 16). With the sign
/// constraint the minimum lies on a face $w_0 = 0$ or $w_1 = 0$ (Karush-Kuhn-
/// Tucker: the unconstrained minimum is infeasible and the problem is
/// convex), a one-variable least-squares problem each; the better face wins.
pub fn nonnegative_endpoint_weights(m: [[f64; 2]; 2], threshold: f64) -> [f64; 2] {
    let [[ap, bp], [aq, bq]] = m;
    let det = ap * bq - bp * aq;
    if det != 0.0 {
        let w0 = threshold * (bq - bp) / det;
        let w1 = threshold * (ap - aq) / det;
        if w0 >= 0.0 && w1 >= 0.0 && w0.is_finite() && w1.is_finite() {
            return [w0, w1];
        }
    }
    // one column at a time: w = T (c . 1) / (c . c), clamped at 0
    let face = |c0: f64, c1: f64| -> (f64, f64) {
        let cc = c0 * c0 + c1 * c1;
        let w = if cc > 0.0 {
            (threshold * (c0 + c1) / cc).max(0.0)
        } else {
            0.0
        };
        let r = (c0 * w - threshold).powi(2) + (c1 * w - threshold).powi(2);
        (w, r)
    };
    let (w0, r0) = face(ap, aq);
    let (w1, r1) = face(bp, bq);
    if r0 <= r1 {
        [w0, 0.0]
    } else {
        [0.0, w1]
    }
}

/// Weights of all segments, divided at joints when `divide_at_joints`.
pub fn weights(
    raws: &[RawSegment],
    normal: [f64; 3],
    threshold: f64,
    s: f64,
    mode: WeightMode,
    divide_at_joints: bool,
) -> Result<Vec<Segment>, ConvError> {
    raws.iter()
        .map(|r| {
            let mut seg = segment_weights(r, normal, threshold, s, mode)?;
            if divide_at_joints {
                seg.w0 /= r.degree[0].max(1) as f64;
                seg.w1 /= r.degree[1].max(1) as f64;
            }
            Ok(seg)
        })
        .collect()
}

/// Result of a global interpolation.
#[derive(Clone, Debug, serde::Serialize)]
pub struct FitReport {
    pub solver: Solver,
    pub lambda: Vec<f64>,
    /// $\max_j |F(r_j) - T| / T$ at the silhouette points.
    pub max_rel_error: f64,
    /// RMS of $(F(r_j) - T)/T$.
    pub rms_rel_error: f64,
    pub iterations: usize,
    /// The solver met its stopping rule (`false`: it ran into its
    /// iteration cap and `lambda` is its last iterate).
    pub converged: bool,
    pub seconds: f64,
}

/// Column matrix $\mathbf F$ (rows: points, columns: segments).
pub fn field_matrix(segments: &[Segment], points: &[[f64; 3]], s: f64) -> DMatrix<f64> {
    DMatrix::from_fn(points.len(), segments.len(), |j, i| {
        segments[i].unscaled_field(points[j], s)
    })
}

/// Relative residuals (max, rms) of `lambda`.
pub fn fit_errors(f: &DMatrix<f64>, lambda: &DVector<f64>, threshold: f64) -> (f64, f64) {
    let r = f * lambda;
    let m = r.len().max(1) as f64;
    let mut mx: f64 = 0.0;
    let mut ss = 0.0;
    for v in r.iter() {
        let e = (v - threshold) / threshold;
        mx = mx.max(e.abs());
        ss += e * e;
    }
    (mx, (ss / m).sqrt())
}

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
fn kkt_residual(q: &DMatrix<f64>, c: &DVector<f64>, x: &DVector<f64>) -> f64 {
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
fn hildreth(q: &DMatrix<f64>, c: &DVector<f64>, x: &mut DVector<f64>) -> (usize, bool) {
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

fn lawson_hanson(a: &DMatrix<f64>, b: &DVector<f64>) -> (DVector<f64>, usize, bool) {
    let n = a.ncols();
    let mut x = DVector::zeros(n);
    let mut passive = vec![false; n];
    let tol = 1e-12 * a.norm() * b.norm().max(1.0);
    let mut iters = 0;
    let mut converged = false;
    let ls = |passive: &[bool]| -> DVector<f64> {
        let cols: Vec<usize> = (0..n).filter(|&i| passive[i]).collect();
        let sub = DMatrix::from_fn(a.nrows(), cols.len(), |r, c| a[(r, cols[c])]);
        let sol = sub
            .svd(true, true)
            .solve(b, 1e-14)
            .unwrap_or_else(|_| DVector::zeros(cols.len()));
        let mut z = DVector::zeros(n);
        for (k, &i) in cols.iter().enumerate() {
            z[i] = sol[k];
        }
        z
    };
    for _ in 0..3 * n + 10 {
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
                if passive[i] && x[i] <= 1e-15 {
                    passive[i] = false;
                    x[i] = 0.0;
                }
            }
            if iters > 10 * n + 100 {
                break;
            }
        }
    }
    (x, iters, converged)
}

/// Largest iteration count of the projected Levenberg-Marquardt solver.
pub const LM_MAX_ITERATIONS: usize = 500;

fn projected_lm(a: &DMatrix<f64>, b: &DVector<f64>, x: &mut DVector<f64>) -> (usize, bool) {
    let jtj = a.transpose() * a;
    let cost = |x: &DVector<f64>| (a * x - b).norm_squared();
    let mut mu = 1e-3;
    let mut c = cost(x);
    let n = x.len();
    for it in 0..LM_MAX_ITERATIONS {
        let g = a.transpose() * (a * &*x - b);
        let mut m = jtj.clone();
        for i in 0..n {
            m[(i, i)] += mu * jtj[(i, i)].max(1e-300);
        }
        let Some(chol) = m.cholesky() else {
            mu *= 10.0;
            continue;
        };
        let d = chol.solve(&(-g));
        let trial = (&*x + d).map(|v| v.max(0.0));
        let ct = cost(&trial);
        if ct < c {
            let done = (c - ct) <= SOLVER_STOP * c;
            *x = trial;
            c = ct;
            mu = (mu / 3.0).max(1e-12);
            if done {
                return (it + 1, true);
            }
        } else {
            mu *= 4.0;
            if mu > 1e12 {
                // no descent step left: stationary within rounding
                return (it + 1, true);
            }
        }
    }
    (LM_MAX_ITERATIONS, false)
}

/// Solves the global interpolation for `segments` at `points`.
pub fn global_fit(
    segments: &[Segment],
    points: &[[f64; 3]],
    threshold: f64,
    s: f64,
    solver: Solver,
) -> Result<FitReport, ConvError> {
    if segments.is_empty() || points.is_empty() {
        return Err(ConvError::Numerical("nothing to fit".into()));
    }
    let t0 = std::time::Instant::now();
    let f = field_matrix(segments, points, s);
    let tv = DVector::from_element(points.len(), threshold);
    let ones = DVector::from_element(segments.len(), 1.0);
    let (lambda, iterations, converged) = match solver {
        Solver::None => (ones, 0, true),
        Solver::HildrethDEsopo => {
            let q = f.transpose() * &f;
            let c = f.transpose() * &tv;
            let mut x = ones;
            let (it, ok) = hildreth(&q, &c, &mut x);
            (x, it, ok)
        }
        Solver::LawsonHanson => lawson_hanson(&f, &tv),
        Solver::ProjectedLm => {
            let mut x = ones;
            let (it, ok) = projected_lm(&f, &tv, &mut x);
            (x, it, ok)
        }
    };
    let seconds = t0.elapsed().as_secs_f64();
    if lambda.iter().any(|v| !v.is_finite()) {
        return Err(ConvError::Numerical(format!(
            "{solver:?} returned a non-finite lambda"
        )));
    }
    let (max_rel_error, rms_rel_error) = fit_errors(&f, &lambda, threshold);
    Ok(FitReport {
        solver,
        lambda: lambda.iter().copied().collect(),
        max_rel_error,
        rms_rel_error,
        iterations,
        converged,
        seconds,
    })
}
