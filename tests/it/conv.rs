//! Integration tests of the conv family.

use pdesculpt::conv::model::{Component, Model, Polygonizer};
use pdesculpt::conv::{shapes, sketch};
use pdesculpt::mesh::topology::report;

#[test]
fn smoke_ellipse_star_folding_figure() {
    for (name, st) in [
        ("ellipse", shapes::ellipse(2.0, 1.0, 300)),
        ("star", shapes::star(5, 0.6, 1.6, 400)),
        ("folding", shapes::folding(1.5, 0.4, 4.0, 400)),
        ("figure", shapes::figure(500)),
    ] {
        let sk = sketch::build(&st, &Default::default()).expect(name);
        eprintln!(
            "{name}: poly {} tris {} nodes {} segs {} s {:.3} fit max {:.2e} rms {:.2e} it {} {:.3}s",
            sk.polygon.len(), sk.skeleton.triangles.len(), sk.skeleton.nodes.len(), sk.segments.len(),
            sk.s, sk.fit.max_rel_error, sk.fit.rms_rel_error, sk.fit.iterations, sk.fit.seconds
        );
        let m = Model {
            name: name.into(),
            components: vec![Component {
                name: name.into(),
                stroke: st,
                ..Default::default()
            }],
            ..Default::default()
        };
        let b = m.build().expect("build");
        let mesh = b
            .polygonize(40, 1.0, Polygonizer::MarchingTetrahedra)
            .expect("poly");
        let r = report(&mesh);
        eprintln!("  {r:?}");
    }
}

#[test]
fn debug_ellipse_skeleton() {
    let st = shapes::ellipse(2.0, 1.0, 300);
    let poly = pdesculpt::conv::stroke::filter_stroke(&st, &Default::default()).unwrap();
    let sk = pdesculpt::conv::skeleton::extract(&poly, &Default::default()).unwrap();
    let mut counts = std::collections::HashMap::new();
    for t in &sk.triangles {
        *counts
            .entry(format!("{:?}/{:?}", t.kind, t.circle))
            .or_insert(0) += 1;
    }
    eprintln!("n {} tris {} {:?}", poly.len(), sk.triangles.len(), counts);
    let mut seen = std::collections::HashSet::new();
    for t in &sk.triangles {
        let mut v = t.vertices;
        v.sort();
        if !seen.insert(v) {
            eprintln!("dup {:?}", v);
        }
    }
    for t in sk.triangles.iter().take(10) {
        eprintln!(
            "{:?} {:?} c {:?} r {:.3} nb {:?}",
            t.vertices, t.kind, t.centre, t.radius, t.neighbours
        );
    }
}

#[test]
fn debug_star() {
    let st = shapes::star(5, 0.6, 1.6, 400);
    let sk = sketch::build(&st, &Default::default()).unwrap();
    for (i, n) in sk.skeleton.nodes.iter().enumerate() {
        eprintln!("node {i} {:?} r {:.3}", n, sk.skeleton.radii[i]);
    }
    eprintln!("edges {:?}", sk.skeleton.edges);
    for s in &sk.segments {
        eprintln!(
            "seg {:?} {:?} w {:.3} {:.3} lam {:.3}",
            s.p, s.q, s.w0, s.w1, s.lambda
        );
    }
    for p in sk.polygon.iter().step_by(5) {
        eprintln!("pt {:?} F {:.3}", p, sk.field([p[0], p[1], 0.0]));
    }
}

#[test]
fn debug_solvers() {
    use pdesculpt::conv::fit::Solver;
    for (name, st) in [
        ("ellipse", shapes::ellipse(2.0, 1.0, 300)),
        ("star", shapes::star(5, 0.6, 1.6, 400)),
        ("folding", shapes::folding(1.5, 0.4, 4.0, 400)),
        ("figure", shapes::figure(500)),
    ] {
        for solver in [
            Solver::None,
            Solver::HildrethDEsopo,
            Solver::LawsonHanson,
            Solver::ProjectedLm,
        ] {
            let o = sketch::ConvOptions {
                solver,
                ..Default::default()
            };
            let sk = sketch::build(&st, &o).unwrap();
            eprintln!(
                "{name} {solver:?}: segs {} max {:.3e} rms {:.3e} it {} t {:.4}",
                sk.segments.len(),
                sk.fit.max_rel_error,
                sk.fit.rms_rel_error,
                sk.fit.iterations,
                sk.fit.seconds
            );
        }
    }
}

#[test]
fn debug_silhouette() {
    use pdesculpt::conv::silhouette::silhouette_error;
    for (name, st) in [
        ("ellipse", shapes::ellipse(2.0, 1.0, 300)),
        ("star", shapes::star(5, 0.6, 1.6, 400)),
        ("folding", shapes::folding(1.5, 0.4, 4.0, 400)),
        ("figure", shapes::figure(500)),
    ] {
        for solver in [
            pdesculpt::conv::fit::Solver::None,
            pdesculpt::conv::fit::Solver::LawsonHanson,
        ] {
            let m = Model {
                name: name.into(),
                options: sketch::ConvOptions {
                    solver,
                    ..Default::default()
                },
                components: vec![Component {
                    name: name.into(),
                    stroke: st.clone(),
                    ..Default::default()
                }],
                ..Default::default()
            };
            let b = m.build().expect("build");
            let mesh = b
                .polygonize(64, 1.0, Polygonizer::MarchingTetrahedra)
                .expect("poly");
            let e = silhouette_error(
                &mesh,
                [0.0; 3],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                &b.components[0].sketch.polygon,
            );
            eprintln!("{name} {solver:?}: {e:?}");
        }
    }
}
