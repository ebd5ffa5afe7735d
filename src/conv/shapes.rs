//! Example silhouette strokes (deterministic, densely and unevenly sampled
//! like mouse input) for tests, figures and the bundled model files.

use std::f64::consts::TAU;

/// Uneven sampling parameter: `t` in [0, 1) mapped with a small wobble so
/// spacing varies like hand-drawn input.
fn uneven(i: usize, n: usize) -> f64 {
    let t = i as f64 / n as f64;
    t + 0.02 * (TAU * 3.0 * t).sin() / 3.0
}

/// An ellipse with semi-axes `a`, `b` sampled at `n` points.
pub fn ellipse(a: f64, b: f64, n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let th = TAU * uneven(i, n);
            [a * th.cos(), b * th.sin()]
        })
        .collect()
}

/// A star with `arms` rounded arms between radii `r_in` and `r_out`.
pub fn star(arms: usize, r_in: f64, r_out: f64, n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let th = TAU * uneven(i, n);
            let c = 0.5 + 0.5 * (arms as f64 * th).cos();
            let r = r_in + (r_out - r_in) * c.powf(1.5);
            [r * th.cos(), r * th.sin()]
        })
        .collect()
}

/// A folding stroke: a thick "C" (an annular sector of radii `r_mid -
/// half_width`, `r_mid + half_width` over `sweep` radians with round caps).
pub fn folding(r_mid: f64, half_width: f64, sweep: f64, n: usize) -> Vec<[f64; 2]> {
    let mut pts = Vec::with_capacity(n);
    let arc = n * 2 / 5;
    let cap = (n - 2 * arc) / 2;
    let a0 = -0.5 * sweep;
    let a1 = 0.5 * sweep;
    let on = |r: f64, a: f64| [r * a.cos(), r * a.sin()];
    for i in 0..arc {
        pts.push(on(r_mid + half_width, a0 + sweep * uneven(i, arc)));
    }
    for i in 0..cap {
        // round cap at a1, from the outer to the inner side
        let c = on(r_mid, a1);
        let phi = a1 + std::f64::consts::PI * i as f64 / cap as f64;
        pts.push([c[0] + half_width * phi.cos(), c[1] + half_width * phi.sin()]);
    }
    for i in 0..arc {
        pts.push(on(r_mid - half_width, a1 - sweep * uneven(i, arc)));
    }
    for i in 0..cap {
        let c = on(r_mid, a0);
        let phi = a0 + std::f64::consts::PI + std::f64::consts::PI * i as f64 / cap as f64;
        pts.push([c[0] + half_width * phi.cos(), c[1] + half_width * phi.sin()]);
    }
    pts
}

/// A gingerbread-like figure (head, arms, legs) as one silhouette: a
/// radial function with five lobes of different sizes.
pub fn figure(n: usize) -> Vec<[f64; 2]> {
    // lobes: (angle, width, extra radius)
    let lobes = [
        (0.25 * TAU, 0.35, 0.55), // head
        (0.05 * TAU, 0.22, 0.75), // right arm
        (0.45 * TAU, 0.22, 0.75), // left arm
        (0.68 * TAU, 0.25, 0.95), // left leg
        (0.82 * TAU, 0.25, 0.95), // right leg
    ];
    (0..n)
        .map(|i| {
            let th = TAU * uneven(i, n);
            let mut r = 0.55;
            for (a, w, e) in lobes {
                let mut d = (th - a).rem_euclid(TAU);
                if d > 0.5 * TAU {
                    d -= TAU;
                }
                r += e * (-(d / w).powi(2) * 2.0).exp();
            }
            [r * th.cos(), r * th.sin()]
        })
        .collect()
}

/// A self-intersecting figure eight (must be rejected).
pub fn figure_eight(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let th = TAU * i as f64 / n as f64;
            [th.sin(), (2.0 * th).sin() * 0.5]
        })
        .collect()
}
