//! Issue 35, files: concurrent `character edit` runs lose no edit, saves go
//! through symbolic links and keep permissions, no output may be an input
//! or another output (checked before anything is written), documents are
//! JSON, the TUI creates nothing before its first save, and document paths
//! naming a FIFO are refused without blocking.

use crate::cli::{assert_clear_error, pdesculpt, tmpdir};
use pdesculpt::character::doc::CharacterDoc;
use std::path::{Path, PathBuf};
use std::process::Command;

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/sketch/");

fn s(p: &Path) -> &str {
    p.to_str().expect("utf8")
}

/// A built male document `doc.json` in a fresh directory.
fn doc_in(name: &str) -> (PathBuf, PathBuf) {
    let d = tmpdir(&format!("harden-{name}"));
    let doc = d.join("doc.json");
    let out = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        &format!("{DATA}male_front.svg"),
        "--side",
        &format!("{DATA}male_side.svg"),
        "-o",
        s(&d.join("base.obj")),
        "--save-doc",
        s(&doc),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (d, doc)
}

fn op(d: &Path, name: &str, json: &str) -> PathBuf {
    let p = d.join(name);
    std::fs::write(&p, json).expect("op");
    p
}

const TORSO: &str = r#"{"op": "shape_parameter", "part": "torso", "a": 0.3}"#;
const HEAD: &str = r#"{"op": "shape_parameter", "part": "head", "a": 0.2}"#;

#[test]
fn concurrent_character_edits_lose_no_edit() {
    let (d, doc) = doc_in("concurrent");
    let (a, b) = (op(&d, "a.json", TORSO), op(&d, "b.json", HEAD));
    let clean = std::fs::read(&doc).expect("doc");
    for trial in 0..3 {
        std::fs::write(&doc, &clean).expect("reset");
        let kids: Vec<_> = [&a, &b]
            .into_iter()
            .map(|o| {
                Command::new(env!("CARGO_BIN_EXE_pdesculpt"))
                    .args(["character", "edit", s(&doc), "--op", s(o)])
                    .spawn()
                    .expect("spawn")
            })
            .collect();
        for mut k in kids {
            assert!(k.wait().expect("wait").success(), "trial {trial}");
        }
        let after = CharacterDoc::load(&doc).expect("doc");
        assert_eq!(after.edits().len(), 2, "trial {trial}: both edits kept");
        assert_eq!(after.cursor(), 2);
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[cfg(unix)]
#[test]
fn an_edit_through_a_symlink_edits_the_target_and_keeps_its_mode() {
    use std::os::unix::fs::PermissionsExt;
    let (d, doc) = doc_in("symlink");
    let real = d.join("real.json");
    std::fs::rename(&doc, &real).expect("move");
    std::os::unix::fs::symlink("real.json", &doc).expect("link");
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o600)).expect("chmod");
    let out = pdesculpt(&[
        "character",
        "edit",
        s(&doc),
        "--op",
        s(&op(&d, "a.json", TORSO)),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::symlink_metadata(&doc)
        .expect("link")
        .file_type()
        .is_symlink());
    assert_eq!(CharacterDoc::load(&real).expect("target").edits().len(), 1);
    let mode = std::fs::metadata(&real).expect("meta").permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
    let _ = std::fs::remove_dir_all(&d);
}

/// Runs `args`; expects a clear error naming `needle`, and every file of
/// `keep` unchanged and every path of `absent` not created.
fn refused(args: &[&str], needle: &str, keep: &[&Path], absent: &[&Path]) {
    let before: Vec<Vec<u8>> = keep
        .iter()
        .map(|p| std::fs::read(p).expect("input"))
        .collect();
    let out = pdesculpt(args);
    assert_clear_error(&out, needle);
    for (p, b) in keep.iter().zip(&before) {
        assert_eq!(
            &std::fs::read(p).expect("kept"),
            b,
            "{} changed",
            p.display()
        );
    }
    for p in absent {
        assert!(!p.exists(), "{} was written", p.display());
    }
}

#[test]
fn no_output_may_overwrite_an_input_or_another_output() {
    let d = tmpdir("harden-outputs");
    let front = d.join("F.svg");
    std::fs::copy(format!("{DATA}male_front.svg"), &front).expect("copy");
    let sections = d.join("S.json");
    std::fs::copy(format!("{DATA}male_sections.json"), &sections).expect("copy");
    let o = d.join("o.obj");
    let side = format!("{DATA}male_side.svg");
    refused(
        &[
            "sketch",
            "build",
            "--front",
            s(&front),
            "-o",
            s(&o),
            "--save-doc",
            s(&front),
        ],
        "a character document is JSON",
        &[&front],
        &[&o],
    );
    let front_json = d.join("F.json");
    std::fs::write(&front_json, "[[0, 0], [1, 0], [0.5, 1]]").expect("write");
    refused(
        &[
            "sketch",
            "build",
            "--front",
            s(&front_json),
            "-o",
            s(&o),
            "--save-doc",
            s(&front_json),
        ],
        "is the input --front",
        &[&front_json],
        &[&o],
    );
    refused(
        &[
            "sketch",
            "build",
            "--front",
            s(&front),
            "--side",
            &side,
            "--sections",
            s(&sections),
            "-o",
            s(&o),
            "--save-doc",
            s(&sections),
        ],
        "is the input --sections",
        &[&sections],
        &[&o],
    );
    let x = d.join("x.json");
    refused(
        &[
            "sketch",
            "build",
            "--front",
            s(&front),
            "-o",
            s(&d.join("x.obj")),
            "--save-doc",
            s(&d.join("sub/../x.obj")),
        ],
        "a character document is JSON",
        &[],
        &[&d.join("x.obj")],
    );
    // an output that cannot be written: nothing else is written either
    let file = d.join("file.txt");
    std::fs::write(&file, "x").expect("write");
    let out = pdesculpt(&[
        "sketch",
        "build",
        "--front",
        s(&front),
        "-o",
        s(&file.join("x.obj")),
        "--save-doc",
        s(&x),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(!x.exists(), "--save-doc written although -o failed");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn template_and_tbsm_outputs_are_checked_before_work() {
    let d = tmpdir("harden-template");
    let t = d.join("T.obj");
    std::fs::write(
        &t,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .expect("write");
    refused(
        &[
            "template",
            "fit",
            "--template",
            s(&t),
            "--front",
            &format!("{DATA}male_front.svg"),
            "-o",
            s(&t),
        ],
        "is the input --template",
        &[&t],
        &[],
    );
    let (dd, doc) = doc_in("tbsm");
    let x = dd.join("x.obj");
    refused(
        &[
            "template",
            "tbsm",
            "replace",
            s(&doc),
            "--part",
            "leg_l",
            "-o",
            s(&x),
        ],
        "a character document is JSON",
        &[&doc],
        &[&x],
    );
    let y = dd.join("y.obj");
    refused(
        &[
            "character",
            "build",
            s(&doc),
            "-o",
            s(&y),
            "--save-doc",
            s(&dd.join("y.obj")),
        ],
        "a character document is JSON",
        &[&doc],
        &[&y],
    );
    let _ = std::fs::remove_dir_all(&d);
    let _ = std::fs::remove_dir_all(&dd);
}

#[cfg(unix)]
#[test]
fn a_document_path_naming_a_fifo_is_refused_without_blocking() {
    let (d, doc) = doc_in("fifo");
    let fifo = d.join("fifo.svg");
    let c = std::ffi::CString::new(s(&fifo)).expect("c");
    // SAFETY: a valid NUL-terminated path
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&doc).expect("doc")).expect("json");
    v["inputs"]["front"] = serde_json::json!({"path": "fifo.svg"});
    std::fs::write(&doc, v.to_string()).expect("write");
    let o = d.join("o.obj");
    refused(
        &["character", "build", s(&doc), "-o", s(&o)],
        "a FIFO",
        &[&doc],
        &[&o],
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn the_tui_creates_nothing_before_its_first_save() {
    use crate::tui::{key, settle, RES};
    use crossterm::event::KeyCode;
    use pdesculpt::tui::app::Effect;
    use pdesculpt::tui::term::{open, Options};
    let d = tmpdir("harden-tui");
    let dir = d.join("nodir").join("sub");
    let o = Options::new(dir.join("x.json"), "female").with_preview(RES);
    let mut app = open(&o).expect("opens");
    settle(&mut app, vec![Effect::Rebuild]);
    key(&mut app, KeyCode::Char('q'));
    assert!(!d.join("nodir").exists(), "created before any save");
    let _ = std::fs::remove_dir_all(&d);
}
