//! The `routh exact` and `routh steady` commands run as a user would: JSON keys, CSV output,
//! and exit code 2 with a message on bad input.

use std::process::Output;

mod common;
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
