//! The pde6 part surface: the globally solved C2 sixth-order PDE chain
//! (`pde6::Chain::c2_global`, paper 002) through the part's key sections.

use super::PartGeometry;
use crate::curve::Fourier3;
use crate::pde6::{Chain, EndCurvature, Section};
use crate::surface::Joined;

/// Solves the C2 chain of PDE parameter `a` through `sections`, with the
/// given end condition at its start and end.
pub(super) fn build(
    a: f64,
    sections: &[Section],
    ends: [EndCurvature; 2],
) -> Result<Chain, crate::pde6::Pde6Error> {
    Chain::c2_global_ends(a, sections, ends)
}

impl PartGeometry for Chain {
    fn section(&self, u: f64, d: usize) -> Fourier3 {
        self.pieces[self.piece_at(u)].global_section(u, d)
    }

    fn family(&self) -> &'static str {
        "pde6_c2"
    }

    fn internal_jumps(&self, samples: usize) -> [f64; 3] {
        self.join_jumps(samples)
    }
}
