//! Template-based shape manipulation (TBSM, 000 sec 5.4, Fig 11b): the
//! elliptic key sections of a sketched part (a foot or a hand built from
//! ellipses at the sketch issue's intermediate level) are replaced by the
//! real cross sections of the matching template part, each scaled to the
//! ellipse it replaces.
//!
//! A [`TemplatePart`] is a template part's key sections as planar loops in
//! their own frames, at normalised positions `t` in `[0, 1]` along the
//! part ([`TemplatePart::from_mesh`] slices a mesh perpendicular to an
//! axis). For a part section at normalised position `t` (its `u` over the
//! part's `u` range) the template loop at `t` is the blend of the two
//! template sections around `t` (both resampled by arc length from the
//! crossing of their centroid's +e1 ray, linear in `t`); it is moved so its bounding-box centre is at
//! the origin and scaled per axis so its half-extents are the ellipse's
//! semi-axes `(a, b)` (a circle: `(r, r)`), placed at the ellipse's centre
//! (with its offset along `e2`) and GEC-fitted in the section's frame. The
//! part keeps its `u`, centres and frames, so its chain and transitions are
//! built as before; collapsed end rings (`r = 0`) and sections that are
//! already GECs are kept.
//!
//! Part creation from a sketched profile by correspondence with a template
//! part (Fig 11a) is the low level of [`super::fit`] applied to the part's
//! mesh with the [`super::Scheme::Extremes`] landmarks
//! ([`part_from_profile`]).

use super::fit::{fit, FitOptions, Sketch, Template};
use super::polygon::{bbox, validated};
use super::{OutlineFn, Scheme, TemplateError};
use crate::character::doc::{PartSpec, SectionShape, SectionSpec};
use crate::curve::gec::{self, Frame};
use crate::mesh::slice::slice;
use crate::mesh::Mesh;

/// Points per template loop after resampling by angle.
pub const LOOP_POINTS: usize = 96;

/// A template part: loops `(t, points in the section plane)`, `t` increasing.
#[derive(Clone, Debug, PartialEq)]
pub struct TemplatePart {
    pub sections: Vec<(f64, Vec<[f64; 2]>)>,
}

fn bad(problem: String) -> TemplateError {
    TemplateError::BadProfile {
        what: "template-based shape manipulation".into(),
        problem,
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn centroid(p: &[[f64; 2]]) -> [f64; 2] {
    let n = p.len();
    // twice the area, summed from the centroid's own cross terms
    let mut a2 = 0.0;
    let mut c = [0.0; 2];
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let w = a[0] * b[1] - b[0] * a[1];
        a2 += w;
        c[0] += (a[0] + b[0]) * w;
        c[1] += (a[1] + b[1]) * w;
    }
    [c[0] / (3.0 * a2), c[1] / (3.0 * a2)]
}

/// `m` points of a closed (counter-clockwise) loop equally spaced by arc
/// length, starting where the ray from its area centroid along +e1 leaves
/// it, so loops of different shapes correspond by arc-length fraction from
/// a common direction (concavities are kept).
pub fn by_arc(p: &[[f64; 2]], m: usize) -> Vec<[f64; 2]> {
    use super::polygon::{cumulative, point_at};
    let c = centroid(p);
    let (lo, hi) = bbox(p);
    let d = 2.0 * (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
    let start = super::sections::ray_partner(p, c, [c[0] + d, c[1]]);
    // arc-length position of `start` on p
    let cum = cumulative(p);
    let n = p.len();
    let (mut best, mut s0) = (f64::INFINITY, 0.0);
    for i in 0..n {
        let (a, b) = (p[i], p[(i + 1) % n]);
        let dd = super::polygon::seg_dist(start, a, b);
        if dd < best {
            best = dd;
            s0 = cum[i] + (start[0] - a[0]).hypot(start[1] - a[1]);
        }
    }
    let per = cum[n];
    (0..m)
        .map(|k| point_at(p, &cum, s0 + per * k as f64 / m as f64))
        .collect()
}

impl TemplatePart {
    /// Checks and orders the loops (each validated, `t` finite in [0, 1]).
    pub fn new(mut sections: Vec<(f64, Vec<[f64; 2]>)>) -> Result<TemplatePart, TemplateError> {
        if sections.len() < 2 {
            return Err(bad(format!(
                "a template part needs at least 2 sections, got {}",
                sections.len()
            )));
        }
        for (i, (t, l)) in sections.iter_mut().enumerate() {
            if !(t.is_finite() && (0.0..=1.0).contains(t)) {
                return Err(bad(format!(
                    "template section {i}: position {t} is not in [0, 1]"
                )));
            }
            *l = validated(&format!("template section {i}"), l)?;
        }
        sections.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(TemplatePart { sections })
    }

    /// `count` sections of `mesh` cut perpendicular to the axis `start ->
    /// end` at `t` in `[t0, t1]`, each the closed loop whose centroid is
    /// nearest the axis, in the frame `(e1, e2)` (`e1` made perpendicular
    /// to the axis).
    pub fn from_mesh(
        mesh: &Mesh,
        start: [f64; 3],
        end: [f64; 3],
        e1: [f64; 3],
        (t0, t1, count): (f64, f64, usize),
    ) -> Result<TemplatePart, TemplateError> {
        let axis = sub(end, start);
        let len = dot(axis, axis).sqrt();
        if !(len.is_finite() && len > 0.0) || count < 2 {
            return Err(bad(
                "the template axis is degenerate or fewer than 2 sections asked".into(),
            ));
        }
        if !(t0.is_finite() && t1.is_finite() && t0 < t1) {
            return Err(bad(format!(
                "section range [{t0}, {t1}] is not an increasing finite range"
            )));
        }
        let n = [axis[0] / len, axis[1] / len, axis[2] / len];
        let e1 = sub(
            e1,
            [n[0] * dot(e1, n), n[1] * dot(e1, n), n[2] * dot(e1, n)],
        );
        let l1 = dot(e1, e1).sqrt();
        if l1.is_nan() || l1 <= 1e-9 {
            return Err(bad("e1 is parallel to the template axis".into()));
        }
        let e1 = [e1[0] / l1, e1[1] / l1, e1[2] / l1];
        let e2 = [
            n[1] * e1[2] - n[2] * e1[1],
            n[2] * e1[0] - n[0] * e1[2],
            n[0] * e1[1] - n[1] * e1[0],
        ];
        let mut out = Vec::with_capacity(count);
        for k in 0..count {
            let t = t0 + (t1 - t0) * k as f64 / (count - 1) as f64;
            let o = [
                start[0] + t * axis[0],
                start[1] + t * axis[1],
                start[2] + t * axis[2],
            ];
            let best = slice(mesh, o, n)
                .into_iter()
                .filter(|l| l.closed && l.points.len() >= 3)
                .map(|l| {
                    l.points
                        .iter()
                        .map(|p| {
                            let d = sub(*p, o);
                            [dot(d, e1), dot(d, e2)]
                        })
                        .collect::<Vec<[f64; 2]>>()
                })
                .min_by(|a, b| {
                    let (ca, cb) = (centroid(a), centroid(b));
                    ca[0].hypot(ca[1]).total_cmp(&cb[0].hypot(cb[1]))
                })
                .ok_or_else(|| bad(format!("no closed section of the template at t = {t:.3}")))?;
            out.push((t, best));
        }
        TemplatePart::new(out)
    }

    /// The template loop at `t` (clamped): the two sections around `t`
    /// blended linearly, point by point after [`by_arc`], [`LOOP_POINTS`] points.
    pub fn loop_at(&self, t: f64) -> Vec<[f64; 2]> {
        let s = &self.sections;
        let t = t.clamp(s[0].0, s[s.len() - 1].0);
        let k = s.partition_point(|(u, _)| *u <= t).clamp(1, s.len() - 1);
        let ((ta, la), (tb, lb)) = (&s[k - 1], &s[k]);
        let w = if tb > ta { (t - ta) / (tb - ta) } else { 0.0 };
        let (a, b) = (by_arc(la, LOOP_POINTS), by_arc(lb, LOOP_POINTS));
        a.iter()
            .zip(&b)
            .map(|(p, q)| [p[0] + w * (q[0] - p[0]), p[1] + w * (q[1] - p[1])])
            .collect()
    }
}

/// `loop_` moved and scaled per axis so its bounding box is centred at
/// `centre` with half-extents `(a, b)`.
pub fn fit_box(loop_: &[[f64; 2]], centre: [f64; 2], a: f64, b: f64) -> Vec<[f64; 2]> {
    let (lo, hi) = bbox(loop_);
    let c = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let (hx, hy) = (0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1]));
    loop_
        .iter()
        .map(|p| {
            [
                centre[0] + a * (p[0] - c[0]) / hx,
                centre[1] + b * (p[1] - c[1]) / hy,
            ]
        })
        .collect()
}

/// The part with every elliptic (or round, non-collapsed) section replaced
/// by the template's section at the same normalised position, scaled to
/// it, GEC-fitted with `terms` terms.
pub fn replace_sections(
    part: &PartSpec,
    template: &TemplatePart,
    terms: usize,
) -> Result<PartSpec, TemplateError> {
    let err = |i: usize, m: String| bad(format!("part '{}', section {i}: {m}", part.name));
    let (u0, u1) = match (part.sections.first(), part.sections.last()) {
        (Some(a), Some(b)) if b.u > a.u => (a.u, b.u),
        _ => {
            return Err(bad(format!(
                "part '{}' needs at least 2 sections with increasing u",
                part.name
            )))
        }
    };
    let mut out = part.clone();
    for (i, s) in out.sections.iter_mut().enumerate() {
        let (a, b, offset) = match s.shape {
            SectionShape::Circle { r } if r > 0.0 => (r, r, 0.0),
            SectionShape::Ellipse { a, b, offset } => (a, b, offset),
            _ => continue,
        };
        if !(a.is_finite() && b.is_finite() && offset.is_finite() && a > 0.0 && b > 0.0) {
            return Err(err(
                i,
                format!("semi-axes ({a}, {b}) must be finite and positive"),
            ));
        }
        let t = (s.u - u0) / (u1 - u0);
        let shaped = fit_box(&template.loop_at(t), [0.0, offset], a, b);
        *s = gec_section(s, &shaped, terms).map_err(|e| err(i, e.to_string()))?;
    }
    Ok(out)
}

/// A section of the same frame whose shape is the GEC fit of `plane`
/// (points in the section's frame).
fn gec_section(
    s: &SectionSpec,
    plane: &[[f64; 2]],
    terms: usize,
) -> Result<SectionSpec, TemplateError> {
    let frame = Frame::new(s.centre, s.e1, s.e2).map_err(|e| bad(e.to_string()))?;
    let pts: Vec<[f64; 3]> = plane.iter().map(|p| frame.place(p[0], p[1])).collect();
    let most = (plane.len().saturating_sub(1) / 2).max(1);
    let mut opts = gec::fit::FitOptions::new(terms.clamp(1, most));
    opts.frame = gec::fit::FrameChoice::Given(frame);
    let rep = gec::fit::fit(&pts, &opts).map_err(|e| bad(format!("GEC fit: {e}")))?;
    Ok(SectionSpec {
        shape: SectionShape::Gec {
            centre: rep.gec.centre,
            x: rep.gec.x.clone(),
            y: rep.gec.y.clone(),
        },
        ..s.clone()
    })
}

/// Part creation by correspondence (Fig 11a): the template part's mesh
/// warped so its front outline is the sketched profile; landmarks are the outline's extremes (top, left, bottom,
/// right). Returns the new vertex positions (same order as `part`).
pub fn part_from_profile(
    part: &Mesh,
    profile: &[[f64; 2]],
    outline: &OutlineFn,
) -> Result<Vec<[f64; 3]>, TemplateError> {
    let opts = FitOptions {
        front_scheme: Scheme::Extremes,
        condition: false,
        ..Default::default()
    };
    let sketch = Sketch {
        front: profile.to_vec(),
        ..Default::default()
    };
    let r = fit(&Template::whole(part.clone()), &sketch, &opts, outline)?;
    Ok(r.last().to_vec())
}

/// [`part_from_profile`] for a profile drawn in `view`: a side profile
/// (`(z, y)`) fits the part turned a quarter turn about y (`(x, y, z) ->
/// (z, y, -x)`), which is turned back after the fit.
pub fn part_from_view(
    part: &Mesh,
    profile: &[[f64; 2]],
    view: super::View,
    outline: &OutlineFn,
) -> Result<Vec<[f64; 3]>, TemplateError> {
    match view {
        super::View::Front => return part_from_profile(part, profile, outline),
        super::View::Side => {}
        _ => {
            return Err(bad(format!(
                "a part is created from a front or side profile, not a {} one",
                view.name()
            )))
        }
    }
    let mut turned = part.clone();
    turned.map_positions(|p| [p[2], p[1], -p[0]]);
    let out = part_from_profile(&turned, profile, outline)?;
    Ok(out.into_iter().map(|p| [-p[2], p[1], p[0]]).collect())
}

/// The axis of MakeHuman's left foot (x > 0) in the base skin: heel to toe
/// through the foot's vertices below [`FOOT_HEIGHT`] of the body's height,
/// `e1` = +x; and the foot mesh itself (triangles of the left foot, x > 0,
/// entirely below that height, so sections of the forefoot are closed
/// loops; the right foot was in it once, so a part created from a front
/// profile was refused as two outlines).
pub fn makehuman_left_foot() -> Result<(Mesh, [f64; 3], [f64; 3]), TemplateError> {
    let skin = super::study::makehuman_template(&[])?.skin;
    let (lo, hi) = skin
        .positions
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p[1]), h.max(p[1]))
        });
    let cap = lo + FOOT_HEIGHT * (hi - lo);
    let foot: Vec<[f64; 3]> = skin
        .positions
        .iter()
        .filter(|p| p[1] < cap && p[0] > 0.0)
        .copied()
        .collect();
    if foot.is_empty() {
        return Err(bad("the template has no left foot".into()));
    }
    let n = foot.len() as f64;
    let (xc, yc) = foot
        .iter()
        .fold((0.0, 0.0), |(x, y), p| (x + p[0] / n, y + p[1] / n));
    let (z0, z1) = foot
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p[2]), h.max(p[2]))
        });
    let tris: Vec<[u32; 3]> = skin
        .triangles
        .iter()
        .filter(|t| {
            t.iter().all(|&i| {
                let p = skin.positions[i as usize];
                p[1] < cap && p[0] > 0.0
            })
        })
        .copied()
        .collect();
    Ok((
        Mesh::new(skin.positions.clone(), tris),
        [xc, yc, z0],
        [xc, yc, z1],
    ))
}

/// The MakeHuman left foot as a template part: `count` forefoot sections
/// (normalised positions 0.5 to 0.95 heel to toe, `e1` = +x), and the foot
/// mesh compacted to its own vertices.
pub fn makehuman_foot_part(count: usize) -> Result<(TemplatePart, Mesh), TemplateError> {
    let (mesh, start, end) = makehuman_left_foot()?;
    let part = TemplatePart::from_mesh(&mesh, start, end, [1.0, 0.0, 0.0], (0.5, 0.95, count))?;
    let (foot, _) = mesh.filter_triangles(&vec![true; mesh.triangles.len()]);
    Ok((part, foot))
}

/// [`replace_sections`] on the part named `name` of a character document;
/// returns how many sections were replaced (elliptic or round ones).
pub fn replace_in_doc(
    doc: &mut crate::character::doc::CharacterDoc,
    name: &str,
    template: &TemplatePart,
    terms: usize,
) -> Result<usize, TemplateError> {
    let names: Vec<&str> = doc.parts().iter().map(|p| p.name.as_str()).collect();
    let Some(part) = doc.parts().iter().find(|p| p.name == name) else {
        return Err(bad(format!(
            "the document has no part '{name}' (parts: {})",
            if names.is_empty() {
                "none".to_string()
            } else {
                names.join(", ")
            }
        )));
    };
    let replaceable = |s: &SectionSpec| {
        matches!(s.shape, SectionShape::Circle { r } if r > 0.0)
            || matches!(s.shape, SectionShape::Ellipse { .. })
    };
    let count = part.sections.iter().filter(|s| replaceable(s)).count();
    if count == 0 {
        return Err(bad(format!(
            "part '{name}' has no elliptic or round section to replace"
        )));
    }
    let replaced = replace_sections(part, template, terms)?;
    *doc.part_mut(name).expect("the part was found above") = replaced;
    Ok(count)
}

/// Height (fraction of the body's) below which skin counts as foot.
pub const FOOT_HEIGHT: f64 = 0.05;

/// Round trip of [`replace_sections`] on a template part: a part whose
/// sections are ellipses with each template section's half-extents (frame
/// origin at the section's bounding-box centre) gets the template's
/// sections back. Returns the largest Hausdorff distance between a new
/// section (GEC, `terms` terms) and its template loop, divided by the
/// largest template loop's diameter.
pub fn round_trip_error(template: &TemplatePart, terms: usize) -> Result<f64, TemplateError> {
    let (t0, t1) = (
        template.sections[0].0,
        template.sections[template.sections.len() - 1].0,
    );
    if t1 <= t0 {
        return Err(bad("the template sections are all at one position".into()));
    }
    let mut sections = Vec::new();
    let mut boxed = Vec::new();
    for (t, l) in &template.sections {
        let (lo, hi) = bbox(l);
        let c = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
        sections.push(SectionSpec {
            u: (t - t0) / (t1 - t0),
            centre: [c[0], 0.0, 3.0 * t],
            e1: [1.0, 0.0, 0.0],
            e2: [0.0, 1.0, 0.0],
            shape: SectionShape::Ellipse {
                a: 0.5 * (hi[0] - lo[0]),
                b: 0.5 * (hi[1] - lo[1]),
                offset: c[1],
            },
        });
        boxed.push((
            l.iter().map(|p| [p[0] - c[0], p[1]]).collect::<Vec<_>>(),
            (hi[0] - lo[0]).hypot(hi[1] - lo[1]),
        ));
    }
    let part = PartSpec {
        name: "round-trip".into(),
        surface: crate::character::doc::SurfaceSpec::Pde6C2 {
            a: 0.0,
            open_ends: Default::default(),
        },
        sections,
        closed_start: false,
        closed_end: false,
    };
    let rescaled = TemplatePart {
        sections: template
            .sections
            .iter()
            .map(|(t, l)| ((t - t0) / (t1 - t0), l.clone()))
            .collect(),
    };
    let out = replace_sections(&part, &rescaled, terms)?;
    let diam = boxed.iter().map(|b| b.1).fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for (s, (expected, _)) in out.sections.iter().zip(&boxed) {
        let SectionShape::Gec { centre, x, y } = &s.shape else {
            return Err(bad("a section was not replaced".into()));
        };
        let frame = Frame::new(s.centre, s.e1, s.e2).map_err(|e| bad(e.to_string()))?;
        let g =
            gec::Gec::new(frame, *centre, x.clone(), y.clone()).map_err(|e| bad(e.to_string()))?;
        let got = g.sample_plane(4 * LOOP_POINTS);
        worst = worst.max(super::polygon::hausdorff(&got, expected, 1e-3 * diam));
    }
    Ok(worst / diam)
}
