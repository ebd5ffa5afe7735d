//! Props: convolution-surface models (paper 003, `conv`) attached to a
//! character document and composed into its mesh.
//!
//! A prop is `{name, model, translate, scale}` in the document's `props`
//! list: `model` a conv model file (`data/conv/*.json`, what `pdesculpt conv
//! build` reads; relative to the document's directory), placed by the
//! similarity `x -> scale * x + translate` (model units). Each prop is built
//! by the conv library (narrow-band sampler, marching tetrahedra, the
//! defaults of `conv build`) and appended to the character mesh as **its own
//! mesh component**: one group named after the prop (in GLB its own
//! primitive and material), **not stitched** to the body (it may overlap
//! it, like a removed part). It is left out of the body's profile error.
//!
//! Resolution: [`PROP_RESOLUTION`] grid cells along the longest side at the
//! character's default resolution (`conv build`'s default), scaled with the
//! character's rings per height (a preview builds coarser props).
//!
//! Props are rebuilt incrementally: a process-wide cache keyed by the model
//! file's content (`conv::incremental`: sketches by stroke and options,
//! group meshes by segments, resolution, threshold and polygoniser, compared
//! exactly) so an unchanged prop is not refitted or re-polygonised, and the
//! result is bit for bit the one a fresh build computes.

use crate::conv::incremental::{MeshCache, SketchCache};
use crate::conv::model::{Model, Polygonizer};
use crate::mesh::Mesh;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Grid cells along a prop's longest side at the default resolution.
pub const PROP_RESOLUTION: usize = 64;
/// Fewest and most grid cells of a prop at any resolution.
pub const PROP_CELLS: (usize, usize) = (12, 256);
/// Largest scale factor of a prop.
pub const PROP_SCALE_MAX: f64 = 1e3;
/// Largest size of a prop's translation component (model units): past it
/// the mesh leaves the range of the 32-bit floats mesh files store.
pub const PROP_TRANSLATE_MAX: f64 = 1e6;
/// Most props in one document.
pub const MAX_PROPS: usize = 64;

/// A prop attached to the character.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PropSpec {
    pub name: String,
    /// The conv model file (relative to the document's directory).
    pub model: String,
    #[serde(default)]
    pub translate: [f64; 3],
    #[serde(default = "one")]
    pub scale: f64,
}

fn one() -> f64 {
    1.0
}

/// Errors of props.
#[derive(Debug, thiserror::Error)]
pub enum PropError {
    #[error("prop '{name}': {message}")]
    Invalid { name: String, message: String },
    #[error("prop '{name}': {message} (file {path})")]
    File {
        name: String,
        path: PathBuf,
        message: String,
    },
    #[error("prop '{name}': conv build: {source}")]
    Build {
        name: String,
        source: crate::conv::ConvError,
    },
}

/// What a build says about one prop.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct PropReport {
    pub name: String,
    pub model: String,
    pub triangles: usize,
    pub resolution: usize,
    /// Always false: a prop is a separate component.
    pub stitched: bool,
}

impl PropSpec {
    /// Checks the numbers and the name (no file access).
    pub fn validate(&self) -> Result<(), PropError> {
        let bad = |m: String| PropError::Invalid {
            name: self.name.clone(),
            message: m,
        };
        if self.name.trim().is_empty() || self.name.chars().any(char::is_whitespace) {
            return Err(bad("the name must be non-empty without white space".into()));
        }
        if self.model.trim().is_empty() {
            return Err(bad("no model file".into()));
        }
        if !(self.scale.is_finite() && self.scale > 0.0 && self.scale <= PROP_SCALE_MAX) {
            return Err(bad(format!(
                "scale = {} is out of range: in (0, {PROP_SCALE_MAX}]",
                crate::limits::Num(self.scale)
            )));
        }
        if let Some(t) = self.translate.iter().find(|t| !t.is_finite()) {
            return Err(bad(format!("translate has a non-finite value {t}")));
        }
        if let Some(t) = self.translate.iter().find(|t| t.abs() > PROP_TRANSLATE_MAX) {
            return Err(bad(format!(
                "translate component {} is out of range: at most {PROP_TRANSLATE_MAX:e} in size",
                crate::limits::Num(*t)
            )));
        }
        Ok(())
    }

    /// The model file's path against `base`.
    pub fn path(&self, base: &Path) -> PathBuf {
        let p = Path::new(&self.model);
        if p.is_absolute() {
            p.into()
        } else {
            base.join(p)
        }
    }

    /// Reads and parses the model file.
    pub fn read_model(&self, base: &Path) -> Result<(String, Model), PropError> {
        let path = self.path(base);
        let file = |m: String| PropError::File {
            name: self.name.clone(),
            path: path.clone(),
            message: m,
        };
        let text = crate::mesh::io::read_input_text(&path, "conv model")
            .map_err(|e| file(e.to_string()))?;
        let model =
            Model::from_json(&text).map_err(|e| file(format!("not a conv model file: {e}")))?;
        Ok((text, model))
    }
}

/// Grid cells of a prop for a character built at `rings_per_height`.
pub fn resolution(rings_per_height: f64) -> usize {
    let default = crate::character::Resolution::default().rings_per_height;
    let r = (PROP_RESOLUTION as f64 * rings_per_height / default).round();
    if !r.is_finite() {
        return PROP_RESOLUTION;
    }
    (r as usize).clamp(PROP_CELLS.0, PROP_CELLS.1)
}

/// Caches by model text (see the module notes).
type Cache = Vec<(String, SketchCache, MeshCache)>;
static CACHE: Mutex<Cache> = Mutex::new(Vec::new());
/// Models kept in the cache.
const CACHE_MODELS: usize = 16;

/// Builds one prop's mesh in its own frame (before the placement), reusing
/// the process-wide cache.
pub fn build_model(
    text: &str,
    model: &Model,
    cells: usize,
) -> Result<Mesh, crate::conv::ConvError> {
    let mut guard = CACHE.lock().unwrap_or_else(|p| p.into_inner());
    let i = match guard.iter().position(|(t, _, _)| t == text) {
        Some(i) => i,
        None => {
            if guard.len() >= CACHE_MODELS {
                guard.remove(0);
            }
            guard.push((
                text.to_string(),
                SketchCache::default(),
                MeshCache::default(),
            ));
            guard.len() - 1
        }
    };
    let (_, sketches, meshes) = &mut guard[i];
    let built = model.build_cached(sketches)?;
    meshes.polygonize(
        &built,
        cells,
        model.options.threshold,
        Polygonizer::MarchingTetrahedra,
    )
}

/// Places a prop's mesh: `scale * x + translate`, every triangle in the
/// single group `name`.
pub fn place(mut m: Mesh, p: &PropSpec) -> Mesh {
    for x in &mut m.positions {
        for k in 0..3 {
            x[k] = p.scale * x[k] + p.translate[k];
        }
    }
    m.set_single_group(&p.name);
    m
}

/// Builds every prop and appends it to `mesh` (its own group, not
/// stitched); `rings_per_height` is the character's resolution.
pub fn compose(
    mesh: &mut Mesh,
    props: &[PropSpec],
    base: &Path,
    rings_per_height: f64,
) -> Result<Vec<PropReport>, PropError> {
    let cells = resolution(rings_per_height);
    props
        .iter()
        .map(|p| compose_one(mesh, p, base, cells))
        .collect()
}

/// Builds one prop at `cells` grid cells and appends it to `mesh` (its
/// own group, not stitched).
pub fn compose_one(
    mesh: &mut Mesh,
    p: &PropSpec,
    base: &Path,
    cells: usize,
) -> Result<PropReport, PropError> {
    p.validate()?;
    let (text, model) = p.read_model(base)?;
    let m = build_model(&text, &model, cells).map_err(|e| PropError::Build {
        name: p.name.clone(),
        source: e,
    })?;
    let m = place(m, p);
    crate::conv::sample::check_f32_output(&m).map_err(|e| PropError::Build {
        name: p.name.clone(),
        source: e,
    })?;
    let report = PropReport {
        name: p.name.clone(),
        model: p.model.clone(),
        triangles: m.triangles.len(),
        resolution: cells,
        stitched: false,
    };
    mesh.append(&m);
    Ok(report)
}
