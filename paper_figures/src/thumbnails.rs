//! `paper_figures thumbnails`: small copies of a few figures and of the
//! demo picture for the repository's docs (`docs/img/`), so that a reader
//! sees them without building anything. Each is the figure's PNG from the
//! output directory with its white margins trimmed, scaled down by an
//! integer box filter to at most [`MAX_WIDTH`] pixels wide.

use anyhow::Context;
use pdesculpt::render::Image;
use std::path::Path;

/// Widest thumbnail in pixels (chosen so that three fit side by side in a
/// README table and the set stays well under a megabyte).
pub const MAX_WIDTH: usize = 480;

/// `(source in the output directory, target under docs/img/)`.
pub const THUMBNAILS: &[(&str, &str)] = &[
    ("000-fig6.png", "figures/000-fig6.png"),
    ("002-fig6.png", "figures/002-fig6.png"),
    ("004-fig6.png", "figures/004-fig6.png"),
    ("003-fig7.png", "figures/003-fig7.png"),
    ("001-fig11-square-shapes.png", "figures/001-fig11.png"),
    ("000-fig13.png", "figures/000-fig13.png"),
];

/// Reads an RGB or RGBA 8-bit PNG.
pub fn read_png(path: &Path) -> anyhow::Result<Image> {
    let file = std::fs::File::open(path).with_context(|| format!("{}", path.display()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info()?;
    let size = reader
        .output_buffer_size()
        .context("image too large to decode")?;
    let mut buf = vec![0; size];
    let info = reader.next_frame(&mut buf)?;
    let (w, h) = (info.width as usize, info.height as usize);
    let channels = match info.color_type {
        png::ColorType::Rgba => 4,
        png::ColorType::Rgb => 3,
        png::ColorType::GrayscaleAlpha => 2,
        png::ColorType::Grayscale => 1,
        png::ColorType::Indexed => {
            anyhow::bail!("{}: indexed colour after expansion", path.display())
        }
    };
    let mut img = Image::new(w, h, [255; 4]);
    for y in 0..h {
        for x in 0..w {
            let p = &buf[y * info.line_size + x * channels..][..channels];
            let c = match channels {
                4 => [p[0], p[1], p[2], p[3]],
                3 => [p[0], p[1], p[2], 255],
                2 => [p[0], p[0], p[0], p[1]],
                _ => [p[0], p[0], p[0], 255],
            };
            img.put(x as i64, y as i64, c);
        }
    }
    Ok(img)
}

/// The bounding box `(x0, y0, x1, y1)` (exclusive ends) of the pixels that
/// are not near-white, grown by `pad`; the whole image when all are white.
fn content_box(img: &Image, pad: usize) -> (usize, usize, usize, usize) {
    let (mut x0, mut y0, mut x1, mut y1) = (img.width, img.height, 0, 0);
    for y in 0..img.height {
        for x in 0..img.width {
            let c = img.get(x, y);
            if c[3] > 0 && (c[0] < 245 || c[1] < 245 || c[2] < 245) {
                (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x + 1), y1.max(y + 1));
            }
        }
    }
    if x1 <= x0 || y1 <= y0 {
        return (0, 0, img.width, img.height);
    }
    (
        x0.saturating_sub(pad),
        y0.saturating_sub(pad),
        (x1 + pad).min(img.width),
        (y1 + pad).min(img.height),
    )
}

/// `img` trimmed to its content and reduced by the smallest integer factor
/// that brings it to at most `max_width` pixels (box filter).
pub fn thumbnail(img: &Image, max_width: usize) -> Image {
    let (x0, y0, x1, y1) = content_box(img, 6);
    let (w, h) = (x1 - x0, y1 - y0);
    let f = w.div_ceil(max_width.max(1)).max(1);
    let (tw, th) = (w / f, h / f);
    let mut out = Image::new(tw.max(1), th.max(1), [255; 4]);
    for ty in 0..th {
        for tx in 0..tw {
            let mut acc = [0u32; 4];
            for dy in 0..f {
                for dx in 0..f {
                    let c = img.get(x0 + tx * f + dx, y0 + ty * f + dy);
                    for k in 0..4 {
                        acc[k] += c[k] as u32;
                    }
                }
            }
            let n = (f * f) as u32;
            out.put(tx as i64, ty as i64, acc.map(|a| (a / n) as u8));
        }
    }
    out
}

/// Writes the thumbnails of [`THUMBNAILS`] from `out` into `docs/img/`
/// (and `docs/img/demo.png` from the demo's `demo.png` in `demo_dir`,
/// 600 pixels wide) under `docs`.
pub fn write(out: &Path, demo_dir: &Path, docs: &Path) -> anyhow::Result<()> {
    let img_dir = docs.join("img");
    std::fs::create_dir_all(img_dir.join("figures"))?;
    let mut jobs: Vec<(std::path::PathBuf, std::path::PathBuf, usize)> = THUMBNAILS
        .iter()
        .map(|(src, dst)| (out.join(src), img_dir.join(dst), MAX_WIDTH))
        .collect();
    jobs.push((demo_dir.join("demo.png"), img_dir.join("demo.png"), 600));
    for (src, dst, width) in jobs {
        let img = read_png(&src)
            .with_context(|| format!("{} (run the figure or the demo first)", src.display()))?;
        let t = thumbnail(&img, width);
        t.save_png(&dst)?;
        eprintln!("  wrote {} ({} x {})", dst.display(), t.width, t.height);
    }
    Ok(())
}
