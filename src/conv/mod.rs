//! SketchCo convolution surfaces from sketched silhouettes (paper 003).
//!
//! Not implemented yet: this module is a placeholder for its issue.

pub mod check;
