//! Named test surfaces and meshes of the mesh infrastructure (a torus and
//! a reproducible random source), shared by checks, tests and benches.

use super::Mesh;
use crate::surface::{tessellate, Domain, Surface, Tessellation};
use std::f64::consts::PI;

/// A torus with major radius `big` and minor radius `small` about the y
/// axis, closed in both directions.
#[derive(Clone, Copy, Debug)]
pub struct Torus {
    pub big: f64,
    pub small: f64,
}

impl Surface for Torus {
    fn eval<T: crate::jet::Real>(&self, u: T, v: T) -> [T; 3] {
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

/// Deterministic pseudo-random numbers in [0, 1) (xorshift), so checks are
/// reproducible without a dependency.
pub fn lcg(seed: &mut u64) -> f64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// The torus (R = 2, r = 0.5) tessellated on a 2n x n grid.
pub fn torus_mesh(n: usize) -> Mesh {
    tessellate(
        &Torus {
            big: 2.0,
            small: 0.5,
        },
        Tessellation { nu: 2 * n, nv: n },
    )
}
