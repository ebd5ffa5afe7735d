//! The checks of the face reconstruction (family `face` in
//! [`crate::verify`]): the base face rebuilt by the default network with the
//! default shape parameters (no optimisation: fast), its MVE against the
//! base's own vertices within a measured bound, C2 across its edges.

use super::extract::{rebuild, FaceOptions, DEFAULT_PATCHES};
use crate::check::{tol, Check, Kind};

/// Bound on the base face's MVE (dm) with the default network and default
/// parameters: measured 0.0475 (the lip corners and the nose wings, where
/// the skin folds between two column curves); 5 % above it.
pub const BASE_MVE_DM: f64 = 0.05;

/// Bound on the distance (dm) of the base's face-region vertices inside
/// the sketched web's outer ring from the web's surface
/// ([`super::sketched`], default strokes): measured 0.0475 (the skin
/// between the nostril and the cheek, where the 3-sided fan meets the
/// first ring); 5 % above it.
pub const SKETCHED_SKIN_DM: f64 = 0.05;

/// Bound on the ear's MVE (dm) rebuilt from its four column curves
/// ([`super::ear`]) on the base: measured 0.113 (25 % of the ear's
/// height: the helix, which folds over itself, and the window's corners);
/// 6 % above it.
pub const EAR_MVE_DM: f64 = 0.12;

/// The sketched web on the base: `(largest relative jump over its edges,
/// apex interpolation, skin distance max)`, NaN when it cannot be built.
fn sketched_web() -> (f64, f64, f64) {
    use super::sketched::{polar_network, skin_distance, RINGS, SPOKES};
    let run = || -> Option<(f64, f64, f64)> {
        let (base, body) = super::extract::base().ok()?;
        let doc = polar_network(base, body, &super::BASE_WINDOW, RINGS, SPOKES).ok()?;
        let net = crate::ode6::network::Network::build(doc.clone()).ok()?;
        let r = net.report(4);
        let jump = r.max_relative_jump();
        let d = skin_distance(base, body, &super::BASE_WINDOW, &doc, &net.mesh(10)).ok()?;
        Some((jump, r.apex_interpolation, d.max))
    };
    run().unwrap_or((f64::NAN, f64::NAN, f64::NAN))
}

/// The face checks.
pub fn checks() -> Vec<Check> {
    let base = crate::makehuman::base_mesh();
    let r = base
        .ok()
        .and_then(|m| rebuild(&m, &FaceOptions::new(DEFAULT_PATCHES, false)).ok())
        .map(|(_, r, _)| r);
    let (mve, c2) = r.as_ref().map_or((f64::NAN, f64::NAN), |r| {
        let c2 = r
            .u_edges
            .iter()
            .chain(&r.v_edges)
            .fold(0.0f64, |a, b| crate::ode6::network::report::nan_max(a, *b));
        (r.max_error, c2)
    });
    let n = r.as_ref().map_or(0, |r| r.face_vertices);
    let web = sketched_web();
    let ear = super::extract::base()
        .ok()
        .and_then(|(m, body)| super::ear::rebuild_ear(m, body).ok())
        .map(|(_, r, _)| r);
    let ear_mve = ear.as_ref().map_or(f64::NAN, |r| r.max_error);
    let ear_n = ear.as_ref().map_or(0, |r| r.vertices);
    vec![
        Check::new(
            "face",
            "004",
            "sec 6.3",
            "face.base_mve",
            Kind::Threshold,
            mve,
            BASE_MVE_DM,
        )
        .note(format!(
            "the MakeHuman base face ({n} vertices) rebuilt from its {DEFAULT_PATCHES}-patch column network: largest distance (dm) of a regenerated vertex from the base's own vertex"
        )),
        Check::new(
            "face",
            "004",
            "eqs 23-26",
            "face.network_c2",
            Kind::Continuity,
            c2,
            tol::SOLVE,
        )
        .note("the face network: largest relative jump of the derivatives up to order 2 across its u- and v-edges"),
        Check::new(
            "face",
            "004",
            "Fig 8",
            "face.sketched_c2",
            Kind::Continuity,
            web.0,
            tol::SOLVE,
        )
        .note("the web sketched in the front view around the tip of the nose (face::sketched, 3-sided patches at the tip): largest relative jump of the derivatives up to order 2 across its u- and v-edges"),
        Check::new(
            "face",
            "004",
            "Fig 8",
            "face.sketched_apex",
            Kind::Boundary,
            web.1,
            tol::SOLVE,
        )
        .note("the sketched web's 3-sided patches: largest distance of S(0, v) from the apex (the tip of the nose), relative to the network's size"),
        Check::new(
            "face",
            "004",
            "Fig 8",
            "face.sketched_skin_distance",
            Kind::Threshold,
            web.2,
            SKETCHED_SKIN_DM,
        )
        .note("the sketched web: largest distance (dm) of a base face-region vertex inside its outer ring from its surface"),
        Check::new(
            "face",
            "004",
            "Fig 9e-f",
            "face.ear_mve",
            Kind::Threshold,
            ear_mve,
            EAR_MVE_DM,
        )
        .note(format!(
            "the base's left ear ({ear_n} vertices) rebuilt from four column curves (three C2 ODE patches, face::ear): largest distance (dm) of a regenerated vertex from the base's own vertex"
        )),
    ]
}
