//! A property-testing harness for any surface solver (cargo feature
//! `harness`, which brings in `proptest`).
//!
//! Two halves, usable apart:
//!
//! * [`strategies`]: proptest strategies for the inputs of a PDE/ODE surface
//!   solver: closed boundary curves ([`strategies::ring_curve`],
//!   [`strategies::star_curve`]), generalized elliptic cross sections placed
//!   in any plane ([`strategies::gec_section`]), shape parameters of the
//!   kit's three families ([`strategies::pde4_shape`],
//!   [`strategies::pde6_shape`], [`strategies::ode6_shape`]) and sculpting
//!   forces ([`strategies::pde4_force`]); plus [`strategies::config`], a
//!   proptest configuration with a fixed seed (the same cases on every run).
//! * [`properties`]: measurements that take **any** [`crate::surface::Surface`]
//!   and return a number to compare with a tolerance: boundary
//!   interpolation of a curve or of a u-derivative
//!   ([`properties::boundary_gap`]), the residual of a differential operator
//!   written on exact jet derivatives ([`properties::residual`]), the jumps
//!   of derivatives across joins, inside one surface or between two
//!   ([`properties::joins_within`], [`properties::join_between`]), and jet
//!   derivatives against finite differences
//!   ([`properties::derivatives_vs_finite_differences`]). [`properties::within`]
//!   turns a measurement into a proptest result with a readable message.
//!
//! A measurement never asserts: a NaN measurement fails [`properties::within`]
//! (a failed computation is no evidence). The tutorial's last chapter
//! (`docs/tutorial/09_verify.md`) writes a small solver and runs this
//! harness on it and on a deliberately broken copy; `tests/it/harness.rs`
//! runs it on the kit's own families.
//!
//! Use it from another crate with
//! `pdesculpt = { version = "0.1", features = ["harness"] }` (a
//! dev-dependency is enough) and `proptest` as a dev-dependency.

pub mod properties;
pub mod strategies;
