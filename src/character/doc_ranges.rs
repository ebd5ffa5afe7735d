//! The documented range of every value of a character document, checked
//! on load (and before every save and build) with the field's path in the
//! message: `parts[2].sections[5].shape.circle.r = 1e30 is out of range`.
//!
//! | field | range |
//! |---|---|
//! | every coordinate, length, radius, GEC coefficient, apex | finite, magnitude at most [`MODEL_COORD`] (model units) |
//! | `inputs.tolerance` | [`crate::limits::SKETCH_TOLERANCE`] |
//! | `inputs.front/side` points, `removed_parts[i].front/side` points | at most [`SVG_POINTS`] |
//! | `inputs.sections` | at most [`PART_SECTIONS`]; each [`KEY_SECTION_POINTS`] points |
//! | `parts`, `transitions` | at most [`DOC_PARTS`] each |
//! | `parts[i].surface.a` | `|a| <=` [`crate::pde6::A_MAX`] |
//! | `parts[i].sections` | [`PART_SECTIONS`]; `u` strictly increasing |
//! | `parts[i].sections[j].e1, e2` | orthonormal within [`FRAME_TOL`] |
//! | `...shape.gec.x, y` | equal lengths, at most [`SECTION_HARMONICS`] harmonics |
//! | a collapsed section (circle `r = 0`, ellipse `a = 0` or `b = 0`) | only as the first section of a part with `closed_start` or the last with `closed_end` |
//! | `transitions[i].cut_angles`, `tangent_scale`, `child_tangent_scales` | checked by name when built (`character::assembly`: front angles in `[0, pi]`, back in `[pi, 2 pi]`; each scale in `(0,` [`crate::character::assembly::TANGENT_SCALE_MAX`]`]`, one per child or none) |
//! | `transitions[i].child_rises` | checked by name when built (`character::assembly`: each start in `[0,` [`crate::character::rise::RISE_MAX`]`]`, one `[-z, +z]` pair per child or none) |
//! | `edits` | at most [`LOG_EDITS`]; each its own ranges (`character::edit::validate_params`) |
//! | `props` | at most [`DOC_PROPS`]; each `PropSpec::validate` |
//! | names of parts, transitions, removed parts, props | non-empty, unique |

use super::inputs::{DocError, Inputs, ProfileInput, RemovedPart};
use super::props::PropSpec;
use super::spec::TransitionSpec;
use super::spec::{PartSpec, SectionShape, SectionSpec};
use crate::limits::{
    Num, Range, DOC_PROPS, KEY_SECTION_POINTS, LOG_EDITS, MODEL_COORD, PART_SECTIONS,
    SECTION_HARMONICS, SVG_POINTS,
};

/// Parts (and transitions) of one document.
pub const DOC_PARTS: Range = Range {
    min: 0,
    max: 256,
    why: "parts of one document",
};

/// Orthonormality of a section frame accepted on load (a GEC section is
/// held to the stricter `curve::gec::FRAME_TOL` when built).
pub const FRAME_TOL: f64 = 1e-6;

fn range_err(field: String, value: String, expected: String) -> DocError {
    DocError::Range {
        field,
        value,
        expected,
    }
}

fn count(field: &str, n: usize, r: Range) -> Result<(), DocError> {
    if (n as u64) < r.min || (n as u64) > r.max {
        return Err(range_err(
            format!("{field} (count)"),
            n.to_string(),
            format!("from {} to {} ({})", r.min, r.max, r.why),
        ));
    }
    Ok(())
}

/// A length or coordinate: finite, `lo <= x`, `|x| <= MODEL_COORD`.
fn length(field: impl Fn() -> String, x: f64, lo: f64) -> Result<(), DocError> {
    if x.is_finite() && x >= lo && x.abs() <= MODEL_COORD {
        return Ok(());
    }
    let expected = if lo > f64::NEG_INFINITY {
        format!("from {} to {} model units", Num(lo), Num(MODEL_COORD))
    } else {
        format!("finite, at most {} in size (model units)", Num(MODEL_COORD))
    };
    Err(range_err(field(), Num(x).to_string(), expected))
}

fn coords(field: impl Fn() -> String, xs: &[f64]) -> Result<(), DocError> {
    for (k, &x) in xs.iter().enumerate() {
        length(|| format!("{}[{k}]", field()), x, f64::NEG_INFINITY)?;
    }
    Ok(())
}

fn profile_input(field: &str, p: &ProfileInput) -> Result<(), DocError> {
    match p {
        ProfileInput::Path(s) if s.trim().is_empty() => Err(range_err(
            format!("{field}.path"),
            "\"\"".into(),
            "a file path".into(),
        )),
        ProfileInput::Path(_) => Ok(()),
        ProfileInput::Points(pts) => {
            count(&format!("{field}.points"), pts.len(), SVG_POINTS)?;
            for (i, q) in pts.iter().enumerate() {
                coords(|| format!("{field}.points[{i}]"), q)?;
            }
            Ok(())
        }
    }
}

/// What [`check`] reads of a document (`CharacterDoc::validate` lends
/// its fields: this file does not name the document's own file).
pub struct Fields<'a> {
    pub inputs: &'a Inputs,
    pub parts: &'a [PartSpec],
    pub transitions: &'a [TransitionSpec],
    pub removed_parts: &'a [RemovedPart],
    pub props: &'a [PropSpec],
    /// The length of the edit log.
    pub edits: usize,
}

/// Checks every value of a document against its documented range.
pub fn check(doc: &Fields) -> Result<(), DocError> {
    let i = &doc.inputs;
    if let Some(t) = i.tolerance {
        crate::limits::check_real("inputs.tolerance", t, crate::limits::SKETCH_TOLERANCE)
            .map_err(|e| range_err("inputs.tolerance".into(), Num(t).to_string(), e.to_string()))?;
    }
    profile_input("inputs.front", &i.front)?;
    if let Some(s) = &i.side {
        profile_input("inputs.side", s)?;
    }
    count(
        "inputs.sections",
        i.sections.len(),
        PART_SECTIONS.with_min(0),
    )?;
    for (k, s) in i.sections.iter().enumerate() {
        let f = format!("inputs.sections[{k}]");
        length(|| format!("{f}.y"), s.y, f64::NEG_INFINITY)?;
        count(&format!("{f}.points"), s.points.len(), KEY_SECTION_POINTS)?;
        for (j, q) in s.points.iter().enumerate() {
            coords(|| format!("{f}.points[{j}]"), q)?;
        }
    }
    count("parts", doc.parts.len(), DOC_PARTS)?;
    count("transitions", doc.transitions.len(), DOC_PARTS)?;
    for (k, p) in doc.parts.iter().enumerate() {
        part(&format!("parts[{k}] ('{}')", p.name), p)?;
    }
    for (k, t) in doc.transitions.iter().enumerate() {
        let f = format!("transitions[{k}] ('{}')", t.name);
        for (j, a) in t.seam_apex.iter().enumerate() {
            coords(|| format!("{f}.seam_apex[{j}]"), a)?;
        }
        // cut_angles and the tangent scales: refused by name by the build
        // (`character::assembly`), which knows the finer rules
    }
    for (k, r) in doc.removed_parts.iter().enumerate() {
        profile_input(
            &format!("removed_parts[{k}] ('{}').front", r.name),
            &r.front,
        )?;
        if let Some(s) = &r.side {
            profile_input(&format!("removed_parts[{k}] ('{}').side", r.name), s)?;
        }
    }
    count("edits", doc.edits, LOG_EDITS)?;
    count("props", doc.props.len(), DOC_PROPS)?;
    names(doc)
}

/// Names: non-empty and unique across parts, transitions, removed parts
/// and props, except that a removed part (an input: an outline built as
/// its own component) shares its name with the part derived from it.
fn names(doc: &Fields) -> Result<(), DocError> {
    let all: Vec<(String, &str)> = doc
        .parts
        .iter()
        .enumerate()
        .map(|(k, p)| (format!("parts[{k}].name"), p.name.as_str()))
        .chain(
            doc.transitions
                .iter()
                .enumerate()
                .map(|(k, t)| (format!("transitions[{k}].name"), t.name.as_str())),
        )
        .chain(
            doc.removed_parts
                .iter()
                .enumerate()
                .map(|(k, r)| (format!("removed_parts[{k}].name"), r.name.as_str())),
        )
        .chain(
            doc.props
                .iter()
                .enumerate()
                .map(|(k, p)| (format!("props[{k}].name"), p.name.as_str())),
        )
        .collect();
    for (k, (field, name)) in all.iter().enumerate() {
        if name.trim().is_empty() {
            return Err(range_err(
                field.clone(),
                format!("{name:?}"),
                "a non-empty name".into(),
            ));
        }
        let derived =
            |first: &str| field.starts_with("removed_parts[") && first.starts_with("parts[");
        if let Some((first, _)) = all[..k].iter().find(|(f, n)| n == name && !derived(f)) {
            return Err(range_err(
                field.clone(),
                format!("{name:?}"),
                format!("a name not used before (a name used twice); {first} is {name:?} already"),
            ));
        }
    }
    Ok(())
}

fn part(f: &str, p: &PartSpec) -> Result<(), DocError> {
    if let Some((name, value, expected)) = p.surface.out_of_range() {
        return Err(range_err(
            format!("{f}.surface.{name}"),
            Num(value).to_string(),
            expected,
        ));
    }
    count(&format!("{f}.sections"), p.sections.len(), PART_SECTIONS)?;
    let last = p.sections.len() - 1;
    for (j, s) in p.sections.iter().enumerate() {
        let g = format!("{f}.sections[{j}]");
        section(&g, s)?;
        if j > 0 && s.u <= p.sections[j - 1].u {
            return Err(range_err(
                format!("{g}.u"),
                Num(s.u).to_string(),
                format!(
                    "greater than the previous section's u = {} (u is arc length along the part)",
                    Num(p.sections[j - 1].u)
                ),
            ));
        }
        let collapsed = match &s.shape {
            SectionShape::Circle { r } => *r == 0.0,
            SectionShape::Ellipse { a, b, .. } => *a == 0.0 || *b == 0.0,
            SectionShape::Gec { .. } => false,
        };
        let closed_end = (j == 0 && p.closed_start) || (j == last && p.closed_end);
        if collapsed && !closed_end {
            return Err(range_err(
                format!("{g}.shape"),
                "a collapsed ring (zero radius)".into(),
                "a positive radius: only the first section of a part with closed_start, or the last with closed_end, may collapse to a point".into(),
            ));
        }
    }
    Ok(())
}

fn section(g: &str, s: &SectionSpec) -> Result<(), DocError> {
    length(|| format!("{g}.u"), s.u, f64::NEG_INFINITY)?;
    coords(|| format!("{g}.centre"), &s.centre)?;
    coords(|| format!("{g}.e1"), &s.e1)?;
    coords(|| format!("{g}.e2"), &s.e2)?;
    let v = crate::vec3::norm;
    let err = (v(s.e1) - 1.0)
        .abs()
        .max((v(s.e2) - 1.0).abs())
        .max(crate::vec3::dot(s.e1, s.e2).abs());
    if err.is_nan() || err > FRAME_TOL {
        return Err(range_err(
            format!("{g}.e1, e2"),
            format!("{:?}, {:?}", s.e1, s.e2),
            format!("two orthonormal axes (|e1| = |e2| = 1, e1.e2 = 0 within {FRAME_TOL:e}; measured error {})", Num(err)),
        ));
    }
    match &s.shape {
        SectionShape::Circle { r } => length(|| format!("{g}.shape.circle.r"), *r, 0.0),
        SectionShape::Ellipse { a, b, offset } => {
            length(|| format!("{g}.shape.ellipse.a"), *a, 0.0)?;
            length(|| format!("{g}.shape.ellipse.b"), *b, 0.0)?;
            length(
                || format!("{g}.shape.ellipse.offset"),
                *offset,
                f64::NEG_INFINITY,
            )
        }
        SectionShape::Gec { centre, x, y } => {
            coords(|| format!("{g}.shape.gec.centre"), centre)?;
            if x.len() != y.len() {
                return Err(range_err(
                    format!("{g}.shape.gec.y"),
                    format!("{} harmonics", y.len()),
                    format!("as many harmonics as x ({})", x.len()),
                ));
            }
            count(&format!("{g}.shape.gec.x"), x.len(), SECTION_HARMONICS)?;
            for (k, c) in x.iter().enumerate() {
                coords(|| format!("{g}.shape.gec.x[{k}]"), c)?;
            }
            for (k, c) in y.iter().enumerate() {
                coords(|| format!("{g}.shape.gec.y[{k}]"), c)?;
            }
            Ok(())
        }
    }
}
