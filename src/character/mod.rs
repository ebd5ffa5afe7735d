//! Characters: assembling the families into one model (paper 000 secs 4-5).
//!
//! [`demo`] is the pipeline behind `pdesculpt demo`: the MakeHuman template
//! (template-based global modeling), two local edits made the way the papers
//! make them (a closed curve plus one drag: paper 000's fourth-order PDE
//! deformation, Fig 14; a region plus a cursor force: paper 001's C1 plate
//! bending), and the C2 sixth-order PDE reconstruction of the edited body
//! from its cross sections (paper 002), a skirt fitted to the body as a C2
//! sixth-order ODE surface through boundary and control curves (paper 004,
//! [`skirt`]) and a prop sketched in silhouettes as a convolution surface
//! (paper 003). Every step reports what it measured.

pub mod demo;
pub mod doc;
pub mod doc_ranges;
pub mod edit;
pub mod props;
pub mod skirt;
