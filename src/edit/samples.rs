//! Named edits for checks, tests, benches and figures: forces in the
//! middle of a part.

use crate::character::log::Edit;
use crate::character::spec::PartSpec;
use crate::pde4::{Force, ForceKind};

/// A force edit in the middle of a part: an area force over the middle half
/// of its u range, pushing along `p`.
pub fn sample_force(p: &PartSpec, push: [f64; 3]) -> Edit {
    let (u0, u1) = (p.sections[0].u, p.sections[p.sections.len() - 1].u);
    Edit::Force {
        part: p.name.clone(),
        u: [u0 + 0.25 * (u1 - u0), u0 + 0.75 * (u1 - u0)],
        force: Force {
            kind: ForceKind::Area {
                u0: 0.2,
                u1: 0.8,
                v0: 0.1,
                v1: 0.4,
            },
            p: push,
        },
        a: 1.0,
    }
}

/// A 4-sided force edit on a part: an area force in the middle of the
/// patch inside the rectangle `u` in the middle half of the part's range by
/// `theta` in `[theta_a, theta_a + 1.2]`, pushing along `p`.
pub fn sample_force_region(p: &PartSpec, theta_a: f64, push: [f64; 3]) -> Edit {
    let (u0, u1) = (p.sections[0].u, p.sections[p.sections.len() - 1].u);
    Edit::ForceRegion {
        part: p.name.clone(),
        u: [u0 + 0.25 * (u1 - u0), u0 + 0.75 * (u1 - u0)],
        theta: [theta_a, theta_a + 1.2],
        force: Force {
            kind: ForceKind::Area {
                u0: 0.2,
                u1: 0.8,
                v0: 0.25,
                v1: 0.75,
            },
            p: push,
        },
        a: 1.0,
    }
}
