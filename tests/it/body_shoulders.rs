//! The closed body's shoulder transitions (issue 15, build item 2): no
//! crossing triangle pairs inside the shoulders on the bodies fixed.

use pdesculpt::body::closed::{load_body, reconstruct_closed, ClosedOptions};
use pdesculpt::body::intersect::self_intersections;

/// Crossing pairs with both triangles in the shoulders transition, and the
/// shoulders' cut angles (empty: the fixed cuts).
fn shoulders(morph: Option<&str>) -> (usize, Vec<f64>) {
    let morphs: Vec<String> = morph.map(|m| vec![format!("{m}=1")]).unwrap_or_default();
    let morphs: Vec<&str> = morphs.iter().map(String::as_str).collect();
    let b = crate::shared::closed_body(&morphs);
    let n = self_intersections(&b.model.mesh)
        .by_groups
        .iter()
        .filter(|(g, _)| g == "shoulders/shoulders")
        .map(|(_, n)| *n)
        .sum();
    let t = b
        .transitions
        .iter()
        .find(|t| t.name == "shoulders")
        .unwrap();
    (n, t.cut_angles.clone())
}

fn shoulder_crossings(morph: Option<&str>) -> usize {
    shoulders(morph).0
}

/// The bodies whose shoulders have no crossing pair. Measured before the
/// capped per-column scales of `character::transition::column_scales` and the
/// seam's `seam_across_weight`: base 3, stomach-pregnant-incr 3,
/// universal-male maxweight 2, caucasian-male-old 2, african-, asian- and
/// caucasian-male-young 1 each. The female armpits are not fixed (README,
/// Self-intersections).
const NO_SHOULDER_CROSSINGS: &[Option<&str>] = &[
    None,
    Some("stomach-pregnant-incr"),
    Some("universal-male-young-averagemuscle-maxweight"),
    Some("caucasian-male-old"),
    Some("african-male-young"),
    Some("asian-male-young"),
    Some("caucasian-male-young"),
];

#[test]
fn the_male_bodies_and_the_base_have_no_shoulder_crossings() {
    // the bodies reconstructed side by side (crate::shared::parallel_map)
    let found = crate::shared::parallel_map(NO_SHOULDER_CROSSINGS, |m| shoulders(*m));
    for (m, (n, cuts)) in NO_SHOULDER_CROSSINGS.iter().zip(found) {
        assert_eq!(n, 0, "{}", m.unwrap_or("base"));
        // no crossing with the fixed cuts: body::closed::shoulder_cuts keeps them
        assert!(cuts.is_empty(), "{}: {cuts:?}", m.unwrap_or("base"));
    }
}

/// The female armpits: with the fixed cuts the shoulders cross (measured:
/// universal-female maxweight 70 pairs, caucasian-female-young 32);
/// `body::closed::shoulder_cuts` moves the cuts
/// toward the arms until they do not, and the cuts it chose are not the
/// fixed ones.
#[test]
fn the_female_armpits_have_no_shoulder_crossings_with_measured_cuts() {
    use pdesculpt::body::closed::{shifted_shoulder_cuts, shoulder_cut_angles};
    let females = [
        "universal-female-young-averagemuscle-maxweight",
        "caucasian-female-young",
    ];
    let found = crate::shared::parallel_map(&females, |m| shoulders(Some(m)));
    for (m, (n, cuts)) in females.into_iter().zip(found) {
        assert_eq!(n, 0, "{m}");
        assert_eq!(cuts.len(), 4, "{m}: {cuts:?}");
        assert_ne!(
            cuts,
            shoulder_cut_angles(shifted_shoulder_cuts(0, 0)),
            "{m}"
        );
    }
}

/// `cut_table` with one angle per seam mirrors the back cut; with a front
/// and a back angle per seam it keeps both; other lengths fall back to the
/// fixed angles. `shifted_shoulder_cuts` moves seam 1 toward the left arm
/// (ring index n / 2) and mirrors seam 2 in x.
#[test]
fn cut_table_takes_front_and_back_angles() {
    use pdesculpt::body::closed::{shifted_shoulder_cuts, shoulder_cut_angles};
    use pdesculpt::character::ring::{cut_indices, cut_table};
    use pdesculpt::character::transition::{loop_len, loop_runs};
    use std::f64::consts::PI;
    let a = |i: usize| i as f64 * PI / 24.0;
    assert_eq!(cut_table(3, &[a(16), a(8)]), vec![(16, 32), (8, 40)]);
    assert_eq!(
        cut_table(3, &[a(17), a(7), a(29), a(43)]),
        vec![(17, 29), (7, 43)]
    );
    assert!(cut_table(3, &[a(17), a(7), a(29)]).is_empty());
    assert_eq!(
        shifted_shoulder_cuts(0, 0),
        [cut_indices(1, 3, &[]), cut_indices(2, 3, &[])]
    );
    let c = shifted_shoulder_cuts(1, 3);
    assert_eq!(c, [(17, 29), (7, 43)]);
    assert_eq!(cut_table(3, &shoulder_cut_angles(c)), c.to_vec());
    // the left arm's loop: its arc from the back cut to the front cut, 12
    // ring steps instead of 16, then the seam
    let runs = loop_runs(0, 3, &c);
    assert_eq!(loop_len(&runs), 12 + 9);
}

/// Diagnostic (run by hand, `--ignored --nocapture`, `XING_MORPH=NAME`):
/// writes the shoulder transition's columns as JSON to the temp dir
/// (`shoulder_dump.json`): per child the loop point, the unit-scale cross
/// tangent, the scale and the child ring angle at 10 samples per column,
/// and the child ring and its u-derivative at 720 angles.
#[test]
#[ignore]
fn dump_shoulder_columns() {
    use pdesculpt::character::ring::cut_table;
    use pdesculpt::character::seam::seams;
    use pdesculpt::character::transition::{child_transition, loop_eval};
    use std::f64::consts::PI;
    let morphs: Vec<String> = std::env::var("XING_MORPH")
        .ok()
        .map(|m| vec![format!("{m}=1")])
        .unwrap_or_default();
    let skin = load_body(None, &morphs).unwrap();
    let b = reconstruct_closed(&skin, &ClosedOptions::default()).unwrap();
    let parts = &b.model.parts;
    let t = b
        .transitions
        .iter()
        .find(|t| t.name == "shoulders")
        .unwrap();
    let find = |n: &str| parts.iter().position(|p| p.name == n).unwrap();
    let pi = find(&t.parent);
    let ci: Vec<usize> = t.children.iter().map(|c| find(c)).collect();
    let centres: Vec<[f64; 3]> = ci
        .iter()
        .map(|&c| parts[c].section(parts[c].u0, 0).c0)
        .collect();
    let cuts = cut_table(ci.len(), &t.cut_angles);
    let ss = seams(
        &parts[pi],
        t.parent_end,
        ci.len(),
        &t.seam_apex,
        &centres,
        &cuts,
    );
    let mut kids = Vec::new();
    for c in 0..ci.len() {
        let ct = child_transition(
            c,
            ci.len(),
            &parts[pi],
            t.parent_end,
            &parts[ci[c]],
            &ss,
            &cuts,
            t.tangent_scale,
            t.continuity,
        );
        let mut cols = Vec::new();
        for k in 0..ct.n * 10 {
            let tau = k as f64 / 10.0;
            let (l, tt) = loop_eval(&ct, &parts[pi], &ss, tau);
            let e = ct.ell_at(tau);
            let th = ct.theta0 + ct.sigma * 2.0 * PI * tau / ct.n as f64;
            cols.push(serde_json::json!({
                "tau": tau, "l": l, "t1": tt.map(|x| x / e), "ell": e, "theta": th
            }));
        }
        let q = parts[ci[c]].section(ct.child_u, 0);
        let dq = parts[ci[c]].section(ct.child_u, 1);
        let ring: Vec<_> = (0..720)
            .map(|a| {
                let th = 2.0 * PI * a as f64 / 720.0;
                serde_json::json!({"q": q.eval(th), "dq": dq.eval(th)})
            })
            .collect();
        kids.push(serde_json::json!({
            "name": t.children[c], "n": ct.n, "ell": ct.ell, "theta0": ct.theta0,
            "sigma": ct.sigma, "runs": format!("{:?}", ct.runs), "cols": cols, "ring": ring
        }));
    }
    let p = std::env::temp_dir().join("shoulder_dump.json");
    std::fs::write(&p, serde_json::to_string(&kids).unwrap()).unwrap();
    println!("wrote {}", p.display());
}

#[test]
#[ignore]
fn shoulder_crossings_print() {
    let m = std::env::var("XING_MORPH").ok();
    println!("{}", shoulder_crossings(m.as_deref()));
}

/// Diagnostic (run by hand, `--ignored --nocapture`): for `XING_MORPH`
/// prints the measured cuts and errors, the torso's end ring near the left
/// arm (point, unit u-tangent), then builds the body with each cut pair of
/// `XING_CUTS` (`f/b`: seam 1's back and front ring index, seam 2 mirrored;
/// `f`: the back index, front mirrored) and prints its crossings by group and
/// errors; with `XING_PNG` set, renders its shoulders to the temp dir.
#[test]
#[ignore]
fn sweep_shoulder_cuts() {
    use pdesculpt::body::closed::shoulder_cut_angles;
    use pdesculpt::body::layout::find_layout;
    use pdesculpt::body::report::measure;
    use std::f64::consts::PI;
    let m = std::env::var("XING_MORPH").ok();
    let morphs: Vec<String> = m.iter().map(|m| format!("{m}=1")).collect();
    let skin = load_body(None, &morphs).unwrap();
    let o = ClosedOptions::default();
    let b = reconstruct_closed(&skin, &o).unwrap();
    let lay = find_layout(&skin).unwrap();
    let r = &b.report;
    println!(
        "rule {:?}: {} pairs {:?}; r->s {:.2} outer s->r {:.2} rms {:.3} at {:?} / {:?}",
        b.transitions[1]
            .cut_angles
            .iter()
            .map(|a| (a * 24.0 / PI).round())
            .collect::<Vec<_>>(),
        r.self_intersections.pairs,
        r.self_intersections.by_groups,
        100.0 * r.recon_to_skin_max_rel,
        100.0 * r.skin_to_recon_outer_max_rel,
        100.0 * r.judged_rms_rel(),
        r.recon_to_skin_max_at
            .as_ref()
            .map(|a| (a.point, a.height_rel)),
        r.skin_to_recon_outer_max_at
            .as_ref()
            .map(|a| (&a.group, a.section, a.point, a.height_rel)),
    );
    // "f" (back mirrored) or "f/b": ring indices of seam 1's cuts, seam 2
    // mirrored in x
    let part = |n: &str| b.model.parts.iter().find(|p| p.name == n).unwrap();
    let range: Vec<(String, [(usize, usize); 2])> = std::env::var("XING_CUTS")
        .ok()
        .map(|s| {
            s.split(',')
                .map(|x| {
                    let (f, bk) = if let Some((f, b)) = x.split_once('/') {
                        (f.parse::<usize>().unwrap(), b.parse::<usize>().unwrap())
                    } else {
                        (x.parse().unwrap(), 48 - x.parse::<usize>().unwrap())
                    };
                    (x.to_string(), [(f, bk), (24 - f, 72 - bk)])
                })
                .collect()
        })
        .unwrap_or_default();
    // the torso's end ring near the left arm: point and unit u-tangent
    let torso = part("torso");
    let u1 = torso.end_u(pdesculpt::character::doc::End::End);
    let (p0, p1) = (torso.section(u1, 0), torso.section(u1, 1));
    for i in 12..=36 {
        let th = 2.0 * PI * i as f64 / 48.0;
        let (p, d) = (p0.eval(th), p1.eval(th));
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        println!(
            "ring {i}: p ({:.3}, {:.3}, {:.3}) |dP/du| {:.2} dir ({:.2}, {:.2}, {:.2})",
            p[0],
            p[1],
            p[2],
            l,
            d[0] / l,
            d[1] / l,
            d[2] / l
        );
    }
    let arm = part("arm_l");
    let q = arm.section(arm.u0, 0);
    println!("arm_l start centre {:?} layout {:?}", q.c0, b.report.layout);
    for (name, c) in range {
        let model = with_shoulder_cuts(&b, shoulder_cut_angles(c), lay.height(), &o);
        if std::env::var("XING_PNG").is_ok() {
            let png = std::env::temp_dir().join(format!("xing_cut_{}.png", name.replace('/', "_")));
            shoulder_png(
                &model.mesh,
                lay.armpit - 0.08 * lay.height(),
                lay.neck,
                &png,
            );
            println!("wrote {}", png.display());
        }
        let r = measure(&skin, &lay, &model, &b.specs, &[]);
        println!(
            "cut {name} {c:?}: {} pairs {:?}; r->s {:.2} outer s->r {:.2} rms {:.3} at {:?}",
            r.self_intersections.pairs,
            r.self_intersections.by_groups,
            100.0 * r.recon_to_skin_max_rel,
            100.0 * r.skin_to_recon_outer_max_rel,
            100.0 * r.judged_rms_rel(),
            r.recon_to_skin_max_at
                .as_ref()
                .map(|a| (a.point, a.height_rel))
        );
    }
}

/// Diagnostic (run by hand): the shoulders' cuts and crossings of the
/// data-size study's densities (base body) and of the demo's closed body.
#[test]
#[ignore]
fn study_and_demo_shoulder_cuts() {
    use pdesculpt::body::study::DENSITIES;
    let skin = load_body(None, &[]).unwrap();
    for d in DENSITIES {
        let o = d.options(&ClosedOptions::default());
        let b = reconstruct_closed(&skin, &o).unwrap();
        let t = b
            .transitions
            .iter()
            .find(|t| t.name == "shoulders")
            .unwrap();
        let r = &b.report;
        println!(
            "study {}: cuts {:?} crossings {:?}; recon->skin {:.2} / {:.2} (skin->recon {:.2} / {:.2}) %",
            d.name,
            t.cut_angles,
            r.self_intersections.by_groups,
            100.0 * r.recon_to_skin_rms_rel,
            100.0 * r.recon_to_skin_max_rel,
            100.0 * r.skin_to_recon_rms_rel,
            100.0 * r.skin_to_recon_max_rel
        );
        if !t.cut_angles.is_empty() {
            use pdesculpt::body::layout::find_layout;
            use pdesculpt::body::report::measure;
            let lay = find_layout(&skin).unwrap();
            let m = with_shoulder_cuts(&b, Vec::new(), lay.height(), &o);
            let r = measure(&skin, &lay, &m, &b.specs, &[]);
            println!(
                "  fixed cuts: crossings {:?}; recon->skin {:.2} / {:.2} (skin->recon {:.2} / {:.2}) %",
                r.self_intersections.by_groups,
                100.0 * r.recon_to_skin_rms_rel,
                100.0 * r.recon_to_skin_max_rel,
                100.0 * r.skin_to_recon_rms_rel,
                100.0 * r.skin_to_recon_max_rel
            );
        }
    }
    let demo = pdesculpt::demo::build().unwrap();
    println!(
        "demo: crossings {:?}",
        demo.report.reconstruction.self_intersections.by_groups
    );
}

/// Renders the triangles of `m` between heights `y0` and `y1` (front and a
/// three-quarter view) to `png`.
fn shoulder_png(m: &pdesculpt::mesh::Mesh, y0: f64, y1: f64, png: &std::path::Path) {
    use pdesculpt::render::{render_views, RenderOptions, View};
    let mut sub = pdesculpt::mesh::Mesh::default();
    let mut map = std::collections::HashMap::new();
    for tri in &m.triangles {
        let inside = tri.iter().all(|&v| {
            let y = m.positions[v as usize][1];
            y >= y0 && y <= y1
        });
        if !inside {
            continue;
        }
        let t = tri.map(|v| {
            *map.entry(v).or_insert_with(|| {
                sub.positions.push(m.positions[v as usize]);
                (sub.positions.len() - 1) as u32
            })
        });
        sub.triangles.push(t);
        sub.tri_group.push(0);
    }
    sub.groups = vec!["shoulders".into()];
    let views = [
        View::Front,
        View::Perspective {
            yaw: 35.0,
            pitch: 10.0,
        },
    ];
    let o = RenderOptions::default().with_width(600).with_height(600);
    render_views(&sub, &views, &o).save_png(png).unwrap();
}

/// The closed body `b` rebuilt with the shoulders' `cut_angles` replaced
/// (empty: the fixed cuts); the other transitions (hips, wrists) as built.
fn with_shoulder_cuts(
    b: &pdesculpt::body::closed::ClosedBody,
    cuts: Vec<f64>,
    height: f64,
    o: &ClosedOptions,
) -> pdesculpt::character::assembly::Model {
    let mut tr = b.transitions.clone();
    let k = tr.iter().position(|t| t.name == "shoulders").unwrap();
    tr[k].cut_angles = cuts;
    pdesculpt::character::assembly::build_model(
        &b.specs,
        &tr,
        height,
        pdesculpt::character::assembly::Resolution {
            rings_per_height: o.rings_per_height,
            transition_rows: o.transition_rows,
        },
    )
    .unwrap()
}
