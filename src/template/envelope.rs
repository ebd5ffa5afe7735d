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

use super::fit::{FitOptions, Template};
use super::polygon::bbox;
use super::refine::{depth_span, side_outlines};
use super::weights::{relative_depth, SpanProfile, SPAN_SMOOTH};
use super::{OutlineFn, TemplateError};

/// Rows per height of the correction profile.
pub const ROWS: usize = 1024;
/// Half-width (rows) of the box filter smoothing the row corrections.
pub const SMOOTH_ROWS: usize = 2;
/// Fraction of the height over which a trunk bulge found where the sketch
/// is in front of an arm carries on above and below (decaying linearly)
/// at heights where the arm is in front of the sketch.
pub const BULGE_REACH: f64 = 0.03;
/// The arm is the front-most (back-most) part at a height when it is this
/// fraction of the height beyond the trunk.
pub const ARM_EPS: f64 = 1e-3;

/// An arm in front of the sketch's front by more than this fraction of
/// the height is absent from the sketch at that height (its end is higher
/// or lower there), not misplaced.
pub const ARM_ABSENT: f64 = 0.02;

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
    /// Largest row correction applied (model units).
    pub max_correction: f64,
}

/// Every crossing (first coordinate) of the horizontal line at height `y`
/// with the closed polygon `p`, sorted.
pub fn crossings(p: &[[f64; 2]], y: f64) -> Vec<f64> {
    let n = p.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if (a[1] - y) * (b[1] - y) > 0.0 || a[1] == b[1] {
            continue;
        }
        out.push(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
    }
    out.sort_by(f64::total_cmp);
    out
}

fn smooth(v: &mut [f64], known: &[bool]) {
    let src = v.to_vec();
    let n = v.len();
    for i in 0..n {
        if !known[i] {
            continue;
        }
        let (lo, hi) = (i.saturating_sub(SMOOTH_ROWS), (i + SMOOTH_ROWS).min(n - 1));
        let (mut s, mut w) = (0.0, 0.0);
        for j in lo..=hi {
            if known[j] {
                s += src[j];
                w += 1.0;
            }
        }
        v[i] = s / w;
    }
}

/// Replaces each NaN by the nearest finite value (0 when there is none).
fn fill_nearest(v: &mut [f64]) {
    let src = v.to_vec();
    let n = v.len();
    for i in 0..n {
        if src[i].is_nan() {
            v[i] = (1..n)
                .find_map(|d| {
                    let a = i.checked_sub(d).map(|j| src[j]).filter(|x| !x.is_nan());
                    let b = src.get(i + d).copied().filter(|x| !x.is_nan());
                    a.or(b)
                })
                .unwrap_or(0.0);
        }
    }
}

/// Half-width (rows) of the triangle window over which an arm vertex
/// averages the paired rows' remaps ([`remap_near`]).
pub const PAIR_ROWS: usize = 4;

/// The depth change at depth `z` of one paired row: the arm's fitted
/// crossings `c` moved onto the sketched ones `d` (paired in order),
/// linear between them and constant beyond the first and last (0 for no
/// pairs).
pub fn remap(pairs: &[(f64, f64)], z: f64) -> f64 {
    let (Some(&first), Some(&last)) = (pairs.first(), pairs.last()) else {
        return 0.0;
    };
    if z <= first.0 {
        return first.1 - first.0;
    }
    for w in pairs.windows(2) {
        let ((c0, d0), (c1, d1)) = (w[0], w[1]);
        if z <= c1 {
            let t = if c1 > c0 { (z - c0) / (c1 - c0) } else { 0.0 };
            return (1.0 - t) * (d0 - c0) + t * (d1 - c1);
        }
    }
    last.1 - last.0
}

/// Rows over which a paired row's remap carries to rows that do not pair
/// (a finger's web or tip where the fitted outline and the sketch cross a
/// row a different number of times), fading linearly.
pub const PAIR_REACH: usize = 16;

/// Per row, the nearest paired row and its distance (rows), within
/// [`PAIR_REACH`].
fn nearest_paired(paired: &[Option<Vec<(f64, f64)>>]) -> Vec<Option<(usize, usize)>> {
    let n = paired.len();
    (0..n)
        .map(|r| {
            (0..PAIR_REACH).find_map(|d| {
                let below = r.checked_sub(d).filter(|&j| paired[j].is_some());
                let above = Some(r + d).filter(|&j| j < n && paired[j].is_some());
                below.or(above).map(|j| (j, d))
            })
        })
        .collect()
}

/// An arm vertex's remap at fractional row `r`, depth `z`: over a triangle
/// window of [`PAIR_ROWS`] rows, each row's nearest paired row's remap,
/// weighted by the window and by its fading with the distance to that
/// row; with the share `w` of the window's weight it carries (the vertex
/// blends `w` of it with the envelope correction, so the remap fades out
/// continuously away from the paired rows).
fn remap_near(
    paired: &[Option<Vec<(f64, f64)>>],
    nearest: &[Option<(usize, usize)>],
    r: f64,
    z: f64,
) -> Option<(f64, f64)> {
    let k = PAIR_ROWS as f64 + 1.0;
    let lo = (r - k).ceil().max(0.0) as usize;
    let hi = ((r + k).floor().max(0.0) as usize).min(paired.len() - 1);
    let (mut all, mut wp, mut sum) = (0.0, 0.0, 0.0);
    for (j, near) in nearest.iter().enumerate().take(hi + 1).skip(lo) {
        let w = 1.0 - (j as f64 - r).abs() / k;
        if w <= 0.0 {
            continue;
        }
        all += w;
        let Some((jj, d)) = *near else {
            continue;
        };
        let Some(p) = paired[jj].as_deref().filter(|p| !p.is_empty()) else {
            continue;
        };
        let w = w * (1.0 - d as f64 / PAIR_REACH as f64);
        wp += w;
        sum += w * remap(p, z);
    }
    (wp > 0.0).then(|| (wp / all, sum / wp))
}

/// Linear interpolation of a per-row value at fractional row `r`.
fn at(v: &[f64], r: f64) -> f64 {
    let n = v.len();
    let r = r.clamp(0.0, (n - 1) as f64);
    let i = (r.floor() as usize).min(n - 2);
    let t = r - i as f64;
    (1.0 - t) * v[i] + t * v[i + 1]
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
        } else {
            full.front.push(sf - ff);
            body.front.push(sf - tf);
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
            full.back.push(sb - fb);
            body.back.push(sb - tb);
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
