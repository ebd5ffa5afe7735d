//! The small solver of tutorial chapter 9: a tube between two closed curves
//! whose every line v = const solves the fourth-order ODE S_uuuu = 0 with the
//! position and the u-tangent given at both ends (a cubic Hermite blend).
//! Two deliberately broken copies sit beside it; the harness must tell them
//! apart. (Shared by `examples/09_verify/main.rs` and `tests/it/tutorial.rs`.)

use pdesculpt::curve::Fourier3;
use pdesculpt::jet::Real;
use pdesculpt::surface::{Domain, Surface};

/// Which version of the solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// The cubic Hermite blend, right.
    Correct,
    /// A sign slip in the start tangent's basis function (`- u` for `+ u`).
    SignSlip,
    /// The angle computed in plain f64 (`T::cst(v.value())`): values right,
    /// derivatives in v lost.
    LostJet,
}

/// The tube: curves `c0`, `c1` at u = 0, 1 and u-tangents `t0`, `t1` there,
/// all closed curves of `theta = 2 pi v`.
#[derive(Clone, Debug)]
pub struct HermiteTube {
    pub c0: Fourier3,
    pub c1: Fourier3,
    pub t0: Fourier3,
    pub t1: Fourier3,
    pub variant: Variant,
}

impl Surface for HermiteTube {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        let theta = match self.variant {
            Variant::LostJet => T::cst(std::f64::consts::TAU * v.value()),
            _ => v * std::f64::consts::TAU,
        };
        let (u2, u3) = (u * u, u * u * u);
        let h00 = u3 * 2.0 - u2 * 3.0 + 1.0;
        let h10 = match self.variant {
            Variant::SignSlip => u3 - u2 * 2.0 - u,
            _ => u3 - u2 * 2.0 + u,
        };
        let h01 = u2 * 3.0 - u3 * 2.0;
        let h11 = u3 - u2;
        let (a, b) = (self.c0.eval(theta), self.t0.eval(theta));
        let (c, d) = (self.c1.eval(theta), self.t1.eval(theta));
        std::array::from_fn(|k| a[k] * h00 + b[k] * h10 + c[k] * h01 + d[k] * h11)
    }

    fn domain(&self) -> Domain {
        Domain {
            closed_v: true,
            ..Domain::UNIT
        }
    }
}
