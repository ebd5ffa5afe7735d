//! The study (issue 12, 000 Fig 7 analogue): MakeHuman's own morph targets
//! are artist-made ground truth for template fitting. For each case the
//! template (a young average male or female) is fitted to profiles
//! extracted from the morphed body, at each level, and compared vertex by
//! vertex with that body, beside the template scaled to the sketch's
//! bounding box.

use super::fit::{fit, FitOptions, Level, Sketch, Template};
use super::measure::{bbox_baseline, mesh_outline, profile_errors_with, vertex_errors, ViewError};
use super::sections::SectionSketch;
use super::{TemplateError, View};
use crate::makehuman;
use crate::mesh::slice::slice;
use crate::mesh::Mesh;

/// Heights of the key cross-sections, as fractions of the body's height
/// from its lowest point (lower belly, belly, waist, chest). The two lowest
/// cut the underside of a pregnant belly (0.50-0.56 on the side outline):
/// with the lowest at 0.56 the medium level's full-width depth push stayed
/// there (README, `000-fig7`).
pub const SECTION_HEIGHTS: [f64; 6] = [0.51, 0.535, 0.56, 0.61, 0.66, 0.72];

/// One study case: template targets and the morphed body's targets.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    pub name: &'static str,
    pub template: &'static [&'static str],
    pub target: &'static [&'static str],
}

const MALE: &[&str] = &[
    "caucasian-male-young",
    "universal-male-young-averagemuscle-averageweight",
];
const FEMALE: &[&str] = &[
    "caucasian-female-young",
    "universal-female-young-averagemuscle-averageweight",
];

/// The cases: male and female into fat, child, old; female into pregnant.
pub const CASES: &[Case] = &[
    Case {
        name: "male->fat",
        template: MALE,
        target: &[
            "caucasian-male-young",
            "universal-male-young-averagemuscle-maxweight",
        ],
    },
    Case {
        name: "male->boy",
        template: MALE,
        target: &[
            "caucasian-male-child",
            "universal-male-child-averagemuscle-averageweight",
        ],
    },
    Case {
        name: "male->old",
        template: MALE,
        target: &[
            "caucasian-male-old",
            "universal-male-old-averagemuscle-averageweight",
        ],
    },
    Case {
        name: "female->fat",
        template: FEMALE,
        target: &[
            "caucasian-female-young",
            "universal-female-young-averagemuscle-maxweight",
        ],
    },
    Case {
        name: "female->girl",
        template: FEMALE,
        target: &[
            "caucasian-female-child",
            "universal-female-child-averagemuscle-averageweight",
        ],
    },
    Case {
        name: "female->old",
        template: FEMALE,
        target: &[
            "caucasian-female-old",
            "universal-female-old-averagemuscle-averageweight",
        ],
    },
    Case {
        name: "female->pregnant",
        template: FEMALE,
        target: &[
            "caucasian-female-young",
            "universal-female-young-averagemuscle-averageweight",
            "stomach-pregnant-incr",
        ],
    },
];

fn targets(names: &[&str]) -> Result<Vec<(makehuman::Target, f64)>, TemplateError> {
    names
        .iter()
        .map(|n| Ok((makehuman::target(n)?, 1.0)))
        .collect()
}

/// The MakeHuman template: every `v` of the base OBJ with `names` applied;
/// the skin is the `body` group.
pub fn makehuman_template(names: &[&str]) -> Result<Template, TemplateError> {
    let ts = targets(names)?;
    let mut mesh = makehuman::base_mesh()?;
    for (t, w) in &ts {
        for &(i, d) in &t.offsets {
            if let Some(p) = mesh.positions.get_mut(i as usize) {
                for k in 0..3 {
                    p[k] += w * d[k];
                }
            }
        }
    }
    let (skin, skin_index) = mesh.group_submesh("body").ok_or_else(|| {
        TemplateError::Mesh(crate::mesh::MeshError::Invalid(
            "base.obj has no 'body' group".into(),
        ))
    })?;
    Ok(Template {
        mesh,
        skin,
        skin_index,
    })
}

/// The torso loop (largest area) of `m` cut at height `y`, as `(x, z)`.
pub fn torso_section(m: &Mesh, y: f64) -> Option<Vec<[f64; 2]>> {
    slice(m, [0.0, y, 0.0], [0.0, 1.0, 0.0])
        .into_iter()
        .filter(|l| l.closed && l.points.len() >= 8)
        .map(|l| {
            l.points
                .iter()
                .map(|p| [p[0], p[2]])
                .collect::<Vec<[f64; 2]>>()
        })
        .max_by(|a, b| {
            super::polygon::signed_area(a)
                .abs()
                .total_cmp(&super::polygon::signed_area(b).abs())
        })
}

/// The sketch a user would draw of `m`: its front and side outlines and its
/// torso sections at [`SECTION_HEIGHTS`].
pub fn sketch_of(m: &Mesh) -> Result<Sketch, TemplateError> {
    let front = mesh_outline(m, View::Front)?;
    let side = mesh_outline(m, View::Side)?;
    let (lo, hi) = super::polygon::bbox(&front);
    let sections = SECTION_HEIGHTS
        .iter()
        .filter_map(|f| {
            let y = lo[1] + f * (hi[1] - lo[1]);
            torso_section(m, y)
                .filter(|l| super::polygon::validated("torso section", l).is_ok())
                .map(|l| SectionSketch { y, loops: vec![l] })
        })
        .collect();
    Ok(Sketch {
        front,
        side: Some(side),
        sections,
    })
}

/// One row of the study.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Row {
    pub case: String,
    /// `"bbox"`, `"low"`, `"medium"`, `"high"`.
    pub method: String,
    /// RMS and max vertex distance to the target, relative to its height.
    pub rms_rel: f64,
    pub max_rel: f64,
    pub profiles: Vec<ViewError>,
    /// Creases ([`super::measure::crease`], radians) on the front of the
    /// lower belly and of the face ([`CREASE_REGIONS`]).
    pub creases: [f64; 2],
    pub seconds: f64,
}

/// Crease regions, by the template's skin at rest: the trunk's front half
/// (depth beyond the trunk's mean depth at the vertex's height,
/// [`trunk_depth`]) between two fractions of the height and within a
/// half-width (fraction of the height) of the middle in x (no hands, no
/// arms).
pub const CREASE_REGIONS: [(&str, f64, f64, f64); 2] =
    [("belly", 0.50, 0.62, 0.07), ("face", 0.87, 1.0, 0.04)];

/// Height bins of [`trunk_depth`].
pub const DEPTH_BINS: usize = 100;

/// The trunk's mean depth per height bin ([`DEPTH_BINS`] over the skin's
/// height): the mean z of the skin's vertices at rest, arms left out
/// ([`super::refine::arm_mask`] on the template; every vertex when the
/// arms are not found); an empty bin takes the nearest filled one. The
/// middle of the whole body's depth range is no reference for "front":
/// MakeHuman's hands (and toes) reach in front of the belly, so the
/// middle of the bounding box lies in front of it.
pub fn trunk_depth(template: &Template) -> Vec<f64> {
    let rest = &template.skin;
    let (lo, hi) = rest.bbox();
    let h = (hi[1] - lo[1]).max(f64::MIN_POSITIVE);
    let arms = super::outlines::arm_mask(
        template,
        &template.mesh.positions,
        &FitOptions::default(),
        &mesh_outline,
    );
    let is_arm = |i: usize| {
        arms.as_ref()
            .is_some_and(|a| a[template.skin_index[i] as usize])
    };
    let (mut sum, mut count) = (vec![0.0; DEPTH_BINS], vec![0usize; DEPTH_BINS]);
    for (i, p) in rest.positions.iter().enumerate() {
        if is_arm(i) {
            continue;
        }
        let b = depth_bin(p[1], lo[1], h);
        sum[b] += p[2];
        count[b] += 1;
    }
    (0..DEPTH_BINS)
        .map(|b| {
            (0..DEPTH_BINS)
                .flat_map(|d| [b.checked_sub(d), Some(b + d)])
                .flatten()
                .find(|&j| count.get(j).is_some_and(|&c| c > 0))
                .map_or(0.5 * (lo[2] + hi[2]), |j| sum[j] / count[j] as f64)
        })
        .collect()
}

fn depth_bin(y: f64, lo: f64, h: f64) -> usize {
    (((y - lo) / h * DEPTH_BINS as f64).max(0.0) as usize).min(DEPTH_BINS - 1)
}

/// The skin vertices (at rest) in each of [`CREASE_REGIONS`].
pub fn crease_regions(template: &Template) -> [Vec<bool>; 2] {
    let rest = &template.skin;
    let (lo, hi) = rest.bbox();
    let xc = 0.5 * (lo[0] + hi[0]);
    let h = (hi[1] - lo[1]).max(f64::MIN_POSITIVE);
    let depth = trunk_depth(template);
    CREASE_REGIONS.map(|(_, a, b, w)| {
        rest.positions
            .iter()
            .map(|p| {
                let f = (p[1] - lo[1]) / h;
                p[2] > depth[depth_bin(p[1], lo[1], h)]
                    && f >= a
                    && f <= b
                    && (p[0] - xc).abs() < w * h
            })
            .collect()
    })
}

/// The creases of `positions` (every template vertex) over the template at
/// rest, per [`CREASE_REGIONS`].
pub fn creases(template: &Template, positions: &[[f64; 3]]) -> [f64; 2] {
    creases_of(template, &crease_regions(template), positions)
}

/// [`creases`] with the regions ([`crease_regions`]) given.
pub fn creases_of(
    template: &Template,
    regions: &[Vec<bool>; 2],
    positions: &[[f64; 3]],
) -> [f64; 2] {
    let c = super::measure::creases_in(
        &template.skin,
        &template.skin_at(positions),
        &[&regions[0], &regions[1]],
    );
    [c[0], c[1]]
}

/// A case's rows and the positions of the template and of every level.
pub type CaseResult = (Vec<Row>, Vec<Vec<[f64; 3]>>);

/// Runs one case: the bounding-box baseline, then every level.
/// A case's MakeHuman target: the base body with the case's targets
/// applied (weight 1).
pub fn target_mesh(case: &Case) -> Result<Mesh, TemplateError> {
    Ok(makehuman::body(&targets(case.target)?)?.mesh)
}

pub fn run_case(case: &Case, opts: &FitOptions) -> Result<CaseResult, TemplateError> {
    let template = makehuman_template(case.template)?;
    let target = target_mesh(case)?;
    let sketch = sketch_of(&target)?;
    let (lo, hi) = super::polygon::bbox(&sketch.front);
    let h = hi[1] - lo[1];
    let skin_of = |pos: &[[f64; 3]]| template.skin_at(pos).positions;
    let bb = bbox_baseline(&template, &sketch);
    let regions = crease_regions(&template);
    let creases = |pos: &[[f64; 3]]| creases_of(&template, &regions, pos);
    let memo = super::memo::OutlineMemo::new(&mesh_outline);
    let outline = |m: &Mesh, v: View| memo.outline(m, v);
    let profile_errors = |pos: &[[f64; 3]]| profile_errors_with(&template, pos, &sketch, &outline);
    let (rms, mx) = vertex_errors(&skin_of(&bb), &target.positions, h);
    let mut rows = vec![Row {
        case: case.name.into(),
        method: "bbox".into(),
        rms_rel: rms,
        max_rel: mx,
        profiles: profile_errors(&bb)?,
        creases: creases(&bb),
        seconds: 0.0,
    }];
    let r = fit(&template, &sketch, opts, &outline)?;
    let mut meshes = vec![template.mesh.positions.clone()];
    for (rep, pos) in &r.levels {
        let (rms, mx) = vertex_errors(&skin_of(pos), &target.positions, h);
        rows.push(Row {
            case: case.name.into(),
            method: match rep.level {
                Level::Low => "low",
                Level::Medium => "medium",
                Level::High => "high",
            }
            .into(),
            rms_rel: rms,
            max_rel: mx,
            profiles: profile_errors(pos)?,
            creases: creases(pos),
            seconds: rep.seconds,
        });
        meshes.push(pos.clone());
    }
    // the target itself (its own creases over the template: the ground
    // truth's sharpening, e.g. a pregnant belly's underside)
    let mut tpos = template.mesh.positions.clone();
    for (p, &i) in target.positions.iter().zip(&template.skin_index) {
        tpos[i as usize] = *p;
    }
    rows.push(Row {
        case: case.name.into(),
        method: "target".into(),
        rms_rel: 0.0,
        max_rel: 0.0,
        profiles: Vec::new(),
        creases: creases(&tpos),
        seconds: 0.0,
    });
    Ok((rows, meshes))
}
