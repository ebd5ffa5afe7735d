//! The connected run of a region's slices: the one tube a part's key
//! sections follow (`section_place::samples`), through the branch that
//! goes on where the slices split.

/// A region's slice: its height, the interval its pick takes and every
/// interval the pick admits there ([`super::region::candidates`]).
pub(super) struct Slice {
    pub(super) y: f64,
    pub(super) iv: [f64; 2],
    pub(super) admitted: Vec<[f64; 2]>,
}

/// How much two intervals overlap (negative: the gap between them).
fn overlap(a: &[f64; 2], b: &[f64; 2]) -> f64 {
    a[1].min(b[1]) - a[0].max(b[0])
}

/// How many of the slices `next` (in walking order) a tube starting in
/// `iv` runs through, each slice's admitted interval overlapping the one
/// before most taken.
fn run_length<'a>(iv: [f64; 2], next: impl Iterator<Item = &'a Slice>) -> usize {
    let mut cur = iv;
    let mut k = 0;
    for q in next {
        let best = q
            .admitted
            .iter()
            .map(|c| (overlap(&cur, c), *c))
            .filter(|(o, _)| *o >= 0.0)
            .max_by(|a, b| a.0.total_cmp(&b.0));
        match best {
            Some((_, c)) => cur = c,
            None => break,
        }
        k += 1;
    }
    k
}

/// The run of slices around the region's middle whose intervals overlap
/// their neighbours' ones: one connected tube. Near a join a slice's pick
/// can miss the part's interval and catch a sliver of a neighbour beside
/// it (a T-pose arm's top beside the neck); such a sample jumps sideways
/// by more than the two half widths, and a section there (nearly on top
/// of the next one, in another frame) made the PDE chain overshoot by
/// metres. Where the tube splits (more than one admitted interval of the
/// next slice overlaps it: a shoulder's peak beside the neck), the run
/// follows the branch that goes on longest ([`run_length`]), the pick's
/// own on a tie: the widest interval there was the left shoulder's peak,
/// a hair wider than the neck, the run ended on it, and a body chained up
/// through the head was closed at the top of the head from there and shot
/// a cone four heights out (seed 4242's random_41, issue ranges). The
/// run ends where no admitted interval overlaps it. No tolerance: two
/// slices of one tube, `section_place::PROFILE_SAMPLES` apart, always overlap.
pub(super) fn connected_run(mut s: Vec<Slice>) -> Vec<Slice> {
    if s.len() < 3 {
        return s;
    }
    // the interval at `to` that continues the one at `from` (walking by
    // `to - from`), if any
    let step = |s: &mut Vec<Slice>, from: usize, to: usize| -> bool {
        let prev = s[from].iv;
        let going: Vec<[f64; 2]> = s[to]
            .admitted
            .iter()
            .copied()
            .filter(|c| overlap(&prev, c) >= 0.0)
            .collect();
        let next = match going.len() {
            0 => return false,
            1 => going[0],
            _ => {
                let len = |c: [f64; 2]| {
                    if to > from {
                        run_length(c, s[to + 1..].iter())
                    } else {
                        run_length(c, s[..to].iter().rev())
                    }
                };
                let own = going.contains(&s[to].iv).then(|| (len(s[to].iv), s[to].iv));
                let longest = going
                    .iter()
                    .map(|&c| (len(c), c))
                    .max_by_key(|x| x.0)
                    .expect("two or more");
                match own {
                    Some(o) if o.0 >= longest.0 => o.1,
                    _ => longest.1,
                }
            }
        };
        s[to].iv = next;
        true
    };
    let m = s.len() / 2;
    let mut lo = m;
    while lo > 0 && step(&mut s, lo, lo - 1) {
        lo -= 1;
    }
    let mut hi = m;
    while hi + 1 < s.len() && step(&mut s, hi, hi + 1) {
        hi += 1;
    }
    s.truncate(hi + 1);
    s.drain(..lo);
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A slice of the three intervals `ivs` at height `y`, its pick `pick`.
    fn at(y: f64, ivs: &[[f64; 2]], pick: usize) -> Slice {
        Slice {
            y,
            iv: ivs[pick],
            admitted: ivs.to_vec(),
        }
    }

    /// A body going up into a neck between two shoulder peaks, the left
    /// peak a hair wider than the neck for its few slices (the pick, the
    /// widest, takes it there): the run goes on up the neck to the head,
    /// not up the peak to its end. The pick's own branch is kept where
    /// both go on as long, and a tube no admitted interval continues ends.
    #[test]
    fn the_run_follows_the_branch_that_goes_on() {
        let mut s: Vec<Slice> = (0..12).map(|k| at(k as f64, &[[-3.0, 3.0]], 0)).collect();
        let split = [[-3.0, -1.05], [-0.95, 0.95], [1.05, 3.0]];
        s.extend((12..15).map(|k| at(k as f64, &split, 0)));
        s.extend((15..22).map(|k| at(k as f64, &[[-1.0, 1.0]], 0)));
        let run = connected_run(s);
        assert_eq!(run.len(), 22, "up to the head");
        for q in &run[12..15] {
            assert_eq!(q.iv, [-0.95, 0.95], "at y = {} the neck", q.y);
        }
        // two branches going on alike: the pick's
        let fork = [[-3.0, -0.5], [0.5, 3.0]];
        let mut s: Vec<Slice> = (0..12).map(|k| at(k as f64, &[[-3.0, 3.0]], 0)).collect();
        s.extend((12..22).map(|k| at(k as f64, &fork, 0)));
        let run = connected_run(s);
        assert_eq!(run.len(), 22);
        assert!(
            run[12..].iter().all(|q| q.iv == [-3.0, -0.5]),
            "the pick's branch"
        );
        // a jump no interval bridges ends the run
        let mut s: Vec<Slice> = (0..10).map(|k| at(k as f64, &[[-1.0, 1.0]], 0)).collect();
        s.extend((10..14).map(|k| at(k as f64, &[[5.0, 6.0]], 0)));
        assert_eq!(connected_run(s).len(), 10, "ends at the jump");
    }
}
