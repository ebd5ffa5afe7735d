//! Atomic writes: write a temporary file `.NAME.tmp-PID` beside the target,
//! sync it, rename it over the target.
//!
//! * The temporary path is registered while it exists; on SIGINT, SIGTERM or
//!   SIGHUP (unix) the handler unlinks every registered path, then re-raises
//!   the signal with its default action (so the exit status is unchanged).
//!   The handler only loads atomics and calls `unlink`, `signal` and `raise`
//!   (async-signal-safe).
//! * Stale temporaries of the same target left by a process that no longer
//!   exists (killed with SIGKILL, power loss) are removed by the next write
//!   of that target.
//! * [`same_file`] / [`refuse_overwriting_input`]: commands with an input and
//!   an output refuse an output that is the input.

use crate::mesh::MeshError;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Writes `bytes` to a temporary file beside `path`, syncs it and renames it
/// over `path`. Creates missing parent directories. A symbolic link is
/// followed: its target is replaced and the link kept
/// ([`super::write_target`]); an existing file keeps its permissions (and,
/// best effort, its owner).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), MeshError> {
    write_all_atomic(&[(path, bytes)])
}

/// Several files written as one step: every temporary file is written and
/// synced first, and only when all of them are complete are they renamed
/// over their targets, so a failure (a full disk, a missing permission)
/// leaves every target as it was. Each file as in [`write_atomic`].
pub fn write_all_atomic(files: &[(&Path, &[u8])]) -> Result<(), MeshError> {
    let mut staged: Vec<Staged> = Vec::with_capacity(files.len());
    for (path, bytes) in files {
        match stage(path, bytes) {
            Ok(s) => staged.push(s),
            Err(e) => {
                for s in &staged {
                    let _ = std::fs::remove_file(&s.tmp);
                }
                return Err(e);
            }
        }
    }
    let mut first_err = None;
    for s in &staged {
        if let Err(source) = std::fs::rename(&s.tmp, &s.target) {
            let _ = std::fs::remove_file(&s.tmp);
            first_err.get_or_insert(MeshError::Io {
                path: s.path.display().to_string(),
                source,
            });
        }
    }
    drop(staged);
    first_err.map_or(Ok(()), Err)
}

/// A complete temporary file waiting to be renamed over its target.
struct Staged {
    path: PathBuf,
    target: PathBuf,
    tmp: PathBuf,
    _guard: signals::Guard,
}

fn stage(path: &Path, bytes: &[u8]) -> Result<Staged, MeshError> {
    let err = |source| MeshError::Io {
        path: path.display().to_string(),
        source,
    };
    let target = super::write_target(path)?;
    if target.is_dir() {
        return Err(MeshError::Invalid(format!(
            "{}: is a directory, not a file path",
            path.display()
        )));
    }
    if let Some(dir) = target.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(err)?;
    }
    let file_name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    sweep_stale(&target, &file_name);
    let tmp = target.with_file_name(format!(".{file_name}.tmp-{}", std::process::id()));
    let guard = signals::register(&tmp);
    let previous = std::fs::metadata(&target).ok();
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        if let Some(m) = &previous {
            keep_mode_and_owner(&f, m)?;
        }
        f.write_all(bytes)?;
        f.sync_all()
    })();
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(err(e));
    }
    Ok(Staged {
        path: path.to_path_buf(),
        target,
        tmp,
        _guard: guard,
    })
}

/// Gives the new file the replaced file's permissions, and its owner when
/// the process may (best effort: a user cannot give a file away).
fn keep_mode_and_owner(f: &std::fs::File, previous: &std::fs::Metadata) -> std::io::Result<()> {
    f.set_permissions(previous.permissions())?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let _ = std::os::unix::fs::fchown(f, Some(previous.uid()), Some(previous.gid()));
    }
    Ok(())
}

/// Removes `.NAME.tmp-PID` files beside `path` whose PID is not a live
/// process (best effort: errors are ignored).
fn sweep_stale(path: &Path, file_name: &str) {
    let dir = match path.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(d) => d.to_path_buf(),
        None => PathBuf::from("."),
    };
    let prefix = format!(".{file_name}.tmp-");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return;
    };
    for e in entries.flatten() {
        let name = e.file_name();
        let Some(pid) = name
            .to_str()
            .and_then(|n| n.strip_prefix(&prefix))
            .and_then(|p| p.parse::<u32>().ok())
        else {
            continue;
        };
        if pid != std::process::id() && !signals::alive(pid) {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

/// Whether `a` and `b` name the same file (same device and inode when both
/// exist; otherwise the same absolute path).
pub fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return x.dev() == y.dev() && x.ino() == y.ino();
        }
    }
    let abs = |p: &Path| {
        std::fs::canonicalize(p).unwrap_or_else(|_| {
            std::env::current_dir()
                .map(|d| d.join(p))
                .unwrap_or_else(|_| p.to_path_buf())
        })
    };
    abs(a) == abs(b)
}

/// Refuses an `output` that is one of `inputs` (it would be overwritten
/// before, or while, being read).
pub fn refuse_overwriting_input(inputs: &[&Path], output: &Path) -> Result<(), MeshError> {
    for input in inputs {
        if same_file(input, output) {
            return Err(MeshError::Invalid(format!(
                "the output {} is the input file {}; choose another output path",
                output.display(),
                input.display()
            )));
        }
    }
    Ok(())
}

#[cfg(unix)]
mod signals {
    use std::ffi::CString;
    use std::os::unix::ffi::OsStrExt;
    use std::path::Path;
    use std::sync::atomic::{AtomicPtr, Ordering};
    use std::sync::Once;

    const SLOTS: usize = 64;
    static TEMP: [AtomicPtr<libc::c_char>; SLOTS] =
        [const { AtomicPtr::new(std::ptr::null_mut()) }; SLOTS];
    static INSTALL: Once = Once::new();

    extern "C" fn on_signal(sig: libc::c_int) {
        for slot in &TEMP {
            let p = slot.load(Ordering::SeqCst);
            if !p.is_null() {
                // SAFETY: p is a NUL-terminated string leaked by `register`
                // and freed only after its slot is cleared.
                unsafe { libc::unlink(p) };
            }
        }
        // SAFETY: restoring the default action and re-raising is
        // async-signal-safe.
        unsafe {
            libc::signal(sig, libc::SIG_DFL);
            libc::raise(sig);
        }
    }

    fn install() {
        INSTALL.call_once(|| {
            for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
                let handler = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
                // SAFETY: installs a handler that only uses async-signal-safe
                // calls; an ignored signal (nohup) stays ignored.
                unsafe {
                    let old = libc::signal(sig, handler);
                    if old == libc::SIG_IGN {
                        libc::signal(sig, libc::SIG_IGN);
                    }
                }
            }
        });
    }

    /// Unregisters its path when dropped.
    pub struct Guard(Option<(usize, *mut libc::c_char)>);

    impl Drop for Guard {
        fn drop(&mut self) {
            if let Some((i, p)) = self.0.take() {
                TEMP[i].store(std::ptr::null_mut(), Ordering::SeqCst);
                // SAFETY: p came from CString::into_raw in `register`.
                drop(unsafe { CString::from_raw(p) });
            }
        }
    }

    /// Registers `path` for removal on a terminating signal (silently not
    /// registered when all slots are in use).
    pub fn register(path: &Path) -> Guard {
        install();
        let Ok(c) = CString::new(path.as_os_str().as_bytes()) else {
            return Guard(None);
        };
        let p = c.into_raw();
        for (i, slot) in TEMP.iter().enumerate() {
            if slot
                .compare_exchange(std::ptr::null_mut(), p, Ordering::SeqCst, Ordering::SeqCst)
                .is_ok()
            {
                return Guard(Some((i, p)));
            }
        }
        // SAFETY: p came from into_raw just above and was not stored.
        drop(unsafe { CString::from_raw(p) });
        Guard(None)
    }

    /// Whether a process `pid` exists.
    pub fn alive(pid: u32) -> bool {
        let Ok(pid) = libc::pid_t::try_from(pid) else {
            return false;
        };
        // SAFETY: signal 0 only checks for existence and permission.
        let r = unsafe { libc::kill(pid, 0) };
        r == 0 || std::io::Error::last_os_error().raw_os_error() != Some(libc::ESRCH)
    }
}

#[cfg(not(unix))]
mod signals {
    pub struct Guard;
    pub fn register(_: &std::path::Path) -> Guard {
        Guard
    }
    pub fn alive(_: u32) -> bool {
        true
    }
}
