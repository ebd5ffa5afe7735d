//! Polyharmonic radial basis function interpolation with a linear polynomial
//! part (000 sec 4.2: "RBF interpolation").
//!
//! For centres $c_i \in \mathbb{R}^d$ and values $f_i \in \mathbb{R}^m$ the
//! interpolant is
//! $$ s(x) = \sum_i w_i\,\varphi(\lVert x - c_i\rVert) + a_0 + A x, $$
//! with the thin-plate spline $\varphi(r) = r^2 \log r$ in the plane
//! ($d = 2$) and the biharmonic spline $\varphi(r) = r$ in space ($d = 3$),
//! both conditionally positive definite of order 2, so the saddle-point system
//! $$ \begin{pmatrix} \Phi & P \\ P^T & 0 \end{pmatrix}
//!    \begin{pmatrix} w \\ a \end{pmatrix} = \begin{pmatrix} f \\ 0 \end{pmatrix} $$
//! has one solution whenever the centres are distinct and not all on one
//! hyperplane. Linear maps are reproduced exactly (the side conditions
//! $P^T w = 0$ make $w = 0$ for affine data), which is what makes a fit
//! covariant under similarity transforms of the sketch.
//!
//! The system is solved densely (faer, LU with partial pivoting) on
//! coordinates centred and scaled to unit diameter; the solve is proved by
//! its residual, and the 2-norm condition number is measured from the
//! eigenvalues of the (symmetric) matrix when the centres are at most
//! [`CONDITION_MAX_CENTRES`].

use faer::prelude::Solve;
use faer::{Mat, Side};
use thiserror::Error;

/// Above this many centres the condition number is not computed (an
/// eigenvalue decomposition costs more than the fit).
pub const CONDITION_MAX_CENTRES: usize = 2500;
/// Two centres closer than this (relative to the centres' diameter) are
/// coincident.
pub const COINCIDENT_REL: f64 = 1e-9;

/// Errors of RBF construction.
#[derive(Debug, Error, PartialEq)]
pub enum RbfError {
    #[error("an RBF needs at least {need} centres in {dim}D, got {got}")]
    TooFewCentres { need: usize, got: usize, dim: usize },
    #[error("RBF centres {i} and {j} coincide ({at:?})")]
    CoincidentCentres { i: usize, j: usize, at: Vec<f64> },
    #[error("RBF centre {index} or its value is not finite")]
    NonFinite { index: usize },
    #[error("{centres} centres but {values} values")]
    CountMismatch { centres: usize, values: usize },
    #[error("the RBF centres lie on one {what}: the linear part is undetermined")]
    Degenerate { what: &'static str },
    #[error("the RBF system is singular to working precision (residual {residual:e})")]
    Singular { residual: f64 },
}

/// A fitted polyharmonic interpolant from `D` dimensions to `M` values.
#[derive(Clone, Debug)]
pub struct Rbf<const D: usize, const M: usize> {
    centres: Vec<[f64; D]>,
    weights: Vec<[f64; M]>,
    /// `poly[0]`: constant, `poly[1 + k]`: coefficient of coordinate `k`.
    poly: [[f64; M]; 4],
    shift: [f64; D],
    scale: f64,
    /// Relative residual of the solve: max |A x - b| / max |b|.
    pub residual: f64,
    /// 2-norm condition number of the (scaled) system, when measured.
    pub condition: Option<f64>,
}

/// The kernel for dimension `d`: $r^2 \log r$ (d = 2) or $r$ (d = 3).
pub fn kernel(d: usize, r: f64) -> f64 {
    if d == 2 {
        if r <= 0.0 {
            0.0
        } else {
            r * r * r.ln()
        }
    } else {
        r
    }
}

fn dist<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    let mut s = 0.0;
    for k in 0..D {
        let d = a[k] - b[k];
        s += d * d;
    }
    s.sqrt()
}

impl<const D: usize, const M: usize> Rbf<D, M> {
    /// Fits the interpolant; `condition` asks for the condition number.
    pub fn fit(
        centres: &[[f64; D]],
        values: &[[f64; M]],
        condition: bool,
    ) -> Result<Self, RbfError> {
        assert!(D == 2 || D == 3, "RBF dimension must be 2 or 3");
        check_input(centres, values)?;
        let n = centres.len();
        let Normalised { xs, shift, scale } = normalise(centres)?;
        coincident(&xs, centres)?;
        if degenerate_affine(&xs) {
            return Err(RbfError::Degenerate {
                what: if D == 2 { "line" } else { "plane" },
            });
        }
        let q = D + 1;
        let a = system_matrix(&xs);
        let b = Mat::<f64>::from_fn(n + q, M, |i, m| if i < n { values[i][m] } else { 0.0 });
        let x = a.partial_piv_lu().solve(&b);
        let residual = relative_residual(&a, &x, &b, n);
        if !residual.is_finite() || residual > 1e-6 {
            return Err(RbfError::Singular { residual });
        }
        let weights = (0..n)
            .map(|i| {
                let mut w = [0.0; M];
                for m in 0..M {
                    w[m] = x[(i, m)];
                }
                w
            })
            .collect();
        let mut poly = [[0.0; M]; 4];
        for k in 0..q {
            for m in 0..M {
                poly[k][m] = x[(n + k, m)];
            }
        }
        let condition = if condition && n <= CONDITION_MAX_CENTRES {
            a.self_adjoint_eigenvalues(Side::Lower).ok().map(|ev| {
                let mx = ev.iter().fold(0.0f64, |s, v| s.max(v.abs()));
                let mn = ev.iter().fold(f64::INFINITY, |s, v| s.min(v.abs()));
                mx / mn
            })
        } else {
            None
        };
        Ok(Rbf {
            centres: xs,
            weights,
            poly,
            shift,
            scale,
            residual,
            condition,
        })
    }

    /// Number of centres.
    pub fn len(&self) -> usize {
        self.centres.len()
    }

    /// Always false: a fitted interpolant has centres.
    pub fn is_empty(&self) -> bool {
        self.centres.is_empty()
    }

    /// The interpolant at `p`.
    pub fn eval(&self, p: &[f64; D]) -> [f64; M] {
        let mut x = [0.0; D];
        for k in 0..D {
            x[k] = (p[k] - self.shift[k]) * self.scale;
        }
        let mut out = self.poly[0];
        for k in 0..D {
            for m in 0..M {
                out[m] += self.poly[1 + k][m] * x[k];
            }
        }
        if D == 2 {
            // r^2 log r = r^2 ln(r^2) / 2: no square root per centre
            for (c, w) in self.centres.iter().zip(&self.weights) {
                let r2 = (x[0] - c[0]).powi(2) + (x[1] - c[1]).powi(2);
                let phi = if r2 > 0.0 { 0.5 * r2 * r2.ln() } else { 0.0 };
                for m in 0..M {
                    out[m] += w[m] * phi;
                }
            }
            return out;
        }
        for (c, w) in self.centres.iter().zip(&self.weights) {
            let phi = kernel(D, dist(&x, c));
            for m in 0..M {
                out[m] += w[m] * phi;
            }
        }
        out
    }
}

/// Refuses centres and values of different counts, fewer than `D + 2`
/// centres, and a value or coordinate not finite.
fn check_input<const D: usize, const M: usize>(
    centres: &[[f64; D]],
    values: &[[f64; M]],
) -> Result<(), RbfError> {
    let n = centres.len();
    if n != values.len() {
        return Err(RbfError::CountMismatch {
            centres: n,
            values: values.len(),
        });
    }
    if n < D + 2 {
        return Err(RbfError::TooFewCentres {
            need: D + 2,
            got: n,
            dim: D,
        });
    }
    for (i, (c, v)) in centres.iter().zip(values).enumerate() {
        if c.iter().chain(v.iter()).any(|x| !x.is_finite()) {
            return Err(RbfError::NonFinite { index: i });
        }
    }
    Ok(())
}

/// Centres normalised: `(c - shift) * scale`.
struct Normalised<const D: usize> {
    xs: Vec<[f64; D]>,
    shift: [f64; D],
    scale: f64,
}

/// The centres normalised (centred on their bounding box, unit
/// diameter); refuses a box of zero diameter.
fn normalise<const D: usize>(centres: &[[f64; D]]) -> Result<Normalised<D>, RbfError> {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for c in centres {
        for k in 0..D {
            lo[k] = lo[k].min(c[k]);
            hi[k] = hi[k].max(c[k]);
        }
    }
    let mut shift = [0.0; D];
    for k in 0..D {
        shift[k] = 0.5 * (lo[k] + hi[k]);
    }
    let diam = dist(&lo, &hi);
    if diam <= 0.0 {
        return Err(RbfError::CoincidentCentres {
            i: 0,
            j: 1,
            at: centres[0].to_vec(),
        });
    }
    let scale = 1.0 / diam;
    let xs: Vec<[f64; D]> = centres
        .iter()
        .map(|c| {
            let mut p = [0.0; D];
            for k in 0..D {
                p[k] = (c[k] - shift[k]) * scale;
            }
            p
        })
        .collect();
    Ok(Normalised { xs, shift, scale })
}

/// The interpolation system's matrix: the kernel between the centres
/// `xs`, bordered by the affine polynomial basis.
fn system_matrix<const D: usize>(xs: &[[f64; D]]) -> Mat<f64> {
    let n = xs.len();
    let size = n + D + 1;
    Mat::<f64>::from_fn(size, size, |i, j| {
        if i < n && j < n {
            kernel(D, dist(&xs[i], &xs[j]))
        } else if i < n {
            poly_basis(&xs[i], j - n)
        } else if j < n {
            poly_basis(&xs[j], i - n)
        } else {
            0.0
        }
    })
}

/// The proof of the solve `a x = b` (`n` centres): the largest residual
/// over the largest value (at least 1), infinite where a residual is not
/// finite.
fn relative_residual(a: &Mat<f64>, x: &Mat<f64>, b: &Mat<f64>, n: usize) -> f64 {
    let (size, m_count) = (b.nrows(), b.ncols());
    let r = a * x - b;
    let bmax = (0..n)
        .flat_map(|i| (0..m_count).map(move |m| (i, m)))
        .map(|(i, m)| b[(i, m)].abs())
        .fold(0.0f64, f64::max)
        .max(1e-300);
    let mut rmax = 0.0f64;
    for i in 0..size {
        for m in 0..m_count {
            let v = r[(i, m)];
            rmax = if v.is_finite() {
                rmax.max(v.abs())
            } else {
                f64::INFINITY
            };
        }
    }
    rmax / bmax.max(1.0)
}

fn poly_basis<const D: usize>(x: &[f64; D], k: usize) -> f64 {
    if k == 0 {
        1.0
    } else {
        x[k - 1]
    }
}

/// Errors on the first pair of centres closer than [`COINCIDENT_REL`] (on
/// unit-diameter coordinates), found by sorting along the first axis.
fn coincident<const D: usize>(xs: &[[f64; D]], orig: &[[f64; D]]) -> Result<(), RbfError> {
    let mut order: Vec<usize> = (0..xs.len()).collect();
    order.sort_by(|&a, &b| xs[a][0].total_cmp(&xs[b][0]));
    for (s, &i) in order.iter().enumerate() {
        for &j in &order[s + 1..] {
            if xs[j][0] - xs[i][0] > COINCIDENT_REL {
                break;
            }
            if dist(&xs[i], &xs[j]) <= COINCIDENT_REL {
                let (i, j) = (i.min(j), i.max(j));
                return Err(RbfError::CoincidentCentres {
                    i,
                    j,
                    at: orig[i].to_vec(),
                });
            }
        }
    }
    Ok(())
}

/// True when the centres lie on one line (2D) or plane (3D): the smallest
/// singular value of the centred coordinates vanishes.
fn degenerate_affine<const D: usize>(xs: &[[f64; D]]) -> bool {
    let n = xs.len() as f64;
    let mut mean = [0.0; D];
    for x in xs {
        for k in 0..D {
            mean[k] += x[k] / n;
        }
    }
    let c = Mat::<f64>::from_fn(xs.len(), D, |i, k| xs[i][k] - mean[k]);
    match c.singular_values() {
        Ok(s) => s.iter().fold(f64::INFINITY, |a, &b| a.min(b)) <= 1e-9 * n.sqrt(),
        Err(_) => true,
    }
}
