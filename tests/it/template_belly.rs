//! The pregnant belly at the high level (issue 12, 000 sec 4.2.3): the key
//! cross-sections must narrow the medium level's full-width depth push back
//! to the target's belly shape.

use pdesculpt::template::study::{makehuman_template, run_case, target_mesh, torso_section, CASES};
use pdesculpt::template::{FitOptions, OnMiss};

fn pregnant() -> &'static pdesculpt::template::study::Case {
    CASES.iter().find(|c| c.name == "female->pregnant").unwrap()
}

use pdesculpt::template::belly::{belly_miss, belly_misses, BELLY_REL};
use pdesculpt::template::polygon::validated;
use pdesculpt::template::sections::{gec_loop, gec_or_sketched};
use pdesculpt::template::study::sketch_of;

/// The medium level's full-width depth push is the defect the key sections
/// must undo: its belly slices miss the target's by more than
/// [`BELLY_REL`]; the high level's (six sections, two across the belly's
/// underside) lie within it at every compared height.
#[test]
fn pregnant_high_level_belly_slices_match_the_target() {
    let case = pregnant();
    let template = makehuman_template(case.template).unwrap();
    let target = target_mesh(case).unwrap();
    // the fit of the template family's checks (condition numbers off,
    // misses reported), shared with them in this process
    let (_, meshes) = pdesculpt::template::check::study_case(case).expect("pregnant case");
    let medium = belly_miss(&template, &meshes[2], &target);
    let high = belly_misses(&template, &meshes[3], &target);
    assert!(medium > BELLY_REL, "medium belly miss {medium}");
    for (k, m) in high.iter().enumerate() {
        assert!(*m < BELLY_REL, "high belly miss {m} at height {k}");
    }
}

/// The study's lowest sections (just above the crotch) of the fat male:
/// the 10-term GEC of at least one rings into a self-intersection (the
/// cleft between the buttocks); the high level then takes the sketched
/// loop itself instead of refusing the sketch.
#[test]
fn a_section_whose_gec_self_intersects_falls_back_to_the_sketched_loop() {
    let case = CASES.iter().find(|c| c.name == "male->fat").unwrap();
    let target = target_mesh(case).unwrap();
    let sketch = sketch_of(&target).unwrap();
    let opts = FitOptions::default();
    let m = 4 * opts.section_points;
    let mut rang = 0;
    for s in &sketch.sections {
        let lp = &s.loops[0];
        if validated("gec", &gec_loop(s.y, lp, opts.gec_terms, m).unwrap()).is_err() {
            rang += 1;
        }
        let got = gec_or_sketched(s.y, lp, opts.gec_terms, m).unwrap();
        assert_eq!(got.len(), m);
        assert!(validated("section", &got).is_ok());
    }
    assert!(rang > 0, "no section's GEC self-intersects");
}

/// Diagnostic: the pregnant case's error per height (fiftieths of the
/// height, 0.40-0.80) and axis, per x across the belly's front, and the
/// torso slices of template, medium, high and target at belly heights as
/// JSON (`BELLY_DUMP=DIR`). `cargo test --release --test it belly_diagnostic
/// -- --ignored --nocapture`.
#[test]
#[ignore]
fn belly_diagnostic() {
    let mut opts = FitOptions::default();
    opts.condition = false;
    opts.on_miss = OnMiss::Report;
    let case = pregnant();
    let (rows, meshes) = run_case(case, &opts).unwrap();
    let template = makehuman_template(case.template).unwrap();
    let target = target_mesh(case).unwrap();
    for (k, m) in meshes.iter().enumerate() {
        let v: Vec<String> = belly_misses(&template, m, &target)
            .iter()
            .map(|x| format!("{:.2}", 100.0 * x))
            .collect();
        println!("BELLY level {k}: {}", v.join(" "));
    }
    // the sections from 0.56 up only (the study's sketch before)
    let mut sk = sketch_of(&target).unwrap();
    let (lo, hi) = target.bbox();
    sk.sections
        .retain(|s| s.y >= lo[1] + 0.555 * (hi[1] - lo[1]));
    let r = pdesculpt::template::fit(
        &template,
        &sk,
        &opts,
        &pdesculpt::template::measure::mesh_outline,
    )
    .unwrap();
    let v: Vec<String> = belly_misses(&template, &r.levels[2].1, &target)
        .iter()
        .map(|x| format!("{:.2}", 100.0 * x))
        .collect();
    println!(
        "BELLY high, {} sections from 0.56: {}",
        sk.sections.len(),
        v.join(" ")
    );
    for r in &rows {
        println!(
            "ROW {} rms {:.3} max {:.3}",
            r.method,
            100.0 * r.rms_rel,
            100.0 * r.max_rel
        );
    }
    let template = makehuman_template(case.template).unwrap();
    let target = target_mesh(case).unwrap();
    let (lo, hi) = target.bbox();
    let h = hi[1] - lo[1];
    let n = target.positions.len() as f64;
    for (k, m) in meshes.iter().enumerate() {
        let skin = template.skin_at(m).positions;
        let mut band = [[0.0f64; 3]; 20];
        for (p, q) in skin.iter().zip(&target.positions) {
            let f = (q[1] - lo[1]) / h;
            if !(0.4..0.8).contains(&f) {
                continue;
            }
            let b = (((f - 0.4) * 50.0) as usize).min(19);
            for a in 0..3 {
                band[b][a] += (100.0 * (p[a] - q[a]) / h).powi(2) / n;
            }
        }
        let cells: Vec<String> = band
            .iter()
            .enumerate()
            .map(|(b, c)| {
                format!(
                    "{:.2}:{:.3}/{:.3}/{:.3}",
                    0.4 + b as f64 / 50.0,
                    c[0],
                    c[1],
                    c[2]
                )
            })
            .collect();
        println!("BANDS level {k}: {}", cells.join(" "));
        // mean signed z error of front vertices (z above the target's
        // median at that height) per x bin, belly heights 0.48-0.66
        let xc = 0.5 * (lo[0] + hi[0]);
        for (ya, yb) in [
            (0.46, 0.50),
            (0.50, 0.54),
            (0.54, 0.58),
            (0.58, 0.62),
            (0.62, 0.66),
        ] {
            let mut bins = [(0.0f64, 0usize, 0.0f64); 12];
            for (p, q) in skin.iter().zip(&target.positions) {
                let f = (q[1] - lo[1]) / h;
                if f < ya || f >= yb || q[2] < 0.5 {
                    continue;
                }
                let xb = ((q[0] - xc) / h * 100.0 + 12.0) / 2.0;
                if !(0.0..12.0).contains(&xb) {
                    continue;
                }
                let b = xb as usize;
                bins[b].0 += 100.0 * (p[2] - q[2]) / h;
                bins[b].1 += 1;
                bins[b].2 += 100.0 * (p[0] - q[0]) / h;
            }
            let cells: Vec<String> = bins
                .iter()
                .map(|(s, c, x)| {
                    if *c == 0 {
                        "   -   ".into()
                    } else {
                        format!("{:+.2}/{:+.2}", s / *c as f64, x / *c as f64)
                    }
                })
                .collect();
            println!(
                "XBINS level {k} y {ya:.2}-{yb:.2} dz/dx: {}",
                cells.join(" ")
            );
        }
    }
    if let Ok(dir) = std::env::var("BELLY_DUMP") {
        let mut out = serde_json::Map::new();
        for f in [0.48, 0.50, 0.52, 0.54, 0.56, 0.58, 0.60, 0.62, 0.64] {
            let y = lo[1] + f * h;
            let mut row = serde_json::Map::new();
            row.insert(
                "target".into(),
                serde_json::json!(torso_section(&target, y)),
            );
            for (k, m) in meshes.iter().enumerate() {
                let skin = template.skin_at(m);
                row.insert(
                    format!("level{k}"),
                    serde_json::json!(torso_section(&skin, y)),
                );
            }
            out.insert(format!("{f:.2}"), serde_json::Value::Object(row));
        }
        // side outlines
        use pdesculpt::template::measure::mesh_outline;
        use pdesculpt::template::View;
        out.insert(
            "side_target".into(),
            serde_json::json!(mesh_outline(&target, View::Side).unwrap()),
        );
        for (k, m) in meshes.iter().enumerate() {
            let skin = template.skin_at(m);
            out.insert(
                format!("side{k}"),
                serde_json::json!(mesh_outline(&skin, View::Side).unwrap()),
            );
        }
        out.insert("lo".into(), serde_json::json!(lo[1]));
        out.insert("h".into(), serde_json::json!(h));
        std::fs::write(
            format!("{dir}/belly.json"),
            serde_json::Value::Object(out).to_string(),
        )
        .unwrap();
    }
}
