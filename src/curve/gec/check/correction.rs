//! Checks of the parameter correction ([`crate::curve::gec::correct`]) on
//! the MakeHuman cross sections of the study (paper 002 Table 1 analogue):
//! the default fit is never worse than the chord-length fit it replaced, at
//! any section and J of Table 1, and on the upper chest, where polar angles
//! gave a third less ErM than chord length at J = 10, it is strictly better
//! than every uncorrected rule.

use super::c;
use crate::check::{worst, Worst};
use crate::check::{Check, Kind};
use crate::curve::gec::study::{base_sections, correction_study, TABLE1_TERMS};
use crate::curve::gec::{fit, Correction, FitOptions, Param};

/// The named section and J of the strict-gain check.
pub const GAIN_SECTION: &str = "torso_upper_chest";
pub const GAIN_TERMS: usize = 10;
/// The corrected ErM on [`GAIN_SECTION`] must be below this fraction of the
/// best uncorrected rule's (strictly better, by a margin).
pub const GAIN_RATIO_MAX: f64 = 0.9;

/// `gec.correction_never_worse` and `gec.correction_gain_upper_chest`.
pub fn correction_checks(out: &mut Vec<Check>) {
    let (worse, gain, note) = match measure() {
        Ok(m) => m,
        Err(e) => (f64::NAN, f64::NAN, format!("failed: {e}")),
    };
    out.push(c(
        "002 Table 1",
        "gec.correction_never_worse",
        Kind::Threshold,
        worse,
        0.0,
        &format!("largest (ErM default - ErM chord length uncorrected) / D over the 11 MakeHuman sections and J in 1, 3, 5, 7, 10 (<= 0: never worse); {note}"),
    ));
    out.push(c(
        "002 Table 1",
        "gec.correction_gain_upper_chest",
        Kind::Threshold,
        gain,
        GAIN_RATIO_MAX,
        &format!("ErM of the default fit / smallest ErM of the four uncorrected rules on {GAIN_SECTION} at J = {GAIN_TERMS}"),
    ));
}

fn measure() -> Result<(f64, f64, String), String> {
    let secs = base_sections().map_err(|e| e.to_string())?;
    let rows =
        correction_study(&secs, &TABLE1_TERMS, Param::ChordLength).map_err(|e| e.to_string())?;
    let worse = rows
        .iter()
        .map(|r| (r.erm_after - r.erm_before) / r.scale)
        .fold(f64::NEG_INFINITY, worst);
    let (mut before, mut after) = (0.0, 0.0);
    for r in &rows {
        before += r.erm_before / rows.len() as f64;
        after += r.erm_after / rows.len() as f64;
    }
    let sec = secs
        .iter()
        .find(|s| s.name == GAIN_SECTION)
        .ok_or_else(|| format!("no section {GAIN_SECTION}"))?;
    let erm = |param: Param, correction: Correction| {
        fit(
            &sec.points,
            &FitOptions {
                param,
                correction,
                ..FitOptions::new(GAIN_TERMS)
            },
        )
        .map(|r| r.errors.erm)
        .map_err(|e| e.to_string())
    };
    let mut best_rule = f64::INFINITY;
    for p in Param::ALL {
        best_rule = best_rule.least(erm(p, Correction::None)?);
    }
    let corrected = erm(Param::default(), Correction::default())?;
    Ok((
        worse,
        corrected / best_rule,
        format!("mean ErM over the 55 fits {before:.5} -> {after:.5} (data units)"),
    ))
}
