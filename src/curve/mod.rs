//! Curves: closed space curves as Fourier series ([`fourier::Fourier3`]),
//! and generalized elliptic curves ([`gec`]), the cross sections every
//! PDE/ODE family interpolates.

pub mod fourier;
pub mod gec;

pub use fourier::Fourier3;
