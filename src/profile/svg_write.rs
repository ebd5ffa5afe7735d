//! SVG output: profiles as an SVG document (unitless, or at a physical
//! size) and written atomically so that every file read back by
//! [`super::read_svg`]. The conventions are in the module docs of
//! [`crate::profile`].

use super::{Profile, ProfileError, View};
use std::fmt::Write as _;
use std::path::Path;

/// An SVG document with one closed `<path>` per profile (id = the view
/// name, `-2`, `-3`... appended on repeats), stroke only, with a `viewBox`
/// (and equal `width`/`height`) fitting every profile with a 5 % margin.
/// Coordinates follow the module conventions, printed so that they read
/// back exactly in f64 (usvg itself parses in f32). The page size is
/// unitless, so a reader of physical sizes takes a user unit for a CSS
/// pixel ([`super::units`]); [`to_svg_physical`] states the size.
pub fn to_svg(profiles: &[&Profile]) -> String {
    svg_document(profiles, None)
}

/// [`to_svg`] with the page's `width`/`height` in millimetres so that one
/// user unit (one model unit) is `metres_per_unit` metres when read back by
/// the physical-size rule ([`super::units`]).
pub fn to_svg_physical(profiles: &[&Profile], metres_per_unit: f64) -> String {
    svg_document(profiles, Some(metres_per_unit))
}

fn svg_document(profiles: &[&Profile], metres_per_unit: Option<f64>) -> String {
    let svg_pt = |v: View, p: [f64; 2]| if v.svg_y_flipped() { [p[0], -p[1]] } else { p };
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for pr in profiles {
        for &p in pr.points() {
            let q = svg_pt(pr.view(), p);
            for k in 0..2 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
    }
    if profiles.is_empty() {
        lo = [0.0; 2];
        hi = [1.0; 2];
    }
    let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let m = 0.05 * extent;
    let (x0, y0) = (lo[0] - m, lo[1] - m);
    let (w, h) = (hi[0] - lo[0] + 2.0 * m, hi[1] - lo[1] + 2.0 * m);
    let mut s = String::new();
    let _ = writeln!(s, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let (pw, ph) = match metres_per_unit {
        Some(m) => (format!("{}mm", 1e3 * m * w), format!("{}mm", 1e3 * m * h)),
        None => (w.to_string(), h.to_string()),
    };
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{pw}" height="{ph}" viewBox="{x0} {y0} {w} {h}">"#
    );
    let mut used: Vec<View> = Vec::new();
    for pr in profiles {
        let v = pr.view();
        used.push(v);
        let k = used.iter().filter(|&&u| u == v).count();
        let id = if k == 1 {
            v.name().to_string()
        } else {
            format!("{}-{k}", v.name())
        };
        let _ = write!(
            s,
            r#"  <path id="{id}" fill="none" stroke="black" stroke-width="{}" d=""#,
            extent * 2e-3
        );
        for (i, &p) in pr.points().iter().enumerate() {
            let q = svg_pt(v, p);
            let _ = write!(s, "{}{} {}", if i == 0 { "M" } else { " L" }, q[0], q[1]);
        }
        let _ = writeln!(s, r#" Z"/>"#);
    }
    s.push_str("</svg>\n");
    s
}

/// Writes [`to_svg_physical`] atomically (temporary file, then rename):
/// one model unit is `metres_per_unit` metres on the page. Refuses
/// profiles that the SVG readers would refuse (a coordinate beyond the
/// drawing range [`crate::limits::DRAWING_SIZE`]), so that every SVG
/// written reads back.
pub fn write_svg(
    path: &Path,
    profiles: &[&Profile],
    metres_per_unit: f64,
) -> Result<(), ProfileError> {
    let range = crate::limits::DRAWING_SIZE;
    for pr in profiles {
        let reach = pr
            .points()
            .iter()
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        if reach.is_nan() || reach > range.max {
            return Err(ProfileError::DrawingSize {
                size: reach,
                what: format!("the {} outline's largest coordinate", pr.view().name()),
                min: range.min,
                max: range.max,
            });
        }
    }
    let text = to_svg_physical(profiles, metres_per_unit);
    crate::mesh::io::write_atomic(path, text.as_bytes()).map_err(|e| match e {
        crate::mesh::MeshError::Io { path, source } => ProfileError::Io { path, source },
        e => ProfileError::Mesh(e),
    })
}
