//! One closed body from PDE surfaces: the parts of [`super::layout`]
//! (torso, two legs, two arms, neck and head) as C2 sixth-order PDE chains
//! (`Chain::c2_global`, the sketch's [`crate::character::part`]), joined at the
//! hips (crotch) and the shoulders (armpits, neck) by the sketch's
//! transition surfaces ([`crate::character::transition`]: cubic Hermite blends
//! of the boundary curves and cross tangents of the parts, C1 on the part
//! boundaries) and assembled with shared vertices by
//! [`crate::character::build_model`] — one implementation for sketched and
//! reconstructed characters.
//!
//! Ends. The crown, the soles and the tips of the hands and thumbs are
//! closed by a collapsed ring: the last section of the chain is a point (a
//! circle of radius 0) at the extreme skin point along the part's axis, so
//! the PDE chain itself closes the part, C2 along u, and the mesh ends in a
//! pole. Feet are mittens: their sections are the convex hull of every loop
//! the section plane cuts near the axis (toes merged). The chin is not a
//! separate part: the head's horizontal sections run from the neck to the
//! crown, through the jaw.
//!
//! Hands. Each arm ends at the wrist, [`WRIST_GAP`] before the plane of
//! its trace where the thumb's loop separates from the palm's
//! ([`super::hand`]: found from the section loops, no vertex ids). A
//! **wrist transition** (`wrist_l`, `wrist_r`: the same Hermite transition
//! as the hips, one parent end ring branching into two children with a
//! seam through an apex, the crotch between thumb and index finger) joins
//! the arm's end ring to the hand (`hand_l`/`hand_r`: palm and fingers, a
//! mitten of convex hulls with the thumb's loops left out) and the thumb
//! (`thumb_l`/`thumb_r`: its own pde6 chain traced along the thumb's axis,
//! closed by a collapsed tip). The thumb is the transition's last child,
//! so it gets the wrist ring's arc around theta = 0 ([`THUMB_ARC_SHARE`],
//! `TransitionSpec::cut_angles`); the arm's sections are fitted with the
//! phase that puts theta = 0 towards the thumb (`phase_towards`). The
//! arm is a child of the shoulders and the parent of its wrist: its tube
//! switches from the shoulder loop's angles to the uniform ring halfway
//! (`character::assembly`). Separate fingers are not built: they would need a
//! branching part per finger (a transition from the palm to four tubes),
//! and the finger loops of the MakeHuman hand (a few millimetres, curled)
//! separate at planes where the palm's trace already swings.
//!
//! Shoulder cuts. Where the shoulders' seams cut the torso's end ring is
//! measured per body ([`shoulder_cuts`]): the fixed cuts (a third of the
//! ring per child) unless the shoulders built with them cross themselves
//! (the female armpits, where the ring runs over the upper slope of the
//! breasts); then the smallest shift of the cuts toward the arms whose
//! shoulders do not cross, within the max error target.

use super::hand::find_hand;
use super::intersect::{crossing_pairs, CrossingPair};
use super::layout::{find_layout, trace, Layout, TraceOptions, TraceSample};
use super::report::measure_with_crossings;
pub use super::report::{load_body, ClosedReport, MORPH_WEIGHT_MAX};
use super::BodyError;
use crate::character::assembly::{build_model_with, Model, PartCache, Resolution};
use crate::character::doc::{
    End, PartSpec, SectionShape, SectionSpec, SurfaceSpec, TransitionSpec,
};
use crate::character::ring::{cut_indices, RING_VERTICES};
use crate::curve::gec::Gec;
use crate::mesh::metrics::TriangleBvh;
use crate::mesh::topology::report as topology;
use crate::mesh::{add, dot, norm, scale, sub, Mesh};
use crate::pde6::sampling::fit_anchored;

/// Options of the closed reconstruction.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct ClosedOptions {
    /// GEC terms J per section.
    pub terms: usize,
    /// PDE parameter a of every part.
    pub a: f64,
    /// Sections per tube (7 + 3k, counting the collapsed tip where there is one).
    pub torso_sections: usize,
    pub leg_sections: usize,
    pub arm_sections: usize,
    pub head_sections: usize,
    /// Sections of each hand's palm-and-fingers mitten and of each thumb
    /// (7 + 3k, counting the collapsed tip).
    pub hand_sections: usize,
    pub thumb_sections: usize,
    /// Build each hand as a mitten and a thumb joined at the wrist (default
    /// true). Off, or where an arm's trace finds no thumb separating from the
    /// palm (a mesh with mitten hands), the whole arm is one chain ending in
    /// a mitten of convex hulls, thumb merged (the arm is then named in
    /// [`ClosedReport::thumbless`] with the reason).
    pub thumbs: bool,
    /// Anchored sampling (see [`crate::pde6::sampling`]).
    pub anchors: usize,
    pub samples: usize,
    pub pull: f64,
    /// Mesh rings per body height along the parts, rows across a transition.
    pub rings_per_height: f64,
    pub transition_rows: usize,
}

impl Default for ClosedOptions {
    fn default() -> Self {
        ClosedOptions {
            terms: 10,
            a: super::parts::BODY_A,
            torso_sections: 13,
            leg_sections: 19,
            arm_sections: 10,
            head_sections: 16,
            hand_sections: 7,
            thumb_sections: 7,
            thumbs: true,
            anchors: super::parts::DEFAULT_ANCHORS,
            samples: super::parts::DEFAULT_SAMPLES,
            pull: super::parts::DEFAULT_PULL,
            rings_per_height: 160.0,
            transition_rows: 10,
        }
    }
}

/// Targets of the reconstruction (issue 15), relative to the body height:
/// RMS and max distance in both directions, and the C1 jump at the joins.
pub const RMS_MAX_REL: f64 = 0.005;
pub const MAX_MAX_REL: f64 = 0.03;
pub const JOIN_C1_MAX: f64 = 1e-6;
/// Regression bound (not a target) on the skin -> recon max over every skin
/// vertex, cavities included: the known state is up to 3.7 % (the mouth
/// pocket of caucasian-male-old, README).
pub const FULL_SKIN_MAX_KNOWN: f64 = 0.04;

/// Bound on the skin -> recon max over the skin's thumb vertices
/// ([`super::hand::thumb_vertices`]), relative to the height: measured
/// 0.085-0.101 % on the base and the checked morphs (README).
pub const THUMB_SKIN_MAX_REL: f64 = 0.002;

/// Bundled MakeHuman morphs whose closed reconstruction is checked.
pub const CHECKED_MORPHS: &[&str] = &[
    "caucasian-male-child=1",
    "universal-male-young-averagemuscle-maxweight=1",
    "stomach-pregnant-incr=1",
    "caucasian-male-young=1",
    "universal-female-young-averagemuscle-maxweight=1",
    // within the max target on the outer skin (their full-skin max, 3.4-3.7 %,
    // sits in the mouth pocket: body::cavity)
    "caucasian-male-old=1",
    "caucasian-female-young=1",
    "african-male-young=1",
];

/// Gaps between the landmarks and the part ends, relative to the height.
pub const CROTCH_GAP: f64 = 0.03;
pub const ARMPIT_GAP: f64 = 0.005;
pub const NECK_GAP: f64 = 0.0;
/// The arm starts this far (relative to the height) along its axis from the
/// arm loop below the armpit: the shoulder between is the transition's.
pub const ARM_OFFSET: f64 = 0.04;
/// Cross-tangent scale of the shoulder transition. Measured on the base and
/// nine morphs (README): 0.7 instead of 1 flattens the Hermite bulge in
/// front of the throat (recon -> skin max of african-male-young 3.89 ->
/// 2.68 %, caucasian-female-young 3.38 -> 2.48 %,
/// universal-female-young-averagemuscle-maxweight 3.78 -> 2.80 %), at a
/// cost on the base (2.51 -> 2.94 %); 0.5 overshoots (base 3.2 %).
pub const SHOULDER_TANGENT_SCALE: f64 = 0.7;
/// The arm ends this far (relative to the height) along its trace before
/// the plane where the thumb's loop separates from the palm's
/// ([`super::hand`]); the wrist transition spans the gap.
pub const WRIST_GAP: f64 = 0.012;
/// The palm-and-fingers mitten starts this far past that plane.
pub const PALM_GAP: f64 = 0.006;
/// The wrist ring's arc given to the thumb, radians either side of the
/// thumb's direction: this factor times pi times the thumb's share of the
/// thumb's and palm's loop perimeters at the split, clamped to
/// [`THUMB_ARC_MIN`, `THUMB_ARC_MAX`]. Measured (README): at 1 (the
/// perimeter share itself, +-0.76 rad on the base) the thumb's transition
/// folded at the seam's front cut (26 crossing pairs on the base's left
/// wrist); 0.7 leaves none there.
pub const THUMB_ARC_SHARE: f64 = 0.7;
/// Cross-tangent scale of the wrist transitions. Measured with
/// [`THUMB_ARC_SHARE`] 0.7 (README): at 0.7 african-male-young kept 10
/// crossing pairs in its left wrist, caucasian-male-old 2, at 0.8 25; at
/// 0.5 and 0.6 none on the base and the checked morphs.
pub const WRIST_TANGENT_SCALE: f64 = 0.5;
pub const THUMB_ARC_MIN: f64 = std::f64::consts::PI / 16.0;
pub const THUMB_ARC_MAX: f64 = std::f64::consts::PI / 3.0;
/// The arm's sections keep the spacing of a chain of this many sections
/// (with the collapsed tip) over the whole arm trace, to the fingertips,
/// at the default 10 arm sections; `n` arm sections keep that of
/// `(n - 1) 14 / 9 + 1` fitted ones ([`arm_picks`]).
pub const ARM_SPACING_SECTIONS: usize = 16;
/// Trace step, relative to the height.
pub const TRACE_STEP: f64 = 0.004;

/// A closed reconstruction.
#[derive(Clone, Debug)]
pub struct ClosedBody {
    pub model: Model,
    pub specs: Vec<PartSpec>,
    pub transitions: Vec<TransitionSpec>,
    pub report: ClosedReport,
}

/// The GEC coefficients of `C(theta + delta)`.
pub fn shift_phase(g: &Gec, delta: f64) -> Gec {
    let mut out = g.clone();
    for n in 0..g.x.len() {
        let (c, s) = (
            ((n + 1) as f64 * delta).cos(),
            ((n + 1) as f64 * delta).sin(),
        );
        let [a, b] = g.x[n];
        out.x[n] = [a * c + b * s, b * c - a * s];
        let [a, b] = g.y[n];
        out.y[n] = [a * c - b * s, a * s + b * c];
    }
    out
}

/// Phase of the torso sections: the anchored rule puts theta = 0 at the
/// front (+z); the transitions cut the parent ring expecting theta = 0 on
/// the +x side and pi on the -x side (children ordered by x), so the torso
/// is evaluated at theta + pi / 2.
pub const TORSO_PHASE: f64 = std::f64::consts::FRAC_PI_2;

fn fit_gec(t: &TraceSample, o: &ClosedOptions, what: &str) -> Result<Gec, BodyError> {
    let terms = o.terms.min(t.plane.len().saturating_sub(1) / 2).max(1);
    // a section whose centroid sees no crossing on the start ray (a
    // crescent) falls back to its convex hull
    Ok(
        fit_anchored(&t.plane, t.frame, terms, o.anchors, o.samples, o.pull)
            .or_else(|_| {
                let h = crate::profile::shapes::convex_hull(&t.plane);
                fit_anchored(&h, t.frame, terms, o.anchors, o.samples, o.pull)
            })
            .map_err(|e| e.in_section(what))?,
    )
}

fn fit_section(
    t: &TraceSample,
    u: f64,
    o: &ClosedOptions,
    what: &str,
    phase: f64,
) -> Result<SectionSpec, BodyError> {
    let g = shift_phase(&fit_gec(t, o, what)?, phase);
    Ok(SectionSpec {
        u,
        centre: t.frame.origin,
        e1: t.frame.e1,
        e2: t.frame.e2,
        shape: SectionShape::Gec {
            centre: g.centre,
            x: g.x,
            y: g.y,
        },
    })
}

/// The phase that puts theta = 0 of the section `end` (a GEC fitted by the
/// anchored rule) on the ray from its centre towards `towards`: the wrist
/// transition gives its last child (the thumb) the arc around theta = 0.
fn phase_towards(t: &TraceSample, towards: [f64; 3], o: &ClosedOptions) -> Result<f64, BodyError> {
    let g = fit_gec(t, o, "the arm's end section")?;
    let (q, _) = t.frame.project(towards);
    let v = [q[0] - g.centre[0], q[1] - g.centre[1]];
    let steps = 1440;
    let best = (0..steps)
        .map(|i| 2.0 * std::f64::consts::PI * i as f64 / steps as f64)
        .max_by(|&a, &b| {
            let c = |th: f64| {
                let p = g.eval_plane(th);
                let w = [p[0] - g.centre[0], p[1] - g.centre[1]];
                (w[0] * v[0] + w[1] * v[1])
                    / (w[0].hypot(w[1]) * v[0].hypot(v[1])).max(f64::MIN_POSITIVE)
            };
            c(a).total_cmp(&c(b))
        })
        .unwrap_or(0.0);
    Ok(best)
}

/// Picks `n` samples evenly in s over [s0, last] (nearest, strictly increasing).
fn pick(tr: &[TraceSample], s0: f64, n: usize, what: &str) -> Result<Vec<usize>, BodyError> {
    let first = tr.iter().position(|t| t.s >= s0);
    let last = tr.len().checked_sub(1);
    let (Some(first), Some(last)) = (first, last) else {
        return Err(BodyError::LayoutNotFound {
            what: "a limb",
            detail: format!("{what}: the trace found no sections"),
        });
    };
    if last < first + n {
        return Err(BodyError::LayoutNotFound {
            what: "a limb",
            detail: format!(
                "{what}: the trace found {} sections, {n} needed",
                last + 1 - first.min(last)
            ),
        });
    }
    let (a, b) = (tr[first].s, tr[last].s);
    let mut out: Vec<usize> = Vec::with_capacity(n);
    for i in 0..n {
        let s = a + (b - a) * i as f64 / (n - 1) as f64;
        let mut k = (first..=last)
            .min_by(|&x, &y| (tr[x].s - s).abs().total_cmp(&(tr[y].s - s).abs()))
            .unwrap_or(first);
        if let Some(&p) = out.last() {
            k = k.max(p + 1);
        }
        out.push(k.min(last));
    }
    out.dedup();
    if out.len() < n {
        return Err(BodyError::LayoutNotFound {
            what: "a limb",
            detail: format!("{what}: too few distinct sections"),
        });
    }
    Ok(out)
}

/// The farthest skin point along `d` from `c` within `r` of the axis.
fn tip(m: &Mesh, c: [f64; 3], d: [f64; 3], r: f64) -> [f64; 3] {
    let mut best = 0.0f64;
    for p in &m.positions {
        let v = sub(*p, c);
        let a = dot(v, d);
        let perp = norm(sub(v, scale(d, a)));
        if perp <= r && a > best {
            best = a;
        }
    }
    add(c, scale(d, best))
}

/// Builds a part from a trace: `n` sections (the last a collapsed tip when
/// `tip_end`).
#[allow(clippy::too_many_arguments)]
fn part_from_trace(
    m: &Mesh,
    name: &str,
    tr: &[TraceSample],
    s0: f64,
    n: usize,
    tip_end: bool,
    o: &ClosedOptions,
    phase: f64,
) -> Result<PartSpec, BodyError> {
    let fitted = if tip_end { n - 1 } else { n };
    let idx = pick(tr, s0, fitted, name)?;
    part_from_picks(m, name, tr, &idx, tip_end, o, phase)
}

/// [`part_from_trace`] with the trace samples of the fitted sections given.
fn part_from_picks(
    m: &Mesh,
    name: &str,
    tr: &[TraceSample],
    idx: &[usize],
    tip_end: bool,
    o: &ClosedOptions,
    phase: f64,
) -> Result<PartSpec, BodyError> {
    let fitted = idx.len();
    let n = if tip_end { fitted + 1 } else { fitted };
    let mut sections = Vec::with_capacity(n);
    for (i, &k) in idx.iter().enumerate() {
        sections.push(fit_section(
            &tr[k],
            tr[k].s,
            o,
            &format!("{name} section {i}"),
            phase,
        )?);
    }
    if tip_end {
        let last = &tr[idx[fitted - 1]];
        let d = last.frame.normal();
        let c = last.frame.origin;
        let p = tip(m, c, d, last.radius);
        let gap = dot(sub(p, c), d);
        let gap = gap.max(0.25 * (tr[idx[1]].s - tr[idx[0]].s));
        sections.push(SectionSpec {
            u: last.s + gap,
            centre: add(c, scale(d, gap)),
            e1: last.frame.e1,
            e2: last.frame.e2,
            shape: SectionShape::Circle { r: 0.0 },
        });
    }
    Ok(PartSpec {
        name: name.into(),
        surface: SurfaceSpec::Pde6C2 { a: o.a },
        sections,
        closed_start: false,
        closed_end: tip_end,
    })
}

/// The arm's sections: the first `n - 1` where a chain of
/// [`ARM_SPACING_SECTIONS`] sections over the whole trace (wrist, hand and
/// fingers: the arm of the mitten body; scaled for other `n`) has them, and
/// the last at the wrist
/// (`end` samples of `tr` are the arm's). The shoulder transition then sees
/// the arm it was tuned on (its crossings depend on the arm's first
/// sections: 10 sections spread evenly to the wrist left 2 crossing pairs
/// at the shoulders of caucasian-male-child and caucasian-male-old). Falls
/// back to `n` sections evenly to the wrist when the wrist comes before
/// the `n - 1`-th of those.
fn arm_picks(
    tr: &[TraceSample],
    end: usize,
    s0: f64,
    n: usize,
    what: &str,
) -> Result<Vec<usize>, BodyError> {
    let arm = &tr[..end];
    let even = || pick(arm, s0, n, what);
    let m = ((n.saturating_sub(1) * (ARM_SPACING_SECTIONS - 2)) as f64 / 9.0).round() as usize + 1;
    let Ok(whole) = pick(tr, s0, m, what) else {
        return even();
    };
    if n < 2 || whole.len() < n || whole[n - 2] + 1 >= end {
        return even();
    }
    let mut idx = whole[..n - 1].to_vec();
    idx.push(end - 1);
    Ok(idx)
}

fn check_count(what: &'static str, n: usize) -> Result<(), BodyError> {
    if n < 7 || (n - 7) % 3 != 0 || n > 7 + 3 * 30 {
        return Err(BodyError::SectionCount { what, got: n });
    }
    Ok(())
}

/// Reconstructs the closed body of `skin` (a standing humanoid, Y up).
pub fn reconstruct_closed(skin: &Mesh, o: &ClosedOptions) -> Result<ClosedBody, BodyError> {
    check_count("torso sections", o.torso_sections)?;
    check_count("leg sections", o.leg_sections)?;
    check_count("arm sections", o.arm_sections)?;
    check_count("head sections", o.head_sections)?;
    check_count("hand sections", o.hand_sections)?;
    check_count("thumb sections", o.thumb_sections)?;
    let topo = topology(skin);
    if !topo.watertight {
        return Err(BodyError::LayoutNotFound {
            what: "a closed body",
            detail: format!(
                "open mesh: {} boundary edges, {} non-manifold edges (the skin must be one closed surface)",
                topo.boundary_edges, topo.nonmanifold_edges
            ),
        });
    }
    let lay = find_layout(skin)?;
    let h = lay.height();
    let step = TRACE_STEP * h;
    let centre_at = |y: f64, x_pick: f64| -> Result<([f64; 3], f64), BodyError> {
        let f = crate::pde6::sampling::section_frame(y)?;
        let ls = super::layout::loops_in_plane(skin, &f);
        let l = ls
            .iter()
            .min_by(|a, b| {
                (a.centroid[0] - x_pick)
                    .abs()
                    .total_cmp(&(b.centroid[0] - x_pick).abs())
            })
            .ok_or_else(|| BodyError::LayoutNotFound {
                what: "a section",
                detail: format!("no loop at y = {y:.3}"),
            })?;
        Ok((f.place(l.centroid[0], l.centroid[1]), l.radius))
    };
    let straight = |max_len: f64, hull: bool| TraceOptions {
        step,
        max_len,
        follow: false,
        hull,
        skip: 0.0,
        jump: super::layout::JUMP,
    };
    // torso: crotch + gap up to armpit - gap
    let y0 = lay.crotch + CROTCH_GAP * h;
    let y1 = lay.armpit - ARMPIT_GAP * h;
    let (c, r) = centre_at(y0, 0.0)?;
    let tt = trace(skin, c, [0.0, 1.0, 0.0], r, straight(y1 - y0, false))?;
    let torso = part_from_trace(
        skin,
        "torso",
        &tt,
        0.0,
        o.torso_sections,
        false,
        o,
        TORSO_PHASE,
    )?;
    // the torso's start must be its bottom: u increases upwards, fine.
    let mut specs = vec![torso];
    // legs: down from crotch - gap
    let yl = lay.crotch - CROTCH_GAP * h;
    for (name, x) in [("leg_l", -1.0), ("leg_r", 1.0)] {
        let f = crate::pde6::sampling::section_frame(yl)?;
        let ls = super::layout::loops_in_plane(skin, &f);
        let l = ls
            .iter()
            .filter(|l| l.centroid[0] * x > 0.0)
            .max_by(|a, b| a.radius.total_cmp(&b.radius))
            .ok_or_else(|| BodyError::LayoutNotFound {
                what: "a leg",
                detail: format!("{name}: no loop at y = {yl:.3}"),
            })?;
        let c = f.place(l.centroid[0], l.centroid[1]);
        let tr = trace(skin, c, [0.0, -1.0, 0.0], l.radius, straight(h, true))?;
        specs.push(part_from_trace(
            skin,
            name,
            &tr,
            0.0,
            o.leg_sections,
            true,
            o,
            0.0,
        )?);
    }
    // arms: from the arm loop under the armpit, following the arm, to the
    // wrist; each hand a mitten and a thumb (super::hand)
    let ya = lay.arm_left[1];
    let mut hand_specs = Vec::new();
    let mut wrists = Vec::new();
    let mut hands = Vec::new();
    let mut thumbless = Vec::new();
    for (side, start) in [("l", lay.arm_left), ("r", lay.arm_right)] {
        let name = format!("arm_{side}");
        let (c0, r0) = centre_at(ya, start[0])?;
        let (c1, _) = centre_at(ya - 0.04 * h, start[0] + 0.5 * start[0].signum() * 0.04 * h)?;
        let d = sub(c1, c0);
        let tr = trace(
            skin,
            c0,
            d,
            r0,
            TraceOptions {
                step,
                max_len: h,
                follow: true,
                hull: true,
                skip: 0.05 * h,
                jump: super::layout::JUMP,
            },
        )?;
        let found = if o.thumbs {
            find_hand(skin, &tr, h, step)
        } else {
            Err(BodyError::LayoutNotFound {
                what: "a thumb",
                detail: "thumbs off (ClosedOptions::thumbs)".into(),
            })
        };
        let hand = match found {
            Ok(hand) => hand,
            Err(e) => {
                // no thumb: the whole arm one chain ending in a mitten
                specs.push(part_from_trace(
                    skin,
                    &name,
                    &tr,
                    ARM_OFFSET * h,
                    o.arm_sections,
                    true,
                    o,
                    0.0,
                )?);
                thumbless.push(format!("{name}: {e}"));
                continue;
            }
        };
        let s_end = tr[hand.split].s - WRIST_GAP * h;
        let arm: Vec<TraceSample> = tr.iter().take_while(|t| t.s <= s_end).cloned().collect();
        let last = arm.last().ok_or_else(|| BodyError::LayoutNotFound {
            what: "a wrist",
            detail: format!("{name}: the thumb separates at the start of the arm's trace"),
        })?;
        let phase = phase_towards(last, hand.track[0].0, o)?;
        let idx = arm_picks(&tr, arm.len(), ARM_OFFSET * h, o.arm_sections, &name)?;
        specs.push(part_from_picks(skin, &name, &tr, &idx, false, o, phase)?);
        let (palm, thumb) = (format!("hand_{side}"), format!("thumb_{side}"));
        hand_specs.push(part_from_trace(
            skin,
            &palm,
            &hand.palm,
            PALM_GAP * h,
            o.hand_sections,
            true,
            o,
            0.0,
        )?);
        hand_specs.push(part_from_trace(
            skin,
            &thumb,
            &hand.thumb,
            0.0,
            o.thumb_sections,
            true,
            o,
            0.0,
        )?);
        wrists.push(TransitionSpec {
            name: format!("wrist_{side}"),
            parent: name,
            parent_end: End::End,
            children: vec![palm, thumb],
            seam_apex: vec![hand.apex],
            cut_angles: vec![(THUMB_ARC_SHARE * std::f64::consts::PI * hand.thumb_share)
                .clamp(THUMB_ARC_MIN, THUMB_ARC_MAX)],
            tangent_scale: WRIST_TANGENT_SCALE,
            continuity: Default::default(),
        });
        hands.push((hand, wrists[wrists.len() - 1].cut_angles[0]));
    }
    // head: from the neck up to the crown
    let yn = lay.neck + NECK_GAP * h;
    let (c, r) = centre_at(yn, 0.0)?;
    let head_trace = TraceOptions {
        jump: f64::INFINITY,
        ..straight(h, false)
    };
    let tr = trace(skin, c, [0.0, 1.0, 0.0], r, head_trace)?;
    specs.push(part_from_trace(
        skin,
        "head",
        &tr,
        0.0,
        o.head_sections,
        true,
        o,
        0.0,
    )?);
    specs.extend(hand_specs);
    let mut transitions = transitions(skin, &lay, &specs)?;
    transitions.extend(wrists);
    let (transitions, model, pairs) = shoulder_cuts(
        skin,
        &specs,
        transitions,
        h,
        Resolution {
            rings_per_height: o.rings_per_height,
            transition_rows: o.transition_rows,
        },
    )?;
    let mut report = measure_with_crossings(skin, &lay, &model, &specs, &hands, &pairs);
    report.thumbless = thumbless;
    Ok(ClosedBody {
        model,
        specs,
        transitions,
        report,
    })
}

/// How far (ring vertices of [`RING_VERTICES`]) [`shoulder_cuts`] may move
/// each shoulder cut from the fixed angles toward its arm: 5 of 48 keeps at
/// least a third of the end ring between an arm's cuts.
pub const SHOULDER_CUT_SHIFT_MAX: usize = 5;

/// The shoulders' cut indices with seam 1's back cut moved `a` and its
/// front cut `b` ring vertices toward the left arm, seam 2's mirrored toward
/// the right arm, as `[(front, back); 2]` in
/// [`crate::character::ring::cut_table`]'s order. Ring index 0 is +x, and
/// the indices (0, n / 2) lie behind the torso (z < 0), (n / 2, n) in front.
pub fn shifted_shoulder_cuts(a: usize, b: usize) -> [(usize, usize); 2] {
    let (f1, b1) = cut_indices(1, 3, &[]);
    let (f2, b2) = cut_indices(2, 3, &[]);
    [(f1 + a, b1 - b), (f2 - a, b2 + b)]
}

/// `cuts` as `TransitionSpec::cut_angles` (the angles of the cuts in
/// (0, pi), then those in (pi, 2 pi)).
pub fn shoulder_cut_angles(cuts: [(usize, usize); 2]) -> Vec<f64> {
    let a = |i: usize| 2.0 * std::f64::consts::PI * i as f64 / RING_VERTICES as f64;
    vec![a(cuts[0].0), a(cuts[1].0), a(cuts[0].1), a(cuts[1].1)]
}

/// Crossing pairs with a triangle in the shoulders transition, the largest
/// distance (relative to the height) from its vertices and triangle
/// centroids to the skin, and every crossing pair of `m` (for the report).
fn shoulder_state(skin_bvh: &TriangleBvh, m: &Mesh, h: f64) -> (usize, f64, Vec<CrossingPair>) {
    let pairs = crossing_pairs(m);
    let Some(g) = m.groups.iter().position(|g| g == "shoulders") else {
        return (0, 0.0, pairs);
    };
    let g = g as u32;
    let crossings = pairs
        .iter()
        .filter(|&&(t, u, _)| m.tri_group[t] == g || m.tri_group[u] == g)
        .count();
    let mut far = 0.0f64;
    for (t, tri) in m.triangles.iter().enumerate() {
        if m.tri_group[t] != g {
            continue;
        }
        let [a, b, c] = tri.map(|v| m.positions[v as usize]);
        for p in [a, b, c, scale(add(add(a, b), c), 1.0 / 3.0)] {
            if let Some(hit) = skin_bvh.closest(p) {
                far = far.max(hit.1);
            }
        }
    }
    (crossings, far / h, pairs)
}

/// The shoulders' cuts of one body, measured (issue 15's female armpits).
///
/// With the fixed cuts (`pi - j pi / 3`) the arm's loop starts at a third
/// of the torso's end ring from the side. On the female chests that ring
/// runs over the upper slope of the breasts, where the torso's u-tangent
/// (the loop's cross tangent there, for C1) points up, back and in and is
/// up to 3 times as long as elsewhere; the arm's front columns leave the
/// ring toward the midline and turn back out to the arm ring, across one
/// another, and the back corner likewise. Where the cuts should go differs
/// per body and is not monotonic in the cut (README, Self-intersections:
/// moving them one vertex can double the crossings), so the cuts are
/// measured: when the shoulders built with the fixed cuts have a crossing
/// pair, every shift `(a, b)` of the back and front cut toward the arm
/// (0..=[`SHOULDER_CUT_SHIFT_MAX`] each, seam 2 mirrored) is built, the
/// smallest total shift with no crossing pair in the shoulders wins, else
/// the fewest pairs; a candidate is admitted only when the shoulders'
/// distance to the skin stays within the max target ([`MAX_MAX_REL`]; a
/// larger head loop bulges more in front of the throat) or within that of
/// the fixed cuts. Bodies whose shoulders do not cross (the base, the male
/// bodies) keep the fixed cuts untouched. Returns the chosen transitions
/// and model, and the model's crossing pairs.
fn shoulder_cuts(
    skin: &Mesh,
    specs: &[PartSpec],
    mut transitions: Vec<TransitionSpec>,
    h: f64,
    res: Resolution,
) -> Result<(Vec<TransitionSpec>, Model, Vec<CrossingPair>), BodyError> {
    let mut cache = PartCache::default();
    let model = build_model_with(specs, &transitions, h, res, &[], Some(&mut cache))?;
    let bvh = TriangleBvh::new(skin);
    let (x0, far0, pairs0) = shoulder_state(&bvh, &model.mesh, h);
    let shoulders = transitions.iter().position(|t| t.name == "shoulders");
    let Some(k) = shoulders.filter(|_| x0 > 0) else {
        return Ok((transitions, model, pairs0));
    };
    let bound = MAX_MAX_REL.max(far0);
    let mut shifts: Vec<(usize, usize)> = (0..=SHOULDER_CUT_SHIFT_MAX)
        .flat_map(|a| (0..=SHOULDER_CUT_SHIFT_MAX).map(move |b| (a, b)))
        .filter(|&s| s != (0, 0))
        .collect();
    shifts.sort_by_key(|&(a, b)| (a + b, a));
    type Best = (usize, Vec<f64>, Option<(Model, Vec<CrossingPair>)>);
    let mut best: Best = (x0, Vec::new(), None);
    for (a, b) in shifts {
        let mut tr = transitions.clone();
        tr[k].cut_angles = shoulder_cut_angles(shifted_shoulder_cuts(a, b));
        let m = build_model_with(specs, &tr, h, res, &[], Some(&mut cache))?;
        let (x, far, pairs) = shoulder_state(&bvh, &m.mesh, h);
        if x < best.0 && far <= bound {
            best = (x, tr[k].cut_angles.clone(), Some((m, pairs)));
            if x == 0 {
                break;
            }
        }
    }
    match best {
        (_, angles, Some((m, pairs))) => {
            transitions[k].cut_angles = angles;
            Ok((transitions, m, pairs))
        }
        _ => Ok((transitions, model, pairs0)),
    }
}

/// The hips and shoulders transitions with their seam apexes: the crotch,
/// and the top of each shoulder halfway between the neck and the outer
/// shoulder.
fn transitions(
    skin: &Mesh,
    lay: &Layout,
    specs: &[PartSpec],
) -> Result<Vec<TransitionSpec>, BodyError> {
    let h = lay.height();
    let bottom = specs[0].sections[0].centre;
    let top = specs[0].sections[specs[0].sections.len() - 1].centre;
    let crotch = [bottom[0], lay.crotch, bottom[2]];
    let neck_f = crate::pde6::sampling::section_frame(lay.neck)?;
    let neck = super::layout::loops_in_plane(skin, &neck_f);
    let neck_x = neck
        .iter()
        .min_by(|a, b| a.centroid[0].abs().total_cmp(&b.centroid[0].abs()))
        .map(|l| l.x_range)
        .ok_or_else(|| BodyError::LayoutNotFound {
            what: "the neck",
            detail: format!("no loop at y = {:.3}", lay.neck),
        })?;
    let mut apex = Vec::new();
    for (sign, arm) in [(-1.0, lay.arm_left), (1.0, lay.arm_right)] {
        let nx = if sign < 0.0 { neck_x.0 } else { neck_x.1 };
        let x = 0.5 * (nx + arm[0]);
        let band = 0.01 * h;
        let y = skin
            .positions
            .iter()
            .filter(|p| (p[0] - x).abs() < band && p[1] < lay.neck && p[1] > lay.armpit)
            .map(|p| p[1])
            .fold(f64::NAN, f64::max);
        if !y.is_finite() {
            return Err(BodyError::LayoutNotFound {
                what: "a shoulder top",
                detail: format!("no skin vertex near x = {x:.3} between the armpits and the neck"),
            });
        }
        apex.push([x, y, top[2]]);
    }
    Ok(vec![
        TransitionSpec {
            name: "hips".into(),
            parent: "torso".into(),
            parent_end: End::Start,
            children: vec!["leg_l".into(), "leg_r".into()],
            seam_apex: vec![crotch],
            cut_angles: Vec::new(),
            tangent_scale: 1.0,
            continuity: Default::default(),
        },
        TransitionSpec {
            name: "shoulders".into(),
            parent: "torso".into(),
            parent_end: End::End,
            children: vec!["arm_l".into(), "head".into(), "arm_r".into()],
            seam_apex: apex,
            // measured per body by shoulder_cuts
            cut_angles: Vec::new(),
            tangent_scale: SHOULDER_TANGENT_SCALE,
            continuity: Default::default(),
        },
    ])
}
