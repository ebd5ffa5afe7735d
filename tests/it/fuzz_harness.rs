//! Fuzz harness on stable Rust, shared by `cargo test` (tests/it/fuzz.rs,
//! a fixed number of cases from a fixed seed) and
//! `cargo run --release --example fuzz -- --cases N` (more cases, any seed).
//!
//! Inputs are drawn with proptest: byte strings and structure-aware
//! documents (OBJ, PLY, STL, CSV and every JSON document, built from a pool
//! of hostile numbers: NaN, inf, 1e300, 2^63, usize::MAX, -0, ...).
//! * parser targets run in-process through the library entry points
//!   (`mesh::io::parse_*`, `pde4::spec::Spec`, `curve::gec::Gec`);
//! * command targets run the built binary with generated files and numeric
//!   arguments (every subcommand's numbers: counts, sizes, parameters).
//!
//! Each case asserts: no panic (catch_unwind in-process, exit code 101 or
//! "panicked" for the binary), no hang (a per-case time limit), no
//! non-finite output (in-process: every returned number finite; binary: exit
//! 0 never prints NaN/inf/null on stdout, never writes a file with them).

#![allow(dead_code)]

/// The targets of the new surfaces: SVG, documents, edits (issue 35).
#[path = "fuzz_targets.rs"]
pub mod targets;

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// Outcome counts of one target.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tally {
    pub name: String,
    pub kind: &'static str,
    pub cases: usize,
    /// Cases accepted (exit 0 / `Ok`).
    pub accepted: usize,
    pub panics: usize,
    pub hangs: usize,
    pub non_finite: usize,
    /// The first failing input, for the report.
    pub first_failure: Option<String>,
}

impl Tally {
    pub fn failures(&self) -> usize {
        self.panics + self.hangs + self.non_finite
    }
}

/// Deterministic choices drawn by proptest (a fixed seed in `cargo test`).
pub struct Pick {
    seeds: Vec<u64>,
    at: usize,
}

impl Pick {
    pub fn u(&mut self) -> u64 {
        let v = self.seeds[self.at % self.seeds.len()];
        self.at += 1;
        // mix so that reuse after wrap-around differs
        v.rotate_left((self.at / self.seeds.len()) as u32 * 7)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.u() % n.max(1) as u64) as usize
    }
    pub fn chance(&mut self, percent: u64) -> bool {
        self.u() % 100 < percent
    }
    pub fn of<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[self.below(xs.len())]
    }
    /// A number: usually ordinary, often hostile.
    pub fn num(&mut self) -> String {
        if self.chance(60) {
            let x = (self.u() % 20001) as f64 / 1000.0 - 10.0;
            return format!("{x}");
        }
        self.of(HOSTILE_NUMBERS).to_string()
    }
    /// A count: usually small, often hostile.
    pub fn count(&mut self) -> String {
        if self.chance(60) {
            return format!("{}", self.u() % 40);
        }
        self.of(HOSTILE_COUNTS).to_string()
    }
}

/// Hostile real numbers.
pub const HOSTILE_NUMBERS: &[&str] = &[
    "0", "-0", "1", "-1", "0.5", "1e-300", "-1e-300", "1e300", "-1e300", "1e38", "3.5e38", "1e308",
    "NaN", "nan", "inf", "-inf", "1e9", "-1e9", "2", "0.2", "1e-8", "abc", "", "1,2",
];

/// Hostile counts.
pub const HOSTILE_COUNTS: &[&str] = &[
    "0",
    "1",
    "2",
    "3",
    "7",
    "64",
    "1000",
    "100000",
    "4294967296",
    "9223372036854775808",
    "18446744073709551615",
    "-1",
    "1.5",
    "x",
];

/// Runs `f` on another thread with a time limit; `Err` names a panic or a
/// timeout.
pub fn guarded<T: Send + 'static>(
    limit: Duration,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, &'static str> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
        let _ = tx.send(r);
    });
    match rx.recv_timeout(limit) {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(_)) => Err("panic"),
        Err(_) => Err("hang"),
    }
}

/// An in-process target: input bytes -> `Ok(numbers produced)` or an error
/// message.
pub type ParseFn = fn(&[u8]) -> Result<Vec<f64>, String>;

/// A generator of input bytes.
pub type GenFn = fn(&mut Pick) -> Vec<u8>;

/// In-process parser targets: (name, generator, parser).
pub fn parser_targets() -> Vec<(&'static str, GenFn, ParseFn)> {
    vec![
        ("OBJ bytes", gen_bytes, parse_obj),
        ("OBJ documents", gen_obj, parse_obj),
        ("PLY bytes", gen_bytes, parse_ply),
        ("PLY documents", gen_ply, parse_ply),
        ("STL bytes", gen_bytes, parse_stl),
        ("STL documents", gen_stl, parse_stl),
        ("GLB bytes", gen_bytes, parse_glb),
        ("GLB documents", gen_glb, parse_glb),
        ("pde4 spec JSON", gen_pde4_spec, parse_pde4_spec),
        ("GEC JSON", gen_gec_json, parse_gec),
        ("CSV bytes", gen_bytes, parse_csv_fit),
        ("CSV documents", gen_csv, parse_csv_fit),
        ("SVG drawings", targets::gen_svg, targets::parse_svg),
        ("character documents", targets::gen_doc, targets::parse_doc),
        ("edits", targets::gen_edit, targets::apply_edit),
    ]
}

fn mesh_numbers(m: pdesculpt::mesh::Mesh) -> Result<Vec<f64>, String> {
    m.validate().map_err(|e| e.to_string())?;
    // a mesh that reads must also encode (or be refused clearly)
    for fmt in [
        pdesculpt::mesh::io::Format::Obj,
        pdesculpt::mesh::io::Format::Stl,
        pdesculpt::mesh::io::Format::Ply,
        pdesculpt::mesh::io::Format::Glb,
    ] {
        if let Ok(bytes) = pdesculpt::mesh::io::encode(&m, fmt) {
            if fmt == pdesculpt::mesh::io::Format::Obj {
                let text = String::from_utf8_lossy(&bytes);
                if text.contains("inf") || text.contains("NaN") {
                    return Ok(vec![f64::NAN]);
                }
            }
        }
    }
    Ok(m.positions.iter().flatten().copied().collect())
}

fn parse_obj(b: &[u8]) -> Result<Vec<f64>, String> {
    let m = pdesculpt::mesh::io::parse_obj(&String::from_utf8_lossy(b), "fuzz.obj")
        .map_err(|e| e.to_string())?;
    mesh_numbers(m)
}

fn parse_ply(b: &[u8]) -> Result<Vec<f64>, String> {
    let m = pdesculpt::mesh::io::parse_ply(b, "fuzz.ply").map_err(|e| e.to_string())?;
    mesh_numbers(m)
}

fn parse_stl(b: &[u8]) -> Result<Vec<f64>, String> {
    let m = pdesculpt::mesh::io::parse_stl(b, "fuzz.stl").map_err(|e| e.to_string())?;
    mesh_numbers(m)
}

fn parse_glb(b: &[u8]) -> Result<Vec<f64>, String> {
    let opts = pdesculpt::mesh::io::GltfOptions::default();
    let s = pdesculpt::mesh::io::parse_gltf(b, None, &opts).map_err(|e| e.to_string())?;
    mesh_numbers(s.flatten())
}

/// A valid GLB (a small torus in two parts) with one field of its JSON set
/// to a hostile number or count, bytes overwritten, or cut short.
fn gen_glb(p: &mut Pick) -> Vec<u8> {
    let mut m = pdesculpt::mesh::samples::torus_mesh(3);
    m.groups = vec!["a".into(), "b".into()];
    m.tri_group = (0..m.triangles.len()).map(|t| (t % 2) as u32).collect();
    let fmt = pdesculpt::mesh::io::Format::Glb;
    let mut b = pdesculpt::mesh::io::encode(&m, fmt).unwrap_or_default();
    let jl = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
    match p.below(4) {
        0 | 1 => {
            let mut doc: serde_json::Value =
                serde_json::from_slice(&b[20..20 + jl]).unwrap_or_default();
            // (object, key, 0 for a scalar or the length of an array of it)
            let fields: [(&str, &str, usize); 15] = [
                ("/accessors/0", "count", 0),
                ("/accessors/2", "count", 0),
                ("/accessors/0", "byteOffset", 0),
                ("/accessors/2", "componentType", 0),
                ("/bufferViews/0", "byteOffset", 0),
                ("/bufferViews/1", "byteLength", 0),
                ("/bufferViews/2", "byteStride", 0),
                ("/buffers/0", "byteLength", 0),
                ("/meshes/0/primitives/0", "mode", 0),
                ("/meshes/1/primitives/0", "indices", 0),
                ("/nodes/0", "children", 1),
                ("", "scene", 0),
                ("/nodes/1", "translation", 3),
                ("/nodes/0", "scale", 3),
                ("/nodes/2", "rotation", 4),
            ];
            let value = if p.chance(50) { p.num() } else { p.count() };
            let value = serde_json::from_str(&value).unwrap_or(serde_json::Value::String(value));
            let (path, key, arity) = *p.of(&fields);
            let value = match arity {
                0 => value,
                n => serde_json::Value::Array(vec![value; n]),
            };
            if let Some(serde_json::Value::Object(o)) = doc.pointer_mut(path) {
                o.insert(key.to_string(), value);
            }
            let mut j = serde_json::to_vec(&doc).unwrap_or_default();
            j.resize(j.len().div_ceil(4) * 4, b' ');
            let bin = b[20 + jl..].to_vec();
            b = b"glTF".to_vec();
            for x in [2, (12 + 8 + j.len() + bin.len()) as u32, j.len() as u32] {
                b.extend(x.to_le_bytes());
            }
            b.extend(b"JSON");
            b.extend(j);
            b.extend(bin);
        }
        2 => {
            for _ in 0..1 + p.below(8) {
                let i = p.below(b.len());
                b[i] = p.u() as u8;
            }
        }
        _ => b.truncate(p.below(b.len())),
    }
    b
}

fn parse_pde4_spec(b: &[u8]) -> Result<Vec<f64>, String> {
    use pdesculpt::surface::Surface;
    let spec: pdesculpt::pde4::spec::Spec = serde_json::from_slice(b).map_err(|e| e.to_string())?;
    let patch = spec.solve().map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for (u, v) in [(0.0, 0.0), (0.3, 0.7), (0.5, 0.5), (1.0, 0.25)] {
        out.extend(patch.point(u, v));
    }
    Ok(out)
}

/// A points file through `gec fit`'s library path (J = 3).
fn parse_csv_fit(b: &[u8]) -> Result<Vec<f64>, String> {
    use pdesculpt::curve::gec::fit::{fit, FitOptions};
    let mut f = pdesculpt::curve::gec::input::parse_points(&String::from_utf8_lossy(b))
        .map_err(|e| e.to_string())?;
    pdesculpt::curve::gec::strip_closing_copy(&mut f.points);
    let r = fit(&f.points, &FitOptions::new(3)).map_err(|e| e.to_string())?;
    let g = &r.gec;
    let mut out = vec![g.centre[0], g.centre[1], r.errors.erm, r.errors.era];
    out.extend(g.x.iter().chain(&g.y).flatten());
    Ok(out)
}

fn parse_gec(b: &[u8]) -> Result<Vec<f64>, String> {
    let g: pdesculpt::curve::gec::Gec = serde_json::from_slice(b).map_err(|e| e.to_string())?;
    let g =
        pdesculpt::curve::gec::Gec::new(g.frame, g.centre, g.x, g.y).map_err(|e| e.to_string())?;
    pdesculpt::curve::gec::input::check_magnitudes(&g).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for k in 0..3 {
        out.extend(g.derivative(0.7, k));
    }
    Ok(out)
}

pub fn gen_bytes(p: &mut Pick) -> Vec<u8> {
    let n = p.below(300);
    let mut v: Vec<u8> = (0..n).map(|_| p.u() as u8).collect();
    // sometimes a plausible magic in front
    let magic: &[u8] = match p.below(5) {
        0 => b"ply\nformat ascii 1.0\n",
        1 => b"solid x\n",
        2 => b"v 0 0 0\nf 1 2 3\n",
        _ => b"",
    };
    v.splice(0..0, magic.iter().copied());
    v
}

pub fn gen_obj(p: &mut Pick) -> Vec<u8> {
    let mut s = String::new();
    for _ in 0..p.below(12) {
        match p.below(6) {
            0 | 1 => s += &format!("v {} {} {}\n", p.num(), p.num(), p.num()),
            2 | 3 => {
                let k = 1 + p.below(5);
                let idx: Vec<String> = (0..k)
                    .map(|_| {
                        if p.chance(70) {
                            format!("{}", p.below(6) as i64 - 2)
                        } else {
                            p.count()
                        }
                    })
                    .collect();
                s += &format!("f {}\n", idx.join(" "));
            }
            4 => s += &format!("g {}\n", p.of(&["", "a", "b c", "#"])),
            _ => s += &format!("{} {}\n", p.of(&["vn", "vt", "#", "o", "usemtl"]), p.num()),
        }
    }
    s.into_bytes()
}

pub fn gen_ply(p: &mut Pick) -> Vec<u8> {
    if p.chance(50) {
        // well formed, with one hostile value at most
        let mut body = String::new();
        for k in 0..4 {
            let mut c = [k % 2, k / 2, k % 3].map(|x| x.to_string());
            if p.chance(15) {
                c[p.below(3)] = p.num();
            }
            body += &format!("{} {} {}\n", c[0], c[1], c[2]);
        }
        let idx = if p.chance(85) {
            "2".to_string()
        } else {
            p.count()
        };
        body += &format!("3 0 1 {idx}\n4 0 1 2 3\n");
        let ty = *p.of(&["int", "uint", "float", "uchar"]);
        return format!(
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\nelement face 2\nproperty list uchar {ty} vertex_indices\nend_header\n{body}"
        )
        .into_bytes();
    }
    let ascii = p.chance(70);
    let nv = p.count();
    let nf = p.count();
    let ty = |p: &mut Pick| {
        *p.of(&[
            "float", "double", "int", "uchar", "char", "short", "uint", "bogus",
        ])
    };
    let mut h = format!(
        "ply\nformat {} 1.0\nelement vertex {nv}\n",
        if ascii {
            "ascii"
        } else {
            "binary_little_endian"
        }
    );
    for name in ["x", "y", "z", "nx"] {
        if p.chance(85) {
            h += &format!("property {} {name}\n", ty(p));
        }
    }
    h += &format!(
        "element face {nf}\nproperty list {} {} vertex_indices\nend_header\n",
        ty(p),
        ty(p)
    );
    let mut b = h.into_bytes();
    if ascii {
        for _ in 0..p.below(30) {
            let t = if p.chance(50) {
                p.num()
            } else {
                format!("{}", p.below(5))
            };
            b.extend(format!("{t} ").bytes());
        }
    } else {
        for _ in 0..p.below(120) {
            b.push(p.u() as u8);
        }
    }
    b
}

pub fn gen_stl(p: &mut Pick) -> Vec<u8> {
    if p.chance(50) {
        let n = p.below(4);
        let declared = if p.chance(80) { n as u32 } else { p.u() as u32 };
        let mut b = vec![0u8; 80];
        b.extend(declared.to_le_bytes());
        for _ in 0..n {
            for _ in 0..12 {
                let x: f32 = if p.chance(80) {
                    (p.u() % 200) as f32 / 10.0 - 10.0
                } else {
                    *p.of(&[f32::NAN, f32::INFINITY, f32::MAX, -0.0, 1e-45])
                };
                b.extend(x.to_le_bytes());
            }
            b.extend([0, 0]);
        }
        b
    } else {
        let mut s = "solid fuzz\n".to_string();
        for _ in 0..p.below(4) {
            s += "facet normal 0 0 1\nouter loop\n";
            for _ in 0..(2 + p.below(2)) {
                s += &format!("vertex {} {} {}\n", p.num(), p.num(), p.num());
            }
            s += "endloop\nendfacet\n";
        }
        s.into_bytes()
    }
}

fn force_json(p: &mut Pick) -> String {
    let pv = format!("[{}, {}, {}]", p.num(), p.num(), p.num());
    match p.below(5) {
        0 => format!(
            r#"{{"type": "concentrated", "u0": {}, "v0": {}, "p": {pv}}}"#,
            p.num(),
            p.num()
        ),
        1 => format!(
            r#"{{"type": "line", "u0": {}, "u1": {}, "v0": {}, "p": {pv}}}"#,
            p.num(),
            p.num(),
            p.num()
        ),
        2 => format!(
            r#"{{"type": "area", "u0": {}, "u1": {}, "v0": {}, "v1": {}, "p": {pv}}}"#,
            p.num(),
            p.num(),
            p.num(),
            p.num()
        ),
        3 => format!(r#"{{"type": "uniform", "p": {pv}}}"#),
        _ => format!(r#"{{"type": "uniform", "p": {pv}, "extra": 1}}"#),
    }
}

pub fn gen_pde4_spec(p: &mut Pick) -> Vec<u8> {
    if p.chance(60) {
        // a valid spec with one field perturbed at most
        let (patch, method) = *p.of(&[
            ("two-sided", "exact"),
            ("two-sided", "paper"),
            ("two-sided", "least-squares"),
            ("four-sided", "galerkin"),
            ("four-sided", "paper"),
        ]);
        let m = *p.of(&["1", "2", "4", "6"]);
        let n = *p.of(&["1", "3", "5"]);
        let mut a = ["1".to_string(), "2".to_string(), "1".to_string()];
        if p.chance(30) {
            a[p.below(3)] = p.num();
        }
        let force = if p.chance(70) {
            format!(
                r#"{{"type": "concentrated", "u0": 0.5, "v0": 0.25, "p": [0, 0, {}]}}"#,
                p.num()
            )
        } else {
            force_json(p)
        };
        return format!(
            r#"{{"patch": "{patch}", "method": "{method}", "shape": {{"a1": {}, "a2": {}, "a3": {}}}, "terms": [{m}, {n}], "forces": [{force}]}}"#,
            a[0], a[1], a[2]
        )
        .into_bytes();
    }
    let patch = *p.of(&["two-sided", "four-sided", "three-sided"]);
    let method = *p.of(&["exact", "paper", "least-squares", "galerkin"]);
    // small term counts (cheap) and hostile ones (refused before work)
    let t = |p: &mut Pick| {
        *p.of(&[
            "0",
            "1",
            "2",
            "5",
            "8",
            "257",
            "100000",
            "18446744073709551615",
            "-1",
        ])
    };
    let forces: Vec<String> = (0..p.below(3)).map(|_| force_json(p)).collect();
    let unknown = if p.chance(10) { r#", "colour": 1"# } else { "" };
    format!(
        r#"{{"patch": "{patch}", "method": "{method}", "shape": {{"a1": {}, "a2": {}, "a3": {}}},
            "terms": [{}, {}], "forces": [{}]{unknown}}}"#,
        p.num(),
        p.num(),
        p.num(),
        t(p),
        t(p),
        forces.join(", ")
    )
    .into_bytes()
}

fn gec_value(p: &mut Pick, terms: usize) -> String {
    let pair = |p: &mut Pick| format!("[{}, {}]", p.num(), p.num());
    let xs: Vec<String> = (0..terms).map(|_| pair(p)).collect();
    let ys: Vec<String> = (0..terms + usize::from(p.chance(10)))
        .map(|_| pair(p))
        .collect();
    let z = p.num();
    format!(
        r#"{{"frame": {{"origin": [0, 0, {z}], "e1": [1, 0, 0], "e2": [0, {}, 0]}}, "centre": [{}, {}], "x": [{}], "y": [{}]}}"#,
        if p.chance(90) {
            "1".to_string()
        } else {
            p.num()
        },
        p.num(),
        p.num(),
        xs.join(", "),
        ys.join(", ")
    )
}

pub fn gen_gec_json(p: &mut Pick) -> Vec<u8> {
    let n = p.below(6);
    gec_value(p, n).into_bytes()
}

/// A circle-ish closed polyline as CSV (sometimes hostile rows).
pub fn gen_csv(p: &mut Pick) -> Vec<u8> {
    let n = 3 + p.below(40);
    let r: f64 = *p.of(&[1.0, 1e-200, 1e200, 3.0, 1e-5]);
    let mut s = String::new();
    if p.chance(20) {
        s += "x,y\n";
    }
    for k in 0..n {
        let t = std::f64::consts::TAU * k as f64 / n as f64;
        if p.chance(5) {
            s += &format!("{},{}\n", p.num(), p.num());
        } else if p.chance(3) {
            s += "# open\n";
        } else {
            s += &format!(
                "{},{}\n",
                r * t.cos(),
                r * (1.0 + 0.3 * (2.0 * t).cos()) * t.sin()
            );
        }
    }
    s.into_bytes()
}

/// A command target: builds the argument list, writing any input files into
/// `dir` (`OUT` names the output file in `dir`).
pub type CommandGen = fn(&mut Pick, &Path) -> Vec<String>;

fn file(dir: &Path, name: &str, bytes: &[u8]) -> String {
    let p = dir.join(name);
    std::fs::write(&p, bytes).expect("write fuzz input");
    p.display().to_string()
}

fn out(dir: &Path, ext: &str) -> String {
    dir.join(format!("out.{ext}")).display().to_string()
}

const TETRA: &[u8] = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

fn args(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

fn cmd_gec_fit(p: &mut Pick, d: &Path) -> Vec<String> {
    let csv = gen_csv(p);
    let i = file(d, "in.csv", &csv);
    let mut a = args(&["gec", "fit", "-i", &i]);
    match p.below(4) {
        0 => a.extend(args(&["--terms", &p.count()])),
        1 => a.extend(args(&["--tol", &p.num(), "--max-terms", &p.count()])),
        2 => a.extend(args(&["--terms", &p.count(), "--solver", "fft"])),
        _ => a.extend(args(&[
            "--theta0",
            &p.num(),
            "--param",
            *p.of(&["polar", "uniform", "centripetal", "chord"]),
        ])),
    }
    a.extend(args(&["-o", &out(d, "json")]));
    a
}

fn cmd_gec_eval(p: &mut Pick, d: &Path) -> Vec<String> {
    let n = 1 + p.below(4);
    let g = file(d, "g.json", gec_value(p, n).as_bytes());
    let mut a = args(&["gec", "eval", "--gec", &g, "--derivative", &p.count()]);
    if p.chance(50) {
        a.extend(args(&["--samples", &p.count()]));
    } else {
        a.extend(args(&["--at", &p.num(), "--at", &p.num()]));
    }
    if p.chance(50) {
        a.push("--turns".into());
    }
    a
}

fn cmd_pde4_eval(p: &mut Pick, d: &Path) -> Vec<String> {
    let s = file(d, "spec.json", &gen_pde4_spec(p));
    args(&[
        "pde4",
        "eval",
        &s,
        "--at",
        &format!("{},{}", p.num(), p.num()),
    ])
}

fn cmd_pde6_mode(p: &mut Pick, _: &Path) -> Vec<String> {
    let vals: Vec<String> = (0..6).map(|_| p.num()).collect();
    args(&[
        "pde6",
        "mode",
        "--a",
        &p.num(),
        "--n",
        &p.count(),
        "--values",
        &vals.join(","),
        "--at",
        &p.num(),
    ])
}

fn sections(p: &mut Pick, n: usize) -> String {
    let terms = 1 + p.below(3);
    let secs: Vec<String> = (0..n)
        .map(|i| {
            let g = if p.chance(90) {
                format!(
                    r#"{{"frame": {{"origin": [0, 0, {i}], "e1": [1, 0, 0], "e2": [0, 1, 0]}}, "centre": [0, 0], "x": [{}], "y": [{}]}}"#,
                    (0..terms).map(|k| if k == 0 { "[1, 0]".to_string() } else { format!("[{}, 0]", p.num()) }).collect::<Vec<_>>().join(","),
                    (0..terms).map(|k| if k == 0 { "[1, 0]".to_string() } else { format!("[0, {}]", p.num()) }).collect::<Vec<_>>().join(",")
                )
            } else {
                gec_value(p, terms)
            };
            let u = if p.chance(90) { format!("{}", i as f64 / n as f64) } else { p.num() };
            format!(r#"{{"u": {u}, "gec": {g}}}"#)
        })
        .collect();
    format!(r#"{{"sections": [{}]}}"#, secs.join(", "))
}

fn cmd_pde6_patch(p: &mut Pick, d: &Path) -> Vec<String> {
    let n = *p.of(&[6usize, 7, 9, 10, 3]);
    let s = file(d, "sections.json", sections(p, n).as_bytes());
    let method = *p.of(&["global", "method1", "method2"]);
    let nu = if p.chance(70) {
        format!("{}", 1 + p.below(6))
    } else {
        p.count()
    };
    let nv = if p.chance(70) {
        format!("{}", 3 + p.below(12))
    } else {
        p.count()
    };
    args(&[
        "pde6",
        "patch",
        &s,
        "--a",
        &p.num(),
        "--method",
        method,
        "--first",
        &p.count(),
        "--nu",
        &nu,
        "--nv",
        &nv,
        "-o",
        &out(d, "obj"),
    ])
}

fn curve_json(p: &mut Pick) -> String {
    match p.below(4) {
        0 => {
            let n = p.below(8);
            let pts: Vec<String> = (0..n)
                .map(|k| {
                    let t = std::f64::consts::TAU * k as f64 / n.max(1) as f64;
                    if p.chance(90) {
                        format!("[{}, {}, 0]", t.cos(), t.sin())
                    } else {
                        format!("[{}, {}, {}]", p.num(), p.num(), p.num())
                    }
                })
                .collect();
            format!(
                r#"{{"polyline": {{"points": [{}], "closed": {}}}}}"#,
                pts.join(","),
                p.chance(70)
            )
        }
        1 => {
            let n = 1 + p.below(2);
            format!(r#"{{"gec": {}}}"#, gec_value(p, n))
        }
        2 => format!(
            r#"{{"fourier": {{"c0": [0, 0, {}], "cos": [[1, 0, 0]], "sin": [[0, {}, 0]]}}}}"#,
            p.num(),
            p.num()
        ),
        _ => format!(
            r#"{{"hermite": {{"start": [[0,0,0],[1,0,0],[0,0,0]], "end": [[{},1,0],[1,0,0],[0,0,{}]]}}}}"#,
            p.num(),
            p.num()
        ),
    }
}

fn cmd_ode6_surface(p: &mut Pick, d: &Path) -> Vec<String> {
    let params = format!(
        r#"{{"rho": {}, "eta": {}, "lambda": {}}}"#,
        p.num(),
        p.num(),
        p.num()
    );
    let curves = if p.chance(50) {
        format!(
            r#"{{"approach1": {{"c1": {}, "c4": {}, "w": [{}, {}, {}, {}]}}}}"#,
            curve_json(p),
            curve_json(p),
            p.num(),
            p.num(),
            p.num(),
            p.num()
        )
    } else {
        let cs: Vec<String> = (0..6).map(|_| curve_json(p)).collect();
        format!(r#"{{"direct": [{}]}}"#, cs.join(", "))
    };
    let s = file(
        d,
        "spec.json",
        format!(r#"{{"params": {params}, "curves": {curves}}}"#).as_bytes(),
    );
    let mut a = args(&["ode6", "surface", &s, "-o", &out(d, "ply")]);
    if p.chance(50) {
        a.extend(args(&["--nu", &p.count(), "--nv", &p.count()]));
    }
    a
}

fn cmd_ode6_eval(p: &mut Pick, _: &Path) -> Vec<String> {
    let bc: Vec<String> = (0..6).map(|_| p.num()).collect();
    args(&[
        "ode6",
        "eval",
        "--rho",
        &p.num(),
        "--eta",
        &p.num(),
        "--lambda",
        &p.num(),
        "--bc",
        &bc.join(","),
        "--at",
        &p.num(),
    ])
}

fn cmd_render(p: &mut Pick, d: &Path) -> Vec<String> {
    let m = if p.chance(70) {
        TETRA.to_vec()
    } else {
        gen_obj(p)
    };
    let i = file(d, "in.obj", &m);
    let size = if p.chance(60) {
        format!("{}", 16 + p.below(48))
    } else {
        p.count()
    };
    let views = (0..1 + p.below(3))
        .map(|_| *p.of(&["front", "side", "top", "perspective", "nope"]))
        .collect::<Vec<_>>();
    args(&[
        "render",
        &i,
        "-o",
        &out(d, "png"),
        "--size",
        &size,
        "--view",
        &views.join(","),
    ])
}

fn cmd_convert(p: &mut Pick, d: &Path) -> Vec<String> {
    let (name, bytes) = match p.below(3) {
        0 => ("in.obj", gen_obj(p)),
        1 => ("in.ply", gen_ply(p)),
        _ => ("in.stl", gen_stl(p)),
    };
    let i = file(d, name, &bytes);
    let ext = *p.of(&["obj", "stl", "ply", "glb", "fbx"]);
    args(&["convert", &i, "-o", &out(d, ext)])
}

fn cmd_plate_compare(p: &mut Pick, _: &Path) -> Vec<String> {
    let grid = if p.chance(60) {
        format!("{}", 4 + p.below(8))
    } else {
        p.count()
    };
    let it = if p.chance(60) {
        format!("{}", p.below(5))
    } else {
        p.count()
    };
    args(&[
        "plate",
        "compare",
        "--shape",
        *p.of(&["square", "circle", "triangle", "blob"]),
        "--grid",
        &grid,
        "--dm-iterations",
        &it,
        "--dm-step",
        &p.num(),
        "--lap-weight",
        &p.num(),
    ])
}

/// Command targets: (name, generator).
pub fn command_targets() -> Vec<(&'static str, CommandGen)> {
    vec![
        ("gec fit (CSV + numbers)", cmd_gec_fit),
        ("gec eval (JSON + numbers)", cmd_gec_eval),
        ("pde4 eval (spec JSON)", cmd_pde4_eval),
        ("pde6 patch (sections JSON + numbers)", cmd_pde6_patch),
        ("pde6 mode (numbers)", cmd_pde6_mode),
        ("ode6 surface (spec JSON + numbers)", cmd_ode6_surface),
        ("ode6 eval (numbers)", cmd_ode6_eval),
        ("render (mesh + numbers)", cmd_render),
        ("convert (OBJ/PLY/STL)", cmd_convert),
        ("plate compare (numbers)", cmd_plate_compare),
        (
            "profile check (SVG + tolerance)",
            targets::cmd_profile_check,
        ),
    ]
}

/// Command targets too slow for `cargo test`'s debug binary (each case
/// builds a character); the fuzz example runs them on the release binary.
pub fn heavy_command_targets() -> Vec<(&'static str, CommandGen)> {
    vec![("character edit (edit JSON)", targets::cmd_character_edit)]
}

fn runner(seed: u64) -> TestRunner {
    let mut key = [0u8; 32];
    key[..8].copy_from_slice(&seed.to_le_bytes());
    TestRunner::new_with_rng(
        Config::default(),
        TestRng::from_seed(RngAlgorithm::ChaCha, &key),
    )
}

fn picks(r: &mut TestRunner) -> Pick {
    let s = proptest::collection::vec(any::<u64>(), 64);
    Pick {
        seeds: s.new_tree(r).expect("strategy").current(),
        at: 0,
    }
}

fn record(t: &mut Tally, what: &'static str, input: String) {
    match what {
        "panic" => t.panics += 1,
        "hang" => t.hangs += 1,
        _ => t.non_finite += 1,
    }
    if t.first_failure.is_none() {
        t.first_failure = Some(format!("{what}: {input}"));
    }
}

/// Runs every parser target for `cases` cases from `seed`.
pub fn run_parsers(cases: usize, seed: u64, limit: Duration) -> Vec<Tally> {
    parser_targets()
        .into_iter()
        .enumerate()
        .map(|(k, (name, gen, parse))| {
            let mut r = runner(seed.wrapping_add(k as u64));
            let mut t = Tally {
                name: name.into(),
                kind: "parser",
                ..Tally::default()
            };
            for _ in 0..cases {
                let input = gen(&mut picks(&mut r));
                t.cases += 1;
                let copy = input.clone();
                match guarded(limit, move || parse(&copy)) {
                    Ok(Ok(nums)) => {
                        t.accepted += 1;
                        if nums.iter().any(|x| !x.is_finite()) {
                            record(&mut t, "non-finite", String::from_utf8_lossy(&input).into());
                        }
                    }
                    Ok(Err(_)) => {}
                    Err(what) => record(&mut t, what, String::from_utf8_lossy(&input).into()),
                }
            }
            t
        })
        .collect()
}

/// Runs every command target `cases` times through the binary `exe`, in
/// scratch directories under `scratch`.
pub fn run_commands(
    exe: &Path,
    scratch: &Path,
    cases: usize,
    seed: u64,
    limit: Duration,
) -> Vec<Tally> {
    run_command_targets(command_targets(), exe, scratch, cases, seed, limit)
}

/// Runs the given command targets (see [`run_commands`]).
pub fn run_command_targets(
    targets: Vec<(&'static str, CommandGen)>,
    exe: &Path,
    scratch: &Path,
    cases: usize,
    seed: u64,
    limit: Duration,
) -> Vec<Tally> {
    targets
        .into_iter()
        .enumerate()
        .map(|(k, (name, gen))| {
            let mut r = runner(seed.wrapping_add(1000 + k as u64));
            let mut t = Tally {
                name: name.into(),
                kind: "command",
                ..Tally::default()
            };
            let dir: PathBuf = scratch.join(format!("t{k}"));
            for _ in 0..cases {
                let _ = std::fs::remove_dir_all(&dir);
                std::fs::create_dir_all(&dir).expect("scratch dir");
                let a = gen(&mut picks(&mut r), &dir);
                t.cases += 1;
                let shown = a.join(" ");
                match run_binary(exe, &a, limit) {
                    Err(what) => record(&mut t, what, shown),
                    Ok((code, stdout, stderr)) => {
                        if code == Some(101) || stderr.contains("panicked") {
                            record(&mut t, "panic", format!("{shown}\n{stderr}"));
                        } else if code == Some(0) {
                            t.accepted += 1;
                            if has_non_finite(&stdout) || outputs_non_finite(&dir) {
                                record(&mut t, "non-finite", shown);
                            }
                        } else if code != Some(1) && code != Some(2) {
                            record(&mut t, "panic", format!("{shown}: exit {code:?}\n{stderr}"));
                        }
                    }
                }
            }
            let _ = std::fs::remove_dir_all(&dir);
            t
        })
        .collect()
}

fn run_binary(
    exe: &Path,
    a: &[String],
    limit: Duration,
) -> Result<(Option<i32>, String, String), &'static str> {
    let mut child = Command::new(exe)
        .args(a)
        .arg("--json")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("spawn the binary");
    let start = Instant::now();
    loop {
        match child.try_wait().expect("wait") {
            Some(_) => break,
            None if start.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Err("hang");
            }
            None => std::thread::sleep(Duration::from_millis(2)),
        }
    }
    let o = child.wait_with_output().expect("output");
    Ok((
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    ))
}

/// NaN or inf as a token of `s`, or, when `s` is JSON, a null (serde_json's
/// spelling of a non-finite float) anywhere but under the optional fields
/// `tol`, `theta0`, `output` and `boundary`.
fn has_non_finite(s: &str) -> bool {
    if let Ok(v) = serde_json::from_str::<serde_json::Value>(s) {
        return json_null(&v, "");
    }
    s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.'))
        .any(|w| w.eq_ignore_ascii_case("nan") || w.eq_ignore_ascii_case("inf"))
}

fn json_null(v: &serde_json::Value, key: &str) -> bool {
    match v {
        serde_json::Value::Null => !matches!(key, "tol" | "theta0" | "output" | "boundary"),
        serde_json::Value::Array(a) => a.iter().any(|x| json_null(x, key)),
        serde_json::Value::Object(o) => o.iter().any(|(k, x)| json_null(x, k)),
        _ => false,
    }
}

/// A written OBJ/JSON/PLY/STL output with a non-finite number.
fn outputs_non_finite(dir: &Path) -> bool {
    for ext in ["obj", "json"] {
        if let Ok(s) = std::fs::read_to_string(dir.join(format!("out.{ext}"))) {
            if has_non_finite(&s) {
                return true;
            }
        }
    }
    for ext in ["ply", "stl"] {
        let p = dir.join(format!("out.{ext}"));
        if p.exists() && pdesculpt::mesh::io::read(&p).is_err() {
            return true;
        }
    }
    false
}

/// A markdown table of the tallies.
pub fn table(tallies: &[Tally]) -> String {
    let mut s = String::from("| target | kind | inputs | accepted | panics | hangs | non-finite |\n|---|---|---|---|---|---|---|\n");
    for t in tallies {
        s += &format!(
            "| {} | {} | {} | {} | {} | {} | {} |\n",
            t.name, t.kind, t.cases, t.accepted, t.panics, t.hangs, t.non_finite
        );
    }
    s
}
