//! The one build (issue 29): what one edit costs, each beside the path it
//! replaced, rebuilt here from the same library pieces in the same run.
//!
//! * `tui_edit_to_preview`: the TUI's edit (a new GEC scale of the left
//!   arm): `push_checked` on the worker, the document with the edit built
//!   once at the preview resolution with the worker's part cache (only the
//!   edited part is solved), then the preview render. Baseline
//!   `tui_edit_to_preview_before`: `push_edit` on the UI thread (the log's
//!   spec edits replayed, the edited part solved without the cache), the
//!   app's part tree refreshed (the spec edits replayed again), the
//!   worker's pre-warm (replayed again, parts fetched from the cache) and
//!   its build (replayed again), then the render.
//! * `character_edit`: `pdesculpt character edit` in process: the document
//!   read, the edit pushed by building the document with it once (default
//!   resolution, no cache: a fresh process), that build's document saved.
//!   Baseline `character_edit_before`: read, `push_edit` (replay, the
//!   edited part solved), a whole build whose result is thrown away, save.

use criterion::{criterion_group, criterion_main, Criterion};
use pdesculpt::character::assembly::PartCache;
use pdesculpt::character::doc::{CharacterDoc, Level};
use pdesculpt::character::log::{Edit, SectionTransform};
use pdesculpt::character::Resolution;
use pdesculpt::pipeline::{build, build_document, push_checked, BuildOptions};
use pdesculpt::sketch::check::bundled;
use pdesculpt::tui::preview::{self, ViewSet};
use pdesculpt::tui::term::{preview_resolution, PREVIEW_RINGS};
use std::hint::black_box;
use std::path::Path;

fn edit(i: u64) -> Edit {
    Edit::GecTransform {
        part: "arm_l".into(),
        section: None,
        transform: SectionTransform::Scale {
            sx: 1.0 + 1e-4 * (i % 2000) as f64,
            sy: 1.0,
        },
    }
}

fn render(mesh: &pdesculpt::mesh::Mesh, parts: &[String]) {
    black_box(preview::render(
        mesh,
        parts,
        Some("arm_l"),
        ViewSet::Front,
        82,
        46,
    ));
}

fn bench(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("pdesculpt-bench-pipeline-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let doc = bundled("female", Level::Final).expect("bundled");
    let doc = build_document(&doc, &dir, Resolution::default(), true)
        .expect("builds")
        .doc;
    let path = dir.join("char.json");
    doc.save(&path).expect("saves");
    let parts: Vec<String> = doc.parts().iter().map(|p| p.name.clone()).collect();
    let preview_res = preview_resolution(PREVIEW_RINGS);
    let mut g = c.benchmark_group("pipeline");
    g.sample_size(10);
    let opts = BuildOptions::new(&dir).res(preview_res);
    let mut cache = PartCache::default();
    build(&doc, &opts, Some(&mut cache)).expect("builds");
    let mut k = 0u64;
    g.bench_function("tui_edit_to_preview", |b| {
        b.iter(|| {
            k += 1;
            let mut d = doc.clone();
            let built = push_checked(&mut d, edit(k), &opts, Some(&mut cache)).expect("valid");
            render(&built.model.mesh, &parts);
        })
    });
    g.bench_function("tui_edit_to_preview_before", |b| {
        b.iter(|| {
            k += 1;
            let mut d = doc.clone();
            // the UI thread: push_edit (replay, part solved) and the tree
            d.push_edit(edit(k)).expect("valid");
            black_box(pdesculpt::edit::apply_to_parts(d.parts(), d.active_edits()).expect("ok"));
            // the worker: the document as read back, pre-warm, build
            let text = serde_json::to_string_pretty(&d).expect("serialises");
            let d = CharacterDoc::parse(&text, Path::new("document")).expect("parses");
            let edited = pdesculpt::edit::apply_to_parts(d.parts(), d.active_edits()).expect("ok");
            for p in &edited {
                cache.get(p).expect("solves");
            }
            let built = build(&d, &opts, Some(&mut cache)).expect("builds");
            render(&built.model.mesh, &parts);
        })
    });
    let mut j = 0u64;
    g.bench_function("character_edit", |b| {
        b.iter(|| {
            j += 1;
            let mut d = CharacterDoc::load(&path).expect("loads");
            let built =
                push_checked(&mut d, edit(j), &BuildOptions::new(&dir), None).expect("valid");
            built.doc.save(&dir.join("out.json")).expect("saves");
        })
    });
    g.bench_function("character_edit_before", |b| {
        b.iter(|| {
            j += 1;
            let mut d = CharacterDoc::load(&path).expect("loads");
            d.push_edit(edit(j)).expect("valid");
            black_box(build_document(&d, &dir, Resolution::default(), false).expect("builds"));
            d.save(&dir.join("out.json")).expect("saves");
        })
    });
    g.finish();
    std::fs::remove_dir_all(&dir).ok();
}

criterion_group!(benches, bench);
criterion_main!(benches);
