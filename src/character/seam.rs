//! The seams between neighbouring children of a transition (see
//! [`super::transition`] for the construction): each seam is two cubic
//! Hermite pieces from the front cut through the apex to the back cut,
//! with the across-seam direction both transitions beside it share, so
//! they meet G1 along it.

use super::part::PartSurface;
use super::ring::{cut_indices, hermite, RING_VERTICES};
use crate::character::spec::End;
use crate::mesh::{add, dot, norm, scale, sub};
use crate::vec3::cross;
use std::f64::consts::PI;

/// Geometry of one seam: two cubic Hermite pieces, front cut to apex and
/// apex to back cut, leaving the parent ring along the parent's own
/// u-tangent and crossing the apex parallel to the front-to-back chord.
#[derive(Clone, Copy, Debug)]
pub struct Seam {
    pub front: [f64; 3],
    pub back: [f64; 3],
    pub apex: [f64; 3],
    /// Unit normal of the plane through the cuts and the apex, pointing
    /// from child j to child j+1.
    pub normal: [f64; 3],
    /// Parent ring indices of the front and back cuts.
    pub i_front: usize,
    pub i_back: usize,
    /// `dS/dt` at the front cut, the apex and the back cut.
    pub d_front: [f64; 3],
    pub d_apex: [f64; 3],
    pub d_back: [f64; 3],
    /// Outward unit surface normals the seam's cross tangents are built
    /// from: the parent's at the cuts, across the seam plane at the apex.
    pub n_front: [f64; 3],
    pub n_apex: [f64; 3],
    pub n_back: [f64; 3],
}

/// Cubic Hermite on [0, 1] through `p0`, `p1` with derivatives `m0`, `m1`
/// (d = 0: point, d = 1: derivative).
fn hermite_curve(
    p0: [f64; 3],
    m0: [f64; 3],
    p1: [f64; 3],
    m1: [f64; 3],
    v: f64,
    d: usize,
) -> [f64; 3] {
    let h = hermite(v, d);
    add(
        add(scale(p0, h[0]), scale(m0, h[1])),
        add(scale(p1, h[2]), scale(m1, h[3])),
    )
}

impl Seam {
    /// Point (d = 0) or t-derivative (d = 1) of the seam at `t` in [0, 1].
    pub fn eval(&self, t: f64, d: usize) -> [f64; 3] {
        let (p0, m0, p1, m1, v) = if t <= 0.5 {
            (self.front, self.d_front, self.apex, self.d_apex, 2.0 * t)
        } else {
            (
                self.apex,
                self.d_apex,
                self.back,
                self.d_back,
                2.0 * t - 1.0,
            )
        };
        // dS/dv = dS/dt / 2 on each half
        let x = hermite_curve(p0, scale(m0, 0.5), p1, scale(m1, 0.5), v, d);
        if d == 0 {
            x
        } else {
            scale(x, 2.0)
        }
    }

    pub fn point(&self, t: f64) -> [f64; 3] {
        self.eval(t, 0)
    }

    /// Unit direction across the seam toward child j+1, in the surface's
    /// tangent plane along the seam: `N(t) x S'(t)` with `N` the outward
    /// normal blended from the parent's at the cuts to the apex's, so it
    /// lies in the parent's tangent plane at the cuts and is `normal` at
    /// the apex. Both transitions beside the seam take their cross tangent
    /// from it with opposite signs, so they share the tangent plane
    /// `span(S', D)` along the seam (G1).
    pub fn across(&self, t: f64) -> [f64; 3] {
        let w = (PI * t).sin().powi(2);
        let lin = add(scale(self.n_front, 1.0 - t), scale(self.n_back, t));
        let nn = add(scale(lin, 1.0 - w), scale(self.n_apex, w));
        let sd = self.eval(t, 1);
        let d = cross(nn, sd);
        let d = scale(d, 1.0 / norm(d).max(f64::MIN_POSITIVE));
        if dot(d, self.normal) < 0.0 {
            scale(d, -1.0)
        } else {
            d
        }
    }
}

/// The cross tangent of a transition along a seam, on the side `side`
/// (+1 or -1): the parent's scaled u-tangent at the cuts, turning into
/// `side ell` times [`Seam::across`] toward the apex: `(1 - w) c(t) S'(t)
/// + a side ell D(t)`, `w` [`seam_weight`], `a` [`seam_across_weight`].
///
/// With `w = sin^2(pi t)`, `a = sin(pi t)`, `D` the
/// seam's [`Seam::across`], `c` linear with `c(0) S'(0)` the parent's
/// scaled tangent `sgn ell dP/du` at the front cut and `c(1) S'(1)` the one
/// at the back cut (the seam leaves the ring along it), so the loop's cross
/// tangent is continuous at the cuts. Modulo `S'` the two sides' tangents
/// are `-+a ell D`: opposite, so the two transitions meet G1 along the
/// whole seam, and at the cuts both are tangent to the parent.
pub(super) fn seam_tangent(
    s: &Seam,
    t: f64,
    ell: f64,
    side: f64,
    p1: &crate::curve::Fourier3,
) -> [f64; 3] {
    let n = RING_VERTICES as f64;
    let pf = norm(p1.eval(2.0 * PI * s.i_front as f64 / n));
    let pb = norm(p1.eval(2.0 * PI * s.i_back as f64 / n));
    let c0 = ell * pf / norm(s.d_front).max(f64::MIN_POSITIVE);
    let c1 = -ell * pb / norm(s.d_back).max(f64::MIN_POSITIVE);
    let w = seam_weight(t);
    let base = scale(s.eval(t, 1), (1.0 - t) * c0 + t * c1);
    add(
        scale(base, 1.0 - w),
        scale(s.across(t), seam_across_weight(t) * side * ell),
    )
}

/// Weight of the across-seam direction `D` in a seam's cross tangent,
/// `sin(pi t)`: 0 at the cuts, 1 at the apex, rising linearly from the
/// cuts. With `sin^2(pi t)` (the fade of the along-seam part,
/// [`seam_weight`]) the two transitions beside a seam left it near the
/// cuts almost along the seam itself (at the first seam vertex 0.12 of
/// their tangent across it), nearly coplanar, and where their scales
/// differed (the arm's corner column against the head's) their first rows
/// crossed: one pair on the base, stomach-pregnant-incr, african-, asian-
/// and caucasian-male-young. The along-seam part and the tangent plane
/// `span(S', D)` are unchanged, so the seam stays G1.
pub fn seam_across_weight(t: f64) -> f64 {
    (PI * t).sin()
}

/// Weight of the across-seam direction in a seam's cross tangent,
/// `w = sin^2(pi t)`: 0 at the cuts (the parent's tangent), 1 at the apex.
/// (A faster rise, `1 - (1 - sin(pi t))^3`, was tried: more creased.)
pub fn seam_weight(t: f64) -> f64 {
    (PI * t).sin().powi(2)
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
    let u = parent.end_u(parent_end);
    let sgn = if parent_end == End::End { 1.0 } else { -1.0 };
    let ring = parent.section(u, 0);
    let ring_u = parent.section(u, 1);
    let n = RING_VERTICES as f64;
    let unit = |v: [f64; 3]| scale(v, 1.0 / norm(v).max(f64::MIN_POSITIVE));
    // outward unit tangent of the parent at ring angle phi (away from the
    // parent) and its outward unit normal
    let frame = |phi: f64| -> ([f64; 3], [f64; 3]) {
        let tu = unit(scale(ring_u.eval(phi), sgn));
        let h = 1e-6;
        let tr = sub(ring.eval(phi + h), ring.eval(phi - h));
        let mut nn = unit(cross(tr, tu));
        if dot(nn, sub(ring.eval(phi), ring.c0)) < 0.0 {
            nn = scale(nn, -1.0);
        }
        (tu, nn)
    };
    (1..k)
        .map(|j| {
            let (f, b) = cut_indices(j, k, cuts);
            let (phf, phb) = (2.0 * PI * f as f64 / n, 2.0 * PI * b as f64 / n);
            let front = ring.eval(phf);
            let back = ring.eval(phb);
            let a = apex[j - 1];
            let m = scale(add(front, back), 0.5);
            let c = cross(sub(back, front), sub(a, m));
            let cn = norm(c).max(f64::MIN_POSITIVE);
            let mut normal = scale(c, 1.0 / cn);
            if dot(normal, sub(child_centres[j], child_centres[j - 1])) < 0.0 {
                normal = scale(normal, -1.0);
            }
            let chord = sub(back, front);
            let floor = 0.1 * norm(chord);
            let (tf, nf) = frame(phf);
            let (tb, nb) = frame(phb);
            // a quarter ellipse of height h leaves at pi h, crosses its top
            // at pi / 2 times the chord
            let hf = dot(sub(a, front), tf).max(floor);
            let hb = dot(sub(a, back), tb).max(floor);
            let d_apex = scale(chord, 0.5 * PI);
            let mut n_apex = unit(cross(d_apex, normal));
            if dot(n_apex, sub(a, ring.c0)) < 0.0 {
                n_apex = scale(n_apex, -1.0);
            }
            Seam {
                front,
                back,
                apex: a,
                normal,
                i_front: f,
                i_back: b,
                d_front: scale(tf, PI * hf),
                d_apex,
                d_back: scale(tb, -PI * hb),
                n_front: nf,
                n_apex,
                n_back: nb,
            }
        })
        .collect()
}
