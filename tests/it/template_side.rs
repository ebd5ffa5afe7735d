//! The envelope passes' arm rows (issue 12, side profile within 0.5 %):
//! the paired-crossing remap of an arm's depth.

use pdesculpt::template::envelope::remap;

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
