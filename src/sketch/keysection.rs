//! Key cross-section sketches (paper 000 sec 4.1.3, Fig 6h): a closed curve
//! in the horizontal plane at a height of a part, fitted by a GEC
//! (`curve::gec::fit`) that replaces the part's section nearest that height.

use super::SketchError;
use crate::character::doc::{KeySection, PartSpec, SectionShape};
use crate::curve::gec::Frame;

/// GEC terms for key cross-section sketches.
pub const GEC_TERMS: usize = 6;
/// How far a key section may reach beyond its part's width (relative).
pub const SECTION_SLACK: f64 = 0.15;

/// Fits a key cross-section sketch and puts it in place of the nearest
/// section of its part.
pub fn apply_key_section(parts: &mut [PartSpec], k: &KeySection) -> Result<(), SketchError> {
    let part = parts
        .iter_mut()
        .find(|p| p.name == k.part)
        .ok_or_else(|| SketchError::Section(format!("unknown part '{}'", k.part)))?;
    let ys: Vec<f64> = part.sections.iter().map(|s| s.centre[1]).collect();
    let (lo, hi) = ys
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| {
            (a.min(y), b.max(y))
        });
    if !(k.y > lo && k.y < hi) {
        return Err(SketchError::Section(format!(
            "section of '{}' at y = {} is outside the part (y from {lo:.4} to {hi:.4})",
            k.part, k.y
        )));
    }
    let (j, _) = ys
        .iter()
        .enumerate()
        .filter(|(j, _)| *j > 0 && *j + 1 < ys.len())
        .min_by(|a, b| (a.1 - k.y).abs().total_cmp(&(b.1 - k.y).abs()))
        .ok_or_else(|| SketchError::Section("part has no interior section".into()))?;
    let sec = &part.sections[j];
    let half_width = match sec.shape {
        SectionShape::Circle { r } => r,
        SectionShape::Ellipse { a, .. } => a,
        SectionShape::Gec { .. } => f64::INFINITY,
    };
    let cx = sec.centre[0];
    for p in &k.points {
        if (p[0] - cx).abs() > (1.0 + SECTION_SLACK) * half_width {
            return Err(SketchError::Section(format!(
                "section of '{}' at y = {}: point ({}, {}) is outside the part (half-width {half_width:.4} about x = {cx:.4})",
                k.part, k.y, p[0], p[1]
            )));
        }
    }
    // the sketch lies in the horizontal plane at its y; its angles are those
    // of its bounding ellipse (the parameter of the neighbouring ellipse
    // sections, so the chain does not twist between them)
    let centre = [sec.centre[0], k.y, 0.0];
    // the horizontal frame at the section's height must exist
    Frame::new(centre, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0])
        .map_err(|e| SketchError::SectionFrame(Box::new(e)))?;
    let mut pts: Vec<[f64; 2]> = k.points.iter().map(|p| [p[0] - cx, p[1]]).collect();
    if pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    if pts.len() < 2 * GEC_TERMS + 2 {
        return Err(SketchError::Section(format!(
            "section of '{}' at y = {}: {} points, at least {} needed",
            k.part,
            k.y,
            pts.len(),
            2 * GEC_TERMS + 2
        )));
    }
    crate::polygon::validate(&pts).map_err(|e| SketchError::Outline {
        what: "key section".into(),
        message: e.to_string(),
    })?;
    let thetas = ellipse_angles(&pts, k)?;
    let (gc, gx, gy) = crate::curve::gec::fit::solve(&pts, &thetas, GEC_TERMS, Default::default())
        .map_err(|e| {
            SketchError::section_fit(format!("section of '{}' at y = {}", k.part, k.y), e)
        })?;
    let sec = &mut part.sections[j];
    sec.centre = centre;
    sec.e1 = [1.0, 0.0, 0.0];
    sec.e2 = [0.0, 0.0, 1.0];
    sec.shape = SectionShape::Gec {
        centre: gc,
        x: gx,
        y: gy,
    };
    // re-measure u along the section centres
    let mut u = 0.0;
    for i in 1..part.sections.len() {
        u += crate::mesh::dist(part.sections[i - 1].centre, part.sections[i].centre);
        part.sections[i].u = u;
    }
    Ok(())
}

/// The angles of a key section's points on its bounding ellipse, unwrapped
/// to a monotone sequence in the direction of travel (the parameter of the
/// neighbouring ellipse sections, so the chain does not twist between
/// them); a curve winding around its centre more than once is refused.
fn ellipse_angles(pts: &[[f64; 2]], k: &KeySection) -> Result<Vec<f64>, SketchError> {
    let (lo, hi) = crate::polygon::bbox(pts);
    let mid = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let half = [0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1])];
    let mut thetas: Vec<f64> = pts
        .iter()
        .map(|p| ((p[1] - mid[1]) / half[1]).atan2((p[0] - mid[0]) / half[0]))
        .collect();
    // unwrap to a monotone sequence in the direction of travel
    let dir = if crate::polygon::signed_area(pts) > 0.0 {
        1.0
    } else {
        -1.0
    };
    let tau = 2.0 * std::f64::consts::PI;
    let step = 1e-3 * tau / thetas.len() as f64;
    for i in 1..thetas.len() {
        // nearest branch to the previous angle, then monotone
        let d = (thetas[i] - thetas[i - 1]) / tau;
        thetas[i] -= d.round() * tau;
        if dir * (thetas[i] - thetas[i - 1]) < step {
            thetas[i] = thetas[i - 1] + dir * step;
        }
    }
    if dir * (thetas[thetas.len() - 1] - thetas[0]) >= tau {
        return Err(SketchError::Section(format!(
            "section of '{}' at y = {}: the curve winds around its centre more than once",
            k.part, k.y
        )));
    }
    Ok(thetas)
}
