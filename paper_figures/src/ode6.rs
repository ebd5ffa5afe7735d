//! Figures of the ode6 family (none yet).

use crate::common::Figure;

/// The figures of the ode6 family.
pub fn figures() -> Vec<Figure> {
    Vec::new()
}
