//! Where an animal's parts are cut off its lateral outline for the shells
//! ([`super::shells`]): a leg at a slice, the run of the outline beyond it
//! replaced by the chord ([`without_run`]); a tail or neck rising from a
//! corner of the back at a **root chord** from the corner across to where
//! its other side meets the body ([`root_point`], [`split_at_root`]).

use super::super::poly::dist;
use super::hanging::HANG_ROOT;

/// `poly` with the run beyond `y` (below it when `below`) between its
/// crossings of `y` nearest `range`'s ends replaced by the chord between
/// them; None when no such run lies wholly beyond `y`.
pub fn without_run(
    poly: &[[f64; 2]],
    y: f64,
    range: [f64; 2],
    below: bool,
) -> Option<Vec<[f64; 2]>> {
    let n = poly.len();
    let (a, b) = super::hanging::chord_ends(poly, y, range)?;
    let beyond = |p: &[f64; 2]| if below { p[1] < y } else { p[1] > y };
    // the run after edge `from` up to vertex `to`, both ways round
    let run_ok = |from: usize, to: usize| {
        let mut k = (from + 1) % n;
        loop {
            if !beyond(&poly[k]) {
                return false;
            }
            if k == to {
                return true;
            }
            k = (k + 1) % n;
        }
    };
    // keep the other run: from after the run's end round to its start
    let (first, last) = if run_ok(a.0, b.0) {
        (a, b)
    } else if run_ok(b.0, a.0) {
        (b, a)
    } else {
        return None;
    };
    let mut out = vec![[first.1, y]];
    let mut k = (last.0 + 1) % n;
    out.push([last.1, y]);
    loop {
        out.push(poly[k]);
        if k == first.0 {
            break;
        }
        k = (k + 1) % n;
    }
    // the chord from the run's start crossing to its end, then the kept run
    Some(out)
}

/// The next index of a walk round `n` vertices: in index order when
/// `forward`, else backward.
fn stepper(n: usize, forward: bool) -> impl Fn(usize) -> usize {
    move |k| {
        if forward {
            (k + 1) % n
        } else {
            (k + n - 1) % n
        }
    }
}

/// The part beyond a top corner of the outline (a tail or a neck rising
/// from the back): from the corner's vertex `c` the outline is walked into
/// the part (`forward`: in index order) up to its first point at `top`
/// (the part's highest), on to its **tip**, the first point farther from
/// the corner than every point within that distance of walk after it (a
/// tail's end, a muzzle), then to the **root point**, the first point
/// after the tip nearer the corner than every point within that distance
/// of walk after it (the part's other side meets the body there, the
/// outline then moving away down the rump or the chest). Returns the
/// root's index; None when the walk comes back to the corner first.
pub fn root_point(front: &[[f64; 2]], c: usize, forward: bool, top: f64) -> Option<usize> {
    let step = stepper(front.len(), forward);
    let mut k = step(c);
    while front[k][1] < top {
        k = step(k);
        if k == c {
            return None;
        }
    }
    let d = |k: usize| dist(front[k], front[c]);
    // whether k is beyond (farther when `far`, else nearer) every point
    // within its distance of walk after it; None: the walk is back at c
    let extreme = |k: usize, far: bool| -> bool {
        let (dk, mut j, mut walked) = (d(k), k, 0.0);
        loop {
            let next = step(j);
            walked += dist(front[j], front[next]);
            j = next;
            if j == c || walked > dk {
                return true;
            }
            if (d(j) > dk) == far && d(j) != dk {
                return false;
            }
        }
    };
    for far in [true, false] {
        while !extreme(k, far) {
            k = step(k);
            if k == c {
                return None;
            }
        }
        if far {
            k = step(k);
        }
    }
    Some(concave_after(front, k, c, forward))
}

/// Turn (radians) of the outline's walk that makes a corner where a part
/// meets the body: a third of a right angle.
const CORNER_TURN: f64 = std::f64::consts::FRAC_PI_6;

/// The root point moved on from the nearest point `m` (after a part's
/// tip) to where the outline turns into the body: the walk goes on from
/// `m` while its direction stays within [`CORNER_TURN`] of its direction
/// at `m`; when it first turns by more, against the walk's material side
/// (concave: the part's side meeting the body at a corner) within twice
/// `m`'s distance to the corner `c`, that point; else (it bends outward,
/// into a rump or a chest, or runs on) `m`. A tail's underside running
/// on straight past the point nearest the corner before it meets the rump
/// left the body a wedge there, which its sections folded over (corpus
/// dog: 180 degrees).
fn concave_after(front: &[[f64; 2]], m: usize, c: usize, forward: bool) -> usize {
    let step = stepper(front.len(), forward);
    let dm = dist(front[m], front[c]);
    let dir = |k: usize| {
        let (p, q) = (front[k], front[step(k)]);
        (q[1] - p[1]).atan2(q[0] - p[0])
    };
    // + toward the material: left of a counter-clockwise walk, right of a
    // clockwise one
    let sign = if forward { 1.0 } else { -1.0 };
    let start = dir(m);
    let (mut k, mut walked) = (m, 0.0);
    while walked <= 2.0 * dm {
        let d = dir(k) - start;
        let turned = sign * d.sin().atan2(d.cos());
        if turned.abs() > CORNER_TURN {
            return if turned < 0.0 { k } else { m };
        }
        let next = step(k);
        if next == c {
            break;
        }
        walked += dist(front[k], front[next]);
        k = next;
    }
    m
}

/// The run of `front` from index `from` to `to` in index order, both
/// included.
fn run(front: &[[f64; 2]], from: usize, to: usize) -> Vec<[f64; 2]> {
    let n = front.len();
    let mut out = vec![front[from]];
    let mut k = from;
    while k != to {
        k = (k + 1) % n;
        out.push(front[k]);
    }
    out
}

/// The index of `front`'s vertex nearest `p`.
pub fn nearest_vertex(front: &[[f64; 2]], p: [f64; 2]) -> usize {
    (0..front.len())
        .min_by(|&a, &b| dist(front[a], p).total_cmp(&dist(front[b], p)))
        .unwrap_or(0)
}

/// `front` split at a part's root chord from vertex `c` (the corner) to
/// vertex `r` (the root point, [`root_point`]) walked `forward`: the body's
/// outline without the part, and the part's closed by a root bulging
/// [`HANG_ROOT`] of the chord's length into the body.
pub fn split_at_root(
    front: &[[f64; 2]],
    c: usize,
    r: usize,
    forward: bool,
) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let (a, b) = if forward { (c, r) } else { (r, c) };
    let body = run(front, b, a);
    let mut part = run(front, a, b);
    // the part runs a -> b; its root goes from b back to a, into the body:
    // away from the part's centroid
    let (pa, pb) = (front[a], front[b]);
    let len = dist(pa, pb).max(f64::MIN_POSITIVE);
    let normal = [-(pb[1] - pa[1]) / len, (pb[0] - pa[0]) / len];
    let m = part.len() as f64;
    let cen = part
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0] / m, s[1] + p[1] / m]);
    let mid = [0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])];
    let toward = (cen[0] - mid[0]) * normal[0] + (cen[1] - mid[1]) * normal[1];
    let into = if toward > 0.0 {
        [-normal[0], -normal[1]]
    } else {
        normal
    };
    part.extend(super::super::thumb::root_arc(pb, pa, into, HANG_ROOT * len));
    (body, part)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A U: two legs x 0-1 and 2-3 below y = 1, the body 0-3 to y = 2
    /// (counter-clockwise).
    fn u_shape() -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [2.0, 1.0],
            [2.0, 0.0],
            [3.0, 0.0],
            [3.0, 2.0],
            [0.0, 2.0],
        ]
    }

    #[test]
    fn a_leg_is_cut_off_at_its_chord() {
        const CUT: f64 = 0.5;
        let p = without_run(&u_shape(), CUT, [2.0, 3.0], true).expect("the right leg");
        // the right leg's run below 0.5 is gone, its chord kept
        // (the left leg, x up to LEFT_LEG, keeps its run)
        const LEFT_LEG: f64 = 1.0;
        assert!(p.iter().all(|q| q[1] >= CUT || q[0] <= LEFT_LEG), "{p:?}");
        assert!(p.contains(&[2.0, CUT]) && p.contains(&[3.0, CUT]), "{p:?}");
        assert_eq!(crate::polygon::signed_area(&p).signum(), 1.0, "{p:?}");
        // area: the U's 5 less the leg's half below the cut, up to rounding
        const U_AREA: f64 = 5.0;
        const ROUNDING: f64 = 1e-12;
        let area = crate::polygon::signed_area(&p);
        assert!((area - (U_AREA - CUT)).abs() < ROUNDING, "{area}");
        // two legs and the gap between them rise above the cut: no one
        // run lies below it
        assert!(without_run(&u_shape(), CUT, [0.0, 2.0], true).is_none());
    }

    /// A body x 1 to 4 under y = 2, its tail rising up-left from the corner
    /// (1, 2), 0.4 wide, its underside running on straight past the point
    /// nearest the corner down to the rump's edge at x = 1
    /// (counter-clockwise, the underside finely sampled).
    fn wedge_tail() -> (Vec<[f64; 2]>, usize, usize) {
        let w = 0.4 / std::f64::consts::SQRT_2;
        let mut p = vec![[1.0, 0.0], [4.0, 0.0], [4.0, 2.0], [1.0, 2.0], [-1.0, 4.0]];
        let corner = 3;
        let t2 = [-1.0 - w, 4.0 - w];
        // down-right along (1, -1) to x = 1
        let run = 1.0 - t2[0];
        const STEPS: usize = 40;
        for k in 0..=STEPS {
            let s = run * k as f64 / STEPS as f64;
            p.push([t2[0] + s, t2[1] - s]);
        }
        let junction = p.len() - 1;
        (p, corner, junction)
    }

    #[test]
    fn a_tail_underside_running_on_is_cut_where_it_meets_the_rump() {
        let (p, c, j) = wedge_tail();
        assert!(crate::polygon::signed_area(&p) > 0.0);
        let root = root_point(&p, c, true, 4.0).expect("a root");
        assert_eq!(root, j, "{:?} (junction {:?})", p[root], p[j]);
        // the nearest point, where the cut stood before, lies up the tail
        let nearest = (j - 20..=j)
            .min_by(|&a, &b| dist(p[a], p[c]).total_cmp(&dist(p[b], p[c])))
            .expect("points");
        assert_ne!(nearest, j);
        // the body keeps no wedge: it is the rectangle
        let (body, part) = split_at_root(&p, c, root, true);
        // the rectangle 3 x 2 (the chord runs down its edge x = 1); cut at
        // the nearest point it kept the wedge between the chord and the
        // underside, 0.4 x 0.4 / 2
        const RECTANGLE: f64 = 6.0;
        // (half of that tells them apart)
        const HALF_WEDGE: f64 = 0.04;
        let area = crate::polygon::signed_area(&body);
        assert!((area - RECTANGLE).abs() < HALF_WEDGE, "{area}");
        assert!(part.len() > 20, "{}", part.len());
    }
}
