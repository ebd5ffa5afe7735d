//! The part layout of a standing humanoid found from its mesh alone (no
//! skeleton, no vertex groups): the sole, crotch, armpit, neck and crown
//! heights from horizontal slices, and each limb's axis traced by marching
//! planes along it.
//!
//! Assumptions (checked, each failure names what was not found): Y up, the
//! body stands (its y extent is the largest), the legs separate below a
//! crotch, the arms hang free of the torso below the armpits (A-pose or
//! T-pose; arms against the body are refused), the neck is narrower than the
//! shoulders.
//!
//! Landmarks, scanning horizontal slices at steps of [`SCAN_STEP`] x height:
//! * crotch: going up from a quarter of the height, the first slice whose loop
//!   nearest to x = 0 straddles x = 0 (the two legs have merged);
//! * armpit: going up from the crotch, the first slice where that torso loop
//!   widens by more than [`ARMPIT_WIDENING`] over the previous one (the arms
//!   have joined it); below it there must be one free arm loop on each side;
//! * neck: going up from the armpit, the first slice where the loop around
//!   x = 0 is narrower than [`NECK_NARROWING`] x the widest shoulder slice.
//!
//! Limbs are traced by [`trace`]: a plane with normal `d` through the
//! predicted centre cuts the mesh; the loops whose centroids lie within
//! [`CAPTURE`] x the previous radius of the prediction are kept (a mitten:
//! their convex hull when `hull`, the nearest loop otherwise); `d` follows
//! the centroids when `follow`.

use super::BodyError;
use crate::curve::gec::fit::polygon_area_centroid;
use crate::curve::gec::Frame;
use crate::mesh::slice::slice;
use crate::mesh::{add, dist, dot, norm, scale, sub, Mesh};
use crate::profile::shapes::convex_hull;

/// Scan step of the landmark search, relative to the height.
pub const SCAN_STEP: f64 = 0.005;
/// The armpit: the torso slice widens by more than this factor at once.
pub const ARMPIT_WIDENING: f64 = 1.25;
/// The neck: the slice around x = 0 narrower than this fraction of the
/// widest shoulder slice.
pub const NECK_NARROWING: f64 = 0.45;
/// Loops whose centroid lies within this factor of the previous radius are
/// captured by a trace.
pub const CAPTURE: f64 = 1.25;
/// Loops smaller than this fraction of the squared previous radius are
/// ignored (slivers where the plane grazes a sole or a fingertip).
pub const MIN_AREA: f64 = 0.02;
/// A trace stops when the radius grows by more than this factor in a step.
pub const JUMP: f64 = 1.8;

fn layout_err(what: &'static str, detail: impl Into<String>) -> BodyError {
    BodyError::LayoutNotFound {
        what,
        detail: detail.into(),
    }
}

/// Heights of the landmarks (model units, y).
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Layout {
    pub sole: f64,
    pub crown: f64,
    pub crotch: f64,
    pub armpit: f64,
    pub neck: f64,
    /// Centroids of the free arm loops just below the armpit (left: x < 0).
    pub arm_left: [f64; 3],
    pub arm_right: [f64; 3],
}

impl Layout {
    pub fn height(&self) -> f64 {
        self.crown - self.sole
    }
}

/// A closed section loop in plane coordinates, with its area centroid and
/// largest distance from it.
#[derive(Clone, Debug)]
pub struct Loop2 {
    pub points: Vec<[f64; 2]>,
    /// Absolute enclosed area.
    pub area: f64,
    pub centroid: [f64; 2],
    pub radius: f64,
    pub x_range: (f64, f64),
}

fn loop2(points: Vec<[f64; 2]>) -> Option<Loop2> {
    if points.len() < 3 {
        return None;
    }
    let (area, c) = polygon_area_centroid(&points);
    if !(area.is_finite() && area.abs() > 0.0) {
        return None;
    }
    let radius = points
        .iter()
        .map(|p| (p[0] - c[0]).hypot(p[1] - c[1]))
        .fold(0.0, f64::max);
    let x_range = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p[0]), b.max(p[0]))
        });
    Some(Loop2 {
        area: area.abs(),
        points,
        centroid: c,
        radius,
        x_range,
    })
}

/// The frame of a section plane with normal `n` through `origin`: e2 is -z
/// made perpendicular to n (so anchor 0 of the sampling, at -e2, faces the
/// front), e1 = e2 x n.
pub fn plane_frame(origin: [f64; 3], n: [f64; 3]) -> Result<Frame, BodyError> {
    let n = scale(n, 1.0 / norm(n).max(f64::MIN_POSITIVE));
    let mut e2 = sub([0.0, 0.0, -1.0], scale(n, -n[2]));
    if norm(e2) < 0.2 {
        e2 = sub([0.0, -1.0, 0.0], scale(n, -n[1]));
    }
    let e2 = scale(e2, 1.0 / norm(e2));
    let e1 = crate::vec3::cross(e2, n);
    Ok(Frame::new(origin, e1, e2)?)
}

/// The closed loops of `m` in the plane (origin, n), in frame coordinates.
pub fn loops_in_plane(m: &Mesh, frame: &Frame) -> Vec<Loop2> {
    slice(m, frame.origin, frame.normal())
        .into_iter()
        .filter(|l| l.closed && l.points.len() >= 6)
        .filter_map(|l| loop2(l.points.iter().map(|p| frame.project(*p).0).collect()))
        .collect()
}

fn horizontal(m: &Mesh, y: f64) -> Result<Vec<Loop2>, BodyError> {
    let f = crate::pde6::sampling::section_frame(y)?;
    Ok(loops_in_plane(m, &f))
}

/// The loop nearest to x = 0 (by the distance of its x range to 0), if any.
fn central(loops: &[Loop2]) -> Option<&Loop2> {
    loops.iter().min_by(|a, b| {
        let d = |l: &Loop2| (l.x_range.0.max(0.0)).max(-l.x_range.1.min(0.0));
        d(a).total_cmp(&d(b)).then(b.radius.total_cmp(&a.radius))
    })
}

/// Finds the [`Layout`] of a standing humanoid mesh.
pub fn find_layout(m: &Mesh) -> Result<Layout, BodyError> {
    let (lo, hi, h) = standing_extent(m)?;
    let step = SCAN_STEP * h;
    let crotch = find_crotch(m, lo, h, step)?;
    check_legs(m, crotch, h)?;
    let armpit = find_armpit(m, crotch, hi, h, step)?;
    let (arm_left, arm_right) = free_arms(m, armpit, h)?;
    let neck = find_neck(m, armpit, hi, step)?;
    Ok(Layout {
        sole: lo[1],
        crown: hi[1],
        crotch,
        armpit,
        neck,
        arm_left,
        arm_right,
    })
}

/// The bounding box of `m` and its height; refuses an empty mesh, one
/// not finite and one whose y extent is not the largest.
fn standing_extent(m: &Mesh) -> Result<([f64; 3], [f64; 3], f64), BodyError> {
    if m.positions.is_empty() || m.triangles.is_empty() {
        return Err(layout_err("a body", "the mesh is empty"));
    }
    let (lo, hi) = m.bbox();
    let ext = sub(hi, lo);
    if !ext.iter().all(|x| x.is_finite()) {
        return Err(BodyError::NotFinite("mesh coordinates".into()));
    }
    let h = ext[1];
    if h <= 0.0 || h < ext[0] * 0.9 || h < ext[2] {
        return Err(layout_err(
            "a standing humanoid",
            format!(
                "the y extent {:.3} is not the largest (x {:.3}, z {:.3}); the body must stand with Y up",
                ext[1], ext[0], ext[2]
            ),
        ));
    }
    Ok((lo, hi, h))
}

/// The crotch: the first horizontal slice from a quarter of the height up
/// whose central loop spans x = 0.
fn find_crotch(m: &Mesh, lo: [f64; 3], h: f64, step: f64) -> Result<f64, BodyError> {
    let mut y = lo[1] + 0.25 * h;
    let mut crotch = None;
    while y < lo[1] + 0.75 * h {
        let ls = horizontal(m, y)?;
        if let Some(c) = central(&ls) {
            if c.x_range.0 < 0.0 && c.x_range.1 > 0.0 {
                crotch = Some(y);
                break;
            }
        }
        y += step;
    }
    crotch.ok_or_else(|| {
        layout_err(
            "the crotch",
            "no horizontal slice between 25 % and 75 % of the height has a loop around x = 0 (legs do not merge, or the body is not centred on x = 0)",
        )
    })
}

/// Refuses a body without a loop on each side of x = 0 just below the
/// crotch.
fn check_legs(m: &Mesh, crotch: f64, h: f64) -> Result<(), BodyError> {
    let below = horizontal(m, crotch - 0.02 * h)?;
    let legs = (
        below.iter().any(|l| l.x_range.1 < 0.0),
        below.iter().any(|l| l.x_range.0 > 0.0),
    );
    if !(legs.0 && legs.1) {
        return Err(layout_err(
            "two legs",
            format!(
                "below the crotch (y = {crotch:.3}) there is not one loop on each side of x = 0"
            ),
        ));
    }
    Ok(())
}

/// The armpits: a step below the first slice above the crotch where the
/// torso's loop widens suddenly ([`ARMPIT_WIDENING`]).
fn find_armpit(m: &Mesh, crotch: f64, hi: [f64; 3], h: f64, step: f64) -> Result<f64, BodyError> {
    let mut y = crotch + 2.0 * step;
    let mut prev_w = f64::NAN;
    let mut armpit = None;
    while y < hi[1] - 0.1 * h {
        let ls = horizontal(m, y)?;
        let c = central(&ls).filter(|c| c.x_range.0 < 0.0 && c.x_range.1 > 0.0);
        let Some(c) = c else {
            return Err(layout_err(
                "the torso",
                format!("no loop around x = 0 at y = {y:.3}"),
            ));
        };
        let w = c.x_range.1 - c.x_range.0;
        if w > ARMPIT_WIDENING * prev_w && y > crotch + 0.15 * h {
            armpit = Some(y - step);
            break;
        }
        prev_w = w;
        y += step;
    }
    armpit.ok_or_else(|| {
        layout_err(
            "the armpits",
            "the torso slice never widens suddenly above the crotch (arms against the body, or no arms)",
        )
    })
}

/// The centroids of the free arm loops just below the armpits (left,
/// right): on each side the largest loop apart from the torso's.
fn free_arms(m: &Mesh, armpit: f64, h: f64) -> Result<([f64; 3], [f64; 3]), BodyError> {
    let ya = armpit - 0.02 * h;
    let ls = horizontal(m, ya)?;
    let torso = central(&ls)
        .cloned()
        .ok_or_else(|| layout_err("the torso", format!("no loop at y = {ya:.3}")))?;
    let side = |left: bool| -> Option<[f64; 3]> {
        ls.iter()
            .filter(|l| {
                if left {
                    l.x_range.1 < torso.x_range.0
                } else {
                    l.x_range.0 > torso.x_range.1
                }
            })
            .max_by(|a, b| a.radius.total_cmp(&b.radius))
            .map(|l| [l.centroid[0], ya, -l.centroid[1]])
    };
    let (Some(arm_left), Some(arm_right)) = (side(true), side(false)) else {
        return Err(layout_err(
            "free arms",
            format!("below the armpits (y = {ya:.3}) there is no arm loop apart from the torso on each side (arms against the body?)"),
        ));
    };
    Ok((arm_left, arm_right))
}

/// The neck: the first slice above the armpits whose central loop is
/// narrower than [`NECK_NARROWING`] times the widest below it.
fn find_neck(m: &Mesh, armpit: f64, hi: [f64; 3], step: f64) -> Result<f64, BodyError> {
    let mut y = armpit + step;
    let mut widest: f64 = 0.0;
    let mut neck = None;
    while y < hi[1] - step {
        let ls = horizontal(m, y)?;
        if let Some(c) = central(&ls).filter(|c| c.x_range.0 < 0.0 && c.x_range.1 > 0.0) {
            let w = c.x_range.1 - c.x_range.0;
            widest = widest.max(w);
            if w < NECK_NARROWING * widest {
                neck = Some(y);
                break;
            }
        }
        y += step;
    }
    neck.ok_or_else(|| {
        layout_err(
            "the neck",
            "no slice above the armpits narrower than the shoulders",
        )
    })
}

/// One traced section.
#[derive(Clone, Debug)]
pub struct TraceSample {
    /// Arc length of the centres from the first sample.
    pub s: f64,
    pub frame: Frame,
    /// The section polygon in frame coordinates (origin = its centroid).
    pub plane: Vec<[f64; 2]>,
    pub radius: f64,
}

/// Options of a trace: [`TraceOptions::new`] (a step and a length, the
/// direction fixed, no hull, no skip, [`JUMP`]), then the builders.
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub struct TraceOptions {
    pub step: f64,
    pub max_len: f64,
    /// Update the direction from the centroids.
    pub follow: bool,
    /// Take the convex hull of the captured loops (a mitten).
    pub hull: bool,
    /// Keep marching without a loop up to this distance (leaving a junction).
    pub skip: f64,
    /// Stop when the radius grows by more than this factor in one step
    /// ([`JUMP`]; infinite where the section legitimately grows fast, as
    /// from the neck into the jaw).
    pub jump: f64,
}

impl TraceOptions {
    /// Sections every `step` up to `max_len` along a fixed direction, each
    /// the loop itself (no hull), none skipped, a jump stop at [`JUMP`].
    pub fn new(step: f64, max_len: f64) -> TraceOptions {
        TraceOptions {
            step,
            max_len,
            follow: false,
            hull: false,
            skip: 0.0,
            jump: JUMP,
        }
    }

    /// Updates the direction from the centroids.
    pub fn following(mut self, follow: bool) -> TraceOptions {
        self.follow = follow;
        self
    }

    /// Takes the convex hull of the captured loops.
    pub fn with_hull(mut self, hull: bool) -> TraceOptions {
        self.hull = hull;
        self
    }

    /// Keeps marching without a loop up to `skip`.
    pub fn with_skip(mut self, skip: f64) -> TraceOptions {
        self.skip = skip;
        self
    }

    /// Stops when the radius grows by more than `jump` in one step.
    pub fn with_jump(mut self, jump: f64) -> TraceOptions {
        self.jump = jump;
        self
    }
}

/// Traces a limb from `start` in direction `dir` (see the module doc).
/// `radius0` is the expected radius at the start.
pub fn trace(
    m: &Mesh,
    start: [f64; 3],
    dir: [f64; 3],
    radius0: f64,
    o: TraceOptions,
) -> Result<Vec<TraceSample>, BodyError> {
    trace_excluding(m, start, dir, radius0, o, &|_| false)
}

/// [`trace`] leaving out every loop whose centroid (model coordinates)
/// `exclude` names: a palm traced without the thumb's loops.
pub fn trace_excluding(
    m: &Mesh,
    start: [f64; 3],
    dir: [f64; 3],
    radius0: f64,
    o: TraceOptions,
    exclude: &dyn Fn([f64; 3]) -> bool,
) -> Result<Vec<TraceSample>, BodyError> {
    let mut d = scale(dir, 1.0 / norm(dir).max(f64::MIN_POSITIVE));
    let mut p = start;
    let mut radius = radius0;
    let mut out: Vec<TraceSample> = Vec::new();
    let mut walked = 0.0;
    let mut last_c: Option<[f64; 3]> = None;
    while walked <= o.max_len {
        let f = plane_frame(p, d)?;
        let ls = loops_in_plane(m, &f);
        let caught: Vec<&Loop2> = ls
            .iter()
            .filter(|l| l.centroid[0].hypot(l.centroid[1]) <= CAPTURE * radius)
            .filter(|l| l.area >= MIN_AREA * radius * radius)
            .filter(|l| !exclude(f.place(l.centroid[0], l.centroid[1])))
            .collect();
        let chosen = if caught.is_empty() {
            None
        } else if o.hull {
            let pts: Vec<[f64; 2]> = caught
                .iter()
                .flat_map(|l| l.points.iter().copied())
                .collect();
            loop2(convex_hull(&pts))
        } else {
            caught
                .iter()
                .min_by(|a, b| {
                    a.centroid[0]
                        .hypot(a.centroid[1])
                        .total_cmp(&b.centroid[0].hypot(b.centroid[1]))
                })
                .map(|l| (*l).clone())
        };
        match chosen {
            None if out.is_empty() && walked < o.skip => {}
            None => break,
            Some(l) => {
                if !out.is_empty() && l.radius > o.jump * radius {
                    break;
                }
                let c = f.place(l.centroid[0], l.centroid[1]);
                let frame = plane_frame(c, d)?;
                let plane = l
                    .points
                    .iter()
                    .map(|q| frame.project(f.place(q[0], q[1])).0)
                    .collect();
                let s = match (out.last(), last_c) {
                    (Some(prev), Some(lc)) => prev.s + dist(lc, c),
                    _ => 0.0,
                };
                if o.follow {
                    if let Some(lc) = last_c {
                        let dn = sub(c, lc);
                        if norm(dn) > 0.0 && dot(dn, d) > 0.0 {
                            let dn = scale(dn, 1.0 / norm(dn));
                            let b = add(scale(d, 0.7), scale(dn, 0.3));
                            d = scale(b, 1.0 / norm(b));
                        }
                    }
                }
                radius = l.radius;
                out.push(TraceSample {
                    s,
                    frame,
                    plane,
                    radius,
                });
                last_c = Some(c);
                p = c;
            }
        }
        p = add(p, scale(d, o.step));
        walked += o.step;
    }
    Ok(out)
}
