//! Named test curves of the GEC family, shared by checks, tests and other
//! families' samples.

use super::{Frame, Gec};

/// A tilted, non-axis-aligned GEC for round trips.
pub fn tilted_gec() -> Gec {
    let frame = Frame {
        origin: [0.3, 8.0, -0.2],
        e1: [0.8, 0.0, -0.6],
        e2: [0.36, 0.8, 0.48],
    };
    Gec {
        frame,
        centre: [0.1, -0.05],
        x: vec![[1.2, 0.1], [0.1, -0.05], [0.02, 0.03]],
        y: vec![[0.8, 0.05], [-0.04, 0.06], [0.01, -0.02]],
    }
}
