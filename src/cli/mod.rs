//! Subcommands. Conventions: machine output (`--json`) on stdout, progress
//! and logs on stderr, errors as `error: ...` on stderr with exit code 1
//! (2 for usage errors, from clap).

mod convert;
mod demo;
mod outputs;
mod render;
mod units;

mod character;
mod sketch;
mod study;
mod verify;

mod conv;
mod gec;
mod ode6;
mod pde4;
mod pde6;
mod plate;
mod profile;
mod template;
mod tui;

use clap::{Parser, Subcommand};

/// pdesculpt: PDE and ODE surfaces for 3D characters, verified equation by
/// equation.
#[derive(Parser, Debug)]
#[command(name = "pdesculpt", version, about, long_about = None)]
pub struct Cli {
    /// Print machine-readable JSON on stdout.
    #[arg(long, global = true)]
    pub json: bool,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Run the verification checks of every equation family.
    Verify(verify::Args),
    /// Run a study: an experiment over many inputs (every checked body, the template study's cases, the data-size table).
    Study(study::Args),
    /// Render a mesh to a PNG preview.
    Render(render::Args),
    /// Convert a mesh between OBJ, GLB, glTF, STL and PLY (models and parts kept).
    Convert(convert::Args),
    /// Build the demo character from bundled data into out/.
    Demo(demo::Args),
    /// Generalized elliptic curves (papers 000, 002).
    Gec(gec::Args),
    /// Fourth-order PDE sculpting deformations (paper 000).
    Pde4(pde4::Args),
    /// C1 plate-bending deformation of mesh regions (paper 001).
    Plate(plate::Args),
    /// C2 sixth-order PDE patches (paper 002).
    Pde6(pde6::Args),
    /// C2 sixth-order ODE surfaces (paper 004).
    Ode6(ode6::Args),
    /// Convolution surfaces from sketched silhouettes (paper 003).
    Conv(conv::Args),
    /// Characters from sketched profiles (paper 000 sec 4.1).
    Sketch(sketch::Args),
    /// Character documents: build, and the edit log (edit, undo, redo, log).
    Character(character::Args),
    /// Template-based global modeling: fit a template to sketched profiles (paper 000 sec 4.2).
    Template(template::Args),
    /// Closed outlines of a view: mesh outlines and sketch checks (paper 000).
    Profile(profile::Args),
    /// Terminal UI to assemble and edit a character document (issue 14).
    Tui(tui::Args),
}

/// Parses the arguments, runs the command, returns the exit code.
pub fn main() -> i32 {
    let cli = Cli::parse();
    let json = cli.json;
    let result = match cli.command {
        Command::Verify(a) => verify::run(a, json),
        Command::Study(a) => study::run(a, json),
        Command::Render(a) => render::run(a, json),
        Command::Convert(a) => convert::run(a, json),
        Command::Demo(a) => demo::run(a, json),
        Command::Gec(a) => gec::run(a, json),
        Command::Pde4(a) => pde4::run(a, json),
        Command::Plate(a) => plate::run(a, json),
        Command::Pde6(a) => pde6::run(a, json),
        Command::Ode6(a) => ode6::run(a, json),
        Command::Conv(a) => conv::run(a, json),
        Command::Sketch(a) => sketch::run(a, json),
        Command::Character(a) => character::run(a, json),
        Command::Template(a) => template::run(a, json),
        Command::Profile(a) => profile::run(a, json),
        Command::Tui(a) => tui::run(a, json),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {}", error_message(&e));
            1
        }
    }
}

/// The error and its causes on one line, each cause once: library errors
/// often already carry their source in their own message (`{path}: {source}`),
/// so a cause whose text the line already holds is not repeated.
fn error_message(e: &anyhow::Error) -> String {
    let mut msg = e.to_string();
    for cause in e.chain().skip(1) {
        let c = cause.to_string();
        if !msg.contains(&c) {
            msg.push_str(": ");
            msg.push_str(&c);
        }
    }
    msg
}

/// Prints a serialisable value as pretty JSON on stdout.
pub fn print_json<T: serde::Serialize>(v: &T) -> anyhow::Result<()> {
    println!("{}", serde_json::to_string_pretty(v)?);
    Ok(())
}
