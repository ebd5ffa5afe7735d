//! The three levels of template-based global modeling (000 secs 4.2.1-4.2.3).

use super::landmarks::{self, arc_fractions, correspond, Scheme, Similarity};
use super::polygon::{bbox, validated};
use super::refine::{self, DepthMap, OnMiss, SidePartner, ViewFit, WarpStats};
use super::sections::{self, SectionMatch, SectionSketch};
use super::{OutlineFn, TemplateError, View};
use crate::mesh::Mesh;
use std::time::Instant;

/// Largest ratio between the arc-length shares of corresponding landmark arcs
/// on the template and the sketch before the landmarks count as unmatched.
pub const ARC_RATIO_MAX: f64 = 3.0;
/// Side-outline stretches steeper than this (|dy/ds|) take their partner
/// at the same height.
pub const STEEP: f64 = 0.5;

/// A template: every vertex that moves (`mesh`) and the skin whose outlines
/// and sections are fitted (`skin`, vertex `i` at `mesh.positions[skin_index[i]]`).
#[derive(Clone, Debug)]
pub struct Template {
    pub mesh: Mesh,
    pub skin: Mesh,
    pub skin_index: Vec<u32>,
}

impl Template {
    /// A template whose skin is the whole mesh.
    pub fn whole(mesh: Mesh) -> Template {
        let skin_index = (0..mesh.positions.len() as u32).collect();
        Template {
            skin: mesh.clone(),
            mesh,
            skin_index,
        }
    }

    /// The skin with the mesh's vertices moved to `positions`.
    pub fn skin_at(&self, positions: &[[f64; 3]]) -> Mesh {
        let mut s = self.skin.clone();
        for (p, &i) in s.positions.iter_mut().zip(&self.skin_index) {
            *p = positions[i as usize];
        }
        s
    }

    /// Skin height (y extent).
    pub fn height(&self) -> f64 {
        let (lo, hi) = self
            .skin
            .positions
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
                (l.min(p[1]), h.max(p[1]))
            });
        hi - lo
    }
}

/// The sketched profiles: front (x, y) required, side (z, y) for the medium
/// level, key cross-sections for the high level.
#[derive(Clone, Debug, Default)]
pub struct Sketch {
    pub front: Vec<[f64; 2]>,
    pub side: Option<Vec<[f64; 2]>>,
    pub sections: Vec<SectionSketch>,
}

/// Options of [`fit`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct FitOptions {
    /// RBF centres on the front outline (default 400).
    pub front_centres: usize,
    /// RBF centres on the side outline (default 160).
    pub side_centres: usize,
    /// Points per key cross-section loop (default 32).
    pub section_points: usize,
    /// Silhouette anchors per view at the high level (default 240).
    pub anchors: usize,
    /// GEC terms for the key cross-sections (default 10).
    pub gec_terms: usize,
    /// Front landmark scheme (default [`Scheme::Human`]).
    pub front_scheme: Scheme,
    /// Side landmark scheme (default [`Scheme::Side`]).
    pub side_scheme: Scheme,
    /// Measure each RBF system's condition number (default true).
    pub condition: bool,
    /// Largest profile error allowed, relative to the sketch's height
    /// (default [`super::check::PROFILE_REL`], 0.5 %).
    pub tolerance: f64,
    /// Correction passes per level while a view misses the tolerance
    /// (default 3; a pass that does not reduce the miss is undone and ends
    /// the corrections).
    pub passes: usize,
    /// What to do when a view still misses after the passes (default
    /// [`OnMiss::Fail`]).
    pub on_miss: OnMiss,
    /// How section points correspond at the high level (default
    /// [`SectionMatch::Radial`]).
    pub section_match: SectionMatch,
    /// How the side pass partners steep outline points (default
    /// [`SidePartner::Envelope`]).
    pub side_partner: SidePartner,
    /// The side pass's overall depth map (default [`DepthMap::Robust`]).
    pub depth_map: DepthMap,
    /// Exponent of the side pass's relative-depth weights (default
    /// [`refine::DEPTH_FALLOFF`]).
    pub depth_falloff: i32,
    /// With [`SidePartner::Envelope`]: partner the trunk's side outline
    /// (arms found from the front landmarks, left out; arms take the
    /// affine depth map only). Default false: in the MakeHuman study it
    /// fits the pregnant belly (high-level RMS 0.27 % against 0.37 %) but
    /// loses on four other targets (README).
    pub side_trunk: bool,
    /// Zero-displacement anchors of the high level on skin vertices away
    /// from the sections' heights (default 300; 0: none).
    pub band_anchors: usize,
    /// Envelope correction passes ([`super::envelope`]) after the medium
    /// and high levels while the side view misses the tolerance (default
    /// 4; 0: none. In the MakeHuman study they bring the medium side miss
    /// from 0.60-5.56 % to 0.28-0.73 % on six targets, female->old 2.28 %;
    /// README).
    pub envelope_passes: usize,
    /// The envelope passes decide per height whether an arm or the trunk
    /// forms the fitted outline (default true).
    pub envelope_arms: bool,
    /// Where both the fitted outline and the sketch show an arm apart from
    /// the trunk, the envelope passes also move the arm's back to the
    /// sketch's second interval (default false: in the MakeHuman study it
    /// paired a fitted finger with the sketched palm on the pregnant case).
    pub envelope_arm_back: bool,
    /// Exponent of the envelope passes' relative-depth weights (default 2:
    /// a vertex at relative depth `s` in its part's span takes `s^2` of the
    /// front's correction and `(1 - s)^2` of the back's, so a belly's sides
    /// move less than its front; 1, linear, made the pregnant high level
    /// lose to the bounding-box baseline, RMS 0.42 % against 0.40 %).
    pub envelope_falloff: i32,
    /// Where the fitted outline and the sketch both show an arm apart from
    /// the trunk with as many crossings at a height, the envelope passes
    /// move the arm's vertices by the paired crossings (the fingers'
    /// edges, in order), blended over a few rows (default true).
    pub envelope_pairs: bool,
    /// Each envelope pass first moves the arm's vertices in depth and
    /// height so the fitted side outline's webs and fingertips land on the
    /// sketch's ([`super::envelope::feature_warp`]; default true). A pass
    /// that takes the front view past the tolerance is undone.
    pub envelope_features: bool,
    /// Each envelope pass first moves the face in height where the fitted
    /// side outline's front is a shelf off the sketch
    /// ([`super::envelope::shelf_warp`]).
    pub envelope_shelves: bool,
    /// Before each side pass, move the face in height so the fitted side
    /// outline's head landmarks (neck, chin, nose) sit at the sketch's
    /// ([`super::weights::remap_heights`]; default true). The medium
    /// level then measures the front view again.
    pub side_landmarks: bool,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions {
            front_centres: 400,
            side_centres: 160,
            section_points: 32,
            anchors: 240,
            gec_terms: 10,
            front_scheme: Scheme::Human,
            side_scheme: Scheme::Side,
            condition: true,
            tolerance: super::check::PROFILE_REL,
            passes: 3,
            on_miss: OnMiss::Fail,
            section_match: SectionMatch::Radial,
            band_anchors: 300,
            side_partner: SidePartner::Envelope,
            depth_map: DepthMap::Robust,
            depth_falloff: refine::DEPTH_FALLOFF,
            side_trunk: false,
            envelope_passes: 4,
            envelope_arms: true,
            envelope_arm_back: false,
            envelope_falloff: 2,
            envelope_pairs: true,
            envelope_features: true,
            envelope_shelves: true,
            side_landmarks: true,
        }
    }
}

/// A fitting level.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    Low,
    Medium,
    High,
}

impl Level {
    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Level::Low => "low",
            Level::Medium => "medium",
            Level::High => "high",
        }
    }
}

/// What one level did.
#[derive(Clone, Debug, serde::Serialize)]
pub struct LevelReport {
    pub level: Level,
    /// RBF centres of this level's interpolants (summed).
    pub centres: usize,
    /// Largest condition number among this level's RBF systems.
    pub condition: Option<f64>,
    /// Largest relative residual of this level's RBF solves.
    pub residual: f64,
    /// Largest displacement applied at this level.
    pub max_displacement: f64,
    /// Correction passes run after the level's first warp.
    pub passes: usize,
    /// The fitted outlines measured against the sketch after this level.
    pub profiles: Vec<ViewFit>,
    pub seconds: f64,
}

/// The result: positions of every template vertex after each level.
#[derive(Clone, Debug)]
pub struct FitResult {
    /// The front-view similarity that aligned the template to the sketch.
    pub alignment: Similarity,
    /// Depth centre the depth was scaled about.
    pub depth_centre: f64,
    pub levels: Vec<(LevelReport, Vec<[f64; 3]>)>,
}

impl FitResult {
    /// Positions after the last level.
    pub fn last(&self) -> &[[f64; 3]] {
        &self.levels.last().expect("fit always runs the low level").1
    }
}

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

/// Landmarks on both outlines, checked against each other.
pub fn matched_landmarks(
    view: View,
    scheme: Scheme,
    template: &[[f64; 2]],
    sketch: &[[f64; 2]],
) -> Result<(Vec<usize>, Vec<usize>), TemplateError> {
    let lt = landmarks::find(
        template,
        scheme,
        &format!("template {} outline", view.name()),
    )?;
    let ls = landmarks::find(sketch, scheme, &format!("sketched {} profile", view.name()))?;
    let (ft, fs) = (arc_fractions(template, &lt), arc_fractions(sketch, &ls));
    let names = scheme.names();
    for k in 0..ft.len() {
        let r = ft[k] / fs[k];
        if !(1.0 / ARC_RATIO_MAX..=ARC_RATIO_MAX).contains(&r) {
            return Err(TemplateError::LandmarkMismatch {
                view: view.name().into(),
                from: names[k].into(),
                to: names[(k + 1) % names.len()].into(),
                template: 100.0 * ft[k],
                sketch: 100.0 * fs[k],
            });
        }
    }
    Ok((lt, ls))
}

/// The crossing of the horizontal line at height `y` with the closed
/// polygon `p` nearest to `near`; `near` itself when the line misses it.
pub fn level_partner(p: &[[f64; 2]], y: f64, near: f64) -> f64 {
    let n = p.len();
    let mut best = near;
    let mut dist = f64::INFINITY;
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        if (a[1] - y) * (b[1] - y) > 0.0 || a[1] == b[1] {
            continue;
        }
        let t = (y - a[1]) / (b[1] - a[1]);
        let x = a[0] + t * (b[0] - a[0]);
        if (x - near).abs() < dist {
            dist = (x - near).abs();
            best = x;
        }
    }
    best
}

/// Largest [`FitOptions::envelope_falloff`] (a weight `s^k` is below
/// 0.004 at `s = 1/2` by then; a negative `k` would divide by a zero depth
/// weight).
pub const ENVELOPE_FALLOFF_MAX: i32 = 8;

/// Most [`FitOptions::envelope_passes`] (each re-extracts the fitted
/// outlines; the study's cases keep at most 4).
pub const ENVELOPE_PASSES_MAX: usize = 64;

/// Envelope correction passes ([`super::envelope::envelope_pass`]) while
/// the side view misses the tolerance, at most
/// [`FitOptions::envelope_passes`]; a pass that does not reduce the miss
/// is undone and ends them. Returns the passes kept.
fn envelope_passes(
    template: &Template,
    positions: &mut Vec<[f64; 3]>,
    side_err: &mut f64,
    front: &[[f64; 2]],
    side: &[[f64; 2]],
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<usize, TemplateError> {
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
    // the passes ask for outlines of unchanged skins again (super::memo)
    let memo = super::memo::OutlineMemo::new(outline);
    let remembered = |m: &Mesh, v: View| memo.outline(m, v);
    let outline: &OutlineFn = &remembered;
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
    let front = validated("the sketched front profile", &sketch.front)?;
    let side = match &sketch.side {
        Some(s) => Some(validated("the sketched side profile", s)?),
        None => None,
    };
    if !sketch.sections.is_empty() && side.is_none() {
        return Err(TemplateError::BadProfile {
            what: "the sketch".into(),
            problem: "key cross-sections (high level) need a side profile (medium level)".into(),
        });
    }
    let t_front = outline_of(outline, &template.skin, View::Front)?;
    let (lt, ls) = matched_landmarks(View::Front, opts.front_scheme, &t_front, &front)?;
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
    let (ca, cb) = correspond(&aligned_outline, &lt, &front, &ls, opts.front_centres);
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
    let mut front_err = refine::measure(template, &low, View::Front, &front, outline)?;
    let mut passes = 0;
    // correction passes while off; a pass that does not improve is undone
    while front_err > opts.tolerance && passes < opts.passes {
        let mut next = low.clone();
        refine::front_pass(template, &mut next, &front, opts, outline, &mut stats)?;
        let err = refine::measure(template, &next, View::Front, &front, outline)?;
        if err >= front_err {
            break;
        }
        (low, front_err) = (next, err);
        passes += 1;
    }
    let front_fit = refine::view_fit(View::Front, front_err, opts);
    refine::enforce(Level::Low, &[front_fit], passes, opts)?;
    let mut levels = vec![(
        LevelReport {
            level: Level::Low,
            centres: stats.centres,
            condition: stats.condition,
            residual: stats.residual,
            max_displacement: max_norm(&before, &low),
            passes,
            profiles: vec![front_fit],
            seconds: t0.elapsed().as_secs_f64(),
        },
        low,
    )];
    let done = |levels: Vec<(LevelReport, Vec<[f64; 3]>)>| FitResult {
        alignment: sim,
        depth_centre: zc,
        levels,
    };
    let Some(side) = side else {
        return Ok(done(levels));
    };
    // medium: depth (the envelope passes' hand features and shelves, and
    // the head's remap, also heights: the front view is measured again)
    let t1 = Instant::now();
    let low = &levels[0].1;
    let mut medium = low.clone();
    let mut stats = WarpStats::default();
    refine::side_pass(template, &mut medium, &side, opts, outline, &mut stats)?;
    let mut side_err = refine::measure(template, &medium, View::Side, &side, outline)?;
    let mut passes = 0;
    while side_err > opts.tolerance && passes < opts.passes {
        let mut next = medium.clone();
        refine::side_pass(template, &mut next, &side, opts, outline, &mut stats)?;
        let err = refine::measure(template, &next, View::Side, &side, outline)?;
        if err >= side_err {
            break;
        }
        (medium, side_err) = (next, err);
        passes += 1;
    }
    passes += envelope_passes(
        template,
        &mut medium,
        &mut side_err,
        &front,
        &side,
        opts,
        outline,
    )?;
    // the side landmarks, hand features and shelves move heights: the
    // front view again
    let front_fit = if opts.side_landmarks || opts.envelope_features || opts.envelope_shelves {
        let err = refine::measure(template, &medium, View::Front, &front, outline)?;
        refine::view_fit(View::Front, err, opts)
    } else {
        front_fit
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
    levels.push((rep, medium));
    if sketch.sections.is_empty() {
        return Ok(done(levels));
    }
    let t2 = Instant::now();
    let medium = &levels[1].1;
    let (rep, mut high) =
        sections::fit_sections(template, medium, &front, &side, &sketch.sections, opts)?;
    let mut side_err = refine::measure(template, &high, View::Side, &side, outline)?;
    let passes = envelope_passes(
        template,
        &mut high,
        &mut side_err,
        &front,
        &side,
        opts,
        outline,
    )?;
    let fits = vec![
        refine::view_fit(
            View::Front,
            refine::measure(template, &high, View::Front, &front, outline)?,
            opts,
        ),
        refine::view_fit(View::Side, side_err, opts),
    ];
    refine::enforce(Level::High, &fits, passes, opts)?;
    levels.push((
        LevelReport {
            passes,
            profiles: fits,
            seconds: t2.elapsed().as_secs_f64(),
            ..rep
        },
        high,
    ));
    Ok(done(levels))
}
