//! Edits that act beyond the part specifications: force displacements on
//! the built parts, the plate bending of the built mesh, and an editing
//! [`Session`] that re-solves only the parts an edit changed.

use super::{Edit, EditError};
use crate::character::doc::CharacterDoc;
use crate::mesh::{dist, Mesh};
use crate::pde4::two_sided::Method;
use crate::pde4::{ShapeParams, TwoSided};
use crate::plate::deformer::{BoundaryMethod, MappingMethod, PlateDeformer, RegionOptions};
use crate::sketch::build::{build_model_with, Displacement, PartCache};
use crate::sketch::part::PartSurface;
use crate::sketch::report::build_document_with;
use crate::sketch::{Built, Model, Resolution, SketchError};
use crate::surface::Surface;
use std::f64::consts::PI;
use std::path::PathBuf;

/// Series terms `(M, N)` of a force edit's 2-sided patch (sine terms in u,
/// harmonics in v).
pub const FORCE_TERMS: (usize, usize) = (16, 8);

/// The 2-sided pde4 solution of a force edit (clamped at both ends of its
/// range: zero boundary curves and tangents), shape parameters
/// `a1 = 1, a2 = 2 a^2, a3 = a^4` (`ShapeParams::plate_ratio`: scaling all
/// three alike would only rescale the response).
pub fn force_field(e: &Edit) -> Result<TwoSided, EditError> {
    let Edit::Force { force, a, .. } = e else {
        return Err(EditError::Invalid {
            op: e.op(),
            part: e.part().unwrap_or("").into(),
            message: "not a force edit".into(),
        });
    };
    let p = ShapeParams::plate_ratio(*a);
    TwoSided::new(
        [p; 3],
        std::slice::from_ref(force),
        FORCE_TERMS.0,
        FORCE_TERMS.1,
        Method::Exact,
        None,
    )
    .map_err(|err| EditError::Invalid {
        op: e.op(),
        part: e.part().unwrap_or("").into(),
        message: format!("force patch: {err}"),
    })
}

/// The displacement fields of the force edits (2- and 4-sided) among
/// `edits`, in order.
pub fn displacements(edits: &[Edit]) -> Result<Vec<Displacement>, EditError> {
    edits
        .iter()
        .filter_map(|e| {
            super::force4::field_of(e).map(|f| {
                f.map(|(u, field)| Displacement {
                    part: e.part().unwrap_or("").to_string(),
                    u,
                    field,
                })
            })
        })
        .collect()
}

/// Samples per direction of [`distance_to_part`].
pub const DISTANCE_SAMPLES: usize = 64;

/// Smallest distance from `c` to a grid of the part's surface points.
pub fn distance_to_part(p: &PartSurface, c: [f64; 3]) -> f64 {
    let n = DISTANCE_SAMPLES;
    let mut best = f64::INFINITY;
    for i in 0..=n {
        let u = p.u0 + (p.u1 - p.u0) * i as f64 / n as f64;
        for j in 0..n {
            let th = 2.0 * PI * j as f64 / n as f64;
            best = best.min(dist(p.chain.point(u, th), c));
        }
    }
    best
}

/// Applies the mesh-level edits among `edits` to the built mesh, in log
/// order: plate bendings ([`Edit::Plate`]) and SASM features
/// ([`Edit::Sasm`], [`Edit::SasmAux`], on `parts`, the built part surfaces)
/// interleaved as the log has them (a SASM feature keeps what an earlier
/// plate or force did to its part: it adds its height to the vertices'
/// current positions).
pub fn apply_mesh_edits(
    mesh: &mut Mesh,
    parts: &[PartSurface],
    edits: &[Edit],
) -> Result<(), EditError> {
    for e in edits {
        match e {
            Edit::Plate { .. } => apply_plate(mesh, e)?,
            Edit::Sasm(_) | Edit::SasmAux(_) => {
                let invalid = |m: String| EditError::Invalid {
                    op: e.op(),
                    part: e.part().unwrap_or("").into(),
                    message: m,
                };
                if let Some(f) = crate::sasm::edit::feature_of(e, parts) {
                    let f = f.map_err(|err| invalid(err.to_string()))?;
                    let p = parts
                        .iter()
                        .find(|p| p.name == f.part)
                        .ok_or_else(|| invalid("the part is not built".into()))?;
                    crate::sasm::apply_feature(mesh, p, &f)
                        .map_err(|err| invalid(err.to_string()))?;
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// Applies the plate edits among `edits` to the built mesh, in order (the
/// SASM edits left out: [`apply_mesh_edits`] applies both).
pub fn apply_plates(mesh: &mut Mesh, edits: &[Edit]) -> Result<(), EditError> {
    for e in edits {
        if matches!(e, Edit::Plate { .. }) {
            apply_plate(mesh, e)?;
        }
    }
    Ok(())
}

/// One plate edit: the region is the part group's vertices within the
/// radius, bent as a clamped plate (mesh-edge boundary, harmonic disk
/// mapping) scaled so that the peak displacement is the edit's `d`.
fn apply_plate(mesh: &mut Mesh, e: &Edit) -> Result<(), EditError> {
    let Edit::Plate {
        part,
        centre,
        radius,
        d,
    } = e
    else {
        return Ok(());
    };
    let invalid = |m: String| EditError::Invalid {
        op: e.op(),
        part: part.clone(),
        message: m,
    };
    let g = mesh
        .groups
        .iter()
        .position(|n| n == part)
        .ok_or_else(|| invalid("the mesh has no group of this part".into()))? as u32;
    let mut inside = vec![false; mesh.positions.len()];
    for (t, tr) in mesh.triangles.iter().enumerate() {
        if mesh.tri_group[t] == g {
            for &v in tr {
                inside[v as usize] = dist(mesh.positions[v as usize], *centre) < *radius;
            }
        }
    }
    let region: Vec<u32> = (0..inside.len())
        .filter(|&i| inside[i])
        .map(|i| i as u32)
        .collect();
    let opts = RegionOptions {
        boundary: BoundaryMethod::MeshEdges,
        mapping: MappingMethod::Harmonic,
        ..RegionOptions::default()
    };
    let plate = PlateDeformer::new(mesh, &region, &opts)
        .map_err(|err| invalid(format!("plate region ({} vertices): {err}", region.len())))?;
    let peak = plate.weights().iter().copied().fold(0.0, f64::max);
    if !(peak.is_finite() && peak > 0.0) {
        return Err(invalid(format!(
            "the plate region ({} vertices) has no interior vertex to move",
            region.len()
        )));
    }
    let q = [d[0] / peak, d[1] / peak, d[2] / peak];
    plate
        .apply(&mut mesh.positions, q)
        .map_err(|err| invalid(err.to_string()))?;
    if plate
        .region()
        .iter()
        .any(|&v| mesh.positions[v as usize].iter().any(|x| !x.is_finite()))
    {
        return Err(invalid(format!(
            "the motion d = {d:?} moves vertices to non-finite positions; reduce it"
        )));
    }
    Ok(())
}

/// An editing session: the document, where its profiles live, the mesh
/// resolution and a cache of built parts, so that a rebuild after an edit
/// re-solves only the part the edit changed.
#[derive(Clone, Debug)]
pub struct Session {
    pub doc: CharacterDoc,
    pub base: PathBuf,
    pub res: Resolution,
    pub cache: PartCache,
    /// Model height, read from the front profile at the first build.
    pub height: Option<f64>,
}

impl Session {
    /// A session on `doc` (profiles relative to `base`).
    pub fn new(doc: CharacterDoc, base: PathBuf, res: Resolution) -> Session {
        Session {
            doc,
            base,
            res,
            cache: PartCache::default(),
            height: None,
        }
    }

    /// Validates and appends an edit ([`CharacterDoc::push_edit`]).
    pub fn push(&mut self, e: Edit) -> Result<(), EditError> {
        self.doc.push_edit(e)
    }

    /// Builds the document's current state, re-solving only changed parts
    /// (with the report: profiles read, silhouettes measured).
    pub fn build(&mut self) -> Result<Built, SketchError> {
        let b = build_document_with(
            &self.doc,
            &self.base,
            self.res,
            false,
            Some(&mut self.cache),
        )?;
        self.height = Some(b.report.height);
        Ok(b)
    }

    /// The interactive path: only the model (mesh and joins) of the current
    /// state, re-solving only changed parts, without reading the profiles or
    /// measuring silhouettes (the mesh equals [`Session::build`]'s bit for
    /// bit). Needs stored parts; the first call runs [`Session::build`] once
    /// to learn the height.
    pub fn model(&mut self) -> Result<Model, SketchError> {
        let height = match self.height {
            Some(h) => h,
            None => self.build()?.report.height,
        };
        if self.doc.parts.is_empty() {
            return Err(SketchError::Document(
                "the session's document has no stored parts".into(),
            ));
        }
        let active = self.doc.active_edits();
        let err = |e: EditError| SketchError::Document(e.to_string());
        super::check_order(&self.doc.transitions, active).map_err(err)?;
        let edited = super::apply_to_parts(&self.doc.parts, active).map_err(err)?;
        let disp = displacements(active).map_err(err)?;
        let mut model = build_model_with(
            &edited,
            &self.doc.transitions,
            height,
            self.res,
            &disp,
            Some(&mut self.cache),
        )?;
        apply_mesh_edits(&mut model.mesh, &model.parts, active).map_err(err)?;
        Ok(model)
    }
}

/// Pushes `e` and keeps it only when the document still builds as
/// `character build` builds it (default resolution, profiles read from
/// `base`): [`CharacterDoc::push_edit`] validates an edit against the parts,
/// but a mesh-level edit (a plate region whose projection overlaps, a
/// motion that overflows) can only be judged on the built mesh. On error
/// `doc` is unchanged.
pub fn push_checked(
    doc: &mut CharacterDoc,
    e: Edit,
    base: &std::path::Path,
) -> Result<Built, SketchError> {
    let mut next = doc.clone();
    let summary = e.summary();
    next.push_edit(e)
        .map_err(|err| SketchError::Document(err.to_string()))?;
    let what = format!("edit {} ({summary})", next.cursor - 1);
    let built = super::effect::validate_by_build(&next, base, &what)?;
    *doc = next;
    Ok(built)
}

/// Redoes the next undone edit and keeps it only when the document then
/// builds as [`push_checked`] requires (validated by its effect: a log
/// written by hand or by an older version is not trusted). On error `doc`
/// is unchanged.
pub fn redo_checked(doc: &mut CharacterDoc, base: &std::path::Path) -> Result<Built, SketchError> {
    let mut next = doc.clone();
    next.redo()
        .map_err(|err| SketchError::Document(err.to_string()))?;
    let i = next.cursor - 1;
    let what = format!("redo of edit {i} ({})", next.edits[i].summary());
    let built = super::effect::validate_by_build(&next, base, &what)?;
    *doc = next;
    Ok(built)
}
