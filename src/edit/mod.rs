//! Local modeling (paper 000 sec 5; paper 001 for the mesh-level plate
//! edit): what the edits of a document's log (`crate::character::log`) do
//! to its parts. Spec-level edits change the part specifications
//! ([`apply_to_parts`]: shape parameter, GEC transforms, boundary curves and
//! tangents); force edits add displacement fields to the built part surfaces
//! ([`force4`]: 2-sided, 4-sided and stroke-bounded pde4 patches, the
//! stroke's map onto the square in `crate::character::log::stroke`); the plate edit bends a region of the built mesh
//! ([`apply_plates`]). The SASM edits are `crate::sasm`'s; replaying a whole
//! log (edits of every kind, in order) is `crate::pipeline`.

mod apply;
pub mod check;
pub mod check_stroke;
pub mod force4;
mod mesh;
pub mod samples;

pub use crate::character::log::stroke;

pub use apply::{apply_one, apply_to_parts, section_gec};
pub use force4::{
    field_of, force_field, force_region_field, ForceField, FORCE4_TERMS, FORCE_TERMS,
};
pub use mesh::{apply_plate, apply_plates, displacements, distance_to_part, DISTANCE_SAMPLES};
