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
