//! Smoothness checks of the body reconstruction (paper 002 section 4,
//! Figs 5-6): the current options against [`legacy_options`] on the parts
//! that rippled (torso and head).

use crate::body::parts::{
    legacy_options, makehuman_parts, part_smoothness, reconstruct_part, BodyOptions,
};
use crate::check::Worst;
use crate::check::{Check, Kind};

const FAMILY: &str = "body";
const PAPER: &str = "002";
/// The ripple fix must at least halve the u-roughness of torso and head.
pub const ROUGHNESS_RATIO_MAX: f64 = 0.5;
/// Largest mean polar-angle slip of theta between consecutive sections (degrees).
pub const SLIP_MAX_DEG: f64 = 3.0;
/// The parts measured.
const PARTS: [&str; 2] = ["torso", "head"];

/// `pde6.body_smoothness` and `pde6.body_section_slip`.
pub fn body_smoothness_checks(out: &mut Vec<Check>) {
    let (mut ratio, mut slip, mut slip_old) = (0.0f64, 0.0f64, 0.0f64);
    let mut notes = Vec::new();
    let measured = (|| -> Result<(), String> {
        let body = crate::makehuman::base_body().map_err(|e| e.to_string())?;
        for spec in makehuman_parts().iter().filter(|p| PARTS.contains(&p.name)) {
            let run = |o: &BodyOptions| {
                reconstruct_part(&body.mesh, spec, o)
                    .map(|p| part_smoothness(&p))
                    .map_err(|e| e.to_string())
            };
            let (r_old, s_old, _) = run(&legacy_options())?;
            let (r_new, s_new, _) = run(&BodyOptions::default())?;
            ratio = ratio.worst(r_new.u / r_old.u);
            slip = slip.worst(s_new);
            slip_old = slip_old.worst(s_old);
            notes.push(format!(
                "{}: roughness u {:.4} -> {:.4}, v {:.4} -> {:.4}, slip {:.2} -> {:.2} deg",
                spec.name, r_old.u, r_new.u, r_old.v, r_new.v, s_old, s_new
            ));
        }
        Ok(())
    })();
    if let Err(e) = measured {
        ratio = f64::NAN;
        slip = f64::NAN;
        notes.push(format!("failed: {e}"));
    }
    let notes = notes.join("; ");
    out.push(
        Check::new(FAMILY, PAPER, "sec 4, Figs 5-6", "pde6.body_smoothness", Kind::Threshold, ratio, ROUGHNESS_RATIO_MAX)
            .note(format!("max over torso/head of the mean second difference of the unit normal along u (default options / legacy a = -0.5 + chord parameter from the first sliced vertex); {notes}")),
    );
    out.push(
        Check::new(FAMILY, PAPER, "sec 4, Figs 5-6", "pde6.body_section_slip", Kind::Threshold, slip, SLIP_MAX_DEG)
            .note(format!("max over torso/head of the mean polar-angle slip of C(theta) between consecutive sections, degrees (legacy {slip_old:.2})")),
    );
}
