//! Transition surfaces at the joins (paper 000 sec 4.1.1: "the boundary
//! curves between two adjacent parts are determined, then the tangents of
//! surfaces at these two boundary curves are calculated, finally a smooth
//! transition surface is created from them").
//!
//! pdesculpt's construction (simpler than a PDE transition): a parent end
//! ring branches into k children ordered by x. The ring is cut at
//! `phi_F(j) = pi - j pi / k` (front) and `phi_B(j) = pi + j pi / k` (back)
//! (or at `cut_angles`); between children j and j+1 a **seam** runs from the
//! front cut to the back cut through an apex (the crotch point, the top of
//! a shoulder): two cubic Hermite pieces that leave the ring along the
//! parent's own u-tangent, `S'(0) = pi h_F t_F` (`t_F` the unit tangent
//! away from the parent, `h_F` the apex's height above the cut along it),
//! and cross the apex parallel to the chord, `S'(1/2) = (pi/2)(P_B - P_F)`
//! (a quarter ellipse's derivatives).
//! Child j's **loop** `L(tau)` is its arcs of the parent ring plus the seams
//! beside it; its transition blends, for s in [0, 1], the loop with cross
//! derivatives `T`, `A` into the child's start ring `Q` with `D = ell dQ/du`,
//! `B = ell^2 d2Q/du2` (`ell`: the distance between the loop's and the
//! ring's centroids, times `tangent_scale`):
//!
//! $$ X(s, \tau) = H_0 L + H_1 T + H_2 A + H_3 Q + H_4 D + H_5 B $$
//!
//! with the quintic Hermite basis `H` ([`quintic`]; continuity `c2`), or
//! the cubic one without `A`, `B` (continuity `c1`, the default). On the
//! parent's arcs `T = +-ell dP/du` and `A = ell^2 d2P/du2`, so the
//! transition meets both parts **C2** with `c2` (C1 with `c1`),
//! parametrically with scale `ell`: the parts are C2 pde6 chains, so their
//! second derivatives at the boundary rings exist.
//!
//! Why `c1` stays the default: the quintic carries the parts' end
//! curvature `ell^2 d2P/du2` across the whole transition, which bulges where
//! a part's end is strongly curved (the bundled animal's profile error
//! rises from 0.90 % to 1.47 % of the height, past the 1 %; the
//! closed body (`pde6 body`) grows horns at the shoulders, max
//! reconstruction error 2.4 % -> 4.7 %); C2 is measured and claimed only
//! for transitions that ask for it.
//!
//! Along a seam the cross tangent is `T = (1 - w) c(t) S'(t) + a side ell D(t)`,
//! `w = sin^2(pi t)`, `a = sin(pi t)`, with `D` the unit direction across the seam in the
//! tangent plane ([`Seam::across`]: perpendicular to `S'` and to a normal
//! blended from the parent's at the cuts to the seam plane's at the apex)
//! and `c(t) S'(t)` equal to the parent's scaled tangent at the cuts. The
//! two transitions beside a seam have tangents that differ only in the sign
//! of the `D` term, so modulo `S'` they are opposite and the two surfaces
//! share the tangent plane `span(S', D)` along the whole seam: **G1** across
//! the seam (its normal jump is measured: `SeamReport`), and tangent to the
//! parent at the cuts. (An earlier seam, `S(t) = (1-t) P_F + t P_B +
//! sin(pi t)(A - M)`, left the ring across the parent's surface and blended
//! the parent's tangent, which is not in the seam's tangent plane, into
//! both sides: the two sides met at an angle, the visible shoulder crease.)
//! Along a seam `A` is the parent's second derivative at the cuts, blended
//! and faded out by `1 - w` as `T` is; C2 across a seam is not claimed.
//!
//! `ell` is per loop column where the child turns back against the parent
//! (the arms under the shoulders): [`column_scales`] makes it follow each
//! column's chord to the child ring, which stops the armpit's corner
//! columns folding through their neighbours. Everywhere else it is one
//! scale per child. A transition with `cap_tangents` (sketched ones) then
//! caps each column's tangent at its scale where the parent's end ring
//! flares ([`super::tangent_cap`]).
//!
//! Nothing here assumes a vertical axis: the cuts are ring angles of the
//! parent's own section parameter, the seams are built from the parent's
//! end tangent and the apex, and [`column_scales`]'s turn-back measure is
//! the angle between the parent's end tangent and the loop-to-ring
//! direction (a wrist, whose arm points down and forward and whose thumb
//! leaves it at ~30 degrees, has none: one scale per child). A part may be
//! a child of one transition and the parent of another at its end (an
//! arm: child of the shoulders, parent of its wrist): its tube switches
//! from the first transition's loop angles to the uniform end ring the
//! second's cuts index, halfway along (`character::assembly`).

use super::part::PartSurface;
use crate::character::spec::{Continuity, End};
use crate::mesh::{add, dist, dot, norm, scale, sub};
use std::f64::consts::PI;

pub use super::ring::quintic;
use super::ring::{hermite, RING_VERTICES, SEAM_VERTICES};
pub use super::rise::{late_weight, RISE_MAX};
pub use super::runs::{loop_len, loop_runs, Run};
use super::seam::{seam_tangent, seam_weight, Seam};
use crate::character::spec::TransitionSpec;

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
    /// Per loop vertex scale of the cross tangents ([`ChildTransition::ell_at`],
    /// [`column_scales`]); empty: `ell` everywhere.
    pub ell_vertex: Vec<f64>,
    /// Child ring angle of loop vertex i: `theta0 + sigma 2 pi i / n`.
    pub theta0: f64,
    pub sigma: f64,
    /// -1 when the child is left of the seam, +1 when right, per seam j.
    pub side: Vec<(usize, f64)>,
    /// Cubic (C1) or quintic (C2) Hermite blend.
    pub continuity: Continuity,
    /// Per loop vertex start `s0` of the late depth blend
    /// ([`late_weight`], [`set_rises`]); empty: the plain blend.
    pub rise_vertex: Vec<f64>,
}

impl ChildTransition {
    /// The cross-tangent scale at loop parameter `tau`: the per-vertex
    /// scales interpolated linearly (periodic), or `ell` when none.
    pub fn ell_at(&self, tau: f64) -> f64 {
        periodic_lerp(&self.ell_vertex, tau).unwrap_or(self.ell)
    }

    /// The late depth blend's start at loop parameter `tau` (0 when none).
    pub fn rise_at(&self, tau: f64) -> f64 {
        periodic_lerp(&self.rise_vertex, tau).unwrap_or(0.0)
    }
}

/// Per-vertex values `v` interpolated linearly at `tau` (periodic); `None`
/// when there are none.
fn periodic_lerp(v: &[f64], tau: f64) -> Option<f64> {
    let n = v.len();
    if n == 0 {
        return None;
    }
    let t = tau.rem_euclid(n as f64);
    let i = (t.floor() as usize).min(n - 1);
    let f = t - i as f64;
    Some(v[i] * (1.0 - f) + v[(i + 1) % n] * f)
}

/// Loop point and cross tangent at continuous loop parameter `tau`.
pub fn loop_eval(
    ct: &ChildTransition,
    parent: &PartSurface,
    seams: &[Seam],
    tau: f64,
) -> ([f64; 3], [f64; 3]) {
    let n = RING_VERTICES as f64;
    let p0 = parent.section(ct.parent_u, 0);
    let p1 = parent.section(ct.parent_u, 1);
    let ell = ct.ell_at(tau);
    let ptan = |phi: f64| scale(p1.eval(phi), ct.sgn * ell);
    match locate(ct, tau) {
        (Run::Arc { from, count }, f) => {
            let phi = 2.0 * PI * (from as f64 + f * count as f64) / n;
            (p0.eval(phi), ptan(phi))
        }
        (Run::Seam { j, reversed }, f) => {
            let s = &seams[j];
            let t = if reversed { 1.0 - f } else { f };
            let side = ct.side.iter().find(|(jj, _)| *jj == j).map_or(0.0, |x| x.1);
            (s.point(t), seam_tangent(s, t, ell, side, &p1))
        }
    }
}

/// The run of the loop at continuous parameter `tau` (taken modulo the
/// loop's length) and the fraction `f` in [0, 1] of the way along it.
pub(super) fn locate(ct: &ChildTransition, tau: f64) -> (Run, f64) {
    let tau = tau.rem_euclid(ct.n as f64);
    let mut start = 0.0;
    for r in &ct.runs {
        let len = match r {
            Run::Arc { count, .. } => *count as f64,
            Run::Seam { .. } => (SEAM_VERTICES + 1) as f64,
        };
        if tau < start + len || std::ptr::eq(r, ct.runs.last().unwrap_or(r)) {
            return (*r, (tau - start) / len);
        }
        start += len;
    }
    unreachable!("tau is reduced into the loop")
}

/// The loop's second cross derivative at `tau`: `ell^2 d2P/du2` on the
/// parent's arcs; along a seam the parent's at the two cuts, blended
/// linearly and faded out by `1 - w` as the cross tangent is.
pub fn loop_second(
    ct: &ChildTransition,
    parent: &PartSurface,
    seams: &[Seam],
    tau: f64,
) -> [f64; 3] {
    let n = RING_VERTICES as f64;
    let p2 = parent.section(ct.parent_u, 2);
    let e2 = ct.ell_at(tau).powi(2);
    match locate(ct, tau) {
        (Run::Arc { from, count }, f) => {
            scale(p2.eval(2.0 * PI * (from as f64 + f * count as f64) / n), e2)
        }
        (Run::Seam { j, reversed }, f) => {
            let s = &seams[j];
            let t = if reversed { 1.0 - f } else { f };
            let w = seam_weight(t);
            let af = p2.eval(2.0 * PI * s.i_front as f64 / n);
            let ab = p2.eval(2.0 * PI * s.i_back as f64 / n);
            scale(add(scale(af, 1.0 - t), scale(ab, t)), e2 * (1.0 - w))
        }
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
    blend(ct, &column(ct, parent, child, seams, tau), s, d)
}

/// One column of a transition: its Hermite data `[L, T, A, Q, D, B]`
/// (module docs; `A` and `B` zero for a `c1` blend) and the start of its
/// late depth blend ([`late_weight`]), which [`blend`] weighs at any `s`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Column {
    pub data: [[f64; 3]; 6],
    pub rise: f64,
}

/// The column of the transition at loop parameter `tau`.
pub fn column(
    ct: &ChildTransition,
    parent: &PartSurface,
    child: &PartSurface,
    seams: &[Seam],
    tau: f64,
) -> Column {
    let (l, t) = loop_eval(ct, parent, seams, tau);
    let th = ct.theta0 + ct.sigma * 2.0 * PI * tau / ct.n as f64;
    let q = child.section(ct.child_u, 0).eval(th);
    let ell = ct.ell_at(tau);
    let dq = scale(child.section(ct.child_u, 1).eval(th), ell);
    let rise = ct.rise_at(tau);
    if ct.continuity == Continuity::C1 {
        let data = [l, t, [0.0; 3], q, dq, [0.0; 3]];
        return Column { data, rise };
    }
    let a = loop_second(ct, parent, seams, tau);
    let b = scale(child.section(ct.child_u, 2).eval(th), ell * ell);
    Column {
        data: [l, t, a, q, dq, b],
        rise,
    }
}

/// The d-th s-derivative at `s` of column `c`: cubic for `c1`, quintic
/// for `c2`. With a late depth blend (`c.rise` > 0) the depth (z) part of
/// the chord `Q - L` is weighed by [`late_weight`] instead of the basis'
/// own position weight, and the depth parts of the child's end terms `D`
/// (and `B`) by its squeezed end weights; `T` (and `A`) and the other
/// coordinates keep the basis' weights. Every late weight has the basis'
/// own end derivatives, so the column still leaves `L` along `T` and
/// enters `Q` along `D` (and for `c2` with `A`, `B`): the joins keep their
/// order of continuity (`tests/it/transition_rise.rs`).
pub fn blend(ct: &ChildTransition, c: &Column, s: f64, d: usize) -> [f64; 3] {
    let [l, t, a, q, dq, b] = c.data;
    let quintic_blend = ct.continuity != Continuity::C1;
    let (h, pos): ([f64; 6], [f64; 2]) = if quintic_blend {
        let h = quintic(s, d);
        (h, [h[0], h[3]])
    } else {
        let h = hermite(s, d);
        ([h[0], h[1], 0.0, h[2], h[3], 0.0], [h[0], h[2]])
    };
    let tangents = [t, a, dq, b]
        .iter()
        .zip([h[1], h[2], h[4], h[5]])
        .fold([0.0; 3], |acc, (v, w)| add(acc, scale(*v, w)));
    let mut out = add(tangents, add(scale(l, pos[0]), scale(q, pos[1])));
    if c.rise > 0.0 {
        // the depth part of the chord and of the child's end derivatives
        // follow the late weights instead
        let late = late_weight(s, c.rise, d, quintic_blend);
        out[2] +=
            (q[2] - l[2]) * (late[0] - pos[1]) + dq[2] * (late[1] - h[4]) + b[2] * (late[2] - h[5]);
    }
    out
}

/// Sets the per-vertex starts of `ct`'s late depth blend: `rise[0]` on the
/// loop's -z side, `rise[1]` on its +z side, interpolated by each loop
/// vertex's depth `zeta` in [-1, 1] (its z from the loop's mid-depth over
/// half the loop's depth): `s0 = rise[0] max(-zeta, 0) + rise[1] max(zeta, 0)`,
/// so the columns at the loop's sides (its seams) keep the plain blend and
/// the start varies smoothly around the loop. Both 0: none.
pub fn set_rises(ct: &mut ChildTransition, parent: &PartSurface, seams: &[Seam], rise: [f64; 2]) {
    ct.rise_vertex.clear();
    if rise.iter().all(|r| *r <= 0.0) {
        return;
    }
    let z: Vec<f64> = (0..ct.n)
        .map(|i| loop_eval(ct, parent, seams, i as f64).0[2])
        .collect();
    let (lo, hi) = z
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(*v), b.max(*v))
        });
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    if !(half > 0.0 && half.is_finite()) {
        return;
    }
    ct.rise_vertex = z
        .iter()
        .map(|v| {
            let zeta = ((v - mid) / half).clamp(-1.0, 1.0);
            rise[0].clamp(0.0, RISE_MAX) * (-zeta).max(0.0)
                + rise[1].clamp(0.0, RISE_MAX) * zeta.max(0.0)
        })
        .collect();
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
    tangent_scale: f64,
    continuity: Continuity,
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
        ell_vertex: Vec::new(),
        theta0: 0.0,
        sigma: 1.0,
        side,
        continuity,
        rise_vertex: Vec::new(),
    };
    let pts: Vec<[f64; 3]> = (0..n)
        .map(|i| loop_eval(&ct, parent, seams, i as f64).0)
        .collect();
    let cl = centroid(&pts);
    let q = child.section(child.u0, 0);
    let cq = q.c0;
    ct.ell = dist(cl, cq).max(1e-9) * tangent_scale;
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
    ct.ell_vertex = column_scales(&ct, parent, &pts, &q);
    ct
}

/// How strongly the per-column cross-tangent scale follows the column's
/// chord in a child that turns back against its parent
/// ([`column_scales`]). Measured on the closed body (README): crossing
/// triangle pairs of the base and the five checked morphs, 703 with one
/// scale, 249 at 3, 202 at 4.5, 169 at 6 (95 of them in the mitten hands,
/// which this does not touch); uncapped, 6 raised caucasian-female-young's
/// max 2.56 -> 3.06 %. With [`TURN_BACK_SCALE_MAX`] 6 leaves no shoulder
/// crossing on the base and the male bodies (at 4.5 the base kept a fold
/// at loop columns 2-3, rows 2-4, where the scale fell too slowly from the
/// back corner) and the error columns within 0.2 % of the height.
pub const TURN_BACK_EXPONENT: f64 = 6.0;

/// Largest per-column scale of a turning-back child, relative to its
/// `ell` ([`column_scales`]). At a cut the seam leaves the parent ring
/// along the parent's u-tangent, which is also the corner column's cross
/// tangent, so the corner column's first rows run along the seam; with the
/// corner's long chord the uncapped scale (up to 2.3 `ell`) pushed them
/// past the neighbouring arc column (caucasian-male-old: loop columns
/// 15-16, rows 0-1, at the front of the armpit).
pub const TURN_BACK_SCALE_MAX: f64 = 1.3;

/// Per loop vertex cross-tangent scales of a child that turns back against
/// its parent (an arm hanging from the shoulder: the parent's end tangent
/// points up, the child's ring lies below and outside the loop). With one
/// scale `ell` for every column, the columns at the loop's corners (the
/// cuts, where the parent's arc turns into a seam: the front and back of
/// the armpit) have chords to the child ring up to 1.7 times those under
/// the armpit, and their short Hermite tangents make them sweep flat across
/// the rising neighbours: the sheet folds through itself at rows 1-5
/// (`body::diagnose_self_crossings`). Here column i gets
/// `ell min((c_i / c_mean)^(TURN_BACK_EXPONENT g), TURN_BACK_SCALE_MAX)`, `c_i` its chord
/// `|Q(theta_i) - L_i|`, `c_mean` the loop's mean chord, `g = max(0, -cos)` of the angle between the parent's end
/// direction and the loop-centroid-to-ring-centre direction: 0 for a child
/// that continues the parent (legs, a head, every sketch transition: the
/// scales are then `ell`, unchanged), growing as the child turns back. The
/// cross tangents stay parallel to the parts' u-tangents, so the joins stay
/// C1 with the column's scale (measured with it) and the seams G1 (both
/// sides' tangents are still opposite modulo the seam's).
pub fn column_scales(
    ct: &ChildTransition,
    parent: &PartSurface,
    pts: &[[f64; 3]],
    ring: &crate::curve::Fourier3,
) -> Vec<f64> {
    let n = pts.len();
    let axis = scale(parent.section(ct.parent_u, 1).c0, ct.sgn);
    let towards = sub(ring.c0, centroid(pts));
    let c = dot(axis, towards) / (norm(axis) * norm(towards)).max(f64::MIN_POSITIVE);
    let g = (-c).max(0.0);
    if n == 0 || g <= 0.0 || !g.is_finite() {
        return Vec::new();
    }
    let chords: Vec<f64> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let th = ct.theta0 + ct.sigma * 2.0 * PI * i as f64 / n as f64;
            dist(*p, ring.eval(th))
        })
        .collect();
    let mean = chords.iter().sum::<f64>() / n as f64;
    if !(mean.is_finite() && mean > 0.0) {
        return Vec::new();
    }
    chords
        .iter()
        .map(|c| {
            ct.ell
                * (c / mean)
                    .max(f64::MIN_POSITIVE)
                    .powf(TURN_BACK_EXPONENT * g)
                    .min(TURN_BACK_SCALE_MAX)
        })
        .collect()
}

fn centroid(p: &[[f64; 3]]) -> [f64; 3] {
    let s = p.iter().fold([0.0; 3], |a, b| add(a, *b));
    scale(s, 1.0 / p.len().max(1) as f64)
}
/// A transition with its resolved parts, seams and child transitions.
pub(super) struct Built {
    pub(super) spec: TransitionSpec,
    pub(super) parent: usize,
    pub(super) children: Vec<usize>,
    pub(super) seams: Vec<Seam>,
    pub(super) cts: Vec<ChildTransition>,
}
