//! Limits before work for SVG drawings (issue 35): what the reader may
//! open, how many nodes and shapes it accepts, which numbers it accepts,
//! and how many points flattening may produce, all decided before any
//! curve is flattened.
//!
//! * No external resources: `<image>` references (files, data URLs,
//!   nested SVGs) are never resolved, so reading a drawing opens no file
//!   but the drawing itself (usvg is built without text, so no font is
//!   looked up either). The XML reader resolves no external entity.
//! * [`check_numbers`]: every number of the geometric attributes (`d`,
//!   `points`, `transform`, `x`, `cx`, `r`, ...) must be finite and within
//!   the 32-bit float range usvg computes in; NaN, infinity, `1e39` and a
//!   chain of transforms whose product overflows are named with their
//!   element and attribute (usvg would otherwise drop the shape silently,
//!   and the drawing would have "no closed outline").
//! * [`estimate_points`]: an upper estimate of the points kurbo's
//!   flattening emits for a path, from each curve's control polygon
//!   length `L` and the tolerance `t`: `1 + ceil(sqrt(L / t))` per curve
//!   (a parabola of chord deviation `t` needs `sqrt(|p0 - 2 p1 + p2| /
//!   (4 t))` pieces and `|p0 - 2 p1 + p2| <= L`; kurbo's parabola-based
//!   subdivision needs no more; `tests/it/profile_guard.rs` checks the
//!   bound against kurbo on random and extreme curves).

use super::ProfileError;
use crate::limits::{DRAWING_SIZE, SVG_NODES, SVG_POINTS, SVG_SHAPES};
use kurbo::{BezPath, PathEl, Point};
use usvg::roxmltree;

/// XML options: DTDs allowed (inkscape files carry them; roxmltree bounds
/// entity expansion and resolves no external entity), a node limit.
pub(super) fn xml_options<'a>() -> roxmltree::ParsingOptions<'a> {
    roxmltree::ParsingOptions {
        allow_dtd: true,
        nodes_limit: SVG_NODES.max as u32,
        ..Default::default()
    }
}

/// usvg options that resolve no `<image>` reference.
pub(super) fn usvg_options() -> usvg::Options<'static> {
    usvg::Options {
        image_href_resolver: usvg::ImageHrefResolver {
            resolve_data: Box::new(|_, _, _| None),
            resolve_string: Box::new(|_, _| None),
        },
        ..usvg::Options::default()
    }
}

/// An XML parse error, with the node limit named.
pub(super) fn xml_error(e: roxmltree::Error) -> ProfileError {
    match e {
        roxmltree::Error::NodesLimitReached => {
            ProfileError::Limit(crate::limits::LimitError::OutOfRange {
                param: "XML nodes".into(),
                value: format!("more than {}", SVG_NODES.max),
                min: SVG_NODES.min,
                max: SVG_NODES.max,
                why: SVG_NODES.why,
            })
        }
        e => ProfileError::Svg {
            message: e.to_string(),
        },
    }
}

/// Attributes whose numbers place geometry.
const GEOMETRY_ATTRIBUTES: &[&str] = &[
    "d",
    "points",
    "transform",
    "x",
    "y",
    "width",
    "height",
    "cx",
    "cy",
    "r",
    "rx",
    "ry",
    "x1",
    "y1",
    "x2",
    "y2",
];

/// Product of the transform bounds along an element's ancestors past which
/// coordinates may overflow 32-bit floats (no real drawing comes near).
const TRANSFORM_PRODUCT_MAX: f64 = 1e30;

/// How an element is named in messages: `<path id="body">` or `<path> at
/// line 12`.
fn element_name(doc: &roxmltree::Document, n: roxmltree::Node) -> String {
    match n.attribute("id") {
        Some(id) if !id.is_empty() => format!("<{} id={id:?}>", n.tag_name().name()),
        _ => {
            let pos = doc.text_pos_at(n.range().start);
            format!("<{}> at line {}", n.tag_name().name(), pos.row)
        }
    }
}

/// The numbers of an attribute value: `Err(token)` for a token that is not
/// a finite number of f32 range (NaN, inf, 1e39).
fn numbers(value: &str) -> Result<Vec<f64>, (String, &'static str)> {
    let b = value.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_alphabetic() {
            let start = i;
            while i < b.len() && b[i].is_ascii_alphabetic() {
                i += 1;
            }
            let word = value[start..i].to_ascii_lowercase();
            if word.contains("nan") || word.contains("inf") {
                return Err((value[start..i].to_string(), "not a finite number"));
            }
            continue;
        }
        if c.is_ascii_digit() || c == b'.' || ((c == b'-' || c == b'+') && i + 1 < b.len()) {
            let start = i;
            if c == b'-' || c == b'+' {
                i += 1;
            }
            let mut digits = false;
            let mut dot = false;
            while i < b.len() && (b[i].is_ascii_digit() || (b[i] == b'.' && !dot)) {
                digits |= b[i].is_ascii_digit();
                dot |= b[i] == b'.';
                i += 1;
            }
            if digits && i + 1 < b.len() && (b[i] == b'e' || b[i] == b'E') {
                let mut j = i + 1;
                if j < b.len() && (b[j] == b'-' || b[j] == b'+') {
                    j += 1;
                }
                if j < b.len() && b[j].is_ascii_digit() {
                    while j < b.len() && b[j].is_ascii_digit() {
                        j += 1;
                    }
                    i = j;
                }
            }
            if !digits {
                i = start + 1;
                continue;
            }
            let token = &value[start..i];
            match token.parse::<f64>() {
                Ok(x) if x.abs() <= f32::MAX as f64 => out.push(x),
                _ => {
                    return Err((
                        token.to_string(),
                        "beyond the 32-bit float range of the SVG reader (|x| <= 3.4e38)",
                    ))
                }
            }
            continue;
        }
        i += 1;
    }
    Ok(out)
}

/// Refuses a drawing with a non-finite or f32-overflowing number in a
/// geometric attribute, or transforms whose product may overflow.
pub(super) fn check_numbers(doc: &roxmltree::Document) -> Result<(), ProfileError> {
    for n in doc.descendants().filter(|n| n.is_element()) {
        let mut transform_bound = None;
        for a in n.attributes() {
            if !GEOMETRY_ATTRIBUTES.contains(&a.name()) {
                continue;
            }
            let xs = numbers(a.value()).map_err(|(token, why)| ProfileError::BadNumber {
                element: element_name(doc, n),
                attribute: a.name().to_string(),
                token,
                why,
            })?;
            if a.name() == "transform" {
                transform_bound = Some(1.0 + xs.iter().map(|x| x.abs()).sum::<f64>());
            }
        }
        if transform_bound.is_some() {
            let product: f64 = n
                .ancestors()
                .filter_map(|m| m.attribute("transform"))
                .map(|t| {
                    1.0 + numbers(t)
                        .unwrap_or_default()
                        .iter()
                        .map(|x| x.abs())
                        .sum::<f64>()
                })
                .product();
            if product > TRANSFORM_PRODUCT_MAX {
                return Err(ProfileError::BadNumber {
                    element: element_name(doc, n),
                    attribute: "transform".into(),
                    token: n.attribute("transform").unwrap_or("").to_string(),
                    why: "with its ancestors' transforms it may scale coordinates past the 32-bit float range",
                });
            }
        }
    }
    Ok(())
}

/// An upper estimate of the points kurbo's flattening of `b` at
/// `tolerance` emits (see the module docs).
pub fn estimate_points(b: &BezPath, tolerance: f64) -> f64 {
    let mut last = Point::ZERO;
    let mut n = 0.0;
    let curve = |len: f64| 1.0 + (len / tolerance).sqrt().ceil();
    for el in b.elements() {
        match *el {
            PathEl::MoveTo(p) | PathEl::LineTo(p) => {
                n += 1.0;
                last = p;
            }
            PathEl::QuadTo(p1, p2) => {
                n += curve(last.distance(p1) + p1.distance(p2));
                last = p2;
            }
            PathEl::CurveTo(p1, p2, p3) => {
                n += curve(last.distance(p1) + p1.distance(p2) + p2.distance(p3));
                last = p3;
            }
            PathEl::ClosePath => n += 1.0,
        }
    }
    n
}

/// Points of an exact ellipse `c + A cos t + B sin t` flattened so that
/// every chord is within `tolerance` (chord error of a step `dt` at most
/// `(|A| + |B|) dt^2 / 8`), at least 8.
pub(super) fn ellipse_points(size: f64, tolerance: f64) -> f64 {
    let dt = (8.0 * tolerance / size).sqrt();
    (2.0 * std::f64::consts::PI / dt).ceil().max(8.0)
}

/// One shape before flattening: its name, control points (for bounds) and
/// estimated flattened points.
pub(super) struct Planned {
    pub id: String,
    pub lo: [f64; 2],
    pub hi: [f64; 2],
    pub estimate: f64,
}

impl Planned {
    /// Bounds of the control points of `b` (NaN-propagating).
    pub fn of_path(id: String, b: &BezPath, tolerance: f64) -> Planned {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        let mut finite = true;
        for el in b.elements() {
            for p in el_points(el) {
                finite &= p.x.is_finite() && p.y.is_finite();
                lo = [lo[0].min(p.x), lo[1].min(p.y)];
                hi = [hi[0].max(p.x), hi[1].max(p.y)];
            }
        }
        if !finite {
            lo = [f64::NAN; 2];
        }
        Planned {
            id,
            lo,
            hi,
            estimate: estimate_points(b, tolerance),
        }
    }
}

fn el_points(el: &PathEl) -> Vec<Point> {
    match *el {
        PathEl::MoveTo(p) | PathEl::LineTo(p) => vec![p],
        PathEl::QuadTo(a, b) => vec![a, b],
        PathEl::CurveTo(a, b, c) => vec![a, b, c],
        PathEl::ClosePath => vec![],
    }
}

/// Checks the plan of every shape before flattening: the number of
/// shapes, finite coordinates within the drawing range, the drawing's
/// size, and the total point estimate.
pub(super) fn check_plan(shapes: &[Planned], tolerance: f64) -> Result<(), ProfileError> {
    if shapes.is_empty() {
        return Err(ProfileError::NoOutline);
    }
    crate::limits::check("shapes of the SVG drawing", shapes.len(), SVG_SHAPES)?;
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for s in shapes {
        if !(s.lo.iter().chain(&s.hi).all(|x| x.is_finite())) {
            return Err(ProfileError::Shape {
                id: s.id.clone(),
                message: "a coordinate is not finite after its transforms".into(),
            });
        }
        let reach = s.lo.iter().chain(&s.hi).fold(0.0f64, |m, x| m.max(x.abs()));
        if reach > DRAWING_SIZE.max {
            return Err(ProfileError::Shape {
                id: s.id.clone(),
                message: format!(
                    "reaches a coordinate of {} user units after its transforms, beyond the drawing range of +-{} user units: scale the drawing down on the page (the model's size is the drawing's physical size, or give --height)",
                    crate::limits::Num(reach),
                    crate::limits::Num(DRAWING_SIZE.max)
                ),
            });
        }
        lo = [lo[0].min(s.lo[0]), lo[1].min(s.lo[1])];
        hi = [hi[0].max(s.hi[0]), hi[1].max(s.hi[1])];
    }
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    if size < DRAWING_SIZE.min {
        return Err(ProfileError::DrawingSize {
            size,
            what: "the bounding box of every shape".into(),
            min: DRAWING_SIZE.min,
            max: DRAWING_SIZE.max,
        });
    }
    let total: f64 = shapes.iter().map(|s| s.estimate).sum();
    if total.is_nan() || total > SVG_POINTS.max as f64 {
        let largest = shapes
            .iter()
            .max_by(|a, b| a.estimate.total_cmp(&b.estimate))
            .map(|s| (s.id.clone(), s.estimate))
            .unwrap_or_default();
        return Err(ProfileError::TooManyPoints {
            tolerance,
            estimate: total,
            largest: largest.0,
            largest_estimate: largest.1,
            limit: SVG_POINTS.max,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_refuses_nan_inf_and_f32_overflow_by_token() {
        assert_eq!(
            numbers("M0,0 L1e3-2.5.5Z"),
            Ok(vec![0.0, 0.0, 1e3, -2.5, 0.5])
        );
        assert_eq!(
            numbers("translate(1 2) scale(3e-2)"),
            Ok(vec![1.0, 2.0, 3e-2])
        );
        assert_eq!(numbers("M 0 0 L NaN 1").map_err(|e| e.0), Err("NaN".into()));
        assert_eq!(numbers("scale(inf)").map_err(|e| e.0), Err("inf".into()));
        assert_eq!(
            numbers("M 0 0 L 1e39 1").map_err(|e| e.0),
            Err("1e39".into())
        );
    }
}
