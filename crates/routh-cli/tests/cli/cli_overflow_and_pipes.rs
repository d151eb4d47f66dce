//! `steady` names the quantity that overflows and its cause (issue 10, item 5), and JSON output
//! to a closed pipe ends quietly instead of panicking.

use std::process::Command;

use crate::common;

fn routh() -> Command {
    common::command()
}

/// The default case with one line replaced, written to a temporary file.
fn case_with(name: &str, from: &str, to: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(format!("{}/cases/default.toml", common::ROOT)).unwrap();
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
    // A mass of 1e-300 no longer overflows Q'' (the frames of the poles have no huge
    // cancelling terms): `steady` answers, and its steady motions are those of the m -> 0
    // limit, the same as at m = 1e-30 (their dependence on m is of relative size m R^2 / I1,
    // far below the round-off: equal to 1e-12 relative, or 1e-12 absolute for the omega_t of
    // 1e-15 that are zeros in round-off). The precession at theta = pi/2 whose omega_t ~ 13 / m
    // is listed where the samples of Q' resolve its coefficient ~ m (m = 1e-10: omega_t =
    // 1.333e11) and left out where they do not (m <= 1e-12; it printed 8.1e31 at m = 1e-30 and
    // 2.7e31 at m = 1e-300, both wrong). No other input was found that overflows Q'' any more
    // (G, R, I1, I3, a, m up to 1e300 or down to 1e-300 are refused at the case file or
    // overflow the Jacobian, as the spin above); this part checks the m -> 0 limit instead.
    let precessions = |m: &str| {
        let path = case_with(&format!("m_{m}.toml"), "m ", &format!("m = {m}"));
        let out = routh()
            .args(["steady", "--json", "--case"])
            .arg(&path)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "m = {m}");
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let pairs = |key: &str, value: &str| {
            json[key]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| (p["theta"].as_f64().unwrap(), p[value].as_f64().unwrap()))
                .collect::<Vec<_>>()
        };
        (
            pairs("precessions", "omega_t"),
            pairs("unlisted_far_precessions", "beyond_omega_t"),
        )
    };
    let ((tiny, tiny_unlisted), (small, small_unlisted), (light, light_unlisted)) = (
        precessions("1e-300"),
        precessions("1e-30"),
        precessions("1e-10"),
    );
    // The far precession left out is said, at theta = pi/2 only, with a bound below its true
    // omega_t ~ 13 / m (so the statement "beyond about" is not false); at m = 1e-10 it is
    // listed and nothing is said.
    for (unlisted, m) in [(&tiny_unlisted, 1e-300), (&small_unlisted, 1e-30)] {
        assert_eq!(unlisted.len(), 1, "m = {m}: {unlisted:?}");
        let (theta, beyond) = unlisted[0];
        assert!(
            (theta - std::f64::consts::FRAC_PI_2).abs() < 1e-12,
            "{theta}"
        );
        assert!(beyond > 1e6 && beyond < 13.0 / m, "m = {m}: {beyond}");
    }
    assert!(light_unlisted.is_empty(), "{light_unlisted:?}");
    let fast = |list: &[(f64, f64)]| list.iter().filter(|p| p.1.abs() > 1e6).count();
    assert_eq!((fast(&tiny), fast(&small), fast(&light)), (0, 0, 1));
    assert_eq!(tiny.len(), small.len());
    for (a, b) in tiny.iter().zip(&small) {
        assert!((a.0 - b.0).abs() <= 1e-12 * a.0.abs(), "{a:?} {b:?}");
        assert!(
            (a.1 - b.1).abs() <= 1e-12 * a.1.abs().max(1.0),
            "{a:?} {b:?}"
        );
    }
    // Negative control: the listing at m = 1e-10 differs (its fast precession).
    assert_ne!(tiny.len(), light.len());
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
