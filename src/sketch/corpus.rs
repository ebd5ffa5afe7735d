//! Writing drawings the way vector editors save them (issue 28 item 6):
//! an outline in model metres becomes an SVG document in one of several
//! common styles (page units, viewBox or none, a figure anywhere on the
//! page inside transformed groups, absolute or relative path commands,
//! lines, cubics, quadratics and arcs).
//!
//! The writer is the corpus's, not the reader's: it computes the page and
//! path coordinates with its own affine maps, so a reader that ignored a
//! transform or a unit would put the figure elsewhere or at another size.

use std::fmt::Write as _;

/// A document style.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Style {
    /// Inkscape 1.x: `width="210mm" height="297mm" viewBox="0 0 210 297"`,
    /// a translated layer group, relative cubics (`c`).
    InkscapeMm,
    /// Inkscape 0.92: A4 in mm over a 90-dpi user space
    /// (`viewBox="0 0 744.09448819 1052.3622047"`), a `matrix(...)` group,
    /// absolute cubics and lines.
    Inkscape092,
    /// Pixels without a viewBox (`width="800" height="1100"`): one user
    /// unit is one CSS pixel; nested `scale` and `translate`, arcs.
    PxNoViewBox,
    /// Inches: `width="8.5in" height="11in" viewBox="0 0 8.5 11"`, a
    /// rotated group undone by an inner one, arcs and lines (`H`, `V`).
    Inches,
    /// Centimetres over a millimetre user space (`width="100cm"
    /// height="200cm" viewBox="0 0 1000 2000"`), relative lines and smooth
    /// cubics (`l`, `s`).
    Cm,
    /// Points: `width="595pt" height="842pt" viewBox="0 0 595 842"`,
    /// quadratics (`Q`, `t`).
    Points,
}

impl Style {
    /// Every style.
    pub const ALL: [Style; 6] = [
        Style::InkscapeMm,
        Style::Inkscape092,
        Style::PxNoViewBox,
        Style::Inches,
        Style::Cm,
        Style::Points,
    ];

    /// (root attributes, metres per user unit, page size in user units).
    fn page(self) -> (&'static str, f64, [f64; 2]) {
        match self {
            Style::InkscapeMm => (
                r#"width="210mm" height="297mm" viewBox="0 0 210 297""#,
                1e-3,
                [210.0, 297.0],
            ),
            Style::Inkscape092 => (
                r#"width="210mm" height="297mm" viewBox="0 0 744.09448819 1052.3622047""#,
                0.0254 / 90.0,
                [744.094_488_19, 1_052.362_204_7],
            ),
            Style::PxNoViewBox => (
                r#"width="800" height="1100""#,
                0.0254 / 96.0,
                [800.0, 1100.0],
            ),
            Style::Inches => (
                r#"width="8.5in" height="11in" viewBox="0 0 8.5 11""#,
                0.0254,
                [8.5, 11.0],
            ),
            Style::Cm => (
                r#"width="100cm" height="200cm" viewBox="0 0 1000 2000""#,
                1e-3,
                [1000.0, 2000.0],
            ),
            Style::Points => (
                r#"width="595pt" height="842pt" viewBox="0 0 595 842""#,
                0.0254 / 72.0,
                [595.0, 842.0],
            ),
        }
    }

    /// The group transforms (outermost first, SVG syntax) and their
    /// composed matrix `[a, b, c, d, e, f]` (SVG's `matrix`).
    fn groups(self, at: [f64; 2]) -> (Vec<String>, [f64; 6]) {
        let t = |x: f64, y: f64| [1.0, 0.0, 0.0, 1.0, x, y];
        let sc = |k: f64| [k, 0.0, 0.0, k, 0.0, 0.0];
        let rot = |deg: f64| {
            let (s, c) = deg.to_radians().sin_cos();
            [c, s, -s, c, 0.0, 0.0]
        };
        let list: Vec<(String, [f64; 6])> = match self {
            Style::InkscapeMm => vec![(format!("translate({},{})", at[0], at[1]), t(at[0], at[1]))],
            Style::Inkscape092 => {
                let m = [1.25, 0.0, 0.0, 1.25, at[0], at[1]];
                vec![(format!("matrix(1.25,0,0,1.25,{},{})", at[0], at[1]), m)]
            }
            Style::PxNoViewBox => vec![
                (format!("translate({},{})", at[0], at[1]), t(at[0], at[1])),
                ("scale(2)".into(), sc(2.0)),
                ("translate(-15,7.5)".into(), t(-15.0, 7.5)),
            ],
            Style::Inches => vec![
                (format!("translate({},{})", at[0], at[1]), t(at[0], at[1])),
                ("rotate(90)".into(), rot(90.0)),
                ("rotate(-90)".into(), rot(-90.0)),
                ("scale(0.5)".into(), sc(0.5)),
            ],
            Style::Cm => vec![(format!("translate({},{})", at[0], at[1]), t(at[0], at[1]))],
            Style::Points => vec![
                (format!("translate({} {})", at[0], at[1]), t(at[0], at[1])),
                ("scale(1.5 1.5)".into(), sc(1.5)),
            ],
        };
        let mut m = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
        for (_, g) in &list {
            m = compose(m, *g);
        }
        (list.into_iter().map(|l| l.0).collect(), m)
    }
}

/// `m * g` (apply `g` first), SVG matrices.
fn compose(m: [f64; 6], g: [f64; 6]) -> [f64; 6] {
    [
        m[0] * g[0] + m[2] * g[1],
        m[1] * g[0] + m[3] * g[1],
        m[0] * g[2] + m[2] * g[3],
        m[1] * g[2] + m[3] * g[3],
        m[0] * g[4] + m[2] * g[5] + m[4],
        m[1] * g[4] + m[3] * g[5] + m[5],
    ]
}

fn invert(m: [f64; 6]) -> [f64; 6] {
    let det = m[0] * m[3] - m[1] * m[2];
    let (a, b, c, d) = (m[3] / det, -m[1] / det, -m[2] / det, m[0] / det);
    [a, b, c, d, -(a * m[4] + c * m[5]), -(b * m[4] + d * m[5])]
}

fn apply(m: [f64; 6], p: [f64; 2]) -> [f64; 2] {
    [
        m[0] * p[0] + m[2] * p[1] + m[4],
        m[1] * p[0] + m[3] * p[1] + m[5],
    ]
}

/// `n` points equally spaced by arc length on a closed polyline.
pub fn resample(p: &[[f64; 2]], n: usize) -> Vec<[f64; 2]> {
    let m = p.len();
    let mut cum = vec![0.0; m + 1];
    for i in 0..m {
        let (a, b) = (p[i], p[(i + 1) % m]);
        cum[i + 1] = cum[i] + (b[0] - a[0]).hypot(b[1] - a[1]);
    }
    let total = cum[m];
    let mut out = Vec::with_capacity(n);
    let mut j = 0;
    for k in 0..n {
        let s = total * k as f64 / n as f64;
        while j + 1 < m && cum[j + 1] < s {
            j += 1;
        }
        let (a, b) = (p[j], p[(j + 1) % m]);
        let l = (cum[j + 1] - cum[j]).max(f64::MIN_POSITIVE);
        let t = ((s - cum[j]) / l).clamp(0.0, 1.0);
        out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
    }
    out
}

fn num(x: f64) -> String {
    let s = format!("{x:.5}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// Path data through the closed knots `k` in the style's commands.
fn path_data(style: Style, k: &[[f64; 2]]) -> String {
    let n = k.len();
    let at = |i: usize| k[i % n];
    let mut d = format!("M {} {}", num(k[0][0]), num(k[0][1]));
    // Catmull-Rom tangents: the cubic through every knot
    let ctrl = |i: usize| {
        let (p0, p1, p2, p3) = (at(i + n - 1), at(i), at(i + 1), at(i + 2));
        (
            [p1[0] + (p2[0] - p0[0]) / 6.0, p1[1] + (p2[1] - p0[1]) / 6.0],
            [p2[0] - (p3[0] - p1[0]) / 6.0, p2[1] - (p3[1] - p1[1]) / 6.0],
        )
    };
    let mut i = 0;
    let mut cur = k[0];
    while i < n {
        match style {
            Style::InkscapeMm | Style::Inkscape092 | Style::Cm => {
                let (c1, c2) = ctrl(i);
                // relative commands from the position as written (rounded):
                // from the exact one, 500 rounded steps drifted by up to
                // 4e-4 units and the path's end crossed its start
                cur = cubic_command(&mut d, style, i, [c1, c2, at(i + 1)], cur);
                i += 1;
            }
            Style::PxNoViewBox | Style::Inches => {
                let step = arc_or_line(&mut d, style, i, n, [cur, at(i + 1), at(i + 2)]);
                cur = at(i + step);
                i += step;
            }
            Style::Points => {
                // a quadratic whose control point is the cubic's mean
                let (c1, c2) = ctrl(i);
                let c = [0.5 * (c1[0] + c2[0]), 0.5 * (c1[1] + c2[1])];
                let p = at(i + 1);
                let _ = write!(
                    d,
                    " Q {} {} {} {}",
                    num(c[0]),
                    num(c[1]),
                    num(p[0]),
                    num(p[1])
                );
                cur = p;
                i += 1;
            }
        }
    }
    d.push_str(" Z");
    d
}

/// The command from `cur` to knot `i + 1` (controls `c1`, `c2`, end `p`)
/// in one of the cubic styles: relative cubics (Inkscape mm), absolute
/// cubics with every fourth a line (Inkscape 0.92), or relative lines and
/// smooth cubics (cm).
fn cubic_command(
    d: &mut String,
    style: Style,
    i: usize,
    [c1, c2, p]: [[f64; 2]; 3],
    cur: [f64; 2],
) -> [f64; 2] {
    let rel = |q: [f64; 2]| [q[0] - cur[0], q[1] - cur[1]];
    // where the reader ends up: the written relative step or absolute point
    let moved = |q: [f64; 2]| [cur[0] + written(q[0]), cur[1] + written(q[1])];
    let absolute = [written(p[0]), written(p[1])];
    match (style, i % 4) {
        (Style::InkscapeMm, _) => {
            let (a, b, q) = (rel(c1), rel(c2), rel(p));
            let _ = write!(
                d,
                " c {} {} {} {} {} {}",
                num(a[0]),
                num(a[1]),
                num(b[0]),
                num(b[1]),
                num(q[0]),
                num(q[1])
            );
            moved(q)
        }
        (Style::Inkscape092, 3) => {
            let _ = write!(d, " L {} {}", num(p[0]), num(p[1]));
            absolute
        }
        (Style::Inkscape092, _) => {
            let _ = write!(
                d,
                " C {},{} {},{} {},{}",
                num(c1[0]),
                num(c1[1]),
                num(c2[0]),
                num(c2[1]),
                num(p[0]),
                num(p[1])
            );
            absolute
        }
        (_, 0) | (_, 2) => {
            let q = rel(p);
            let _ = write!(d, " l {} {}", num(q[0]), num(q[1]));
            moved(q)
        }
        _ => {
            // smooth cubic: its first control point mirrors the previous
            // command's (a line's: the current point)
            let (b, q) = (rel(c2), rel(p));
            let _ = write!(
                d,
                " s {} {} {} {}",
                num(b[0]),
                num(b[1]),
                num(q[0]),
                num(q[1])
            );
            moved(q)
        }
    }
}

/// The value `num(x)` writes, as a reader parses it.
fn written(x: f64) -> f64 {
    num(x).parse().unwrap_or(x)
}

/// An arc through the current point `cur` and knots `p1`, `p2`, or a line
/// to `p1` (a horizontal one as `H` in the inches style); returns how many
/// knots it advanced (2 or 1).
fn arc_or_line(
    d: &mut String,
    style: Style,
    i: usize,
    n: usize,
    [cur, p1, p2]: [[f64; 2]; 3],
) -> usize {
    match arc_through(cur, p1, p2) {
        Some((r, sweep)) if i + 2 <= n && i % 6 != 4 => {
            let _ = write!(
                d,
                " A {} {} 0 0 {} {} {}",
                num(r),
                num(r),
                sweep as u8,
                num(p2[0]),
                num(p2[1])
            );
            2
        }
        _ => {
            if style == Style::Inches && (p1[1] - cur[1]).abs() < 1e-12 {
                let _ = write!(d, " H {}", num(p1[0]));
            } else {
                let _ = write!(d, " L {} {}", num(p1[0]), num(p1[1]));
            }
            1
        }
    }
}

/// The circle through `a`, `b`, `c`: (radius, sweep flag for SVG's y-down
/// page) when the three are not collinear and the arc from `a` to `c`
/// through `b` is the minor one.
fn arc_through(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<(f64, bool)> {
    let cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    let (ab, bc, ca) = (
        (b[0] - a[0]).hypot(b[1] - a[1]),
        (c[0] - b[0]).hypot(c[1] - b[1]),
        (a[0] - c[0]).hypot(a[1] - c[1]),
    );
    if cross.abs() <= 1e-9 * ab * bc {
        return None;
    }
    let r = ab * bc * ca / (2.0 * cross.abs());
    // SVG sweep 1 is "positive angle direction": clockwise on a y-down page
    Some((r, cross > 0.0))
}

/// One figure view written as a document: `outline` in model metres (y up),
/// drawn `drawn_height` metres tall (its physical size), placed with its
/// lowest point at page position `at` (user units) inside the style's
/// groups; `knots` points along the outline.
pub fn document(
    style: Style,
    outline: &[[f64; 2]],
    drawn_height: f64,
    at: [f64; 2],
    knots: usize,
    id: &str,
) -> String {
    let (attrs, metres_per_unit, _) = style.page();
    let (ylo, yhi) = outline
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p[1]), h.max(p[1]))
        });
    let k = drawn_height / (yhi - ylo) / metres_per_unit;
    // page user units: y down, lowest point at `at`
    let page = |p: [f64; 2]| [at[0] + k * p[0], at[1] - k * (p[1] - ylo)];
    let (groups, m) = style.groups([0.0, 0.0]);
    let inv = invert(m);
    let pts: Vec<[f64; 2]> = resample(outline, knots)
        .into_iter()
        .map(|p| apply(inv, page(p)))
        .collect();
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<?xml version="1.0" encoding="UTF-8" standalone="no"?>"#
    );
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" {attrs}>"#
    );
    for (i, g) in groups.iter().enumerate() {
        let layer = if i == 0 {
            r#" inkscape:groupmode="layer" inkscape:label="Layer 1""#
        } else {
            ""
        };
        let _ = writeln!(s, r#"{}<g transform="{g}"{layer}>"#, "  ".repeat(i + 1));
    }
    let _ = writeln!(
        s,
        r#"{}<path id="{id}" style="fill:none;stroke:#000000;stroke-width:0.5" d="{}"/>"#,
        "  ".repeat(groups.len() + 1),
        path_data(style, &pts)
    );
    for i in (0..groups.len()).rev() {
        let _ = writeln!(s, "{}</g>", "  ".repeat(i + 1));
    }
    s.push_str("</svg>\n");
    s
}

/// A page position for a figure `drawn_height` metres tall in `style`, at
/// the fractions `u` of the room left on the page (so figures sit anywhere
/// on it, not at the origin).
pub fn page_position(
    style: Style,
    drawn_height: f64,
    width_of_height: f64,
    u: [f64; 2],
) -> [f64; 2] {
    let (_, mpu, size) = style.page();
    let (w, h) = (width_of_height * drawn_height / mpu, drawn_height / mpu);
    let room = [(size[0] - w).max(0.0), (size[1] - h).max(0.0)];
    [0.5 * w + u[0] * room[0], h + u[1] * room[1]]
}
