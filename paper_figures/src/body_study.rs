//! Figures of the closed body's studies (issue 15):
//!
//! * `000-fig13`: the data-size study (`pdesculpt::body::study`):
//!   error against the numbers stored, log axes, for PDE6, ODE6 and a loft
//!   through the same sections at three densities, beside the mesh's vertex
//!   coordinates; a markdown table per part.
//! * `002-table1-corrected`: the GEC fit of the MakeHuman sections before
//!   (chord length, the old default) and after parameter correction (the
//!   default) at the same J (`curve::gec::study::correction_study`).

use crate::common::{Ctx, Figure, PlotPng};
use pdesculpt::body::closed::ClosedOptions;
use pdesculpt::body::study::{data_size_study, StudyRow, DENSITIES, METHODS};
use pdesculpt::curve::gec::study::{base_sections, correction_study, TABLE1_TERMS};
use pdesculpt::curve::gec::Param;
use plotters::prelude::*;

/// The figures of this module.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "000-fig13",
            paper: "000",
            title: "Data size against error: PDE6, ODE6 and a loft through the same sections of the MakeHuman body",
            run: fig13,
        },
        Figure {
            id: "002-table1-corrected",
            paper: "002",
            title: "GEC fits of the MakeHuman sections before and after parameter correction",
            run: table1_corrected,
        },
    ]
}

fn pct(x: f64) -> String {
    format!("{:.3}", 100.0 * x)
}

fn fig13(ctx: &Ctx) -> anyhow::Result<()> {
    let skin = pdesculpt::makehuman::base_body()?.mesh;
    let rows = data_size_study(&skin, &DENSITIES, &ClosedOptions::default())?;
    let mut md = String::from(
        "| density | surface | part | sections | numbers stored | mesh coordinates | ratio | recon->skin RMS / max (% h) | skin->recon RMS / max (% h) |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in &rows {
        md += &format!(
            "| {} | {} | {} | {} | {} | {} | {:.1} | {} / {} | {} / {} |\n",
            r.density,
            r.method,
            r.part,
            r.sections,
            r.stored_numbers,
            r.mesh_numbers,
            r.mesh_numbers as f64 / r.stored_numbers.max(1) as f64,
            pct(r.recon_to_skin_rms_rel),
            pct(r.recon_to_skin_max_rel),
            pct(r.skin_to_recon_rms_rel),
            pct(r.skin_to_recon_max_rel),
        );
    }
    eprintln!("{md}");
    ctx.write_bytes("000-fig13.md", md.as_bytes())?;
    ctx.write_json(
        "000-fig13.json",
        &serde_json::json!({
            "definition": "numbers stored: per fitted GEC section 1 (u) + 9 (frame) + 2 (centre) + 4J, per collapsed tip 4, plus the surface's parameters (pde6 a, ode6 rho/eta/lambda, loft none); mesh coordinates: 3 per skin vertex (the body) or per skin vertex nearest to the part's tube; errors relative to the body height; recon->skin over tube vertices and triangle centroids, skin->recon over the assigned skin vertices",
            "densities": DENSITIES,
            "rows": rows,
        }),
    )?;
    plot(ctx, &rows)?;
    Ok(())
}

fn plot(ctx: &Ctx, rows: &[StudyRow]) -> anyhow::Result<()> {
    let path = ctx.path("000-fig13.png");
    let body: Vec<&StudyRow> = rows.iter().filter(|r| r.part == "body").collect();
    let mesh = body.first().map_or(1, |r| r.mesh_numbers) as f64;
    {
        let mut plot = PlotPng::new((1000, 650));
        {
            let root = plot.area();
            root.fill(&WHITE)?;
            let (xmin, xmax) = (1e3f64, 1e5f64);
            let (ymin, ymax) = (1e-3f64, 0.2f64);
            let mut chart = ChartBuilder::on(&root)
                .caption(
                    "Whole body: numbers stored against error (MakeHuman base body)",
                    ("sans-serif", 22),
                )
                .margin(15)
                .x_label_area_size(45)
                .y_label_area_size(75)
                .build_cartesian_2d((xmin..xmax).log_scale(), (ymin..ymax).log_scale())?;
            chart
                .configure_mesh()
                .x_desc("numbers stored")
                .y_desc("distance / body height")
                .label_style(("sans-serif", 14))
                .draw()?;
            let styles: [(&str, RGBColor); 4] = [
                ("pde6-closed", BLACK),
                ("pde6", RED),
                ("ode6", BLUE),
                ("loft", GREEN),
            ];
            for (m, c) in styles {
                let sel: Vec<&&StudyRow> = body.iter().filter(|r| r.method == m).collect();
                let rms: Vec<(f64, f64)> = sel
                    .iter()
                    .map(|r| (r.stored_numbers as f64, r.recon_to_skin_rms_rel.max(ymin)))
                    .collect();
                let max: Vec<(f64, f64)> = sel
                    .iter()
                    .map(|r| {
                        // the tubes leave the armpits and the crotch uncovered:
                        // their skin -> recon maximum sits there (table), so
                        // their curve is recon -> skin; the closed body's both ways
                        let m = if r.method == "pde6-closed" {
                            r.recon_to_skin_max_rel.max(r.skin_to_recon_max_rel)
                        } else {
                            r.recon_to_skin_max_rel
                        };
                        (r.stored_numbers as f64, m.clamp(ymin, ymax))
                    })
                    .collect();
                chart
                    .draw_series(LineSeries::new(rms.clone(), c.stroke_width(2)))?
                    .label(format!("{m}: RMS recon->skin"))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                    });
                chart.draw_series(rms.iter().map(|p| Circle::new(*p, 4, c.filled())))?;
                chart
                    .draw_series(LineSeries::new(max.clone(), c.stroke_width(1)))?
                    .label(if m == "pde6-closed" {
                        format!("{m}: max (both ways)")
                    } else {
                        format!("{m}: max recon->skin")
                    })
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(1))
                    });
                chart.draw_series(max.iter().map(|p| TriangleMarker::new(*p, 5, c.filled())))?;
            }
            // the mesh: its vertex coordinates (error 0: a vertical line)
            let grey = RGBColor(120, 120, 120);
            chart
                .draw_series(LineSeries::new(
                    vec![(mesh.min(xmax), ymin), (mesh.min(xmax), ymax)],
                    grey.stroke_width(2),
                ))?
                .label(format!("mesh: {mesh} vertex coordinates"))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], grey.stroke_width(2))
                });
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .position(SeriesLabelPosition::UpperRight)
                .draw()?;
            root.present()?;
        }
        plot.save(&path)?;
    }
    eprintln!("  wrote {}", path.display());
    let _ = METHODS;
    Ok(())
}

fn table1_corrected(ctx: &Ctx) -> anyhow::Result<()> {
    let secs = base_sections()?;
    let rows = correction_study(&secs, &TABLE1_TERMS, Param::ChordLength)?;
    let mut md = String::from(
        "| J | ErM chord (mean, dm) | ErM default (mean, dm) | gain | ErA chord | ErA default | max ErM/D chord | max ErM/D default | sections improved |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for j in TABLE1_TERMS {
        let sel: Vec<_> = rows.iter().filter(|r| r.terms == j).collect();
        let n = sel.len().max(1) as f64;
        let mean = |f: &dyn Fn(&&pdesculpt::curve::gec::study::CorrectionRow) -> f64| {
            sel.iter().map(f).sum::<f64>() / n
        };
        let (mb, ma) = (mean(&|r| r.erm_before), mean(&|r| r.erm_after));
        let (ab, aa) = (mean(&|r| r.era_before), mean(&|r| r.era_after));
        let xb = sel
            .iter()
            .map(|r| r.erm_before / r.scale)
            .fold(0.0, f64::max);
        let xa = sel
            .iter()
            .map(|r| r.erm_after / r.scale)
            .fold(0.0, f64::max);
        let improved = sel.iter().filter(|r| r.erm_after < r.erm_before).count();
        md += &format!(
            "| {j} | {mb:.5} | {ma:.5} | {:.0} % | {ab:.5} | {aa:.5} | {xb:.4} | {xa:.4} | {improved} / {} |\n",
            100.0 * (1.0 - ma / mb),
            sel.len()
        );
    }
    md += "\nPer section at J = 10 (ErM before -> after, data units):\n\n";
    for r in rows.iter().filter(|r| r.terms == 10) {
        md += &format!(
            "- {}: {:.5} -> {:.5} ({:+.0} %), ErA {:.5} -> {:.5}\n",
            r.section,
            r.erm_before,
            r.erm_after,
            100.0 * (r.erm_after / r.erm_before - 1.0),
            r.era_before,
            r.era_after
        );
    }
    eprintln!("{md}");
    ctx.write_bytes("002-table1-corrected.md", md.as_bytes())?;
    ctx.write_json(
        "002-table1-corrected.json",
        &serde_json::json!({
            "before": "chord length, angles as given (Correction::None, the old default)",
            "after": "the default fit (Correction::Best: every rule, corrected, smallest ErM)",
            "rows": rows,
        }),
    )?;
    Ok(())
}
