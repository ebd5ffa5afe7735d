//! `pdesculpt character build CHAR.json -o OUT [--json]`.

use pdesculpt::character::doc::CharacterDoc;
use pdesculpt::mesh::io;
use pdesculpt::sketch::{build_document, Resolution};
use std::path::PathBuf;

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
    /// document without parts is derived from its inputs at its level.
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
    }
}
