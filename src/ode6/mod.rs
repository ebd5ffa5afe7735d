//! C2 continuous sixth-order ODE surfaces (paper 004).
//!
//! Not implemented yet: this module is a placeholder for its issue.

pub mod check;
