//! Figures of the gec family (none yet).

use crate::common::Figure;

/// The figures of the gec family.
pub fn figures() -> Vec<Figure> {
    Vec::new()
}
