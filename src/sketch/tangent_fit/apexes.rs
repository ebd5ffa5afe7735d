//! The seam apexes of sketched transitions fitted to the drawing: each
//! alternative apex `sketch::apex` derives (a raised shoulder's peak
//! nearer the neck than halfway) is tried against the derived apex on
//! the two children whose loops share the seam, by the factors' rules
//! ([`Scene::fit_members`] with [`Guard::NoCrease`]): taken only when it
//! misses the drawn views by less (beyond [`super::FIT_TIE`]) without a
//! crease or fold the derived apex avoids.

use super::{drawn_views, part_sets, Guard, Scene};
use crate::character::assembly::{transition_points, BlendTry, Resolution};
use crate::character::part::PartSurface;
use crate::character::spec::TransitionSpec;
use crate::character::ModelError;
use crate::profile::Profile;
use crate::sketch::derived::ApexAlternative;

/// The plain blend at the derived tangent factor: the apexes are fitted
/// before the factors and rises (`fit_child_scales`).
const PLAIN: [BlendTry; 1] = [BlendTry {
    factor: 1.0,
    rise: [0.0; 2],
}];

/// Fits the seam apexes of `transitions` among `alts` (module docs,
/// [`fit_apexes`]), then each child's tangent factor and late depth blend
/// ([`super::fit_child_scales`]). `parts`: the solved parts; `front`,
/// `side`: the placed drawn outlines; `height`: the model height.
pub fn fit_transitions(
    transitions: &mut [TransitionSpec],
    alts: &[ApexAlternative],
    parts: &[PartSurface],
    front: &Profile,
    side: Option<&Profile>,
    height: f64,
) -> Result<(), ModelError> {
    if !alts.is_empty() {
        let res = Resolution::default();
        let rows = res.transition_rows;
        let mut all = part_sets(parts, height, &res);
        for (ti, t) in transitions.iter().enumerate() {
            for c in 0..t.children.len() {
                let pts = transition_points(t, parts, c, rows, &PLAIN)?;
                all.push((
                    format!("{ti}/{c}"),
                    pts.into_iter().next().unwrap_or_default(),
                ));
            }
        }
        let mut scene = Scene {
            drawn: drawn_views(front, side),
            all,
            rows,
            height,
        };
        fit_apexes(&mut scene, transitions, alts, parts)?;
    }
    super::fit_child_scales(transitions, parts, front, side, height)
}

/// Each alternative of `alts` tried against its seam's derived apex on
/// the two children beside the seam, whose points at the derived apex
/// the `scene` already holds; a kept one replaces the apex.
fn fit_apexes(
    scene: &mut Scene,
    transitions: &mut [TransitionSpec],
    alts: &[ApexAlternative],
    parts: &[PartSurface],
) -> Result<(), ModelError> {
    let rows = scene.rows;
    for a in alts {
        let Some(t) = transitions.get(a.transition) else {
            continue;
        };
        if a.seam + 1 >= t.children.len() || a.seam >= t.seam_apex.len() {
            continue;
        }
        let me = [
            format!("{}/{}", a.transition, a.seam),
            format!("{}/{}", a.transition, a.seam + 1),
        ];
        let derived: Vec<Vec<[f64; 3]>> = me
            .iter()
            .map(|n| {
                let slot = scene.all.iter().find(|(m, _)| m == n);
                slot.map(|(_, p)| p.clone()).unwrap_or_default()
            })
            .collect();
        let mut tc = t.clone();
        tc.seam_apex[a.seam] = a.apex;
        let mut moved = Vec::with_capacity(2);
        for c in [a.seam, a.seam + 1] {
            let pts = transition_points(&tc, parts, c, rows, &PLAIN)?;
            moved.push(pts.into_iter().next().unwrap_or_default());
        }
        let tried = vec![derived, moved];
        if scene.fit_members(&[me[0].as_str(), me[1].as_str()], tried, Guard::NoCrease) == 1 {
            transitions[a.transition].seam_apex[a.seam] = a.apex;
        }
    }
    Ok(())
}
