//! The MakeHuman study table (issue 12), printed; slow (7 cases, every
//! level), so ignored by default: `cargo test --release --test it
//! template_study -- --ignored --nocapture`. The registry's checks assert
//! the numbers that must hold.

use pdesculpt::template::refine::{DepthMap, SidePartner};
use pdesculpt::template::study::{run_case, CASES};
use pdesculpt::template::{FitOptions, OnMiss};

#[test]
#[ignore]
fn study_table() {
    let mut opts = FitOptions::default();
    opts.condition = false;
    opts.on_miss = OnMiss::Report;
    if std::env::var("STUDY_ARCLENGTH").is_ok() {
        opts.section_match = pdesculpt::template::sections::SectionMatch::ArcLength;
    }
    if std::env::var("STUDY_NOBAND").is_ok() {
        opts.band_anchors = 0;
    }
    let only = std::env::var("STUDY_CASE").ok();
    // STUDY_VARIANTS="robust:heading:2,lsq:arc:2": side-pass variants
    // (depth map, partner, falloff), each run on every case
    let variants = std::env::var("STUDY_VARIANTS").unwrap_or_default();
    let mut runs = vec![("default".to_string(), opts.clone())];
    if !variants.is_empty() {
        runs = variants
            .split(',')
            .map(|v| {
                let f: Vec<&str> = v.split(':').collect();
                let mut o = opts.clone();
                o.depth_map = match f[0] {
                    "none" => DepthMap::None,
                    "lsq" => DepthMap::LeastSquares,
                    _ => DepthMap::Robust,
                };
                o.side_partner = match f.get(1) {
                    Some(&"arc") => SidePartner::ArcLength,
                    _ => SidePartner::Heading,
                };
                if let Some(x) = f.get(2) {
                    o.depth_falloff = x.parse().unwrap();
                }
                (v.to_string(), o)
            })
            .collect();
    }
    for case in CASES {
        if only
            .as_deref()
            .is_some_and(|o| !o.split(',').any(|o| o == case.name))
        {
            continue;
        }
        for (label, opts) in &runs {
            println!("VARIANT {label}");
            one_case(case, opts);
        }
    }
}

fn one_case(case: &pdesculpt::template::study::Case, opts: &FitOptions) {
    {
        let (rows, meshes) = run_case(case, opts).unwrap();
        if std::env::var("STUDY_BANDS").is_ok() {
            bands(case, &meshes);
        }
        for r in rows {
            let prof: Vec<String> = r
                .profiles
                .iter()
                .map(|p| format!("{} {:.2}", p.view.name(), 100.0 * p.distance.max_rel))
                .collect();
            println!(
                "STUDY {:18} {:6} rms {:.2} max {:.2} | {} | {:.2} s",
                r.case,
                r.method,
                100.0 * r.rms_rel,
                100.0 * r.max_rel,
                prof.join(", "),
                r.seconds
            );
        }
    }
}

/// Diagnostic (`STUDY_BANDS=1`): each level's squared-RMS share per height
/// band (tenths of the height) and per axis, in (% of height)^2.
fn bands(case: &pdesculpt::template::study::Case, meshes: &[Vec<[f64; 3]>]) {
    use pdesculpt::template::study::makehuman_template;
    let template = makehuman_template(case.template).unwrap();
    let ts: Vec<_> = case
        .target
        .iter()
        .map(|n| (pdesculpt::makehuman::target(n).unwrap(), 1.0))
        .collect();
    let target = pdesculpt::makehuman::body(&ts).unwrap().mesh;
    let (lo, hi) = target
        .positions
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p[1]), h.max(p[1]))
        });
    let h = hi - lo;
    let n = target.positions.len() as f64;
    for (k, m) in meshes.iter().enumerate() {
        let skin = template.skin_at(m).positions;
        let mut band = [[0.0f64; 3]; 10];
        for (p, q) in skin.iter().zip(&target.positions) {
            let b = (((q[1] - lo) / h * 10.0) as usize).min(9);
            for a in 0..3 {
                band[b][a] += (100.0 * (p[a] - q[a]) / h).powi(2) / n;
            }
        }
        let cells: Vec<String> = band
            .iter()
            .map(|b| format!("{:.3}/{:.3}/{:.3}", b[0], b[1], b[2]))
            .collect();
        println!("BANDS {} level {k}: {}", case.name, cells.join(" "));
        let (i, d) = skin
            .iter()
            .zip(&target.positions)
            .map(|(p, q)| {
                ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
            })
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        println!(
            "WORST level {k}: vertex {i} off {:.2} %: template {:?} fitted {:?} target {:?}",
            100.0 * d / h,
            template.skin.positions[i].map(|v| (v * 100.0).round() / 100.0),
            skin[i].map(|v| (v * 100.0).round() / 100.0),
            target.positions[i].map(|v| (v * 100.0).round() / 100.0)
        );
    }
}
