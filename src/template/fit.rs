//! The three levels of template-based global modeling (000 secs 4.2.1-4.2.3).

use super::landmarks::{correspond, Similarity};
pub use super::options::{
    level_partner, matched_landmarks, FitOptions, Level, Sketch, Template, ARC_RATIO_MAX, STEEP,
};
use super::options::{FitResult, LevelReport};
use super::polygon::{bbox, validated};
use super::refine::{self, WarpStats};
use super::sections;
use super::{OutlineFn, TemplateError, View};
use crate::mesh::Mesh;
use std::time::Instant;

fn outline_of(
    outline: &OutlineFn,
    skin: &Mesh,
    view: View,
) -> Result<Vec<[f64; 2]>, TemplateError> {
    let p = outline(skin, view)?;
    validated(&format!("the template's {} outline", view.name()), &p).map_err(|e| {
        TemplateError::NoOutline {
            view: view.name().into(),
            problem: e.to_string(),
        }
    })
}

/// Largest [`FitOptions::envelope_falloff`] (a weight `s^k` is below
/// 0.004 at `s = 1/2` by then; a negative `k` would divide by a zero depth
/// weight).
pub const ENVELOPE_FALLOFF_MAX: i32 = 8;

/// Most [`FitOptions::envelope_passes`] (each re-extracts the fitted
/// outlines; the study's cases keep at most 4).
pub const ENVELOPE_PASSES_MAX: usize = 64;

pub(crate) fn max_norm(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(p, q)| {
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        })
        .fold(0.0, f64::max)
}

/// Fits the template to the sketch: the low level always, the medium level
/// when the sketch has a side profile, the high level when it also has key
/// cross-sections. `outline` gives a mesh's outline in a view. After every
/// level the fitted outlines are measured against the sketch and corrected
/// ([`refine`]); a view that stays off by more than
/// [`FitOptions::tolerance`] fails the fit unless [`FitOptions::on_miss`]
/// is [`OnMiss::Report`].
pub fn fit(
    template: &Template,
    sketch: &Sketch,
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<FitResult, TemplateError> {
    let t0 = Instant::now();
    let memo = super::memo::OutlineMemo::new(outline); // passes re-ask unchanged skins
    let outline: &OutlineFn = &|m: &Mesh, v: View| memo.outline(m, v);
    check_options(opts)?;
    let front = validated("the sketched front profile", &sketch.front)?;
    let side_of = |s: &Vec<[f64; 2]>| validated("the sketched side profile", s);
    let side = sketch.side.as_ref().map(side_of).transpose()?;
    if !sketch.sections.is_empty() && side.is_none() {
        return Err(TemplateError::BadProfile {
            what: "the sketch".into(),
            problem: "key cross-sections (high level) need a side profile (medium level)".into(),
        });
    }
    let fitter = Fitter {
        template,
        front: &front,
        opts,
        outline,
    };
    let (alignment, depth_centre, low) = fitter.low(t0)?;
    let mut levels = vec![low];
    let done = |levels: Vec<(LevelReport, Vec<[f64; 3]>)>| FitResult {
        alignment,
        depth_centre,
        levels,
    };
    let Some(side) = side else {
        return Ok(done(levels));
    };
    let medium = fitter.medium(&levels[0], &side)?;
    levels.push(medium);
    if sketch.sections.is_empty() {
        return Ok(done(levels));
    }
    let high = fitter.high(&levels[1].1, &side, &sketch.sections)?;
    levels.push(high);
    Ok(done(levels))
}

/// The fit options' own bounds: a finite positive tolerance, the envelope
/// falloff and passes within their maxima.
fn check_options(opts: &FitOptions) -> Result<(), TemplateError> {
    if !(opts.tolerance.is_finite() && opts.tolerance > 0.0) {
        return Err(TemplateError::BadProfile {
            what: "the fit options".into(),
            problem: format!(
                "tolerance must be finite and positive, got {}",
                opts.tolerance
            ),
        });
    }
    if !(1..=ENVELOPE_FALLOFF_MAX).contains(&opts.envelope_falloff)
        || opts.envelope_passes > ENVELOPE_PASSES_MAX
    {
        return Err(TemplateError::BadProfile {
            what: "the fit options".into(),
            problem: format!(
                "envelope_falloff must lie in 1..={ENVELOPE_FALLOFF_MAX} (got {}) and envelope_passes in 0..={ENVELOPE_PASSES_MAX} (got {})",
                opts.envelope_falloff, opts.envelope_passes
            ),
        });
    }
    Ok(())
}

/// One fit's inputs shared by its levels: the template, the validated
/// front profile, the options and the (memoised) outline function.
struct Fitter<'a> {
    template: &'a Template,
    front: &'a [[f64; 2]],
    opts: &'a FitOptions,
    outline: &'a OutlineFn<'a>,
}

/// A level's report and its fitted vertex positions.
type LevelFit = (LevelReport, Vec<[f64; 3]>);

/// One correction pass of the fitted positions toward a profile
/// ([`refine::front_pass`], [`refine::side_pass`]).
type CorrectionPass = fn(
    &Template,
    &mut [[f64; 3]],
    &[[f64; 2]],
    &FitOptions,
    &OutlineFn,
    &mut WarpStats,
) -> Result<(), TemplateError>;

impl Fitter<'_> {
    /// Correction passes (`pass`: [`refine::front_pass`] or
    /// [`refine::side_pass`]) of `positions` toward `profile` in `view`
    /// while its error `err` is over the tolerance, at most
    /// [`FitOptions::passes`]; a pass that does not reduce the error is
    /// undone and ends them. Returns the passes kept.
    fn corrections(
        &self,
        pass: CorrectionPass,
        (view, profile): (View, &[[f64; 2]]),
        positions: &mut Vec<[f64; 3]>,
        err: &mut f64,
        stats: &mut WarpStats,
    ) -> Result<usize, TemplateError> {
        let (template, opts, outline) = (self.template, self.opts, self.outline);
        let mut passes = 0;
        while *err > opts.tolerance && passes < opts.passes {
            let mut next = positions.clone();
            pass(template, &mut next, profile, opts, outline, stats)?;
            let e = refine::measure(template, &next, view, profile, outline)?;
            if e >= *err {
                break;
            }
            (*positions, *err) = (next, e);
            passes += 1;
        }
        Ok(passes)
    }

    /// Envelope correction passes ([`super::envelope::envelope_pass`])
    /// while the side view misses the tolerance, at most
    /// [`FitOptions::envelope_passes`]; a pass that does not reduce the
    /// miss is undone and ends them. Returns the passes kept.
    fn envelope(
        &self,
        positions: &mut Vec<[f64; 3]>,
        side_err: &mut f64,
        side: &[[f64; 2]],
    ) -> Result<usize, TemplateError> {
        let (template, front, opts, outline) = (self.template, self.front, self.opts, self.outline);
        let mut kept = 0;
        let mut front_err = None;
        while *side_err > opts.tolerance && kept < opts.envelope_passes {
            let mut next = positions.clone();
            let features = opts.envelope_features
                && super::envelope::feature_warp(template, &mut next, side, opts, outline)? > 0;
            let shelves = opts.envelope_shelves
                && super::envelope::shelf_warp(template, &mut next, side, opts, outline)? > 0;
            let features = features || shelves;
            super::envelope::envelope_pass(template, &mut next, side, opts, outline)?;
            let err = refine::measure(template, &next, View::Side, side, outline)?;
            if err >= *side_err {
                break;
            }
            if features {
                // heights moved: the front view must stay within the tolerance
                // (or no worse than it was)
                let before = match front_err {
                    Some(e) => e,
                    None => refine::measure(template, positions, View::Front, front, outline)?,
                };
                let after = refine::measure(template, &next, View::Front, front, outline)?;
                if after > before.max(opts.tolerance) {
                    break;
                }
                front_err = Some(after);
            }
            (*positions, *side_err) = (next, err);
            kept += 1;
        }
        Ok(kept)
    }

    /// The low level (000 sec 4.2.1): the template aligned to the front
    /// profile by a similarity on matched landmarks, warped and corrected
    /// in the front view. Returns the similarity, the depth centre it
    /// scales about, and the level. `t0`: when the fit started.
    fn low(&self, t0: Instant) -> Result<(Similarity, f64, LevelFit), TemplateError> {
        let (template, front, opts, outline) = (self.template, self.front, self.opts, self.outline);
        let t_front = outline_of(outline, &template.skin, View::Front)?;
        let (lt, ls) = matched_landmarks(View::Front, opts.front_scheme, &t_front, front)?;
        let ta: Vec<[f64; 2]> = lt.iter().map(|&i| t_front[i]).collect();
        let sa: Vec<[f64; 2]> = ls.iter().map(|&i| front[i]).collect();
        let sim = Similarity::fit(&ta, &sa);
        let (blo, bhi) = {
            let zs: Vec<[f64; 2]> = template
                .skin
                .positions
                .iter()
                .map(|p| [p[2], p[1]])
                .collect();
            bbox(&zs)
        };
        let zc = 0.5 * (blo[0] + bhi[0]);
        let aligned_outline: Vec<[f64; 2]> = t_front.iter().map(|&p| sim.apply(p)).collect();
        let (ca, cb) = correspond(&aligned_outline, &lt, front, &ls, opts.front_centres);
        let before: Vec<[f64; 3]> = template
            .mesh
            .positions
            .iter()
            .map(|p| {
                let q = sim.apply([p[0], p[1]]);
                [q[0], q[1], sim.scale * (p[2] - zc) + zc]
            })
            .collect();
        let mut low = before.clone();
        let mut stats = WarpStats::default();
        refine::front_warp(&mut low, &ca, &cb, opts, &mut stats)?;
        let mut front_err = refine::measure(template, &low, View::Front, front, outline)?;
        let passes = self.corrections(
            refine::front_pass,
            (View::Front, front),
            &mut low,
            &mut front_err,
            &mut stats,
        )?;
        let front_fit = refine::view_fit(View::Front, front_err, opts);
        refine::enforce(Level::Low, &[front_fit], passes, opts)?;
        let rep = LevelReport {
            level: Level::Low,
            centres: stats.centres,
            condition: stats.condition,
            residual: stats.residual,
            max_displacement: max_norm(&before, &low),
            passes,
            profiles: vec![front_fit],
            seconds: t0.elapsed().as_secs_f64(),
        };
        Ok((sim, zc, (rep, low)))
    }

    /// The medium level (000 sec 4.2.2): depth from the side profile (the
    /// envelope passes' hand features and shelves, and the head's remap,
    /// also move heights: the front view is measured again).
    fn medium(&self, low: &LevelFit, side: &[[f64; 2]]) -> Result<LevelFit, TemplateError> {
        let (template, front, opts, outline) = (self.template, self.front, self.opts, self.outline);
        let t1 = Instant::now();
        let (low_rep, low) = low;
        let mut medium = low.clone();
        let mut stats = WarpStats::default();
        refine::side_pass(template, &mut medium, side, opts, outline, &mut stats)?;
        let mut side_err = refine::measure(template, &medium, View::Side, side, outline)?;
        let mut passes = self.corrections(
            refine::side_pass,
            (View::Side, side),
            &mut medium,
            &mut side_err,
            &mut stats,
        )?;
        passes += self.envelope(&mut medium, &mut side_err, side)?;
        // the side landmarks, hand features and shelves move heights: the
        // front view again
        let front_fit = if opts.side_landmarks || opts.envelope_features || opts.envelope_shelves {
            let err = refine::measure(template, &medium, View::Front, front, outline)?;
            refine::view_fit(View::Front, err, opts)
        } else {
            low_rep.profiles[0]
        };
        let fits = vec![front_fit, refine::view_fit(View::Side, side_err, opts)];
        refine::enforce(Level::Medium, &fits, passes, opts)?;
        let rep = LevelReport {
            level: Level::Medium,
            centres: stats.centres,
            condition: stats.condition,
            residual: stats.residual,
            max_displacement: max_norm(low, &medium),
            passes,
            profiles: fits,
            seconds: t1.elapsed().as_secs_f64(),
        };
        Ok((rep, medium))
    }

    /// The high level (000 sec 4.2.3): the key cross-sections, then the
    /// envelope passes again.
    fn high(
        &self,
        medium: &[[f64; 3]],
        side: &[[f64; 2]],
        sections: &[super::options::SectionSketch],
    ) -> Result<LevelFit, TemplateError> {
        let (template, front, opts, outline) = (self.template, self.front, self.opts, self.outline);
        let t2 = Instant::now();
        let (rep, mut high) =
            sections::fit_sections(template, medium, front, side, sections, opts)?;
        let mut side_err = refine::measure(template, &high, View::Side, side, outline)?;
        let passes = self.envelope(&mut high, &mut side_err, side)?;
        let fits = vec![
            refine::view_fit(
                View::Front,
                refine::measure(template, &high, View::Front, front, outline)?,
                opts,
            ),
            refine::view_fit(View::Side, side_err, opts),
        ];
        refine::enforce(Level::High, &fits, passes, opts)?;
        let rep = LevelReport {
            passes,
            profiles: fits,
            seconds: t2.elapsed().as_secs_f64(),
            ..rep
        };
        Ok((rep, high))
    }
}
