//! Template-based global modeling (000 sec 4.2): RBF, landmarks, fits.

use pdesculpt::check::tol;
use pdesculpt::mesh::Mesh;
use pdesculpt::template::check::PROFILE_REL;
use pdesculpt::template::landmarks::{self, Scheme, Similarity};
use pdesculpt::template::polygon::{hausdorff, validated};
use pdesculpt::template::shapes::{figure, prism, refined, Figure};
use pdesculpt::template::{fit, FitOptions, Rbf, RbfError, Sketch, Template, TemplateError, View};
use proptest::prelude::*;

/// A landmark of the synthetic figure found within this distance of where
/// it was drawn (model units; the figure is 15 tall).
const LANDMARK: f64 = 0.1;

/// The prism template's outline: its first ring, projected.
fn prism_outline(m: &Mesh, view: View) -> Result<Vec<[f64; 2]>, TemplateError> {
    let n = m.positions.len() / 2;
    Ok(m.positions[..n].iter().map(|p| view.project(*p)).collect())
}

fn template() -> Template {
    Template::whole(prism(&refined(&figure(Figure::default()), 0.1), 1.0))
}

fn sketch_of(f: Figure) -> Vec<[f64; 2]> {
    refined(&figure(f), 0.05)
}

#[test]
fn rbf_reproduces_affine_maps_and_interpolates() {
    let c: Vec<[f64; 2]> = (0..40)
        .map(|i| {
            let t = i as f64 * 0.7;
            [t.cos() * (1.0 + 0.1 * t), t.sin() * 2.0 + 0.05 * t]
        })
        .collect();
    let affine: Vec<[f64; 2]> = c
        .iter()
        .map(|p| [2.0 * p[0] - p[1] + 3.0, 0.5 * p[1] + 1.0])
        .collect();
    let r = Rbf::<2, 2>::fit(&c, &affine, true).unwrap();
    let q = [0.3, -0.7];
    let v = r.eval(&q);
    let exact = [2.0 * q[0] - q[1] + 3.0, 0.5 * q[1] + 1.0];
    assert!(
        (v[0] - exact[0]).abs() < tol::SOLVE * 1e3 && (v[1] - exact[1]).abs() < tol::SOLVE * 1e3,
        "{v:?} {exact:?}"
    );
    let wiggle: Vec<[f64; 1]> = c.iter().map(|p| [(3.0 * p[0]).sin() * p[1]]).collect();
    let r = Rbf::<2, 1>::fit(&c, &wiggle, true).unwrap();
    for (p, w) in c.iter().zip(&wiggle) {
        assert!((r.eval(p)[0] - w[0]).abs() < tol::SOLVE * 1e3);
    }
    // the identity's condition number is the least there is
    let identity = 1.0;
    assert!(r.condition.unwrap() > identity);
}

#[test]
fn rbf_rejects_coincident_and_collinear_centres() {
    let mut c: Vec<[f64; 2]> = (0..10).map(|i| [i as f64, (i * i) as f64]).collect();
    c.push(c[3]);
    let v = vec![[0.0]; c.len()];
    assert!(matches!(
        Rbf::<2, 1>::fit(&c, &v, false),
        Err(RbfError::CoincidentCentres { i: 3, j: 10, .. })
    ));
    let line: Vec<[f64; 2]> = (0..10).map(|i| [i as f64, 2.0 * i as f64]).collect();
    assert!(matches!(
        Rbf::<2, 1>::fit(&line, &v[..10], false),
        Err(RbfError::Degenerate { .. })
    ));
}

#[test]
fn figure_landmarks_are_found_in_order() {
    let p = validated("figure", &sketch_of(Figure::default())).unwrap();
    let m = landmarks::find(&p, Scheme::Human, "figure").unwrap();
    assert_eq!(m.len(), 8);
    let crotch = p[m[4]];
    assert!(
        crotch[0].abs() < LANDMARK && (crotch[1] - 7.0).abs() < LANDMARK,
        "{crotch:?}"
    );
    // an ellipse has no armpits
    let e: Vec<[f64; 2]> = (0..100)
        .map(|i| {
            let t = i as f64 * std::f64::consts::TAU / 100.0;
            [3.0 * t.cos(), 8.0 * t.sin()]
        })
        .collect();
    let err = landmarks::find(&e, Scheme::Human, "ellipse").unwrap_err();
    assert!(
        err.to_string().contains("armpit") || err.to_string().contains("foot"),
        "{err}"
    );
}

#[test]
fn low_level_fits_the_front_profile() {
    let t = template();
    let target = Figure {
        waist: 2.8,
        shoulders: 2.5,
        height: 15.0,
        reach: 5.5,
    };
    let sketch = Sketch {
        front: sketch_of(target),
        ..Default::default()
    };
    let r = fit(&t, &sketch, &FitOptions::default(), &prism_outline).unwrap();
    let out = prism_outline(&Mesh::new(r.last().to_vec(), vec![]), View::Front).unwrap();
    let d = hausdorff(&out, &sketch.front, 0.01);
    assert!(d < PROFILE_REL * 15.0, "front profile off by {d}");
    assert_eq!(r.last().len(), t.mesh.positions.len());
}

#[test]
fn similarity_of_the_sketch_gives_the_similar_result() {
    let t = template();
    let target = Figure {
        waist: 2.6,
        ..Default::default()
    };
    let base = Sketch {
        front: sketch_of(target),
        ..Default::default()
    };
    let r0 = fit(&t, &base, &FitOptions::default(), &prism_outline).unwrap();
    let s = Similarity {
        scale: 1.7,
        angle: 0.3,
        translation: [4.0, -2.0],
    };
    let moved = Sketch {
        front: base.front.iter().map(|&p| s.apply(p)).collect(),
        ..Default::default()
    };
    let r1 = fit(&t, &moved, &FitOptions::default(), &prism_outline).unwrap();
    let zc = r0.depth_centre;
    let mut worst = 0.0f64;
    for (a, b) in r0.last().iter().zip(r1.last()) {
        let q = s.apply([a[0], a[1]]);
        let z = s.scale * (a[2] - zc) + zc;
        worst = worst
            .max((q[0] - b[0]).abs())
            .max((q[1] - b[1]).abs())
            .max((z - b[2]).abs());
    }
    assert!(
        worst < tol::scaled(tol::SOLVE * 1e3, 16.0 * s.scale),
        "{worst}"
    );
}

/// Options for the property tests: the default levels without the
/// condition number (an eigen-decomposition per case).
fn fast_options() -> FitOptions {
    FitOptions::default().with_condition(false)
}

/// Height of the reference figure (the scale of every tolerance below).
const FIGURE_HEIGHT: f64 = 16.0;

/// A smooth displacement field of the plane: `(ax, ay)` amplitudes (in units
/// of the figure's height), wave numbers `k` (per figure height, 1-3) and
/// phases.
fn smooth_field(p: [f64; 2], amp: [f64; 2], k: [f64; 2], phase: [f64; 2]) -> [f64; 2] {
    let (u, v) = (p[0] / FIGURE_HEIGHT, p[1] / FIGURE_HEIGHT);
    let tau = std::f64::consts::TAU;
    [
        amp[0] * FIGURE_HEIGHT * (tau * k[0] * v + phase[0]).sin(),
        amp[1] * FIGURE_HEIGHT * (tau * k[1] * u + phase[1]).cos() * (tau * v).sin(),
    ]
}

proptest! {
    #![proptest_config(crate::strategies::config(6))]

    /// Covariance of the low level (000 sec 4.2.1): fitting to a similar
    /// copy of the sketch (scale 0.5-2, rotation within +-10 degrees, any
    /// translation) gives the first fit mapped by that similarity (depth
    /// scaled about the depth centre), to the RBF solve's accuracy
    /// (tol::SOLVE * 1e3, relative to the moved figure's height).
    #[test]
    fn fit_is_covariant_under_similarities_of_the_sketch(
        scale in 0.5f64..2.0,
        degrees in -10.0f64..10.0,
        tx in -20.0f64..20.0,
        ty in -20.0f64..20.0,
        waist in 1.8f64..2.8,
    ) {
        let t = template();
        let opts = fast_options();
        let base = Sketch {
            front: sketch_of(Figure { waist, ..Default::default() }),
            ..Default::default()
        };
        let r0 = fit(&t, &base, &opts, &prism_outline).unwrap();
        let s = Similarity { scale, angle: degrees.to_radians(), translation: [tx, ty] };
        let moved = Sketch {
            front: base.front.iter().map(|&p| s.apply(p)).collect(),
            ..Default::default()
        };
        let r1 = fit(&t, &moved, &opts, &prism_outline).unwrap();
        let zc = r0.depth_centre;
        let mut worst = 0.0f64;
        for (a, b) in r0.last().iter().zip(r1.last()) {
            let q = s.apply([a[0], a[1]]);
            let z = s.scale * (a[2] - zc) + zc;
            worst = worst
                .max((q[0] - b[0]).abs())
                .max((q[1] - b[1]).abs())
                .max((z - b[2]).abs());
        }
        prop_assert!(
            worst < tol::scaled(tol::SOLVE * 1e3, FIGURE_HEIGHT * scale),
            "worst vertex deviation {worst}"
        );
    }

    /// Robustness of the low level: a smooth random displacement of the
    /// sketched profile (up to 8 % of the height per component, 1-3 waves
    /// per height) is either fitted (the fitted outline, exact for the
    /// prism, within check::PROFILE_REL of the height of the sketch, every
    /// coordinate finite) or rejected with an error naming the problem;
    /// never a panic or a NaN. `fit` measures its own result and corrects
    /// or fails, so "Ok but off" must not happen (see
    /// `eight_percent_perturbation_is_fitted_within_tolerance`).
    #[test]
    fn perturbed_profiles_are_fitted_or_rejected_cleanly(
        ax in 0.0f64..0.08,
        ay in 0.0f64..0.08,
        kx in 1.0f64..3.0,
        ky in 1.0f64..3.0,
        px in 0.0f64..std::f64::consts::TAU,
        py in 0.0f64..std::f64::consts::TAU,
    ) {
        let t = template();
        let front: Vec<[f64; 2]> = sketch_of(Figure::default())
            .into_iter()
            .map(|p| {
                let d = smooth_field(p, [ax, ay], [kx, ky], [px, py]);
                [p[0] + d[0], p[1] + d[1]]
            })
            .collect();
        let sketch = Sketch { front, ..Default::default() };
        match fit(&t, &sketch, &fast_options(), &prism_outline) {
            Ok(r) => {
                prop_assert!(r.last().iter().flatten().all(|x| x.is_finite()));
                let out = prism_outline(&Mesh::new(r.last().to_vec(), vec![]), View::Front).unwrap();
                let (lo, hi) = pdesculpt::template::polygon::bbox(&sketch.front);
                let h = hi[1] - lo[1];
                let d = hausdorff(&out, &sketch.front, 0.01);
                prop_assert!(
                    d < pdesculpt::template::check::PROFILE_REL * h,
                    "fitted outline off by {d} (height {h})"
                );
            }
            Err(e) => {
                let msg = e.to_string();
                eprintln!("perturbed profile rejected: {msg}");
                prop_assert!(!msg.is_empty() && !msg.contains("NaN"), "unclear error: {msg}");
            }
        }
    }
}

mod cli_tests {
    use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
    use pdesculpt::template::measure::mesh_outline;
    use pdesculpt::template::study::{makehuman_template, CASES};
    use pdesculpt::template::View;
    use std::path::Path;

    fn write_profile(path: &Path, view: &str, pts: &[[f64; 2]]) {
        let v = serde_json::json!({ "view": view, "points": pts });
        std::fs::write(path, v.to_string()).unwrap();
    }

    #[test]
    fn cli_fits_makehuman_to_a_front_profile() {
        let d = tmpdir("template-fit");
        let case = CASES.iter().find(|c| c.name == "male->boy").unwrap();
        let target = pdesculpt::template::study::target_mesh(case).unwrap();
        let front = d.join("front.json");
        write_profile(
            &front,
            "front",
            &mesh_outline(&target, View::Front).unwrap(),
        );
        let out = d.join("boy.obj");
        let o = pdesculpt(&[
            "--json",
            "template",
            "fit",
            "--template",
            "makehuman",
            "--front",
            front.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let rep: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let err = rep["profile_errors"][0]["max_rel"].as_f64().unwrap();
        assert!(err < pdesculpt::template::check::PROFILE_REL, "{err}");
        let written = pdesculpt::mesh::io::read(&out).unwrap();
        let base = makehuman_template(&[]).unwrap();
        assert_eq!(written.positions.len(), base.mesh.positions.len());
        assert_eq!(written.triangles.len(), base.mesh.triangles.len());
    }

    #[test]
    fn cli_bad_profiles_fail_cleanly_without_output() {
        let d = tmpdir("template-bad");
        let out = d.join("never.obj");
        let run = |front: &Path, tpl: &str| {
            pdesculpt(&[
                "template",
                "fit",
                "--template",
                tpl,
                "--front",
                front.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ])
        };
        // self-intersecting (a bow tie)
        let bow = d.join("bow.json");
        write_profile(
            &bow,
            "front",
            &[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]],
        );
        assert_clear_error(&run(&bow, "makehuman"), "intersect");
        // open SVG path
        let open = d.join("open.svg");
        std::fs::write(
            &open,
            r#"<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 L 1 0 L 1 -2"/></svg>"#,
        )
        .unwrap();
        assert_clear_error(&run(&open, "makehuman"), "open");
        // an ellipse: no armpits, no crotch
        let ell = d.join("ellipse.json");
        let e: Vec<[f64; 2]> = (0..120)
            .map(|i| {
                let t = i as f64 * std::f64::consts::TAU / 120.0;
                [3.0 * t.cos(), 8.0 + 8.0 * t.sin()]
            })
            .collect();
        write_profile(&ell, "front", &e);
        assert_clear_error(&run(&ell, "makehuman"), "landmark");
        // a template seen edge-on in the front view has no closed outline
        let flat = d.join("flat.obj");
        std::fs::write(&flat, "v 0 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n").unwrap();
        assert_clear_error(&run(&ell, flat.to_str().unwrap()), "outline");
        assert!(!out.exists());
    }
}

/// The figure's front profile moved by the smooth field that an earlier
/// `fit` (no self-check) accepted 0.517 % of the height off the sketch.
fn eight_percent_sketch() -> Sketch {
    let front: Vec<[f64; 2]> = sketch_of(Figure::default())
        .into_iter()
        .map(|p| {
            let d = smooth_field(p, [0.028, 0.048], [2.95, 2.86], [1.5, 0.0]);
            [p[0] + d[0], p[1] + d[1]]
        })
        .collect();
    Sketch {
        front,
        ..Default::default()
    }
}

/// Regression (issue 12): the 8 % perturbation (ax = 0.028, ay = 0.048,
/// kx = 2.95, ky = 2.86, px = 1.5, py = 0) was fitted "Ok" but 0.517 % of
/// the height off. Now the first warp's miss is caught and corrected: the
/// fit reports at least one correction pass, its own measure is within
/// tolerance and agrees with an independent Hausdorff distance on the
/// exact (prism) outline.
#[test]
fn eight_percent_perturbation_is_fitted_within_tolerance() {
    let t = template();
    let sketch = eight_percent_sketch();
    let r = fit(&t, &sketch, &fast_options(), &prism_outline).unwrap();
    let rep = &r.levels[0].0;
    assert!(rep.passes >= 1, "the first warp alone was expected to miss");
    let out = prism_outline(&Mesh::new(r.last().to_vec(), vec![]), View::Front).unwrap();
    let (lo, hi) = pdesculpt::template::polygon::bbox(&sketch.front);
    let h = hi[1] - lo[1];
    let d = hausdorff(&out, &sketch.front, 0.01) / h;
    let own = rep.profiles[0].max_rel;
    assert!(rep.profiles[0].within && own <= PROFILE_REL, "{own}");
    assert!(d < PROFILE_REL, "independent measure {d}");
    assert!((d - own).abs() < 0.1 * PROFILE_REL, "own {own} vs {d}");
}

/// Without correction passes the same sketch is a clear error naming the
/// level, the view and the miss, not an "Ok" result off the sketch.
#[test]
fn eight_percent_perturbation_without_passes_is_an_error() {
    let t = template();
    let mut o = fast_options();
    o.passes = 0;
    match fit(&t, &eight_percent_sketch(), &o, &prism_outline) {
        Err(e @ TemplateError::ProfileMiss { .. }) => {
            let msg = e.to_string();
            assert!(msg.contains("low level") && msg.contains("front"), "{msg}");
        }
        other => panic!(
            "expected a profile miss, got {:?}",
            other.map(|r| r.levels[0].0.clone())
        ),
    }
    o.on_miss = pdesculpt::template::OnMiss::Report;
    let r = fit(&t, &eight_percent_sketch(), &o, &prism_outline).unwrap();
    let v = r.levels[0].0.profiles[0];
    assert!(!v.within && v.max_rel > PROFILE_REL, "{v:?}");
}

/// `polygon::line_crossings` (the envelope's row crossings) lists every
/// crossing of a row, sorted: a U shape (two prongs) is crossed four times
/// between its prongs' heights, twice below.
#[test]
fn envelope_crossings_of_a_u_shape() {
    use pdesculpt::polygon::line_crossings as crossings;
    let u = [
        [0.0, 0.0],
        [3.0, 0.0],
        [3.0, 2.0],
        [2.0, 2.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
    ];
    let c = crossings(&u, 1.5);
    assert_eq!(c.len(), 4);
    for (a, b) in c.iter().zip([0.0, 1.0, 2.0, 3.0]) {
        assert!((a - b).abs() <= tol::SOLVE, "{c:?}");
    }
    assert_eq!(crossings(&u, 0.5).len(), 2);
    assert!(crossings(&u, 3.0).is_empty());
}

/// One envelope pass moves a figure prism's side outline (a rectangle in
/// depth -1..1) onto a sketched side profile whose front bulges by up to
/// 0.6 (a belly) and whose back is 0.2 deeper: within the fit's tolerance
/// after the pass, far off before.
#[test]
fn envelope_pass_fits_a_bulging_side_profile() {
    use pdesculpt::profile::{profile_distance, Profile};
    use pdesculpt::template::envelope::envelope_pass;
    use pdesculpt::template::measure::mesh_outline;
    let t = Template::whole(prism(&refined(&figure(Figure::default()), 0.1), 1.0));
    let (lo, hi) = t
        .skin
        .positions
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p[1]), h.max(p[1]))
        });
    let bump = |y: f64| {
        let u = (y - (lo + 0.55 * (hi - lo))) / (0.08 * (hi - lo));
        0.6 * (-u * u).exp()
    };
    let n = 400;
    let mut side: Vec<[f64; 2]> = (0..=n)
        .map(|k| {
            let y = lo + (hi - lo) * k as f64 / n as f64;
            [1.0 + bump(y), y]
        })
        .collect();
    side.extend(
        (0..=n)
            .rev()
            .map(|k| [-1.2, lo + (hi - lo) * k as f64 / n as f64]),
    );
    let side = validated("side", &side).unwrap();
    let dist = |pos: &[[f64; 3]]| {
        let o = mesh_outline(&t.skin_at(pos), View::Side).unwrap();
        profile_distance(
            &Profile::new(View::Side, o).unwrap(),
            &Profile::new(View::Side, side.clone()).unwrap(),
        )
        .max_rel
    };
    let mut pos = t.mesh.positions.clone();
    let before = dist(&pos);
    let mut opts = FitOptions::default();
    opts.envelope_arms = false;
    envelope_pass(&t, &mut pos, &side, &opts, &mesh_outline).unwrap();
    let after = dist(&pos);
    assert!(before > 4.0 * PROFILE_REL, "before {before}");
    assert!(after <= PROFILE_REL, "before {before}, after {after}");
}

/// `measure::crease` is the largest increase of the dihedral angle over
/// the rest mesh: a flat square (two triangles) whose second triangle is
/// folded by 0.7 rad about the diagonal creases by 0.7; the same mesh, or
/// a region leaving out an end of the diagonal, by 0; an edge next to a
/// degenerate face is left out.
#[test]
fn crease_of_a_folded_square() {
    use pdesculpt::template::measure::{crease, creases, dihedral_angles};
    let tris = vec![[0, 1, 2], [0, 2, 3]];
    let flat = Mesh::new(
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        tris.clone(),
    );
    // fold vertex 3 about the diagonal 0-2 by `t`
    let fold = |t: f64| {
        let mut m = flat.clone();
        let (c, s) = (t.cos(), t.sin());
        // distance of vertex 3 from the diagonal, along (-1, 1)/sqrt 2
        let d = 0.5f64.sqrt();
        let foot = [0.5, 0.5, 0.0];
        let out = [-0.5f64.sqrt(), 0.5f64.sqrt(), 0.0];
        m.positions[3] = [foot[0] + d * c * out[0], foot[1] + d * c * out[1], d * s];
        m
    };
    let all = |_: &[f64; 3]| true;
    let angle = 0.7;
    let folded = fold(angle);
    assert!((crease(&flat, &folded, &all) - angle).abs() <= tol::SOLVE);
    assert!(crease(&flat, &flat, &all).abs() <= tol::ROUNDING);
    // unfolding is not a crease (an increase only)
    assert!(crease(&folded, &flat, &all).abs() <= tol::ROUNDING);
    let no_origin = |p: &[f64; 3]| p[0] + p[1] > 0.5;
    let c = creases(&flat, &folded, &[&all, &no_origin]);
    assert!(
        (c[0] - angle).abs() <= tol::SOLVE && c[1].abs() <= tol::ROUNDING,
        "{c:?}"
    );
    // one interior edge; a degenerate face gives no angle
    let mut flat_deg = flat.clone();
    flat_deg.positions[3] = [0.5, 0.5, 0.0];
    assert_eq!(dihedral_angles(&flat).len(), 1);
    assert_eq!(dihedral_angles(&flat_deg).values().next(), Some(&None));
    assert!(crease(&flat_deg, &folded, &all).abs() <= tol::ROUNDING);
}

/// Fewest skin vertices a crease region of the MakeHuman templates holds
/// (the male's belly region has hundreds; the old rule left it empty).
const MIN_REGION_VERTICES: usize = 20;

/// The crease regions' front half is the trunk's own (its mean depth at
/// the vertex's height, arms left out): on both MakeHuman templates every
/// region holds vertices, and moving the arms (hands) far in front of the
/// body leaves the regions as they were. The old rule (the middle of the
/// skin's depth range) left the male's belly region empty (the hands and
/// toes pull the middle in front of the belly) and followed the hands.
#[test]
fn crease_regions_use_the_trunks_depth() {
    use pdesculpt::template::measure::mesh_outline;
    use pdesculpt::template::refine::arm_mask;
    use pdesculpt::template::study::{crease_regions, makehuman_template, CASES};
    for case in [CASES[0], CASES[3]] {
        let mut t = makehuman_template(case.template).unwrap();
        let regions = crease_regions(&t);
        for (r, name) in regions.iter().zip(["belly", "face"]) {
            let n = r.iter().filter(|&&x| x).count();
            assert!(
                n >= MIN_REGION_VERTICES,
                "{} {name}: {n} vertices",
                case.name
            );
        }
        let arms = arm_mask(&t, &t.mesh.positions, &FitOptions::default(), &mesh_outline)
            .expect("the MakeHuman template's arms are found");
        let forward = 0.5 * t.height();
        for (p, &a) in t.mesh.positions.iter_mut().zip(&arms) {
            if a {
                p[2] += forward;
            }
        }
        t.skin = t.skin_at(&t.mesh.positions);
        assert!(
            crease_regions(&t) == regions,
            "{}: the hands moved the regions",
            case.name
        );
    }
}

/// Fraction of a step's height a smoothed span may change across
/// `2 * PROBE` of height near the step (the ramp's slope is the step over
/// the filter's half-width; the bound allows the rows' discretisation).
const RAMP_SLACK: f64 = 1.5;

/// The side passes' spans are continuous ([`template::weights`]): an
/// outline with an overhang (a wider block on a narrower one: the front
/// jumps by 1 at height 1) has a raw depth span that jumps by the whole
/// step between two close heights, and a smoothed span that changes by no
/// more than the filter's ramp allows; away from the step the smoothed
/// span is the true one.
#[test]
fn smoothed_depth_span_is_continuous_at_an_overhang() {
    use pdesculpt::template::refine::depth_span;
    use pdesculpt::template::weights::{relative_depth, SpanProfile, SPAN_SMOOTH};
    let outline = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
        [2.0, 1.0],
        [2.0, 2.0],
        [0.0, 2.0],
    ];
    let (height, step) = (2.0, 1.0);
    let probe = 1e-4 * height;
    let raw = |y: f64| depth_span(&outline, y).unwrap().1;
    assert!((raw(1.0 + probe) - raw(1.0 - probe) - step).abs() <= tol::ROUNDING);
    let s = SpanProfile::of_outline(&outline, SPAN_SMOOTH).unwrap();
    let w = SPAN_SMOOTH * height;
    let jump = s.at(1.0 + probe).1 - s.at(1.0 - probe).1;
    assert!(
        jump >= 0.0 && jump <= RAMP_SLACK * step * 2.0 * probe / w,
        "smoothed front jumps by {jump}"
    );
    for y in [0.5, 1.5] {
        let (b, f) = s.at(y);
        let (rb, rf) = depth_span(&outline, y).unwrap();
        assert!((b - rb).abs() <= tol::ROUNDING && (f - rf).abs() <= tol::ROUNDING);
    }
    // relative depth: clamped to [0, 1], one half for an empty span
    assert!((relative_depth(3.0, (0.0, 2.0)) - 1.0).abs() <= tol::ROUNDING);
    assert!((relative_depth(0.5, (0.0, 2.0)) - 0.25).abs() <= tol::ROUNDING);
    assert!((relative_depth(0.5, (1.0, 1.0)) - 0.5).abs() <= tol::ROUNDING);
}

/// Out-of-range envelope options are refused by name before any work: a
/// negative falloff divided by a zero depth weight, a huge pass count
/// re-extracted the outlines without end.
#[test]
fn envelope_options_out_of_range_are_refused() {
    let t = template();
    let sketch = Sketch {
        front: sketch_of(Figure::default()),
        ..Default::default()
    };
    for (falloff, passes) in [(-1, 4), (0, 4), (9, 4), (2, 65), (2, usize::MAX)] {
        let mut opts = FitOptions::default();
        (opts.envelope_falloff, opts.envelope_passes) = (falloff, passes);
        let e = fit(&t, &sketch, &opts, &prism_outline).expect_err("refused");
        assert!(
            e.to_string().contains("envelope_falloff must lie in"),
            "{e}"
        );
    }
    let mut ok = FitOptions::default();
    (ok.envelope_falloff, ok.envelope_passes) = (1, 0);
    assert!(fit(&t, &sketch, &ok, &prism_outline).is_ok());
}
