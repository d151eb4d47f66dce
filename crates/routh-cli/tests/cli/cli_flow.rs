//! `routh exact --flow`: the JSON keys of `routh exact` where they apply, the state agreeing
//! with the library's quadrature (to round-off: the state passes through `State`), the CSV of samples, and bad input with exit code 2.

use crate::common;

use common::{assert_exit_2, routh};
use routh::case::Case;
use routh::poisson::flows::{Condition, Field, Flow};

#[test]
fn flow_json_has_the_keys_of_exact_and_the_library_state() {
    let out = routh(&[
        "exact",
        "--flow",
        "X2",
        "--condition",
        "cond2",
        "--alpha",
        "0.7",
        "--t",
        "3",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "case",
        "flow",
        "condition",
        "alpha",
        "motion",
        "theta_min",
        "theta_max",
        "gamma3_min",
        "gamma3_max",
        "period",
        "precession_advance_per_period",
        "precession_rate",
        "t",
        "gamma",
        "M",
        "omega",
        "H1",
        "H3",
        "K",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["flow"], "X2");
    assert_eq!(v["motion"], "nutation");
    let case = Case::load(None).unwrap();
    let flow = Flow::new(
        Condition::Cond2.bracket(case.body("the flows").unwrap(), 0.7),
        Field::X2,
        &case.initial.to_array(),
    )
    .unwrap();
    let x = flow.state_at(3.0);
    for i in 0..3 {
        assert!((v["gamma"][i].as_f64().unwrap() - x[i]).abs() < 1e-14);
        assert!((v["M"][i].as_f64().unwrap() - x[3 + i]).abs() < 1e-13);
    }
}

#[test]
fn flow_samples_are_written_as_csv() {
    let out = routh(&["exact", "--flow", "Xhat2", "--t", "2", "--samples", "5"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 6);
    assert!(lines[0].starts_with("t,gamma1"));
}

#[test]
fn bad_flow_options_exit_2() {
    assert_exit_2(&["exact", "--flow", "Y1"], "unknown flow");
    assert_exit_2(
        &["exact", "--flow", "X1", "--condition", "cond3"],
        "unknown condition",
    );
    assert_exit_2(&["exact", "--flow", "X1", "--alpha", "0"], "alpha");
    assert_exit_2(&["exact", "--condition", "cond2"], "--flow");
}
