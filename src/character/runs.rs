//! The runs of a child's loop around its parent's end ring: arcs of the
//! ring and the seams beside the child (`character::transition`).

use super::ring::{cut_indices, RING_VERTICES, SEAM_VERTICES};

/// A run of a child's loop.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Run {
    /// Parent ring from index `from` for `count` steps (increasing phi).
    Arc { from: usize, count: usize },
    /// Seam j traversed front to back (`reversed = false`) or back to front.
    Seam { j: usize, reversed: bool },
}

/// The runs of child `c` (0-based) of `k`.
pub fn loop_runs(c: usize, k: usize, cuts: &[(usize, usize)]) -> Vec<Run> {
    let n = RING_VERTICES;
    let cut_indices = |j: usize, k: usize| cut_indices(j, k, cuts);
    let steps = |a: usize, b: usize| (b + n - a) % n;
    if k == 1 {
        return vec![Run::Arc { from: 0, count: n }];
    }
    let j = c + 1; // seam to the right of child c is seam j (1-based), left is j - 1
    if c == 0 {
        let (f, b) = cut_indices(1, k);
        vec![
            Run::Arc {
                from: f,
                count: steps(f, b),
            },
            Run::Seam {
                j: 0,
                reversed: true,
            },
        ]
    } else if c + 1 == k {
        let (f, b) = cut_indices(k - 1, k);
        vec![
            Run::Arc {
                from: b,
                count: steps(b, f),
            },
            Run::Seam {
                j: k - 2,
                reversed: false,
            },
        ]
    } else {
        let (fl, bl) = cut_indices(j - 1, k);
        let (fr, br) = cut_indices(j, k);
        vec![
            Run::Arc {
                from: fr,
                count: steps(fr, fl),
            },
            Run::Seam {
                j: j - 2,
                reversed: false,
            },
            Run::Arc {
                from: bl,
                count: steps(bl, br),
            },
            Run::Seam {
                j: j - 1,
                reversed: true,
            },
        ]
    }
}

/// Number of loop vertices (each run contributes its steps).
pub fn loop_len(runs: &[Run]) -> usize {
    runs.iter()
        .map(|r| match r {
            Run::Arc { count, .. } => *count,
            Run::Seam { .. } => SEAM_VERTICES + 1,
        })
        .sum()
}
