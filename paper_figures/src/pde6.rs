//! Figures of the pde6 family (none yet).

use crate::common::Figure;

/// The figures of the pde6 family.
pub fn figures() -> Vec<Figure> {
    Vec::new()
}
