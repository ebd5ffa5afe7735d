//! Pushing an edit onto a document's log: validated against the document's
//! current state (the stored parts with the active edits applied, the
//! edited part built) before anything changes. Every edit kind is judged
//! here, so this sits above the operations that apply them
//! (`crate::edit`, `crate::sasm`).

use crate::character::doc::CharacterDoc;
use crate::character::log::{check_order, unknown_part, validate_params, Edit, EditError};
use crate::character::spec::PartSpec;
use std::f64::consts::PI;

impl CharacterDoc {
    /// Validates `e` against the current state (the stored parts with the
    /// active edits applied) before changing anything, then drops the redo
    /// tail, appends `e` and moves the cursor to the end.
    pub fn push_edit(&mut self, e: Edit) -> Result<(), EditError> {
        if self.parts().is_empty() {
            return Err(EditError::NoParts);
        }
        let mut parts = crate::edit::apply_to_parts(self.parts(), self.active_edits())?;
        validate_params(&e)?;
        let mut log = self.active_edits().to_vec();
        log.push(e.clone());
        check_order(self.transitions(), &log)?;
        crate::edit::apply_one(&mut parts, &e)?;
        check_builds(&parts, &e)?;
        self.append_edit(e);
        Ok(())
    }
}

/// Builds the part an edit targets (the chain solver's own guards).
fn check_builds(parts: &[PartSpec], e: &Edit) -> Result<(), EditError> {
    let Some(name) = e.part() else {
        return Ok(());
    };
    let Some(p) = parts.iter().find(|p| p.name == name) else {
        return Err(unknown_part(parts, name));
    };
    let built = crate::character::part::build_part(p).map_err(|err| EditError::Build {
        op: e.op(),
        part: name.into(),
        source: err,
    })?;
    match e {
        Edit::Force { .. } | Edit::ForceRegion { .. } | Edit::ForceStroke { .. } => {
            if let Some(f) = crate::edit::field_of(e) {
                f?;
            }
        }
        Edit::Plate { centre, radius, .. } => {
            let d = crate::edit::distance_to_part(&built, *centre);
            if d > *radius {
                return Err(EditError::Invalid {
                    op: e.op(),
                    part: name.into(),
                    message: format!(
                        "the region centre lies {d:.4} from the part's surface, farther than the radius {radius}"
                    ),
                });
            }
        }
        Edit::Sasm(_) | Edit::SasmAux(_) => {
            let f = crate::sasm::edit::feature_of(e, std::slice::from_ref(&built));
            if let Some(Err(err)) = f {
                return Err(EditError::Invalid {
                    op: e.op(),
                    part: name.into(),
                    message: err.to_string(),
                });
            }
        }
        _ => {}
    }
    Ok(())
}

/// Sets the `stroke` of a stroke force edit from a stroke drawn in a view
/// (`crate::sasm::Stroke`: 2D points in an orthographic view), projected
/// onto the target part of `doc`'s current state (its stored parts with the
/// active spec-level edits; an earlier force's displacement is not
/// included) by ray casting (`sasm::project`); the angles are unwrapped
/// along the stroke so that a stroke across `theta = 0` stays one curve.
/// A point that misses the part is a named error.
pub fn project_force_stroke(
    doc: &CharacterDoc,
    e: &mut Edit,
    drawn: &crate::character::log::Stroke,
) -> Result<(), EditError> {
    let op = e.op();
    let Edit::ForceStroke { part, stroke, .. } = e else {
        return Err(EditError::Invalid {
            op,
            part: e.part().unwrap_or("").into(),
            message: "a drawn stroke needs a force_stroke edit".into(),
        });
    };
    let invalid = |m: String| EditError::Invalid {
        op,
        part: part.clone(),
        message: m,
    };
    // the stroke's own limit, before a ray is cast for every point
    let count = drawn.points.len();
    if count > crate::edit::stroke::STROKE_POINTS_MAX {
        let err = crate::edit::stroke::StrokeError::TooManyPoints { count };
        return Err(invalid(format!("stroke: {err}")));
    }
    let parts = crate::edit::apply_to_parts(doc.parts(), doc.active_edits())?;
    let spec = parts
        .iter()
        .find(|p| &p.name == part)
        .ok_or_else(|| unknown_part(&parts, part))?;
    let surf = crate::character::part::build_part(spec).map_err(|source| EditError::Build {
        op,
        part: part.clone(),
        source,
    })?;
    let pr = crate::sasm::project::Projector::new(&surf, drawn.view);
    let hits = crate::sasm::project::project_stroke(&pr, "force stroke", &drawn.points)
        .map_err(|err| invalid(err.to_string()))?;
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(hits.len());
    for h in hits {
        let t = match out.last() {
            Some(l) => l[1] + (h.theta - l[1] + PI).rem_euclid(2.0 * PI) - PI,
            None => h.theta,
        };
        out.push([h.u, t]);
    }
    *stroke = out;
    Ok(())
}
