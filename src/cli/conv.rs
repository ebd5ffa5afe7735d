//! `pdesculpt conv` (not implemented yet).

/// Arguments of `pdesculpt conv`.
#[derive(clap::Args, Debug)]
pub struct Args {}

/// Runs `pdesculpt conv`.
pub fn run(_args: Args, _json: bool) -> anyhow::Result<i32> {
    anyhow::bail!("'pdesculpt conv' is not implemented yet")
}
