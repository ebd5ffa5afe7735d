//! Applying edits to a document's part specifications.

use crate::character::log::{
    param, unknown_part, validate_params, Edit, EditError, SectionTransform, SECTION_SAMPLES,
};
use crate::character::spec::{End, PartSpec, SectionShape, SectionSpec, SurfaceSpec};
use crate::curve::gec::transform::Bend;
use crate::curve::gec::{Frame, Gec, GecError};
use crate::mesh::{add, dist, dot, scale, sub};
use std::f64::consts::PI;

use super::force4::U_SPAN_MIN_FRACTION;

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
pub fn section_gec(s: &SectionSpec) -> Result<Gec, GecError> {
    let frame = Frame::new(s.centre, s.e1, s.e2)?;
    let (centre, x, y) = match &s.shape {
        SectionShape::Circle { r } => ([0.0, 0.0], vec![[*r, 0.0]], vec![[*r, 0.0]]),
        SectionShape::Ellipse { a, b, offset } => {
            ([0.0, *offset], vec![[*a, 0.0]], vec![[*b, 0.0]])
        }
        SectionShape::Gec { centre, x, y } => (*centre, x.clone(), y.clone()),
    };
    Gec::new(frame, centre, x, y)
}

/// The error of section `i` of `p` that is no GEC, under edit `e`.
fn not_a_gec<'a>(e: &'a Edit, p: &'a PartSpec, i: usize) -> impl Fn(GecError) -> EditError + 'a {
    move |source| EditError::Section {
        op: e.op(),
        part: p.name.clone(),
        section: i,
        source: Box::new(source),
    }
}

fn collapsed(s: &SectionSpec) -> bool {
    matches!(s.shape, SectionShape::Circle { r } if r == 0.0)
}

/// Applies one (parameter-checked) spec-level edit to `parts`.
pub fn apply_one(parts: &mut [PartSpec], e: &Edit) -> Result<(), EditError> {
    let name = e.part().unwrap_or("");
    let known = parts.to_vec();
    let p = find(parts, name).map_err(|_| unknown_part(&known, name))?;
    match e {
        Edit::ShapeParameter { a, .. } => match p.surface {
            SurfaceSpec::Pde6C2 { open_ends, .. } => {
                p.surface = SurfaceSpec::Pde6C2 { a: *a, open_ends };
                Ok(())
            }
            // the shape parameter a is the pde6 family's (000 sec 5.1)
            ref other => Err(EditError::Invalid {
                op: e.op(),
                part: name.to_string(),
                message: format!(
                    "the shape parameter a belongs to pde6 surfaces; this part is an {}",
                    other.describe()
                ),
            }),
        },
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
        Edit::Force { u, .. } | Edit::ForceRegion { u, .. } => force_range(p, e, *u),
        Edit::ForceStroke { .. } => force_range(p, e, super::force4::stroke_map(e)?.u),
        Edit::Boundary {
            end,
            curve,
            tangent,
            reach,
            ..
        } => boundary(p, e, *end, curve.as_ref(), *tangent, *reach),
        Edit::Plate { .. } | Edit::Sasm(_) | Edit::SasmAux(_) => Ok(()),
    }
}

/// A force's u range (a stroke's bounding box) lies inside the part's and
/// spans at least [`U_SPAN_MIN_FRACTION`] of it.
fn force_range(p: &PartSpec, e: &Edit, u: [f64; 2]) -> Result<(), EditError> {
    let (u0, u1) = (p.sections[0].u, p.sections[p.sections.len() - 1].u);
    let what = match e {
        Edit::ForceStroke { .. } => "the stroke's u range",
        _ => "the force range",
    };
    if u[0] < u0 || u[1] > u1 {
        return Err(EditError::Invalid {
            op: e.op(),
            part: p.name.clone(),
            message: format!(
                "{what} [{}, {}] lies outside the part's u range [{u0}, {u1}]",
                u[0], u[1]
            ),
        });
    }
    let min = U_SPAN_MIN_FRACTION * (u1 - u0);
    if u[1] - u[0] < min {
        return Err(EditError::Invalid {
            op: e.op(),
            part: p.name.clone(),
            message: format!(
                "{what} [{}, {}] is narrower than the smallest force, {U_SPAN_MIN_FRACTION} of the part's u range ({min:.3e})",
                u[0], u[1]
            ),
        });
    }
    Ok(())
}

fn boundary(
    p: &mut PartSpec,
    e: &Edit,
    end: End,
    curve: Option<&SectionShape>,
    tangent: Option<[f64; 3]>,
    reach: f64,
) -> Result<(), EditError> {
    let invalid = |m: String| EditError::Invalid {
        op: e.op(),
        part: p.name.clone(),
        message: m,
    };
    let n = p.sections.len();
    let (ie, closed) = match end {
        End::Start => (0, p.closed_start),
        End::End => (n - 1, p.closed_end),
    };
    if let Some(c) = curve {
        if closed {
            return Err(invalid(format!(
                "the part's {end:?} is a closed end (a point): it has no boundary curve to replace"
            )));
        }
        let mut s = p.sections[ie].clone();
        s.shape = c.clone();
        let g = section_gec(&s).map_err(not_a_gec(e, p, ie))?;
        if let Some((a, b, _)) = crate::polygon::self_intersection(&g.sample_plane(SECTION_SAMPLES))
        {
            return Err(EditError::SelfIntersecting {
                op: e.op(),
                part: p.name.clone(),
                section: ie,
                first: a,
                second: b,
            });
        }
        p.sections[ie] = s;
    }
    let Some(t) = tangent else {
        return Ok(());
    };
    let tt = dot(t, t);
    if tt == 0.0 {
        return Ok(());
    }
    let ue = p.sections[ie].u;
    let l = reach * (p.sections[n - 1].u - p.sections[0].u);
    let phi: Vec<(usize, f64)> = (0..n)
        .filter(|&k| k != ie)
        .filter_map(|k| {
            let x = (p.sections[k].u - ue).abs() / l;
            (x < 1.0).then(|| (k, (p.sections[k].u - ue) * (1.0 - x).powi(3)))
        })
        .collect();
    if phi.is_empty() {
        return Err(invalid(format!(
            "no section lies within reach {reach} of the part's {end:?}"
        )));
    }
    let build = |q: &PartSpec| {
        crate::character::part::build_part(q).map_err(|err| EditError::Build {
            op: e.op(),
            part: q.name.clone(),
            source: err,
        })
    };
    let before = build(p)?.section(ue, 1).c0;
    let mut q = p.clone();
    for &(k, f) in &phi {
        q.sections[k].centre = add(q.sections[k].centre, scale(t, f));
    }
    let after = build(&q)?.section(ue, 1).c0;
    let response = dot(sub(after, before), t) / tt;
    if response.is_nan() || response.abs() <= TANGENT_RESPONSE_MIN {
        return Err(invalid(format!(
            "the end tangent does not respond to the sections within reach {reach} (response {response:e})"
        )));
    }
    for &(k, f) in &phi {
        p.sections[k].centre = add(p.sections[k].centre, scale(t, f / response));
    }
    Ok(())
}

/// Smallest end-tangent response of a boundary tangent edit (per unit
/// section offset weight) accepted.
pub const TANGENT_RESPONSE_MIN: f64 = 1e-6;

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
    let g = section_gec(s).map_err(not_a_gec(e, p, i))?;
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
                .map_err(not_a_gec(e, p, i))?
        }
    };
    if !out.is_finite() {
        return Err(invalid(
            "the transform gives non-finite coefficients".into(),
        ));
    }
    if !point {
        let pts = out.sample_plane(SECTION_SAMPLES);
        if let Some((a, b, _)) = crate::polygon::self_intersection(&pts) {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shape_parameter_edit_is_refused_on_an_ode6_part() {
        let mut parts = vec![PartSpec {
            name: "arm".into(),
            surface: SurfaceSpec::Ode6C2 {
                rho: 1.0,
                eta: 3.0,
                lambda: 1.0,
            },
            sections: vec![],
            closed_start: false,
            closed_end: false,
        }];
        let e = Edit::ShapeParameter {
            part: "arm".into(),
            a: 0.5,
        };
        let err = apply_one(&mut parts, &e).unwrap_err().to_string();
        assert!(err.contains("belongs to pde6 surfaces"), "{err}");
        assert!(matches!(parts[0].surface, SurfaceSpec::Ode6C2 { .. }));
        parts[0].surface = SurfaceSpec::Pde6C2 {
            a: 0.0,
            open_ends: Default::default(),
        };
        apply_one(&mut parts, &e).unwrap();
        assert_eq!(
            parts[0].surface,
            SurfaceSpec::Pde6C2 {
                a: 0.5,
                open_ends: Default::default()
            }
        );
    }

    /// A section the document holds but that is no GEC (its frame's axes
    /// are parallel) refuses a transform with the gec error as its typed
    /// source, naming the section.
    #[test]
    fn a_section_with_a_broken_frame_is_refused_with_its_gec_error() {
        let good = SectionSpec {
            u: 0.0,
            centre: [0.0; 3],
            e1: [1.0, 0.0, 0.0],
            e2: [0.0, 1.0, 0.0],
            shape: SectionShape::Circle { r: 1.0 },
        };
        let bad = SectionSpec {
            u: 1.0,
            e2: [1.0, 0.0, 0.0],
            ..good.clone()
        };
        let mut parts = vec![PartSpec {
            name: "arm".into(),
            surface: SurfaceSpec::Pde6C2 {
                a: 0.0,
                open_ends: Default::default(),
            },
            sections: vec![good, bad],
            closed_start: false,
            closed_end: false,
        }];
        let e = Edit::GecTransform {
            part: "arm".into(),
            section: Some(1),
            transform: SectionTransform::Scale { sx: 1.1, sy: 1.1 },
        };
        let err = apply_one(&mut parts, &e).unwrap_err();
        match &err {
            EditError::Section {
                section, source, ..
            } => {
                assert_eq!(*section, 1);
                assert!(matches!(**source, GecError::InvalidFrame(_)), "{source:?}");
            }
            other => panic!("not a section error: {other:?}"),
        }
        assert!(
            err.to_string().contains("section 1: invalid frame"),
            "{err}"
        );
    }
}
