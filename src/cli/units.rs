//! The unit flags every mesh-writing subcommand flattens in (the rule is in
//! `pdesculpt::mesh::unit`): `--unit` for OBJ/STL/PLY output (GLB is always
//! metres) and `--input-unit` for the numbers it reads (mesh files, JSON
//! specs; bundled MakeHuman data is always decimetres), with
//! `--single-mesh` (the layout: `pdesculpt::mesh::io::scene`).

use pdesculpt::mesh::io::{Layout, Scene};
use pdesculpt::mesh::unit::Unit;
use pdesculpt::mesh::{io, Mesh};
use std::path::Path;

/// `--single-mesh`: the file layout of GLB and OBJ output.
#[derive(clap::Args, Debug, Clone, Copy, Default)]
pub struct LayoutArgs {
    /// Write one mesh (GLB: one node, one primitive per part; OBJ: one
    /// object) instead of one node/object per part, for 3D printing or
    /// booleans.
    #[arg(long)]
    pub single_mesh: bool,
}

impl LayoutArgs {
    pub fn layout(&self) -> Layout {
        if self.single_mesh {
            Layout::SingleMesh
        } else {
            Layout::Parts
        }
    }

    /// Writes `m` (in its own unit) as one model named after the file.
    pub fn write(&self, m: &Mesh, path: &Path) -> anyhow::Result<()> {
        let scene = Scene::single(&io::model_name(path), m.clone());
        Ok(io::write_scene(&scene, path, self.layout())?)
    }
}

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
    #[command(flatten)]
    pub layout: LayoutArgs,
}

impl UnitArgs {
    /// Writes `m` (coordinates in `source`) to `path` in the unit the format
    /// takes; returns that unit for the report.
    pub fn write(&self, m: &Mesh, path: &Path, source: Unit) -> anyhow::Result<Unit> {
        let scene = Scene::single(&io::model_name(path), m.clone());
        self.write_scene(&scene, path, source)
    }

    /// Writes a scene of models (coordinates in `source`).
    pub fn write_scene(&self, s: &Scene, path: &Path, source: Unit) -> anyhow::Result<Unit> {
        let layout = self.layout.layout();
        Ok(io::write_scene_in_unit(s, path, source, self.unit, layout)?)
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
    #[command(flatten)]
    pub layout: LayoutArgs,
}

impl OutputUnitArgs {
    /// Writes `m` (coordinates in `source`) to `path` in the unit the format
    /// takes; returns that unit for the report.
    pub fn write(&self, m: &Mesh, path: &Path, source: Unit) -> anyhow::Result<Unit> {
        let scene = Scene::single(&io::model_name(path), m.clone());
        self.write_scene(&scene, path, source)
    }

    /// Writes a scene of models (coordinates in `source`).
    pub fn write_scene(&self, s: &Scene, path: &Path, source: Unit) -> anyhow::Result<Unit> {
        let layout = self.layout.layout();
        Ok(io::write_scene_in_unit(s, path, source, self.unit, layout)?)
    }
}
