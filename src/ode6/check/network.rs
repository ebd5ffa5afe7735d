//! Checks of the curve networks (`super::super::network`): C2 across every
//! edge of every bundled network, the ODE residual inside their patches,
//! and the interpolation of a 3-sided patch's apex and far side.

use super::ck;
use crate::check::{tol, Check, Kind};
use crate::ode6::network::report::nan_max;
use crate::ode6::network::samples;
use crate::ode6::network::{EdgeKind, Network};

/// The relative C2 bound of issue 32 across every edge.
pub const NETWORK_C2: f64 = 1e-9;
/// Intervals sampled along each edge by the checks (the tests and the CLI
/// report use `report::EDGE_SAMPLES`).
pub const CHECK_EDGE_SAMPLES: usize = 4;

/// The network checks.
pub fn network_checks() -> Vec<Check> {
    let mut out = Vec::new();
    // two networks: the vase (a fan and a closed ring of strips) and the
    // quadruped (parts, fans at both ends, open tubes); the tests cover all
    for (name, doc) in [
        ("vase", samples::vase()),
        ("quadruped", samples::quadruped()),
    ] {
        let net = Network::build(doc);
        let (jump, res, edges) = match &net {
            Ok(n) => {
                let (u, v) = n.max_jumps(CHECK_EDGE_SAMPLES);
                let m = u.iter().chain(&v).fold(0.0f64, |a, b| nan_max(a, *b));
                let edges = n
                    .topology
                    .edges
                    .iter()
                    .filter(|e| matches!(e, EdgeKind::U { .. } | EdgeKind::V { .. }))
                    .count();
                (m, n.residual(3), edges)
            }
            Err(_) => (f64::NAN, f64::NAN, 0),
        };
        out.push(ck(
            "eqs 23-26",
            &format!("ode6.network_c2.{name}"),
            Kind::Continuity,
            jump,
            NETWORK_C2,
            &format!("bundled network {name}: largest jump of S, S_u, S_v, S_uu, S_uv, S_vv across its {edges} u- and v-edges ({} samples each), over the network size (order 0) or the derivatives' magnitude (orders 1, 2)", CHECK_EDGE_SAMPLES + 1),
        ));
        out.push(ck(
            "eqs 8-19",
            &format!("ode6.network_residual.{name}"),
            Kind::Residual,
            res,
            tol::SOLVE,
            "|rho S^(6) + eta S^(4) + lambda S''| / (sum of the terms, floored at the parameters times the size) at 4 interior points of every patch (jets)",
        ));
    }
    let vase = Network::build(samples::vase()).map(|n| n.report(1));
    let (apex, side) = vase.as_ref().map_or((f64::NAN, f64::NAN), |r| {
        (r.apex_interpolation, r.u_side_interpolation)
    });
    out.push(ck(
        "sec 6.2",
        "ode6.network_three_sided_apex",
        Kind::Boundary,
        apex,
        tol::ROUNDING,
        "the vase's 3-sided fan: |S(0, v) - apex| / size at 17 v per patch (the collapsed side c_1 = apex)",
    ));
    out.push(ck(
        "sec 6.2",
        "ode6.network_u_sides",
        Kind::Boundary,
        side,
        tol::SOLVE,
        "the vase's u-sides (the 3-sided patches' far sides included): |S(0 or 1, t_i) - P_i| / size at every document point",
    ));
    out
}
