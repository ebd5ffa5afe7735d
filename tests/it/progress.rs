//! Progress lines: never drawn under `--json`, never drawn when stderr is
//! not a terminal (as under `cargo test`), and then every call is a no-op.

use pdesculpt::progress::{enabled, Progress};
use std::io::IsTerminal;

#[test]
fn progress_is_hidden_under_json_and_off_a_terminal() {
    assert!(!enabled(true), "--json never draws");
    assert_eq!(enabled(false), std::io::stderr().is_terminal());
    for p in [
        Progress::spinner("work", true),
        Progress::bar(3, "steps", true),
        Progress::hidden(),
    ] {
        assert!(!p.is_drawn());
        p.set_message("still working");
        p.inc(1);
        p.finish();
    }
}
