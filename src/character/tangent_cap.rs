//! The cap on a sketched transition's cross tangents where the parent's
//! end ring flares ([`cap_tangents`], a transition's `cap_tangents`):
//! per loop column factors composed into
//! [`super::transition::ChildTransition::ell_vertex`].

use super::part::PartSurface;
use super::ring::RING_VERTICES;
use super::seam::Seam;
use super::transition::{locate, ChildTransition, Run};
use crate::mesh::norm;
use std::f64::consts::PI;

/// Caps each loop column's cross tangent at its scale (a transition's
/// `cap_tangents`, set by sketch-guided modeling): the column's scale
/// times `1 / max(1, |dP/du|)`, `|dP/du|` the parent's u-speed at the
/// column's ring angle (along a seam: linear between the two cuts'
/// factors), composed with the scales already there ([`column_scales`](super::transition::column_scales)).
///
/// On the parent's arcs the cross tangent is `ell dP/du`. A part is
/// parametrised by the arc length of its centre, so `|dP/du|` is about 1
/// where its width changes slowly, and `ell` (the loop-to-ring distance)
/// is the tangent's length. Where a drawn outline runs nearly level into
/// the end ring (a torso narrowing in a shelf under the armpits: random_9
/// of the seed-7777 drawings, `|dP/du|` up to 26), `ell dP/du` was 26
/// times the gap the transition bridges and its rows shot past the head
/// (front profile error 23.9 % of the height, capped 2.05 %;
/// docs/drawing-corpus.md, fourteenth measurement). The join stays C1
/// with the column's scale, as with [`column_scales`](super::transition::column_scales), and the seams G1
/// (both sides' tangents stay in `span(S', D)`).
///
/// Not the default: documents written before it keep their shapes, and
/// the closed body (`body::joins`) does not set it: there it moved the
/// maxweight female's largest reconstruction error past its target
/// (3.13 %) and left shoulder crossings on the maxweight male (tests
/// `body`, `body_shoulders`).
pub fn cap_tangents(ct: &mut ChildTransition, parent: &PartSurface, seams: &[Seam]) {
    let n = RING_VERTICES as f64;
    let p1 = parent.section(ct.parent_u, 1);
    let at = |phi: f64| 1.0 / norm(p1.eval(phi)).max(1.0);
    let speed: Vec<f64> = (0..ct.n)
        .map(|i| match locate(ct, i as f64) {
            (Run::Arc { from, count }, f) => at(2.0 * PI * (from as f64 + f * count as f64) / n),
            (Run::Seam { j, reversed }, f) => {
                let s = &seams[j];
                let t = if reversed { 1.0 - f } else { f };
                let ff = at(2.0 * PI * s.i_front as f64 / n);
                let fb = at(2.0 * PI * s.i_back as f64 / n);
                ff * (1.0 - t) + fb * t
            }
        })
        .collect();
    if speed.iter().all(|f| *f >= 1.0) {
        return;
    }
    let base = std::mem::take(&mut ct.ell_vertex);
    ct.ell_vertex = speed
        .iter()
        .enumerate()
        .map(|(i, f)| base.get(i).copied().unwrap_or(ct.ell) * f)
        .collect();
}
