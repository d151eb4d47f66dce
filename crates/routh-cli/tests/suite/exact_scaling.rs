//! `routh exact` in other units and with bounded output (issue 33): the reproducers as a user
//! types them. The numerics behind them are tested in the library
//! (`crates/routh/tests/suite/quadrature.rs`, module `exact_in_any_units`).

use crate::common;

use common::{assert_exit_2, routh};
use std::path::{Path, PathBuf};

/// A case file in a fresh directory: the default case with `body` as its `[body]` table.
fn case_with_body(name: &str, body: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-exact-scaling-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(
        &path,
        format!(
            "[body]\n{body}\n[initial]\ngamma = [0.29552020666133955, 0.0, 0.955336489125606]\n\
             omega = [0.5, 0.2, 8.0]\n"
        ),
    )
    .unwrap();
    path
}

/// `routh exact --t 1 --json` on `case`, parsed.
fn exact_json(case: &Path) -> serde_json::Value {
    let out = routh(&[
        "exact",
        "--case",
        case.to_str().unwrap(),
        "--t",
        "1",
        "--json",
    ]);
    common::json_of(&out)
}

#[test]
fn the_default_case_with_mass_and_moments_scaled_is_the_same_nutation() {
    // The default case with m, I1 and I3 times 1e12 is the same motion: `exact --t 1` called it
    // steady. Now the same nutation, its period and gamma at t = 1 the default's to 1e-12 (the
    // library's COPY_AGREEMENT) and M scaled by 1e12 to the same relative accuracy.
    let default = exact_json(&case_with_body(
        "default",
        "m = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\nG = 9.81",
    ));
    let scaled = exact_json(&case_with_body(
        "scaled",
        "m = 1e12\nR = 1.0\na = 0.3\nI1 = 0.4e12\nI3 = 0.5e12\nG = 9.81",
    ));
    assert_eq!(scaled["motion"], "nutation");
    let number = |v: &serde_json::Value| v.as_f64().unwrap();
    let (p, q) = (number(&default["period"]), number(&scaled["period"]));
    assert!((p - q).abs() <= 1e-12 * p, "{p} {q}");
    for i in 0..3 {
        let (g, h) = (number(&default["gamma"][i]), number(&scaled["gamma"][i]));
        assert!((g - h).abs() <= 1e-12, "gamma{i}: {g} {h}");
        let (m, n) = (number(&default["M"][i]), number(&scaled["M"][i]));
        assert!((1e12 * m - n).abs() <= 1e-12 * 1e12 * 8.0, "M{i}: {m} {n}");
    }
}

#[test]
fn a_state_that_does_not_fix_omega_is_refused_naming_it() {
    // m = 1e30: `exact --t 0` printed omega = [-1.62, 0.2, -1.01] for the case's (0.5, 0.2, 8),
    // the state (gamma, M) holding no digit of the spin about the contact vector. Refused.
    let case = case_with_body(
        "heavy",
        "m = 1e30\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\nG = 9.81",
    );
    assert_exit_2(
        &["exact", "--case", case.to_str().unwrap(), "--t", "0"],
        "omega",
    );
}

#[test]
fn samples_are_bounded_as_for_simulate() {
    // `exact --samples` had no bound (a file grew without end): now that of `routh simulate
    // --samples` (MAX_SAMPLES), checked before any work, with the same rule in the message.
    assert_exit_2(&["exact", "--samples", "10000001"], "10000000");
    assert_exit_2(&["simulate", "--samples", "10000001"], "10000000");
    assert_exit_2(&["exact", "--samples", "1"], "samples");
}

#[test]
fn csv_to_standard_output_sends_the_summary_to_standard_error() {
    // `exact --out - --json` wrote the CSV and the JSON into one stream. As `routh simulate
    // --out -` does, the CSV goes alone to standard output and the summary to standard error.
    for extra in [&["--json"][..], &[][..]] {
        let mut args = vec!["exact", "--t", "1", "--samples", "3", "--out", "-"];
        args.extend_from_slice(extra);
        let out = routh(&args);
        assert!(out.status.success(), "{args:?}");
        let stdout = String::from_utf8(out.stdout).unwrap();
        let lines: Vec<&str> = stdout.lines().collect();
        assert_eq!(lines.len(), 4, "{args:?}: {stdout}");
        assert!(lines[0].starts_with("t,gamma1"), "{stdout}");
        assert!(lines[1..].iter().all(|l| l.split(',').count() == 14));
        let stderr = String::from_utf8(out.stderr).unwrap();
        if extra.is_empty() {
            assert!(stderr.contains("motion: nutation"), "{stderr}");
        } else {
            let v: serde_json::Value = serde_json::from_str(&stderr).expect("JSON on stderr");
            assert_eq!(v["motion"], "nutation");
        }
    }
    // Negative control: without `--out -` the summary stays on standard output.
    let out = routh(&["exact", "--t", "1", "--json"]);
    assert!(serde_json::from_slice::<serde_json::Value>(&out.stdout).is_ok());
}
