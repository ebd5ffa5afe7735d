//! The comparisons of sec 5: the error table, Fig 11 and Fig 12.

use super::render_row;
use crate::common::Ctx;
use pdesculpt::mesh::Mesh;
use pdesculpt::plate::baselines::{DeltaMushParams, LaplacianParams};
use pdesculpt::plate::shapes::{compare, sheet, Comparison, Shape};
use pdesculpt::render::{Image, View};
use plotters::prelude::*;

/// Sheet resolution of the comparisons.
const GRID: usize = 60;
/// Height of the unit-peak deflection in the renders (sheet is 2.5 wide).
const RENDER_HEIGHT: f64 = 0.6;

fn run(shape: Shape) -> anyhow::Result<Comparison> {
    Ok(compare(
        shape,
        GRID,
        &DeltaMushParams::default(),
        &LaplacianParams::default(),
    )?)
}

/// The sheet with a normalised deflection field applied along z.
fn deformed(c: &Comparison, w: &[f64]) -> Mesh {
    let mut m = sheet(c.grid);
    for (k, &v) in c.region.iter().enumerate() {
        m.positions[v as usize][2] = RENDER_HEIGHT * w[k];
    }
    m
}

/// Full-grid field (zero outside the region).
fn field(c: &Comparison, w: &[f64]) -> Vec<f64> {
    let n = (c.grid + 1) * (c.grid + 1);
    let mut f = vec![0.0; n];
    for (k, &v) in c.region.iter().enumerate() {
        f[v as usize] = w[k];
    }
    f
}

/// Banded contour map (10 levels of the unit-peak deflection, isolines in
/// black, region outline in red) rasterised from the sheet grid.
fn contour_map(c: &Comparison, w: &[f64], size: usize) -> Image {
    let f = field(c, w);
    let n = c.grid;
    let mut img = Image::new(size, size, [255, 255, 255, 255]);
    let level = |x: f64| -> i64 { (x * 10.0).floor() as i64 };
    let sample = |px: usize, py: usize| -> f64 {
        let gx = px as f64 / (size - 1) as f64 * n as f64;
        let gy = (size - 1 - py) as f64 / (size - 1) as f64 * n as f64;
        let (i, j) = (
            (gx.floor() as usize).min(n - 1),
            (gy.floor() as usize).min(n - 1),
        );
        let (tx, ty) = (gx - i as f64, gy - j as f64);
        let id = |i: usize, j: usize| j * (n + 1) + i;
        f[id(i, j)] * (1.0 - tx) * (1.0 - ty)
            + f[id(i + 1, j)] * tx * (1.0 - ty)
            + f[id(i, j + 1)] * (1.0 - tx) * ty
            + f[id(i + 1, j + 1)] * tx * ty
    };
    let vals: Vec<f64> = (0..size * size)
        .map(|k| sample(k % size, k / size))
        .collect();
    for py in 0..size {
        for px in 0..size {
            let v = vals[py * size + px];
            let l = level(v);
            let iso = (px + 1 < size && level(vals[py * size + px + 1]) != l)
                || (py + 1 < size && level(vals[(py + 1) * size + px]) != l);
            let col = if iso && v > 1e-3 {
                [0, 0, 0, 255]
            } else if v <= 1e-6 {
                [245, 245, 245, 255]
            } else {
                let t = v.clamp(0.0, 1.0);
                [
                    (60.0 + 195.0 * t) as u8,
                    (120.0 + 80.0 * (1.0 - (2.0 * t - 1.0).abs())) as u8,
                    (230.0 - 190.0 * t) as u8,
                    255,
                ]
            };
            img.put(px as i64, py as i64, col);
        }
    }
    // region outline
    let poly = c.shape.polygon();
    let to_px = |p: [f64; 2]| {
        (
            (p[0] + 1.25) / 2.5 * (size - 1) as f64,
            (1.25 - p[1]) / 2.5 * (size - 1) as f64,
        )
    };
    for k in 0..poly.len() {
        let (a, b) = (to_px(poly[k]), to_px(poly[(k + 1) % poly.len()]));
        for s in 0..=400 {
            let t = s as f64 / 400.0;
            img.put(
                (a.0 + t * (b.0 - a.0)).round() as i64,
                (a.1 + t * (b.1 - a.1)).round() as i64,
                [220, 30, 30, 255],
            );
        }
    }
    img
}

/// The row `img` of equal-width panels with one caption above each.
fn with_captions(img: &Image, captions: &[String]) -> anyhow::Result<Image> {
    let bar = 30usize;
    let w = img.width;
    let mut buf = vec![255u8; w * bar * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w as u32, bar as u32)).into_drawing_area();
        root.fill(&WHITE)?;
        let pw = w / captions.len().max(1);
        for (k, c) in captions.iter().enumerate() {
            root.draw(&Text::new(
                c.clone(),
                ((k * pw + 12) as i32, 7),
                ("sans-serif", 16).into_font(),
            ))?;
        }
        root.present()?;
    }
    let mut out = Image::new(w, img.height + bar, [255, 255, 255, 255]);
    for y in 0..bar {
        for x in 0..w {
            let i = (y * w + x) * 3;
            out.put(x as i64, y as i64, [buf[i], buf[i + 1], buf[i + 2], 255]);
        }
    }
    for y in 0..img.height {
        for x in 0..w {
            out.put(x as i64, (y + bar) as i64, img.get(x, y));
        }
    }
    Ok(out)
}

fn methods(c: &Comparison) -> [(&'static str, &Vec<f64>); 4] {
    [
        ("ground_truth", &c.truth),
        ("ours", &c.ours),
        ("delta_mush", &c.delta_mush),
        ("laplacian", &c.laplacian),
    ]
}

/// The error table for every shape.
pub fn table(ctx: &Ctx) -> anyhow::Result<()> {
    let mut rows = Vec::new();
    let mut md = String::from(
        "| shape | vertices | ours rms | ours max | ours (harmonic map) rms | ours (harmonic map) max | Delta Mush rms | Delta Mush max | Laplacian rms | Laplacian max | ours/truth peak |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for s in Shape::ALL {
        let c = run(s)?;
        let e = |m: &str| {
            c.errors
                .iter()
                .find(|x| x.method == m)
                .map(|x| (x.rms, x.max))
                .unwrap_or((f64::NAN, f64::NAN))
        };
        let (o, hm, d, l) = (
            e("ours"),
            e("ours_harmonic"),
            e("delta_mush"),
            e("laplacian"),
        );
        md.push_str(&format!(
            "| {} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.3} |\n",
            s.name(),
            c.region.len(),
            o.0,
            o.1,
            hm.0,
            hm.1,
            d.0,
            d.1,
            l.0,
            l.1,
            c.amplitude_ratio
        ));
        rows.push(serde_json::json!({
            "shape": s.name(),
            "region_vertices": c.region.len(),
            "errors": c.errors,
            "amplitude_ratio_ours_over_truth": c.amplitude_ratio,
        }));
    }
    let (dm, lap) = (DeltaMushParams::default(), LaplacianParams::default());
    md.push_str(&format!(
        "\nErrors of the unit-peak deflection against the raw Morley FE clamped plate on the region's triangles ({GRID}x{GRID} sheet, q = 1). Laplacian: linearised Sorkine et al. 2004 (no implicit rotations), {:?} weights, handle weight {}; Delta Mush: {} iterations, step {}. Regenerate the table and Figs 1, 8, 9, 11, 12 with\n`cargo run --release -p paper_figures -- 001-table-errors 001-fig11 001-fig12 001-fig8 001-fig9 001-fig1`\n",
        lap.weights, lap.handle_weight, dm.iterations, dm.step
    ));
    eprintln!("{md}");
    ctx.write_bytes("001-table-errors.md", md.as_bytes())?;
    ctx.write_json(
        "001-table-errors.json",
        &serde_json::json!({
            "grid": GRID,
            "normalisation": "every deflection field scaled to unit peak before differencing",
            "ground_truth": "Morley FE clamped plate on the region's triangles, q = 1",
            "laplacian_model": "linearised (Sorkine et al. 2004 without implicit rotations)",
            "delta_mush": DeltaMushParams::default(),
            "laplacian": LaplacianParams::default(),
            "rows": rows,
        }),
    )?;
    Ok(())
}

/// Fig 11: square and pentagram, deformed shapes (row 1) and contour maps
/// (row 2) for the ground truth, ours, Delta Mush, Laplacian.
pub fn fig11(ctx: &Ctx) -> anyhow::Result<()> {
    let mut data = Vec::new();
    for s in [Shape::Square, Shape::Pentagram] {
        let c = run(s)?;
        let ms = methods(&c);
        let meshes: Vec<Mesh> = ms.iter().map(|(_, w)| deformed(&c, w)).collect();
        let outline: Vec<[f64; 3]> = s.polygon().iter().map(|p| [p[0], p[1], 0.0]).collect();
        let row: Vec<(&Mesh, Vec<[f64; 3]>)> =
            meshes.iter().map(|m| (m, outline.clone())).collect();
        let shapes = render_row(
            &row,
            View::Perspective {
                yaw: 30.0,
                pitch: 35.0,
            },
            360,
        );
        let contours: Vec<Image> = ms.iter().map(|(_, w)| contour_map(&c, w, 360)).collect();
        let contour_row = Image::hstack(&contours, [255, 255, 255, 255]);
        let captions: Vec<String> = ms
            .iter()
            .map(|(m, _)| match c.errors.iter().find(|e| e.method == *m) {
                Some(e) => format!("{m}  rms {:.3} max {:.3}", e.rms, e.max),
                None => format!("{m} (FE)"),
            })
            .collect();
        let shapes = with_captions(&shapes, &captions)?;
        let contour_row = with_captions(&contour_row, &captions)?;
        ctx.write_bytes(
            &format!("001-fig11-{}-shapes.png", s.name()),
            &shapes.encode_png(),
        )?;
        ctx.write_bytes(
            &format!("001-fig11-{}-contours.png", s.name()),
            &contour_row.encode_png(),
        )?;
        data.push(serde_json::json!({
            "shape": s.name(),
            "panels_left_to_right": ms.iter().map(|m| m.0).collect::<Vec<_>>(),
            "errors": c.errors,
            "contour_levels": "0.1 steps of the unit-peak deflection",
        }));
    }
    ctx.write_json("001-fig11.json", &data)?;
    Ok(())
}

/// Side-view silhouette: for each grid column x, the max of w over y.
fn silhouette(c: &Comparison, w: &[f64]) -> Vec<(f64, f64)> {
    let f = field(c, w);
    let n = c.grid;
    (0..=n)
        .map(|i| {
            let x = -1.25 + 2.5 * i as f64 / n as f64;
            let m = (0..=n).map(|j| f[j * (n + 1) + i]).fold(0.0, f64::max);
            (x, m)
        })
        .collect()
}

/// Fig 12: side views of the triangle and rectangle regions.
pub fn fig12(ctx: &Ctx) -> anyhow::Result<()> {
    let (w, h) = (1100u32, 420u32);
    let mut buf = vec![0u8; (w * h * 3) as usize];
    let mut data = Vec::new();
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        root.fill(&WHITE)?;
        let panels = root.split_evenly((1, 2));
        for (panel, s) in panels.iter().zip([Shape::Triangle, Shape::Rectangle]) {
            let c = run(s)?;
            let mut chart = ChartBuilder::on(panel)
                .caption(
                    format!("{} region, side view (unit peak)", s.name()),
                    ("sans-serif", 20),
                )
                .margin(12)
                .x_label_area_size(35)
                .y_label_area_size(45)
                .build_cartesian_2d(-1.25f64..1.25, 0.0f64..1.1)?;
            chart
                .configure_mesh()
                .x_desc("x")
                .y_desc("max_y w / w_max")
                .label_style(("sans-serif", 14))
                .draw()?;
            let styles = [
                ("ground truth (FE)", BLACK),
                ("ours (eq 12)", RED),
                ("Delta Mush", BLUE),
                ("Laplacian", GREEN),
            ];
            let mut series = Vec::new();
            for ((name, col), (key, wv)) in styles.iter().zip(methods(&c)) {
                let pts = silhouette(&c, wv);
                let col = *col;
                chart
                    .draw_series(LineSeries::new(pts.clone(), col.stroke_width(2)))?
                    .label(*name)
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col));
                series.push(serde_json::json!({ "method": key, "silhouette": pts }));
            }
            chart
                .configure_series_labels()
                .label_font(("sans-serif", 14))
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()?;
            data.push(serde_json::json!({
                "shape": s.name(),
                "errors": c.errors,
                "series": series,
            }));
        }
        root.present()?;
    }
    let img = Image {
        width: w as usize,
        height: h as usize,
        rgba: buf
            .chunks(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect(),
    };
    ctx.write_bytes("001-fig12.png", &img.encode_png())?;
    ctx.write_json("001-fig12.json", &data)?;
    Ok(())
}
