//! The demo character: template, two local sculpting edits, C2 PDE
//! reconstruction, and a prop sketched as a convolution surface, each step
//! measured.

pub mod skirt;

use crate::body::closed::{reconstruct_closed, ClosedOptions, ClosedReport};
use crate::makehuman;
use crate::mesh::unit::{self, Unit};
use crate::mesh::Mesh;
use crate::pde4::apply::{deform_region, Direction as Pde4Direction};
use crate::pde4::force::{Force, ForceKind};
use crate::pde4::four_sided::{self, FourSided};
use crate::pde4::ShapeParams;
use crate::plate::deformer::{
    BoundaryMethod, Direction as PlateDirection, PlateDeformer, RegionOptions,
};
use serde::Serialize;
use thiserror::Error;

/// A failure of one demo step.
#[derive(Debug, Error)]
pub enum DemoError {
    #[error("template")]
    Template(#[from] crate::mesh::MeshError),
    #[error("pde4 chest sculpt")]
    Pde4(#[from] crate::pde4::Pde4Error),
    #[error("plate belly push")]
    Plate(#[from] crate::plate::PlateError),
    #[error("pde6 reconstruction")]
    Body(#[from] crate::body::BodyError),
    #[error(transparent)]
    Skirt(#[from] skirt::SkirtError),
    #[error("SketchCo prop")]
    Conv(#[from] crate::conv::ConvError),
    #[error("sketched female")]
    Sketch(#[from] crate::pipeline::BuildError),
    #[error("{0}")]
    Step(String),
}

/// What one local edit did.
#[derive(Clone, Debug, Serialize)]
pub struct EditReport {
    pub name: &'static str,
    pub paper: &'static str,
    pub moved_vertices: usize,
    /// Largest displacement (decimetres).
    pub max_displacement: f64,
    /// Largest displacement among the moved vertices that share a triangle
    /// with an unmoved one (the first ring inside the clamped edge). A C1
    /// clamped edit makes it O(h^2) in the edge spacing h, so on the coarse
    /// MakeHuman mesh it is a visible fraction of the peak.
    pub max_first_ring_displacement: f64,
}

/// Step 1: the bundled female built from her sketches (paper 000 sec 4.1,
/// final level: front and side profiles and key cross sections).
#[derive(Clone, Debug, Serialize)]
pub struct SketchStep {
    pub example: &'static str,
    pub level: &'static str,
    pub triangles: usize,
    pub watertight: bool,
    /// Max profile error per view, relative to the height.
    pub profile_error: Vec<(&'static str, f64)>,
    pub max_c1: f64,
    /// The document's parts, transitions and removed parts, by name: the
    /// nodes of `demo-sketch.glb` (checked in Blender by CI).
    pub parts: Vec<String>,
}

/// Builds the bundled female from her sketches (metres).
pub fn sketched_female() -> Result<(Mesh, SketchStep), DemoError> {
    use crate::character::doc::Level;
    let doc = crate::sketch::check::bundled("female", Level::Final)
        .ok_or_else(|| DemoError::Step("the bundled female sketch does not parse".into()))?;
    let b = crate::pipeline::build_document(
        &doc,
        std::path::Path::new("."),
        crate::character::Resolution::default(),
        true,
    )?;
    let r = &b.report;
    let step = SketchStep {
        example: "data/sketch/female_*",
        level: r.level.name(),
        triangles: r.topology.triangles,
        watertight: r.topology.watertight && r.topology.manifold && r.topology.oriented,
        profile_error: r
            .profile_error
            .iter()
            .map(|p| (p.view, p.max_rel))
            .collect(),
        max_c1: r.max_c1,
        parts: (b.doc.parts().iter().map(|p| &p.name))
            .chain(b.doc.transitions().iter().map(|t| &t.name))
            .chain(b.doc.removed_parts().iter().map(|r| &r.name))
            .cloned()
            .collect(),
    };
    Ok((b.model.mesh, step))
}

/// The demo's outputs and measurements.
#[derive(Clone, Debug)]
pub struct Demo {
    /// Step 1: the character built from the bundled female sketches, in
    /// metres (not the template's unit).
    pub sketched: Mesh,
    /// Unit of every mesh below: decimetres, the MakeHuman data's unit
    /// ([`unit::MAKEHUMAN`]); writers convert (GLB to metres).
    pub unit: Unit,
    /// The sculpted template.
    pub sculpted: Mesh,
    /// Its C2 sixth-order PDE reconstruction (one group per part).
    pub reconstruction: Mesh,
    /// A skirt fitted to the sculpted body (paper 004; group `"skirt"`).
    pub skirt: Mesh,
    /// A prop sketched in silhouettes (paper 003), standing beside the body
    /// (group `"teddy"`).
    pub prop: Mesh,
    pub report: DemoReport,
}

/// Everything the demo measured.
#[derive(Clone, Debug, Serialize)]
pub struct DemoReport {
    /// Unit of every length in this report (decimetres, the template's).
    pub unit: Unit,
    /// Step 1 (its lengths are relative to its height).
    pub sketched: SketchStep,
    pub template: &'static str,
    pub template_vertices: usize,
    pub edits: Vec<EditReport>,
    /// The plate edit against MakeHuman's pregnancy morph.
    pub belly_vs_morph: BellyComparison,
    pub reconstruction: ClosedReport,
    pub skirt: skirt::SkirtReport,
    pub prop: PropReport,
}

/// The sketched prop: a convolution-surface teddy bear (paper 003) built
/// from the bundled model file `data/conv/teddy.json` (eight strokes, merge
/// and carve operations).
#[derive(Clone, Debug, Serialize)]
pub struct PropReport {
    pub model: &'static str,
    pub components: usize,
    pub segments: usize,
    pub triangles: usize,
    pub watertight: bool,
    pub manifold: bool,
    pub oriented: bool,
    /// Worst global-interpolation error |F - T| / T at the stroke points
    /// over the components (paper 003 sec 3.3).
    pub fit_max_rel: f64,
    /// How the body component's surface follows its stroke: max distance
    /// between its projected outline and the stroke, / stroke size.
    pub body_silhouette_max_rel: f64,
    /// Height of the prop in the scene (decimetres).
    pub height: f64,
}

/// The unit the demo works in: the MakeHuman template's.
pub const UNIT: Unit = unit::MAKEHUMAN;

/// The bundled teddy model file.
pub const TEDDY_MODEL: &str = include_str!("../../data/conv/teddy.json");

/// Grid cells along the longest side of the teddy's box.
pub const TEDDY_RESOLUTION: usize = 72;

/// Paper 003: the teddy bear sketched in eight strokes, polygonised by
/// marching tetrahedra, scaled to a quarter of the body's height and stood
/// on the floor to the body's right.
pub fn teddy_prop(body: &Mesh) -> Result<(Mesh, PropReport), DemoError> {
    use crate::conv::model::{Model, Polygonizer};
    let model = Model::from_json(TEDDY_MODEL)?;
    let built = model.build()?;
    let mut mesh = built.polygonize(
        TEDDY_RESOLUTION,
        model.options.threshold,
        Polygonizer::MarchingTetrahedra,
    )?;
    let topo = crate::mesh::topology::report(&mesh);
    // the body component alone, built as its own model: its surface,
    // projected onto its (z = 0, front) plane, against its stroke
    let body_only = Model {
        components: model
            .components
            .iter()
            .filter(|c| c.name == "body")
            .cloned()
            .collect(),
        operations: Vec::new(),
        ..model.clone()
    };
    let stroke = match body_only.components.first() {
        Some(c) => c.stroke.clone(),
        None => {
            return Err(DemoError::Step(
                "the teddy model has no \"body\" component".into(),
            ))
        }
    };
    let silhouette = crate::conv::silhouette::silhouette_error(
        &body_only.build()?.polygonize(
            TEDDY_RESOLUTION,
            body_only.options.threshold,
            Polygonizer::MarchingTetrahedra,
        )?,
        [0.0; 3],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        &stroke,
    );
    let fit_max_rel = built
        .components
        .iter()
        .map(|c| c.sketch.fit.max_rel_error)
        .fold(0.0, f64::max);
    let segments = built.components.iter().map(|c| c.segments.len()).sum();
    let (blo, bhi) = body.bbox();
    let (tlo, thi) = mesh.bbox();
    let height = 0.25 * (bhi[1] - blo[1]);
    let k = height / (thi[1] - tlo[1]);
    let at = [bhi[0] + 0.6 * (thi[0] - tlo[0]) * k, blo[1], 0.0];
    let centre = [0.5 * (tlo[0] + thi[0]), tlo[1], 0.5 * (tlo[2] + thi[2])];
    mesh.map_positions(|p| {
        [
            at[0] + k * (p[0] - centre[0]),
            at[1] + k * (p[1] - centre[1]),
            at[2] + k * (p[2] - centre[2]),
        ]
    });
    mesh.set_single_group("teddy");
    mesh.validate()?;
    let triangles = mesh.triangles.len();
    Ok((
        mesh,
        PropReport {
            model: "data/conv/teddy.json",
            components: built.components.len(),
            segments,
            triangles,
            watertight: topo.watertight,
            manifold: topo.manifold,
            oriented: topo.oriented,
            fit_max_rel,
            body_silhouette_max_rel: silhouette.max_rel,
            height,
        },
    ))
}

/// Largest displacement between two vertex buffers over the vertices in
/// `which` (all when `None`).
fn max_move(a: &Mesh, b: &Mesh, which: Option<&[bool]>) -> f64 {
    a.positions
        .iter()
        .zip(&b.positions)
        .enumerate()
        .filter(|(i, _)| which.is_none_or(|w| w[*i]))
        .map(|(_, (p, q))| crate::mesh::dist(*p, *q))
        .fold(0.0, f64::max)
}

/// Vertices moved by more than rounding, and those of them on the boundary
/// of the moved set (sharing a triangle with an unmoved vertex).
fn moved_sets(a: &Mesh, b: &Mesh) -> (Vec<bool>, Vec<bool>) {
    let moved: Vec<bool> = a
        .positions
        .iter()
        .zip(&b.positions)
        .map(|(p, q)| crate::mesh::dist(*p, *q) > 1e-12)
        .collect();
    let mut edge = vec![false; moved.len()];
    for t in &b.triangles {
        let m = t.map(|i| moved[i as usize]);
        if m.iter().any(|&x| x) && m.iter().any(|&x| !x) {
            for (k, &i) in t.iter().enumerate() {
                if m[k] {
                    edge[i as usize] = true;
                }
            }
        }
    }
    (moved, edge)
}

fn edit_report(name: &'static str, paper: &'static str, before: &Mesh, after: &Mesh) -> EditReport {
    let (moved, edge) = moved_sets(before, after);
    EditReport {
        name,
        paper,
        moved_vertices: moved.iter().filter(|&&m| m).count(),
        max_displacement: max_move(before, after, None),
        max_first_ring_displacement: max_move(before, after, Some(&edge)),
    }
}

/// Paper 000 sec 5.1 / Fig 14: one closed curve and one drag (0.15 dm along
/// the surface normal) per side make a chest deformation, a clamped 4-sided
/// fourth-order PDE patch with a concentrated sculpting force (Galerkin).
pub fn chest_sculpt(body: &Mesh) -> Result<Mesh, DemoError> {
    let d = FourSided::new(
        [ShapeParams::uniform(1.0); 3],
        &[Force {
            kind: ForceKind::Concentrated { u0: 0.5, v0: 0.5 },
            p: [1.0; 3],
        }],
        10,
        10,
        four_sided::Method::Galerkin,
    )?;
    let mut m = body.clone();
    for side in [1.0, -1.0] {
        m = deform_region(
            &m,
            &crate::pde4::samples::chest_curve(side, 0.0),
            &d,
            Pde4Direction::Normal,
            0.15,
            0.8,
        )?
        .mesh;
    }
    Ok(m)
}

/// Result of the pregnancy edit and its comparison with the artist's morph.
#[derive(Clone, Debug, Serialize)]
pub struct BellyComparison {
    /// Region size (vertices the MakeHuman morph moves by more than
    /// `REGION_FRACTION` of its peak).
    pub region_vertices: usize,
    /// Peak displacement of the morph (and of the plate edit, by scaling).
    pub peak: f64,
    /// RMS and max distance between the plate edit and the morph over the
    /// region, relative to the peak.
    pub rms_rel: f64,
    pub max_rel: f64,
}

/// Vertices the morph moves by more than this fraction of its peak form
/// the plate region: the artist's region, frontal enough to project.
pub const REGION_FRACTION: f64 = 0.2;

/// Paper 001 against MakeHuman's own pregnancy morph (the "female into
/// pregnant woman" template experiment): the region the artist's morph
/// moves is bent as a clamped plate by a forward cursor force, scaled to the
/// morph's peak; the two are compared vertex by vertex.
pub fn belly_push(
    body: &Mesh,
    original_index: &[u32],
) -> Result<(Mesh, BellyComparison), DemoError> {
    let morph = makehuman::target("stomach-pregnant-incr")?;
    let mut offset = vec![[0.0; 3]; body.positions.len()];
    let mut to_body = std::collections::HashMap::new();
    for (i, &o) in original_index.iter().enumerate() {
        to_body.insert(o, i);
    }
    for &(o, d) in &morph.offsets {
        if let Some(&i) = to_body.get(&o) {
            offset[i] = d;
        }
    }
    let peak = offset
        .iter()
        .map(|d| crate::mesh::norm(*d))
        .fold(0.0, f64::max);
    if peak.is_nan() || peak <= 0.0 {
        return Err(DemoError::Step(
            "the pregnancy morph moves no body vertex".into(),
        ));
    }
    let region: Vec<u32> = (0..body.positions.len())
        .filter(|&i| crate::mesh::norm(offset[i]) > REGION_FRACTION * peak)
        .map(|i| i as u32)
        .collect();
    let opts = RegionOptions {
        // MakeHuman's vertex spacing is not uniform: the paper's alpha rule
        // (eq 15) leaves gaps there, so the region's own mesh edges bound it
        boundary: BoundaryMethod::MeshEdges,
        view: Some([0.0, 0.0, 1.0]),
        ..RegionOptions::default()
    };
    let plate = PlateDeformer::new(body, &region, &opts)?;
    let unit = plate.deform(body, [0.0, 0.0, 1.0], 1.0, PlateDirection::Cursor)?;
    let unit_peak = max_move(body, &unit, None);
    if !(unit_peak.is_finite() && unit_peak > 0.0) {
        return Err(DemoError::Step(format!(
            "the plate region did not move (peak {unit_peak})"
        )));
    }
    let edited = plate.deform(
        body,
        [0.0, 0.0, 1.0],
        peak / unit_peak,
        PlateDirection::Cursor,
    )?;
    let diffs: Vec<f64> = region
        .iter()
        .map(|&i| {
            let i = i as usize;
            let target = crate::mesh::add(body.positions[i], offset[i]);
            crate::mesh::dist(edited.positions[i], target) / peak
        })
        .collect();
    let s = crate::mesh::metrics::stats(&diffs);
    Ok((
        edited,
        BellyComparison {
            region_vertices: region.len(),
            peak,
            rms_rel: s.rms,
            max_rel: s.max,
        },
    ))
}

/// Runs the whole demo pipeline.
pub fn build() -> Result<Demo, DemoError> {
    let (sketched, sketch_step) = sketched_female()?;
    // the base body: the reconstruction's part layout (pde6::body) is
    // fitted to its proportions
    let base = makehuman::base_body()?;
    let template = base.mesh;
    let chest = chest_sculpt(&template)?;
    let (belly, belly_vs_morph) = belly_push(&chest, &base.original_index)?;
    let edits = vec![
        edit_report(
            "chest: curve + drag, 4-sided PDE (Galerkin)",
            "000",
            &template,
            &chest,
        ),
        edit_report(
            "belly: morph region + cursor force, C1 plate bending",
            "001",
            &chest,
            &belly,
        ),
    ];
    // one closed body: parts, mitten hands with thumbs, crown and the
    // hips/shoulders/wrists transitions
    let closed = reconstruct_closed(&belly, &ClosedOptions::default())?;
    let (reconstruction, body_report) = (closed.model.mesh, closed.report);
    let (skirt, skirt_report) = skirt::skirt(&belly, &skirt::SkirtOptions::default())?;
    let (prop, prop_report) = teddy_prop(&belly)?;
    Ok(Demo {
        unit: UNIT,
        report: DemoReport {
            unit: UNIT,
            sketched: sketch_step,
            template: "MakeHuman hm08 base body (skin group)",
            template_vertices: template.positions.len(),
            edits,
            belly_vs_morph,
            reconstruction: body_report,
            skirt: skirt_report,
            prop: prop_report,
        },
        skirt,
        sketched,
        sculpted: belly,
        reconstruction,
        prop,
    })
}
