//! Output paths checked before any work, files written together, and the
//! document lock of the commands that change a document in place.
//!
//! Every command names its inputs and outputs to [`check`] before it
//! computes anything: an output that is an input (after following links),
//! two outputs that are one file, or an output that is a directory are
//! refused with nothing written. A command with several outputs writes
//! them with `mesh::io::write_all_atomic`: all complete, or none replaced.

use pdesculpt::character::doc::CharacterDoc;
use pdesculpt::mesh::io;
use std::path::Path;
use std::time::Duration;

/// How long `character edit/undo/redo` wait for another process editing
/// the same document (each edit holds it for one build, about a second).
pub const LOCK_WAIT: Duration = Duration::from_secs(120);

/// Refuses outputs that are inputs or each other (see the module docs).
pub fn check(inputs: &[(&str, &Path)], outputs: &[(&str, &Path)]) -> anyhow::Result<()> {
    io::check_outputs(inputs, outputs)?;
    Ok(())
}

/// Refuses `path` (the output of option `role`) unless it ends in `.ext`
/// (any case); `what` says what the file holds.
fn require_extension(role: &str, path: &Path, ext: &str, what: &str) -> anyhow::Result<()> {
    let got = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    if !got.eq_ignore_ascii_case(ext) {
        anyhow::bail!(
            "{role} {}: {what}; give a path ending in .{ext}",
            path.display()
        );
    }
    Ok(())
}

/// A character document is written as JSON: refuses another extension
/// (`--save-doc x.obj` would put JSON into a mesh file name).
pub fn doc_output(role: &str, path: &Path) -> anyhow::Result<()> {
    require_extension(role, path, "json", "a character document is JSON")
}

/// An overlay (`--overlay`) is SVG: refuses another extension.
pub fn svg_output(role: &str, path: &Path) -> anyhow::Result<()> {
    require_extension(role, path, "svg", "the overlay is an SVG picture")
}

/// Writes the mesh (format by extension) and, when given, the document and
/// the overlay picture, as one step: every file complete, or none replaced.
pub fn write_mesh_and_doc(
    mesh: &pdesculpt::mesh::Mesh,
    output: &Path,
    layout: io::Layout,
    doc: Option<(&CharacterDoc, &Path)>,
    overlay: Option<(&Path, String)>,
) -> anyhow::Result<()> {
    let scene = io::Scene::single(&io::model_name(output), mesh.clone());
    let mesh_bytes = io::encode_scene(&scene, io::Format::from_path(output)?, layout)?;
    let doc_bytes = doc.map(|(d, _)| d.to_bytes()).transpose()?;
    let mut files: Vec<(&Path, &[u8])> = vec![(output, &mesh_bytes)];
    if let (Some((_, p)), Some(b)) = (doc, &doc_bytes) {
        files.push((p, b));
    }
    if let Some((p, svg)) = &overlay {
        files.push((p, svg.as_bytes()));
    }
    io::write_all_atomic(&files)?;
    for (p, _) in &files[1..] {
        eprintln!("wrote {}", p.display());
    }
    Ok(())
}

/// Saves `d` to `path` while `lock` is held, unless another program
/// replaced the file since the lock was taken (then nothing is written).
pub fn save_locked(d: &CharacterDoc, path: &Path, lock: &io::FileLock) -> anyhow::Result<()> {
    if !lock.unchanged() {
        anyhow::bail!(
            "{}: the document was replaced by another program while this command ran; nothing written: run it again",
            path.display()
        );
    }
    d.save(path)?;
    Ok(())
}
