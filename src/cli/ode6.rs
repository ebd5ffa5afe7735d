//! `pdesculpt ode6` (not implemented yet).

/// Arguments of `pdesculpt ode6`.
#[derive(clap::Args, Debug)]
pub struct Args {}

/// Runs `pdesculpt ode6`.
pub fn run(_args: Args, _json: bool) -> anyhow::Result<i32> {
    anyhow::bail!("'pdesculpt ode6' is not implemented yet")
}
