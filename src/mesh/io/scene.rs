//! Scenes: the models one file holds, each a [`Mesh`] whose groups are its
//! parts (a character's `torso`, `arm_l`, transitions such as `hips`,
//! removed parts and props), and the [`Layout`] they are written in.
//!
//! In the default [`Layout::Parts`] a GLB holds one root node per model
//! (named after the model) with one child node per part, each its own mesh
//! and material named after the part; a model of one part is one node,
//! named after the model. Part meshes keep only the vertices their
//! triangles use, so a vertex on a seam between two parts is written once
//! in each, at bit-identical coordinates, with the same normal (normals are
//! computed on the whole model): welding coincident vertices gives back the
//! shared-vertex whole, watertight when the model was. An OBJ holds one `o`
//! per part over one shared vertex list (seams shared as they are).
//! [`Layout::SingleMesh`] writes one node and one mesh (one primitive and
//! material per part over one shared vertex buffer; OBJ: one `o`, a `g` per
//! part), for 3D printing or booleans. STL and PLY have no parts: every
//! layout writes the welded whole.

use super::check_f32_range;
use crate::mesh::{Mesh, MeshError};
use std::path::Path;

/// One model of a scene: a name (the root node's) and its mesh, whose
/// groups are the model's parts.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    pub name: String,
    pub mesh: Mesh,
}

/// The models of one file, in order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    pub models: Vec<Model>,
}

/// How parts are laid out in a written file (see the module doc).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Layout {
    /// One node (GLB) or object (OBJ) per part, under one root per model.
    #[default]
    Parts,
    /// One node and one mesh for everything (`--single-mesh`).
    SingleMesh,
}

impl Scene {
    /// A scene of one model.
    pub fn single(name: &str, mesh: Mesh) -> Scene {
        Scene {
            models: vec![Model {
                name: name.to_string(),
                mesh,
            }],
        }
    }

    /// Adds a model (builder style).
    pub fn with(mut self, name: &str, mesh: Mesh) -> Scene {
        self.models.push(Model {
            name: name.to_string(),
            mesh,
        });
        self
    }

    /// Every model appended into one mesh (groups of equal names merge).
    pub fn flatten(&self) -> Mesh {
        let mut out = Mesh {
            groups: Vec::new(),
            ..Mesh::default()
        };
        for m in &self.models {
            out.append(&m.mesh);
        }
        if out.groups.is_empty() {
            out.groups.push("mesh".into());
        }
        out
    }

    /// Every model validated (finite, indices in range, 32-bit range) and
    /// at least one triangle in all.
    pub fn validate(&self) -> Result<(), MeshError> {
        for m in &self.models {
            m.mesh.validate()?;
            check_f32_range(&m.mesh)?;
        }
        if self.models.iter().all(|m| m.mesh.triangles.is_empty()) {
            return Err(MeshError::Empty);
        }
        Ok(())
    }

    /// The name of the single node a [`Layout::SingleMesh`] file holds: the
    /// models' names joined by `+`.
    pub fn joined_name(&self) -> String {
        let names: Vec<&str> = self.models.iter().map(|m| m.name.as_str()).collect();
        names.join("+")
    }

    /// The same scene with every model's coordinates scaled by `k`.
    pub fn scaled(&self, k: f64) -> Scene {
        let mut s = self.clone();
        for m in &mut s.models {
            m.mesh.map_positions(|p| [k * p[0], k * p[1], k * p[2]]);
        }
        s
    }
}

/// The model name a file path gives a mesh written alone: the file stem
/// (`out/female.glb` -> `female`), or `model` when there is none.
pub fn model_name(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "model".into())
}
