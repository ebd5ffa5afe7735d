//! From outlines to the document's derived parts: key sections per part
//! (circles, ellipses with the side profile, GEC fits of key cross-section
//! sketches) and the transitions.

use super::poly::slice;
use super::segment::{interval, landmarks, regions, shoulder_top, Landmarks, Region};
use super::SketchError;
use crate::character::doc::{
    End, KeySection, Level, PartSpec, SectionShape, SectionSpec, SurfaceSpec, TransitionSpec,
};
use crate::curve::gec::Frame;

/// Sections per part: `3 P + 1` (the C2 PDE chain's rule), P = 4.
pub const SECTIONS_PER_PART: usize = 13;
/// Dense samples of a region's profile used to place sections.
const PROFILE_SAMPLES: usize = 240;
/// GEC terms for key cross-section sketches.
pub const GEC_TERMS: usize = 6;
/// Largest allowed side/front height mismatch (relative).
pub const HEIGHT_MISMATCH: f64 = 0.05;
/// How far a key section may reach beyond its part's width (relative).
pub const SECTION_SLACK: f64 = 0.15;

/// Parts and transitions derived from the outlines.
#[derive(Clone, Debug)]
pub struct Derived {
    pub landmarks: Landmarks,
    pub parts: Vec<PartSpec>,
    pub transitions: Vec<TransitionSpec>,
}

struct Sample {
    y: f64,
    c: f64,
    w: f64,
}

fn samples(front: &[[f64; 2]], r: &Region) -> Vec<Sample> {
    let n = PROFILE_SAMPLES;
    // stay a hair inside the tip so the slice exists
    let eps = 1e-4 * (r.y1 - r.y0);
    (0..=n)
        .filter_map(|k| {
            let t = k as f64 / n as f64;
            let y = if r.downward {
                r.y1 - t * (r.y1 - r.y0 - if r.tip { eps } else { 0.0 })
            } else {
                r.y0 + t * (r.y1 - r.y0 - if r.tip { eps } else { 0.0 })
            };
            interval(front, r.pick, y).map(|iv| Sample {
                y,
                c: 0.5 * (iv[0] + iv[1]),
                w: 0.5 * (iv[1] - iv[0]),
            })
        })
        .collect()
}

/// Indices of `m` samples: half arc length, half profile variation.
fn place(s: &[Sample], m: usize) -> Vec<usize> {
    let n = s.len();
    let mut len = vec![0.0; n];
    let mut inc = vec![0.0; n];
    let wmax = s.iter().map(|q| q.w).fold(f64::MIN_POSITIVE, f64::max);
    for i in 1..n {
        len[i] = len[i - 1] + (s[i].y - s[i - 1].y).hypot(s[i].c - s[i - 1].c);
        if i + 1 < n {
            // second differences of the squared half-width (smooth at a
            // round tip, where the half-width itself is not) and the centre
            let w2 = |k: usize| s[k].w * s[k].w / wmax;
            let d2w = w2(i + 1) - 2.0 * w2(i) + w2(i - 1);
            let d2c = s[i + 1].c - 2.0 * s[i].c + s[i - 1].c;
            inc[i] = d2w.abs() + d2c.abs();
        }
    }
    // no single slice may attract more than a few sections
    let mean = inc.iter().sum::<f64>() / n as f64;
    let mut var = vec![0.0; n];
    for i in 1..n {
        var[i] = var[i - 1] + inc[i].min(4.0 * mean);
    }
    let (lt, vt) = (len[n - 1], var[n - 1].max(f64::MIN_POSITIVE));
    let f: Vec<f64> = (0..n)
        .map(|i| 0.5 * len[i] / lt + 0.5 * var[i] / vt)
        .collect();
    let mut idx: Vec<usize> = (0..m)
        .map(|j| {
            let target = j as f64 / (m - 1) as f64;
            f.iter().position(|&v| v >= target - 1e-12).unwrap_or(n - 1)
        })
        .collect();
    idx[0] = 0;
    idx[m - 1] = n - 1;
    // strictly increasing, keeping the ends
    for j in 1..m {
        idx[j] = idx[j].max(idx[j - 1] + 1).min(n - m + j);
    }
    for j in (0..m - 1).rev() {
        if idx[j] >= idx[j + 1] {
            idx[j] = idx[j + 1] - 1;
        }
    }
    idx
}

/// Side-profile depth at height y: `(centre z, half depth)`.
fn side_depth(side: &[[f64; 2]], map: [f64; 2], y: f64) -> Option<(f64, f64)> {
    let s = slice(side, map[0] + map[1] * y);
    let lo = s.first()?[0];
    let hi = s.last()?[1];
    Some((0.5 * (lo + hi), 0.5 * (hi - lo)))
}

fn part_from_region(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    r: &Region,
) -> Result<PartSpec, SketchError> {
    // side heights mapped onto the front's (the two agree within 5 %)
    let map = match side {
        Some(sd) => {
            let (fy, _) = super::poly::bounds(front);
            let (sy, _) = super::poly::bounds(sd);
            let k = (sy[1] - sy[0]) / (fy[1] - fy[0]);
            [sy[0] - k * fy[0], k]
        }
        None => [0.0, 1.0],
    };
    let s = samples(front, r);
    if s.len() < SECTIONS_PER_PART + 2 {
        return Err(SketchError::Segmentation(format!(
            "{}: only {} slices",
            r.name,
            s.len()
        )));
    }
    let idx = place(&s, SECTIONS_PER_PART);
    let uses_side = side.is_some() && !r.name.starts_with("arm");
    let mut sections = Vec::with_capacity(idx.len() + 1);
    let mut u = 0.0;
    let mut prev: Option<[f64; 3]> = None;
    for (j, &i) in idx.iter().enumerate() {
        // tangent from neighbouring samples
        let (a, b) = (i.saturating_sub(2), (i + 2).min(s.len() - 1));
        let t = [s[b].c - s[a].c, s[b].y - s[a].y, 0.0];
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
        let last = j + 1 == idx.len();
        let shape = match (uses_side, side) {
            (true, Some(sd)) if !(last && r.tip) => match side_depth(sd, map, s[i].y) {
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
    if r.tip {
        // the free end collapses to the outline's extreme point
        let tip_y = if r.downward { r.y0 } else { r.y1 };
        let lastc = sections.last().map(|q| q.centre).unwrap_or([0.0; 3]);
        let mut zc = 0.0;
        if let (true, Some(sd)) = (uses_side, side) {
            if let Some((z, _)) = side_depth(sd, map, s[s.len() - 1].y) {
                zc = z;
            }
        }
        let tip = [lastc[0], tip_y, 0.0];
        let last = sections.last_mut().expect("sections");
        last.u += crate::mesh::dist(lastc, tip);
        last.centre = [tip[0], tip[1], zc];
        last.shape = SectionShape::Circle { r: 0.0 };
    }
    Ok(PartSpec {
        name: r.name.into(),
        surface: SurfaceSpec::Pde6C2 { a: 0.0 },
        sections,
        closed_start: false,
        closed_end: r.tip,
    })
}

/// Fits a key cross-section sketch and puts it in place of the nearest
/// section of its part.
fn apply_key_section(parts: &mut [PartSpec], k: &KeySection) -> Result<(), SketchError> {
    let part = parts
        .iter_mut()
        .find(|p| p.name == k.part)
        .ok_or_else(|| SketchError::Section(format!("unknown part '{}'", k.part)))?;
    let ys: Vec<f64> = part.sections.iter().map(|s| s.centre[1]).collect();
    let (lo, hi) = ys
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| {
            (a.min(y), b.max(y))
        });
    if !(k.y > lo && k.y < hi) {
        return Err(SketchError::Section(format!(
            "section of '{}' at y = {} is outside the part (y from {lo:.4} to {hi:.4})",
            k.part, k.y
        )));
    }
    let (j, _) = ys
        .iter()
        .enumerate()
        .filter(|(j, _)| *j > 0 && *j + 1 < ys.len())
        .min_by(|a, b| (a.1 - k.y).abs().total_cmp(&(b.1 - k.y).abs()))
        .ok_or_else(|| SketchError::Section("part has no interior section".into()))?;
    let sec = &part.sections[j];
    let half_width = match sec.shape {
        SectionShape::Circle { r } => r,
        SectionShape::Ellipse { a, .. } => a,
        SectionShape::Gec { .. } => f64::INFINITY,
    };
    let cx = sec.centre[0];
    for p in &k.points {
        if (p[0] - cx).abs() > (1.0 + SECTION_SLACK) * half_width {
            return Err(SketchError::Section(format!(
                "section of '{}' at y = {}: point ({}, {}) is outside the part (half-width {half_width:.4} about x = {cx:.4})",
                k.part, k.y, p[0], p[1]
            )));
        }
    }
    // the sketch lies in the horizontal plane at its y; its angles are those
    // of its bounding ellipse (the parameter of the neighbouring ellipse
    // sections, so the chain does not twist between them)
    let centre = [sec.centre[0], k.y, 0.0];
    let frame = Frame::new(centre, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0])
        .map_err(|e| SketchError::Section(e.to_string()))?;
    let mut pts: Vec<[f64; 2]> = k.points.iter().map(|p| [p[0] - cx, p[1]]).collect();
    if pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    if pts.len() < 2 * GEC_TERMS + 2 {
        return Err(SketchError::Section(format!(
            "section of '{}' at y = {}: {} points, at least {} needed",
            k.part,
            k.y,
            pts.len(),
            2 * GEC_TERMS + 2
        )));
    }
    super::poly::validate_outline("key section", &pts)?;
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in &pts {
        for d in 0..2 {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    let mid = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let half = [0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1])];
    let mut thetas: Vec<f64> = pts
        .iter()
        .map(|p| ((p[1] - mid[1]) / half[1]).atan2((p[0] - mid[0]) / half[0]))
        .collect();
    // unwrap to a monotone sequence in the direction of travel
    let dir = if super::poly::signed_area2(&pts) > 0.0 {
        1.0
    } else {
        -1.0
    };
    let tau = 2.0 * std::f64::consts::PI;
    let step = 1e-3 * tau / thetas.len() as f64;
    for i in 1..thetas.len() {
        // nearest branch to the previous angle, then monotone
        let d = (thetas[i] - thetas[i - 1]) / tau;
        thetas[i] -= d.round() * tau;
        if dir * (thetas[i] - thetas[i - 1]) < step {
            thetas[i] = thetas[i - 1] + dir * step;
        }
    }
    if dir * (thetas[thetas.len() - 1] - thetas[0]) >= tau {
        return Err(SketchError::Section(format!(
            "section of '{}' at y = {}: the curve winds around its centre more than once",
            k.part, k.y
        )));
    }
    let (gc, gx, gy) = crate::curve::gec::fit::solve(&pts, &thetas, GEC_TERMS, Default::default())
        .map_err(|e| {
            SketchError::Section(format!("section of '{}' at y = {}: {e}", k.part, k.y))
        })?;
    let _ = frame;
    let rep = (gc, gx, gy);
    let sec = &mut part.sections[j];
    sec.centre = centre;
    sec.e1 = [1.0, 0.0, 0.0];
    sec.e2 = [0.0, 0.0, 1.0];
    sec.shape = SectionShape::Gec {
        centre: rep.0,
        x: rep.1,
        y: rep.2,
    };
    // re-measure u along the section centres
    let mut u = 0.0;
    for i in 1..part.sections.len() {
        u += crate::mesh::dist(part.sections[i - 1].centre, part.sections[i].centre);
        part.sections[i].u = u;
    }
    Ok(())
}

/// Derives parts and transitions from validated, counter-clockwise outlines.
pub fn derive(
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    sections: &[KeySection],
    level: Level,
) -> Result<Derived, SketchError> {
    let lm = landmarks(front)?;
    if let Some(sd) = side {
        let (ys, _) = super::poly::bounds(sd);
        let hs = ys[1] - ys[0];
        let rel = (hs - lm.height()).abs() / lm.height();
        if rel > HEIGHT_MISMATCH {
            return Err(SketchError::Mismatch(format!(
                "side profile height {hs:.4} differs from the front height {:.4} by {:.1} % (> {:.0} %)",
                lm.height(),
                100.0 * rel,
                100.0 * HEIGHT_MISMATCH
            )));
        }
    }
    let side = if level == Level::Initial { None } else { side };
    let regs = regions(front, &lm)?;
    let mut parts = regs
        .iter()
        .map(|r| part_from_region(front, side, r))
        .collect::<Result<Vec<_>, _>>()?;
    if level == Level::Final {
        for k in sections {
            apply_key_section(&mut parts, k)?;
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
    let neck_iv = interval(
        front,
        super::segment::Pick::CentreIn(lm.armpit_l[0], lm.armpit_r[0]),
        lm.neck_base,
    );
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
        let out_x = match (outer.first(), outer.last()) {
            (Some(a), Some(b)) => {
                if sign < 0.0 {
                    a[0]
                } else {
                    b[1]
                }
            }
            _ => top_c[0] + sign * r_top,
        };
        let x = 0.5 * (neck_x + out_x);
        let y = shoulder_top(front, x)
            .filter(|y| *y < lm.neck_base + g)
            .unwrap_or(ya + 4.0 * g);
        [x, y, top_c[2]]
    };
    let bot_c = torso.sections[0].centre;
    let transitions = vec![
        TransitionSpec {
            name: "hips".into(),
            parent: "torso".into(),
            parent_end: End::Start,
            children: vec!["leg_l".into(), "leg_r".into()],
            seam_apex: vec![[lm.crotch[0], lm.crotch[1], bot_c[2]]],
        },
        TransitionSpec {
            name: "shoulders".into(),
            parent: "torso".into(),
            parent_end: End::End,
            children: vec!["arm_l".into(), "head".into(), "arm_r".into()],
            seam_apex: vec![apex(-1.0), apex(1.0)],
        },
    ];
    Ok(Derived {
        landmarks: lm,
        parts,
        transitions,
    })
}
