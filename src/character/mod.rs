//! Characters: assembling the families into one model (paper 000 secs 4-5).
//!
//! [`demo`] is the pipeline behind `pdesculpt demo`: the MakeHuman template
//! (template-based global modeling), two local edits made the way the papers
//! make them (a closed curve plus one drag: paper 000's fourth-order PDE
//! deformation, Fig 14; a region plus a cursor force: paper 001's C1 plate
//! bending), and the C2 sixth-order PDE reconstruction of the edited body
//! from its cross sections (paper 002). Every step reports what it measured.

pub mod demo;
