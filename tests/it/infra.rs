//! Infrastructure tests.
