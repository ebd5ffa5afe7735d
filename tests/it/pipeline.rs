//! The one build (issue 29): a document with edits and a prop builds to
//! the same bytes through the library, the TUI's worker and an editing
//! session, and the CLI builds the saved document to the same vertices; a
//! checked push builds once and keeps its build's document.

use pdesculpt::character::doc::{CharacterDoc, Level};
use pdesculpt::character::log::{Edit, SectionTransform};
use pdesculpt::character::props::PropSpec;
use pdesculpt::character::Resolution;
use pdesculpt::mesh::io;
use pdesculpt::pipeline::{build, push_checked, BuildError, BuildOptions, Session};
use pdesculpt::sketch::check::bundled;
use pdesculpt::tui::worker::{self, Job, Task};
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The bundled female with its parts stored, one edit of her torso and a
/// conv prop, saved in a fresh directory (the prop's model beside it).
fn props_doc(name: &str) -> (CharacterDoc, PathBuf) {
    let dir =
        std::env::temp_dir().join(format!("pdesculpt-pipeline-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::copy(format!("{ROOT}/data/conv/blob.json"), dir.join("blob.json")).expect("copies");
    let doc = bundled("female", Level::Intermediate).expect("bundled");
    let derived = pdesculpt::pipeline::build_document(&doc, &dir, Resolution::default(), true)
        .expect("derives");
    let mut doc = derived.doc;
    doc.push_edit(Edit::GecTransform {
        part: "torso".into(),
        section: None,
        transform: SectionTransform::Scale { sx: 1.05, sy: 0.97 },
    })
    .expect("a valid edit");
    doc.push_prop(PropSpec {
        name: "ball".into(),
        model: "blob.json".into(),
        translate: [0.1, 0.5, 0.3],
        scale: 0.05,
    });
    doc.save(&dir.join("doc.json")).expect("saves");
    (doc, dir)
}

/// The mesh as OBJ bytes (one model of a fixed name: a file's name would
/// name the model, `_path` is where it would be written).
fn obj_bytes(mesh: &pdesculpt::mesh::Mesh, _path: &Path) -> Vec<u8> {
    io::encode(mesh, io::Format::Obj).expect("encodes")
}

#[test]
fn a_document_with_props_builds_to_the_same_bytes_everywhere() {
    let (doc, dir) = props_doc("bytes");
    let library = build(&doc, &BuildOptions::new(&dir), None).expect("builds");
    assert!(library.model.mesh.groups.iter().any(|g| g == "ball"));
    let lib = obj_bytes(&library.model.mesh, &dir.join("library.obj"));
    // the TUI's worker (the document as read back from disk)
    let job = Job {
        gen: 1,
        doc: doc.clone(),
        base: dir.clone(),
        res: Resolution::default(),
        task: Task::Rebuild,
    };
    let tui = worker::build(&job).expect("the worker builds");
    let tui = obj_bytes(&tui.mesh, &dir.join("tui.obj"));
    // an editing session (its model used to leave the props out)
    let mut s = Session::new(doc, dir.clone(), Resolution::default());
    let session = obj_bytes(&s.model().expect("builds").mesh, &dir.join("session.obj"));
    std::fs::remove_dir_all(&dir).ok();
    assert!(lib == tui, "the TUI's mesh differs from the library's");
    assert!(
        lib == session,
        "the session's mesh differs from the library's"
    );
}

/// The CLI's `character build` of the saved document builds the same
/// vertices as the library in this process. It failed while serde_json
/// parsed floats without `float_roundtrip` (a saved document read back
/// differed in the last bit of some numbers); the message names the first
/// vertex that differs.
#[test]
fn the_cli_builds_a_document_with_props_as_the_library_does() {
    let (doc, dir) = props_doc("cli");
    let library = build(&doc, &BuildOptions::new(&dir), None).expect("builds");
    let out = dir.join("cli.obj");
    let run = super::cli::pdesculpt(&[
        "character",
        "build",
        &dir.join("doc.json").display().to_string(),
        "-o",
        &out.display().to_string(),
        "--single-mesh",
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let cli = io::read(&out).expect("reads the CLI's mesh");
    let lib = io::read(&{
        let p = dir.join("library.obj");
        io::write(&library.model.mesh, &p).expect("writes");
        p
    })
    .expect("reads");
    std::fs::remove_dir_all(&dir).ok();
    let first = lib
        .positions
        .iter()
        .zip(&cli.positions)
        .position(|(a, b)| a != b);
    assert!(
        lib.positions.len() == cli.positions.len() && first.is_none(),
        "{} vertices from the library, {} from the CLI; first difference at {first:?}",
        lib.positions.len(),
        cli.positions.len()
    );
}

#[test]
fn a_checked_push_builds_once_and_keeps_the_edit() {
    let (doc, dir) = props_doc("push");
    let e = Edit::ShapeParameter {
        part: "arm_l".into(),
        a: 1.5,
    };
    // the cancel hook counts the build's questions: one build is one
    // question before it, one per part, one per prop, one at its end
    let asked = std::sync::atomic::AtomicUsize::new(0);
    let hook = || {
        asked.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        false
    };
    let mut d = doc.clone();
    let opts = BuildOptions::new(&dir).cancel(&hook);
    let built = push_checked(&mut d, e.clone(), &opts, None).expect("a valid edit");
    let questions = asked.load(std::sync::atomic::Ordering::SeqCst);
    assert_eq!(questions, doc.parts().len() + doc.props().len() + 2);
    assert_eq!(d.edits().len(), doc.edits().len() + 1);
    assert_eq!(built.doc, d, "the build's document is the one kept");
    // refused: the document is unchanged and the edit's own error named
    let mut d2 = doc.clone();
    let bad = Edit::GecTransform {
        part: "nobody".into(),
        section: None,
        transform: SectionTransform::Rotate { angle: 0.1 },
    };
    let err = push_checked(&mut d2, bad, &BuildOptions::new(&dir), None).expect_err("refused");
    assert!(matches!(err, BuildError::Edit(_)), "{err}");
    assert!(err.to_string().contains("unknown part 'nobody'"), "{err}");
    assert_eq!(d2, doc);
    // cancelled before anything: the document is unchanged
    let stop = || true;
    let mut d3 = doc.clone();
    let err = push_checked(&mut d3, e, &BuildOptions::new(&dir).cancel(&stop), None)
        .expect_err("cancelled");
    assert!(matches!(err, BuildError::Cancelled));
    assert_eq!(d3, doc);
    std::fs::remove_dir_all(&dir).ok();
}
