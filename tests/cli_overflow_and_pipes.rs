//! `steady` names the quantity that overflows and its cause (issue 10, item 5), and JSON output
//! to a closed pipe ends quietly instead of panicking.

use std::process::Command;

mod common;

fn routh() -> Command {
    Command::new(env!("CARGO_BIN_EXE_routh"))
}

/// The default case with one line replaced, written to a temporary file.
fn case_with(name: &str, from: &str, to: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string("cases/default.toml").unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with(from))
        .unwrap_or_else(|| panic!("no line {from}"));
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, text.replace(line, to)).unwrap();
    path
}

/// Exit code and standard error of `routh steady --case path`.
fn steady(path: &std::path::Path) -> (Option<i32>, String) {
    let out = routh()
        .args(["steady", "--case"])
        .arg(path)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

#[test]
fn steady_names_the_overflowing_quantity_and_its_cause() {
    // A spin of 1e100 rad/s: the Jacobian of (mg-eq), whose entries are of the size of
    // omega^2, overflows in the Schur iteration.
    let spin = case_with("spin_1e100.toml", "omega", "omega = [0.0, 0.0, 1e100]");
    let (code, err) = steady(&spin);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("the spin omega3 = 9.99"), "{err}");
    assert!(
        err.contains("the Jacobian of (mg-eq)") && err.contains("overflow"),
        "{err}"
    );
    assert!(
        !err.contains("non-finite") && !err.contains("NaN]"),
        "{err}"
    );
    // A mass of 1e-300: the steady precessions need omega_t ~ 1/m, whose square overflows.
    let light = case_with("m_1e-300.toml", "m ", "m = 1e-300");
    let (code, err) = steady(&light);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("m = 1e-300 makes"), "{err}");
    assert!(
        err.contains("Q''(gamma3)") && err.contains("overflow"),
        "{err}"
    );
    // Negative control: a large but representable spin is analysed.
    let fast = case_with("spin_1e20.toml", "omega", "omega = [0.0, 0.0, 1e20]");
    let (code, err) = steady(&fast);
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn json_to_a_closed_pipe_ends_quietly() {
    // The reader has gone before `steady` writes (it computes first): the write fails with
    // EPIPE, which ends the process with exit code 0 and nothing on stderr (it panicked with
    // exit code 101 before).
    let mut command = routh();
    command.args(["steady", "--json"]);
    let out = common::with_closed_stdout(command);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.is_empty(), "{err}");
    // Negative control: another write error (a full device) is reported with exit code 2.
    if let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") {
        let out = routh()
            .args(["steady", "--json"])
            .stdout(full)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains("standard output"), "{err}");
    }
}
