//! The feature's region in its view: a closed polygon, star-shaped about a
//! centre, represented by a Fourier series of its polar radius `R(phi)`.

use super::SasmError;
use std::f64::consts::PI;

/// Fourier harmonics of the polar radius.
pub const HARMONICS: usize = 16;
/// Uniform angle samples of the polygon's radius for the fit.
pub const FIT_SAMPLES: usize = 512;
/// Largest accepted deviation of the fitted boundary from the stroke,
/// relative to the mean radius.
pub const MAX_FIT_DEVIATION: f64 = 0.1;

/// A star-shaped region with a smooth boundary.
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    pub centre: [f64; 2],
    pub a0: f64,
    pub cos: Vec<f64>,
    pub sin: Vec<f64>,
    /// The stroke polygon (counter-clockwise about the centre).
    pub polygon: Vec<[f64; 2]>,
    /// Largest radial distance of the stroke's vertices from the fitted
    /// boundary, relative to the mean radius `a0`.
    pub fit_deviation: f64,
}

/// Polar radius of `poly` about `c` at every polygon vertex, with the
/// polygon made counter-clockwise about `c`; errors when a ray from `c`
/// would cross it more than once.
fn polar(poly: &[[f64; 2]], c: [f64; 2]) -> Result<(Vec<[f64; 2]>, Vec<(f64, f64)>), SasmError> {
    let ang = |p: [f64; 2]| (p[1] - c[1]).atan2(p[0] - c[0]);
    let n = poly.len();
    let mut total = 0.0;
    let mut steps = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let mut d = ang(b) - ang(a);
        while d > PI {
            d -= 2.0 * PI;
        }
        while d < -PI {
            d += 2.0 * PI;
        }
        steps.push(d);
        total += d;
    }
    let bad = |m: String| SasmError::NotStarShaped {
        centre: c,
        message: m,
    };
    if (total.abs() - 2.0 * PI).abs() > 1e-6 {
        return Err(bad("the centre is outside the curve".into()));
    }
    if total < 0.0 {
        let r: Vec<[f64; 2]> = poly.iter().rev().copied().collect();
        return polar(&r, c);
    }
    let p: Vec<[f64; 2]> = poly.to_vec();
    if let Some(i) = steps.iter().position(|&d| !(d > 0.0)) {
        return Err(bad(format!(
            "the ray from the centre through stroke point {i} crosses the curve more than once"
        )));
    }
    let rs = p
        .iter()
        .map(|q| (ang(*q), (q[0] - c[0]).hypot(q[1] - c[1])))
        .collect();
    Ok((p, rs))
}

/// Radius of the polygon along angle `phi` (ray-segment intersection).
fn ray_radius(p: &[[f64; 2]], c: [f64; 2], phi: f64) -> f64 {
    let d = [phi.cos(), phi.sin()];
    let n = p.len();
    let mut best = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let e = [b[0] - a[0], b[1] - a[1]];
        let w = [a[0] - c[0], a[1] - c[1]];
        let den = d[0] * (-e[1]) - d[1] * (-e[0]);
        if den == 0.0 {
            continue;
        }
        // c + t d = a + s e
        let t = (w[0] * (-e[1]) - w[1] * (-e[0])) / den;
        let s = (d[0] * w[1] - d[1] * w[0]) / den;
        if (-1e-12..=1.0 + 1e-12).contains(&s) && t > 0.0 {
            best = best.min(t);
        }
    }
    best
}

impl Region {
    /// Fits the region of a closed polygon about `centre`.
    pub fn new(poly: &[[f64; 2]], centre: [f64; 2]) -> Result<Region, SasmError> {
        let (p, rs) = polar(poly, centre)?;
        let m = FIT_SAMPLES;
        let samples: Vec<f64> = (0..m)
            .map(|k| ray_radius(&p, centre, 2.0 * PI * k as f64 / m as f64))
            .collect();
        if samples.iter().any(|r| !r.is_finite()) {
            return Err(SasmError::NotStarShaped {
                centre,
                message: "a ray from the centre misses the curve".into(),
            });
        }
        let a0 = samples.iter().sum::<f64>() / m as f64;
        let mut cos = Vec::with_capacity(HARMONICS);
        let mut sin = Vec::with_capacity(HARMONICS);
        for k in 1..=HARMONICS {
            let (mut a, mut b) = (0.0, 0.0);
            for (i, r) in samples.iter().enumerate() {
                let phi = 2.0 * PI * i as f64 / m as f64;
                a += r * (k as f64 * phi).cos();
                b += r * (k as f64 * phi).sin();
            }
            cos.push(2.0 * a / m as f64);
            sin.push(2.0 * b / m as f64);
        }
        let mut reg = Region {
            centre,
            a0,
            cos,
            sin,
            polygon: p,
            fit_deviation: 0.0,
        };
        reg.fit_deviation = rs
            .iter()
            .map(|&(phi, r)| (reg.radius(phi) - r).abs() / a0)
            .fold(0.0, f64::max);
        if !(reg.fit_deviation <= MAX_FIT_DEVIATION) {
            return Err(SasmError::NotStarShaped {
                centre,
                message: format!(
                    "the curve is too irregular for a {HARMONICS}-harmonic polar fit (deviation {:.3} of its mean radius, limit {MAX_FIT_DEVIATION})",
                    reg.fit_deviation
                ),
            });
        }
        let rmin = (0..m)
            .map(|k| reg.radius(2.0 * PI * k as f64 / m as f64))
            .fold(f64::INFINITY, f64::min);
        if !(rmin > 0.05 * a0) {
            return Err(SasmError::NotStarShaped {
                centre,
                message: "the centre is too close to the curve".into(),
            });
        }
        Ok(reg)
    }

    /// Fitted polar radius at angle `phi`.
    pub fn radius(&self, phi: f64) -> f64 {
        let mut r = self.a0;
        for k in 0..self.cos.len() {
            let a = (k + 1) as f64 * phi;
            r += self.cos[k] * a.cos() + self.sin[k] * a.sin();
        }
        r
    }

    /// `(rho, phi)`: `rho = r / R(phi)` (1 on the boundary).
    pub fn polar(&self, q: [f64; 2]) -> (f64, f64) {
        let (dx, dy) = (q[0] - self.centre[0], q[1] - self.centre[1]);
        let phi = dy.atan2(dx);
        (dx.hypot(dy) / self.radius(phi), phi)
    }

    /// The view-plane point at `(rho, phi)`.
    pub fn at(&self, rho: f64, phi: f64) -> [f64; 2] {
        let r = rho * self.radius(phi);
        [
            self.centre[0] + r * phi.cos(),
            self.centre[1] + r * phi.sin(),
        ]
    }

    /// Largest radius (for bounding).
    pub fn max_radius(&self) -> f64 {
        (0..FIT_SAMPLES)
            .map(|k| self.radius(2.0 * PI * k as f64 / FIT_SAMPLES as f64))
            .fold(0.0, f64::max)
    }
}

/// Area centroid of a polygon.
pub fn centroid(p: &[[f64; 2]]) -> [f64; 2] {
    let (mut a, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..p.len() {
        let (u, v) = (p[i], p[(i + 1) % p.len()]);
        let w = u[0] * v[1] - v[0] * u[1];
        a += w;
        cx += (u[0] + v[0]) * w;
        cy += (u[1] + v[1]) * w;
    }
    [cx / (3.0 * a), cy / (3.0 * a)]
}
