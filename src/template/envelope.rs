//! Side-outline correction by envelope rows (issue 12: the side profile
//! within 0.5 % of the height at the medium and high levels).
//!
//! The smooth side warp ([`super::refine::side_pass`]) leaves misses where
//! its partners land on the wrong body part (a forearm in front of a
//! pregnant belly, a chin over a neck). This pass re-extracts the fitted
//! skin's side outline and compares it with the sketch *row by row*: at
//! each height `y` the outline's back-most and front-most crossings
//! `[zb, zf]` against the sketch's `[sb, sf]`. Occlusion is decided on the
//! fitted state (after the front level moved the arms), not on the
//! template at rest: with the arms known (front landmarks,
//! [`super::refine::arm_mask`]) the trunk's own outline (arms left out)
//! gives the trunk's span `[tb, tf]`, and at a height where an arm is the
//! front-most part (`zf > tf`)
//! - a sketch in front of the arm by more than the fit's tolerance
//!   (`sf >= zf + tol h`) is a bulge of the trunk (a pregnant belly): the
//!   trunk's front moves to `sf`, the arm stays;
//! - a sketch behind the arm's front moves the arm back to `sf`, and the
//!   trunk's front only as far as it would stick out of the sketch, or as
//!   far as a bulge found at nearby heights carries ([`BULGE_REACH`]), so
//!   the trunk's correction is continuous where the sketch's front passes
//!   the arm.
//!
//! - a sketch whose crossings at that height make two intervals or more
//!   (the trunk, then the arm, apart) moves the trunk's front to the end
//!   of the back-most interval and the arm's to the sketch's front: a
//!   belly between the body's back and the hands is an inner crossing,
//!   not the envelope (MakeHuman's hands are in front of the belly).
//!
//! - where the trunk is the fitted outline's front but the sketch shows an
//!   arm apart in front of it (a sketched fingertip lower than the fitted
//!   one), the trunk's front goes to the end of the sketch's back-most
//!   interval ([`uncovered_split`]), not to the sketched finger;
//! - elsewhere a row's correction is clamped by the outlines' distance
//!   there ([`shallow_clamp`]), so a shallow stretch is not sheared.
//!
//! Before the rows, [`feature_warp`] moves the arm's vertices in depth
//! *and height* so the fitted outline's webs and fingertips land on the
//! sketch's (a web between two fingers lower on the fitted hand cannot be
//! raised in depth).
//!
//! Likewise at the back. Each vertex then moves in depth by the
//! correction of its part's front and back at its height, weighted by
//! its relative depth in its part's span (smoothed over heights,
//! [`super::weights`], so the weights do not jump at overhangs), so a
//! vertex on the envelope lands on the sketch's crossing of its height
//! (with [`FitOptions::envelope_falloff`] 2, by the square of the relative
//! depth, so a belly's sides move less than its front). The row
//! corrections are smoothed over [`SMOOTH_ROWS`] rows so an overhang (a
//! chin, a nose) met at slightly different heights does not shear the
//! skin. The fit repeats the pass while the view misses the tolerance
//! (bounded, reported, undone when it does not help).

pub use super::features::{
    feature_warp, hand_features, paired_features, shelf_warp, Feature, FEATURE_PAIR,
};
use super::options::{FitOptions, Template};
use super::outlines::side_outlines;
use super::polygon::depth_span;
use super::polygon::{bbox, boundary_distance};
use super::rows::{at, fill_nearest, nearest_paired, remap_near, smooth};
pub use super::rows::{remap, ARM_EPS, PAIR_REACH, PAIR_ROWS, SMOOTH_ROWS};
use super::weights::{relative_depth, SpanProfile, SPAN_SMOOTH};
use super::{OutlineFn, TemplateError};
use crate::polygon::line_crossings as crossings;

/// Rows per height of the correction profile.
pub const ROWS: usize = 1024;
/// Fraction of the height over which a trunk bulge found where the sketch
/// is in front of an arm carries on above and below (decaying linearly)
/// at heights where the arm is in front of the sketch.
pub const BULGE_REACH: f64 = 0.03;

/// An arm in front of the sketch's front by more than this fraction of
/// the height is absent from the sketch at that height (its end is higher
/// or lower there), not misplaced.
pub const ARM_ABSENT: f64 = 0.02;

/// Fraction of the height below (above) the fitted arms' lowest (highest)
/// vertex where a sketch's extra intervals in front of the trunk still
/// count as an arm ([`uncovered_split`]).
pub const ARM_REACH: f64 = 0.05;

/// Where the fitted outline's front is the trunk (no fitted arm in front
/// of it at that height) but the sketch's crossings `sc` (sorted) make two
/// intervals or more and the back-most ends in front of the trunk's back
/// `tb`: the end of the sketch's back-most interval, the trunk's front
/// there. The sketch's intervals in front are an arm the fitted outline
/// does not show at that height (a sketched fingertip lower than the
/// fitted one); partnering the trunk's front with the sketch's front-most
/// crossing pushed it onto the sketched finger (the girl's and the old
/// woman's spikes, up to 2.2 % of the height). `None` otherwise.
pub fn uncovered_split(sc: &[f64], tb: f64) -> Option<f64> {
    (sc.len() >= 4 && sc[1] > tb).then(|| sc[1])
}

/// A row's depth correction `c` is at most this many times the larger of
/// the two outlines' distances there ([`shallow_clamp`]).
pub const SHALLOW_FACTOR: f64 = 2.0;

/// A row's depth correction `c` (sketch crossing minus fitted crossing at
/// one height) limited to [`SHALLOW_FACTOR`] times `d`, the larger of the
/// fitted crossing's distance to the sketch and the sketch crossing's
/// distance to the fitted outline. On a steep stretch `d` is about `|c|`
/// (no change); on a shallow one (a chin's underside, a fingertip, where
/// the outlines cross a row at depths far apart although they lie close)
/// `|c|` overstates the miss, and moving each row by it sheared the
/// stretch into hooks (the old woman's chin, 0.67 % of the height).
pub fn shallow_clamp(c: f64, d: f64) -> f64 {
    let m = SHALLOW_FACTOR * d.max(0.0);
    c.clamp(-m, m)
}

/// Row corrections of one part: front and back depth changes and the
/// part's span, per row (`None`: the part does not reach that row).
#[derive(Clone, Debug, Default)]
struct Rows {
    span: Vec<Option<(f64, f64)>>,
    front: Vec<f64>,
    back: Vec<f64>,
}

/// An arm's own row where the fitted outline shows it apart from the
/// trunk: its span and its front and back corrections.
#[derive(Clone, Copy, Debug)]
struct ArmRow {
    span: (f64, f64),
    front: f64,
    back: f64,
}

/// Statistics of one envelope pass.
#[derive(Clone, Copy, Debug, Default, serde::Serialize)]
pub struct EnvelopeStats {
    /// Rows where an arm is the fitted outline's front-most part.
    pub arm_rows: usize,
    /// Of those, rows where the sketch is in front of the arm (a bulge of
    /// the trunk).
    pub bulge_rows: usize,
    /// Of those, rows where the sketch shows the trunk and the arm apart
    /// (two intervals or more): the trunk's front goes to the back-most
    /// interval's front.
    pub split_rows: usize,
    /// Rows where the fitted outline shows a gap between the trunk and an
    /// arm that the sketch does not: the trunk's front closes it.
    pub closed_rows: usize,
    /// Rows where an arm is the fitted outline's front but the sketch's
    /// front is more than [`ARM_ABSENT`] of the height behind it.
    pub absent_rows: usize,
    /// Rows where the trunk is the fitted outline's front but the sketch
    /// shows an arm apart in front of it ([`uncovered_split`]): the
    /// trunk's front goes to the sketch's back-most interval's end.
    pub uncovered_rows: usize,
    /// Largest row correction applied (model units).
    pub max_correction: f64,
}

/// One envelope correction pass on `positions` (every template vertex)
/// towards the sketched side profile `side`.
pub fn envelope_pass(
    template: &Template,
    positions: &mut [[f64; 3]],
    side: &[[f64; 2]],
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<EnvelopeStats, TemplateError> {
    let (o, split) = side_outlines(template, positions, opts.envelope_arms, opts, outline)?;
    let (arms, trunk) = split.unzip();
    let (lo, hi) = bbox(&o);
    let (slo, shi) = bbox(side);
    let (y0, y1) = (lo[1].min(slo[1]), hi[1].max(shi[1]));
    let h = (y1 - y0).max(f64::MIN_POSITIVE);
    let dy = h / (ROWS - 1) as f64;
    let eps = ARM_EPS * h;
    // a sketch this far beyond an arm is the trunk bulging past it; nearer,
    // the sketch's crossing is the arm itself
    let bulge_min = opts.tolerance * h;
    // the sketch's span per row (used again for the hidden rows' fill)
    let sketch_span: Vec<Option<(f64, f64)>> = (0..ROWS)
        .map(|r| depth_span(side, y0 + r as f64 * dy))
        .collect();
    let mut full = Rows::default();
    let mut body = Rows::default();
    // the arm's own rows: the full outline's, except where the fitted
    // outline shows the arm apart from the trunk (its back is the start of
    // the second interval)
    let mut arm_rows: Vec<Option<ArmRow>> = vec![None; ROWS];
    // rows where the fitted outline and the sketch both show the arm apart
    // from the trunk with as many crossings: the arm's crossings, fitted
    // and sketched, paired in order
    let mut paired: Vec<Option<Vec<(f64, f64)>>> = vec![None; ROWS];
    let mut bulge = vec![0.0f64; ROWS];
    let mut arm_front = vec![false; ROWS];
    let mut arm_back = vec![false; ROWS];
    let mut stats = EnvelopeStats::default();
    // the heights the fitted arms span, widened by [`ARM_REACH`] of the
    // height (a sketched hand may end lower or higher than the fitted one)
    let arm_band = arms.as_ref().and_then(|a| {
        let (lo, hi) = positions
            .iter()
            .zip(a)
            .filter(|(_, &m)| m)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, u), (p, _)| {
                (l.min(p[1]), u.max(p[1]))
            });
        (lo <= hi).then_some((lo - ARM_REACH * h, hi + ARM_REACH * h))
    });
    for r in 0..ROWS {
        let y = y0 + r as f64 * dy;
        let f = depth_span(&o, y);
        let s = sketch_span[r];
        let t = trunk.as_deref().and_then(|t| depth_span(t, y)).or(f);
        full.span.push(f);
        body.span.push(t);
        let (Some((fb, ff)), Some((sb, sf)), Some((tb, tf))) = (f, s, t) else {
            full.front.push(0.0);
            full.back.push(0.0);
            body.front.push(0.0);
            body.back.push(0.0);
            continue;
        };
        // the fitted outline's own gap between the trunk's front and an
        // arm (intervals paired with the sketch's by order)
        let fc = crossings(&o, y);
        let fitted_gap =
            (fc.len() >= 4 && (fc[1] - tf).abs() <= eps && fc[2] > fc[1] + eps).then(|| fc[2]);
        // front
        if ff > tf + eps {
            arm_front[r] = true;
            stats.arm_rows += 1;
            let sc = crossings(side, y);
            // the fitted outline and the sketch cross this row a different
            // number of times (a fingertip ends above the row in one and
            // below it in the other): their front-most intervals need not
            // be the same finger, the arm takes the nearest rows' correction
            let unpaired = fc.len() != sc.len();
            let front_of = |c: f64| if unpaired { f64::NAN } else { c };
            if opts.envelope_pairs && !unpaired && fitted_gap.is_some() && sc[1] > tb {
                paired[r] = Some(
                    fc[2..]
                        .iter()
                        .copied()
                        .zip(sc[2..].iter().copied())
                        .collect(),
                );
            }
            if sc.len() >= 4 && sc[1] > tb {
                // the sketch shows a gap in front of the trunk at this
                // height (trunk, then the arm): the trunk's front goes to
                // the end of the back-most interval, the arm to the front
                // (and its back, when the fitted outline shows it, to the
                // start of the sketch's second interval)
                stats.split_rows += 1;
                full.front.push(front_of(sf - ff));
                body.front.push(sc[1] - tf);
                if opts.envelope_arm_back {
                    arm_rows[r] = fitted_gap.map(|ab| ArmRow {
                        span: (ab, ff),
                        front: sf - ff,
                        back: sc[2] - ab,
                    });
                }
            } else if let Some(ab) = fitted_gap.filter(|&ab| sf < ff + bulge_min && sf >= ab) {
                // the fitted outline shows a gap the sketch does not: the
                // arm moves as a whole to the sketch's front, the trunk's
                // front closes the gap up to the arm's back
                stats.closed_rows += 1;
                full.front.push(sf - ff);
                body.front.push(ab + (sf - ff) + eps - tf);
                arm_rows[r] = Some(ArmRow {
                    span: (ab, ff),
                    front: sf - ff,
                    back: sf - ff,
                });
            } else if sf >= ff + bulge_min {
                stats.bulge_rows += 1;
                bulge[r] = sf - tf;
                full.front.push(0.0);
                body.front.push(sf - tf);
            } else if sf < ff - ARM_ABSENT * h || (fc.len() >= 4 && sf < fc[fc.len() - 2]) {
                // the sketch ends far behind the arm at this height, or
                // behind the fitted outline's front-most interval (a
                // fitted fingertip below the sketched one): pulling the
                // arm's end back to the trunk would shear it; it takes the
                // correction of the nearest rows where the sketch shows it
                stats.absent_rows += 1;
                full.front.push(f64::NAN);
                body.front.push(f64::NAN);
            } else {
                full.front.push(front_of(sf - ff));
                body.front.push(f64::NAN);
            }
        } else if let Some(front) = arm_band
            .is_some_and(|(a, b)| y >= a && y <= b)
            .then(|| uncovered_split(&crossings(side, y), tb))
            .flatten()
        {
            // the trunk is the fitted outline's front but the sketch shows
            // an arm apart in front of it (a sketched fingertip lower than
            // the fitted one): the trunk's front goes to the end of the
            // sketch's back-most interval, not to the sketched finger; an
            // arm at this height (hidden in the trunk's span) takes the
            // nearest rows' correction, not the trunk's
            stats.uncovered_rows += 1;
            full.front.push(f64::NAN);
            body.front.push(front - tf);
        } else {
            let d = boundary_distance(side, [ff, y]).max(boundary_distance(&o, [sf, y]));
            full.front.push(shallow_clamp(sf - ff, d));
            body.front.push(shallow_clamp(sf - tf, d));
        }
        // back
        if fb < tb - eps {
            arm_back[r] = true;
            if sb <= fb - bulge_min {
                bulge[r] = bulge[r].max(tb - sb);
                full.back.push(0.0);
                body.back.push(sb - tb);
            } else {
                full.back.push(sb - fb);
                body.back.push(f64::NAN);
            }
        } else {
            let d = boundary_distance(side, [fb, y]).max(boundary_distance(&o, [sb, y]));
            full.back.push(shallow_clamp(sb - fb, d));
            body.back.push(shallow_clamp(sb - tb, d));
        }
    }
    // the trunk behind an arm: the bulge carried from nearby rows, no
    // farther than the sketch allows
    let reach = (BULGE_REACH * h / dy).max(1.0);
    let carried = |r: usize, sign: f64| -> f64 {
        let k = reach.ceil() as usize;
        let mut best = 0.0f64;
        for j in r.saturating_sub(k)..=(r + k).min(ROWS - 1) {
            let w = 1.0 - (j as f64 - r as f64).abs() / reach;
            let v = if sign > 0.0 {
                body.front[j]
            } else {
                -body.back[j]
            };
            let bulged = if sign > 0.0 {
                arm_front[j]
            } else {
                arm_back[j]
            };
            if w > 0.0 && bulged && v.is_finite() && v > 0.0 {
                best = best.max(w * v);
            }
        }
        best
    };
    let fills: Vec<(Option<f64>, Option<f64>)> = (0..ROWS)
        .map(|r| {
            let (Some((tb, tf)), Some((sb, sf))) = (body.span[r], sketch_span[r]) else {
                return (None, None);
            };
            (
                body.front[r].is_nan().then(|| carried(r, 1.0).min(sf - tf)),
                body.back[r]
                    .is_nan()
                    .then(|| (-carried(r, -1.0)).max(sb - tb)),
            )
        })
        .collect();
    for (r, (f, b)) in fills.into_iter().enumerate() {
        if let Some(f) = f {
            body.front[r] = f;
        }
        if let Some(b) = b {
            body.back[r] = b;
        }
    }
    for v in body.front.iter_mut().chain(body.back.iter_mut()) {
        if v.is_nan() {
            *v = 0.0;
        }
    }
    fill_nearest(&mut full.front);
    // the arm's rows: the full outline's, with the arm's own rows where the
    // fitted outline shows it apart
    let mut arm = full.clone();
    for (r, a) in arm_rows.iter().enumerate() {
        if let Some(a) = a {
            arm.span[r] = Some(a.span);
            arm.front[r] = a.front;
            arm.back[r] = a.back;
        }
    }
    let known_full: Vec<bool> = full.span.iter().map(Option::is_some).collect();
    let known_body: Vec<bool> = body.span.iter().map(Option::is_some).collect();
    for (v, k) in [
        (&mut full.front, &known_full),
        (&mut full.back, &known_full),
        (&mut body.front, &known_body),
        (&mut body.back, &known_body),
        (&mut arm.front, &known_full),
        (&mut arm.back, &known_full),
    ] {
        smooth(v, k);
    }
    stats.max_correction = full
        .front
        .iter()
        .chain(&full.back)
        .chain(&body.front)
        .chain(&body.back)
        .fold(0.0f64, |m, v| m.max(v.abs()));
    // each part's span smoothed over heights: continuous weights
    // ([`super::weights`]; the nearest row's span jumps at overhangs)
    let smooth = SPAN_SMOOTH * h;
    let arm_span = SpanProfile::of_rows(y0, dy, &arm.span, smooth);
    let body_span = SpanProfile::of_rows(y0, dy, &body.span, smooth);
    let nearest = nearest_paired(&paired);
    for (i, p) in positions.iter_mut().enumerate() {
        let r = (p[1] - y0) / dy;
        let is_arm = matches!(&arms, Some(a) if a[i]);
        let (part, span) = if is_arm {
            (&arm, &arm_span)
        } else {
            (&body, &body_span)
        };
        let Some(span) = span else {
            continue;
        };
        let s = relative_depth(p[2], span.at(p[1]));
        let k = opts.envelope_falloff;
        let d = s.powi(k) * at(&part.front, r) + (1.0 - s).powi(k) * at(&part.back, r);
        p[2] += match is_arm
            .then(|| remap_near(&paired, &nearest, r, p[2]))
            .flatten()
        {
            Some((w, m)) => w * m + (1.0 - w) * d,
            None => d,
        };
    }
    Ok(stats)
}
