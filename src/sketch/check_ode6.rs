//! The bundled female with ODE6 arms (issue 29: parts behind a trait): the
//! same document with `arm_l` and `arm_r` switched to the `ode6_c2` surface
//! family (paper 004) builds, meets its transitions C1 as the pde6 parts do
//! and is C2 along the arms.

use crate::character::doc::SurfaceSpec;
use crate::character::Resolution;
use crate::check::{tol, worst, Check, Kind};
use crate::pipeline::{build_document, Built};

/// The arms' ODE shape parameters: 004's own case (rho = lambda = 1,
/// eta = 3, the parameters of its Fig 6 and of the ode6 family's checks).
pub const ARM: SurfaceSpec = SurfaceSpec::Ode6C2 {
    rho: 1.0,
    eta: 3.0,
    lambda: 1.0,
};

/// Names of the parts switched to ODE6.
pub const ARMS: [&str; 2] = ["arm_l", "arm_r"];

/// `b`'s document with its arms switched to [`ARM`] (and every
/// transition to the quintic C2 one when `c2`), built.
pub fn with_ode6_arms(b: &Built, c2: bool) -> Option<Built> {
    let mut d = b.doc.clone();
    for arm in ARMS {
        if let Some(p) = d.part_mut(arm) {
            p.surface = ARM;
        }
    }
    if c2 {
        d.set_continuity(crate::character::doc::Continuity::C2);
    }
    build_document(&d, std::path::Path::new("."), Resolution::default(), false).ok()
}

/// The largest `C1` or `C2` jump (`order` 1 or 2) of the joins of the
/// arms, NaN unless both arms built as ode6.
fn arm_jump(built: &Option<Built>, order: usize) -> f64 {
    let Some(o) = built else { return f64::NAN };
    let ode6 = o
        .model
        .parts
        .iter()
        .filter(|p| ARMS.contains(&p.name.as_str()) && p.surface.family() == "ode6_c2")
        .count();
    if ode6 != ARMS.len() {
        return f64::NAN;
    }
    o.model
        .joins
        .iter()
        .filter(|j| ARMS.contains(&j.part.as_str()))
        .map(|j| if order == 1 { j.c1 } else { j.c2 })
        .fold(0.0, worst)
}

/// The four checks, from the built pde6 female `b`, with the bounds of
/// the pde6 female's own checks (`sketch::check`'s `C1_JUMP` and
/// `PROFILE_FRONT`; the C2 option's bound is the C1 one, as there).
pub fn checks(b: &Built, c1_jump: f64, profile_front: f64) -> Vec<Check> {
    let c = |name: &str, kind, m: f64, t: f64| {
        Check::new(
            "sketch",
            "004",
            "eqs 19, 23-25",
            &format!("sketch.female.ode6_arms.{name}"),
            kind,
            m,
            t,
        )
    };
    let built = with_ode6_arms(b, false);
    let c2 = arm_jump(&with_ode6_arms(b, true), 2);
    let arms: Vec<_> = built
        .iter()
        .flat_map(|o| o.model.parts.iter())
        .filter(|p| ARMS.contains(&p.name.as_str()) && p.surface.family() == "ode6_c2")
        .collect();
    let switched = built.is_some() && arms.len() == ARMS.len();
    let c1 = arm_jump(&built, 1);
    let inside = if switched {
        arms.iter()
            .flat_map(|p| p.surface.internal_jumps(crate::pde6::JOIN_SAMPLES))
            .fold(0.0, worst)
    } else {
        f64::NAN
    };
    let front = built
        .iter()
        .flat_map(|o| o.report.profile_error.iter())
        .filter(|p| p.view == "front")
        .map(|p| p.max_rel)
        .fold(if switched { 0.0 } else { f64::NAN }, worst);
    vec![
        c("transition_c1", Kind::Continuity, c1, c1_jump)
            .note("largest C1 jump |X_s - ell dX/du| / max |ell dX/du| of the shoulder transitions against the ODE6 arms (jets of the ode6 patches; the transitions take the arms' sections from PartGeometry::section), 3 samples per loop vertex; NaN if the arms did not build as ode6")
            .loose_because(crate::check::JOIN_REQUIREMENT_REASON),
        c("transition_c2_option", Kind::Continuity, c2, c1_jump)
            .note("largest C2 jump |X_ss - ell^2 d2X/du2| / max(|ell^2 d2X/du2|, |ell dX/du|) of the shoulder transitions built with continuity c2 (quintic Hermite) against the ODE6 arms: the arms' second derivative vanishes at their natural start and the transition's is built from it (PartGeometry::section), so this is exactly 0 unless the section derivative and the arm's jets disagree")
            .loose_because(crate::check::JOIN_REQUIREMENT_REASON),
        c("c2_inside", Kind::Continuity, inside, tol::ROUNDING)
            .note("largest jump of S, S_u, S_uu across the ODE6 arms' own section joins, relative to max(|derivative|, 1) (the natural spline's derivative curves make each join's six constraints equal on both sides)"),
        c("profile_error_front", Kind::Threshold, front, profile_front)
            .note("front-view profile error of the female with ODE6 arms (relative to the height): the arms still follow the drawing between their sections"),
    ]
}
