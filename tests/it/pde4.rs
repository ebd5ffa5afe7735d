//! Integration tests of the pde4 family (none yet).
