//! Fourth-order PDE deformation surfaces with sculpting forces
//! (paper 000 sec 3.1, eqs 1-15, appendices A and B; used by sec 5.1).
//!
//! Each component $t \in \{x, y, z\}$ of a deformation solves (eq 1)
//! $$a_{t1}\,t_{uuuu} + a_{t2}\,t_{uuvv} + a_{t3}\,t_{vvvv} = P_t(u, v)$$
//! on the unit square, clamped ($t = t_u = 0$) at $u = 0, 1$ (eq 5) and, for
//! 4-sided patches, also at $v = 0, 1$ (eq 10). The operator is elliptic iff
//! $a_{t1} > 0$, $a_{t3} > 0$ and $a_{t2} > -2\sqrt{a_{t1}a_{t3}}$ (the symbol
//! $a_1\xi^4 + a_2\xi^2\eta^2 + a_3\eta^4$ is then positive); anything else is
//! rejected. $a_1 = a_3 = 1$, $a_2 = 2$ is the biharmonic thin plate
//! $D\Delta^2 w = q$; $a_1 = 1$, $a_2 = 2\rho^2$, $a_3 = \rho^4$ is a plate of side
//! ratio $\rho = a/b$ with $t$ in units of $q a^4 / D$.
//!
//! * [`force`]: concentrated, line and area forces (eqs 2-3), their series
//!   (eqs 4, 11) in closed form and as printed (appendices A, B).
//! * [`two_sided`]: 2-sided patches, the printed basis (eqs 6-9) and the
//!   exact per-Fourier-mode solution of the clamped ODE (every root case),
//!   with non-zero boundary curves and tangents (sec 5.1).
//! * [`four_sided`]: 4-sided patches, printed eqs 12-15 and a coupled
//!   Ritz-Galerkin solution in the same basis, validated against classical
//!   clamped-plate values.
//! * [`apply`]: deforming surfaces and mesh regions.
//! * [`spec`]: the JSON spec of `pdesculpt pde4`.
//!
//! Documented parameter ranges (swept by the property tests): $a_1, a_3 \in
//! [0.05, 5]$, $a_2 = \tau\,2\sqrt{a_1a_3}$ with $\tau \in (-0.95, 4)$; force
//! positions and ranges anywhere in $[0, 1]$ with widths $\ge 0.02$;
//! $1 \le M, N \le$ [`MAX_TERMS`] (the exact 2-sided solver is checked to
//! rounding for every such case; the Galerkin solve is dense, $(MN)^3/3$ flops).

pub mod apply;
pub mod check;
pub mod fd;
pub mod force;
pub mod four_sided;
pub mod quad;
pub mod samples;
pub mod spec;
pub mod two_sided;

pub use force::{Force, ForceKind};
pub use four_sided::FourSided;
pub use two_sided::TwoSided;

/// Largest magnitude of a force component and of a shape parameter (and
/// the inverse of the smallest positive a_t1, a_t3): keeps every
/// displacement finite.
pub const MAX_MAGNITUDE: f64 = 1e100;

/// Largest number of series terms per direction accepted.
pub const MAX_TERMS: usize = 256;

/// Errors of the pde4 family.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Pde4Error {
    #[error("{what} = {value} is not finite")]
    NonFinite { what: &'static str, value: f64 },
    #[error("shape parameter a_t1 = {0} must be > 0")]
    NonPositiveA1(f64),
    #[error("shape parameters a_t1 = {a1}, a_t2 = {a2}, a_t3 = {a3} make PDE (1) non-elliptic (need a_t3 > 0 and a_t2 > -2 sqrt(a_t1 a_t3))")]
    NotElliptic { a1: f64, a2: f64, a3: f64 },
    #[error("{what} = [{lo}, {hi}] lies outside [0, 1]")]
    OutsidePatch {
        what: &'static str,
        lo: f64,
        hi: f64,
    },
    #[error("{what} = [{lo}, {hi}] is empty (need lower < upper)")]
    EmptyRange {
        what: &'static str,
        lo: f64,
        hi: f64,
    },
    #[error("number of terms M = {m}, N = {n} must be between 1 and {max}")]
    Terms { m: usize, n: usize, max: usize },
    #[error("no forces given")]
    NoForces,
    #[error("boundary data has {got} harmonics, more than N = {n}")]
    BoundaryHarmonics { got: usize, n: usize },
    /// A patch type, method and data combination no solver here handles.
    #[error("{0}")]
    Unsupported(&'static str),
    /// A linear system that could not be factored or solved.
    #[error("{system}: {reason}")]
    Solve {
        system: &'static str,
        reason: String,
    },
    /// A solution that is not finite at a point of the patch.
    #[error("the solution is not finite at (u, v) = ({u}, {v}) (method {method} singular or overflowing for these shape parameters and forces; try method exact or galerkin, or smaller numbers)")]
    NonFiniteSolution { u: f64, v: f64, method: String },
    /// A number too large or too small for the closed forms.
    #[error("{what} = {value:e} lies outside [{lo:e}, {hi:e}] ({why})")]
    Magnitude {
        what: String,
        value: f64,
        lo: f64,
        hi: f64,
        why: &'static str,
    },
    /// A range outside the surface's base domain.
    #[error("{what} [{lo}, {hi}] lies outside the base domain [{dlo}, {dhi}]")]
    OutsideDomain {
        what: &'static str,
        lo: f64,
        hi: f64,
        dlo: f64,
        dhi: f64,
    },
    /// A value that must be finite and positive.
    #[error("{what} {value} must be finite and > 0")]
    NotPositive { what: &'static str, value: f64 },
    /// A drawn curve or part axis that defines no deformation.
    #[error("{0}")]
    Region(String),
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
}

/// Shape parameters `(a_t1, a_t2, a_t3)` of one component.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShapeParams {
    pub a1: f64,
    pub a2: f64,
    pub a3: f64,
}

impl ShapeParams {
    /// The biharmonic (thin plate) operator `(1, 2, 1)`.
    pub const PLATE: ShapeParams = ShapeParams {
        a1: 1.0,
        a2: 2.0,
        a3: 1.0,
    };

    /// All three equal to `a` (the paper's "shape parameters a").
    pub fn uniform(a: f64) -> Self {
        ShapeParams {
            a1: a,
            a2: a,
            a3: a,
        }
    }

    /// Clamped rectangular plate of side ratio `rho = a / b` (u along `a`).
    pub fn plate_ratio(rho: f64) -> Self {
        ShapeParams {
            a1: 1.0,
            a2: 2.0 * rho * rho,
            // (rho^2)^2 multiplied out: `powi` may round differently when
            // the compiler folds it than at run time, which moved
            // pde4.four_sided.plate_rect_1_5_sine (rho = 2/3) by 3e-11
            // between two builds of unchanged pde4 code
            a3: (rho * rho) * (rho * rho),
        }
    }

    /// Finite, `a1 > 0`, elliptic.
    pub fn validate(&self) -> Result<(), Pde4Error> {
        for (what, value) in [("a_t1", self.a1), ("a_t2", self.a2), ("a_t3", self.a3)] {
            if !value.is_finite() {
                return Err(Pde4Error::NonFinite { what, value });
            }
        }
        if self.a1 <= 0.0 {
            return Err(Pde4Error::NonPositiveA1(self.a1));
        }
        if self.a3 <= 0.0 || self.a2 <= -2.0 * (self.a1 * self.a3).sqrt() {
            return Err(Pde4Error::NotElliptic {
                a1: self.a1,
                a2: self.a2,
                a3: self.a3,
            });
        }
        for (what, value) in [("a_t1", self.a1), ("a_t2", self.a2), ("a_t3", self.a3)] {
            if value.abs() > MAX_MAGNITUDE || (what != "a_t2" && value < 1.0 / MAX_MAGNITUDE) {
                return Err(Pde4Error::Magnitude {
                    what: format!("shape parameter {what}"),
                    value,
                    lo: 1.0 / MAX_MAGNITUDE,
                    hi: MAX_MAGNITUDE,
                    why: "the solution would overflow or underflow",
                });
            }
        }
        Ok(())
    }

    /// Symbol of the operator for the mode `sin(k u) e^{i w v}`:
    /// `a1 k^4 + a2 k^2 w^2 + a3 w^4`.
    pub fn symbol(&self, k: f64, w: f64) -> f64 {
        self.a1 * k.powi(4) + self.a2 * k * k * w * w + self.a3 * w.powi(4)
    }
}

pub(crate) fn check_terms(m: usize, n: usize, n_min: usize) -> Result<(), Pde4Error> {
    if m < 1 || n < n_min || m > MAX_TERMS || n > MAX_TERMS {
        return Err(Pde4Error::Terms {
            m,
            n,
            max: MAX_TERMS,
        });
    }
    Ok(())
}

/// Refuses a Galerkin solve (dense `MN x MN` stiffness matrix, Cholesky in
/// `(MN)^3 / 3` operations) whose memory or work passes the budgets of
/// [`crate::limits`], before allocating anything.
pub fn check_galerkin_cost(m: usize, n: usize) -> Result<(), Pde4Error> {
    let mn = (m as f64) * (n as f64);
    let value = format!("[{m}, {n}]");
    let what = format!("the Galerkin solve with M x N = {mn} unknowns");
    crate::limits::check_memory("terms", &value, &what, 8.0 * mn * mn)?;
    crate::limits::check_work("terms", &value, &what, mn * mn * mn / 3.0 + 3.0 * mn * mn)?;
    Ok(())
}

pub(crate) fn check_forces(forces: &[Force]) -> Result<(), Pde4Error> {
    if forces.is_empty() {
        return Err(Pde4Error::NoForces);
    }
    forces.iter().try_for_each(Force::validate)
}
