//! A humanoid's upper body as shells: the torso chained on up through the
//! neck to the top of the head, the arms as closed chains reaching into it
//! (paper 000's composition of removed parts, sec 4.1), instead of the
//! shoulders transition from the torso's end ring to three children.
//!
//! The front outline's body is what is left when each arm is cut off at
//! its root chord, from the armpit to the shoulder point the arm's trace
//! found ([`super::limb::trace_arm`]), the arm's run replaced by the chord
//! ([`split_at_root`]). The torso's region is then sliced on up to the top
//! of the head (its sections and the head's, [`BODY_SECTIONS`]), closed
//! there; its start ring stays where the stacked torso's is, so the hips
//! transition and the legs are the stacked model's. Each arm is its trace
//! from the cut on ([`super::limb::part_from_trace`]), closed by a dome
//! reaching half its width back past the body's chord's middle
//! ([`cap_start_by`]).
//!
//! Why: where the neck is nearly as wide as the torso right above it (a
//! big-headed figure's, no shoulders drawn) or the torso is short, the
//! shoulders transition's seams between the neck's arcs and the arms' run
//! up a short, crowded transition and fold (seed 4242's random_27 and
//! random_38, seed 9191's random_29: 174 to 180 degrees,
//! docs/drawing-corpus.md, thirty-fourth measurement). The build tries
//! these only when the stacked model misses issue 28's bounds and keeps
//! whichever misses them least (`pipeline::alternatives::keep_least_excess`).
//! Four cuts are tried ([`ArmCut`]): at the shoulder point, at the
//! shoulder's corner, at the corner with the arm traced on up its root to
//! it, and upright from the armpit (the body's side continued under the
//! arm's root, [`upright_top`]).
//!
//! A humanoid whose arms join the body below the crotch or just above it
//! has no torso between them to build stacked: it is built as shells
//! only ([`short_torso_models`]; before, refused).

use super::arm_cut::{arm_run, cut_tops, with_vertex};
pub use super::arm_cut::{ArmCut, ArmTrace};
use super::quadruped::root_cut::split_at_root;
use super::quadruped::shells::cap_start_by;
use super::region::{Pick, Region};
use super::segment::Landmarks;
use crate::character::doc::{Level, PartSpec, TransitionSpec};

/// The body chain's sections: the torso's and the head's
/// ([`super::section_place::SECTIONS_PER_PART`] each) less the one they
/// would share, `3 P + 1` with P = 8.
pub const BODY_SECTIONS: usize = 2 * super::section_place::SECTIONS_PER_PART - 1;

/// A model's parts and transitions.
pub type Model = (Vec<PartSpec>, Vec<TransitionSpec>);

/// `front` with each arm's run from its armpit to its shoulder point (the
/// one holding its hand) replaced by the chord between them; with the
/// other cuts, to the cut's other end instead ([`cut_tops`]). None when an
/// arm's three points are not three distinct vertices.
pub fn armless_outline(
    front: &[[f64; 2]],
    arms: &[ArmTrace],
    cut: ArmCut,
) -> Option<Vec<[f64; 2]>> {
    armless_at(front, arms, &cut_tops(front, arms, cut)?, cut)
}

/// [`armless_outline`] with the cuts' body ends `tops` (one per arm)
/// already found.
fn armless_at(
    front: &[[f64; 2]],
    arms: &[ArmTrace],
    tops: &[[f64; 2]],
    cut: ArmCut,
) -> Option<Vec<[f64; 2]>> {
    let mut poly = front.to_vec();
    for (a, &top) in arms.iter().zip(tops) {
        let t = &a.trace;
        if cut == ArmCut::Upright {
            poly = with_vertex(&poly, top);
        }
        let (p, s, forward) = arm_run(&poly, t.armpit, top, t.tip)?;
        poly = split_at_root(&poly, p, s, forward).0;
        if poly.len() < 3 {
            return None;
        }
    }
    Some(poly)
}

/// The shells a humanoid's derivation offers the build: at the
/// intermediate level (the one issue 28's bounds are for; the final
/// level's key sections sculpt the stacked parts), the arms cut off at
/// their shoulder points, then at their shoulders' corners when the trace
/// found one, then upright from their armpits ([`shell_alternative`],
/// [`ArmCut::ALL`]); the build keeps whichever model
/// misses the bounds by least. `stacked`: the derivation's parts and
/// transitions.
pub fn alternatives(
    level: Level,
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &Landmarks,
    torso: &Region,
    arms: &[ArmTrace],
    stacked: (&[PartSpec], &[TransitionSpec]),
) -> Vec<(Vec<PartSpec>, Vec<TransitionSpec>)> {
    let has_corner = arms.iter().any(|a| a.trace.corner.is_some());
    ArmCut::ALL
        .into_iter()
        .filter(|&c| level == Level::Intermediate && (c.needs_no_corner() || has_corner))
        .filter_map(|cut| shell_alternative(front, side, lm, torso, arms, stacked, cut))
        .collect()
}

/// The shells' parts and transitions (see the module docs) from the
/// stacked derivation's parts (torso, head, arms, legs, thumbs, by name)
/// and transitions and the torso's region `torso`, the arms cut
/// off as [`armless_outline`] cuts them (at the corners unless `cut` is [`ArmCut::Shoulder`]): None when the body
/// or an arm cannot be built this way.
pub fn shell_alternative(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &Landmarks,
    torso: &Region,
    arms: &[ArmTrace],
    (parts, transitions): (&[PartSpec], &[TransitionSpec]),
    cut: ArmCut,
) -> Option<(Vec<PartSpec>, Vec<TransitionSpec>)> {
    let tops = cut_tops(front, arms, cut)?;
    let outline = armless_at(front, arms, &tops, cut)?;
    let region = Region {
        name: torso.name.clone(),
        y0: torso.y0,
        y1: lm.y_max,
        pick: Pick::CentreIn(lm.armpit_l[0], lm.armpit_r[0]),
        downward: false,
        tip: true,
        shoulder: None,
        horizontal: false,
        side: torso.side,
    };
    let body =
        super::part_slices::part_with_sections(&outline, side, &region, BODY_SECTIONS).ok()?;
    let mut out = vec![body];
    for (a, &top) in arms.iter().zip(&tops) {
        // the arm from its cut on, its dome reaching back past the body's
        // chord's middle by what it would reach past its own start
        let (t, rooted) = match &a.trace.from_corner {
            Some(c) if cut == ArmCut::Rooted => (&**c, true),
            _ => (&a.trace, false),
        };
        let mut p = super::limb::part_from_trace(front, &a.name, t, 0.0, a.z).ok()?;
        let top = match cut {
            ArmCut::Rooted => t.shoulder,
            _ => top,
        };
        let mid = [
            0.5 * (t.armpit[0] + top[0]),
            0.5 * (t.armpit[1] + top[1]),
            a.z,
        ];
        // an arm traced up to its corner closes there
        let reach = if rooted {
            0.0
        } else {
            crate::mesh::dist(p.sections.first()?.centre, mid)
        };
        cap_start_by(&mut p, reach);
        out.push(p);
    }
    let replaced = |n: &str| n == region.name || n == "head" || arms.iter().any(|a| a.name == n);
    out.extend(parts.iter().filter(|p| !replaced(&p.name)).cloned());
    // the transitions whose parts are all still there (the hips)
    let kept = transitions
        .iter()
        .filter(|t| {
            t.children
                .iter()
                .all(|c| !replaced(c) && out.iter().any(|p| &p.name == c))
        })
        .cloned()
        .collect();
    Some((out, kept))
}

/// The models of a humanoid with no torso to build stacked: its arms
/// join the body below the crotch or too near above it
/// ([`Landmarks::torso_is_short`], a big-headed figure's). Only the shells
/// ([`shell_alternative`]) are built, with each cut of [`ArmCut::ALL`], the
/// first as the derivation's parts; the legs are sliced
/// from the outline without the arms (an arm's root beside the crotch is
/// not the leg's); the hips transition joins them to the body chain, whose
/// start is the stacked torso's (`regs`: the regions, torso first). At the
/// final level the key sections apply to the parts by name, a head's to
/// the body chain that holds it. Empty when no model can be built.
pub fn short_torso_models(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &Landmarks,
    regs: &[Region],
    (arms, thumbs): (&[ArmTrace], &[PartSpec]),
    keys: &[crate::character::doc::KeySection],
) -> Result<Vec<Model>, super::SketchError> {
    let has_corner = arms.iter().any(|a| a.trace.corner.is_some());
    let mut out = Vec::new();
    for cut in ArmCut::ALL
        .into_iter()
        .filter(|&c| c.needs_no_corner() || has_corner)
    {
        let Some(armless) = armless_outline(front, arms, cut) else {
            continue;
        };
        let legs: Result<Vec<PartSpec>, _> = regs
            .iter()
            .filter(|r| r.name.starts_with("leg"))
            .map(|r| super::part_slices::part_from_region(&armless, side, r))
            .collect();
        let Ok(mut rest) = legs else {
            continue;
        };
        rest.extend(thumbs.iter().cloned());
        let Some(torso) = regs.first() else {
            continue;
        };
        let Some((mut parts, mut transitions)) =
            shell_alternative(front, side, lm, torso, arms, (&rest, &[]), cut)
        else {
            continue;
        };
        let z = parts[0].sections.first().map_or(0.0, |s| s.centre[2]);
        let crotch = [lm.crotch[0], lm.crotch[1], z];
        let hips = TransitionSpec::humanoid(crotch, Vec::new(), 1.0, 1.0)
            .into_iter()
            .filter(|t| t.name == "hips")
            .map(|t| TransitionSpec {
                cap_tangents: true,
                ..t
            });
        transitions.extend(hips);
        for k in keys {
            let mut k = k.clone();
            if k.part == "head" {
                k.part = torso.name.clone();
            }
            super::keysection::apply_key_section(&mut parts, &k)?;
        }
        out.push((parts, transitions));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A T: a bar (the arm) from x = 1 to 4 at y 2..3 on a stem x 0..1,
    /// y 0..3 (counter-clockwise); the arm's armpit (1, 2), shoulder
    /// (1, 3), tip (4, 2.5).
    #[test]
    fn an_arm_is_cut_off_at_its_root_chord() {
        let front = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 2.0],
            [4.0, 2.0],
            [4.0, 3.0],
            [1.0, 3.0],
            [0.0, 3.0],
        ];
        let arm = super::super::arm_cut::fixtures::arm([1.0, 2.0], [1.0, 3.0], [4.0, 2.5]);
        let body = armless_outline(&front, &[arm], ArmCut::Corner).unwrap();
        let xmax = body.iter().map(|p| p[0]).fold(f64::MIN, f64::max);
        assert_eq!(xmax, 1.0, "{body:?}");
        assert!(crate::polygon::signed_area(&body) > 0.0, "{body:?}");
        assert_eq!(body.len(), 5, "{body:?}");
    }

    /// The upright cut leaves the body no wedge of a T-pose arm's root
    /// beyond the body's side; the shortest cut keeps it out to the
    /// shoulder point.
    #[test]
    fn an_upright_cut_leaves_the_body_no_wedge_of_the_arm_s_root() {
        use super::super::arm_cut::fixtures::t_pose;
        let xmax = |b: &[[f64; 2]]| b.iter().map(|p| p[0]).fold(f64::MIN, f64::max);
        let (front, t) = t_pose();
        let body = armless_outline(&front, &[t], ArmCut::Upright).unwrap();
        assert_eq!(xmax(&body), 1.1, "{body:?}");
        let (front, t) = t_pose();
        let body = armless_outline(&front, &[t], ArmCut::Shoulder).unwrap();
        assert_eq!(xmax(&body), 1.5, "{body:?}");
    }
}
