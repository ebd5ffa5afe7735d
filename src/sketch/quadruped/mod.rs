//! Segmentation of a four-legged animal (body plan `quadruped`).
//!
//! **Views and axes.** The model axes follow the views, not the figure: the
//! primary profile (the "front" file, the view along z, model x-y) holds the
//! animal's **lateral silhouette**, head toward +x or -x, its legs apart
//! (2 legs, or all 4 in a walking pose); the secondary profile (the "side"
//! file, the view along x, model z-y) holds the animal **seen head-on**, its
//! left and right legs apart in z. The lateral view is the one that shows
//! the parts apart, as the view from the front does for a humanoid, so it
//! is the one segmented; svg x is model x in it and model z in the head-on
//! view, as for every drawing (`--help`).
//!
//! **Landmarks** from horizontal slices of the lateral outline, as for a
//! humanoid ([`super::segment`]): the **leg gaps** are the gap tops in the
//! lower half (where, going up, two leg intervals merge under the belly);
//! the **top gaps** are the gap tops of the outline seen upside down in the
//! upper half: the concave corners where, going down, the tail, the back and
//! the neck merge into the body. A corner found on two neighbouring slices
//! counts once, and a corner with no part rising above it (the tail's
//! underside meeting a rounded rump below a flat back) is dropped
//! (`landmarks::prune_notches`). With no such corner (one part above the
//! back: a neck, the tail hanging or absent), the back line under that
//! part is where the slices step from its width to the body's
//! (`landmarks::back_line`), and the part is the head. 1 or 3 leg gaps (2
//! or 4 legs) and 1 or 2 top gaps (tail and head, or tail, back and head;
//! or the lone head's back line) are accepted; anything else is an error
//! naming what was found.
//!
//! **Parts**, each the slice intervals of a region of heights as for a
//! humanoid, so each is a C2 pde6 chain with sections perpendicular to its
//! central curve (`derive::part_from_region`): `body` between the highest
//! leg gap and the lowest top gap (minus the join bands of half-height
//! `GAP_FRACTION` x height); the legs below the belly (hanging, closed at the
//! foot); above the body the tail, the `back` (a dome between tail and neck,
//! when the outline has one) and `head` (neck and head, closed at the top of
//! the skull). The head is the larger of the two end parts above the body
//! (a raised tail may reach higher): it says which way the animal faces
//! and so which legs are front legs.
//! **Legs**: with 4, the outer leg of each pair (farthest from the body's
//! middle) is the near one, seen from +z (the right when the animal faces
//! +x: `leg_fr`, `leg_br`), the inner one the far one (`leg_fl`, `leg_bl`);
//! with the head-on view, each takes its depth and z from the head-on
//! slice's interval on its side of the view's middle. With 2, `leg_f` and
//! `leg_b`, their depth from the whole head-on slice (first interval to
//! last, `SidePick::Span`), as the body's: at the belly the legs are still
//! apart in the head-on view. The tail is hidden in
//! the head-on view (circles, like a humanoid's arms).
//!
//! **Transitions** (`character::transition`): `underside` joins the body's
//! lower end to the legs (seams through the leg gaps), `topside` its upper
//! end to tail, back and head (seams through the top gaps). Both cut the
//! body's end ring where the seam apexes lie along it (`cut_angles`), not
//! at the humanoid's fixed angles.
//!
//! With no part above the back at all (a head level with it, in front of
//! the body: an elephant), the body's slices reach the top and close there,
//! with no `topside`, and the animal faces where the outline's centroid
//! lies from its legs' middle.
//!
//! **Hanging parts** ([`hanging`]): a tail or trunk hanging below the
//! body and ending above the ground is cut off the outline where it
//! leaves the body and built from its own outline as a separate closed
//! chain reaching into the body (`tail` behind the legs, `trunk` in front),
//! as paper 000 builds a removed part. One at the front or the back whose
//! gap with the nearest leg closes under the outline's middle (read as a
//! leg gap) is not a leg when that gap closes above the belly
//! (`landmarks::without_hanging_ends`); one hanging between the legs, or
//! leaving the body level with the belly, is refused, named.
//!
//! **Shells** ([`shells`]): below the final level the same regions are
//! also built as shells, the body chained along its own length with every
//! other part a closed chain reaching into it and no transitions; the
//! build keeps whichever model exceeds issue 28's bounds by less
//! (`pipeline::build`, `sketch::quality::excess`). The stacked body's
//! transitions fold (corpus animals: 156 to 180 degrees); the shells do
//! not on four legs, at the price of a larger miss where a drawn end is
//! blunt. Key sections sculpt the stacked body, so the final level keeps
//! it.
//!
//! Not supported yet: cuts, alignment of a tilted drawing (an animal's principal axis does not
//! say where "up" is).

pub mod hanging;
pub mod hull_section;
pub mod landmarks;
pub mod root_cut;
pub mod shells;
pub use landmarks::{landmarks, longer_than_tall, QuadLandmarks};

use super::derived::{check_side_height, e1_half_width, ring_angle, Derived};
use super::part_slices::part_from_region;
use super::segment::{interval, reach, Pick, Region, SidePick, GAP_FRACTION};
use super::SketchError;
use crate::character::doc::{BodyPlan, End, KeySection, Level, PartSpec, TransitionSpec};

/// Legs start this many join half-bands (`GAP_FRACTION` x height) below
/// their gap tops: one band leaves the leg's top section in the rounded
/// corner of the gap, whose fast widening makes the transition bulge
/// sideways (bundled animal: 20 % head-on profile error); two cut the
/// belly's corners (1.4 %).
pub const LEG_BAND: f64 = 1.5;
/// Underside cut angles are moved from where the ring reaches the seam apex
/// toward the ring's middle (90 degrees) by `1 - UNDERSIDE_CUT_BLEND`: the
/// near (outer) legs then take more of the body's flank, which the inner
/// legs' stripes otherwise sweep across to the far side, leaving a notch in
/// the head-on silhouette (bundled animal 2.1 % at 1, 0.98 % at 0.35).
pub const UNDERSIDE_CUT_BLEND: f64 = 0.35;
/// Hermite tangent factor of both transitions (shorter tangents dip less
/// below the belly between the legs: bundled animal front 1.1 % at 1,
/// 0.92 % at 0.8).
pub const TANGENT_SCALE: f64 = 0.8;

/// The body plan to segment with: `Auto` is a quadruped when the front
/// outline is longer than tall ([`longer_than_tall`]).
pub fn resolve_plan(plan: BodyPlan, front: &[[f64; 2]]) -> BodyPlan {
    match plan {
        BodyPlan::Auto if longer_than_tall(front) => BodyPlan::Quadruped,
        BodyPlan::Auto => BodyPlan::Humanoid,
        p => p,
    }
}

/// Names of the legs by x, given the facing.
fn leg_names(n: usize, facing: f64) -> Vec<&'static str> {
    let names: Vec<&str> = match n {
        2 => vec!["leg_b", "leg_f"],
        // outer legs are the near ones (seen from +z): right when facing +x
        _ => vec!["leg_br", "leg_bl", "leg_fl", "leg_fr"],
    };
    if facing > 0.0 {
        names
    } else if n == 2 {
        vec!["leg_f", "leg_b"]
    } else {
        vec!["leg_fl", "leg_fr", "leg_br", "leg_bl"]
    }
}

/// The regions of a quadruped, body first, then the legs and the parts
/// above by x. Sets `lm.facing`.
pub fn regions(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &mut QuadLandmarks,
) -> Result<Vec<Region>, SketchError> {
    let g = GAP_FRACTION * lm.height();
    let big = 1e3 * lm.height();
    let leg_top = lm.leg_gaps.iter().map(|p| p[1]).fold(f64::MIN, f64::max);
    // with nothing above the back the body reaches the top and closes there
    let closed_top = lm.top_gaps.is_empty() && lm.back_line.is_none();
    let top_low = lm
        .top_gaps
        .iter()
        .chain(&lm.back_line)
        .map(|p| p[1])
        .fold(lm.y_max + g, f64::min);
    let mut out = vec![Region {
        name: "body".into(),
        y0: leg_top + g,
        y1: top_low - g,
        pick: Pick::CentreIn(-big, big),
        downward: false,
        tip: closed_top,
        shoulder: None,
        horizontal: true,
        side: SidePick::Span,
    }];
    if let Some(b) = lm.back_line {
        lone_above(front, lm, b[1] + g, big, &mut out)?;
    } else if closed_top {
        // the head is within the body's slices
        lm.facing = facing_of_mass(front, lm);
    } else {
        above_regions(front, lm, g, big, &mut out)?;
    }
    leg_regions(front, side, lm, g, big, &mut out)?;
    for r in &out {
        if (r.y1 - r.y0).partial_cmp(&(2.0 * g)) != Some(std::cmp::Ordering::Greater) {
            return Err(SketchError::Segmentation(format!(
                "{}: too short ({:.4} between y = {:.4} and {:.4}): draw it longer",
                r.name,
                r.y1 - r.y0,
                r.y0,
                r.y1
            )));
        }
    }
    Ok(out)
}

/// +1 when the outline's centroid lies right of the middle of its leg
/// gaps: a head in front of the body, level with the back, outweighs the
/// rump behind the hind legs (the corpus elephant).
fn facing_of_mass(front: &[[f64; 2]], lm: &QuadLandmarks) -> f64 {
    let (_, c, _) = super::align::moments(front);
    let n = lm.leg_gaps.len().max(1) as f64;
    let legs = lm.leg_gaps.iter().map(|p| p[0]).sum::<f64>() / n;
    if c[0] < legs {
        -1.0
    } else {
        1.0
    }
}

/// The parts above an animal's body (tail, back, head), by x; sets
/// `lm.facing` from which end part is the larger (the head, [`region_area`]).
fn above_regions(
    front: &[[f64; 2]],
    lm: &mut QuadLandmarks,
    g: f64,
    big: f64,
    out: &mut Vec<Region>,
) -> Result<(), SketchError> {
    let mut xs = vec![-big];
    xs.extend(lm.top_gaps.iter().map(|p| p[0]));
    xs.push(big);
    let mut above = Vec::new();
    for i in 0..xs.len() - 1 {
        let pick = Pick::CentreIn(xs[i], xs[i + 1]);
        let y0 = [i.checked_sub(1), Some(i)]
            .iter()
            .flatten()
            .filter_map(|&j| lm.top_gaps.get(j))
            .map(|p| p[1])
            .fold(f64::MIN, f64::max)
            + g;
        if interval(front, pick, y0).is_none() {
            return Err(SketchError::Segmentation(format!(
                "quadruped: no outline above the corner at y = {:.4}: draw the neck and the tail rising above the back, each meeting it at a corner",
                y0 - g
            )));
        }
        let y1 = reach(front, pick, y0, lm.y_max + g);
        above.push((pick, y0, y1));
    }
    let area = |(pick, y0, y1): (Pick, f64, f64)| region_area(front, pick, y0, y1);
    let (first, last) = (area(above[0]), area(above[above.len() - 1]));
    lm.facing = if last >= first { 1.0 } else { -1.0 };
    let mut names = match above.len() {
        2 => vec!["tail", "head"],
        _ => vec!["tail", "back", "head"],
    };
    if lm.facing < 0.0 {
        names.reverse();
    }
    for ((pick, y0, y1), name) in above.into_iter().zip(names) {
        out.push(above_region(name, pick, y0, y1));
    }
    Ok(())
}

/// The one part above the body over its back line (a lone neck,
/// `landmarks::back_line`): the head, the whole slice over the back line
/// from `y0` up; the animal faces where it stands from the outline's
/// middle.
fn lone_above(
    front: &[[f64; 2]],
    lm: &mut QuadLandmarks,
    y0: f64,
    big: f64,
    out: &mut Vec<Region>,
) -> Result<(), SketchError> {
    let pick = Pick::CentreIn(-big, big);
    let Some(iv) = interval(front, pick, y0) else {
        return Err(SketchError::Segmentation(
            "quadruped: no neck rising above the back line: draw the neck rising above the back"
                .into(),
        ));
    };
    let xr = crate::polygon::span(front, 0);
    lm.facing = if iv[0] + iv[1] >= xr[0] + xr[1] {
        1.0
    } else {
        -1.0
    };
    let y1 = reach(front, pick, y0, lm.y_max + lm.height() * GAP_FRACTION);
    out.push(above_region("head", pick, y0, y1));
    Ok(())
}

/// A part above an animal's body, closed at its top; a tail is hidden in
/// the head-on view.
fn above_region(name: &str, pick: Pick, y0: f64, y1: f64) -> Region {
    Region {
        name: name.into(),
        y0,
        y1,
        pick,
        downward: false,
        tip: true,
        shoulder: None,
        horizontal: true,
        side: if name == "tail" {
            SidePick::Hidden
        } else {
            SidePick::Whole
        },
    }
}

/// The area of a region's slices between two heights (64 slices): the
/// neck and head outweigh a tail, however high the tail is raised (the
/// corpus dog's tail tip is above its head).
fn region_area(front: &[[f64; 2]], pick: Pick, y0: f64, y1: f64) -> f64 {
    let n = 64;
    let dy = (y1 - y0) / n as f64;
    (0..n)
        .filter_map(|k| interval(front, pick, y0 + (k as f64 + 0.5) * dy))
        .map(|iv| (iv[1] - iv[0]) * dy)
        .sum()
}

/// The middle of the head-on view's extent in z: a leg's pair splits
/// there (its near leg beyond it, at +z).
fn head_on_middle(side: &[[f64; 2]]) -> f64 {
    let zr = crate::polygon::span(side, 0);
    0.5 * (zr[0] + zr[1])
}

/// An animal's legs below its body, by x, named by `lm.facing`.
fn leg_regions(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &QuadLandmarks,
    g: f64,
    big: f64,
    out: &mut Vec<Region>,
) -> Result<(), SketchError> {
    let mut xs = vec![-big];
    xs.extend(lm.leg_gaps.iter().map(|p| p[0]));
    xs.push(big);
    let n = xs.len() - 1;
    let zc = side.map_or(0.0, head_on_middle);
    for (i, name) in leg_names(n, lm.facing).into_iter().enumerate() {
        let pick = Pick::CentreIn(xs[i], xs[i + 1]);
        let y1 = [i.checked_sub(1), Some(i)]
            .iter()
            .flatten()
            .filter_map(|&j| lm.leg_gaps.get(j))
            .map(|p| p[1])
            .fold(f64::MAX, f64::min)
            - LEG_BAND * g;
        if interval(front, pick, y1).is_none() {
            return Err(SketchError::Segmentation(format!(
                "{name}: no outline below its join: draw each leg reaching down from the body to the ground"
            )));
        }
        let y0 = reach(front, pick, y1, lm.y_min - g);
        let outer = i == 0 || i + 1 == n;
        let side_pick = if n == 2 {
            SidePick::Span
        } else if outer {
            SidePick::CentreIn(zc, big)
        } else {
            SidePick::CentreIn(-big, zc)
        };
        out.push(Region {
            name: name.into(),
            y0,
            y1,
            pick,
            downward: true,
            tip: true,
            shoulder: None,
            horizontal: true,
            side: side_pick,
        });
    }
    Ok(())
}

/// The body ring's cut angle for a seam apex at `x`: where the ring's e1
/// coordinate (x for the body's horizontal sections) reaches the apex, as
/// an angle in (0, pi) (front cut; the back cut mirrors it), moved toward
/// 90 degrees by `1 - blend`.
fn cut_angle(ring_centre: f64, half_width: f64, x: f64, l: f64) -> f64 {
    let a = ring_angle(ring_centre, half_width.max(f64::MIN_POSITIVE), x);
    std::f64::consts::FRAC_PI_2 + l * (a - std::f64::consts::FRAC_PI_2)
}

fn half_width(p: &PartSpec, end: End) -> (f64, f64) {
    let s = match end {
        End::Start => &p.sections[0],
        End::End => &p.sections[p.sections.len() - 1],
    };
    (s.centre[0], e1_half_width(&s.shape))
}

/// Derives a quadruped's parts and transitions from validated,
/// counter-clockwise outlines (see the module docs).
pub fn derive(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    sections: &[KeySection],
    cuts: &[super::cuts::CutPath],
    level: Level,
) -> Result<Derived, SketchError> {
    if let Some((id, _)) = cuts.first() {
        return Err(SketchError::Cut {
            id: id.clone(),
            message: "cuts are not supported for a quadruped yet".into(),
        });
    }
    let mut lm = landmarks(front)?;
    check_side_height(lm.height(), side)?;
    let side = if level == Level::Initial { None } else { side };
    let regs = regions(front, side, &mut lm)?;
    let mut parts: Vec<PartSpec> = regs
        .iter()
        .map(|r| part_from_region(front, side, r))
        .collect::<Result<Vec<_>, _>>()?;
    if level == Level::Final {
        for k in sections {
            super::keysection::apply_key_section(&mut parts, k)?;
        }
    }
    let body_z =
        parts[0].sections.iter().map(|s| s.centre[2]).sum::<f64>() / parts[0].sections.len() as f64;
    let taken: Vec<String> = parts.iter().map(|p| p.name.clone()).collect();
    let hanging = hanging::hanging_parts(front, &lm, regs[0].y0, body_z, &taken);
    let body = &parts[0];
    let z0 = body.sections[0].centre[2];
    let z1 = body.sections[body.sections.len() - 1].centre[2];
    let names = |r: &[Region]| r.iter().map(|r| r.name.clone()).collect::<Vec<_>>();
    let n_above = regs[1..].iter().filter(|r| !r.downward).count();
    let above = names(&regs[1..1 + n_above]);
    let legs = names(&regs[1 + n_above..]);
    // seams between the parts above at their corners (a lone head over
    // the back line has none)
    let seams_above = &lm.top_gaps;
    let (c0, a0) = half_width(body, End::Start);
    let (c1, a1) = half_width(body, End::End);
    let mut transitions = vec![
        TransitionSpec {
            name: "underside".into(),
            parent: "body".into(),
            parent_end: End::Start,
            children: legs,
            seam_apex: lm.leg_gaps.iter().map(|p| [p[0], p[1], z0]).collect(),
            cut_angles: lm
                .leg_gaps
                .iter()
                .map(|p| cut_angle(c0, a0, p[0], UNDERSIDE_CUT_BLEND))
                .collect(),
            tangent_scale: TANGENT_SCALE,
            child_tangent_scales: Vec::new(),
            continuity: Default::default(),
            cap_tangents: true,
            child_rises: Vec::new(),
        },
        TransitionSpec {
            name: "topside".into(),
            parent: "body".into(),
            parent_end: End::End,
            children: above,
            seam_apex: seams_above.iter().map(|p| [p[0], p[1], z1]).collect(),
            cut_angles: seams_above
                .iter()
                .map(|p| cut_angle(c1, a1, p[0], 1.0))
                .collect(),
            tangent_scale: TANGENT_SCALE,
            child_tangent_scales: Vec::new(),
            continuity: Default::default(),
            cap_tangents: true,
            child_rises: Vec::new(),
        },
    ];
    if n_above == 0 {
        transitions.pop();
    }
    // key sections sculpt the stacked body: the final level keeps it
    let alternatives = if level == Level::Final {
        Vec::new()
    } else {
        shells::alternatives(front, side, &lm, &regs, &parts, &hanging)
    };
    parts.extend(hanging);
    Ok(Derived {
        plan: BodyPlan::Quadruped,
        alignment: super::align::Alignment::identity(),
        landmarks: None,
        quadruped: Some(lm),
        parts,
        transitions,
        apex_alternatives: Vec::new(),
        alternatives,
        shells: false,
    })
}
