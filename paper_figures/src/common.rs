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
        std::fs::create_dir_all(&out).map_err(|e| {
            anyhow::anyhow!("cannot create the output directory {}: {e}", out.display())
        })?;
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

/// A plot drawn by plotters' bitmap backend in memory and written as a PNG
/// by the crate's own encoder (`Image::save_png`: atomic, one PNG crate).
/// Plotters' file output would build the `image` crate, with a JPEG decoder
/// and a second PNG crate, for nothing else.
///
/// ```ignore
/// let mut plot = PlotPng::new((900, 600));
/// {
///     let root = plot.area();
///     root.fill(&WHITE)?;
///     // ... draw ...
///     root.present()?;
/// }
/// plot.save(&path)?;
/// ```
pub struct PlotPng {
    size: (u32, u32),
    rgb: Vec<u8>,
}

impl PlotPng {
    pub fn new(size: (u32, u32)) -> PlotPng {
        PlotPng::from_rgb(size, vec![0; size.0 as usize * size.1 as usize * 3])
    }

    /// A picture to draw over: `rgb` holds `size.0 * size.1` pixels, rows
    /// from the top, three bytes each.
    pub fn from_rgb(size: (u32, u32), rgb: Vec<u8>) -> PlotPng {
        debug_assert_eq!(rgb.len(), size.0 as usize * size.1 as usize * 3);
        PlotPng { size, rgb }
    }

    /// The drawing area over the whole picture (drop it before `save`).
    pub fn area(
        &mut self,
    ) -> plotters::drawing::DrawingArea<plotters::prelude::BitMapBackend<'_>, plotters::coord::Shift>
    {
        use plotters::prelude::IntoDrawingArea;
        plotters::prelude::BitMapBackend::with_buffer(&mut self.rgb, self.size).into_drawing_area()
    }

    /// The picture as an opaque image.
    pub fn into_image(self) -> pdesculpt::render::Image {
        let rgba = self
            .rgb
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        pdesculpt::render::Image {
            width: self.size.0 as usize,
            height: self.size.1 as usize,
            rgba,
        }
    }

    /// Writes the picture (opaque) to `path`.
    pub fn save(self, path: &Path) -> anyhow::Result<()> {
        self.into_image().save_png(path)?;
        Ok(())
    }
}
