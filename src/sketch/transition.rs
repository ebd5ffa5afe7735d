//! Transition surfaces at the joins (paper 000 sec 4.1.1: "the boundary
//! curves between two adjacent parts are determined, then the tangents of
//! surfaces at these two boundary curves are calculated, finally a smooth
//! transition surface is created from them").
//!
//! pdesculpt's construction (simpler than a PDE transition): a parent end
//! ring branches into k children ordered by x. The ring is cut at
//! `phi_F(j) = pi - j pi / k` (front) and `phi_B(j) = pi + j pi / k` (back);
//! between children j and j+1 a **seam** runs from the front cut to the back
//! cut through an apex (the crotch point, the top of a shoulder):
//! `S(t) = (1-t) P_F + t P_B + sin(pi t) (A - (P_F + P_B)/2)`.
//! Child j's **loop** is its arcs of the parent ring plus the seams beside
//! it; its transition is the cubic Hermite blend in s in [0, 1]
//!
//! $$ X(s, \tau) = h_{00}(s) L(\tau) + h_{10}(s) T(\tau) + h_{01}(s) Q(\theta(\tau)) + h_{11}(s) D(\theta(\tau)) $$
//!
//! between the loop `L` with cross tangents `T` and the child's start ring
//! `Q` with `D = ell * dQ/du` (`ell`: the distance between the loop's and
//! the ring's centroids). On the parent's arcs `T = +-ell * dP/du`, so the
//! transition meets both parts **C1** (parametrically, with scale `ell`);
//! along a seam `T` blends from the parent's tangent at the cuts to
//! `-+ell n` (n the seam plane's normal, pointing to the next child), so the
//! two transitions beside a seam are tangent-continuous only where that
//! blend is complete; the seam itself is claimed C0 only and its normal
//! jump is measured. C2 is not claimed (a cubic Hermite has no curvature
//! condition); the C2 jump is measured and reported.

use super::part::PartSurface;
use crate::character::doc::End;
use crate::mesh::{add, dist, dot, norm, scale, sub};
use std::f64::consts::PI;

/// Vertices on the parent's end ring (divisible by 4 and 6).
pub const RING_VERTICES: usize = 48;
/// Interior vertices per seam.
pub const SEAM_VERTICES: usize = 8;

/// A run of a child's loop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Run {
    /// Parent ring from index `from` for `count` steps (increasing phi).
    Arc { from: usize, count: usize },
    /// Seam j traversed front to back (`reversed = false`) or back to front.
    Seam { j: usize, reversed: bool },
}

/// Geometry of one seam.
#[derive(Clone, Copy, Debug)]
pub struct Seam {
    pub front: [f64; 3],
    pub back: [f64; 3],
    pub apex: [f64; 3],
    /// Unit normal pointing from child j to child j+1.
    pub normal: [f64; 3],
    /// Parent ring indices of the front and back cuts.
    pub i_front: usize,
    pub i_back: usize,
}

impl Seam {
    pub fn point(&self, t: f64) -> [f64; 3] {
        let m = scale(add(self.front, self.back), 0.5);
        add(
            add(scale(self.front, 1.0 - t), scale(self.back, t)),
            scale(sub(self.apex, m), (PI * t).sin()),
        )
    }
}

/// The ring indices of the front and back cuts of seam j (1-based) among
/// k children: `cuts[j - 1]` when given ([`cut_table`]), else the fixed
/// angles `pi - j pi / k`.
pub fn cut_indices(j: usize, k: usize, cuts: &[(usize, usize)]) -> (usize, usize) {
    if let Some(c) = cuts.get(j - 1) {
        return *c;
    }
    let n = RING_VERTICES;
    let f = n / 2 - j * n / (2 * k);
    let b = n / 2 + j * n / (2 * k);
    (f % n, b % n)
}

/// Ring indices of the cuts at the given front angles (radians in (0, pi),
/// decreasing): rounded to ring vertices, kept strictly decreasing and
/// inside (0, pi). Empty when `angles` does not have one angle per seam
/// (the fixed angles are used).
pub fn cut_table(k: usize, angles: &[f64]) -> Vec<(usize, usize)> {
    let n = RING_VERTICES;
    if k < 2 || angles.len() != k - 1 || angles.iter().any(|a| !a.is_finite()) {
        return Vec::new();
    }
    let mut f: Vec<usize> = angles
        .iter()
        .map(|a| ((a / (2.0 * PI) * n as f64).round() as usize).clamp(1, n / 2 - 1))
        .collect();
    // strictly decreasing, each at least 1 and below n / 2
    for j in 1..f.len() {
        if f[j] >= f[j - 1] {
            f[j] = f[j - 1].saturating_sub(1);
        }
    }
    if f.last().is_some_and(|&x| x < 1) || f[0] >= n / 2 {
        return Vec::new();
    }
    f.into_iter().map(|x| (x, n - x)).collect()
}

/// The runs of child `c` (0-based) of `k`.
pub fn loop_runs(c: usize, k: usize, cuts: &[(usize, usize)]) -> Vec<Run> {
    let n = RING_VERTICES;
    let cut_indices = |j: usize, k: usize| cut_indices(j, k, cuts);
    let steps = |a: usize, b: usize| (b + n - a) % n;
    if k == 1 {
        return vec![Run::Arc { from: 0, count: n }];
    }
    let j = c + 1; // seam to the right of child c is seam j (1-based), left is j - 1
    if c == 0 {
        let (f, b) = cut_indices(1, k);
        vec![
            Run::Arc {
                from: f,
                count: steps(f, b),
            },
            Run::Seam {
                j: 0,
                reversed: true,
            },
        ]
    } else if c + 1 == k {
        let (f, b) = cut_indices(k - 1, k);
        vec![
            Run::Arc {
                from: b,
                count: steps(b, f),
            },
            Run::Seam {
                j: k - 2,
                reversed: false,
            },
        ]
    } else {
        let (fl, bl) = cut_indices(j - 1, k);
        let (fr, br) = cut_indices(j, k);
        vec![
            Run::Arc {
                from: fr,
                count: steps(fr, fl),
            },
            Run::Seam {
                j: j - 2,
                reversed: false,
            },
            Run::Arc {
                from: bl,
                count: steps(bl, br),
            },
            Run::Seam {
                j: j - 1,
                reversed: true,
            },
        ]
    }
}

/// Number of loop vertices (each run contributes its steps).
pub fn loop_len(runs: &[Run]) -> usize {
    runs.iter()
        .map(|r| match r {
            Run::Arc { count, .. } => *count,
            Run::Seam { .. } => SEAM_VERTICES + 1,
        })
        .sum()
}

/// One child's transition surface.
#[derive(Clone, Debug)]
pub struct ChildTransition {
    pub runs: Vec<Run>,
    pub n: usize,
    /// Sign of the parent's u toward the transition.
    pub sgn: f64,
    pub parent_u: f64,
    pub child_u: f64,
    pub ell: f64,
    /// Child ring angle of loop vertex i: `theta0 + sigma 2 pi i / n`.
    pub theta0: f64,
    pub sigma: f64,
    /// -1 when the child is left of the seam, +1 when right, per seam j.
    pub side: Vec<(usize, f64)>,
}

/// Loop point and cross tangent at continuous loop parameter `tau`.
pub fn loop_eval(
    ct: &ChildTransition,
    parent: &PartSurface,
    seams: &[Seam],
    tau: f64,
) -> ([f64; 3], [f64; 3]) {
    let n = RING_VERTICES as f64;
    let tau = tau.rem_euclid(ct.n as f64);
    let mut start = 0.0;
    let p0 = parent.section(ct.parent_u, 0);
    let p1 = parent.section(ct.parent_u, 1);
    let ptan = |phi: f64| scale(p1.eval(phi), ct.sgn * ct.ell);
    for r in &ct.runs {
        let len = match r {
            Run::Arc { count, .. } => *count as f64,
            Run::Seam { .. } => (SEAM_VERTICES + 1) as f64,
        };
        if tau < start + len || std::ptr::eq(r, ct.runs.last().unwrap_or(r)) {
            let f = (tau - start) / len;
            match *r {
                Run::Arc { from, count } => {
                    let phi = 2.0 * PI * (from as f64 + f * count as f64) / n;
                    return (p0.eval(phi), ptan(phi));
                }
                Run::Seam { j, reversed } => {
                    let s = &seams[j];
                    let t = if reversed { 1.0 - f } else { f };
                    let side = ct.side.iter().find(|(jj, _)| *jj == j).map_or(0.0, |x| x.1);
                    let tf = ptan(2.0 * PI * s.i_front as f64 / n);
                    let tb = ptan(2.0 * PI * s.i_back as f64 / n);
                    let w = (PI * t).sin().powi(2);
                    let base = add(scale(tf, 1.0 - t), scale(tb, t));
                    let tan = add(scale(base, 1.0 - w), scale(s.normal, w * side * ct.ell));
                    return (s.point(t), tan);
                }
            }
        }
        start += len;
    }
    unreachable!("tau is reduced into the loop")
}

/// Hermite basis values and derivatives (d = 0, 1, 2) at s.
fn hermite(s: f64, d: usize) -> [f64; 4] {
    match d {
        0 => [
            2.0 * s * s * s - 3.0 * s * s + 1.0,
            s * s * s - 2.0 * s * s + s,
            -2.0 * s * s * s + 3.0 * s * s,
            s * s * s - s * s,
        ],
        1 => [
            6.0 * s * s - 6.0 * s,
            3.0 * s * s - 4.0 * s + 1.0,
            -6.0 * s * s + 6.0 * s,
            3.0 * s * s - 2.0 * s,
        ],
        _ => [
            12.0 * s - 6.0,
            6.0 * s - 4.0,
            -12.0 * s + 6.0,
            6.0 * s - 2.0,
        ],
    }
}

/// The transition's d-th s-derivative at `(s, tau)`.
pub fn eval(
    ct: &ChildTransition,
    parent: &PartSurface,
    child: &PartSurface,
    seams: &[Seam],
    s: f64,
    tau: f64,
    d: usize,
) -> [f64; 3] {
    let (l, t) = loop_eval(ct, parent, seams, tau);
    let th = ct.theta0 + ct.sigma * 2.0 * PI * tau / ct.n as f64;
    let q = child.section(ct.child_u, 0).eval(th);
    let dq = scale(child.section(ct.child_u, 1).eval(th), ct.ell);
    let h = hermite(s, d);
    add(
        add(scale(l, h[0]), scale(t, h[1])),
        add(scale(q, h[2]), scale(dq, h[3])),
    )
}

/// Builds a child transition: loop runs, scale and the angular alignment of
/// the child ring to the loop (best rigid match of centred points over
/// 720 start angles and both directions).
pub fn child_transition(
    c: usize,
    k: usize,
    parent: &PartSurface,
    parent_end: End,
    child: &PartSurface,
    seams: &[Seam],
    cuts: &[(usize, usize)],
) -> ChildTransition {
    let runs = loop_runs(c, k, cuts);
    let n = loop_len(&runs);
    let mut side = Vec::new();
    if c > 0 {
        side.push((c - 1, 1.0));
    }
    if c + 1 < k {
        side.push((c, -1.0));
    }
    let mut ct = ChildTransition {
        runs,
        n,
        sgn: if parent_end == End::End { 1.0 } else { -1.0 },
        parent_u: parent.end_u(parent_end),
        child_u: child.u0,
        ell: 1.0,
        theta0: 0.0,
        sigma: 1.0,
        side,
    };
    let pts: Vec<[f64; 3]> = (0..n)
        .map(|i| loop_eval(&ct, parent, seams, i as f64).0)
        .collect();
    let cl = centroid(&pts);
    let q = child.section(child.u0, 0);
    let cq = q.c0;
    ct.ell = dist(cl, cq).max(1e-9);
    let mut best = (f64::INFINITY, 0.0, 1.0);
    for sigma in [1.0, -1.0] {
        for a in 0..720 {
            let th0 = 2.0 * PI * a as f64 / 720.0;
            let e: f64 = pts
                .iter()
                .enumerate()
                .map(|(i, p)| {
                    let th = th0 + sigma * 2.0 * PI * i as f64 / n as f64;
                    let d = sub(sub(*p, cl), sub(q.eval(th), cq));
                    dot(d, d)
                })
                .sum();
            if e < best.0 {
                best = (e, th0, sigma);
            }
        }
    }
    ct.theta0 = best.1;
    ct.sigma = best.2;
    ct
}

fn centroid(p: &[[f64; 3]]) -> [f64; 3] {
    let s = p.iter().fold([0.0; 3], |a, b| add(a, *b));
    scale(s, 1.0 / p.len().max(1) as f64)
}

/// Seams of a transition from the parent ring and the apexes.
pub fn seams(
    parent: &PartSurface,
    parent_end: End,
    k: usize,
    apex: &[[f64; 3]],
    child_centres: &[[f64; 3]],
    cuts: &[(usize, usize)],
) -> Vec<Seam> {
    let ring = parent.section(parent.end_u(parent_end), 0);
    let n = RING_VERTICES as f64;
    (1..k)
        .map(|j| {
            let (f, b) = cut_indices(j, k, cuts);
            let front = ring.eval(2.0 * PI * f as f64 / n);
            let back = ring.eval(2.0 * PI * b as f64 / n);
            let a = apex[j - 1];
            let m = scale(add(front, back), 0.5);
            let c = cross(sub(back, front), sub(a, m));
            let cn = norm(c).max(f64::MIN_POSITIVE);
            let mut normal = scale(c, 1.0 / cn);
            if dot(normal, sub(child_centres[j], child_centres[j - 1])) < 0.0 {
                normal = scale(normal, -1.0);
            }
            Seam {
                front,
                back,
                apex: a,
                normal,
                i_front: f,
                i_back: b,
            }
        })
        .collect()
}

/// Cross product.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
