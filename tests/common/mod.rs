//! Running the `routh` binary from the integration tests, as a user would.

use std::process::{Command, Output};

/// Run `routh` with `args` and collect its output.
pub fn routh(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_routh"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Run `routh` with `args` and check that it fails as bad input should: exit code 2, a
/// message containing `expected` on stderr, and no panic.
pub fn assert_exit_2(args: &[&str], expected: &str) {
    let out = routh(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(
        err.contains(expected),
        "{args:?}: `{err}` lacks `{expected}`"
    );
    assert!(!err.contains("panicked"), "{args:?}: {err}");
}
