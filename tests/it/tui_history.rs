//! One undo history for edits and the input commands (add part, key
//! section, prop), and paths stored relative to the document so a copied
//! document builds in its new place.

use super::tui::{built, key, screen, settle, to_row, typed};
use super::tui_commands::{command, tail_svg};
use crate::cli::{pdesculpt, tmpdir};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pdesculpt::character::doc::{CharacterDoc, ProfileInput};
use pdesculpt::character::Resolution;
use pdesculpt::mesh::Mesh;
use pdesculpt::tui::app::{App, Focus, Mode};
use pdesculpt::tui::autosave;
use pdesculpt::tui::commands::stored_path;
use std::path::Path;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn mesh(app: &App) -> Mesh {
    assert!(!app.stale, "rebuilt: {:?}", app.message);
    app.shown.as_ref().expect("built").mesh.clone()
}

/// The sidecar holds the document (both compared as read back from JSON).
fn autosaved(app: &App) {
    let side = CharacterDoc::load(&autosave::sidecar(&app.path)).expect("autosave");
    let text = serde_json::to_string_pretty(&app.doc).expect("serialises");
    let doc = CharacterDoc::parse(&text, Path::new("doc")).expect("parses");
    assert!(side == doc, "the autosave is not the document");
}

fn ok(app: &App) {
    assert_eq!(app.mode, Mode::Normal, "{:?}", app.message);
    assert!(
        app.message.as_ref().is_some_and(|m| !m.error),
        "{:?}",
        app.message
    );
}

#[test]
fn tui_undo_redo_steps_over_add_part_key_section_and_prop() {
    let mut app = built("hist");
    let dir = app.base.clone();
    // rebuilt from the stored parts (the first build derived them, and
    // JSON float parsing may round them)
    key(&mut app, KeyCode::Char('b'));
    let original = app.doc.clone();
    let original_mesh = mesh(&app);
    // an edit first: edits and commands share one history
    to_row(&mut app, "scale");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "1.1");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.doc.cursor(), 1, "{:?}", app.message);
    let edited = app.doc.clone();
    let edited_mesh = mesh(&app);
    app.focus = Focus::Tree;
    let svg = tail_svg(&dir);
    command(&mut app, 'a', &svg.display().to_string());
    ok(&app);
    command(&mut app, 'x', "1.0 0.12 0.09");
    ok(&app);
    command(
        &mut app,
        'p',
        &format!("{ROOT}/data/conv/blob.json ball 0.1 0.5 1.0 0.3"),
    );
    ok(&app);
    let result = app.doc.clone();
    let result_mesh = mesh(&app);
    assert_eq!(result.removed_parts().len(), 1);
    assert_eq!(
        result.inputs().sections.len(),
        original.inputs().sections.len() + 1
    );
    assert_eq!(result.props().len(), 1);
    autosaved(&app);
    for k in 0..3 {
        key(&mut app, KeyCode::Char('u'));
        ok(&app);
        autosaved(&app);
        assert!(!app.stale, "undo {k} rebuilt: {:?}", app.message);
    }
    assert!(screen(&app).contains("undo: add part 'tail'"));
    assert_eq!(
        app.doc, edited,
        "undo x3 gives back the document before the commands"
    );
    assert!(mesh(&app) == edited_mesh, "undo x3 gives back the preview");
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(app.doc.cursor(), 0);
    assert_eq!(
        app.doc.edits(),
        edited.edits(),
        "undo keeps the log for redo"
    );
    assert!(
        mesh(&app) == original_mesh,
        "undo x4 gives back the preview"
    );
    key(&mut app, KeyCode::Char('u'));
    assert!(app
        .message
        .as_ref()
        .is_some_and(|m| m.error && m.text == "nothing to undo"));
    for _ in 0..2 {
        let e = app.on_key(KeyEvent::new(KeyCode::Char('y'), KeyModifiers::CONTROL));
        settle(&mut app, e);
        ok(&app);
    }
    key(&mut app, KeyCode::Char('r'));
    key(&mut app, KeyCode::Char('r'));
    ok(&app);
    autosaved(&app);
    assert!(app.doc == result, "redo x4 gives back the result");
    assert!(mesh(&app) == result_mesh, "redo x4 gives back the preview");
    key(&mut app, KeyCode::Char('r'));
    assert!(app
        .message
        .as_ref()
        .is_some_and(|m| m.error && m.text == "nothing to redo"));
    // the log cursor does not step over a command
    app.focus = Focus::Log;
    app.log_sel = 0;
    key(&mut app, KeyCode::Enter);
    assert!(app.doc == result, "{:?}", app.message);
    assert!(screen(&app).contains("input command"));
    // a new command after an undo drops the redo tail
    key(&mut app, KeyCode::Char('u'));
    app.focus = Focus::Tree;
    command(
        &mut app,
        'p',
        &format!("{ROOT}/data/conv/blob.json other 0.1 -0.5 1.0 0.3"),
    );
    ok(&app);
    assert_eq!(app.doc.props().len(), 1);
    assert_eq!(app.doc.props()[0].name, "other");
    key(&mut app, KeyCode::Char('r'));
    assert!(app.message.as_ref().is_some_and(|m| m.error));
    key(&mut app, KeyCode::Char('u'));
    key(&mut app, KeyCode::Char('u'));
    key(&mut app, KeyCode::Char('u'));
    key(&mut app, KeyCode::Char('u'));
    // the original with the undone edit still in the log (redo-able)
    assert_eq!((app.doc.cursor(), app.doc.edits().len()), (0, 1));
    let mut d = app.doc.clone();
    d.drop_inactive_edits();
    assert!(d == original, "undo to the start gives back the original");
}

#[test]
fn tui_command_after_an_undone_edit_drops_the_inactive_edits() {
    let mut app = built("hist-tail");
    to_row(&mut app, "scale");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "1.1");
    key(&mut app, KeyCode::Enter);
    key(&mut app, KeyCode::Char('u'));
    assert_eq!((app.doc.edits().len(), app.doc.cursor()), (1, 0));
    app.focus = Focus::Tree;
    let sections = app.doc.inputs().sections.clone();
    command(&mut app, 'x', "1.0 0.12 0.09");
    ok(&app);
    assert_eq!((app.doc.edits().len(), app.doc.cursor()), (0, 0));
    autosaved(&app);
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(
        app.doc.inputs().sections,
        sections,
        "the key section is undone"
    );
    assert!(
        app.doc.edits().is_empty(),
        "the dropped edit does not come back"
    );
    key(&mut app, KeyCode::Char('u'));
    assert!(app
        .message
        .as_ref()
        .is_some_and(|m| m.text == "nothing to undo"));
}

/// Copies the regular files of `from` into `to` (one level).
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("creates");
    for e in std::fs::read_dir(from).expect("reads") {
        let e = e.expect("entry");
        if e.path().is_dir() {
            copy_dir(&e.path(), &to.join(e.file_name()));
        } else {
            std::fs::copy(e.path(), to.join(e.file_name())).expect("copies");
        }
    }
}

#[test]
fn tui_paths_below_the_document_are_stored_relative_and_a_copy_builds_elsewhere() {
    let mut app = built("rel");
    let dir = app.base.clone();
    let models = dir.join("models");
    std::fs::create_dir_all(&models).expect("creates");
    let svg = tail_svg(&models);
    std::fs::copy(
        format!("{ROOT}/data/conv/blob.json"),
        models.join("ball.json"),
    )
    .expect("copies");
    command(&mut app, 'a', &svg.display().to_string());
    ok(&app);
    command(
        &mut app,
        'p',
        &format!("{}/ball.json ball 0.1 0.5 1.0 0.3", models.display()),
    );
    ok(&app);
    // a file outside the document's directory stays absolute
    let blob = std::fs::canonicalize(format!("{ROOT}/data/conv/blob.json")).expect("exists");
    command(
        &mut app,
        'p',
        &format!("{} far 0.1 -0.5 1.0 0.3", blob.display()),
    );
    ok(&app);
    key(&mut app, KeyCode::Char('s'));
    let saved = CharacterDoc::load(&app.path).expect("saved");
    assert_eq!(
        saved.removed_parts()[0].front,
        ProfileInput::Path("models/tail.svg".into())
    );
    assert_eq!(saved.props()[0].model, "models/ball.json");
    assert_eq!(saved.props()[1].model, blob.display().to_string());
    assert_eq!(stored_path(&blob, &dir), blob.display().to_string());
    // the document and its files copied elsewhere, the original gone
    let there = tmpdir("tui-rel-copy").join("moved");
    let _ = std::fs::remove_dir_all(&there);
    copy_dir(&dir, &there);
    std::fs::remove_dir_all(models).expect("removes");
    let doc = there.join("char.json");
    let a = pdesculpt::pipeline::build_document(
        &CharacterDoc::load(&doc).expect("loads"),
        &there,
        Resolution::default(),
        false,
    )
    .expect("the copy builds in its new place");
    assert!(a.model.mesh.groups.iter().any(|g| g == "tail"));
    assert!(a.model.mesh.groups.iter().any(|g| g == "ball"));
    let glb = there.join("out.glb");
    let out = pdesculpt(&[
        "character",
        "build",
        doc.to_str().expect("utf-8"),
        "-o",
        glb.to_str().expect("utf-8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // and the original, without its files, names the missing one
    let out = pdesculpt(&[
        "character",
        "build",
        app.path.to_str().expect("utf-8"),
        "-o",
        glb.to_str().expect("utf-8"),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("tail.svg"));
}
