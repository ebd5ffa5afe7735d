//! Hand-computed values: a unit square, a bow tie, a concave L, collinear
//! and touching cases, NaN. The inputs are small integers and halves, so
//! every expected value is exact in floating point.

use super::*;

const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// Edge 0 ((0,0)-(1,1)) crosses edge 2 ((1,0)-(0,1)) at (0.5, 0.5).
const BOW_TIE: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
/// A 2 x 2 square without its top-right unit square: area 3.
const L: [[f64; 2]; 6] = [
    [0.0, 0.0],
    [2.0, 0.0],
    [2.0, 1.0],
    [1.0, 1.0],
    [1.0, 2.0],
    [0.0, 2.0],
];

fn reversed(p: &[[f64; 2]]) -> Vec<[f64; 2]> {
    p.iter().rev().copied().collect()
}

#[test]
fn area_and_orientation() {
    assert_eq!(signed_area(&SQUARE), 1.0);
    assert_eq!(signed_area(&reversed(&SQUARE)), -1.0);
    assert_eq!(signed_area(&L), 3.0);
    // far from the origin the fan from the first point stays exact
    let moved: Vec<[f64; 2]> = L.iter().map(|p| [p[0] + 1e8, p[1] - 1e8]).collect();
    assert_eq!(signed_area(&moved), 3.0);
    // the bow tie's two lobes cancel
    assert_eq!(signed_area(&BOW_TIE), 0.0);
    assert_eq!(signed_area(&SQUARE[..2]), 0.0);
    assert_eq!(orientation(&L), Some(Orientation::CounterClockwise));
    assert_eq!(orientation(&reversed(&L)), Some(Orientation::Clockwise));
    assert_eq!(orientation(&BOW_TIE), None);
    assert_eq!(orientation(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]), None);
    assert_eq!(orient([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]), 1.0);
    assert_eq!(orient([0.0, 0.0], [1.0, 0.0], [2.0, 0.0]), 0.0);
}

#[test]
fn point_in_polygon_even_odd() {
    for p in [SQUARE.to_vec(), reversed(&SQUARE)] {
        assert!(point_in_polygon(&p, [0.5, 0.5]));
        assert!(!point_in_polygon(&p, [1.5, 0.5]));
        assert!(!point_in_polygon(&p, [0.5, -0.5]));
        // the boundary: left and bottom in, right and top out
        assert!(point_in_polygon(&p, [0.0, 0.5]));
        assert!(point_in_polygon(&p, [0.5, 0.0]));
        assert!(!point_in_polygon(&p, [1.0, 0.5]));
        assert!(!point_in_polygon(&p, [0.5, 1.0]));
        assert!(point_in_polygon(&p, [0.0, 0.0]));
        assert!(!point_in_polygon(&p, [1.0, 0.0]));
        assert!(!point_in_polygon(&p, [0.0, 1.0]));
        assert!(!point_in_polygon(&p, [1.0, 1.0]));
    }
    // the L's missing corner is outside, its arms inside; a ray through
    // the reflex vertex's height counts once
    assert!(!point_in_polygon(&L, [1.5, 1.5]));
    assert!(point_in_polygon(&L, [0.5, 1.5]));
    assert!(point_in_polygon(&L, [1.5, 0.5]));
    assert!(point_in_polygon(&L, [0.5, 1.0]));
    // even-odd in the bow tie: the lobes in, the gaps between them out
    assert!(point_in_polygon(&BOW_TIE, [0.25, 0.5]));
    assert!(!point_in_polygon(&BOW_TIE, [0.5, 0.25]));
    assert!(!point_in_polygon(&SQUARE, [f64::NAN, 0.5]));
    assert!(!point_in_polygon(&[], [0.0, 0.0]));
}

#[test]
fn segment_intersection() {
    let (a, b, c, d) = ([0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]);
    assert!(segments_cross(a, b, c, d));
    assert_eq!(segments_meet(a, b, c, d), Some([1.0, 1.0]));
    // touching: an end on the other segment meets but does not cross
    let e = [1.0, 1.0];
    assert!(!segments_cross(a, b, c, e));
    assert_eq!(segments_meet(a, b, c, e), Some(e));
    assert!(segments_intersect(a, b, c, e));
    // shared end
    assert_eq!(segments_meet(a, b, b, [3.0, 0.0]), Some(b));
    // collinear: overlapping meets, disjoint does not
    let (f, g) = ([1.0, 1.0], [3.0, 3.0]);
    assert!(!segments_cross(a, b, f, g));
    assert!(segments_intersect(a, b, f, g));
    assert!(!segments_intersect(a, [0.5, 0.5], f, g));
    // parallel apart, and a miss beyond an end
    assert!(!segments_intersect(a, b, [0.0, 1.0], [1.0, 2.0]));
    assert!(!segments_intersect(a, [0.5, 0.5], c, d));
}

#[test]
fn simple_polygon_sweep() {
    assert!(is_simple(&SQUARE));
    assert!(is_simple(&L));
    assert_eq!(self_intersection(&BOW_TIE), Some((0, 2, [0.5, 0.5])));
    assert_eq!(
        self_intersection(&reversed(&BOW_TIE)),
        Some((0, 2, [0.5, 0.5]))
    );
    // a figure eight through a shared vertex touches: not simple
    let eight = [
        [0.0, 0.0],
        [1.0, 1.0],
        [2.0, 0.0],
        [2.0, 2.0],
        [1.0, 1.0],
        [0.0, 2.0],
    ];
    assert_eq!(self_intersection(&eight), Some((0, 3, [1.0, 1.0])));
    // a vertex on a non-adjacent edge
    let touch = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    assert_eq!(self_intersection(&touch), Some((0, 2, [2.0, 0.0])));
    // a spike folding back onto its own edge
    let spike = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
    assert_eq!(self_intersection(&spike), Some((0, 1, [2.0, 0.0])));
    // a straight run through a vertex is no fold
    assert!(is_simple(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 1.0]]));
    // the lowest pair among several: a zig-zag crossing twice
    let zig = [[0.0, 0.0], [3.0, 1.0], [3.0, 0.0], [0.0, 1.0], [1.5, 3.0]];
    assert_eq!(
        self_intersection(&zig).map(|(a, b, _)| (a, b)),
        Some((0, 2))
    );
}

#[test]
fn bounds() {
    assert_eq!(bbox(&L), ([0.0, 0.0], [2.0, 2.0]));
    assert_eq!(bbox(&[]), ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]));
    assert_eq!(diagonal(&[[0.0, 0.0], [3.0, 4.0]]), 5.0);
    assert_eq!(diagonal(&[]), 0.0);
}

#[test]
fn outline_validation() {
    let o = Outline::new(reversed(&L)).expect("the L is valid");
    // clockwise input reversed keeping its first point first
    assert_eq!(o.points()[0], L[5]);
    assert_eq!(o.area(), 3.0);
    assert_eq!(o.given_orientation(), Orientation::Clockwise);
    let placed = o.placed(2.0, [1.0, 0.0]).expect("a positive scale");
    assert_eq!(placed.points()[1], [1.0, 0.0]);
    assert_eq!(placed.area(), 12.0);
    assert_eq!(o.placed(-1.0, [0.0; 2]), None);
    assert_eq!(o.scaled(f64::NAN), None);
    assert_eq!(
        Outline::new(L.to_vec()).map(|o| o.given_orientation()),
        Ok(Orientation::CounterClockwise)
    );
    // equal as polygons, however they were given
    let again = Outline::new(o.points().to_vec()).expect("valid");
    assert_eq!(again.given_orientation(), Orientation::CounterClockwise);
    assert_eq!(again, o);
    assert_eq!(orientation(o.points()), Some(Orientation::CounterClockwise));
    // repeats and a closing copy dropped
    let mut p = SQUARE.to_vec();
    p.insert(1, SQUARE[0]);
    p.push(SQUARE[0]);
    assert_eq!(
        Outline::new(p).map(Outline::into_points),
        Ok(SQUARE.to_vec())
    );
    assert_eq!(validate(&SQUARE), Ok(()));
    let mut nan = SQUARE.to_vec();
    nan[2][1] = f64::NAN;
    assert_eq!(validate(&nan), Err(OutlineError::NonFinite { index: 2 }));
    assert_eq!(
        validate(&[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 0.0]]),
        Err(OutlineError::TooFewPoints { count: 2 })
    );
    assert_eq!(
        validate(&[[0.0, 0.0], [1.0, 1.0], [3.0, 3.0], [2.0, 2.0]]),
        Err(OutlineError::ZeroArea)
    );
    assert_eq!(
        validate(&BOW_TIE),
        Err(OutlineError::SelfIntersecting {
            a: 0,
            b: 2,
            at: [0.5, 0.5]
        })
    );
    // indices name the points as given, repeats included
    let mut bow = BOW_TIE.to_vec();
    bow.insert(0, BOW_TIE[0]);
    assert!(matches!(
        validate(&bow),
        Err(OutlineError::SelfIntersecting { a: 0, b: 3, .. })
    ));
    assert_eq!(
        OutlineError::NonFinite { index: 2 }.to_string(),
        "point 2 has a non-finite coordinate"
    );
}

#[test]
fn views() {
    assert_eq!("Front ".parse::<View>(), Ok(View::Front));
    assert_eq!(
        "back".parse::<View>(),
        Err(UnknownView {
            name: "back".into()
        })
    );
    assert_eq!(View::Side.project([1.0, 2.0, 3.0]), [3.0, 2.0]);
    assert_eq!(View::Top.project([1.0, 2.0, 3.0]), [1.0, 3.0]);
    assert_eq!(View::default(), View::Front);
}
