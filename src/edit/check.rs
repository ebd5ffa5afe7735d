//! The `edit` family's checks (paper 000 sec 5, paper 001): on the bundled
//! female (final level, low resolution).

use super::apply_to_parts;
pub use super::samples::{sample_force, sample_force_region};
use crate::character::doc::{CharacterDoc, Level};
use crate::character::log::{Edit, SectionTransform};
use crate::character::part::{build_part, PartSurface};
use crate::character::spec::{End, PartSpec};
use crate::character::Resolution;
use crate::check::Worst;
use crate::check::{tol, Check, Kind};
use crate::mesh::{dist, dot, norm, scale, sub, Mesh};
use crate::pipeline::build_document;
use crate::pipeline::Session;
use crate::sketch::check::bundled;
use crate::surface::Surface;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// Resolution of the checks (each builds the character several times).
pub const CHECK_RES: Resolution = Resolution {
    rings_per_height: 40.0,
    transition_rows: 4,
};

/// Grid of surface samples per direction in the transform checks.
const GRID: usize = 24;

/// The bundled female (final level) with its parts derived and stored.
pub fn female() -> Option<CharacterDoc> {
    let doc = bundled("female", Level::Final)?;
    build_document(&doc, Path::new("."), CHECK_RES, true)
        .ok()
        .map(|b| b.doc)
}

/// Samples per edge of the 4-sided force checks.
const EDGE: usize = 64;

/// The 4-sided force checks: `(c0, c1, outside)` on the curve (the
/// rectangle's edges) and off it, each divided by the peak displacement.
fn force4_measures(e: &Edit) -> Option<(f64, f64, f64)> {
    let Some(Ok((u, field))) = super::field_of(e) else {
        return None;
    };
    let super::ForceField::Four { patch, theta } = &field else {
        return None;
    };
    let (mut peak, mut c0, mut c1) = (0.0f64, 0.0f64, 0.0f64);
    for i in 0..=EDGE {
        let t = i as f64 / EDGE as f64;
        for (s, v) in [(0.0, t), (1.0, t), (t, 0.0), (t, 1.0)] {
            c0 = c0.worst(norm(patch.point(s, v)));
            c1 = c1
                .worst(norm(patch.derivative(s, v, 1, 0)))
                .worst(norm(patch.derivative(s, v, 0, 1)));
        }
        for j in 1..EDGE {
            peak = peak.worst(norm(patch.point(t, j as f64 / EDGE as f64)));
        }
    }
    // outside: the field on the part's parameter grid (u over twice the
    // range, every angle) where the point is off the open rectangle
    let d = crate::character::assembly::Displacement {
        part: e.part()?.to_string(),
        u,
        field: std::sync::Arc::new(field.clone()),
    };
    let (l, w) = (u[1] - u[0], theta[1] - theta[0]);
    let mut outside = 0.0f64;
    for i in 0..=4 * EDGE {
        let uu = u[0] - 0.5 * l + 2.0 * l * i as f64 / (4 * EDGE) as f64;
        for j in 0..4 * EDGE {
            let th = theta[0] - PI + 2.0 * PI * j as f64 / (4 * EDGE) as f64;
            let inside =
                uu > u[0] && uu < u[1] && super::force4::angle_coordinate(*theta, th).is_some();
            if !inside {
                outside = outside.worst(norm(d.at(uu, th)));
            }
        }
    }
    let _ = w;
    (peak > 0.0).then_some((c0 / peak, c1 / peak, outside / peak))
}

fn part<'a>(parts: &'a [PartSpec], name: &str) -> Option<&'a PartSpec> {
    parts.iter().find(|p| p.name == name)
}

fn built(parts: &[PartSpec], e: &Edit, name: &str) -> Option<(PartSurface, PartSurface)> {
    let before = build_part(part(parts, name)?).ok()?;
    let after = apply_to_parts(parts, std::slice::from_ref(e)).ok()?;
    Some((before, build_part(part(&after, name)?).ok()?))
}

/// Largest `|after(u, t) - map(before(u, t), c0(u))|` over a grid, divided
/// by `h`.
fn grid_error(
    b: &PartSurface,
    a: &PartSurface,
    h: f64,
    map: impl Fn([f64; 3], [f64; 3]) -> [f64; 3],
) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..=GRID {
        let u = b.u0 + (b.u1 - b.u0) * i as f64 / GRID as f64;
        let c0 = b.section(u, 0).c0;
        for j in 0..GRID {
            let t = 2.0 * PI * j as f64 / GRID as f64;
            let want = map(b.point(u, t), c0);
            worst = worst.worst(dist(a.point(u, t), want) / h);
        }
    }
    worst
}

/// Vertices the 4-sided force moves outside its part's group (NaN when it
/// moves none at all).
pub(super) fn force4_mesh(doc: &CharacterDoc, e: &Edit) -> f64 {
    let mut d = doc.clone();
    if d.push_edit(e.clone()).is_err() {
        return f64::NAN;
    }
    let (Ok(a), Ok(b)) = (
        build_document(doc, Path::new("."), CHECK_RES, false),
        build_document(&d, Path::new("."), CHECK_RES, false),
    ) else {
        return f64::NAN;
    };
    let (ma, mb) = (&a.model.mesh, &b.model.mesh);
    if ma.triangles != mb.triangles || ma.positions.len() != mb.positions.len() {
        return f64::NAN;
    }
    let Some(g) = ma.groups.iter().position(|n| Some(n.as_str()) == e.part()) else {
        return f64::NAN;
    };
    let mut in_part = vec![false; ma.positions.len()];
    for (t, tr) in ma.triangles.iter().enumerate() {
        if ma.tri_group[t] as usize == g {
            tr.iter().for_each(|&v| in_part[v as usize] = true);
        }
    }
    let (mut inside, mut outside) = (0usize, 0usize);
    for (i, (p, q)) in ma.positions.iter().zip(&mb.positions).enumerate() {
        if p != q {
            if in_part[i] {
                inside += 1;
            } else {
                outside += 1;
            }
        }
    }
    if inside == 0 {
        f64::NAN
    } else {
        outside as f64
    }
}

fn differing(a: &Mesh, b: &Mesh) -> f64 {
    if a.triangles != b.triangles || a.positions.len() != b.positions.len() {
        return f64::INFINITY;
    }
    a.positions
        .iter()
        .zip(&b.positions)
        .filter(|(p, q)| p.map(f64::to_bits) != q.map(f64::to_bits))
        .count() as f64
}

/// The edits of the undo and replay checks: one of every kind.
pub fn sample_edits(doc: &CharacterDoc) -> Vec<Edit> {
    let torso = &doc.parts()[0];
    let c = torso.sections[torso.sections.len() / 2].centre;
    vec![
        Edit::ShapeParameter {
            part: "head".into(),
            a: 0.3,
        },
        Edit::GecTransform {
            part: "arm_l".into(),
            section: None,
            transform: SectionTransform::Bend {
                kappa: 1.0,
                axis: [0.0, 0.0, 1.0],
            },
        },
        sample_force(torso, [0.0, 0.0, 5.0]),
        sample_force_region(torso, 0.2, [0.0, 0.0, 5.0]),
        Edit::Boundary {
            part: "head".into(),
            end: End::End,
            curve: None,
            tangent: Some([0.0, 0.0, 0.1]),
            reach: 0.5,
        },
        Edit::Plate {
            part: "torso".into(),
            centre: [c[0], c[1], c[2] + 0.1],
            radius: 0.12,
            d: [0.0, 0.0, 0.02],
        },
    ]
}

fn c(eq: &str, n: &str, kind: Kind, m: f64, t: f64) -> Check {
    Check::new("edit", "000", eq, &format!("edit.{n}"), kind, m, t)
}

/// Every check of the family.
pub fn checks() -> Vec<Check> {
    let Some(doc) = female() else {
        return vec![c("sec 5", "setup", Kind::Threshold, f64::NAN, 0.0)
            .note("the bundled female failed to build")];
    };
    let mut out = Vec::new();
    force_checks(&doc, &mut out);
    out.extend(super::check_stroke::checks(&doc, |e| force4_mesh(&doc, e)));
    transform_checks(doc.parts(), &mut out);
    boundary_checks(doc.parts(), &mut out);
    replay_checks(&doc, &mut out);
    out
}

/// Sec 5.1: the 2-sided and 4-sided force edits are clamped at their
/// boundary and local.
fn force_checks(doc: &CharacterDoc, out: &mut Vec<Check>) {
    let torso = &doc.parts()[0];
    // force: the displacement and its u-derivative vanish at the range ends
    let force = sample_force(torso, [0.0, 0.0, 5.0]);
    let field = super::force4::force_field(&force);
    let m = field
        .as_ref()
        .map(|f| {
            let (mut peak, mut end0, mut end1) = (0.0f64, 0.0f64, 0.0f64);
            for j in 0..GRID {
                let v = j as f64 / GRID as f64;
                for s in [0.0, 1.0] {
                    end0 = end0.worst(norm(f.point(s, v)));
                    end1 = end1.worst(norm(f.derivative(s, v, 1, 0)));
                }
                for i in 1..GRID {
                    peak = peak.worst(norm(f.point(i as f64 / GRID as f64, v)));
                }
            }
            if peak > 0.0 {
                (end0 / peak, end1 / peak)
            } else {
                (f64::NAN, f64::NAN)
            }
        })
        .unwrap_or((f64::NAN, f64::NAN));
    out.push(c("sec 5.1", "force_clamped_c0", Kind::Boundary, m.0, tol::SOLVE).note(
        "force edit on the torso (pde4 2-sided, area force): displacement at both ends of the u range / peak displacement",
    ));
    out.push(c("sec 5.1", "force_clamped_c1", Kind::Boundary, m.1, tol::SOLVE).note(
        "force edit on the torso: u-derivative of the displacement at both ends of the range / peak displacement (C1 to the unedited part)",
    ));

    // 4-sided force: the displacement and both first derivatives vanish on
    // the closed curve, and it is zero outside it
    let f4 = sample_force_region(torso, 0.2, [0.0, 0.0, 5.0]);
    let m = force4_measures(&f4).unwrap_or((f64::NAN, f64::NAN, f64::NAN));
    out.push(c("sec 5.1 eq 10", "force4_clamped_c0", Kind::Boundary, m.0, tol::ROUNDING).note(
        "4-sided force edit on the torso (pde4 4-sided Galerkin patch inside the (u, theta) rectangle, area force): largest displacement on the closed curve (4 x 65 samples) / peak displacement",
    ));
    out.push(c("sec 5.1 eq 10", "force4_clamped_c1", Kind::Boundary, m.1, tol::ROUNDING).note(
        "4-sided force edit: largest first derivative (s and v) of the displacement on the closed curve / peak displacement (the edited part is C1 across the curve)",
    ));
    out.push(c("sec 5.1", "force4_outside", Kind::Threshold, m.2, 0.0).note(
        "4-sided force edit: largest displacement at 257 x 256 part-parameter samples off the open rectangle (u over twice its range, every angle) / peak (exactly zero)",
    ));
    let moved_elsewhere = force4_mesh(doc, &f4);
    out.push(c("sec 5.1", "force4_mesh_local", Kind::Threshold, moved_elsewhere, 0.0).note(
        "4-sided force edit on the female: vertices moved outside the torso's group (the edit did move torso vertices; NaN if not)",
    ));
}

/// Sec 5.2: GEC transforms of every torso section equal the same transform
/// of the surface points.
fn transform_checks(parts: &[PartSpec], out: &mut Vec<Check>) {
    let h = 1.7;
    let torso = &parts[0];
    let e1 = torso.sections[0].e1;
    let e2 = torso.sections[0].e2;
    let parallel = torso
        .sections
        .iter()
        .all(|s| dist(s.e1, e1) < tol::ROUNDING && dist(s.e2, e2) < tol::ROUNDING);

    let d = [0.01, -0.02, 0.03];
    let tr = Edit::GecTransform {
        part: "torso".into(),
        section: None,
        transform: SectionTransform::Translate { d },
    };
    let m = built(parts, &tr, "torso")
        .map(|(b, a)| grid_error(&b, &a, h, |p, _| crate::mesh::add(p, d)))
        .unwrap_or(f64::NAN);
    out.push(c("sec 5.2", "gec_translate", Kind::Reference, m, tol::SOLVE).note(
        "translating every torso section's GEC moves every surface point by the same vector (max error / height, 25 x 24 grid)",
    ));
    let (sx, sy, phi) = (1.3, 0.8, 0.4);
    let in_plane = |p: [f64; 3], c0: [f64; 3], f: &dyn Fn(f64, f64) -> (f64, f64)| {
        let r = sub(p, c0);
        let (x, y) = (dot(r, e1), dot(r, e2));
        let (x2, y2) = f(x, y);
        crate::mesh::add(c0, crate::mesh::add(scale(e1, x2), scale(e2, y2)))
    };
    let sc = Edit::GecTransform {
        part: "torso".into(),
        section: None,
        transform: SectionTransform::Scale { sx, sy },
    };
    let m = built(parts, &sc, "torso")
        .filter(|_| parallel)
        .map(|(b, a)| grid_error(&b, &a, h, |p, c0| in_plane(p, c0, &|x, y| (sx * x, sy * y))))
        .unwrap_or(f64::NAN);
    out.push(c("sec 5.2", "gec_scale", Kind::Reference, m, tol::SOLVE).note(
        "scaling every torso section (parallel frames) by (1.3, 0.8) about its centre scales every ring of the surface about the centre curve",
    ));
    let ro = Edit::GecTransform {
        part: "torso".into(),
        section: None,
        transform: SectionTransform::Rotate { angle: phi },
    };
    let (s, co) = f64::sin_cos(phi);
    let m = built(parts, &ro, "torso")
        .filter(|_| parallel)
        .map(|(b, a)| {
            grid_error(&b, &a, h, |p, c0| {
                in_plane(p, c0, &|x, y| (co * x - s * y, s * x + co * y))
            })
        })
        .unwrap_or(f64::NAN);
    out.push(c("sec 5.2", "gec_rotate", Kind::Reference, m, tol::SOLVE).note(
        "rotating every torso section in its plane by 0.4 rad rotates every ring of the surface about the centre curve",
    ));
}

/// Sec 5.1: a boundary tangent edit changes the end tangent by the request
/// and keeps the end curve.
fn boundary_checks(parts: &[PartSpec], out: &mut Vec<Check>) {
    let h = 1.7;
    let t = [0.05, 0.0, 0.08];
    let bt = Edit::Boundary {
        part: "torso".into(),
        end: End::End,
        curve: None,
        tangent: Some(t),
        reach: 0.4,
    };
    let (m_t, m_c) = built(parts, &bt, "torso")
        .map(|(b, a)| {
            let dt = sub(a.section(b.u1, 1).c0, b.section(b.u1, 1).c0);
            let mut ring = 0.0f64;
            for j in 0..GRID {
                let th = 2.0 * PI * j as f64 / GRID as f64;
                ring = ring.worst(dist(a.point(b.u1, th), b.point(b.u1, th)) / h);
            }
            (dist(dt, t) / norm(t), ring)
        })
        .unwrap_or((f64::NAN, f64::NAN));
    out.push(c("sec 5.1", "boundary_tangent", Kind::Boundary, m_t, tol::SOLVE).note(
        "boundary tangent edit at the torso's end: |change of the solved end tangent - requested| / |requested|",
    ));
    out.push(c("sec 5.1", "boundary_curve_kept", Kind::Boundary, m_c, tol::SOLVE).note(
        "boundary tangent edit: largest move of the end ring / height (the boundary curve stays)",
    ));
}

/// Sec 5: undo after N edits and the replayed log against incremental
/// application, bit for bit.
fn replay_checks(doc: &CharacterDoc, out: &mut Vec<Check>) {
    let edits = sample_edits(doc);
    let base = build_document(doc, Path::new("."), CHECK_RES, false).ok();
    let mut session = Session::new(doc.clone(), PathBuf::from("."), CHECK_RES);
    let mut incremental = None;
    let mut ok = true;
    for e in &edits {
        ok &= session.push(e.clone()).is_ok();
        incremental = session.build().ok();
    }
    let scratch = build_document(&session.doc, Path::new("."), CHECK_RES, false).ok();
    let fast = session.model().ok();
    let m = match (&incremental, &scratch, &fast) {
        (Some(a), Some(b), Some(f)) if ok => {
            differing(&a.model.mesh, &b.model.mesh).worst(differing(&f.mesh, &b.model.mesh))
        }
        _ => f64::NAN,
    };
    out.push(c("sec 5", "replay_equals_incremental", Kind::Reference, m, 0.0).note(
        "six edits (one of every PDE-level kind and a plate) applied one by one in a session with a part cache (full build and the interactive model path) vs the log replayed from scratch: differing vertex coordinates (bit for bit)",
    ));
    let moved = match (&base, &scratch) {
        (Some(a), Some(b)) => differing(&a.model.mesh, &b.model.mesh),
        _ => 0.0,
    };
    let topo = scratch
        .as_ref()
        .map(|b| {
            let t = &b.report.topology;
            if t.watertight && t.manifold && t.oriented {
                0.0
            } else {
                1.0
            }
        })
        .unwrap_or(f64::NAN);
    out.push(
        c("sec 5", "edited_watertight", Kind::Threshold, topo, 0.0)
            .note("the female after the six edits is watertight, manifold and oriented (0 = yes)"),
    );
    for _ in &edits {
        ok &= session.doc.undo().is_ok();
    }
    let undone = session.build().ok();
    let m = match (&base, &undone) {
        (Some(a), Some(b)) if ok && moved > 0.0 && b.doc.parts() == doc.parts() => {
            differing(&a.model.mesh, &b.model.mesh)
        }
        _ => f64::NAN,
    };
    out.push(c("sec 5", "undo_bit_for_bit", Kind::Reference, m, 0.0).note(
        "six edits then six undos: differing vertex coordinates against the unedited build (bit for bit; the edits did move vertices)",
    ));
}
