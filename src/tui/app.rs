//! The TUI's state and its reaction to keys: pure (no terminal), so tests
//! drive it key by key and look at the result.
//!
//! The document is changed only through the edit log (`push_edit`, `undo`,
//! `redo`); every change is autosaved and asks for a rebuild, which runs on
//! the worker thread ([`super::worker`]). `good` is the document of the last
//! successful build: when a rebuild fails or panics, the document goes back
//! to it (the edit is dropped and the error shown), so a bad edit never
//! leaves a document that does not build.

use super::autosave;
use super::history::History;
use super::params::{self, Row};
use super::preview::ViewSet;
pub use super::prompt::PromptKind;
use super::worker::{Outcome, Rebuilt};
use crate::character::doc::{CharacterDoc, PartSpec};
use crate::edit::apply_to_parts;
use crate::mesh::Mesh;
use crate::sketch::SketchReport;
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// The focused panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Focus {
    Tree,
    Params,
    Log,
}

/// What the keys do now.
#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    Normal,
    /// Typing a value into parameter row `row`.
    Editing {
        row: usize,
        buffer: String,
    },
    /// Typing the export path.
    Export {
        buffer: String,
    },
    /// Typing a command's input ([`super::commands`]); `error`: why the
    /// last Enter was refused.
    Prompt {
        kind: PromptKind,
        buffer: String,
        error: Option<String>,
    },
    Help,
    /// Quit with unsaved changes: save, discard or stay.
    ConfirmQuit,
    /// A newer autosave was found on start: recover it or not.
    Recovery(Box<CharacterDoc>),
}

/// What the event loop must do after a key.
#[derive(Clone, Debug, PartialEq)]
pub enum Effect {
    /// Rebuild the current document (preview, status).
    Rebuild,
    /// Build at export resolution and write to the path.
    Export(PathBuf),
    /// Push an edit that is kept only when the document still builds
    /// (`pipeline::push_checked`, on the worker).
    Check(crate::character::log::Edit),
    /// Abandon the running job.
    Cancel,
    Quit,
}

/// Kind of a tree item.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ItemKind {
    Part,
    Transition,
    Removed,
    Prop,
}

/// One entry of the part tree.
#[derive(Clone, Debug, PartialEq)]
pub struct TreeItem {
    pub kind: ItemKind,
    pub name: String,
    pub detail: String,
}

/// A line under the status line.
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    pub text: String,
    pub error: bool,
}

/// A job on the worker.
#[derive(Clone, Debug, PartialEq)]
pub struct Running {
    pub gen: u64,
    pub export: bool,
    pub since: Instant,
}

/// The last build's mesh and report.
#[derive(Clone, Debug)]
pub struct Shown {
    /// Counts builds (the preview cache's key).
    pub id: u64,
    pub mesh: Mesh,
    pub report: SketchReport,
    pub elapsed: Duration,
}

/// The application state.
pub struct App {
    pub doc: CharacterDoc,
    /// Where the document is saved (its sidecar is `path.autosave`).
    pub path: PathBuf,
    /// Directory of relative profile paths.
    pub base: PathBuf,
    /// The document as last saved (None: never saved).
    pub saved: Option<CharacterDoc>,
    /// The document of the last successful build.
    pub good: Option<CharacterDoc>,
    /// The parts with the active edits applied (what the panel shows).
    pub edited: Vec<PartSpec>,
    pub shown: Option<Shown>,
    /// The preview is older than the document.
    pub stale: bool,
    pub focus: Focus,
    pub tree_sel: usize,
    pub param_sel: usize,
    pub log_sel: usize,
    /// Section the GEC transforms act on (None: all).
    pub section: Option<usize>,
    pub mode: Mode,
    pub message: Option<Message>,
    pub running: Option<Running>,
    pub next_gen: u64,
    pub view: ViewSet,
    /// Undo history of edits and input commands ([`super::history`]).
    pub history: History,
    /// The history of `good`.
    pub good_history: History,
}

impl App {
    /// A new state for `doc` saved at `path` (`on_disk`: the document as it
    /// is on disk, None for a new one).
    pub fn new(doc: CharacterDoc, path: PathBuf, on_disk: Option<CharacterDoc>) -> App {
        let base = path
            .parent()
            .map(PathBuf::from)
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or_else(|| PathBuf::from("."));
        let history = History::of(&doc);
        let mut app = App {
            good_history: history.clone(),
            history,
            doc,
            path,
            base,
            saved: on_disk,
            good: None,
            edited: Vec::new(),
            shown: None,
            stale: true,
            focus: Focus::Tree,
            tree_sel: 0,
            param_sel: 1,
            log_sel: 0,
            section: None,
            mode: Mode::Normal,
            message: None,
            running: None,
            next_gen: 1,
            view: ViewSet::Front,
        };
        app.refresh_edited();
        app
    }

    /// Unsaved changes.
    pub fn dirty(&self) -> bool {
        self.saved.as_ref() != Some(&self.doc)
    }

    fn refresh_edited(&mut self) {
        self.edited = apply_to_parts(self.doc.parts(), self.doc.active_edits())
            .unwrap_or_else(|_| self.doc.parts().to_vec());
        self.log_sel = self.log_sel.min(self.doc.edits().len());
    }

    /// The part tree.
    pub fn tree(&self) -> Vec<TreeItem> {
        let removed = |n: &str| self.doc.removed_parts().iter().any(|r| r.name == n);
        let mut out: Vec<TreeItem> = self
            .edited
            .iter()
            .map(|p| TreeItem {
                kind: if removed(&p.name) {
                    ItemKind::Removed
                } else {
                    ItemKind::Part
                },
                name: p.name.clone(),
                detail: format!("{} sections", p.sections.len()),
            })
            .collect();
        out.extend(self.doc.transitions().iter().map(|t| TreeItem {
            kind: ItemKind::Transition,
            name: t.name.clone(),
            detail: format!("{} -> {}", t.parent, t.children.join(", ")),
        }));
        out.extend(
            self.doc
                .removed_parts()
                .iter()
                .filter(|r| !self.edited.iter().any(|p| p.name == r.name))
                .map(|r| TreeItem {
                    kind: ItemKind::Removed,
                    name: r.name.clone(),
                    detail: "removed, not built".into(),
                }),
        );
        out.extend(self.doc.props().iter().map(|p| TreeItem {
            kind: ItemKind::Prop,
            name: p.name.clone(),
            detail: format!("conv model x{}", p.scale),
        }));
        out
    }

    /// The selected tree item.
    pub fn selected(&self) -> Option<TreeItem> {
        self.tree().into_iter().nth(self.tree_sel)
    }

    pub(super) fn selected_part(&self) -> Option<&PartSpec> {
        let item = self.selected()?;
        self.edited.iter().find(|p| p.name == item.name)
    }

    /// Rows of the parameter panel.
    pub fn rows(&self) -> Vec<Row> {
        match self.selected() {
            None => Vec::new(),
            Some(item) => match self.edited.iter().find(|p| p.name == item.name) {
                Some(p) => params::part_rows(p, self.section),
                None => params::other_rows(&self.doc, &item.name),
            },
        }
    }

    /// The error of the value being typed, if any (None when valid or not
    /// editing).
    pub fn typing_error(&self) -> Option<String> {
        let Mode::Editing { row, buffer } = &self.mode else {
            return None;
        };
        let kind = self.rows().get(*row)?.kind;
        let part = self.selected_part()?;
        params::parse(kind, buffer, part, self.section).err()
    }

    pub(super) fn say(&mut self, text: impl Into<String>, error: bool) {
        self.message = Some(Message {
            text: text.into(),
            error,
        });
    }

    /// After every change of the document: refresh, autosave, rebuild.
    /// Nothing is created before the first save: the autosave is written
    /// only where the document's directory exists.
    pub(super) fn changed(&mut self) -> Vec<Effect> {
        self.refresh_edited();
        self.changed_without_replay()
    }

    /// [`App::changed`] when the edited parts are known already (a checked
    /// edit's build brought them).
    pub(super) fn changed_without_replay(&mut self) -> Vec<Effect> {
        self.stale = true;
        let dir = self.path.parent().filter(|d| !d.as_os_str().is_empty());
        if dir.is_some_and(|d| !d.is_dir()) {
            return vec![Effect::Rebuild];
        }
        if let Err(e) = autosave::write(&self.doc, &self.path) {
            self.say(format!("autosave failed: {e}"), true);
        }
        vec![Effect::Rebuild]
    }

    /// Saves the document and removes the sidecar; refused when another
    /// program changed the file since this session read or saved it
    /// ([`autosave::save_checked`]).
    pub fn save(&mut self) -> bool {
        match autosave::save_checked(&self.doc, &self.path, self.saved.as_ref()) {
            Ok(()) => {
                self.saved = Some(self.doc.clone());
                let _ = autosave::remove(&self.path);
                self.say(format!("saved {}", self.path.display()), false);
                true
            }
            Err(e) => {
                self.say(format!("save failed: {e}"), true);
                false
            }
        }
    }

    /// Marks a job as started on the worker; returns its number.
    pub fn start_job(&mut self, export: bool) -> u64 {
        let gen = self.next_gen;
        self.next_gen += 1;
        self.running = Some(Running {
            gen,
            export,
            since: Instant::now(),
        });
        gen
    }

    /// Takes a worker outcome into account (outcomes of abandoned jobs are
    /// dropped).
    pub fn on_outcome(&mut self, o: Outcome) -> Vec<Effect> {
        if self.running.as_ref().map(|r| r.gen) != Some(o.gen()) {
            return Vec::new();
        }
        match o {
            Outcome::Started { .. } => Vec::new(),
            Outcome::Built {
                result, elapsed, ..
            } => {
                self.running = None;
                match result {
                    Ok(r) => self.built(*r, elapsed),
                    Err(e) => self.failed(format!("rebuild failed: {e}")),
                }
            }
            Outcome::Exported {
                result, elapsed, ..
            } => {
                self.running = None;
                match result {
                    Ok(p) => self.say(
                        format!("exported {} in {} ms", p.display(), elapsed.as_millis()),
                        false,
                    ),
                    Err(e) => self.say(format!("export failed: {e}"), true),
                }
                Vec::new()
            }
            Outcome::Checked {
                edit,
                result,
                elapsed,
                ..
            } => {
                self.running = None;
                self.checked(*edit, result, elapsed)
            }
            Outcome::Panicked { message, .. } => {
                self.running = None;
                self.failed(format!("rebuild panicked: {message}"))
            }
        }
    }

    pub(super) fn built(&mut self, r: Rebuilt, elapsed: Duration) -> Vec<Effect> {
        let mut effects = Vec::new();
        if self.doc.parts().is_empty() {
            // the first build derived the parts: the document keeps them
            // (edits act on stored parts)
            self.doc
                .set_derived(r.doc.parts().to_vec(), r.doc.transitions().to_vec());
            effects = self.changed();
            effects.clear();
        }
        self.good = Some(self.doc.clone());
        self.good_history = self.history.clone();
        self.stale = false;
        self.edited = r.edited;
        let id = self.shown.as_ref().map_or(1, |s| s.id + 1);
        self.shown = Some(Shown {
            id,
            mesh: r.mesh,
            report: r.report,
            elapsed,
        });
        effects
    }

    fn failed(&mut self, text: String) -> Vec<Effect> {
        let effects = match self.good.clone() {
            Some(g) if g != self.doc => {
                self.doc = g;
                self.history = self.good_history.clone();
                self.say(
                    format!("{text}; the document is back to its last good state"),
                    true,
                );
                let mut e = self.changed();
                e.clear(); // the last good state is what the preview shows
                self.stale = false;
                e
            }
            _ => {
                self.say(text, true);
                Vec::new()
            }
        };
        self.refresh_edited();
        effects
    }

    /// Reacts to one key.
    pub fn on_key(&mut self, k: KeyEvent) -> Vec<Effect> {
        let ctrl = k.modifiers.contains(KeyModifiers::CONTROL);
        match self.mode.clone() {
            Mode::Help => {
                self.mode = Mode::Normal;
                Vec::new()
            }
            Mode::Recovery(doc) => match k.code {
                KeyCode::Char('y') => {
                    self.doc = *doc;
                    self.history = History::of(&self.doc);
                    self.mode = Mode::Normal;
                    self.say("recovered the autosaved changes (not saved yet)", false);
                    self.changed()
                }
                KeyCode::Char('n') | KeyCode::Esc => {
                    self.mode = Mode::Normal;
                    let _ = autosave::remove(&self.path);
                    self.say("autosave discarded", false);
                    Vec::new()
                }
                _ => Vec::new(),
            },
            Mode::ConfirmQuit => match k.code {
                KeyCode::Char('y') if self.save() => vec![Effect::Quit],
                KeyCode::Char('n') => {
                    let _ = autosave::remove(&self.path);
                    vec![Effect::Quit]
                }
                _ => {
                    self.mode = Mode::Normal;
                    Vec::new()
                }
            },
            Mode::Export { mut buffer } => match k.code {
                KeyCode::Esc => {
                    self.mode = Mode::Normal;
                    Vec::new()
                }
                KeyCode::Enter => {
                    let path = PathBuf::from(buffer.trim());
                    match super::worker::check_export_path(&path) {
                        Ok(()) => {
                            self.mode = Mode::Normal;
                            vec![Effect::Export(path)]
                        }
                        Err(e) => {
                            self.say(e, true);
                            Vec::new()
                        }
                    }
                }
                KeyCode::Backspace => {
                    buffer.pop();
                    self.mode = Mode::Export { buffer };
                    Vec::new()
                }
                KeyCode::Char(c) => {
                    buffer.push(c);
                    self.mode = Mode::Export { buffer };
                    Vec::new()
                }
                _ => Vec::new(),
            },
            Mode::Editing { row, buffer } => self.on_edit_key(k, row, buffer),
            Mode::Prompt { kind, buffer, .. } => self.on_prompt_key(k, kind, buffer),
            Mode::Normal => self.on_normal_key(k, ctrl),
        }
    }
}
