//! `routh sweep`, run as a user would: each run equals `routh simulate` on the same case bit
//! for bit whatever the thread count; the nutation from events agrees with the quadrature;
//! bad `[sweep]` tables are refused before any run; a stopped sweep leaves a readable table
//! that `--resume` completes into the table of an uninterrupted sweep.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::common;
use common::{assert_exit_2, routh};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-cli-sweep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

const BODY: &str = "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\nG = 9.81\n";

/// A case file of the default body with `initial`, `t_end` and the `[sweep]` table `sweep`.
fn case_file(name: &str, gamma: [f64; 3], omega: [f64; 3], t_end: f64, sweep: &str) -> PathBuf {
    let path = scratch(name);
    let text = format!(
        "{BODY}[initial]\ngamma = {gamma:?}\nomega = {omega:?}\n[integration]\nt_end = {t_end:?}\nrtol = 1e-10\natol = 1e-10\n{sweep}"
    );
    std::fs::write(&path, text).unwrap();
    path
}

fn sweep_json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["sweep", "--json"];
    all.extend_from_slice(args);
    let out = routh(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

const GRID: &str = "[sweep]\ntilt = { range = [0.3, 1.2], n = 4 }\nspin = { values = [4.0, 6.0] }\n\"body.a\" = { values = [0.2, 0.3] }\n";

/// Each run of a sweep gives the numbers of `routh simulate` on the same case, bit for bit
/// (final state, integrals and drift, steps; the field evaluations add those of the dense
/// output that locates the turning points)
/// (serde_json writes the shortest decimal that reads back to the same f64, so equal JSON
/// numbers are equal doubles), with 1 thread and with 2. Negative control: the simulation of
/// run 0's case differs from run 1's row.
#[test]
fn every_run_equals_routh_simulate_bitwise_whatever_the_thread_count() {
    every_run_equals_routh_simulate("dop853");
}

/// The same with the Taylor method (its runs in the Taylor lanes of the sweep, one at a time
/// in `routh simulate`).
#[test]
fn every_taylor_run_equals_routh_simulate_bitwise_whatever_the_thread_count() {
    every_run_equals_routh_simulate("taylor");
}

fn every_run_equals_routh_simulate(method: &str) {
    let case = case_file(
        &format!("grid-{method}.toml"),
        [0.0, 0.0, 1.0],
        [0.5, 0.2, 8.0],
        5.0,
        GRID,
    );
    let case = case.to_str().unwrap();
    let one = sweep_json(&["--case", case, "--threads", "1", "--method", method]);
    let two = sweep_json(&["--case", case, "--threads", "2", "--method", method]);
    let rows = one["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 16);
    assert_eq!(one["rows"], two["rows"], "1 thread and 2 threads differ");
    for row in rows {
        let tilt = row["tilt"].as_f64().unwrap();
        let spin = row["spin"].as_f64().unwrap();
        let a = row["body.a"].as_f64().unwrap();
        let single = scratch(&format!("run{}-{method}.toml", row["run"]));
        let text = format!(
            "[body]\nm = 1.0\nR = 1.0\na = {a:?}\nI1 = 0.4\nI3 = 0.5\nG = 9.81\n[initial]\ngamma = {:?}\nomega = [0.5, 0.2, {spin:?}]\n[integration]\nt_end = 5.0\nrtol = 1e-10\natol = 1e-10\n",
            [tilt.sin(), 0.0, tilt.cos()]
        );
        std::fs::write(&single, text).unwrap();
        let out = routh(&[
            "simulate",
            "--json",
            "--case",
            single.to_str().unwrap(),
            "--method",
            method,
        ]);
        assert!(out.status.success());
        let sim: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let fs = &sim["final_state"];
        let finals = [
            &fs["gamma"][0],
            &fs["gamma"][1],
            &fs["gamma"][2],
            &fs["M"][0],
            &fs["M"][1],
            &fs["M"][2],
        ];
        for (name, v) in ["gamma1", "gamma2", "gamma3", "M1", "M2", "M3"]
            .iter()
            .zip(finals)
        {
            assert_eq!(
                &row[format!("final_{name}")],
                v,
                "run {}: {name}",
                row["run"]
            );
        }
        for key in ["steps", "rejected"] {
            assert_eq!(row[key], sim[key], "run {}: {key}", row["run"]);
        }
        // Locating a turning point prepares DOP853's 7th-order dense output on its step,
        // which costs 3 more field evaluations: the only difference in the counts (none for
        // the Taylor method, whose dense output is the step's series).
        let extra = row["rhs_evals"].as_u64().unwrap() - sim["rhs_evals"].as_u64().unwrap();
        assert!(
            extra % 3 == 0 && extra <= 3 * row["steps"].as_u64().unwrap(),
            "{extra}"
        );
        for name in ["H1", "H2", "H3", "H4", "K"] {
            assert_eq!(
                row[format!("{name}_drift")],
                sim["integrals"][name]["max_rel_drift"]
            );
            assert_eq!(
                row[format!("{name}_final")],
                sim["integrals"][name]["final"]
            );
        }
        if row["run"] == 0 {
            assert_ne!(rows[1]["final_M3"], fs["M"][2], "negative control");
        }
    }
}

/// The nutation period and the precession per period found from the turning points of an
/// integration at 1e-10 agree with the quadrature: Brent's method on DOP853's 7th-order
/// dense output locates each turning point to about the tolerance, and the period is a
/// difference of two of them divided by the number of periods, so 1e-7 leaves a wide margin
/// (the observed differences are below 1e-8). Negative control: the events of one spin do
/// not match the quadrature of another.
#[test]
fn nutation_from_events_agrees_with_the_quadrature() {
    let case = case_file(
        "nutation.toml",
        [0.0, 0.0, 1.0],
        [0.5, 0.2, 8.0],
        20.0,
        "[sweep]\ntilt = { range = [0.3, 1.4], n = 6 }\nspin = { values = [3.0, 6.0] }\n",
    );
    let v = sweep_json(&["--case", case.to_str().unwrap()]);
    let rows = v["rows"].as_array().unwrap();
    for row in rows {
        assert_eq!(row["status"], "ok", "{row}");
        let d = row["period_difference"].as_f64().unwrap();
        let p = row["precession_difference"].as_f64().unwrap();
        assert!(
            d.abs() < 1e-7 && p.abs() < 1e-7,
            "run {}: {d:e} {p:e}",
            row["run"]
        );
        let th = (
            row["theta_min"].as_f64().unwrap(),
            row["theta_max"].as_f64().unwrap(),
        );
        let tilt = row["tilt"].as_f64().unwrap();
        assert!(
            th.0 <= tilt + 1e-12 && tilt <= th.1 + 1e-12,
            "{th:?} {tilt}"
        );
    }
    let other =
        rows[0]["period_events"].as_f64().unwrap() - rows[6]["period_quadrature"].as_f64().unwrap();
    assert!(other.abs() > 1e-3, "negative control: {other}");
}

/// Bad tables are refused before any run starts (no output file), exit 2, naming the key
/// and the value.
#[test]
fn bad_sweep_tables_are_refused_naming_key_and_value() {
    let out = scratch("refused.csv");
    let cases = [
        (
            "tilt = { range = [0.1, 1.0], n = 4 }\nfoo = { values = [1.0] }",
            "`foo`",
        ),
        (
            "tilt = { range = [1.0, 0.5], n = 4 }",
            "range = [1, 0.5]: empty range",
        ),
        ("tilt = { range = [0.1, 1.0], n = 0 }", "n = 0"),
        ("tilt = { values = [] }", "`tilt` = values = []"),
        ("\"body.a\" = { values = [0.3, 1.5] }", "body.a = 1.5"),
        ("\"body.I3\" = { values = [0.5, 0.9] }", "body.I3 = 0.9"),
        ("tilt = { range = [0.1, 1.0], n = 4, step = 2 }", "`tilt`"),
        (
            "samples = 0\ntilt = { range = [0.1, 1.0] }",
            "`samples` = 0",
        ),
        (
            "samples = 8\ndesign = \"halton\"\ntilt = { range = [0.1, 1.0] }",
            "`design` = \"halton\"",
        ),
        (
            "tilt = { values = [0.1] }\ngamma1 = { values = [0.1] }",
            "`tilt`",
        ),
    ];
    for (i, (table, expected)) in cases.iter().enumerate() {
        let case = case_file(
            &format!("bad{i}.toml"),
            [0.0, 0.0, 1.0],
            [0.5, 0.2, 8.0],
            1.0,
            &format!("[sweep]\n{table}\n"),
        );
        assert_exit_2(
            &[
                "sweep",
                "--case",
                case.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
            ],
            expected,
        );
        assert!(!out.exists(), "a refused sweep wrote {}", out.display());
    }
    // Negative control: the same file with a good table runs.
    let good = case_file(
        "good.toml",
        [0.0, 0.0, 1.0],
        [0.5, 0.2, 8.0],
        1.0,
        "[sweep]\n\"body.a\" = { values = [0.3] }\n",
    );
    let run = routh(&[
        "sweep",
        "--case",
        good.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(run.status.success());
    assert!(out.exists());
}

fn sorted_lines(path: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines: Vec<String> = text.lines().skip(1).map(str::to_string).collect();
    lines.sort_by_key(|l| l.split(',').next().unwrap().parse::<u64>().unwrap());
    lines
}

/// SIGTERM halfway: the process stops cleanly, the target is a complete CSV holding only
/// finished rows (some, not all), `--resume` completes it, and the result equals an
/// uninterrupted sweep row for row (after ordering by `run`: resumed rows come after the
/// kept ones).
#[test]
fn an_interrupted_sweep_is_readable_and_resume_completes_it() {
    let case = case_file(
        "long.toml",
        [0.0, 0.0, 1.0],
        [0.5, 0.2, 8.0],
        30.0,
        "[sweep]\ntilt = { range = [0.3, 1.4], n = 150 }\nspin = { values = [3.0, 5.0] }\n",
    );
    let case = case.to_str().unwrap();
    let stopped = scratch("stopped.csv");
    let child = common::command()
        .args([
            "sweep",
            "--case",
            case,
            "--threads",
            "1",
            "--out",
            stopped.to_str().unwrap(),
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let tmp = stopped.with_file_name(format!(".stopped.csv.tmp-{}", child.id()));
    let start = std::time::Instant::now();
    while std::fs::read_to_string(&tmp).map_or(0, |t| t.lines().count()) < 2 {
        assert!(start.elapsed().as_secs() < 120, "no rows written");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(!stopped.exists(), "the target exists before the sweep ends");
    let kill = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{err}");
    assert!(err.contains("--resume"), "{err}");
    let kept = sorted_lines(&stopped);
    assert!(
        !kept.is_empty() && kept.len() < 300,
        "{} rows kept",
        kept.len()
    );
    assert!(!tmp.exists(), "the temporary file was left behind");
    let resumed = routh(&[
        "sweep",
        "--case",
        case,
        "--out",
        stopped.to_str().unwrap(),
        "--resume",
        "--json",
    ]);
    assert!(
        resumed.status.success(),
        "{}",
        String::from_utf8_lossy(&resumed.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&resumed.stdout).unwrap();
    assert_eq!(v["resumed"], kept.len());
    assert_eq!(v["ran"], 300 - kept.len());
    let whole = scratch("whole.csv");
    let run = routh(&["sweep", "--case", case, "--out", whole.to_str().unwrap()]);
    assert!(run.status.success());
    assert_eq!(sorted_lines(&stopped), sorted_lines(&whole));
    // Resuming with other settings is refused: the rows would not be runs of that sweep.
    assert_exit_2(
        &[
            "sweep",
            "--case",
            case,
            "--out",
            whole.to_str().unwrap(),
            "--resume",
            "--t-end",
            "1",
        ],
        "cannot resume",
    );
}

/// Settings are validated once, by the library: `sweep` refuses a tolerance exactly as
/// `simulate` does (the same message, exit code 2), on both sides of the accepted range
/// (issue 32). Control: a tolerance inside the range is not refused by that rule.
#[test]
fn sweep_refuses_tolerances_as_simulate_does() {
    for rtol in ["1", "1e-20"] {
        let simulate = common::routh(&["simulate", "--rtol", rtol]);
        let sweep = common::routh(&["sweep", "--case", "cases/sweep.toml", "--rtol", rtol]);
        assert_eq!(simulate.status.code(), Some(2), "simulate --rtol {rtol}");
        assert_eq!(sweep.status.code(), Some(2), "sweep --rtol {rtol}");
        let message = |out: &std::process::Output| {
            String::from_utf8_lossy(&out.stderr)
                .lines()
                .find(|l| l.contains("rtol"))
                .map(str::to_string)
        };
        let (a, b) = (message(&simulate), message(&sweep));
        assert!(a.is_some(), "simulate names rtol: {a:?}");
        assert_eq!(a, b, "--rtol {rtol}");
    }
    let ok = common::routh(&["simulate", "--rtol", "1e-8", "--t-end", "0.1"]);
    assert_eq!(ok.status.code(), Some(0));
}
