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
            // progress: the figures' own lines go to stderr, so the count
            // is a line per figure rather than a redrawn bar
            for (k, f) in figures.iter().enumerate() {
                eprintln!("== figure {}/{}", k + 1, figures.len());
                ctx.run(f)?;
            }
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
