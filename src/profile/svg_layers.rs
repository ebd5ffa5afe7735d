//! One page, several views: the layers of an SVG page that name a view.
//!
//! The drawing template (`data/sketch/template_a4.svg`) holds the front and
//! the side view on one A4 page, each in its own layer. Reading view `V`
//! from such a page reads only the layer(s) naming `V`: the groups naming
//! another view are left out before the page is parsed, every other shape
//! is read as in a one-view file. A group names a view when it is an
//! Inkscape layer (`inkscape:groupmode="layer"`) whose label's first word
//! is `front`, `side` or `top` (any case: "Front view", "side (profile)"),
//! or when its `id` is exactly one of those words (a layer exported by
//! another editor, `<g id="front">`). A page with view layers but none for
//! `V` is an error naming the layers it has; a file without view layers is
//! read whole, as before.
//!
//! On a page with view layers, the view's layer is read even when it is
//! hidden in the editor (`display:none`: one hides the side while drawing
//! the front; the layer's name says what it is for), and the other layers
//! that name no view and hold none (notes, a frame, a traced reference
//! image's outline) are left out: drawn in any view, an open line or a
//! second closed shape in them made reading a view fail. Shapes outside
//! every layer are read in every view.

use super::{ProfileError, View};
use std::ops::Range;
use usvg::roxmltree::{Document, Node};

const INKSCAPE_NS: &str = "http://www.inkscape.org/namespaces/inkscape";

/// What reading one view of a page leaves out.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct ViewLayers {
    /// Byte ranges of the groups naming another view, in document order.
    pub removed: Vec<Range<usize>>,
    /// The label (or id) of the first layer naming the view read, when the
    /// page has view layers.
    pub selected: Option<String>,
    /// Byte ranges of the attributes hiding a layer of the view read
    /// (`display="none"`, or a `style` holding `display:none`), removed so
    /// the layer is drawn.
    pub shown: Vec<Range<usize>>,
}

impl ViewLayers {
    /// The error of a view with no outline: its layer named when the
    /// page has view layers.
    pub fn no_outline(&self, view: View) -> ProfileError {
        match &self.selected {
            Some(layer) => ProfileError::EmptyViewLayer {
                view,
                layer: layer.clone(),
            },
            None => ProfileError::NoOutline,
        }
    }

    /// Whether byte `at` lies in a left-out group.
    pub fn removes(&self, at: usize) -> bool {
        self.removed.iter().any(|r| r.contains(&at))
    }
}

/// The view a group names, and the name it does so by.
fn named_view(node: Node) -> Option<(View, String)> {
    if !(node.is_element() && node.tag_name().name() == "g") {
        return None;
    }
    let layer = node.attribute((INKSCAPE_NS, "groupmode")) == Some("layer");
    if let Some(label) = node.attribute((INKSCAPE_NS, "label")).filter(|_| layer) {
        let word = label
            .split(|c: char| !c.is_alphanumeric())
            .find(|w| !w.is_empty())?;
        return view_named(word).map(|v| (v, label.to_string()));
    }
    let id = node.attribute("id")?;
    view_named(id).map(|v| (v, id.to_string()))
}

/// Whether `node` is an Inkscape layer (or sublayer).
fn is_layer(node: Node) -> bool {
    node.is_element()
        && node.tag_name().name() == "g"
        && node.attribute((INKSCAPE_NS, "groupmode")) == Some("layer")
}

/// The attribute of a group that hides it, if any: `display="none"` or a
/// `style` declaring `display: none`.
fn hiding_attribute(node: Node) -> Option<Range<usize>> {
    node.attributes().find_map(|a| {
        let hides = match a.name() {
            "display" => a.value().trim() == "none",
            "style" => a.value().split(';').any(|decl| {
                let mut kv = decl.splitn(2, ':').map(str::trim);
                kv.next() == Some("display") && kv.next() == Some("none")
            }),
            _ => false,
        };
        hides.then(|| a.range())
    })
}

fn view_named(word: &str) -> Option<View> {
    View::ALL
        .into_iter()
        .find(|v| v.name().eq_ignore_ascii_case(word))
}

/// The groups to leave out when reading `view` from `doc` (outermost view
/// groups only: a view group inside another goes with it), and, on a page
/// with view layers, the outermost layers naming no view and holding none.
pub(super) fn select(doc: &Document, view: View) -> Result<ViewLayers, ProfileError> {
    let mut out = ViewLayers::default();
    let mut others = Vec::new();
    let mut plain: Vec<Range<usize>> = Vec::new();
    let in_view = |n: Node| n.ancestors().skip(1).any(|a| named_view(a).is_some());
    for node in doc.descendants() {
        let Some((v, name)) = named_view(node) else {
            let holds_view = || node.descendants().any(|d| named_view(d).is_some());
            // in document order a layer inside a left-out one follows it
            let outer = !plain
                .last()
                .is_some_and(|r| r.contains(&node.range().start));
            if is_layer(node) && outer && !in_view(node) && !holds_view() {
                plain.push(node.range());
            }
            continue;
        };
        if in_view(node) {
            continue;
        }
        if v == view {
            out.selected.get_or_insert(name);
            out.shown.extend(hiding_attribute(node));
        } else {
            others.push(format!("{name:?}"));
            out.removed.push(node.range());
        }
    }
    if out.selected.is_none() && !others.is_empty() {
        return Err(ProfileError::NoViewLayer {
            view,
            layers: others,
        });
    }
    if out.selected.is_some() {
        out.removed.extend(plain);
        out.removed.sort_by_key(|r| r.start);
    }
    Ok(out)
}

/// The views an SVG page has layers for, in document order (none for a
/// file that is not an SVG page with view layers, or that cannot be read:
/// reading it as a view reports why).
pub fn page_views(path: &std::path::Path) -> Vec<View> {
    let is_svg = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
    let Some(text) = is_svg
        .then(|| crate::mesh::io::read_input_text(path, "SVG drawing").ok())
        .flatten()
    else {
        return Vec::new();
    };
    let Ok(doc) = Document::parse_with_options(&text, super::svg_guard::xml_options()) else {
        return Vec::new();
    };
    let mut views = Vec::new();
    for (v, _) in doc.descendants().filter_map(named_view) {
        if !views.contains(&v) {
            views.push(v);
        }
    }
    views
}

#[cfg(test)]
mod tests {
    use super::*;
    use usvg::roxmltree::Document;

    const PAGE: &str = r#"<svg xmlns="http://www.w3.org/2000/svg"
        xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape">
      <g inkscape:groupmode="layer" inkscape:label="Front view"><path d="M0 0 L1 0 L1 1 Z"/></g>
      <g inkscape:groupmode="layer" inkscape:label="side (profile)"><g id="top"/></g>
      <g inkscape:label="front arm"/>
      <g id="front_leg"/>
    </svg>"#;

    #[test]
    fn a_view_reads_its_own_layer_and_leaves_out_the_others() {
        let doc = Document::parse(PAGE).unwrap();
        let front = select(&doc, View::Front).unwrap();
        assert_eq!(front.selected.as_deref(), Some("Front view"));
        // the side layer only: its nested "top" goes with it, and neither
        // a labelled group that is not a layer nor an id that is not a
        // view's name counts
        assert_eq!(front.removed.len(), 1);
        assert!(PAGE[front.removed[0].clone()].contains("side (profile)"));
        let side = select(&doc, View::Side).unwrap();
        assert_eq!(side.selected.as_deref(), Some("side (profile)"));
        assert!(PAGE[side.removed[0].clone()].contains("Front view"));
    }

    /// usvg parses in f32: a radius-3 circle's points are within this of
    /// it (1e-4, a few hundred f32 ulps at 20).
    const CIRCLE_TOL: f64 = 1e-4;

    #[test]
    fn each_view_of_a_page_is_read_from_its_layer_with_its_circles_exact() {
        // an unnamed circle gets an id before parsing; in the layer left
        // out it must not (the two edits would overlap)
        let page = r#"<svg xmlns="http://www.w3.org/2000/svg"
            xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape">
          <g inkscape:groupmode="layer" inkscape:label="front">
            <path id="body" d="M0 0 L4 0 L4 8 Z"/></g>
          <g inkscape:groupmode="layer" inkscape:label="side">
            <circle cx="20" cy="4" r="3"/></g>
        </svg>"#;
        let front = crate::profile::parse_svg(page, View::Front, 0.01).unwrap();
        assert_eq!(front.outline.len(), 3);
        let side = crate::profile::parse_svg(page, View::Side, 0.01).unwrap();
        let r = side
            .outline
            .points()
            .iter()
            .map(|p| (p[0] - 20.0).hypot(p[1] + 4.0))
            .fold(0.0f64, f64::max);
        assert!(
            (r - 3.0).abs() < CIRCLE_TOL,
            "the side's circle: radius {r}"
        );
        let e = crate::profile::parse_svg(PAGE, View::Side, 0.01).unwrap_err();
        assert!(
            matches!(&e, ProfileError::EmptyViewLayer { layer, .. } if layer == "side (profile)"),
            "{e}"
        );
    }

    #[test]
    fn a_page_without_the_views_layer_names_the_layers_it_has() {
        let doc = Document::parse(PAGE).unwrap();
        let e = select(&doc, View::Top).unwrap_err().to_string();
        assert!(e.contains("top") && e.contains("Front view"), "{e}");
        let plain = Document::parse(r#"<svg xmlns="http://www.w3.org/2000/svg"><g id="x"/></svg>"#)
            .unwrap();
        assert_eq!(select(&plain, View::Side).unwrap(), ViewLayers::default());
    }

    #[test]
    fn a_hidden_view_layer_is_read_and_layers_naming_no_view_are_left_out() {
        // the side layer hidden in the editor; a notes layer with an open
        // line and a frame, and a sublayer of notes beside the views inside
        // a "drawing" layer: read in a view, each made it fail
        let page = r#"<svg xmlns="http://www.w3.org/2000/svg"
            xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape">
          <g inkscape:groupmode="layer" inkscape:label="notes">
            <path d="M0 0 L100 0" fill="none" stroke="black"/>
            <rect x="-50" y="-50" width="200" height="200"/></g>
          <g inkscape:groupmode="layer" inkscape:label="drawing">
            <g inkscape:groupmode="layer" inkscape:label="front">
              <path d="M0 0 L4 0 L4 8 Z"/></g>
            <g inkscape:groupmode="layer" inkscape:label="side" style="opacity:1; display : none">
              <path d="M20 0 L22 0 L22 8 L20 8 Z"/></g>
            <g inkscape:groupmode="layer" inkscape:label="arrows">
              <path d="M0 0 L1 1"/></g></g>
        </svg>"#;
        let front = crate::profile::parse_svg(page, View::Front, 0.01).unwrap();
        assert_eq!(front.outline.len(), 3);
        let side = crate::profile::parse_svg(page, View::Side, 0.01).unwrap();
        assert_eq!(side.outline.len(), 4);
        // the side's square starts at x = 20 exactly (nothing else read)
        const SIDE_LEFT: f64 = 20.0;
        assert!(side.outline.points().iter().all(|p| p[0] >= SIDE_LEFT));
        // the same notes on a page without view layers are read, as in any
        // one-view file: the open line is an error
        let plain = page
            .replace("label=\"front\"", "label=\"body\"")
            .replace("label=\"side\"", "label=\"profile\"");
        assert!(crate::profile::parse_svg(&plain, View::Front, 0.01).is_err());
    }
}
