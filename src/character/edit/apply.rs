//! Applying edits to a document's part specifications.

use super::{
    unknown_part, Edit, EditError, SectionTransform, SCALE_MAX, SECTION_SAMPLES, SIGMA_MAX,
};
use crate::character::doc::{PartSpec, SectionShape, SectionSpec, SurfaceSpec};
use crate::curve::gec::transform::Bend;
use crate::curve::gec::{Frame, Gec};
use crate::mesh::{dist, sub};
use std::f64::consts::PI;

fn param(
    e: &Edit,
    name: &'static str,
    value: f64,
    ok: bool,
    expected: &str,
) -> Result<(), EditError> {
    if ok && value.is_finite() {
        return Ok(());
    }
    Err(EditError::Parameter {
        op: e.op(),
        part: e.part().unwrap_or("").into(),
        name,
        value,
        expected: expected.into(),
    })
}

/// Checks an edit's parameters that do not depend on the document: finite
/// numbers in their documented ranges.
pub fn validate_params(e: &Edit) -> Result<(), EditError> {
    match e {
        Edit::ShapeParameter { a, .. } => param(
            e,
            "a",
            *a,
            a.abs() <= crate::pde6::A_MAX,
            &format!(
                "|a| <= {} (the pde6 family's documented range)",
                crate::pde6::A_MAX
            ),
        ),
        Edit::GecTransform { transform, .. } => match transform {
            SectionTransform::Translate { d } => {
                for (k, name) in ["d[0]", "d[1]", "d[2]"].into_iter().enumerate() {
                    param(e, name, d[k], true, "a finite number")?;
                }
                Ok(())
            }
            SectionTransform::Scale { sx, sy } => {
                let exp = format!("a factor in (0, {SCALE_MAX}]");
                param(e, "sx", *sx, *sx > 0.0 && *sx <= SCALE_MAX, &exp)?;
                param(e, "sy", *sy, *sy > 0.0 && *sy <= SCALE_MAX, &exp)
            }
            SectionTransform::Rotate { angle } => param(e, "angle", *angle, true, "finite"),
            SectionTransform::Bend { kappa, axis } => {
                param(e, "kappa", *kappa, true, "finite")?;
                for (k, name) in ["axis[0]", "axis[1]", "axis[2]"].into_iter().enumerate() {
                    param(e, name, axis[k], true, "finite")?;
                }
                Ok(())
            }
            SectionTransform::Bump { h, theta, sigma } => {
                param(e, "h", *h, true, "finite")?;
                param(e, "theta", *theta, true, "finite")?;
                param(
                    e,
                    "sigma",
                    *sigma,
                    *sigma > 0.0 && *sigma <= SIGMA_MAX,
                    &format!("a width in (0, {SIGMA_MAX}]"),
                )
            }
        },
    }
}

/// The parts with `edits` applied in order (spec-level edits; validated as
/// they are applied; an error names the edit's index in `edits`).
pub fn apply_to_parts(parts: &[PartSpec], edits: &[Edit]) -> Result<Vec<PartSpec>, EditError> {
    let mut out = parts.to_vec();
    for (i, e) in edits.iter().enumerate() {
        validate_params(e)
            .and_then(|_| apply_one(&mut out, e))
            .map_err(|err| EditError::Replay {
                index: i,
                summary: e.summary(),
                source: Box::new(err),
            })?;
    }
    Ok(out)
}

fn find<'a>(parts: &'a mut [PartSpec], name: &str) -> Result<&'a mut PartSpec, EditError> {
    let i = parts
        .iter()
        .position(|p| p.name == name)
        .ok_or_else(|| unknown_part(parts, name))?;
    Ok(&mut parts[i])
}

/// A section as a GEC in its frame (circles and ellipses converted exactly).
pub fn section_gec(s: &SectionSpec) -> Result<Gec, String> {
    let frame = Frame::new(s.centre, s.e1, s.e2).map_err(|e| e.to_string())?;
    let (centre, x, y) = match &s.shape {
        SectionShape::Circle { r } => ([0.0, 0.0], vec![[*r, 0.0]], vec![[*r, 0.0]]),
        SectionShape::Ellipse { a, b, offset } => {
            ([0.0, *offset], vec![[*a, 0.0]], vec![[*b, 0.0]])
        }
        SectionShape::Gec { centre, x, y } => (*centre, x.clone(), y.clone()),
    };
    Gec::new(frame, centre, x, y).map_err(|e| e.to_string())
}

fn collapsed(s: &SectionSpec) -> bool {
    matches!(s.shape, SectionShape::Circle { r } if r == 0.0)
}

/// Applies one (parameter-checked) spec-level edit to `parts`.
pub(crate) fn apply_one(parts: &mut [PartSpec], e: &Edit) -> Result<(), EditError> {
    let name = e.part().unwrap_or("");
    let known = parts.to_vec();
    let p = find(parts, name).map_err(|_| unknown_part(&known, name))?;
    match e {
        Edit::ShapeParameter { a, .. } => {
            p.surface = SurfaceSpec::Pde6C2 { a: *a };
            Ok(())
        }
        Edit::GecTransform {
            section, transform, ..
        } => {
            let count = p.sections.len();
            let idx: Vec<usize> = match section {
                Some(s) if *s >= count => {
                    return Err(EditError::NoSection {
                        part: name.into(),
                        section: *s,
                        count,
                    })
                }
                Some(s) => vec![*s],
                None => (0..count).collect(),
            };
            let bend = match transform {
                SectionTransform::Bend { kappa, axis } => Some(bend_of(p, e, *kappa, *axis)?),
                _ => None,
            };
            for i in idx {
                transform_section(p, i, e, transform, bend.as_ref())?;
            }
            Ok(())
        }
    }
}

fn bend_of(p: &PartSpec, e: &Edit, kappa: f64, axis: [f64; 3]) -> Result<Bend, EditError> {
    let (first, last) = (
        p.sections[0].centre,
        p.sections[p.sections.len() - 1].centre,
    );
    let len = dist(first, last);
    param(
        e,
        "kappa",
        kappa,
        kappa.abs() * len <= PI,
        &format!("|kappa| * part length ({len:.4}) <= pi"),
    )?;
    Bend::new(first, sub(last, first), axis, kappa).map_err(|err| EditError::Invalid {
        op: e.op(),
        part: p.name.clone(),
        message: err.to_string(),
    })
}

fn transform_section(
    p: &mut PartSpec,
    i: usize,
    e: &Edit,
    t: &SectionTransform,
    bend: Option<&Bend>,
) -> Result<(), EditError> {
    let invalid = |m: String| EditError::Invalid {
        op: e.op(),
        part: p.name.clone(),
        message: format!("section {i}: {m}"),
    };
    let s = &p.sections[i];
    let g = section_gec(s).map_err(invalid)?;
    let point = collapsed(s);
    let c = g.centre;
    let out = match t {
        SectionTransform::Translate { d } => g.translated(*d),
        SectionTransform::Scale { sx, sy } => g.scaled(*sx, *sy, c),
        SectionTransform::Rotate { angle } => g.rotated(*angle, c),
        SectionTransform::Bend { .. } => match bend {
            Some(b) => b.apply_gec(&g),
            None => g,
        },
        SectionTransform::Bump { h, theta, sigma } => {
            if point {
                return Err(invalid(
                    "a bump needs a section with a size (this one is a collapsed end)".into(),
                ));
            }
            g.with_bump(*h, *theta, *sigma)
                .map_err(|err| invalid(err.to_string()))?
        }
    };
    if !out.is_finite() {
        return Err(invalid(
            "the transform gives non-finite coefficients".into(),
        ));
    }
    if !point {
        let pts = out.sample_plane(SECTION_SAMPLES);
        if let Some((a, b)) = crate::template::polygon::self_intersection(&pts) {
            return Err(EditError::SelfIntersecting {
                op: e.op(),
                part: p.name.clone(),
                section: i,
                first: a,
                second: b,
            });
        }
    }
    let s = &mut p.sections[i];
    s.centre = out.frame.origin;
    s.e1 = out.frame.e1;
    s.e2 = out.frame.e2;
    if !point {
        s.shape = SectionShape::Gec {
            centre: out.centre,
            x: out.x,
            y: out.y,
        };
    }
    Ok(())
}

/// Builds the part an edit targets (the chain solver's own guards).
pub(crate) fn check_builds(parts: &[PartSpec], e: &Edit) -> Result<(), EditError> {
    let Some(name) = e.part() else {
        return Ok(());
    };
    let Some(p) = parts.iter().find(|p| p.name == name) else {
        return Err(unknown_part(parts, name));
    };
    crate::sketch::part::build_part(p).map_err(|err| EditError::Build {
        op: e.op(),
        part: name.into(),
        message: err.to_string(),
    })?;
    Ok(())
}
