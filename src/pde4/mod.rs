//! Fourth-order PDE deformation surfaces with sculpting forces (paper 000 sec 3.1).
//!
//! Not implemented yet: this module is a placeholder for its issue.

pub mod check;
