//! Figures of the conv family (none yet).

use crate::common::Figure;

/// The figures of the conv family.
pub fn figures() -> Vec<Figure> {
    Vec::new()
}
