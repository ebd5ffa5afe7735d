//! The shoulders' transition on drawings whose torso ends oddly under the
//! arms (seed 7777's issue-range humanoids, `tests/data/sketch/`; written
//! by `cargo run --release --example sketch_corpus -- write DIR --seed 7777
//! --random 40 --ranges issue` as random_9 and random_6).

use crate::sketch_draw::{assert_shells, build, build_with, data_pair, shoulders};
use std::path::PathBuf;

/// The whole model's profile error bound of these checks, relative to the
/// height, per view: 1.5 times issue 28's side bound. The shelf drawing
/// now misses by 2.05 % (front) and 1.70 % (side); before the cap its
/// shoulders reached past the head (23.9 % and 19.0 %).
const SHELF_PROFILE_MAX: f64 = 0.03;

/// Creased length (edges turning more than 60 degrees) of the drawing
/// whose left apex fell over a gap, in heights: 0.96 now, 14.7 when a
/// sheet hung from an apex near its feet.
const GAP_APEX_CREASED_MAX: f64 = 2.0;

/// A torso narrowing in a nearly level shelf under the armpits has an end
/// ring whose u-speed `|dP/du|` reaches 26: the transition's cross
/// tangents `ell dP/du` were 26 times the gap they bridge, and the
/// shoulders shot past the head. Sketched transitions cap each column's
/// tangent at its scale (`character::tangent_cap::cap_tangents`).
#[test]
fn a_torso_ending_in_a_shelf_keeps_its_shoulders_under_the_head() {
    let (f, s) = data_pair("shelf_torso");
    let b = build(&f, &s, None).expect("builds");
    let shoulders = shoulders(&b);
    assert!(
        shoulders.cap_tangents,
        "sketched transitions cap their tangents"
    );
    for v in &b.report.quality.whole.views {
        assert!(
            v.max_rel <= SHELF_PROFILE_MAX,
            "{} profile error {:.2} % of the height",
            v.view,
            100.0 * v.max_rel
        );
    }
}

/// Halfway between the neck and an arm's shoulder point the drawing can
/// have a notch or a gap, and the outline's highest top below the neck
/// there was a leg's: an apex near the feet, a sheet hung from it. The
/// apex now lies above the torso's end ring and not above the neck base
/// (else on the straight shoulder line from the neck's base to the
/// shoulder point). The stacked model's (the build now keeps this
/// drawing's upper body as shells, `crowded_shoulders_are_built_as_shells`).
#[test]
fn a_shoulder_apex_over_a_gap_stays_between_the_torso_and_the_neck() {
    let (f, s) = data_pair("short_torso");
    let b = build_with(&f, &s, None, false).expect("builds");
    let part = |n: &str| {
        b.doc
            .parts()
            .iter()
            .find(|p| p.name == n)
            .unwrap_or_else(|| panic!("part {n}"))
    };
    let torso_top = part("torso").sections.last().expect("sections").centre[1];
    let head_base = part("head").sections[0].centre[1];
    let t = shoulders(&b);
    for a in &t.seam_apex {
        assert!(
            a[1] > torso_top && a[1] <= head_base,
            "apex at y = {:.4}, torso's end at {torso_top:.4}, head's base at {head_base:.4}",
            a[1]
        );
    }
    let creased = b.report.quality.whole.creased_rel;
    assert!(
        creased <= GAP_APEX_CREASED_MAX,
        "creased length {creased:.2} heights"
    );
}

/// Builds the corpus drawing `name` as `sketch build` would; the shells
/// tried only with `alternatives` ([`build_with`]).
pub(crate) fn corpus_build(name: &str, alternatives: bool) -> pdesculpt::pipeline::Built {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/sketch/corpus");
    let m = pdesculpt::pipeline::corpus::read_manifest(&dir).expect("the corpus manifest");
    let e = m
        .entries
        .iter()
        .find(|e| e.name == name)
        .unwrap_or_else(|| panic!("the corpus has {name}"));
    let (f, s) = (dir.join(&e.front), dir.join(&e.side));
    build_with(&f, &s, e.height_m, alternatives).unwrap_or_else(|err| panic!("{name}: {err}"))
}

/// The arms leave the corpus's random_4 close under a neck nearly as wide
/// as its torso: the stacked model's shoulders transition creased 0.32
/// heights, past the issue's 0.3. Below the final level the build also
/// derives the upper body as shells (`sketch::humanoid_shells`: the torso
/// chained on to the top of the head, each arm a closed chain reaching
/// into it) and keeps them when they miss the bounds by less: no
/// shoulders transition, no head part, and the whole model within the
/// issue's bounds. A drawing whose stacked model passes (t_pose) keeps it.
#[test]
fn crowded_shoulders_are_built_as_shells() {
    use pdesculpt::sketch::quality::{warnings, Bounds};
    let stacked = corpus_build("random_4", false);
    assert!(
        !warnings(&stacked.report.quality, &Bounds::ISSUE).is_empty(),
        "the stacked model misses the bounds"
    );
    shoulders(&stacked);
    let b = corpus_build("random_4", true);
    let d = b
        .report
        .derivation
        .as_ref()
        .expect("the report says what was tried");
    assert!(d.kept > 0 && d.excess.len() > 1, "{d:?}");
    assert_eq!(d.excess[d.kept], Some(0.0), "{d:?}");
    assert_shells(&b, "random_4");
    let w = warnings(&b.report.quality, &Bounds::ISSUE);
    assert!(w.is_empty(), "{w:?}");
    let kept = corpus_build("t_pose", true);
    shoulders(&kept);
    assert!(kept.doc.parts().iter().any(|p| p.name == "head"));
    assert!(kept.report.derivation.is_none(), "nothing else tried");
}

/// A figure whose left shoulder rises in a peak beside the neck, a hair
/// wider than the neck for a few slices (seed 4242's issue-range
/// random_41, `tests/data/sketch/shoulder_peak_*.svg`, held out there).
/// The body chain of its shells followed the widest slice interval up the
/// peak and ended there, then was closed at the top of the head: a cone
/// four heights out of the drawing (the tried models' excess over the
/// issue's bounds 1468 and 1766; the stacked model was kept). It follows
/// the branch that goes on, the neck (`sketch::tube`): every model the
/// build tries stays within a height of its drawing, and the kept one,
/// shells, meets the issue's bounds.
#[test]
fn a_shoulder_peak_beside_the_neck_does_not_end_the_body() {
    use pdesculpt::sketch::quality::{warnings, Bounds};
    let (f, s) = data_pair("shoulder_peak");
    let b = build(&f, &s, None).expect("builds");
    let d = b
        .report
        .derivation
        .as_ref()
        .expect("the stacked model misses the bounds: others are tried");
    // a model with a point a height outside its drawing scores at least
    // (100 % / the 1 % bound) - 1 in that view alone
    let a_height_out = 1.0 / Bounds::ISSUE.outside - 1.0;
    for (k, e) in d.excess.iter().enumerate() {
        let e = e.unwrap_or_else(|| panic!("model {k} builds: {d:?}"));
        assert!(e < a_height_out, "model {k} leaves its drawing: {d:?}");
    }
    assert!(d.kept > 0, "a shells model kept: {d:?}");
    let w = warnings(&b.report.quality, &Bounds::ISSUE);
    assert!(w.is_empty(), "{w:?}");
}
