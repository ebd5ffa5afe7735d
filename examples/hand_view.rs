//! Renders one hand of the closed body (top row) above the skin's (bottom
//! row), both cropped to the box of the hand, thumb and wrist transition
//! (padded), in four views; prints the hand reports and the wrist
//! transitions' crossing triangles (index within the transition's group):
//! `cargo run --release --example hand_view -- OUT.png [r|l] [MORPH=W ...]`.
use pdesculpt::body::closed::{load_body, reconstruct_closed, ClosedOptions};
use pdesculpt::mesh::Mesh;
use pdesculpt::render::{render_views, Image, RenderOptions};

fn crop(m: &Mesh, lo: [f64; 3], hi: [f64; 3]) -> Mesh {
    let mut out = m.clone();
    let keep: Vec<usize> = (0..m.triangles.len())
        .filter(|&t| {
            m.triangles[t].iter().all(|&v| {
                let p = m.positions[v as usize];
                (0..3).all(|k| p[k] >= lo[k] && p[k] <= hi[k])
            })
        })
        .collect();
    out.triangles = keep.iter().map(|&t| m.triangles[t]).collect();
    out.tri_group = keep
        .iter()
        .map(|&t| m.tri_group.get(t).copied().unwrap_or(0))
        .collect();
    let mut map = vec![u32::MAX; m.positions.len()];
    out.positions.clear();
    for t in out.triangles.iter_mut() {
        for v in t.iter_mut() {
            if map[*v as usize] == u32::MAX {
                map[*v as usize] = out.positions.len() as u32;
                out.positions.push(m.positions[*v as usize]);
            }
            *v = map[*v as usize];
        }
    }
    out
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let out = std::path::PathBuf::from(&args[0]);
    let side = args.get(1).cloned().unwrap_or_else(|| "r".into());
    let morphs: Vec<String> = args.iter().skip(2).cloned().collect();
    let skin = load_body(None, &morphs).unwrap();
    let b = reconstruct_closed(&skin, &ClosedOptions::default()).unwrap();
    let m = &b.model.mesh;
    let names = [
        format!("hand_{side}"),
        format!("thumb_{side}"),
        format!("wrist_{side}"),
    ];
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for (t, tri) in m.triangles.iter().enumerate() {
        let g = &m.groups[m.tri_group[t] as usize];
        if names.contains(g) {
            for &v in tri {
                let p = m.positions[v as usize];
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
    }
    let pad = 0.25 * (hi[1] - lo[1]);
    for k in 0..3 {
        lo[k] -= pad;
        hi[k] += pad;
    }
    let r = crop(m, lo, hi);
    let s = crop(&skin, lo, hi);
    use pdesculpt::render::View;
    let views = vec![
        View::Front,
        View::Side,
        View::Perspective {
            yaw: 60.0,
            pitch: 20.0,
        },
        View::Perspective {
            yaw: -120.0,
            pitch: 10.0,
        },
    ];
    let o = RenderOptions::default().with_width(360).with_height(360);
    let a = render_views(&r, &views, &o);
    let c = render_views(&s, &views, &o);
    let img = Image::new(a.width, a.height + c.height, [255, 255, 255, 255]);
    let mut img = img;
    for y in 0..a.height {
        for x in 0..a.width {
            img.put(x as i64, y as i64, a.get(x, y));
            img.put(x as i64, (y + a.height) as i64, c.get(x, y));
        }
    }
    img.save_png(&out).unwrap();
    println!("{:?}", b.report.hands);
    let pairs = pdesculpt::body::intersect::crossing_pairs(m);
    for tr in &b.transitions {
        if !tr.name.starts_with("wrist") {
            continue;
        }
        let g = m.groups.iter().position(|x| *x == tr.name).unwrap() as u32;
        let first = m.tri_group.iter().position(|&x| x == g).unwrap();
        let cts: Vec<usize> = b
            .model
            .parts
            .iter()
            .filter(|p| tr.children.contains(&p.name))
            .map(|_| 0)
            .collect();
        let _ = cts;
        for &(a, c, x) in &pairs {
            for t in [a, c] {
                if m.tri_group[t] == g {
                    let loc = t - first;
                    println!(
                        "{} tri {} local {} (band {}?) other group {} at {:?}",
                        tr.name,
                        t,
                        loc,
                        loc,
                        m.groups[m.tri_group[if t == a { c } else { a }] as usize],
                        x
                    );
                }
            }
        }
    }
    println!(
        "crossings {} {:?}",
        b.report.self_intersections.pairs, b.report.self_intersections.by_groups
    );
}
