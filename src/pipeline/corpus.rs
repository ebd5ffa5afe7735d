//! The corpus of drawings (`data/sketch/corpus/`, written by
//! `examples/sketch_corpus.rs`) and its measurement: every drawing built
//! at the intermediate level as a user would (`sketch build --front F
//! --side S`, no flag but `--height` where its entry asks for one) and
//! measured ([`crate::sketch::quality`]).

use crate::character::doc::{CharacterDoc, Inputs, Level, ProfileInput};
use crate::character::Resolution;
use crate::pipeline::build_document;
use crate::sketch::quality::{Bounds, Quality};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// One drawing of the corpus (an entry of `corpus.json`).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Entry {
    pub name: String,
    /// Front (humanoid) or lateral (quadruped) view, relative to the corpus.
    pub front: String,
    /// Side (humanoid) or head-on (quadruped) view.
    pub side: String,
    /// The document style (`crate::sketch::corpus::Style`, or `"hand"`).
    pub style: String,
    /// The figure's height as drawn, metres (its physical size).
    pub drawn_height_m: f64,
    /// `--height` for this entry's build (metres), when it asks for one.
    pub height_m: Option<f64>,
    /// What the drawing shows (pose, proportions, animal).
    pub what: String,
    /// Kept out of the development loop: measured only at the end.
    pub held_out: bool,
}

/// The manifest.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Manifest {
    pub entries: Vec<Entry>,
}

/// One drawing's measurement.
#[derive(Clone, Debug, Serialize)]
pub struct Row {
    pub name: String,
    pub style: String,
    pub held_out: bool,
    /// The build's error (None: built).
    pub error: Option<String>,
    pub watertight_manifold_oriented: bool,
    /// Model height against the expected one (`--height` or the drawn
    /// size), relative.
    pub height_error: f64,
    pub quality: Option<Quality>,
    pub warnings: Vec<String>,
    /// Every bound of [`Bounds::ISSUE`] met, and built closed.
    pub passed: bool,
}

/// Builds one entry as `sketch build --front F --side S [--height H]`
/// would (`dir`: the corpus directory).
pub fn build_entry(
    dir: &Path,
    e: &Entry,
) -> Result<crate::pipeline::Built, crate::pipeline::BuildError> {
    let path = |f: &str| ProfileInput::Path(dir.join(f).display().to_string());
    build_views(e, path(&e.front), path(&e.side))
}

/// Builds an entry's two views at the intermediate level, with its
/// `--height`.
fn build_views(
    e: &Entry,
    front: ProfileInput,
    side: ProfileInput,
) -> Result<crate::pipeline::Built, crate::pipeline::BuildError> {
    let doc = CharacterDoc::from_inputs(
        Inputs {
            front,
            side: Some(side),
            sections: Vec::new(),
            tolerance: None,
            height: e.height_m,
            body_plan: Default::default(),
        },
        Level::Intermediate,
    );
    build_document(&doc, Path::new("."), Resolution::default(), true)
}

/// Builds an entry as [`build_entry`] does, but from its outlines' points
/// with the front (or lateral) view's x stretched by `1 + eps` about its
/// middle: the same drawing a little wider or narrower, for the continuity
/// study (`sketch_corpus measure --stretch-x EPS`, docs/drawing-corpus.md).
/// At `eps` = 0 it builds the same model as [`build_entry`] (cut paths
/// aside: the corpus drawings have none).
pub fn build_entry_stretched(
    dir: &Path,
    e: &Entry,
    eps: f64,
) -> Result<crate::pipeline::Built, crate::pipeline::BuildError> {
    use crate::profile::View;
    use crate::sketch::input::read_profile;
    let read = |f: &str, view| {
        read_profile(
            &ProfileInput::Path(dir.join(f).display().to_string()),
            Path::new("."),
            view,
            None,
        )
    };
    let front = read(&e.front, View::Front)?;
    let side = read(&e.side, View::Side)?;
    let xr = crate::polygon::span(front.points(), 0);
    let mid = 0.5 * (xr[0] + xr[1]);
    let stretched = front
        .points()
        .iter()
        .map(|p| [mid + (p[0] - mid) * (1.0 + eps), p[1]])
        .collect();
    build_views(
        e,
        ProfileInput::Points(stretched),
        ProfileInput::Points(side.points().to_vec()),
    )
}

/// Measures one entry's build ([`build_entry`]).
pub fn measure_entry(
    e: &Entry,
    built: &Result<crate::pipeline::Built, crate::pipeline::BuildError>,
) -> Row {
    let mut row = Row {
        name: e.name.clone(),
        style: e.style.clone(),
        held_out: e.held_out,
        error: None,
        watertight_manifold_oriented: false,
        height_error: f64::NAN,
        quality: None,
        warnings: Vec::new(),
        passed: false,
    };
    match built {
        Err(err) => row.error = Some(err.to_string()),
        Ok(b) => {
            let r = &b.report;
            let t = &r.topology;
            row.watertight_manifold_oriented = t.watertight && t.manifold && t.oriented;
            let want = e.height_m.unwrap_or(e.drawn_height_m);
            row.height_error = (r.height_m - want).abs() / want;
            row.warnings = r.warnings.clone();
            row.passed = row.watertight_manifold_oriented
                && row.height_error <= HEIGHT_TOLERANCE
                && crate::sketch::quality::warnings(&r.quality, &Bounds::ISSUE).is_empty();
            row.quality = Some(r.quality.clone());
        }
    }
    row
}

/// The model's height must equal the drawing's physical size (or
/// `--height`) within this (the issue's 0.5 %).
pub const HEIGHT_TOLERANCE: f64 = 0.005;

/// Reads `dir/corpus.json`.
pub fn read_manifest(dir: &Path) -> Result<Manifest, String> {
    let p = dir.join("corpus.json");
    let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", p.display()))
}

/// A Markdown table of rows: one line per drawing.
pub fn table(rows: &[Row]) -> String {
    let mut s = String::from(
        "| drawing | style | built | closed | height err % | front max % | side max % | outside % (f/s) | dihedral deg | creased / h | passes |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let name = if r.held_out {
            format!("{} (held out)", r.name)
        } else {
            r.name.clone()
        };
        match (&r.error, &r.quality) {
            (Some(e), _) => {
                let short: String = e.chars().take(90).collect();
                s.push_str(&format!(
                    "| {name} | {} | no: {} | | | | | | | | no |\n",
                    r.style,
                    short.replace('|', "/")
                ));
            }
            (None, Some(q)) => {
                let v = |k: usize, f: fn(&crate::sketch::quality::ViewQuality) -> f64| {
                    q.whole.views.get(k).map_or(f64::NAN, f)
                };
                s.push_str(&format!(
                    "| {name} | {} | yes | {} | {:.2} | {:.2} | {:.2} | {:.2} / {:.2} | {:.1} | {:.2} | {} |\n",
                    r.style,
                    if r.watertight_manifold_oriented { "yes" } else { "no" },
                    100.0 * r.height_error,
                    100.0 * v(0, |x| x.max_rel),
                    100.0 * v(1, |x| x.max_rel),
                    100.0 * v(0, |x| x.outside_rel),
                    100.0 * v(1, |x| x.outside_rel),
                    q.whole.dihedral_deg,
                    q.whole.creased_rel,
                    if r.passed { "yes" } else { "no" }
                ));
            }
            (None, None) => {}
        }
    }
    s
}
