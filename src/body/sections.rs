//! The sections of a closed body ([`super::closed`]): its options, the
//! GEC fits of the traced section loops (phases, picks along a trace, the
//! collapsed tips) and the part specifications they make.

use super::layout::TraceSample;
use super::BodyError;
use crate::character::assembly::Resolution;
use crate::character::doc::{PartSpec, SectionShape, SectionSpec, SurfaceSpec};
use crate::curve::gec::Gec;
use crate::mesh::{add, dot, norm, scale, sub, Mesh};
use crate::pde6::sampling::fit_anchored;

/// Options of the closed reconstruction. Outside the crate, start from
/// [`ClosedOptions::default`] and change fields with the `with_*` setters
/// (or by assignment).
#[derive(Clone, Copy, Debug, serde::Serialize)]
#[non_exhaustive]
pub struct ClosedOptions {
    /// GEC terms J per section (default 10).
    pub terms: usize,
    /// PDE parameter a of every part (default [`super::parts::BODY_A`]).
    pub a: f64,
    /// Sections of the torso tube (7 + 3k, counting the collapsed tip
    /// where there is one; default 13).
    pub torso_sections: usize,
    /// Sections of each leg (7 + 3k; default 19).
    pub leg_sections: usize,
    /// Sections of each arm (7 + 3k; default 10).
    pub arm_sections: usize,
    /// Sections of the neck and head (7 + 3k; default 16).
    pub head_sections: usize,
    /// Sections of each hand's palm-and-fingers mitten (7 + 3k, counting
    /// the collapsed tip; default 7).
    pub hand_sections: usize,
    /// Sections of each thumb (7 + 3k, counting the collapsed tip;
    /// default 7).
    pub thumb_sections: usize,
    /// Build each hand as a mitten and a thumb joined at the wrist (default
    /// true). Off, or where an arm's trace finds no thumb separating from the
    /// palm (a mesh with mitten hands), the whole arm is one chain ending in
    /// a mitten of convex hulls, thumb merged (the arm is then named in
    /// [`super::report::ClosedReport::thumbless`] with the reason).
    pub thumbs: bool,
    /// Anchors of the anchored sampling (see [`crate::pde6::sampling`];
    /// default [`super::parts::DEFAULT_ANCHORS`]).
    pub anchors: usize,
    /// Samples of the anchored sampling (default
    /// [`super::parts::DEFAULT_SAMPLES`]).
    pub samples: usize,
    /// Pull of the anchored sampling (default [`super::parts::DEFAULT_PULL`]).
    pub pull: f64,
    /// Mesh rings per body height along the parts (default 160).
    pub rings_per_height: f64,
    /// Mesh rows across a transition (default 10).
    pub transition_rows: usize,
}

setters!(ClosedOptions {
    with_terms: terms: usize,
    with_a: a: f64,
    with_torso_sections: torso_sections: usize,
    with_leg_sections: leg_sections: usize,
    with_arm_sections: arm_sections: usize,
    with_head_sections: head_sections: usize,
    with_hand_sections: hand_sections: usize,
    with_thumb_sections: thumb_sections: usize,
    with_thumbs: thumbs: bool,
    with_anchors: anchors: usize,
    with_samples: samples: usize,
    with_pull: pull: f64,
    with_rings_per_height: rings_per_height: f64,
    with_transition_rows: transition_rows: usize,
});

impl ClosedOptions {
    /// The mesh resolution of the assembled body.
    pub fn resolution(&self) -> Resolution {
        Resolution {
            rings_per_height: self.rings_per_height,
            transition_rows: self.transition_rows,
        }
    }
}

impl Default for ClosedOptions {
    fn default() -> Self {
        ClosedOptions {
            terms: 10,
            a: super::parts::BODY_A,
            torso_sections: 13,
            leg_sections: 19,
            arm_sections: 10,
            head_sections: 16,
            hand_sections: 7,
            thumb_sections: 7,
            thumbs: true,
            anchors: super::parts::DEFAULT_ANCHORS,
            samples: super::parts::DEFAULT_SAMPLES,
            pull: super::parts::DEFAULT_PULL,
            rings_per_height: 160.0,
            transition_rows: 10,
        }
    }
}

/// The arm's sections keep the spacing of a chain of this many sections
/// (with the collapsed tip) over the whole arm trace, to the fingertips,
/// at the default 10 arm sections; `n` arm sections keep that of
/// `(n - 1) 14 / 9 + 1` fitted ones ([`arm_picks`]).
pub const ARM_SPACING_SECTIONS: usize = 16;
/// The GEC coefficients of `C(theta + delta)`.
pub fn shift_phase(g: &Gec, delta: f64) -> Gec {
    let mut out = g.clone();
    for n in 0..g.x.len() {
        let (c, s) = (
            ((n + 1) as f64 * delta).cos(),
            ((n + 1) as f64 * delta).sin(),
        );
        let [a, b] = g.x[n];
        out.x[n] = [a * c + b * s, b * c - a * s];
        let [a, b] = g.y[n];
        out.y[n] = [a * c - b * s, a * s + b * c];
    }
    out
}

/// Phase of the torso sections: the anchored rule puts theta = 0 at the
/// front (+z); the transitions cut the parent ring expecting theta = 0 on
/// the +x side and pi on the -x side (children ordered by x), so the torso
/// is evaluated at theta + pi / 2.
pub const TORSO_PHASE: f64 = std::f64::consts::FRAC_PI_2;

fn fit_gec(t: &TraceSample, o: &ClosedOptions, what: &str) -> Result<Gec, BodyError> {
    let terms = o.terms.min(t.plane.len().saturating_sub(1) / 2).max(1);
    // a section whose centroid sees no crossing on the start ray (a
    // crescent) falls back to its convex hull
    Ok(
        fit_anchored(&t.plane, t.frame, terms, o.anchors, o.samples, o.pull)
            .or_else(|_| {
                let h = crate::profile::shapes::convex_hull(&t.plane);
                fit_anchored(&h, t.frame, terms, o.anchors, o.samples, o.pull)
            })
            .map_err(|e| e.in_section(what))?,
    )
}

fn fit_section(
    t: &TraceSample,
    u: f64,
    o: &ClosedOptions,
    what: &str,
    phase: f64,
) -> Result<SectionSpec, BodyError> {
    let g = shift_phase(&fit_gec(t, o, what)?, phase);
    Ok(SectionSpec {
        u,
        centre: t.frame.origin,
        e1: t.frame.e1,
        e2: t.frame.e2,
        shape: SectionShape::Gec {
            centre: g.centre,
            x: g.x,
            y: g.y,
        },
    })
}

/// The phase that puts theta = 0 of the section `end` (a GEC fitted by the
/// anchored rule) on the ray from its centre towards `towards`: the wrist
/// transition gives its last child (the thumb) the arc around theta = 0.
pub(super) fn phase_towards(
    t: &TraceSample,
    towards: [f64; 3],
    o: &ClosedOptions,
) -> Result<f64, BodyError> {
    let g = fit_gec(t, o, "the arm's end section")?;
    let (q, _) = t.frame.project(towards);
    let v = [q[0] - g.centre[0], q[1] - g.centre[1]];
    let steps = 1440;
    let best = (0..steps)
        .map(|i| 2.0 * std::f64::consts::PI * i as f64 / steps as f64)
        .max_by(|&a, &b| {
            let c = |th: f64| {
                let p = g.eval_plane(th);
                let w = [p[0] - g.centre[0], p[1] - g.centre[1]];
                (w[0] * v[0] + w[1] * v[1])
                    / (w[0].hypot(w[1]) * v[0].hypot(v[1])).max(f64::MIN_POSITIVE)
            };
            c(a).total_cmp(&c(b))
        })
        .unwrap_or(0.0);
    Ok(best)
}

/// Picks `n` samples evenly in s over [s0, last] (nearest, strictly increasing).
fn pick(tr: &[TraceSample], s0: f64, n: usize, what: &str) -> Result<Vec<usize>, BodyError> {
    let first = tr.iter().position(|t| t.s >= s0);
    let last = tr.len().checked_sub(1);
    let (Some(first), Some(last)) = (first, last) else {
        return Err(BodyError::LayoutNotFound {
            what: "a limb",
            detail: format!("{what}: the trace found no sections"),
        });
    };
    if last < first + n {
        return Err(BodyError::LayoutNotFound {
            what: "a limb",
            detail: format!(
                "{what}: the trace found {} sections, {n} needed",
                last + 1 - first.min(last)
            ),
        });
    }
    let (a, b) = (tr[first].s, tr[last].s);
    let mut out: Vec<usize> = Vec::with_capacity(n);
    for i in 0..n {
        let s = a + (b - a) * i as f64 / (n - 1) as f64;
        let mut k = (first..=last)
            .min_by(|&x, &y| (tr[x].s - s).abs().total_cmp(&(tr[y].s - s).abs()))
            .unwrap_or(first);
        if let Some(&p) = out.last() {
            k = k.max(p + 1);
        }
        out.push(k.min(last));
    }
    out.dedup();
    if out.len() < n {
        return Err(BodyError::LayoutNotFound {
            what: "a limb",
            detail: format!("{what}: too few distinct sections"),
        });
    }
    Ok(out)
}

/// The farthest skin point along `d` from `c` within `r` of the axis.
fn tip(m: &Mesh, c: [f64; 3], d: [f64; 3], r: f64) -> [f64; 3] {
    let mut best = 0.0f64;
    for p in &m.positions {
        let v = sub(*p, c);
        let a = dot(v, d);
        let perp = norm(sub(v, scale(d, a)));
        if perp <= r && a > best {
            best = a;
        }
    }
    add(c, scale(d, best))
}

/// Builds a part from a trace: `n` sections (the last a collapsed tip when
/// `tip_end`).
#[allow(clippy::too_many_arguments)]
pub(super) fn part_from_trace(
    m: &Mesh,
    name: &str,
    tr: &[TraceSample],
    s0: f64,
    n: usize,
    tip_end: bool,
    o: &ClosedOptions,
    phase: f64,
) -> Result<PartSpec, BodyError> {
    let fitted = if tip_end { n - 1 } else { n };
    let idx = pick(tr, s0, fitted, name)?;
    part_from_picks(m, name, tr, &idx, tip_end, o, phase)
}

/// [`part_from_trace`] with the trace samples of the fitted sections given.
pub(super) fn part_from_picks(
    m: &Mesh,
    name: &str,
    tr: &[TraceSample],
    idx: &[usize],
    tip_end: bool,
    o: &ClosedOptions,
    phase: f64,
) -> Result<PartSpec, BodyError> {
    let fitted = idx.len();
    let n = if tip_end { fitted + 1 } else { fitted };
    let mut sections = Vec::with_capacity(n);
    for (i, &k) in idx.iter().enumerate() {
        sections.push(fit_section(
            &tr[k],
            tr[k].s,
            o,
            &format!("{name} section {i}"),
            phase,
        )?);
    }
    if tip_end {
        let last = &tr[idx[fitted - 1]];
        let d = last.frame.normal();
        let c = last.frame.origin;
        let p = tip(m, c, d, last.radius);
        let gap = dot(sub(p, c), d);
        let gap = gap.max(0.25 * (tr[idx[1]].s - tr[idx[0]].s));
        sections.push(SectionSpec {
            u: last.s + gap,
            centre: add(c, scale(d, gap)),
            e1: last.frame.e1,
            e2: last.frame.e2,
            shape: SectionShape::Circle { r: 0.0 },
        });
    }
    Ok(PartSpec {
        name: name.into(),
        surface: SurfaceSpec::Pde6C2 {
            a: o.a,
            open_ends: Default::default(),
        },
        sections,
        closed_start: false,
        closed_end: tip_end,
    })
}

/// The arm's sections: the first `n - 1` where a chain of
/// [`ARM_SPACING_SECTIONS`] sections over the whole trace (wrist, hand and
/// fingers: the arm of the mitten body; scaled for other `n`) has them, and
/// the last at the wrist
/// (`end` samples of `tr` are the arm's). The shoulder transition then sees
/// the arm it was tuned on (its crossings depend on the arm's first
/// sections: 10 sections spread evenly to the wrist left 2 crossing pairs
/// at the shoulders of caucasian-male-child and caucasian-male-old). Falls
/// back to `n` sections evenly to the wrist when the wrist comes before
/// the `n - 1`-th of those.
pub(super) fn arm_picks(
    tr: &[TraceSample],
    end: usize,
    s0: f64,
    n: usize,
    what: &str,
) -> Result<Vec<usize>, BodyError> {
    let arm = &tr[..end];
    let even = || pick(arm, s0, n, what);
    let m = ((n.saturating_sub(1) * (ARM_SPACING_SECTIONS - 2)) as f64 / 9.0).round() as usize + 1;
    let Ok(whole) = pick(tr, s0, m, what) else {
        return even();
    };
    if n < 2 || whole.len() < n || whole[n - 2] + 1 >= end {
        return even();
    }
    let mut idx = whole[..n - 1].to_vec();
    idx.push(end - 1);
    Ok(idx)
}

pub(super) fn check_count(what: &'static str, n: usize) -> Result<(), BodyError> {
    if n < 7 || (n - 7) % 3 != 0 || n > 7 + 3 * 30 {
        return Err(BodyError::SectionCount { what, got: n });
    }
    Ok(())
}
