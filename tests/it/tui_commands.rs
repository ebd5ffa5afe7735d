//! The TUI's commands that change the document's inputs: add a part from
//! an SVG profile, add a key section, attach a prop from a conv model file.
//! Every bad input is refused with its error on screen and the document
//! unchanged; a document with a prop builds the same through the TUI's
//! export and through `character build`.

use super::tui::{built, key, screen, to_row, typed};
use crate::cli::pdesculpt;
use crossterm::event::KeyCode;
use pdesculpt::character::doc::{CharacterDoc, SectionShape};
use pdesculpt::character::props::{place, PropSpec, PROP_RESOLUTION};
use pdesculpt::character::Resolution;
use pdesculpt::conv::model::{Model, Polygonizer};
use pdesculpt::tui::app::{App, ItemKind, Mode};
use pdesculpt::tui::commands::{complete, PromptKind};
use pdesculpt::tui::worker::{self, Job, Task};
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// A tail: an ellipse 0.4 x 0.06 turned 30 degrees beside the legs, as an
/// SVG path in model units (front view: SVG y is minus model y).
pub(crate) fn tail_svg(dir: &Path) -> PathBuf {
    let (s, c) = 30f64.to_radians().sin_cos();
    let d: Vec<String> = (0..200)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 200.0;
            let (x, y) = (0.2 * t.cos(), 0.03 * t.sin());
            let (mx, my) = (0.45 + c * x - s * y, 0.6 + s * x + c * y);
            format!("{} {mx:.6},{:.6}", if i == 0 { "M" } else { "L" }, -my)
        })
        .collect();
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="100cm" height="100cm" viewBox="0 -1 1 1"><path id="outline" d="{} Z"/></svg>"#,
        d.join(" ")
    );
    let p = dir.join("tail.svg");
    std::fs::write(&p, svg).expect("writes");
    p
}

/// Opens the prompt with key `k`, types `text`, presses Enter.
pub(crate) fn command(app: &mut App, k: char, text: &str) {
    key(app, KeyCode::Char(k));
    assert!(matches!(app.mode, Mode::Prompt { .. }), "{:?}", app.mode);
    typed(app, text);
    key(app, KeyCode::Enter);
}

/// The command is refused: the prompt stays open with an error containing
/// `needle`, the document is `before`.
fn refused(app: &mut App, before: &CharacterDoc, needle: &str) {
    match &app.mode {
        Mode::Prompt { error: Some(e), .. } => {
            assert!(e.contains(needle), "error {e:?} lacks {needle:?}")
        }
        m => panic!("expected a refused prompt, got {m:?} ({:?})", app.message),
    }
    assert!(screen(app).contains(needle), "{}", screen(app));
    assert_eq!(&app.doc, before, "a refused command changed the document");
    key(app, KeyCode::Esc);
    assert_eq!(app.mode, Mode::Normal);
}

#[test]
fn tui_add_part_from_svg_refuses_bad_input_and_builds_a_separate_component() {
    let mut app = built("cmd-part");
    let dir = app.base.clone();
    let svg = tail_svg(&dir);
    let before = app.doc.clone();
    command(&mut app, 'a', &format!("{}/missing.svg", dir.display()));
    refused(&mut app, &before, "No such file");
    std::fs::write(dir.join("bad.svg"), "not an svg").expect("writes");
    command(&mut app, 'a', &format!("{}/bad.svg", dir.display()));
    refused(&mut app, &before, "bad.svg");
    command(&mut app, 'a', &format!("{} torso", svg.display()));
    refused(&mut app, &before, "already used");
    command(&mut app, 'a', &format!("{}/tail.obj", dir.display()));
    refused(&mut app, &before, "expected a .svg or .json file");
    // Tab completes the path
    key(&mut app, KeyCode::Char('a'));
    typed(&mut app, &format!("{}/ta", dir.display()));
    key(&mut app, KeyCode::Tab);
    let want = format!("{}/tail.svg", dir.display());
    assert!(
        matches!(&app.mode, Mode::Prompt { kind: PromptKind::AddPart, buffer, .. } if *buffer == want),
        "{:?}",
        app.mode
    );
    assert_eq!(
        complete(&format!("x {}/ta", dir.display())),
        format!("x {want}")
    );
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.mode, Mode::Normal, "{:?}", app.message);
    assert!(!app.stale, "rebuilt: {:?}", app.message);
    assert!(app.doc.removed_parts().iter().any(|r| r.name == "tail"));
    assert!(app.doc.parts().iter().any(|p| p.name == "tail"));
    let shown = app.shown.as_ref().expect("built");
    assert!(shown.mesh.groups.iter().any(|g| g == "tail"));
    assert!(shown
        .report
        .removed
        .iter()
        .any(|r| r.name == "tail" && !r.stitched));
    assert!(shown.report.not_built.is_empty());
    let t = &shown.report.topology;
    assert!(t.watertight && t.manifold && t.oriented, "{t:?}");
    assert!(app
        .tree()
        .iter()
        .any(|i| i.name == "tail" && i.kind == ItemKind::Removed));
    assert!(screen(&app).contains("tail"));
    // the saved document builds the same part through `character build`
    key(&mut app, KeyCode::Char('s'));
    let saved = CharacterDoc::load(&app.path).expect("saved");
    assert_eq!(saved.removed_parts().len(), 1);
}

#[test]
fn tui_key_section_as_ellipse_or_curve_file_refuses_bad_input() {
    let mut app = built("cmd-key");
    assert_eq!(app.selected().map(|t| t.name), Some("torso".to_string()));
    let before = app.doc.clone();
    command(&mut app, 'x', "abc 0.1 0.1");
    refused(&mut app, &before, "height 'abc' is not a number");
    command(&mut app, 'x', "1.2 -0.1 0.1");
    refused(&mut app, &before, "semi-axes must be positive");
    command(&mut app, 'x', "9 0.1 0.1");
    refused(&mut app, &before, "outside the part");
    command(&mut app, 'x', "1.2 5 0.1");
    refused(&mut app, &before, "outside the part");
    command(&mut app, 'x', "1.2");
    refused(&mut app, &before, "expected Y A B");
    command(&mut app, 'x', &format!("1.0 {ROOT}/data/conv/blob.json"));
    refused(&mut app, &before, "expected [[x, z]");
    // an ellipse
    command(&mut app, 'x', "1.0 0.12 0.09");
    assert_eq!(app.mode, Mode::Normal, "{:?}", app.message);
    assert!(!app.stale, "rebuilt: {:?}", app.message);
    assert_eq!(
        app.doc.inputs().sections.len(),
        before.inputs().sections.len() + 1
    );
    let torso = |d: &CharacterDoc| d.parts()[0].clone();
    let changed: Vec<usize> = (0..torso(&before).sections.len())
        .filter(|&j| torso(&before).sections[j] != torso(&app.doc).sections[j])
        .collect();
    assert!(!changed.is_empty());
    let j = changed[0];
    let sec = &torso(&app.doc).sections[j];
    assert!(matches!(sec.shape, SectionShape::Gec { .. }));
    assert_eq!(sec.centre[1], 1.0);
    // a curve from the bundled sections file (its torso section nearest y)
    let again = app.doc.clone();
    command(
        &mut app,
        'x',
        &format!("1.15 {ROOT}/data/sketch/female_sections.json"),
    );
    assert_eq!(app.mode, Mode::Normal, "{:?}", app.message);
    assert_ne!(app.doc, again);
    let t = &app.shown.as_ref().expect("built").report.topology;
    assert!(t.watertight, "{t:?}");
    // a transition selected: not a part
    app.tree_sel = app
        .tree()
        .iter()
        .position(|i| i.kind == ItemKind::Transition)
        .expect("a transition");
    let before = app.doc.clone();
    command(&mut app, 'x', "1.0 0.1 0.1");
    refused(&mut app, &before, "is not a part");
}

fn export(app: &App, path: &Path) {
    let j = Job {
        gen: 0,
        doc: app.doc.clone(),
        base: app.base.clone(),
        res: Resolution::default(),
        task: Task::Export {
            path: path.to_path_buf(),
        },
    };
    let r = worker::build(&j).expect("builds");
    worker::write_export(&r, path).expect("writes");
}

#[test]
fn tui_prop_builds_as_its_own_component_equal_to_character_build() {
    let mut app = built("cmd-prop");
    let blob = format!("{ROOT}/data/conv/blob.json");
    let before = app.doc.clone();
    let missing = format!("{}/nothing.json", app.base.display());
    command(&mut app, 'p', &missing);
    refused(&mut app, &before, "No such file");
    // a JSON file that is not a conv model, deep enough that the prompt
    // line cannot hold both the path and the error (CI checks out in a
    // longer directory than a developer does): the error stays on screen
    let deep = app
        .base
        .join("a_directory_with_a_rather_long_name_for_this_test/and_another_one_below_it");
    std::fs::create_dir_all(&deep).expect("creates");
    let not_conv = deep.join("female_sections.json");
    std::fs::copy(
        format!("{ROOT}/data/sketch/female_sections.json"),
        &not_conv,
    )
    .expect("copies");
    command(&mut app, 'p', &not_conv.display().to_string());
    refused(&mut app, &before, "not a conv model file");
    command(&mut app, 'p', &format!("{blob} ball 0"));
    refused(&mut app, &before, "scale = 0 is out of range");
    command(&mut app, 'p', &format!("{blob} ball 1 1 2"));
    refused(&mut app, &before, "expected MODEL.json");
    command(&mut app, 'p', &format!("{blob} torso"));
    refused(&mut app, &before, "already used");
    command(&mut app, 'p', &format!("{blob} ball 0.1 0.5 1.0 0.3"));
    assert_eq!(app.mode, Mode::Normal, "{:?}", app.message);
    assert!(!app.stale, "rebuilt: {:?}", app.message);
    let shown = app.shown.as_ref().expect("built");
    assert_eq!(shown.report.props.len(), 1);
    assert!(!shown.report.props[0].stitched);
    assert!(shown.mesh.groups.iter().any(|g| g == "ball"));
    assert!(app
        .tree()
        .iter()
        .any(|i| i.name == "ball" && i.kind == ItemKind::Prop));
    let s = screen(&app);
    assert!(s.contains("prop ball"), "{s}");
    key(&mut app, KeyCode::Char('s'));
    // the TUI's export and `character build` of the saved document agree
    let dir = app.base.clone();
    // one file name in two directories: the model is named after the file
    for sub in ["tui", "cli"] {
        std::fs::create_dir_all(dir.join(sub)).expect("dir");
    }
    let tui_glb = dir.join("tui").join("model.glb");
    export(&app, &tui_glb);
    let cli_glb = dir.join("cli").join("model.glb");
    let out = pdesculpt(&[
        "character",
        "build",
        app.path.to_str().expect("utf-8"),
        "-o",
        cli_glb.to_str().expect("utf-8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let a = std::fs::read(&tui_glb).expect("tui export");
    let b = std::fs::read(&cli_glb).expect("cli build");
    assert!(a == b, "the TUI's GLB differs from `character build`");
    // the prop is the conv model built afresh (no cache), placed: the same
    // vertices, bit for bit
    let saved = CharacterDoc::load(&app.path).expect("saved");
    let b = pdesculpt::pipeline::build_document(&saved, &dir, Resolution::default(), false)
        .expect("builds");
    let text = std::fs::read_to_string(&blob).expect("reads");
    let m = Model::from_json(&text).expect("model");
    let fresh = m
        .build()
        .expect("conv builds")
        .polygonize(
            PROP_RESOLUTION,
            m.options.threshold,
            Polygonizer::MarchingTetrahedra,
        )
        .expect("polygonises");
    let spec: &PropSpec = &saved.props()[0];
    let placed = place(fresh, spec);
    let g = b
        .model
        .mesh
        .groups
        .iter()
        .position(|g| g == "ball")
        .expect("group") as u32;
    let tris: Vec<[u32; 3]> = b
        .model
        .mesh
        .triangles
        .iter()
        .zip(&b.model.mesh.tri_group)
        .filter(|(_, &tg)| tg == g)
        .map(|(t, _)| *t)
        .collect();
    assert_eq!(tris.len(), placed.triangles.len());
    let first = tris.iter().flatten().min().copied().expect("vertices") as usize;
    for (t, q) in tris.iter().zip(&placed.triangles) {
        for k in 0..3 {
            assert_eq!(
                b.model.mesh.positions[t[k] as usize], placed.positions[q[k] as usize],
                "prop vertex"
            );
            assert_eq!(t[k] as usize - first, q[k] as usize);
        }
    }
    // the report leaves the prop out of the body's profile error
    let without = {
        let mut d = saved.clone();
        d.remove_prop("ball").expect("the prop");
        assert!(d.props().is_empty(), "the ball was the only prop");
        pdesculpt::pipeline::build_document(&d, &dir, Resolution::default(), false).expect("builds")
    };
    assert_eq!(
        b.report.profile_error[0].max_rel,
        without.report.profile_error[0].max_rel
    );
}

#[test]
fn documents_without_props_load_and_save_without_the_field() {
    let app = built("cmd-old");
    let text = serde_json::to_string(&app.doc).expect("serialises");
    assert!(
        !text.contains("\"props\""),
        "an empty props list is not written"
    );
    let d = CharacterDoc::parse(&text, Path::new("old.json")).expect("an old document loads");
    assert!(d.props().is_empty());
    // unknown fields in a prop are refused
    let mut v: serde_json::Value = serde_json::from_str(&text).expect("json");
    v["props"] = serde_json::json!([{"name": "b", "model": "m.json", "colour": 1}]);
    let e = CharacterDoc::parse(&v.to_string(), Path::new("x.json")).expect_err("refused");
    assert!(e.to_string().contains("colour"), "{e}");
    // a prop named like a part
    v["props"] = serde_json::json!([{"name": "torso", "model": "m.json"}]);
    let e = CharacterDoc::parse(&v.to_string(), Path::new("x.json")).expect_err("refused");
    assert!(e.to_string().contains("used twice"), "{e}");
}

/// Types `value` into the row labelled `row` and presses Enter.
fn form(app: &mut App, row: &str, value: &str) {
    to_row(app, row);
    key(app, KeyCode::Enter);
    typed(app, value);
    key(app, KeyCode::Enter);
}

#[test]
fn tui_force_boundary_plate_forms_check_numbers_and_refuse_bad_edits() {
    let mut app = built("cmd-forms");
    let torso = app.doc.parts()[0].clone();
    let len = torso.sections.last().expect("sections").u;
    let before = app.doc.clone();
    // checked as typed: shown on screen, Enter does nothing
    to_row(&mut app, "force");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "0.3 0.1 0 0 1");
    assert!(screen(&app).contains("u[1] > u[0]"), "{}", screen(&app));
    key(&mut app, KeyCode::Enter);
    assert!(matches!(app.mode, Mode::Editing { .. }));
    assert_eq!(app.doc, before);
    key(&mut app, KeyCode::Esc);
    form(&mut app, "force", &format!("0 {} 0 0 1", 2.0 * len));
    assert!(matches!(app.mode, Mode::Editing { .. }));
    assert!(
        screen(&app).contains("not inside the part"),
        "{}",
        screen(&app)
    );
    key(&mut app, KeyCode::Esc);
    form(&mut app, "boundary", "middle 0 0 1");
    assert!(
        screen(&app).contains("'start' or 'end'"),
        "{}",
        screen(&app)
    );
    key(&mut app, KeyCode::Esc);
    form(&mut app, "plate", "0 1 0 -0.1 0 0 0.01");
    assert!(screen(&app).contains("radius = -0.1"), "{}", screen(&app));
    key(&mut app, KeyCode::Esc);
    assert_eq!(app.doc, before);
    // parsed, but refused when pushed (a region with no vertex of the part):
    // the document is unchanged and the reason shown
    form(&mut app, "plate", "5 5 5 0.1 0 0 0.01");
    assert_eq!(app.mode, Mode::Normal);
    assert_eq!(app.doc, before);
    let m = app.message.clone().expect("a message");
    assert!(
        m.error && m.text.contains("farther than the radius"),
        "{m:?}"
    );
    // valid edits go through push_checked and land in the log
    form(
        &mut app,
        "force",
        &format!("{} {} 0 0 0.5", 0.2 * len, 0.8 * len),
    );
    assert_eq!(app.doc.edits().len(), 1, "{:?}", app.message);
    form(&mut app, "boundary", "start 0 0 0.05");
    assert_eq!(app.doc.edits().len(), 2, "{:?}", app.message);
    let c = torso.sections[torso.sections.len() / 2].centre;
    form(
        &mut app,
        "plate",
        &format!("{} {} {} 0.12 0 0 0.01", c[0], c[1], c[2] + 0.1),
    );
    assert_eq!(app.doc.edits().len(), 3, "{:?}", app.message);
    let ops: Vec<&str> = app.doc.edits().iter().map(|e| e.op()).collect();
    assert_eq!(ops, ["force", "boundary", "plate"]);
    assert!(!app.stale);
    let t = &app.shown.as_ref().expect("built").report.topology;
    assert!(t.watertight && t.manifold, "{t:?}");
    assert!(screen(&app).contains("Edit log (3 of 3 active)"));
}

#[test]
fn tui_cancelled_build_stops_between_parts_and_leaves_the_document() {
    use pdesculpt::character::assembly::PartCache;
    use std::cell::Cell;
    let mut app = built("cmd-cancel");
    let j = Job {
        gen: 1,
        doc: app.doc.clone(),
        base: app.base.clone(),
        res: Resolution::default(),
        task: Task::Export {
            path: app.base.join("never.glb"),
        },
    };
    // cancelled after the third question: two parts solved, then stopped
    let asked = Cell::new(0);
    let mut cache = PartCache::default();
    let r = worker::build_cancellable(&j, Some(&mut cache), &|| {
        asked.set(asked.get() + 1);
        asked.get() > 3
    });
    assert_eq!(r.err().as_deref(), Some(worker::CANCELLED));
    assert_eq!(cache.solved, 2, "stopped between parts");
    assert!(app.doc.parts().len() > 2);
    // not cancelled: the same call builds (and finds the two parts cached)
    let r = worker::build_cancellable(&j, Some(&mut cache), &|| false);
    assert!(r.is_ok());
    assert_eq!(cache.solved, app.doc.parts().len());
    // through the app and the real worker: Esc while exporting cancels it,
    // nothing is written and the document is unchanged
    let before = app.doc.clone();
    let w = pdesculpt::tui::worker::Worker::spawn();
    key(&mut app, KeyCode::Char('e'));
    key(&mut app, KeyCode::Enter);
    assert!(app.running.is_none(), "the test runs effects itself");
    let out = app.base.join("cancelled.glb");
    let gen = app.start_job(true);
    w.cancel(gen);
    assert!(w.send(Job {
        gen,
        doc: app.doc.clone(),
        base: app.base.clone(),
        res: Resolution::default(),
        task: Task::Export { path: out.clone() },
    }));
    let effects = app.on_key(crossterm::event::KeyEvent::new(
        KeyCode::Esc,
        crossterm::event::KeyModifiers::NONE,
    ));
    assert_eq!(effects, vec![pdesculpt::tui::app::Effect::Cancel]);
    loop {
        let o = w
            .wait(std::time::Duration::from_secs(60))
            .expect("the worker reports");
        if let pdesculpt::tui::worker::Outcome::Exported { result, .. } = o {
            assert_eq!(result.err().as_deref(), Some(worker::CANCELLED));
            break;
        }
    }
    assert!(!out.exists(), "a cancelled export wrote its file");
    assert_eq!(app.doc, before);
    assert!(screen(&app).contains("cancelled the running job"));
}

/// How long a cancel takes after Esc, in steps: the build asks before it
/// starts, before each part's solve and each prop, and after the model is
/// built. Raised before question `k`, it stops at question `k` with every
/// part before it solved and none after: between two questions lies at
/// most one part's solve, or (after the last part) the transitions and the
/// mesh assembly, which are not interruptible.
#[test]
fn tui_cancel_stops_at_the_next_question_at_most_one_part_solve_later() {
    use pdesculpt::character::assembly::PartCache;
    use std::cell::Cell;
    let app = built("cmd-cancel-steps");
    let n = app.doc.parts().len();
    assert!(app.doc.props().is_empty());
    let j = Job {
        gen: 1,
        doc: app.doc.clone(),
        base: app.base.clone(),
        res: super::tui::RES,
        task: Task::Rebuild,
    };
    // questions: 1 before the build, 2..=n+1 before each part, n+2 after
    for k in 1..=n + 2 {
        let asked = Cell::new(0);
        let mut cache = PartCache::default();
        let r = worker::build_cancellable(&j, Some(&mut cache), &|| {
            asked.set(asked.get() + 1);
            asked.get() >= k
        });
        assert_eq!(r.err().as_deref(), Some(worker::CANCELLED), "k = {k}");
        assert_eq!(
            asked.get(),
            k,
            "stopped at the first question after the cancel"
        );
        assert_eq!(cache.solved, k.saturating_sub(2).min(n), "k = {k}");
    }
    // not cancelled: n + 2 questions, every part solved once
    let asked = Cell::new(0);
    let mut cache = PartCache::default();
    let r = worker::build_cancellable(&j, Some(&mut cache), &|| {
        asked.set(asked.get() + 1);
        false
    });
    assert!(r.is_ok(), "{:?}", r.err());
    assert_eq!((asked.get(), cache.solved), (n + 2, n));
}
