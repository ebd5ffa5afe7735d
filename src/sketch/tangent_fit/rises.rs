//! The late depth blend of each sketched child that continues its parent,
//! fitted to the drawings (`character::rise`; module docs of
//! [`super`]).

use super::{Guard, Scene};
use crate::character::assembly::{transition_points, BlendTry};
use crate::character::part::PartSurface;
use crate::character::spec::TransitionSpec;
use crate::character::ModelError;

/// The starts of a late depth blend tried on each side of each child
/// ([`Scene::fit_rises`]), the plain blend first (ties keep it): from
/// none to three quarters of the transition, in steps of 0.15 as
/// [`FIT_FACTORS`](super::FIT_FACTORS); not fitted to the corpus. A later start turns the
/// column in depth within fewer of the mesh's rows than its 10 across the
/// transition can show smoothly.
pub const FIT_RISES: [f64; 6] = [0.0, 0.15, 0.3, 0.45, 0.6, 0.75];
/// The late depth blend is fitted only to a child that continues its
/// parent (`continues_parent`): its ring's centre within 45 degrees of the
/// parent's end direction, seen from the centroid of its loop (a head over
/// the torso, a leg under it; not an arm hanging from the shoulders or held
/// out to the side, whose transition turns away from the parent's axis and
/// whose depth a side view does not show apart from the torso's: there a
/// late start only folded the armpit, the corpus's random_4).
pub const CONTINUES_COS: f64 = std::f64::consts::FRAC_1_SQRT_2;
impl Scene<'_> {
    /// The starts of the late depth blend of child `c` and its mirror
    /// child `k - 1 - c` (the same child for the middle one), on their
    /// loops' -z and +z sides (`TransitionSpec::child_rises`): a side view
    /// sees both children of a pair in one place, so they are fitted
    /// together and a symmetric drawing keeps a symmetric model. Each side
    /// tries [`FIT_RISES`] in turn (the -z side with the +z side's plain
    /// blend, then the +z side with the -z side's pick) at each child's
    /// fitted tangent factor (`factors`, by child), kept as
    /// [`Scene::fit_members`] keeps a factor, but a rise may crease (a
    /// square shoulder is a drawn corner) as long as it turns no more
    /// than a fold or the plain blend ([`Guard::NoFold`]; with the
    /// factors' guard the corpus's side misses grew back,
    /// docs/drawing-corpus.md, twenty-fourth measurement).
    pub(super) fn fit_rises(
        &mut self,
        t: &TransitionSpec,
        parts: &[PartSurface],
        c: usize,
        names: &[&str],
        factors: &[f64],
    ) -> Result<[f64; 2], ModelError> {
        let k = t.children.len();
        if !continues_parent(t, parts, c, self.rows)? {
            return Ok([0.0; 2]);
        }
        let mut members = vec![c];
        if k - 1 - c != c {
            members.push(k - 1 - c);
        }
        let me: Vec<&str> = members.iter().map(|&m| names[m]).collect();
        let mut rise = [0.0; 2];
        for side in 0..2 {
            let mut tried = vec![Vec::new(); FIT_RISES.len()];
            for &m in &members {
                let tries: Vec<BlendTry> = FIT_RISES
                    .iter()
                    .map(|&r| {
                        let mut rise = rise;
                        rise[side] = r;
                        BlendTry {
                            factor: factors[m],
                            rise,
                        }
                    })
                    .collect();
                let pts = transition_points(t, parts, m, self.rows, &tries)?;
                for (slot, p) in tried.iter_mut().zip(pts) {
                    slot.push(p);
                }
            }
            rise[side] = FIT_RISES[self.fit_members(&me, tried, Guard::NoFold)];
        }
        Ok(rise)
    }
}

/// Whether child `c` of `t` continues its parent ([`CONTINUES_COS`]): the
/// cosine of the angle between the parent's end direction and the
/// direction from the centroid of the child's loop (row 0 of its points)
/// to the centroid of its ring (the last row).
fn continues_parent(
    t: &TransitionSpec,
    parts: &[PartSurface],
    c: usize,
    rows: usize,
) -> Result<bool, ModelError> {
    use crate::character::spec::End;
    use crate::mesh::{dot, norm, sub};
    let Some(parent) = parts.iter().find(|p| p.name == t.parent) else {
        return Ok(false);
    };
    let sgn = if t.parent_end == End::End { 1.0 } else { -1.0 };
    let axis = parent
        .section(parent.end_u(t.parent_end), 1)
        .c0
        .map(|x| sgn * x);
    let pts = transition_points(t, parts, c, rows, &[BlendTry::document(t, c)])?;
    let Some(pts) = pts.first() else {
        return Ok(false);
    };
    let n = pts.len() / (rows + 1);
    let centroid = |row: &[[f64; 3]]| {
        let s = row
            .iter()
            .fold([0.0; 3], |a, p| [a[0] + p[0], a[1] + p[1], a[2] + p[2]]);
        s.map(|x| x / row.len().max(1) as f64)
    };
    let towards = sub(centroid(&pts[rows * n..]), centroid(&pts[..n]));
    let cos = dot(axis, towards) / (norm(axis) * norm(towards));
    Ok(cos >= CONTINUES_COS)
}
