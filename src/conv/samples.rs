//! Named test problems of the convolution family (paper 003): a
//! deterministic random source and random segment cases, shared by checks,
//! tests and benches.

use super::kernel::Segment;

/// Deterministic pseudo-random numbers in [0, 1) (no dependency).
pub struct Lcg(pub u64);

impl Lcg {
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next_f64()
    }
}

/// A random segment and point for the quadrature checks.
pub fn random_case(rng: &mut Lcg) -> (Segment, [f64; 3], f64) {
    let p = [
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
    ];
    let mut q = [
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
        rng.range(-1.0, 1.0),
    ];
    if crate::mesh::dist(p, q) < 0.2 {
        q[0] += 0.5;
    }
    let seg = Segment {
        p,
        q,
        w0: rng.range(0.1, 3.0),
        w1: rng.range(0.1, 3.0),
        lambda: rng.range(0.2, 2.0),
    };
    let r = [
        rng.range(-2.0, 2.0),
        rng.range(-2.0, 2.0),
        rng.range(-2.0, 2.0),
    ];
    (seg, r, rng.range(0.3, 4.0))
}
