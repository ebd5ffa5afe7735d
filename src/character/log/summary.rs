//! One line per edit, for `character log` and the TUI.

use super::{Edit, SectionTransform};

impl Edit {
    /// One line for `character log` and the TUI.
    pub fn summary(&self) -> String {
        match self {
            Edit::ShapeParameter { part, a } => format!("shape parameter of {part}: a = {a}"),
            Edit::GecTransform {
                part,
                section,
                transform,
            } => {
                let which = match section {
                    Some(s) => format!("section {s} of {part}"),
                    None => format!("all sections of {part}"),
                };
                let t = match transform {
                    SectionTransform::Translate { d } => {
                        format!("translate by ({}, {}, {})", d[0], d[1], d[2])
                    }
                    SectionTransform::Scale { sx, sy } => format!("scale by ({sx}, {sy})"),
                    SectionTransform::Rotate { angle } => format!("rotate by {angle} rad"),
                    SectionTransform::Bend { kappa, axis } => format!(
                        "bend with curvature {kappa} about ({}, {}, {})",
                        axis[0], axis[1], axis[2]
                    ),
                    SectionTransform::Bump { h, theta, sigma } => {
                        format!("bump of height {h} at {theta} rad, width {sigma}")
                    }
                };
                format!("GEC {t}: {which}")
            }
            Edit::Force { part, u, force, a } => format!(
                "force {:?} p = ({}, {}, {}) on {part} over u in [{}, {}], a = {a}",
                force.kind, force.p[0], force.p[1], force.p[2], u[0], u[1]
            ),
            Edit::ForceRegion {
                part,
                u,
                theta,
                force,
                a,
            } => format!(
                "4-sided force {:?} p = ({}, {}, {}) on {part} inside u in [{}, {}], theta in [{}, {}], a = {a}",
                force.kind, force.p[0], force.p[1], force.p[2], u[0], u[1], theta[0], theta[1]
            ),
            Edit::ForceStroke {
                part,
                stroke,
                corners,
                force,
                a,
            } => format!(
                "4-sided force {:?} p = ({}, {}, {}) on {part} inside a stroke of {} points{}, a = {a}",
                force.kind,
                force.p[0],
                force.p[1],
                force.p[2],
                stroke.len(),
                match corners {
                    Some(c) => format!(" (corners {}, {}, {}, {})", c[0], c[1], c[2], c[3]),
                    None => String::new(),
                }
            ),
            Edit::Boundary {
                part,
                end,
                curve,
                tangent,
                ..
            } => {
                let mut what = Vec::new();
                if curve.is_some() {
                    what.push("new curve".to_string());
                }
                if let Some(t) = tangent {
                    what.push(format!("tangent change ({}, {}, {})", t[0], t[1], t[2]));
                }
                format!("boundary of {part} at its {end:?}: {}", what.join(", "))
            }
            Edit::Plate {
                part,
                centre,
                radius,
                d,
            } => format!(
                "plate bend of {part} within {radius} of ({}, {}, {}) by ({}, {}, {})",
                centre[0], centre[1], centre[2], d[0], d[1], d[2]
            ),
            Edit::Sasm(s) => format!(
                "SASM on {}: closed curve of {} points ({} view) + {} profile(s)",
                s.part,
                s.curve.points.len(),
                s.curve.view,
                s.profiles.len()
            ),
            Edit::SasmAux(s) => format!(
                "SASM on {}: auxiliary line of {} points ({} view, mirrored about {}) + {} profile",
                s.part,
                s.line.points.len(),
                s.line.view,
                s.mirror,
                s.profile.view
            ),
        }
    }
}
