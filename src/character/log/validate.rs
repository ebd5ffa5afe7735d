//! Validation of an edit's own parameters, before it meets a document
//! (ranges, finiteness, shape parameters, transform limits).

use super::{Edit, EditError, SectionTransform, SCALE_MAX, SIGMA_MAX};
use crate::character::spec::SectionShape;
use std::f64::consts::PI;

/// Smallest angle range of a 4-sided force (rectangle or stroke's bounding
/// box), radians: a narrower patch bends within less than a mesh ring's
/// angle step and its derivatives grow as the inverse width.
pub const THETA_SPAN_MIN: f64 = 1e-2;
/// Largest angle range of a 4-sided force (the whole ring).
pub const THETA_SPAN_MAX: f64 = 2.0 * PI;

/// The stroke map of a stroke force edit (its validation errors named).
pub fn stroke_map(e: &Edit) -> Result<super::stroke::StrokeMap, EditError> {
    let Edit::ForceStroke {
        part,
        stroke,
        corners,
        ..
    } = e
    else {
        return Err(EditError::Invalid {
            op: e.op(),
            part: e.part().unwrap_or("").into(),
            message: "not a stroke force edit".into(),
        });
    };
    super::stroke::StrokeMap::new(stroke, *corners).map_err(|err| EditError::Invalid {
        op: e.op(),
        part: part.clone(),
        message: format!("stroke: {err}"),
    })
}

/// The u-range, shape parameter and force of a 2- or 4-sided force edit.
fn check_force(
    e: &Edit,
    u: &[f64; 2],
    a: f64,
    force: &crate::pde4::Force,
) -> Result<(), EditError> {
    param(e, "u[0]", u[0], true, "finite")?;
    param(e, "u[1]", u[1], u[1] > u[0], "u[1] > u[0]")?;
    check_patch(e, a, force)
}

/// The shape parameter and force of a force edit.
fn check_patch(e: &Edit, a: f64, force: &crate::pde4::Force) -> Result<(), EditError> {
    param(
        e,
        "a",
        a,
        (A_FORCE_MIN..=A_FORCE_MAX).contains(&a),
        &format!("a shape parameter in [{A_FORCE_MIN}, {A_FORCE_MAX}]"),
    )?;
    force.validate().map_err(|err| EditError::Invalid {
        op: e.op(),
        part: e.part().unwrap_or("").into(),
        message: format!("force: {err}"),
    })
}

/// A length or coordinate of an edit (model units): finite, at most
/// [`crate::limits::MODEL_COORD`] in size, the bound of every document
/// length.
fn length(e: &Edit, name: &'static str, value: f64) -> Result<(), EditError> {
    let max = crate::limits::MODEL_COORD;
    param(
        e,
        name,
        value,
        value.abs() <= max,
        &format!("a finite length of at most {max:e} model units in size"),
    )
}

/// `Ok` when `ok` holds and `value` is finite, else the edit's named
/// [`EditError::Parameter`] with the range `expected`.
pub fn param(
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
        Edit::GecTransform { transform, .. } => check_transform(e, transform),
        Edit::Force { u, force, a, .. } => check_force(e, u, *a, force),
        Edit::ForceRegion {
            u, theta, force, a, ..
        } => {
            param(e, "theta[0]", theta[0], true, "finite")?;
            let span = theta[1] - theta[0];
            param(
                e,
                "theta[1]",
                theta[1],
                span > 0.0 && span <= THETA_SPAN_MAX,
                "theta[0] < theta[1] <= theta[0] + 2 pi (the curve must enclose a region of the part)",
            )?;
            param(
                e,
                "theta[1] - theta[0]",
                span,
                span >= THETA_SPAN_MIN,
                &format!("at least {THETA_SPAN_MIN} rad (the smallest 4-sided force)"),
            )?;
            check_force(e, u, *a, force)
        }
        Edit::ForceStroke { force, a, .. } => {
            check_patch(e, *a, force)?;
            let map = stroke_map(e)?;
            let span = map.theta[1] - map.theta[0];
            param(
                e,
                "the stroke's angle span",
                span,
                span >= THETA_SPAN_MIN,
                &format!("at least {THETA_SPAN_MIN} rad (the smallest 4-sided force)"),
            )
        }
        Edit::Boundary {
            curve,
            tangent,
            reach,
            ..
        } => check_boundary(e, curve.as_ref(), tangent.as_ref(), *reach),
        Edit::Plate {
            centre, radius, d, ..
        } => {
            for k in 0..3 {
                length(e, ["centre[0]", "centre[1]", "centre[2]"][k], centre[k])?;
                length(e, ["d[0]", "d[1]", "d[2]"][k], d[k])?;
            }
            length(e, "radius", *radius)?;
            param(e, "radius", *radius, *radius > 0.0, "a positive radius")
        }
        // strokes are validated against the built part in `check_builds`
        Edit::Sasm(_) | Edit::SasmAux(_) => Ok(()),
    }
}

/// A section transform's parameters: finite, and within their ranges.
fn check_transform(e: &Edit, transform: &SectionTransform) -> Result<(), EditError> {
    match transform {
        SectionTransform::Translate { d } => {
            for (k, name) in ["d[0]", "d[1]", "d[2]"].into_iter().enumerate() {
                length(e, name, d[k])?;
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
            length(e, "h", *h)?;
            param(e, "theta", *theta, true, "finite")?;
            param(
                e,
                "sigma",
                *sigma,
                *sigma > 0.0 && *sigma <= SIGMA_MAX,
                &format!("a width in (0, {SIGMA_MAX}]"),
            )
        }
    }
}

/// A boundary edit's reach in (0, 1], a new curve with finite numbers and
/// positive radii, a finite tangent change; one of the two given.
fn check_boundary(
    e: &Edit,
    curve: Option<&SectionShape>,
    tangent: Option<&[f64; 3]>,
    reach: f64,
) -> Result<(), EditError> {
    param(e, "reach", reach, reach > 0.0 && reach <= 1.0, "in (0, 1]")?;
    if curve.is_none() && tangent.is_none() {
        return Err(EditError::Invalid {
            op: e.op(),
            part: e.part().unwrap_or("").into(),
            message: "give a new \"curve\", a \"tangent\" change, or both".into(),
        });
    }
    if let Some(t) = tangent {
        for (k, name) in ["tangent[0]", "tangent[1]", "tangent[2]"]
            .into_iter()
            .enumerate()
        {
            length(e, name, t[k])?;
        }
    }
    if let Some(c) = curve {
        let ok = match c {
            SectionShape::Circle { r } => r.is_finite() && *r > 0.0,
            SectionShape::Ellipse { a, b, offset } => {
                a.is_finite() && b.is_finite() && offset.is_finite() && *a > 0.0 && *b > 0.0
            }
            SectionShape::Gec { centre, x, y } => centre
                .iter()
                .chain(x.iter().flatten())
                .chain(y.iter().flatten())
                .all(|v| v.is_finite()),
        };
        if !ok {
            return Err(EditError::Invalid {
                op: e.op(),
                part: e.part().unwrap_or("").into(),
                message: "the new curve needs finite numbers and positive radii".into(),
            });
        }
    }
    Ok(())
}

/// Smallest shape parameter of a force edit.
pub const A_FORCE_MIN: f64 = 0.05;
/// Largest shape parameter of a force edit.
pub const A_FORCE_MAX: f64 = 20.0;
