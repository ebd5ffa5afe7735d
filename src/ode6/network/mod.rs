//! Curve networks of 3- and 4-sided ODE patches, C2 across every edge
//! (paper 004 secs 5, 6.2-6.3, Figs 6-8).
//!
//! A network document ([`doc`]) lists nodes, curves between nodes and
//! patches bounded by three or four curves. Every patch is the ODE surface
//! of eq 19, $S(u,v) = \sum_{j=1}^6 g_j(u)\,c_j(v)$, between its `u = 0`
//! and `u = 1` sides; its `v = 0` and `v = 1` sides are iso-parametric
//! lines of the ODE through the corners. Continuity:
//!
//! * **across a u-edge** (sec 5.1, eqs 23-25) the two patches read the same
//!   position curve and the same first and second cross-derivative curves
//!   (the document's, or the neighbouring sections' three-point
//!   derivatives, [`solve`]), so $S$, $S_u$, $S_{uu}$ agree for any shape
//!   parameters, and with them every $v$-derivative of those;
//! * **across a v-edge** (sec 5.2, eq 26) $S^{(i)}(u,1) = \hat S^{(i)}(u,0)$
//!   needs $g_k = \hat g_k$ (equal shape parameters along a v-strip; the
//!   document is refused otherwise) and constraint curves that are C2
//!   across the shared corners, which [`lines`] makes so by splining the
//!   `u`-sides of a v-strip as one curve;
//! * a **3-sided patch** is a 4-sided one whose `u = 0` side is collapsed
//!   to the apex: $c_1(v) = $ apex, and $c_2, c_3$ the one-sided
//!   three-point derivatives of the apex, the `u = 1` side and the next
//!   section. $S(0, v)$ is the apex for every $v$ (since $g_j(0) =
//!   \delta_{j1}$), $S(1, v)$ the `u = 1` side, and $S_u(0, v) = c_2(v)$
//!   turns with $v$ like the radius of a polar parameterisation. The two
//!   other sides are ODE lines from the apex to the ends of the `u = 1`
//!   side; how far they pass from the document's curves is measured
//!   ([`report`]), like the `v`-sides of a 4-sided patch.
//!
//! What is not C2: a network whose strips do not line up (a line ends,
//! [`lines`]) stays C0 there and the report gives the jumps; the surface
//! at an apex is C2 along every edge but not a regular parameterisation
//! at the apex point itself.

pub mod doc;
pub mod lines;
pub mod report;
pub mod samples;
pub mod solve;
pub mod topology;

pub use doc::{Apex, Cross, CurveDoc, Derivatives, NetworkDoc, PatchDoc, NETWORK_VERSION};
pub use report::{EdgeReport, NetworkReport};
pub use solve::Network;
pub use topology::{EdgeKind, Role, Topology};

use crate::ode6::Ode6Error;

/// Errors of a curve-network document or its solution.
#[derive(Debug, thiserror::Error)]
pub enum NetworkError {
    #[error("network JSON, line {line}: {message}")]
    Json { line: usize, message: String },
    #[error("network version {found} is not supported (this build reads version {supported})")]
    Version { found: u32, supported: u32 },
    #[error("the network has no patches")]
    Empty,
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
    #[error("{what} = {value:e} is beyond {max:e} in magnitude (the model coordinate bound)")]
    Coordinate { what: String, value: f64, max: f64 },
    #[error("{what} is not finite")]
    NonFinite { what: String },
    #[error("curve {curve} names node {node}, but there are {nodes} nodes")]
    NodeIndex {
        curve: usize,
        node: usize,
        nodes: usize,
    },
    #[error("patch {patch} names curve {curve}, but there are {curves} curves")]
    CurveIndex {
        patch: usize,
        curve: usize,
        curves: usize,
    },
    #[error("curve {curve} has {got} points; a curve needs at least its two end points")]
    TooFewPoints { curve: usize, got: usize },
    #[error(
        "curve {curve} does not meet its node {node}: its {end} point is {distance:.3e} away \
         (tolerance {tolerance:.3e})"
    )]
    CurveOffNode {
        curve: usize,
        end: &'static str,
        node: usize,
        distance: f64,
        tolerance: f64,
    },
    #[error(
        "curve {curve}: params must be finite, one per point, strictly increasing from 0 to 1"
    )]
    CurveParams { curve: usize },
    #[error("curve {curve} has two consecutive equal points (no chord-length parameter)")]
    DegenerateCurve { curve: usize },
    #[error("patch {patch} has {sides} sides; a patch has 3 or 4")]
    Sides { patch: usize, sides: usize },
    #[error(
        "the curves of patch {patch} do not close a loop: each must start at the node where the \
         previous one ends (in either direction) and the last end where the first starts"
    )]
    OpenBoundary { patch: usize },
    #[error("patch {patch}: invalid shape parameters: {source}")]
    Params { patch: usize, source: Ode6Error },
    #[error("patch {patch} is 3-sided with its apex at {side}: that side takes no derivatives")]
    ApexDerivatives { patch: usize, side: &'static str },
    #[error("patch {patch} has four sides: \"apex\" applies to 3-sided patches only")]
    ApexOnQuad { patch: usize },
    #[error(
        "patch {patch} derivatives.{side}.{what} has {got} values; its curve has {expected} points"
    )]
    CrossLength {
        patch: usize,
        side: &'static str,
        what: &'static str,
        got: usize,
        expected: usize,
    },
    #[error(
        "curve {curve} joins patches {patches:?} as {roles:?}: {why}; \
         C2 needs U1 against U0 (or V1 against V0) with the other parameter running the same way"
    )]
    Join {
        curve: usize,
        patches: [usize; 2],
        roles: [Role; 2],
        why: &'static str,
    },
    #[error(
        "curve {curve} is a v-edge between patches {patches:?} with different shape parameters; \
         eq 26 makes a v-join C2 only with equal parameters"
    )]
    VParams { curve: usize, patches: [usize; 2] },
    #[error("curve {curve} is used by patches {patches:?}; a curve bounds at most two patches")]
    Shared { curve: usize, patches: Vec<usize> },
    #[error(
        "patch {patch} gives order-{order} derivatives on curve {curve} that differ from its \
         neighbour's by {difference:.3e}: the join could not be C{order}"
    )]
    CrossDisagree {
        curve: usize,
        patch: usize,
        order: usize,
        difference: f64,
    },
    #[error("patch {patch}: {source}")]
    Solve { patch: usize, source: Ode6Error },
    #[error("patch {patch} is in no u-strip (internal error)")]
    Unplaced { patch: usize },
}
