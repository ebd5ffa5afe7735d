//! Rebuilds and exports off the UI thread.
//!
//! One worker thread receives [`Job`]s over a channel and sends back
//! [`Outcome`]s. Jobs are numbered (`gen`); when several rebuilds are queued
//! only the newest runs (the others are stale). Cancelling
//! ([`Worker::cancel`]) marks every job up to a number as abandoned: the
//! running build (the one `pipeline::build`, with the cancel hook) checks
//! the mark before it starts, between the solves of its parts (they are
//! solved one by one into the part cache before the model is assembled),
//! between its props, and after the model is built (before an export
//! writes anything), and stops there with the error [`CANCELLED`]; the app
//! drops the result and the document stays as it was. A checked edit
//! ([`Task::Check`]) is pushed by `pipeline::push_checked`: the document
//! with the edit built once, with the same cache and hook. What is not interruptible: one part's solve, the transitions and
//! the mesh assembly (`character::assembly::build_model_with`), one prop's conv
//! build, the file write (atomic). A panic inside a build is caught (`catch_unwind`) and reported as
//! [`Outcome::Panicked`]; the thread lives on.
//!
//! Every build starts from the document as it would be read back from disk
//! (serialised and parsed again), so an export is bit for bit what
//! `character build` makes of the saved file.

use crate::character::assembly::PartCache;
use crate::character::doc::CharacterDoc;
use crate::character::log::Edit;
use crate::character::Resolution;
use crate::mesh::Mesh;
use crate::pipeline::{build as build_doc, push_checked, BuildError, BuildOptions};
use crate::sketch::SketchReport;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender, TryRecvError};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// What to do.
#[derive(Clone, Debug)]
pub enum Task {
    /// Build for the preview and the status line.
    Rebuild,
    /// Build at `res` and write the mesh (format from the extension: OBJ,
    /// GLB, STL, PLY) or a PNG of the front, side and top views.
    Export { path: PathBuf },
    /// Push `edit` through `pipeline::push_checked` (kept only when
    /// the document still builds as `character build` builds it); the
    /// result is the build with the edit.
    Check { edit: Edit },
}

/// A job for the worker.
#[derive(Clone, Debug)]
pub struct Job {
    pub gen: u64,
    pub doc: CharacterDoc,
    /// Directory that relative profile paths are resolved against.
    pub base: PathBuf,
    pub res: Resolution,
    pub task: Task,
}

/// A finished build.
#[derive(Clone, Debug)]
pub struct Rebuilt {
    /// The document with its derived parts filled in.
    pub doc: CharacterDoc,
    /// Its parts with the log's spec-level edits applied (the app's part
    /// tree and parameter rows read them: no replay on the UI thread).
    pub edited: Vec<crate::character::spec::PartSpec>,
    pub mesh: Mesh,
    pub report: SketchReport,
}

/// What the worker reports.
#[derive(Debug)]
pub enum Outcome {
    Started {
        gen: u64,
    },
    Built {
        gen: u64,
        result: Result<Box<Rebuilt>, String>,
        elapsed: Duration,
    },
    Exported {
        gen: u64,
        result: Result<PathBuf, String>,
        elapsed: Duration,
    },
    /// A [`Task::Check`]: `result` is the build with `edit` pushed, or why
    /// the edit was refused.
    Checked {
        gen: u64,
        edit: Box<Edit>,
        result: Result<Box<Rebuilt>, String>,
        elapsed: Duration,
    },
    Panicked {
        gen: u64,
        message: String,
    },
}

impl Outcome {
    /// The job number.
    pub fn gen(&self) -> u64 {
        match self {
            Outcome::Started { gen }
            | Outcome::Built { gen, .. }
            | Outcome::Exported { gen, .. }
            | Outcome::Checked { gen, .. }
            | Outcome::Panicked { gen, .. } => *gen,
        }
    }
}

/// The build function the worker calls (the real one is [`build`]; tests
/// may pass one that panics).
pub type BuildFn = dyn FnMut(&Job) -> Result<Rebuilt, String> + Send + 'static;

/// Builds a job's document as `character build` reads it from disk.
pub fn build(job: &Job) -> Result<Rebuilt, String> {
    build_with(job, None)
}

/// [`build`] re-solving only the parts not in `cache` (the same mesh, bit
/// for bit: `character::assembly::PartCache`).
pub fn build_with(job: &Job, cache: Option<&mut PartCache>) -> Result<Rebuilt, String> {
    build_cancellable(job, cache, &|| false)
}

/// The error of a cancelled build.
pub const CANCELLED: &str = "cancelled";

/// [`build_with`] that stops with [`CANCELLED`] when `cancelled` says so:
/// the one build (`pipeline::build`) asks it before it starts, before
/// each part's solve, before each prop and at its end.
pub fn build_cancellable(
    job: &Job,
    cache: Option<&mut PartCache>,
    cancelled: &dyn Fn() -> bool,
) -> Result<Rebuilt, String> {
    let text = serde_json::to_string_pretty(&job.doc).map_err(|e| e.to_string())?;
    let mut doc = CharacterDoc::parse(&text, Path::new("document")).map_err(|e| e.to_string())?;
    let opts = BuildOptions::new(&job.base).res(job.res).cancel(cancelled);
    let built = match &job.task {
        Task::Check { edit } => push_checked(&mut doc, edit.clone(), &opts, cache),
        _ => build_doc(&doc, &opts, cache),
    };
    let built = built.map_err(|e| match e {
        BuildError::Cancelled => CANCELLED.to_string(),
        e => e.to_string(),
    })?;
    Ok(Rebuilt {
        doc: built.doc,
        edited: built.edited,
        mesh: built.model.mesh,
        report: built.report,
    })
}

/// Writes a built mesh (or its PNG preview) to `path`.
pub fn write_export(r: &Rebuilt, path: &Path) -> Result<(), String> {
    let is_png = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if is_png {
        let o = crate::render::RenderOptions::default();
        let views = [
            crate::render::View::Front,
            crate::render::View::Side,
            crate::render::View::Top,
        ];
        crate::render::render_views(&r.mesh, &views, &o)
            .save_png(path)
            .map_err(|e| e.to_string())
    } else {
        // the same file as `character build -o PATH`: one model named
        // after the file, a node (object) per part
        use crate::mesh::io::{model_name, write_scene, Layout, Scene};
        let scene = Scene::single(&model_name(path), r.mesh.clone());
        write_scene(&scene, path, Layout::Parts).map_err(|e| e.to_string())
    }
}

/// Checks an export path before any work: a known extension.
pub fn check_export_path(path: &Path) -> Result<(), String> {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    if ext.eq_ignore_ascii_case("png") {
        return Ok(());
    }
    crate::mesh::io::Format::from_path(path)
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// The worker's handle: send jobs, poll outcomes.
pub struct Worker {
    tx: Option<Sender<Job>>,
    /// Jobs numbered up to this are cancelled.
    cancelled: Arc<AtomicU64>,
    rx: Receiver<Outcome>,
    handle: Option<std::thread::JoinHandle<()>>,
}

fn panic_message(p: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = p.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = p.downcast_ref::<String>() {
        s.clone()
    } else {
        "panic without a message".into()
    }
}

/// Name of the worker thread (the TUI's panic hook keeps its panics off
/// the screen).
pub const THREAD_NAME: &str = "pdesculpt-tui-worker";

impl Worker {
    /// Starts the worker with the real build; built parts are cached
    /// across jobs, so an edit of one part re-solves that part only.
    pub fn spawn() -> Worker {
        let mut cache = PartCache::default();
        let cancelled = Arc::new(AtomicU64::new(0));
        let mark = cancelled.clone();
        let mut w = Worker::with_build(Box::new(move |j: &Job| {
            let gen = j.gen;
            build_cancellable(j, Some(&mut cache), &|| mark.load(Ordering::SeqCst) >= gen)
        }));
        w.cancelled = cancelled;
        w
    }

    /// Cancels every job numbered up to `gen` (the running one stops at
    /// its next check, queued ones before they start).
    pub fn cancel(&self, gen: u64) {
        self.cancelled.fetch_max(gen, Ordering::SeqCst);
    }

    /// Starts the worker with a given build function.
    pub fn with_build(f: Box<BuildFn>) -> Worker {
        let (tx, jobs) = channel::<Job>();
        let (out, rx) = channel::<Outcome>();
        let handle = std::thread::Builder::new()
            .name(THREAD_NAME.into())
            .spawn(move || worker_loop(jobs, out, f))
            .ok();
        Worker {
            tx: Some(tx),
            cancelled: Arc::new(AtomicU64::new(0)),
            rx,
            handle,
        }
    }

    /// Queues a job (false when the worker is gone).
    pub fn send(&self, job: Job) -> bool {
        self.tx.as_ref().is_some_and(|t| t.send(job).is_ok())
    }

    /// The next outcome, if one is ready.
    pub fn poll(&self) -> Option<Outcome> {
        self.rx.try_recv().ok()
    }

    /// Waits up to `timeout` for the next outcome.
    pub fn wait(&self, timeout: Duration) -> Option<Outcome> {
        self.rx.recv_timeout(timeout).ok()
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        self.tx = None;
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}

fn worker_loop(jobs: Receiver<Job>, out: Sender<Outcome>, mut f: Box<BuildFn>) {
    while let Ok(mut job) = jobs.recv() {
        // coalesce: of queued rebuilds only the newest matters; exports all run
        loop {
            match jobs.try_recv() {
                Ok(next) => {
                    if matches!(job.task, Task::Export { .. }) {
                        run_one(&job, &out, f.as_mut());
                    }
                    job = next;
                }
                Err(TryRecvError::Empty) => break,
                Err(TryRecvError::Disconnected) => break,
            }
        }
        run_one(&job, &out, f.as_mut());
    }
}

fn run_one(job: &Job, out: &Sender<Outcome>, f: &mut BuildFn) {
    let _ = out.send(Outcome::Started { gen: job.gen });
    let t0 = Instant::now();
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let built = f(job)?;
        if let Task::Export { path } = &job.task {
            write_export(&built, path)?;
        }
        Ok::<_, String>(built)
    }));
    let elapsed = t0.elapsed();
    let msg = match r {
        Err(p) => Outcome::Panicked {
            gen: job.gen,
            message: panic_message(p.as_ref()),
        },
        Ok(result) => match &job.task {
            Task::Rebuild => Outcome::Built {
                gen: job.gen,
                result: result.map(Box::new),
                elapsed,
            },
            Task::Export { path } => Outcome::Exported {
                gen: job.gen,
                result: result.map(|_| path.clone()),
                elapsed,
            },
            Task::Check { edit } => Outcome::Checked {
                gen: job.gen,
                edit: Box::new(edit.clone()),
                result: result.map(Box::new),
                elapsed,
            },
        },
    };
    let _ = out.send(msg);
}
