//! Interactivity of `pdesculpt tui` (issue 14: keystroke to redrawn screen
//! under 50 ms without a rebuild; a part rebuild plus preview under 200 ms).
//!
//! * `key_redraw_params`: one key in the parameter panel (selection moves,
//!   nothing is rebuilt or re-rendered) and a full redraw of a 160 x 48
//!   screen on ratatui's `TestBackend` (the terminal write itself is not
//!   included);
//! * `key_redraw_tree`: one key in the part tree: the highlighted part
//!   changes, so the half-block preview is rendered again by the CPU
//!   rasteriser, then the full redraw;
//! * `edit_part_rebuild_preview`: what applying an edit costs: `push_edit`
//!   of a new GEC scale of one part (validated on the UI thread, which
//!   solves that part once), the worker's rebuild at the preview resolution
//!   (60 rings per height) with its part cache (only the edited part is
//!   solved again; transitions and mesh are rebuilt whole) and the preview
//!   render;
//! * baseline `full_rebuild_preview`: the same document rebuilt from
//!   scratch at the preview resolution (every part solved) plus the render;
//! * `full_rebuild_export`: the document at the default resolution of
//!   `character build` (what an export does), no cache;
//! * `cancel_wait_one_part_solve`, `cancel_wait_export_tail`: the longest
//!   waits between two cancel questions of a build (one part's solve; the
//!   export build after the last part, every part cached), against
//!   `full_rebuild_export`. At load 12: 0.17 ms and 489 ms against 524 ms
//!   (the assembly and report after the last part are the wait).

use criterion::{criterion_group, criterion_main, Criterion};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pdesculpt::character::assembly::PartCache;
use pdesculpt::character::log::{Edit, SectionTransform};
use pdesculpt::character::Resolution;
use pdesculpt::tui::app::{App, Effect, Focus};
use pdesculpt::tui::preview::{self, ViewSet};
use pdesculpt::tui::term::{open, preview_resolution, Options, PREVIEW_RINGS};
use pdesculpt::tui::view::{draw, PreviewCache};
use pdesculpt::tui::worker::{build, build_with, Job, Outcome, Task};
use ratatui::backend::TestBackend;
use ratatui::Terminal;
use std::hint::black_box;
use std::time::Duration;

fn preview_res() -> Resolution {
    preview_resolution(PREVIEW_RINGS)
}

fn job(app: &mut App, res: Resolution) -> Job {
    Job {
        gen: app.start_job(false),
        doc: app.doc.clone(),
        base: app.base.clone(),
        res,
        task: Task::Rebuild,
    }
}

fn built_app() -> App {
    let dir = std::env::temp_dir().join(format!("pdesculpt-bench-tui-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let o = Options::new(dir.join("char.json"), "female").with_preview(preview_res());
    let mut app = open(&o).expect("opens");
    let j = job(&mut app, preview_res());
    let r = build(&j).expect("builds");
    let e = app.on_outcome(Outcome::Built {
        gen: j.gen,
        result: Ok(Box::new(r)),
        elapsed: Duration::ZERO,
    });
    assert!(e.iter().all(|e| *e != Effect::Quit));
    app
}

fn bench(c: &mut Criterion) {
    let mut app = built_app();
    let mut term = Terminal::new(TestBackend::new(160, 48)).expect("terminal");
    let mut cache = PreviewCache::default();
    let mut g = c.benchmark_group("tui");
    app.focus = Focus::Params;
    let mut down = true;
    g.bench_function("key_redraw_params", |b| {
        b.iter(|| {
            let code = if down { KeyCode::Down } else { KeyCode::Up };
            down = !down;
            black_box(app.on_key(KeyEvent::new(code, KeyModifiers::NONE)));
            term.draw(|f| draw(f, &app, &mut cache)).expect("draws");
        })
    });
    app.focus = Focus::Tree;
    g.bench_function("key_redraw_tree", |b| {
        b.iter(|| {
            let code = if down { KeyCode::Down } else { KeyCode::Up };
            down = !down;
            black_box(app.on_key(KeyEvent::new(code, KeyModifiers::NONE)));
            term.draw(|f| draw(f, &app, &mut cache)).expect("draws");
        })
    });
    let parts: Vec<String> = app.edited.iter().map(|p| p.name.clone()).collect();
    let render = |r: &pdesculpt::tui::worker::Rebuilt| {
        black_box(preview::render(
            &r.mesh,
            &parts,
            Some("arm_l"),
            ViewSet::Front,
            82,
            46,
        ))
    };
    g.sample_size(10);
    let mut cache = PartCache::default();
    let mut j = job(&mut app, preview_res());
    build_with(&j, Some(&mut cache)).expect("builds");
    let base = j.doc.clone();
    let mut k = 0u32;
    g.bench_function("edit_part_rebuild_preview", |b| {
        b.iter(|| {
            // a new scale each time: the edited part is never cached
            k += 1;
            j.doc = base.clone();
            j.doc
                .push_edit(Edit::GecTransform {
                    part: "arm_l".into(),
                    section: None,
                    transform: SectionTransform::Scale {
                        sx: 1.0 + 1e-4 * k as f64,
                        sy: 1.0,
                    },
                })
                .expect("valid edit");
            let r = build_with(&j, Some(&mut cache)).expect("builds");
            render(&r);
        })
    });
    j.doc = base;
    g.bench_function("full_rebuild_preview", |b| {
        b.iter(|| {
            let r = build(&j).expect("builds");
            render(&r);
        })
    });
    let j = job(&mut app, Resolution::default());
    g.bench_function("full_rebuild_export", |b| {
        b.iter(|| black_box(build(&j).expect("builds")))
    });
    // the longest stretches a cancel waits for (Esc is seen at the next
    // question of `build_cancellable`): one part's solve (the torso, the
    // most sections) and the export build after the last question (every
    // part cached: transitions, mesh assembly, report)
    let torso = app
        .doc
        .parts()
        .iter()
        .max_by_key(|p| p.sections.len())
        .expect("parts")
        .clone();
    g.bench_function("cancel_wait_one_part_solve", |b| {
        b.iter(|| black_box(PartCache::default().get(&torso).expect("solves")))
    });
    let mut warm = PartCache::default();
    build_with(&j, Some(&mut warm)).expect("builds");
    g.bench_function("cancel_wait_export_tail", |b| {
        b.iter(|| black_box(build_with(&j, Some(&mut warm)).expect("builds")))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
