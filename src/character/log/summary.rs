//! One line per edit, for `character log` and the TUI.

use super::{Edit, SectionTransform};
use crate::limits::Num;

/// A number as error messages show it (`1e30`, not 31 digits).
fn n(x: f64) -> Num {
    Num(x)
}

impl Edit {
    /// One line for `character log` and the TUI.
    pub fn summary(&self) -> String {
        match self {
            Edit::ShapeParameter { part, a } => format!("shape parameter of {part}: a = {}", n(*a)),
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
                        format!("translate by ({}, {}, {})", n(d[0]), n(d[1]), n(d[2]))
                    }
                    SectionTransform::Scale { sx, sy } => format!("scale by ({}, {})", n(*sx), n(*sy)),
                    SectionTransform::Rotate { angle } => format!("rotate by {} rad", n(*angle)),
                    SectionTransform::Bend { kappa, axis } => format!(
                        "bend with curvature {} about ({}, {}, {})",
                        n(*kappa),
                        n(axis[0]),
                        n(axis[1]),
                        n(axis[2])
                    ),
                    SectionTransform::Bump { h, theta, sigma } => {
                        format!("bump of height {} at {} rad, width {}", n(*h), n(*theta), n(*sigma))
                    }
                };
                format!("GEC {t}: {which}")
            }
            Edit::Force { part, u, force, a } => format!(
                "force {:?} p = ({}, {}, {}) on {part} over u in [{}, {}], a = {}",
                force.kind,
                n(force.p[0]),
                n(force.p[1]),
                n(force.p[2]),
                n(u[0]),
                n(u[1]),
                n(*a)
            ),
            Edit::ForceRegion {
                part,
                u,
                theta,
                force,
                a,
            } => format!(
                "4-sided force {:?} p = ({}, {}, {}) on {part} inside u in [{}, {}], theta in [{}, {}], a = {}",
                force.kind,
                n(force.p[0]),
                n(force.p[1]),
                n(force.p[2]),
                n(u[0]),
                n(u[1]),
                n(theta[0]),
                n(theta[1]),
                n(*a)
            ),
            Edit::ForceStroke {
                part,
                stroke,
                corners,
                force,
                a,
            } => format!(
                "4-sided force {:?} p = ({}, {}, {}) on {part} inside a stroke of {} points{}, a = {}",
                force.kind,
                n(force.p[0]),
                n(force.p[1]),
                n(force.p[2]),
                stroke.len(),
                match corners {
                    Some(c) => format!(" (corners {}, {}, {}, {})", c[0], c[1], c[2], c[3]),
                    None => String::new(),
                },
                n(*a)
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
                    what.push(format!("tangent change ({}, {}, {})", n(t[0]), n(t[1]), n(t[2])));
                }
                format!("boundary of {part} at its {end:?}: {}", what.join(", "))
            }
            Edit::Plate {
                part,
                centre,
                radius,
                d,
            } => format!(
                "plate bend of {part} within {} of ({}, {}, {}) by ({}, {}, {})",
                n(*radius),
                n(centre[0]),
                n(centre[1]),
                n(centre[2]),
                n(d[0]),
                n(d[1]),
                n(d[2])
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
