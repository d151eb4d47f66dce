//! The `routh simulate` command, run as a user would: default case, JSON keys, CSV columns,
//! overrides, and bad input (exit code 2, a message, no panic, no output file).

use std::path::PathBuf;
use std::process::Output;

use crate::common;
use common::{assert_exit_2, routh};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-cli-simulate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn assert_usage_error(out: &Output, expected: &str) {
    let err = stderr(out);
    assert_eq!(
        out.status.code(),
        Some(2),
        "expected exit 2 with `{expected}`, got {:?}: {err}",
        out.status
    );
    assert!(err.contains(expected), "message `{err}` lacks `{expected}`");
    assert!(!err.contains("panicked"), "panic: {err}");
}

#[test]
fn default_case_prints_a_readable_summary() {
    let out = routh(&["simulate", "--t-end", "5"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = String::from_utf8(out.stdout).unwrap();
    for needle in ["<built-in default>", "dop853", "H1", "max relative drift"] {
        assert!(text.contains(needle), "summary lacks {needle}:\n{text}");
    }
}

#[test]
fn json_summary_has_the_promised_keys() {
    let out = routh(&["simulate", "--t-end", "5", "--json"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "steps",
        "rhs_evals",
        "t_end",
        "final_state",
        "integrals",
        "elapsed_s",
    ] {
        assert!(v.get(key).is_some(), "JSON lacks {key}: {v}");
    }
    assert_eq!(v["t_end"], 5.0);
    let elapsed = v["elapsed_s"].as_f64().unwrap();
    assert!(
        (0.0..60.0).contains(&elapsed),
        "elapsed_s is a wall time in seconds: {elapsed}"
    );
    assert!(v["final_state"]["gamma"].as_array().unwrap().len() == 3);
    assert!(v["final_state"]["M"].as_array().unwrap().len() == 3);
    for name in ["H1", "H2", "H3", "H4", "K"] {
        let d = &v["integrals"][name];
        assert!(
            d["initial"].is_f64() && d["max_rel_drift"].is_f64(),
            "{name}: {d}"
        );
    }
}

#[test]
fn csv_has_the_promised_columns_and_samples() {
    let path = scratch("run.csv");
    let out = routh(&[
        "simulate",
        "--t-end",
        "1",
        "--samples",
        "11",
        "--out",
        path.to_str().unwrap(),
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "t,gamma1,gamma2,gamma3,M1,M2,M3,omega1,omega2,omega3,H1,H2,H3,H4,K"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 11);
    assert_eq!(rows[0][0], 0.0);
    assert_eq!(rows[10][0], 1.0);
    assert!(rows.iter().all(|r| r.len() == 15));
}

#[test]
fn rk4_and_projection_options_run() {
    let out = routh(&[
        "simulate",
        "--t-end",
        "1",
        "--method",
        "rk4:2000",
        "--project",
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["method"], "rk4:2000");
    assert_eq!(v["steps"], 2000);
    assert!(v["integrals"]["H1"]["max_rel_drift"].as_f64().unwrap() < 1e-13);
}

#[test]
fn bad_options_exit_2_with_a_message() {
    assert_exit_2(&["simulate", "--t-end", "nan"], "t_end");
    assert_exit_2(&["simulate", "--t-end", "-1"], "t_end");
    assert_exit_2(&["simulate", "--rtol", "-1e-9"], "rtol");
    assert_exit_2(&["simulate", "--atol", "nan"], "atol");
    assert_exit_2(
        &["simulate", "--method", "euler"],
        "unknown integration method",
    );
    assert_exit_2(
        &["simulate", "--case", "/nonexistent/case.toml"],
        "/nonexistent/case.toml",
    );
    assert_exit_2(
        &["simulate", "--project", "--project-every", "0"],
        "project_every",
    );
    assert_exit_2(&["simulate", "--project-every", "10"], "--project");
}

#[test]
fn projection_every_nth_step_is_reported_and_holds_the_integrals() {
    // Vern9 at 1e-8 to t = 100 (about 1,000 steps), projected every 10th step: the JSON names
    // the interval; the integrals' drift is at most that of 9 unprojected steps, far below
    // the unprojected run's (measured 1.2e-10 against 1.3e-8; bound 1e-9, and a gain of 10
    // or more over the run without projection, the negative control).
    let drift = |args: &[&str]| {
        let base = [
            "simulate", "--t-end", "100", "--method", "vern9", "--rtol", "1e-8",
        ];
        let out = routh(&[&base[..], &["--atol", "1e-8", "--json"], args].concat());
        assert!(out.status.success(), "{}", stderr(&out));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let d = v["integrals"]["H1"]["max_rel_drift"].as_f64().unwrap();
        (v, d)
    };
    let (v, projected) = drift(&["--project", "--project-every", "10"]);
    assert_eq!(v["projected"], true);
    assert_eq!(v["project_every"], 10);
    let (v, plain) = drift(&[]);
    assert_eq!(v["projected"], false);
    println!("H1 drift: every 10th step {projected:e}, without projection {plain:e}");
    assert!(
        projected < 1e-9 && plain > 10.0 * projected,
        "{projected:e} {plain:e}"
    );
}

/// `--method auto` resolves by the tolerance and by whether the run projects
/// (`auto::AUTO_TABLE` and `AUTO_TABLE_PROJECTED`): at tol 1e-11 Vern9 plain and the
/// Taylor method projected; at 1e-10 Vern9 either way, at 1e-12 the Taylor method either way.
/// The JSON names the method that ran.
#[test]
fn auto_picks_by_tolerance_and_projection() {
    let method = |tol: &str, project: bool| {
        let mut args = vec![
            "simulate", "--t-end", "1", "--method", "auto", "--rtol", tol, "--atol", tol, "--json",
        ];
        if project {
            args.push("--project");
        }
        let out = routh(&args);
        assert!(out.status.success(), "{}", stderr(&out));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        v["method"].as_str().unwrap().to_string()
    };
    assert_eq!(method("1e-11", false), "vern9");
    assert_eq!(method("1e-11", true), "taylor");
    assert_eq!(method("1e-10", true), "vern9");
    assert_eq!(method("1e-12", false), "taylor");
}

#[test]
fn bad_case_files_exit_2_naming_the_key_and_file() {
    let default = routh::case::DEFAULT_CASE;
    for (old, new, expected) in [
        // item 7: the schema
        ("G = 9.81", "G = 9.81\nspin = 1", "unknown field `spin`"),
        (
            "[integration]",
            "[integration]\nsteps = 3",
            "unknown field `steps`",
        ),
        ("[body]", "t_end = 5\n[body]", "unknown key `t_end`"),
        ("R = 1.0\n", "", "missing field `R`"),
        ("[body]", "[body", "malformed TOML"),
        (
            "omega = [0.5, 0.2, 8.0]",
            "omega = [0.5, 0.2, 8.0]\nM = [0.0, 0.0, 1.0]",
            "exactly one",
        ),
        // item 1: the body
        ("m = 1.0", "m = nan", "m = NaN: must be finite"),
        ("m = 1.0", "m = -1.0", "m = -1: must be > 0"),
        ("R = 1.0", "R = 0.0", "R = 0: must be > 0"),
        ("a = 0.3", "a = 1.5", "|a| < R"),
        ("a = 0.3", "a = inf", "a = inf: must be finite"),
        ("I1 = 0.4", "I1 = -0.4", "I1 = -0.4: must be > 0"),
        ("I3 = 0.5", "I3 = 0.0", "I3 = 0: must be > 0"),
        ("I3 = 0.5", "I3 = 0.5\nI2 = -1.0", "I2 = -1: must be > 0"),
        ("G = 9.81", "G = -9.81", "G = -9.81: must be >= 0"),
        ("I3 = 0.5", "I3 = 0.9", "I1 + I2 >= I3"),
        ("I3 = 0.5", "I3 = 0.2\nI2 = 0.1", "I2 + I3 >= I1"),
        ("I3 = 0.5", "I3 = 0.5\nI2 = 1.0", "I3 + I1 >= I2"),
        // item 2: the state
        (
            "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
            "gamma = [1.0, 1.0, 0.0]",
            "not a unit vector",
        ),
        (
            "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
            "gamma = [nan, 0.0, 1.0]",
            "non-finite",
        ),
        (
            "omega = [0.5, 0.2, 8.0]",
            "omega = [0.5, inf, 8.0]",
            "non-finite",
        ),
        // invalid option values in the file
        ("rtol = 1e-12", "rtol = -1e-12", "rtol"),
        ("t_end = 100.0", "t_end = nan", "t_end"),
    ] {
        let path = scratch("bad.toml");
        std::fs::write(&path, default.replacen(old, new, 1)).unwrap();
        let out = routh(&["simulate", "--case", path.to_str().unwrap()]);
        assert_usage_error(&out, expected);
        assert!(
            stderr(&out).contains("bad.toml"),
            "file not named: {}",
            stderr(&out)
        );
    }
}

#[test]
fn a_failed_run_leaves_no_output_file() {
    let path = scratch("never.csv");
    let _ = std::fs::remove_file(&path);
    let out = routh(&[
        "simulate",
        "--t-end",
        "nan",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!path.exists(), "a failed run wrote {}", path.display());
    let dir = path.parent().unwrap();
    let leftovers: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains("never.csv"))
        .collect();
    assert!(leftovers.is_empty(), "temporary files left: {leftovers:?}");
}

#[test]
fn full_motion_adds_orientation_and_positions_to_the_csv() {
    let path = scratch("full.csv");
    let out = routh(&[
        "simulate",
        "--full",
        "--t-end",
        "1",
        "--samples",
        "6",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&path).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    assert_eq!(header.len(), 24);
    assert_eq!(
        &header[15..],
        [
            "qw",
            "qx",
            "qy",
            "qz",
            "x",
            "y",
            "z",
            "contact_x",
            "contact_y"
        ]
    );
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        // The quaternion is unit (1e-12: DOP853 at the default 1e-12 tolerance over t = 1)
        // and the centre of mass is at the height (r, gamma) = R (gamma, gamma) + a gamma3 of the
        // default body (R = 1, a = 0.3), to round-off.
        let norm = (v[15] * v[15] + v[16] * v[16] + v[17] * v[17] + v[18] * v[18]).sqrt();
        assert!((norm - 1.0).abs() < 1e-12, "|q| = {norm}");
        let height = v[1] * v[1] + v[2] * v[2] + v[3] * v[3] + 0.3 * v[3];
        assert!(
            (v[21] - height).abs() < 1e-14,
            "height {} vs (r, gamma) = {height}",
            v[21]
        );
    }
}
