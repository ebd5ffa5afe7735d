//! Each child's cross-tangent factor of a sketched transition, fitted to
//! the drawing (issue 28 item 4: "transition tangents scaled to the gap
//! they bridge").
//!
//! A transition's Hermite blend leaves its parent's end ring along the
//! parent's own tangent and enters the child's ring along the child's,
//! each scaled by the gap between the two rings times the child's factor
//! (`TransitionSpec::child_scale`). One factor per kind of child (the
//! arms', the head's) cannot suit every drawing: a tangent too long
//! carries the blend out past the drawn outline, one too short cuts the
//! corner inside it (the corpus's cartoon, its shoulders 1.7 % of the
//! height off the drawn front).
//!
//! So, after the parts are solved (`pipeline::build`, when it derives a
//! document from its drawings), each child of every derived transition
//! is planned once and tries its derived factor times each of
//! [`FIT_FACTORS`] (`character::assembly::transition_points` scales the
//! planned child's tangents), and keeps the one whose transition
//! points (the mesh's own rows and loop vertices) miss the drawing least,
//! summed over the front and side views. A view's miss is the larger of
//! - the largest distance of a projected point outside the drawn outline,
//! - the largest distance from a drawn-outline sample, within the height
//!   range the points span, to the nearest projected point of the model
//!   (this child's points or any other surface's, sampled as the mesh
//!   is): where the drawing reaches farther than the model.
//!
//! The fit never makes a crease it can avoid, nor a fold: each
//! candidate's grid is triangulated as the mesh is and its largest turn
//! between adjacent triangles measured ([`grid_turn`]); when a factor
//! turns by no more than a crease ([`CREASED_EDGE_DEG`]), only such
//! factors are taken, else when one turns by no more than a fold
//! ([`FOLD_DEG`]) only those turning no more than a fold and the derived
//! one, else only those turning no more than the derived one
//! ([`turn_limit`], [`Guard::NoCrease`]). (Until 2026-11-30 the turn was measured between
//! quads' normals, blind to a quad folded along its diagonal, and any
//! factor turning no more than the derived one's was taken: on the
//! corpus's big-headed figures the fit chose a longer arm tangent whose
//! corner quad folded by 154 degrees, docs/drawing-corpus.md,
//! twenty-fourth measurement.) Misses within [`FIT_TIE`]
//! of the least keep the factor nearest 1 (the derived blend). The
//! factors are written into the document (`child_tangent_scales`), so a
//! saved document rebuilds the same; documents read back are not fitted
//! again.
//!
//! With a side view each child then tries, at its fitted factor, a late
//! depth blend (`character::rise`: the column rises along its parent
//! before it turns in depth toward the child) starting at each of
//! [`FIT_RISES`], first on its loop's -z side, then on its +z side, and
//! keeps them by the same rules (`child_rises`). A drawn side view with
//! square shoulders, which the plain blend cut by up to 3.75 % of the
//! height on the corpus, is followed within issue 28's 2 % on most of its
//! humanoids (docs/drawing-corpus.md, twenty-second measurement).

use crate::character::assembly::{transition_points, BlendTry, Resolution};
use crate::character::part::PartSurface;
use crate::character::spec::TransitionSpec;
use crate::character::ModelError;
use crate::profile::{Profile, ProfileIndex, View};
use crate::sketch::quality::{CREASED_EDGE_DEG, FOLD_DEG};
use crate::sketch::vertex_grid::VertexGrid;

mod apexes;
mod rises;
pub use apexes::fit_transitions;

/// One candidate's points: those of each child it blends, in order.
type Sets = Vec<Vec<[f64; 3]>>;
pub use rises::{CONTINUES_COS, FIT_RISES};

/// The factors tried on each child's derived tangent factor, nearest 1
/// first (ties keep the derived blend): 0.4 to 1.3 in steps of 0.15, a
/// range chosen around the derived blend, not fitted to the corpus (no
/// other range was tried). Shorter tangents turn the corner between the
/// rings in fewer of the mesh's rows; a turn sharper than the derived
/// blend's is refused anyway ([`fit_child_scales`]).
pub const FIT_FACTORS: [f64; 7] = [1.0, 0.85, 1.15, 0.7, 1.3, 0.55, 0.4];
/// Misses (relative to the height) closer than this count as equal: a
/// tenth of issue 28's outside bound (1 %), about the spacing of the
/// transition's rows on a small child.
pub const FIT_TIE: f64 = 1e-3;
/// Drawn-outline samples per view: about 0.3 % of the height apart on a
/// figure's outline (4 to 6 heights long), half as dense as the report's
/// (`sketch::quality`, 4,000): the fit compares factors, the report
/// measures the model.
const OUTLINE_SAMPLES: usize = 2000;
/// Model points this far (relative to the height) above or below the
/// candidates' height range are left out of the nearest-point grid: a
/// sample nearest to one of them misses by more than every bound, and is
/// reported that far off.
const NEAR_BAND: f64 = 0.05;

/// One drawn view: its outline, distance index and samples.
struct Drawn<'a> {
    view: View,
    profile: &'a Profile,
    index: ProfileIndex,
    samples: Vec<[f64; 2]>,
}

impl Drawn<'_> {
    /// How far a child's transition points `pts` miss this outline: the
    /// largest distance of a point outside it, and of a drawn sample in
    /// the points' height range from the nearest projected point of the
    /// model (`others`: the rest of it, as distances per sample).
    fn miss(&self, pts: &[[f64; 3]], others: &[f64]) -> f64 {
        let proj: Vec<[f64; 2]> = pts.iter().map(|p| self.view.project(*p)).collect();
        let mut worst = 0.0f64;
        for q in &proj {
            if !self.profile.contains(*q) {
                worst = worst.max(self.index.distance(*q));
            }
        }
        let (lo, hi) = proj
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), q| (a.min(q[1]), b.max(q[1])));
        let grid = VertexGrid::new(proj);
        for (d, &o) in self.samples.iter().zip(others) {
            if d[1] >= lo && d[1] <= hi && o > worst {
                worst = worst.max(grid.distance_within(*d, worst, o));
            }
        }
        worst
    }
}

/// The largest turn (degrees) between neighbouring triangles of a
/// transition's grid (`rows + 1` rows of periodic columns, as
/// [`transition_points`] gives them), triangulated as the mesh is
/// (`character::assembly::weave`: each quad `a_i a_j b_j b_i` split along
/// its `a_i b_j` diagonal), so a quad folded along that diagonal counts;
/// measured as the report measures a group's creases
/// (`character::crease::creases`).
fn grid_turn(pts: &[[f64; 3]], rows: usize) -> f64 {
    let n = pts.len() / (rows + 1);
    if n < 3 {
        return 0.0;
    }
    let id = |r: usize, i: usize| (r * n + i % n) as u32;
    let mut triangles = Vec::with_capacity(2 * rows * n);
    for r in 0..rows {
        for i in 0..n {
            let (a_i, a_j, b_i, b_j) = (id(r, i), id(r, i + 1), id(r + 1, i), id(r + 1, i + 1));
            triangles.push([a_i, a_j, b_j]);
            triangles.push([a_i, b_j, b_i]);
        }
    }
    let mesh = crate::mesh::Mesh::new(pts[..n * (rows + 1)].to_vec(), triangles);
    crate::character::crease::creases(&mesh)
        .first()
        .map_or(0.0, |c| c.interior_deg)
}

/// What a fit may not make.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Guard {
    /// The tangent factors: a crease ([`CREASED_EDGE_DEG`]) when some
    /// candidate avoids one, else a fold ([`FOLD_DEG`]) or a turn beyond
    /// the derived blend's when some candidate avoids a fold, else a turn
    /// beyond the derived blend's. (Where every candidate folds, as on the
    /// bundled quadruped's legs, the least turning one is no better a
    /// surface: taking it there moved the animal's front miss from 0.85 %
    /// to 1.57 % of the height.)
    NoCrease,
    /// The late depth blends, whose square corner a side view draws: a
    /// turn beyond the plain blend's or a fold, whichever is more.
    NoFold,
}

/// The largest turn (degrees) a candidate may make, given every
/// candidate's `turns` (the derived or plain blend's first) and the
/// fit's `guard`; never less than the least turn, so one candidate
/// always remains.
fn turn_limit(turns: &[f64], guard: Guard) -> f64 {
    let least = turns.iter().copied().fold(f64::INFINITY, f64::min);
    let derived = turns.first().copied().unwrap_or(least);
    let limit = match guard {
        Guard::NoCrease if least <= CREASED_EDGE_DEG => CREASED_EDGE_DEG,
        Guard::NoCrease if least <= FOLD_DEG => derived.min(FOLD_DEG),
        Guard::NoCrease => derived,
        Guard::NoFold => derived.max(FOLD_DEG),
    };
    limit.max(least)
}

/// Per view, each drawn sample's distance to the nearest projected point of
/// the model but child `me`'s transition, at most `height` (`height` for
/// samples outside the height range the candidates `tried` span: not
/// used).
fn others_in_range(
    drawn: &[Drawn],
    all: &[(String, Vec<[f64; 3]>)],
    me: &[&str],
    tried: &[Sets],
    height: f64,
) -> Vec<Vec<f64>> {
    drawn
        .iter()
        .map(|d| {
            let (lo, hi) = tried
                .iter()
                .flatten()
                .flat_map(|pts| pts.iter().map(|p| d.view.project(*p)[1]))
                .fold((f64::MAX, f64::MIN), |(a, b), y| (a.min(y), b.max(y)));
            let band = NEAR_BAND * height;
            let g = VertexGrid::new(
                all.iter()
                    .filter(|(n, _)| !me.contains(&n.as_str()))
                    .flat_map(|(_, pts)| pts.iter().map(|p| d.view.project(*p)))
                    .filter(|q| q[1] >= lo - band && q[1] <= hi + band)
                    .collect(),
            );
            d.samples
                .iter()
                .map(|q| {
                    if q[1] >= lo && q[1] <= hi {
                        g.distance_within(*q, 0.0, height)
                    } else {
                        height
                    }
                })
                .collect()
        })
        .collect()
}

/// Every solved part's sample points by name, as the mesh samples it
/// (`res.rings_per_height` rings per model height `height`).
fn part_sets(parts: &[PartSurface], height: f64, res: &Resolution) -> Vec<(String, Vec<[f64; 3]>)> {
    parts
        .iter()
        .map(|p| {
            let len = (p.u1 - p.u0).abs();
            let rings = ((res.rings_per_height * len / height).ceil() as usize).max(2);
            (p.name.clone(), part_points(p, rings))
        })
        .collect()
}

/// Sample points of a solved part's surface.
fn part_points(p: &PartSurface, rings: usize) -> Vec<[f64; 3]> {
    let n = crate::character::ring::RING_VERTICES;
    let mut out = Vec::with_capacity((rings + 1) * n);
    for r in 0..=rings {
        let u = p.u0 + (p.u1 - p.u0) * r as f64 / rings as f64;
        let sec = p.section(u, 0);
        out.extend((0..n).map(|i| sec.eval(2.0 * std::f64::consts::PI * i as f64 / n as f64)));
    }
    out
}

/// Everything the fit measures against: the drawn views, every surface's
/// sample points (parts by name, transition children as `"t/c"`).
struct Scene<'a> {
    drawn: Vec<Drawn<'a>>,
    all: Vec<(String, Vec<[f64; 3]>)>,
    rows: usize,
    height: f64,
}

impl Scene<'_> {
    /// Which of the candidate point sets `tried` (in order of preference,
    /// the derived blend first; each the points of every child named in
    /// `me`, in that order) is kept (module docs), by index; the scene's
    /// points of those children move to it. The miss is measured on all
    /// of a candidate's points, the grid's turn on each child's own;
    /// `guard`: what it may not make ([`turn_limit`]).
    fn fit_members(&mut self, me: &[&str], tried: Vec<Sets>, guard: Guard) -> usize {
        let others = others_in_range(&self.drawn, &self.all, me, &tried, self.height);
        let rows = self.rows;
        let mut scored: Vec<(usize, f64, f64, Sets)> = tried
            .into_iter()
            .enumerate()
            .map(|(f, sets)| {
                let pts: Vec<[f64; 3]> = sets.iter().flatten().copied().collect();
                let miss = self
                    .drawn
                    .iter()
                    .zip(&others)
                    .map(|(d, o)| d.miss(&pts, o))
                    .sum::<f64>()
                    / self.height;
                let turn = sets.iter().map(|p| grid_turn(p, rows)).fold(0.0, f64::max);
                (f, miss, turn, sets)
            })
            .collect();
        let turns: Vec<f64> = scored.iter().map(|x| x.2).collect();
        let limit = turn_limit(&turns, guard);
        scored.retain(|x| x.2 <= limit);
        let least = scored.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
        let Some(pick) = scored.into_iter().find(|x| x.1 <= least + FIT_TIE) else {
            return 0;
        };
        for (name, pts) in me.iter().zip(pick.3) {
            if let Some(slot) = self.all.iter_mut().find(|(n, _)| n == name) {
                slot.1 = pts;
            }
        }
        pick.0
    }
}

/// The drawn views the fit measures against (the side when there is one).
fn drawn_views<'a>(front: &'a Profile, side: Option<&'a Profile>) -> Vec<Drawn<'a>> {
    [(View::Front, Some(front)), (View::Side, side)]
        .into_iter()
        .filter_map(|(view, p)| {
            p.map(|profile| Drawn {
                view,
                profile,
                index: ProfileIndex::new(profile),
                samples: profile.resample_arclength(OUTLINE_SAMPLES),
            })
        })
        .filter(|d| !d.samples.is_empty())
        .collect()
}

/// Fits the child factors of every transition (module docs). `parts`:
/// the solved parts the transitions join; `front`, `side`: the placed
/// drawn outlines; `height`: the model height.
pub fn fit_child_scales(
    transitions: &mut [TransitionSpec],
    parts: &[PartSurface],
    front: &Profile,
    side: Option<&Profile>,
    height: f64,
) -> Result<(), ModelError> {
    let res = Resolution::default();
    let rows = res.transition_rows;
    let drawn = drawn_views(front, side);
    // each child planned once, its points at every factor; the scene holds
    // every part's points as the mesh samples it and each child's at its
    // derived factor (the first)
    let mut candidates = Vec::new();
    for t in transitions.iter() {
        for c in 0..t.children.len() {
            let tries: Vec<BlendTry> = FIT_FACTORS
                .iter()
                .map(|&factor| BlendTry {
                    factor,
                    rise: [0.0; 2],
                })
                .collect();
            candidates.push(transition_points(t, parts, c, rows, &tries)?);
        }
    }
    let mut all = part_sets(parts, height, &res);
    let names: Vec<String> = transitions
        .iter()
        .enumerate()
        .flat_map(|(ti, t)| (0..t.children.len()).map(move |c| format!("{ti}/{c}")))
        .collect();
    all.extend(
        names
            .iter()
            .zip(&candidates)
            .map(|(n, pts)| (n.clone(), pts[0].clone())),
    );
    let mut scene = Scene {
        drawn,
        all,
        rows,
        height,
    };
    let mut candidates = candidates.into_iter();
    let mut names = names.iter();
    let has_side = scene.drawn.iter().any(|d| d.view == View::Side);
    for t in transitions.iter_mut() {
        let k = t.children.len();
        let base: Vec<f64> = (0..k).map(|c| t.child_scale(c)).collect();
        let mut fitted = Vec::with_capacity(k);
        let mut factors = Vec::with_capacity(k);
        let mut mine = Vec::with_capacity(k);
        for b in &base {
            let (Some(me), Some(tried)) = (names.next(), candidates.next()) else {
                return Ok(());
            };
            let tried = tried.into_iter().map(|p| vec![p]).collect();
            let factor = FIT_FACTORS[scene.fit_members(&[me.as_str()], tried, Guard::NoCrease)];
            fitted.push(b * factor);
            factors.push(factor);
            mine.push(me.as_str());
        }
        let mut rises = vec![[0.0; 2]; k];
        if has_side {
            for c in 0..k.div_ceil(2) {
                let r = scene.fit_rises(t, parts, c, &mine, &factors)?;
                rises[c] = r;
                rises[k - 1 - c] = r;
            }
        }
        t.child_tangent_scales = if fitted.iter().all(|&s| s == t.tangent_scale) {
            Vec::new()
        } else {
            fitted
        };
        t.child_rises = if rises.iter().flatten().all(|&r| r == 0.0) {
            Vec::new()
        } else {
            rises
        };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(rows: usize, n: usize, fold_at: Option<usize>) -> Vec<[f64; 3]> {
        let mut out = Vec::new();
        for r in 0..=rows {
            for i in 0..n {
                let a = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
                // a cylinder; a fold turns one row back on itself
                let z = match fold_at {
                    Some(f) if r > f => (2 * f) as f64 - r as f64,
                    _ => r as f64,
                } * 0.1;
                out.push([a.cos(), a.sin(), z]);
            }
        }
        out
    }

    /// A 48-gon cylinder's neighbouring quads turn by 360 / 48 = 7.5
    /// degrees; a row turned back on itself turns by 180.
    const CYLINDER_TURN_MAX: f64 = 7.5 + 1e-9;
    const FOLD_TURN_MIN: f64 = 180.0 - 1e-6;

    #[test]
    fn grid_turn_sees_a_fold_and_not_a_cylinder() {
        let smooth = grid_turn(&grid(10, 48, None), 10);
        assert!(
            smooth <= CYLINDER_TURN_MAX,
            "a 48-gon cylinder turns by {smooth} degrees"
        );
        let folded = grid_turn(&grid(10, 48, Some(5)), 10);
        assert!(
            folded >= FOLD_TURN_MIN,
            "a row turned back turns by {folded} degrees"
        );
    }

    /// A quad whose corner `b_j` is pulled back past `a_i` and above the
    /// surface closes like a book along its `a_i b_j` diagonal (the mesh's
    /// split): its two triangles turn by more than a fold (167.6 degrees,
    /// by hand). The measure before 2026-11-30 (the normals of
    /// neighbouring quads) missed such a fold inside one quad.
    #[test]
    fn grid_turn_sees_a_quad_folded_along_its_diagonal() {
        let (rows, n) = (4, 48);
        let mut pts = grid(rows, n, None);
        // row 1's vertex 1 (b_j of the quad at row 0, column 0): half a
        // column back, half a row up, a tenth of a column outward of a_i
        pts[n + 1] = [1.013, -0.065, 0.05];
        let turn = grid_turn(&pts, rows);
        assert!(
            turn > FOLD_DEG,
            "a quad folded along its diagonal turns by {turn} degrees"
        );
    }

    #[test]
    fn the_factors_avoid_a_crease_and_the_rises_a_fold_beyond_the_plain_blend() {
        // some candidate does not crease: only such are taken
        assert_eq!(
            turn_limit(&[142.0, 117.0, 38.0], Guard::NoCrease),
            CREASED_EDGE_DEG
        );
        // all crease, some do not fold: no more than the derived blend,
        // nor a fold
        assert_eq!(turn_limit(&[92.7, 87.1, 102.0], Guard::NoCrease), 92.7);
        assert_eq!(
            turn_limit(&[150.0, 117.0, 130.0], Guard::NoCrease),
            FOLD_DEG
        );
        // all fold: no more than the derived blend
        assert_eq!(turn_limit(&[170.0, 150.0, 175.0], Guard::NoCrease), 170.0);
        // rises: a crease is allowed, a fold only as far as the plain blend
        assert_eq!(turn_limit(&[40.0, 75.0, 130.0], Guard::NoFold), FOLD_DEG);
        assert_eq!(turn_limit(&[140.0, 75.0, 150.0], Guard::NoFold), 140.0);
        assert_eq!(turn_limit(&[], Guard::NoFold), f64::INFINITY);
    }
}
