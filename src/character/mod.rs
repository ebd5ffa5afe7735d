//! Characters: the document that assembles parts (paper 000 secs 4-5).
//!
//! Not implemented yet beyond the MakeHuman template loader in
//! [`crate::makehuman`].
