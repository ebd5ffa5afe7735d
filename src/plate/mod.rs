//! C1 plate-bending deformation of mesh regions (paper 001).
//!
//! Not implemented yet: this module is a placeholder for its issue.

pub mod check;
