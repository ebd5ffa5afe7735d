//! Integration tests of the pde6 family (none yet).
