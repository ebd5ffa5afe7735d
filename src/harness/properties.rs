//! Measurements for property tests of any [`Surface`]: boundary
//! interpolation, residuals through jets, join continuity, jets against
//! finite differences.
//!
//! Each function returns the measured error (relative where it says so);
//! the caller compares it with a named tolerance through [`within`]. None
//! of them asserts, so they serve tests, checks and reports alike.

use crate::jet::Jet;
use crate::surface::Surface;
use proptest::test_runner::TestCaseError;

/// Highest derivative order in each direction that [`Derivatives`] holds.
pub const MAX_ORDER: usize = 6;

/// Every partial derivative `d^(i+j) S / du^i dv^j`, `i, j <= 6`, of a
/// surface at one point, from one evaluation in truncated Taylor arithmetic
/// (exact to rounding; no finite differences).
#[derive(Clone, Debug, PartialEq)]
pub struct Derivatives {
    d: [[[f64; 3]; MAX_ORDER + 1]; MAX_ORDER + 1],
}

impl Derivatives {
    /// The derivatives of `s` at `(u, v)`.
    pub fn at<S: Surface + ?Sized>(s: &S, u: f64, v: f64) -> Derivatives {
        let p = s.eval(Jet::<7, 7>::var_u(u), Jet::<7, 7>::var_v(v));
        let mut d = [[[0.0; 3]; MAX_ORDER + 1]; MAX_ORDER + 1];
        for (i, row) in d.iter_mut().enumerate() {
            for (j, dij) in row.iter_mut().enumerate() {
                *dij = [p[0].deriv(i, j), p[1].deriv(i, j), p[2].deriv(i, j)];
            }
        }
        Derivatives { d }
    }

    /// `d^(i+j) S / du^i dv^j` (zero beyond order 6 in either direction).
    pub fn get(&self, i: usize, j: usize) -> [f64; 3] {
        if i > MAX_ORDER || j > MAX_ORDER {
            return [0.0; 3];
        }
        self.d[i][j]
    }
}

/// `n` parameters evenly spread over `[lo, hi]` (both ends when `closed`
/// is false, the upper end left out when it repeats the lower one).
fn spread(lo: f64, hi: f64, n: usize, closed: bool) -> Vec<f64> {
    let n = n.max(2);
    let steps = if closed { n } else { n - 1 };
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / steps as f64)
        .collect()
}

/// Largest distance between the `order`-th u-derivative of `s` along the
/// line `u` (`order = 0`: the surface itself) and `curve(v)`, over `samples`
/// values of `v` spread over the domain, relative to `max(1, |curve(v)|)`.
///
/// This is the boundary-interpolation property: a patch built to pass
/// through `C(v)` at `u = 0` with u-tangent `T(v)` has
/// `boundary_gap(s, 0.0, 0, C, n)` and `boundary_gap(s, 0.0, 1, T, n)` at
/// rounding level.
pub fn boundary_gap<S: Surface + ?Sized>(
    s: &S,
    u: f64,
    order: usize,
    curve: impl Fn(f64) -> [f64; 3],
    samples: usize,
) -> f64 {
    let d = s.domain();
    let mut worst: f64 = 0.0;
    for v in spread(d.v.0, d.v.1, samples, d.closed_v) {
        let got = s.derivative(u, v, order.min(MAX_ORDER), 0);
        let want = curve(v);
        let e = crate::vec3::dist(got, want) / crate::vec3::norm(want).max(1.0);
        worst = if e.is_nan() { f64::NAN } else { worst.max(e) };
    }
    worst
}

/// Largest norm of `operator(derivatives)` over `points`, relative to the
/// scale the operator returns beside it: `operator` gets the exact
/// derivatives of `s` at each point and returns `(residual, scale)`, e.g.
/// for `S_uuuu + 2 S_uuvv + S_vvvv = 0` the residual vector and the largest
/// magnitude of its terms. The result is `max |residual| / max(1, scale)`.
pub fn residual<S: Surface + ?Sized>(
    s: &S,
    points: &[(f64, f64)],
    operator: impl Fn(&Derivatives, f64, f64) -> ([f64; 3], f64),
) -> f64 {
    let mut worst: f64 = 0.0;
    for &(u, v) in points {
        let (r, scale) = operator(&Derivatives::at(s, u, v), u, v);
        let e = crate::vec3::norm(r) / scale.abs().max(1.0);
        worst = if e.is_nan() { f64::NAN } else { worst.max(e) };
    }
    worst
}

/// `points` spread over the interior of `s`'s domain: an `n x n` grid at
/// fractions `(i + 0.5) / n` (never on an edge or a join at a round
/// fraction).
pub fn interior_points<S: Surface + ?Sized>(s: &S, n: usize) -> Vec<(f64, f64)> {
    let d = s.domain();
    let n = n.max(1);
    let f = |i: usize| (i as f64 + 0.5) / n as f64;
    (0..n)
        .flat_map(|i| (0..n).map(move |j| d.at(f(i), f(j))))
        .collect()
}

/// Offset from a join at which [`joins_within`] evaluates each side: the
/// one-sided jets there are Taylor-extrapolated to the join, a truncation
/// of order `OFFSET^(7 - k)` for the k-th derivative, far below rounding.
pub const JOIN_OFFSET: f64 = 1e-7;

/// The u-derivatives of order `0..=order` of `s` at `(u0 + h, v)`
/// extrapolated to `(u0, v)` by their Taylor series (from the side of `h`).
fn one_sided<S: Surface + ?Sized>(s: &S, u0: f64, h: f64, v: f64, order: usize) -> Vec<[f64; 3]> {
    let p = s.eval(Jet::<7, 1>::var_u(u0 + h), Jet::<7, 1>::constant(v));
    (0..=order.min(MAX_ORDER))
        .map(|k| {
            std::array::from_fn(|c| {
                let mut acc = 0.0;
                let mut term = 1.0;
                for m in 0..=(MAX_ORDER - k) {
                    acc += p[c].deriv(k + m, 0) * term;
                    term *= -h / (m + 1) as f64;
                }
                acc
            })
        })
        .collect()
}

/// Relative jumps `[C0, C1, ..., C_order]` of the u-derivatives across the
/// joins `u = at[i]` inside one surface (a chain of patches that
/// [`Surface::eval`] switches between): each side's derivatives are taken
/// [`JOIN_OFFSET`] away and extrapolated to the join, compared over
/// `samples` values of v, relative to `max(1, |left|, |right|)`.
pub fn joins_within<S: Surface + ?Sized>(
    s: &S,
    at: &[f64],
    order: usize,
    samples: usize,
) -> Vec<f64> {
    let d = s.domain();
    let width = d.u.1 - d.u.0;
    let h = JOIN_OFFSET * width.abs().max(1.0);
    let mut worst = vec![0.0f64; order.min(MAX_ORDER) + 1];
    for &u0 in at {
        for v in spread(d.v.0, d.v.1, samples, d.closed_v) {
            let l = one_sided(s, u0, -h, v, order);
            let r = one_sided(s, u0, h, v, order);
            for (k, w) in worst.iter_mut().enumerate() {
                let scale = crate::vec3::norm(l[k])
                    .max(crate::vec3::norm(r[k]))
                    .max(1.0);
                let e = crate::vec3::dist(l[k], r[k]) / scale;
                *w = if e.is_nan() { f64::NAN } else { w.max(e) };
            }
        }
    }
    worst
}

/// Relative jumps `[C0, ..., C_order]` between two surfaces meeting along
/// `left`'s end `u = u_1` and `right`'s start `u = u_0`, the same fraction of
/// each v domain compared, over `samples` values. Both must use the same
/// u scale at the join (a patch of length L parameterised over [0, 1] has
/// its k-th derivative scaled by L^-k: rescale first).
pub fn join_between<A: Surface + ?Sized, B: Surface + ?Sized>(
    left: &A,
    right: &B,
    order: usize,
    samples: usize,
) -> Vec<f64> {
    let (dl, dr) = (left.domain(), right.domain());
    let mut worst = vec![0.0f64; order.min(MAX_ORDER) + 1];
    for t in spread(0.0, 1.0, samples, dl.closed_v) {
        let (_, vl) = dl.at(1.0, t);
        let (_, vr) = dr.at(0.0, t);
        for (k, w) in worst.iter_mut().enumerate() {
            let a = left.derivative(dl.u.1, vl, k, 0);
            let b = right.derivative(dr.u.0, vr, k, 0);
            let scale = crate::vec3::norm(a).max(crate::vec3::norm(b)).max(1.0);
            let e = crate::vec3::dist(a, b) / scale;
            *w = if e.is_nan() { f64::NAN } else { w.max(e) };
        }
    }
    worst
}

/// Jet derivatives `S_u, S_v, S_uu, S_uv, S_vv` against Richardson-
/// extrapolated central differences at four interior points, relative:
/// the kit's own derivative check ([`crate::surface::check::jet_vs_fd`]),
/// whose tolerance is [`crate::surface::check::FD_TOL`]. It catches a
/// hand-written `eval` whose jets disagree with its values (a derivative
/// formula that is not the derivative).
pub fn derivatives_vs_finite_differences<S: Surface>(s: &S) -> f64 {
    crate::surface::check::jet_vs_fd(s)
}

/// `Ok` when `measured <= tolerance` (NaN and infinity fail), else a
/// proptest failure naming the property and both numbers.
pub fn within(property: &str, measured: f64, tolerance: f64) -> Result<(), TestCaseError> {
    if measured.is_finite() && measured <= tolerance {
        Ok(())
    } else {
        Err(TestCaseError::fail(format!(
            "{property}: measured {measured:e} > tolerance {tolerance:e}"
        )))
    }
}
