//! One parametric-surface trait for every family, and tessellation.
//!
//! A surface is a map $S : [u_0, u_1] \times [v_0, v_1] \to \mathbb{R}^3$,
//! written once generically over [`Real`] so that the same code gives points
//! (`f64`) and exact derivatives of any order (jets). Each direction may be
//! closed (periodic), as the v direction of every PDE patch built from closed
//! cross-section curves is.
//!
//! [`tessellate`] turns any surface into a [`Mesh`](crate::mesh::Mesh); on a
//! closed direction the seam is shared (no duplicated seam vertices, no
//! cracks). [`DynSurface`] is the object-safe face of the trait, used where
//! surfaces of different families are stored together (character assembly).

pub mod check;
mod join;
pub mod samples;
mod tessellate;

pub use join::Joined;
pub use tessellate::{tessellate, tessellate_grid, Tessellation};

use crate::jet::{Jet, Real};

/// Parameter domain and closedness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Domain {
    pub u: (f64, f64),
    pub v: (f64, f64),
    /// `S(u_0, v) = S(u_1, v)` with matching derivatives.
    pub closed_u: bool,
    /// `S(u, v_0) = S(u, v_1)` with matching derivatives.
    pub closed_v: bool,
}

impl Domain {
    /// The unit square, open in both directions.
    pub const UNIT: Domain = Domain {
        u: (0.0, 1.0),
        v: (0.0, 1.0),
        closed_u: false,
        closed_v: false,
    };

    /// Parameter `(u, v)` at fractions `(s, t)` of the domain.
    pub fn at(&self, s: f64, t: f64) -> (f64, f64) {
        (
            self.u.0 + s * (self.u.1 - self.u.0),
            self.v.0 + t * (self.v.1 - self.v.0),
        )
    }
}

/// A parametric surface written generically over the scalar.
pub trait Surface {
    /// The point `S(u, v)`; with jet arguments, all its derivatives.
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3];

    /// Parameter domain and closedness.
    fn domain(&self) -> Domain;

    /// The point at `(u, v)` in `f64`.
    fn point(&self, u: f64, v: f64) -> [f64; 3] {
        self.eval(u, v)
    }

    /// `d^(i+j) S / du^i dv^j` at `(u, v)`, exact to rounding, for
    /// `i, j <= 6`.
    ///
    /// # Panics
    /// If `i > 6` or `j > 6`.
    ///
    /// Evaluated in the smallest jet that holds order `(i, j)` (`Jet<3, 1>`
    /// for `i <= 2, j = 0`, `Jet<1, 3>`, `Jet<3, 3>`, else `Jet<7, 7>`): the
    /// coefficient `(i, j)` of a truncated product or series depends only on
    /// the coefficients `(a, b) <= (i, j)`, summed in the same order in every
    /// ring, so each size gives the bits `Jet<7, 7>` gives (test
    /// `surface_derivative_jet_size_is_bit_identical`) at a fraction of the
    /// work (a `Jet<7, 7>` product is 784 multiplications, a `Jet<3, 1>`
    /// product 6).
    fn derivative(&self, u: f64, v: f64, i: usize, j: usize) -> [f64; 3] {
        macro_rules! at {
            ($u:literal, $v:literal) => {{
                let ju = if $u > 1 {
                    Jet::<$u, $v>::var_u(u)
                } else {
                    Jet::constant(u)
                };
                let jv = if $v > 1 {
                    Jet::<$u, $v>::var_v(v)
                } else {
                    Jet::constant(v)
                };
                let p = self.eval(ju, jv);
                [p[0].deriv(i, j), p[1].deriv(i, j), p[2].deriv(i, j)]
            }};
        }
        match (i, j) {
            (0..=2, 0) => at!(3, 1),
            (0, 1..=2) => at!(1, 3),
            (0..=2, 0..=2) => at!(3, 3),
            _ => at!(7, 7),
        }
    }

    /// Unit normal `S_u x S_v / |S_u x S_v|` (zero where the surface is
    /// degenerate).
    fn normal(&self, u: f64, v: f64) -> [f64; 3] {
        let p = self.eval(Jet::<2, 2>::var_u(u), Jet::<2, 2>::var_v(v));
        let su = [p[0].c[1][0], p[1].c[1][0], p[2].c[1][0]];
        let sv = [p[0].c[0][1], p[1].c[0][1], p[2].c[0][1]];
        normalize(cross(su, sv))
    }

    /// Points on the `nu x nv` grid of parameters `us x vs`, row-major in u
    /// (`index = iu * vs.len() + iv`). Families override this with fast
    /// tensor-product evaluators; the default calls [`Surface::point`].
    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let mut out = Vec::with_capacity(us.len() * vs.len());
        for &u in us {
            for &v in vs {
                out.push(self.point(u, v));
            }
        }
        out
    }
}

/// The object-safe face of [`Surface`]: points, derivatives up to (6, 6),
/// grids. Every `Surface` is a `DynSurface`.
pub trait DynSurface: Send + Sync {
    fn domain(&self) -> Domain;
    fn point(&self, u: f64, v: f64) -> [f64; 3];
    fn derivative(&self, u: f64, v: f64, i: usize, j: usize) -> [f64; 3];
    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]>;
}

impl<S: Surface + Send + Sync> DynSurface for S {
    fn domain(&self) -> Domain {
        Surface::domain(self)
    }
    fn point(&self, u: f64, v: f64) -> [f64; 3] {
        Surface::point(self, u, v)
    }
    fn derivative(&self, u: f64, v: f64, i: usize, j: usize) -> [f64; 3] {
        Surface::derivative(self, u, v, i, j)
    }
    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        Surface::grid(self, us, vs)
    }
}

pub use crate::vec3::{cross, normalize};

/// A surface of revolution about the y axis, `(r(u) cos 2 pi v, u, r(u) sin
/// 2 pi v)` with `r(u) = r0 + r1 sin(pi u)`: closed in v, used by the
/// infrastructure checks and tests as a known shape.
#[derive(Clone, Copy, Debug)]
pub struct Revolution {
    pub r0: f64,
    pub r1: f64,
}

impl Surface for Revolution {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let r = (u * std::f64::consts::PI).sin() * self.r1 + self.r0;
        let a = v * (2.0 * std::f64::consts::PI);
        [r * a.cos(), u, r * a.sin()]
    }
    fn domain(&self) -> Domain {
        Domain {
            closed_v: true,
            ..Domain::UNIT
        }
    }
}
