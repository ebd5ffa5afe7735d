//! Integration tests of the plate family (paper 001).

use pdesculpt::check::tol;
use pdesculpt::mesh::io;
use pdesculpt::mesh::Mesh;
use pdesculpt::plate::baselines::{DeltaMushParams, LaplacianParams};
use pdesculpt::plate::check::{ellipse_centre, observed_order, rectangle_centre};
use pdesculpt::plate::shapes::{compare, region_in_polygon, sheet, Shape};
use pdesculpt::plate::{
    BoundaryMethod, Direction, MappingMethod, Material, PlateDeformer, PlateError, RegionOptions,
};
use proptest::prelude::*;

/// Accepted band of the observed convergence order (expected 2).
const ORDER_BAND: (f64, f64) = (1.75, 2.25);
/// The peak weight sits at the mesh vertex nearest the region's centre, not
/// at the centre: on the 20x20 sheet it reaches this fraction of the
/// closed-form centre value `s d / (64 D)` at least.
const SHEET_PEAK_FRACTION: f64 = 0.9;
/// The same on the coarse body mesh, whose region is a few rings wide.
const BODY_PEAK_FRACTION: f64 = 0.5;
/// A force this small counts as zero for the relative residual of eq 3.
const FORCE_FLOOR: f64 = 1e-12;

fn top() -> RegionOptions {
    RegionOptions::default().with_view(Some([0.0, 0.0, 1.0]))
}

fn ellipse_poly(a: f64, b: f64, rot: f64) -> Vec<[f64; 2]> {
    (0..64)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 64.0;
            let (x, y) = (a * t.cos(), b * t.sin());
            [x * rot.cos() - y * rot.sin(), x * rot.sin() + y * rot.cos()]
        })
        .collect()
}

#[test]
fn plate_checks_pass() {
    let c = crate::shared::family_checks("plate");
    assert!(c.len() >= 15);
    for k in c {
        assert!(
            k.passed,
            "{} failed: {} > {}",
            k.name, k.measured, k.tolerance
        );
    }
}

#[test]
fn plate_reference_converges_at_order_two() {
    let sq = [8, 16, 32].map(|n| rectangle_centre(1.0, 1.0, n).unwrap());
    let p = observed_order(sq);
    assert!(p > ORDER_BAND.0 && p < ORDER_BAND.1, "square order {p}");
    // disk against the exact solution: error ratio between ring counts 8, 16
    let e = [8, 16].map(|r| (ellipse_centre(1.0, 1.0, r).unwrap() * 64.0 - 1.0).abs());
    let p = (e[0] / e[1]).log2();
    assert!(p > ORDER_BAND.0 && p < ORDER_BAND.1, "disk order {p}");
}

#[test]
fn plate_deformer_moves_only_the_interior_and_is_linear_in_the_force() {
    let mesh = sheet(30);
    let region = region_in_polygon(&mesh, &Shape::Triangle.polygon());
    let p = PlateDeformer::new(&mesh, &region, &top()).unwrap();
    let d = [0.3, -0.2, 1.0];
    let m1 = p.deform(&mesh, d, 40.0, Direction::Cursor).unwrap();
    let m2 = p.deform(&mesh, d, 80.0, Direction::Cursor).unwrap();
    let mut inside = vec![false; mesh.positions.len()];
    for &v in p.region() {
        inside[v as usize] = true;
    }
    for i in 0..mesh.positions.len() {
        let (a, b, c) = (mesh.positions[i], m1.positions[i], m2.positions[i]);
        if !inside[i] {
            assert_eq!(a, b);
        }
        for k in 0..3 {
            let (d1, d2) = (b[k] - a[k], c[k] - a[k]);
            assert!((d2 - 2.0 * d1).abs() <= tol::ROUNDING * (1.0 + d2.abs()));
        }
    }
    for &i in &p.boundary().loop_indices {
        let v = p.region()[i] as usize;
        assert_eq!(mesh.positions[v], m1.positions[v]);
    }
    // centre moves by s d /(64 D) within the discretisation of the centroid
    let peak = p.weights().iter().fold(0.0f64, |m, w| m.max(*w));
    let bound = 1.0 / (64.0 * p.rigidity());
    assert!(peak <= bound * (1.0 + tol::ROUNDING));
    assert!(peak > SHEET_PEAK_FRACTION * bound);
}

#[test]
fn plate_normal_direction_follows_the_region_normal() {
    let mesh = sheet(20);
    let region = region_in_polygon(&mesh, &Shape::Square.polygon());
    let p = PlateDeformer::new(&mesh, &region, &RegionOptions::default()).unwrap();
    let f = p.force([0.5, 0.5, 2.0], 10.0, Direction::Normal);
    assert!(f[0].abs() < tol::ROUNDING && f[1].abs() < tol::ROUNDING);
    assert!((f[2].abs() - 20.0).abs() < tol::ROUNDING * 20.0);
}

#[test]
fn plate_comparison_ordering() {
    let (dm, lap) = (DeltaMushParams::default(), LaplacianParams::default());
    for s in Shape::ALL {
        let c = compare(s, 40, &dm, &lap).unwrap();
        let rms = |m: &str| c.errors.iter().find(|e| e.method == m).unwrap().rms;
        // the paper's claim holds for these shapes; for the triangle and the
        // pentagram it does not (see the comparison table), so no assertion
        if matches!(s, Shape::Square | Shape::Rectangle | Shape::Circle) {
            assert!(rms("ours") < rms("delta_mush"), "{s:?}: {:?}", c.errors);
            assert!(rms("ours") < rms("laplacian"), "{s:?}: {:?}", c.errors);
        }
        for w in [&c.truth, &c.ours, &c.delta_mush, &c.laplacian] {
            assert!(w.iter().all(|x| x.is_finite()));
        }
    }
}

fn uv_sphere(n: usize) -> Mesh {
    let mut pos = Vec::new();
    let mut tris = Vec::new();
    for j in 0..=n {
        let th = std::f64::consts::PI * j as f64 / n as f64;
        for i in 0..2 * n {
            let ph = std::f64::consts::PI * i as f64 / n as f64;
            pos.push([th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]);
        }
    }
    let id = |i: usize, j: usize| (j * 2 * n + i % (2 * n)) as u32;
    for j in 0..n {
        for i in 0..2 * n {
            tris.push([id(i, j), id(i, j + 1), id(i + 1, j + 1)]);
            tris.push([id(i, j), id(i + 1, j + 1), id(i + 1, j)]);
        }
    }
    Mesh::new(pos, tris)
}

#[test]
fn plate_stated_limits_and_bad_input_are_clear_errors() {
    let mesh = sheet(20);
    let all: Vec<u32> = region_in_polygon(&mesh, &Shape::Square.polygon());
    // tiny / empty selection
    assert!(matches!(
        PlateDeformer::new(&mesh, &[], &top()),
        Err(PlateError::TooFewVertices(0, _))
    ));
    assert!(matches!(
        PlateDeformer::new(&mesh, &all[..2], &top()),
        Err(PlateError::TooFewVertices(2, _))
    ));
    // out of bounds
    assert!(matches!(
        PlateDeformer::new(&mesh, &[0, 1, 2, 99_999], &top()),
        Err(PlateError::VertexOutOfBounds(99_999, _))
    ));
    // NaN
    let mut bad = mesh.clone();
    bad.positions[all[3] as usize][1] = f64::NAN;
    assert!(matches!(
        PlateDeformer::new(&bad, &all, &top()),
        Err(PlateError::NonFinite(_))
    ));
    // edge-on view: degenerate projection
    let side = RegionOptions::default().with_view(Some([1.0, 0.0, 0.0]));
    assert!(matches!(
        PlateDeformer::new(&mesh, &all, &side),
        Err(PlateError::DegenerateProjection(_))
    ));
    // alpha_0 out of range, and too small to close the boundary
    let mut o = top();
    o.alpha0 = 0.3;
    assert!(matches!(
        PlateDeformer::new(&mesh, &all, &o),
        Err(PlateError::Parameter { .. })
    ));
    o.alpha0 = 0.6;
    assert!(matches!(
        PlateDeformer::new(&mesh, &all, &o),
        Err(PlateError::BoundaryNotClosed { .. })
    ));
    // bad material
    let mut o = top();
    o.material = Material {
        poisson: 0.7,
        ..Material::default()
    };
    assert!(matches!(
        PlateDeformer::new(&mesh, &all, &o),
        Err(PlateError::Parameter { .. })
    ));
    // limit 2: C-shaped region, centroid in the gap
    let c_shape: Vec<u32> = (0..mesh.positions.len() as u32)
        .filter(|&i| {
            let p = mesh.positions[i as usize];
            let r = p[0].hypot(p[1]);
            (0.7..=1.2).contains(&r) && p[0] < 0.5
        })
        .collect();
    assert!(matches!(
        PlateDeformer::new(&mesh, &c_shape, &top()),
        Err(PlateError::CentroidOutside)
    ));
    // ... which the harmonic mapping handles
    let harmonic = top().with_mapping(MappingMethod::Harmonic);
    let p = PlateDeformer::new(&mesh, &c_shape, &harmonic).unwrap();
    assert!(p.weights().iter().all(|w| w.is_finite() && *w >= 0.0));
    assert!(p.weights().iter().any(|w| *w > 0.0));
    for &i in &p.boundary().loop_indices {
        assert_eq!(p.weights()[i], 0.0);
    }
    // limit 1: an equatorial band of a sphere seen from the pole overlaps
    let s = uv_sphere(16);
    let band: Vec<u32> = (0..s.positions.len() as u32)
        .filter(|&i| s.positions[i as usize][2].abs() < 0.45)
        .collect();
    assert!(matches!(
        PlateDeformer::new(&s, &band, &top()),
        Err(PlateError::OverlappingProjection(_))
    ));
    // a cap of the sphere is fine
    let cap: Vec<u32> = (0..s.positions.len() as u32)
        .filter(|&i| s.positions[i as usize][2] > 0.5)
        .collect();
    // the paper's alpha rule (alpha = 0.86 d_P) fails on the crowded pole ...
    assert!(matches!(
        PlateDeformer::new(&s, &cap, &RegionOptions::default()),
        Err(PlateError::BoundaryNotClosed { .. })
    ));
    // ... the mesh-edge boundary does not
    let mesh_edges = RegionOptions::default().with_boundary(BoundaryMethod::MeshEdges);
    let p = PlateDeformer::new(&s, &cap, &mesh_edges).unwrap();
    let m = p
        .deform(&s, [0.0, 0.0, 1.0], 70.0, Direction::Normal)
        .unwrap();
    assert!(m.positions.iter().flatten().all(|c| c.is_finite()));
    // non-finite force
    assert!(p
        .deform(&s, [f64::NAN, 0.0, 0.0], 70.0, Direction::Cursor)
        .is_err());
}

proptest! {
    #![proptest_config(crate::strategies::config(32))]
    #[test]
    fn plate_pipeline_sweeps_documented_ranges(
        a in 0.4f64..1.15, b in 0.4f64..1.15, rot in 0.0f64..3.2,
        s in 0.0f64..200.0, dx in -1.0f64..1.0, dy in -1.0f64..1.0, dz in -1.0f64..1.0,
        alpha0 in 0.75f64..1.5, young in 1e3f64..1e8, mu in 0.0f64..0.5, h in 0.01f64..1.0,
        normal in any::<bool>(), harmonic in any::<bool>(),
    ) {
        let mesh = sheet(24);
        let region = region_in_polygon(&mesh, &ellipse_poly(a, b, rot));
        let opts = RegionOptions::default().with_material(Material { young, poisson: mu, thickness: h }).with_alpha0(alpha0).with_view(Some([0.0, 0.0, 1.0])).with_mapping(if harmonic { MappingMethod::Harmonic } else { MappingMethod::LengthBased });
        let p = PlateDeformer::new(&mesh, &region, &opts).unwrap();
        let dir = if normal { Direction::Normal } else { Direction::Cursor };
        let m = p.deform(&mesh, [dx, dy, dz], s, dir).unwrap();
        prop_assert!(m.positions.iter().flatten().all(|c| c.is_finite()));
        for &i in &p.boundary().loop_indices {
            let v = p.region()[i] as usize;
            prop_assert_eq!(mesh.positions[v], m.positions[v]);
        }
        prop_assert!(p.weights().iter().all(|w| w.is_finite() && *w >= 0.0));
    }
}

#[test]
fn plate_cli_deform_and_compare() {
    let dir = std::env::temp_dir().join(format!("plate_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mesh = sheet(16);
    let input = dir.join("sheet.obj");
    io::write(&mesh, &input).unwrap();
    let region = region_in_polygon(&mesh, &Shape::Circle.polygon());
    let rfile = dir.join("region.txt");
    let text: Vec<String> = region.iter().map(|v| v.to_string()).collect();
    std::fs::write(&rfile, text.join(" ")).unwrap();
    let out = dir.join("out.obj");
    let bin = env!("CARGO_BIN_EXE_pdesculpt");
    let st = std::process::Command::new(bin)
        .args(["plate", "deform"])
        .arg(&input)
        .arg("--region")
        .arg(&rfile)
        .args(["--force", "0,0,1", "--sensitivity", "110", "--normal", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        st.status.success(),
        "{}",
        String::from_utf8_lossy(&st.stderr)
    );
    let m = io::read(&out).unwrap();
    let zmax = m.positions.iter().map(|p| p[2]).fold(0.0, f64::max);
    assert!(zmax > 0.0);
    // bad region file: clear error, exit 1
    std::fs::write(&rfile, "1 2 x").unwrap();
    let st = std::process::Command::new(bin)
        .args(["plate", "deform"])
        .arg(&input)
        .arg("--region")
        .arg(&rfile)
        .args(["--force", "0,0,1", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(st.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&st.stderr).contains("not a vertex index"));
    let st = crate::cli::pdesculpt(&[
        "--json", "plate", "compare", "--shape", "square", "--grid", "24",
    ]);
    assert!(st.status.success());
    let v: serde_json::Value = serde_json::from_slice(&st.stdout).unwrap();
    assert_eq!(v["errors"].as_array().unwrap().len(), 4);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn plate_on_the_makehuman_belly() {
    let body = pdesculpt::makehuman::base_body().unwrap().mesh;
    // a patch of the front of the torso (Y up, facing +z)
    let (lo, hi) = body.bbox();
    let height = hi[1] - lo[1];
    let centre_y = lo[1] + 0.6 * height;
    let normals = body.vertex_normals();
    let front = |i: usize| {
        let p = body.positions[i];
        p[0].abs() < 0.08 * height && (p[1] - centre_y).abs() < 0.06 * height && normals[i][2] > 0.5
    };
    let region: Vec<u32> = (0..body.positions.len())
        .filter(|&i| front(i))
        .map(|i| i as u32)
        .collect();
    assert!(region.len() > 20, "{} region vertices", region.len());
    let opts = RegionOptions::default()
        .with_view(Some([0.0, 0.0, 1.0]))
        .with_boundary(BoundaryMethod::MeshEdges);
    let p = PlateDeformer::new(&body, &region, &opts).unwrap();
    let s = 70.0;
    let d = [0.0, 0.0, 1.0];
    let m = p.deform(&body, d, s, Direction::Normal).unwrap();
    assert!(m.positions.iter().flatten().all(|c| c.is_finite()));
    let disp: Vec<f64> = m
        .positions
        .iter()
        .zip(&body.positions)
        .map(|(a, b)| pdesculpt::mesh::dist(*a, *b))
        .collect();
    let peak = disp.iter().fold(0.0f64, |a, b| a.max(*b));
    let bound = s / (64.0 * p.rigidity());
    assert!(
        peak <= bound * (1.0 + tol::ROUNDING) && peak > BODY_PEAK_FRACTION * bound,
        "{peak} vs {bound}"
    );
    for &i in &p.boundary().loop_indices {
        assert_eq!(disp[p.region()[i] as usize], 0.0);
    }
}

#[test]
fn plate_region_files_vertex_list_and_lasso() {
    use pdesculpt::plate::parse_region;
    let mesh = sheet(20);
    assert_eq!(
        parse_region("1, 2 3\n# comment\n4", &mesh).unwrap(),
        vec![1, 2, 3, 4]
    );
    assert_eq!(
        parse_region(r#"{"vertices": [5, 6]}"#, &mesh).unwrap(),
        vec![5, 6]
    );
    // a lasso square seen from +z selects the same vertices as the polygon
    let lasso = r#"{"lasso": {"view": [0, 0, 1], "polygon": [[-0.5,-0.5],[0.5,-0.5],[0.5,0.5],[-0.5,0.5]]}}"#;
    let mut a = parse_region(lasso, &mesh).unwrap();
    let sq = [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]];
    let frame = pdesculpt::plate::projection::LocalFrame::new([0.0; 3], [0.0, 0.0, 1.0]).unwrap();
    let mut b: Vec<u32> = (0..mesh.positions.len() as u32)
        .filter(|&i| {
            let l = frame.to_local(mesh.positions[i as usize]);
            pdesculpt::polygon::point_in_polygon(&sq, [l[0], l[1]])
        })
        .collect();
    a.sort_unstable();
    b.sort_unstable();
    assert!(!a.is_empty());
    assert_eq!(a, b);
    assert!(parse_region(r#"{"foo": 1}"#, &mesh).is_err());
    assert!(parse_region(
        r#"{"lasso": {"view": [0, 0, 1], "polygon": [[0, 0]]}}"#,
        &mesh
    )
    .is_err());
    assert!(parse_region("{not json", &mesh).is_err());
}

proptest! {
    #![proptest_config(crate::strategies::config(12))]
    #[test]
    fn plate_compare_sweeps_baseline_parameters(
        shape in 0usize..5, grid in 16usize..36, iterations in 1usize..60,
        step in 0.05f64..1.0, handle_weight in 0.1f64..100.0, uniform in any::<bool>(),
    ) {
        use pdesculpt::plate::baselines::Weights;
        let dm = DeltaMushParams { iterations, step };
        let lap = LaplacianParams {
            weights: if uniform { Weights::Uniform } else { Weights::Cotangent },
            handle_weight,
        };
        let c = compare(Shape::ALL[shape], grid, &dm, &lap).unwrap();
        for e in &c.errors {
            prop_assert!(e.rms.is_finite() && e.max.is_finite() && e.rms <= e.max + tol::ROUNDING);
        }
        prop_assert!(c.amplitude_ratio.is_finite() && c.amplitude_ratio > 0.0);
    }
}

#[test]
fn plate_compare_rejects_bad_parameters() {
    let lap = LaplacianParams::default();
    let bad_step = DeltaMushParams {
        iterations: 10,
        step: 1.5,
    };
    assert!(compare(Shape::Square, 20, &bad_step, &lap).is_err());
    let bad_w = LaplacianParams {
        handle_weight: f64::NAN,
        ..lap
    };
    assert!(compare(Shape::Square, 20, &DeltaMushParams::default(), &bad_w).is_err());
    assert!(compare(Shape::Square, 4, &DeltaMushParams::default(), &lap).is_err());
}

#[test]
fn plate_cli_bad_input_is_a_clear_error() {
    let dir = std::env::temp_dir().join(format!("plate_cli_bad_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mesh = sheet(16);
    let input = dir.join("sheet.obj");
    io::write(&mesh, &input).unwrap();
    let square = region_in_polygon(&mesh, &Shape::Square.polygon());
    let list = |r: &[u32]| {
        r.iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join(" ")
    };
    // a sheet whose OBJ holds a NaN coordinate
    let nan_obj = dir.join("nan.obj");
    let text = std::fs::read_to_string(&input).unwrap();
    let mut done = false;
    let lines: Vec<String> = text
        .lines()
        .map(|l| {
            if !done && l.starts_with("v ") {
                done = true;
                "v nan 0 0".to_string()
            } else {
                l.to_string()
            }
        })
        .collect();
    std::fs::write(&nan_obj, lines.join("\n")).unwrap();
    // C-shaped region: centroid in the gap (paper limit 2)
    let c_shape: Vec<u32> = (0..mesh.positions.len() as u32)
        .filter(|&i| {
            let p = mesh.positions[i as usize];
            let r = p[0].hypot(p[1]);
            (0.7..=1.2).contains(&r) && p[0] < 0.5
        })
        .collect();
    let out = dir.join("out.obj");
    let bin = env!("CARGO_BIN_EXE_pdesculpt");
    // (region text, mesh, extra args, expected message)
    let cases: Vec<(String, &std::path::Path, Vec<&str>, &str)> = vec![
        (String::new(), &input, vec![], "region has 0 vertices"),
        (list(&square[..2]), &input, vec![], "region has 2 vertices"),
        (
            list(&square),
            &input,
            vec!["--view", "1,0,0"],
            "degenerate projection",
        ),
        (
            list(&square),
            &input,
            vec!["--alpha0", "0.6"],
            "does not close",
        ),
        (
            list(&square),
            &input,
            vec!["--force", "nan,0,0"],
            "--force needs three finite numbers",
        ),
        (
            list(&square),
            &input,
            vec!["--sensitivity", "nan"],
            "--sensitivity must be finite",
        ),
        (list(&square), &nan_obj, vec![], "non-finite"),
        (list(&c_shape), &input, vec![], "centroid lies outside"),
        (list(&square), &input, vec!["--poisson", "0.7"], "mu"),
    ];
    let rfile = dir.join("region.txt");
    for (region, mesh_path, extra, expect) in cases {
        std::fs::write(&rfile, &region).unwrap();
        let mut cmd = std::process::Command::new(bin);
        cmd.args(["plate", "deform"])
            .arg(mesh_path)
            .arg("--region")
            .arg(&rfile)
            .args(["-o"])
            .arg(&out);
        if !extra.contains(&"--force") {
            cmd.args(["--force", "0,0,1"]);
        }
        let st = cmd.args(&extra).output().unwrap();
        let err = String::from_utf8_lossy(&st.stderr);
        assert_eq!(st.status.code(), Some(1), "{extra:?}: {err}");
        assert!(
            err.contains(expect),
            "{extra:?}: expected {expect:?} in {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
        assert!(!out.exists(), "{extra:?} wrote an output");
    }
    // the harmonic mapping handles the C-shaped region
    std::fs::write(&rfile, list(&c_shape)).unwrap();
    let st = std::process::Command::new(bin)
        .args(["plate", "deform"])
        .arg(&input)
        .arg("--region")
        .arg(&rfile)
        .args(["--force", "0,0,1", "--harmonic", "-o"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        st.status.success(),
        "{}",
        String::from_utf8_lossy(&st.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

proptest! {
    #![proptest_config(crate::strategies::config(64))]
    /// Eq 3 and eq 12 over the documented material ranges (E > 0, mu in
    /// [0, 0.5], h > 0) and forces: the biharmonic residual equals q/D and
    /// the C1 conditions hold on the unit circle, measured with jets.
    #[test]
    fn plate_model_checks_hold_over_material_ranges(
        young in 1e2f64..1e9, mu in 0.0f64..=0.5, h in 1e-3f64..1.0,
        q in -1e3f64..1e3, r in 0.0f64..1.0, th in 0.0f64..6.3, tb in 0.0f64..6.3,
    ) {
        use pdesculpt::jet::Jet4x4;
        use pdesculpt::plate::disk_solution;
        let d = Material { young, poisson: mu, thickness: h }.rigidity().unwrap();
        prop_assert!(d.is_finite() && d > 0.0);
        let w = disk_solution(q, d, Jet4x4::var_u(r * th.cos()), Jet4x4::var_v(r * th.sin()));
        let bl = w.deriv(4, 0) + 2.0 * w.deriv(2, 2) + w.deriv(0, 4);
        prop_assert!((d * bl - q).abs() <= tol::SOLVE * q.abs().max(FORCE_FLOOR), "residual {}", d * bl - q);
        let wb = disk_solution(q, d, Jet4x4::var_u(tb.cos()), Jet4x4::var_v(tb.sin()));
        let scale = (q / d).abs().max(1e-300);
        for v in [wb.value(), wb.deriv(1, 0), wb.deriv(0, 1)] {
            prop_assert!(v.abs() <= tol::ROUNDING * scale, "boundary value {v}");
        }
    }
}
