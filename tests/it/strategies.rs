//! The proptest strategies and the fixed-seed configuration of every
//! property test: the public harness (`pdesculpt::harness::strategies`,
//! feature `harness`, on for the tests through the dev-dependency), named
//! here so that the tests keep `crate::strategies::...`.

#[allow(unused_imports)]
pub use pdesculpt::harness::strategies::*;
