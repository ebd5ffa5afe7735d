//! Generalized elliptic curves (paper 000 eq 16, paper 002 eq 1).
//!
//! Not implemented yet: this module is a placeholder for its issue.

pub mod check;
