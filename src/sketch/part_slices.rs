//! A slice-based part's key sections (paper 000 sec 4.1.2): one section
//! per placed slice of the front outline, perpendicular to the part's
//! centre line, an ellipse with the side view's depth; a free end closed
//! at the outline's extreme point, an arm's top tilted toward its
//! shoulder, a humanoid leg turned along a foot drawn in the side view
//! (`super::foot`).

use super::poly::slice;
use super::section_place::{
    centre_slope, direction, on_centre_line, place, samples, Sample, SECTIONS_PER_PART,
};
use super::segment::{Region, SidePick};
use super::SketchError;
use crate::character::doc::{EndCurvature, PartSpec, SectionShape, SectionSpec, SurfaceSpec};

/// Tilt of an arm's top section (degrees from horizontal, see `tilt_top`).
pub const SHOULDER_TILT_DEG: f64 = 60.0;
/// Sections of an arm's top that are tilted (by linearly less).
pub const SHOULDER_TILT_SECTIONS: usize = 2;
/// Weight of the change of the radii in an upright part's parameter: `u`
/// grows from one section to the next by `hypot(d, k |dr|)`, `d` the
/// distance between their centres, `dr` the change of their two radii
/// (`slice_sections`). With `k = 0` (the centres' arc length) a ledge in
/// the drawn profile (a waist stepping out to wide hips within a join
/// band) is a jump of the radius over a short span of `u`, and the C2
/// chain through it rang: the model's outline swung out past the drawn
/// one beside the step and waved along the torso (seed 4242's random_40,
/// issue ranges: 2.3 % of the height outside). Counting the radii gives
/// the step the parameter length of the outline it draws. Measured, not
/// derived: 0, 0.5, 0.75 and 1 on the two issue-range sets and the
/// corpus (docs/drawing-corpus.md, twenty-eighth measurement); at 1 (the
/// outline's own chord length) the radius term now dominates at a chin or
/// a sole and the chain overshoots there instead (real bodies' side views
/// 1 % outside). Not for a leg turned into a foot (its foot's sections
/// keep the centres' distance) nor for an animal's horizontal slices
/// (its parts bend within their own width: the bundled animal 0.85 ->
/// 1.6 % of the height). On a seed chosen after it (7777, issue ranges)
/// passes 27 -> 28. A traced arm's parameter follows its rims instead
/// (`uncross::rim_arc_lengths`, about k = 1).
pub const RADIUS_WEIGHT: f64 = 0.5;
/// Side-profile depth at height y: `(centre z, half depth)` of the slice
/// part `pick` names (None when hidden or when there is none).
pub(super) fn side_depth(
    side: &[[f64; 2]],
    map: [f64; 2],
    y: f64,
    pick: SidePick,
) -> Option<(f64, f64)> {
    let s = slice(side, map[0] + map[1] * y);
    let (lo, hi) = match pick {
        SidePick::Hidden => return None,
        // the widest interval: a hand or a finger hanging in front of the
        // body is a separate interval of a real body's side view, and the
        // slice's whole extent (first to last) doubled the torso's depth
        // there: the chain shot a sheet metres out
        SidePick::Whole => {
            let iv = s
                .iter()
                .max_by(|p, q| (p[1] - p[0]).total_cmp(&(q[1] - q[0])))?;
            (iv[0], iv[1])
        }
        SidePick::Span => (s.first()?[0], s.last()?[1]),
        SidePick::Within(a, b) => s
            .iter()
            .map(|iv| [iv[0].max(a), iv[1].min(b)])
            .filter(|iv| iv[1] > iv[0])
            .max_by(|p, q| (p[1] - p[0]).total_cmp(&(q[1] - q[0])))
            .map(|iv| (iv[0], iv[1]))?,
        SidePick::CentreIn(a, b) => {
            let iv = s
                .iter()
                .filter(|iv| {
                    let c = 0.5 * (iv[0] + iv[1]);
                    c > a && c < b
                })
                .max_by(|p, q| (p[1] - p[0]).total_cmp(&(q[1] - q[0])))?;
            (iv[0], iv[1])
        }
    };
    Some((0.5 * (lo + hi), 0.5 * (hi - lo)))
}

/// Side heights mapped onto the front's (the two agree within 5 %):
/// `side y = map[0] + map[1] front y`.
pub(super) fn height_map(front: &[[f64; 2]], side: Option<&[[f64; 2]]>) -> [f64; 2] {
    match side {
        Some(sd) => {
            let fy = crate::polygon::span(front, 1);
            let sy = crate::polygon::span(sd, 1);
            let k = (sy[1] - sy[0]) / (fy[1] - fy[0]);
            [sy[0] - k * fy[0], k]
        }
        None => [0.0, 1.0],
    }
}

pub(super) fn part_from_region(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    r: &Region,
) -> Result<PartSpec, SketchError> {
    part_with_sections(front, side, r, SECTIONS_PER_PART)
}

/// [`part_from_region`] with `m` sections (`3 P + 1`) where no foot takes
/// some: a long part (an animal's body) needs more than a limb.
pub(super) fn part_with_sections(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    r: &Region,
    m: usize,
) -> Result<PartSpec, SketchError> {
    match region_part(front, side, r, true, m)? {
        Some(p) => Ok(p),
        // a foot whose sections do not all meet the outlines: the leg
        // without it, horizontal sections down to the sole
        None => region_part(front, side, r, false, m)?
            .ok_or_else(|| SketchError::Segmentation(format!("{}: no sections", r.name))),
    }
}

/// Region `r`'s slices; an upright part's midpoints without pulses
/// (`on_centre_line`). A horizontal region's slices cross a part that bends
/// within its own width (an animal's neck into its head), whose midpoints
/// are its shape: kept as drawn (the median moved the bundled animal's
/// head off its outline, 0.90 -> 0.99 % of the height).
fn region_samples(front: &[[f64; 2]], r: &Region) -> Vec<Sample> {
    if r.horizontal {
        samples(front, r)
    } else {
        on_centre_line(samples(front, r))
    }
}

/// The part of region `r`; with `with_foot`, a humanoid leg follows a
/// foot drawn in the side view (`super::foot`). None: the foot was found
/// but one of its sections missed an outline.
fn region_part(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    r: &Region,
    with_foot: bool,
    m: usize,
) -> Result<Option<PartSpec>, SketchError> {
    let map = height_map(front, side);
    let s = region_samples(front, r);
    if s.len() < m + 2 {
        return Err(SketchError::Segmentation(format!(
            "{}: only {} slices: draw it larger (longer or wider)",
            r.name,
            s.len()
        )));
    }
    let uses_side = side.is_some() && r.side != SidePick::Hidden;
    // the side profile's depth at every sample (None where it has no slice:
    // then the front alone places the sections)
    let depth: Option<Vec<(f64, f64)>> = match (uses_side, side) {
        (true, Some(sd)) => s.iter().map(|q| side_depth(sd, map, q.y, r.side)).collect(),
        _ => None,
    };
    // a humanoid leg whose side view shows a foot turns into it
    let foot = match (
        with_foot && super::foot::leg_with_side(r),
        side,
        depth.as_deref(),
    ) {
        (true, Some(sd), Some(d)) => super::foot::find(sd, map, &s, d, SECTIONS_PER_PART + 3),
        _ => None,
    };
    let mut plan = super::foot::plan(&s, foot.as_ref(), side.unwrap_or(&[]));
    if foot.is_none() {
        plan.m_upper = m;
    }
    let upper_depth = depth.as_deref().map(|d| &d[..plan.n_upper]);
    let idx = match &foot {
        // the bend's sections are a sixth of pi of its radius apart (side
        // units, `map[1]` per front unit)
        Some(f) => super::section_place::graded_place(
            &s[..plan.n_upper],
            upper_depth,
            plan.m_upper,
            std::f64::consts::FRAC_PI_6 * f.radius / map[1].abs(),
        ),
        None => place(&s[..plan.n_upper], upper_depth, plan.m_upper),
    };
    let upright = foot.is_none() && !r.horizontal;
    let ctx = SliceCtx {
        r,
        side: if uses_side { side } else { None },
        map,
        close_last: foot.is_none(),
        radius_weight: if upright { RADIUS_WEIGHT } else { 0.0 },
    };
    let (mut sections, u) = slice_sections(&s, &idx, &ctx);
    if let (Some(f), Some(sd)) = (&foot, side) {
        let lastc = sections.last().map(|q| q.centre).unwrap_or([0.0; 3]);
        let i = idx[idx.len() - 1];
        let end = super::foot::LegEnd {
            front,
            pick: r.pick,
            side: sd,
            map,
            u,
            centre: [
                lastc[0],
                lastc[1],
                side_depth(sd, map, s[i].y, r.side).map_or(0.0, |d| d.0),
            ],
            e1x: sections.last().map_or(-1.0, |q| q.e1[0].signum()),
        };
        let pts = super::foot::path(sd, f, &plan.stations);
        match super::foot::sections(&end, f, &pts) {
            Some(more) => sections.extend(more),
            None => return Ok(None),
        }
    } else if r.tip {
        close_tip(&s, &ctx, &mut sections);
    }
    if let Some(out) = r.shoulder {
        tilt_top(front, &s, &idx, out, &mut sections);
    }
    Ok(Some(PartSpec {
        name: r.name.clone(),
        surface: SurfaceSpec::Pde6C2 {
            a: 0.0,
            open_ends: EndCurvature::Guarded,
        },
        sections,
        closed_start: false,
        closed_end: r.tip,
    }))
}

/// What the sections of a slice-based part need besides its samples.
struct SliceCtx<'a> {
    r: &'a Region,
    /// The side outline when the part reads its depth from it.
    side: Option<&'a [[f64; 2]]>,
    map: [f64; 2],
    /// The last section is the part's last (a tip closes it).
    close_last: bool,
    /// The radii's weight in the part's parameter ([`RADIUS_WEIGHT`] or 0).
    radius_weight: f64,
}

/// One key section per index of `idx`: perpendicular to the centre line as
/// seen at its own scale (`centre_slope`), an ellipse with the side's depth
/// or a circle; returns them and the last one's `u`.
fn slice_sections(s: &[Sample], idx: &[usize], ctx: &SliceCtx) -> (Vec<SectionSpec>, f64) {
    let r = ctx.r;
    let mut sections = Vec::with_capacity(idx.len() + 1);
    let mut u = 0.0;
    let mut prev: Option<([f64; 3], Option<f64>, [f64; 2])> = None;
    let follows_depth = !r.horizontal && r.side == SidePick::Whole;
    for (j, &i) in idx.iter().enumerate() {
        let dir = direction(s, i);
        let t = if r.horizontal {
            [0.0, dir, 0.0]
        } else {
            [dir * centre_slope(s, i), dir, 0.0]
        };
        let tn = t[0].hypot(t[1]);
        let t = [t[0] / tn, t[1] / tn, 0.0];
        let e1 = [t[1], -t[0], 0.0];
        let e2 = [0.0, 0.0, 1.0];
        let cos_tilt = t[1].abs();
        let centre0 = [s[i].c, s[i].y, 0.0];
        let a_r = s[i].w * cos_tilt;
        let last = j + 1 == idx.len() && ctx.close_last;
        let shape = match ctx.side {
            Some(sd) if !(last && r.tip) => match side_depth(sd, ctx.map, s[i].y, r.side) {
                Some((zc, b)) => SectionShape::Ellipse {
                    a: a_r,
                    b,
                    offset: zc,
                },
                None => SectionShape::Circle { r: a_r },
            },
            _ => SectionShape::Circle { r: a_r },
        };
        // u runs along the ring centres themselves: between two sections
        // that both take their depth from the side view, its depth centre
        // moves them too
        let zc = match shape {
            SectionShape::Ellipse { offset, .. } => Some(offset),
            _ => None,
        };
        let radii = match shape {
            SectionShape::Ellipse { a, b, .. } => [a, b],
            SectionShape::Circle { r } => [r, r],
            SectionShape::Gec { .. } => [0.0, 0.0],
        };
        if let Some((p, pz, pr)) = prev {
            let dz = match (pz, zc) {
                (Some(a), Some(b)) if follows_depth => b - a,
                _ => 0.0,
            };
            // a tip's closing span keeps the centres' distance ([`close_tip`]
            // replaces its section)
            let k = if last && r.tip {
                0.0
            } else {
                ctx.radius_weight
            };
            let dr = (radii[0] - pr[0]).hypot(radii[1] - pr[1]);
            u += crate::mesh::dist(p, centre0).hypot(dz).hypot(k * dr);
        }
        prev = Some((centre0, zc, radii));
        sections.push(SectionSpec {
            u,
            centre: centre0,
            e1,
            e2,
            shape,
        });
    }
    (sections, u)
}

/// Collapses a part's free end to the outline's extreme point.
fn close_tip(s: &[Sample], ctx: &SliceCtx, sections: &mut [SectionSpec]) {
    let r = ctx.r;
    let tip_y = if r.downward { r.y0 } else { r.y1 };
    let lastc = sections.last().map(|q| q.centre).unwrap_or([0.0; 3]);
    // where the side view has no slice of the part at its very end (an
    // animal's near leg at the sole, seen head-on), the tip keeps the depth
    // centre of the section before it (the tip's own is a circle): at
    // z = 0 it pulled the near hind leg's foot under the body's middle
    // (corpus dog: 6.2 % of the height outside the head-on view)
    let before = sections.len().checked_sub(2).and_then(|i| sections.get(i));
    let last_z = before.map_or(0.0, |q| match q.shape {
        SectionShape::Ellipse { offset, .. } => q.centre[2] + offset,
        _ => q.centre[2],
    });
    let zc = ctx
        .side
        .and_then(|sd| side_depth(sd, ctx.map, s[s.len() - 1].y, r.side))
        .map_or(last_z, |d| d.0);
    let tip = [lastc[0], tip_y, 0.0];
    let Some(last) = sections.last_mut() else {
        return;
    };
    last.u += crate::mesh::dist(lastc, tip);
    last.centre = [tip[0], tip[1], zc];
    last.shape = SectionShape::Circle { r: 0.0 };
}

/// Tilts the top sections of a limb hanging from a shoulder (an arm): the
/// top section runs from the limb's inner side (just below the armpit) up to
/// the outline's outer side [`SHOULDER_TILT_DEG`] higher, the next
/// `SHOULDER_TILT_SECTIONS - 1` sections by linearly less. Each is the
/// circle through its two outline points. Without it the shoulder above
/// the armpit is left wholly to the transition, whose Hermite arch falls
/// short of a square shoulder (bundled female 1.03 %, male 1.41 % of the
/// height; with it 0.75 % and 0.67 %).
fn tilt_top(
    front: &[[f64; 2]],
    s: &[Sample],
    idx: &[usize],
    out: f64,
    sections: &mut [SectionSpec],
) {
    let theta = SHOULDER_TILT_DEG.to_radians();
    let nt = SHOULDER_TILT_SECTIONS;
    for j in 0..nt.min(sections.len() - 2) {
        let f = 1.0 - j as f64 / nt as f64;
        let q = &s[idx[j]];
        let inner = [q.c - out * q.w, q.y];
        let w2 = 2.0 * q.w;
        let yo = q.y + (theta * f).tan() * w2;
        let iv = slice(front, yo);
        let xo = if out > 0.0 {
            iv.last().map(|v| v[1])
        } else {
            iv.first().map(|v| v[0])
        };
        // the outer point must lie outward of the limb's inner side by at
        // least its half-width (else the slice is not the shoulder's: keep
        // the section perpendicular)
        let Some(xo) = xo.filter(|x| out * (x - inner[0]) >= q.w) else {
            continue;
        };
        let outer = [xo, yo];
        let d = [inner[0] - outer[0], inner[1] - outer[1]];
        let len = d[0].hypot(d[1]);
        let sec = &mut sections[j];
        let mut e1 = [d[0] / len, d[1] / len, 0.0];
        if e1[0] * sec.e1[0] + e1[1] * sec.e1[1] < 0.0 {
            e1 = [-e1[0], -e1[1], 0.0];
        }
        sec.e1 = e1;
        sec.centre = [
            0.5 * (inner[0] + outer[0]),
            0.5 * (inner[1] + outer[1]),
            sec.centre[2],
        ];
        sec.shape = SectionShape::Circle { r: 0.5 * len };
    }
    let mut u = 0.0;
    for i in 1..sections.len() {
        u += crate::mesh::dist(sections[i - 1].centre, sections[i].centre);
        sections[i].u = u;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A side view whose arm hangs in front of the body, apart from it: at
    /// the hand's height the body's depth is its own interval, not the
    /// slice's whole extent (the hand in front once doubled a real body's
    /// torso depth, and its chain shot a sheet out of the model).
    #[test]
    fn a_hand_apart_in_the_side_view_is_not_the_body_s_depth() {
        // body z in [-1, 1] up to y = 10; an arm from its top out to z = 3
        // and down to y = 4, its hand at z in [2.5, 3]
        let side = vec![
            [-1.0, 0.0],
            [1.0, 0.0],
            [1.0, 8.0],
            [2.5, 8.0],
            [2.5, 4.0],
            [3.0, 4.0],
            [3.0, 9.0],
            [1.0, 9.0],
            [1.0, 10.0],
            [-1.0, 10.0],
        ];
        let (z, half) = side_depth(&side, [0.0, 1.0], 5.0, SidePick::Whole).expect("a slice");
        assert!(
            z.abs() < crate::check::tol::ROUNDING
                && (half - 1.0).abs() < crate::check::tol::ROUNDING,
            "{z} {half}"
        );
        // above the arm the slice is one interval, the whole of it
        let (z, half) = side_depth(&side, [0.0, 1.0], 8.5, SidePick::Whole).expect("a slice");
        assert!(
            (z - 1.0).abs() < crate::check::tol::ROUNDING
                && (half - 2.0).abs() < crate::check::tol::ROUNDING,
            "{z} {half}"
        );
    }

    /// An upright part's parameter counts its radii ([`RADIUS_WEIGHT`]):
    /// across a ledge (a waist stepping out to the hips) a span of `u` is
    /// the centres' distance and the radii's change, so the step is not a
    /// jump of the radius over a short span (which made the chain ring).
    #[test]
    fn an_upright_part_s_parameter_counts_its_radii_change() {
        let (wide, narrow, step) = (0.3, 0.15, 0.45);
        let right = [[wide, 0.0], [wide, step], [narrow, step], [narrow, 1.0]];
        let mut front = right.to_vec();
        front.extend(right.iter().rev().map(|p| [-p[0], p[1]]));
        let r = Region {
            name: "torso".into(),
            y0: 0.05,
            y1: 0.95,
            pick: super::super::segment::Pick::CentreIn(-1.0, 1.0),
            downward: false,
            tip: false,
            shoulder: None,
            side: SidePick::Whole,
            horizontal: false,
        };
        let part = part_from_region(&front, None, &r).expect("the part");
        let radius = |s: &SectionSpec| match s.shape {
            SectionShape::Circle { r } => r,
            _ => panic!("no side view: circles"),
        };
        let mut stepped = 0;
        for w in part.sections.windows(2) {
            let d = crate::mesh::dist(w[0].centre, w[1].centre);
            let dr = (radius(&w[1]) - radius(&w[0])) * std::f64::consts::SQRT_2;
            let want = d.hypot(RADIUS_WEIGHT * dr);
            let got = w[1].u - w[0].u;
            assert!(
                (got - want).abs() <= crate::check::tol::ROUNDING * want.max(1.0),
                "span {got} against {want}"
            );
            if dr.abs() > d {
                stepped += 1;
            }
        }
        assert!(stepped > 0, "a span crosses the ledge");
    }
}
