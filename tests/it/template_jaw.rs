//! Feature correspondence on the side outline (issue 12, "jaw"): the head's
//! landmarks ([`landmarks::face_marks`]) and the height remap of the face
//! ([`weights::remap_heights`]) on a synthetic body whose chin is known.

use pdesculpt::mesh::Mesh;
use pdesculpt::template::landmarks::{self, face_marks, CHIN_WINDOW};
use pdesculpt::template::measure::mesh_outline;
use pdesculpt::template::weights::{self, HeightRemap};
use pdesculpt::template::{FitOptions, Template, View};

/// The synthetic body's height.
const HEIGHT: f64 = 10.0;
/// A landmark is found within this fraction of the height of where it was
/// drawn: two of the detector's windows (the chin's underside is a
/// shallow stretch [`SHELF`] tall, found as the front's largest step in
/// depth within [`CHIN_WINDOW`]).
const FOUND: f64 = 2.0 * CHIN_WINDOW;
/// Height of the chin's underside (from the throat to the chin's front).
const SHELF: f64 = 0.05;

fn lerp(y: f64, pts: &[(f64, f64)]) -> f64 {
    for w in pts.windows(2) {
        if y <= w[1].0 {
            let t = ((y - w[0].0) / (w[1].0 - w[0].0)).clamp(0.0, 1.0);
            return w[0].1 + t * (w[1].1 - w[0].1);
        }
    }
    pts.last().map_or(0.0, |p| p.1)
}

/// Front and back depth and half-width of a body 10 tall with its chin's
/// underside from `chin` to `chin + SHELF` (above 8.1), neck 7.8-8.5
/// (narrowest at 8.1), nose tip at 9.2.
fn body(chin: f64, y: f64) -> (f64, f64, f64) {
    let front = [
        (0.0, 1.0),
        (7.5, 1.0),
        (7.8, 0.5),
        (8.1, 0.4),
        (chin, 0.5),
        (chin + SHELF, 1.2),
        (9.0, 1.2),
        (9.2, 1.6),
        (9.3, 1.2),
        (9.8, 1.2),
        (10.0, 0.0),
    ];
    let back = [
        (0.0, -1.0),
        (7.5, -1.0),
        (7.8, -0.3),
        (8.1, -0.25),
        (8.5, -0.3),
        (8.8, -1.0),
        (9.8, -1.0),
        (10.0, 0.0),
    ];
    let half = [
        (0.0, 1.5),
        (7.5, 1.5),
        (7.8, 0.5),
        (8.5, 0.5),
        (8.8, 0.9),
        (9.8, 0.9),
        (10.0, 0.0),
    ];
    (lerp(y, &front), lerp(y, &back), lerp(y, &half))
}

/// Rows of the synthetic body's heights: every 0.02, plus the chin's.
fn rows(chin: f64) -> Vec<f64> {
    let mut ys: Vec<f64> = (0..=500).map(|j| j as f64 * 0.02).collect();
    ys.extend([chin, chin + 0.5 * SHELF, chin + SHELF]);
    ys.sort_by(f64::total_cmp);
    ys.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    ys
}

/// The side outline (depth, height) of [`body`], counter-clockwise.
fn side_outline(chin: f64) -> Vec<[f64; 2]> {
    let ys = rows(chin);
    let inner = &ys[1..ys.len() - 1];
    let mut p = vec![[0.0, 0.0]];
    p.extend(inner.iter().map(|&y| [body(chin, y).0, y]));
    p.push([0.0, HEIGHT]);
    p.extend(inner.iter().rev().map(|&y| [body(chin, y).1, y]));
    p
}

/// A closed tube mesh of [`body`]: elliptic rings (`m` points) on
/// [`rows`], poles at the bottom and top.
fn body_mesh(chin: f64, m: usize) -> Mesh {
    let ys = rows(chin);
    let inner = &ys[1..ys.len() - 1];
    let mut pos = vec![[0.0, 0.0, 0.0]];
    for &y in inner {
        let (f, b, a) = body(chin, y);
        let (mid, half) = (0.5 * (f + b), 0.5 * (f - b));
        for k in 0..m {
            let t = std::f64::consts::TAU * k as f64 / m as f64;
            pos.push([a * t.sin(), y, mid + half * t.cos()]);
        }
    }
    let top = pos.len() as u32;
    pos.push([0.0, HEIGHT, 0.0]);
    let (r, m32) = (inner.len() as u32, m as u32);
    let at = |row: u32, k: u32| 1 + row * m32 + k % m32;
    let mut tri = Vec::new();
    for k in 0..m32 {
        tri.push([0, at(0, k + 1), at(0, k)]);
        for row in 0..r - 1 {
            let (a, b, c, d) = (
                at(row, k),
                at(row, k + 1),
                at(row + 1, k),
                at(row + 1, k + 1),
            );
            tri.push([a, b, d]);
            tri.push([a, d, c]);
        }
        tri.push([top, at(r - 1, k), at(r - 1, k + 1)]);
    }
    Mesh::new(pos, tri)
}

#[test]
fn face_marks_find_a_known_chin_nose_and_neck() {
    for chin in [8.3, 8.6] {
        let f = face_marks(&side_outline(chin), "synthetic side outline").unwrap();
        let off = |found: f64, drawn: f64| (found - drawn).abs() / HEIGHT;
        assert!(
            off(f.chin, chin + 0.5 * SHELF) < FOUND,
            "chin drawn at {chin}, found at {}",
            f.chin
        );
        assert!(off(f.nose, 9.2) < FOUND, "nose found at {}", f.nose);
        // the drawn neck runs between these heights
        let (neck_low, neck_high) = (7.8, 8.5);
        assert!(
            f.neck > neck_low - FOUND * HEIGHT && f.neck < neck_high + FOUND * HEIGHT,
            "neck found at {}",
            f.neck
        );
        assert_eq!((f.top, f.bottom), (HEIGHT, 0.0));
    }
}

#[test]
fn face_marks_name_a_missing_chin() {
    // a column: no narrowing, no nose, no chin
    let p = vec![[-1.0, 0.0], [1.0, 0.0], [1.0, HEIGHT], [-1.0, HEIGHT]];
    let e = face_marks(&p, "column").unwrap_err().to_string();
    assert!(e.contains("column") && e.contains("chin"), "{e}");
}

#[test]
fn height_remap_is_monotone_and_the_identity_outside_its_knots() {
    let t = face_marks(&side_outline(8.6), "template").unwrap();
    let s = face_marks(&side_outline(8.3), "sketch").unwrap();
    let r = HeightRemap::between(&t, &s).unwrap();
    for k in &r.knots {
        assert!((k.0 + r.shift(k.0) - k.1).abs() < pdesculpt::check::tol::JOIN);
    }
    let mut last = f64::NEG_INFINITY;
    for j in 0..=10_000 {
        let y = j as f64 * HEIGHT / 10_000.0;
        let m = y + r.shift(y);
        assert!(m > last, "not increasing at {y}");
        last = m;
    }
    assert_eq!(r.shift(1.0), 0.0);
    // landmarks out of order on one side: no map
    let swapped = landmarks::FaceMarks {
        chin: s.nose,
        nose: s.chin,
        ..s
    };
    assert!(HeightRemap::between(&t, &swapped).is_none());
}

#[test]
fn remap_moves_a_templates_chin_to_the_sketched_chins_height() {
    let (from, to) = (8.6, 8.3);
    let template = Template::whole(body_mesh(from, 16));
    let mut pos = template.mesh.positions.clone();
    let sketch = side_outline(to);
    let opts = FitOptions::default();
    let before = face_marks(&mesh_outline(&template.skin, View::Side).unwrap(), "t").unwrap();
    assert!((before.chin - (from + 0.5 * SHELF)).abs() / HEIGHT < FOUND);
    let moved = weights::remap_heights(&template, &mut pos, &sketch, &opts, &mesh_outline).unwrap();
    // at least half of the drawn chin's shift
    let half_shift = 0.5 * (from - to);
    assert!(moved > half_shift, "largest shift {moved}");
    let after = face_marks(
        &mesh_outline(&template.skin_at(&pos), View::Side).unwrap(),
        "remapped",
    )
    .unwrap();
    let want = face_marks(&sketch, "sketch").unwrap();
    assert!(
        (after.chin - want.chin).abs() / HEIGHT < FOUND,
        "chin at {} after the remap, the sketch's at {}",
        after.chin,
        want.chin
    );
    // the front outline's silhouette stays put (its vertices take no shift)
    let fa = mesh_outline(&template.skin, View::Front).unwrap();
    let fb = mesh_outline(&template.skin_at(&pos), View::Front).unwrap();
    let d = pdesculpt::template::polygon::hausdorff(&fa, &fb, 0.01) / HEIGHT;
    assert!(
        d < pdesculpt::template::check::PROFILE_REL,
        "front moved {d}"
    );
    // nothing to remap between equal outlines
    let mut same = template.mesh.positions.clone();
    let none = weights::remap_heights(
        &template,
        &mut same,
        &side_outline(from),
        &opts,
        &mesh_outline,
    )
    .unwrap();
    assert_eq!(none, 0.0);
}

/// The envelope passes' shelf warp ([`envelope::shelf_warp`]) moves a
/// template's chin underside (a shelf of the side outline) towards a
/// sketch whose chin is 0.5 % of the height lower: the side outlines come
/// closer and the chin's landmark moves down; the front silhouette stays
/// within the tolerance; between equal outlines nothing moves.
#[test]
fn shelf_warp_moves_a_chins_underside_to_the_sketched_height() {
    use pdesculpt::template::envelope;
    use pdesculpt::template::polygon::{boundary_distance, hausdorff};
    let (from, to) = (8.6, 8.55);
    let template = Template::whole(body_mesh(from, 16));
    let sketch = side_outline(to);
    let opts = FitOptions::default();
    let side_of = |pos: &[[f64; 3]]| mesh_outline(&template.skin_at(pos), View::Side).unwrap();
    let mut pos = template.mesh.positions.clone();
    // the fitted outline's mean distance to the sketch around the chin
    let near_chin = |o: &[[f64; 2]]| {
        let d: Vec<f64> = o
            .iter()
            .filter(|q| (8.4..8.8).contains(&q[1]) && q[0] > 0.0)
            .map(|&q| boundary_distance(&sketch, q))
            .collect();
        d.iter().sum::<f64>() / d.len().max(1) as f64
    };
    let before = near_chin(&side_of(&pos));
    let centres = envelope::shelf_warp(&template, &mut pos, &sketch, &opts, &mesh_outline).unwrap();
    assert!(centres > 0, "no shelf found");
    let after = near_chin(&side_of(&pos));
    // the warp removes at least a fifth of the miss
    let kept = 0.8 * before;
    assert!(after < kept, "side miss near the chin {before} -> {after}");
    let chin = |p: &[[f64; 2]]| face_marks(p, "side").unwrap().chin;
    let c0 = chin(&side_of(&template.mesh.positions));
    let c1 = chin(&side_of(&pos));
    assert!(c1 < c0, "chin {c0} -> {c1}");
    let fa = mesh_outline(&template.skin, View::Front).unwrap();
    let fb = mesh_outline(&template.skin_at(&pos), View::Front).unwrap();
    let d = hausdorff(&fa, &fb, 0.01) / HEIGHT;
    assert!(
        d < pdesculpt::template::check::PROFILE_REL,
        "front moved {d}"
    );
    let mut same = template.mesh.positions.clone();
    envelope::shelf_warp(
        &template,
        &mut same,
        &side_outline(from),
        &opts,
        &mesh_outline,
    )
    .unwrap();
    let moved = same
        .iter()
        .zip(&template.mesh.positions)
        .map(|(a, b)| (a[1] - b[1]).abs())
        .fold(0.0, f64::max);
    assert!(
        moved < pdesculpt::check::tol::SOLVE,
        "equal outlines moved {moved}"
    );
}
