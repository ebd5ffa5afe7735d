//! From outlines to the document's derived parts: key sections per part
//! (circles, ellipses with the side profile, GEC fits of key cross-section
//! sketches) and the transitions.

use super::align::{alignment, Alignment};
use super::cuts::{join_heights, CutPath};
use super::humanoid_shells::ArmTrace;
use super::poly::slice;
use super::segment::{landmarks, regions, Landmarks};
use super::SketchError;
use crate::character::doc::{
    BodyPlan, KeySection, Level, PartSpec, SectionShape, SectionSpec, TransitionSpec,
};
use std::f64::consts::{FRAC_PI_3, TAU};

pub(super) use super::derived::{check_side_height, check_side_position};
use super::derived::{e1_half_width, ring_angle};
pub use super::derived::{ApexAlternative, Derived, HEIGHT_MISMATCH};
pub use super::keysection::{GEC_TERMS, SECTION_SLACK};
pub(super) use super::part_slices::part_from_region;
pub use super::part_slices::{SHOULDER_TILT_DEG, SHOULDER_TILT_SECTIONS};
pub use super::section_place::SECTIONS_PER_PART;

/// Derives parts and transitions from validated, counter-clockwise outlines
/// with the given body plan ([`super::quadruped::resolve_plan`]). A humanoid's front outline
/// drawn a few degrees off upright is derived upright and the result turned
/// back ([`super::align`]); a quadruped is segmented as drawn
/// ([`super::quadruped`]).
pub fn derive(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    sections: &[KeySection],
    cuts: &[CutPath],
    level: Level,
    plan: BodyPlan,
) -> Result<Derived, SketchError> {
    check_side_position(front, side)?;
    if super::quadruped::resolve_plan(plan, front) == BodyPlan::Quadruped {
        return super::quadruped::derive(front, side, sections, cuts, level).map_err(|e| {
            // asked for a quadruped: its refusal stands
            let turn = (plan == BodyPlan::Auto)
                .then(|| lying_figure(front))
                .flatten();
            match turn {
                Some(t) => lying_error(t, &e.to_string()),
                None => e,
            }
        });
    }
    let ax = super::align::axes(front);
    if ax.anisotropy >= super::align::MIN_ANISOTROPY && ax.major.abs() < std::f64::consts::FRAC_PI_4
    {
        if let Some(turn) = lying_figure(front) {
            return Err(lying_error(turn, ""));
        }
        return Err(SketchError::Segmentation(format!(
            "the front outline is longer than tall (principal axis {:.0} degrees from horizontal), as a four-legged animal's, \
             but the humanoid body plan was asked for: use body plan auto or quadruped (--body-plan, inputs.body_plan)",
            ax.major.to_degrees().abs()
        )));
    }
    let al = alignment(front)?;
    if al.is_identity() {
        return derive_upright(front, side, sections, cuts, level);
    }
    let up: Vec<[f64; 2]> = front.iter().map(|p| al.to_upright(*p)).collect();
    let cuts: Vec<CutPath> = cuts
        .iter()
        .map(|(id, c)| (id.clone(), c.iter().map(|p| al.to_upright(*p)).collect()))
        .collect();
    let keys: Vec<KeySection> = sections
        .iter()
        .map(|k| {
            let mx = k.points.iter().map(|p| p[0]).sum::<f64>() / k.points.len().max(1) as f64;
            let c = al.to_upright([mx, k.y]);
            KeySection {
                part: k.part.clone(),
                y: c[1],
                points: k.points.iter().map(|p| [p[0] + c[0] - mx, p[1]]).collect(),
            }
        })
        .collect();
    let mut d = derive_upright(&up, side, &keys, &cuts, level)?;
    turn_back(&al, &mut d.parts, &mut d.transitions);
    for (parts, transitions) in &mut d.alternatives {
        turn_back(&al, parts, transitions);
    }
    for a in &mut d.apex_alternatives {
        a.apex = al.point_back(a.apex);
    }
    d.alignment = al;
    Ok(d)
}

/// Parts and transitions derived upright turned back by `al`.
fn turn_back(al: &Alignment, parts: &mut [PartSpec], transitions: &mut [TransitionSpec]) {
    for p in parts {
        let leg = p.name.starts_with("leg");
        for s in &mut p.sections {
            // a foot's sections (`super::foot`) have the side view's
            // heights, drawn level: turned with the front, one foot sank
            // below the ground and the other rose (seed 9191's random_11,
            // random_37: 1.0-1.1 % of the height). Their heights stay as
            // the side view has them, the bend's in proportion to its
            // turn (the sine of its plane's tilt from horizontal, 0 at the
            // ankle's ring, 1 along the foot)
            let w = if leg { s.e2[1].abs().min(1.0) } else { 0.0 };
            let y = s.centre[1];
            s.centre = al.point_back(s.centre);
            s.centre[1] += w * (y - s.centre[1]);
            s.e1 = al.vector_back(s.e1);
            s.e2 = al.vector_back(s.e2);
        }
    }
    for t in transitions {
        for a in &mut t.seam_apex {
            *a = al.point_back(*a);
        }
    }
}

/// Which way a front outline longer than tall would be turned to stand
/// as a humanoid: `Some("counter-clockwise")` when, turned by 90 degrees
/// that way, it has a crotch, two armpits and a torso between them
/// ([`landmarks`]); a standing figure drawn lying on its side.
fn lying_figure(front: &[[f64; 2]]) -> Option<&'static str> {
    // turning by +90 degrees (counter-clockwise), then by -90
    [("counter-clockwise", 1.0), ("clockwise", -1.0)]
        .into_iter()
        .find_map(|(name, s): (&'static str, f64)| {
            let up: Vec<[f64; 2]> = front.iter().map(|p| [-s * p[1], s * p[0]]).collect();
            let lm = landmarks(&up).ok()?;
            (!lm.torso_is_short()).then_some(name)
        })
}

/// The refusal of a figure lying down ([`lying_figure`]); `animal`: why it
/// is not a four-legged animal either (empty: not tried).
fn lying_error(turn: &str, animal: &str) -> SketchError {
    let why = if animal.is_empty() {
        String::new()
    } else {
        let animal = animal.trim_start_matches("segmentation: ");
        format!(" (read as a four-legged animal's side view: {animal})")
    };
    SketchError::Segmentation(format!(
        "the front outline is a standing figure lying on its side: turned 90 degrees {turn} it has a crotch, \
         two armpits and a head{why}; draw the figure upright, feet on the ground line"
    ))
}

/// Why [`traced_arms`] failed: one arm's own refusal (`right`: whether
/// the right arm's) or the drawing's (`None`: no neck).
struct ArmsError {
    right: Option<bool>,
    error: SketchError,
}

impl From<ArmsError> for SketchError {
    fn from(e: ArmsError) -> SketchError {
        e.error
    }
}

/// The two arms traced from the armpits ([`super::limb`]): their parts
/// and their traces (left, right). An arm starts a
/// join band ([`super::segment::GAP_FRACTION`] of the height) out from its
/// cut, or where a user's cut path crosses it.
fn traced_arms(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &Landmarks,
    joins: &super::cuts::JoinHeights,
) -> Result<(Vec<PartSpec>, Vec<ArmTrace>), ArmsError> {
    let g = super::segment::GAP_FRACTION * lm.height();
    let neck = super::segment::neck_interval(front, lm).ok_or_else(|| ArmsError {
        right: None,
        error: SketchError::Segmentation(
            "no neck found above the armpits: draw the head on a neck narrower than the shoulders, above both arms".into(),
        ),
    })?;
    // hidden in the side view: the arms hang at the torso's centre depth
    // at the armpits' height
    let ya = lm.armpit_l[1].min(lm.armpit_r[1]);
    let z = side
        .and_then(|sd| {
            let s = slice(sd, ya);
            Some(0.5 * (s.first()?[0] + s.last()?[1]))
        })
        .unwrap_or(0.0);
    let mut parts = Vec::new();
    let mut traces = Vec::new();
    for (name, armpit, sign, neck_x) in [
        ("arm_l", lm.armpit_l, -1.0, neck[0]),
        ("arm_r", lm.armpit_r, 1.0, neck[1]),
    ] {
        let arm = |error| ArmsError {
            right: Some(sign > 0.0),
            error,
        };
        let t = super::limb::trace_arm(front, armpit, sign, neck_x, name).map_err(arm)?;
        let cut_mid = [
            0.5 * (t.armpit[0] + t.shoulder[0]),
            0.5 * (t.armpit[1] + t.shoulder[1]),
        ];
        let start = match joins.limb(name) {
            // the arc length along the traced axis to where its centre
            // passes the cut's height
            Some(yc) => {
                let mut s = 0.0;
                let mut prev = cut_mid;
                let mut found = None;
                for c in &t.centre {
                    s += (c[0] - prev[0]).hypot(c[1] - prev[1]);
                    prev = *c;
                    if c[1] <= yc {
                        found = Some(s);
                        break;
                    }
                }
                found.unwrap_or(g)
            }
            None => g,
        };
        parts.push(super::limb::part_from_trace(front, name, &t, start, z).map_err(arm)?);
        parts.extend(thumb_part(&t, name, z));
        traces.push(ArmTrace {
            name: name.into(),
            trace: t,
            z,
        });
    }
    Ok((parts, traces))
}

/// A traced arm's thumb ([`super::thumb`]) as a separate closed chain at
/// the arm's depth `z`, named after the arm (`thumb_l`, `thumb_r`); none
/// when the arm has no thumb or its outline gives no chain (the arm is
/// built without it, as a mitten).
fn thumb_part(t: &super::limb::TracedArm, arm: &str, z: f64) -> Option<PartSpec> {
    let name = arm.replacen("arm", "thumb", 1);
    let mut spec = super::removed::upright_chain(&name, t.thumb.as_deref()?, None).ok()?;
    for s in &mut spec.sections {
        s.centre[2] += z;
    }
    Some(spec)
}

fn derive_upright(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    sections: &[KeySection],
    cuts: &[CutPath],
    level: Level,
) -> Result<Derived, SketchError> {
    let mut lm = landmarks(front)?;
    let joins = join_heights(front, &lm, cuts)?;
    if let Some(y) = joins.neck {
        lm.neck_base = y;
    }
    check_side_height(lm.height(), side)?;
    let side = if level == Level::Initial { None } else { side };
    let regs = regions(front, &lm, &joins)?;
    if lm.torso_is_short() {
        return short_torso(front, side, sections, level, lm, &joins, &regs);
    }
    let mut parts = regs
        .iter()
        .map(|r| part_from_region(front, side, r))
        .collect::<Result<Vec<_>, _>>()?;
    let (arms, traces) = traced_arms(front, side, &lm, &joins)?;
    let shoulders = [traces[0].trace.shoulder, traces[1].trace.shoulder];
    // parts in the order torso, head, arm_l, arm_r, leg_l, leg_r
    for (k, arm) in arms.into_iter().enumerate() {
        parts.insert(2 + k, arm);
    }
    if level == Level::Final {
        for k in sections {
            super::keysection::apply_key_section(&mut parts, k)?;
        }
    }
    let g = super::segment::GAP_FRACTION * lm.height();
    let torso = &parts[0];
    let r_top = match torso.sections.last().map(|s| &s.shape) {
        Some(SectionShape::Circle { r }) => *r,
        Some(SectionShape::Ellipse { a, .. }) => *a,
        _ => g,
    };
    let top_c = torso.sections.last().map(|s| s.centre).unwrap_or([0.0; 3]);
    // the shoulders' seam apexes and their alternatives (`super::apex`)
    let neck_x = super::segment::neck_interval(front, &lm)
        .map_or([top_c[0] - 0.5 * r_top, top_c[0] + 0.5 * r_top], |iv| iv);
    let neck_y = parts[1]
        .sections
        .first()
        .map_or(lm.neck_base, |s| s.centre[1]);
    let apexes =
        super::apex::shoulder_apexes(front, &lm, [top_c, [0.0, neck_y, g]], neck_x, shoulders);
    let bot_c = torso.sections[0].centre;
    let mut transitions = TransitionSpec::humanoid(
        [lm.crotch[0], lm.crotch[1], bot_c[2]],
        vec![apexes[0].0, apexes[1].0],
        crate::character::spec::SHOULDER_TANGENT_SCALE,
        1.0,
    );
    for t in &mut transitions {
        t.cap_tangents = true;
        if t.name == "shoulders" {
            if let (Some(end), Some(neck)) = (torso.sections.last(), parts[1].sections.first()) {
                t.cut_angles = neck_cuts(end, neck);
            }
        }
    }
    let apex_alternatives = apexes
        .iter()
        .enumerate()
        .filter_map(|(seam, a)| {
            Some(ApexAlternative {
                transition: transitions.iter().position(|t| t.name == "shoulders")?,
                seam,
                apex: a.1?,
            })
        })
        .collect();
    let alternatives = super::humanoid_shells::alternatives(
        level,
        front,
        side,
        &lm,
        &regs[0],
        &traces,
        (&parts, &transitions),
    );
    Ok(Derived {
        apex_alternatives,
        alternatives,
        ..Derived::humanoid(lm, parts, transitions)
    })
}

/// A humanoid with no torso to build stacked
/// ([`super::humanoid_shells::short_torso_models`]); refused, naming the
/// lower armpit and the crotch, when neither shells model builds.
fn short_torso(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    sections: &[KeySection],
    level: Level,
    lm: Landmarks,
    joins: &super::cuts::JoinHeights,
    regs: &[super::region::Region],
) -> Result<Derived, SketchError> {
    // an arm that does not reach out of the body from a low armpit lies
    // on the hip and leg: named as the arm joining the body there
    let (arms, traces) = traced_arms(front, side, &lm, joins).map_err(|e| {
        let h = lm.height();
        let least = super::segment::torso_min(h);
        // a refusal of neither arm (no neck) names the left one, as the
        // match on the error's text ("arm_r:") did before
        let (which, a) = if e.right == Some(true) {
            ("right", lm.armpit_r)
        } else {
            ("left", lm.armpit_l)
        };
        if a[1] <= lm.crotch[1] + least {
            super::refusal::arm_too_low(a, lm.crotch, h, least, which)
        } else {
            e.error
        }
    })?;
    let thumbs: Vec<PartSpec> = arms
        .into_iter()
        .filter(|p| p.name.starts_with("thumb"))
        .collect();
    let keys = if level == Level::Final { sections } else { &[] };
    let mut models = super::humanoid_shells::short_torso_models(
        front,
        side,
        &lm,
        regs,
        (&traces, &thumbs),
        keys,
    )?;
    if models.is_empty() {
        return Err(lm.short_torso_error());
    }
    let (parts, transitions) = models.remove(0);
    Ok(Derived {
        alternatives: models,
        shells: true,
        ..Derived::humanoid(lm, parts, transitions)
    })
}

/// The shoulders transition's cut angles when a wide neck starts close
/// above the torso's end ring `end`: the fixed cuts (a third of pi either
/// side of the ring's middle, at half the torso's width) move toward the
/// sides of the neck's first ring `neck` by the weight `1 - gap / a`
/// (`gap`: the distance between the two rings' centres, `a`: the torso
/// ring's half width), front cuts then the back ones mirrored;
/// empty (the fixed cuts) when the neck is no wider than they are or
/// starts a half width or more above. With the fixed cuts a neck as wide
/// as the torso right above it (a big-headed figure's) got half the
/// ring: the seams between its arcs and the arms' ran outward up a short
/// transition and the arms' pieces folded between them (random_33 of the
/// issue-range seed-4242 set: 175 degrees beside the neck). A neck far
/// above the ring leaves the transition room to narrow (the corpus's
/// random_1, 0.36 of the height above: moved cuts folded it more).
fn neck_cuts(end: &SectionSpec, neck: &SectionSpec) -> Vec<f64> {
    let (a, a1) = (e1_half_width(&end.shape), e1_half_width(&neck.shape));
    let gap = crate::mesh::dist(end.centre, neck.centre);
    let w = (1.0 - gap / a).clamp(0.0, 1.0);
    let a0 = a * end.e1[0];
    if !(a0.abs() > 0.0 && a1 > 0.0 && w > 0.0) {
        return Vec::new();
    }
    let cut = |x: f64| ring_angle(end.centre[0], a0, x);
    let (l, r) = (cut(neck.centre[0] - a1), cut(neck.centre[0] + a1));
    let (l, r) = (l.max(r), l.min(r));
    let (fixed_l, fixed_r) = (2.0 * FRAC_PI_3, FRAC_PI_3);
    if l <= fixed_l && r >= fixed_r {
        return Vec::new();
    }
    let l = fixed_l + w * (l.max(fixed_l) - fixed_l);
    let r = fixed_r + w * (r.min(fixed_r) - fixed_r);
    vec![l, r, TAU - l, TAU - r]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(x: f64, y: f64, a: f64, e1x: f64) -> SectionSpec {
        SectionSpec {
            u: 0.0,
            centre: [x, y, 0.0],
            e1: [e1x, 0.0, 0.0],
            e2: [0.0, 0.0, 1.0],
            shape: SectionShape::Ellipse {
                a,
                b: 0.5 * a,
                offset: 0.0,
            },
        }
    }

    /// A neck narrower than half the torso keeps the fixed cuts (no angles
    /// written); one 0.8 of the torso's width right above it is cut at its
    /// sides, the back cuts mirrored; one wider than the torso at the
    /// bound; one half a half width above, halfway from the fixed cuts;
    /// one a half width above, not at all; degenerate rings, not at all.
    #[test]
    fn the_shoulders_are_cut_at_a_wide_neck_s_sides_when_it_starts_close() {
        let torso = ring(0.0, 1.0, 1.0, 1.0);
        assert!(neck_cuts(&torso, &ring(0.0, 1.0, 0.4, 1.0)).is_empty());
        assert!(neck_cuts(&torso, &ring(0.0, 1.0, 0.5, 1.0)).is_empty());
        let tol = crate::check::tol::ROUNDING;
        let c = neck_cuts(&torso, &ring(0.0, 1.0, 0.8, 1.0));
        let want = [(-0.8f64).acos(), 0.8f64.acos()];
        assert_eq!(c.len(), 4, "{c:?}");
        for (k, w) in want.iter().enumerate() {
            assert!((c[k] - w).abs() < tol, "{c:?}");
            assert!((c[2 + k] - (TAU - w)).abs() < tol, "{c:?}");
        }
        // a torso ring whose e1 runs along -x sees the same neck
        let flipped = neck_cuts(&ring(0.0, 1.0, 1.0, -1.0), &ring(0.0, 1.0, 0.8, 1.0));
        assert!(
            c.iter().zip(&flipped).all(|(a, b)| (a - b).abs() < tol),
            "{flipped:?}"
        );
        let wide = neck_cuts(&torso, &ring(0.0, 1.0, 1.3, 1.0));
        assert!(
            (wide[1] - crate::sketch::derived::CUT_MAX_COS.acos()).abs() < tol,
            "{wide:?}"
        );
        // a neck off the ring's middle widens only the side it reaches, by
        // 1 - 0.35 (its centre is 0.35 from the ring's)
        let off = neck_cuts(&torso, &ring(0.35, 1.0, 0.4, 1.0));
        let r = FRAC_PI_3 + 0.65 * (0.75f64.acos() - FRAC_PI_3);
        assert!(
            (off[0] - 2.0 * FRAC_PI_3).abs() < tol && (off[1] - r).abs() < tol,
            "{off:?}"
        );
        // farther above, less
        let half = neck_cuts(&torso, &ring(0.0, 1.5, 0.8, 1.0));
        assert!(
            (half[1] - 0.5 * (FRAC_PI_3 + want[1])).abs() < tol,
            "{half:?}"
        );
        assert!(neck_cuts(&torso, &ring(0.0, 2.0, 0.8, 1.0)).is_empty());
        for bad in [ring(0.0, 1.0, 0.0, 1.0), ring(0.0, f64::NAN, 1.0, 1.0)] {
            assert!(neck_cuts(&bad, &ring(0.0, 1.0, 0.8, 1.0)).is_empty());
            assert!(neck_cuts(&torso, &bad).is_empty());
        }
    }
}
