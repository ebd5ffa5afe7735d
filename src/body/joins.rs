//! The joins of a closed body ([`super::closed`]): the hips and shoulders
//! transitions with their seam apexes found on the skin, and where the
//! shoulders' seams cut the torso's end ring, measured per body.

use super::intersect::{crossing_pairs, CrossingPair};
use super::layout::Layout;
use super::BodyError;
use crate::character::assembly::{build_model_with, Model, PartCache, Resolution};
use crate::character::doc::{PartSpec, TransitionSpec};
use crate::character::ring::{cut_indices, RING_VERTICES};
use crate::mesh::metrics::TriangleBvh;
use crate::mesh::{add, scale, Mesh};

pub use crate::character::spec::SHOULDER_TANGENT_SCALE;

/// How far (ring vertices of [`RING_VERTICES`]) [`shoulder_cuts`] may move
/// each shoulder cut from the fixed angles toward its arm: 5 of 48 keeps at
/// least a third of the end ring between an arm's cuts.
pub const SHOULDER_CUT_SHIFT_MAX: usize = 5;

/// The shoulders' cut indices with seam 1's back cut moved `a` and its
/// front cut `b` ring vertices toward the left arm, seam 2's mirrored toward
/// the right arm, as `[(front, back); 2]` in
/// [`crate::character::ring::cut_table`]'s order. Ring index 0 is +x, and
/// the indices (0, n / 2) lie behind the torso (z < 0), (n / 2, n) in front.
pub fn shifted_shoulder_cuts(a: usize, b: usize) -> [(usize, usize); 2] {
    let (f1, b1) = cut_indices(1, 3, &[]);
    let (f2, b2) = cut_indices(2, 3, &[]);
    [(f1 + a, b1 - b), (f2 - a, b2 + b)]
}

/// `cuts` as `TransitionSpec::cut_angles` (the angles of the cuts in
/// (0, pi), then those in (pi, 2 pi)).
pub fn shoulder_cut_angles(cuts: [(usize, usize); 2]) -> Vec<f64> {
    let a = |i: usize| 2.0 * std::f64::consts::PI * i as f64 / RING_VERTICES as f64;
    vec![a(cuts[0].0), a(cuts[1].0), a(cuts[0].1), a(cuts[1].1)]
}

/// Crossing pairs with a triangle in the shoulders transition, the largest
/// distance (relative to the height) from its vertices and triangle
/// centroids to the skin, and every crossing pair of `m` (for the report).
fn shoulder_state(skin_bvh: &TriangleBvh, m: &Mesh, h: f64) -> (usize, f64, Vec<CrossingPair>) {
    let pairs = crossing_pairs(m);
    let Some(g) = m.groups.iter().position(|g| g == "shoulders") else {
        return (0, 0.0, pairs);
    };
    let g = g as u32;
    let crossings = pairs
        .iter()
        .filter(|&&(t, u, _)| m.tri_group[t] == g || m.tri_group[u] == g)
        .count();
    let mut far = 0.0f64;
    for (t, tri) in m.triangles.iter().enumerate() {
        if m.tri_group[t] != g {
            continue;
        }
        let [a, b, c] = tri.map(|v| m.positions[v as usize]);
        for p in [a, b, c, scale(add(add(a, b), c), 1.0 / 3.0)] {
            if let Some(hit) = skin_bvh.closest(p) {
                far = far.max(hit.1);
            }
        }
    }
    (crossings, far / h, pairs)
}

/// The shoulders' cuts of one body, measured (issue 15's female armpits).
///
/// With the fixed cuts (`pi - j pi / 3`) the arm's loop starts at a third
/// of the torso's end ring from the side. On the female chests that ring
/// runs over the upper slope of the breasts, where the torso's u-tangent
/// (the loop's cross tangent there, for C1) points up, back and in and is
/// up to 3 times as long as elsewhere; the arm's front columns leave the
/// ring toward the midline and turn back out to the arm ring, across one
/// another, and the back corner likewise. Where the cuts should go differs
/// per body and is not monotonic in the cut (README, Self-intersections:
/// moving them one vertex can double the crossings), so the cuts are
/// measured: when the shoulders built with the fixed cuts have a crossing
/// pair, every shift `(a, b)` of the back and front cut toward the arm
/// (0..=[`SHOULDER_CUT_SHIFT_MAX`] each, seam 2 mirrored) is built, the
/// smallest total shift with no crossing pair in the shoulders wins, else
/// the fewest pairs; a candidate is admitted only when the shoulders'
/// distance to the skin stays within `max_rel` (the max error target,
/// `closed::MAX_MAX_REL`; a
/// larger head loop bulges more in front of the throat) or within that of
/// the fixed cuts. Bodies whose shoulders do not cross (the base, the male
/// bodies) keep the fixed cuts untouched. Returns the chosen transitions
/// and model, and the model's crossing pairs.
pub(super) fn shoulder_cuts(
    skin: &Mesh,
    specs: &[PartSpec],
    mut transitions: Vec<TransitionSpec>,
    h: f64,
    max_rel: f64,
    res: Resolution,
) -> Result<(Vec<TransitionSpec>, Model, Vec<CrossingPair>), BodyError> {
    let mut cache = PartCache::default();
    let model = build_model_with(specs, &transitions, h, res, &[], Some(&mut cache))?;
    let bvh = TriangleBvh::new(skin);
    let (x0, far0, pairs0) = shoulder_state(&bvh, &model.mesh, h);
    let shoulders = transitions.iter().position(|t| t.name == "shoulders");
    let Some(k) = shoulders.filter(|_| x0 > 0) else {
        return Ok((transitions, model, pairs0));
    };
    let bound = max_rel.max(far0);
    let mut shifts: Vec<(usize, usize)> = (0..=SHOULDER_CUT_SHIFT_MAX)
        .flat_map(|a| (0..=SHOULDER_CUT_SHIFT_MAX).map(move |b| (a, b)))
        .filter(|&s| s != (0, 0))
        .collect();
    shifts.sort_by_key(|&(a, b)| (a + b, a));
    type Best = (usize, Vec<f64>, Option<(Model, Vec<CrossingPair>)>);
    let mut best: Best = (x0, Vec::new(), None);
    for (a, b) in shifts {
        let mut tr = transitions.clone();
        tr[k].cut_angles = shoulder_cut_angles(shifted_shoulder_cuts(a, b));
        let m = build_model_with(specs, &tr, h, res, &[], Some(&mut cache))?;
        let (x, far, pairs) = shoulder_state(&bvh, &m.mesh, h);
        if x < best.0 && far <= bound {
            best = (x, tr[k].cut_angles.clone(), Some((m, pairs)));
            if x == 0 {
                break;
            }
        }
    }
    match best {
        (_, angles, Some((m, pairs))) => {
            transitions[k].cut_angles = angles;
            Ok((transitions, m, pairs))
        }
        _ => Ok((transitions, model, pairs0)),
    }
}

/// The hips and shoulders transitions with their seam apexes: the crotch,
/// and the top of each shoulder halfway between the neck and the outer
/// shoulder.
pub(super) fn transitions(
    skin: &Mesh,
    lay: &Layout,
    specs: &[PartSpec],
) -> Result<Vec<TransitionSpec>, BodyError> {
    let h = lay.height();
    let bottom = specs[0].sections[0].centre;
    let top = specs[0].sections[specs[0].sections.len() - 1].centre;
    let crotch = [bottom[0], lay.crotch, bottom[2]];
    let neck_f = crate::pde6::sampling::section_frame(lay.neck)?;
    let neck = super::layout::loops_in_plane(skin, &neck_f);
    let neck_x = neck
        .iter()
        .min_by(|a, b| a.centroid[0].abs().total_cmp(&b.centroid[0].abs()))
        .map(|l| l.x_range)
        .ok_or_else(|| BodyError::LayoutNotFound {
            what: "the neck",
            detail: format!("no loop at y = {:.3}", lay.neck),
        })?;
    let mut apex = Vec::new();
    for (sign, arm) in [(-1.0, lay.arm_left), (1.0, lay.arm_right)] {
        let nx = if sign < 0.0 { neck_x.0 } else { neck_x.1 };
        let x = 0.5 * (nx + arm[0]);
        let band = 0.01 * h;
        let y = skin
            .positions
            .iter()
            .filter(|p| (p[0] - x).abs() < band && p[1] < lay.neck && p[1] > lay.armpit)
            .map(|p| p[1])
            .fold(f64::NAN, f64::max);
        if !y.is_finite() {
            return Err(BodyError::LayoutNotFound {
                what: "a shoulder top",
                detail: format!("no skin vertex near x = {x:.3} between the armpits and the neck"),
            });
        }
        apex.push([x, y, top[2]]);
    }
    // the shoulders' cut angles are measured per body by shoulder_cuts
    Ok(TransitionSpec::humanoid(
        crotch,
        apex,
        SHOULDER_TANGENT_SCALE,
        SHOULDER_TANGENT_SCALE,
    ))
}
