//! The edit log (local modeling, paper 000 sec 5): the document API, replay
//! in `build_document`, and the CLI's edit/undo/redo/log with bad edits.

use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
use pdesculpt::character::doc::{CharacterDoc, Level};
use pdesculpt::character::log::{Edit, EditError, SectionTransform};
use pdesculpt::character::Resolution;
use pdesculpt::pipeline::build_document;
use pdesculpt::sketch::check::bundled;
use proptest::prelude::*;
use std::path::Path;

/// Low resolution for tests (each case builds a character).
pub fn low() -> Resolution {
    Resolution {
        rings_per_height: 40.0,
        transition_rows: 4,
    }
}

/// The bundled female (final level) with its parts derived and stored.
pub fn female() -> CharacterDoc {
    let doc = bundled("female", Level::Final).expect("bundled");
    build_document(&doc, Path::new("."), low(), true)
        .expect("builds")
        .doc
}

fn shape(part: &str, a: f64) -> Edit {
    Edit::ShapeParameter {
        part: part.into(),
        a,
    }
}

fn gec(part: &str, section: Option<usize>, transform: SectionTransform) -> Edit {
    Edit::GecTransform {
        part: part.into(),
        section,
        transform,
    }
}

#[test]
fn push_undo_redo_move_the_cursor_and_drop_the_redo_tail() {
    let mut d = female();
    assert!(matches!(d.undo(), Err(EditError::NothingToUndo)));
    d.push_edit(shape("torso", 0.3)).expect("valid");
    d.push_edit(gec(
        "arm_l",
        None,
        SectionTransform::Scale { sx: 1.2, sy: 1.1 },
    ))
    .expect("valid");
    assert_eq!(d.active_edits().len(), 2);
    assert!(matches!(d.redo(), Err(EditError::NothingToRedo { len: 2 })));
    d.undo().expect("undo");
    assert_eq!(d.active_edits().len(), 1);
    assert_eq!(d.edits().len(), 2);
    d.redo().expect("redo");
    d.undo().expect("undo");
    d.push_edit(shape("head", 1.0)).expect("valid");
    assert_eq!(d.edits().len(), 2, "the redo tail is dropped");
    assert_eq!(d.edits()[1], shape("head", 1.0));
    assert_eq!(d.cursor(), 2);
}

#[test]
fn bad_edits_are_refused_before_anything_changes() {
    let mut d = female();
    d.push_edit(shape("torso", 0.3)).expect("valid");
    let before = d.clone();
    let bad = [
        (shape("tail", 0.3), "unknown part 'tail'"),
        (shape("torso", 50.0), "a = 50"),
        (shape("torso", f64::NAN), "a = NaN"),
        (
            gec("torso", Some(99), SectionTransform::Rotate { angle: 0.1 }),
            "section 99 does not exist",
        ),
        (
            gec("torso", None, SectionTransform::Scale { sx: 0.0, sy: 1.0 }),
            "sx = 0",
        ),
        (
            gec(
                "torso",
                Some(3),
                SectionTransform::Bump {
                    h: -1.0,
                    theta: 0.0,
                    sigma: 0.2,
                },
            ),
            "self-intersect",
        ),
        (
            gec(
                "leg_l",
                None,
                SectionTransform::Bend {
                    kappa: 100.0,
                    axis: [0.0, 0.0, 1.0],
                },
            ),
            "kappa = 100",
        ),
    ];
    for (e, needle) in bad {
        let err = d.push_edit(e.clone()).expect_err(needle);
        assert!(err.to_string().contains(needle), "{needle}: {err}");
        assert_eq!(d, before, "{e:?} changed the document");
    }
}

#[test]
fn build_replays_the_active_edits_and_saving_keeps_the_parts_unedited() {
    let d0 = female();
    let base = build_document(&d0, Path::new("."), low(), false).expect("builds");
    let mut d = d0.clone();
    d.push_edit(gec(
        "torso",
        None,
        SectionTransform::Translate {
            d: [0.0, 0.0, 0.05],
        },
    ))
    .expect("valid");
    let b = build_document(&d, Path::new("."), low(), false).expect("builds");
    assert_eq!(b.doc.parts(), d0.parts(), "stored parts are not edited");
    assert_ne!(b.model.mesh.positions, base.model.mesh.positions);
    assert!(b.report.topology.watertight, "{:?}", b.report.topology);
    d.undo().expect("undo");
    let u = build_document(&d, Path::new("."), low(), false).expect("builds");
    assert_eq!(
        u.model.mesh, base.model.mesh,
        "undo gives the mesh bit for bit"
    );
}

fn write(path: &Path, text: &str) {
    std::fs::write(path, text).expect("writes");
}

#[test]
fn cli_edit_undo_redo_log_and_bad_edits_leave_the_file_unchanged() {
    let dir = tmpdir("edit-cli");
    let doc = dir.join("char.json");
    female().save(&doc).expect("saves");
    let docs = doc.to_str().unwrap();
    let op = dir.join("op.json");
    let ops = op.to_str().unwrap();
    write(
        &op,
        r#"{"op": "shape_parameter", "part": "torso", "a": 0.3}"#,
    );
    let o = pdesculpt(&["character", "edit", docs, "--op", ops]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    write(
        &op,
        r#"{"op": "gec_transform", "part": "arm_r", "transform": {"kind": "rotate", "angle": 0.2}}"#,
    );
    let o = pdesculpt(&["character", "edit", docs, "--op", ops]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = pdesculpt(&["character", "undo", docs]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = pdesculpt(&["--json", "character", "log", docs]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    assert_eq!(v["cursor"], 1);
    assert_eq!(v["edits"].as_array().map(|a| a.len()), Some(2));
    assert_eq!(v["edits"][1]["active"], false);
    let o = pdesculpt(&["character", "redo", docs]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let torso = female().parts()[0].clone();
    let (u0, u1) = (
        torso.sections[0].u,
        torso.sections[torso.sections.len() - 1].u,
    );
    write(
        &op,
        &format!(
            r#"{{"op": "force_region", "part": "torso", "u": [{}, {}], "theta": [0.2, 1.4], "force": {{"type": "area", "u0": 0.2, "u1": 0.8, "v0": 0.25, "v1": 0.75, "p": [0.0, 0.0, 5.0]}}}}"#,
            u0 + 0.25 * (u1 - u0),
            u0 + 0.75 * (u1 - u0)
        ),
    );
    let o = pdesculpt(&["character", "edit", docs, "--op", ops]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = pdesculpt(&["character", "log", docs]);
    let log = String::from_utf8_lossy(&o.stdout);
    assert!(log.contains("3 edits, 3 active"), "{log}");
    assert!(log.contains("4-sided force"), "{log}");

    let before = std::fs::read(&doc).expect("reads");
    let bad = [
        (
            r#"{"op": "shape_parameter", "part": "tail", "a": 0.3}"#,
            "unknown part 'tail'",
        ),
        (
            r#"{"op": "shape_parameter", "part": "torso", "a": 1e3}"#,
            "a = 1000",
        ),
        (
            r#"{"op": "shape_parameter", "part": "torso", "a": NaN}"#,
            "not an edit",
        ),
        (
            r#"{"op": "gec_transform", "part": "torso", "section": 3, "transform": {"kind": "bump", "h": -1.0, "theta": 0.0, "sigma": 0.2}}"#,
            "self-intersect",
        ),
        (
            r#"{"op": "gec_transform", "part": "torso", "transform": {"kind": "scale", "sx": -1.0, "sy": 1.0}}"#,
            "sx = -1",
        ),
        (r#"{"op": "teleport", "part": "torso"}"#, "not an edit"),
        (
            r#"{"op": "force_region", "part": "torso", "u": [0.0, 9.0], "theta": [0.0, 1.0], "force": {"type": "uniform", "p": [0.0, 0.0, 1.0]}}"#,
            "outside the part",
        ),
        (
            r#"{"op": "force_region", "part": "torso", "u": [1.0, 1.2], "theta": [1.0, 1.0], "force": {"type": "uniform", "p": [0.0, 0.0, 1.0]}}"#,
            "theta[1] = 1",
        ),
        // valid parameters, but the plate region (the whole torso) overlaps
        // itself in projection: only the built mesh can tell
        (
            r#"{"op": "plate", "part": "torso", "centre": [0.0, 1.1, 0.1], "radius": 1e3, "d": [0.0, 0.0, 0.01]}"#,
            "overlapping projection",
        ),
        (
            r#"{"op": "plate", "part": "torso", "centre": [0.0, 1.1, 0.1], "radius": 0.05, "d": [0.0, 0.0, 1e308]}"#,
            "d[2] = 1e308 is out of range",
        ),
        (
            r#"{"op": "shape_parameter", "part": "torso", "a": 0.3, "b": 1}"#,
            "unknown field",
        ),
    ];
    for (text, needle) in bad {
        write(&op, text);
        let o = pdesculpt(&["character", "edit", docs, "--op", ops]);
        assert_clear_error(&o, needle);
        assert_eq!(std::fs::read(&doc).expect("reads"), before, "{text}");
    }
    let o = pdesculpt(&["character", "redo", docs]);
    assert_clear_error(&o, "nothing to redo");
    assert_eq!(std::fs::read(&doc).expect("reads"), before);
    // a document whose cursor is past its log is refused on load
    let text = String::from_utf8(before.clone()).unwrap();
    let broken = text.replace("\"cursor\": 3", "\"cursor\": 7");
    assert_ne!(broken, text);
    let bdoc = dir.join("broken.json");
    write(&bdoc, &broken);
    let o = pdesculpt(&["character", "undo", bdoc.to_str().unwrap()]);
    assert_clear_error(&o, "cursor 7");
    assert_eq!(std::fs::read_to_string(&bdoc).unwrap(), broken);
}

#[test]
fn edit_checks_pass() {
    let checks = crate::shared::family_checks("edit");
    assert!(checks.len() >= 10);
    for c in checks {
        assert!(
            c.passed,
            "{} measured {} > {}",
            c.name, c.measured, c.tolerance
        );
    }
}

#[test]
fn force_boundary_and_plate_edits_refuse_bad_parameters() {
    let mut d = female();
    let torso = d.parts()[0].clone();
    let before = d.clone();
    let good = pdesculpt::edit::check::sample_force(&torso, [0.0, 0.0, 1.0]);
    let Edit::Force { force, .. } = good.clone() else {
        unreachable!()
    };
    let bad = [
        (
            Edit::Force {
                part: "torso".into(),
                u: [-1.0, 0.2],
                force,
                a: 1.0,
            },
            "outside the part",
        ),
        (
            Edit::Force {
                part: "torso".into(),
                u: [0.1, 0.2],
                force,
                a: 0.0,
            },
            "a = 0",
        ),
        (
            Edit::Boundary {
                part: "head".into(),
                end: pdesculpt::character::doc::End::End,
                curve: Some(pdesculpt::character::doc::SectionShape::Circle { r: 0.05 }),
                tangent: None,
                reach: 0.3,
            },
            "closed end",
        ),
        (
            Edit::Boundary {
                part: "torso".into(),
                end: pdesculpt::character::doc::End::End,
                curve: None,
                tangent: None,
                reach: 0.3,
            },
            "give a new",
        ),
        (
            Edit::Plate {
                part: "torso".into(),
                centre: [5.0, 5.0, 5.0],
                radius: 0.1,
                d: [0.0, 0.0, 0.01],
            },
            "farther than the radius",
        ),
        (
            Edit::Plate {
                part: "torso".into(),
                centre: [0.0, 1.0, 0.0],
                radius: -0.1,
                d: [0.0, 0.0, 0.01],
            },
            "radius = -0.1",
        ),
    ];
    for (e, needle) in bad {
        let err = d.push_edit(e.clone()).expect_err(needle);
        assert!(err.to_string().contains(needle), "{needle}: {err}");
        assert_eq!(d, before, "{e:?} changed the document");
    }
    d.push_edit(good).expect("the sample force is valid");
}

#[test]
fn force_region_edits_are_validated_and_applied_inside_their_curve() {
    use pdesculpt::edit::check::sample_force_region;
    let mut d = female();
    let torso = d.parts()[0].clone();
    let before = d.clone();
    let good = sample_force_region(&torso, 0.2, [0.0, 0.0, 5.0]);
    let Edit::ForceRegion { force, u, .. } = good.clone() else {
        unreachable!()
    };
    let region = |u: [f64; 2], theta: [f64; 2], part: &str| Edit::ForceRegion {
        part: part.into(),
        u,
        theta,
        force,
        a: 1.0,
    };
    let bad = [
        (
            region([-1.0, u[1]], [0.0, 1.0], "torso"),
            "outside the part",
        ),
        (region(u, [0.5, 0.5], "torso"), "theta[1] = 0.5"),
        (region(u, [0.0, 7.0], "torso"), "theta[1] = 7"),
        (region(u, [f64::NAN, 1.0], "torso"), "theta[0] = NaN"),
        (region([u[1], u[0]], [0.0, 1.0], "torso"), "u[1] > u[0]"),
        (region(u, [0.0, 1.0], "tail"), "unknown part 'tail'"),
    ];
    for (e, needle) in bad {
        let err = d.push_edit(e.clone()).expect_err(needle);
        assert!(err.to_string().contains(needle), "{needle}: {err}");
        assert_eq!(d, before, "{e:?} changed the document");
    }
    let base = build_document(&d, Path::new("."), low(), false).expect("builds");
    d.push_edit(good)
        .expect("the sample 4-sided force is valid");
    let b = build_document(&d, Path::new("."), low(), false).expect("builds");
    assert!(b.report.topology.watertight, "{:?}", b.report.topology);
    let moved: Vec<usize> = (0..base.model.mesh.positions.len())
        .filter(|&i| base.model.mesh.positions[i] != b.model.mesh.positions[i])
        .collect();
    assert!(!moved.is_empty(), "the force moves the torso");
    let all = base.model.mesh.positions.len();
    assert!(moved.len() * 4 < all, "{} of {all} moved", moved.len());
}

fn edit_strategy(doc: &CharacterDoc) -> impl Strategy<Value = Option<Edit>> {
    let torso = doc.parts()[0].clone();
    let names: Vec<String> = doc.parts().iter().map(|p| p.name.clone()).collect();
    let c = torso.sections[torso.sections.len() / 2].centre;
    (
        0usize..8,
        proptest::sample::select(names),
        -1.0f64..1.0,
        -1.0f64..1.0,
    )
        .prop_map(move |(kind, part, x, y)| {
            Some(match kind {
                0 => shape(&part, 2.0 * x),
                1 => gec(
                    &part,
                    None,
                    SectionTransform::Scale {
                        sx: 1.0 + 0.3 * x,
                        sy: 1.0 + 0.3 * y,
                    },
                ),
                2 => gec(&part, Some(2), SectionTransform::Rotate { angle: 3.0 * x }),
                3 => pdesculpt::edit::check::sample_force(&torso, [0.0, 3.0 * y, 10.0 * x]),
                4 => Edit::Boundary {
                    part,
                    end: pdesculpt::character::doc::End::End,
                    curve: None,
                    tangent: Some([0.1 * x, 0.0, 0.1 * y]),
                    reach: 0.4,
                },
                5 => pdesculpt::edit::check::sample_force_region(
                    &torso,
                    3.0 * y,
                    [10.0 * y, 0.0, 10.0 * x],
                ),
                6 => pdesculpt::edit::check_stroke::sample_force_stroke(
                    &torso,
                    3.0 * x,
                    [0.0, 10.0 * y, 10.0 * x],
                ),
                _ => Edit::Plate {
                    part: "torso".into(),
                    centre: [c[0] + 0.05 * x, c[1] + 0.05 * y, c[2] + 0.1],
                    radius: 0.12,
                    d: [0.0, 0.01 * y, 0.02 * x],
                },
            })
        })
}

proptest! {
    #![proptest_config(crate::strategies::config(6))]
    #[test]
    fn random_edits_with_undo_redo_replay_like_incremental(
        steps in proptest::collection::vec((0usize..4, edit_strategy(&female())), 1..5)
    ) {
        use pdesculpt::pipeline::Session;
        let mut s = Session::new(female(), ".".into(), low());
        for (what, e) in steps {
            let before = s.doc.clone();
            let r = match (what, e) {
                (0, _) => s.doc.undo(),
                (1, _) => s.doc.redo(),
                (_, Some(e)) => s.push(e),
                (_, None) => Ok(()),
            };
            if r.is_err() {
                prop_assert_eq!(&s.doc, &before);
            }
            let inc = s.build().expect("an accepted log builds");
            prop_assert!(inc.model.mesh.positions.iter().flatten().all(|x| x.is_finite()));
            let t = &inc.report.topology;
            prop_assert!(t.watertight && t.manifold && t.oriented, "{:?}", t);
            let scratch = build_document(&s.doc, Path::new("."), low(), false).expect("replays");
            prop_assert!(scratch.model.mesh == inc.model.mesh, "replay differs from incremental");
        }
    }
}

#[test]
fn the_log_order_is_the_application_order_or_the_edit_is_refused() {
    use pdesculpt::pipeline::Session;
    use pdesculpt::sasm::demo::breast;
    let d0 = female();
    let b = build_document(&d0, Path::new("."), low(), false).expect("builds");
    let torso = b.model.parts.iter().find(|p| p.name == "torso").unwrap();
    let sasm = Edit::Sasm(
        breast(torso, b.report.drawing.placement.front_shift[1]).expect("the bundled breast"),
    );
    let Edit::Sasm(spec) = &sasm else {
        unreachable!()
    };
    // a plate over the upper edge of the breast's region, pushing forward
    let c = spec.curve.points[0];
    let pr = pdesculpt::sasm::project::Projector::new(torso, spec.curve.view);
    let hit = pr.cast([c[0] - 0.044, c[1] + 0.05]).expect("on the torso");
    let plate = Edit::Plate {
        part: "torso".into(),
        centre: hit.point,
        radius: 0.05,
        d: [0.0, 0.0, 0.01],
    };
    // mesh-level edits in either order: both build, differ, and the
    // interactive path equals the replay bit for bit
    let mut meshes = Vec::new();
    for order in [[&plate, &sasm], [&sasm, &plate]] {
        let mut s = Session::new(d0.clone(), ".".into(), Resolution::default());
        for e in order {
            s.push((*e).clone()).expect("valid in this order");
        }
        let full = s.build().expect("builds");
        let fast = s.model().expect("builds");
        assert!(fast.mesh == full.model.mesh, "interactive path differs");
        assert!(full.report.topology.watertight);
        meshes.push(full.model.mesh);
    }
    assert!(
        meshes[0] != meshes[1],
        "the order of plate and sasm matters"
    );
    // a PDE-level edit of the torso after a mesh-level edit of it: refused
    let mut d = d0.clone();
    d.push_edit(plate.clone()).expect("valid");
    let before = d.clone();
    let err = d.push_edit(shape("torso", 0.3)).expect_err("order");
    assert!(
        matches!(
            err,
            EditError::Order {
                index: 1,
                earlier: 0,
                ..
            }
        ),
        "{err}"
    );
    assert!(
        err.to_string().contains("undo the mesh-level edit"),
        "{err}"
    );
    assert_eq!(d, before);
    // ... but not of a child part, whose edit leaves the torso's mesh alone
    d.push_edit(shape("head", 0.3))
        .expect("the head's mesh is its own");
    // a hand-written log in an order that cannot be honoured is refused
    // at build
    let bad = crate::harden_doc::with_hand_written_log(&d0, vec![plate, shape("torso", 0.3)], 2);
    let err = build_document(&bad, Path::new("."), low(), false).expect_err("order");
    assert!(err.to_string().contains("cannot follow"), "{err}");
}
