//! `pdesculpt pde6` (not implemented yet).

/// Arguments of `pdesculpt pde6`.
#[derive(clap::Args, Debug)]
pub struct Args {}

/// Runs `pdesculpt pde6`.
pub fn run(_args: Args, _json: bool) -> anyhow::Result<i32> {
    anyhow::bail!("'pdesculpt pde6' is not implemented yet")
}
