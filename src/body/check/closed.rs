//! Checks of the closed body (issue 15): the base MakeHuman body and the
//! morphs of [`CHECKED_MORPHS`] reconstruct as one watertight, manifold,
//! oriented mesh, C1 at every join, within the error targets.

use crate::body::closed::{
    load_body, reconstruct_closed, ClosedOptions, CHECKED_MORPHS, JOIN_C1_MAX, MAX_MAX_REL,
    RMS_MAX_REL,
};
use crate::check::{Check, Kind};

const FAMILY: &str = "body";
const PAPER: &str = "002";
const WHERE: &str = "sec 4, Figs 5-6 (closed body)";

/// `pde6.body_closed_*` for the base body and each checked morph.
pub fn body_closed_checks(out: &mut Vec<Check>) {
    let mut bodies: Vec<(String, Vec<String>)> = vec![("base".into(), vec![])];
    for m in CHECKED_MORPHS {
        let name = m.split('=').next().unwrap_or(m).to_string();
        bodies.push((name, vec![m.to_string()]));
    }
    for (name, morphs) in bodies {
        let run = load_body(None, &morphs)
            .and_then(|skin| reconstruct_closed(&skin, &ClosedOptions::default()));
        let (topo, c1, rms, max, note) = match run {
            Ok(b) => {
                let r = b.report;
                let t = &r.topology;
                let bad = (t.boundary_edges
                    + t.nonmanifold_edges
                    + t.misoriented_edges
                    + t.nonmanifold_vertices) as f64;
                let note = format!(
                    "{} triangles; recon->skin RMS {:.3} % max {:.3} %, skin->recon RMS {:.3} % max {:.3} %; C0 {:.1e} C1 {:.1e} C2 {:.2} (Hermite transitions: C2 not claimed)",
                    r.triangles,
                    100.0 * r.recon_to_skin_rms_rel,
                    100.0 * r.recon_to_skin_max_rel,
                    100.0 * r.skin_to_recon_rms_rel,
                    100.0 * r.skin_to_recon_max_rel,
                    r.max_join[0],
                    r.max_join[1],
                    r.max_join[2]
                );
                (
                    bad,
                    r.max_join[1],
                    r.recon_to_skin_rms_rel.max(r.skin_to_recon_rms_rel),
                    r.recon_to_skin_max_rel.max(r.skin_to_recon_max_rel),
                    note,
                )
            }
            Err(e) => (
                f64::NAN,
                f64::NAN,
                f64::NAN,
                f64::NAN,
                format!("failed: {e}"),
            ),
        };
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
            .note("largest relative C1 jump of a transition against its parts along every join"),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_rms_{name}"), Kind::Threshold, rms, RMS_MAX_REL)
                .note("larger of the RMS distances reconstruction->skin and skin->reconstruction, relative to the height"),
        );
        out.push(
            Check::new(FAMILY, PAPER, WHERE, &format!("pde6.body_closed_max_{name}"), Kind::Threshold, max, MAX_MAX_REL)
                .note("larger of the max distances reconstruction->skin and skin->reconstruction, relative to the height"),
        );
    }
}
