//! The terminal event loop: crossterm events and worker outcomes in, the
//! app's effects out, one redraw per event (and every 100 ms while a job
//! runs, for the progress spinner).

use super::app::{App, Effect, Mode};
use super::autosave;
use super::view::{self, PreviewCache};
use super::worker::{Job, Task, Worker, THREAD_NAME};
use super::TuiError;
use crate::character::doc::{CharacterDoc, Level};
use crate::character::Resolution;
use crossterm::event::{self, Event, KeyEventKind};
use std::path::PathBuf;
use std::time::Duration;

/// How the TUI starts: [`Options::new`] (a document path and the bundled
/// example it starts from when the file does not exist; the preview at
/// [`PREVIEW_RINGS`] rings per height), then [`Options::with_preview`].
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Options {
    /// The document (created on the first save when it does not exist).
    pub path: PathBuf,
    /// The bundled example a new document starts from (`female`, `male`).
    pub bundled: String,
    /// Resolution of the preview's rebuilds (exports use the default).
    pub preview: Resolution,
}

/// The preview's default resolution: rings per model height.
pub const PREVIEW_RINGS: f64 = 60.0;

/// The preview's resolution at `rings_per_height` (the CLI's
/// `--preview-rings`, [`PREVIEW_RINGS`] by default), every other setting
/// the export's.
pub fn preview_resolution(rings_per_height: f64) -> Resolution {
    Resolution {
        rings_per_height,
        ..Resolution::default()
    }
}

impl Options {
    /// The document at `path`; a new one starts from the bundled example
    /// `bundled` (`female`, `male`); the preview at [`PREVIEW_RINGS`].
    pub fn new(path: impl Into<PathBuf>, bundled: impl Into<String>) -> Options {
        Options {
            path: path.into(),
            bundled: bundled.into(),
            preview: preview_resolution(PREVIEW_RINGS),
        }
    }

    /// The preview's resolution.
    pub fn with_preview(mut self, preview: Resolution) -> Options {
        self.preview = preview;
        self
    }
}

/// Loads the document (or the bundled example for a new one) and the
/// recovery offer: the app as it starts.
pub fn open(o: &Options) -> Result<App, TuiError> {
    let (doc, on_disk) = if o.path.exists() {
        let d = CharacterDoc::load(&o.path)?;
        (d.clone(), Some(d))
    } else {
        let d = crate::sketch::check::bundled(&o.bundled, Level::Final)
            .ok_or_else(|| TuiError::Bundled(o.bundled.clone()))?;
        (d, None)
    };
    let recovery = autosave::offer(&o.path)?;
    let mut app = App::new(doc, o.path.clone(), on_disk);
    if let Some(r) = recovery {
        app.mode = Mode::Recovery(Box::new(r.doc));
    }
    Ok(app)
}

/// Sends the effects' jobs; true when the app asked to quit.
pub fn run_effects(app: &mut App, worker: &Worker, effects: Vec<Effect>, res: Resolution) -> bool {
    for e in effects {
        match e {
            Effect::Quit => return true,
            // every job sent so far (only the newest can be running)
            Effect::Cancel => worker.cancel(app.next_gen.saturating_sub(1)),
            Effect::Rebuild => {
                let gen = app.start_job(false);
                worker.send(Job {
                    gen,
                    doc: app.doc.clone(),
                    base: app.base.clone(),
                    res,
                    task: Task::Rebuild,
                });
            }
            Effect::Check(edit) => {
                let gen = app.start_job(false);
                worker.send(Job {
                    gen,
                    doc: app.doc.clone(),
                    base: app.base.clone(),
                    res: Resolution::default(),
                    task: Task::Check { edit },
                });
            }
            Effect::Export(path) => {
                let gen = app.start_job(true);
                worker.send(Job {
                    gen,
                    doc: app.doc.clone(),
                    base: app.base.clone(),
                    res: Resolution::default(),
                    task: Task::Export { path },
                });
            }
        }
    }
    false
}

fn install_panic_hook() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        // a panic in a rebuild is caught and shown in the status line:
        // printing it would scribble over the screen
        if std::thread::current().name() == Some(THREAD_NAME) {
            return;
        }
        previous(info);
    }));
}

/// Runs the TUI until the user quits.
pub fn run(o: Options) -> Result<(), TuiError> {
    let mut app = open(&o)?;
    // drawing into a pipe or a file would write escape sequences there, and
    // without a controlling terminal ratatui's `init` panics
    if !std::io::IsTerminal::is_terminal(&std::io::stdout()) {
        return Err(TuiError::NotATerminal);
    }
    let mut terminal = ratatui::try_init().inspect_err(|_| ratatui::restore())?;
    let worker = Worker::spawn();
    install_panic_hook();
    let kitty = super::kitty::detect();
    let mut cache = if kitty {
        PreviewCache::with_kitty()
    } else {
        PreviewCache::default()
    };
    run_effects(&mut app, &worker, vec![Effect::Rebuild], o.preview);
    let result = (|| -> Result<(), TuiError> {
        loop {
            terminal.draw(|f| view::draw(f, &app, &mut cache))?;
            if let Some(seq) = cache.take_kitty() {
                write_raw(&seq)?;
            }
            let mut quit = false;
            while let Some(out) = worker.poll() {
                let effects = app.on_outcome(out);
                quit |= run_effects(&mut app, &worker, effects, o.preview);
            }
            let wait = if app.running.is_some() { 100 } else { 250 };
            if event::poll(Duration::from_millis(wait))? {
                if let Event::Key(k) = event::read()? {
                    if k.kind == KeyEventKind::Press {
                        let effects = app.on_key(k);
                        quit |= run_effects(&mut app, &worker, effects, o.preview);
                    }
                }
            }
            if quit {
                return Ok(());
            }
        }
    })();
    if kitty {
        let _ = write_raw(&super::kitty::clear());
    }
    ratatui::restore();
    result
}

/// Writes escape sequences straight to the terminal.
fn write_raw(seq: &str) -> std::io::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(seq.as_bytes())?;
    out.flush()
}
