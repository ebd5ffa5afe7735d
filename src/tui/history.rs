//! One undo history for the edit log and the input commands.
//!
//! The edit log (`CharacterDoc::edits` with its cursor) is the document's
//! own history of edits; the commands `a` (add part), `x` (key section) and
//! `p` (attach prop) change the document's inputs instead. [`History`]
//! interleaves both in the order they happened: a [`Step::Edit`] is undone
//! and redone by moving the log cursor, a [`Step::Inputs`] by putting back
//! the input fields ([`InputState`]: inputs, stored parts, transitions,
//! removed parts, props) as they were before or after the command. `u` and
//! `r` walk this one history, so undoing three commands gives back the
//! document they started from, exactly.
//!
//! Invariant: the `Edit` steps before the position are the log's active
//! edits (as many as `cursor`), those after it the inactive ones. A new
//! edit or command drops the steps after the position (and so the log's
//! inactive edits: a command truncates the log at its cursor).
//!
//! The history lives in the session (the autosave and the saved file keep
//! the document, whose log alone survives a restart).

use crate::character::doc::{CharacterDoc, Inputs, PartSpec, RemovedPart, TransitionSpec};
use crate::character::props::PropSpec;

/// The document's fields an input command changes.
#[derive(Clone, Debug, PartialEq)]
pub struct InputState {
    pub inputs: Inputs,
    pub parts: Vec<PartSpec>,
    pub transitions: Vec<TransitionSpec>,
    pub removed_parts: Vec<RemovedPart>,
    pub props: Vec<PropSpec>,
}

impl InputState {
    /// The input fields of `doc`.
    pub fn of(doc: &CharacterDoc) -> InputState {
        InputState {
            inputs: doc.inputs().clone(),
            parts: doc.parts().to_vec(),
            transitions: doc.transitions().to_vec(),
            removed_parts: doc.removed_parts().to_vec(),
            props: doc.props().to_vec(),
        }
    }

    /// Puts these input fields into `doc` (its edit log is left alone).
    pub fn put(&self, doc: &mut CharacterDoc) {
        doc.restore_content(
            self.inputs.clone(),
            self.parts.clone(),
            self.transitions.clone(),
            self.removed_parts.clone(),
            self.props.clone(),
        );
    }
}

/// One step of the history.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    /// An entry of the edit log.
    Edit,
    /// An input command: `what` it did, the fields before and after.
    Inputs {
        what: String,
        before: Box<InputState>,
        after: Box<InputState>,
    },
}

/// The session's history and the position in it.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct History {
    pub steps: Vec<Step>,
    pub pos: usize,
}

/// Why a step could not be undone or redone.
#[derive(Debug, thiserror::Error)]
pub enum HistoryError {
    #[error("nothing to undo")]
    NothingToUndo,
    #[error("nothing to redo")]
    NothingToRedo,
    #[error("the edit log no longer matches the history: {0}")]
    Log(#[from] crate::character::log::EditError),
}

impl History {
    /// The history of a document as loaded: its edit log (the active edits
    /// before the position, the inactive ones after).
    pub fn of(doc: &CharacterDoc) -> History {
        History {
            steps: vec![Step::Edit; doc.edits().len()],
            pos: doc.cursor(),
        }
    }

    /// Records an edit just pushed on the log.
    pub fn record_edit(&mut self) {
        self.steps.truncate(self.pos);
        self.steps.push(Step::Edit);
        self.pos = self.steps.len();
    }

    /// Records an input command that turned `before` into `doc` (whose
    /// inactive edits are dropped: they were the redo tail).
    pub fn record_inputs(&mut self, what: String, before: &CharacterDoc, doc: &mut CharacterDoc) {
        doc.drop_inactive_edits();
        self.steps.truncate(self.pos);
        self.steps.push(Step::Inputs {
            what,
            before: Box::new(InputState::of(before)),
            after: Box::new(InputState::of(doc)),
        });
        self.pos = self.steps.len();
    }

    /// The step `undo` would undo.
    pub fn last(&self) -> Option<&Step> {
        self.pos.checked_sub(1).and_then(|i| self.steps.get(i))
    }

    /// The step `redo` would redo.
    pub fn next(&self) -> Option<&Step> {
        self.steps.get(self.pos)
    }

    /// Undoes one step of `doc`; returns what was undone.
    pub fn undo(&mut self, doc: &mut CharacterDoc) -> Result<String, HistoryError> {
        let step = self.last().ok_or(HistoryError::NothingToUndo)?.clone();
        let what = match step {
            Step::Edit => {
                let summary = doc
                    .last_active()
                    .map(|(_, e)| e.summary())
                    .unwrap_or_default();
                doc.undo()?;
                summary
            }
            Step::Inputs { what, before, .. } => {
                before.put(doc);
                what
            }
        };
        self.pos -= 1;
        Ok(what)
    }

    /// Redoes one step of `doc`; returns what was redone.
    pub fn redo(&mut self, doc: &mut CharacterDoc) -> Result<String, HistoryError> {
        let step = self.next().ok_or(HistoryError::NothingToRedo)?.clone();
        let what = match step {
            Step::Edit => {
                doc.redo()?;
                doc.last_active()
                    .map(|(_, e)| e.summary())
                    .unwrap_or_default()
            }
            Step::Inputs { what, after, .. } => {
                after.put(doc);
                what
            }
        };
        self.pos += 1;
        Ok(what)
    }
}
