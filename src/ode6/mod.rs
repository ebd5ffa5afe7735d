//! C2 continuous sixth-order ODE surfaces (paper 004: Bian, Maguire, Kokke,
//! You, Zhang, "Efficient C2 continuous surface creation technique based on
//! ordinary differential equation", Symmetry 12 (2020) 38).
//!
//! Every iso-parametric line $S(u, v_i)$ of a patch solves (eq 2)
//! $$ \rho\, \frac{d^6 S}{du^6} + \eta\, \frac{d^4 S}{du^4} + \lambda\, \frac{d^2 S}{du^2} = F(u), \qquad u \in [0, 1], $$
//! subject to the six constraints of eq 1:
//! $S(0,v) = c_1(v)$, $S_u(0,v) = c_2(v)$, $S_{uu}(0,v) = c_3(v)$,
//! $S(1,v) = c_4(v)$, $S_u(1,v) = c_5(v)$, $S_{uu}(1,v) = c_6(v)$.
//! The complementary solution (eqs 8-22) is the tensor product of eq 19,
//! $$ S(u,v) = \sum_{j=1}^{6} g_j(u)\, c_j(v), $$
//! where $g_j$ meets the unit constraint $j$ and zero for the others.
//!
//! * [`basis`]: $g_1..g_6$ for **every** parameter case (the paper solves
//!   only $4\rho\lambda/\eta^2 < 1$ with $\rho, \eta, \lambda > 0$), with a
//!   named error for singular boundary systems and the $\rho = 0$
//!   degeneration.
//! * [`paper`]: the printed constants of eqs 14-15 and 20-22, literally,
//!   for the paper-literal checks.
//! * [`boundary`]: approach 1 ($c_2 = w_1 c_1$, ...) and approach 2 (four
//!   control curves, the difference formulas of eqs 3-7, printed and
//!   corrected); boundary curves as [`crate::curve::Fourier3`] or sampled
//!   polylines.
//! * [`force`]: particular solutions for polynomial and sine sculpting forces
//!   $F(u)$ (left to future work by the paper).
//! * [`spline`]: the natural cubic spline of open polyline curves and of
//!   the loft baseline.
//! * [`spec`]: the JSON surface spec of `pdesculpt ode6 surface` and the
//!   one-line evaluation of `ode6 eval`.
//! * [`surface`]: [`Ode6Surface`] (the [`crate::surface::Surface`] impl, fast
//!   tensor-product grids), chains of patches in $u$ (eqs 23-25), splits in
//!   $v$ and [`Grid`]s of patches C2 in both directions (eq 26).

pub mod basis;
pub mod boundary;
pub mod check;
pub mod force;
pub mod network;
pub mod paper;
pub mod samples;
pub mod spec;
pub mod spline;
pub mod surface;

pub use basis::{Basis, Params, RootCase};
pub use boundary::{Approach2, BoundaryCurves, Curve, DiffFormula};
pub use force::Force;
pub use surface::{Chain, Grid, GridJumps, Ode6Surface, VSplit};

/// Errors of the ode6 family.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Ode6Error {
    #[error("shape parameter {name} is not finite ({value})")]
    NonFinite { name: &'static str, value: f64 },
    #[error("rho = eta = lambda = 0: the ODE is empty and determines nothing")]
    AllZero,
    #[error(
        "rho = 0: the ODE is of fourth order (eta S'''' + lambda S'' = 0, eta = {eta}, lambda = {lambda}) \
         and its four constants cannot meet the six constraints of eq 1; \
         use Basis::reduced to impose positions and tangents only"
    )]
    RhoZero { eta: f64, lambda: f64 },
    #[error(
        "singular boundary system for {case} (rho = {rho}, eta = {eta}, lambda = {lambda}, \
         reciprocal condition {rcond:.3e}): no unique solution meets the six constraints"
    )]
    Singular {
        case: String,
        rcond: f64,
        rho: f64,
        eta: f64,
        lambda: f64,
    },
    #[error(
        "sine force resonates: kappa^2 = {kappa2} is a double root of rho q^2 - eta q + lambda = 0, or kappa = 0 (symbol {symbol:.3e}); \
         no particular solution of the form u cos(kappa u + phase)"
    )]
    Resonance { kappa2: f64, symbol: f64 },
    #[error("{what} is not finite")]
    NotFinite { what: &'static str },
    #[error("{what} {value} is not finite")]
    NonFiniteValue { what: &'static str, value: f64 },
    #[error("a natural spline needs as many values as knots, at least 2 (got {knots} knots, {values} values)")]
    SplineSize { knots: usize, values: usize },
    #[error("spline knots must increase strictly: knot {index} = {knot} follows {previous}")]
    KnotsNotIncreasing {
        index: usize,
        previous: f64,
        knot: f64,
    },
    #[error("approach 1 coefficients not finite: {weights:?}")]
    NonFiniteWeights { weights: [f64; 4] },
    #[error("a {} polyline needs at least {min} vertices (got {got})", if *closed { "closed" } else { "open" })]
    TooFewVertices {
        closed: bool,
        min: usize,
        got: usize,
    },
    #[error("no boundary curves")]
    NoCurves,
    #[error("boundary curves mix closed and open curves")]
    MixedClosure,
    #[error(
        "control positions need 0 < u2 < u3 < 1 and 0 < u5 < u6 < 1 \
         (got u2 = {u2}, u3 = {u3}, u5 = {u5}, u6 = {u6})"
    )]
    ControlPositions { u2: f64, u3: f64, u5: f64, u6: f64 },
    #[error("v range must satisfy 0 <= v0 < v1 <= 1 (got {v0}, {v1})")]
    VRange { v0: f64, v1: f64 },
    #[error(
        "a chain of n patches needs n + 1 >= 2 sections (got {sections} sections, {params} parameter sets)"
    )]
    ChainShape { sections: usize, params: usize },
    #[error(
        "a grid needs n + 1 >= 2 sections for n parameter sets and >= 2 knots in v \
         (got {sections} sections, {params} parameter sets, {knots} knots)"
    )]
    GridShape {
        sections: usize,
        params: usize,
        knots: usize,
    },
    #[error("every section and constraint needs the same number of v-knots")]
    UnequalKnots,
    #[error(
        "case {case} does not solve eq 8 for rho = {rho}, eta = {eta}, lambda = {lambda} \
         (relative residual {residual:.2e})"
    )]
    WrongCase {
        case: String,
        rho: f64,
        eta: f64,
        lambda: f64,
        residual: f64,
    },
    #[error("Basis::reduced needs rho = 0 (got rho = {rho})")]
    ReducedNeedsRhoZero { rho: f64 },
    #[error("sine force kappa = {kappa} overflows the symbol")]
    SymbolOverflow { kappa: f64 },
    #[error("nu (intervals in u) must be in 1..={max} and nv in 3..={max} (got {nu}, {nv})")]
    Intervals { nu: usize, nv: usize, max: usize },
    #[error("no parameter value u to evaluate")]
    NoParameterValues,
    #[error(
        "S(u = {u}) is not finite in double precision for rho {rho}, eta {eta}, lambda {lambda} \
         and these constraints (scale the boundary values or the parameters down)"
    )]
    LineOverflow {
        u: f64,
        rho: f64,
        eta: f64,
        lambda: f64,
    },
    #[error("{what} = {value} must lie in {range}")]
    OutOfRange {
        what: &'static str,
        value: f64,
        range: &'static str,
    },
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
    #[error("invalid gec curve: {0}")]
    Gec(#[from] crate::curve::gec::GecError),
}
