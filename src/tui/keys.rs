//! Key bindings of the normal and editing modes (the table shown by `?`
//! and in the README is [`BINDINGS`]).

use super::app::{App, Effect, Focus, Mode};
use super::commands::PromptKind;
use super::params::{self, Parsed};
use crossterm::event::{KeyCode, KeyEvent};

/// Every key binding: keys, what they do.
pub const BINDINGS: &[(&str, &str)] = &[
    (
        "Tab / Shift-Tab",
        "next / previous panel (parts, parameters, edit log)",
    ),
    ("Up/Down, k/j", "move in the focused panel"),
    (
        "Enter",
        "parameters: edit the row; log: move the cursor there",
    ),
    (
        "Esc",
        "cancel typing, or abandon the running rebuild/export",
    ),
    (
        "u, Ctrl-Z",
        "undo the last edit or command (add part, key section, prop)",
    ),
    ("r, Ctrl-Y", "redo"),
    ("v", "preview view: front, side, top, all three"),
    (
        "a",
        "add a part from an SVG/JSON outline (a separate component)",
    ),
    (
        "x",
        "add a key section to the selected part (ellipse or curve file)",
    ),
    (
        "p",
        "attach a prop from a conv model file (data/conv/*.json)",
    ),
    ("Tab (in a prompt)", "complete the file path"),
    ("b", "rebuild now"),
    (
        "e",
        "export: OBJ/GLB/STL/PLY mesh or PNG preview (type the path)",
    ),
    ("s, Ctrl-S", "save the document (removes the autosave)"),
    ("?", "this help"),
    ("q, Ctrl-C", "quit (asks when there are unsaved changes)"),
];

impl App {
    /// Undoes one step of the history: an edit or an input command.
    pub fn undo(&mut self) -> Vec<Effect> {
        self.step_history(true)
    }

    /// Redoes one step of the history.
    pub fn redo(&mut self) -> Vec<Effect> {
        self.step_history(false)
    }

    /// One step back (`undo`) or forward through the history.
    fn step_history(&mut self, undo: bool) -> Vec<Effect> {
        let (r, word) = if undo {
            (self.history.undo(&mut self.doc), "undo")
        } else {
            (self.history.redo(&mut self.doc), "redo")
        };
        match r {
            Ok(what) => {
                self.log_sel = self.doc.cursor();
                self.say(
                    format!("{word}: {what} (log cursor {})", self.doc.cursor()),
                    false,
                );
                self.changed()
            }
            Err(e) => {
                self.say(e.to_string(), true);
                Vec::new()
            }
        }
    }

    fn move_sel(&mut self, down: bool) {
        let step = |v: usize, n: usize| -> usize {
            if n == 0 {
                0
            } else if down {
                (v + 1).min(n - 1)
            } else {
                v.saturating_sub(1)
            }
        };
        match self.focus {
            Focus::Tree => {
                let n = self.tree().len();
                let before = self.tree_sel;
                self.tree_sel = step(self.tree_sel, n);
                if before != self.tree_sel {
                    self.section = None;
                    self.param_sel = 1;
                }
            }
            Focus::Params => {
                let rows = self.rows();
                let mut i = self.param_sel;
                // skip read-only rows
                loop {
                    let j = step(i, rows.len());
                    if j == i {
                        break;
                    }
                    i = j;
                    if rows[i].kind.editable() {
                        self.param_sel = i;
                        break;
                    }
                }
            }
            Focus::Log => self.log_sel = step(self.log_sel, self.doc.edits().len() + 1),
        }
    }

    /// Moves the log cursor to `target` by undoing or redoing edits; it
    /// stops at an input command (only `u`/`r` step over those).
    fn seek(&mut self, target: usize) -> Vec<super::app::Effect> {
        use super::history::Step;
        let target = target.min(self.doc.edits().len());
        let mut moved = false;
        while self.doc.cursor() > target
            && self.history.last() == Some(&Step::Edit)
            && self.history.undo(&mut self.doc).is_ok()
        {
            moved = true;
        }
        while self.doc.cursor() < target
            && self.history.next() == Some(&Step::Edit)
            && self.history.redo(&mut self.doc).is_ok()
        {
            moved = true;
        }
        let blocked = self.doc.cursor() != target;
        if blocked {
            self.say(
                format!(
                    "log cursor at {}: an input command (add part, key section, prop) lies between; step over it with u/r",
                    self.doc.cursor()
                ),
                true,
            );
        } else if moved {
            self.say(format!("log cursor at {}", self.doc.cursor()), false);
        }
        self.log_sel = self.doc.cursor();
        if moved {
            self.changed()
        } else {
            Vec::new()
        }
    }

    pub(super) fn on_normal_key(&mut self, k: KeyEvent, ctrl: bool) -> Vec<Effect> {
        match k.code {
            KeyCode::Char('z') if ctrl => self.undo(),
            KeyCode::Char('y') if ctrl => self.redo(),
            KeyCode::Char('s') if ctrl => {
                self.save();
                Vec::new()
            }
            KeyCode::Char('c') if ctrl => self.quit(),
            KeyCode::Char('u') => self.undo(),
            KeyCode::Char('r') => self.redo(),
            KeyCode::Char('s') => {
                self.save();
                Vec::new()
            }
            KeyCode::Char('q') => self.quit(),
            KeyCode::Char('?') => {
                self.mode = Mode::Help;
                Vec::new()
            }
            KeyCode::Char('v') => {
                self.view = self.view.next();
                Vec::new()
            }
            KeyCode::Char('b') => vec![Effect::Rebuild],
            KeyCode::Char('a') => self.prompt(PromptKind::AddPart),
            KeyCode::Char('x') => self.prompt(PromptKind::KeySection),
            KeyCode::Char('p') => self.prompt(PromptKind::AddProp),
            KeyCode::Char('e') => {
                let stem = self
                    .path
                    .file_stem()
                    .and_then(|s| s.to_str())
                    .unwrap_or("character");
                let default = self.base.join(format!("{stem}.glb"));
                self.mode = Mode::Export {
                    buffer: default.display().to_string(),
                };
                Vec::new()
            }
            KeyCode::Esc => {
                if self.running.take().is_some() {
                    self.say(
                        "cancelled the running job (the document is unchanged)",
                        false,
                    );
                    vec![Effect::Cancel]
                } else {
                    Vec::new()
                }
            }
            KeyCode::Tab => {
                self.focus = match self.focus {
                    Focus::Tree => Focus::Params,
                    Focus::Params => Focus::Log,
                    Focus::Log => Focus::Tree,
                };
                Vec::new()
            }
            KeyCode::BackTab => {
                self.focus = match self.focus {
                    Focus::Tree => Focus::Log,
                    Focus::Params => Focus::Tree,
                    Focus::Log => Focus::Params,
                };
                Vec::new()
            }
            KeyCode::Down | KeyCode::Char('j') => {
                self.move_sel(true);
                Vec::new()
            }
            KeyCode::Up | KeyCode::Char('k') => {
                self.move_sel(false);
                Vec::new()
            }
            KeyCode::Enter => match self.focus {
                Focus::Params => {
                    let rows = self.rows();
                    match rows.get(self.param_sel) {
                        Some(r) if r.kind.editable() && self.selected_part().is_some() => {
                            self.mode = Mode::Editing {
                                row: self.param_sel,
                                buffer: String::new(),
                            };
                        }
                        _ => self.say("nothing to edit here", true),
                    }
                    Vec::new()
                }
                Focus::Log => self.seek(self.log_sel),
                Focus::Tree => {
                    self.focus = Focus::Params;
                    Vec::new()
                }
            },
            _ => Vec::new(),
        }
    }

    fn quit(&mut self) -> Vec<Effect> {
        if self.dirty() {
            self.mode = Mode::ConfirmQuit;
            Vec::new()
        } else {
            vec![Effect::Quit]
        }
    }

    pub(super) fn on_edit_key(
        &mut self,
        k: KeyEvent,
        row: usize,
        mut buffer: String,
    ) -> Vec<Effect> {
        match k.code {
            KeyCode::Esc => {
                self.mode = Mode::Normal;
                Vec::new()
            }
            KeyCode::Backspace => {
                buffer.pop();
                self.mode = Mode::Editing { row, buffer };
                Vec::new()
            }
            KeyCode::Char(c) => {
                buffer.push(c);
                self.mode = Mode::Editing { row, buffer };
                Vec::new()
            }
            KeyCode::Enter => {
                let Some(kind) = self.rows().get(row).map(|r| r.kind) else {
                    self.mode = Mode::Normal;
                    return Vec::new();
                };
                let Some(part) = self.selected_part().cloned() else {
                    self.mode = Mode::Normal;
                    return Vec::new();
                };
                match params::parse(kind, &buffer, &part, self.section) {
                    // invalid: stay in the editor, the error is on screen
                    Err(e) => {
                        self.say(format!("not applied: {e}"), true);
                        Vec::new()
                    }
                    Ok(Parsed::Section(s)) => {
                        self.section = s;
                        self.mode = Mode::Normal;
                        Vec::new()
                    }
                    Ok(Parsed::Edit(e)) => {
                        self.mode = Mode::Normal;
                        // every edit is judged by building the document
                        // with it once, on the worker (never a solve on
                        // the UI thread)
                        self.say(format!("checking: {}", e.summary()), false);
                        vec![Effect::Check(e)]
                    }
                }
            }
            _ => Vec::new(),
        }
    }
}
