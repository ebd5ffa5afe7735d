//! Figures of the gec family: the analogue of paper 002 Table 1 (ErM, ErA
//! per J on MakeHuman cross sections, with the parameter-choice study) and
//! of paper 000 Fig 3 (original section, GEC, standard ellipse).

use crate::common::{Ctx, Figure, PlotPng};
use pdesculpt::curve::gec::metrics::errors;
use pdesculpt::curve::gec::study::{self, BodySection, StudyRow, TABLE1_TERMS};
use pdesculpt::curve::gec::{fit, FitOptions, Gec, Param};
use plotters::prelude::*;

/// Paper 002 Table 1 as printed (n, ErM, ErA; units not stated).
const PAPER_TABLE1: [(usize, f64, f64); 5] = [
    (1, 0.065371, 0.044169),
    (3, 0.040636, 0.012367),
    (5, 0.010601, 0.007068),
    (7, 0.005312, 0.001767),
    (10, 0.002534, 0.000883),
];

/// Terms of the GEC drawn in the Fig 3 analogue.
const FIG3_TERMS: usize = 7;

/// The figures of the gec family.
pub fn figures() -> Vec<Figure> {
    vec![
        Figure {
            id: "002-table1",
            paper: "002",
            title: "GEC fitting errors ErM/ErA per J on MakeHuman cross sections",
            run: table1,
        },
        Figure {
            id: "000-fig3",
            paper: "000",
            title: "Original cross sections, GECs and standard ellipses (MakeHuman)",
            run: fig3,
        },
    ]
}

#[derive(serde::Serialize)]
struct MeanRow {
    terms: usize,
    param: &'static str,
    erm_rel_mean: f64,
    erm_rel_max: f64,
    era_rel_mean: f64,
    erm_mean: f64,
    era_mean: f64,
}

fn means(rows: &[StudyRow], j: usize, p: &'static str) -> MeanRow {
    let sel: Vec<&StudyRow> = rows
        .iter()
        .filter(|r| r.terms == j && r.param == p)
        .collect();
    let n = sel.len().max(1) as f64;
    MeanRow {
        terms: j,
        param: p,
        erm_rel_mean: sel.iter().map(|r| r.erm_rel).sum::<f64>() / n,
        erm_rel_max: sel.iter().map(|r| r.erm_rel).fold(0.0, f64::max),
        era_rel_mean: sel.iter().map(|r| r.era_rel).sum::<f64>() / n,
        erm_mean: sel.iter().map(|r| r.erm).sum::<f64>() / n,
        era_mean: sel.iter().map(|r| r.era).sum::<f64>() / n,
    }
}

fn table1(ctx: &Ctx) -> anyhow::Result<()> {
    let secs = study::base_sections()?;
    let rows = study::run(&secs, &TABLE1_TERMS, &Param::ALL)?;
    let mut mean_rows = Vec::new();
    for p in Param::ALL {
        for j in TABLE1_TERMS {
            mean_rows.push(means(&rows, j, p.name()));
        }
    }
    // which parameter choice fits best: mean relative ErA over all J and sections
    let score = |p: Param| {
        mean_rows
            .iter()
            .filter(|m| m.param == p.name())
            .map(|m| m.era_rel_mean)
            .sum::<f64>()
    };
    let best = Param::ALL
        .into_iter()
        .min_by(|a, b| score(*a).total_cmp(&score(*b)))
        .unwrap_or_default();
    let def = Param::default();
    let mut md = String::from(
        "| J | ErM (mean, dm) | ErA (mean, dm) | ErM/D mean | ErM/D max | ErA/D mean | paper ErM | paper ErA |\n|---|---|---|---|---|---|---|---|\n",
    );
    for (j, pm, pa) in PAPER_TABLE1 {
        let m = means(&rows, j, def.name());
        md += &format!(
            "| {j} | {:.5} | {:.5} | {:.5} | {:.5} | {:.5} | {pm} | {pa} |\n",
            m.erm_mean, m.era_mean, m.erm_rel_mean, m.erm_rel_max, m.era_rel_mean
        );
    }
    md += "\nParameter choices (sum over J of mean ErA/D):\n\n";
    for p in Param::ALL {
        md += &format!("- {}: {:.5}\n", p.name(), score(p));
    }
    eprintln!("{md}");
    ctx.write_bytes("002-table1.md", md.as_bytes())?;
    ctx.write_json(
        "002-table1.json",
        &serde_json::json!({
            "definition": "ErM = max_k d_k, ErA = mean_k d_k, d_k = distance from the k-th section vertex to the fitted GEC (global minimum over theta); D = in-plane bounding-box diagonal of the section; units: MakeHuman units (decimetres)",
            "default_param": def.name(),
            "best_param_by_mean_era": best.name(),
            "sections": secs.iter().map(|s| serde_json::json!({"name": s.name, "origin": s.origin, "normal": s.normal, "points": s.points.len()})).collect::<Vec<_>>(),
            "paper_table1": PAPER_TABLE1.iter().map(|(n, m, a)| serde_json::json!({"n": n, "ErM": m, "ErA": a})).collect::<Vec<_>>(),
            "means": mean_rows,
            "rows": rows,
        }),
    )?;
    plot_table1(ctx, &rows)?;
    Ok(())
}

fn plot_table1(ctx: &Ctx, rows: &[StudyRow]) -> anyhow::Result<()> {
    let path = ctx.path("002-table1.png");
    {
        let mut plot = PlotPng::new((900, 600));
        {
            let root = plot.area();
            root.fill(&WHITE)?;
            let mut chart = ChartBuilder::on(&root)
                .caption(
                    "GEC fit errors on MakeHuman sections (relative to section diagonal)",
                    ("sans-serif", 20),
                )
                .margin(15)
                .x_label_area_size(40)
                .y_label_area_size(70)
                .build_cartesian_2d(0.5f64..10.5f64, (3e-4f64..0.2f64).log_scale())?;
            chart
                .configure_mesh()
                .x_desc("J (terms)")
                .y_desc("error / D")
                .label_style(("sans-serif", 14))
                .draw()?;
            let colours = [RED, BLUE, GREEN, MAGENTA];
            for (i, p) in Param::ALL.iter().enumerate() {
                let c = colours[i];
                let erm: Vec<(f64, f64)> = TABLE1_TERMS
                    .iter()
                    .map(|&j| (j as f64, means(rows, j, p.name()).erm_rel_mean.max(3e-4)))
                    .collect();
                let era: Vec<(f64, f64)> = TABLE1_TERMS
                    .iter()
                    .map(|&j| (j as f64, means(rows, j, p.name()).era_rel_mean.max(3e-4)))
                    .collect();
                chart
                    .draw_series(LineSeries::new(erm.clone(), c.stroke_width(2)))?
                    .label(format!("ErM/D {}", p.name()))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                    });
                chart.draw_series(erm.iter().map(|p| Circle::new(*p, 4, c.filled())))?;
                chart
                    .draw_series(LineSeries::new(era.clone(), c.stroke_width(1)))?
                    .label(format!("ErA/D {}", p.name()))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(1))
                    });
                chart.draw_series(era.iter().map(|p| TriangleMarker::new(*p, 4, c.filled())))?;
            }
            let pm: Vec<(f64, f64)> = PAPER_TABLE1
                .iter()
                .map(|(n, m, _)| (*n as f64, *m))
                .collect();
            let pa: Vec<(f64, f64)> = PAPER_TABLE1
                .iter()
                .map(|(n, _, a)| (*n as f64, *a))
                .collect();
            chart
                .draw_series(LineSeries::new(pm, BLACK.stroke_width(2)))?
                .label("paper 002 ErM (units unstated)")
                .legend(|(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2))
                });
            chart
                .draw_series(LineSeries::new(pa, BLACK.mix(0.5).stroke_width(1)))?
                .label("paper 002 ErA")
                .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.mix(0.5)));
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .label_font(("sans-serif", 12))
                .position(SeriesLabelPosition::LowerLeft)
                .draw()?;
            root.present()?;
        }
        plot.save(&path)?;
    }
    eprintln!("  wrote {}", path.display());
    Ok(())
}

#[derive(serde::Serialize)]
struct Fig3Panel {
    section: String,
    terms: usize,
    gec_erm: f64,
    gec_era: f64,
    ellipse_erm: f64,
    ellipse_era: f64,
    lsq_ellipse_erm: f64,
    lsq_ellipse_era: f64,
    gec: Gec,
}

fn fig3(ctx: &Ctx) -> anyhow::Result<()> {
    let secs = study::base_sections()?;
    let chosen = [
        "torso_chest",
        "torso_hips",
        "neck",
        "head",
        "upper_arm",
        "thigh",
    ];
    let sel: Vec<&BodySection> = chosen
        .iter()
        .filter_map(|n| secs.iter().find(|s| s.name == *n))
        .collect();
    let path = ctx.path("000-fig3.png");
    let mut panels = Vec::new();
    {
        let mut plot = PlotPng::new((1200, 800));
        {
            let root = plot.area();
            root.fill(&WHITE)?;
            let areas = root.split_evenly((2, 3));
            for (s, area) in sel.iter().zip(areas.iter()) {
                let r = fit(&s.points, &FitOptions::new(FIG3_TERMS))?;
                let r1 = fit(&s.points, &FitOptions::new(1))?;
                let ell = study::silhouette_ellipse(r.gec.frame, &r.plane_points);
                let e_ell = errors(&ell, &r.plane_points);
                panels.push(Fig3Panel {
                    section: s.name.clone(),
                    terms: FIG3_TERMS,
                    gec_erm: r.errors.erm,
                    gec_era: r.errors.era,
                    ellipse_erm: e_ell.erm,
                    ellipse_era: e_ell.era,
                    lsq_ellipse_erm: r1.errors.erm,
                    lsq_ellipse_era: r1.errors.era,
                    gec: r.gec.clone(),
                });
                let orig: Vec<(f64, f64)> = r.plane_points.iter().map(|p| (p[0], p[1])).collect();
                let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
                for p in &orig {
                    lo = lo.min(p.0.min(p.1));
                    hi = hi.max(p.0.max(p.1));
                }
                let pad = 0.08 * (hi - lo);
                let (cx, cy) = {
                    let n = orig.len() as f64;
                    (
                        orig.iter().map(|p| p.0).sum::<f64>() / n,
                        orig.iter().map(|p| p.1).sum::<f64>() / n,
                    )
                };
                let half = 0.5 * (hi - lo) + pad;
                let mut chart = ChartBuilder::on(area)
                    .caption(
                        format!("{} (GEC J={FIG3_TERMS})", s.name),
                        ("sans-serif", 16),
                    )
                    .margin(8)
                    .x_label_area_size(25)
                    .y_label_area_size(35)
                    .build_cartesian_2d(cx - half..cx + half, cy - half..cy + half)?;
                chart
                    .configure_mesh()
                    .label_style(("sans-serif", 10))
                    .draw()?;
                let close = |mut v: Vec<(f64, f64)>| {
                    if let Some(f) = v.first().copied() {
                        v.push(f);
                    }
                    v
                };
                let g: Vec<(f64, f64)> = r
                    .gec
                    .sample_plane(400)
                    .iter()
                    .map(|p| (p[0], p[1]))
                    .collect();
                let e: Vec<(f64, f64)> =
                    ell.sample_plane(400).iter().map(|p| (p[0], p[1])).collect();
                let key = |c: RGBColor| {
                    move |(x, y): (i32, i32)| {
                        PathElement::new([(x, y), (x + 16, y)], c.stroke_width(2))
                    }
                };
                chart
                    .draw_series(LineSeries::new(close(e), BLUE.stroke_width(2)))?
                    .label("standard ellipse")
                    .legend(key(BLUE));
                chart
                    .draw_series(LineSeries::new(close(orig), RED.stroke_width(3)))?
                    .label("MakeHuman section")
                    .legend(key(RED));
                chart
                    .draw_series(LineSeries::new(close(g), GREEN.stroke_width(2)))?
                    .label(format!("GEC, J = {FIG3_TERMS}"))
                    .legend(key(GREEN));
                chart
                    .configure_series_labels()
                    .label_font(("sans-serif", 10))
                    .background_style(WHITE.mix(0.8))
                    .border_style(BLACK)
                    .position(SeriesLabelPosition::LowerRight)
                    .draw()?;
            }
            root.present()?;
        }
        plot.save(&path)?;
    }
    eprintln!("  wrote {}", path.display());
    ctx.write_json(
        "000-fig3.json",
        &serde_json::json!({
            "colours": {"original": "red", "gec": "green", "standard_ellipse": "blue"},
            "standard_ellipse": "axis-aligned in the section frame, semi-axes half the in-plane bounding box (paper 000's silhouette ellipses); lsq_ellipse_* is the best general ellipse (J = 1 least squares)",
            "units": "MakeHuman units (decimetres); in-plane coordinates of each section's fitted frame",
            "panels": panels,
        }),
    )?;
    Ok(())
}
