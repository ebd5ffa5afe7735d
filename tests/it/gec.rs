//! Integration tests of the gec family (none yet).
