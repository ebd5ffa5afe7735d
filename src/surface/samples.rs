//! Named test surfaces of the surface layer, shared by checks, tests and
//! benches.

use super::{Domain, Surface};
use crate::jet::Real;
use std::f64::consts::PI;

/// A torus with major radius `big` and minor radius `small` about the y
/// axis, closed in both directions (`mesh::samples::torus_mesh` samples the
/// same torus).
#[derive(Clone, Copy, Debug)]
pub struct Torus {
    pub big: f64,
    pub small: f64,
}

impl Surface for Torus {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let (a, b) = (u * (2.0 * PI), v * (2.0 * PI));
        let r = b.cos() * self.small + self.big;
        [r * a.cos(), b.sin() * self.small, -(r * a.sin())]
    }
    fn domain(&self) -> Domain {
        Domain {
            closed_u: true,
            closed_v: true,
            ..Domain::UNIT
        }
    }
}
