//! Integration tests of the conv family (none yet).
