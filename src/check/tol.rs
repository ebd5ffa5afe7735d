//! Named tolerances. Tests and checks use these, never bare literals.

/// Rounding level of a well-conditioned closed form evaluated in f64
/// (relative to the magnitude of the quantities involved).
pub const ROUNDING: f64 = 1e-12;
/// Rounding level after a dense solve or a long sum (relative).
pub const SOLVE: f64 = 1e-9;
/// Adaptive quadrature against a closed form (relative).
pub const QUADRATURE: f64 = 1e-10;
/// Relative jump across a C2 join of patches that were solved separately
/// (each side carries a dense solve's rounding, amplified by the join's
/// conditioning).
pub const JOIN: f64 = 1e-7;
/// A central difference of step about `1e-5` against the exact derivative
/// (truncation `h^2` times the third derivative, rounding `eps / h`).
pub const CENTRAL_DIFFERENCE: f64 = 1e-6;
/// A defect a measurement must see: a broken join, a displaced curve. Far
/// above every rounding tolerance here, so "measured above this" cannot be
/// rounding.
pub const DETECTED: f64 = 1e-3;
/// Agreement with a tabulated value printed to four significant digits.
pub const TABLE_4_DIGITS: f64 = 5e-4;
/// Agreement with classical plate-theory coefficients demanded by the issues
/// (0.5 %).
pub const PLATE_THEORY: f64 = 5e-3;

/// `tol * max(1, scale)`: tolerances grow with the magnitude of the data
/// (NaN for a NaN scale, so a failed computation cannot set its own bound).
pub fn scaled(tol: f64, scale: f64) -> f64 {
    tol * super::Worst::worst(scale.abs(), 1.0)
}
