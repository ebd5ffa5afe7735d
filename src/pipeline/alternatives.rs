//! The other derivations a build tries (an animal as shells, a
//! humanoid's upper body as shells, `sketch::Derived::alternatives`) when
//! the first model misses issue 28's bounds, and the choice between them.

use crate::character::doc::{CharacterDoc, PartSpec, TransitionSpec};
use crate::sketch::quality::Quality;
use crate::sketch::report::DerivationReport;

/// `first`, or the model of another derivation (a model as shells) when
/// `first` misses issue 28's bounds and that one misses them by less
/// ([`crate::sketch::quality::excess`] of its `quality`), a model whose
/// surface folds or creases (a turn between adjacent triangles, or the
/// length of edges turning more than 60 degrees, over its bound) never
/// kept over one that does neither (a fold is a broken surface, a profile
/// miss an inexact one: seed 3131's random_44 kept a 179 degree fold for
/// a front miss of 1.76 % of the height against 2.62 %): the others are
/// built in turn (`build`) until one meets them; one that fails to build
/// is left. When any other was tried, what the kept model's report says
/// of them (`SketchReport::derivation`; `first_shells`: the first model
/// is itself shells).
pub(super) fn keep_least_excess<T, E>(
    (first, first_shells): (T, bool),
    others: Vec<CharacterDoc>,
    quality: impl Fn(&T) -> &Quality,
    mut build: impl FnMut(CharacterDoc) -> Result<T, E>,
) -> (T, Option<DerivationReport>) {
    let bounds = crate::sketch::quality::Bounds::ISSUE;
    let score = |b: &T| crate::sketch::quality::excess(quality(b), &bounds);
    // within both bounds (NaN is not)
    let sound = |b: &T| {
        let w = &quality(b).whole;
        w.dihedral_deg <= bounds.dihedral_deg && w.creased_rel <= bounds.creased_rel
    };
    let better = |b: &T, than: &T| (sound(b), -score(b)) > (sound(than), -score(than));
    let mut excess = vec![Some(score(&first))];
    let (mut best, mut kept) = (first, 0);
    for o in others {
        if score(&best) <= 0.0 {
            break;
        }
        let b = build(o).ok();
        excess.push(b.as_ref().map(score));
        if let Some(b) = b.filter(|b| better(b, &best)) {
            (best, kept) = (b, excess.len() - 1);
        }
    }
    let report = (excess.len() > 1).then_some(DerivationReport {
        kept,
        excess,
        first_shells,
    });
    (best, report)
}

/// The documents of a derivation's `alternatives` (`doc` with each one's
/// parts and transitions, the removed parts added): a transition the
/// derivation has too (a humanoid shells' hips) is its fitted one,
/// `fitted`.
pub(super) fn docs(
    doc: &CharacterDoc,
    alternatives: Vec<(Vec<PartSpec>, Vec<TransitionSpec>)>,
    removed: &[crate::sketch::removed::BuiltRemoved],
    fitted: &[TransitionSpec],
) -> Vec<CharacterDoc> {
    alternatives
        .into_iter()
        .map(|(mut parts, mut transitions)| {
            parts.extend(removed.iter().map(|r| r.spec.clone()));
            for t in &mut transitions {
                if let Some(f) = fitted.iter().find(|f| f.name == t.name) {
                    *t = f.clone();
                }
            }
            let mut o = doc.clone();
            o.set_derived(parts, transitions);
            o
        })
        .collect()
}
