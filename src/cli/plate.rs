//! `pdesculpt plate` (not implemented yet).

/// Arguments of `pdesculpt plate`.
#[derive(clap::Args, Debug)]
pub struct Args {}

/// Runs `pdesculpt plate`.
pub fn run(_args: Args, _json: bool) -> anyhow::Result<i32> {
    anyhow::bail!("'pdesculpt plate' is not implemented yet")
}
