//! Template-based shape manipulation (000 sec 5.4, Fig 11b): elliptic part
//! sections replaced by a template part's real sections.

use pdesculpt::character::doc::{PartSpec, SectionShape, SectionSpec, SurfaceSpec};
use pdesculpt::curve::gec::{Frame, Gec};
use pdesculpt::template::check::TBSM_REL;
use pdesculpt::template::polygon::bbox;
use pdesculpt::template::tbsm::{
    makehuman_left_foot, replace_sections, round_trip_error, TemplatePart,
};

/// Two ellipses blended by angle stay within this relative distance of an
/// ellipse (the blend's radius is linear in t).
const ELLIPSE_BLEND: f64 = 0.02;

fn foot() -> TemplatePart {
    let (mesh, start, end) = makehuman_left_foot().unwrap();
    TemplatePart::from_mesh(&mesh, start, end, [1.0, 0.0, 0.0], (0.5, 0.95, 6)).unwrap()
}

fn ellipse_part(n: usize, a: f64, b: f64) -> PartSpec {
    PartSpec {
        name: "foot".into(),
        surface: SurfaceSpec::Pde6C2 {
            a: 0.0,
            open_ends: Default::default(),
        },
        sections: (0..n)
            .map(|k| SectionSpec {
                u: k as f64,
                centre: [0.5, 0.3, 0.2 * k as f64],
                e1: [1.0, 0.0, 0.0],
                e2: [0.0, 1.0, 0.0],
                shape: SectionShape::Ellipse {
                    a: a * (1.0 + 0.1 * k as f64),
                    b,
                    offset: 0.05,
                },
            })
            .collect(),
        closed_start: false,
        closed_end: false,
    }
}

fn plane_loop(s: &SectionSpec) -> Vec<[f64; 2]> {
    let SectionShape::Gec { centre, x, y } = &s.shape else {
        panic!("section not replaced: {:?}", s.shape)
    };
    let f = Frame::new(s.centre, s.e1, s.e2).unwrap();
    Gec::new(f, *centre, x.clone(), y.clone())
        .unwrap()
        .sample_plane(400)
}

/// An ellipse foot made from the MakeHuman foot's own section extents gets
/// the real foot sections back (GEC, 10 terms).
#[test]
fn tbsm_round_trip_restores_the_makehuman_foot() {
    let t = foot();
    assert_eq!(t.sections.len(), 6);
    let e = round_trip_error(&t, 10).unwrap();
    eprintln!("tbsm round trip: {e}");
    assert!(e < TBSM_REL, "{e}");
}

/// Replaced sections have exactly the ellipses' extents and centres (up to
/// the GEC fit) and keep u, centre and frame.
#[test]
fn tbsm_sections_take_the_ellipses_extents() {
    let t = foot();
    let part = ellipse_part(5, 0.4, 0.3);
    let out = replace_sections(&part, &t, 10).unwrap();
    assert_eq!(out.sections.len(), part.sections.len());
    for (s, o) in part.sections.iter().zip(&out.sections) {
        assert_eq!((s.u, s.centre, s.e1, s.e2), (o.u, o.centre, o.e1, o.e2));
        let SectionShape::Ellipse { a, b, offset } = s.shape else {
            unreachable!()
        };
        let (lo, hi) = bbox(&plane_loop(o));
        let tol = TBSM_REL * 2.0 * a.max(b);
        assert!(
            (0.5 * (hi[0] - lo[0]) - a).abs() < tol,
            "{lo:?} {hi:?} a {a}"
        );
        assert!(
            (0.5 * (hi[1] - lo[1]) - b).abs() < tol,
            "{lo:?} {hi:?} b {b}"
        );
        assert!((0.5 * (hi[0] + lo[0])).abs() < tol);
        assert!((0.5 * (hi[1] + lo[1]) - offset).abs() < tol);
    }
}

/// A template made of ellipses turns ellipses into the same ellipses.
#[test]
fn tbsm_with_an_elliptic_template_is_the_identity() {
    let ell = |a: f64, b: f64| -> Vec<[f64; 2]> {
        (0..64)
            .map(|i| {
                let th = std::f64::consts::TAU * i as f64 / 64.0;
                [a * th.cos(), b * th.sin()]
            })
            .collect()
    };
    let t = TemplatePart::new(vec![(0.0, ell(2.0, 1.0)), (1.0, ell(3.0, 1.0))]).unwrap();
    let part = ellipse_part(4, 0.4, 0.3);
    let out = replace_sections(&part, &t, 10).unwrap();
    for (s, o) in part.sections.iter().zip(&out.sections) {
        let SectionShape::Ellipse { a, b, offset } = s.shape else {
            unreachable!()
        };
        let worst = plane_loop(o)
            .iter()
            .map(|p| ((p[0] / a).powi(2) + ((p[1] - offset) / b).powi(2)).sqrt() - 1.0)
            .fold(0.0f64, |m, e| m.max(e.abs()));
        // an ellipse blended with an ellipse (by angle) is close to, not
        // exactly, an ellipse: the blend's radius is linear in t
        assert!(worst < ELLIPSE_BLEND, "{worst}");
    }
}

#[test]
fn tbsm_bad_input_is_a_clear_error() {
    let t = foot();
    let mut part = ellipse_part(3, 0.4, 0.3);
    part.sections[1].shape = SectionShape::Ellipse {
        a: f64::NAN,
        b: 0.3,
        offset: 0.0,
    };
    let e = replace_sections(&part, &t, 10).unwrap_err().to_string();
    assert!(e.contains("section 1") && e.contains("semi-axes"), "{e}");
    let one = ellipse_part(1, 0.4, 0.3);
    let e = replace_sections(&one, &t, 10).unwrap_err().to_string();
    assert!(e.contains("at least 2 sections"), "{e}");
    let e = TemplatePart::new(vec![(0.0, vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]])])
        .unwrap_err()
        .to_string();
    assert!(e.contains("at least 2"), "{e}");
}

mod cli_tests {
    use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
    use pdesculpt::character::doc::{CharacterDoc, Level, SectionShape};
    use pdesculpt::character::Resolution;
    use pdesculpt::pipeline::build_document;
    use pdesculpt::sketch::check::bundled;
    use std::path::Path;

    /// The bundled female at the intermediate level (elliptic sections),
    /// parts derived, written to `path`; returns the name of a part with
    /// elliptic sections.
    fn female_doc(path: &Path) -> String {
        let doc = bundled("female", Level::Intermediate).expect("bundled");
        let res = Resolution {
            rings_per_height: 40.0,
            transition_rows: 4,
        };
        let doc = build_document(&doc, Path::new("."), res, true)
            .expect("builds")
            .doc;
        doc.save(path).unwrap();
        doc.parts()
            .iter()
            .find(|p| {
                p.sections
                    .iter()
                    .any(|s| matches!(s.shape, SectionShape::Ellipse { .. }))
            })
            .expect("an elliptic part")
            .name
            .clone()
    }

    #[test]
    fn cli_tbsm_replace_turns_ellipses_into_foot_sections() {
        let d = tmpdir("tbsm-replace");
        let doc = d.join("female.json");
        let part = female_doc(&doc);
        let out = d.join("out.json");
        let o = pdesculpt(&[
            "--json",
            "template",
            "tbsm",
            "replace",
            doc.to_str().unwrap(),
            "--part",
            &part,
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let rep: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let replaced = rep["replaced"].as_u64().unwrap() as usize;
        assert!(replaced > 0, "{rep}");
        let (before, after) = (
            CharacterDoc::load(&doc).unwrap(),
            CharacterDoc::load(&out).unwrap(),
        );
        let (b, a) = (
            before.parts().iter().find(|p| p.name == part).unwrap(),
            after.parts().iter().find(|p| p.name == part).unwrap(),
        );
        assert_eq!(a.sections.len(), b.sections.len());
        let gecs = a
            .sections
            .iter()
            .filter(|s| matches!(s.shape, SectionShape::Gec { .. }))
            .count();
        assert!(gecs >= replaced, "{gecs} < {replaced}");
        for (x, y) in a.sections.iter().zip(&b.sections) {
            assert_eq!((x.u, x.centre, x.e1, x.e2), (y.u, y.centre, y.e1, y.e2));
        }
        // the other parts are untouched
        for (x, y) in after.parts().iter().zip(before.parts()) {
            if x.name != part {
                assert_eq!(x, y);
            }
        }
    }

    #[test]
    fn cli_tbsm_bad_input_fails_cleanly_without_output() {
        let d = tmpdir("tbsm-bad");
        let doc = d.join("female.json");
        female_doc(&doc);
        let out = d.join("never.json");
        let replace = |extra: &[&str]| {
            let mut a = vec![
                "template",
                "tbsm",
                "replace",
                doc.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ];
            a.extend_from_slice(extra);
            pdesculpt(&a)
        };
        assert_clear_error(&replace(&["--part", "tail"]), "no part 'tail'");
        assert_clear_error(&replace(&["--part", "torso", "--terms", "0"]), "--terms");
        assert_clear_error(
            &replace(&["--part", "torso", "--template-sections", "1"]),
            "--template-sections",
        );
        // --e1 is a mesh template's: makehuman-foot refuses it (it used to
        // be ignored silently)
        assert_clear_error(
            &replace(&["--part", "torso", "--e1", "0,0,1"]),
            "--e1 is for a mesh template",
        );
        let obj = d.join("cube.obj");
        std::fs::write(&obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        // a mesh template's --axis / --e1, each with what its error names
        let mesh = obj.to_str().unwrap();
        for (extra, needle) in [
            (&["--axis", "0,0,0,0,1,0", "--e1", "NaN,0,0"][..], "finite"),
            (
                &["--axis", "0,0,0,0,1,0", "--e1", "1,0"][..],
                "--e1 takes 3 numbers",
            ),
            // the comma form of --axis counted as one value (clap num_args
            // = 6 counted raw arguments): now split and counted by the
            // command
            (&["--axis", "0,0,0,0,1"][..], "--axis takes 6 numbers"),
            (&[][..], "--axis"),
        ] {
            let mut args = vec!["--part", "torso", "--template", mesh];
            args.extend_from_slice(extra);
            assert_clear_error(&replace(&args), needle);
        }
        let broken = d.join("broken.json");
        std::fs::write(&broken, "{\"version\": ").unwrap();
        let o = pdesculpt(&[
            "template",
            "tbsm",
            "replace",
            broken.to_str().unwrap(),
            "--part",
            "torso",
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_clear_error(&o, "broken.json");
        // create: a bow-tie profile, a top view
        let bow = d.join("bow.json");
        let v = serde_json::json!({"view": "front", "points": [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]});
        std::fs::write(&bow, v.to_string()).unwrap();
        let mesh_out = d.join("never.obj");
        let create = |view: &str| {
            pdesculpt(&[
                "template",
                "tbsm",
                "create",
                "--profile",
                bow.to_str().unwrap(),
                "--view",
                view,
                "-o",
                mesh_out.to_str().unwrap(),
            ])
        };
        assert_clear_error(&create("front"), "intersect");
        assert_clear_error(&create("top"), "--view");
        assert!(!out.exists() && !mesh_out.exists());
    }

    /// A side profile of the MakeHuman foot, made 5 % longer, creates a
    /// foot mesh (same vertices and faces) whose side outline is the
    /// profile's within the fit's tolerance. (20 % longer is refused: the
    /// fit stays 1.8 % of the foot's height off after its passes.)
    #[test]
    fn cli_tbsm_create_fits_a_side_profile() {
        create_fits(pdesculpt::template::View::Side, 1.05);
    }

    /// The same from the foot's own front profile. The foot template held
    /// both feet once (the right one's triangles were kept), so its front
    /// view was two outlines and every front profile was refused. (Not
    /// met: the front profile 2 % or 5 % wider stays 1.0-1.1 % of the
    /// foot's height off: the extremes scheme's landmarks sit on the flat
    /// sole and ankle cut.)
    #[test]
    fn cli_tbsm_create_fits_a_front_profile_of_the_left_foot_alone() {
        use pdesculpt::template::tbsm::makehuman_foot_part;
        let (_, foot) = makehuman_foot_part(6).unwrap();
        assert!(foot.positions.iter().all(|p| p[0] > 0.0));
        create_fits(pdesculpt::template::View::Front, 1.0);
    }

    /// `tbsm create --view VIEW` on the foot's own outline in that view,
    /// stretched by `stretch` horizontally: same vertices and faces, and
    /// the created foot's outline within the fit's tolerance of the
    /// profile.
    fn create_fits(view: pdesculpt::template::View, stretch: f64) {
        use pdesculpt::template::measure::mesh_outline;
        use pdesculpt::template::tbsm::makehuman_foot_part;
        let d = tmpdir(&format!("tbsm-create-{}", view.name()));
        let (_, foot) = makehuman_foot_part(6).unwrap();
        let profile: Vec<[f64; 2]> = mesh_outline(&foot, view)
            .unwrap()
            .into_iter()
            .map(|p| [stretch * p[0], p[1]])
            .collect();
        let prof = d.join("profile.json");
        let v = serde_json::json!({"view": view.name(), "points": profile});
        std::fs::write(&prof, v.to_string()).unwrap();
        let out = d.join("foot.obj");
        let o = pdesculpt(&[
            "--json",
            "template",
            "tbsm",
            "create",
            "--profile",
            prof.to_str().unwrap(),
            "--view",
            view.name(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let m = pdesculpt::mesh::io::read(&out).unwrap();
        assert_eq!(m.positions.len(), foot.positions.len());
        assert_eq!(m.triangles.len(), foot.triangles.len());
        let got = mesh_outline(&m, view).unwrap();
        let (lo, hi) = pdesculpt::template::polygon::bbox(&profile);
        let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let e = pdesculpt::template::polygon::hausdorff(&got, &profile, 1e-3 * size) / size;
        assert!(e < pdesculpt::template::check::PROFILE_REL, "{e}");
    }
}
