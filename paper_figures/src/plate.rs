//! Figures of the plate family (none yet).

use crate::common::Figure;

/// The figures of the plate family.
pub fn figures() -> Vec<Figure> {
    Vec::new()
}
