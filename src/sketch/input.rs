//! Reading profiles and cuts: SVG files (one closed outline path, optional
//! `cut*` paths), JSON polylines or inline points.
//!
//! Every profile is read at its physical size, in metres: an SVG by its
//! document's size ([`crate::profile::units`]: `width`/`height` over the
//! `viewBox`, transforms applied), a JSON polyline or inline points as
//! metres. Scaling to `--height` and placing each view by its own outline
//! follow in [`super::place`].

use super::SketchError;
use crate::character::doc::ProfileInput;
use crate::polygon::segments_intersect;
use crate::profile::{Profile, View};
use std::path::Path;

impl Outline {
    /// The outline's points, counter-clockwise.
    pub fn points(&self) -> &[[f64; 2]] {
        self.profile.points()
    }
}

/// Largest SVG flattening tolerance relative to the drawing's height.
pub const MAX_RELATIVE_TOLERANCE: f64 = 0.01;
/// Flattening tolerance when none is given, relative to the height of the
/// drawing's bounding box: a tenth of [`MAX_RELATIVE_TOLERANCE`]'s 1 %, so
/// that flattening stays well below the 1.5 % profile bound of a build
/// whatever the drawing's size or unit.
pub const DEFAULT_FLATNESS: f64 = 1e-3;

/// A profile: its outline, validated once where it was read (a
/// [`Profile`]: simple, counter-clockwise), and its cuts, in metres.
#[derive(Clone, Debug)]
pub struct Outline {
    pub profile: Profile,
    pub cuts: Vec<(String, Vec<[f64; 2]>)>,
    /// The SVG document's size of a user unit (None for JSON or inline
    /// points, which are metres).
    pub units: Option<crate::profile::DocumentUnits>,
}

fn json_points(path: &Path, text: &str) -> Result<Vec<[f64; 2]>, SketchError> {
    #[derive(serde::Deserialize)]
    #[serde(untagged)]
    enum J {
        Bare(Vec<[f64; 2]>),
        Obj { points: Vec<[f64; 2]> },
    }
    let j: J = serde_json::from_str(text).map_err(|e| SketchError::File {
        path: path.display().to_string(),
        message: format!("not a JSON polyline ([[x, y], ...] or {{\"points\": ...}}): {e}"),
    })?;
    Ok(match j {
        J::Bare(p) | J::Obj { points: p } => p,
    })
}

/// Reads one profile at its physical size (metres). `tol`: the flattening
/// tolerance in metres of the drawing as drawn; None: [`DEFAULT_FLATNESS`]
/// of its height.
pub fn read_profile(
    input: &ProfileInput,
    base: &Path,
    view: View,
    tol: Option<f64>,
) -> Result<Outline, SketchError> {
    let what = match view {
        View::Front => "front profile",
        View::Side => "side profile",
        View::Top => "top profile",
    };
    if let Some(tol) = tol {
        crate::limits::check_real(
            "tolerance (--tolerance, inputs.tolerance)",
            tol,
            crate::limits::SKETCH_TOLERANCE,
        )?;
    }
    let mut units = None;
    let invalid = |e: crate::profile::ProfileError| SketchError::Outline {
        what: what.into(),
        message: e.to_string(),
    };
    // each input validated once: an SVG's outline by the SVG reader, points
    // here
    let (profile, cuts) = match input {
        ProfileInput::Points(p) => (Profile::new(view, p.clone()).map_err(invalid)?, Vec::new()),
        ProfileInput::Path(p) => {
            let path = if Path::new(p).is_absolute() {
                Path::new(p).to_path_buf()
            } else {
                base.join(p)
            };
            let ext = path
                .extension()
                .and_then(|e| e.to_str())
                .unwrap_or("")
                .to_ascii_lowercase();
            if ext == "svg" {
                let (profile, cuts, u) = read_svg(&path, view, tol)?;
                units = Some(u);
                (profile, cuts)
            } else {
                let text =
                    crate::mesh::io::read_input_text(&path, "JSON profile").map_err(|e| {
                        let message = match e {
                            crate::mesh::MeshError::Io { source, .. } => source.to_string(),
                            e => without_path(&path, e.to_string()),
                        };
                        SketchError::File {
                            path: path.display().to_string(),
                            message,
                        }
                    })?;
                let raw = json_points(&path, &text)?;
                (Profile::new(view, raw).map_err(invalid)?, Vec::new())
            }
        }
    };
    let points = profile.points();
    check_drawing_size(what, points)?;
    let height = profile.height();
    let tol = tol.unwrap_or(DEFAULT_FLATNESS * height);
    if tol > MAX_RELATIVE_TOLERANCE * height {
        return Err(SketchError::Outline {
            what: what.into(),
            message: format!(
                "the flattening tolerance {tol:e} is more than {} % of the drawing's height {height:.4}: give a smaller --tolerance",
                100.0 * MAX_RELATIVE_TOLERANCE
            ),
        });
    }
    for (id, c) in &cuts {
        validate_cut(id, c, points)?;
    }
    Ok(Outline {
        profile,
        cuts,
        units,
    })
}

/// A profile's size (largest side of its bounding box) and coordinates
/// must lie in the drawing range [`crate::limits::DRAWING_SIZE`] (SVG
/// drawings are held to it before flattening; inline and JSON points
/// here): a 1e30-sized drawing is refused by its size, not by a solver's
/// condition number later.
fn check_drawing_size(what: &str, points: &[[f64; 2]]) -> Result<(), SketchError> {
    let r = crate::limits::DRAWING_SIZE;
    let (ys, xs) = (
        crate::polygon::span(points, 1),
        crate::polygon::span(points, 0),
    );
    let size = (xs[1] - xs[0]).max(ys[1] - ys[0]);
    let reach = points.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if size >= r.min && size <= r.max && reach <= r.max {
        return Ok(());
    }
    Err(SketchError::Outline {
        what: what.into(),
        message: format!(
            "the drawing is {} model units across and reaches {} from the origin: its size must lie in {} to {} and its coordinates within +-{} (model units are metres): scale the drawing",
            crate::limits::Num(size),
            crate::limits::Num(reach),
            crate::limits::Num(r.min),
            crate::limits::Num(r.max),
            crate::limits::Num(r.max)
        ),
    })
}

/// A cut must be an open polyline crossing the outline at least twice.
pub fn validate_cut(id: &str, cut: &[[f64; 2]], outline: &[[f64; 2]]) -> Result<(), SketchError> {
    if cut.len() < 2 {
        return Err(SketchError::Cut {
            id: id.into(),
            message: "needs at least two points".into(),
        });
    }
    let n = outline.len();
    let mut crossings = 0;
    for w in cut.windows(2) {
        for i in 0..n {
            if segments_intersect(w[0], w[1], outline[i], outline[(i + 1) % n]) {
                crossings += 1;
            }
        }
    }
    if crossings < 2 {
        return Err(SketchError::Cut {
            id: id.into(),
            message: format!(
                "does not cross the outline (it meets the outline {crossings} time(s); a cut must run across a part, from outside to outside)"
            ),
        });
    }
    Ok(())
}

#[allow(clippy::type_complexity)]
fn read_svg(
    path: &Path,
    view: View,
    tol: Option<f64>,
) -> Result<
    (
        Profile,
        Vec<(String, Vec<[f64; 2]>)>,
        crate::profile::DocumentUnits,
    ),
    SketchError,
> {
    let flat = match tol {
        Some(t) => crate::profile::Flatness::Metres(t),
        None => crate::profile::Flatness::OfHeight(DEFAULT_FLATNESS),
    };
    let read = crate::profile::read_svg_with(path, view, flat).and_then(|s| s.into_metres());
    let sk = read.map_err(|e| {
        // the I/O variant already names the path: keep only its cause
        let message = match e {
            crate::profile::ProfileError::Io { source, .. } => source.to_string(),
            crate::profile::ProfileError::NoOutline => format!(
                "{e}; if it has one, the drawing may be too small to read: the SVG reader keeps \
                 about 7 significant digits of each coordinate, so a shape smaller than a millionth \
                 of its position on the page collapses (draw it larger, or give --height)"
            ),
            other => without_path(path, other.to_string()),
        };
        SketchError::File {
            path: path.display().to_string(),
            message,
        }
    })?;
    Ok((
        sk.outline,
        sk.cuts.into_iter().map(|c| (c.id, c.points)).collect(),
        sk.units,
    ))
}

/// `message` without a leading `path: ` (the error that wraps it names
/// the path already).
fn without_path(path: &Path, message: String) -> String {
    let prefix = format!("{}: ", path.display());
    match message.strip_prefix(&prefix) {
        Some(rest) => rest.to_string(),
        None => message,
    }
}
