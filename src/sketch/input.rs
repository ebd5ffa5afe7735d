//! Reading profiles and cuts: SVG files (one closed outline path, optional
//! `cut*` paths), JSON polylines or inline points.

use super::poly::segments_intersect;
use super::SketchError;
use crate::character::doc::ProfileInput;
use std::path::Path;

/// Largest SVG flattening tolerance relative to the drawing's height.
pub const MAX_RELATIVE_TOLERANCE: f64 = 0.01;

/// Which view a profile is drawn in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewKind {
    /// Model (x, y).
    Front,
    /// Model (z, y).
    Side,
}

/// A profile: validated counter-clockwise outline and its cuts.
#[derive(Clone, Debug)]
pub struct Outline {
    pub points: Vec<[f64; 2]>,
    pub cuts: Vec<(String, Vec<[f64; 2]>)>,
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

/// Reads one profile.
pub fn read_profile(
    input: &ProfileInput,
    base: &Path,
    view: ViewKind,
    tol: f64,
) -> Result<Outline, SketchError> {
    let what = match view {
        ViewKind::Front => "front profile",
        ViewKind::Side => "side profile",
    };
    crate::limits::check_real(
        "tolerance (--tolerance, inputs.tolerance)",
        tol,
        crate::limits::SKETCH_TOLERANCE,
    )?;
    let (raw, cuts) = match input {
        ProfileInput::Points(p) => (p.clone(), Vec::new()),
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
                read_svg(&path, view, tol)?
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
                (json_points(&path, &text)?, Vec::new())
            }
        }
    };
    let profile = crate::profile::Profile::new(view.profile_view(), raw).map_err(|e| {
        SketchError::Outline {
            what: what.into(),
            message: e.to_string(),
        }
    })?;
    let points = profile.points().to_vec();
    check_drawing_size(what, &points)?;
    let height = profile.height();
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
        validate_cut(id, c, &points)?;
    }
    Ok(Outline { points, cuts })
}

/// A profile's size (largest side of its bounding box) and coordinates
/// must lie in the drawing range [`crate::limits::DRAWING_SIZE`] (SVG
/// drawings are held to it before flattening; inline and JSON points
/// here): a 1e30-sized drawing is refused by its size, not by a solver's
/// condition number later.
fn check_drawing_size(what: &str, points: &[[f64; 2]]) -> Result<(), SketchError> {
    let r = crate::limits::DRAWING_SIZE;
    let (ys, xs) = super::poly::bounds(points);
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
    view: ViewKind,
    tol: f64,
) -> Result<(Vec<[f64; 2]>, Vec<(String, Vec<[f64; 2]>)>), SketchError> {
    let sk = crate::profile::read_svg(path, view.profile_view(), tol).map_err(|e| {
        // the I/O variant already names the path: keep only its cause
        let message = match e {
            crate::profile::ProfileError::Io { source, .. } => source.to_string(),
            other => without_path(path, other.to_string()),
        };
        SketchError::File {
            path: path.display().to_string(),
            message,
        }
    })?;
    Ok((
        sk.outline.points().to_vec(),
        sk.cuts.into_iter().map(|c| (c.id, c.points)).collect(),
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

impl ViewKind {
    /// The profile module's view.
    pub fn profile_view(self) -> crate::profile::View {
        match self {
            ViewKind::Front => crate::profile::View::Front,
            ViewKind::Side => crate::profile::View::Side,
        }
    }
}
