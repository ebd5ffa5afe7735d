//! Mesh files: OBJ (read and write, with groups), binary glTF 2.0 (GLB,
//! write), STL (binary write; binary and ASCII read), PLY (binary
//! little-endian write; ASCII and binary little-endian read).
//!
//! Every writer first validates the mesh (finite coordinates, indices in
//! range), then writes to a temporary file beside the target and renames it
//! over the target, so a failure never leaves a half-written file and never
//! loses the previous one.

mod atomic;
mod files;
mod glb;
mod in_unit;
mod lock;
mod obj;
mod ply;
mod stl;

pub use atomic::{refuse_overwriting_input, same_file, write_all_atomic, write_atomic};
pub use files::{check_outputs, read_input, read_input_text, strip_bom, write_target};
pub use glb::{encode_glb, group_colour as group_colour_rgb};
pub use in_unit::{output_unit, write_in_unit};
pub use lock::FileLock;
pub use obj::{encode_obj, parse_obj};
pub use ply::{encode_ply, parse_ply};
pub use stl::{encode_stl, parse_stl};

use super::{Mesh, MeshError};
use std::path::Path;

/// Mesh file formats, chosen by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Obj,
    Glb,
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
            "stl" => Ok(Format::Stl),
            "ply" => Ok(Format::Ply),
            _ => Err(MeshError::UnknownFormat {
                path: path.display().to_string(),
                ext,
            }),
        }
    }
}

/// Reads a mesh (OBJ, STL or PLY by extension) and validates it (finite,
/// indices in range, at least one triangle).
pub fn read(path: &Path) -> Result<Mesh, MeshError> {
    let fmt = Format::from_path(path)?;
    let name = path.display().to_string();
    let bytes = read_input(path, "mesh")?;
    let m = match fmt {
        Format::Obj => {
            let text = String::from_utf8_lossy(&bytes);
            parse_obj(&text, &name)?
        }
        Format::Stl => parse_stl(&bytes, &name)?,
        Format::Ply => parse_ply(&bytes, &name)?,
        Format::Glb => {
            return Err(MeshError::Invalid(format!(
                "{name}: reading GLB is not supported (write-only); convert it to OBJ first"
            )))
        }
    };
    m.validate()?;
    if m.triangles.is_empty() {
        return Err(MeshError::Invalid(format!(
            "{name}: no triangles (an empty file, or not a valid {} file?)",
            format!("{fmt:?}").to_uppercase()
        )));
    }
    Ok(m)
}

/// Encodes `m` in `fmt` after validating it.
pub fn encode(m: &Mesh, fmt: Format) -> Result<Vec<u8>, MeshError> {
    m.validate()?;
    if m.triangles.is_empty() {
        return Err(MeshError::Empty);
    }
    check_f32_range(m)?;
    Ok(match fmt {
        Format::Obj => encode_obj(m).into_bytes(),
        Format::Glb => encode_glb(m),
        Format::Stl => encode_stl(m),
        Format::Ply => encode_ply(m),
    })
}

/// Writes `m` to `path` in the format named by its extension, atomically.
pub fn write(m: &Mesh, path: &Path) -> Result<(), MeshError> {
    let fmt = Format::from_path(path)?;
    let bytes = encode(m, fmt)?;
    write_atomic(path, &bytes)
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
