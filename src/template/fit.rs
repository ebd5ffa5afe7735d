//! The three levels of template-based global modeling (000 secs 4.2.1-4.2.3).

use super::landmarks::{self, arc_fractions, correspond, Scheme, Similarity};
use super::polygon::{bbox, validated};
use super::rbf::Rbf;
use super::sections::{self, SectionSketch};
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

fn max_norm(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(p, q)| {
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
        })
        .fold(0.0, f64::max)
}

/// Fits the template to the sketch: the low level always, the medium level
/// when the sketch has a side profile, the high level when it also has key
/// cross-sections. `outline` gives a mesh's outline in a view.
pub fn fit(
    template: &Template,
    sketch: &Sketch,
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<FitResult, TemplateError> {
    let t0 = Instant::now();
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
    let values: Vec<[f64; 2]> = ca
        .iter()
        .zip(&cb)
        .map(|(a, b)| [b[0] - a[0], b[1] - a[1]])
        .collect();
    let warp =
        Rbf::<2, 2>::fit(&ca, &values, opts.condition).map_err(|source| TemplateError::Rbf {
            stage: "front warp",
            source,
        })?;
    let before: Vec<[f64; 3]> = template
        .mesh
        .positions
        .iter()
        .map(|p| {
            let q = sim.apply([p[0], p[1]]);
            [q[0], q[1], sim.scale * (p[2] - zc) + zc]
        })
        .collect();
    let low: Vec<[f64; 3]> = before
        .iter()
        .map(|p| {
            let d = warp.eval(&[p[0], p[1]]);
            [p[0] + d[0], p[1] + d[1], p[2]]
        })
        .collect();
    let mut levels = vec![(
        LevelReport {
            level: Level::Low,
            centres: warp.len(),
            condition: warp.condition,
            residual: warp.residual,
            max_displacement: max_norm(&before, &low),
            seconds: t0.elapsed().as_secs_f64(),
        },
        low,
    )];
    let Some(side) = side else {
        return Ok(FitResult {
            alignment: sim,
            depth_centre: zc,
            levels,
        });
    };
    // medium: depth only, from the side outline of the low-level model
    let t1 = Instant::now();
    let low = &levels[0].1;
    let low_skin = template.skin_at(low);
    let l_side = outline_of(outline, &low_skin, View::Side)?;
    let (lt, ls) = matched_landmarks(View::Side, opts.side_scheme, &l_side, &side)?;
    let (ca, cb) = correspond(&l_side, &lt, &side, &ls, opts.side_centres);
    // depth only: where the low outline is steep (|dy/ds| >= STEEP) the
    // partner is the sketch's crossing of the same height nearest to the
    // arc-length partner; on shallow stretches (soles, the top of the head,
    // under a belly) the arc-length partner's depth
    let m = ca.len();
    let values: Vec<[f64; 1]> = (0..m)
        .map(|i| {
            let (a, b) = (ca[i], cb[i]);
            let (p, q) = (ca[(i + m - 1) % m], ca[(i + 1) % m]);
            let len = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2))
                .sqrt()
                .max(f64::MIN_POSITIVE);
            let z = if ((q[1] - p[1]) / len).abs() >= STEEP {
                level_partner(&side, a[1], b[0])
            } else {
                b[0]
            };
            [z - a[0]]
        })
        .collect();
    let depth =
        Rbf::<2, 1>::fit(&ca, &values, opts.condition).map_err(|source| TemplateError::Rbf {
            stage: "side depth warp",
            source,
        })?;
    let medium: Vec<[f64; 3]> = low
        .iter()
        .map(|p| [p[0], p[1], p[2] + depth.eval(&[p[2], p[1]])[0]])
        .collect();
    let rep = LevelReport {
        level: Level::Medium,
        centres: depth.len(),
        condition: depth.condition,
        residual: depth.residual,
        max_displacement: max_norm(low, &medium),
        seconds: t1.elapsed().as_secs_f64(),
    };
    levels.push((rep, medium));
    if sketch.sections.is_empty() {
        return Ok(FitResult {
            alignment: sim,
            depth_centre: zc,
            levels,
        });
    }
    let t2 = Instant::now();
    let medium = &levels[1].1;
    let (rep, high) =
        sections::fit_sections(template, medium, &front, &side, &sketch.sections, opts)?;
    levels.push((
        LevelReport {
            seconds: t2.elapsed().as_secs_f64(),
            ..rep
        },
        high,
    ));
    Ok(FitResult {
        alignment: sim,
        depth_centre: zc,
        levels,
    })
}
