//! The unit flags every mesh-writing subcommand flattens in (the rule is in
//! `pdesculpt::mesh::unit`): `--unit` for OBJ/STL/PLY output (GLB is always
//! metres) and `--input-unit` for the numbers it reads (mesh files, JSON
//! specs; bundled MakeHuman data is always decimetres).

use pdesculpt::mesh::unit::Unit;
use pdesculpt::mesh::{io, Mesh};
use std::path::Path;

/// `--unit` and `--input-unit`.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct UnitArgs {
    /// Unit of OBJ/STL/PLY output: m, dm, cm or mm (GLB is always metres).
    #[arg(long, default_value = "m")]
    pub unit: Unit,
    /// Unit of the coordinates read from mesh files and JSON specs: m, dm,
    /// cm or mm (bundled MakeHuman data is always decimetres).
    #[arg(long, default_value = "m")]
    pub input_unit: Unit,
}

impl UnitArgs {
    /// Writes `m` (coordinates in `source`) to `path` in the unit the format
    /// takes; returns that unit for the report.
    pub fn write(&self, m: &Mesh, path: &Path, source: Unit) -> anyhow::Result<Unit> {
        Ok(io::write_in_unit(m, path, source, self.unit)?)
    }

    /// Writes `m` whose coordinates are in `--input-unit`.
    pub fn write_input(&self, m: &Mesh, path: &Path) -> anyhow::Result<Unit> {
        self.write(m, path, self.input_unit)
    }
}

/// `--unit` alone, for commands that read only bundled data (whose unit is
/// known: MakeHuman is decimetres).
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct OutputUnitArgs {
    /// Unit of OBJ/STL/PLY output: m, dm, cm or mm (GLB is always metres).
    #[arg(long, default_value = "m")]
    pub unit: Unit,
}

impl OutputUnitArgs {
    /// Writes `m` (coordinates in `source`) to `path` in the unit the format
    /// takes; returns that unit for the report.
    pub fn write(&self, m: &Mesh, path: &Path, source: Unit) -> anyhow::Result<Unit> {
        Ok(io::write_in_unit(m, path, source, self.unit)?)
    }
}
