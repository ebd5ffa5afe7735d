//! Table 1 in the spirit of paper 004: the MakeHuman body's left leg, head
//! and face (front half of the head) cut into horizontal cross sections, each
//! resampled to `m` points and interpolated (closed: trigonometrically; face:
//! open natural splines) or, for the closed regions, fitted by a GEC of J
//! terms (`crate::curve::gec::fit`, theta = 0 forward on every section;
//! 4J + 3 scalars per section), joined by a C2 chain of ODE6 patches
//! (derivative curves from finite differences of the sections), and compared
//! with the polygon region: vertex counts (the paper's counting: positions,
//! first and second derivatives per curve vertex; a GEC section counts as
//! (4J + 3)/3 vertices) and the reconstruction error both ways, beside a
//! natural-spline loft through the same sections.

use super::{sections_from, NU};
use crate::common::Ctx;
use pdesculpt::mesh::dist;
use pdesculpt::mesh::metrics::{point_distances, stats};
use pdesculpt::mesh::slice::{slice, Polyline};
use pdesculpt::ode6::boundary::trig_interpolate;
use pdesculpt::ode6::{Basis, Chain, Curve, Params};
use pdesculpt::surface::{tessellate, Tessellation};
use serde_json::json;

/// Resamples a closed loop to `m` points equally spaced in arc length,
/// starting at its front-most point (max z), turning counter-clockwise
/// about +y.
fn resample(loop_: &Polyline, m: usize) -> Vec<[f64; 3]> {
    let mut p = loop_.points.clone();
    // Orientation: signed area in the (z, x) plane.
    let n = p.len();
    let area: f64 = (0..n)
        .map(|i| p[i][2] * p[(i + 1) % n][0] - p[(i + 1) % n][2] * p[i][0])
        .sum();
    if area < 0.0 {
        p.reverse();
    }
    let start = (0..n)
        .max_by(|&a, &b| p[a][2].total_cmp(&p[b][2]))
        .unwrap_or(0);
    p.rotate_left(start);
    let len = loop_.length();
    let mut out = Vec::with_capacity(m);
    let mut acc = 0.0;
    let mut i = 0;
    for k in 0..m {
        let target = len * k as f64 / m as f64;
        while i < n && acc + dist(p[i], p[(i + 1) % n]) < target {
            acc += dist(p[i], p[(i + 1) % n]);
            i += 1;
        }
        let (a, b) = (p[i % n], p[(i + 1) % n]);
        let seg = dist(a, b).max(f64::MIN_POSITIVE);
        let t = ((target - acc) / seg).clamp(0.0, 1.0);
        out.push([
            a[0] + t * (b[0] - a[0]),
            a[1] + t * (b[1] - a[1]),
            a[2] + t * (b[2] - a[2]),
        ]);
    }
    out
}

struct Region {
    name: &'static str,
    y: (f64, f64),
    /// Picks the loop of the region among a slice's loops.
    pick: fn(&[Polyline]) -> Option<Polyline>,
    /// Keep only the front half (z above the loop centroid): open curves.
    front: bool,
}

/// The front arc (z above the centroid) of a loop, resampled to `m` points.
fn front_arc(l: &Polyline, m: usize) -> Vec<[f64; 3]> {
    let dense = resample(l, 8 * m);
    let cz = l.centroid()[2];
    let n = dense.len();
    // Walk backwards and forwards from the front-most point (index 0).
    let mut lo = 0usize;
    while lo + 1 < n && dense[(n - lo - 1) % n][2] > cz {
        lo += 1;
    }
    let mut hi = 0usize;
    while hi + 1 < n && dense[(hi + 1) % n][2] > cz {
        hi += 1;
    }
    let arc: Vec<[f64; 3]> = (0..=lo + hi).map(|k| dense[(n + k - lo) % n]).collect();
    let poly = Polyline {
        points: arc,
        closed: false,
    };
    let len = poly.length();
    let mut out = Vec::with_capacity(m);
    let (mut acc, mut i) = (0.0, 0usize);
    for k in 0..m {
        let target = len * k as f64 / (m - 1) as f64;
        while i + 2 < poly.points.len() && acc + dist(poly.points[i], poly.points[i + 1]) < target {
            acc += dist(poly.points[i], poly.points[i + 1]);
            i += 1;
        }
        let (a, b) = (poly.points[i], poly.points[i + 1]);
        let t = ((target - acc) / dist(a, b).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
        out.push([
            a[0] + t * (b[0] - a[0]),
            a[1] + t * (b[1] - a[1]),
            a[2] + t * (b[2] - a[2]),
        ]);
    }
    out
}

fn left_leg(loops: &[Polyline]) -> Option<Polyline> {
    // The loop with centroid x > 0 nearest the body's midline (hands are further out).
    loops
        .iter()
        .filter(|l| l.closed && l.centroid()[0] > 0.0)
        .min_by(|a, b| a.centroid()[0].total_cmp(&b.centroid()[0]))
        .cloned()
}

fn longest(loops: &[Polyline]) -> Option<Polyline> {
    loops
        .iter()
        .filter(|l| l.closed)
        .max_by(|a, b| a.length().total_cmp(&b.length()))
        .cloned()
}

/// A closed loop fitted by a GEC of `j` terms (paper 000 eq 16) in the
/// horizontal plane at height `y`, axes front (+z) and +x so that theta = 0
/// points forward on every section, from `m` arc-length samples starting at
/// the front-most point.
fn gec_section(l: &Polyline, m: usize, j: usize, y: f64) -> anyhow::Result<Curve> {
    use pdesculpt::curve::gec::{fit, FitOptions, Frame, FrameChoice};
    let frame = Frame::new([0.0, y, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0])?;
    let opts = FitOptions::new(j).with_frame(FrameChoice::Given(frame));
    let rep = fit(&resample(l, m), &opts)?;
    Ok(Curve::from_gec(&rep.gec)?)
}

pub fn table1(ctx: &Ctx) -> anyhow::Result<()> {
    let body = pdesculpt::makehuman::base_body()?.mesh;
    let (lo, hi) = body.bbox();
    let h = hi[1] - lo[1];
    let regions = [
        Region {
            name: "left leg (knee to upper thigh and calf)",
            y: (lo[1] + 0.12 * h, lo[1] + 0.42 * h),
            pick: left_leg,
            front: false,
        },
        Region {
            name: "head (chin to crown, face and skull)",
            y: (lo[1] + 0.885 * h, lo[1] + 0.975 * h),
            pick: longest,
            front: false,
        },
        Region {
            name: "face (front half of the head, open curves)",
            y: (lo[1] + 0.885 * h, lo[1] + 0.965 * h),
            pick: longest,
            front: true,
        },
    ];
    let mut rows = Vec::new();
    for r in &regions {
        let mut configs: Vec<(usize, usize, Option<usize>)> =
            [(6usize, 16usize), (8, 24), (12, 32), (16, 48)]
                .iter()
                .map(|&(k, m)| (k, m, None))
                .collect();
        if !r.front {
            // Closed sections as fitted GECs (crate::curve::gec) of J terms.
            configs.extend([(12, 96, Some(6)), (12, 96, Some(12))]);
        }
        for (k, m, gec_terms) in configs {
            let ys: Vec<f64> = (0..k)
                .map(|i| r.y.0 + (r.y.1 - r.y.0) * i as f64 / (k - 1) as f64)
                .collect();
            let mut secs: Vec<Curve> = Vec::new();
            let mut centroids = Vec::new();
            let mut radius = 0.0f64;
            for &y in &ys {
                let loops = slice(&body, [0.0, y, 0.0], [0.0, 1.0, 0.0]);
                let l = (r.pick)(&loops)
                    .ok_or_else(|| anyhow::anyhow!("no loop at y = {y} for {}", r.name))?;
                let c = l.centroid();
                radius = radius.max(l.points.iter().map(|p| dist(*p, c)).fold(0.0, f64::max));
                centroids.push(c);
                secs.push(if let Some(j) = gec_terms {
                    gec_section(&l, m, j, y)?
                } else if r.front {
                    Curve::from_polyline(&front_arc(&l, m), false)?
                } else {
                    Curve::Fourier(trig_interpolate(&resample(&l, m)))
                });
            }
            let sections = sections_from(&secs);
            let bases = (0..k - 1)
                .map(|_| Basis::new(Params::new(1.0, 3.0, 1.0)))
                .collect::<Result<Vec<_>, _>>()?;
            let chain = Chain::from_sections(&sections, bases)?;
            let rec = tessellate(
                &chain,
                Tessellation {
                    nu: (k - 1) * NU / 4,
                    nv: 2 * m,
                },
            );
            // Polygon vertices of the region: within the y range, near the slice centroids.
            let region_vertices: Vec<[f64; 3]> = body
                .positions
                .iter()
                .copied()
                .filter(|p| {
                    if p[1] < r.y.0 || p[1] > r.y.1 {
                        return false;
                    }
                    let i = (((p[1] - r.y.0) / (r.y.1 - r.y.0) * (k - 1) as f64).round() as usize)
                        .min(k - 1);
                    let c = centroids[i];
                    ((p[0] - c[0]).powi(2) + (p[2] - c[2]).powi(2)).sqrt() < 1.5 * radius
                        && (!r.front || p[2] > c[2])
                })
                .collect();
            let to_rec = stats(&point_distances(&region_vertices, &rec));
            let to_orig = stats(&point_distances(&rec.positions, &body));
            // Baseline: a natural-spline loft through the same sections.
            let knots: Vec<f64> = (0..k).map(|i| i as f64).collect();
            let refs: Vec<&Curve> = secs.iter().collect();
            let lofted = super::loft(&refs, &knots, (k - 1) * NU / 4, 2 * m)?;
            let loft_to_rec = stats(&point_distances(&region_vertices, &lofted));
            // Stored scalars per section: 3 per resampled point, or the
            // GEC's centre and 4J coefficients plus its plane's height.
            let section_scalars = match gec_terms {
                Some(j) => 4 * j + 3,
                None => 3 * m,
            };
            // "Curve vertices" in scalar-equivalent units (3 scalars each).
            let curve_vertices = k * section_scalars / 3;
            let paper_variables = k * section_scalars;
            rows.push(json!({
                "region": r.name,
                "sections": k,
                "points_per_section": m,
                "section": match gec_terms {
                    Some(j) => format!("GEC J = {j} (fit to {m} points)"),
                    None => format!("{m} points"),
                },
                "stored_scalars_positions_only": paper_variables,
                "polygon_vertices": region_vertices.len(),
                "curve_vertices": curve_vertices,
                "curve_variables_paper_counting": paper_variables,
                "data_size_paper_counting": paper_variables as f64 / region_vertices.len() as f64,
                "data_size_positions_only": curve_vertices as f64 / region_vertices.len() as f64,
                "original_to_reconstruction": {"rms": to_rec.rms, "max": to_rec.max},
                "reconstruction_to_original": {"rms": to_orig.rms, "max": to_orig.max},
                "original_to_loft_baseline": {"rms": loft_to_rec.rms, "max": loft_to_rec.max},
                "body_height": h,
            }));
            if k == 12 && gec_terms.is_none() {
                let img = pdesculpt::render::render(
                    &rec,
                    &pdesculpt::render::RenderOptions::default()
                        .with_width(360)
                        .with_height(480)
                        .with_view(pdesculpt::render::View::Perspective {
                            yaw: 30.0,
                            pitch: 10.0,
                        }),
                );
                let tag = match r.name.split_whitespace().next() {
                    Some("left") => "leg",
                    Some(t) => t,
                    None => "region",
                };
                super::annotate(
                    &img,
                    &format!("ODE6 reconstruction: {tag}"),
                    &[format!(
                        "{k} sections x {m} points\nC2 chain, rho = lambda = 1, eta = 3"
                    )],
                    pdesculpt::render::View::Perspective {
                        yaw: 30.0,
                        pitch: 10.0,
                    },
                    false,
                )?
                .save_png(&ctx.path(&format!("004-table1_{tag}.png")))?;
            }
        }
    }
    let mut md = String::from("| region | sections x section curve | polygon verts | curve variables (paper counting) | data size | positions only | rms / max error orig->rec (dm) | rms / max rec->orig (dm) | loft baseline rms / max orig->loft (dm) |\n|---|---|---|---|---|---|---|---|---|\n");
    for r in &rows {
        md += &format!(
            "| {} | {} x {} | {} | {} | {:.0}% | {:.0}% | {:.3} / {:.3} | {:.3} / {:.3} | {:.3} / {:.3} |\n",
            r["region"].as_str().unwrap_or(""),
            r["sections"],
            r["section"].as_str().unwrap_or(""),
            r["polygon_vertices"],
            r["curve_variables_paper_counting"],
            100.0 * r["data_size_paper_counting"].as_f64().unwrap_or(f64::NAN),
            100.0 * r["data_size_positions_only"].as_f64().unwrap_or(f64::NAN),
            r["original_to_reconstruction"]["rms"]
                .as_f64()
                .unwrap_or(f64::NAN),
            r["original_to_reconstruction"]["max"]
                .as_f64()
                .unwrap_or(f64::NAN),
            r["reconstruction_to_original"]["rms"]
                .as_f64()
                .unwrap_or(f64::NAN),
            r["reconstruction_to_original"]["max"]
                .as_f64()
                .unwrap_or(f64::NAN),
            r["original_to_loft_baseline"]["rms"].as_f64().unwrap_or(f64::NAN),
            r["original_to_loft_baseline"]["max"].as_f64().unwrap_or(f64::NAN));
    }
    ctx.write_bytes("004-table1.md", md.as_bytes())?;
    ctx.write_json("004-table1.json", &json!({"rows": rows, "params": {"rho": 1.0, "eta": 3.0, "lambda": 1.0}, "note": "data size = curve variables / polygon vertices as in paper 004 Table 1 (3 variables per curve vertex: position, first and second derivative)"}))?;
    super::networks::table1_face_rows(ctx)
}
