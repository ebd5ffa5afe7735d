//! Checks of the closed body (issue 15): the base MakeHuman body (in
//! `verify`) and the morphs of [`CHECKED_MORPHS`](crate::body::closed::CHECKED_MORPHS) (`pdesculpt study
//! bodies`) reconstruct as one watertight, manifold, oriented mesh, C1 at
//! every join, within the error targets.

use crate::body::closed::{
    load_body, reconstruct_closed, ClosedOptions, ClosedReport, FULL_SKIN_MAX_KNOWN, JOIN_C1_MAX,
    MAX_MAX_REL, RMS_MAX_REL, THUMB_SKIN_MAX_REL,
};
use crate::body::intersect::known_crossings;
use crate::check::worst;
use crate::check::{Check, Kind};

const FAMILY: &str = "body";
const PAPER: &str = "002";
const WHERE: &str = "sec 4, Figs 5-6 (closed body)";

/// `pde6.body_closed_*` for the base body (family `body` of `verify`).
pub fn body_closed_checks(out: &mut Vec<Check>) {
    closed_checks(out, vec![("base".into(), vec![])]);
}

/// `pde6.body_closed_*` for the checked morph `m` of [`CHECKED_MORPHS`](crate::body::closed::CHECKED_MORPHS)
/// (`NAME=WEIGHT`; the checks are named after `NAME`): the multi-body table
/// of `pdesculpt study bodies` ([`crate::study`]), where each body runs on
/// its own thread.
pub fn morph_closed_checks(out: &mut Vec<Check>, m: &str) {
    let name = m.split('=').next().unwrap_or(m).to_string();
    closed_checks(out, vec![(name, vec![m.to_string()])]);
}

/// What the closed-body checks read from one reconstruction.
struct Measured {
    /// Boundary, non-manifold and misoriented edges, non-manifold vertices.
    topo: f64,
    c1: f64,
    rms: f64,
    /// Outer-skin max, full-skin max.
    max: [f64; 2],
    note: String,
    /// Crossing pairs and their description.
    crossings: (f64, String),
    /// Thumb max distance, web points inside, description.
    thumb: (f64, f64, String),
}

impl Measured {
    fn of(r: &ClosedReport) -> Self {
        let thumb = (
            // NaN for no hands (a missing hand fails, not 0)
            if r.hands.is_empty() {
                f64::NAN
            } else {
                r.hands
                    .iter()
                    .map(|h| h.thumb_skin_to_recon_max_rel)
                    .fold(0.0, worst)
            },
            r.hands
                .iter()
                .map(|h| h.web_points_inside as f64 + if h.web_points == 0 { f64::INFINITY } else { 0.0 })
                .sum::<f64>()
                + if r.hands.len() == 2 { 0.0 } else { f64::INFINITY },
            format!(
                "per hand (left, right): {}",
                r.hands
                    .iter()
                    .map(|h| format!(
                        "{} thumb vertices, max {:.3} %; {} of {} web points inside; thumb arc +-{:.3} rad",
                        h.thumb_vertices,
                        100.0 * h.thumb_skin_to_recon_max_rel,
                        h.web_points_inside,
                        h.web_points,
                        h.thumb_arc
                    ))
                    .collect::<Vec<_>>()
                    .join("; ")
            ),
        );
        let t = &r.topology;
        let bad =
            (t.boundary_edges + t.nonmanifold_edges + t.misoriented_edges + t.nonmanifold_vertices)
                as f64;
        let note = format!(
            "{} triangles; recon->skin RMS {:.3} % max {:.3} %, skin->recon RMS {:.3} % max {:.3} % (all skin), outer skin RMS {:.3} % max {:.3} % ({} cavity vertices left out); C0 {:.1e} C1 {:.1e} C2 {:.2} (Hermite transitions: C2 not claimed)",
            r.triangles,
            100.0 * r.recon_to_skin_rms_rel,
            100.0 * r.recon_to_skin_max_rel,
            100.0 * r.skin_to_recon_rms_rel,
            100.0 * r.skin_to_recon_max_rel,
            100.0 * r.skin_to_recon_outer_rms_rel,
            100.0 * r.skin_to_recon_outer_max_rel,
            r.skin_cavities.count,
            r.max_join[0],
            r.max_join[1],
            r.max_join[2]
        );
        let x = &r.self_intersections;
        let crossings = (
            x.pairs as f64,
            format!(
                "{} crossing triangle pairs {:?}, first at {:?}",
                x.pairs, x.by_groups, x.example
            ),
        );
        Measured {
            topo: bad,
            c1: r.max_join[1],
            rms: r.judged_rms_rel(),
            max: [r.judged_max_rel(), r.skin_to_recon_max_rel],
            note,
            crossings,
            thumb,
        }
    }

    /// A failed reconstruction: every measurement NaN, so every check fails.
    fn failed(e: impl std::fmt::Display) -> Self {
        Measured {
            topo: f64::NAN,
            c1: f64::NAN,
            rms: f64::NAN,
            max: [f64::NAN; 2],
            note: format!("failed: {e}"),
            crossings: (f64::NAN, String::new()),
            thumb: (f64::NAN, f64::NAN, String::new()),
        }
    }
}

fn closed_checks(out: &mut Vec<Check>, bodies: Vec<(String, Vec<String>)>) {
    for (name, morphs) in bodies {
        let known = known_crossings(&name);
        let run = load_body(None, &morphs)
            .and_then(|skin| reconstruct_closed(&skin, &ClosedOptions::default()));
        let Measured {
            topo,
            c1,
            rms,
            max,
            note,
            crossings,
            thumb,
        } = match run {
            Ok(b) => Measured::of(&b.report),
            Err(e) => Measured::failed(e),
        };
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_thumb_{name}"), Kind::Threshold, thumb.0, THUMB_SKIN_MAX_REL)
                .note(format!("largest distance from the skin's thumb vertices (body::hand::thumb_vertices: near the sections of the thumb traced along its own axis) to the reconstruction, relative to the height, over both hands; {}", thumb.2)),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_thumb_web_{name}"), Kind::Threshold, thumb.1, 0.0)
                .note(format!("web points (air between the thumb and the palm or index finger: middles of the gaps between their loops in the arm trace's planes past the split) enclosed by the reconstruction (generalised winding number > 1/2), both hands: a mitten without a thumb fills the web and encloses them; infinite when a hand found no web point or has no thumb; {}", thumb.2)),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_topology_{name}"), Kind::Threshold, topo, 0.0)
                .note(format!("boundary + non-manifold + misoriented edges + non-manifold vertices of the closed body (0 = watertight, manifold, oriented); {note}")),
        );
        out.push(
            Check::new(
                FAMILY,
                PAPER,
                WHERE,
                &format!("pde6.body_closed_c1_{name}"),
                Kind::Continuity,
                c1,
                JOIN_C1_MAX,
            )
            .note("largest relative C1 jump of a transition against its parts along every join")
            .loose_because(crate::check::JOIN_REQUIREMENT_REASON),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_rms_{name}"), Kind::Threshold, rms, RMS_MAX_REL)
                .note("larger of the RMS distances reconstruction->skin and skin->reconstruction, relative to the height"),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_max_{name}"), Kind::Threshold, max[0], MAX_MAX_REL)
                .note("larger of the max distances reconstruction->skin and skin->reconstruction over the OUTER skin, relative to the height: the skin's cavity vertices (body::cavity: on a horizontal slice loop nested inside another, the mouth and eye-socket pockets of the MakeHuman skin) are left out, since no section with one outer loop, this method's or paper 002's, reaches them; the full-skin max is the next check"),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_full_skin_max_{name}"), Kind::Threshold, max[1], FULL_SKIN_MAX_KNOWN)
                .note("skin->reconstruction max over EVERY skin vertex, cavities included, relative to the height: not the issue's target (see pde6.body_closed_max_*), a regression bound at the known state so the full number stays in verify"),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_self_crossings_{name}"), Kind::Threshold, crossings.0, known as f64)
                .note(if known == 0 {
                    format!("crossing triangle pairs (sharing no vertex) of the closed mesh, grid + Moller-Trumbore edge tests; the issue's target 0; {}", crossings.1)
                } else {
                    format!("crossing triangle pairs (sharing no vertex) of the closed mesh, grid + Moller-Trumbore edge tests; the issue's target is 0, NOT MET for this body: the tolerance is its known state (body::intersect::KNOWN_CROSSINGS, a regression bound); {}", crossings.1)
                }),
        );
    }
}

/// `pde6.body_cavity_nested_shells`: the cavity rule on a sphere with a
/// spherical pocket inside it (the inner shell's triangles reversed: one
/// closed skin with an inner wall). Every inner vertex must be a cavity
/// vertex, no outer one.
pub fn body_cavity_checks(out: &mut Vec<Check>) {
    let (skin, inner) = crate::body::cavity::nested_shells();
    let c = crate::body::cavity::find_cavities(&skin, -1.0, 2.0);
    let wrong = c
        .cavity
        .iter()
        .enumerate()
        .filter(|&(i, &cv)| cv != (i >= inner))
        .count();
    out.push(
        Check::new(FAMILY, PAPER, WHERE, "pde6.body_cavity_nested_shells", Kind::Threshold, wrong as f64, 0.0)
            .note(format!(
                "misclassified vertices of a unit sphere holding a reversed sphere of radius 0.5 ({} + {} vertices; {} found in the cavity)",
                inner,
                skin.positions.len() - inner,
                c.count
            )),
    );
}
