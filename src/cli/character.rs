//! `pdesculpt character build|edit|undo|redo|log`.

use super::outputs::{self, LOCK_WAIT};
use pdesculpt::character::doc::CharacterDoc;
use pdesculpt::character::log::Edit;
use pdesculpt::character::Resolution;
use pdesculpt::mesh::io;
use pdesculpt::pipeline::build_document;
use pdesculpt::pipeline::{push_checked, redo_checked, BuildOptions};
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
        /// Output mesh (.obj, .glb, .gltf, .stl, .ply): one node/object
        /// per part, transition, removed part and prop.
        #[arg(short, long)]
        output: PathBuf,
        #[command(flatten)]
        layout: super::units::LayoutArgs,
        /// Also save the document with its derived parts filled in.
        #[arg(long)]
        save_doc: Option<PathBuf>,
        /// Also write a picture (SVG) of where the model misses its
        /// drawings: per view, the drawn outline in red, the model's in
        /// blue, the largest miss circled.
        #[arg(long)]
        overlay: Option<PathBuf>,
    },
    /// Append one edit to the document's log, dropping the redo tail: the
    /// document with the edit is built once and kept only when that build
    /// succeeds with finite geometry; saves that build's document atomically.
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
    let text = io::read_input_text(path, "edit")?;
    serde_json::from_str(&text).map_err(|e| anyhow::anyhow!("{}: not an edit: {e}", path.display()))
}

/// The files a document reads (profiles, removed parts' profiles, props'
/// models), resolved against the document's directory, for the output
/// checks.
fn doc_inputs(d: &CharacterDoc, doc: &Path) -> Vec<PathBuf> {
    use pdesculpt::character::doc::ProfileInput;
    let mut out = Vec::new();
    let mut profile = |p: &ProfileInput| {
        if let ProfileInput::Path(s) = p {
            out.push(CharacterDoc::resolve(doc, s));
        }
    };
    profile(&d.inputs().front);
    if let Some(s) = &d.inputs().side {
        profile(s);
    }
    for r in d.removed_parts() {
        profile(&r.front);
        if let Some(s) = &r.side {
            profile(s);
        }
    }
    out.extend(
        d.props()
            .iter()
            .map(|p| CharacterDoc::resolve(doc, &p.model)),
    );
    out
}

fn print_log(d: &CharacterDoc, json: bool) -> anyhow::Result<()> {
    if json {
        let v = serde_json::json!({
            "cursor": d.cursor(),
            "edits": d.edits().iter().enumerate().map(|(i, e)| serde_json::json!({
                "index": i,
                "active": i < d.cursor(),
                "summary": e.summary(),
                "edit": e,
            })).collect::<Vec<_>>(),
        });
        super::print_json(&v)?;
    } else {
        for (i, e) in d.edits().iter().enumerate() {
            let mark = if i < d.cursor() { '*' } else { ' ' };
            println!("{mark} {i:3} {}", e.summary());
        }
        println!("{} edits, {} active", d.edits().len(), d.cursor());
    }
    Ok(())
}

/// Runs `character`.
pub fn run(args: Args, json: bool) -> anyhow::Result<i32> {
    match args.command {
        Sub::Build {
            doc,
            output,
            layout,
            save_doc,
            overlay,
        } => {
            io::Format::from_path(&output)?;
            if let Some(p) = &save_doc {
                outputs::doc_output("--save-doc", p)?;
            }
            if let Some(p) = &overlay {
                outputs::svg_output("--overlay", p)?;
            }
            // saving the derived parts into the document itself is the
            // documented way to store them: that one file is locked, read
            // whole, and replaced atomically
            let lock = match &save_doc {
                Some(p) if io::same_file(p, &doc) => Some(io::FileLock::acquire(&doc, LOCK_WAIT)?),
                _ => None,
            };
            let d = CharacterDoc::load(&doc)?;
            let read = doc_inputs(&d, &doc);
            let mut inputs: Vec<(&str, &Path)> = read
                .iter()
                .map(|p| ("file of the document", p.as_path()))
                .collect();
            if lock.is_none() {
                inputs.push(("DOC", &doc));
            }
            let mut outs: Vec<(&str, &Path)> = vec![("-o", &output)];
            if let Some(p) = &save_doc {
                outs.push(("--save-doc", p));
            }
            if let Some(p) = &overlay {
                outs.push(("--overlay", p));
            }
            outputs::check(&inputs, &outs)?;
            let base = doc.parent().map(PathBuf::from).unwrap_or_default();
            let progress = pdesculpt::progress::Progress::spinner("character build", json);
            let built = build_document(&d, &base, Resolution::default(), false)?;
            progress.finish();
            if let Some(l) = &lock {
                if !l.unchanged() {
                    anyhow::bail!("{}: the document was replaced by another program during the build; nothing written: run it again", doc.display());
                }
            }
            let with_doc = save_doc.as_deref().map(|p| (&built.doc, p));
            let overlay = overlay.as_deref().map(|p| (p, built.overlay_svg()));
            outputs::write_mesh_and_doc(
                &built.model.mesh,
                &output,
                layout.layout(),
                with_doc,
                overlay,
            )?;
            super::sketch::report(&built, &output, json)
        }
        Sub::Edit { doc, op, drawn } => {
            // one editor at a time: a second waits, then edits the result
            let lock = io::FileLock::acquire(&doc, LOCK_WAIT)?;
            let mut d = CharacterDoc::load(&doc)?;
            let mut e = read_edit(&op)?;
            if let Some(p) = &drawn {
                let text = io::read_input_text(p, "drawn stroke")
                    .map_err(|err| anyhow::anyhow!("{}: {err}", p.display()))?;
                let s: pdesculpt::sasm::Stroke = serde_json::from_str(&text)
                    .map_err(|err| anyhow::anyhow!("{}: not a drawn stroke: {err}", p.display()))?;
                pdesculpt::pipeline::project_force_stroke(&d, &mut e, &s)?;
            }
            let summary = e.summary();
            let base = doc.parent().map(PathBuf::from).unwrap_or_default();
            // the document with the edit built once; that document is saved
            push_checked(&mut d, e, &BuildOptions::new(&base), None)?;
            outputs::save_locked(&d, &doc, &lock)?;
            eprintln!("edit {}: {summary}", d.cursor() - 1);
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
    let lock = io::FileLock::acquire(doc, LOCK_WAIT)?;
    let mut d = CharacterDoc::load(doc)?;
    if undo {
        d.undo()?;
    } else {
        // the edit re-applied is validated by its effect, as when pushed
        let base = doc.parent().map(PathBuf::from).unwrap_or_default();
        redo_checked(&mut d, &BuildOptions::new(&base), None)?;
    }
    outputs::save_locked(&d, doc, &lock)?;
    eprintln!(
        "{} edit {}: {} edits active",
        if undo { "undid" } else { "redid" },
        if undo { d.cursor() } else { d.cursor() - 1 },
        d.cursor()
    );
    if json {
        print_log(&d, true)?;
    }
    Ok(0)
}
