//! Per-vertex depth weights of the side passes (issue 12: creases).
//!
//! The side passes ([`super::refine::side_pass`],
//! [`super::envelope::envelope_pass`]) move a vertex in depth by the
//! corrections of the front and back of the body at its height, weighted
//! by its relative depth `s = (z - back) / (front - back)` in the depth
//! span `[back, front]` of the side outline at that height. That span is
//! not continuous in the height: where the outline overhangs (the tip of
//! the nose, a pregnant belly's underside, the fingertips of MakeHuman's
//! hands, which hang in front of the belly) the front-most crossing jumps
//! from one part of the body to another between two neighbouring heights,
//! and so do `s`, the point where the correction is read and the vertex's
//! displacement: neighbouring skin vertices on either side of that height
//! move apart, a crease (the MakeHuman female->pregnant medium level had a
//! shelf across the lower belly at the fingertips' height, 2.21 rad; the
//! boy's and girl's faces folded at the mouth).
//!
//! Two changes make the weights continuous:
//! - the span is the vertex's own part's: the trunk's side outline (arm
//!   triangles left out, arms by [`super::refine::arm_mask`]) for trunk
//!   vertices, the whole outline for arm vertices, so a hand in front of
//!   the belly does not set the belly's span;
//! - the span is smoothed over heights ([`SpanProfile`]: sampled on
//!   [`SPAN_ROWS`] rows, a triangle filter of half-width [`SPAN_SMOOTH`] of
//!   the height), so an overhang's jump becomes a ramp.

use super::landmarks::{face_marks, FaceMarks};
use super::options::{FitOptions, Template};
use super::outlines::side_outlines;
use super::polygon::depth_span;
use super::{OutlineFn, TemplateError};

/// Rows (heights) of a [`SpanProfile`].
pub const SPAN_ROWS: usize = 1024;
/// Half-width of the triangle filter smoothing a span over heights, as a
/// fraction of the outline's height.
pub const SPAN_SMOOTH: f64 = 0.01;

/// A depth span `[back, front]` per height, smoothed over heights and
/// interpolated linearly between rows: continuous in the height.
#[derive(Clone, Debug)]
pub struct SpanProfile {
    y0: f64,
    dy: f64,
    back: Vec<f64>,
    front: Vec<f64>,
}

impl SpanProfile {
    /// The span of the closed polygon `outline` (depth, height) at every
    /// row between its lowest and highest point, smoothed with half-width
    /// `smooth` (fraction of its height); `None` for a flat or empty
    /// outline.
    pub fn of_outline(outline: &[[f64; 2]], smooth: f64) -> Option<SpanProfile> {
        let (lo, hi) = outline
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
                (l.min(p[1]), h.max(p[1]))
            });
        if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let dy = (hi - lo) / (SPAN_ROWS - 1) as f64;
        let rows: Vec<Option<(f64, f64)>> = (0..SPAN_ROWS)
            .map(|r| depth_span(outline, (lo + r as f64 * dy).clamp(lo, hi)))
            .collect();
        SpanProfile::of_rows(lo, dy, &rows, smooth * (hi - lo))
    }

    /// A profile from spans per row (`rows[r]` at height `y0 + r dy`;
    /// `None`: no span there, filled from the nearest row that has one),
    /// smoothed with half-width `smooth` (model units); `None` when no row
    /// has a span.
    pub fn of_rows(
        y0: f64,
        dy: f64,
        rows: &[Option<(f64, f64)>],
        smooth: f64,
    ) -> Option<SpanProfile> {
        let first = rows.iter().position(Option::is_some)?;
        let mut last = rows[first].expect("found");
        let mut filled: Vec<(f64, f64)> = Vec::with_capacity(rows.len());
        // forward fill, then the rows before the first span
        for r in rows {
            if let Some(s) = r {
                last = *s;
            }
            filled.push(last);
        }
        for f in filled.iter_mut().take(first) {
            *f = rows[first].expect("found");
        }
        let k = if dy > 0.0 {
            (smooth / dy).round().max(0.0) as usize
        } else {
            0
        };
        let back: Vec<f64> = filled.iter().map(|s| s.0).collect();
        let front: Vec<f64> = filled.iter().map(|s| s.1).collect();
        Some(SpanProfile {
            y0,
            dy,
            back: triangle_filter(&back, k),
            front: triangle_filter(&front, k),
        })
    }

    /// The smoothed span `(back, front)` at height `y` (clamped to the
    /// profile's heights).
    pub fn at(&self, y: f64) -> (f64, f64) {
        let n = self.front.len();
        if n == 1 || self.dy <= 0.0 {
            return (self.back[0], self.front[0]);
        }
        let r = ((y - self.y0) / self.dy).clamp(0.0, (n - 1) as f64);
        let i = (r.floor() as usize).min(n - 2);
        let t = r - i as f64;
        (
            (1.0 - t) * self.back[i] + t * self.back[i + 1],
            (1.0 - t) * self.front[i] + t * self.front[i + 1],
        )
    }
}

/// `v` filtered by a triangle (two box filters of half-width `k / 2`, ends
/// averaged over the part of the window inside).
fn triangle_filter(v: &[f64], k: usize) -> Vec<f64> {
    let h = k.div_ceil(2);
    box_filter(&box_filter(v, h), h)
}

fn box_filter(v: &[f64], k: usize) -> Vec<f64> {
    if k == 0 || v.is_empty() {
        return v.to_vec();
    }
    let n = v.len();
    let mut prefix = Vec::with_capacity(n + 1);
    prefix.push(0.0);
    for x in v {
        prefix.push(prefix.last().copied().unwrap_or(0.0) + x);
    }
    (0..n)
        .map(|i| {
            let (lo, hi) = (i.saturating_sub(k), (i + k).min(n - 1));
            (prefix[hi + 1] - prefix[lo]) / (hi + 1 - lo) as f64
        })
        .collect()
}

/// The relative-depth spans of a fitted state: per template vertex, its
/// part's smoothed span (trunk or arm, see the module's notes).
#[derive(Clone, Debug)]
pub struct DepthSpans {
    whole: Option<SpanProfile>,
    trunk: Option<(Vec<bool>, SpanProfile)>,
}

impl DepthSpans {
    /// The spans of the skin at `positions`; `whole` is its side outline
    /// (already extracted by the caller). The trunk's span is used when the
    /// arms are found ([`super::refine::arm_mask`]: the human front
    /// scheme) and the trunk's outline is a simple polygon.
    pub fn new(
        template: &Template,
        positions: &[[f64; 3]],
        whole: &[[f64; 2]],
        opts: &FitOptions,
        outline: &OutlineFn,
    ) -> Result<DepthSpans, TemplateError> {
        let smooth = SPAN_SMOOTH;
        let (_, split) = side_outlines(template, positions, true, opts, outline)?;
        Ok(DepthSpans {
            whole: SpanProfile::of_outline(whole, smooth),
            trunk: split.and_then(|(mask, t)| Some((mask, SpanProfile::of_outline(&t, smooth)?))),
        })
    }

    /// The span `(back, front)` for template vertex `i` at height `y`.
    pub fn at(&self, i: usize, y: f64) -> Option<(f64, f64)> {
        match &self.trunk {
            Some((arms, t)) if !arms.get(i).copied().unwrap_or(false) => Some(t.at(y)),
            _ => self.whole.as_ref().map(|w| w.at(y)),
        }
    }
}

/// The relative depth of `z` in the span `(back, front)`, in `[0, 1]`
/// (`0.5` for an empty span).
pub fn relative_depth(z: f64, (back, front): (f64, f64)) -> f64 {
    if front > back {
        ((z - back) / (front - back)).clamp(0.0, 1.0)
    } else {
        0.5
    }
}

/// Fraction of the height below the lower of the two necks
/// ([`FaceMarks::neck`]) where the head's height remap ends.
pub const NECK_ANCHOR: f64 = 0.04;

/// Below this largest landmark shift (fraction of the height) the head
/// is not remapped: the landmarks' rows (1/[`super::landmarks::FACE_ROWS`]
/// of the height) jitter by about this much on outlines that match.
pub const REMAP_MIN: f64 = 0.004;

/// A smooth increasing map of heights taking the template's side-outline
/// landmarks of the head ([`FaceMarks`]: neck, chin, nose) to the
/// sketch's, the identity below an anchor under the necks and at the top
/// of the head (a monotone cubic, Fritsch-Butland slopes, slope 1 at both
/// ends so it joins the identity smoothly).
#[derive(Clone, Debug, PartialEq)]
pub struct HeightRemap {
    /// Knots (template height, sketch height), strictly increasing in both.
    pub knots: Vec<(f64, f64)>,
    slopes: Vec<f64>,
}

impl HeightRemap {
    /// The remap from the template's landmarks `t` to the sketch's `s`;
    /// `None` when they are not in the same order on both (no monotone
    /// map). The neck knot is left out when a chin lies below its neck.
    pub fn between(t: &FaceMarks, s: &FaceMarks) -> Option<HeightRemap> {
        let anchor = t.neck.min(s.neck) - NECK_ANCHOR * (t.top - t.bottom);
        let mut knots = vec![(anchor, anchor)];
        if t.chin > t.neck && s.chin > s.neck {
            knots.push((t.neck, s.neck));
        }
        knots.extend([(t.chin, s.chin), (t.nose, s.nose), (t.top, t.top)]);
        let finite = knots.iter().all(|k| k.0.is_finite() && k.1.is_finite());
        if !finite
            || knots
                .windows(2)
                .any(|w| w[1].0 <= w[0].0 || w[1].1 <= w[0].1)
        {
            return None;
        }
        let d: Vec<f64> = knots
            .windows(2)
            .map(|w| (w[1].1 - w[0].1) / (w[1].0 - w[0].0))
            .collect();
        let m = knots.len();
        let slopes = (0..m)
            .map(|k| match k {
                // slope 1 at the ends (joins the identity), limited so the
                // cubic stays monotone (at most 3 times the secant)
                0 => 1.0f64.min(3.0 * d[0]),
                k if k == m - 1 => 1.0f64.min(3.0 * d[m - 2]),
                k => 2.0 / (1.0 / d[k - 1] + 1.0 / d[k]),
            })
            .collect();
        Some(HeightRemap { knots, slopes })
    }

    /// The largest change of height at a knot.
    pub fn largest(&self) -> f64 {
        self.knots
            .iter()
            .map(|k| (k.1 - k.0).abs())
            .fold(0.0, f64::max)
    }

    /// The change of height `map(y) - y` (0 outside the knots).
    pub fn shift(&self, y: f64) -> f64 {
        let k = &self.knots;
        let Some(i) = k.windows(2).position(|w| y >= w[0].0 && y <= w[1].0) else {
            return 0.0;
        };
        let (x0, x1, y0, y1) = (k[i].0, k[i + 1].0, k[i].1, k[i + 1].1);
        let hx = x1 - x0;
        let t = (y - x0) / hx;
        let (t2, t3) = (t * t, t * t * t);
        let v = (2.0 * t3 - 3.0 * t2 + 1.0) * y0
            + (t3 - 2.0 * t2 + t) * hx * self.slopes[i]
            + (-2.0 * t3 + 3.0 * t2) * y1
            + (t3 - t2) * hx * self.slopes[i + 1];
        v - y
    }
}

/// Moves the head of the fitted state `positions` in height so that its
/// side outline's landmarks ([`FaceMarks`]: neck, chin, nose) sit at the
/// sketch's heights ([`HeightRemap`]): a vertex takes the shift of its
/// height times `s^p` of its relative depth `s` in its part's smoothed
/// span ([`DepthSpans`], `p` = [`FitOptions::depth_falloff`]) and
/// `(1 - u^2)^2` of its place `u` across the front outline's width at its
/// height (-1 and 1 at the silhouette), so the face moves and neither the
/// back of the head nor the front view's silhouette (ears, jaw, neck). Without it the
/// side pass, which matches heights, pushes the template's neck out to
/// form a chin that is lower on the sketch (a child's, an old woman's).
/// Returns the largest shift applied; 0 (nothing moved) when either
/// outline has no face landmarks or they do not match in order, or for a
/// front scheme other than [`super::Scheme::Human`].
pub fn remap_heights(
    template: &Template,
    positions: &mut [[f64; 3]],
    side: &[[f64; 2]],
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<f64, TemplateError> {
    if opts.front_scheme != super::Scheme::Human {
        return Ok(0.0);
    }
    let (o, _) = side_outlines(template, positions, false, opts, outline)?;
    let (Ok(t), Ok(s)) = (
        face_marks(&o, "fitted side outline"),
        face_marks(side, "sketched side profile"),
    ) else {
        return Ok(0.0);
    };
    let Some(remap) = HeightRemap::between(&t, &s) else {
        return Ok(0.0);
    };
    if remap.largest() < REMAP_MIN * (t.top - t.bottom) {
        return Ok(0.0);
    }
    let spans = DepthSpans::new(template, positions, &o, opts, outline)?;
    // the front outline's span per height: its silhouette stays put
    let f = outline(&template.skin_at(positions), super::View::Front)?;
    let width = SpanProfile::of_outline(&f, SPAN_SMOOTH);
    let mut largest = 0.0f64;
    for (i, p) in positions.iter_mut().enumerate() {
        let d = remap.shift(p[1]);
        if d == 0.0 {
            continue;
        }
        let s = spans
            .at(i, p[1])
            .map_or(0.0, |span| relative_depth(p[2], span));
        let u = width.as_ref().map_or(0.0, |w| {
            let (l, r) = w.at(p[1]);
            if r > l {
                ((2.0 * p[0] - l - r) / (r - l)).clamp(-1.0, 1.0)
            } else {
                1.0
            }
        });
        let d = s.powi(opts.depth_falloff) * (1.0 - u * u).powi(2) * d;
        p[1] += d;
        largest = largest.max(d.abs());
    }
    Ok(largest)
}
