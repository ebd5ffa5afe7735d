//! Integration tests of the plate family.
use pdesculpt::plate::check::*;
#[test]
fn plate_explore() {
    for n in [8, 16, 32, 64] {
        eprintln!(
            "sq n={n} {:?} rect2 {:?} circ {:?} ell {:?}",
            rectangle_centre(1.0, 1.0, n),
            rectangle_centre(1.0, 2.0, n),
            ellipse_centre(1.0, 1.0, n / 2).map(|w| w * 64.0),
            ellipse_centre(1.0, 0.5, n / 2)
        );
    }
}
