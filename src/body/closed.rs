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
//! measured per body (`joins::shoulder_cuts`): the fixed cuts (a third of the
//! ring per child) unless the shoulders built with them cross themselves
//! (the female armpits, where the ring runs over the upper slope of the
//! breasts); then the smallest shift of the cuts toward the arms whose
//! shoulders do not cross, within the max error target.

use super::hand::{find_hand, Hand};
pub use super::joins::{
    shifted_shoulder_cuts, shoulder_cut_angles, SHOULDER_CUT_SHIFT_MAX, SHOULDER_TANGENT_SCALE,
};
use super::joins::{shoulder_cuts, transitions};
use super::layout::{find_layout, trace, Layout, TraceOptions, TraceSample};
use super::report::measure_with_crossings;
pub use super::report::{load_body, ClosedReport, MORPH_WEIGHT_MAX};
use super::sections::{arm_picks, check_count, part_from_picks, part_from_trace, phase_towards};
pub use super::sections::{shift_phase, ClosedOptions, ARM_SPACING_SECTIONS, TORSO_PHASE};
use super::BodyError;
use crate::character::assembly::Model;
use crate::character::doc::{End, PartSpec, TransitionSpec};
use crate::mesh::topology::report as topology;
use crate::mesh::{sub, Mesh};

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

/// Reconstructs the closed body of `skin` (a standing humanoid, Y up).
pub fn reconstruct_closed(skin: &Mesh, o: &ClosedOptions) -> Result<ClosedBody, BodyError> {
    check_counts(o)?;
    check_watertight(skin)?;
    let lay = find_layout(skin)?;
    let h = lay.height();
    let step = TRACE_STEP * h;
    let t = Tracing { skin, h, step };
    let torso = torso_spec(&t, &lay, o)?;
    // the torso's start must be its bottom: u increases upwards, fine.
    let mut specs = vec![torso];
    leg_specs(&t, &lay, o, &mut specs)?;
    // arms: from the arm loop under the armpit, following the arm, to the
    // wrist; each hand a mitten and a thumb (super::hand)
    let ya = lay.arm_left[1];
    let mut arms = Arms::default();
    for (side, start) in [("l", lay.arm_left), ("r", lay.arm_right)] {
        arm_specs(&t, o, side, start, ya, &mut specs, &mut arms)?;
    }
    specs.push(head_spec(&t, &lay, o)?);
    specs.extend(arms.hand_specs);
    let mut transitions = transitions(skin, &lay, &specs)?;
    transitions.extend(arms.wrists);
    let (transitions, model, pairs) =
        shoulder_cuts(skin, &specs, transitions, h, MAX_MAX_REL, o.resolution())?;
    let mut report = measure_with_crossings(skin, &lay, &model, &specs, &arms.hands, &pairs);
    report.thumbless = arms.thumbless;
    Ok(ClosedBody {
        model,
        specs,
        transitions,
        report,
    })
}

/// Refuses a section count of `o` out of range.
fn check_counts(o: &ClosedOptions) -> Result<(), BodyError> {
    check_count("torso sections", o.torso_sections)?;
    check_count("leg sections", o.leg_sections)?;
    check_count("arm sections", o.arm_sections)?;
    check_count("head sections", o.head_sections)?;
    check_count("hand sections", o.hand_sections)?;
    check_count("thumb sections", o.thumb_sections)?;
    Ok(())
}

/// Refuses a skin that is not one closed surface.
fn check_watertight(skin: &Mesh) -> Result<(), BodyError> {
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
    Ok(())
}

/// The skin the parts are traced on, its height and the trace step.
struct Tracing<'a> {
    skin: &'a Mesh,
    h: f64,
    step: f64,
}

impl Tracing<'_> {
    /// The centre and radius of the loop nearest to `x = x_pick` in the
    /// horizontal plane at `y`.
    fn centre_at(&self, y: f64, x_pick: f64) -> Result<([f64; 3], f64), BodyError> {
        let f = crate::pde6::sampling::section_frame(y)?;
        let ls = super::layout::loops_in_plane(self.skin, &f);
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
    }

    /// Options of a trace along a fixed direction, up to `max_len`, its
    /// sections convex hulls when `hull`.
    fn straight(&self, max_len: f64, hull: bool) -> TraceOptions {
        TraceOptions::new(self.step, max_len).with_hull(hull)
    }
}

/// The torso: from the crotch plus a gap up to the armpit less a gap.
fn torso_spec(t: &Tracing, lay: &Layout, o: &ClosedOptions) -> Result<PartSpec, BodyError> {
    let (skin, h) = (t.skin, t.h);
    let y0 = lay.crotch + CROTCH_GAP * h;
    let y1 = lay.armpit - ARMPIT_GAP * h;
    let (c, r) = t.centre_at(y0, 0.0)?;
    let tt = trace(skin, c, [0.0, 1.0, 0.0], r, t.straight(y1 - y0, false))?;
    part_from_trace(
        skin,
        "torso",
        &tt,
        0.0,
        o.torso_sections,
        false,
        o,
        TORSO_PHASE,
    )
}

/// The legs, left then right, pushed to `specs`: down from the crotch less
/// a gap, each from the largest loop on its side.
fn leg_specs(
    t: &Tracing,
    lay: &Layout,
    o: &ClosedOptions,
    specs: &mut Vec<PartSpec>,
) -> Result<(), BodyError> {
    let (skin, h) = (t.skin, t.h);
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
        let tr = trace(skin, c, [0.0, -1.0, 0.0], l.radius, t.straight(h, true))?;
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
    Ok(())
}

/// What the arms add besides their own parts: the hands' parts, the wrist
/// transitions, the hands found (with their thumb arcs) and why an arm has
/// no thumb.
#[derive(Default)]
struct Arms {
    hand_specs: Vec<PartSpec>,
    wrists: Vec<TransitionSpec>,
    hands: Vec<(Hand, f64)>,
    thumbless: Vec<String>,
}

/// The trace of the arm starting at the arm loop `start` (at height `ya`),
/// following the arm.
fn arm_trace(t: &Tracing, ya: f64, start: [f64; 3]) -> Result<Vec<TraceSample>, BodyError> {
    let h = t.h;
    let (c0, r0) = t.centre_at(ya, start[0])?;
    let (c1, _) = t.centre_at(ya - 0.04 * h, start[0] + 0.5 * start[0].signum() * 0.04 * h)?;
    let d = sub(c1, c0);
    trace(
        t.skin,
        c0,
        d,
        r0,
        TraceOptions::new(t.step, h)
            .following(true)
            .with_hull(true)
            .with_skip(0.05 * h),
    )
}

/// The arm of `side`: its part pushed to `specs`, and with a thumb found
/// its hand, thumb and wrist in `arms` ([`hand_specs`]); without one the
/// whole arm is one chain ending in a mitten.
fn arm_specs(
    t: &Tracing,
    o: &ClosedOptions,
    side: &str,
    start: [f64; 3],
    ya: f64,
    specs: &mut Vec<PartSpec>,
    arms: &mut Arms,
) -> Result<(), BodyError> {
    let (skin, h) = (t.skin, t.h);
    let name = format!("arm_{side}");
    let tr = arm_trace(t, ya, start)?;
    let found = if o.thumbs {
        find_hand(skin, &tr, h, t.step)
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
            arms.thumbless.push(format!("{name}: {e}"));
            return Ok(());
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
    hand_specs(t, o, side, name, hand, arms)
}

/// The hand (palm and fingers, a mitten) and the thumb of `side` past the
/// arm `arm`'s wrist, and the wrist transition joining them to the arm.
fn hand_specs(
    t: &Tracing,
    o: &ClosedOptions,
    side: &str,
    arm: String,
    hand: Hand,
    arms: &mut Arms,
) -> Result<(), BodyError> {
    let (skin, h) = (t.skin, t.h);
    let (palm, thumb) = (format!("hand_{side}"), format!("thumb_{side}"));
    arms.hand_specs.push(part_from_trace(
        skin,
        &palm,
        &hand.palm,
        PALM_GAP * h,
        o.hand_sections,
        true,
        o,
        0.0,
    )?);
    arms.hand_specs.push(part_from_trace(
        skin,
        &thumb,
        &hand.thumb,
        0.0,
        o.thumb_sections,
        true,
        o,
        0.0,
    )?);
    arms.wrists.push(TransitionSpec {
        name: format!("wrist_{side}"),
        parent: arm,
        parent_end: End::End,
        children: vec![palm, thumb],
        seam_apex: vec![hand.apex],
        cut_angles: vec![(THUMB_ARC_SHARE * std::f64::consts::PI * hand.thumb_share)
            .clamp(THUMB_ARC_MIN, THUMB_ARC_MAX)],
        tangent_scale: WRIST_TANGENT_SCALE,
        child_tangent_scales: Vec::new(),
        continuity: Default::default(),
        cap_tangents: false,
        child_rises: Vec::new(),
    });
    arms.hands
        .push((hand, arms.wrists[arms.wrists.len() - 1].cut_angles[0]));
    Ok(())
}

/// The head: from the neck up to the crown.
fn head_spec(t: &Tracing, lay: &Layout, o: &ClosedOptions) -> Result<PartSpec, BodyError> {
    let (skin, h) = (t.skin, t.h);
    let yn = lay.neck + NECK_GAP * h;
    let (c, r) = t.centre_at(yn, 0.0)?;
    let head_trace = t.straight(h, false).with_jump(f64::INFINITY);
    let tr = trace(skin, c, [0.0, 1.0, 0.0], r, head_trace)?;
    part_from_trace(skin, "head", &tr, 0.0, o.head_sections, true, o, 0.0)
}
