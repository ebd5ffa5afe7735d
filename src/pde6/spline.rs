//! A stable C2 chain: the conditions of method 2 solved globally as a
//! two-point problem (pdesculpt's construction, not the paper's).
//!
//! Method 2 (eqs 24-27) propagates the slope and curvature patch by patch.
//! Per harmonic that is a linear recursion $(A', A'')_{j+1} = T (A', A'')_j +
//! b_j$ whose matrix has eigenvalues $\lambda, 1/\lambda$; for the quintic
//! $\lambda = -(13 + \sqrt{165})/2 \approx -12.92$ (`verify/pde6_closed_form.py`,
//! check `pde6.method2_amplification`): every patch multiplies the growing
//! mode by ~13, so a chain of more than two or three patches through real
//! data oscillates wildly (the cubic-spline recursion has the same structure
//! with $2 + \sqrt3$). As for cubic splines the cure is to impose one
//! condition at each end and solve all patches together:
//!
//! * $M = 3P + 1$ sections, piece $p$ through sections $3p, \dots, 3p+3$;
//! * C1 and C2 (in the global u) at the $P - 1$ interior joins;
//! * at each end the u-curvature of the six-point (method 1) patch through the
//!   six end sections (or another end condition, [`EndCurvature`]: zero
//!   curvature, or the u-slope of the chord to the neighbouring section).
//!
//! That is $4P + 2(P-1) + 2 = 6P$ conditions for $6P$ coefficients per
//! harmonic; the matrix is the same for every coefficient of a harmonic, so it
//! is factorised once per harmonic.

use super::chain::{validate_sections, Method, Piece, Section};
use super::mode::{Condition, ModeBasis};
use super::patch::{HarmonicCoef, Patch};
use super::{Chain, Pde6Error};
use crate::curve::Fourier3;
use nalgebra::{DMatrix, DVector};

/// Largest 1-norm condition number accepted for the global system.
pub const MAX_GLOBAL_CONDITION: f64 = 1e12;

/// The condition a chain's end is given (the one condition at each end
/// of the global system).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EndCurvature {
    /// The curvature of the six-point (method 1) patch through the six end
    /// sections: a chain through smooth data keeps its shape to the end.
    #[default]
    SixPoint,
    /// None (a natural spline's end): the end section's own curvature is
    /// zero, so the end tangent follows the last sections' slope. The
    /// six-point curvature is a quintic's through six sections; where their
    /// spacing or radii wiggle near the end (a torso's lowest sections,
    /// whose depth the thighs widen in a side view), it overshoots, and the
    /// end tangent of the MakeHuman girl's torso leaned 57 degrees forward
    /// where its last two sections slope 12 (docs/drawing-corpus.md,
    /// eighteenth measurement).
    Natural,
    /// [`EndCurvature::SixPoint`], unless the chain's end tangent then turns
    /// from the chord to the neighbouring section by more than
    /// [`END_TURN_GUARD_DEG`] somewhere on the ring: then
    /// [`EndCurvature::Chord`]. (Until the nineteenth measurement of
    /// docs/drawing-corpus.md it fell back to [`EndCurvature::Natural`],
    /// whose end tangent still leaned: the MakeHuman girl's hips folded by
    /// 125 degrees, 117 with the chord.)
    Guarded,
    /// No curvature condition: the end's u-slope is the chord's to the
    /// neighbouring section (a clamped end: the global system's end row is
    /// the slope, not the curvature), so the chain leaves its end section
    /// along the sections' own slope there, whatever the sections beyond
    /// do.
    Chord,
}

/// The largest angle (degrees) between a chain's end tangent and the chord
/// from its end section to the neighbouring one, over the ring, that
/// [`EndCurvature::Guarded`] accepts from the six-point curvature. A chain
/// through sections `h` apart on a surface of curvature `k` turns from its
/// chord by about `k h / 2`: 30 degrees is a section spacing about as large
/// as the radius of curvature, where the sections no longer say how the
/// surface bends. Chosen so, not swept: the MakeHuman girl's torso start
/// turned 45 degrees (docs/drawing-corpus.md, eighteenth measurement).
pub const END_TURN_GUARD_DEG: f64 = 30.0;

/// Ring points the guard compares at.
const GUARD_SAMPLES: usize = 48;

/// The largest angle (degrees) over the ring between the chain's
/// u-derivative at section `i` (0 or the last) and the chord from it to
/// its neighbouring section (toward increasing u).
fn end_turn_deg(chain: &Chain, sections: &[Section], last: bool) -> f64 {
    use crate::mesh::{dot, norm, sub};
    let m = sections.len();
    let (i, j) = if last { (m - 2, m - 1) } else { (0, 1) };
    let at = sections[if last { j } else { i }].u;
    let d = chain.pieces[chain.piece_at(at)].global_section(at, 1);
    let mut worst = 0.0f64;
    for k in 0..GUARD_SAMPLES {
        let th = 2.0 * std::f64::consts::PI * k as f64 / GUARD_SAMPLES as f64;
        let chord = sub(sections[j].curve.eval(th), sections[i].curve.eval(th));
        let t = d.eval(th);
        let (lc, lt) = (norm(chord), norm(t));
        if lc > 0.0 && lt > 0.0 {
            worst = worst.max(
                (dot(chord, t) / (lc * lt))
                    .clamp(-1.0, 1.0)
                    .acos()
                    .to_degrees(),
            );
        }
    }
    worst
}

impl Chain {
    /// The globally solved C2 chain through `sections` (M = 3P + 1 >= 7),
    /// each end with the six-point curvature.
    pub fn c2_global(a: f64, sections: &[Section]) -> Result<Chain, Pde6Error> {
        Chain::c2_global_ends(a, sections, [EndCurvature::SixPoint; 2])
    }

    /// The globally solved C2 chain with the given end condition at its
    /// start and its end. A guarded end solves twice where the guard fires
    /// (the end rows differ, so the first solve's matrices are not reused).
    pub fn c2_global_ends(
        a: f64,
        sections: &[Section],
        end_curvature: [EndCurvature; 2],
    ) -> Result<Chain, Pde6Error> {
        if end_curvature.contains(&EndCurvature::Guarded) {
            let six = |e: EndCurvature| match e {
                EndCurvature::Guarded => EndCurvature::SixPoint,
                e => e,
            };
            let first = Chain::c2_global_ends(a, sections, end_curvature.map(six))?;
            let guard = |k: usize| match end_curvature[k] {
                EndCurvature::Guarded
                    if end_turn_deg(&first, sections, k == 1) > END_TURN_GUARD_DEG =>
                {
                    EndCurvature::Chord
                }
                e => six(e),
            };
            let ends = [guard(0), guard(1)];
            if ends == end_curvature.map(six) {
                return Ok(first);
            }
            return Chain::c2_global_ends(a, sections, ends);
        }
        validate_sections(sections, 7, 1)?;
        let m = sections.len();
        let p_count = (m - 1) / 3;
        let big_n = sections[0].curve.harmonics();
        let ends = end_values(a, sections, end_curvature)?;
        let slope_ends = end_curvature.map(|e| e == EndCurvature::Chord);
        let geo: Vec<(f64, f64, [f64; 4])> = (0..p_count)
            .map(|p| {
                let w = &sections[3 * p..3 * p + 4];
                let (o, l) = (w[0].u, w[3].u - w[0].u);
                (o, l, [0.0, (w[1].u - o) / l, (w[2].u - o) / l, 1.0])
            })
            .collect();
        let mut coefs: Vec<Vec<HarmonicCoef>> = vec![Vec::with_capacity(big_n + 1); p_count];
        let mut bases = Vec::with_capacity(big_n + 1);
        let mut worst_condition: f64 = 0.0;
        for n in 0..=big_n {
            let b = ModeBasis::new(a, n);
            let mat = global_matrix(&b, &geo, slope_ends);
            let lu = mat.clone().full_piv_lu();
            let inv = lu.try_inverse().ok_or(Pde6Error::Singular { q: b.q })?;
            let condition = norm1(&mat) * norm1(&inv);
            if !condition.is_finite() || condition > MAX_GLOBAL_CONDITION {
                return Err(Pde6Error::IllConditioned { q: b.q, condition });
            }
            worst_condition = worst_condition.max(condition);
            let hc = harmonic_coefs(n, sections, &ends, &mat, &inv);
            for (p, hp) in hc.into_iter().enumerate() {
                coefs[p].push(hp);
            }
            bases.push(b);
        }
        let pieces = coefs
            .into_iter()
            .zip(&geo)
            .map(|(coef, &(o, l, _))| Piece {
                patch: Patch {
                    a,
                    basis: bases.clone(),
                    coef,
                    max_condition: worst_condition,
                },
                origin: o,
                length: l,
                start: o,
                end: o + l,
            })
            .collect();
        Ok(Chain {
            method: Method::GlobalC2,
            pieces,
        })
    }
}

/// The right-hand sides of the global system's two end rows (global u):
/// the six-point patches' end curvatures, zero (the zero curve of the
/// sections' harmonics), or the chord's slope to the neighbouring section.
fn end_values(
    a: f64,
    sections: &[Section],
    end_curvature: [EndCurvature; 2],
) -> Result<[Fourier3; 2], Pde6Error> {
    let m = sections.len();
    let zero = || Fourier3::weighted_sum(&[(0.0, &sections[0].curve)]);
    // the chord's slope from section i to section j
    let chord = |i: usize, j: usize| {
        let du = sections[j].u - sections[i].u;
        Fourier3::weighted_sum(&[
            (1.0 / du, &sections[j].curve),
            (-1.0 / du, &sections[i].curve),
        ])
    };
    let k_start = match end_curvature[0] {
        EndCurvature::SixPoint | EndCurvature::Guarded => {
            Chain::method1_window(a, &sections[..6])?.global_section(sections[0].u, 2)
        }
        EndCurvature::Natural => zero(),
        EndCurvature::Chord => chord(0, 1),
    };
    let k_end = match end_curvature[1] {
        EndCurvature::SixPoint | EndCurvature::Guarded => {
            Chain::method1_window(a, &sections[m - 6..])?.global_section(sections[m - 1].u, 2)
        }
        EndCurvature::Natural => zero(),
        EndCurvature::Chord => chord(m - 2, m - 1),
    };
    Ok([k_start, k_end])
}

/// A piece's origin, length and its four sections' local parameters.
type Geo = (f64, f64, [f64; 4]);

/// The global system's matrix for mode basis `b`: the value at each
/// piece's four sections, C1 and C2 at the interior joins, at each end the
/// curvature, or the slope where `slope_ends` says so (a chord end).
fn global_matrix(b: &ModeBasis, geo: &[Geo], slope_ends: [bool; 2]) -> DMatrix<f64> {
    let p_count = geo.len();
    let size = 6 * p_count;
    let row = |c: Condition| -> [f64; 6] {
        let (u, d) = match c {
            Condition::Value(u) => (u, 0),
            Condition::Slope(u) => (u, 1),
            Condition::Curvature(u) => (u, 2),
        };
        b.jet2(u)[d]
    };
    let mut mat = DMatrix::<f64>::zeros(size, size);
    let mut r = 0;
    for (p, (_, _, nodes)) in geo.iter().enumerate() {
        for &x in nodes {
            mat.view_mut((r, 6 * p), (1, 6))
                .copy_from_slice(&row(Condition::Value(x)));
            r += 1;
        }
    }
    for p in 0..p_count - 1 {
        let (l0, l1) = (geo[p].1, geo[p + 1].1);
        for d in 1..=2 {
            let (ca, cb) = if d == 1 {
                (Condition::Slope(1.0), Condition::Slope(0.0))
            } else {
                (Condition::Curvature(1.0), Condition::Curvature(0.0))
            };
            let (ra, rb) = (row(ca), row(cb));
            for j in 0..6 {
                mat[(r, 6 * p + j)] = ra[j] / l0.powi(d);
                mat[(r, 6 * (p + 1) + j)] = -rb[j] / l1.powi(d);
            }
            r += 1;
        }
    }
    // the end rows: the u-curvature, or the u-slope at a chord end (the
    // local derivative of order d over the piece's length to the d)
    let end_row = |slope: bool, x: f64, l: f64| -> [f64; 6] {
        let (c, d) = if slope {
            (Condition::Slope(x), 1)
        } else {
            (Condition::Curvature(x), 2)
        };
        row(c).map(|v| v / l.powi(d))
    };
    let rs = end_row(slope_ends[0], 0.0, geo[0].1);
    let re = end_row(slope_ends[1], 1.0, geo[p_count - 1].1);
    for j in 0..6 {
        mat[(r, j)] = rs[j];
        mat[(r + 1, 6 * (p_count - 1) + j)] = re[j];
    }
    mat
}

/// Every piece's coefficients of harmonic `n` (each coordinate, cosine and
/// sine): the system `mat` (inverse `inv`) solved for the sections' and the
/// end curvatures' (`ends`) coefficients, with one step of refinement.
fn harmonic_coefs(
    n: usize,
    sections: &[Section],
    ends: &[Fourier3; 2],
    mat: &DMatrix<f64>,
    inv: &DMatrix<f64>,
) -> Vec<HarmonicCoef> {
    let size = mat.nrows();
    let p_count = size / 6;
    let [k_start, k_end] = ends;
    let mut hc: Vec<HarmonicCoef> = vec![[[[0.0; 6]; 2]; 3]; p_count];
    for k in 0..3 {
        for cs in 0..2 {
            if n == 0 && cs == 1 {
                continue;
            }
            let pick = |f: &Fourier3| -> f64 {
                let (x, y) = f.harmonic(n, k);
                if cs == 0 {
                    x
                } else {
                    y
                }
            };
            let mut rhs = DVector::<f64>::zeros(size);
            let mut r = 0;
            for p in 0..p_count {
                for i in 0..4 {
                    rhs[r] = pick(&sections[3 * p + i].curve);
                    r += 1;
                }
            }
            r += 2 * (p_count - 1);
            rhs[r] = pick(k_start);
            rhs[r + 1] = pick(k_end);
            let mut x = inv * &rhs;
            let res = &rhs - mat * &x;
            x += inv * res;
            for (p, hp) in hc.iter_mut().enumerate() {
                for j in 0..6 {
                    hp[k][cs][j] = x[6 * p + j];
                }
            }
        }
    }
    hc
}

fn norm1(m: &DMatrix<f64>) -> f64 {
    m.column_iter()
        .map(|c| c.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}
