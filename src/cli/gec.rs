//! `pdesculpt gec` (not implemented yet).

/// Arguments of `pdesculpt gec`.
#[derive(clap::Args, Debug)]
pub struct Args {}

/// Runs `pdesculpt gec`.
pub fn run(_args: Args, _json: bool) -> anyhow::Result<i32> {
    anyhow::bail!("'pdesculpt gec' is not implemented yet")
}
