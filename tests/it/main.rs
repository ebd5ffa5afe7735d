//! Integration tests: one binary (fast links), one module per area.

mod cli;
mod fuzz;
mod fuzz_harness;
mod infra;
mod layers;
mod registry;
mod strategies;
mod tolerances;
mod units;

mod body;
mod body_shoulders;
mod body_thumb;
mod conv;
mod edit;
mod edit_stroke;
mod gec;
mod gec_correct;
mod ode6;
mod pde4;
mod pde6;
mod plate;
mod profile;
mod sasm;
mod sketch;
mod sketch_animal;
mod template;
mod template_belly;
mod template_jaw;
mod template_side;
mod template_study;
mod template_tbsm;
mod tui;
mod tui_commands;
mod tui_e2e;
mod tui_history;
