//! The envelope passes' arm rows (issue 12, side profile within 0.5 %):
//! the paired-crossing remap of an arm's depth, the trunk's front where
//! the sketch shows an arm the fitted outline does not, the clamp of a
//! shallow row's correction, the webs and fingertips that move the arm
//! in height.

use pdesculpt::template::envelope::{
    hand_features, paired_features, remap, shallow_clamp, uncovered_split, Feature, FEATURE_PAIR,
    SHALLOW_FACTOR,
};

/// A row's fitted arm crossings land on the sketched ones (paired in
/// order), the depth change is linear between them and constant beyond.
#[test]
fn paired_remap_moves_fitted_crossings_onto_the_sketched() {
    let tol = pdesculpt::check::tol::SOLVE;
    let pairs = [(1.0, 1.1), (2.0, 1.8), (3.0, 3.3)];
    for &(c, d) in &pairs {
        assert!((c + remap(&pairs, c) - d).abs() < tol, "crossing {c}");
    }
    // halfway between the first two: the mean of their changes
    assert!((remap(&pairs, 1.5) - (-0.05)).abs() < tol);
    // beyond the ends: the end's change
    assert!((remap(&pairs, 0.0) - 0.1).abs() < tol);
    assert!((remap(&pairs, 9.0) - 0.3).abs() < tol);
    // one pair: a shift
    assert!((remap(&[(2.0, 2.5)], -4.0) - 0.5).abs() < tol);
}

/// The study's template and target meshes as OBJ files for trying
/// `template fit` on the binary: `STUDY_MESHES=DIR cargo test --release
/// --test it write_study_meshes -- --ignored` writes `DIR/<case>-template.obj`
/// and `DIR/<case>-target.obj` (skin only).
#[test]
#[ignore]
fn write_study_meshes() {
    use pdesculpt::template::study::{makehuman_template, target_mesh, CASES};
    let dir = std::env::var("STUDY_MESHES").unwrap_or_else(|_| {
        std::env::temp_dir()
            .join("study_meshes")
            .to_string_lossy()
            .into()
    });
    std::fs::create_dir_all(&dir).unwrap();
    for case in CASES {
        let name = case.name.replace("->", "_");
        let template = makehuman_template(case.template).unwrap();
        let target = target_mesh(case).unwrap();
        let path = |k: &str| std::path::PathBuf::from(&dir).join(format!("{name}-{k}.obj"));
        pdesculpt::mesh::io::write(&template.skin, &path("template")).unwrap();
        pdesculpt::mesh::io::write(&target, &path("target")).unwrap();
    }
}

/// No pairs: no change (the remap is only read where a row paired).
#[test]
fn remap_of_no_pairs_is_zero() {
    assert_eq!(remap(&[], 1.0), 0.0);
}

/// A row where the sketch shows the trunk and, apart in front of it, a
/// finger (four crossings) but the fitted outline no arm: the trunk's
/// front goes to the end of the sketch's back-most interval, not to the
/// finger; one interval, or a back-most interval ending behind the trunk's
/// back, gives no such row.
#[test]
fn trunk_front_goes_to_the_sketchs_backmost_interval_not_to_a_finger() {
    // back -1.0, trunk's front 1.0, a finger from 1.6 to 1.8
    assert_eq!(uncovered_split(&[-1.0, 1.0, 1.6, 1.8], -0.9), Some(1.0));
    // two fingers: still the trunk's interval end
    assert_eq!(
        uncovered_split(&[-1.0, 1.1, 1.6, 1.8, 2.0, 2.2], -0.9),
        Some(1.1)
    );
    // one interval: the sketch's front is the trunk's
    assert_eq!(uncovered_split(&[-1.0, 1.8], -0.9), None);
    // the back-most interval ends behind the trunk's back (a hand behind
    // the body): not the trunk's front
    assert_eq!(uncovered_split(&[-2.0, -1.5, -1.0, 1.0], -0.9), None);
}

/// A steep row's correction is kept (the outlines' distance there is about
/// the correction); on a shallow stretch (outlines close, their crossings
/// of the row far apart) it is limited to SHALLOW_FACTOR times the
/// distance, keeping its sign.
#[test]
fn shallow_row_correction_is_limited_by_the_outlines_distance() {
    let tol = pdesculpt::check::tol::SOLVE;
    // steep: distance 0.2 for a correction of 0.2 (or of a 45 degree
    // slope's 0.2 / sqrt 2)
    assert!((shallow_clamp(0.2, 0.2) - 0.2).abs() < tol);
    assert!((shallow_clamp(-0.2, 0.2 / 2f64.sqrt()) + 0.2).abs() < tol);
    // shallow: outlines 0.01 apart, crossings 0.3 apart
    assert!((shallow_clamp(0.3, 0.01) - SHALLOW_FACTOR * 0.01).abs() < tol);
    assert!((shallow_clamp(-0.3, 0.01) + SHALLOW_FACTOR * 0.01).abs() < tol);
    // on the sketch: no correction
    assert_eq!(shallow_clamp(0.3, 0.0), 0.0);
}

/// A palm (depth 0-3, height 1-2) with two fingers hanging from it, their
/// tips at (0.5, -0.2) and (2.5, -0.2), the web between them at
/// (1.5, `web`); counter-clockwise.
fn comb(web: f64) -> Vec<[f64; 2]> {
    vec![
        [0.0, 0.0],
        [0.5, -0.2],
        [1.0, 0.0],
        [1.0, 0.5],
        [1.5, web],
        [2.0, 0.5],
        [2.0, 0.0],
        [2.5, -0.2],
        [3.0, 0.0],
        [3.0, 2.0],
        [0.0, 2.0],
    ]
}

fn features_of(p: &[[f64; 2]]) -> Vec<([f64; 2], Feature)> {
    let mut f: Vec<([f64; 2], Feature)> = hand_features(p, 0.1)
        .into_iter()
        .map(|(i, k)| (p[i], k))
        .collect();
    f.sort_by(|a, b| a.0[0].total_cmp(&b.0[0]));
    f
}

/// The web (top of the gap between the fingers, outside below) and the two
/// fingertips (inside above) are found, in either orientation; the palm's
/// top corners (a maximum with the inside below) and the fingers' sides
/// are not features.
#[test]
fn webs_and_fingertips_are_found_on_a_comb() {
    let want = vec![
        ([0.5, -0.2], Feature::Tip),
        ([1.5, 1.0], Feature::Web),
        ([2.5, -0.2], Feature::Tip),
    ];
    let p = comb(1.0);
    assert_eq!(features_of(&p), want);
    let mut r = p.clone();
    r.reverse();
    assert_eq!(features_of(&r), want);
}

/// The fitted web pairs with a sketched web nearer than FEATURE_PAIR of
/// the height (the tips with the tips), not with one farther away.
#[test]
fn features_pair_only_within_reach() {
    let h = 10.0;
    let all = |_: [f64; 2]| true;
    let near = paired_features(&comb(1.0), &comb(1.0 + 0.8 * FEATURE_PAIR * h), &all, h);
    assert_eq!(near.len(), 3);
    assert!(near.iter().any(|(f, s)| f == &[1.5, 1.0]
        && (s[1] - 1.0 - 0.8 * FEATURE_PAIR * h).abs() < pdesculpt::check::tol::ROUNDING));
    let far = paired_features(&comb(1.0), &comb(1.0 + 1.5 * FEATURE_PAIR * h), &all, h);
    assert_eq!(far.len(), 2, "only the tips: {far:?}");
    assert!(far.iter().all(|(f, s)| f == s));
    // nothing in front of the trunk: nothing paired
    let none = paired_features(&comb(1.0), &comb(1.1), &|_: [f64; 2]| false, h);
    assert!(none.is_empty());
}
