//! Writing in a length unit: the one writer entry point that knows units
//! (the rule is in [`crate::mesh::unit`]). GLB is always written in metres;
//! OBJ, STL and PLY in the unit asked for.

use super::{encode, write_atomic, Format};
use crate::mesh::unit::{self, Unit};
use crate::mesh::{Mesh, MeshError};
use std::path::Path;

/// The unit `fmt` is written in when the user asks for `requested`: GLB
/// ignores the request (glTF is metres), the others follow it.
pub fn output_unit(fmt: Format, requested: Unit) -> Unit {
    match fmt {
        Format::Glb => unit::GLB,
        Format::Obj | Format::Stl | Format::Ply => requested,
    }
}

/// Writes `m`, whose coordinates are in `source`, to `path` (format by
/// extension) converted to [`output_unit`]`(format, requested)`, atomically
/// and validated like [`super::write`]. Returns the unit written, for the
/// caller's report.
pub fn write_in_unit(
    m: &Mesh,
    path: &Path,
    source: Unit,
    requested: Unit,
) -> Result<Unit, MeshError> {
    let fmt = Format::from_path(path)?;
    let to = output_unit(fmt, requested);
    let bytes = if to == source {
        encode(m, fmt)?
    } else {
        encode(&unit::convert(m, source, to), fmt)?
    };
    write_atomic(path, &bytes)?;
    Ok(to)
}
