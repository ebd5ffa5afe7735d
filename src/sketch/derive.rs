//! From outlines to the document's derived parts: key sections per part
//! (circles, ellipses with the side profile, GEC fits of key cross-section
//! sketches) and the transitions.

use super::align::{alignment, Alignment};
use super::cuts::{join_heights, CutPath};
use super::poly::slice;
use super::segment::{landmarks, regions, shoulder_top, Landmarks, Region, SidePick};
use super::SketchError;
use crate::character::doc::{
    BodyPlan, KeySection, Level, PartSpec, SectionShape, SectionSpec, SurfaceSpec, TransitionSpec,
};

pub use super::section_place::SECTIONS_PER_PART;
use super::section_place::{centre_slope, direction, place, samples, Sample};
/// Tilt of an arm's top section (degrees from horizontal, see `tilt_top`).
pub const SHOULDER_TILT_DEG: f64 = 60.0;
/// Sections of an arm's top that are tilted (by linearly less).
pub const SHOULDER_TILT_SECTIONS: usize = 2;
/// GEC terms for key cross-section sketches.
pub const GEC_TERMS: usize = 6;
/// Largest allowed side/front height mismatch (relative).
pub const HEIGHT_MISMATCH: f64 = 0.05;
/// How far a key section may reach beyond its part's width (relative).
pub const SECTION_SLACK: f64 = 0.15;

/// Parts and transitions derived from the outlines.
#[derive(Clone, Debug)]
pub struct Derived {
    /// The body plan used (never `Auto`).
    pub plan: BodyPlan,
    /// The drawing's rotation from upright (identity when upright).
    pub alignment: Alignment,
    /// A humanoid's landmarks in the upright frame.
    pub landmarks: Option<Landmarks>,
    /// A quadruped's landmarks.
    pub quadruped: Option<super::quadruped::QuadLandmarks>,
    pub parts: Vec<PartSpec>,
    pub transitions: Vec<TransitionSpec>,
}

/// Side-profile depth at height y: `(centre z, half depth)` of the slice
/// part `pick` names (None when hidden or when there is none).
fn side_depth(side: &[[f64; 2]], map: [f64; 2], y: f64, pick: SidePick) -> Option<(f64, f64)> {
    let s = slice(side, map[0] + map[1] * y);
    let (lo, hi) = match pick {
        SidePick::Hidden => return None,
        SidePick::Whole => (s.first()?[0], s.last()?[1]),
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

pub(super) fn part_from_region(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    r: &Region,
) -> Result<PartSpec, SketchError> {
    // side heights mapped onto the front's (the two agree within 5 %)
    let map = match side {
        Some(sd) => {
            let fy = crate::polygon::span(front, 1);
            let sy = crate::polygon::span(sd, 1);
            let k = (sy[1] - sy[0]) / (fy[1] - fy[0]);
            [sy[0] - k * fy[0], k]
        }
        None => [0.0, 1.0],
    };
    let s = samples(front, r);
    if s.len() < SECTIONS_PER_PART + 2 {
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
    let foot = match (leg_with_side(r), side, depth.as_deref()) {
        (true, Some(sd), Some(d)) => super::foot::find(sd, map, &s, d, SECTIONS_PER_PART + 3),
        _ => None,
    };
    let (n_upper, m_foot) = match &foot {
        Some(f) => (f.last_upper + 1, foot_sections(&s, f)),
        None => (s.len(), 0),
    };
    // the leg above the bend keeps its sections; the chain's count stays
    // 3 P + 1 (`SECTIONS_PER_PART`'s rule)
    let m_upper = match &foot {
        Some(_) => {
            let lower = 3 + m_foot;
            (SECTIONS_PER_PART + lower - 1).div_ceil(3) * 3 + 1 - lower
        }
        None => SECTIONS_PER_PART,
    };
    let idx = place(
        &s[..n_upper],
        depth.as_deref().map(|d| &d[..n_upper]),
        m_upper,
    );
    let mut sections = Vec::with_capacity(idx.len() + 1);
    let mut u = 0.0;
    let mut prev: Option<[f64; 3]> = None;
    for (j, &i) in idx.iter().enumerate() {
        let dir = direction(&s, i);
        let t = if r.horizontal {
            [0.0, dir, 0.0]
        } else {
            [dir * centre_slope(&s, i), dir, 0.0]
        };
        let tn = t[0].hypot(t[1]);
        let t = [t[0] / tn, t[1] / tn, 0.0];
        let e1 = [t[1], -t[0], 0.0];
        let e2 = [0.0, 0.0, 1.0];
        let cos_tilt = t[1].abs();
        let centre0 = [s[i].c, s[i].y, 0.0];
        if let Some(p) = prev {
            u += crate::mesh::dist(p, centre0);
        }
        prev = Some(centre0);
        let a_r = s[i].w * cos_tilt;
        let last = j + 1 == idx.len() && foot.is_none();
        let shape = match (uses_side, side) {
            (true, Some(sd)) if !(last && r.tip) => match side_depth(sd, map, s[i].y, r.side) {
                Some((zc, b)) => SectionShape::Ellipse {
                    a: a_r,
                    b,
                    offset: zc,
                },
                None => SectionShape::Circle { r: a_r },
            },
            _ => SectionShape::Circle { r: a_r },
        };
        sections.push(SectionSpec {
            u,
            centre: centre0,
            e1,
            e2,
            shape,
        });
    }
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
        let pts = super::foot::path(sd, f, m_foot);
        sections.extend(super::foot::sections(&end, f, &pts));
    } else if r.tip {
        // the free end collapses to the outline's extreme point
        let tip_y = if r.downward { r.y0 } else { r.y1 };
        let lastc = sections.last().map(|q| q.centre).unwrap_or([0.0; 3]);
        let mut zc = 0.0;
        if let (true, Some(sd)) = (uses_side, side) {
            if let Some((z, _)) = side_depth(sd, map, s[s.len() - 1].y, r.side) {
                zc = z;
            }
        }
        let tip = [lastc[0], tip_y, 0.0];
        let last = sections.last_mut().expect("sections");
        last.u += crate::mesh::dist(lastc, tip);
        last.centre = [tip[0], tip[1], zc];
        last.shape = SectionShape::Circle { r: 0.0 };
    }
    if let Some(out) = r.shoulder {
        tilt_top(front, &s, &idx, out, &mut sections);
    }
    Ok(PartSpec {
        name: r.name.clone(),
        surface: SurfaceSpec::Pde6C2 { a: 0.0 },
        sections,
        closed_start: false,
        closed_end: r.tip,
    })
}

/// A humanoid leg read with the side view (its depth from the side's whole
/// slice): the only part whose side view can show a foot.
fn leg_with_side(r: &Region) -> bool {
    r.downward && r.tip && r.shoulder.is_none() && r.side == SidePick::Whole
}

/// Sections along a foot (after the three of the bend, the last one its
/// toe): its share of the leg's path length, so that the foot's sections
/// are spaced like the leg's, between 2 and 4.
fn foot_sections(s: &[Sample], f: &super::foot::Foot) -> usize {
    let up: f64 = s[..=f.last_upper]
        .windows(2)
        .map(|w| (w[1].y - w[0].y).hypot(w[1].c - w[0].c))
        .sum();
    let bend = std::f64::consts::FRAC_PI_2 * f.radius;
    let along = (f.toe[0] - f.start[0]).abs() - f.radius;
    let total = up + bend + along;
    let share = (SECTIONS_PER_PART - 1) as f64 * along / total;
    (share.round() as usize).clamp(2, 4)
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

/// The side profile must be drawn at the front's heights: its lowest point
/// within [`HEIGHT_MISMATCH`] of the front's height from the front's (the
/// views share model y; a side drawn 5 m higher would be measured against
/// a model that is not there). Checked on the outlines as drawn.
pub(super) fn check_side_position(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
) -> Result<(), SketchError> {
    let Some(sd) = side else { return Ok(()) };
    let fy = crate::polygon::span(front, 1);
    let ys = crate::polygon::span(sd, 1);
    let shift = (ys[0] - fy[0]).abs() / (fy[1] - fy[0]);
    if shift > HEIGHT_MISMATCH {
        return Err(SketchError::Mismatch(format!(
            "the side profile spans model y {:.4} to {:.4}, the front {:.4} to {:.4}: draw both views at the same heights (their lowest points within {:.0} % of the height; they differ by {:.1} %)",
            ys[0],
            ys[1],
            fy[0],
            fy[1],
            100.0 * HEIGHT_MISMATCH,
            100.0 * shift
        )));
    }
    Ok(())
}

/// The side profile's height must match the front's within
/// [`HEIGHT_MISMATCH`].
pub(super) fn check_side_height(
    front_height: f64,
    side: Option<&[[f64; 2]]>,
) -> Result<(), SketchError> {
    if let Some(sd) = side {
        let ys = crate::polygon::span(sd, 1);
        let hs = ys[1] - ys[0];
        let rel = (hs - front_height).abs() / front_height;
        if rel > HEIGHT_MISMATCH {
            return Err(SketchError::Mismatch(format!(
                "side profile height {hs:.4} differs from the front height {front_height:.4} by {:.1} % (> {:.0} %)",
                100.0 * rel,
                100.0 * HEIGHT_MISMATCH
            )));
        }
    }
    Ok(())
}

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
        return super::quadruped::derive(front, side, sections, cuts, level);
    }
    let ax = super::align::axes(front);
    if ax.anisotropy >= super::align::MIN_ANISOTROPY && ax.major.abs() < std::f64::consts::FRAC_PI_4
    {
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
    for p in &mut d.parts {
        for s in &mut p.sections {
            s.centre = al.point_back(s.centre);
            s.e1 = al.vector_back(s.e1);
            s.e2 = al.vector_back(s.e2);
        }
    }
    for t in &mut d.transitions {
        for a in &mut t.seam_apex {
            *a = al.point_back(*a);
        }
    }
    d.alignment = al;
    Ok(d)
}

/// The two arms traced from the armpits ([`super::limb`]): their parts
/// and their shoulder points (left, right). An arm starts a join band
/// ([`super::segment::GAP_FRACTION`] of the height) out from its cut, or
/// where a user's cut path crosses it.
fn traced_arms(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    lm: &Landmarks,
    joins: &super::cuts::JoinHeights,
) -> Result<(Vec<PartSpec>, [[f64; 2]; 2]), SketchError> {
    let g = super::segment::GAP_FRACTION * lm.height();
    let neck = super::segment::neck_interval(front, lm)
        .ok_or_else(|| SketchError::Segmentation(
            "no neck found above the armpits: draw the head on a neck narrower than the shoulders, above both arms".into(),
        ))?;
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
    let mut shoulders = [[0.0; 2]; 2];
    for (k, (name, armpit, sign, neck_x)) in [
        ("arm_l", lm.armpit_l, -1.0, neck[0]),
        ("arm_r", lm.armpit_r, 1.0, neck[1]),
    ]
    .into_iter()
    .enumerate()
    {
        let t = super::limb::trace_arm(front, armpit, sign, neck_x, name)?;
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
        parts.push(super::limb::part_from_trace(front, name, &t, start, z)?);
        shoulders[k] = t.shoulder;
    }
    Ok((parts, shoulders))
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
    let mut parts = regs
        .iter()
        .map(|r| part_from_region(front, side, r))
        .collect::<Result<Vec<_>, _>>()?;
    let (arms, shoulders) = traced_arms(front, side, &lm, &joins)?;
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
    let ya = lm.armpit_l[1].min(lm.armpit_r[1]) - g;
    let torso = &parts[0];
    let r_top = match torso.sections.last().map(|s| &s.shape) {
        Some(SectionShape::Circle { r }) => *r,
        Some(SectionShape::Ellipse { a, .. }) => *a,
        _ => g,
    };
    let top_c = torso.sections.last().map(|s| s.centre).unwrap_or([0.0; 3]);
    // shoulder apex: the top of the outline halfway between the neck's side
    // and the shoulder's outer side (at the armpits' height)
    let neck_iv = super::segment::neck_interval(front, &lm);
    let outer = slice(front, ya + g);
    let apex = |sign: f64| -> [f64; 3] {
        let neck_x = match neck_iv {
            Some(iv) => {
                if sign < 0.0 {
                    iv[0]
                } else {
                    iv[1]
                }
            }
            None => top_c[0] + sign * 0.5 * r_top,
        };
        // the arm's shoulder point (the upper end of its cut)
        let out_x = if sign < 0.0 {
            shoulders[0][0]
        } else {
            shoulders[1][0]
        };
        let _ = &outer;
        let x = 0.5 * (neck_x + out_x);
        let y = shoulder_top(front, x)
            .filter(|y| *y < lm.neck_base + g)
            .unwrap_or(ya + 4.0 * g);
        [x, y, top_c[2]]
    };
    let bot_c = torso.sections[0].centre;
    let transitions = TransitionSpec::humanoid(
        [lm.crotch[0], lm.crotch[1], bot_c[2]],
        vec![apex(-1.0), apex(1.0)],
        1.0,
    );
    Ok(Derived {
        plan: BodyPlan::Humanoid,
        alignment: Alignment::identity(),
        landmarks: Some(lm),
        quadruped: None,
        parts,
        transitions,
    })
}
