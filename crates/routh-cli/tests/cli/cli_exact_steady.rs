//! The `routh exact` and `routh steady` commands run as a user would: JSON keys, CSV output,
//! and exit code 2 with a message on bad input.

use std::process::Output;

use crate::common;
use common::{assert_exit_2, routh};

fn json(out: &Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON on stdout")
}

#[test]
fn exact_json_has_the_required_keys() {
    let v = json(&routh(&["exact", "--t", "12.5", "--json"]));
    for key in ["theta_min", "theta_max", "period", "t", "gamma", "M"] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["t"], 12.5);
    assert!(v["theta_min"].as_f64().unwrap() < v["theta_max"].as_f64().unwrap());
    assert_eq!(v["gamma"].as_array().unwrap().len(), 3);
}

#[test]
fn exact_writes_csv_samples_atomically() {
    let dir = std::env::temp_dir().join(format!("routh-exact-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("samples.csv");
    let out = routh(&[
        "exact",
        "--t",
        "3",
        "--samples",
        "7",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 8);
    assert!(
        lines[0].starts_with("t,gamma1,gamma2,gamma3,M1,M2,M3,omega1,omega2,omega3,theta,H1,H3,K")
    );
    assert_eq!(lines[1].split(',').count(), 14);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn steady_json_has_the_threshold_spin() {
    let v = json(&routh(&["steady", "--json"]));
    let threshold = v["threshold_spin"].as_f64().unwrap();
    assert!(
        (threshold - 2.7556608402825384).abs() < 1e-12,
        "{threshold}"
    );
    assert_eq!(v["vertical"].as_array().unwrap().len(), 2);
    assert!(!v["precessions"].as_array().unwrap().is_empty());
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let dir = std::env::temp_dir().join(format!("routh-exact-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let asymmetric = dir.join("asymmetric.toml");
    std::fs::write(
        &asymmetric,
        "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI2 = 0.45\nI3 = 0.5\nG = 9.81\n\
         [initial]\ngamma = [0.0, 0.6, 0.8]\nomega = [0.1, 0.2, 3.0]\n\
         [integration]\nt_end = 1.0\nrtol = 1e-10\natol = 1e-10\n",
    )
    .unwrap();
    let cases: [&[&str]; 5] = [
        &["exact", "--t", "NaN"],
        &["exact", "--samples", "1"],
        &["exact", "--case", "/nonexistent/case.toml"],
        &["exact", "--case", asymmetric.to_str().unwrap()],
        &["steady", "--case", asymmetric.to_str().unwrap()],
    ];
    for args in cases {
        assert_exit_2(args, "error: ");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A case file of the default body with the given body line changed and initial state.
fn case_file(name: &str, body_edit: (&str, &str), gamma: &str, omega: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-exact-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("case.toml");
    let body = "m = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\nG = 9.81\n"
        .replace(body_edit.0, body_edit.1);
    std::fs::write(
        &path,
        format!(
            "[body]\n{body}[initial]\ngamma = {gamma}\nomega = {omega}\nnormalize = true\n\
             [integration]\nt_end = 10.0\nrtol = 1e-12\natol = 1e-12\n"
        ),
    )
    .unwrap();
    path
}

#[test]
fn exact_does_not_call_a_nutation_near_the_axis_steady() {
    // Issue 10: called "steady" on ded9944 while it nutates.
    let path = case_file(
        "nutates",
        ("", ""),
        "[0.001, 0.0, 0.9999995]",
        "[0.0, 0.0, 5.0]",
    );
    let v = json(&routh(&[
        "exact",
        "--case",
        path.to_str().unwrap(),
        "--t",
        "10",
        "--json",
    ]));
    assert_eq!(v["motion"], "nutation");
    assert!(
        v["theta_max"].as_f64().unwrap() > 0.00119,
        "{}",
        v["theta_max"]
    );
    // The state at t = 10 by DOP853 (simulate, rtol 1e-12): gamma1 = -0.000801508955813.
    let g1 = v["gamma"][0].as_f64().unwrap();
    assert!((g1 + 0.000801508955813).abs() < 1e-10, "{g1}");
}

#[test]
fn exact_json_is_json_with_samples_inside() {
    // Issue 10: `exact --samples 3 --json` printed CSV.
    let v = json(&routh(&["exact", "--t", "1", "--samples", "3", "--json"]));
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 3);
    assert_eq!(samples[2]["t"], 1.0);
    assert_eq!(samples[2]["gamma"], v["gamma"]);
}

#[test]
fn exact_refuses_times_beyond_its_horizon() {
    // Issue 10: `exact --t 1e300` printed a 301-digit t and a pinned state.
    let out = routh(&["exact", "--t", "1e300"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("t = 1e300 is beyond the range"), "{err}");
    assert!(!err.contains("000000000000"), "{err}");
    // Negative control: t = 100 is well inside the horizon.
    assert!(routh(&["exact", "--t", "100"]).status.success());
}

#[test]
fn steady_names_an_overflowing_mass_and_labels_poles_by_the_sign_of_a() {
    // Issue 10: m = 1e300 printed omega = [0, 0, NaN]; a = 0 called both poles "centre of
    // mass below".
    let big = case_file(
        "big",
        ("m = 1.0", "m = 1e300"),
        "[0.0, 0.6, 0.8]",
        "[0.1, 0.2, 3.0]",
    );
    assert_exit_2(
        &["steady", "--case", big.to_str().unwrap()],
        "inertia about the contact point",
    );
    let centred = case_file(
        "centred",
        ("a = 0.3", "a = 0.0"),
        "[0.0, 0.6, 0.8]",
        "[0.1, 0.2, 3.0]",
    );
    let v = json(&routh(&[
        "steady",
        "--case",
        centred.to_str().unwrap(),
        "--json",
    ]));
    for spin in v["vertical"].as_array().unwrap() {
        assert_eq!(spin["centre_of_mass"], "at the geometric centre");
    }
    let flipped = case_file(
        "flipped",
        ("a = 0.3", "a = -0.3"),
        "[0.0, 0.6, 0.8]",
        "[0.1, 0.2, 3.0]",
    );
    let v = json(&routh(&[
        "steady",
        "--case",
        flipped.to_str().unwrap(),
        "--json",
    ]));
    let labels: Vec<_> = v["vertical"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| (s["gamma3"].as_f64().unwrap(), s["centre_of_mass"].clone()))
        .collect();
    assert_eq!(labels, vec![(1.0, "below".into()), (-1.0, "above".into())]);
}

#[test]
fn tiny_numbers_are_printed_in_scientific_notation() {
    // A body of mass 1e-300 is valid; its Routh threshold is ~4e-150, which `{}` printed as
    // 150 zeros and digits. The text output keeps it readable; the JSON keeps the number.
    let tiny = case_file(
        "tiny",
        ("m = 1.0", "m = 1e-300"),
        "[0.0, 0.6, 0.8]",
        "[0.1, 0.2, 3.0]",
    );
    let out = routh(&["steady", "--case", tiny.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let line = text
        .lines()
        .find(|l| l.contains("centre of mass above"))
        .expect("the top-heavy vertical spin");
    assert!(line.contains("threshold |omega3| = 4.3"), "{line}");
    assert!(line.contains("e-150"), "{line}");
    assert!(!line.contains("0.0000000"), "{line}");
    let v = json(&routh(&[
        "steady",
        "--case",
        tiny.to_str().unwrap(),
        "--json",
    ]));
    let threshold = v["vertical"][0]["threshold_spin"].as_f64().unwrap();
    assert!(threshold > 1e-151 && threshold < 1e-149, "{threshold}");
    // The same rule in the summary of `routh simulate` (the body line printed 300 digits).
    let out = routh(&["simulate", "--case", tiny.to_str().unwrap(), "--t-end", "1"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("m = 1e-300, R = 1, a = 0.3"), "{text}");
}
