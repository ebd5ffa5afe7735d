//! Progress on stderr for commands that can run over a second (the CLI and
//! `paper_figures`), drawn with `indicatif`: a spinner with the elapsed
//! time and the current step, or a bar over a known number of steps.
//!
//! Drawn only when stderr is a terminal and the command was not asked for
//! `--json` ([`enabled`]); otherwise every call is a no-op, so logs, pipes
//! and CI output carry no control characters. Lines a command prints while
//! a progress line is shown go through [`Progress::println`], which prints
//! them above it. The TUI keeps its own spinner and does not use this.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

/// Whether progress is drawn: stderr is a terminal and the output is not
/// machine-readable (`--json`).
pub fn enabled(json: bool) -> bool {
    !json && std::io::stderr().is_terminal()
}

/// How often a spinner redraws on its own.
const TICK: Duration = Duration::from_millis(120);

/// A progress line on stderr (or nothing, when not [`enabled`]).
pub struct Progress {
    bar: Option<ProgressBar>,
}

impl Progress {
    /// Nothing drawn.
    pub fn hidden() -> Progress {
        Progress { bar: None }
    }

    /// A spinner with the elapsed time and `message`, redrawn on its own
    /// while the work runs.
    pub fn spinner(message: &str, json: bool) -> Progress {
        if !enabled(json) {
            return Progress::hidden();
        }
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
        bar.set_style(
            ProgressStyle::with_template("{spinner} [{elapsed}] {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_spinner()),
        );
        bar.set_message(message.to_string());
        bar.enable_steady_tick(TICK);
        Progress { bar: Some(bar) }
    }

    /// A bar over `steps` steps with `message`.
    pub fn bar(steps: u64, message: &str, json: bool) -> Progress {
        if !enabled(json) {
            return Progress::hidden();
        }
        let bar = ProgressBar::with_draw_target(Some(steps), ProgressDrawTarget::stderr());
        bar.set_style(
            ProgressStyle::with_template("{spinner} [{elapsed}] {bar:30} {pos}/{len} {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar.set_message(message.to_string());
        bar.enable_steady_tick(TICK);
        Progress { bar: Some(bar) }
    }

    /// Whether anything is drawn.
    pub fn is_drawn(&self) -> bool {
        self.bar.is_some()
    }

    /// Replaces the step shown.
    pub fn set_message(&self, message: &str) {
        if let Some(b) = &self.bar {
            b.set_message(message.to_string());
        }
    }

    /// Advances a bar by `n` steps.
    pub fn inc(&self, n: u64) {
        if let Some(b) = &self.bar {
            b.inc(n);
        }
    }

    /// Prints `line` to stderr (above the progress line when one is shown).
    pub fn println(&self, line: &str) {
        match &self.bar {
            Some(b) => b.suspend(|| eprintln!("{line}")),
            None => eprintln!("{line}"),
        }
    }

    /// Removes the progress line.
    pub fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}
