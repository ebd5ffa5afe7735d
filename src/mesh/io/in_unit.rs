//! Writing in a length unit: the one writer entry point that knows units
//! (the rule is in [`crate::mesh::unit`]). GLB is always written in metres;
//! OBJ, STL and PLY in the unit asked for.

use super::encode_scene;
use super::scene::{model_name, Layout, Scene};
use super::{write_atomic, Format};
use crate::mesh::unit::{self, Unit};
use crate::mesh::{Mesh, MeshError};
use std::path::Path;

/// The unit `fmt` is written in when the user asks for `requested`: GLB
/// ignores the request (glTF is metres), the others follow it.
pub fn output_unit(fmt: Format, requested: Unit) -> Unit {
    match fmt {
        Format::Glb | Format::Gltf => unit::GLB,
        Format::Obj | Format::Stl | Format::Ply => requested,
    }
}

/// Writes `m`, whose coordinates are in `source`, to `path` (format by
/// extension) converted to [`output_unit`]`(format, requested)`, atomically
/// and validated like [`super::write`], as one model named after the file
/// in the default layout. Returns the unit written, for the caller's
/// report.
pub fn write_in_unit(
    m: &Mesh,
    path: &Path,
    source: Unit,
    requested: Unit,
) -> Result<Unit, MeshError> {
    let scene = Scene::single(&model_name(path), m.clone());
    write_scene_in_unit(&scene, path, source, requested, Layout::Parts)
}

/// [`write_in_unit`] for a scene of several models, in `layout`.
pub fn write_scene_in_unit(
    scene: &Scene,
    path: &Path,
    source: Unit,
    requested: Unit,
    layout: Layout,
) -> Result<Unit, MeshError> {
    let fmt = Format::from_path(path)?;
    let to = output_unit(fmt, requested);
    let bytes = if to == source {
        encode_scene(scene, fmt, layout)?
    } else {
        encode_scene(&scene.scaled(source.factor_to(to)), fmt, layout)?
    };
    write_atomic(path, &bytes)?;
    Ok(to)
}
