//! The fitted body's outlines the side passes read: the arms of a human
//! template found on its front outline ([`arm_mask`]) and the side outline
//! of the whole skin and of the trunk alone ([`side_outlines`]).

use super::options::{FitOptions, Template};
use super::{OutlineFn, TemplateError, View};

/// Fraction of the height below the hands' (crotch's) landmark still
/// counted as arm.
pub const ARM_MARGIN: f64 = 0.05;

/// The arms of a human template at `positions`: vertices below the higher
/// armpit, above the hands and the crotch (less [`ARM_MARGIN`]) and
/// outside the armpits' x range, the armpits found on the fitted
/// front outline; `None` unless the front scheme is [`super::Scheme::Human`]
/// and its landmarks are found.
pub fn arm_mask(
    template: &Template,
    positions: &[[f64; 3]],
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Option<Vec<bool>> {
    if opts.front_scheme != super::Scheme::Human {
        return None;
    }
    let f = outline(&template.skin_at(positions), View::Front).ok()?;
    let f = super::polygon::validated("the fitted front outline", &f).ok()?;
    let marks = super::landmarks::find(&f, super::Scheme::Human, "fitted front outline").ok()?;
    let (l, r) = (f[marks[2]], f[marks[6]]);
    let (x0, x1, top) = (l[0].min(r[0]), l[0].max(r[0]), l[1].max(r[1]));
    // not the feet: arms end above the lower of the hands' and the
    // crotch's heights, less a margin for the hand below its extreme point
    let (lo, hi) = super::polygon::bbox(&f);
    let bottom =
        f[marks[1]][1].min(f[marks[7]][1]).min(f[marks[4]][1]) - ARM_MARGIN * (hi[1] - lo[1]);
    Some(
        positions
            .iter()
            .map(|p| p[1] < top && p[1] > bottom && (p[0] < x0 || p[0] > x1))
            .collect(),
    )
}

/// The fitted skin's side outline and, when `trunk` asks for it and the
/// arms are found ([`arm_mask`]), the arm mask (by template vertex) with
/// the trunk's outline (the skin without the triangles touching an arm
/// vertex) if that is a simple closed polygon.
pub type SideOutlines = (Vec<[f64; 2]>, Option<(Vec<bool>, Vec<[f64; 2]>)>);

/// See [`SideOutlines`]; errors when the whole outline is not simple. The
/// arms are found on the template at rest (its front outline shows them
/// apart from the trunk; on a fitted fat body the belly's sides reach past
/// the armpits and were taken for arm), the outlines on `positions`.
pub fn side_outlines(
    template: &Template,
    positions: &[[f64; 3]],
    trunk: bool,
    opts: &FitOptions,
    outline: &OutlineFn,
) -> Result<SideOutlines, TemplateError> {
    let skin = template.skin_at(positions);
    let o = outline(&skin, View::Side)?;
    let o = super::polygon::validated("the fitted side outline", &o).map_err(|e| {
        TemplateError::NoOutline {
            view: "side".into(),
            problem: e.to_string(),
        }
    })?;
    let arms = trunk
        .then(|| arm_mask(template, &template.mesh.positions, opts, outline))
        .flatten();
    let split = arms.and_then(|mask| {
        let keep: Vec<bool> = skin
            .triangles
            .iter()
            .map(|t| {
                t.iter()
                    .all(|&i| !mask[template.skin_index[i as usize] as usize])
            })
            .collect();
        let (tm, _) = skin.filter_triangles(&keep);
        let t = outline(&tm, View::Side).ok()?;
        let t = super::polygon::validated("the trunk's side outline", &t).ok()?;
        Some((mask, t))
    });
    Ok((o, split))
}
