//! The MakeHuman study table (issue 12), printed; slow (7 cases, every
//! level), so ignored by default: `cargo test --release --test it
//! template_study -- --ignored --nocapture`. The registry's checks assert
//! the numbers that must hold.

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
    for case in CASES {
        if only.as_deref().is_some_and(|o| o != case.name) {
            continue;
        }
        let (rows, _) = run_case(case, &opts).unwrap();
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
