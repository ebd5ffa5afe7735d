//! Regenerates the papers' figures and tables: `cargo run --release -p
//! paper_figures -- list | all | <id or paper>...` (a paper number such as
//! `001` selects all of that paper's figures). Each figure writes its images
//! (PNG/SVG) and a data JSON beside them into `paper_figures/out/` (or
//! `--out DIR`), and records the checks it relied on. `all` (and `gallery`,
//! which uses whatever is already in the output directory) also writes the
//! gallery page `index.html` (see `gallery.rs`).

mod body_study;
mod common;

mod conv;
mod edit;
mod gallery;
mod gec;
mod ode6;
mod pde4;
mod pde6;
mod plate;
mod sasm;
mod sketch;
mod template;
mod thumbnails;

use common::{Ctx, Figure};

fn all_figures() -> Vec<Figure> {
    let mut v = Vec::new();
    v.extend(gec::figures());
    v.extend(body_study::figures());
    v.extend(pde4::figures());
    v.extend(plate::figures());
    v.extend(pde6::figures());
    v.extend(ode6::figures());
    v.extend(conv::figures());
    v.extend(sketch::figures());
    v.extend(template::figures());
    v.extend(sasm::figures());
    v.extend(edit::figures());
    v.extend(gallery::figures());
    v
}

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e:#}");
        std::process::exit(1);
    }
}

/// Runs every registered check (`verify --json`'s rows) and writes the
/// gallery page for the files in the output directory.
fn write_gallery(ctx: &Ctx, figures: &[Figure]) -> anyhow::Result<()> {
    let t = std::time::Instant::now();
    let checks = pdesculpt::verify::run(None);
    eprintln!(
        "[gallery] {} checks in {:.1} s",
        checks.len(),
        t.elapsed().as_secs_f64()
    );
    let p = gallery::write_index(ctx, figures, &checks)?;
    eprintln!("[gallery] open {}", p.display());
    Ok(())
}

/// Runs every figure, on as many threads as the machine has cores: the
/// figures are independent (each writes its own files and reads none of
/// another's), and most of them run on one core, so on CI's two cores this
/// about halves the step (docs/test-time.md). Progress goes to stderr a
/// line per figure (their own lines, prefixed with their id, interleave).
/// Every figure runs even when one fails; the first failure in the
/// figures' order is the error. The figures of [`START_FIRST`] start
/// first, the rest in their listed order.
fn run_all(ctx: &Ctx, figures: &[Figure]) -> anyhow::Result<()> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Mutex;
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, figures.len().max(1));
    let order = start_order(figures);
    let next = AtomicUsize::new(0);
    let failed: Mutex<Vec<(usize, anyhow::Error)>> = Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                while let Some(&k) = order.get(next.fetch_add(1, Ordering::Relaxed)) {
                    let f = &figures[k];
                    eprintln!("== figure {}/{} ({})", k + 1, figures.len(), f.id);
                    if let Err(e) = ctx.run(f) {
                        eprintln!("[{}] failed: {e:#}", f.id);
                        failed
                            .lock()
                            .unwrap_or_else(|p| p.into_inner())
                            .push((k, e));
                    }
                }
            });
        }
    });
    let mut failed = failed.into_inner().unwrap_or_else(|p| p.into_inner());
    failed.sort_by_key(|(k, _)| *k);
    match failed.into_iter().next() {
        Some((_, e)) => Err(e),
        None => Ok(()),
    }
}

/// Figures that alone take most of what all the others take on one core:
/// `003-polygonizers` ran 89.5 s of the 143.9 s two-thread step in CI's
/// dev profile (the others 140 s of CPU together), and listed 37th it
/// started when the other core had little left to do. Started first, the
/// other core works through the rest meanwhile (docs/test-time.md).
const START_FIRST: &[&str] = &["003-polygonizers"];

/// The indices of `figures` in the order `all` starts them.
fn start_order(figures: &[Figure]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..figures.len()).collect();
    order.sort_by_key(|&k| !START_FIRST.contains(&figures[k].id));
    order
}

fn run() -> anyhow::Result<()> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut out = std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/out"));
    if let Some(i) = args.iter().position(|a| a == "--out") {
        if i + 1 >= args.len() {
            anyhow::bail!("--out needs a directory");
        }
        out = args.remove(i + 1).into();
        args.remove(i);
    }
    let figures = all_figures();
    let ctx = Ctx::new(out)?;
    match args.first().map(String::as_str) {
        None | Some("list") | Some("--help") | Some("-h") => {
            println!(
                "usage: paper_figures [--out DIR] list | all | gallery | thumbnails [DEMO_DIR] | <id or paper number, e.g. 001>..."
            );
            for f in &figures {
                println!("{:<24} paper {}  {}", f.id, f.paper, f.title);
            }
            Ok(())
        }
        Some("all") => {
            run_all(&ctx, &figures)?;
            write_gallery(&ctx, &figures)
        }
        Some("gallery") => write_gallery(&ctx, &figures),
        // small copies of a few figures and of the demo picture (from
        // DEMO_DIR, default out/) for the repository's docs/img/
        Some("thumbnails") => {
            let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
            let demo = args
                .get(1)
                .map_or(root.join("out"), std::path::PathBuf::from);
            thumbnails::write(&ctx.out, &demo, &root.join("docs"))
        }
        Some(_) => {
            for id in &args {
                let chosen: Vec<&Figure> = figures
                    .iter()
                    .filter(|f| f.id == id || f.paper == id)
                    .collect();
                if chosen.is_empty() {
                    anyhow::bail!("unknown figure or paper {id:?}; try 'list'");
                }
                for f in chosen {
                    ctx.run(f)?;
                }
            }
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_figures_started_first_exist_and_start_first() {
        let figures = all_figures();
        let order = start_order(&figures);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..figures.len()).collect::<Vec<_>>());
        for (i, id) in START_FIRST.iter().enumerate() {
            assert_eq!(
                figures[order[i]].id, *id,
                "{id} is not a figure or not started first"
            );
        }
        // the rest keep their listed order
        let rest: Vec<usize> = order[START_FIRST.len()..].to_vec();
        assert!(rest.windows(2).all(|w| w[0] < w[1]));
    }
}
