//! The seam apexes of a humanoid's shoulders transition: where each seam
//! between the neck's and an arm's pieces crosses the top of the drawn
//! shoulder (`character::transition`: the seam runs from the torso ring's
//! front cut through its apex to the back cut).
//!
//! The derived apex is the drawn shoulder's top halfway between the neck's
//! side and the arm's shoulder point (the upper end of its cut), or a
//! raised shoulder's own top there ([`raised_shoulder`]), or the straight
//! shoulder line. The **alternative** is the highest drawn top over the
//! neck's half of the shoulder ([`highest_shoulder`]): a raised shoulder (a
//! trapezius) peaks nearer the neck than halfway, and the seam through the
//! halfway top crossed the outline below the peak, the model's shoulder
//! line sagging under the drawn one (seed 4242's random_23, random_28,
//! random_46: 1.55-2.51 % of the height off the front). Moved there
//! unconditionally the apex folded other figures' shoulders (random_16,
//! random_31 of that set: 115 -> 175 degrees), so the alternative is a
//! candidate of the transition fit (`tangent_fit::fit_apexes`), kept only
//! where it misses the drawing less without a crease or fold the derived
//! apex avoids.

use super::poly::slice;
use super::segment::{shoulder_top, Landmarks};

/// Each shoulder's (left, right) derived seam apex and its alternative
/// (None when the highest top is the derived apex or there is none), for
/// the placed outline `front` with landmarks `lm`: `top_c` the torso's
/// end ring's centre, `neck_y` the neck's first ring's height and `g` a
/// join band (`[top_c, [_, neck_y, g]]`), `neck_x` the neck's sides at
/// its base, `shoulders` the arms' shoulder points.
pub fn shoulder_apexes(
    front: &[[f64; 2]],
    lm: &Landmarks,
    [top_c, [_, neck_y, g]]: [[f64; 3]; 2],
    neck_x: [f64; 2],
    shoulders: [[f64; 2]; 2],
) -> [([f64; 3], Option<[f64; 3]>); 2] {
    // the outline's top at x when it lies between the torso's end ring
    // and the neck; else (x over a notch or a gap of the drawing, whose
    // top below the neck can be a leg's: random_6 of the seed-7777 set
    // put an apex near the feet and a sheet hung from it) None
    let top = |x: f64| {
        shoulder_top(front, x, lm)
            .filter(|y| *y > top_c[1] && *y <= lm.neck)
            .or_else(|| raised_shoulder(front, x, top_c[1], lm, g))
    };
    [0, 1].map(|k| {
        let (x0, out) = (neck_x[k], shoulders[k]);
        let x = 0.5 * (x0 + out[0]);
        // else the straight shoulder line from the neck's base to the
        // shoulder point, halfway
        let y = top(x).unwrap_or_else(|| (0.5 * (lm.neck_base + out[1])).max(top_c[1] + g));
        let derived = [x, y, top_c[2]];
        let alt = highest_shoulder([x0, out[0]], neck_y, top)
            .filter(|a| a[1] > y)
            .map(|a| [a[0], a[1], top_c[2]]);
        (derived, alt)
    })
}

/// Samples of the apex's search across the middle of the shoulder.
pub const APEX_SAMPLES: usize = 12;
/// The apex is searched between these fractions of the way from the
/// neck's side to the shoulder point: the neck's half of the shoulder
/// (the other half is the arm's: its first sections turn to the drawn
/// corner there, `shoulder_tilt::shoulder_corner`), not its first quarter
/// (an apex at the neck's side leaves the neck's loop no width there).
pub const APEX_SPAN: [f64; 2] = [0.25, 0.5];

/// The seam apex of a shoulder between the neck's side at `x0` and the
/// arm's shoulder point at `x1`: the highest of the drawn shoulder's tops
/// (`top`: None where the outline has no shoulder top) over the middle
/// of the way ([`APEX_SPAN`]), the one nearest halfway among tops equal
/// within a thousandth of the way; a top off halfway only when it is no
/// higher than `ceiling` (the neck's first ring: a seam above it ran up
/// past the neck's loop and folded, random_23 of seed 4242's set); None
/// when no sample has a top. The
/// halfway point alone missed a raised shoulder (a trapezius) whose
/// highest point lies nearer the neck: the seam crossed the outline below
/// it and the model's shoulder line sagged under the drawn one.
fn highest_shoulder(
    [x0, x1]: [f64; 2],
    ceiling: f64,
    top: impl Fn(f64) -> Option<f64>,
) -> Option<[f64; 2]> {
    let tie = 1e-3 * (x1 - x0).abs();
    (0..=APEX_SAMPLES)
        .map(|k| {
            let t = APEX_SPAN[0] + (APEX_SPAN[1] - APEX_SPAN[0]) * k as f64 / APEX_SAMPLES as f64;
            (x0 + t * (x1 - x0), (t - 0.5).abs())
        })
        .filter_map(|(x, off)| Some((x, top(x)?, off)))
        .filter(|c| c.2 == 0.0 || c.1 <= ceiling)
        .fold(None, |best: Option<(f64, f64, f64)>, c| match best {
            Some(b) if b.1 > c.1 + tie || (b.1 >= c.1 - tie && b.2 <= c.2) => Some(b),
            _ => Some(c),
        })
        .map(|(x, y, _)| [x, y])
}

/// A shoulder's top that rises above the neck's narrowest height (a
/// short neck between raised shoulders: seed 4242's chubby, whose drawn
/// shoulder rose 4.3 % of the height above the straight shoulder line the
/// apex fell back to): the top of the outline's vertical interval at `x`
/// that holds the torso's end ring's height `y_ring`, taken only when a
/// join band `g` below that top the shoulder is apart from the interval on
/// the torso's axis (the neck): a head resting on the shoulder, or a
/// shoulder line that runs into the neck, is left to the straight line.
fn raised_shoulder(front: &[[f64; 2]], x: f64, y_ring: f64, lm: &Landmarks, g: f64) -> Option<f64> {
    let y = super::poly::top_through(front, x, y_ring).filter(|y| *y > y_ring + g)?;
    let axis = 0.5 * (lm.armpit_l[0] + lm.armpit_r[0]);
    let head_over_x = slice(front, y - g)
        .iter()
        .any(|iv| iv[0] <= axis && axis <= iv[1] && iv[0] <= x && x <= iv[1]);
    (!head_over_x).then_some(y)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bump of a shoulder rising above a short neck is the apex's
    /// height; a head resting on the shoulders, and a height outside the
    /// outline, are not.
    #[test]
    fn a_raised_shoulder_is_its_own_top_not_a_head_s() {
        let lm = Landmarks {
            y_min: 0.0,
            y_max: 8.0,
            crotch: [0.0, 1.0],
            armpit_l: [-3.0, 3.0],
            armpit_r: [3.0, 3.0],
            neck_base: 4.8,
            neck: 5.0,
        };
        let bumps = [
            [-3.0, 0.0],
            [3.0, 0.0],
            [3.0, 4.5],
            [2.0, 5.5],
            [1.0, 4.8],
            [0.5, 4.8],
            [0.5, 6.0],
            [1.0, 6.0],
            [1.0, 8.0],
            [-1.0, 8.0],
            [-1.0, 6.0],
            [-0.5, 6.0],
            [-0.5, 4.8],
            [-1.0, 4.8],
            [-2.0, 5.5],
            [-3.0, 4.5],
        ];
        let tol = crate::check::tol::ROUNDING;
        let top = raised_shoulder(&bumps, -2.0, 4.0, &lm, 0.1).expect("the bump");
        assert!((top - 5.5).abs() < tol, "{top}");
        // under the head, beside the neck: the shoulder line runs into
        // the neck a band below its top
        assert_eq!(raised_shoulder(&bumps, -0.8, 4.0, &lm, 0.1), None);
        // outside the outline at the ring's height
        assert_eq!(raised_shoulder(&bumps, -3.5, 4.0, &lm, 0.1), None);
        let resting = [
            [-3.0, 0.0],
            [3.0, 0.0],
            [3.0, 4.5],
            [2.0, 5.5],
            [2.0, 8.0],
            [-2.0, 8.0],
            [-2.0, 5.5],
            [-3.0, 4.5],
        ];
        assert_eq!(raised_shoulder(&resting, -1.5, 4.0, &lm, 0.1), None);
        assert_eq!(raised_shoulder(&resting, -2.5, 4.0, &lm, 0.1), None);
    }

    /// The highest top over the neck's half of the shoulder: a bump
    /// peaking at 0.3125 of the way (a sample) is taken there; a flat shoulder keeps
    /// halfway (ties go to the middle); a peak above the ceiling off
    /// halfway is passed over; no top anywhere, None.
    #[test]
    fn the_apex_alternative_is_the_shoulder_s_peak_on_the_neck_s_half() {
        let tol = crate::check::tol::ROUNDING;
        let bump = |x: f64| Some(1.0 - (x - 0.3125).abs());
        let [x, y] = highest_shoulder([0.0, 1.0], 2.0, bump).expect("a top");
        assert!((x - 0.3125).abs() < tol && (y - 1.0).abs() < tol, "{x} {y}");
        // mirrored (a left shoulder: the neck's side right of the arm's)
        let bump_l = |x: f64| Some(1.0 - (x + 0.3125).abs());
        let [x, _] = highest_shoulder([0.0, -1.0], 2.0, bump_l).expect("a top");
        assert!((x + 0.3125).abs() < tol, "{x}");
        let [x, _] = highest_shoulder([0.0, 1.0], 2.0, |_| Some(1.0)).expect("a top");
        assert!((x - 0.5).abs() < tol, "a flat shoulder: {x}");
        // every top off halfway (0.8125) above the ceiling (the lowest,
        // at 0.4792, is 0.8333): halfway is kept
        let [x, _] = highest_shoulder([0.0, 1.0], 0.82, bump).expect("a top");
        assert!((x - 0.5).abs() < tol, "above the ceiling: {x}");
        assert_eq!(highest_shoulder([0.0, 1.0], 2.0, |_| None), None);
    }
}
