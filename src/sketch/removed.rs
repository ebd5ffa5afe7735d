//! Removed parts (paper 000 sec 4.1, paragraph 3: hair, a tail, ears are
//! "removed" from the primary profile and modeled from their own profiles,
//! then composed with the rest).
//!
//! A removed part is one closed front outline (and optionally its side
//! outline) in model coordinates, drawn where the part sits. It is built
//! like a limb, as one C2 sixth-order PDE chain (`pde6`, [`crate::character::part`]):
//! the outline is turned so that its principal axis ([`super::align::axes`])
//! is vertical, sliced into sections placed where its profile's curvature
//! changes ([`super::derive::part_from_region`]), both ends closed to the
//! outline's extreme points, and the sections turned back. With a side
//! outline (used only when the part's axis is already vertical, within
//! [`super::align::ROTATION_EPS_DEG`]) the sections are ellipses whose depth
//! comes from it, else circles.
//!
//! Composition: the part is a **separate closed component** of the model
//! mesh (its own group), **not stitched** to the body: it may overlap the
//! body, as in the paper's composition. It is measured on its own: its
//! front silhouette against its own outline.

use super::align::{axes, Alignment, ROTATION_EPS_DEG};
use super::input::{read_profile, Outline};
use super::place::Placement;
use super::segment::{Pick, Region, SidePick};
use super::SketchError;
use crate::character::doc::{PartSpec, RemovedPart, SectionShape};
use crate::profile::View;
use std::path::Path;

/// A removed part built into a part spec, with its outlines.
#[derive(Clone, Debug)]
pub struct BuiltRemoved {
    pub spec: PartSpec,
    pub front: Outline,
    pub side: Option<Outline>,
}

/// Builds one removed part from its profiles (relative paths against
/// `base`), drawn on the body's pages: `placement` takes them to the
/// model's frame as it takes the body's views ([`super::place`]).
pub fn removed_part(
    rp: &RemovedPart,
    base: &Path,
    tol: Option<f64>,
    placement: &Placement,
) -> Result<BuiltRemoved, SketchError> {
    let bad = |m: String| SketchError::Part {
        part: rp.name.clone(),
        message: m,
    };
    let front = read_profile(&rp.front, base, View::Front, tol).map_err(|e| bad(e.to_string()))?;
    let front = placement
        .front_outline(&front)
        .map_err(|e| bad(e.to_string()))?;
    let side = match &rp.side {
        Some(s) => {
            let o = read_profile(s, base, View::Side, tol).map_err(|e| bad(e.to_string()))?;
            Some(placement.side_outline(&o).map_err(|e| bad(e.to_string()))?)
        }
        None => None,
    };
    let side_pts = side.as_ref().map(|s| s.points());
    let spec = upright_chain(&rp.name, front.points(), side_pts).map_err(|e| bad(e.to_string()))?;
    Ok(BuiltRemoved { spec, front, side })
}

/// A part built from its own closed outline (model coordinates), as one
/// chain along the outline's principal axis, closed at both ends: turned
/// upright, sliced, and turned back. With `side` (used only when the axis
/// is vertical already) the sections are ellipses of its depth, else
/// circles at z = 0.
pub fn upright_chain(
    name: &str,
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
) -> Result<PartSpec, SketchError> {
    upright_chain_n(name, front, side, super::derive::SECTIONS_PER_PART, false)
}

/// [`upright_chain`] with `m` sections (`3 P + 1`); `parallel`: the
/// sections stay across the principal axis whatever the central curve's
/// tilt (an animal's body, whose cut ends pull its slices' midpoints).
pub fn upright_chain_n(
    name: &str,
    front: &[[f64; 2]],
    side: Option<&[[f64; 2]]>,
    m: usize,
    parallel: bool,
) -> Result<PartSpec, SketchError> {
    let ax = axes(front);
    // turn the major axis vertical: angle into (-90, 90] degrees
    let half = std::f64::consts::FRAC_PI_2;
    let mut turn = half - ax.major;
    if turn > half {
        turn -= std::f64::consts::PI;
    }
    let al = Alignment {
        pivot: ax.centroid,
        angle: -turn,
    };
    let up: Vec<[f64; 2]> = front.iter().map(|p| al.to_upright(*p)).collect();
    let upright = turn.abs().to_degrees() < ROTATION_EPS_DEG;
    let side_pts = if upright { side } else { None };
    let yr = crate::polygon::span(&up, 1);
    let big = 1e3 * (yr[1] - yr[0]).max(f64::MIN_POSITIVE);
    let region = Region {
        name: name.into(),
        y0: yr[0],
        y1: yr[1],
        pick: Pick::CentreIn(-big, big),
        downward: false,
        tip: true,
        shoulder: None,
        horizontal: parallel,
        side: SidePick::Whole,
    };
    let mut spec = super::part_slices::part_with_sections(&up, side_pts, &region, m)?;
    // close the start at the outline's lowest point (in the upright frame)
    let first = spec.sections[0].centre;
    spec.sections[0].centre = [first[0], yr[0], first[2]];
    spec.sections[0].shape = SectionShape::Circle { r: 0.0 };
    spec.closed_start = true;
    if !al.is_identity() {
        for s in &mut spec.sections {
            s.centre = al.point_back(s.centre);
            s.e1 = al.vector_back(s.e1);
            s.e2 = al.vector_back(s.e2);
        }
    }
    let mut u = 0.0;
    spec.sections[0].u = 0.0;
    for i in 1..spec.sections.len() {
        u += crate::mesh::dist(spec.sections[i - 1].centre, spec.sections[i].centre);
        spec.sections[i].u = u;
    }
    Ok(spec)
}
