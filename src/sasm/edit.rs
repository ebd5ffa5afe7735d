//! SASM as edits of the character document (`Edit::Sasm`,
//! `Edit::SasmAux`): applied to the built mesh in log order with the plate
//! edits (`pipeline::apply_mesh_edits`). A feature adds its height
//! to the mesh as it is (`apply`), so an earlier force or plate edit of
//! the same part is kept under it.

use super::{apply_feature, Feature, SasmError};
use crate::character::log::Edit;
use crate::character::part::PartSurface;
use crate::mesh::Mesh;

/// The feature of a SASM edit on the part it names (`None` for other
/// edits).
pub fn feature_of(e: &Edit, parts: &[PartSurface]) -> Option<Result<Feature, SasmError>> {
    let name = match e {
        Edit::Sasm(s) => &s.part,
        Edit::SasmAux(s) => &s.part,
        _ => return None,
    };
    let Some(p) = parts.iter().find(|p| &p.name == name) else {
        return Some(Err(SasmError::UnknownPart(name.clone())));
    };
    match e {
        Edit::Sasm(s) => Some(Feature::from_spec(p, s)),
        Edit::SasmAux(s) => Some(Feature::from_aux(p, s)),
        _ => None,
    }
}

/// Applies the SASM edits among `edits` to the mesh, in order (the plate
/// edits left out: `pipeline::apply_mesh_edits` applies both).
pub fn apply_edits(
    mesh: &mut Mesh,
    parts: &[PartSurface],
    edits: &[Edit],
) -> Result<(), SasmError> {
    for e in edits {
        if let Some(f) = feature_of(e, parts) {
            let f = f?;
            let p = parts
                .iter()
                .find(|p| p.name == f.part)
                .ok_or_else(|| SasmError::UnknownPart(f.part.clone()))?;
            apply_feature(mesh, p, &f)?;
        }
    }
    Ok(())
}
