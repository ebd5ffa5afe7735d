//! Named test problems of the pde6 family (paper 002): synthetic cross
//! sections and the three signs of a, shared by checks, tests, benches and
//! figures.

use super::Section;
use crate::curve::Fourier3;

/// The representative a of each sign.
pub const SIGNS: [(&str, f64); 3] = [("a_neg", -0.5), ("a_zero", 0.0), ("a_pos", 0.8)];

/// Deterministic test sections: `m` body-like cross sections with `n`
/// harmonics at u = 0, 1, ..., m-1 (z = 0.9 u + wobble, so z is non-uniform).
pub fn synthetic_sections(m: usize, n: usize) -> Vec<Section> {
    (0..m)
        .map(|i| {
            let t = i as f64;
            let r = 1.0 + 0.3 * (0.7 * t).sin();
            let mut cos = vec![[0.0; 3]; n];
            let mut sin = vec![[0.0; 3]; n];
            if n > 0 {
                cos[0] = [r, 0.0, 0.0];
                sin[0] = [0.0, 0.8 * r + 0.1 * (1.3 * t).cos(), 0.0];
            }
            for h in 2..=n {
                let s = 0.15 / (h * h) as f64;
                cos[h - 1] = [s * (t + h as f64).cos(), s * (0.5 * t).sin(), 0.0];
                sin[h - 1] = [
                    s * (0.3 * t * h as f64).sin(),
                    s * (t - h as f64).cos(),
                    0.0,
                ];
            }
            Section {
                u: t,
                curve: Fourier3 {
                    c0: [
                        0.1 * (0.9 * t).sin(),
                        0.05 * t,
                        0.9 * t + 0.2 * (t * 1.7).sin(),
                    ],
                    cos,
                    sin,
                },
            }
        })
        .collect()
}

/// The method-2 chain through 12 synthetic sections (first patch on sections
/// 4-9) for the shape parameter `a`.
pub fn chain(a: f64) -> Result<super::Chain, super::Pde6Error> {
    super::Chain::method2(a, &synthetic_sections(12, 6), 3)
}
