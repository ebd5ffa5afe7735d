//! Chains of PDE6 patches through cross sections at increasing u
//! (paper 002 section 3.2, eqs 14-27, appendix B, Fig 4).
//!
//! * Method 2 ([`Chain::method2`], the C2 construction): a first patch through
//!   six sections, then neighbours in both directions, each through the
//!   shared section and three new ones with the u-slope and u-curvature of
//!   its neighbour carried over at the join (eqs 24-25). Sections at
//!   arbitrary increasing u: local parameters are $t = (u - u_s)/L$, and the
//!   carried derivatives are rescaled by $L_{new}/L_{old}$ and its square so
//!   that the chain is C2 in the global u.
//! * Method 1 ([`Chain::method1`], as printed): patches through windows of
//!   six sections overlapping by three, each used from its join outwards. The paper claims C2 at the joins;
//!   two different interpolants through the same three sections only share
//!   the position there, so the chain is C0 and the slope jumps (measured by
//!   `pde6.method1_c2_claim`, ERRATA).
//!
//! Both need $M = 6 + 3k$ sections.

use super::patch::{validate_curves, Patch};
use super::Pde6Error;
use crate::check::{Measure, Worst};
use crate::curve::Fourier3;
use crate::jet::{Jet, Real};
use crate::surface::{Domain, Joined, Surface};
use std::f64::consts::PI;

/// A cross section at a position u along the chain.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Section {
    pub u: f64,
    pub curve: Fourier3,
}

/// A patch used on the global range `[start, end]`, with local parameter
/// `t = (u - origin) / length`.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Piece {
    pub patch: Patch,
    pub origin: f64,
    pub length: f64,
    pub start: f64,
    pub end: f64,
}

/// How neighbouring patches were built.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Method {
    /// Shared sections (paper method 1): C0 at joins.
    SharedCurves,
    /// Carried-over derivatives (paper method 2): C2 at joins, unstable
    /// propagation (see [`super::spline`]).
    CarriedDerivatives,
    /// Method-2 conditions solved globally with end curvatures: C2, stable.
    GlobalC2,
}

/// A chain of patches, a surface on `[u_0, u_{M-1}] x [0, 2 pi)`.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Chain {
    pub method: Method,
    /// Pieces in increasing u.
    pub pieces: Vec<Piece>,
}

fn scaled(f: &Fourier3, s: f64) -> Fourier3 {
    let m = |v: &Vec<[f64; 3]>| v.iter().map(|c| c.map(|x| x * s)).collect();
    Fourier3 {
        c0: f.c0.map(|x| x * s),
        cos: m(&f.cos),
        sin: m(&f.sin),
    }
}

/// Checks finite increasing u, equal harmonics, and `M >= min`, `M = 3k + residue`.
pub(crate) fn validate_sections(
    sections: &[Section],
    min: usize,
    residue: usize,
) -> Result<(), Pde6Error> {
    for (i, s) in sections.iter().enumerate() {
        if !s.u.is_finite() {
            return Err(Pde6Error::NotFinite(format!("u position of section {i}")));
        }
        if i > 0 && s.u.partial_cmp(&sections[i - 1].u) != Some(std::cmp::Ordering::Greater) {
            return Err(Pde6Error::NonIncreasing {
                index: i,
                previous: sections[i - 1].u,
                next: s.u,
            });
        }
    }
    let curves: Vec<&Fourier3> = sections.iter().map(|s| &s.curve).collect();
    validate_curves(&curves)?;
    if sections.len() < min || sections.len() % 3 != residue {
        return Err(Pde6Error::ChainLength {
            got: sections.len(),
            rule: if residue == 0 { "6 + 3k" } else { "7 + 3k" },
        });
    }
    Ok(())
}

fn local<const K: usize>(sections: &[Section], origin: f64, length: f64) -> [f64; K] {
    std::array::from_fn(|i| {
        if i == 0 {
            0.0
        } else if i == K - 1 {
            1.0
        } else {
            (sections[i].u - origin) / length
        }
    })
}

impl Piece {
    fn new(patch: Patch, origin: f64, length: f64, start: f64, end: f64) -> Piece {
        Piece {
            patch,
            origin,
            length,
            start,
            end,
        }
    }

    /// The d-th global-u derivative (d <= 2) of the section at global `u`.
    pub fn global_section(&self, u: f64, d: usize) -> Fourier3 {
        let t = (u - self.origin) / self.length;
        scaled(&self.patch.section(t, d), self.length.powi(-(d as i32)))
    }

    /// Slope and curvature sections in the global u at global `u`.
    fn global_jet(&self, u: f64) -> (Fourier3, Fourier3) {
        let t = (u - self.origin) / self.length;
        (
            scaled(&self.patch.section(t, 1), 1.0 / self.length),
            scaled(&self.patch.section(t, 2), 1.0 / (self.length * self.length)),
        )
    }

    /// The point of this piece at global `u` (generic).
    pub fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        self.patch.eval((u - self.origin) / self.length, v)
    }
}

impl Chain {
    /// The six-point patch through exactly six sections, as a piece.
    pub fn method1_window(a: f64, w: &[Section]) -> Result<Piece, Pde6Error> {
        if w.len() != 6 {
            return Err(Pde6Error::ChainLength {
                got: w.len(),
                rule: "6",
            });
        }
        let (origin, length) = (w[0].u, w[5].u - w[0].u);
        let curves: [&Fourier3; 6] = std::array::from_fn(|i| &w[i].curve);
        let patch = Patch::through_curves(a, curves, local(w, origin, length))?;
        Ok(Piece::new(patch, origin, length, origin, w[5].u))
    }

    /// Method 1 as in Fig 4 (section 3.2.2): the centre patch through
    /// `sections[first..first + 6]` used whole; each neighbour is the
    /// six-point patch through the three sections it shares with the previous
    /// patch (the join and the two beyond it) and three new ones, used from
    /// the join outwards (paper: 12 sections, `first = 3`; patch 2 through
    /// C1-C6 used on C1-C4, patch 3 through C7-C12 used on C9-C12).
    pub fn method1(a: f64, sections: &[Section], first: usize) -> Result<Chain, Pde6Error> {
        validate_sections(sections, 6, 0)?;
        let m = sections.len();
        if first % 3 != 0 || m < 6 || first > m - 6 {
            return Err(Pde6Error::FirstPatch { first, sections: m });
        }
        let mut pieces = vec![Chain::method1_window(a, &sections[first..first + 6])?];
        let mut e = first + 5;
        while e + 3 < m {
            let mut p = Chain::method1_window(a, &sections[e - 2..e + 4])?;
            p.start = sections[e].u;
            pieces.push(p);
            e += 3;
        }
        let mut s = first;
        while s >= 3 {
            let mut p = Chain::method1_window(a, &sections[s - 3..s + 3])?;
            p.end = sections[s].u;
            pieces.insert(0, p);
            s -= 3;
        }
        Ok(Chain {
            method: Method::SharedCurves,
            pieces,
        })
    }

    /// Method 2: the first patch through `sections[first..first + 6]`
    /// (`first` a multiple of 3), neighbours of four sections each with
    /// the slope and curvature carried over (paper: the 12-curve example
    /// is `first = 3`).
    pub fn method2(a: f64, sections: &[Section], first: usize) -> Result<Chain, Pde6Error> {
        validate_sections(sections, 6, 0)?;
        let m = sections.len();
        if first % 3 != 0 || m < 6 || first > m - 6 {
            return Err(Pde6Error::FirstPatch { first, sections: m });
        }
        let w = &sections[first..first + 6];
        let (origin, length) = (w[0].u, w[5].u - w[0].u);
        let curves: [&Fourier3; 6] = std::array::from_fn(|i| &w[i].curve);
        let main = Patch::through_curves(a, curves, local(w, origin, length))?;
        let mut pieces = vec![Piece::new(main, origin, length, origin, w[5].u)];
        // forward
        let mut e = first + 5;
        while e + 3 < m {
            let w = &sections[e..e + 4];
            let prev = pieces.last().ok_or(Pde6Error::ChainLength {
                got: m,
                rule: "6 + 3k",
            })?;
            let (s1, s2) = prev.global_jet(w[0].u);
            let (origin, length) = (w[0].u, w[3].u - w[0].u);
            let patch = Patch::carried_over(
                a,
                std::array::from_fn(|i| &w[i].curve),
                local(w, origin, length),
                0.0,
                &scaled(&s1, length),
                &scaled(&s2, length * length),
            )?;
            pieces.push(Piece::new(patch, origin, length, origin, w[3].u));
            e += 3;
        }
        // backward
        let mut s = first;
        while s >= 3 {
            let w = &sections[s - 3..s + 1];
            let (s1, s2) = pieces[0].global_jet(w[3].u);
            let (origin, length) = (w[0].u, w[3].u - w[0].u);
            let patch = Patch::carried_over(
                a,
                std::array::from_fn(|i| &w[i].curve),
                local(w, origin, length),
                1.0,
                &scaled(&s1, length),
                &scaled(&s2, length * length),
            )?;
            pieces.insert(0, Piece::new(patch, origin, length, origin, w[3].u));
            s -= 3;
        }
        Ok(Chain {
            method: Method::CarriedDerivatives,
            pieces,
        })
    }

    /// Global u of the joins between pieces.
    pub fn joins(&self) -> Vec<f64> {
        self.pieces.iter().skip(1).map(|p| p.start).collect()
    }

    /// Index of the piece that owns global `u` (clamped to the ends).
    pub fn piece_at(&self, u: f64) -> usize {
        self.pieces.iter().rposition(|p| u >= p.start).unwrap_or(0)
    }

    /// Stored coefficients (data size).
    pub fn coefficient_count(&self) -> usize {
        self.pieces
            .iter()
            .map(|p| p.patch.coefficient_count())
            .sum()
    }

    /// Worst 1-norm condition number of any 6x6 solve in the chain.
    pub fn max_condition(&self) -> f64 {
        self.pieces.iter().map(|p| p.patch.max_condition).max_nan()
    }
}

impl Surface for Chain {
    fn eval<T: Real>(&self, u: T, v: T) -> [T; 3] {
        self.pieces[self.piece_at(u.value())].eval(u, v)
    }

    fn domain(&self) -> Domain {
        let (u0, u1) = match (self.pieces.first(), self.pieces.last()) {
            (Some(f), Some(l)) => (f.start, l.end),
            _ => (0.0, 1.0),
        };
        Domain {
            u: (u0, u1),
            v: (0.0, 2.0 * PI),
            closed_u: false,
            closed_v: true,
        }
    }

    fn grid(&self, us: &[f64], vs: &[f64]) -> Vec<[f64; 3]> {
        let mut out = Vec::with_capacity(us.len() * vs.len());
        let mut i = 0;
        while i < us.len() {
            let k = self.piece_at(us[i]);
            let mut j = i + 1;
            while j < us.len() && self.piece_at(us[j]) == k {
                j += 1;
            }
            let p = &self.pieces[k];
            let ts: Vec<f64> = us[i..j].iter().map(|u| (u - p.origin) / p.length).collect();
            out.extend(p.patch.grid_local(&ts, vs));
            i = j;
        }
        out
    }
}

/// Jumps of d^i S / du^i (i = 0, 1, 2) across every join of the chain, each
/// relative to max(|derivative|, 1), max over `samples` v samples:
/// `[c0, c1, c2]`.
impl Joined for Chain {
    type Jumps = [f64; 3];

    fn join_jumps(&self, samples: usize) -> [f64; 3] {
        let samples = samples.max(1);
        let mut worst = [0.0f64; 3];
        for w in self.pieces.windows(2) {
            let u = w[1].start;
            for j in 0..samples {
                let v = 2.0 * PI * j as f64 / samples as f64;
                let l = w[0].eval(Jet::<3, 1>::var_u(u), Jet::<3, 1>::constant(v));
                let r = w[1].eval(Jet::<3, 1>::var_u(u), Jet::<3, 1>::constant(v));
                for (d, wd) in worst.iter_mut().enumerate() {
                    for k in 0..3 {
                        let (x, y) = (l[k].deriv(d, 0), r[k].deriv(d, 0));
                        *wd = wd.worst((x - y).abs() / x.abs().worst(y.abs()).worst(1.0));
                    }
                }
            }
        }
        worst
    }
}
