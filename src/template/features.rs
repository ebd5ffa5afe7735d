//! Height moves before the envelope rows ([`super::envelope`]): the hand's
//! webs and fingertips on a side outline paired with the sketch's
//! ([`feature_warp`]), and the front's shelves ([`shelf_warp`]).

use super::options::{FitOptions, Template};
use super::outlines::side_outlines;
use super::polygon::bbox;
use super::polygon::depth_span;
use super::rows::ARM_EPS;
use super::weights::{relative_depth, SpanProfile, SPAN_SMOOTH};
use super::{OutlineFn, TemplateError};

/// Kind of a hand feature on a side outline ([`hand_features`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Feature {
    /// The top of a gap between two fingers (a web): a local maximum of
    /// the height with the outside below it.
    Web,
    /// The bottom of a finger: a local minimum of the height with the
    /// inside above it.
    Tip,
}

/// A feature is the highest (lowest) point of the outline between where
/// the outline has dropped (risen) this fraction of the height on either
/// side of it.
pub const FEATURE_DROP: f64 = 0.002;
/// Outline vertices walked on either side of a candidate feature.
pub const FEATURE_WALK: usize = 400;

/// The webs and fingertips of the closed polygon `p` (depth, height):
/// vertices that are the strict highest (web) or lowest (tip) point of the
/// outline until it has dropped (risen) `drop` on both sides, with the
/// outside below a web and the inside above a tip (by the polygon's
/// orientation), as `(vertex, kind)`.
pub fn hand_features(p: &[[f64; 2]], drop: f64) -> Vec<(usize, Feature)> {
    let n = p.len();
    if n < 3 {
        return Vec::new();
    }
    let ccw = super::polygon::signed_area(p) > 0.0;
    let mut out = Vec::new();
    for i in 0..n {
        for up in [true, false] {
            // sign: heights measured upwards for a maximum, downwards for a
            // minimum
            let sg = if up { 1.0 } else { -1.0 };
            let yi = sg * p[i][1];
            let walk = |step: usize| -> Option<usize> {
                for k in 1..=FEATURE_WALK.min(n - 1) {
                    let j = (i + step * k) % n;
                    let yj = sg * p[j][1];
                    if yj > yi || (yj == yi && step == 1) {
                        return None;
                    }
                    if yj < yi - drop {
                        return Some(j);
                    }
                }
                None
            };
            let (Some(b), Some(a)) = (walk(n - 1), walk(1)) else {
                continue;
            };
            // travelling towards +depth on a counter-clockwise polygon, the
            // inside is above: at a maximum a notch (a web), at a minimum a
            // fingertip
            if (p[a][0] > p[b][0]) == ccw {
                out.push((i, if up { Feature::Web } else { Feature::Tip }));
            }
        }
    }
    out
}

/// A paired feature farther than this fraction of the height from its
/// sketched partner is not the same feature.
pub const FEATURE_PAIR: f64 = 0.012;
/// Width (fraction of the height) of the Gaussian with which a feature's
/// displacement falls off over the arm's vertices in the side plane.
pub const FEATURE_SIGMA: f64 = 0.004;

/// The fitted outline's hand features (webs, fingertips) in front of the
/// trunk paired with the sketch's of the same kind (mutual nearest within
/// [`FEATURE_PAIR`] of the height): `(fitted point, sketched point)`.
pub fn paired_features(
    fitted: &[[f64; 2]],
    sketch: &[[f64; 2]],
    in_front: &dyn Fn([f64; 2]) -> bool,
    h: f64,
) -> Vec<([f64; 2], [f64; 2])> {
    let pick = |p: &[[f64; 2]]| -> Vec<([f64; 2], Feature)> {
        hand_features(p, FEATURE_DROP * h)
            .into_iter()
            .map(|(i, k)| (p[i], k))
            .filter(|(q, _)| in_front(*q))
            .collect()
    };
    let (f, s) = (pick(fitted), pick(sketch));
    let d2 = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2);
    let nearest = |q: [f64; 2], k: Feature, set: &[([f64; 2], Feature)]| {
        set.iter()
            .enumerate()
            .filter(|(_, e)| e.1 == k)
            .min_by(|a, b| d2(q, a.1 .0).total_cmp(&d2(q, b.1 .0)))
            .map(|(j, _)| j)
    };
    let mut out = Vec::new();
    for (i, &(q, k)) in f.iter().enumerate() {
        let Some(j) = nearest(q, k, &s) else {
            continue;
        };
        if nearest(s[j].0, k, &f) == Some(i) && d2(q, s[j].0) <= (FEATURE_PAIR * h).powi(2) {
            out.push((q, s[j].0));
        }
    }
    out
}

/// Moves the arm's vertices in the side plane (depth and height) so the
/// fitted side outline's webs and fingertips land on the sketch's
/// ([`paired_features`]), each pair's displacement falling off as a
/// Gaussian of width [`FEATURE_SIGMA`] of the height. The side view also
/// carries heights the depth-only passes cannot fit (a web between two
/// fingers 0.04 units lower on the fitted boy's hand). Returns the pairs
/// used.
pub fn feature_warp(
    template: &Template,
    positions: &mut [[f64; 3]],
    side: &[[f64; 2]],
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<usize, TemplateError> {
    let (o, split) = side_outlines(template, positions, true, opts, outline)?;
    let Some((arms, trunk)) = split else {
        return Ok(0);
    };
    let (lo, hi) = bbox(&o);
    let h = (hi[1] - lo[1]).max(f64::MIN_POSITIVE);
    let margin = ARM_EPS * 5.0 * h;
    let in_front = |q: [f64; 2]| depth_span(&trunk, q[1]).is_some_and(|(_, tf)| q[0] > tf + margin);
    let pairs = paired_features(&o, side, &in_front, h);
    if pairs.is_empty() {
        return Ok(0);
    }
    let s2 = (FEATURE_SIGMA * h).powi(2);
    for (p, _) in positions.iter_mut().zip(&arms).filter(|(_, &a)| a) {
        let (mut dz, mut dy) = (0.0, 0.0);
        for (f, s) in &pairs {
            let w = (-((p[2] - f[0]).powi(2) + (p[1] - f[1]).powi(2)) / s2).exp();
            dz += w * (s[0] - f[0]);
            dy += w * (s[1] - f[1]);
        }
        p[2] += dz;
        p[1] += dy;
    }
    Ok(pairs.len())
}

/// Outline stretches flatter than this (|dy/ds|) are shelves
/// ([`shelf_warp`]).
pub const SHELF_STEEP: f64 = 0.5;
/// Shelves are looked for above this fraction of the height (from the
/// fitted side outline's lowest point; above the hands and the crotch).
pub const SHELF_FROM: f64 = 0.6;

/// Moves the trunk and head in height where the fitted side outline's
/// front is a shelf (a shallow stretch: a chin's underside, a throat, a
/// bust's underside) that lies above or below the sketch: each shelf
/// vertex of the fitted outline (|dy/ds| below [`SHELF_STEEP`]) between
/// [`SHELF_FROM`] of the height and the nose tip
/// ([`super::landmarks::face_marks`]) and in the front half of its
/// height's span is a centre with the height change to its nearest point
/// on the sketch (within [`FEATURE_PAIR`] of the height); the trunk's
/// vertices take the centres' Gaussian-weighted mean change (width
/// [`FEATURE_SIGMA`] of the height, in the side plane) times the centres'
/// total weight (at most 1), times `s^2` of their relative depth and
/// `(1 - u^2)^2` of their place across the front outline (as the head's
/// height remap, [`super::weights::remap_heights`]), so the front
/// silhouette stays. The depth passes cannot fit a shelf at another
/// height: moving the rows below it in depth left the old woman's throat
/// as a hook 0.67 % of the height off. Returns the centres used.
pub fn shelf_warp(
    template: &Template,
    positions: &mut [[f64; 3]],
    side: &[[f64; 2]],
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<usize, TemplateError> {
    if opts.front_scheme != super::Scheme::Human {
        return Ok(0);
    }
    let (o, split) = side_outlines(template, positions, true, opts, outline)?;
    let Ok(marks) = super::landmarks::face_marks(&o, "fitted side outline") else {
        return Ok(0);
    };
    let h = (marks.top - marks.bottom).max(f64::MIN_POSITIVE);
    let (y_lo, y_hi) = (marks.bottom + SHELF_FROM * h, marks.nose);
    let n = o.len();
    let mut centres: Vec<([f64; 2], f64)> = Vec::new();
    for i in 0..n {
        let q = o[i];
        if q[1] < y_lo || q[1] > y_hi {
            continue;
        }
        let (a, b) = (o[(i + n - 1) % n], o[(i + 1) % n]);
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        if len <= 0.0 {
            continue;
        }
        let shallow = ((b[1] - a[1]) / len).abs() < SHELF_STEEP;
        let Some((zb, zf)) = depth_span(&o, q[1]) else {
            continue;
        };
        if q[0] < 0.5 * (zb + zf) {
            continue;
        }
        // nearest point of the sketch
        let m = side.len();
        let mut best = (f64::INFINITY, q);
        for j in 0..m {
            let (c, d) = (side[j], side[(j + 1) % m]);
            let e = [d[0] - c[0], d[1] - c[1]];
            let l2 = e[0] * e[0] + e[1] * e[1];
            let t = if l2 > 0.0 {
                (((q[0] - c[0]) * e[0] + (q[1] - c[1]) * e[1]) / l2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let p = [c[0] + t * e[0], c[1] + t * e[1]];
            let dd = (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2);
            if dd < best.0 {
                best = (dd, p);
            }
        }
        if shallow && best.0.sqrt() <= FEATURE_PAIR * h {
            centres.push((q, best.1[1] - q[1]));
        }
    }
    if centres.is_empty() {
        return Ok(0);
    }
    let arms = split.map(|(a, _)| a);
    let spans = super::weights::DepthSpans::new(template, positions, &o, opts, outline)?;
    let f = outline(&template.skin_at(positions), super::View::Front)?;
    let width = SpanProfile::of_outline(&f, SPAN_SMOOTH);
    let s2 = (FEATURE_SIGMA * h).powi(2);
    let reach = 4.0 * FEATURE_SIGMA * h;
    for (i, p) in positions.iter_mut().enumerate() {
        if p[1] < y_lo - reach || p[1] > y_hi + reach || arms.as_ref().is_some_and(|a| a[i]) {
            continue;
        }
        let (mut sw, mut sd) = (0.0, 0.0);
        for (c, d) in &centres {
            let w = (-((p[2] - c[0]).powi(2) + (p[1] - c[1]).powi(2)) / s2).exp();
            sw += w;
            sd += w * d;
        }
        if sw <= 1e-12 {
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
        p[1] += sd / sw * sw.min(1.0) * s * s * (1.0 - u * u).powi(2);
    }
    Ok(centres.len())
}
