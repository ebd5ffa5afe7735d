//! The sketch corpus (issue 28 item 6).
//!
//! `cargo run --release --example sketch_corpus -- write data/sketch/corpus`
//! writes the generated drawings (front and side SVG per figure) and
//! `corpus.json`; the hand-made drawings (`hand_*.svg`) already in the
//! directory are kept and listed. `... -- measure data/sketch/corpus
//! [--all] [--sheet OUT.png] [--overlays DIR]` builds every drawing at the
//! intermediate level, prints the Markdown table (stdout) and optionally a
//! contact sheet (front and side renders of each model) and each built
//! drawing's `--overlay` picture (`DIR/NAME.svg`: where the model misses
//! it); without `--all` the held-out drawings are skipped (the development
//! loop never sees them).
//!
//! The humanoids: named poses and proportions covering issue 28 item 3,
//! then figures drawn at random (fixed seed) from `HumanoidRanges::WIDE`,
//! wider than the item's ranges. Every third generated drawing is held out.
//! `write DIR --seed N --random K [--ranges issue]` draws other humanoids
//! (from the item's own ranges with `--ranges issue`); `landmarks
//! FRONT.svg` prints one drawing's landmarks, regions and traced arms.

use pdesculpt::pipeline::corpus::{
    build_entry, build_entry_stretched, measure_entry, read_manifest, table, Entry, Manifest,
};
use pdesculpt::sketch::corpus::{document, page_position, Style};
use pdesculpt::sketch::figure::{Humanoid, HumanoidRanges};
use pdesculpt::sketch::figure_animal::{Quadruped, Tail};
use std::path::Path;

/// The corpus's seed and number of random humanoids (`write`'s defaults:
/// the committed corpus). Other seeds draw humanoids no one tuned on.
const CORPUS_SEED: u64 = 0x5EED_2028;
const CORPUS_RANDOM: usize = 9;
/// More random drawings than this is refused (each is two SVG files).
const MAX_RANDOM: usize = 1000;

/// splitmix64: a fixed-seed generator without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn named_humanoids() -> Vec<(&'static str, Humanoid)> {
    let d = Humanoid::default;
    vec![
        (
            "t_pose",
            Humanoid {
                arm_angle_deg: [0.0, 0.0],
                ..d()
            },
        ),
        (
            "near_t",
            Humanoid {
                arm_angle_deg: [15.0, 12.0],
                ..d()
            },
        ),
        (
            "a_pose",
            Humanoid {
                arm_angle_deg: [45.0, 45.0],
                ..d()
            },
        ),
        (
            "arms_low",
            Humanoid {
                arm_angle_deg: [75.0, 75.0],
                shoulder: 0.14,
                hip: 0.09,
                ..d()
            },
        ),
        (
            "arms_apart",
            Humanoid {
                arm_angle_deg: [10.0, 40.0],
                ..d()
            },
        ),
        (
            "legs_close",
            Humanoid {
                leg_gap: 0.016,
                ..d()
            },
        ),
        (
            "wide_stance",
            Humanoid {
                leg_gap: 0.08,
                stance: 0.06,
                ..d()
            },
        ),
        (
            "cartoon_head_half",
            Humanoid {
                head: 0.5,
                head_aspect: 0.9,
                crotch: 0.25,
                arm_length: 0.22,
                leg_radius: 0.045,
                shoulder: 0.13,
                ..d()
            },
        ),
        (
            "head_eighth",
            Humanoid {
                head: 0.125,
                crotch: 0.5,
                ..d()
            },
        ),
        (
            "chubby",
            Humanoid {
                waist: 0.14,
                hip: 0.15,
                shoulder: 0.16,
                arm_radius: 0.045,
                leg_radius: 0.07,
                leg_gap: 0.02,
                depth: 0.1,
                belly: 0.04,
                arm_angle_deg: [40.0, 40.0],
                arm_length: 0.34,
                ..d()
            },
        ),
        (
            "broad",
            Humanoid {
                shoulder: 0.17,
                waist: 0.1,
                hip: 0.105,
                arm_radius: 0.038,
                ..d()
            },
        ),
        (
            "thin_arms",
            Humanoid {
                arm_radius: 0.018,
                ..d()
            },
        ),
        (
            "child",
            Humanoid {
                head: 0.2,
                crotch: 0.42,
                shoulder: 0.12,
                arm_length: 0.33,
                ..d()
            },
        ),
        (
            "long_legs",
            Humanoid {
                crotch: 0.55,
                ..d()
            },
        ),
        (
            "short_legs",
            Humanoid {
                crotch: 0.36,
                ..d()
            },
        ),
    ]
}

fn animals() -> Vec<(&'static str, Quadruped)> {
    let dog = Quadruped::dog();
    vec![
        ("dog", dog.clone()),
        (
            "dog_tail_down_two_legs",
            Quadruped {
                tail: Tail::Down,
                visible_legs: 2,
                ..dog.clone()
            },
        ),
        (
            "horse",
            Quadruped {
                length: 2.0,
                body: 0.16,
                width: 0.12,
                legs: 0.42,
                leg_radius: [0.035, 0.04],
                neck: 0.3,
                neck_angle_deg: 60.0,
                head: 0.12,
                ..dog.clone()
            },
        ),
        (
            "cat",
            Quadruped {
                length: 0.45,
                body: 0.12,
                legs: 0.22,
                neck: 0.1,
                head: 0.12,
                tail: Tail::Up,
                ..dog.clone()
            },
        ),
        (
            "elephant",
            Quadruped {
                length: 3.0,
                body: 0.22,
                width: 0.18,
                legs: 0.3,
                leg_radius: [0.08, 0.085],
                back_leg_scale: 0.95,
                visible_legs: 2,
                neck: 0.05,
                neck_angle_deg: 20.0,
                head: 0.15,
                tail: Tail::None,
                trunk: true,
            },
        ),
    ]
}

/// Height as drawn (metres) for a style: the page's size, not a human's,
/// except for the centimetre style (a life-size drawing).
fn drawn_height(style: Style, rng: &mut Rng) -> f64 {
    match style {
        Style::InkscapeMm | Style::Inkscape092 | Style::Points => 0.12 + 0.12 * rng.next(),
        Style::PxNoViewBox => 0.15 + 0.1 * rng.next(),
        Style::Inches => 0.0254 * (5.0 + 4.0 * rng.next()),
        Style::Cm => 1.5 + 0.4 * rng.next(),
    }
}

fn write(dir: &Path, seed: u64, random: usize, ranges: &HumanoidRanges) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    let mut rng = Rng(seed);
    let mut entries = Vec::new();
    let mut figures: Vec<(
        String,
        String,
        Option<pdesculpt::sketch::figure::OutlinePair>,
        f64,
    )> = Vec::new();
    for (name, h) in named_humanoids() {
        figures.push((name.into(), describe(&h), h.outlines(), 0.6));
    }
    for k in 0..random {
        let u: [f64; 16] = std::array::from_fn(|_| rng.next());
        let h = ranges.at(&u, 1.0);
        figures.push((format!("random_{k}"), describe(&h), h.outlines(), 0.6));
    }
    for (name, q) in animals() {
        let what = format!("quadruped: {q:?}");
        figures.push((name.into(), what, q.outlines(), 2.0));
    }
    for (i, (name, what, outlines, aspect)) in figures.into_iter().enumerate() {
        let Some((front, side)) = outlines else {
            return Err(format!("{name}: the figure has no outline"));
        };
        let style = Style::ALL[i % Style::ALL.len()];
        let h = drawn_height(style, &mut rng);
        let (ff, sf) = (format!("{name}_front.svg"), format!("{name}_side.svg"));
        for (file, o, id, asp) in [(&ff, &front, "front", aspect), (&sf, &side, "side", 0.6)] {
            let at = page_position(style, h, asp, [rng.next(), rng.next()]);
            let knots = 400 + (rng.next() * 300.0) as usize;
            let text = document(style, o, h, at, knots, id);
            std::fs::write(dir.join(file), text).map_err(|e| e.to_string())?;
        }
        // every fifth asks for a height instead of the drawn size
        let height_m = (i % 5 == 2).then_some(1.75);
        entries.push(Entry {
            name: name.clone(),
            front: ff,
            side: sf,
            style: format!("{style:?}"),
            drawn_height_m: h,
            height_m,
            what,
            held_out: i % 3 == 2,
        });
    }
    let text = serde_json::to_string_pretty(&Manifest { entries }).map_err(|e| e.to_string())?;
    std::fs::write(dir.join("corpus.json"), text + "\n").map_err(|e| e.to_string())?;
    Ok(())
}

fn describe(h: &Humanoid) -> String {
    format!(
        "humanoid: arms {:.0}/{:.0} deg below horizontal, head {:.3} of the height, legs gap {:.3}, crotch {:.2}, shoulder {:.3}, waist {:.3}, hip {:.3}, arm radius {:.3}",
        h.arm_angle_deg[0], h.arm_angle_deg[1], h.head, h.leg_gap, h.crotch, h.shoulder, h.waist, h.hip, h.arm_radius
    )
}

fn measure(
    dir: &Path,
    all: bool,
    sheet: Option<&Path>,
    overlays: Option<&Path>,
    stretch: Option<f64>,
) -> Result<(), String> {
    let m = read_manifest(dir)?;
    if let Some(o) = overlays {
        std::fs::create_dir_all(o).map_err(|e| format!("--overlays {}: {e}", o.display()))?;
    }
    let mut rows = Vec::new();
    let mut images = Vec::new();
    for e in m.entries.iter().filter(|e| all || !e.held_out) {
        let t0 = std::time::Instant::now();
        let built = match stretch {
            None => build_entry(dir, e),
            Some(eps) => build_entry_stretched(dir, e, eps),
        };
        let row = measure_entry(e, &built);
        eprintln!(
            "{}: {} in {:.2} s",
            e.name,
            match &row.error {
                Some(err) => format!("error: {err}"),
                None => format!("passes {}", row.passed),
            },
            t0.elapsed().as_secs_f64()
        );
        if sheet.is_some() {
            images.push(contact(&built));
        }
        if let (Some(o), Ok(b)) = (overlays, &built) {
            let path = o.join(format!("{}.svg", e.name));
            pdesculpt::mesh::io::write_atomic(&path, b.overlay_svg().as_bytes())
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        rows.push(row);
    }
    print!("{}", table(&rows));
    if let Some(out) = sheet {
        let rows: Vec<pdesculpt::render::Image> = images
            .chunks(SHEET_COLUMNS)
            .map(|c| pdesculpt::render::Image::hstack(c, [255, 255, 255, 255]))
            .collect();
        grid(&rows).save_png(out).map_err(|e| e.to_string())?;
        eprintln!("wrote {}", out.display());
    }
    Ok(())
}

/// Tiles per row of the contact sheet.
const SHEET_COLUMNS: usize = 4;

/// Rows stacked vertically (each padded to the widest).
fn grid(rows: &[pdesculpt::render::Image]) -> pdesculpt::render::Image {
    let w = rows.iter().map(|r| r.width).max().unwrap_or(1);
    let h: usize = rows.iter().map(|r| r.height).sum();
    let mut out = pdesculpt::render::Image::new(w, h.max(1), [255, 255, 255, 255]);
    let mut y0 = 0;
    for r in rows {
        for y in 0..r.height {
            for x in 0..r.width {
                out.put(x as i64, (y0 + y) as i64, r.get(x, y));
            }
        }
        y0 += r.height;
    }
    out
}

/// A tile: the model's front and side renders (pink when it fails).
fn contact(
    built: &Result<pdesculpt::pipeline::Built, pdesculpt::pipeline::BuildError>,
) -> pdesculpt::render::Image {
    use pdesculpt::render::View;
    let o = pdesculpt::render::RenderOptions::default()
        .with_width(160)
        .with_height(240);
    match built {
        Ok(b) => {
            let drawn = drawing_tile(b.front.points(), o.width, o.height);
            let model =
                pdesculpt::render::render_views(&b.model.mesh, &[View::Front, View::Side], &o);
            pdesculpt::render::Image::hstack(&[drawn, model], [255, 255, 255, 255])
        }
        Err(_) => pdesculpt::render::Image::new(3 * o.width, o.height, [255, 200, 200, 255]),
    }
}

/// The drawn outline filled in grey, fitted to a `w` x `h` tile (even-odd
/// scanlines through pixel centres).
fn drawing_tile(p: &[[f64; 2]], w: usize, h: usize) -> pdesculpt::render::Image {
    let mut img = pdesculpt::render::Image::new(w, h, [255, 255, 255, 255]);
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for q in p {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    let s = 0.9 * (w as f64 / (hi[0] - lo[0])).min(h as f64 / (hi[1] - lo[1]));
    let (cx, cy) = (0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]));
    for j in 0..h {
        let y = cy + (0.5 * h as f64 - (j as f64 + 0.5)) / s;
        let mut xs: Vec<f64> = Vec::new();
        for i in 0..p.len() {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            if (a[1] > y) != (b[1] > y) {
                xs.push(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
            }
        }
        xs.sort_by(f64::total_cmp);
        for pair in xs.chunks(2) {
            if let [x0, x1] = pair {
                let (i0, i1) = (
                    ((x0 - cx) * s + 0.5 * w as f64).round() as i64,
                    ((x1 - cx) * s + 0.5 * w as f64).round() as i64,
                );
                for i in i0..i1 {
                    img.put(i, j as i64, [150, 150, 150, 255]);
                }
            }
        }
    }
    img
}

/// Prints a front drawing's landmarks and traced arms (a diagnostic).
fn landmarks(front: &Path) -> Result<(), String> {
    use pdesculpt::character::doc::ProfileInput;
    use pdesculpt::profile::View;
    use pdesculpt::sketch::input::read_profile;
    let o = read_profile(
        &ProfileInput::Path(front.display().to_string()),
        Path::new("."),
        View::Front,
        None,
    )
    .map_err(|e| e.to_string())?;
    let p = pdesculpt::sketch::place::place(&o, None, None, Default::default())
        .map_err(|e| e.to_string())?;
    let tops = pdesculpt::sketch::poly::gap_tops(
        p.front.points(),
        pdesculpt::sketch::segment::LANDMARK_SLICES,
    );
    println!("gap tops {tops:?}");
    println!(
        "as an animal: {:?}",
        pdesculpt::sketch::quadruped::landmarks(p.front.points())
    );
    let lm = pdesculpt::sketch::segment::landmarks(p.front.points()).map_err(|e| e.to_string())?;
    println!("{lm:?}");
    match pdesculpt::sketch::segment::regions(p.front.points(), &lm, &Default::default()) {
        Ok(rs) => rs
            .iter()
            .for_each(|r| println!("region {} y {:.4}..{:.4} {:?}", r.name, r.y0, r.y1, r.pick)),
        Err(e) => println!("regions: {e}"),
    }
    let neck = pdesculpt::sketch::segment::neck_interval(p.front.points(), &lm);
    println!("neck {neck:?}");
    for (a, side) in [(lm.armpit_l, -1.0), (lm.armpit_r, 1.0)] {
        let nx = neck.map_or(0.0, |n| if side < 0.0 { n[0] } else { n[1] });
        match pdesculpt::sketch::limb::trace_arm(p.front.points(), a, side, nx, "arm") {
            Ok(t) => println!(
                "armpit {:?} shoulder {:?} tip {:?}",
                t.armpit, t.shoulder, t.tip
            ),
            Err(e) => println!("{e}"),
        }
    }
    Ok(())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let r = match args.first().map(String::as_str) {
        Some("write") if args.len() >= 2 => {
            let flag = |name: &str, default: u64| -> Result<u64, String> {
                match args.iter().position(|a| a == name) {
                    None => Ok(default),
                    Some(i) => {
                        let v = args.get(i + 1).ok_or(format!("{name} needs a value"))?;
                        v.parse::<u64>().map_err(|e| format!("{name} {v}: {e}"))
                    }
                }
            };
            let seed = flag("--seed", CORPUS_SEED);
            let random = flag("--random", CORPUS_RANDOM as u64).and_then(|k| {
                if k <= MAX_RANDOM as u64 {
                    Ok(k as usize)
                } else {
                    Err(format!("--random {k}: at most {MAX_RANDOM} drawings"))
                }
            });
            let ranges = match args.iter().position(|a| a == "--ranges") {
                None => Ok(&HumanoidRanges::WIDE),
                Some(i) => match args.get(i + 1).map(String::as_str) {
                    Some("wide") => Ok(&HumanoidRanges::WIDE),
                    Some("issue") => Ok(&HumanoidRanges::ISSUE),
                    Some(other) => Err(format!("--ranges {other}: expected wide or issue")),
                    None => Err("--ranges needs a value (wide or issue)".into()),
                },
            };
            seed.and_then(|s| {
                random.and_then(|k| ranges.and_then(|r| write(Path::new(&args[1]), s, k, r)))
            })
        }
        Some("measure") if args.len() >= 2 => {
            let all = args.iter().any(|a| a == "--all");
            let sheet = args
                .iter()
                .position(|a| a == "--sheet")
                .and_then(|i| args.get(i + 1))
                .map(Path::new);
            let overlays = args
                .iter()
                .position(|a| a == "--overlays")
                .and_then(|i| args.get(i + 1))
                .map(Path::new);
            let stretch = args
                .iter()
                .position(|a| a == "--stretch-x")
                .and_then(|i| args.get(i + 1))
                .map(|v| v.parse::<f64>().map_err(|e| format!("--stretch-x {v}: {e}")))
                .transpose();
            stretch.and_then(|stretch| measure(Path::new(&args[1]), all, sheet, overlays, stretch))
        }
        Some("landmarks") if args.len() >= 2 => landmarks(Path::new(&args[1])),
        _ => Err("usage: sketch_corpus write DIR [--seed N] [--random K] [--ranges wide|issue] | measure DIR [--all] [--sheet OUT.png] [--overlays OUT_DIR] [--stretch-x EPS] | landmarks FRONT.svg".into()),
    };
    if let Err(e) = r {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}
