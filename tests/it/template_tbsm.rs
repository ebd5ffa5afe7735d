//! Template-based shape manipulation (000 sec 5.4, Fig 11b): elliptic part
//! sections replaced by a template part's real sections.

use pdesculpt::character::doc::{PartSpec, SectionShape, SectionSpec, SurfaceSpec};
use pdesculpt::curve::gec::{Frame, Gec};
use pdesculpt::template::check::TBSM_REL;
use pdesculpt::template::polygon::bbox;
use pdesculpt::template::tbsm::{
    makehuman_left_foot, replace_sections, round_trip_error, TemplatePart,
};

fn foot() -> TemplatePart {
    let (mesh, start, end) = makehuman_left_foot().unwrap();
    TemplatePart::from_mesh(&mesh, start, end, [1.0, 0.0, 0.0], (0.5, 0.95, 6)).unwrap()
}

fn ellipse_part(n: usize, a: f64, b: f64) -> PartSpec {
    PartSpec {
        name: "foot".into(),
        surface: SurfaceSpec::Pde6C2 { a: 0.0 },
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
        assert!(worst < 0.02, "{worst}");
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
