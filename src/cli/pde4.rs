//! `pdesculpt pde4` (not implemented yet).

/// Arguments of `pdesculpt pde4`.
#[derive(clap::Args, Debug)]
pub struct Args {}

/// Runs `pdesculpt pde4`.
pub fn run(_args: Args, _json: bool) -> anyhow::Result<i32> {
    anyhow::bail!("'pdesculpt pde4' is not implemented yet")
}
