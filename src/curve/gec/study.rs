//! The curve-fitting study on real cross sections (paper 002 Table 1 and
//! paper 000 Fig 3 analogues) on the bundled MakeHuman body.
//!
//! Sections: the torso at five heights, the neck and the head cut by
//! horizontal planes (Y is up); the right upper arm, forearm, thigh and calf
//! cut perpendicular to the limb axis. The body is in the A-pose, so the
//! limb axis is estimated from the mesh: the skin vertices in a box around
//! the limb segment are split at the box's middle height and the axis is the
//! difference of the two halves' centroids. The plane passes through the
//! centroid of the box's vertices; of the polylines it cuts, the closed one
//! whose centroid is nearest to that point is the section.

use super::correct::Correction;
use super::fit::{fit, FitOptions, FitReport, Param};
use super::{Frame, Gec, GecError};
use crate::mesh::slice::slice;
use crate::mesh::{dist, norm, scale, sub, Mesh};

/// A named cross section of the body.
#[derive(Clone, Debug)]
pub struct BodySection {
    pub name: String,
    pub origin: [f64; 3],
    pub normal: [f64; 3],
    /// The closed polyline (no repeated closing point).
    pub points: Vec<[f64; 3]>,
}

/// How a section is located.
#[derive(Clone, Copy, Debug)]
pub enum Locator {
    /// Horizontal plane at height `y`, polyline nearest to `(x, z)`.
    Horizontal { y: f64, x: f64, z: f64 },
    /// A limb: skin vertices with `x` in `xr` and `y` in `yr`.
    Limb { xr: [f64; 2], yr: [f64; 2] },
}

/// The study's sections: `(name, locator)`.
pub const SECTIONS: &[(&str, Locator)] = &[
    (
        "torso_hips",
        Locator::Horizontal {
            y: 0.5,
            x: 0.0,
            z: 0.2,
        },
    ),
    (
        "torso_waist",
        Locator::Horizontal {
            y: 2.0,
            x: 0.0,
            z: 0.3,
        },
    ),
    (
        "torso_lower_chest",
        Locator::Horizontal {
            y: 3.0,
            x: 0.0,
            z: 0.4,
        },
    ),
    (
        "torso_chest",
        Locator::Horizontal {
            y: 3.6,
            x: 0.0,
            z: 0.4,
        },
    ),
    (
        "torso_upper_chest",
        Locator::Horizontal {
            y: 4.1,
            x: 0.0,
            z: 0.4,
        },
    ),
    (
        "neck",
        Locator::Horizontal {
            y: 6.0,
            x: 0.0,
            z: 0.2,
        },
    ),
    (
        "head",
        Locator::Horizontal {
            y: 7.5,
            x: 0.0,
            z: 0.6,
        },
    ),
    (
        "upper_arm",
        Locator::Limb {
            xr: [2.0, 4.0],
            yr: [3.2, 4.2],
        },
    ),
    (
        "forearm",
        Locator::Limb {
            xr: [2.5, 5.0],
            yr: [2.3, 3.0],
        },
    ),
    (
        "thigh",
        Locator::Limb {
            xr: [0.2, 2.5],
            yr: [-3.5, -1.8],
        },
    ),
    (
        "calf",
        Locator::Limb {
            xr: [0.2, 2.5],
            yr: [-6.3, -5.0],
        },
    ),
];

fn centroid(p: &[[f64; 3]]) -> [f64; 3] {
    let n = p.len().max(1) as f64;
    let mut c = [0.0; 3];
    for q in p {
        for k in 0..3 {
            c[k] += q[k] / n;
        }
    }
    c
}

/// Plane `(origin, unit normal)` for a locator.
pub fn plane(mesh: &Mesh, loc: Locator) -> Result<([f64; 3], [f64; 3]), GecError> {
    match loc {
        Locator::Horizontal { y, x, z } => Ok(([x, y, z], [0.0, 1.0, 0.0])),
        Locator::Limb { xr, yr } => {
            let inside: Vec<[f64; 3]> = mesh
                .positions
                .iter()
                .copied()
                .filter(|p| p[0] >= xr[0] && p[0] <= xr[1] && p[1] >= yr[0] && p[1] <= yr[1])
                .collect();
            let mid = 0.5 * (yr[0] + yr[1]);
            let (hi, lo): (Vec<[f64; 3]>, Vec<[f64; 3]>) = inside.iter().partition(|p| p[1] > mid);
            if hi.len() < 8 || lo.len() < 8 {
                return Err(GecError::Degenerate(format!(
                    "limb box {xr:?} x {yr:?} holds too few vertices"
                )));
            }
            let axis = sub(centroid(&hi), centroid(&lo));
            let n = norm(axis);
            if n.is_nan() || n <= 0.0 {
                return Err(GecError::Degenerate("limb axis has zero length".into()));
            }
            Ok((centroid(&inside), scale(axis, 1.0 / n)))
        }
    }
}

/// Cuts one section.
pub fn cut(mesh: &Mesh, name: &str, loc: Locator) -> Result<BodySection, GecError> {
    let (origin, normal) = plane(mesh, loc)?;
    let best = slice(mesh, origin, normal)
        .into_iter()
        .filter(|p| p.closed && p.points.len() >= 8)
        .min_by(|a, b| dist(a.centroid(), origin).total_cmp(&dist(b.centroid(), origin)))
        .ok_or_else(|| GecError::Degenerate(format!("no closed section for {name}")))?;
    Ok(BodySection {
        name: name.into(),
        origin,
        normal,
        points: best.points,
    })
}

/// All study sections of `mesh` (the MakeHuman skin).
pub fn sections(mesh: &Mesh) -> Result<Vec<BodySection>, GecError> {
    SECTIONS.iter().map(|(n, l)| cut(mesh, n, *l)).collect()
}

/// Why the base body's sections could not be taken: the bundled body did
/// not load, or a section could not be cut from it.
#[derive(Debug, thiserror::Error)]
pub enum BaseSectionsError {
    #[error("the bundled MakeHuman body: {0}")]
    Body(#[from] crate::mesh::MeshError),
    #[error(transparent)]
    Section(#[from] GecError),
}

/// The study's sections of the base body.
pub fn base_sections() -> Result<Vec<BodySection>, BaseSectionsError> {
    let body = crate::makehuman::base_body()?;
    Ok(sections(&body.mesh)?)
}

/// The term counts of paper 002 Table 1.
pub const TABLE1_TERMS: [usize; 5] = [1, 3, 5, 7, 10];

/// One row of the study: a section fitted with J terms and a parameter.
#[derive(Clone, Debug, serde::Serialize)]
pub struct StudyRow {
    pub section: String,
    pub terms: usize,
    pub param: &'static str,
    pub points: usize,
    pub erm: f64,
    pub era: f64,
    pub erm_rel: f64,
    pub era_rel: f64,
    pub hausdorff_rel: f64,
}

/// Fits every section with every J and parameter rule, each rule's angles
/// as they are ([`Correction::None`]: this compares the rules; the default
/// fit, which corrects and chooses, is [`correction_study`]'s `after`).
pub fn run(
    secs: &[BodySection],
    terms: &[usize],
    params: &[Param],
) -> Result<Vec<StudyRow>, GecError> {
    let mut rows = Vec::new();
    for s in secs {
        for &j in terms {
            for &p in params {
                let r = fit(
                    &s.points,
                    &FitOptions {
                        param: p,
                        correction: Correction::None,
                        ..FitOptions::new(j)
                    },
                )?;
                rows.push(row(s, j, p, &r));
            }
        }
    }
    Ok(rows)
}

fn row(s: &BodySection, j: usize, p: Param, r: &FitReport) -> StudyRow {
    StudyRow {
        section: s.name.clone(),
        terms: j,
        param: p.name(),
        points: s.points.len(),
        erm: r.errors.erm,
        era: r.errors.era,
        erm_rel: r.errors.erm_rel,
        era_rel: r.errors.era_rel,
        hausdorff_rel: r.errors.hausdorff_rel,
    }
}

/// The best standard ellipse in the sense of paper 000 Fig 3: the J = 1 GEC
/// reduced to its principal axes (the least-squares J = 1 fit is a general
/// ellipse; here it is returned as `(a cos, b sin)` about its centre in a
/// rotated frame).
pub fn standard_ellipse(g1: &Gec) -> Gec {
    // P(t) - c = C cos t + S sin t with C = (ax, by), S = (bx, ay)
    let (cx, cy) = (g1.x[0][0], g1.y[0][1]);
    let (sx, sy) = (g1.x[0][1], g1.y[0][0]);
    // phase shift t0 making C' and S' orthogonal
    let t0 = 0.5 * (2.0 * (cx * sx + cy * sy)).atan2(cx * cx + cy * cy - sx * sx - sy * sy);
    let (s0, c0) = t0.sin_cos();
    let u = [cx * c0 + sx * s0, cy * c0 + sy * s0];
    let w = [-cx * s0 + sx * c0, -cy * s0 + sy * c0];
    let (a, b) = (u[0].hypot(u[1]), w[0].hypot(w[1]));
    let f = &g1.frame;
    let e1 = if a > 0.0 {
        [
            (u[0] * f.e1[0] + u[1] * f.e2[0]) / a,
            (u[0] * f.e1[1] + u[1] * f.e2[1]) / a,
            (u[0] * f.e1[2] + u[1] * f.e2[2]) / a,
        ]
    } else {
        f.e1
    };
    let e2 = crate::surface::cross(f.normal(), e1);
    let orient = if u[0] * w[1] - u[1] * w[0] < 0.0 {
        -1.0
    } else {
        1.0
    };
    let frame = Frame {
        origin: f.place(g1.centre[0], g1.centre[1]),
        e1,
        e2,
    };
    Gec::ellipse(frame, [0.0, 0.0], a, orient * b)
}

/// The silhouette ellipse of paper 000's intermediate models: axis-aligned
/// in the section's frame, centred on the in-plane bounding box, semi-axes
/// half its width and depth.
pub fn silhouette_ellipse(frame: Frame, plane_points: &[[f64; 2]]) -> Gec {
    let (lo, hi) = crate::polygon::bbox(plane_points);
    Gec::ellipse(
        frame,
        [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])],
        0.5 * (hi[0] - lo[0]),
        0.5 * (hi[1] - lo[1]),
    )
}

/// One section at one J fitted with and without parameter correction
/// ([`super::correct`]), the same parameter rule.
#[derive(Clone, Debug, serde::Serialize)]
pub struct CorrectionRow {
    pub section: String,
    pub terms: usize,
    pub param: &'static str,
    /// ErM, ErA (data units) without correction.
    pub erm_before: f64,
    pub era_before: f64,
    /// ErM, ErA with correction (the default fit).
    pub erm_after: f64,
    pub era_after: f64,
    /// The section's in-plane diagonal D.
    pub scale: f64,
    /// Correction step of the returned fit (0: the rule's angles kept).
    pub steps: usize,
}

/// Fits every section with every J under `param`, without and with
/// parameter correction.
pub fn correction_study(
    secs: &[BodySection],
    terms: &[usize],
    param: Param,
) -> Result<Vec<CorrectionRow>, GecError> {
    let mut rows = Vec::new();
    for s in secs {
        for &j in terms {
            let opts = FitOptions {
                param,
                ..FitOptions::new(j)
            };
            let before = fit(
                &s.points,
                &FitOptions {
                    correction: Correction::None,
                    ..opts
                },
            )?;
            let after = fit(&s.points, &opts)?;
            rows.push(CorrectionRow {
                section: s.name.clone(),
                terms: j,
                param: param.name(),
                erm_before: before.errors.erm,
                era_before: before.errors.era,
                erm_after: after.errors.erm,
                era_after: after.errors.era,
                scale: before.errors.scale,
                steps: after.correction_steps,
            });
        }
    }
    Ok(rows)
}
