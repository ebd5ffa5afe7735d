//! Integration tests: one binary (fast links), one module per area.

mod cli;
mod infra;
mod registry;
mod strategies;

mod conv;
mod gec;
mod ode6;
mod pde4;
mod pde6;
mod plate;
mod profile;
mod template;
