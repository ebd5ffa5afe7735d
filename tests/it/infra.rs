//! Infrastructure: jets, meshes, files, MakeHuman data, rendering.

use crate::strategies::{point3, tube_mesh};
use pdesculpt::check::tol;
use pdesculpt::jet::{Jet, Jet6x6, Real};
use pdesculpt::makehuman;
use pdesculpt::mesh::io::{self, parse_obj};
use pdesculpt::mesh::{metrics, topology, Mesh, MeshError};
use pdesculpt::render::{render, RenderOptions, View};
use proptest::prelude::*;

fn tmpdir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("pdesculpt-it-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

#[test]
fn jet_product_rule_holds_for_mixed_orders() {
    // d^3/du^2 dv (u^3 v^2) = 12 u v
    let (u, v) = (Jet6x6::var_u(1.5), Jet6x6::var_v(-0.5));
    let f = u.powi(3) * v.powi(2);
    assert!((f.deriv(2, 1) - 12.0 * 1.5 * -0.5).abs() < tol::ROUNDING * 10.0);
    assert!((f.deriv(3, 2) - 12.0).abs() < tol::ROUNDING * 10.0);
    assert_eq!(f.deriv(4, 0), 0.0);
}

proptest! {
    #![proptest_config(crate::strategies::config(64))]

    #[test]
    fn jet_quotient_times_divisor_is_identity(a in -3.0f64..3.0, b in 0.5f64..3.0) {
        let x = Jet::<5, 5>::var_u(a) * Jet::var_v(b) + 1.0;
        let y = Jet::<5, 5>::var_v(b).exp() + Jet::var_u(a).sin();
        let back = (x / y) * y;
        for i in 0..5 {
            for j in 0..5 {
                let want = x.deriv(i, j);
                prop_assert!((back.deriv(i, j) - want).abs() <= tol::SOLVE * want.abs().max(1.0));
            }
        }
    }

    #[test]
    fn real_f64_and_jet_values_agree(a in 0.1f64..3.0) {
        let f = |x: Jet<3, 1>| x.sqrt().atan2(x.ln() + 2.0).cosh();
        let g = |x: f64| x.sqrt().atan2(x.ln() + 2.0).cosh();
        prop_assert!((f(Jet::var_u(a)).value() - g(a)).abs() <= tol::ROUNDING * g(a).abs().max(1.0));
    }

    #[test]
    fn tessellated_tubes_are_oriented_manifolds(m in tube_mesh()) {
        let r = topology::report(&m);
        prop_assert!(r.manifold && r.oriented);
        prop_assert!(m.validate().is_ok());
    }

    #[test]
    fn bvh_matches_brute_force(m in tube_mesh(), p in point3(3.0)) {
        let bvh = metrics::TriangleBvh::new(&m);
        let fast = bvh.closest(p).map(|c| c.1).unwrap_or(f64::INFINITY);
        let brute = (0..m.triangles.len())
            .map(|t| {
                let [a, b, c] = m.corners(t);
                pdesculpt::mesh::dist(p, metrics::closest_point_on_triangle(p, a, b, c))
            })
            .fold(f64::INFINITY, f64::min);
        prop_assert!((fast - brute).abs() <= tol::ROUNDING);
    }

    #[test]
    fn obj_parser_never_panics(s in "[vfg0-9 ./#\\-\n]{0,200}") {
        let _ = parse_obj(&s, "fuzz.obj");
    }
}

#[test]
fn torus_mesh_is_the_tessellated_torus_surface() {
    // mesh::samples builds its torus without the surface layer above it;
    // the parametric surface sample must stay the same torus, bit for bit.
    use pdesculpt::mesh::samples::{torus_mesh, TORUS_RADII};
    use pdesculpt::surface::{samples::Torus, tessellate, Tessellation};
    for n in [3, 12, 24] {
        let (big, small) = TORUS_RADII;
        let s = tessellate(&Torus { big, small }, Tessellation { nu: 2 * n, nv: n });
        let m = torus_mesh(n);
        assert_eq!(m.positions, s.positions, "n = {n}");
        assert_eq!(m.triangles, s.triangles, "n = {n}");
    }
}

#[test]
fn malformed_obj_names_the_line() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
    match parse_obj(text, "bad.obj") {
        Err(MeshError::Parse { line, .. }) => assert_eq!(line, 4),
        other => panic!("expected a parse error, got {other:?}"),
    }
    let nan = "v 0 nan 0\n";
    assert!(matches!(
        parse_obj(nan, "nan.obj"),
        Err(MeshError::Parse { line: 1, .. })
    ));
    let short = "v 0 0\n";
    assert!(matches!(
        parse_obj(short, "short.obj"),
        Err(MeshError::Parse { line: 1, .. })
    ));
}

#[test]
fn obj_groups_and_negative_indices() {
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ng a\nf 1 2 3 4\ng b\nf -4 -2 -1\n";
    let m = parse_obj(text, "g.obj").expect("parses");
    assert_eq!(m.groups, vec!["a".to_string(), "b".to_string()]);
    assert_eq!(m.triangles.len(), 3);
    assert_eq!(m.tri_group, vec![0, 0, 1]);
    assert_eq!(m.triangles[2], [0, 2, 3]);
}

#[test]
fn writing_validates_and_never_leaves_partial_files() {
    let d = tmpdir("atomic");
    let good = Mesh::new(
        vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        vec![[0, 1, 2]],
    );
    let path = d.join("m.obj");
    io::write(&good, &path).expect("writes");
    let before = std::fs::read(&path).expect("exists");
    let mut bad = good.clone();
    bad.positions[1][2] = f64::NAN;
    assert!(matches!(
        io::write(&bad, &path),
        Err(MeshError::NonFinite { index: 1, .. })
    ));
    assert_eq!(
        std::fs::read(&path).expect("still there"),
        before,
        "previous file kept"
    );
    let leftovers: Vec<_> = std::fs::read_dir(&d)
        .expect("dir")
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains(".tmp-"))
        .collect();
    assert!(leftovers.is_empty());
    assert!(matches!(
        io::write(&good, &d.join("m.xyz")),
        Err(MeshError::UnknownFormat { .. })
    ));
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn glb_is_well_formed() {
    let m = pdesculpt::surface::tessellate(
        &pdesculpt::surface::Revolution { r0: 1.0, r1: 0.2 },
        pdesculpt::surface::Tessellation { nu: 4, nv: 8 },
    );
    let b = io::encode(&m, io::Format::Glb).expect("encodes");
    assert_eq!(&b[0..4], b"glTF");
    let total = u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize;
    assert_eq!(total, b.len());
    let json_len = u32::from_le_bytes([b[12], b[13], b[14], b[15]]) as usize;
    assert_eq!(&b[16..20], b"JSON");
    assert_eq!(json_len % 4, 0);
    let doc: serde_json::Value = serde_json::from_slice(&b[20..20 + json_len]).expect("json");
    let bin_len =
        u32::from_le_bytes(b[20 + json_len..24 + json_len].try_into().expect("4 bytes")) as usize;
    assert_eq!(&b[24 + json_len..28 + json_len], b"BIN\0");
    let declared = doc["buffers"][0]["byteLength"]
        .as_u64()
        .expect("byteLength") as usize;
    assert!(
        declared <= bin_len && bin_len - declared < 4,
        "BIN chunk is the buffer plus padding"
    );
    for view in doc["bufferViews"].as_array().expect("views") {
        let end =
            view["byteOffset"].as_u64().unwrap_or(0) + view["byteLength"].as_u64().unwrap_or(0);
        assert!(end as usize <= bin_len);
    }
    assert_eq!(
        doc["accessors"][0]["count"].as_u64(),
        Some(m.positions.len() as u64)
    );
}

#[test]
fn makehuman_body_loads_with_targets() {
    let base = makehuman::base_body().expect("base body");
    assert_eq!(base.mesh.groups, vec!["body".to_string()]);
    assert_eq!(base.mesh.triangles.len(), 2 * 13_378);
    let (lo, hi) = base.mesh.bbox();
    let height = hi[1] - lo[1];
    assert!((15.0..18.5).contains(&height), "height {height}");
    let pregnant = makehuman::target("stomach-pregnant-incr").expect("target");
    let morphed = makehuman::body(&[(pregnant, 1.0)]).expect("morphed");
    let moved = base
        .mesh
        .positions
        .iter()
        .zip(&morphed.mesh.positions)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        moved > 100,
        "the pregnancy target moves the belly ({moved} vertices)"
    );
    // the belly moves forward (+z)
    let dz: f64 = base
        .mesh
        .positions
        .iter()
        .zip(&morphed.mesh.positions)
        .map(|(a, b)| b[2] - a[2])
        .fold(0.0, f64::max);
    assert!(dz > PREGNANT_BELLY_MIN_DZ, "max forward motion {dz}");
    assert!(makehuman::target("no-such-target").is_err());
}

#[test]
fn render_draws_the_mesh_inside_the_frame() {
    let m = pdesculpt::surface::tessellate(
        &pdesculpt::surface::Revolution { r0: 1.0, r1: 0.2 },
        pdesculpt::surface::Tessellation { nu: 8, nv: 16 },
    );
    for view in [
        View::Front,
        View::Side,
        View::Top,
        View::Perspective {
            yaw: 30.0,
            pitch: 20.0,
        },
    ] {
        let img = render(
            &m,
            &RenderOptions::default()
                .with_width(64)
                .with_height(64)
                .with_view(view),
        );
        let painted = (0..64 * 64)
            .filter(|&i| img.rgba[4 * i..4 * i + 3] != [255, 255, 255])
            .count();
        assert!(painted > 200, "{view:?}: {painted} pixels");
        // the border stays background (margin)
        for x in 0..64 {
            assert_eq!(img.get(x, 0), [255, 255, 255, 255]);
        }
    }
}

#[test]
fn skirt_rejects_bad_options() {
    use pdesculpt::demo::skirt::{skirt, SkirtOptions};
    let body = pdesculpt::makehuman::base_body().unwrap().mesh;
    for o in [
        SkirtOptions::default().with_hem_y(1.0),
        SkirtOptions::default().with_ease(f64::NAN),
        SkirtOptions::default().with_ring_samples(2),
        // above the head: no cross section
        SkirtOptions::default().with_waist_y(20.0).with_hem_y(19.0),
        // a = rho = eta = lambda = 0
        SkirtOptions::default()
            .with_rho(0.0)
            .with_eta(0.0)
            .with_lambda(0.0),
    ] {
        let e = skirt(&body, &o).expect_err("bad options are refused");
        assert!(e.to_string().starts_with("skirt"), "{e}");
    }
}

/// The demo's chest drag (decimetres along the normal, paper 000 Fig 14).
const CHEST_DRAG: f64 = 0.15;
/// The belly plate edit against the artist's morph: relative RMS of the
/// difference (the shapes differ: a plate bump, not the modelled belly).
const BELLY_VS_MORPH_RMS_MAX: f64 = 0.5;
/// The teddy's convolution fit: largest relative distance to its strokes.
const TEDDY_FIT_MAX_REL: f64 = 0.1;
/// The teddy's body outline against the sketched silhouette (relative).
const TEDDY_OUTLINE_MAX_REL: f64 = 0.05;
/// The pregnancy morph moves the belly forward by at least this (dm).
const PREGNANT_BELLY_MIN_DZ: f64 = 0.3;

#[test]
fn demo_pipeline_measures_each_step() {
    let d = pdesculpt::demo::build().expect("demo builds");
    assert_eq!(d.report.edits.len(), 2);
    for e in &d.report.edits {
        assert!(
            e.moved_vertices > 50,
            "{}: {} vertices",
            e.name,
            e.moved_vertices
        );
        assert!(e.max_first_ring_displacement < e.max_displacement);
    }
    // the chest drag is 0.15 dm; the plate edit is scaled to the morph's peak
    assert!((d.report.edits[0].max_displacement - CHEST_DRAG).abs() < tol::SOLVE);
    let b = &d.report.belly_vs_morph;
    assert!((d.report.edits[1].max_displacement - b.peak).abs() < tol::SOLVE * b.peak);
    assert!(
        b.rms_rel < BELLY_VS_MORPH_RMS_MAX,
        "plate vs morph RMS {}",
        b.rms_rel
    );
    let r = &d.report.reconstruction;
    assert!(
        r.recon_to_skin_rms_rel < pdesculpt::body::closed::RMS_MAX_REL,
        "reconstruction RMS {}",
        r.recon_to_skin_rms_rel
    );
    assert!(d.sculpted.validate().is_ok() && d.reconstruction.validate().is_ok());
    assert!(d.reconstruction.groups.len() >= 7);
    let p = &d.report.prop;
    assert!(
        p.watertight && p.manifold && p.oriented,
        "teddy topology {p:?}"
    );
    assert!(
        p.fit_max_rel < TEDDY_FIT_MAX_REL,
        "teddy fit {}",
        p.fit_max_rel
    );
    assert!(
        p.body_silhouette_max_rel < TEDDY_OUTLINE_MAX_REL,
        "teddy body outline {}",
        p.body_silhouette_max_rel
    );
    assert_eq!(d.prop.groups, vec!["teddy".to_string()]);
    let (blo, bhi) = d.sculpted.bbox();
    let (tlo, thi) = d.prop.bbox();
    assert!(tlo[0] > bhi[0], "the teddy stands beside the body");
    assert!(
        (tlo[1] - blo[1]).abs() < tol::SOLVE && (thi[1] - tlo[1] - p.height).abs() < tol::SOLVE
    );
}

/// Strict documents (issue 18): a Fourier curve whose cos and sin lists
/// differ in length, or that carries an unknown key, is refused with a
/// message naming the problem; the well-formed one is read.
#[test]
fn fourier_json_refuses_mismatched_lists_and_unknown_keys() {
    use pdesculpt::curve::Fourier3;
    let ok: Fourier3 =
        serde_json::from_str(r#"{"c0": [0, 0, 1], "cos": [[1, 0, 0]], "sin": [[0, 1, 0]]}"#)
            .expect("well-formed curve");
    assert_eq!(ok.harmonics(), 1);
    let e = serde_json::from_str::<Fourier3>(
        r#"{"c0": [0, 0, 1], "cos": [[1, 0, 0], [0, 0, 0]], "sin": [[0, 1, 0]]}"#,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("2 cos terms but 1 sin terms"), "{e}");
    let e = serde_json::from_str::<Fourier3>(
        r#"{"c0": [0, 0, 1], "cos": [[1, 0, 0]], "sin": [[0, 1, 0]], "cosine": []}"#,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("unknown field"), "{e}");
    let e = serde_json::from_str::<pdesculpt::pde6::Section>(
        r#"{"u": 0.0, "curve": {"c0": [0, 0, 0], "cos": [], "sin": []}, "extra": 1}"#,
    )
    .map(|_| ())
    .unwrap_err()
    .to_string();
    assert!(e.contains("unknown field"), "{e}");
}

/// `Fourier3::weighted_sum` (the data-size study's and the ODE6 figures'
/// curve differences) is linear: at every angle it evaluates to the same
/// weighted sum of the curves' points, for curves of different harmonic
/// counts (the shorter zero-padded).
#[test]
fn fourier_weighted_sum_is_the_weighted_sum_of_points() {
    use pdesculpt::curve::Fourier3;
    let a = Fourier3 {
        c0: [1.0, -2.0, 0.5],
        cos: vec![[0.3, 0.1, -0.2], [0.05, 0.0, 0.4]],
        sin: vec![[-0.7, 0.2, 0.1], [0.0, -0.3, 0.2]],
    };
    let b = Fourier3 {
        c0: [0.0, 1.0, -1.0],
        cos: vec![[1.0, 0.0, 0.0]],
        sin: vec![[0.0, 1.0, 0.5]],
    };
    let (wa, wb) = (0.75, -2.5);
    let s = Fourier3::weighted_sum(&[(wa, &a), (wb, &b)]);
    assert_eq!(s.harmonics(), 2);
    for k in 0..16 {
        let t = 2.0 * std::f64::consts::PI * k as f64 / 16.0;
        let (p, pa, pb) = (s.eval(t), a.eval(t), b.eval(t));
        for c in 0..3 {
            assert!((p[c] - (wa * pa[c] + wb * pb[c])).abs() <= tol::ROUNDING);
        }
    }
    assert_eq!(Fourier3::weighted_sum(&[]).harmonics(), 0);
}
