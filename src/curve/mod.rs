//! Curves: generalized elliptic curves (the cross sections every PDE/ODE
//! family interpolates).

pub mod gec;
