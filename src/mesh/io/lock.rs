//! An advisory lock for read-modify-write of a file that is saved by
//! rename ([`super::write_atomic`]).
//!
//! [`FileLock::acquire`] opens the file (after following symbolic links,
//! as saves do) and takes an exclusive `flock` on its inode. A save
//! replaces the inode, so a second process that was waiting on the old
//! inode wakes holding a lock on a file nobody reads any more: after
//! taking the lock it checks that the path still names the locked inode
//! and otherwise starts again on the new one. Two processes that both
//! lock, read, change and save the same document therefore run one after
//! the other, and the second reads the first one's result: no change is
//! lost. Waiting is bounded ([`FileLock::acquire`]'s `wait`); the error then
//! says that another process holds the file.
//!
//! Only processes that lock are ordered; a writer that does not lock is
//! detected by [`FileLock::unchanged`] (the path no longer names the
//! locked inode). On platforms without `flock` the lock is a no-op and
//! only that check remains.

use crate::mesh::MeshError;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// How often a busy lock is tried again.
const RETRY: Duration = Duration::from_millis(25);

/// An exclusive advisory lock on a file, released when dropped.
#[derive(Debug)]
pub struct FileLock {
    file: std::fs::File,
    target: PathBuf,
}

impl FileLock {
    /// Locks the file `path` names (symbolic links followed), waiting at
    /// most `wait` for another holder.
    pub fn acquire(path: &Path, wait: Duration) -> Result<FileLock, MeshError> {
        let target = super::write_target(path)?;
        let start = Instant::now();
        loop {
            let file = std::fs::File::open(&target).map_err(|source| MeshError::Io {
                path: path.display().to_string(),
                source,
            })?;
            if !file.metadata().is_ok_and(|m| m.is_file()) {
                return Err(MeshError::Invalid(format!(
                    "{}: not a regular file",
                    path.display()
                )));
            }
            if try_lock(&file) {
                let lock = FileLock {
                    file,
                    target: target.clone(),
                };
                if lock.unchanged() {
                    return Ok(lock);
                }
                // saved (replaced) while we waited: lock the new file
                continue;
            }
            if start.elapsed() >= wait {
                return Err(MeshError::Invalid(format!(
                    "{}: another process (a `character edit`, `undo`, `redo` or the TUI) has held this document for {:.0} s; try again when it has finished",
                    path.display(),
                    wait.as_secs_f64()
                )));
            }
            std::thread::sleep(RETRY);
        }
    }

    /// Whether the path still names the locked file (nobody replaced it
    /// since the lock was taken).
    pub fn unchanged(&self) -> bool {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            match (self.file.metadata(), std::fs::metadata(&self.target)) {
                (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
                _ => false,
            }
        }
        #[cfg(not(unix))]
        {
            true
        }
    }

    /// The locked file's path (links followed).
    pub fn target(&self) -> &Path {
        &self.target
    }
}

#[cfg(unix)]
fn try_lock(f: &std::fs::File) -> bool {
    use std::os::unix::io::AsRawFd;
    // SAFETY: flock on a file descriptor this process owns.
    unsafe { libc::flock(f.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) == 0 }
}

#[cfg(not(unix))]
fn try_lock(_: &std::fs::File) -> bool {
    true
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn a_second_lock_waits_and_times_out_and_a_save_is_followed() {
        let d = std::env::temp_dir().join(format!("pdesculpt-lock-{}", std::process::id()));
        std::fs::create_dir_all(&d).expect("dir");
        let p = d.join("doc.json");
        std::fs::write(&p, "1").expect("write");
        let a = FileLock::acquire(&p, Duration::ZERO).expect("first lock");
        let e = FileLock::acquire(&p, Duration::ZERO).expect_err("held");
        assert!(e.to_string().contains("another process"), "{e}");
        // a save replaces the inode: the held lock sees it
        crate::mesh::io::write_atomic(&p, b"2").expect("save");
        assert!(!a.unchanged());
        // the old inode is still locked, the new one is free
        let b = FileLock::acquire(&p, Duration::ZERO).expect("lock on the new file");
        assert!(b.unchanged());
        drop((a, b));
        let _ = std::fs::remove_dir_all(&d);
    }
}
