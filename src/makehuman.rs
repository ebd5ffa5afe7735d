//! The bundled CC0 MakeHuman "hm08" base body and its morph targets.
//!
//! `data/makehuman/base.obj` is embedded in the library; the group `body` is
//! the skin (13,378 quads), the other groups are helper geometry that a
//! template drops. Y is up, the body is about 16.7 units (decimetres) tall,
//! in MakeHuman's rest A-pose. A morph target is a list of
//! `INDEX DX DY DZ` lines (gzip), INDEX 0-based into the OBJ vertex list; a
//! morphed body is `base + sum_k w_k target_k`. A few targets are embedded
//! (see [`EMBEDDED_TARGETS`]); the rest are read from the repository's
//! `data/makehuman/targets/` at run time.

use crate::mesh::io::parse_obj;
use crate::mesh::{Mesh, MeshError};
use std::io::Read;
use std::path::{Path, PathBuf};

/// The base mesh OBJ text (CC0, see `data/makehuman/LICENSE.md`).
pub const BASE_OBJ: &str = include_str!("../data/makehuman/base.obj");

/// Targets embedded in the binary: `(name, gzip bytes)`.
pub const EMBEDDED_TARGETS: &[(&str, &[u8])] = &[
    (
        "caucasian-male-young",
        include_bytes!("../data/makehuman/targets/macrodetails/caucasian-male-young.target.gz"),
    ),
    (
        "caucasian-female-young",
        include_bytes!("../data/makehuman/targets/macrodetails/caucasian-female-young.target.gz"),
    ),
    (
        "universal-male-young-averagemuscle-averageweight",
        include_bytes!(
            "../data/makehuman/targets/macrodetails/universal-male-young-averagemuscle-averageweight.target.gz"
        ),
    ),
    (
        "universal-female-young-averagemuscle-averageweight",
        include_bytes!(
            "../data/makehuman/targets/macrodetails/universal-female-young-averagemuscle-averageweight.target.gz"
        ),
    ),
    (
        "stomach-pregnant-incr",
        include_bytes!("../data/makehuman/targets/stomach/stomach-pregnant-incr.target.gz"),
    ),
];

/// Directory of the repository's MakeHuman data (compile-time path).
pub fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("data/makehuman")
}

/// A morph target: sparse vertex offsets.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Target {
    pub name: String,
    pub offsets: Vec<(u32, [f64; 3])>,
}

/// Parses target text (`INDEX DX DY DZ` per line; `#` comments).
pub fn parse_target(name: &str, text: &str) -> Result<Target, MeshError> {
    let mut offsets = Vec::new();
    for (ln, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let err = |message: String| MeshError::Parse {
            path: name.to_string(),
            line: ln + 1,
            message,
        };
        let w: Vec<&str> = line.split_whitespace().collect();
        if w.len() != 4 {
            return Err(err(format!("expected 'INDEX DX DY DZ', found {line:?}")));
        }
        let i: u32 = w[0]
            .parse()
            .map_err(|_| err(format!("bad index {:?}", w[0])))?;
        let mut d = [0.0f64; 3];
        for k in 0..3 {
            d[k] = w[k + 1]
                .parse()
                .map_err(|_| err(format!("bad offset {:?}", w[k + 1])))?;
            if !d[k].is_finite() {
                return Err(err(format!("non-finite offset {:?}", w[k + 1])));
            }
        }
        offsets.push((i, d));
    }
    Ok(Target {
        name: name.to_string(),
        offsets,
    })
}

fn gunzip(name: &str, bytes: &[u8]) -> Result<String, MeshError> {
    let mut s = String::new();
    flate2::read::GzDecoder::new(bytes)
        .read_to_string(&mut s)
        .map_err(|source| MeshError::Io {
            path: name.to_string(),
            source,
        })?;
    Ok(s)
}

/// Largest |weight| of a morph target the kit applies (body morphs and
/// expression units alike): MakeHuman's own sliders span [0, 1] (or
/// [-1, 1]); 2 allows an exaggeration of twice the modelled shape, beyond
/// which a target's displacements fold the skin.
pub const MORPH_WEIGHT_MAX: f64 = 2.0;

/// A target by name: embedded ones first, then
/// `data/makehuman/targets/*/<name>.target.gz`.
pub fn target(name: &str) -> Result<Target, MeshError> {
    if let Some((_, bytes)) = EMBEDDED_TARGETS.iter().find(|(n, _)| *n == name) {
        return parse_target(name, &gunzip(name, bytes)?);
    }
    for sub in ["macrodetails", "stomach"] {
        let p = data_dir()
            .join("targets")
            .join(sub)
            .join(format!("{name}.target.gz"));
        if p.exists() {
            let bytes = std::fs::read(&p).map_err(|source| MeshError::Io {
                path: p.display().to_string(),
                source,
            })?;
            return parse_target(name, &gunzip(name, &bytes)?);
        }
    }
    Err(MeshError::Invalid(format!(
        "unknown MakeHuman target {name:?} (see data/makehuman/targets/)"
    )))
}

/// The whole base mesh, all groups.
pub fn base_mesh() -> Result<Mesh, MeshError> {
    parse_obj(BASE_OBJ, "data/makehuman/base.obj")
}

/// The skin only, with the map from its vertices to base-mesh indices.
#[derive(Clone, Debug)]
pub struct Body {
    pub mesh: Mesh,
    /// `original_index[i]`: index of body vertex `i` in the OBJ `v` list.
    pub original_index: Vec<u32>,
}

/// The body group with `targets` applied with their weights.
pub fn body(targets: &[(Target, f64)]) -> Result<Body, MeshError> {
    let mut base = base_mesh()?;
    for (t, w) in targets {
        for &(i, d) in &t.offsets {
            let p = base.positions.get_mut(i as usize).ok_or_else(|| {
                MeshError::Invalid(format!(
                    "target {} moves vertex {i}, which does not exist",
                    t.name
                ))
            })?;
            for k in 0..3 {
                p[k] += w * d[k];
            }
        }
    }
    let (mesh, original_index) = base
        .group_submesh("body")
        .ok_or_else(|| MeshError::Invalid("base.obj has no 'body' group".into()))?;
    Ok(Body {
        mesh,
        original_index,
    })
}

/// The unmorphed body.
pub fn base_body() -> Result<Body, MeshError> {
    body(&[])
}
