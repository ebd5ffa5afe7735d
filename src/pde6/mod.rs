//! C2 continuous sixth-order PDE patches (paper 002).
//!
//! Not implemented yet: this module is a placeholder for its issue.

pub mod check;
