//! An animal's body as a chain along its own length, its legs, neck and
//! tail as closed chains reaching into it (paper 000's composition of
//! removed parts, sec 4.1), instead of a stack of horizontal slices joined
//! to its parts by transition surfaces.
//!
//! The lateral outline's body is what is left when every other part's
//! region ([`super::regions`]) is cut off at its join: a leg at its top
//! slice, a part above the back at its lowest, each run of the outline
//! beyond the cut replaced by the cut's chord ([`super::root_cut`]). That
//! outline is built as a removed part is, along its principal axis
//! ([`super::super::removed::upright_chain`]): sections across the body,
//! closed at the rump and the chest. The head-on view gives their depth
//! ([`body_depth`]), or each section is the two views' hull
//! ([`super::hull_section`], a second model the build may keep). Each other part keeps its region's chain and is
//! closed at its join by a cap reaching half its width beyond it
//! ([`cap_start`], [`super::hanging::HANG_ROOT`]): into the body, which
//! covers the cut.
//!
//! Why: a body sliced horizontally has its back and belly as end rings,
//! flat, and the transitions from them to four legs and three parts above
//! folded (corpus animals: 166 to 180 degrees, 1.3 to 19 heights of
//! creased edges, docs/drawing-corpus.md).

use super::super::part_slices::part_from_region;
use super::super::poly::slice;
use super::super::removed::upright_chain_n;
use super::super::segment::{interval, Pick, Region, SidePick};
use super::super::SketchError;
use super::hanging::HANG_ROOT;
pub use super::hull_section::body_depth;
use super::hull_section::inscribed_depth;
pub use super::hull_section::BodyDepth;
use super::root_cut::{nearest_vertex, root_point, split_at_root, without_run};
use super::QuadLandmarks;
use crate::character::doc::{PartSpec, SectionShape};

/// How a part other than the body is cut off it.
#[derive(Clone, Debug)]
pub enum Cut {
    /// Kept as its region's chain, capped into the body (a leg, a lone
    /// neck over the back line): cut at its join's slice.
    Region,
    /// Its own closed outline, cut at its root chord ([`split_at_root`]).
    Outline(Vec<[f64; 2]>),
    /// Left in the body (a back between two corners).
    Body,
}

/// The body's outline and how each other region (`regs[1..]`) is cut off
/// it: a part above the back beside one top corner at its root chord
/// ([`root_point`]); a part between two corners stays in the body; a leg,
/// or a lone part over the back line, at its join's slice, the run of the
/// outline beyond it replaced by the chord ([`without_run`]).
pub fn cut_parts(
    front: &[[f64; 2]],
    regs: &[Region],
    top_gaps: &[[f64; 2]],
    leg_raise: f64,
    facing: f64,
) -> Result<(Vec<[f64; 2]>, Vec<Cut>), SketchError> {
    let mut poly = front.to_vec();
    let mut cuts = Vec::new();
    let is_gap = |x: f64| top_gaps.iter().find(|g| g[0] == x).copied();
    let refuse = |name: &str, y: f64| {
        SketchError::Segmentation(format!(
            "{name}: its join at y = {y:.4} does not cut it off the body: draw it apart from the other parts"
        ))
    };
    for r in &regs[1..] {
        let Pick::CentreIn(lo, hi) = r.pick else {
            return Err(refuse(&r.name, r.y0));
        };
        // which way the part lies from its corner: forward (counter-
        // clockwise, right to left along the top) when left of it; a lone
        // part over the back line (no top corner) lies toward the facing
        let toward = match (r.downward, is_gap(lo), is_gap(hi)) {
            (true, _, _) => None,
            (false, Some(_), Some(_)) => {
                cuts.push(Cut::Body);
                continue;
            }
            (false, Some(_), None) => Some(false),
            (false, None, Some(_)) => Some(true),
            (false, None, None) => Some(facing < 0.0),
        };
        let cut = match toward {
            Some(forward) => {
                // the corner's side of the part's lowest slice (a flat
                // back's gap top is the back's middle, not a corner)
                let iv = interval(&poly, r.pick, r.y0).ok_or_else(|| refuse(&r.name, r.y0))?;
                let x = if forward { iv[1] } else { iv[0] };
                let c = nearest_vertex(&poly, [x, r.y0]);
                let root =
                    root_point(&poly, c, forward, r.y1).ok_or_else(|| refuse(&r.name, r.y0))?;
                let (body, part) = split_at_root(&poly, c, root, forward);
                poly = body;
                Cut::Outline(part)
            }
            None => {
                let y = r.y1 + leg_raise;
                poly = interval(&poly, r.pick, y)
                    .and_then(|iv| without_run(&poly, y, iv, true))
                    .ok_or_else(|| refuse(&r.name, y))?;
                Cut::Region
            }
        };
        cuts.push(cut);
    }
    Ok((poly, cuts))
}

/// A chain from a closed outline ([`upright_chain`]); with `side`, its
/// sections are ellipses whose depth is the head-on outline's half width
/// over the heights in `band` ([`body_depth`]) scaled by the section's
/// height over the tallest's, centred at that width's middle; the body's,
/// with [`BodyDepth::Hull`], the two views' hull where it has one.
pub fn outline_part(
    name: &str,
    outline: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    band: [f64; 2],
    depth_by: BodyDepth,
) -> Result<PartSpec, SketchError> {
    let parallel = name == "body";
    let mut spec = upright_chain_n(name, outline, None, sections_for(outline), parallel)?;
    if parallel {
        straight_tips(&mut spec);
    }
    let Some((depth, z)) = side.and_then(|s| body_depth(s, band)) else {
        return Ok(spec);
    };
    let radius = |s: &SectionShape| match s {
        SectionShape::Circle { r } => *r,
        _ => 0.0,
    };
    let tallest = spec
        .sections
        .iter()
        .map(|s| radius(&s.shape))
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let sd = side.unwrap_or(&[]);
    let head_on = (parallel && depth_by == BodyDepth::Hull)
        .then(|| super::hull_section::HeadOn::new(sd, z, 0.5 * (band[0] + band[1])))
        .flatten();
    for s in &mut spec.sections {
        let r = radius(&s.shape);
        s.centre[2] = z;
        // no deeper than fits the head-on view at every height it spans
        // (within the band): the largest inscribed depth
        let seen = inscribed_depth(sd, s.centre[1], r, band);
        if let Some(h) = &head_on {
            if let Some(g) = super::hull_section::hull_section(s, r, h) {
                s.shape = g;
                continue;
            }
        }
        if r > 0.0 {
            s.shape = SectionShape::Ellipse {
                a: r,
                b: (depth * r / tallest).min(seen),
                offset: 0.0,
            };
        }
    }
    Ok(spec)
}

/// Moves each closed end's point onto the line through its neighbour
/// section's centre along the sections' normal: parallel sections whose
/// end point sits off that line (at a cut's corner) slide sideways faster
/// than they advance there, and the surface folds over (the corpus dog's
/// rump, 180 degrees).
fn straight_tips(spec: &mut PartSpec) {
    let n = spec.sections.len();
    if n < 2 {
        return;
    }
    for (tip, next) in [(0, 1), (n - 1, n - 2)] {
        let (t, q) = (&spec.sections[tip], &spec.sections[next]);
        let (a, b) = (q.e1, q.e2);
        let nrm = [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ];
        let len = (nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]).sqrt();
        if len == 0.0 {
            continue;
        }
        let d: [f64; 3] = std::array::from_fn(|k| t.centre[k] - q.centre[k]);
        let along = (d[0] * nrm[0] + d[1] * nrm[1] + d[2] * nrm[2]) / (len * len);
        let centre = std::array::from_fn(|k| q.centre[k] + along * nrm[k]);
        let (e1, e2) = (q.e1, q.e2);
        let t = &mut spec.sections[tip];
        (t.centre, t.e1, t.e2) = (centre, e1, e2);
    }
}

/// Sections along a part cut from its outline: `3 P + 1`, P patches each
/// at most half the part's width long (its extent across its principal
/// axis, [`super::super::align::axes`]), at least the limb's 4: a long
/// body's blunt ends otherwise ring along its whole length.
fn sections_for(outline: &[[f64; 2]]) -> usize {
    let ax = super::super::align::axes(outline);
    let (c, sn) = (ax.major.cos(), ax.major.sin());
    let along: Vec<f64> = outline.iter().map(|p| p[0] * c + p[1] * sn).collect();
    let across: Vec<f64> = outline.iter().map(|p| -p[0] * sn + p[1] * c).collect();
    let ext = |v: &[f64]| {
        v.iter().copied().fold(f64::MIN, f64::max) - v.iter().copied().fold(f64::MAX, f64::min)
    };
    let patches = (2.0 * ext(&along) / ext(&across).max(f64::MIN_POSITIVE)).ceil();
    let p = if patches.is_finite() {
        patches as usize
    } else {
        4
    };
    3 * p.clamp(4, 40) + 1
}

/// Sections a cap adds: a chain holds 7 + 3k sections.
const CAP_SECTIONS: usize = 3;

/// Closes a part's start with a half-ellipsoid dome reaching half its
/// start's e1 width beyond it, back along its first step (into the body
/// it joins): [`CAP_SECTIONS`] sections, the last a point.
pub fn cap_start(spec: &mut PartSpec) {
    cap_start_by(spec, 0.0);
}

/// [`cap_start`] with the dome reaching `extra` farther.
pub fn cap_start_by(spec: &mut PartSpec, extra: f64) {
    let [s0, s1] = [&spec.sections[0], &spec.sections[1]];
    let half = match s0.shape {
        SectionShape::Circle { r } => r,
        SectionShape::Ellipse { a, .. } => a,
        SectionShape::Gec { .. } => return,
    };
    let d: [f64; 3] = std::array::from_fn(|k| s0.centre[k] - s1.centre[k]);
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    if len == 0.0 || half <= 0.0 {
        return;
    }
    let push = 2.0 * HANG_ROOT * half + extra.max(0.0);
    let dome: Vec<_> = (1..=CAP_SECTIONS)
        .rev()
        .map(|k| {
            let t = k as f64 / CAP_SECTIONS as f64;
            let scale = (1.0 - t * t).max(0.0).sqrt();
            let mut c = s0.clone();
            c.centre = std::array::from_fn(|i| s0.centre[i] + t * push * d[i] / len);
            c.u = (1.0 - t) * push;
            c.shape = match c.shape {
                _ if k == CAP_SECTIONS => SectionShape::Circle { r: 0.0 },
                SectionShape::Circle { r } => SectionShape::Circle { r: scale * r },
                SectionShape::Ellipse { a, b, offset } => SectionShape::Ellipse {
                    a: scale * a,
                    b: scale * b,
                    offset: scale * offset,
                },
                g => g,
            };
            c
        })
        .collect();
    for s in &mut spec.sections {
        s.u += push;
    }
    spec.sections.splice(0..0, dome);
    spec.closed_start = true;
}

/// The animal as shells (see the module docs) from its regions `regs`
/// and their chains `parts` (body first, as [`super::regions`] orders
/// them), with its hanging parts: None when a part cannot be cut off or
/// built this way (the build keeps the transitions' model).
fn shell_parts(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &QuadLandmarks,
    regs: &[Region],
    parts: &[PartSpec],
    hanging: &[PartSpec],
    depth_by: BodyDepth,
) -> Option<Vec<PartSpec>> {
    // the body keeps the belly down to half a join band above the legs'
    // gap tops (their top slices are LEG_BAND bands below)
    let g = super::GAP_FRACTION * lm.height();
    let (outline, cuts) = cut_parts(
        front,
        regs,
        &lm.top_gaps,
        (super::LEG_BAND - 0.5) * g,
        lm.facing,
    )
    .ok()?;
    let others = &regs[1..];
    let legs_top = others
        .iter()
        .filter(|r| r.downward)
        .map(|r| r.y1)
        .fold(lm.y_min, f64::max);
    let above_low = others
        .iter()
        .filter(|r| !r.downward)
        .map(|r| r.y0)
        .fold(lm.y_max, f64::min);
    let band = [legs_top, above_low];
    let mut out = vec![outline_part("body", &outline, side, band, depth_by).ok()?];
    for ((r, p), cut) in others.iter().zip(&parts[1..]).zip(cuts) {
        match cut {
            Cut::Body => {}
            Cut::Region => {
                let pair = side.and_then(|sd| leg_pair(front, sd, r, lm.facing));
                for mut p in pair.unwrap_or_else(|| vec![p.clone()]) {
                    cap_start(&mut p);
                    out.push(p);
                }
            }
            Cut::Outline(o) => {
                // a tail is hidden in the head-on view (circles)
                let seen = if r.name == "tail" { None } else { side };
                let band = [r.y0, r.y1];
                out.push(outline_part(&r.name, &o, seen, band, BodyDepth::Ellipse).ok()?);
            }
        }
    }
    out.extend(hanging.iter().cloned());
    Some(out)
}

/// The animal as shells ([`shell_parts`]), its body's sections ellipses
/// and, with a head-on view, then the two views' hull (the build keeps
/// the one that misses the drawing least).
pub fn alternatives(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &QuadLandmarks,
    regs: &[Region],
    parts: &[PartSpec],
    hanging: &[PartSpec],
) -> Vec<(Vec<PartSpec>, Vec<crate::character::doc::TransitionSpec>)> {
    let depths: &[BodyDepth] = match side {
        Some(_) => &[BodyDepth::Ellipse, BodyDepth::Hull],
        None => &[BodyDepth::Ellipse],
    };
    depths
        .iter()
        .filter_map(|&d| shell_parts(front, side, lm, regs, parts, hanging, d))
        .map(|p| (p, Vec::new()))
        .collect()
}

/// A leg of a two-legged lateral view (`leg_f`, `leg_b`: the near leg
/// hides the far one) as the pair the head-on view shows apart: at the
/// leg's middle height, intervals on both sides of the head-on outline's
/// middle. Each takes its depth and z from its own side's interval, as
/// one of four lateral legs does (`super::leg_regions`); the `+z` one is
/// the near leg, the right one when the animal faces `+x`. None: one
/// interval there (the legs drawn as one), or a chain that fails.
fn leg_pair(
    front: &[[f64; 2]],
    side: &[[f64; 2]],
    r: &Region,
    facing: f64,
) -> Option<Vec<PartSpec>> {
    if !r.downward || r.side != SidePick::Span {
        return None;
    }
    let zc = super::head_on_middle(side);
    let mid = |iv: &[f64; 2]| 0.5 * (iv[0] + iv[1]);
    let sl = slice(side, 0.5 * (r.y0 + r.y1));
    if !(sl.iter().any(|iv| mid(iv) < zc) && sl.iter().any(|iv| mid(iv) > zc)) {
        return None;
    }
    let (near, far) = if facing > 0.0 { ("r", "l") } else { ("l", "r") };
    [
        (far, SidePick::Within(f64::NEG_INFINITY, zc)),
        (near, SidePick::Within(zc, f64::INFINITY)),
    ]
    .into_iter()
    .map(|(suffix, pick)| {
        let half = Region {
            name: format!("{}{suffix}", r.name),
            side: pick,
            ..r.clone()
        };
        part_from_region(front, Some(side), &half).ok()
    })
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A lateral outline: the U of two legs below a wider body, nothing
    /// above the back.
    fn u_front() -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [3.0, 1.0],
            [3.0, 0.0],
            [4.0, 0.0],
            [4.0, 2.0],
            [0.0, 2.0],
        ]
    }

    /// A two-legged lateral view's back leg (the U of
    /// [`shells_are_closed_chains_without_transitions`]) becomes a pair
    /// where the head-on view shows the legs apart at the leg's middle
    /// height, the near one (+z) the right when facing +x; one leg where
    /// the head-on view has them as one.
    #[test]
    fn a_leg_is_a_pair_only_where_the_head_on_view_parts_it() {
        let front = u_front();
        let r = Region {
            name: "leg_b".into(),
            y0: 0.0,
            y1: 0.8,
            pick: Pick::CentreIn(f64::NEG_INFINITY, 2.0),
            downward: true,
            tip: true,
            shoulder: None,
            side: SidePick::Span,
            horizontal: true,
        };
        let apart = vec![
            [0.0, 0.0],
            [0.5, 0.0],
            [0.5, 1.0],
            [1.5, 1.0],
            [1.5, 0.0],
            [2.0, 0.0],
            [2.0, 2.0],
            [0.0, 2.0],
        ];
        let pair = leg_pair(&front, &apart, &r, 1.0).expect("a pair");
        // the head-on view's middle, where the pair splits
        let middle = super::super::head_on_middle(&apart);
        let names: Vec<&str> = pair.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["leg_bl", "leg_br"]);
        // a section's depth centre: an ellipse's offset is along e2 = z
        let z = |s: &crate::character::doc::SectionSpec| match s.shape {
            SectionShape::Ellipse { offset, .. } => s.centre[2] + offset * s.e2[2],
            _ => s.centre[2],
        };
        let mean_z = |p: &PartSpec| p.sections.iter().map(z).sum::<f64>() / p.sections.len() as f64;
        assert!(mean_z(&pair[0]) < middle && mean_z(&pair[1]) > middle);
        let facing_back = leg_pair(&front, &apart, &r, -1.0).expect("a pair");
        assert_eq!(facing_back[1].name, "leg_bl", "+z is the left facing -x");
        let together = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        assert!(leg_pair(&front, &together, &r, 1.0).is_none());
    }

    #[test]
    fn shells_are_closed_chains_without_transitions() {
        // the U below a wider body: nothing above the back
        let front = u_front();
        let d = super::super::derive(
            &front,
            None,
            &[],
            &[],
            crate::character::doc::Level::Intermediate,
        )
        .expect("builds");
        let [(parts, transitions)] = &d.alternatives[..] else {
            panic!("one alternative: {}", d.alternatives.len());
        };
        assert!(transitions.is_empty());
        let names: Vec<&str> = parts.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["body", "leg_b", "leg_f"]);
        for p in parts {
            assert!(p.closed_start && p.closed_end, "{}", p.name);
            assert_eq!(p.sections.len() % 3, 1, "{}: 3 P + 1 sections", p.name);
        }
        // the final level keeps the stacked body (key sections sculpt it)
        let d = super::super::derive(&front, None, &[], &[], crate::character::doc::Level::Final)
            .expect("builds");
        assert!(d.alternatives.is_empty());
    }
}
