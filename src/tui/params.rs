//! The parameter panel: rows describing the selected item, some of them
//! editable, and the parsing of typed values into edits.
//!
//! A part shows its surface family and PDE parameter `a` (an
//! [`Edit::ShapeParameter`], PDESM), its key sections, and one row per GEC
//! transform (GECDSM: translate, scale, rotate, bend, bump) acting on the
//! chosen section or on all of them. Values are parsed and range-checked as
//! they are typed ([`parse`]: numbers, then `edit::validate_params`); an
//! invalid value is shown with its error and cannot be applied. Transitions
//! and removed parts are shown read-only. Force, boundary and plate edits
//! (rows `force`, `boundary`, `plate`) are checked as typed the same way and
//! then pushed on the worker through `pipeline::push_checked`, so
//! one that would break the build is refused and the document unchanged.

use crate::character::doc::{CharacterDoc, End, PartSpec, SectionShape, SurfaceSpec};
use crate::character::log::{validate_params, Edit, SectionTransform};
use crate::pde4::{Force, ForceKind};

/// What a row edits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowKind {
    /// Read-only information.
    Info,
    /// The part's PDE parameter `a`.
    ShapeA,
    /// Which section the transforms act on (`all` or an index).
    Section,
    Translate,
    Scale,
    Rotate,
    Bend,
    Bump,
    /// PDESM sculpting force over a u-range of the part.
    Force,
    /// PDESM boundary tangent change at one end.
    Boundary,
    /// Mesh-level plate bending (paper 001).
    Plate,
}

impl RowKind {
    /// Editable rows.
    pub fn editable(self) -> bool {
        self != RowKind::Info
    }

    /// What to type (shown while editing).
    pub fn hint(self) -> &'static str {
        match self {
            RowKind::Info => "",
            RowKind::ShapeA => "a (|a| <= A_MAX)",
            RowKind::Section => "all | section index",
            RowKind::Translate => "dx dy dz (model units)",
            RowKind::Scale => "sx sy (factors along e1, e2)",
            RowKind::Rotate => "angle (degrees)",
            RowKind::Bend => "kappa (1/units) [ax ay az]",
            RowKind::Bump => "h theta(deg) sigma",
            RowKind::Force => "u0 u1 px py pz [uc vc] (uniform, or at uc vc in [0,1])",
            RowKind::Boundary => "start|end tx ty tz [reach] (tangent change)",
            RowKind::Plate => "cx cy cz radius dx dy dz (model units)",
        }
    }
}

/// One row of the panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub label: String,
    pub value: String,
    pub kind: RowKind,
}

fn info(label: impl Into<String>, value: impl Into<String>) -> Row {
    Row {
        label: label.into(),
        value: value.into(),
        kind: RowKind::Info,
    }
}

fn shape_text(s: &SectionShape) -> String {
    match s {
        SectionShape::Circle { r } => format!("circle r {r:.4}"),
        SectionShape::Ellipse { a, b, offset } => {
            format!("ellipse {a:.4} x {b:.4} off {offset:.3}")
        }
        SectionShape::Gec { x, .. } => format!("gec {} harmonics", x.len()),
    }
}

/// Rows for a part (`part` as edited: the stored part with the active edits
/// applied), transforms acting on `section` (None: all sections).
pub fn part_rows(part: &PartSpec, section: Option<usize>) -> Vec<Row> {
    let mut rows = match part.surface {
        SurfaceSpec::Pde6C2 { a, .. } => vec![
            info("surface", "pde6 C2 chain (paper 002)"),
            Row {
                label: "a".into(),
                value: format!("{a}"),
                kind: RowKind::ShapeA,
            },
        ],
        // families without an editable row: their parameters, read only
        ref other => vec![info("surface", other.describe())],
    };
    rows.push(info(
        "ends",
        format!(
            "start {}, end {}",
            if part.closed_start { "closed" } else { "open" },
            if part.closed_end { "closed" } else { "open" }
        ),
    ));
    for (i, s) in part.sections.iter().enumerate() {
        let mark = if section == Some(i) { "▸" } else { " " };
        rows.push(info(
            format!("{mark}sec {i}"),
            format!("u {:.3} y {:.3} {}", s.u, s.centre[1], shape_text(&s.shape)),
        ));
    }
    rows.push(Row {
        label: "section".into(),
        value: match section {
            None => "all".into(),
            Some(i) => format!("{i}"),
        },
        kind: RowKind::Section,
    });
    for (kind, label) in [
        (RowKind::Translate, "translate"),
        (RowKind::Scale, "scale"),
        (RowKind::Rotate, "rotate"),
        (RowKind::Bend, "bend"),
        (RowKind::Bump, "bump"),
        (RowKind::Force, "force"),
        (RowKind::Boundary, "boundary"),
        (RowKind::Plate, "plate"),
    ] {
        rows.push(Row {
            label: label.into(),
            value: format!("<{}>", kind.hint()),
            kind,
        });
    }
    rows
}

/// Rows for a transition or a removed part of `doc`.
pub fn other_rows(doc: &CharacterDoc, name: &str) -> Vec<Row> {
    if let Some(t) = doc.transitions().iter().find(|t| t.name == name) {
        let mut rows = vec![
            info("surface", "cubic Hermite blend (C1)"),
            info("parent", format!("{} ({:?} end)", t.parent, t.parent_end)),
            info("children", t.children.join(", ")),
        ];
        for (i, a) in t.seam_apex.iter().enumerate() {
            rows.push(info(
                format!("apex {i}"),
                format!("{:.3} {:.3} {:.3}", a[0], a[1], a[2]),
            ));
        }
        rows.push(info("edits", "none (transitions follow their parts)"));
        return rows;
    }
    if let Some(p) = doc.props().iter().find(|p| p.name == name) {
        return vec![
            info("prop", "conv model (paper 003), not stitched"),
            info("model", p.model.clone()),
            info(
                "translate",
                format!("{} {} {}", p.translate[0], p.translate[1], p.translate[2]),
            ),
            info("scale", format!("{}", p.scale)),
        ];
    }
    if doc.removed_parts().iter().any(|r| r.name == name) {
        return vec![info("removed", "recorded, not built in version 1")];
    }
    Vec::new()
}

fn numbers(text: &str, min: usize, max: usize) -> Result<Vec<f64>, String> {
    let words: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|w| !w.is_empty())
        .collect();
    if words.len() < min || words.len() > max {
        return Err(if min == max {
            format!("expected {min} number(s), got {}", words.len())
        } else {
            format!("expected {min} to {max} numbers, got {}", words.len())
        });
    }
    words
        .iter()
        .map(|w| match w.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(v) => Err(format!("'{w}' is not finite ({v})")),
            Err(_) => Err(format!("'{w}' is not a number")),
        })
        .collect()
}

/// What a typed value means.
#[derive(Clone, Debug, PartialEq)]
pub enum Parsed {
    /// An edit to push.
    Edit(Edit),
    /// A new section choice (None: all).
    Section(Option<usize>),
}

/// Parses `text` typed into a row of kind `kind` for `part`; errors say
/// what is wrong (shown as typed, never applied).
pub fn parse(
    kind: RowKind,
    text: &str,
    part: &PartSpec,
    section: Option<usize>,
) -> Result<Parsed, String> {
    let edit = match kind {
        RowKind::Info => return Err("this row is read-only".into()),
        RowKind::Section => return parse_section(text, part),
        RowKind::ShapeA => {
            let v = numbers(text, 1, 1)?;
            Edit::ShapeParameter {
                part: part.name.clone(),
                a: v[0],
            }
        }
        RowKind::Translate | RowKind::Scale | RowKind::Rotate | RowKind::Bend | RowKind::Bump => {
            Edit::GecTransform {
                part: part.name.clone(),
                section,
                transform: section_transform(kind, text)?,
            }
        }
        RowKind::Force => force_edit(text, part)?,
        RowKind::Boundary => boundary_edit(text, part)?,
        RowKind::Plate => {
            let v = numbers(text, 7, 7)?;
            Edit::Plate {
                part: part.name.clone(),
                centre: [v[0], v[1], v[2]],
                radius: v[3],
                d: [v[4], v[5], v[6]],
            }
        }
    };
    validate_params(&edit).map_err(|e| e.to_string())?;
    if let Edit::Force { u, .. } = &edit {
        let len = part.sections.last().map_or(0.0, |s| s.u);
        if u[0] < 0.0 || u[1] > len {
            return Err(format!(
                "u range [{}, {}] is not inside the part (u from 0 to {len:.4})",
                u[0], u[1]
            ));
        }
    }
    Ok(Parsed::Edit(edit))
}

/// The section row: `all` or the index of one of the part's sections.
fn parse_section(text: &str, part: &PartSpec) -> Result<Parsed, String> {
    let t = text.trim();
    if t == "all" {
        return Ok(Parsed::Section(None));
    }
    let i: usize = t
        .parse()
        .map_err(|_| format!("'{t}' is neither 'all' nor a section index"))?;
    if i >= part.sections.len() {
        return Err(format!(
            "section {i} does not exist ({} has {} sections)",
            part.name,
            part.sections.len()
        ));
    }
    Ok(Parsed::Section(Some(i)))
}

/// The section transform of a translate, scale, rotate (degrees), bend or
/// bump (angle in degrees) row.
fn section_transform(kind: RowKind, text: &str) -> Result<SectionTransform, String> {
    Ok(match kind {
        RowKind::Translate => {
            let v = numbers(text, 3, 3)?;
            SectionTransform::Translate {
                d: [v[0], v[1], v[2]],
            }
        }
        RowKind::Scale => {
            let v = numbers(text, 1, 2)?;
            SectionTransform::Scale {
                sx: v[0],
                sy: *v.get(1).unwrap_or(&v[0]),
            }
        }
        RowKind::Rotate => {
            let v = numbers(text, 1, 1)?;
            SectionTransform::Rotate {
                angle: v[0].to_radians(),
            }
        }
        RowKind::Bend => {
            let v = numbers(text, 1, 4)?;
            if v.len() != 1 && v.len() != 4 {
                return Err("expected kappa, or kappa and an axis of 3 numbers".into());
            }
            let axis = if v.len() == 4 {
                [v[1], v[2], v[3]]
            } else {
                [0.0, 0.0, 1.0]
            };
            SectionTransform::Bend { kappa: v[0], axis }
        }
        RowKind::Bump => {
            let v = numbers(text, 3, 3)?;
            SectionTransform::Bump {
                h: v[0],
                theta: v[1].to_radians(),
                sigma: v[2],
            }
        }
        _ => return Err(format!("a {kind:?} row is not a section transform")),
    })
}

/// The force row: `u0 u1 px py pz`, a uniform force over the u-range, or
/// with `uc vc` a concentrated one.
fn force_edit(text: &str, part: &PartSpec) -> Result<Edit, String> {
    let v = numbers(text, 5, 7)?;
    let kind = match v.len() {
        5 => ForceKind::Uniform,
        7 => ForceKind::Concentrated { u0: v[5], v0: v[6] },
        _ => return Err("expected u0 u1 px py pz, then optionally uc vc".into()),
    };
    Ok(Edit::Force {
        part: part.name.clone(),
        u: [v[0], v[1]],
        force: Force {
            kind,
            p: [v[2], v[3], v[4]],
        },
        a: 1.0,
    })
}

/// The boundary row: `start` or `end`, the tangent (3 numbers), optionally
/// the reach.
fn boundary_edit(text: &str, part: &PartSpec) -> Result<Edit, String> {
    let t = text.trim_start();
    let (end, rest) = if let Some(r) = t.strip_prefix("start") {
        (End::Start, r)
    } else if let Some(r) = t.strip_prefix("end") {
        (End::End, r)
    } else {
        return Err("begin with 'start' or 'end' (which end of the part)".into());
    };
    let v = numbers(rest, 3, 4)?;
    Ok(Edit::Boundary {
        part: part.name.clone(),
        end,
        curve: None,
        tangent: Some([v[0], v[1], v[2]]),
        reach: *v.get(3).unwrap_or(&0.3),
    })
}
