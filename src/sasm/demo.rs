//! The bundled examples of Fig 10 on the sketched female (data/sketch): a
//! breast on the torso from a closed curve plus a side and a top profile
//! (sketch on the model), and a nose on the head from an auxiliary line
//! plus the side profile. The strokes are drawn over the built model: the
//! breast's profiles are the host's outline over the region's chord in
//! their view (found by ray casting) plus a bump, as a user traces over the
//! model (the nose's, on the symmetry plane, is the host's section there).

use super::measure::{measure, SasmReport};
use super::project::Projector;
use super::{apply_feature, ApplyReport, AuxSpec, Feature, SasmError, SasmSpec, Stroke};
use crate::character::doc::Level;
use crate::character::part::PartSurface;
use crate::character::Resolution;
use crate::mesh::Mesh;
use crate::pipeline::build_document;
use crate::profile::View;
use crate::sketch::check::bundled;
use std::f64::consts::PI;

/// Stroke points per curve.
const N: usize = 64;

/// The female before and after, and the measurements.
pub struct Fig10 {
    pub before: Mesh,
    pub after: Mesh,
    pub breast_spec: SasmSpec,
    pub nose_spec: AuxSpec,
    pub breast: SasmReport,
    pub nose: SasmReport,
    pub applied: Vec<ApplyReport>,
}

fn host_depth(pr: &Projector, q: [f64; 2]) -> Result<f64, SasmError> {
    pr.cast(q).map(|h| h.point[2]).ok_or(SasmError::Misses {
        what: "demo stroke".into(),
        part: pr.part.name.clone(),
        view: View::Front,
        index: 0,
        at: q,
    })
}

/// The host's outline over a chord of the region: its greatest depth at
/// `OUTLINE_SAMPLES` points `q + k e_axis`, `|k| <= half` (a user tracing
/// a profile over the model in a side or top view sees the host's
/// outline, not its section through the centre).
fn outline(pr: &Projector, q: [f64; 2], axis: usize, half: f64) -> Result<f64, SasmError> {
    let mut best = host_depth(pr, q)?;
    for k in 0..OUTLINE_SAMPLES {
        let mut p = q;
        p[axis] += half * (2.0 * k as f64 / (OUTLINE_SAMPLES - 1) as f64 - 1.0);
        if let Some(h) = pr.cast(p) {
            best = best.max(h.point[2]);
        }
    }
    Ok(best)
}

/// Chord samples of [`outline`].
const OUTLINE_SAMPLES: usize = 33;

/// The breast (right of the viewer, model +x) on the torso.
///
/// The strokes are drawn on the drawing (in its metres, feet where the
/// drawing has them); `lift` is the height the build moved the drawing by
/// to stand it on y = 0 (`drawing.placement.front_shift[1]`), so the
/// strokes move with the drawing.
pub fn breast(torso: &PartSurface, lift: f64) -> Result<SasmSpec, SasmError> {
    let pr = Projector::new(torso, View::Front);
    let (cx, cy, rx, ry, h) = (0.066, 1.075 + lift, 0.044, 0.045, 0.028);
    let curve: Vec<[f64; 2]> = (0..=N)
        .map(|i| {
            let t = 2.0 * PI * i as f64 / N as f64;
            [
                cx + rx * t.cos(),
                cy + ry * t.sin() * (1.0 - 0.15 * t.sin()),
            ]
        })
        .collect();
    // side profile: fuller below the centre
    let mut side = Vec::new();
    for i in 0..=N {
        let y = cy + 0.05 - 0.1 * i as f64 / N as f64;
        let t = ((y - cy) / 0.045).clamp(-1.0, 1.0);
        let shape = if t > 0.0 {
            (1.0 - t * t).powi(2)
        } else {
            (1.0 - t * t).sqrt() * (1.0 - t * t)
        };
        side.push([
            outline(&pr, [cx, y], 0, rx * (1.0 - t * t).max(0.0).sqrt())? + h * shape,
            y,
        ]);
    }
    let mut top = Vec::new();
    for i in 0..=N {
        let x = cx - 0.042 + 0.084 * i as f64 / N as f64;
        let t = ((x - cx) / 0.044).clamp(-1.0, 1.0);
        let half = ry * (1.0 - t * t).max(0.0).sqrt();
        top.push([
            x,
            outline(&pr, [x, cy], 1, half)? + h * (1.0 - t * t).powi(2),
        ]);
    }
    Ok(SasmSpec {
        part: torso.name.clone(),
        curve: Stroke {
            view: View::Front,
            points: curve,
        },
        profiles: vec![
            Stroke {
                view: View::Side,
                points: side,
            },
            Stroke {
                view: View::Top,
                points: top,
            },
        ],
    })
}

/// The nose on the head: the right half of its interface and the side
/// profile along the symmetry plane x = 0 (`lift` as in [`breast`]).
pub fn nose(head: &PartSurface, lift: f64) -> Result<AuxSpec, SasmError> {
    let pr = Projector::new(head, View::Front);
    let (top, tip, bottom, w) = (1.605 + lift, 1.553 + lift, 1.535 + lift, 0.019);
    let line: Vec<[f64; 2]> = (0..=N)
        .map(|i| {
            let t = i as f64 / N as f64;
            let y = top + (bottom - top) * t;
            // narrow at the bridge, widest at the wings
            let x = w * (PI * t).sin().sqrt() * (0.45 + 0.55 * t);
            [x, y]
        })
        .collect();
    let mut prof = Vec::new();
    for i in 0..=N {
        let y = top + 0.005 + (bottom - 0.004 - top - 0.005) * i as f64 / N as f64;
        let bump = if y >= tip {
            0.022 * ((top - y) / (top - tip)).clamp(0.0, 1.0).powf(1.3)
        } else {
            0.022 * ((y - bottom) / (tip - bottom)).clamp(0.0, 1.0).sqrt()
        };
        prof.push([host_depth(&pr, [0.0, y])? + bump, y]);
    }
    Ok(AuxSpec {
        part: head.name.clone(),
        line: Stroke {
            view: View::Front,
            points: line,
        },
        mirror: 0.0,
        profile: Stroke {
            view: View::Side,
            points: prof,
        },
    })
}

/// Why [`female_fig10`] failed: the bundled female did not build, or a
/// SASM step failed.
#[derive(Debug, thiserror::Error)]
pub enum Fig10Error {
    #[error("the bundled female does not parse")]
    Bundled,
    #[error("building the bundled female: {0}")]
    Build(#[source] Box<crate::pipeline::BuildError>),
    #[error(transparent)]
    Sasm(#[from] SasmError),
}

/// Builds the female (final level), applies the breast and the nose, and
/// measures both.
pub fn female_fig10() -> Result<Fig10, Fig10Error> {
    let doc = bundled("female", Level::Final).ok_or(Fig10Error::Bundled)?;
    let b = build_document(&doc, std::path::Path::new("."), Resolution::default(), true)
        .map_err(|e| Fig10Error::Build(Box::new(e)))?;
    let part = |n: &str| {
        b.model
            .parts
            .iter()
            .find(|p| p.name == n)
            .ok_or_else(|| SasmError::UnknownPart(n.into()))
    };
    let (torso, head) = (part("torso")?, part("head")?);
    let lift = b.report.drawing.placement.front_shift[1];
    let breast_spec = breast(torso, lift)?;
    let nose_spec = nose(head, lift)?;
    let fb = Feature::from_spec(torso, &breast_spec)?;
    let fnose = Feature::from_aux(head, &nose_spec)?;
    let before = b.model.mesh.clone();
    let mut mid = before.clone();
    let a1 = apply_feature(&mut mid, torso, &fb)?;
    let breast_r = measure(&before, &mid, torso, &fb)?;
    let mut after = mid.clone();
    let a2 = apply_feature(&mut after, head, &fnose)?;
    let nose_r = measure(&mid, &after, head, &fnose)?;
    Ok(Fig10 {
        before,
        after,
        breast_spec,
        nose_spec,
        breast: breast_r,
        nose: nose_r,
        applied: vec![a1, a2],
    })
}
