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
//! * `rebuild_preview`: what an edit costs: the whole document rebuilt at
//!   the preview resolution (60 rings per height: every change rebuilds
//!   every part, there is no partial rebuild) plus the preview render;
//! * baseline `rebuild_export`: the same document at the default
//!   resolution of `character build` (what an export does), in the same run.

use criterion::{criterion_group, criterion_main, Criterion};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pdesculpt::sketch::Resolution;
use pdesculpt::tui::app::{App, Effect, Focus};
use pdesculpt::tui::preview::{self, ViewSet};
use pdesculpt::tui::term::{open, Options, PREVIEW_RINGS};
use pdesculpt::tui::view::{draw, PreviewCache};
use pdesculpt::tui::worker::{build, Job, Outcome, Task};
use ratatui::backend::TestBackend;
use ratatui::Terminal;
use std::hint::black_box;
use std::time::Duration;

fn preview_res() -> Resolution {
    Resolution {
        rings_per_height: PREVIEW_RINGS,
        ..Resolution::default()
    }
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
    let o = Options {
        path: dir.join("char.json"),
        bundled: "female".into(),
        preview: preview_res(),
    };
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
    let j = job(&mut app, preview_res());
    g.sample_size(10);
    g.bench_function("rebuild_preview", |b| {
        b.iter(|| {
            let r = build(&j).expect("builds");
            black_box(preview::render(
                &r.mesh,
                &parts,
                Some("torso"),
                ViewSet::Front,
                82,
                46,
            ));
        })
    });
    let j = job(&mut app, Resolution::default());
    g.bench_function("rebuild_export", |b| {
        b.iter(|| black_box(build(&j).expect("builds")))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
