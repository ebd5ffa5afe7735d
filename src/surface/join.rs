//! Join continuity: one measurement for every composite surface.
//!
//! A chain or grid of patches is C0/C1/C2 across its joins when the
//! derivatives of order 0, 1, 2 across each join agree on both sides.
//! [`Joined::join_jumps`] measures those jumps; checks, the CLI and the
//! figures all call it (no family keeps its own copy).

/// A surface made of pieces that meet at joins.
pub trait Joined {
    /// The measurement: `[c0, c1, c2]` for a chain in one direction, a
    /// per-direction report for a grid.
    type Jumps;

    /// Jumps of the derivatives of order 0, 1, 2 across every join,
    /// maximised over `samples` points along each join (`samples = 0` is
    /// taken as 1: a measurement of no points would report a perfect join).
    fn join_jumps(&self, samples: usize) -> Self::Jumps;
}
