//! The face network of an input mesh, its solution, and the rebuilt mesh
//! (steps 2-3 of [`super`]).

use super::fit::optimise_column;
use super::template::FaceTemplate;
use super::{FaceError, BASE_WINDOW};
use crate::mesh::Mesh;
use crate::ode6::network::doc::{
    Cross, CurveDoc, Derivatives, NetworkDoc, PatchDoc, DEFAULT_PARAMS, NETWORK_VERSION,
};
use crate::ode6::network::Network;
use crate::ode6::Params;
use crate::surface::Surface;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Rows of patches in the face network (the curves are split at `nv + 1`
/// node rows; the shape parameters are per column, eq 26).
pub const ROWS: usize = 4;
/// Default number of patches (`12` columns of `4`): the `--patches`
/// default, chosen from the MVE/data-size table in `docs/networks.md`.
pub const DEFAULT_PATCHES: usize = 48;
/// Samples per row along a column curve (the curve spacing is then about
/// the base mesh's edge length over the face, ~0.04 dm).
pub const PER_ROW: usize = 8;
/// Fewest and most columns `--patches` may ask for.
pub const COLUMNS: (usize, usize) = (2, 40);

/// Options of [`rebuild`].
#[derive(Clone, Copy, Debug)]
#[non_exhaustive]
pub struct FaceOptions {
    /// Patches in the network (a multiple of [`ROWS`]; default
    /// [`DEFAULT_PATCHES`]).
    pub patches: usize,
    /// Optimise the shape parameters per column (default on; off: the
    /// default parameters everywhere).
    pub optimise: bool,
}

impl Default for FaceOptions {
    fn default() -> Self {
        FaceOptions {
            patches: DEFAULT_PATCHES,
            optimise: true,
        }
    }
}

impl FaceOptions {
    pub fn new(patches: usize, optimise: bool) -> FaceOptions {
        FaceOptions { patches, optimise }
    }
}

/// What a rebuild measured.
#[derive(Clone, Debug, serde::Serialize)]
pub struct FaceReport {
    pub vertices: usize,
    pub face_vertices: usize,
    pub columns: usize,
    pub rows: usize,
    pub patches: usize,
    /// Largest and RMS distance of a regenerated vertex from the input's.
    pub max_error: f64,
    pub rms_error: f64,
    /// The vertex with the largest error.
    pub worst_vertex: u32,
    pub head_height: f64,
    pub max_relative: f64,
    pub rms_relative: f64,
    /// The same before the optimisation (default parameters).
    pub max_error_default: f64,
    pub rms_error_default: f64,
    /// Points on the curves (nodes counted once), Table 1's "curve
    /// vertices".
    pub curve_points: usize,
    /// Stored vectors: each curve point with its first and second cross
    /// derivative (Table 1 counts 489 points as 1,467 variables).
    pub curve_variables: usize,
    /// `curve_variables / face_vertices` (Table 1's data size comparison).
    pub data_ratio: f64,
    /// All stored numbers (coordinates, curve parameters, shape parameters)
    /// over the face vertices' coordinates.
    pub numbers_ratio: f64,
    /// Shape parameters per column after the optimisation.
    pub params: Vec<Params>,
    /// `[C0, C1, C2]` largest relative jumps across u-edges and v-edges.
    pub u_edges: [f64; 3],
    pub v_edges: [f64; 3],
}

/// The bundled base mesh (all groups) and its skin flags, parsed once.
pub fn base() -> Result<&'static (Mesh, Vec<bool>), FaceError> {
    static BASE: OnceLock<Result<(Mesh, Vec<bool>), String>> = OnceLock::new();
    BASE.get_or_init(|| {
        let m = crate::makehuman::base_mesh().map_err(|e| e.to_string())?;
        let g = m
            .groups
            .iter()
            .position(|g| g == "body")
            .ok_or("no body group")? as u32;
        let body = m.tri_group.iter().map(|&x| x == g).collect();
        Ok((m, body))
    })
    .as_ref()
    .map_err(|e| FaceError::Template(e.clone()))
}

/// The template for `columns` columns (built once per column count).
pub fn template(columns: usize) -> Result<Arc<FaceTemplate>, FaceError> {
    static CACHE: OnceLock<Mutex<HashMap<usize, Arc<FaceTemplate>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    if let Some(t) = cache.lock().ok().and_then(|c| c.get(&columns).cloned()) {
        return Ok(t);
    }
    let (m, body) = base()?;
    let t = Arc::new(FaceTemplate::new(
        m,
        body,
        BASE_WINDOW,
        (columns, ROWS, PER_ROW),
    )?);
    if let Ok(mut c) = cache.lock() {
        c.insert(columns, t.clone());
    }
    Ok(t)
}

/// Refuses a mesh whose vertices and triangles are not the base's.
pub fn check_topology(m: &Mesh) -> Result<(), FaceError> {
    let (b, _) = base()?;
    let err = |why: String| FaceError::Topology {
        why,
        vertices: b.positions.len(),
        triangles: b.triangles.len(),
    };
    if m.positions.len() != b.positions.len() {
        return Err(err(format!("it has {} vertices", m.positions.len())));
    }
    if m.triangles.len() != b.triangles.len() {
        return Err(err(format!("it has {} triangles", m.triangles.len())));
    }
    if let Some(t) = (0..m.triangles.len()).find(|&t| m.triangles[t] != b.triangles[t]) {
        return Err(err(format!(
            "triangle {t} is {:?}, the base's is {:?}",
            m.triangles[t], b.triangles[t]
        )));
    }
    if let Some(index) = m
        .positions
        .iter()
        .position(|p| p.iter().any(|x| !x.is_finite()))
    {
        return Err(FaceError::NonFinite { index });
    }
    Ok(())
}

/// The network document of the face of `positions` (see [`super`]).
pub fn face_network(t: &FaceTemplate, positions: &[[f64; 3]], params: &[Params]) -> NetworkDoc {
    let (nu, nv) = (t.nu, t.nv);
    let node = |i: usize, j: usize| i * (nv + 1) + j;
    let mut nodes = vec![[0.0; 3]; (nu + 1) * (nv + 1)];
    let mut curves = Vec::new();
    let mut cross: Vec<Cross> = Vec::new();
    for (i, col) in t.columns.iter().enumerate() {
        for j in 0..nv {
            let (lo, hi) = (j as f64 / nv as f64, (j + 1) as f64 / nv as f64);
            let s: Vec<_> = col.iter().filter(|s| s.w >= lo && s.w <= hi).collect();
            let points: Vec<[f64; 3]> = s.iter().map(|s| s.point.eval(positions)).collect();
            let comb = |wts: &dyn Fn(&super::template::Sample) -> [f64; 3]| -> Vec<[f64; 3]> {
                s.iter()
                    .map(|smp| {
                        let w = wts(smp);
                        let pts = smp.stencil.map(|m| m.eval(positions));
                        std::array::from_fn(|k| (0..3).map(|q| w[q] * pts[q][k]).sum())
                    })
                    .collect()
            };
            cross.push(Cross {
                first: comb(&|s| s.first),
                second: comb(&|s| s.second),
            });
            nodes[node(i, j)] = points[0];
            nodes[node(i, j + 1)] = points[points.len() - 1];
            curves.push(CurveDoc {
                from: node(i, j),
                to: node(i, j + 1),
                params: Some(
                    s.iter()
                        .map(|s| ((s.w - lo) * nv as f64).clamp(0.0, 1.0))
                        .collect(),
                ),
                points,
            });
        }
    }
    let vert = |i: usize, j: usize| i * nv + j;
    let hbase = curves.len();
    for i in 0..nu {
        for j in 0..=nv {
            curves.push(CurveDoc {
                from: node(i, j),
                to: node(i + 1, j),
                points: vec![nodes[node(i, j)], nodes[node(i + 1, j)]],
                params: None,
            });
        }
    }
    let horiz = |i: usize, j: usize| hbase + i * (nv + 1) + j;
    let mut patches = Vec::with_capacity(nu * nv);
    for i in 0..nu {
        for j in 0..nv {
            patches.push(PatchDoc {
                name: Some(format!("face.{i}.{j}")),
                curves: vec![vert(i, j), horiz(i, j + 1), vert(i + 1, j), horiz(i, j)],
                params: params.get(i).copied().unwrap_or(DEFAULT_PARAMS),
                derivatives: Some(Derivatives {
                    u0: Some(cross[vert(i, j)].clone()),
                    u1: (i + 1 == nu).then(|| cross[vert(i + 1, j)].clone()),
                }),
                apex: Default::default(),
            });
        }
    }
    NetworkDoc {
        version: NETWORK_VERSION,
        name: "face".into(),
        nodes,
        curves,
        patches,
    }
}

/// Columns for `patches` (a multiple of [`ROWS`] within [`COLUMNS`]).
pub fn columns_for(patches: usize) -> Result<usize, FaceError> {
    let (lo, hi) = (COLUMNS.0 * ROWS, COLUMNS.1 * ROWS);
    if patches % ROWS != 0 || patches < lo || patches > hi {
        return Err(FaceError::Patches {
            patches,
            rows: ROWS,
            min: lo,
            max: hi,
        });
    }
    Ok(patches / ROWS)
}

/// Errors `(max, rms, worst vertex)` of the regenerated region.
pub(super) fn errors(
    t: &FaceTemplate,
    net: &Network,
    positions: &[[f64; 3]],
) -> (f64, f64, u32, Vec<[f64; 3]>) {
    let (mut max, mut sum, mut worst) = (0.0f64, 0.0, 0u32);
    let mut out = Vec::with_capacity(t.vertices.len());
    for p in &t.vertices {
        let s = net.patches[p.column * t.nv + p.row].point(p.u, p.v);
        let e = crate::vec3::dist(s, positions[p.vertex as usize]);
        if e > max || e.is_nan() {
            max = e;
            worst = p.vertex;
        }
        sum += e * e;
        out.push(s);
    }
    (
        max,
        (sum / t.vertices.len().max(1) as f64).sqrt(),
        worst,
        out,
    )
}

/// Rebuilds the face of `mesh` (base topology): the output positions (the
/// input's with the face region regenerated), the report and the network.
pub fn rebuild(
    mesh: &Mesh,
    opts: &FaceOptions,
) -> Result<(Vec<[f64; 3]>, FaceReport, Network), FaceError> {
    check_topology(mesh)?;
    let columns = columns_for(opts.patches)?;
    let t = template(columns)?;
    let pos = &mesh.positions;
    let mut params = vec![DEFAULT_PARAMS; columns];
    let net0 = Network::build(face_network(&t, pos, &params))?;
    let (max0, rms0, _, _) = errors(&t, &net0, pos);
    if opts.optimise {
        for (i, p) in params.iter_mut().enumerate() {
            *p = optimise_column(&t, &net0, pos, i);
        }
    }
    let net = if opts.optimise {
        Network::build(face_network(&t, pos, &params))?
    } else {
        net0
    };
    let (max, rms, worst, regenerated) = errors(&t, &net, pos);
    let mut out = pos.clone();
    for (p, s) in t.vertices.iter().zip(regenerated) {
        out[p.vertex as usize] = s;
    }
    let head = pos[t.top as usize][1] - pos[t.chin as usize][1];
    let (u_edges, v_edges) = net.max_jumps(crate::ode6::network::report::EDGE_SAMPLES);
    let curve_points = net.doc.nodes.len()
        + net.doc.curves[..(columns + 1) * ROWS]
            .iter()
            .map(|c| c.points.len() - 2)
            .sum::<usize>();
    let face_vertices = t.vertices.len();
    let report = FaceReport {
        vertices: pos.len(),
        face_vertices,
        columns,
        rows: ROWS,
        patches: columns * ROWS,
        max_error: max,
        rms_error: rms,
        worst_vertex: worst,
        head_height: head,
        max_relative: max / head,
        rms_relative: rms / head,
        max_error_default: max0,
        rms_error_default: rms0,
        curve_points,
        curve_variables: 3 * curve_points,
        data_ratio: (3 * curve_points) as f64 / face_vertices as f64,
        numbers_ratio: net.stored_numbers() as f64 / (3 * face_vertices) as f64,
        params,
        u_edges,
        v_edges,
    };
    Ok((out, report, net))
}

/// `text` (an OBJ) with its `v` lines replaced by `positions` times
/// `scale`, every other line (faces, groups, normals, texture coordinates)
/// kept as it was; fails unless the counts agree.
pub fn rewrite_obj(text: &str, positions: &[[f64; 3]], scale: f64) -> Result<String, FaceError> {
    let mut out = String::with_capacity(text.len());
    let mut k = 0usize;
    for line in text.split_inclusive('\n') {
        if line.starts_with("v ") || line.starts_with("v\t") {
            let p = positions.get(k).ok_or_else(|| FaceError::Topology {
                why: format!("the OBJ has more than {} vertices", positions.len()),
                vertices: positions.len(),
                triangles: 0,
            })?;
            let end = if line.ends_with("\r\n") {
                "\r\n"
            } else if line.ends_with('\n') {
                "\n"
            } else {
                ""
            };
            out.push_str(&format!(
                "v {} {} {}{end}",
                p[0] * scale,
                p[1] * scale,
                p[2] * scale
            ));
            k += 1;
        } else {
            out.push_str(line);
        }
    }
    if k != positions.len() {
        return Err(FaceError::Topology {
            why: format!("the OBJ has {k} vertices"),
            vertices: positions.len(),
            triangles: 0,
        });
    }
    Ok(out)
}

/// Puts the triangles whose three vertices are regenerated into the group
/// `face-ode6` (for viewers and figures).
pub fn mark_face(m: &mut Mesh, patches: usize) -> Result<(), FaceError> {
    let t = template(columns_for(patches)?)?;
    let mut inside = vec![false; m.positions.len()];
    for p in &t.vertices {
        inside[p.vertex as usize] = true;
    }
    let g = m.group_index("face-ode6");
    for (tri, group) in m.triangles.iter().zip(m.tri_group.iter_mut()) {
        if tri.iter().all(|&i| inside[i as usize]) {
            *group = g;
        }
    }
    Ok(())
}
