//! Reading inputs safely and checking output paths before anything is
//! written.
//!
//! * [`read_input`] / [`read_input_text`]: a file the user named is opened
//!   without blocking (a FIFO opens at once instead of waiting for a
//!   writer), refused unless it is a regular file (a directory, FIFO,
//!   socket or device such as `/dev/zero` is named in the error) and read
//!   up to [`crate::limits::INPUT_BYTES`]; text is UTF-8 with an optional
//!   byte-order mark, which is dropped.
//! * [`write_target`]: where a write to a path lands: a symbolic link is
//!   followed to its target (also a dangling one), so a save through a link
//!   edits the file it points to.
//! * [`check_outputs`]: no output may be an input or another output
//!   (compared after following links and canonicalising the directory), and
//!   none may be a directory; called before any work is written.

use crate::mesh::MeshError;
use std::io::Read;
use std::path::{Path, PathBuf};

/// What kind of file system object `m` is, for messages.
fn kind(m: &std::fs::Metadata) -> &'static str {
    let t = m.file_type();
    if t.is_dir() {
        return "a directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
    }
    if t.is_symlink() {
        return "a symbolic link";
    }
    "not a regular file"
}

/// Reads the regular file `path` (`what` names it in errors, e.g. "SVG
/// drawing"): refuses directories, FIFOs, sockets and devices without
/// blocking on them, and files over [`crate::limits::INPUT_BYTES`].
pub fn read_input(path: &Path, what: &str) -> Result<Vec<u8>, MeshError> {
    let io = |source| MeshError::Io {
        path: path.display().to_string(),
        source,
    };
    let mut opts = std::fs::OpenOptions::new();
    opts.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // a FIFO opened for reading would block until a writer appears
        opts.custom_flags(libc::O_NONBLOCK);
    }
    let mut f = opts.open(path).map_err(io)?;
    let meta = f.metadata().map_err(io)?;
    if !meta.is_file() {
        return Err(MeshError::NotAFile {
            path: path.display().to_string(),
            what: what.to_string(),
            kind: kind(&meta),
        });
    }
    let limit = crate::limits::INPUT_BYTES.max;
    if meta.len() > limit {
        return Err(MeshError::InputTooLarge {
            path: path.display().to_string(),
            what: what.to_string(),
            bytes: meta.len(),
            limit,
        });
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    // a file growing while it is read stops at the limit too
    f.by_ref()
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(MeshError::InputTooLarge {
            path: path.display().to_string(),
            what: what.to_string(),
            bytes: bytes.len() as u64,
            limit,
        });
    }
    Ok(bytes)
}

/// [`read_input`] as UTF-8 text; a leading byte-order mark is dropped.
pub fn read_input_text(path: &Path, what: &str) -> Result<String, MeshError> {
    let bytes = read_input(path, what)?;
    let text = String::from_utf8(bytes).map_err(|e| {
        MeshError::Invalid(format!(
            "{}: the {what} is not UTF-8 text (invalid byte at offset {})",
            path.display(),
            e.utf8_error().valid_up_to()
        ))
    })?;
    Ok(strip_bom(&text).to_string())
}

/// `text` without a leading UTF-8 byte-order mark.
pub fn strip_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

/// Most symbolic links followed from one path (as the kernel's limit).
const MAX_LINKS: usize = 40;

/// The file a write to `path` replaces: symbolic links of the last
/// component followed (a dangling link gives the path it points to).
pub fn write_target(path: &Path) -> Result<PathBuf, MeshError> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p).map_err(|source| MeshError::Io {
                    path: p.display().to_string(),
                    source,
                })?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(MeshError::Invalid(format!(
        "{}: more than {MAX_LINKS} symbolic links to follow",
        path.display()
    )))
}

/// A path's identity for comparisons: device and inode when it exists,
/// else its canonical directory joined with its name.
#[derive(PartialEq, Eq, Debug)]
enum FileId {
    #[cfg(unix)]
    Inode(u64, u64),
    Path(PathBuf),
}

fn file_id(path: &Path) -> FileId {
    let target = write_target(path).unwrap_or_else(|_| path.to_path_buf());
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let Ok(m) = std::fs::metadata(&target) {
            return FileId::Inode(m.dev(), m.ino());
        }
    }
    let abs = std::path::absolute(&target).unwrap_or(target);
    let canonical = match (abs.parent(), abs.file_name()) {
        (Some(dir), Some(name)) => std::fs::canonicalize(dir)
            .map(|d| d.join(name))
            .unwrap_or_else(|_| abs.clone()),
        _ => abs.clone(),
    };
    FileId::Path(canonical)
}

/// Refuses, before anything is written: an output that is one of the
/// `inputs`, an output named twice, an output that is a directory. Each
/// entry is `(role, path)`, the role naming the flag in the message
/// (e.g. `("--save-doc", p)`).
pub fn check_outputs(inputs: &[(&str, &Path)], outputs: &[(&str, &Path)]) -> Result<(), MeshError> {
    for (role, out) in outputs {
        if write_target(out).is_ok_and(|t| t.is_dir()) {
            return Err(MeshError::Invalid(format!(
                "{role} {}: is a directory, not a file path",
                out.display()
            )));
        }
    }
    let ids: Vec<FileId> = outputs.iter().map(|(_, p)| file_id(p)).collect();
    for (i, (role, out)) in outputs.iter().enumerate() {
        for (in_role, input) in inputs {
            if file_id(input) == ids[i] {
                return Err(MeshError::Invalid(format!(
                    "{role} {} is the input {in_role} {}: it would be overwritten; choose another output path",
                    out.display(),
                    input.display()
                )));
            }
        }
        for (j, (other_role, other)) in outputs.iter().enumerate().take(i) {
            if ids[j] == ids[i] {
                return Err(MeshError::Invalid(format!(
                    "{role} {} and {other_role} {} are the same file: one would overwrite the other; give two paths",
                    out.display(),
                    other.display()
                )));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("pdesculpt-files-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).expect("scratch");
        d
    }

    #[test]
    fn bom_is_dropped_and_directories_refused() {
        let d = scratch("bom");
        let p = d.join("a.json");
        std::fs::write(&p, "\u{feff}{}").expect("write");
        assert_eq!(read_input_text(&p, "document").expect("read"), "{}");
        let e = read_input(&d, "document").expect_err("a directory");
        assert!(e.to_string().contains("a directory"), "{e}");
        let _ = std::fs::remove_dir_all(&d);
    }

    #[cfg(unix)]
    #[test]
    fn fifo_and_device_are_refused_without_blocking() {
        let d = scratch("fifo");
        let p = d.join("f.svg");
        let c = std::ffi::CString::new(p.to_str().expect("utf8")).expect("c");
        // SAFETY: a valid NUL-terminated path
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        let e = read_input(&p, "SVG drawing").expect_err("a FIFO");
        assert!(e.to_string().contains("FIFO"), "{e}");
        let e = read_input(Path::new("/dev/zero"), "SVG drawing").expect_err("a device");
        assert!(e.to_string().contains("a device"), "{e}");
        let _ = std::fs::remove_dir_all(&d);
    }

    #[cfg(unix)]
    #[test]
    fn outputs_equal_to_inputs_or_each_other_are_refused() {
        let d = scratch("outputs");
        let input = d.join("front.svg");
        std::fs::write(&input, "x").expect("write");
        let link = d.join("link.svg");
        std::os::unix::fs::symlink("front.svg", &link).expect("link");
        let dotted = d.join(".").join("front.svg");
        for out in [&input, &link, &dotted] {
            let e = check_outputs(&[("--front", &input)], &[("--save-doc", out)])
                .expect_err("output is the input");
            assert!(e.to_string().contains("is the input --front"), "{e}");
        }
        let a = d.join("new.obj");
        let b = d.join("sub/../new.obj");
        std::fs::create_dir_all(d.join("sub")).expect("dir");
        let e = check_outputs(&[], &[("-o", &a), ("--save-doc", &b)]).expect_err("same");
        assert!(e.to_string().contains("are the same file"), "{e}");
        assert!(check_outputs(&[("--front", &input)], &[("-o", &a)]).is_ok());
        let _ = std::fs::remove_dir_all(&d);
    }
}
