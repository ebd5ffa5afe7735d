//! `pdesculpt character build|edit|undo|redo|log`.

use pdesculpt::character::doc::CharacterDoc;
use pdesculpt::character::log::Edit;
use pdesculpt::character::Resolution;
use pdesculpt::mesh::io;
use pdesculpt::pipeline::build_document;
use pdesculpt::pipeline::push_checked;
use std::path::{Path, PathBuf};

/// Arguments of `pdesculpt character`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(subcommand)]
    pub command: Sub,
}

/// Character subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Sub {
    /// Build a character document into a mesh (OBJ/GLB/STL/PLY, one group
    /// per part and transition). Stored parts are built as they are; a
    /// document without parts is derived from its inputs at its level. The
    /// active edits of the log are replayed.
    Build {
        /// The character document (JSON, version 1; schema in the docs of
        /// `pdesculpt::character::doc`).
        doc: PathBuf,
        /// Output mesh (.obj, .glb, .stl, .ply).
        #[arg(short, long)]
        output: PathBuf,
        /// Also save the document with its derived parts filled in.
        #[arg(long)]
        save_doc: Option<PathBuf>,
    },
    /// Append one edit (validated first) to the document's log, dropping
    /// the redo tail; saves the document atomically.
    Edit {
        /// The character document (must have stored parts).
        doc: PathBuf,
        /// A JSON file holding one edit, e.g.
        /// {"op": "shape_parameter", "part": "torso", "a": 0.3}.
        #[arg(long)]
        op: PathBuf,
        /// For a `force_stroke` op: a closed stroke drawn in a view, JSON
        /// {"view": "front", "points": [[x, y], ...]} (model units), projected
        /// onto the op's part; it replaces the op's "stroke".
        #[arg(long)]
        drawn: Option<PathBuf>,
    },
    /// Undo the last active edit (moves the log's cursor back).
    Undo { doc: PathBuf },
    /// Redo the next undone edit (moves the log's cursor forward).
    Redo { doc: PathBuf },
    /// Print the edit log (`*` marks active edits).
    Log { doc: PathBuf },
}

fn read_edit(path: &Path) -> anyhow::Result<Edit> {
    let text =
        std::fs::read_to_string(path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| anyhow::anyhow!("{}: not an edit: {e}", path.display()))
}

fn print_log(d: &CharacterDoc, json: bool) -> anyhow::Result<()> {
    if json {
        let v = serde_json::json!({
            "cursor": d.cursor,
            "edits": d.edits.iter().enumerate().map(|(i, e)| serde_json::json!({
                "index": i,
                "active": i < d.cursor,
                "summary": e.summary(),
                "edit": e,
            })).collect::<Vec<_>>(),
        });
        super::print_json(&v)?;
    } else {
        for (i, e) in d.edits.iter().enumerate() {
            let mark = if i < d.cursor { '*' } else { ' ' };
            println!("{mark} {i:3} {}", e.summary());
        }
        println!("{} edits, {} active", d.edits.len(), d.cursor);
    }
    Ok(())
}

/// Runs `character`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Sub::Build {
            doc,
            output,
            save_doc,
        } => {
            io::Format::from_path(&output)?;
            let d = CharacterDoc::load(&doc)?;
            let base = doc.parent().map(PathBuf::from).unwrap_or_default();
            let built = build_document(&d, &base, Resolution::default(), false)?;
            if let Some(p) = &save_doc {
                built.doc.save(p)?;
                eprintln!("wrote {}", p.display());
            }
            super::sketch::finish(&built, &output, json)
        }
        Sub::Edit { doc, op, drawn } => {
            let mut d = CharacterDoc::load(&doc)?;
            let mut e = read_edit(&op)?;
            if let Some(p) = &drawn {
                let text = std::fs::read_to_string(p)
                    .map_err(|err| anyhow::anyhow!("{}: {err}", p.display()))?;
                let s: pdesculpt::sasm::Stroke = serde_json::from_str(&text)
                    .map_err(|err| anyhow::anyhow!("{}: not a drawn stroke: {err}", p.display()))?;
                pdesculpt::pipeline::project_force_stroke(&d, &mut e, &s)?;
            }
            let summary = e.summary();
            let base = doc.parent().map(PathBuf::from).unwrap_or_default();
            push_checked(&mut d, e, &base)?;
            d.save(&doc)?;
            eprintln!("edit {}: {summary}", d.cursor - 1);
            if json {
                print_log(&d, true)?;
            }
            Ok(0)
        }
        Sub::Undo { doc } => step(&doc, json, true),
        Sub::Redo { doc } => step(&doc, json, false),
        Sub::Log { doc } => {
            print_log(&CharacterDoc::load(&doc)?, json)?;
            Ok(0)
        }
    }
}

fn step(doc: &Path, json: bool, undo: bool) -> anyhow::Result<i32> {
    let mut d = CharacterDoc::load(doc)?;
    if undo {
        d.undo()?;
    } else {
        d.redo()?;
    }
    d.save(doc)?;
    eprintln!(
        "{} edit {}: {} edits active",
        if undo { "undid" } else { "redid" },
        if undo { d.cursor } else { d.cursor - 1 },
        d.cursor
    );
    if json {
        print_log(&d, true)?;
    }
    Ok(0)
}
