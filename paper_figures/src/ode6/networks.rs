//! Figures of curve networks and the face (paper 004 Figs 7-9, 11-13):
//! the bundled networks, the face network, the rebuilt face over the
//! original with both wireframes, and the action units with error maps.

use super::annotate;
use crate::common::Ctx;
use pdesculpt::face::expression;
use pdesculpt::face::extract::{self, FaceOptions, DEFAULT_PATCHES};
use pdesculpt::face::{sketched, BASE_WINDOW};
use pdesculpt::mesh::Mesh;
use pdesculpt::ode6::network::{samples, Network};
use pdesculpt::render::{render_with_camera, Camera, Image, Overlay, RenderOptions, View};
use serde_json::json;

const FRONT_3Q: View = View::Perspective {
    yaw: 30.0,
    pitch: 15.0,
};

fn render_box(m: &Mesh, lo: [f64; 3], hi: [f64; 3], o: &RenderOptions) -> Image {
    let cam = Camera::fit_box(lo, hi, o.view, o.width, o.height, o.margin);
    render_with_camera(m, o, &cam)
}

fn curve_overlays(net: &Network, colour: [u8; 4]) -> Vec<Overlay> {
    net.doc
        .curves
        .iter()
        .map(|c| Overlay {
            points: c.points.clone(),
            closed: false,
            colour,
            depth_test: true,
        })
        .collect()
}

/// Fig 7: objects made of patches, one colour per patch, curves in black.
pub fn fig7(ctx: &Ctx) -> anyhow::Result<()> {
    let mut imgs = Vec::new();
    let mut captions = Vec::new();
    let mut data = Vec::new();
    for (name, doc) in samples::bundled() {
        let net = Network::build(doc)?;
        let r = net.report(8);
        let m = net.mesh(12);
        let (lo, hi) = m.bbox();
        let o = RenderOptions::default()
            .with_width(360)
            .with_height(360)
            .with_view(FRONT_3Q)
            .with_overlays(curve_overlays(&net, [20, 20, 20, 255]));
        imgs.push(render_box(&m, lo, hi, &o));
        let worst = r.max_relative_jump();
        captions.push(format!(
            "{name}: {} patches ({} 3-sided)\nlargest relative jump {worst:.0e}\ndata {:.0} % of the mesh's numbers",
            r.patches,
            r.three_sided,
            100.0 * r.data.ratio
        ));
        data.push(json!({"network": name, "file": format!("data/network/{name}.json"),
            "patches": r.patches, "three_sided": r.three_sided, "curves": r.curves,
            "u_edges": r.u_edges, "v_edges": r.v_edges,
            "max_relative_u_edges": r.max_relative_u_edges, "max_relative_v_edges": r.max_relative_v_edges,
            "max_side_relative": r.max_side_relative, "residual": r.residual, "data": r.data}));
    }
    annotate(
        &Image::hstack(&imgs, [255, 255, 255, 255]),
        "Paper 004 Fig 7: objects from C2 ODE patches (curve networks in data/network/)",
        &captions,
        FRONT_3Q,
        false,
    )?
    .save_png(&ctx.path("004-fig7.png"))?;
    ctx.write_json("004-fig7.json", &json!({"networks": data, "command": "pdesculpt --json ode6 network data/network/NAME.json -o NAME.glb"}))?;
    Ok(())
}

/// The head box of the base (for framing the face figures).
fn head_box(m: &Mesh, ids: &[usize]) -> ([f64; 3], [f64; 3]) {
    let pts: Vec<[f64; 3]> = ids.iter().map(|&i| m.positions[i]).collect();
    pdesculpt::vec3::bounds(&pts).unwrap_or(([0.0; 3], [1.0; 3]))
}

/// The body triangles with every vertex above `y` (the head and neck).
fn head_mesh(m: &Mesh, y: f64) -> Mesh {
    let g = m.groups.iter().position(|g| g == "body").unwrap_or(0) as u32;
    let keep: Vec<bool> = m
        .triangles
        .iter()
        .zip(&m.tri_group)
        .map(|(t, &gr)| gr == g && t.iter().all(|&i| m.positions[i as usize][1] > y))
        .collect();
    let mut out = m.clone();
    let tris: Vec<([u32; 3], u32)> = m
        .triangles
        .iter()
        .zip(&m.tri_group)
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|((t, g), _)| (*t, *g))
        .collect();
    out.triangles = tris.iter().map(|t| t.0).collect();
    out.tri_group = tris.iter().map(|t| t.1).collect();
    out
}

fn wire(m: &Mesh, inside: &[bool], colour: [u8; 4]) -> Vec<Overlay> {
    let mut out = Vec::new();
    for t in &m.triangles {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            if a < b && inside[a] && inside[b] {
                out.push(Overlay {
                    points: vec![m.positions[a], m.positions[b]],
                    closed: false,
                    colour,
                    depth_test: true,
                });
            }
        }
    }
    out
}

/// The base face rebuilt (default patches, optimised) and what the face
/// figures draw it with.
struct FaceScene {
    head: Mesh,
    rebuilt: Mesh,
    inside: Vec<bool>,
    lo: [f64; 3],
    hi: [f64; 3],
    report: extract::FaceReport,
    net: Network,
}

fn face_scene() -> anyhow::Result<FaceScene> {
    let base = pdesculpt::makehuman::base_mesh()?;
    let (pos, report, net) = extract::rebuild(&base, &FaceOptions::new(DEFAULT_PATCHES, true))?;
    let t = extract::template(report.columns)?;
    let mut inside = vec![false; base.positions.len()];
    for p in &t.vertices {
        inside[p.vertex as usize] = true;
    }
    let ids: Vec<usize> = (0..inside.len()).filter(|&i| inside[i]).collect();
    let (lo, hi) = head_box(&base, &ids);
    let head = head_mesh(&base, lo[1] - 0.3);
    let mut rebuilt = head.clone();
    rebuilt.positions = pos;
    extract::mark_face(&mut rebuilt, DEFAULT_PATCHES)?;
    Ok(FaceScene {
        head,
        rebuilt,
        inside,
        lo,
        hi,
        report,
        net,
    })
}

const GOLD: [u8; 3] = [212, 160, 60];
const SILVER: [u8; 3] = [190, 190, 196];

/// Gold for group `face`, silver for the others.
fn colours(n: usize, face: Option<u32>) -> Vec<[u8; 3]> {
    (0..n)
        .map(|g| if Some(g as u32) == face { GOLD } else { SILVER })
        .collect()
}

fn face_opts(view: View, overlays: Vec<Overlay>, colours: Vec<[u8; 3]>) -> RenderOptions {
    RenderOptions::default()
        .with_width(420)
        .with_height(420)
        .with_view(view)
        .with_overlays(overlays)
        .with_group_colours(Some(colours))
}

/// Figs 11-12: the face network on the original (front, side).
pub fn fig11_12(ctx: &Ctx) -> anyhow::Result<()> {
    let f = face_scene()?;
    let curves = curve_overlays(&f.net, [200, 30, 30, 255]);
    let mut panels = Vec::new();
    for view in [View::Front, View::Side] {
        let o = face_opts(view, curves.clone(), colours(f.head.groups.len(), None));
        panels.push(render_box(&f.head, f.lo, f.hi, &o));
    }
    annotate(
        &Image::hstack(&panels, [255, 255, 255, 255]),
        &format!(
            "Paper 004 Figs 11-12: face network, {} x {} patches, {} curve points",
            f.report.columns, f.report.rows, f.report.curve_points
        ),
        &["front".into(), "side".into()],
        View::Front,
        false,
    )?
    .save_png(&ctx.path("004-fig11-12.png"))?;
    ctx.write_json(
        "004-fig11-12.json",
        &json!({"columns": f.report.columns, "rows": f.report.rows, "curve_points": f.report.curve_points,
            "curve_variables": f.report.curve_variables, "face_vertices": f.report.face_vertices,
            "command": "pdesculpt --json ode6 face -o face.obj"}),
    )?;
    Ok(())
}

/// Fig 8: the surface of the face network alone, one colour per patch:
/// the column network extracted from the base, and a web sketched in the
/// front view around the tip of the nose (3-sided patches at the tip).
pub fn fig8(ctx: &Ctx) -> anyhow::Result<()> {
    let f = face_scene()?;
    let nm = f.net.mesh(10);
    let opts = |net: &Network| {
        RenderOptions::default()
            .with_width(420)
            .with_height(420)
            .with_view(FRONT_3Q)
            .with_overlays(curve_overlays(net, [200, 30, 30, 255]))
    };
    let (nlo, nhi) = nm.bbox();
    let (base, body) = extract::base()?;
    let doc = sketched::polar_network(base, body, &BASE_WINDOW, sketched::RINGS, sketched::SPOKES)?;
    let web = Network::build(doc.clone())?;
    let wm = web.mesh(10);
    let wr = web.report(8);
    let skin = sketched::skin_distance(base, body, &BASE_WINDOW, &doc, &wm)?;
    let (dmax, drms) = (skin.max, skin.rms);
    let front = |net: &Network| opts(net).with_view(View::Front);
    let (wlo, whi) = wm.bbox();
    let panels = [
        render_box(&nm, nlo, nhi, &opts(&f.net)),
        render_box(&wm, wlo, whi, &front(&web)),
        render_box(&wm, wlo, whi, &opts(&web)),
    ];
    let web_caption = format!(
        "sketched web: {} patches ({} 3-sided)\nlargest relative jump {:.0e}\nfrom the skin: max {dmax:.3} dm, RMS {drms:.3} dm",
        wr.patches,
        wr.three_sided,
        wr.max_relative_jump()
    );
    annotate(
        &Image::hstack(&panels, [255, 255, 255, 255]),
        "Paper 004 Fig 8: a face from its curve network alone (one colour per patch, curves red)",
        &[
            format!(
                "extracted column network:\n{} C2 ODE patches",
                f.net.patches.len()
            ),
            web_caption.clone(),
            "the sketched web, three-quarter view".to_string(),
        ],
        FRONT_3Q,
        false,
    )?
    .save_png(&ctx.path("004-fig8.png"))?;
    ctx.write_json(
        "004-fig8.json",
        &json!({
            "extracted": {"patches": f.net.patches.len()},
            "sketched": {"patches": wr.patches, "three_sided": wr.three_sided, "rings": sketched::RINGS,
                "spokes": sketched::SPOKES, "max_relative_u_edges": wr.max_relative_u_edges,
                "max_relative_v_edges": wr.max_relative_v_edges, "apex_interpolation": wr.apex_interpolation,
                "max_side_relative": wr.max_side_relative, "skin_distance_max_dm": dmax, "skin_distance_rms_dm": drms, "skin_vertices": skin.samples},
            "note": "the sketched web: pdesculpt::face::sketched::polar_network on the base (spokes and rings drawn in the front view around the tip of the nose, lifted onto the skin); skin distance: from every face-region vertex inside the web's outer ring to the network's mesh (dm)"
        }),
    )?;
    Ok(())
}

/// Fig 9: the rebuilt face (gold) over the original (silver), and the
/// wireframes of both.
pub fn fig9(ctx: &Ctx) -> anyhow::Result<()> {
    let f = face_scene()?;
    let face_group = f
        .rebuilt
        .groups
        .iter()
        .position(|g| g == "face-ode6")
        .map(|g| g as u32);
    let mut panels = Vec::new();
    for view in [View::Front, View::Side] {
        let o = face_opts(
            view,
            Vec::new(),
            colours(f.rebuilt.groups.len(), face_group),
        );
        panels.push(render_box(&f.rebuilt, f.lo, f.hi, &o));
    }
    let mut both = wire(&f.rebuilt, &f.inside, [200, 30, 30, 255]);
    both.extend(wire(&f.head, &f.inside, [30, 150, 40, 255]));
    let o = face_opts(View::Front, both, colours(f.head.groups.len(), None));
    panels.push(render_box(&f.head, f.lo, f.hi, &o));
    let r = &f.report;
    annotate(
        &Image::hstack(&panels, [255, 255, 255, 255]),
        &format!(
            "Paper 004 Fig 9: the face rebuilt with the original's vertices and faces; MVE {:.4} dm ({:.2} % of the head), RMS {:.4} dm",
            r.max_error,
            100.0 * r.max_relative,
            r.rms_error
        ),
        &[
            "front: rebuilt face (gold) in the original".into(),
            "side".into(),
            "wireframes: rebuilt (red), original (green)".into(),
        ],
        View::Front,
        false,
    )?
    .save_png(&ctx.path("004-fig9.png"))?;
    let ear = fig9_ear(ctx)?;
    ctx.write_json(
        "004-fig9.json",
        &json!({"report": r, "ear": ear, "command": "pdesculpt --json ode6 face -o face.obj"}),
    )?;
    Ok(())
}

/// Fig 9e-f: the left ear rebuilt from four column curves (three patches),
/// seen from the side: the original with the curves, the rebuilt ear
/// (gold) in the original, both wireframes.
fn fig9_ear(ctx: &Ctx) -> anyhow::Result<serde_json::Value> {
    use pdesculpt::face::ear;
    let (base, body) = extract::base()?;
    let (pos, r, net) = ear::rebuild_ear(base, body)?;
    let head = head_mesh(base, 6.0);
    let moved: Vec<bool> = pos
        .iter()
        .zip(&base.positions)
        .map(|(a, b)| a != b)
        .collect();
    let ids: Vec<usize> = (0..moved.len()).filter(|&i| moved[i]).collect();
    let (lo, hi) = head_box(base, &ids);
    let mut rebuilt = head.clone();
    rebuilt.positions = pos;
    let g = rebuilt.groups.len() as u32;
    rebuilt.groups.push("ear-ode6".into());
    for (t, gr) in rebuilt.triangles.iter().zip(rebuilt.tri_group.iter_mut()) {
        if t.iter().all(|&i| moved[i as usize]) {
            *gr = g;
        }
    }
    let curves: Vec<Overlay> = net
        .doc
        .curves
        .iter()
        .filter(|c| c.points.len() > 2)
        .map(|c| Overlay {
            points: c.points.iter().map(|&q| ear::from_view(q)).collect(),
            closed: false,
            colour: [200, 30, 30, 255],
            depth_test: true,
        })
        .collect();
    let pad = 0.05;
    let (lo, hi) = (
        [lo[0], lo[1] - pad, lo[2] - pad],
        [hi[0], hi[1] + pad, hi[2] + pad],
    );
    let panels = [
        render_box(
            &head,
            lo,
            hi,
            &face_opts(View::Side, curves, colours(head.groups.len(), None)),
        ),
        render_box(
            &rebuilt,
            lo,
            hi,
            &face_opts(
                View::Side,
                Vec::new(),
                colours(rebuilt.groups.len(), Some(g)),
            ),
        ),
        {
            let mut both = wire(&rebuilt, &moved, [200, 30, 30, 255]);
            both.extend(wire(&head, &moved, [30, 150, 40, 255]));
            render_box(
                &head,
                lo,
                hi,
                &face_opts(View::Side, both, colours(head.groups.len(), None)),
            )
        },
    ];
    annotate(
        &Image::hstack(&panels, [255, 255, 255, 255]),
        &format!(
            "Paper 004 Fig 9e-f: the ear from 4 curves (3 C2 ODE patches), {} vertices; MVE {:.3} dm ({:.0} % of the ear), RMS {:.3} dm",
            r.vertices,
            r.max_error,
            100.0 * r.max_relative,
            r.rms_error
        ),
        &[
            "the original ear and its 4 column curves".into(),
            "rebuilt ear (gold) in the original".into(),
            "wireframes: rebuilt (red), original (green)".into(),
        ],
        View::Side,
        false,
    )?
    .save_png(&ctx.path("004-fig9-ear.png"))?;
    Ok(serde_json::to_value(&r)?)
}

/// Error bins of the colour maps (dm): white below the first edge, dark red
/// above the last.
const ERROR_BINS: [f64; 6] = [0.002, 0.005, 0.01, 0.02, 0.03, 0.05];

fn ramp(k: usize) -> [u8; 3] {
    const C: [[u8; 3]; 7] = [
        [235, 235, 235],
        [200, 220, 250],
        [140, 190, 240],
        [120, 200, 120],
        [250, 220, 90],
        [245, 140, 50],
        [190, 30, 30],
    ];
    C[k.min(6)]
}

/// Fig 13: action units rebuilt, with error colour maps.
pub fn fig13(ctx: &Ctx) -> anyhow::Result<()> {
    let base = pdesculpt::makehuman::base_mesh()?;
    let mut rows = Vec::new();
    let mut top = Vec::new();
    let mut bottom = Vec::new();
    let mut captions = Vec::new();
    let t = extract::template(DEFAULT_PATCHES / extract::ROWS)?;
    let ids: Vec<usize> = t.vertices.iter().map(|p| p.vertex as usize).collect();
    let (lo, hi) = head_box(&base, &ids);
    for au in expression::TABLE_UNITS
        .iter()
        .chain(["AU25", "AU43R"].iter())
    {
        let mut m = base.clone();
        expression::apply(&mut m.positions, &expression::expression(au, 1.0)?)?;
        let (pos, r, net) = extract::rebuild(&m, &FaceOptions::new(DEFAULT_PATCHES, true))?;
        let head = head_mesh(&m, lo[1] - 0.3);
        let points: Vec<Overlay> = net
            .doc
            .curves
            .iter()
            .flat_map(|c| c.points.iter())
            .map(|p| Overlay {
                points: vec![*p, [p[0], p[1] + 0.004, p[2]]],
                closed: false,
                colour: [200, 30, 30, 255],
                depth_test: true,
            })
            .collect();
        let o = RenderOptions::default()
            .with_width(300)
            .with_height(300)
            .with_view(View::Front)
            .with_overlays(points)
            .with_group_colours(Some(vec![[190, 190, 196]; head.groups.len()]));
        top.push(render_box(&head, lo, hi, &o));
        // error map: triangles grouped by their largest vertex error
        let err: Vec<f64> = pos
            .iter()
            .zip(&m.positions)
            .map(|(a, b)| pdesculpt::vec3::dist(*a, *b))
            .collect();
        let mut map = head.clone();
        map.positions = pos;
        map.groups = (0..=ERROR_BINS.len()).map(|k| format!("bin{k}")).collect();
        map.tri_group = map
            .triangles
            .iter()
            .map(|t| {
                let e = t.iter().map(|&i| err[i as usize]).fold(0.0, f64::max);
                ERROR_BINS.iter().filter(|b| e > **b).count() as u32
            })
            .collect();
        let o = RenderOptions::default()
            .with_width(300)
            .with_height(300)
            .with_view(View::Front)
            .with_group_colours(Some((0..=ERROR_BINS.len()).map(ramp).collect()));
        bottom.push(render_box(&map, lo, hi, &o));
        captions.push(format!(
            "{au}: MVE {:.4} dm\nRMS {:.4} dm",
            r.max_error, r.rms_error
        ));
        let unit = expression::FACS.iter().find(|f| f.au == *au);
        rows.push(
            json!({"au": au, "name": unit.map(|u| u.name), "units": unit.map(|u| u.units),
            "in_table_units": expression::TABLE_UNITS.contains(au),
            "max_error_dm": r.max_error, "rms_error_dm": r.rms_error,
            "max_relative_to_head": r.max_relative, "worst_vertex": r.worst_vertex,
            "command": format!("pdesculpt --json ode6 face --expression {au}=1 -o {au}.obj")}),
        );
    }
    let grid = vstack(&[
        Image::hstack(&top, [255, 255, 255, 255]),
        Image::hstack(&bottom, [255, 255, 255, 255]),
    ]);
    let legend = ERROR_BINS
        .iter()
        .map(|b| format!("{b}"))
        .collect::<Vec<_>>()
        .join(" / ");
    annotate(
        &grid,
        &format!("Paper 004 Fig 13: action units (top: expressed original with curve points; bottom: error map, bins {legend} dm)"),
        &captions,
        View::Front,
        false,
    )?
    .save_png(&ctx.path("004-fig13.png"))?;
    ctx.write_json(
        "004-fig13.json",
        &json!({"units": rows, "error_bins_dm": ERROR_BINS}),
    )?;
    Ok(())
}

/// Images one above the other (white where narrower).
fn vstack(images: &[Image]) -> Image {
    let w = images.iter().map(|i| i.width).max().unwrap_or(0);
    let h = images.iter().map(|i| i.height).sum();
    let mut out = Image::new(w, h, [255, 255, 255, 255]);
    let mut y0 = 0;
    for img in images {
        for y in 0..img.height {
            for x in 0..img.width {
                out.put(x as i64, (y0 + y) as i64, img.get(x, y));
            }
        }
        y0 += img.height;
    }
    out
}

/// Table 1's face rows from the face curve network (sec 6.3): for a few
/// `--patches`, the face vertices, curve points, curve variables (Table 1
/// counting: each point with its two cross derivatives), data size and
/// the MVE against the base. Written beside Table 1 as
/// `004-table1-face.{md,json}`.
pub fn table1_face_rows(ctx: &Ctx) -> anyhow::Result<()> {
    let base = pdesculpt::makehuman::base_mesh()?;
    let mut md = String::from("| face network | polygon verts | curve points | curve variables | data size | numbers stored / face coordinates | MVE (dm) | RMS (dm) |\n|---|---|---|---|---|---|---|---|\n");
    let mut rows = Vec::new();
    for patches in [16, 24, 48, 80] {
        let (_, r, _) = extract::rebuild(&base, &FaceOptions::new(patches, true))?;
        md += &format!(
            "| {} patches ({} x {}) | {} | {} | {} | {:.0}% | {:.0}% | {:.4} | {:.4} |\n",
            r.patches,
            r.columns,
            r.rows,
            r.face_vertices,
            r.curve_points,
            r.curve_variables,
            100.0 * r.data_ratio,
            100.0 * r.numbers_ratio,
            r.max_error,
            r.rms_error
        );
        rows.push(json!({"patches": patches, "report": r,
            "command": format!("pdesculpt --json ode6 face --patches {patches} -o face.obj")}));
    }
    ctx.write_bytes("004-table1-face.md", md.as_bytes())?;
    ctx.write_json(
        "004-table1-face.json",
        &json!({"rows": rows, "paper": "4,081 vertices from 489 curve points: 1,467 variables, 36 %"}),
    )?;
    Ok(())
}
