//! Mesh files: OBJ (read and write, one `o` per part), glTF 2.0 (binary
//! GLB and JSON `.gltf`: write, one node per part under one root per model;
//! read, with node transforms, [`read_gltf`]), STL (binary write; binary
//! and ASCII read), PLY (binary little-endian write; ASCII and binary
//! little-endian read). Models, parts and layouts: [`scene`].
//!
//! Every writer first validates the mesh (finite coordinates, indices in
//! range), then writes to a temporary file beside the target and renames it
//! over the target, so a failure never leaves a half-written file and never
//! loses the previous one. Every reader validates what it read (finite,
//! indices in range, at least one triangle). An input path may name parts:
//! `FILE#NAME[,NAME...]` keeps the named glTF nodes (with everything below
//! them) or the named groups of an OBJ/STL/PLY, when no file is named so.

mod atomic;
mod files;
mod glb;
mod in_unit;
mod lock;
mod obj;
mod ply;
pub mod read_gltf;
pub mod scene;
mod stl;

pub use atomic::{refuse_overwriting_input, same_file, write_all_atomic, write_atomic};
pub use files::{check_outputs, read_input, read_input_text, strip_bom, write_target};
pub use glb::{encode_glb, group_colour as group_colour_rgb};
pub use in_unit::{output_unit, write_in_unit, write_scene_in_unit};
pub use lock::FileLock;
pub use obj::{encode_obj, parse_obj};
pub use ply::{encode_ply, parse_ply};
pub use read_gltf::{parse_gltf, GltfError, GltfOptions};
pub use scene::{model_name, Layout, Model, Scene};
pub use stl::{encode_stl, parse_stl};

use super::{Mesh, MeshError};
use std::path::Path;

/// Mesh file formats, chosen by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Obj,
    Glb,
    Gltf,
    Stl,
    Ply,
}

impl Format {
    /// The format named by `path`'s extension (case-insensitive).
    pub fn from_path(path: &Path) -> Result<Format, MeshError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_ascii_lowercase();
        match ext.as_str() {
            "obj" => Ok(Format::Obj),
            "glb" => Ok(Format::Glb),
            "gltf" => Ok(Format::Gltf),
            "stl" => Ok(Format::Stl),
            "ply" => Ok(Format::Ply),
            _ => Err(MeshError::UnknownFormat {
                path: path.display().to_string(),
                ext,
            }),
        }
    }
}

/// Reads a mesh file (OBJ, GLB, glTF, STL or PLY by extension; a
/// `#NAME,...` suffix selects parts, see the module doc): every model
/// appended into one mesh, whose groups are the parts.
pub fn read(path: &Path) -> Result<Mesh, MeshError> {
    Ok(read_scene(path)?.flatten())
}

/// The file and the part names of an input path: `FILE#A,B` when no file
/// is named so and FILE has a mesh extension, else the path as it is.
pub fn split_selection(path: &Path) -> (std::path::PathBuf, Vec<String>) {
    let s = path.to_string_lossy();
    if !path.exists() {
        if let Some((file, names)) = s.rsplit_once('#') {
            if Format::from_path(Path::new(file)).is_ok() {
                let names = names
                    .split(',')
                    .map(str::trim)
                    .filter(|n| !n.is_empty())
                    .map(str::to_string)
                    .collect();
                return (file.into(), names);
            }
        }
    }
    (path.to_path_buf(), Vec::new())
}

/// Reads a mesh file into its models (a glTF file: one per root node; the
/// other formats: one model named after the file), validated: finite,
/// indices in range, at least one triangle.
pub fn read_scene(path: &Path) -> Result<Scene, MeshError> {
    let (file, select) = split_selection(path);
    let fmt = Format::from_path(&file)?;
    let name = file.display().to_string();
    let bytes = read_input(&file, "mesh")?;
    let scene = match fmt {
        Format::Glb | Format::Gltf => {
            let dir = file.parent().map(|d| {
                if d.as_os_str().is_empty() {
                    Path::new(".")
                } else {
                    d
                }
            });
            let opts = GltfOptions {
                select,
                ..GltfOptions::default()
            };
            parse_gltf(&bytes, dir, &opts).map_err(|source| MeshError::Gltf {
                path: name.clone(),
                source,
            })?
        }
        Format::Obj | Format::Stl | Format::Ply => {
            let m = match fmt {
                Format::Stl => parse_stl(&bytes, &name)?,
                Format::Ply => parse_ply(&bytes, &name)?,
                _ => parse_obj(&String::from_utf8_lossy(&bytes), &name)?,
            };
            Scene::single(&model_name(&file), select_groups(m, &select, &name)?)
        }
    };
    for m in &scene.models {
        m.mesh.validate()?;
    }
    if scene.models.iter().all(|m| m.mesh.triangles.is_empty()) {
        return Err(MeshError::Invalid(format!(
            "{name}: no triangles (an empty file, or not a valid {} file?)",
            format!("{fmt:?}").to_uppercase()
        )));
    }
    Ok(scene)
}

/// The triangles of the named groups (all when `select` is empty).
fn select_groups(m: Mesh, select: &[String], path: &str) -> Result<Mesh, MeshError> {
    if select.is_empty() {
        return Ok(m);
    }
    if let Some(missing) = select.iter().find(|s| !m.groups.contains(s)) {
        return Err(MeshError::Invalid(format!(
            "{path}: no group is named {missing:?}; the file's groups: {}",
            m.groups.join(", ")
        )));
    }
    let keep: Vec<bool> = m
        .tri_group
        .iter()
        .map(|&g| select.contains(&m.groups[g as usize]))
        .collect();
    Ok(m.filter_triangles(&keep).0)
}

/// Encodes `m` in `fmt` after validating it.
pub fn encode(m: &Mesh, fmt: Format) -> Result<Vec<u8>, MeshError> {
    encode_scene(&Scene::single("mesh", m.clone()), fmt, Layout::Parts)
}

/// Writes `m` to `path` in the format named by its extension, atomically,
/// as one model named after the file with one node (GLB) or object (OBJ)
/// per group.
pub fn write(m: &Mesh, path: &Path) -> Result<(), MeshError> {
    write_scene(
        &Scene::single(&model_name(path), m.clone()),
        path,
        Layout::Parts,
    )
}

/// Every file format stores positions as 32-bit floats: refuses a vertex
/// whose coordinate would become infinite on narrowing (instead of writing
/// `inf`).
pub fn check_f32_range(m: &Mesh) -> Result<(), MeshError> {
    for (index, p) in m.positions.iter().enumerate() {
        if p.iter().any(|x| x.abs() > f32::MAX as f64) {
            return Err(MeshError::OutOfF32Range { index, value: *p });
        }
    }
    Ok(())
}

/// Encodes `scene` (a [`scene::Scene`]) in `fmt` in `layout` after validating it.
pub fn encode_scene(scene: &Scene, fmt: Format, layout: Layout) -> Result<Vec<u8>, MeshError> {
    scene.validate()?;
    Ok(match fmt {
        Format::Glb => glb::encode_glb_scene(scene, layout),
        Format::Gltf => glb::encode_gltf_scene(scene, layout),
        Format::Obj => obj::encode_obj_scene(scene, layout).into_bytes(),
        Format::Stl => encode_stl(&scene.flatten()),
        Format::Ply => encode_ply(&scene.flatten()),
    })
}

/// Writes `scene` to `path` (format by extension) in `layout`, validated
/// and atomically.
pub fn write_scene(scene: &Scene, path: &Path, layout: Layout) -> Result<(), MeshError> {
    let fmt = Format::from_path(path)?;
    let bytes = encode_scene(scene, fmt, layout)?;
    write_atomic(path, &bytes)
}
