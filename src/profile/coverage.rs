//! Coverage of a sample grid by projected triangles, as runs: exact
//! scanline intervals along grid lines, then the outer part (holes filled,
//! the largest 4-connected part kept) by union-find over runs of samples,
//! so the cost grows with the outline's length, not the grid's area.

/// Intervals per grid line, sorted and merged (CSR layout).
pub(crate) struct Lines {
    start: Vec<u32>,
    iv: Vec<(f64, f64)>,
}

impl Lines {
    pub fn line(&self, j: usize) -> &[(f64, f64)] {
        &self.iv[self.start[j] as usize..self.start[j + 1] as usize]
    }
}

/// For each grid line (horizontal when `swap` is false: `y = o + j h`,
/// intervals in x; vertical when true), the merged intervals where it
/// meets the union of the projected triangles. A shared edge is evaluated
/// in one canonical order, so neighbouring triangles meet without gaps.
pub(crate) fn line_intervals(
    pts: &[[f64; 2]],
    tris: &[[u32; 3]],
    swap: bool,
    o: f64,
    h: f64,
    n: usize,
) -> Lines {
    let (u, v) = if swap { (1, 0) } else { (0, 1) };
    let mut hits: Vec<(u32, f64, f64)> = Vec::with_capacity(8 * tris.len());
    for t in tris {
        let c = [pts[t[0] as usize], pts[t[1] as usize], pts[t[2] as usize]];
        let vmin = c[0][v].min(c[1][v]).min(c[2][v]);
        let vmax = c[0][v].max(c[1][v]).max(c[2][v]);
        let j0 = ((vmin - o) / h).floor().max(0.0) as usize;
        let j1 = (((vmax - o) / h).ceil().max(0.0) as usize).min(n - 1);
        for j in j0..=j1 {
            let y = o + j as f64 * h;
            if y < vmin || y > vmax {
                continue;
            }
            let mut a = f64::INFINITY;
            let mut b = f64::NEG_INFINITY;
            for k in 0..3 {
                let (mut p, mut q) = (c[k], c[(k + 1) % 3]);
                if (p[v], p[u]) > (q[v], q[u]) {
                    std::mem::swap(&mut p, &mut q);
                }
                if y < p[v] || y > q[v] {
                    continue;
                }
                if q[v] > p[v] {
                    let x = p[u] + (y - p[v]) / (q[v] - p[v]) * (q[u] - p[u]);
                    a = a.min(x);
                    b = b.max(x);
                } else {
                    a = a.min(p[u]).min(q[u]);
                    b = b.max(p[u]).max(q[u]);
                }
            }
            if a <= b {
                hits.push((j as u32, a, b));
            }
        }
    }
    // counting sort by line, then sort and merge each line in place
    let mut start = vec![0u32; n + 1];
    for h in &hits {
        start[h.0 as usize + 1] += 1;
    }
    for j in 0..n {
        start[j + 1] += start[j];
    }
    let mut fill = start.clone();
    let mut iv = vec![(0.0, 0.0); hits.len()];
    for &(j, a, b) in &hits {
        iv[fill[j as usize] as usize] = (a, b);
        fill[j as usize] += 1;
    }
    let mut out_start = vec![0u32; n + 1];
    let mut w = 0usize;
    for j in 0..n {
        let (s, e) = (start[j] as usize, start[j + 1] as usize);
        iv[s..e].sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
        let first = w;
        for r in s..e {
            let (a, b) = iv[r];
            if w > first && a <= iv[w - 1].1 {
                iv[w - 1].1 = iv[w - 1].1.max(b);
            } else {
                iv[w] = (a, b);
                w += 1;
            }
        }
        out_start[j + 1] = w as u32;
    }
    iv.truncate(w);
    Lines {
        start: out_start,
        iv,
    }
}

/// Runs of samples `[s, e]` (inclusive) per row (CSR layout).
#[derive(Clone, Debug, Default)]
pub(crate) struct Runs {
    pub start: Vec<u32>,
    pub runs: Vec<(u32, u32)>,
}

impl Runs {
    pub fn row(&self, j: usize) -> &[(u32, u32)] {
        &self.runs[self.start[j] as usize..self.start[j + 1] as usize]
    }
    pub fn rows(&self) -> usize {
        self.start.len() - 1
    }
    fn from_rows(rows: impl Iterator<Item = Vec<(u32, u32)>>) -> Runs {
        let mut r = Runs {
            start: vec![0],
            runs: Vec::new(),
        };
        for row in rows {
            r.runs.extend(row);
            r.start.push(r.runs.len() as u32);
        }
        r
    }
}

/// Inside samples per row: `x_i = ox + i h` covered by a row interval
/// (`a <= x_i <= b`, the same test the crossing lookup uses).
pub(crate) fn inside_runs(rows: &Lines, ny: usize, nx: usize, ox: f64, h: f64) -> Runs {
    let x = |i: usize| ox + i as f64 * h;
    Runs::from_rows((0..ny).map(|j| {
        let mut out: Vec<(u32, u32)> = Vec::new();
        for &(a, b) in rows.line(j) {
            let mut i0 = (((a - ox) / h).floor().max(0.0) as usize).min(nx - 1);
            while i0 < nx && x(i0) < a {
                i0 += 1;
            }
            while i0 > 0 && x(i0 - 1) >= a {
                i0 -= 1;
            }
            let mut i1 = (((b - ox) / h).ceil().max(0.0) as usize).min(nx - 1);
            while i1 > 0 && x(i1) > b {
                i1 -= 1;
            }
            while i1 + 1 < nx && x(i1 + 1) <= b {
                i1 += 1;
            }
            if i0 > i1 || x(i0) < a || x(i1) > b {
                continue;
            }
            match out.last_mut() {
                Some(l) if i0 as u32 <= l.1 + 1 => l.1 = l.1.max(i1 as u32),
                _ => out.push((i0 as u32, i1 as u32)),
            }
        }
        out
    }))
}

/// The complement of `runs` in `[0, nx - 1]`, row by row.
fn complement(runs: &Runs, nx: usize) -> Runs {
    Runs::from_rows((0..runs.rows()).map(|j| {
        let mut out = Vec::new();
        let mut next = 0u32;
        for &(s, e) in runs.row(j) {
            if s > next {
                out.push((next, s - 1));
            }
            next = e + 1;
        }
        if (next as usize) < nx {
            out.push((next, nx as u32 - 1));
        }
        out
    }))
}

struct UnionFind(Vec<u32>);

impl UnionFind {
    fn find(&mut self, mut a: u32) -> u32 {
        while self.0[a as usize] != a {
            let p = self.0[self.0[a as usize] as usize];
            self.0[a as usize] = p;
            a = p;
        }
        a
    }
    fn union(&mut self, a: u32, b: u32) {
        let (a, b) = (self.find(a), self.find(b));
        if a != b {
            self.0[a.max(b) as usize] = a.min(b);
        }
    }
}

/// Connected components of runs: rows `j` and `j + 1` connect runs whose
/// ranges overlap after widening by `slack` (0: 4-connected, 1:
/// 8-connected). Returns the component root of every run.
fn components(runs: &Runs, slack: u32) -> Vec<u32> {
    let mut uf = UnionFind((0..runs.runs.len() as u32).collect());
    for j in 0..runs.rows().saturating_sub(1) {
        let (a0, b0) = (runs.start[j] as usize, runs.start[j + 1] as usize);
        let (a1, b1) = (runs.start[j + 1] as usize, runs.start[j + 2] as usize);
        let (mut p, mut q) = (a0, a1);
        while p < b0 && q < b1 {
            let (s0, e0) = runs.runs[p];
            let (s1, e1) = runs.runs[q];
            if s0 <= e1 + slack && s1 <= e0 + slack {
                uf.union(p as u32, q as u32);
            }
            if e0 < e1 {
                p += 1;
            } else {
                q += 1;
            }
        }
    }
    (0..runs.runs.len() as u32).map(|r| uf.find(r)).collect()
}

/// The outer part: holes (outside regions, 8-connected, not reaching the
/// border) filled, then the 4-connected parts with their sizes in samples,
/// largest first: (runs of the largest part, sizes of all parts).
pub(crate) fn outer_part(inside: &Runs, nx: usize) -> (Runs, Vec<usize>) {
    let gaps = complement(inside, nx);
    let comp = components(&gaps, 1);
    let ny = gaps.rows();
    let mut reached = vec![false; gaps.runs.len()];
    for j in 0..ny {
        for (k, &(s, e)) in gaps.row(j).iter().enumerate() {
            if j == 0 || j + 1 == ny || s == 0 || e as usize + 1 == nx {
                reached[comp[gaps.start[j] as usize + k] as usize] = true;
            }
        }
    }
    let outside = Runs::from_rows((0..ny).map(|j| {
        let base = gaps.start[j] as usize;
        gaps.row(j)
            .iter()
            .enumerate()
            .filter(|&(k, _)| reached[comp[base + k] as usize])
            .map(|(_, &r)| r)
            .collect()
    }));
    let filled = complement(&outside, nx);
    let comp = components(&filled, 0);
    let mut size = vec![0usize; filled.runs.len()];
    for (r, &(s, e)) in filled.runs.iter().enumerate() {
        size[comp[r] as usize] += (e - s + 1) as usize;
    }
    let mut parts: Vec<(usize, u32)> = size
        .iter()
        .enumerate()
        .filter(|&(_, &n)| n > 0)
        .map(|(r, &n)| (n, r as u32))
        .collect();
    parts.sort_by(|a, b| b.0.cmp(&a.0).then(a.1.cmp(&b.1)));
    let sizes = parts.iter().map(|p| p.0).collect();
    let Some(&(_, root)) = parts.first() else {
        return (Runs::from_rows((0..ny).map(|_| Vec::new())), sizes);
    };
    let kept = Runs::from_rows((0..ny).map(|j| {
        let base = filled.start[j] as usize;
        filled
            .row(j)
            .iter()
            .enumerate()
            .filter(|&(k, _)| comp[base + k] == root)
            .map(|(_, &r)| r)
            .collect()
    }));
    (kept, sizes)
}
