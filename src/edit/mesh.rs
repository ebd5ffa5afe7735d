//! Edits that act beyond the part specifications: force displacements on
//! the built parts and the plate bending of the built mesh.

use crate::character::assembly::Displacement;
use crate::character::log::{Edit, EditError};
use crate::character::part::PartSurface;
use crate::mesh::{dist, Mesh};
use crate::plate::deformer::{BoundaryMethod, MappingMethod, PlateDeformer, RegionOptions};
use std::f64::consts::PI;
use std::sync::Arc;

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
                    field: Arc::new(field),
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
            best = best.min(dist(p.point(u, th), c));
        }
    }
    best
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
pub fn apply_plate(mesh: &mut Mesh, e: &Edit) -> Result<(), EditError> {
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
