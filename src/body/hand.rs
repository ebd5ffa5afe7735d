//! The hands of the closed body ([`super::closed`]): where the thumb
//! separates from the palm, found from the section loops along the arm's
//! trace (no vertex ids), the thumb traced along its own axis, and the palm
//! traced without the thumb's loops.
//!
//! Along the arm trace ([`super::layout::trace`], planes across the arm)
//! the hand's section is one loop from the wrist down to the crotch
//! between thumb and index finger; the first plane past the middle of the
//! trace that cuts two loops (near the plane's centre) is the **split**:
//! its loop farthest from the largest one is the thumb's (the thumb
//! separates before the fingers: the web between thumb and index finger
//! reaches deeper towards the wrist than the finger webs). From there:
//! * the thumb's loop is followed through the next arm planes (nearest
//!   centroid, within twice its radius): the track, whose centroids run
//!   along the thumb's axis (oblique cuts of a tube), give its direction;
//! * the thumb is traced along that direction ([`THUMB_STEP`] x the arm's
//!   step, one loop per plane, following its centroids) from the split to
//!   its tip, leaving out the first planes that still cut the palm;
//! * the palm and the fingers are traced on from the split as a mitten
//!   (the convex hull of the captured loops) leaving out every loop near
//!   the thumb's track or trace ([`trace_excluding`]), in planes parallel
//!   to the split's (a straight trace);
//! * the seam apex of the wrist transition is the middle of the gap
//!   between the thumb's loop and the palm's at the split, half a step
//!   back towards the wrist (the crotch of the web);
//! * the **web points** are the middles of the gaps between the thumb's
//!   loop and its nearest other loop in the arm planes past the split:
//!   air between thumb and index finger, which a mitten fills and a hand
//!   with a thumb leaves outside (`pde6.body_closed_thumb_web_*`).

use super::layout::{loops_in_plane, trace_excluding, Loop2, TraceOptions, TraceSample};
use super::layout::{CAPTURE, MIN_AREA};
use super::BodyError;
use crate::mesh::{dist, dot, norm, scale, sub, Mesh};

/// The thumb's trace step, relative to the arm's (the thumb is short: a
/// 7-section chain needs 7 samples).
pub const THUMB_STEP: f64 = 0.5;
/// Thumb vertices of the skin: within this factor of a thumb section's
/// radius of its centre, within half a thumb step of its plane.
pub const THUMB_VERTEX_RADIUS: f64 = 1.3;
/// Loops within this factor of a thumb loop's radius of its centre belong
/// to the thumb (left out of the palm's mitten).
pub const THUMB_EXCLUDE: f64 = 1.6;

/// A hand found along an arm trace.
#[derive(Clone, Debug)]
pub struct Hand {
    /// Index in the arm trace of the first plane cutting the thumb apart.
    pub split: usize,
    /// The thumb's loops in the arm planes from the split on: centroid
    /// (model coordinates) and radius.
    pub track: Vec<([f64; 3], f64)>,
    /// The thumb traced along its own axis, from the split to its tip.
    pub thumb: Vec<TraceSample>,
    /// The palm and fingers (a mitten without the thumb), from the split.
    pub palm: Vec<TraceSample>,
    /// The crotch between thumb and index finger.
    pub apex: [f64; 3],
    /// Air points between the thumb and the palm or index finger.
    pub web: Vec<[f64; 3]>,
    /// The thumb's share of the two loops' perimeters at the split.
    pub thumb_share: f64,
}

fn perimeter(l: &Loop2) -> f64 {
    let n = l.points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (l.points[i], l.points[(i + 1) % n]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .sum()
}

/// The closest pair of points of two loops (2D) and their distance.
fn closest_pair(a: &Loop2, b: &Loop2) -> ([f64; 2], [f64; 2], f64) {
    let mut best = ([0.0; 2], [0.0; 2], f64::INFINITY);
    for p in &a.points {
        for q in &b.points {
            let d = (p[0] - q[0]).hypot(p[1] - q[1]);
            if d < best.2 {
                best = (*p, *q, d);
            }
        }
    }
    best
}

fn unit(v: [f64; 3]) -> [f64; 3] {
    scale(v, 1.0 / norm(v).max(f64::MIN_POSITIVE))
}

fn not_found(detail: String) -> BodyError {
    BodyError::LayoutNotFound {
        what: "a thumb",
        detail,
    }
}

/// Finds the hand at the end of an arm trace `arm` (mitten sections, step
/// `step`, body height `h`).
pub fn find_hand(m: &Mesh, arm: &[TraceSample], h: f64, step: f64) -> Result<Hand, BodyError> {
    let (split, ls) = split_plane(m, arm)?;
    let f = &arm[split].frame;
    let (ti, big) = thumb_and_palm(&ls)?;
    let (thumb0, palm0) = (&ls[ti], &ls[big]);
    let thumb_share = perimeter(thumb0) / (perimeter(thumb0) + perimeter(palm0));
    let (p, q, _) = closest_pair(thumb0, palm0);
    let arm_dir = f.normal();
    let apex = sub(
        f.place(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])),
        scale(arm_dir, 0.5 * step),
    );
    let (track, web) = follow_thumb(m, arm, split, thumb0);
    let thumb = thumb_trace(m, &track, arm_dir, h, step)?;
    let near_thumb = |p: [f64; 3]| {
        track
            .iter()
            .copied()
            .chain(thumb.iter().map(|t| (t.frame.origin, t.radius)))
            .any(|(c, r)| dist(p, c) <= THUMB_EXCLUDE * r)
    };
    let palm = trace_excluding(
        m,
        f.place(palm0.centroid[0], palm0.centroid[1]),
        arm_dir,
        palm0.radius,
        // straight: with its planes following the centroids the palm's
        // trace swung where fingers left the capture, and the mitten
        // chain through those sections crossed itself (README)
        TraceOptions::new(step, 0.2 * h).with_hull(true),
        &near_thumb,
    )?;
    Ok(Hand {
        split,
        track,
        thumb,
        palm,
        apex,
        web,
        thumb_share,
    })
}

/// The split: the first plane of `arm` past its middle cutting two
/// captured loops (near the plane's centre, not tiny), its index and its
/// captured loops.
fn split_plane(m: &Mesh, arm: &[TraceSample]) -> Result<(usize, Vec<Loop2>), BodyError> {
    let s_last = arm.last().map_or(0.0, |t| t.s);
    let captured = |t: &TraceSample| -> Vec<Loop2> {
        loops_in_plane(m, &t.frame)
            .into_iter()
            .filter(|l| l.centroid[0].hypot(l.centroid[1]) <= CAPTURE * t.radius)
            .filter(|l| l.area >= MIN_AREA * t.radius * t.radius)
            .collect()
    };
    let mut found = None;
    for (k, t) in arm.iter().enumerate() {
        if t.s < 0.5 * s_last {
            continue;
        }
        let ls = captured(t);
        if ls.len() >= 2 {
            found = Some((k, ls));
            break;
        }
    }
    found.ok_or_else(|| {
        not_found(format!(
            "no plane of the arm trace (length {s_last:.3}) past its middle cuts two loops"
        ))
    })
}

/// The thumb's and the palm's loops among the split's `ls`: the palm's the
/// largest, the thumb's the one farthest from it.
fn thumb_and_palm(ls: &[Loop2]) -> Result<(usize, usize), BodyError> {
    let big = (0..ls.len())
        .max_by(|&a, &b| ls[a].area.total_cmp(&ls[b].area))
        .unwrap_or(0);
    let cd =
        |a: &Loop2, b: &Loop2| (a.centroid[0] - b.centroid[0]).hypot(a.centroid[1] - b.centroid[1]);
    let ti = (0..ls.len())
        .filter(|&i| i != big)
        .max_by(|&a, &b| cd(&ls[a], &ls[big]).total_cmp(&cd(&ls[b], &ls[big])))
        .ok_or_else(|| not_found("one loop at the split".into()))?;
    Ok((ti, big))
}

/// The thumb's loops in successive arm planes: centroid (model
/// coordinates) and radius.
type Track = Vec<([f64; 3], f64)>;

/// The thumb's loop `thumb0` at the split followed through the next arm
/// planes (nearest centroid within twice its radius): the track (centroid,
/// radius) and the web points between it and its nearest other loop.
fn follow_thumb(
    m: &Mesh,
    arm: &[TraceSample],
    split: usize,
    thumb0: &Loop2,
) -> (Track, Vec<[f64; 3]>) {
    let f = &arm[split].frame;
    let mut track = vec![(
        f.place(thumb0.centroid[0], thumb0.centroid[1]),
        thumb0.radius,
    )];
    let mut web = Vec::new();
    for t in arm.iter().skip(split + 1) {
        let (prev, r) = *track.last().unwrap_or(&([0.0; 3], 0.0));
        let ls = loops_in_plane(m, &t.frame);
        let place = |l: &Loop2| t.frame.place(l.centroid[0], l.centroid[1]);
        let Some(i) = (0..ls.len())
            .filter(|&i| dist(place(&ls[i]), prev) <= 2.0 * r)
            .min_by(|&a, &b| dist(place(&ls[a]), prev).total_cmp(&dist(place(&ls[b]), prev)))
        else {
            break;
        };
        let other = (0..ls.len())
            .filter(|&j| j != i && ls[j].area >= MIN_AREA * t.radius * t.radius)
            .map(|j| closest_pair(&ls[i], &ls[j]))
            .min_by(|a, b| a.2.total_cmp(&b.2));
        if let Some((p, q, _)) = other {
            web.push(t.frame.place(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])));
        }
        track.push((place(&ls[i]), ls[i].radius));
    }
    (track, web)
}

/// The thumb traced from the track's start along the track's direction
/// (the arm's, `arm_dir`, for a track of one loop); refuses fewer than
/// four sections.
fn thumb_trace(
    m: &Mesh,
    track: &[([f64; 3], f64)],
    arm_dir: [f64; 3],
    h: f64,
    step: f64,
) -> Result<Vec<TraceSample>, BodyError> {
    let dir = if track.len() >= 2 {
        unit(sub(track[track.len() - 1].0, track[0].0))
    } else {
        arm_dir
    };
    let (c0, r0) = track[0];
    let thumb = super::layout::trace(
        m,
        c0,
        dir,
        r0,
        TraceOptions::new(THUMB_STEP * step, 0.1 * h)
            .following(true)
            .with_skip(0.03 * h),
    )?;
    if thumb.len() < 4 {
        return Err(not_found(format!(
            "the thumb's trace from ({:.3}, {:.3}, {:.3}) found {} sections",
            c0[0],
            c0[1],
            c0[2],
            thumb.len()
        )));
    }
    Ok(thumb)
}

/// The skin vertices of the thumb: near a section of the thumb's trace
/// (within half a thumb step of its plane, [`THUMB_VERTEX_RADIUS`] x its
/// radius of its centre).
pub fn thumb_vertices(m: &Mesh, hand: &Hand) -> Vec<usize> {
    let half = match hand.thumb.as_slice() {
        [a, b, ..] => 0.5 * (b.s - a.s).abs().max(f64::MIN_POSITIVE),
        _ => return Vec::new(),
    };
    m.positions
        .iter()
        .enumerate()
        .filter(|(_, p)| {
            hand.thumb.iter().any(|t| {
                let (q, d) = t.frame.project(**p);
                d.abs() <= half && q[0].hypot(q[1]) <= THUMB_VERTEX_RADIUS * t.radius
            })
        })
        .map(|(i, _)| i)
        .collect()
}

/// The generalised winding number of a closed oriented mesh around `p`
/// (1 inside, 0 outside; the solid angles of its triangles over 4 pi).
pub fn winding_number(m: &Mesh, p: [f64; 3]) -> f64 {
    let mut w = 0.0;
    for t in &m.triangles {
        let a = sub(m.positions[t[0] as usize], p);
        let b = sub(m.positions[t[1] as usize], p);
        let c = sub(m.positions[t[2] as usize], p);
        let (la, lb, lc) = (norm(a), norm(b), norm(c));
        let det = dot(a, crate::vec3::cross(b, c));
        let den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
        w += 2.0 * det.atan2(den);
    }
    w / (4.0 * std::f64::consts::PI)
}
