//! The command line: help, machine output, and clear errors with a non-zero
//! exit on bad input (never a panic).

use std::path::PathBuf;
use std::process::{Command, Output};

pub fn pdesculpt(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pdesculpt"))
        .args(args)
        .output()
        .expect("the binary runs")
}

pub fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("pdesculpt-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Exit code 1, an `error:` line naming `needle`, no panic.
pub fn assert_clear_error(out: &Output, needle: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "stderr: {err}");
    assert!(err.contains("error:"), "stderr: {err}");
    assert!(
        err.contains(needle),
        "stderr should mention {needle:?}: {err}"
    );
    assert!(!err.contains("panicked"), "stderr: {err}");
}

#[test]
fn help_lists_the_subcommands() {
    let out = pdesculpt(&["--help"]);
    assert!(out.status.success());
    let s = String::from_utf8_lossy(&out.stdout);
    for sub in [
        "verify", "render", "convert", "demo", "gec", "pde4", "plate", "pde6", "ode6", "conv",
    ] {
        assert!(s.contains(sub), "--help lists {sub}");
    }
}

#[test]
fn verify_help_names_every_family() {
    let out = pdesculpt(&["verify", "--help"]);
    assert!(out.status.success());
    let s = String::from_utf8_lossy(&out.stdout);
    for f in pdesculpt::verify::families() {
        assert!(
            s.contains(f.name),
            "`verify --help` omits family {}",
            f.name
        );
    }
}

#[test]
fn verify_json_lists_infrastructure_checks() {
    let out = pdesculpt(&["verify", "--family", "jet", "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json on stdout");
    assert_eq!(v["failed"], 0);
    assert!(v["checks"].as_array().expect("checks").len() >= 5);
    let out = pdesculpt(&["verify", "--family", "mesh", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json on stdout");
    assert!(v["checks"]
        .as_array()
        .expect("checks")
        .iter()
        .all(|c| c["family"] == "mesh"));
    assert_clear_error(
        &pdesculpt(&["verify", "--family", "nope"]),
        "unknown family",
    );
}

#[test]
fn bad_mesh_inputs_get_clear_errors() {
    let d = tmpdir("bad");
    let out_obj = d.join("o.obj");
    let o = out_obj.to_str().expect("utf8");
    assert_clear_error(
        &pdesculpt(&["convert", "/no/such/file.obj", "-o", o]),
        "/no/such/file.obj",
    );
    let bad = d.join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nf 1 2 9\n").expect("write");
    assert_clear_error(
        &pdesculpt(&["convert", bad.to_str().expect("utf8"), "-o", o]),
        "bad.obj:3",
    );
    let nan = d.join("nan.obj");
    std::fs::write(&nan, "v 0 0 0\nv 1 NaN 0\nv 0 1 0\nf 1 2 3\n").expect("write");
    assert_clear_error(
        &pdesculpt(&["convert", nan.to_str().expect("utf8"), "-o", o]),
        "nan.obj:2",
    );
    let good = d.join("good.obj");
    std::fs::write(&good, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").expect("write");
    let unknown = d.join("x.fbx");
    assert_clear_error(
        &pdesculpt(&[
            "convert",
            good.to_str().expect("utf8"),
            "-o",
            unknown.to_str().expect("utf8"),
        ]),
        "unknown mesh format",
    );
    assert!(!out_obj.exists(), "no output on failure");
    assert!(!unknown.exists());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn convert_and_render_round_trip() {
    let d = tmpdir("convert");
    let src = d.join("tri.obj");
    std::fs::write(
        &src,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .expect("write");
    for ext in ["glb", "stl", "ply", "obj"] {
        let dst = d.join(format!("out.{ext}"));
        let out = pdesculpt(&[
            "--json",
            "convert",
            src.to_str().expect("utf8"),
            "-o",
            dst.to_str().expect("utf8"),
        ]);
        assert!(
            out.status.success(),
            "{ext}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
        assert_eq!(v["triangles"], 4);
    }
    let png = d.join("t.png");
    let out = pdesculpt(&[
        "render",
        d.join("out.ply").to_str().expect("utf8"),
        "-o",
        png.to_str().expect("utf8"),
        "--view",
        "front,perspective",
        "--size",
        "64",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&png).expect("png");
    assert_eq!(&bytes[1..4], b"PNG");
    assert_clear_error(
        &pdesculpt(&[
            "render",
            src.to_str().expect("utf8"),
            "-o",
            png.to_str().expect("utf8"),
            "--view",
            "sideways",
        ]),
        "unknown view",
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn demo_writes_its_outputs() {
    let d = tmpdir("demo");
    let out = pdesculpt(&["--json", "demo", "--out", d.to_str().expect("utf8")]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for f in ["demo.glb", "demo.obj", "demo.png"] {
        assert!(
            std::fs::metadata(d.join(f))
                .map(|m| m.len() > 1000)
                .unwrap_or(false),
            "{f}"
        );
    }
    std::fs::remove_dir_all(&d).ok();
}

// ---- hardening (issue 18): each case exits 1 with a message naming the
// offending argument, never panics, never leaves an output behind.

fn path(p: &std::path::Path) -> &str {
    p.to_str().expect("utf8 path")
}

/// A unit circle of 64 points as CSV.
fn circle_csv(d: &std::path::Path, name: &str, radius: f64) -> PathBuf {
    let p = d.join(name);
    let rows: Vec<String> = (0..64)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 64.0;
            format!("{},{}", radius * t.cos(), radius * t.sin())
        })
        .collect();
    std::fs::write(&p, rows.join("\n")).expect("write csv");
    p
}

/// A sections file of `n` copies of a fitted circle at z = 0, 1, ...
fn sections_json(d: &std::path::Path, n: usize) -> PathBuf {
    let csv = circle_csv(d, "sec.csv", 1.0);
    let g = d.join("sec-gec.json");
    let out = pdesculpt(&[
        "gec",
        "fit",
        "-i",
        path(&csv),
        "--terms",
        "3",
        "-o",
        path(&g),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let gec: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&g).expect("gec")).expect("json");
    let sections: Vec<serde_json::Value> = (0..n)
        .map(|i| {
            let mut s = gec.clone();
            s["frame"]["origin"][2] = serde_json::json!(i as f64);
            serde_json::json!({"u": i as f64 / (n - 1) as f64, "gec": s})
        })
        .collect();
    let p = d.join(format!("sections{n}.json"));
    std::fs::write(&p, serde_json::json!({ "sections": sections }).to_string()).expect("write");
    p
}

#[test]
fn gec_fit_huge_terms_is_refused_not_wrapped() {
    let d = tmpdir("gec-terms");
    let csv = circle_csv(&d, "c.csv", 1.0);
    for t in ["9223372036854775808", "18446744073709551615", "100000"] {
        let out = pdesculpt(&["gec", "fit", "-i", path(&csv), "--terms", t]);
        assert_clear_error(&out, &format!("--terms = {t}"));
    }
    let out = pdesculpt(&[
        "gec",
        "fit",
        "-i",
        path(&csv),
        "--tol",
        "1e-3",
        "--max-terms",
        "99999999",
    ]);
    assert_clear_error(&out, "--max-terms");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn gec_fit_refuses_to_overwrite_its_input() {
    let d = tmpdir("gec-same");
    let csv = circle_csv(&d, "c.csv", 1.0);
    let before = std::fs::read(&csv).expect("read");
    let out = pdesculpt(&["gec", "fit", "-i", path(&csv), "-o", path(&csv)]);
    assert_clear_error(&out, "is the input file");
    assert_eq!(
        std::fs::read(&csv).expect("read"),
        before,
        "input untouched"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn gec_fit_tiny_circle_is_a_scale_error_not_a_false_coincidence() {
    let d = tmpdir("gec-tiny");
    let csv = circle_csv(&d, "tiny.csv", 1e-200);
    let out = pdesculpt(&["gec", "fit", "-i", path(&csv), "--terms", "3"]);
    assert_clear_error(&out, "rescale");
    assert!(!String::from_utf8_lossy(&out.stderr).contains("coincide"));
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn pde6_patch_counts_are_checked_before_work() {
    let d = tmpdir("pde6-limits");
    let s7 = sections_json(&d, 7);
    let s6 = sections_json(&d, 6);
    let o = d.join("o.obj");
    let huge = "18446744073709551615";
    assert_clear_error(
        &pdesculpt(&["pde6", "patch", path(&s7), "--nu", huge, "-o", path(&o)]),
        "--nu = 18446744073709551615",
    );
    assert_clear_error(
        &pdesculpt(&["pde6", "patch", path(&s7), "--nv", huge, "-o", path(&o)]),
        "--nv = 18446744073709551615",
    );
    assert_clear_error(
        &pdesculpt(&[
            "pde6",
            "patch",
            path(&s7),
            "--nu",
            "100000",
            "--nv",
            "100000",
            "-o",
            path(&o),
        ]),
        "--nu/--nv",
    );
    assert_clear_error(
        &pdesculpt(&[
            "pde6",
            "patch",
            path(&s6),
            "--method",
            "method1",
            "--first",
            huge,
            "-o",
            path(&o),
        ]),
        "first = 18446744073709551615",
    );
    assert!(!o.exists());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn galerkin_cost_is_refused_before_allocating() {
    let d = tmpdir("pde4-cost");
    let spec = d.join("g.json");
    std::fs::write(
        &spec,
        r#"{"patch":"four-sided","method":"galerkin","shape":{"a1":1,"a2":2,"a3":1},
            "terms":[256,256],"forces":[{"type":"uniform","p":[0,0,1]}]}"#,
    )
    .expect("write");
    assert_clear_error(
        &pdesculpt(&["pde4", "eval", path(&spec), "--at", "0.5,0.5"]),
        "terms = [256, 256]",
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn render_refuses_empty_meshes_and_oversized_images() {
    let d = tmpdir("render-limits");
    let png = d.join("o.png");
    let garbage = d.join("g.obj");
    std::fs::write(&garbage, "hello\nworld\n").expect("write");
    assert_clear_error(
        &pdesculpt(&["render", path(&garbage), "-o", path(&png)]),
        "no triangles",
    );
    let good = d.join("t.obj");
    std::fs::write(&good, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").expect("write");
    assert_clear_error(
        &pdesculpt(&[
            "render",
            path(&good),
            "-o",
            path(&png),
            "--size",
            "8192",
            "--view",
            "front,side,top",
        ]),
        "--size 8192",
    );
    assert_clear_error(
        &pdesculpt(&[
            "render",
            path(&good),
            "-o",
            path(&png),
            "--size",
            "18446744073709551615",
        ]),
        "--size = 18446744073709551615",
    );
    assert!(!png.exists());
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn writers_refuse_coordinates_beyond_f32_and_readers_refuse_bad_ply() {
    let d = tmpdir("io-strict");
    let big = d.join("big.obj");
    std::fs::write(&big, "v 1e300 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n").expect("write");
    for ext in ["obj", "stl", "ply", "glb"] {
        let o = d.join(format!("o.{ext}"));
        assert_clear_error(
            &pdesculpt(&["convert", path(&big), "-o", path(&o)]),
            "vertex 0",
        );
        assert!(!o.exists(), "{ext}: nothing written");
    }
    let header = |props: &str, idx: &str| {
        format!("ply\nformat ascii 1.0\nelement vertex 3\n{props}element face 1\nproperty list uchar {idx} vertex_indices\nend_header\n")
    };
    let cases = [
        ("nox.ply", header("property float y\nproperty float z\n", "int") + "0 0\n1 0\n0 1\n3 0 1 2\n", "no scalar property 'x'"),
        ("frac.ply", header("property float x\nproperty float y\nproperty float z\n", "float") + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", "face index 1.5"),
        ("nan.ply", header("property float x\nproperty float y\nproperty float z\n", "float") + "0 0 0\n1 0 0\n0 1 0\n3 0 nan 2\n", "face index NaN"),
        ("count.ply", "ply\nformat ascii 1.0\nelement vertex 999999999999\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n".to_string(), "999999999999"),
    ];
    let o = d.join("o.obj");
    for (name, text, needle) in cases {
        let p = d.join(name);
        std::fs::write(&p, text).expect("write");
        assert_clear_error(&pdesculpt(&["convert", path(&p), "-o", path(&o)]), needle);
    }
    let stl = d.join("cut.stl");
    std::fs::write(
        &stl,
        "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n",
    )
    .expect("write");
    assert_clear_error(
        &pdesculpt(&["convert", path(&stl), "-o", path(&o)]),
        "ends inside a facet",
    );
    assert_clear_error(
        &pdesculpt(&["convert", path(&big), "-o", path(&big)]),
        "is the input file",
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn eval_commands_refuse_arguments_outside_their_domain() {
    assert_clear_error(
        &pdesculpt(&[
            "pde6",
            "mode",
            "--a",
            "0.5",
            "--n",
            "1",
            "--values",
            "1,2,3,4,5,6",
            "--at",
            "1e300",
        ]),
        "--at",
    );
    assert_clear_error(
        &pdesculpt(&[
            "ode6",
            "eval",
            "--rho",
            "1",
            "--eta",
            "1",
            "--lambda",
            "1",
            "--bc",
            "1,0,0,1,0,0",
            "--at",
            "1e5",
        ]),
        "--at 100000",
    );
}

#[test]
fn demo_checks_its_output_directory_before_building() {
    let d = tmpdir("demo-out");
    let f = d.join("file");
    std::fs::write(&f, "x").expect("write");
    assert_clear_error(&pdesculpt(&["demo", "-o", path(&f)]), "is a file");
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn stale_temporaries_of_dead_processes_are_swept() {
    let d = tmpdir("sweep");
    let mut child = Command::new("true").spawn().expect("spawn");
    let dead = child.id();
    child.wait().expect("wait");
    let stale = d.join(format!(".o.obj.tmp-{dead}"));
    std::fs::write(&stale, "half a file").expect("write");
    let src = d.join("t.obj");
    std::fs::write(&src, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").expect("write");
    let out = pdesculpt(&["convert", path(&src), "-o", path(&d.join("o.obj"))]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(!stale.exists(), "the stale temporary is removed");
    std::fs::remove_dir_all(&d).ok();
}

/// Rounding of a coordinate stored in an OBJ (32-bit floats) near 1.
const OBJ_F32: f64 = 1e-6;

/// `pde4 apply` takes negative numbers as values (an axis starting at a
/// negative coordinate, an inward drag, a direction toward -x); before,
/// clap read `-1,...` as an unknown flag and stopped with a usage error
/// (exit 2) instead of deforming or naming the bad value. A negative
/// radius is a named error, exit 1.
#[test]
fn pde4_apply_takes_negative_values() {
    use pdesculpt::surface::{tessellate, Revolution, Tessellation};
    let d = tmpdir("pde4-negative");
    let part = tessellate(
        &Revolution { r0: 1.0, r1: 0.2 },
        Tessellation { nu: 20, nv: 16 },
    );
    let (mesh, out) = (d.join("part.obj"), d.join("out.obj"));
    pdesculpt::mesh::io::write(&part, &mesh).expect("writes the part");
    let spec = d.join("two.json");
    std::fs::write(
        &spec,
        r#"{"patch":"two-sided","method":"exact","shape":{"a1":1,"a2":1,"a3":1},"terms":[12,6],"forces":[{"type":"area","u0":0.3,"u1":0.7,"v0":0.1,"v1":0.4,"p":[1,0,0]}]}"#,
    )
    .expect("writes the spec");
    let run = |extra: &[&str]| {
        let mut a = vec![
            "pde4",
            "apply",
            path(&spec),
            "--mesh",
            path(&mesh),
            "--out",
            path(&out),
        ];
        a.extend_from_slice(extra);
        pdesculpt(&a)
    };
    let ok = run(&[
        "--axis",
        "0,-1,0,0,2,0",
        "--u-range",
        "0.3,0.6",
        "--drag",
        "-0.05",
        "--direction",
        "-1,0,0",
    ]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let moved = pdesculpt::mesh::io::read(&out).expect("reads the output");
    // a negative drag along -x: the largest move is |drag| toward +x (OBJ
    // stores 32-bit floats)
    let dx = moved
        .positions
        .iter()
        .zip(&part.positions)
        .map(|(p, q)| p[0] - q[0])
        .fold(f64::NEG_INFINITY, f64::max);
    assert!((dx - 0.05).abs() < OBJ_F32, "largest move along +x {dx}");
    std::fs::remove_file(&out).expect("removes the output");
    let bad = run(&["--axis", "0,-1,0,0,2,0", "--radius", "-1", "--drag", "0.1"]);
    assert_clear_error(&bad, "radius");
    assert!(!out.exists(), "a refused apply wrote a file");
    let _ = std::fs::remove_dir_all(&d);
}
