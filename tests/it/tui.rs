//! The terminal UI's state and screens, on ratatui's `TestBackend`: part
//! tree, parameter panel, an invalid value shown as an error and not
//! applied, the edit log with undo/redo, a panicking or failing rebuild
//! leaving the document as it was, autosave and recovery.

use crate::cli::tmpdir;
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use pdesculpt::character::doc::{CharacterDoc, ProfileInput};
use pdesculpt::character::Resolution;
use pdesculpt::tui::app::{App, Effect, Focus, Mode};
use pdesculpt::tui::autosave;
use pdesculpt::tui::term::{open, Options};
use pdesculpt::tui::view::{draw, PreviewCache};
use pdesculpt::tui::worker::{self, Job, Outcome, Task, Worker};
use ratatui::backend::TestBackend;
use ratatui::Terminal;
use std::path::PathBuf;
use std::time::Duration;

/// Coarse resolution: these tests look at the UI, not at the geometry.
pub(crate) const RES: Resolution = Resolution {
    rings_per_height: 24.0,
    transition_rows: 4,
};

fn options(name: &str) -> Options {
    Options::new(tmpdir(&format!("tui-{name}")).join("char.json"), "female").with_preview(RES)
}

pub(crate) fn job(app: &mut App) -> Job {
    Job {
        gen: app.start_job(false),
        doc: app.doc.clone(),
        base: app.base.clone(),
        res: RES,
        task: Task::Rebuild,
    }
}

/// Runs the effects synchronously (rebuilds on this thread).
pub(crate) fn settle(app: &mut App, effects: Vec<Effect>) {
    for e in effects {
        if let Effect::Check(edit) = e {
            let j = Job {
                gen: app.start_job(false),
                doc: app.doc.clone(),
                base: app.base.clone(),
                res: RES,
                task: Task::Check { edit: edit.clone() },
            };
            let result = worker::build(&j).map(Box::new);
            let more = app.on_outcome(Outcome::Checked {
                gen: j.gen,
                edit: Box::new(edit),
                result,
                elapsed: Duration::ZERO,
            });
            settle(app, more);
        } else if e == Effect::Rebuild {
            let j = job(app);
            let result = worker::build(&j).map(Box::new);
            let more = app.on_outcome(Outcome::Built {
                gen: j.gen,
                result,
                elapsed: Duration::ZERO,
            });
            settle(app, more);
        }
    }
}

/// The bundled female, opened at a fresh path and built once.
pub(crate) fn built(name: &str) -> App {
    let o = options(name);
    let _ = std::fs::remove_file(&o.path);
    let _ = autosave::remove(&o.path);
    let mut app = open(&o).expect("opens");
    settle(&mut app, vec![Effect::Rebuild]);
    assert!(app.shown.is_some(), "first build: {:?}", app.message);
    app
}

pub(crate) fn key(app: &mut App, c: KeyCode) {
    let e = app.on_key(KeyEvent::new(c, KeyModifiers::NONE));
    settle(app, e);
}

pub(crate) fn typed(app: &mut App, s: &str) {
    for c in s.chars() {
        key(app, KeyCode::Char(c));
    }
}

pub(crate) fn screen(app: &App) -> String {
    let mut t = Terminal::new(TestBackend::new(160, 48)).expect("terminal");
    let mut cache = PreviewCache::default();
    t.draw(|f| draw(f, app, &mut cache)).expect("draws");
    let buf = t.backend().buffer();
    let mut out = String::new();
    for y in 0..buf.area.height {
        for x in 0..buf.area.width {
            out.push_str(buf[(x, y)].symbol());
        }
        out.push('\n');
    }
    out
}

/// Moves the parameter selection to the row labelled `label`.
pub(crate) fn to_row(app: &mut App, label: &str) {
    app.focus = Focus::Params;
    let i = app
        .rows()
        .iter()
        .position(|r| r.label == label)
        .expect("row exists");
    app.param_sel = i;
}

#[test]
fn tui_screen_shows_part_tree_inputs_status_and_preview() {
    let app = built("tree");
    let s = screen(&app);
    for part in [
        "torso",
        "head",
        "arm_l",
        "arm_r",
        "leg_l",
        "leg_r",
        "shoulders",
        "hips",
    ] {
        assert!(s.contains(part), "{part} missing from the part tree:\n{s}");
    }
    assert!(s.contains("level    final"), "{s}");
    assert!(s.contains("✓ watertight"), "{s}");
    assert!(s.contains("front err"), "{s}");
    assert!(s.contains("Edit log (0 of 0 active)"), "{s}");
    // the preview is drawn with half blocks, and the first part is highlighted
    assert!(s.matches('▀').count() > 100, "{s}");
    assert!(s.contains("Parameters: torso"), "{s}");
}

#[test]
fn tui_invalid_value_is_shown_as_an_error_and_not_applied() {
    let mut app = built("invalid");
    let before = app.doc.clone();
    to_row(&mut app, "a");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "1x");
    let s = screen(&app);
    assert!(s.contains("✗ '1x' is not a number"), "{s}");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.doc, before, "an invalid value must not be applied");
    assert!(matches!(app.mode, Mode::Editing { .. }));
    // out of the documented range: the library's error, shown as typed
    key(&mut app, KeyCode::Backspace);
    key(&mut app, KeyCode::Backspace);
    typed(&mut app, "1e9");
    let s = screen(&app);
    assert!(s.contains("out of range"), "{s}");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.doc, before);
    // a scale factor of zero
    key(&mut app, KeyCode::Esc);
    to_row(&mut app, "scale");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "0 1");
    assert!(screen(&app).contains("sx = 0 is out of range"));
}

#[test]
fn tui_edit_undo_redo_through_the_log() {
    let mut app = built("log");
    to_row(&mut app, "scale");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "1.1 1.05");
    assert!(screen(&app).contains("✓ Enter applies"));
    key(&mut app, KeyCode::Enter);
    assert_eq!(
        (app.doc.edits().len(), app.doc.cursor()),
        (1, 1),
        "{:?}",
        app.message
    );
    let s = screen(&app);
    assert!(s.contains("Edit log (1 of 1 active)"), "{s}");
    assert!(!app.stale, "rebuilt after the edit");
    // the sidecar holds the edit
    // (parts go through JSON, whose float parsing may round: compare the log)
    let side = CharacterDoc::load(&autosave::sidecar(&app.path)).expect("autosave");
    assert_eq!((&side.edits(), side.cursor()), (&app.doc.edits(), 1));
    assert_eq!(side.parts().len(), app.doc.parts().len());
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(app.doc.cursor(), 0);
    assert!(screen(&app).contains("Edit log (0 of 1 active)"));
    let e = app.on_key(KeyEvent::new(KeyCode::Char('y'), KeyModifiers::CONTROL));
    settle(&mut app, e);
    assert_eq!(app.doc.cursor(), 1);
    let e = app.on_key(KeyEvent::new(KeyCode::Char('z'), KeyModifiers::CONTROL));
    settle(&mut app, e);
    assert_eq!(app.doc.cursor(), 0);
    key(&mut app, KeyCode::Char('r'));
    assert_eq!(app.doc.cursor(), 1);
    // quitting with unsaved changes asks; saving removes the sidecar
    key(&mut app, KeyCode::Char('q'));
    assert_eq!(app.mode, Mode::ConfirmQuit);
    assert!(screen(&app).contains("unsaved changes"));
    key(&mut app, KeyCode::Esc);
    key(&mut app, KeyCode::Char('s'));
    assert!(!app.dirty());
    assert!(!autosave::sidecar(&app.path).exists());
    let saved = CharacterDoc::load(&app.path).expect("saved");
    assert_eq!((&saved.edits(), saved.cursor()), (&app.doc.edits(), 1));
    assert_eq!(
        app.on_key(KeyEvent::new(KeyCode::Char('q'), KeyModifiers::NONE)),
        vec![Effect::Quit]
    );
}

#[test]
fn tui_panicking_rebuild_leaves_the_document_as_before_the_edit() {
    let mut app = built("panic");
    let good = app.doc.clone();
    to_row(&mut app, "scale");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "1.2");
    // the rebuild goes to a worker whose build panics
    let effects = app.on_key(KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE));
    // the edit is judged on the worker (built once with it): the document
    // has not changed yet
    assert!(
        matches!(effects.as_slice(), [Effect::Check(_)]),
        "{effects:?}"
    );
    assert_eq!(app.doc.edits().len(), 0);
    let w = Worker::with_build(Box::new(|_| panic!("injected failure")));
    let j = job(&mut app);
    assert!(w.send(j));
    let mut outcome = None;
    while let Some(o) = w.wait(Duration::from_secs(30)) {
        if !matches!(o, Outcome::Started { .. }) {
            outcome = Some(o);
            break;
        }
    }
    let o = outcome.expect("the worker reports");
    assert!(matches!(&o, Outcome::Panicked { message, .. } if message == "injected failure"));
    app.on_outcome(o);
    assert_eq!(app.doc, good, "back to the document before the edit");
    let s = screen(&app);
    assert!(s.contains("rebuild panicked: injected failure"), "{s}");
    // the worker survives its panic
    let j = job(&mut app);
    assert!(w.send(j));
    assert!(w.wait(Duration::from_secs(30)).is_some());
}

#[test]
fn tui_recovery_is_offered_for_a_newer_sidecar() {
    let mut app = built("recover");
    to_row(&mut app, "a");
    key(&mut app, KeyCode::Enter);
    typed(&mut app, "0.5");
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.doc.edits().len(), 1, "{:?}", app.message);
    let edited = app.doc.clone();
    // a new session at the same path: the document does not exist, the
    // sidecar does
    let o = Options::new(app.path.clone(), "female").with_preview(RES);
    let mut again = open(&o).expect("opens");
    // (the parts go through JSON: compare the log)
    assert!(
        matches!(&again.mode, Mode::Recovery(d) if d.edits() == edited.edits() && d.cursor() == 1)
    );
    assert!(screen(&again).contains("Recover?"));
    key(&mut again, KeyCode::Char('y'));
    assert_eq!(again.doc.edits(), edited.edits());
    assert!(again.dirty());
    // after a save nothing is offered
    key(&mut again, KeyCode::Char('s'));
    assert!(autosave::offer(&o.path).expect("reads").is_none());
}

#[test]
fn tui_help_lists_the_key_bindings() {
    let mut app = built("help");
    key(&mut app, KeyCode::Char('?'));
    let s = screen(&app);
    for (k, _) in pdesculpt::tui::keys::BINDINGS {
        assert!(s.contains(k), "{k} missing from help:\n{s}");
    }
    key(&mut app, KeyCode::Char('x'));
    assert_eq!(app.mode, Mode::Normal);
}

#[test]
fn tui_export_path_is_checked_before_any_work() {
    let mut app = built("export");
    key(&mut app, KeyCode::Char('e'));
    assert!(matches!(app.mode, Mode::Export { .. }));
    for _ in 0..200 {
        key(&mut app, KeyCode::Backspace);
    }
    let p: PathBuf = app.base.join("out.xyz");
    typed(&mut app, &p.display().to_string());
    let e = app.on_key(KeyEvent::new(KeyCode::Enter, KeyModifiers::NONE));
    assert!(e.is_empty());
    assert!(
        app.message.as_ref().is_some_and(|m| m.error),
        "{:?}",
        app.message
    );
}

/// A directory whose path is far longer than a screen line (CI checks out
/// in a longer directory than a developer does: no line may depend on it).
pub(crate) fn deep_dir(name: &str) -> PathBuf {
    let mut d = tmpdir(&format!("tui-{name}"));
    for i in 0..8 {
        d = d.join(format!("a_rather_long_directory_name_number_{i}"));
    }
    std::fs::create_dir_all(&d).expect("creates");
    assert!(d.display().to_string().chars().count() > 300);
    d
}

/// The screen's last line (the message line).
fn message_line(app: &App) -> String {
    screen(app).lines().last().unwrap_or_default().to_string()
}

#[test]
fn tui_every_line_keeps_its_point_under_a_long_path() {
    let dir = deep_dir("deep");
    let o = Options::new(dir.join("char.json"), "female").with_preview(RES);
    let mut app = open(&o).expect("opens");
    settle(&mut app, vec![Effect::Rebuild]);
    // the idle line: the document's name and the help key
    app.message = None;
    let m = message_line(&app);
    assert!(m.contains("char.json") && m.contains("? help"), "{m}");
    // saved: the file name stays
    key(&mut app, KeyCode::Char('s'));
    let m = message_line(&app);
    assert!(
        m.starts_with("saved …") && m.trim_end().ends_with("/char.json"),
        "{m}"
    );
    // the export prompt: the end of the typed path and the hint
    key(&mut app, KeyCode::Char('e'));
    let m = message_line(&app);
    assert!(m.contains("char.glb▏") && m.contains("Enter, Esc)"), "{m}");
    key(&mut app, KeyCode::Esc);
    // an export's outcome: where to and how long
    let gen = app.start_job(true);
    app.on_outcome(Outcome::Exported {
        gen,
        result: Ok(dir.join("char.glb")),
        elapsed: Duration::from_millis(42),
    });
    let m = message_line(&app);
    assert!(m.contains("/char.glb in 42 ms"), "{m}");
    // an input profile given by a long path: the panel keeps its lines
    let before = app.doc.clone();
    let mut inputs = before.inputs().clone();
    inputs.side = Some(ProfileInput::Path(
        dir.join("side.svg").display().to_string(),
    ));
    app.doc.restore_content(
        inputs,
        before.parts().to_vec(),
        before.transitions().to_vec(),
        before.removed_parts().to_vec(),
        before.props().to_vec(),
    );
    let s = screen(&app);
    assert!(s.contains("side.svg"), "{s}");
    for l in ["level    final", "sections torso", "template none"] {
        assert!(s.contains(l), "{l} pushed out of the inputs panel:\n{s}");
    }
    app.doc = before;
    // a prop whose model is outside the document's directory (absolute)
    let models = deep_dir("deep-models");
    let blob = models.join("ball.json");
    std::fs::copy(
        format!("{}/data/conv/blob.json", env!("CARGO_MANIFEST_DIR")),
        &blob,
    )
    .expect("copies");
    key(&mut app, KeyCode::Char('p'));
    typed(
        &mut app,
        &format!("{} ball 0.1 0.5 1.0 0.3", blob.display()),
    );
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.mode, Mode::Normal, "{:?}", app.message);
    let m = message_line(&app);
    assert!(
        m.starts_with("attached prop 'ball'") && m.contains("ball.json"),
        "{m}"
    );
    app.tree_sel = app
        .tree()
        .iter()
        .position(|t| t.name == "ball")
        .expect("in the tree");
    let s = screen(&app);
    assert!(s.contains("Parameters: ball"), "{s}");
    let row = s
        .lines()
        .find(|l| l.contains("model     "))
        .expect("model row");
    assert!(row.contains("/ball.json"), "{row}");
    // the recovery question names the sidecar and still asks
    let again = open(&o).expect("opens");
    assert!(matches!(again.mode, Mode::Recovery(_)));
    let s = screen(&again);
    for l in ["is newer than the document:", "y: recover them"] {
        assert!(s.contains(l), "{l}:\n{s}");
    }
}

#[test]
fn tui_kitty_protocol_sends_the_preview_as_png_and_removes_it_under_a_popup() {
    use pdesculpt::tui::kitty::{base64, clear, place, supported, CHUNK, IMAGE_ID};
    assert!(supported(Some("xterm-kitty"), None));
    assert!(supported(Some("xterm-256color"), Some("3")));
    assert!(!supported(Some("xterm-256color"), None));
    assert!(!supported(None, Some("")));
    for (raw, enc) in [
        ("", ""),
        ("f", "Zg=="),
        ("fo", "Zm8="),
        ("foo", "Zm9v"),
        ("foobar", "Zm9vYmFy"),
    ] {
        assert_eq!(base64(raw.as_bytes()), enc);
    }
    // chunks: at most CHUNK bytes each, all but the last marked m=1
    let bytes: Vec<u8> = (0..10_000u32).map(|i| (i * 7 % 251) as u8).collect();
    let seq = place(&bytes, 30, 0, 82, 46);
    let payloads: Vec<&str> = seq
        .split("\x1b_G")
        .skip(1)
        .filter(|c| !c.starts_with("a=d"))
        .collect();
    assert!(payloads.len() > 1);
    let mut data = String::new();
    for (i, p) in payloads.iter().enumerate() {
        let (head, rest) = p.split_once(';').expect("a payload");
        let chunk = rest.strip_suffix("\x1b\\").unwrap_or(rest);
        let chunk = chunk.split("\x1b\\").next().unwrap_or(chunk);
        assert!(chunk.len() <= CHUNK);
        let last = i + 1 == payloads.len();
        assert!(head.ends_with(if last { "m=0" } else { "m=1" }), "{head}");
        if i == 0 {
            assert!(
                head.contains("a=T,f=100") && head.contains("c=82,r=46"),
                "{head}"
            );
        }
        data.push_str(chunk);
    }
    assert_eq!(data, base64(&bytes));
    assert!(
        seq.starts_with("\x1b7\x1b[1;31H"),
        "the cursor goes to the preview"
    );
    // through the draw: a PNG once, nothing while unchanged, removed
    // under the help popup, sent again after it
    let mut app = built("kitty");
    let mut t = Terminal::new(TestBackend::new(160, 48)).expect("terminal");
    let mut cache = PreviewCache::with_kitty();
    t.draw(|f| draw(f, &app, &mut cache)).expect("draws");
    let first = cache.take_kitty().expect("the preview is sent");
    let start = first.find("m=1;").expect("a chunked PNG") + 4;
    assert!(
        first[start..].starts_with(&base64(b"\x89PNG")[..4]),
        "a PNG"
    );
    assert!(first.contains(&format!("i={IMAGE_ID}")));
    t.draw(|f| draw(f, &app, &mut cache)).expect("draws");
    assert!(cache.take_kitty().is_none(), "unchanged: nothing sent");
    key(&mut app, KeyCode::Char('?'));
    t.draw(|f| draw(f, &app, &mut cache)).expect("draws");
    assert_eq!(cache.take_kitty(), Some(clear()));
    key(&mut app, KeyCode::Char('x'));
    t.draw(|f| draw(f, &app, &mut cache)).expect("draws");
    assert!(cache.take_kitty().is_some(), "shown again");
    // without kitty nothing is sent
    let mut plain = PreviewCache::default();
    t.draw(|f| draw(f, &app, &mut plain)).expect("draws");
    assert!(plain.take_kitty().is_none());
}

/// `pdesculpt tui` with its output in a pipe (a script, CI) is a named
/// error, exit 1, and writes nothing: ratatui's `init` used to panic there
/// (no controlling terminal: "failed to initialize terminal") and left an
/// escape sequence on stdout.
#[test]
fn tui_without_a_terminal_is_a_named_error_not_a_panic() {
    let d = tmpdir("tui-no-terminal");
    let doc = d.join("char.json");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_pdesculpt"))
        .args(["tui", doc.to_str().expect("utf-8 path")])
        .stdin(std::process::Stdio::null())
        .output()
        .expect("the binary runs");
    crate::cli::assert_clear_error(&out, "the TUI needs a terminal");
    assert!(out.stdout.is_empty(), "wrote to stdout: {:?}", out.stdout);
    assert!(!doc.exists(), "created the document");
    let _ = std::fs::remove_dir_all(&d);
}
