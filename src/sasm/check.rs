//! The `sasm` verification family: the measurements of [`super::measure`]
//! on the bundled female's breast and nose (paper 000 Fig 10, built by
//! [`super::demo`]).

pub use super::measure::{measure, SasmReport, C1_ANGLE, PROFILE};
use crate::check::Worst;
use crate::check::{Check, Kind};

/// The family's checks: the bundled female's breast and nose.
pub fn checks() -> Vec<Check> {
    let mut out = Vec::new();
    let c = |n: &str, kind, m: f64, t: f64| {
        Check::new("sasm", "000", "sec 5.3", &format!("sasm.{n}"), kind, m, t)
    };
    let demo = match super::demo::female_fig10() {
        Ok(d) => d,
        Err(e) => {
            out.push(
                c("build", Kind::Threshold, f64::NAN, 0.0)
                    .note(format!("the bundled female's Fig 10 edits failed: {e}")),
            );
            return out;
        }
    };
    for (name, r) in [("breast", &demo.breast), ("nose", &demo.nose)] {
        out.push(c(&format!("{name}.join_c0"), Kind::Continuity, r.c0_rel, crate::check::tol::SOLVE).note(
            "largest |S' - S| on the curve (256 ray-cast points of the fitted boundary) / the feature's peak height",
        ));
        out.push(c(&format!("{name}.join_c1"), Kind::Continuity, r.c1_angle_extrapolated, C1_ANGLE).note(
            "angle (rad) between edited and host normals just inside the curve (central differences in (u, theta) at rho = 1 - 2e-3, 1e-3, 5e-4), Richardson-extrapolated to the curve; largest over 256 points",
        ));
        let inside = if r.max_rho_moved < 1.0 {
            r.max_move_outside
        } else {
            r.max_move_outside.worst(1.0)
        };
        out.push(c(&format!("{name}.inside_region"), Kind::Threshold, inside, 0.0).note(
            "largest move of an original vertex outside the curve's region (rho >= 1; 1 if a moved vertex lies outside): the feature lies inside the curve in its view",
        ));
        out.push(c(&format!("{name}.curve_fit"), Kind::Threshold, r.fit_deviation, super::region::MAX_FIT_DEVIATION).note(
            "largest radial distance of the stroke's points from the Fourier-fitted join curve / its mean radius",
        ));
        for (k, e) in r.profile_error_rel.iter().enumerate() {
            out.push(c(&format!("{name}.profile_{}", k + 1), Kind::Threshold, *e, PROFILE).note(
                "largest distance between the feature's outline in the profile's view (greatest depth over the region's chord) and the profile stroke, outside the blend band, / peak height",
            ));
        }
        out.push(c(&format!("{name}.watertight"), Kind::Threshold, if r.watertight { r.bad_topology as f64 } else { (r.bad_topology as f64).worst(1.0) }, 0.0).note(
            "edited model: boundary + non-manifold + misoriented edges, non-manifold vertices, degenerate triangles (mesh::topology)",
        ));
    }
    out
}
