//! A real body's thumb held away from the hand (`sketch::thumb`): cut off
//! the arm's walk and built as a separate closed chain reaching into the
//! hand, as paper 000 composes a removed part.

use super::sketch_draw::{build_real_body, stays_inside};
use pdesculpt::sketch::quality::Bounds;

/// MakeHuman's old, thin woman (front silhouette and armless side, as the
/// issue's held-out real bodies are drawn): her thumbs stand away from her
/// hands, and the arms' tubes averaged them away: the front missed a
/// thumb's tip by 1.87 % of the height, past issue 28's 1.5 %. With the
/// thumbs built on their own: 0.79 % (docs/drawing-corpus.md, thirty-first
/// measurement), and every other bound of the issue met.
#[test]
fn a_real_body_s_thumbs_are_modelled() {
    let t =
        pdesculpt::makehuman::target("universal-female-old-minmuscle-minweight").expect("target");
    let body = pdesculpt::makehuman::body(&[(t, 1.0)]).expect("the morphed body");
    let (b, _) = build_real_body(&body.mesh, "draw-real-thumbs");
    let parts: Vec<&str> = b.doc.parts().iter().map(|p| p.name.as_str()).collect();
    for thumb in ["thumb_l", "thumb_r"] {
        assert!(parts.contains(&thumb), "no {thumb}: {parts:?}");
    }
    let q = &b.report.quality.whole;
    let bounds = Bounds::ISSUE;
    let front = q.view("front").expect("front").max_rel;
    assert!(
        front <= bounds.profile_front,
        "front error {:.2} % of the height",
        100.0 * front
    );
    assert!(
        q.dihedral_deg <= bounds.dihedral_deg && q.creased_rel <= bounds.creased_rel,
        "largest turn {:.1} degrees, creased length {:.3} heights",
        q.dihedral_deg,
        q.creased_rel
    );
    stays_inside(&b, "front");
    stays_inside(&b, "side");
}
