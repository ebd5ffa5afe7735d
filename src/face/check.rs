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
    ]
}
