//! The feet of a drawing derived upright and turned back (`sketch::align`):
//! an issue-range humanoid (`tests/data/sketch/level_feet_*.svg`, written
//! by `cargo run --release --example sketch_corpus -- write DIR --seed 9191
//! --random 48 --ranges issue` as random_37), whose outline's axis leans 2
//! degrees although its feet are drawn level.

use crate::sketch_draw::{build, data_pair};
use pdesculpt::sketch::quality::Bounds;

/// How much deeper one foot may sink below the ground than the other,
/// relative to the height: a tenth of issue 28's outside bound. Both
/// sink 0.59 % now; turned with the front, the feet's side-view heights
/// put one 1.06 % below the ground and the other 0.19 %.
const FEET_LEVEL: f64 = 0.1 * Bounds::ISSUE.outside;

#[test]
fn feet_drawn_level_stay_level_when_the_figure_is_turned_upright() {
    let (f, s) = data_pair("level_feet");
    let b = build(&f, &s, None).expect("builds");
    let m = &b.model.mesh;
    let ys = || m.positions.iter().map(|p| p[1]);
    let h = ys().fold(f64::MIN, f64::max) - ys().fold(f64::MAX, f64::min);
    // the lowest point of each leg's triangles
    let lowest = |name: &str| {
        let g = m
            .groups
            .iter()
            .position(|n| n == name)
            .unwrap_or_else(|| panic!("group {name}")) as u32;
        m.triangles
            .iter()
            .zip(&m.tri_group)
            .filter(|(_, k)| **k == g)
            .flat_map(|(t, _)| t.iter().map(|&i| m.positions[i as usize][1]))
            .fold(f64::MAX, f64::min)
    };
    let (l, r) = (lowest("leg_l"), lowest("leg_r"));
    assert!(
        (l - r).abs() <= FEET_LEVEL * h,
        "feet {:.3} % and {:.3} % of the height from the ground",
        100.0 * l / h,
        100.0 * r / h
    );
    assert!(
        l.min(r) >= -Bounds::ISSUE.outside * h,
        "a foot sinks {:.3} % of the height below the ground",
        -100.0 * l.min(r) / h
    );
}
