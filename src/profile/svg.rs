//! SVG input (parsed by usvg, curves flattened by kurbo; the output is in
//! `svg_write`). The conventions are in the module docs of
//! [`crate::profile`].

use super::svg_guard::{self, Planned};
use super::svg_layers::ViewLayers;
use super::units::DocumentUnits;
use super::{Profile, ProfileError, View};
use kurbo::{BezPath, PathEl, Point};
use serde::{Deserialize, Serialize};
use std::path::Path;
use usvg::roxmltree;

/// A sketch read from SVG: the closed outline and the optional cuts, in
/// user units, and the document's physical size of one user unit.
#[derive(Clone, Debug, PartialEq)]
pub struct SvgSketch {
    pub outline: Profile,
    pub cuts: Vec<Cut>,
    /// Metres per user unit ([`super::units`]).
    pub units: DocumentUnits,
}

/// How finely curves are flattened.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Flatness {
    /// Within this many user units.
    UserUnits(f64),
    /// Within this many metres of the drawing's physical size.
    Metres(f64),
    /// Within this fraction of the height of the drawing's bounding box
    /// (every shape, transforms applied).
    OfHeight(f64),
}

/// An open polyline whose SVG id starts with `cut` (an explicit part
/// boundary), in profile coordinates of the sketch's view.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Cut {
    pub id: String,
    pub points: Vec<[f64; 2]>,
}

/// Reads an SVG sketch; see [`parse_svg`]. Only a regular file is read
/// (a FIFO or device is refused without blocking), at most
/// [`crate::limits::INPUT_BYTES`].
pub fn read_svg(path: &Path, view: View, tolerance: f64) -> Result<SvgSketch, ProfileError> {
    read_svg_with(path, view, Flatness::UserUnits(tolerance))
}

/// Reads an SVG sketch; see [`parse_svg_with`]. Only a regular file is
/// read, at most [`crate::limits::INPUT_BYTES`].
pub fn read_svg_with(
    path: &Path,
    view: View,
    flatness: Flatness,
) -> Result<SvgSketch, ProfileError> {
    let text = crate::mesh::io::read_input_text(path, "SVG drawing").map_err(|e| match e {
        crate::mesh::MeshError::Io { path, source } => ProfileError::Io { path, source },
        e => ProfileError::Input(e),
    })?;
    parse_svg_with(&text, view, flatness)
}

/// A flattened subpath in model-oriented SVG user units (transforms
/// applied, y still down).
struct Subpath {
    id: String,
    points: Vec<[f64; 2]>,
    closed: bool,
}

/// Parses an SVG sketch drawn in `view`: exactly one closed outline plus
/// any cuts (ids starting with `cut`); curves flattened to within
/// `tolerance` model units. Errors: see the module docs.
pub fn parse_svg(text: &str, view: View, tolerance: f64) -> Result<SvgSketch, ProfileError> {
    parse_svg_with(text, view, Flatness::UserUnits(tolerance))
}

/// [`parse_svg`] with the flattening tolerance given as a [`Flatness`].
pub fn parse_svg_with(
    text: &str,
    view: View,
    flatness: Flatness,
) -> Result<SvgSketch, ProfileError> {
    let tolerance = match flatness {
        Flatness::UserUnits(t) | Flatness::Metres(t) | Flatness::OfHeight(t) => t,
    };
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(ProfileError::InvalidParameter {
            message: format!(
                "the flattening tolerance must be finite and positive, got {tolerance}"
            ),
        });
    }
    let (subpaths, units, layers) = flattened_subpaths(text, view, flatness)?;
    let to_model = |p: [f64; 2]| {
        if view.svg_y_flipped() {
            [p[0], -p[1]]
        } else {
            p
        }
    };
    let mut cuts = Vec::new();
    let mut outlines: Vec<Subpath> = Vec::new();
    for s in subpaths {
        if s.id.starts_with("cut") {
            if s.closed {
                return Err(ProfileError::ClosedCut { id: s.id });
            }
            cuts.push(Cut {
                id: s.id,
                points: s.points.into_iter().map(to_model).collect(),
            });
        } else if s.closed {
            outlines.push(s);
        } else {
            return Err(ProfileError::OpenPath { id: s.id });
        }
    }
    match outlines.len() {
        0 => Err(layers.no_outline(view)),
        1 => {
            let s = outlines.pop().unwrap_or_else(|| unreachable!());
            let outline = Profile::new(view, s.points.into_iter().map(to_model).collect())?;
            Ok(SvgSketch {
                outline,
                cuts,
                units,
            })
        }
        _ => Err(ProfileError::SeveralOutlines {
            ids: outlines.into_iter().map(|s| s.id).collect(),
        }),
    }
}

/// Id given to `circle`/`ellipse` elements that have none, so that their
/// usvg paths can be recognised (followed by a counter).
const ELLIPSE_ID: &str = "pdesculpt-ellipse-";

/// Every subpath of every shape in document order, flattened, with its
/// absolute transform applied. Shapes without an id are named
/// `<shape N>` (N counts shapes from 1); a shape with several subpaths
/// gives `id (subpath K)`.
///
/// Edits of the XML text (never of path data) before usvg sees it: the
/// groups naming another view than `view` are left out
/// ([`super::svg_layers`]; returned, to name the layer read in an error), the root `viewBox` is blanked (the points stay in user units, the canvas maps
/// user space by the identity; the physical size of a user unit is read
/// from the root element by [`super::units::document_units`]), and
/// `circle`/`ellipse` elements without an id get one, so that they are
/// flattened from their exact conic rather than from usvg's cubic
/// approximation.
fn flattened_subpaths(
    text: &str,
    view: View,
    flatness: Flatness,
) -> Result<(Vec<Subpath>, DocumentUnits, ViewLayers), ProfileError> {
    let svg_err = |e: &dyn std::fmt::Display| ProfileError::Svg {
        message: e.to_string(),
    };
    let doc = roxmltree::Document::parse_with_options(text, svg_guard::xml_options())
        .map_err(svg_guard::xml_error)?;
    svg_guard::check_numbers(&doc)?;
    let units = super::units::document_units(doc.root_element())?;
    let layers = super::svg_layers::select(&doc, view)?;
    // (position, bytes removed, text inserted), in document order
    let mut edits: Vec<(usize, usize, String)> = layers
        .removed
        .iter()
        .chain(&layers.shown)
        .map(|r| (r.start, r.len(), String::new()))
        .collect();
    if let Some(a) = doc
        .root_element()
        .attributes()
        .find(|a| a.name() == "viewBox")
    {
        let r = a.range();
        edits.push((r.start, r.len(), String::new()));
    }
    let ellipses = name_ellipses(&doc, text, &layers, &mut edits);
    let edited;
    let doc = if edits.is_empty() {
        doc
    } else {
        edited = splice(text, &mut edits);
        roxmltree::Document::parse_with_options(&edited, svg_guard::xml_options())
            .map_err(svg_guard::xml_error)?
    };
    let tree =
        usvg::Tree::from_xmltree(&doc, &svg_guard::usvg_options()).map_err(|e| svg_err(&e))?;
    let tolerance = match flatness {
        Flatness::UserUnits(t) => t,
        Flatness::Metres(t) => t / units.max_scale(),
        Flatness::OfHeight(r) => {
            let h = tree.root().abs_bounding_box().height() as f64;
            if !(h.is_finite() && h > 0.0) {
                return Err(layers.no_outline(view));
            }
            r * h
        }
    };
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(ProfileError::InvalidParameter {
            message: format!(
                "the flattening tolerance in user units ({tolerance:e}) must be finite and positive"
            ),
        });
    }
    let mut shapes = Vec::new();
    let mut shape = 0usize;
    collect(tree.root(), tolerance, &ellipses, &mut shape, &mut shapes);
    let plans: Vec<Planned> = shapes.iter().map(|s| s.plan(tolerance)).collect();
    svg_guard::check_plan(&plans, tolerance).map_err(|e| match e {
        ProfileError::NoOutline => layers.no_outline(view),
        e => e,
    })?;
    let mut out = Vec::new();
    for s in shapes {
        let subs = match s.geometry {
            Geometry::Ellipse(e) => vec![(e.points(), true)],
            Geometry::Path(b) => flatten(&b, tolerance),
        };
        let many = subs.len() > 1;
        for (k, (points, closed)) in subs.into_iter().enumerate() {
            let id = if many {
                format!("{} (subpath {})", s.id, k + 1)
            } else {
                s.id.clone()
            };
            out.push(Subpath { id, points, closed });
        }
    }
    Ok((out, units, layers))
}

/// The ids of the `circle`/`ellipse` elements read (outside the groups
/// `layers` leaves out); an element without one gets [`ELLIPSE_ID`] and a
/// counter, inserted by an edit pushed to `edits`.
fn name_ellipses(
    doc: &roxmltree::Document,
    text: &str,
    layers: &ViewLayers,
    edits: &mut Vec<(usize, usize, String)>,
) -> Vec<String> {
    let mut ellipses: Vec<String> = Vec::new();
    for node in doc.descendants().filter(|n| n.is_element()) {
        let tag = node.tag_name();
        let svg_ns = tag.namespace() == Some("http://www.w3.org/2000/svg");
        if !(svg_ns && matches!(tag.name(), "circle" | "ellipse"))
            || layers.removes(node.range().start)
        {
            continue;
        }
        match node.attribute("id") {
            Some(id) if !id.is_empty() => ellipses.push(id.to_string()),
            _ => {
                let id = format!("{ELLIPSE_ID}{}", ellipses.len());
                // after "<" and the qualified tag name
                let at = node.range().start
                    + 1
                    + text[node.range().start + 1..]
                        .find(|c: char| c.is_whitespace() || c == '/' || c == '>')
                        .unwrap_or(0);
                edits.push((at, 0, format!(" id=\"{id}\"")));
                ellipses.push(id);
            }
        }
    }
    ellipses
}

/// `text` with each `(position, bytes removed, text inserted)` edit made,
/// in position order.
fn splice(text: &str, edits: &mut [(usize, usize, String)]) -> String {
    edits.sort_by_key(|e| e.0);
    let mut t = String::with_capacity(text.len() + 32 * edits.len());
    let mut pos = 0;
    for (at, removed, insert) in edits.iter() {
        t.push_str(&text[pos..*at]);
        t.push_str(insert);
        pos = at + removed;
    }
    t.push_str(&text[pos..]);
    t
}

/// A shape read by usvg, transformed to model-oriented user units, not
/// yet flattened.
struct Shape {
    id: String,
    geometry: Geometry,
}

enum Geometry {
    Path(BezPath),
    Ellipse(Ellipse),
}

impl Shape {
    fn plan(&self, tolerance: f64) -> Planned {
        match &self.geometry {
            Geometry::Path(b) => Planned::of_path(self.id.clone(), b, tolerance),
            Geometry::Ellipse(e) => {
                let r = [e.a[0].abs() + e.b[0].abs(), e.a[1].abs() + e.b[1].abs()];
                Planned {
                    id: self.id.clone(),
                    lo: [e.c[0] - r[0], e.c[1] - r[1]],
                    hi: [e.c[0] + r[0], e.c[1] + r[1]],
                    estimate: e.n as f64,
                }
            }
        }
    }
}

fn collect(
    g: &usvg::Group,
    tolerance: f64,
    ellipses: &[String],
    shape: &mut usize,
    out: &mut Vec<Shape>,
) {
    for node in g.children() {
        match node {
            usvg::Node::Group(g) => collect(g, tolerance, ellipses, shape, out),
            usvg::Node::Path(p) => {
                *shape += 1;
                let id = if p.id().is_empty() || p.id().starts_with(ELLIPSE_ID) {
                    format!("<shape {shape}>")
                } else {
                    p.id().to_string()
                };
                let is_ellipse = !p.id().is_empty() && ellipses.iter().any(|e| e == p.id());
                let geometry = match exact_ellipse(p, tolerance).filter(|_| is_ellipse) {
                    Some(e) => Geometry::Ellipse(e),
                    None => Geometry::Path(to_kurbo(p.data(), p.abs_transform())),
                };
                out.push(Shape { id, geometry });
            }
            _ => {}
        }
    }
}

/// An exact ellipse `c + a cos t + b sin t` (model-oriented user units)
/// and the number of samples that keeps every chord within the tolerance.
struct Ellipse {
    c: [f64; 2],
    a: [f64; 2],
    b: [f64; 2],
    n: usize,
}

impl Ellipse {
    fn points(&self) -> Vec<[f64; 2]> {
        (0..self.n)
            .map(|k| {
                let th = 2.0 * std::f64::consts::PI * k as f64 / self.n as f64;
                let (s, c) = th.sin_cos();
                [
                    self.c[0] + self.a[0] * c + self.b[0] * s,
                    self.c[1] + self.a[1] * c + self.b[1] * s,
                ]
            })
            .collect()
    }
}

/// The exact ellipse of a `circle`/`ellipse` element (its local bounding
/// box: usvg builds it from four arcs through the extreme points), under
/// the path's absolute transform, sampled so that every chord is within
/// `tolerance`: for `x(t) = c + A cos t + B sin t` the chord error of a
/// step `dt` is at most `(|A| + |B|) dt^2 / 8`.
fn exact_ellipse(p: &usvg::Path, tolerance: f64) -> Option<Ellipse> {
    let b = p.data().bounds();
    let (cx, cy) = (
        0.5 * (b.left() + b.right()) as f64,
        0.5 * (b.top() + b.bottom()) as f64,
    );
    let (rx, ry) = (0.5 * b.width() as f64, 0.5 * b.height() as f64);
    let t = p.abs_transform();
    let (sx, ky, kx, sy) = (t.sx as f64, t.ky as f64, t.kx as f64, t.sy as f64);
    let map = |x: f64, y: f64| [sx * x + kx * y + t.tx as f64, ky * x + sy * y + t.ty as f64];
    let a = [sx * rx, ky * rx];
    let bb = [kx * ry, sy * ry];
    let size = a[0].hypot(a[1]) + bb[0].hypot(bb[1]);
    if !(size.is_finite() && size > 0.0) {
        return None;
    }
    // counted (and refused over the budget) before any point is made;
    // the cast saturates for an absurd count, which the budget refuses
    let n = svg_guard::ellipse_points(size, tolerance) as usize;
    Some(Ellipse {
        c: map(cx, cy),
        a,
        b: bb,
        n,
    })
}

/// The path with the affine transform applied (before flattening, so the
/// tolerance is in model units).
fn to_kurbo(path: &usvg::tiny_skia_path::Path, t: usvg::Transform) -> BezPath {
    use usvg::tiny_skia_path::PathSegment as S;
    let map = |p: usvg::tiny_skia_path::Point| {
        let (x, y) = (p.x as f64, p.y as f64);
        Point::new(
            t.sx as f64 * x + t.kx as f64 * y + t.tx as f64,
            t.ky as f64 * x + t.sy as f64 * y + t.ty as f64,
        )
    };
    let mut b = BezPath::new();
    for s in path.segments() {
        match s {
            S::MoveTo(p) => b.move_to(map(p)),
            S::LineTo(p) => b.line_to(map(p)),
            S::QuadTo(p, q) => b.quad_to(map(p), map(q)),
            S::CubicTo(p, q, r) => b.curve_to(map(p), map(q), map(r)),
            S::Close => b.close_path(),
        }
    }
    b
}

/// Flattens to polylines: (points, closed). A subpath is closed when it
/// ends with a close command or its last point equals its first; the
/// closing copy is not repeated. Subpaths of fewer than 2 points are
/// dropped.
fn flatten(b: &BezPath, tolerance: f64) -> Vec<(Vec<[f64; 2]>, bool)> {
    let mut subs: Vec<(Vec<[f64; 2]>, bool)> = Vec::new();
    let mut cur: Vec<[f64; 2]> = Vec::new();
    let mut finish = |cur: &mut Vec<[f64; 2]>, closed: bool| {
        let mut pts = std::mem::take(cur);
        let mut closed = closed;
        if pts.len() > 2 && pts.first() == pts.last() {
            pts.pop();
            closed = true;
        }
        if pts.len() >= 2 {
            subs.push((pts, closed));
        }
    };
    kurbo::flatten(b.iter(), tolerance, |el| match el {
        PathEl::MoveTo(p) => {
            finish(&mut cur, false);
            cur.push([p.x, p.y]);
        }
        PathEl::LineTo(p) => cur.push([p.x, p.y]),
        PathEl::ClosePath => finish(&mut cur, true),
        // flatten emits only the three above
        PathEl::QuadTo(_, p) | PathEl::CurveTo(_, _, p) => cur.push([p.x, p.y]),
    });
    finish(&mut cur, false);
    subs
}

impl SvgSketch {
    /// The sketch at its physical size: outline and cuts scaled from user
    /// units to metres by [`DocumentUnits::metres_per_unit`] (a uniform
    /// scale unless the document says `preserveAspectRatio="none"`).
    pub fn into_metres(self) -> Result<SvgSketch, ProfileError> {
        let [sx, sy] = self.units.metres_per_unit;
        let (h, v) = (sx, sy);
        let scale = |p: &[f64; 2]| [h * p[0], v * p[1]];
        // a uniform positive scale keeps the outline valid: not validated
        // again; another scale makes a new polygon, validated
        let uniform = (h == v).then(|| self.outline.outline().scaled(h)).flatten();
        let outline = match uniform {
            Some(o) => super::Profile::of(self.outline.view(), o),
            None => super::Profile::new(
                self.outline.view(),
                self.outline.points().iter().map(scale).collect(),
            )?,
        };
        let cuts = self
            .cuts
            .into_iter()
            .map(|c| super::Cut {
                id: c.id,
                points: c.points.iter().map(scale).collect(),
            })
            .collect();
        Ok(SvgSketch {
            outline,
            cuts,
            units: self.units,
        })
    }
}
