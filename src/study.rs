//! Studies: experiments that run a method over many inputs and tabulate
//! it, `pdesculpt study NAME` (issue 30). They were part of `verify`
//! (or of the test suite), where they made a run take minutes; `verify`
//! keeps one fast case of each that guards the same claims (family `body`:
//! the base body; family `template`: [`crate::template::check::VERIFY_CASE`]),
//! and a study runs the rest with the same checks, so no check was lost,
//! only moved (the names are unchanged).
//!
//! A study returns its checks (pass/fail, the exit code of the command) and
//! a table of its numbers. Like [`crate::verify`], this is the top of the
//! library: it names the modules whose studies it lists.

use crate::check::{Check, Kind};
use serde::Serialize;

/// A study's result: the checks that guard its claims and its table.
#[derive(Clone, Debug, Default, Serialize)]
pub struct StudyReport {
    pub checks: Vec<Check>,
    /// Column names of [`StudyReport::rows`].
    pub columns: Vec<String>,
    /// One row per measured input, as many cells as `columns`.
    pub rows: Vec<Vec<serde_json::Value>>,
}

/// One study.
pub struct Study {
    pub name: &'static str,
    /// What it measures (one line for `--help` and the list).
    pub about: &'static str,
    pub run: fn() -> StudyReport,
}

/// Every study.
#[rustfmt::skip]
pub fn studies() -> &'static [Study] {
    &[
        Study { name: "bodies", about: "closed reconstruction of every checked MakeHuman morph (body::closed::CHECKED_MORPHS): the pde6.body_closed_* checks per body, one thread per body", run: bodies },
        Study { name: "template", about: "MakeHuman template study: the template checks of every study case (template::study::CASES) but female->pregnant, which verify runs", run: template },
        Study { name: "data-size", about: "data size against error of pde6, ode6 and a loft through the same sections of the base body at three densities (000 Fig 13; paper_figures 000-fig13 draws it)", run: data_size },
    ]
}

/// Runs `f(input)` for every input on its own thread (bounded by the
/// available cores) and concatenates the checks in input order.
fn parallel_checks<T: Sync>(inputs: &[T], f: fn(&mut Vec<Check>, &T)) -> Vec<Check> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut out: Vec<Vec<Check>> = vec![Vec::new(); inputs.len()];
    let next = std::sync::atomic::AtomicUsize::new(0);
    let done = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..threads.min(inputs.len()) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(input) = inputs.get(i) else { break };
                let mut c = Vec::new();
                f(&mut c, input);
                if let Ok(mut d) = done.lock() {
                    d.push((i, c));
                }
            });
        }
    });
    for (i, c) in done.into_inner().unwrap_or_default() {
        out[i] = c;
    }
    out.into_iter().flatten().collect()
}

/// The measured value of check `name`, as a JSON number (null when missing
/// or not finite).
fn measured(checks: &[Check], name: &str) -> serde_json::Value {
    checks
        .iter()
        .find(|c| c.name == name)
        .and_then(|c| serde_json::Number::from_f64(c.measured))
        .map_or(serde_json::Value::Null, serde_json::Value::Number)
}

fn bodies() -> StudyReport {
    use crate::body::closed::CHECKED_MORPHS;
    let checks = parallel_checks(CHECKED_MORPHS, |out, m| {
        crate::body::check::morph_closed_checks(out, m)
    });
    let kinds = [
        "topology",
        "c1",
        "rms",
        "max",
        "full_skin_max",
        "self_crossings",
        "thumb",
        "thumb_web",
    ];
    let rows = CHECKED_MORPHS
        .iter()
        .map(|m| {
            let body = m.split('=').next().unwrap_or(m);
            let mut row = vec![serde_json::Value::from(body)];
            for k in kinds {
                row.push(measured(&checks, &format!("pde6.body_closed_{k}_{body}")));
            }
            row
        })
        .collect();
    StudyReport {
        checks,
        columns: std::iter::once("body".to_string())
            .chain(kinds.iter().map(|k| k.to_string()))
            .collect(),
        rows,
    }
}

fn template() -> StudyReport {
    use crate::template::check::{study_case, study_case_checks, VERIFY_CASE};
    use crate::template::study::CASES;
    let cases: Vec<&crate::template::study::Case> =
        CASES.iter().filter(|c| c.name != VERIFY_CASE).collect();
    let checks = parallel_checks(&cases, |out, c| study_case_checks(out, c.name));
    let mut rows = Vec::new();
    for case in &cases {
        for r in study_case(case).map(|(r, _)| r).unwrap_or_default() {
            let profile = |v: crate::template::View| {
                r.profiles
                    .iter()
                    .find(|p| p.view == v)
                    .map(|p| p.distance.max_rel)
            };
            rows.push(vec![
                r.case.clone().into(),
                r.method.clone().into(),
                r.rms_rel.into(),
                r.max_rel.into(),
                profile(crate::template::View::Front).into(),
                profile(crate::template::View::Side).into(),
                r.creases[0].into(),
                r.creases[1].into(),
            ]);
        }
    }
    StudyReport {
        checks,
        columns: [
            "case",
            "method",
            "rms_rel",
            "max_rel",
            "front_max_rel",
            "side_max_rel",
            "crease_belly",
            "crease_face",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    }
}

fn data_size() -> StudyReport {
    use crate::body::closed::ClosedOptions;
    use crate::body::study::{data_size_study, DENSITIES};
    let run = crate::makehuman::base_body()
        .map_err(|e| e.to_string())
        .and_then(|b| {
            data_size_study(&b.mesh, &DENSITIES, &ClosedOptions::default())
                .map_err(|e| e.to_string())
        });
    let (rows, failure) = match run {
        Ok(rows) => (rows, None),
        Err(e) => (Vec::new(), Some(e)),
    };
    let ran = Check::new(
        "body",
        "000",
        "Fig 13",
        "study.data_size_runs",
        Kind::Threshold,
        if failure.is_some() { 1.0 } else { 0.0 },
        0.0,
    )
    .note(failure.unwrap_or_else(|| format!("{} rows", rows.len())));
    let columns = [
        "density",
        "method",
        "part",
        "sections",
        "stored_numbers",
        "mesh_numbers",
        "recon_to_skin_rms_rel",
        "recon_to_skin_max_rel",
        "skin_to_recon_rms_rel",
        "skin_to_recon_max_rel",
    ];
    let rows = rows
        .iter()
        .map(|r| {
            vec![
                r.density.into(),
                r.method.into(),
                r.part.clone().into(),
                r.sections.into(),
                r.stored_numbers.into(),
                r.mesh_numbers.into(),
                r.recon_to_skin_rms_rel.into(),
                r.recon_to_skin_max_rel.into(),
                r.skin_to_recon_rms_rel.into(),
                r.skin_to_recon_max_rel.into(),
            ]
        })
        .collect();
    StudyReport {
        checks: vec![ran],
        columns: columns.map(String::from).to_vec(),
        rows,
    }
}

/// Runs the study `name`; `None` when there is no such study.
pub fn run(name: &str) -> Option<StudyReport> {
    studies().iter().find(|s| s.name == name).map(|s| (s.run)())
}
