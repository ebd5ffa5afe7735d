//! Occlusion, row by row, for the envelope pass ([`super::envelope`]): at
//! each height, which part (the trunk or an arm) is the fitted side
//! outline's front and back, how the sketch's crossings pair with it, and
//! the front and back corrections of the full outline and of the trunk
//! that follow.

use super::options::FitOptions;
use super::polygon::{boundary_distance, depth_span};
use crate::polygon::line_crossings as crossings;

/// An arm in front of the sketch's front by more than this fraction of
/// the height is absent from the sketch at that height (its end is higher
/// or lower there), not misplaced.
pub const ARM_ABSENT: f64 = 0.02;

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
pub(super) struct Rows {
    pub(super) span: Vec<Option<(f64, f64)>>,
    pub(super) front: Vec<f64>,
    pub(super) back: Vec<f64>,
}

/// An arm's own row where the fitted outline shows it apart from the
/// trunk: its span and its front and back corrections.
#[derive(Clone, Copy, Debug)]
pub(super) struct ArmRow {
    pub(super) span: (f64, f64),
    pub(super) front: f64,
    pub(super) back: f64,
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

/// One pass's inputs: the fitted side outline, the trunk's (arms left
/// out), the sketch, and the rows' heights.
pub(super) struct Pass<'a> {
    pub(super) fitted: &'a [[f64; 2]],
    pub(super) trunk: Option<&'a [[f64; 2]]>,
    pub(super) side: &'a [[f64; 2]],
    pub(super) sketch_span: Vec<Option<(f64, f64)>>,
    pub(super) arm_band: Option<(f64, f64)>,
    /// Row `r` is at height `y0 + r dy`; `h` is the height of the rows.
    pub(super) y0: f64,
    pub(super) dy: f64,
    pub(super) h: f64,
    /// [`ARM_EPS`] of the height.
    pub(super) eps: f64,
    /// A sketch this far beyond an arm is the trunk bulging past it;
    /// nearer, the sketch's crossing is the arm itself.
    pub(super) bulge_min: f64,
    pub(super) opts: &'a FitOptions,
}

/// What the rows found: each part's corrections, the arm's own rows, the
/// paired rows, where an arm is the outline's front or back.
#[derive(Default)]
pub(super) struct Found {
    pub(super) full: Rows,
    pub(super) body: Rows,
    /// The arm's own rows: the full outline's, except where the fitted
    /// outline shows the arm apart from the trunk (its back is the start
    /// of the second interval).
    pub(super) arm_rows: Vec<Option<ArmRow>>,
    /// Rows where the fitted outline and the sketch both show the arm
    /// apart from the trunk with as many crossings: the arm's crossings,
    /// fitted and sketched, paired in order.
    pub(super) paired: Vec<Option<Vec<(f64, f64)>>>,
    pub(super) arm_front: Vec<bool>,
    pub(super) arm_back: Vec<bool>,
    pub(super) stats: EnvelopeStats,
}

/// One row's spans (back, front): the fitted outline's, the sketch's and
/// the trunk's.
#[derive(Clone, Copy)]
pub(super) struct Spans {
    pub(super) r: usize,
    pub(super) y: f64,
    pub(super) fitted: (f64, f64),
    pub(super) sketch: (f64, f64),
    pub(super) trunk: (f64, f64),
}

impl Pass<'_> {
    /// Row `r`'s corrections, appended to `out`.
    pub(super) fn row(&self, r: usize, out: &mut Found) {
        let y = self.y0 + r as f64 * self.dy;
        let f = depth_span(self.fitted, y);
        let s = self.sketch_span[r];
        let t = self.trunk.and_then(|t| depth_span(t, y)).or(f);
        out.full.span.push(f);
        out.body.span.push(t);
        out.arm_rows.push(None);
        out.paired.push(None);
        out.arm_front.push(false);
        out.arm_back.push(false);
        let (Some(fitted), Some(sketch), Some(trunk)) = (f, s, t) else {
            out.full.front.push(0.0);
            out.full.back.push(0.0);
            out.body.front.push(0.0);
            out.body.back.push(0.0);
            return;
        };
        let row = Spans {
            r,
            y,
            fitted,
            sketch,
            trunk,
        };
        let (full, body) = self.front(row, out);
        out.full.front.push(full);
        out.body.front.push(body);
        let (full, body) = self.back(row, out);
        out.full.back.push(full);
        out.body.back.push(body);
    }

    /// A row's front corrections (the full outline's, the trunk's; NaN:
    /// taken from nearby rows).
    fn front(&self, row: Spans, out: &mut Found) -> (f64, f64) {
        let ((_, ff), (_, sf), (tb, tf)) = (row.fitted, row.sketch, row.trunk);
        if ff > tf + self.eps {
            return self.arm_in_front(row, out);
        }
        let uncovered = self
            .arm_band
            .is_some_and(|(a, b)| row.y >= a && row.y <= b)
            .then(|| uncovered_split(&crossings(self.side, row.y), tb))
            .flatten();
        if let Some(front) = uncovered {
            // the trunk is the fitted outline's front but the sketch shows
            // an arm apart in front of it (a sketched fingertip lower than
            // the fitted one): the trunk's front goes to the end of the
            // sketch's back-most interval, not to the sketched finger; an
            // arm at this height (hidden in the trunk's span) takes the
            // nearest rows' correction, not the trunk's
            out.stats.uncovered_rows += 1;
            return (f64::NAN, front - tf);
        }
        let d = boundary_distance(self.side, [ff, row.y])
            .max(boundary_distance(self.fitted, [sf, row.y]));
        (shallow_clamp(sf - ff, d), shallow_clamp(sf - tf, d))
    }

    /// The front corrections of a row where an arm is the fitted
    /// outline's front-most part.
    fn arm_in_front(&self, row: Spans, out: &mut Found) -> (f64, f64) {
        let ((_, ff), (_, sf), (tb, tf)) = (row.fitted, row.sketch, row.trunk);
        let (r, y, eps, h) = (row.r, row.y, self.eps, self.h);
        // the fitted outline's own gap between the trunk's front and an
        // arm (intervals paired with the sketch's by order)
        let fc = crossings(self.fitted, y);
        let fitted_gap =
            (fc.len() >= 4 && (fc[1] - tf).abs() <= eps && fc[2] > fc[1] + eps).then(|| fc[2]);
        out.arm_front[r] = true;
        out.stats.arm_rows += 1;
        let sc = crossings(self.side, y);
        // the fitted outline and the sketch cross this row a different
        // number of times (a fingertip ends above the row in one and
        // below it in the other): their front-most intervals need not be
        // the same finger, the arm takes the nearest rows' correction
        let unpaired = fc.len() != sc.len();
        let front_of = |c: f64| if unpaired { f64::NAN } else { c };
        if self.opts.envelope_pairs && !unpaired && fitted_gap.is_some() && sc[1] > tb {
            out.paired[r] = Some(
                fc[2..]
                    .iter()
                    .copied()
                    .zip(sc[2..].iter().copied())
                    .collect(),
            );
        }
        if sc.len() >= 4 && sc[1] > tb {
            // the sketch shows a gap in front of the trunk at this height
            // (trunk, then the arm): the trunk's front goes to the end of
            // the back-most interval, the arm to the front (and its back,
            // when the fitted outline shows it, to the start of the
            // sketch's second interval)
            out.stats.split_rows += 1;
            if self.opts.envelope_arm_back {
                out.arm_rows[r] = fitted_gap.map(|ab| ArmRow {
                    span: (ab, ff),
                    front: sf - ff,
                    back: sc[2] - ab,
                });
            }
            (front_of(sf - ff), sc[1] - tf)
        } else if let Some(ab) = fitted_gap.filter(|&ab| sf < ff + self.bulge_min && sf >= ab) {
            // the fitted outline shows a gap the sketch does not: the arm
            // moves as a whole to the sketch's front, the trunk's front
            // closes the gap up to the arm's back
            out.stats.closed_rows += 1;
            out.arm_rows[r] = Some(ArmRow {
                span: (ab, ff),
                front: sf - ff,
                back: sf - ff,
            });
            (sf - ff, ab + (sf - ff) + eps - tf)
        } else if sf >= ff + self.bulge_min {
            out.stats.bulge_rows += 1;
            (0.0, sf - tf)
        } else if sf < ff - ARM_ABSENT * h || (fc.len() >= 4 && sf < fc[fc.len() - 2]) {
            // the sketch ends far behind the arm at this height, or behind
            // the fitted outline's front-most interval (a fitted fingertip
            // below the sketched one): pulling the arm's end back to the
            // trunk would shear it; it takes the correction of the nearest
            // rows where the sketch shows it
            out.stats.absent_rows += 1;
            (f64::NAN, f64::NAN)
        } else {
            (front_of(sf - ff), f64::NAN)
        }
    }

    /// A row's back corrections (the full outline's, the trunk's).
    fn back(&self, row: Spans, out: &mut Found) -> (f64, f64) {
        let ((fb, _), (sb, _), (tb, _)) = (row.fitted, row.sketch, row.trunk);
        if fb < tb - self.eps {
            out.arm_back[row.r] = true;
            if sb <= fb - self.bulge_min {
                (0.0, sb - tb)
            } else {
                (sb - fb, f64::NAN)
            }
        } else {
            let d = boundary_distance(self.side, [fb, row.y])
                .max(boundary_distance(self.fitted, [sb, row.y]));
            (shallow_clamp(sb - fb, d), shallow_clamp(sb - tb, d))
        }
    }
}
