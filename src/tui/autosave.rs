//! Never lose work: the autosave sidecar `CHAR.json.autosave`.
//!
//! After every change the TUI writes the whole document to the sidecar
//! (temporary file, then rename: `mesh::io::write_atomic`), so a crash or a
//! SIGKILL loses at most the edit being typed. On start, a sidecar that is
//! newer than the document (or whose document does not exist yet) and whose
//! content differs from it is offered for recovery. Saving the document or
//! discarding the changes on quit removes the sidecar.

use crate::character::doc::{CharacterDoc, DocError};
use std::path::{Path, PathBuf};

/// The sidecar of a document path: the same path with `.autosave` appended.
pub fn sidecar(path: &Path) -> PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(".autosave");
    PathBuf::from(s)
}

/// How long a save waits for a `character edit` of the same document.
const SAVE_LOCK_WAIT: std::time::Duration = std::time::Duration::from_secs(5);

/// Saves `doc` to `path` unless the file changed since the session read or
/// saved it (`saved`): the file is locked as `character edit` locks it and
/// compared with `saved`; when another program edited it meanwhile,
/// saving would lose that edit, so nothing is written (the changes stay in
/// the autosave).
pub fn save_checked(
    doc: &CharacterDoc,
    path: &Path,
    saved: Option<&CharacterDoc>,
) -> Result<(), DocError> {
    if !path.exists() {
        return doc.save(path);
    }
    let _lock = crate::mesh::io::FileLock::acquire(path, SAVE_LOCK_WAIT)?;
    let on_disk = CharacterDoc::load(path).ok();
    if on_disk.is_none() || on_disk.as_ref() != saved {
        return Err(DocError::Invalid(format!(
            "save refused: {} was changed by another program since it was opened; your changes are kept in the autosave (quit, then reopen to recover them onto the new file)",
            path.display()
        )));
    }
    doc.save(path)
}

/// Writes `doc` to the sidecar of `path` atomically.
pub fn write(doc: &CharacterDoc, path: &Path) -> Result<(), DocError> {
    doc.save(&sidecar(path))
}

/// Removes the sidecar (missing is fine).
pub fn remove(path: &Path) -> Result<(), DocError> {
    match std::fs::remove_file(sidecar(path)) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(DocError::Io {
            path: sidecar(path),
            source: e,
        }),
    }
}

/// A recovery offer: the sidecar's document.
#[derive(Clone, Debug)]
pub struct Recovery {
    pub doc: CharacterDoc,
    pub sidecar: PathBuf,
}

/// The recovery to offer for `path`, if any: the sidecar exists, is newer
/// than the document (or the document is missing) and holds a different
/// document. A sidecar that does not parse is an error (it names the file),
/// so the user learns about it instead of losing it silently.
pub fn offer(path: &Path) -> Result<Option<Recovery>, DocError> {
    let side = sidecar(path);
    let Ok(side_meta) = std::fs::metadata(&side) else {
        return Ok(None);
    };
    let on_disk = match std::fs::metadata(path) {
        Ok(m) => {
            let newer = match (side_meta.modified(), m.modified()) {
                (Ok(a), Ok(b)) => a >= b,
                _ => true,
            };
            if !newer {
                return Ok(None);
            }
            Some(CharacterDoc::load(path)?)
        }
        Err(_) => None,
    };
    let doc = CharacterDoc::load(&side)?;
    if on_disk.as_ref() == Some(&doc) {
        return Ok(None);
    }
    Ok(Some(Recovery { doc, sidecar: side }))
}
