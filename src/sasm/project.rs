//! Ray casting of view-plane points onto a part's analytic surface.
//!
//! The part is sampled on a `(u, theta)` grid; each grid cell's projection
//! (two triangles) is binned in a uniform 2D bucket grid. A query point `q`
//! is tested against the cells of its bucket; every cell containing it
//! gives a starting guess (barycentric in the cell), refined by Newton on
//! `P(S(u, theta)) = q` (P: the view's projection) with the pde6 chain's
//! exact first derivatives. The converged solution of greatest depth (the
//! first hit from the viewer) is returned.

use super::{depth_axis, SasmError};
use crate::character::part::PartSurface;
use crate::profile::View;
use std::f64::consts::PI;

/// Grid cells along u and around theta.
pub const GRID_U: usize = 160;
pub const GRID_THETA: usize = 96;
/// Newton iterations.
const NEWTON_MAX: usize = 40;

/// A ray hit on the part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    pub u: f64,
    pub theta: f64,
    pub point: [f64; 3],
}

/// A part prepared for ray casting in one view.
pub struct Projector<'a> {
    pub part: &'a PartSurface,
    pub view: View,
    us: Vec<f64>,
    ths: Vec<f64>,
    /// Projected grid points, row-major in u.
    q: Vec<[f64; 2]>,
    lo: [f64; 2],
    cell: [f64; 2],
    nb: usize,
    buckets: Vec<Vec<u32>>,
    /// Residual accepted by Newton (relative to the part's size).
    pub tol: f64,
}

fn proj(v: View, p: [f64; 3]) -> [f64; 2] {
    v.project(p)
}

impl<'a> Projector<'a> {
    /// Samples the part and bins its cells.
    pub fn new(part: &'a PartSurface, view: View) -> Projector<'a> {
        let us: Vec<f64> = (0..=GRID_U)
            .map(|i| part.u0 + (part.u1 - part.u0) * i as f64 / GRID_U as f64)
            .collect();
        let ths: Vec<f64> = (0..=GRID_THETA)
            .map(|j| 2.0 * PI * j as f64 / GRID_THETA as f64)
            .collect();
        let pts = part.surface.grid(&us, &ths);
        let q: Vec<[f64; 2]> = pts.iter().map(|&p| proj(view, p)).collect();
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in &q {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let size = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(f64::MIN_POSITIVE);
        let nb = 64;
        let cell = [
            ((hi[0] - lo[0]) / nb as f64).max(size * 1e-9),
            ((hi[1] - lo[1]) / nb as f64).max(size * 1e-9),
        ];
        let mut pr = Projector {
            part,
            view,
            us,
            ths,
            q,
            lo,
            cell,
            nb,
            buckets: vec![Vec::new(); nb * nb],
            tol: 1e-12 * size,
        };
        let nt = GRID_THETA + 1;
        for i in 0..GRID_U {
            for j in 0..GRID_THETA {
                let c = [
                    pr.q[i * nt + j],
                    pr.q[i * nt + j + 1],
                    pr.q[(i + 1) * nt + j],
                    pr.q[(i + 1) * nt + j + 1],
                ];
                let (mut a, mut b) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
                for p in &c {
                    for k in 0..2 {
                        a[k] = a[k].min(p[k]);
                        b[k] = b[k].max(p[k]);
                    }
                }
                let (i0, j0) = pr.bucket(a);
                let (i1, j1) = pr.bucket(b);
                for bi in i0..=i1 {
                    for bj in j0..=j1 {
                        pr.buckets[bi * nb + bj].push((i * GRID_THETA + j) as u32);
                    }
                }
            }
        }
        pr
    }

    fn bucket(&self, p: [f64; 2]) -> (usize, usize) {
        let f = |k: usize| {
            (((p[k] - self.lo[k]) / self.cell[k]).floor().max(0.0) as usize).min(self.nb - 1)
        };
        (f(0), f(1))
    }

    /// Depth of a point (its coordinate on the view's depth axis).
    pub fn depth(&self, p: [f64; 3]) -> f64 {
        p[depth_axis(self.view)]
    }

    /// The first hit of the ray through `q`, or `None` when it misses.
    pub fn cast(&self, q: [f64; 2]) -> Option<Hit> {
        if !(q[0].is_finite() && q[1].is_finite()) {
            return None;
        }
        let (a, b) = (
            (q[0] - self.lo[0]) / self.cell[0],
            (q[1] - self.lo[1]) / self.cell[1],
        );
        if a < -1e-9 || b < -1e-9 || a > self.nb as f64 + 1e-9 || b > self.nb as f64 + 1e-9 {
            return None;
        }
        let (bi, bj) = self.bucket(q);
        let nt = GRID_THETA + 1;
        let mut best: Option<Hit> = None;
        for &c in &self.buckets[bi * self.nb + bj] {
            let (i, j) = (c as usize / GRID_THETA, c as usize % GRID_THETA);
            let p00 = self.q[i * nt + j];
            let p01 = self.q[i * nt + j + 1];
            let p10 = self.q[(i + 1) * nt + j];
            let p11 = self.q[(i + 1) * nt + j + 1];
            let guess = [
                (p00, p10, p11, (0.0, 0.0), (1.0, 0.0), (1.0, 1.0)),
                (p00, p11, p01, (0.0, 0.0), (1.0, 1.0), (0.0, 1.0)),
            ]
            .iter()
            .find_map(|&(x, y, z, ax, ay, az)| {
                let w = bary(q, x, y, z)?;
                Some((
                    w[0] * ax.0 + w[1] * ay.0 + w[2] * az.0,
                    w[0] * ax.1 + w[1] * ay.1 + w[2] * az.1,
                ))
            });
            let Some((fu, ft)) = guess else { continue };
            let u = self.us[i] + fu * (self.us[i + 1] - self.us[i]);
            let t = self.ths[j] + ft * (self.ths[j + 1] - self.ths[j]);
            if let Some(h) = self.newton(q, u, t) {
                if best.is_none_or(|b| self.depth(h.point) > self.depth(b.point)) {
                    best = Some(h);
                }
            }
        }
        best
    }

    /// Newton on `P(S(u, theta)) = q` from `(u, theta)`.
    pub fn newton(&self, q: [f64; 2], mut u: f64, mut t: f64) -> Option<Hit> {
        let (ha, va) = self.view.axes();
        let s = &self.part.surface;
        for _ in 0..NEWTON_MAX {
            let p = s.point(u, t);
            let r = [p[ha] - q[0], p[va] - q[1]];
            if r[0].hypot(r[1]) <= self.tol {
                return Some(Hit {
                    u,
                    theta: t.rem_euclid(2.0 * PI),
                    point: p,
                });
            }
            let su = s.derivative(u, t, 1, 0);
            let st = s.derivative(u, t, 0, 1);
            let (a, b, c, d) = (su[ha], st[ha], su[va], st[va]);
            let det = a * d - b * c;
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let du = (d * r[0] - b * r[1]) / det;
            let dt = (-c * r[0] + a * r[1]) / det;
            // damp large steps (stay near the starting cell's sheet)
            let span = (self.part.u1 - self.part.u0) / GRID_U as f64;
            let k = (1.0f64)
                .min(4.0 * span / du.abs().max(1e-300))
                .min(4.0 * 2.0 * PI / GRID_THETA as f64 / dt.abs().max(1e-300));
            u -= k * du;
            t -= k * dt;
            if u < self.part.u0 || u > self.part.u1 {
                u = u.clamp(self.part.u0, self.part.u1);
            }
        }
        None
    }
}

/// Barycentric coordinates of `q` in triangle `(a, b, c)` when inside
/// (with a small tolerance).
fn bary(q: [f64; 2], a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 3]> {
    let d = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    let l1 = ((q[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (q[1] - a[1])) / d;
    let l2 = ((b[0] - a[0]) * (q[1] - a[1]) - (q[0] - a[0]) * (b[1] - a[1])) / d;
    let l0 = 1.0 - l1 - l2;
    let e = -1e-9;
    (l0 >= e && l1 >= e && l2 >= e).then_some([l0, l1, l2])
}

/// Projects every point of a stroke; an error names the first miss.
pub fn project_stroke(pr: &Projector, what: &str, pts: &[[f64; 2]]) -> Result<Vec<Hit>, SasmError> {
    pts.iter()
        .enumerate()
        .map(|(i, &q)| {
            pr.cast(q).ok_or_else(|| SasmError::Misses {
                what: what.into(),
                part: pr.part.name.clone(),
                view: pr.view,
                index: i,
                at: q,
            })
        })
        .collect()
}
