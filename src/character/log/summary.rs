//! One line per edit, for `character log` and the TUI.

use super::{Edit, SectionTransform};
use crate::limits::Num;

/// A number as error messages show it (`1e30`, not 31 digits).
fn n(x: f64) -> Num {
    Num(x)
}

/// A vector as `(x, y, z)` of [`n`]s.
fn v3(v: &[f64; 3]) -> String {
    format!("({}, {}, {})", n(v[0]), n(v[1]), n(v[2]))
}

/// A range as `[a, b]` of [`n`]s.
fn r2(r: &[f64; 2]) -> String {
    format!("[{}, {}]", n(r[0]), n(r[1]))
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
                let t = transform_summary(transform);
                format!("GEC {t}: {which}")
            }
            Edit::Force { part, u, force, a } => format!(
                "force {:?} p = {} on {part} over u in {}, a = {}",
                force.kind,
                v3(&force.p),
                r2(u),
                n(*a)
            ),
            Edit::ForceRegion {
                part,
                u,
                theta,
                force,
                a,
            } => format!(
                "4-sided force {:?} p = {} on {part} inside u in {}, theta in {}, a = {}",
                force.kind,
                v3(&force.p),
                r2(u),
                r2(theta),
                n(*a)
            ),
            Edit::ForceStroke {
                part,
                stroke,
                corners,
                force,
                a,
            } => format!(
                "4-sided force {:?} p = {} on {part} inside a stroke of {} points{}, a = {}",
                force.kind,
                v3(&force.p),
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
                    what.push(format!("tangent change {}", v3(t)));
                }
                format!("boundary of {part} at its {end:?}: {}", what.join(", "))
            }
            Edit::Plate {
                part,
                centre,
                radius,
                d,
            } => format!(
                "plate bend of {part} within {} of {} by {}",
                n(*radius),
                v3(centre),
                v3(d)
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

/// One GEC section transform in words.
fn transform_summary(transform: &SectionTransform) -> String {
    match transform {
        SectionTransform::Translate { d } => format!("translate by {}", v3(d)),
        SectionTransform::Scale { sx, sy } => {
            format!("scale by ({}, {})", n(*sx), n(*sy))
        }
        SectionTransform::Rotate { angle } => format!("rotate by {} rad", n(*angle)),
        SectionTransform::Bend { kappa, axis } => {
            format!("bend with curvature {} about {}", n(*kappa), v3(axis))
        }
        SectionTransform::Bump { h, theta, sigma } => {
            format!(
                "bump of height {} at {} rad, width {}",
                n(*h),
                n(*theta),
                n(*sigma)
            )
        }
    }
}
