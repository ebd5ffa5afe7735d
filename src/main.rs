//! The `pdesculpt` command line. One file per subcommand under `src/cli/`.

mod cli;

fn main() {
    std::process::exit(cli::main());
}
