//! The late depth blend on a whole transition column
//! (`character::transition::blend` with `Column::rise`): the column's
//! value and end derivatives are the plain blend's at both ends (so the
//! joins keep C1, or C2 with the quintic), only its depth (z) moves in
//! between, and it does move.

use pdesculpt::character::spec::Continuity;
use pdesculpt::character::transition::{blend, ChildTransition, Column};

/// Round-off on sums of six terms of order 1.
const EXACT: f64 = 1e-12;
/// The depth must move by more than this somewhere in between (the test's
/// column turns 0.7 in depth; a start of 0.6 holds it back by about half).
const MOVES: f64 = 0.05;

fn transition(continuity: Continuity) -> ChildTransition {
    ChildTransition {
        runs: Vec::new(),
        n: 1,
        sgn: 1.0,
        parent_u: 0.0,
        child_u: 0.0,
        ell: 1.0,
        ell_vertex: Vec::new(),
        theta0: 0.0,
        sigma: 1.0,
        side: Vec::new(),
        continuity,
        rise_vertex: Vec::new(),
    }
}

/// A column from a torso's back up to a neck: `L`, `T`, `A`, `Q`, `D`, `B`
/// with depth in every term.
fn column(rise: f64) -> Column {
    Column {
        data: [
            [0.1, 0.0, -0.3],
            [0.05, 1.0, -0.1],
            [0.2, -0.3, 0.4],
            [0.05, 1.0, 0.4],
            [-0.02, 0.8, 0.3],
            [0.1, 0.2, -0.5],
        ],
        rise,
    }
}

#[test]
fn a_late_depth_blend_keeps_the_ends_and_moves_only_depth() {
    for (continuity, top) in [(Continuity::C1, 1), (Continuity::C2, 2)] {
        let ct = transition(continuity);
        let (plain, late) = (column(0.0), column(0.6));
        for s in [0.0, 1.0] {
            for d in 0..=top {
                let a = blend(&ct, &plain, s, d);
                let b = blend(&ct, &late, s, d);
                for k in 0..3 {
                    assert!(
                        (a[k] - b[k]).abs() <= EXACT,
                        "{continuity:?} s {s} derivative {d} coordinate {k}: {} against {}",
                        b[k],
                        a[k]
                    );
                }
            }
        }
        let mut moved = 0.0f64;
        for i in 1..20 {
            let s = i as f64 / 20.0;
            let a = blend(&ct, &plain, s, 0);
            let b = blend(&ct, &late, s, 0);
            assert!(
                (a[0] - b[0]).abs() <= EXACT && (a[1] - b[1]).abs() <= EXACT,
                "{continuity:?} s {s}: x or y moved"
            );
            moved = moved.max((a[2] - b[2]).abs());
        }
        assert!(moved > MOVES, "{continuity:?}: depth moved only {moved}");
    }
}
