//! The closed body of `pde6 body` (issue 15): watertight, manifold, oriented,
//! C1 at the joins, within the error targets; bad input refused by name.

use pdesculpt::body::closed::{
    load_body, reconstruct_closed, ClosedOptions, CHECKED_MORPHS, JOIN_C1_MAX, MAX_MAX_REL,
    RMS_MAX_REL,
};
use pdesculpt::body::BodyError;
use pdesculpt::mesh::Mesh;
use pdesculpt::profile::shapes::box_mesh;
use proptest::prelude::*;

fn assert_closed(name: &str, skin: &Mesh, o: &ClosedOptions, errors: bool) {
    let b = reconstruct_closed(skin, o).unwrap_or_else(|e| panic!("{name}: {e}"));
    let r = &b.report;
    let t = &r.topology;
    assert!(t.watertight && t.manifold && t.oriented, "{name}: {t:?}");
    assert_eq!(t.degenerate_triangles, 0, "{name}");
    assert!(r.max_join[1] <= JOIN_C1_MAX, "{name}: C1 {}", r.max_join[1]);
    if errors {
        let rms = r.recon_to_skin_rms_rel.max(r.skin_to_recon_rms_rel);
        let max = r.recon_to_skin_max_rel.max(r.skin_to_recon_max_rel);
        assert!(rms <= RMS_MAX_REL, "{name}: RMS {rms}");
        assert!(max <= MAX_MAX_REL, "{name}: max {max}");
    }
}

#[test]
fn base_and_morphs_reconstruct_closed_within_the_targets() {
    let o = ClosedOptions::default();
    assert_closed("base", &load_body(None, &[]).unwrap(), &o, true);
    for m in CHECKED_MORPHS {
        let skin = load_body(None, &[m.to_string()]).unwrap();
        assert_closed(m, &skin, &o, true);
    }
}

/// A coarse, fast resolution for the property test.
fn coarse() -> ClosedOptions {
    ClosedOptions {
        terms: 6,
        rings_per_height: 40.0,
        transition_rows: 4,
        ..ClosedOptions::default()
    }
}

proptest! {
    #![proptest_config(crate::strategies::config(3))]
    #[test]
    fn blends_of_morphs_are_watertight_or_a_clear_error(
        w_old in 0.0f64..1.0,
        w_child in 0.0f64..1.0,
        w_weight in 0.0f64..1.0,
    ) {
        let morphs = vec![
            format!("caucasian-male-old={w_old}"),
            format!("caucasian-male-child={w_child}"),
            format!("universal-male-young-averagemuscle-maxweight={w_weight}"),
        ];
        let skin = load_body(None, &morphs).unwrap();
        match reconstruct_closed(&skin, &coarse()) {
            Ok(b) => {
                let t = &b.report.topology;
                prop_assert!(t.watertight && t.manifold && t.oriented, "{:?}: {:?}", morphs, t);
            }
            Err(e) => prop_assert!(matches!(e, BodyError::LayoutNotFound { .. }) && !e.to_string().is_empty(), "{:?}: {}", morphs, e),
        }
    }
}

#[test]
fn bad_bodies_are_refused_naming_what_was_not_found() {
    let o = coarse();
    // a lying box: not standing
    let e = reconstruct_closed(&box_mesh([0.0; 3], [5.0, 1.0, 1.0]), &o).unwrap_err();
    assert!(e.to_string().contains("standing humanoid"), "{e}");
    // a standing box: no legs
    let e = reconstruct_closed(&box_mesh([-0.5, 0.0, -0.5], [0.5, 5.0, 0.5]), &o).unwrap_err();
    assert!(e.to_string().contains("crotch"), "{e}");
    // an open mesh
    let mut open = load_body(None, &[]).unwrap();
    open.triangles.truncate(open.triangles.len() - 10);
    let e = reconstruct_closed(&open, &o).unwrap_err();
    assert!(e.to_string().contains("open mesh"), "{e}");
    // arms against the body: squeeze every |x| beyond the torso onto its side
    let mut squeezed = load_body(None, &[]).unwrap();
    squeezed.map_positions(|p| [p[0].clamp(-1.45, 1.45), p[1], p[2]]);
    let e = reconstruct_closed(&squeezed, &o).unwrap_err();
    let msg = e.to_string();
    assert!(msg.contains("arm"), "{msg}");
}

#[test]
fn cli_body_from_a_mesh_file_and_bad_input() {
    let exe = env!("CARGO_BIN_EXE_pdesculpt");
    let dir = std::env::temp_dir().join(format!("pdesculpt-body-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // a box OBJ is not a humanoid: exit 1, the message names what was not found
    let boxed = dir.join("box.obj");
    pdesculpt::mesh::io::write(&box_mesh([-0.5, 0.0, -0.5], [0.5, 5.0, 0.5]), &boxed).unwrap();
    let out = std::process::Command::new(exe)
        .args(["pde6", "body", "--mesh"])
        .arg(&boxed)
        .arg("-o")
        .arg(dir.join("out.obj"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("two legs not found"), "{err}");
    assert!(!dir.join("out.obj").exists());
    // --morph needs NAME=WEIGHT
    let out = std::process::Command::new(exe)
        .args(["pde6", "body", "--morph", "old", "-o"])
        .arg(dir.join("out.obj"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("NAME=WEIGHT"));
    let _ = std::fs::remove_dir_all(&dir);
}
