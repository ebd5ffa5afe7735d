//! Integration tests of the plate family (none yet).
