//! Consistent parameterisation of body cross sections, and the smoothness
//! measures that show why it matters.
//!
//! The PDE chain interpolates the sections harmonic by harmonic, so the point
//! $\mathbf{C}_i(\theta)$ of one section is joined to $\mathbf{C}_{i+1}(\theta)$
//! of the next. If the angle $\theta$ lands on different places of
//! neighbouring sections (a different start point, or a different speed along
//! the curve), the surface twists between them and the reconstruction shows
//! diagonal ripples although every section is fitted well.
//!
//! The slicer starts each loop at an arbitrary vertex; the GEC fit's
//! chord-length rule gives the first vertex its polar angle $\varphi_0$ and
//! runs on in arc length. On a non-circular section (torso about 2:1) the
//! point at $\theta = 0$ then depends on where the loop happened to start.
//!
//! [`Sampling::Anchored`] fixes the correspondence: $K$ rays from the area
//! centroid at the polar angles $\varphi_k = \varphi_\mathrm{start} + 2\pi k/K$
//! (anchor 0 in +z, the front) cut the section at its outermost crossing;
//! anchor $k$ at arc length $s_k$ from anchor 0 gets $\theta_k = 2\pi k / K$
//! at the blended arc length $p\, s_k + (1 - p)\, L \theta_k / 2\pi$ (pull
//! $p$; $p = 1$ pins the anchors, $p = 0$ is plain arc length from anchor 0),
//! and between anchors $\theta$ is proportional to the arc length. Pinning
//! fully distorts the speed on irregular sections (a ray catching an ear or
//! a shoulder): on the body $p = 0.75$ gave the smoothest surfaces with
//! the worst section fit error halved against $p = 1$. The section is resampled at $M$ uniform
//! $\theta_j = 2\pi j / M$ (counter-clockwise about +y) and the GEC is the
//! truncated DFT of the samples (the least-squares fit at these angles).
//!
//! Measures: [`angular_slip`] (mean polar-angle difference of $\mathbf{C}_i(\theta)$
//! and $\mathbf{C}_{i+1}(\theta)$ about their centres), [`start_angle`] (polar
//! angle of $\mathbf{C}_i(0)$) and [`Roughness`] of the tessellated surface
//! (mean second difference of the unit normal along u and along v on a fixed
//! grid: geometric, independent of the parameterisation of the result).

use super::{Chain, Pde6Error};
use crate::curve::gec::fit::{dft_coefficients, polygon_area_centroid, Param};
use crate::curve::gec::{Frame, Gec};
use crate::curve::Fourier3;
use crate::mesh::{add, norm, scale, sub};
use crate::surface::{cross, normalize, Surface};
use std::f64::consts::PI;

/// How a section polyline gets its angle theta.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sampling {
    /// The GEC fit's own rule (start at the first sliced vertex).
    Gec(Param),
    /// `anchors` rays from the centroid, arc length between them, resampled
    /// at `samples` uniform angles.
    /// `pull` in [0, 1]: 1 puts anchor k exactly at theta = 2 pi k / K, 0 is
    /// the plain arc length from anchor 0; in between the arc-length
    /// positions of the anchors are blended.
    Anchored {
        anchors: usize,
        samples: usize,
        pull: f64,
    },
}

/// Polar angle (in the section frame: e1 = +x, e2 = -z) of anchor 0: +z.
pub const START_ANGLE: f64 = -PI / 2.0;

/// The section frame at height y: e1 = +x, e2 = -z, so counter-clockwise
/// in the frame is counter-clockwise seen from +y.
pub fn section_frame(y: f64) -> Result<Frame, Pde6Error> {
    Ok(Frame::new(
        [0.0, y, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 0.0, -1.0],
    )?)
}

fn wrap(a: f64) -> f64 {
    (a + PI).rem_euclid(2.0 * PI) - PI
}

/// Outermost crossing of the ray `c + t (cos phi, sin phi)`, t > 0, with the
/// closed polygon `p`: (segment index, fraction along it, t).
fn ray_hit(p: &[[f64; 2]], c: [f64; 2], phi: f64) -> Option<(usize, f64, f64)> {
    let d = [phi.cos(), phi.sin()];
    let n = p.len();
    let mut best: Option<(usize, f64, f64)> = None;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let e = [b[0] - a[0], b[1] - a[1]];
        let den = d[0] * e[1] - d[1] * e[0];
        if den.abs() <= f64::EPSILON * (e[0].abs() + e[1].abs()) {
            continue;
        }
        let w = [a[0] - c[0], a[1] - c[1]];
        let t = (w[0] * e[1] - w[1] * e[0]) / den;
        let s = (w[0] * d[1] - w[1] * d[0]) / den;
        if t > 0.0 && (0.0..1.0).contains(&s) && best.is_none_or(|b| t > b.2) {
            best = Some((i, s, t));
        }
    }
    best
}

/// Resamples a closed polygon (plane coordinates, either orientation) at
/// `samples` uniform angles under the anchored rule (see the module doc).
pub fn anchored_samples(
    points: &[[f64; 2]],
    anchors: usize,
    samples: usize,
    pull: f64,
) -> Result<Vec<[f64; 2]>, Pde6Error> {
    if !(pull.is_finite() && (0.0..=1.0).contains(&pull)) {
        return Err(Pde6Error::Pull(pull));
    }
    if points.len() < 3 || anchors == 0 || samples < 3 {
        return Err(Pde6Error::SamplingCounts {
            points: points.len(),
            anchors,
            samples,
        });
    }
    let (area, c) = polygon_area_centroid(points);
    if area.is_nan() || area == 0.0 {
        return Err(Pde6Error::DegenerateSection("the section encloses no area"));
    }
    let mut p = points.to_vec();
    if area < 0.0 {
        p.reverse();
    }
    let n = p.len();
    // cumulative arc length at each vertex
    let mut cum = Vec::with_capacity(n + 1);
    cum.push(0.0);
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        cum.push(cum[i] + (b[0] - a[0]).hypot(b[1] - a[1]));
    }
    let total = cum[n];
    if !(total.is_finite() && total > 0.0) {
        return Err(Pde6Error::DegenerateSection("the section has no length"));
    }
    let at = |(i, f, _): (usize, f64, f64)| cum[i] + f * (cum[i + 1] - cum[i]);
    let first = ray_hit(&p, c, START_ANGLE)
        .ok_or(Pde6Error::DegenerateSection("no crossing of the start ray"))?;
    let s0 = at(first);
    // knots (arc length from anchor 0, theta), kept strictly increasing
    let mut knots = vec![(0.0, 0.0)];
    for k in 1..anchors {
        let phi = START_ANGLE + 2.0 * PI * k as f64 / anchors as f64;
        if let Some(h) = ray_hit(&p, c, phi) {
            let s = (at(h) - s0).rem_euclid(total);
            if s > knots[knots.len() - 1].0 {
                knots.push((s, 2.0 * PI * k as f64 / anchors as f64));
            }
        }
    }
    knots.push((total, 2.0 * PI));
    // pull < 1: blend with the plain arc length from anchor 0 (less
    // distortion of the speed on irregular sections)
    for k in knots.iter_mut() {
        k.0 = pull * k.0 + (1.0 - pull) * k.1 / (2.0 * PI) * total;
    }
    let point_at = |s: f64| -> [f64; 2] {
        let s = (s + s0).rem_euclid(total);
        let i = cum.partition_point(|&x| x <= s).clamp(1, n) - 1;
        let len = cum[i + 1] - cum[i];
        let f = if len > 0.0 { (s - cum[i]) / len } else { 0.0 };
        let (a, b) = (p[i], p[(i + 1) % n]);
        [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
    };
    let mut out = Vec::with_capacity(samples);
    let mut k = 0;
    for j in 0..samples {
        let th = 2.0 * PI * j as f64 / samples as f64;
        while knots[k + 1].1 <= th {
            k += 1;
        }
        let ((sa, ta), (sb, tb)) = (knots[k], knots[k + 1]);
        out.push(point_at(sa + (th - ta) / (tb - ta) * (sb - sa)));
    }
    Ok(out)
}

/// Fits a section (plane points in `frame`) by J terms under the anchored rule.
pub fn fit_anchored(
    plane: &[[f64; 2]],
    frame: Frame,
    terms: usize,
    anchors: usize,
    samples: usize,
    pull: f64,
) -> Result<Gec, Pde6Error> {
    let s = anchored_samples(plane, anchors, samples, pull)?;
    let (centre, x, y) = dft_coefficients(&s, 0.0, terms)?;
    Ok(Gec::new(frame, centre, x, y)?)
}

/// Polar angle of `C(theta)` about `c0` in the section frame (x, -z).
pub fn polar_angle(c: &Fourier3, theta: f64) -> f64 {
    let p: [f64; 3] = c.eval(theta);
    (c.c0[2] - p[2]).atan2(p[0] - c.c0[0])
}

/// Polar angle of the start point `C(0)`.
pub fn start_angle(c: &Fourier3) -> f64 {
    polar_angle(c, 0.0)
}

/// Mean |polar angle of C_a(theta) - polar angle of C_b(theta)| (radians)
/// over `m` uniform theta: how far the same theta slips round between two
/// sections.
pub fn angular_slip(a: &Fourier3, b: &Fourier3, m: usize) -> f64 {
    let m = m.max(1);
    (0..m)
        .map(|j| {
            let t = 2.0 * PI * j as f64 / m as f64;
            wrap(polar_angle(a, t) - polar_angle(b, t)).abs()
        })
        .sum::<f64>()
        / m as f64
}

/// Mean second difference of the unit normal on a `nu x nv` grid.
#[derive(Clone, Copy, Debug, Default, serde::Serialize)]
pub struct Roughness {
    /// Along u (between sections).
    pub u: f64,
    /// Along v (around the sections).
    pub v: f64,
}

/// [`Roughness`] of a chain on a grid of `nu` intervals in u and `nv`
/// (periodic) in v; normals by central differences of the grid points, so
/// only rows 1..nu-1 have normals and rows 2..nu-2 a u second difference.
pub fn roughness(chain: &Chain, nu: usize, nv: usize) -> Roughness {
    let d = chain.domain();
    let (nu, nv) = (nu.max(4), nv.max(3));
    let us: Vec<f64> = (0..=nu)
        .map(|i| d.u.0 + (d.u.1 - d.u.0) * i as f64 / nu as f64)
        .collect();
    let vs: Vec<f64> = (0..nv)
        .map(|j| d.v.0 + (d.v.1 - d.v.0) * j as f64 / nv as f64)
        .collect();
    let g = chain.grid(&us, &vs);
    let at = |i: usize, j: usize| g[i * nv + j % nv];
    let n: Vec<Vec<[f64; 3]>> = (1..nu)
        .map(|i| {
            (0..nv)
                .map(|j| {
                    let su = sub(at(i + 1, j), at(i - 1, j));
                    let sv = sub(at(i, j + 1), at(i, j + nv - 1));
                    normalize(cross(su, sv))
                })
                .collect()
        })
        .collect();
    let d2 = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| norm(sub(add(a, c), scale(b, 2.0)));
    let (mut ru, mut rv) = (0.0, 0.0);
    for i in 1..n.len() - 1 {
        for j in 0..nv {
            ru += d2(n[i - 1][j], n[i][j], n[i + 1][j]);
        }
    }
    for row in &n {
        for j in 0..nv {
            rv += d2(row[(j + nv - 1) % nv], row[j], row[(j + 1) % nv]);
        }
    }
    Roughness {
        u: ru / ((n.len() - 2) * nv) as f64,
        v: rv / (n.len() * nv) as f64,
    }
}
