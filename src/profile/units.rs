//! The physical size of an SVG drawing: how many metres one user unit is.
//!
//! The rule (CSS Values 3 absolute lengths, SVG 1.1 sec 7.7 "The viewBox
//! attribute" and sec 7.8 "The preserveAspectRatio attribute"), read from the
//! root `<svg>` element only:
//!
//! | root element | one user unit |
//! |---|---|
//! | `viewBox="x y w h"` with `width="W"` and `height="H"` | `W / w` along x, `H / h` along y, then `preserveAspectRatio`: the smaller of the two (`meet`, the default), the larger (`slice`), or each its own (`none`) |
//! | `viewBox` with only `width` (or only `height`) | `W / w` (`H / h`) on both axes: the other length follows the viewBox's aspect |
//! | no `viewBox` | one CSS pixel (`1/96 in`) whatever `width`/`height` say (they only size the page) |
//! | `viewBox`, neither `width` nor `height` | one CSS pixel, as Inkscape reads such a file (the SVG default `100%` has no absolute size) |
//!
//! Lengths: `mm`, `cm`, `in`, `pt`, `pc`, `px`, a bare number is `px`
//! ([`crate::mesh::unit::svg_length_metres`]); `%` is treated as absent.
//! `em`/`ex` or an unknown unit is an error naming the attribute, as is a
//! malformed or non-positive `viewBox`.

use super::ProfileError;
use crate::mesh::unit::svg_length_metres;
use serde::Serialize;
use usvg::roxmltree;

/// One CSS pixel in metres (1 in = 96 px = 25.4 mm).
pub const PX_METRES: f64 = 0.0254 / 96.0;

/// The size of one user unit of an SVG document.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DocumentUnits {
    /// Metres per user unit along SVG x and y (equal unless
    /// `preserveAspectRatio="none"` with a page of another aspect).
    pub metres_per_unit: [f64; 2],
    /// The unit the page size is written in (`"mm"`, `"in"`, `"px"`, ...),
    /// `"px"` when the document gives none.
    pub unit: String,
    /// Which row of the rule applied, in words, for reports.
    pub rule: String,
}

impl DocumentUnits {
    /// One CSS pixel per user unit.
    pub fn pixels(rule: &str) -> DocumentUnits {
        DocumentUnits {
            metres_per_unit: [PX_METRES; 2],
            unit: "px".into(),
            rule: rule.into(),
        }
    }

    /// The larger of the two scales (a tolerance in metres divided by it is
    /// a tolerance in user units that holds on both axes).
    pub fn max_scale(&self) -> f64 {
        self.metres_per_unit[0].max(self.metres_per_unit[1])
    }
}

fn bad(attribute: &str, value: &str, reason: impl Into<String>) -> ProfileError {
    ProfileError::DocumentSize {
        attribute: attribute.into(),
        value: value.into(),
        reason: reason.into(),
    }
}

/// An absolute length, `None` when absent or a percentage.
fn length(node: roxmltree::Node, name: &str) -> Result<Option<(f64, String)>, ProfileError> {
    let Some(v) = node.attribute(name) else {
        return Ok(None);
    };
    let t = v.trim();
    if t.is_empty() || t.ends_with('%') || t == "auto" {
        return Ok(None);
    }
    let m = svg_length_metres(t).map_err(|e| bad(name, v, e.to_string()))?;
    let digits = t.trim_end_matches(|c: char| c.is_ascii_alphabetic());
    let unit = t[digits.len()..].to_ascii_lowercase();
    Ok(Some((m, if unit.is_empty() { "px".into() } else { unit })))
}

fn view_box(node: roxmltree::Node) -> Result<Option<[f64; 4]>, ProfileError> {
    let Some(v) = node.attribute("viewBox") else {
        return Ok(None);
    };
    let nums: Vec<f64> = v
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|s| !s.is_empty())
        .map(|s| s.parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| bad("viewBox", v, "not four numbers"))?;
    match nums[..] {
        [x, y, w, h] if [x, y, w, h].iter().all(|a| a.is_finite()) && w > 0.0 && h > 0.0 => {
            Ok(Some([x, y, w, h]))
        }
        [_, _, _, _] => Err(bad(
            "viewBox",
            v,
            "width and height must be positive and finite",
        )),
        _ => Err(bad("viewBox", v, "not four numbers")),
    }
}

/// The size of one user unit of the document whose root element is `root`
/// (see the module docs).
pub fn document_units(root: roxmltree::Node) -> Result<DocumentUnits, ProfileError> {
    let (w, h) = (length(root, "width")?, length(root, "height")?);
    let Some([_, _, vw, vh]) = view_box(root)? else {
        let mut u = DocumentUnits::pixels("no viewBox: one user unit is one CSS pixel");
        if let Some((_, unit)) = w.as_ref().or(h.as_ref()) {
            u.unit = unit.clone();
        }
        return Ok(u);
    };
    let (sx, sy, unit) = match (&w, &h) {
        (Some((wm, u)), Some((hm, _))) => (wm / vw, hm / vh, u.clone()),
        (Some((wm, u)), None) => (wm / vw, wm / vw, u.clone()),
        (None, Some((hm, u))) => (hm / vh, hm / vh, u.clone()),
        (None, None) => {
            return Ok(DocumentUnits::pixels(
                "viewBox without width or height: one user unit is one CSS pixel",
            ))
        }
    };
    let par = root.attribute("preserveAspectRatio").unwrap_or("").trim();
    let (scale, how) = if par.starts_with("none") {
        ([sx, sy], "preserveAspectRatio none")
    } else if par.ends_with("slice") {
        ([sx.max(sy); 2], "slice: the larger scale")
    } else {
        ([sx.min(sy); 2], "meet: the smaller scale")
    };
    Ok(DocumentUnits {
        metres_per_unit: scale,
        unit,
        rule: format!(
            "width {} / height {} over viewBox {vw} x {vh} ({how})",
            root.attribute("width").unwrap_or("-"),
            root.attribute("height").unwrap_or("-")
        ),
    })
}
