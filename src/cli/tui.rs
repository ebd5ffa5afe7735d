//! `pdesculpt tui [CHAR.json] [--bundled female|male] [--preview-rings N]`.

use pdesculpt::tui::term::{preview_resolution, PREVIEW_RINGS};
use pdesculpt::tui::{self, Options};
use std::path::PathBuf;

/// Arguments of `pdesculpt tui`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The character document; when it does not exist, the TUI starts from
    /// a bundled example and creates the file on the first save.
    #[arg(default_value = "character.json")]
    pub doc: PathBuf,
    /// Bundled example a new document starts from.
    #[arg(long, default_value = "female")]
    pub bundled: String,
    /// Preview rebuild resolution in rings per model height (exports use
    /// the default resolution of `character build`).
    #[arg(long, default_value_t = PREVIEW_RINGS)]
    pub preview_rings: f64,
}

/// Runs `tui`.
pub fn run(a: Args, _json: bool) -> anyhow::Result<i32> {
    if !(a.preview_rings.is_finite() && (8.0..=400.0).contains(&a.preview_rings)) {
        anyhow::bail!(
            "--preview-rings must be in [8, 400], got {}",
            a.preview_rings
        );
    }
    let preview = preview_resolution(a.preview_rings);
    tui::run(Options::new(a.doc, a.bundled).with_preview(preview))?;
    Ok(0)
}
