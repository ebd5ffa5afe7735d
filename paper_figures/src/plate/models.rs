//! Fig 8 (cursor direction and sensitivity), Fig 9 (basic models) and Fig 1
//! (Utah teapot, flat sheet with several deformations).

use super::render_row;
use crate::common::Ctx;
use pdesculpt::mesh::{dot, norm, sub, Mesh};
use pdesculpt::plate::shapes::{region_in_polygon, sheet, Shape};
use pdesculpt::plate::{BoundaryMethod, Direction, MappingMethod, PlateDeformer, RegionOptions};
use pdesculpt::render::View;
use std::collections::HashMap;

const PERSP: View = View::Perspective {
    yaw: 30.0,
    pitch: 30.0,
};

/// Merges vertices closer than 1e-7 and drops degenerate triangles.
fn weld(pos: Vec<[f64; 3]>, tris: Vec<[u32; 3]>) -> Mesh {
    let q = |x: f64| (x * 1e7).round() as i64;
    let mut map: HashMap<(i64, i64, i64), u32> = HashMap::new();
    let mut out = Vec::new();
    let remap: Vec<u32> = pos
        .iter()
        .map(|p| {
            *map.entry((q(p[0]), q(p[1]), q(p[2]))).or_insert_with(|| {
                out.push(*p);
                (out.len() - 1) as u32
            })
        })
        .collect();
    let tris: Vec<[u32; 3]> = tris
        .iter()
        .map(|t| t.map(|v| remap[v as usize]))
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    Mesh::new(out, tris)
}

/// A parametric grid surface (u, v in [0, 1]) as a welded mesh.
fn grid_surface(n: usize, m: usize, f: impl Fn(f64, f64) -> [f64; 3]) -> Mesh {
    let mut pos = Vec::new();
    let mut tris = Vec::new();
    for j in 0..=m {
        for i in 0..=n {
            pos.push(f(i as f64 / n as f64, j as f64 / m as f64));
        }
    }
    let id = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    for j in 0..m {
        for i in 0..n {
            tris.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            tris.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    weld(pos, tris)
}

fn sphere() -> Mesh {
    use std::f64::consts::{PI, TAU};
    grid_surface(64, 32, |u, v| {
        let (th, ph) = (PI * (1.0 - v), TAU * u);
        [th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]
    })
}

fn cube() -> Mesh {
    let n = 24;
    let mut m = Mesh::default();
    let faces: [([f64; 3], [f64; 3], [f64; 3]); 6] = [
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
        ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
        ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
    ];
    for (c, a, b) in faces {
        m.append(&grid_surface(n, n, |u, v| {
            let (s, t) = (2.0 * u - 1.0, 2.0 * v - 1.0);
            [
                c[0] + s * a[0] + t * b[0],
                c[1] + s * a[1] + t * b[1],
                c[2] + s * a[2] + t * b[2],
            ]
        }));
    }
    let tris = m.triangles.clone();
    weld(m.positions, tris)
}

fn cylinder() -> Mesh {
    use std::f64::consts::TAU;
    grid_surface(64, 32, |u, v| {
        [(TAU * u).cos(), (TAU * u).sin(), 2.0 * v - 1.0]
    })
}

fn cone() -> Mesh {
    use std::f64::consts::TAU;
    grid_surface(64, 32, |u, v| {
        let r = 1.0 - v;
        [r * (TAU * u).cos(), r * (TAU * u).sin(), 2.0 * v - 1.0]
    })
}

/// The Utah teapot tessellated from its 32 Bezier patches (data file with
/// its source in `teapot.txt`), `n` x `n` quads per patch.
fn teapot(n: usize) -> anyhow::Result<Mesh> {
    let text = include_str!("teapot.txt");
    let mut patches: Vec<[usize; 16]> = Vec::new();
    let mut verts: Vec<[f64; 3]> = Vec::new();
    let mut section = "";
    for line in text.lines() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if line == "patches" || line == "vertices" {
            section = if line == "patches" { "p" } else { "v" };
            continue;
        }
        let nums: Vec<f64> = line
            .split_whitespace()
            .map(|t| t.parse::<f64>())
            .collect::<Result<_, _>>()?;
        match (section, nums.len()) {
            ("p", 16) => {
                let mut p = [0usize; 16];
                for k in 0..16 {
                    p[k] = nums[k] as usize;
                }
                patches.push(p);
            }
            ("v", 3) => verts.push([nums[0], nums[1], nums[2]]),
            _ => anyhow::bail!("teapot.txt: malformed line {line:?}"),
        }
    }
    anyhow::ensure!(
        patches.len() == 32 && verts.len() == 306,
        "teapot data incomplete"
    );
    let bern = |t: f64| {
        let s = 1.0 - t;
        [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
    };
    let mut m = Mesh::default();
    for p in &patches {
        anyhow::ensure!(
            p.iter().all(|&i| i < verts.len()),
            "teapot index out of range"
        );
        m.append(&grid_surface(n, n, |u, v| {
            let (bu, bv) = (bern(u), bern(v));
            let mut x = [0.0; 3];
            for i in 0..4 {
                for j in 0..4 {
                    let c = verts[p[i * 4 + j]];
                    for k in 0..3 {
                        x[k] += bu[i] * bv[j] * c[k];
                    }
                }
            }
            x
        }));
    }
    let tris = m.triangles.clone();
    Ok(weld(m.positions, tris))
}

/// Vertices within `r` of `c` whose normal faces `dir`.
fn ball_region(m: &Mesh, c: [f64; 3], r: f64, dir: [f64; 3]) -> Vec<u32> {
    let n = m.vertex_normals();
    (0..m.positions.len() as u32)
        .filter(|&i| {
            let p = m.positions[i as usize];
            norm(sub(p, c)) < r && dot(n[i as usize], dir).abs() > 0.2 * norm(dir)
        })
        .collect()
}

/// Prepares a region with the paper's alpha shape, falling back to the
/// mesh-edge boundary where the alpha rule cannot close the boundary.
fn prepare(m: &Mesh, region: &[u32]) -> anyhow::Result<(PlateDeformer, &'static str)> {
    prepare_with(m, region, MappingMethod::LengthBased)
}

fn prepare_with(
    m: &Mesh,
    region: &[u32],
    mapping: MappingMethod,
) -> anyhow::Result<(PlateDeformer, &'static str)> {
    let base = RegionOptions::default().with_mapping(mapping);
    match PlateDeformer::new(m, region, &base) {
        Ok(p) => Ok((p, "alpha_shape")),
        Err(_) => {
            let o = base.with_boundary(BoundaryMethod::MeshEdges);
            Ok((PlateDeformer::new(m, region, &o)?, "mesh_edges"))
        }
    }
}

/// Boundary curve (3D) of a prepared region on mesh `m`.
fn outline(p: &PlateDeformer, m: &Mesh) -> Vec<[f64; 3]> {
    p.boundary()
        .loop_indices
        .iter()
        .map(|&i| m.positions[p.region()[i] as usize])
        .collect()
}

/// Cursor motion whose plate peak is `peak` for sensitivity `s`.
fn motion_for_peak(p: &PlateDeformer, s: f64, peak: f64) -> f64 {
    peak * 64.0 * p.rigidity() / s
}

/// Cursor motion of length `len` along the region normal, oriented
/// towards `outside`.
fn outward(p: &PlateDeformer, outside: [f64; 3], len: f64) -> [f64; 3] {
    let n = p.normal();
    let sgn = if dot(n, outside) < 0.0 { -len } else { len };
    pdesculpt::vec3::scale(n, sgn)
}

/// Fig 8: (a) region, (b, c) same sensitivity, two cursor directions,
/// (d-f) normal direction with sensitivities 40, 70, 110.
pub fn fig8(ctx: &Ctx) -> anyhow::Result<()> {
    let m = sheet(40);
    let sq = [[-0.6, -0.6], [0.6, -0.6], [0.6, 0.6], [-0.6, 0.6]];
    let region = region_in_polygon(&m, &sq);
    let (p, method) = prepare(&m, &region)?;
    let ol = outline(&p, &m);
    let d = motion_for_peak(&p, 70.0, 0.35);
    let cases: Vec<(&str, [f64; 3], f64, Direction)> = vec![
        ("b: cursor up, s=70", [0.0, 0.0, d], 70.0, Direction::Cursor),
        (
            "c: cursor up-right, s=70",
            [0.7 * d, 0.0, 0.7 * d],
            70.0,
            Direction::Cursor,
        ),
        ("d: normal, s=40", [0.0, 0.0, d], 40.0, Direction::Normal),
        ("e: normal, s=70", [0.0, 0.0, d], 70.0, Direction::Normal),
        ("f: normal, s=110", [0.0, 0.0, d], 110.0, Direction::Normal),
    ];
    let mut meshes = vec![m.clone()];
    let mut data = Vec::new();
    for (name, dv, s, dir) in &cases {
        let out = p.deform(&m, *dv, *s, *dir)?;
        let disp = out
            .positions
            .iter()
            .zip(&m.positions)
            .map(|(a, b)| norm(sub(*a, *b)))
            .fold(0.0, f64::max);
        data.push(serde_json::json!({
            "case": name, "cursor_motion": dv, "sensitivity": s,
            "max_displacement": disp,
            "predicted_max_s_d_over_64D": s * norm(*dv) / (64.0 * p.rigidity()),
        }));
        meshes.push(out);
    }
    let row: Vec<(&Mesh, Vec<[f64; 3]>)> = meshes.iter().map(|x| (x, ol.clone())).collect();
    let img = render_row(&row, PERSP, 300);
    ctx.write_bytes("001-fig8.png", &img.encode_png())?;
    ctx.write_json(
        "001-fig8.json",
        &serde_json::json!({ "boundary": method, "panels": "a (region), b, c, d, e, f", "cases": data }),
    )?;
    Ok(())
}

/// Fig 9: sphere, cube, cylinder, cone, each with a deformation region,
/// before and after (pushed out along the region normal).
pub fn fig9(ctx: &Ctx) -> anyhow::Result<()> {
    // (name, mesh, region centre, region radius, outward direction)
    type Model = (&'static str, Mesh, [f64; 3], f64, [f64; 3]);
    let models: Vec<Model> = vec![
        ("sphere", sphere(), [0.6, -0.8, 0.0], 0.6, [0.6, -0.8, 0.0]),
        ("cube", cube(), [0.0, -1.0, 0.2], 0.7, [0.0, -1.0, 0.0]),
        (
            "cylinder",
            cylinder(),
            [0.0, -1.0, 0.0],
            0.7,
            [0.0, -1.0, 0.0],
        ),
        ("cone", cone(), [0.0, -0.5, 0.0], 0.45, [0.0, -1.0, 0.45]),
    ];
    let mut before = Vec::new();
    let mut after = Vec::new();
    let mut data = Vec::new();
    for (name, m, c, r, dir) in models {
        let region = ball_region(&m, c, r, dir);
        let (p, method) = prepare(&m, &region)?;
        let d = outward(&p, dir, motion_for_peak(&p, 70.0, 0.35));
        let out = p.deform(&m, d, 70.0, Direction::Normal)?;
        data.push(serde_json::json!({
            "model": name, "vertices": m.positions.len(), "region_vertices": p.region().len(),
            "boundary": method, "non_star_rays": p.non_star_rays(),
        }));
        let ol = outline(&p, &m);
        before.push((m, ol.clone()));
        after.push((out, ol));
    }
    let mut imgs = Vec::new();
    for (m, ol) in before.iter().chain(after.iter()) {
        imgs.push(render_row(&[(m, ol.clone())], PERSP, 260));
    }
    let top = pdesculpt::render::Image::hstack(&imgs[..4], [255, 255, 255, 255]);
    let bottom = pdesculpt::render::Image::hstack(&imgs[4..], [255, 255, 255, 255]);
    ctx.write_bytes("001-fig9-before.png", &top.encode_png())?;
    ctx.write_bytes("001-fig9-after.png", &bottom.encode_png())?;
    ctx.write_json("001-fig9.json", &data)?;
    Ok(())
}

/// Fig 1: (a) one deformation on the Utah teapot, (b) several deformations
/// on a flat sheet, applied one after the other.
pub fn fig1(ctx: &Ctx) -> anyhow::Result<()> {
    let t = teapot(16)?;
    // (centre, radius, outward direction, peak): body front pulled out,
    // body back pushed in, lid rim pulled up
    let edits: [([f64; 3], f64, [f64; 3], f64); 3] = [
        ([0.0, -2.0, 1.2], 0.9, [0.0, -1.0, 0.0], 0.5),
        ([0.0, 2.0, 1.2], 0.8, [0.0, 1.0, 0.0], -0.3),
        ([0.0, 1.0, 2.5], 0.35, [0.0, 0.0, 1.0], 0.2),
    ];
    let mut out = t.clone();
    let mut out_harmonic = t.clone();
    let mut outlines = Vec::new();
    let mut teapot_steps = Vec::new();
    for (c, r, dir, peak) in edits {
        let region = ball_region(&t, c, r, dir);
        let (p, method) = prepare(&out, &region)?;
        let d = outward(&p, dir, motion_for_peak(&p, 70.0, peak));
        out = p.deform(&out, d, 70.0, Direction::Normal)?;
        let (ph, _) = prepare_with(&out_harmonic, &region, MappingMethod::Harmonic)?;
        let dh = outward(&ph, dir, motion_for_peak(&ph, 70.0, peak));
        out_harmonic = ph.deform(&out_harmonic, dh, 70.0, Direction::Normal)?;
        outlines.extend(outline(&p, &t));
        teapot_steps.push(serde_json::json!({
            "centre": c, "region_vertices": p.region().len(), "boundary": method,
            "peak": peak, "non_star_rays": p.non_star_rays(),
        }));
    }
    let first: Vec<[f64; 3]> = {
        let region = ball_region(&t, edits[0].0, edits[0].1, edits[0].2);
        let (p, _) = prepare(&t, &region)?;
        outline(&p, &t)
    };
    let img = render_row(
        &[(&t, first), (&out, Vec::new()), (&out_harmonic, Vec::new())],
        View::Perspective {
            yaw: 20.0,
            pitch: 15.0,
        },
        400,
    );
    ctx.write_bytes("001-fig1a-teapot.png", &img.encode_png())?;
    // (b) a sheet with three deformations
    let mut m = sheet(60);
    let rest = m.clone();
    let mut steps = Vec::new();
    let shapes = [
        (Shape::Pentagram, [-0.6, 0.55], 0.5, 0.3),
        (Shape::Square, [0.6, 0.5], 0.45, -0.2),
        (Shape::Triangle, [0.0, -0.55], 0.6, 0.25),
    ];
    for (s, c, scale, peak) in shapes {
        let poly: Vec<[f64; 2]> = s
            .polygon()
            .iter()
            .map(|q| [c[0] + scale * q[0], c[1] + scale * q[1]])
            .collect();
        let region = region_in_polygon(&rest, &poly);
        let o = RegionOptions::default().with_view(Some([0.0, 0.0, 1.0]));
        let p = PlateDeformer::new(&m, &region, &o)?;
        let d = motion_for_peak(&p, 70.0, peak);
        m = p.deform(&m, [0.0, 0.0, d], 70.0, Direction::Cursor)?;
        steps.push(serde_json::json!({ "shape": s.name(), "region_vertices": p.region().len(), "peak": peak }));
    }
    let img = render_row(&[(&m, Vec::new())], PERSP, 500);
    ctx.write_bytes("001-fig1b-sheet.png", &img.encode_png())?;
    ctx.write_json(
        "001-fig1.json",
        &serde_json::json!({
            "teapot_panels": "rest with the first region, eq 16 mapping (paper), harmonic mapping (beyond the paper)",
            "teapot": { "source": "Newell's 32 Bezier patches / 306 control points, paper_figures/src/plate/teapot.txt",
                        "vertices": t.positions.len(), "triangles": t.triangles.len(),
                        "steps": teapot_steps },
            "sheet_steps": steps,
        }),
    )?;
    let _ = outlines;
    Ok(())
}
