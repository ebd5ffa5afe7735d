//! Where a model misses its drawing, as a picture (issue 28 item 5: the
//! report says how far; this shows where): one panel per view, the drawn
//! outline (placed as the build placed it) in red, the outline of the
//! model's projection in blue, and the place of the view's largest profile
//! error marked, with its value. SVG, made without a GPU; `sketch build
//! --overlay` and `character build --overlay` write it.
//!
//! The marked place is found over the samples [`super::quality`] measures
//! the profile error on ([`super::quality::miss_samples`]), so the marked
//! number is the report's `max_rel` for the view.

use super::quality::{miss_samples, model_outline};
use crate::mesh::Mesh;
use crate::profile::{Profile, ProfileIndex, View};
use std::fmt::Write;

/// Panel size in pixels (the model's extent fills it, with a margin).
const PANEL: f64 = 420.0;
const MARGIN: f64 = 24.0;

/// The largest distance between the two outlines: (distance, the sample,
/// its nearest point on the other outline).
pub type Miss = (f64, [f64; 2], [f64; 2]);

/// One view's outlines and its largest miss.
#[derive(Clone, Debug)]
pub struct ViewOverlay {
    pub view: View,
    pub drawn: Vec<[f64; 2]>,
    /// None when the model's projection has no outline.
    pub model: Option<Vec<[f64; 2]>>,
    pub miss: Option<Miss>,
}

/// The largest miss between `drawn` and `model`: over the samples the
/// report's profile error takes ([`miss_samples`]), each to its nearest
/// point on the other outline (the points of a [`Profile`] are finite).
pub fn largest_miss(drawn: &Profile, model: &Profile) -> Option<Miss> {
    let (id, im) = (ProfileIndex::new(drawn), ProfileIndex::new(model));
    let (from_model, from_drawn) = miss_samples(drawn, model);
    let samples = from_model
        .into_iter()
        .map(|q| (q, &id))
        .chain(from_drawn.into_iter().map(|q| (q, &im)));
    let mut best: Option<Miss> = None;
    for (q, idx) in samples {
        let (d, _, _, near) = idx.nearest(q);
        if best.is_none_or(|b| d > b.0) {
            best = Some((d, q, near));
        }
    }
    best
}

/// The overlays of the views of `body` (the model without removed parts
/// and props) against the drawn outlines.
pub fn views(body: &Mesh, front: &Profile, side: Option<&Profile>) -> Vec<ViewOverlay> {
    [(View::Front, Some(front)), (View::Side, side)]
        .into_iter()
        .filter_map(|(v, drawn)| {
            let drawn = drawn?;
            let model = model_outline(body, v).map(|m| m.0);
            Some(ViewOverlay {
                view: v,
                drawn: drawn.points().to_vec(),
                miss: model.as_ref().and_then(|m| largest_miss(drawn, m)),
                model: model.map(|m| m.points().to_vec()),
            })
        })
        .collect()
}

fn bounds(v: &ViewOverlay) -> [f64; 4] {
    let mut pts = v.drawn.clone();
    pts.extend_from_slice(v.model.as_deref().unwrap_or(&[]));
    let (lo, hi) = crate::polygon::bbox(&pts);
    [lo[0], lo[1], hi[0], hi[1]]
}

fn polyline(out: &mut String, pts: &[[f64; 2]], map: &dyn Fn([f64; 2]) -> [f64; 2], colour: &str) {
    let _ = write!(
        out,
        r#"<polygon fill="none" stroke="{colour}" stroke-width="1.5" points=""#
    );
    for p in pts {
        let [x, y] = map(*p);
        let _ = write!(out, "{x:.1},{y:.1} ");
    }
    out.push_str("\"/>\n");
}

/// The overlay as an SVG document: the views side by side at one scale,
/// each with its title, a legend, and its largest miss relative to
/// `height` (the model's height).
pub fn svg(views: &[ViewOverlay], height: f64) -> String {
    let bs: Vec<[f64; 4]> = views.iter().map(bounds).collect();
    let extent = bs
        .iter()
        .map(|b| (b[2] - b[0]).max(b[3] - b[1]))
        .fold(f64::MIN_POSITIVE, f64::max);
    let s = (PANEL - 2.0 * MARGIN) / extent;
    let width = PANEL * views.len().max(1) as f64;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{h}" viewBox="0 0 {width} {h}" font-family="sans-serif" font-size="13">"#,
        h = PANEL + 40.0
    );
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (k, (v, b)) in views.iter().zip(&bs).enumerate() {
        let x0 = k as f64 * PANEL;
        let cx = 0.5 * (b[0] + b[2]);
        let map = |p: [f64; 2]| {
            [
                x0 + PANEL / 2.0 + s * (p[0] - cx),
                PANEL - MARGIN - s * (p[1] - b[1]),
            ]
        };
        let _ = writeln!(
            out,
            r#"<text x="{}" y="18">{}</text>"#,
            x0 + MARGIN,
            v.view.name()
        );
        polyline(&mut out, &v.drawn, &map, "#d62728");
        match &v.model {
            Some(m) => polyline(&mut out, m, &map, "#1f5fb4"),
            None => {
                let _ = writeln!(
                    out,
                    r#"<text x="{}" y="36">the model has no outline in this view</text>"#,
                    x0 + MARGIN
                );
            }
        }
        if let Some((d, q, near)) = v.miss {
            let ([ax, ay], [bx, by]) = (map(q), map(near));
            let _ = writeln!(
                out,
                r#"<line x1="{ax:.1}" y1="{ay:.1}" x2="{bx:.1}" y2="{by:.1}" stroke="black" stroke-width="2"/><circle cx="{ax:.1}" cy="{ay:.1}" r="7" fill="none" stroke="black" stroke-width="1.5"/>"#
            );
            let _ = writeln!(
                out,
                r#"<text x="{}" y="{}">largest miss {:.2} % of the height</text>"#,
                x0 + MARGIN,
                PANEL + 16.0,
                100.0 * d / height
            );
        }
    }
    let _ = writeln!(
        out,
        r##"<text x="{}" y="{}"><tspan fill="#d62728">red: drawn</tspan>, <tspan fill="#1f5fb4">blue: model</tspan>, circle: largest miss</text>"##,
        MARGIN,
        PANEL + 34.0
    );
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::tol;

    fn rect(w: f64, h: f64) -> Profile {
        Profile::new(View::Front, vec![[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]])
            .expect("a rectangle")
    }

    /// A model 0.1 taller than its drawn square misses it by 0.1, along
    /// its top edge (every sample there is 0.1 above the drawn top).
    #[test]
    fn a_raised_top_is_the_largest_miss() {
        let (d, q, near) = largest_miss(&rect(1.0, 1.0), &rect(1.0, 1.1)).expect("a miss");
        assert!((d - 0.1).abs() <= tol::ROUNDING, "miss {d}");
        assert!((q[1] - 1.1).abs() <= tol::ROUNDING, "sample {q:?}");
        assert!((near[1] - 1.0).abs() <= tol::ROUNDING, "nearest {near:?}");
    }

    /// The picture parses as SVG and states each view's miss relative to
    /// the height; a view whose model has no outline says so.
    #[test]
    fn the_picture_parses_and_names_each_views_miss() {
        let (drawn, model) = (rect(1.0, 2.0), rect(1.0, 2.2));
        let views = vec![
            ViewOverlay {
                view: View::Front,
                drawn: drawn.points().to_vec(),
                miss: largest_miss(&drawn, &model),
                model: Some(model.points().to_vec()),
            },
            ViewOverlay {
                view: View::Side,
                drawn: drawn.points().to_vec(),
                model: None,
                miss: None,
            },
        ];
        let text = svg(&views, 2.0);
        usvg::Tree::from_str(&text, &usvg::Options::default()).expect("valid SVG");
        assert_eq!(
            text.matches("largest miss 10.00 % of the height").count(),
            1,
            "{text}"
        );
        assert!(
            text.contains("the model has no outline in this view"),
            "{text}"
        );
    }
}
