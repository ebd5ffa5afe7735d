//! Figures of the pde4 family (none yet).

use crate::common::Figure;

/// The figures of the pde4 family.
pub fn figures() -> Vec<Figure> {
    Vec::new()
}
