//! What every figure shares: the output directory, atomic writes, the data
//! JSON, and the bundled font for plotters (DejaVu Sans, see
//! `assets/DejaVuSans-LICENSE.txt`), so no system font library is needed.

#![allow(dead_code)] // helpers are used by the family figure modules as they grow

use std::path::{Path, PathBuf};
use std::sync::Once;

/// A figure or table of a paper.
pub struct Figure {
    /// Stable id, e.g. `"002-table1"`, `"000-fig3"`.
    pub id: &'static str,
    /// Paper file number.
    pub paper: &'static str,
    pub title: &'static str,
    pub run: fn(&Ctx) -> anyhow::Result<()>,
}

/// Where figures go.
pub struct Ctx {
    pub out: PathBuf,
}

static FONT: Once = Once::new();

/// Registers the bundled font under the family name `"sans-serif"`.
pub fn register_font() {
    FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../assets/DejaVuSans.ttf");
        for style in [
            plotters::style::FontStyle::Normal,
            plotters::style::FontStyle::Bold,
            plotters::style::FontStyle::Italic,
            plotters::style::FontStyle::Oblique,
        ] {
            let _ = plotters::style::register_font("sans-serif", style, bytes);
        }
    });
}

impl Ctx {
    /// Creates the output directory.
    pub fn new(out: PathBuf) -> anyhow::Result<Ctx> {
        std::fs::create_dir_all(&out)?;
        register_font();
        Ok(Ctx { out })
    }

    /// Path of an output file.
    pub fn path(&self, name: &str) -> PathBuf {
        self.out.join(name)
    }

    /// Runs one figure, reporting on stderr.
    pub fn run(&self, f: &Figure) -> anyhow::Result<()> {
        eprintln!("[{}] {}", f.id, f.title);
        let t = std::time::Instant::now();
        (f.run)(self).map_err(|e| e.context(format!("figure {}", f.id)))?;
        eprintln!("[{}] done in {:.1} s", f.id, t.elapsed().as_secs_f64());
        Ok(())
    }

    /// Writes a data JSON atomically.
    pub fn write_json<T: serde::Serialize>(
        &self,
        name: &str,
        value: &T,
    ) -> anyhow::Result<PathBuf> {
        let p = self.path(name);
        let bytes = serde_json::to_vec_pretty(value)?;
        pdesculpt::mesh::io::write_atomic(&p, &bytes)?;
        eprintln!("  wrote {}", p.display());
        Ok(p)
    }

    /// Writes any bytes atomically.
    pub fn write_bytes(&self, name: &str, bytes: &[u8]) -> anyhow::Result<PathBuf> {
        let p = self.path(name);
        pdesculpt::mesh::io::write_atomic(&p, bytes)?;
        eprintln!("  wrote {}", p.display());
        Ok(p)
    }
}

/// A path relative to the workspace root.
pub fn workspace_path(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(rel)
}
