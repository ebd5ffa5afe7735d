//! Integration tests of the ode6 family (none yet).
