//! `pdesculpt tui`: a terminal UI to assemble and edit a character document
//! (issue 14), built on ratatui and crossterm.
//!
//! The screen shows the part tree, the document's inputs, a half-block
//! preview rendered by the CPU rasteriser ([`preview`]), the parameter panel
//! of the selected part ([`params`]: PDE parameter and GEC transforms, values
//! checked as typed), the edit log with its cursor (undo/redo move it), a
//! status line with the live measurements (watertight, profile error, C1/C2
//! jumps, rebuild time) and a message line. Keys: [`keys::BINDINGS`].
//!
//! * [`app`]: the state and its reaction to keys, pure (tests drive it and
//!   render it on ratatui's `TestBackend`);
//! * [`worker`]: rebuilds and exports on a worker thread, re-solving only
//!   the parts an edit changed (`character::assembly::PartCache`; transitions and
//!   the mesh are rebuilt whole, at a lower preview resolution); stale jobs
//!   are dropped, a panic is caught and the document goes back to its last
//!   good state;
//! * [`autosave`]: the `CHAR.json.autosave` sidecar written after every
//!   change and offered for recovery on the next start;
//! * [`view`]: drawing (popups in `popup`); [`term`]: the crossterm event loop.
//!
//! * [`commands`]: add a part from an SVG profile, a key section, a prop
//!   from a conv model (`character::props`), typed into a prompt.
//!
//! Force, boundary and plate edits are pushed on the worker through
//! `pipeline::push_checked`; Esc cancels a running rebuild or export
//! between part solves (see [`worker`]).
//!
//! * [`history`]: one undo history over the edit log and the commands.
//!
//! * [`kitty`]: the preview as a PNG through the kitty graphics protocol
//!   when the terminal announces it (half-blocks otherwise, and below it).
//!
//! Not done: other terminal image protocols (sixel, iTerm2); cancelling inside
//! one part's solve or the transition/mesh assembly (they live in
//! `character::assembly`, which has no cancel hook; how long a cancel waits is
//! the longer of the two: `benches/tui.rs` `cancel_wait_*`); a force,
//! boundary or plate edit checked on the worker (`edit::push_checked`)
//! solves every part without the part cache and is not interruptible.

pub mod app;
pub mod autosave;
pub mod commands;
pub mod fit;
pub mod history;
pub mod keys;
pub mod kitty;
pub mod params;
mod popup;
pub mod preview;
pub mod prompt;
pub mod term;
pub mod view;
pub mod worker;

pub use app::App;
pub use term::{run, Options};

/// Errors of the TUI.
#[derive(Debug, thiserror::Error)]
pub enum TuiError {
    #[error(transparent)]
    Doc(#[from] crate::character::doc::DocError),
    #[error("no bundled example '{0}' (female, male)")]
    Bundled(String),
    #[error("terminal: {0}")]
    Terminal(#[from] std::io::Error),
    #[error("the TUI needs a terminal: its standard output is not one (a pipe or a file)")]
    NotATerminal,
}
