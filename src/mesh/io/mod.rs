//! Mesh files: OBJ (read and write, with groups), binary glTF 2.0 (GLB,
//! write), STL (binary write; binary and ASCII read), PLY (binary
//! little-endian write; ASCII and binary little-endian read).
//!
//! Every writer first validates the mesh (finite coordinates, indices in
//! range), then writes to a temporary file beside the target and renames it
//! over the target, so a failure never leaves a half-written file and never
//! loses the previous one.

mod glb;
mod in_unit;
mod obj;
mod ply;
mod stl;

pub use glb::{encode_glb, group_colour as group_colour_rgb};
pub use in_unit::{output_unit, write_in_unit};
pub use obj::{encode_obj, parse_obj};
pub use ply::{encode_ply, parse_ply};
pub use stl::{encode_stl, parse_stl};

use super::{Mesh, MeshError};
use std::io::Write;
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

/// Reads a mesh (OBJ, STL or PLY by extension) and validates it.
pub fn read(path: &Path) -> Result<Mesh, MeshError> {
    let fmt = Format::from_path(path)?;
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io {
        path: name.clone(),
        source,
    })?;
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
    Ok(m)
}

/// Encodes `m` in `fmt` after validating it.
pub fn encode(m: &Mesh, fmt: Format) -> Result<Vec<u8>, MeshError> {
    m.validate()?;
    if m.triangles.is_empty() {
        return Err(MeshError::Empty);
    }
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

/// Writes `bytes` to a temporary file beside `path`, syncs it and renames it
/// over `path`. Creates missing parent directories.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), MeshError> {
    let err = |source| MeshError::Io {
        path: path.display().to_string(),
        source,
    };
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(err)?;
    }
    let file_name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    let tmp = path.with_file_name(format!(".{file_name}.tmp-{}", std::process::id()));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result.map_err(err)
}
