//! The command-line tool as a user runs it: every command, its options, files and messages.
//!
//! One test binary, one module a topic (issue 32: few binaries, each named after what it proves).

mod batch_sweep {
    //! `routh sweep` in SIMD lanes (the default with DOP853) against `routh sweep --no-batch`
    //! (one run at a time): every row is the same, bit for bit (serde_json writes the shortest
    //! decimal that reads back to the same f64, so equal JSON numbers are equal doubles), on a
    //! grid that mixes bodies (runs of one body share lanes), fails some runs (max steps) and
    //! has more runs than lanes. Tolerance zero: the lanes do the one-at-a-time arithmetic.

    use crate::common;
    use common::routh;

    fn sweep_rows(case: &str, extra: &[&str]) -> Vec<serde_json::Value> {
        let mut args = vec!["sweep", "--json", "--case", case, "--threads", "2"];
        args.extend_from_slice(extra);
        let out = routh(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        json["rows"].as_array().unwrap().clone()
    }

    /// 25 tilts x 2 spins x 2 offsets = 100 runs (two bodies, interleaved in the grid), with
    /// max_steps low enough that the fastest spins fail: the rows in lanes and one at a time are
    /// equal, failures included (same message). Negative control: the rows at another tolerance
    /// differ.
    #[test]
    fn sweep_rows_in_lanes_equal_one_at_a_time_bitwise() {
        rows_in_lanes_equal_one_at_a_time("dop853", "150");
    }

    /// The same with `--method taylor` (the Taylor lanes of `routh::batch::taylor`), max_steps
    /// set so that the fastest spins fail (the runs take 8 to 150 steps at rtol 1e-10 with the
    /// order rule of `taylor::step_exponent`; 120 fails the fast spins only).
    #[test]
    fn taylor_sweep_rows_in_lanes_equal_one_at_a_time_bitwise() {
        rows_in_lanes_equal_one_at_a_time("taylor", "120");
    }

    fn rows_in_lanes_equal_one_at_a_time(method: &str, max_steps: &str) {
        let dir = std::env::temp_dir().join(format!("routh-batch-sweep-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let case = dir.join(format!("grid-{method}.toml"));
        std::fs::write(
            &case,
            "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\nG = 9.81\n\
         [initial]\ngamma = [0.0, 0.0, 1.0]\nomega = [0.5, 0.2, 8.0]\n\
         [integration]\nt_end = 4.0\nrtol = 1e-10\natol = 1e-10\n\
         [sweep]\ntilt = { range = [0.05, 1.5], n = 25 }\nspin = { values = [3.0, 40.0] }\n\
         \"body.a\" = { values = [0.1, 0.3] }\n",
        )
        .unwrap();
        let case = case.to_str().unwrap();
        let limit = ["--max-steps", max_steps, "--method", method];
        let lanes = sweep_rows(case, &limit);
        let alone = sweep_rows(case, &[&limit[..], &["--no-batch"]].concat());
        assert_eq!(lanes.len(), 100);
        let failed = lanes.iter().filter(|r| r["status"] == "failed").count();
        assert!(
            (1..100).contains(&failed),
            "{failed} runs failed: the grid should fail some, not all"
        );
        for (a, b) in lanes.iter().zip(&alone) {
            assert_eq!(a, b, "run {}", a["run"]);
        }
        let other = sweep_rows(case, &[&limit[..], &["--rtol", "1e-9"]].concat());
        let differ = lanes
            .iter()
            .zip(&other)
            .filter(|(a, b)| a["status"] == "ok" && a["final_M3"] != b["final_M3"])
            .count();
        assert!(differ > 40, "negative control: {differ} rows differ");
    }
}

mod cli_audit {
    //! The `routh audit` command: JSON output with the documented keys, the markdown report, and
    //! exit code 0 although some printed claims fail.

    use crate::common;
    use std::process::Command;

    fn routh() -> Command {
        common::command()
    }

    #[test]
    fn audit_json_is_an_array_of_verdicts_with_the_keys() {
        let out = routh()
            .args(["audit", "--json", "--points", "3", "--seed", "5"])
            .output()
            .unwrap();
        assert!(out.status.success(), "exit status {:?}", out.status);
        let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let verdicts = value.as_array().expect("a JSON array");
        assert!(verdicts.len() >= 25);
        for v in verdicts {
            for key in ["id", "label", "statement", "status", "residual", "note"] {
                assert!(v.get(key).is_some(), "missing {key} in {v}");
            }
            let status = v["status"].as_str().unwrap();
            assert!(["OK", "FAIL", "NOT-CHECKED", "OK-WITHIN-ANSATZ"].contains(&status));
        }
        assert!(verdicts.iter().any(|v| v["status"] == "FAIL"));
        let eq_cf = verdicts.iter().find(|v| v["id"] == "eq-cf").unwrap();
        assert_eq!(eq_cf["status"], "OK-WITHIN-ANSATZ");
        assert!(eq_cf["residual"].as_f64().unwrap() > 1e-2);
    }

    #[test]
    fn audit_markdown_writes_a_report_by_equation() {
        let dir = std::env::temp_dir().join(format!("routh-audit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("audit.md");
        let out = routh()
            .args(["audit", "--points", "3", "--markdown"])
            .arg(&file)
            .output()
            .unwrap();
        assert!(out.status.success());
        let table = String::from_utf8(out.stdout).unwrap();
        assert!(table.contains("p-br.jacobi") && table.contains("claims:"));
        let text = std::fs::read_to_string(&file).unwrap();
        assert!(text.starts_with("# Audit"));
        for heading in ["## (p-br)", "## (p-bv)", "## (g-eq3)", "## (int-sph2)"] {
            assert!(text.contains(heading), "missing {heading}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn audit_rejects_zero_points_with_exit_code_2() {
        let out = routh().args(["audit", "--points", "0"]).output().unwrap();
        assert_eq!(out.status.code(), Some(2));
    }
}

mod cli_exact_steady {
    //! The `routh exact` and `routh steady` commands run as a user would: JSON keys, CSV output,
    //! and exit code 2 with a message on bad input.

    use crate::common;
    use common::{assert_exit_2, routh};

    use common::json_of as json;

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
        assert!(lines[0]
            .starts_with("t,gamma1,gamma2,gamma3,M1,M2,M3,omega1,omega2,omega3,theta,H1,H3,K"));
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
    fn case_file(
        name: &str,
        body_edit: (&str, &str),
        gamma: &str,
        omega: &str,
    ) -> std::path::PathBuf {
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

    /// Issue 33, last item (test 4): the default case in units of mass 1e-300 (m = 1e-300,
    /// I1 = 4e-301, I3 = 5e-301; omega has no unit of mass), refused before by the absolute
    /// range of the inertia, is simulated by the binary with exit 0 and the default case's
    /// answer, with DOP853 and the Taylor method: gamma and `M / 1e-300` within 1e-8 of the
    /// default's after t = 1 (rtol = atol = 1e-12 of the case file: the two runs differ by
    /// the rounding of the decimal factor in each parameter, a relative 1e-16 amplified along
    /// the run, and by at most a step or two of the step control, well within 1e-8), and the
    /// energy's relative drift of the same size (each below 1e-12).
    #[test]
    fn simulate_takes_the_default_case_in_units_of_mass_1e_minus_300() {
        let dir = std::env::temp_dir().join(format!("routh-tiny-mass-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("case.toml");
        let default = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/default.toml"),
        )
        .unwrap();
        let tiny = default
            .replace("m = 1.0", "m = 1e-300")
            .replace("I1 = 0.4", "I1 = 4e-301")
            .replace("I3 = 0.5", "I3 = 5e-301");
        assert_ne!(tiny, default);
        std::fs::write(&path, tiny).unwrap();
        for method in ["dop853", "taylor"] {
            let run = |case: &std::path::Path| {
                json(&routh(&[
                    "simulate",
                    "--case",
                    case.to_str().unwrap(),
                    "--method",
                    method,
                    "--t-end",
                    "1",
                    "--json",
                ]))
            };
            let reference =
                run(&std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join("../../cases/default.toml"));
            let copy = run(&path);
            let values = |v: &serde_json::Value, key: &str, unit: f64| -> Vec<f64> {
                v["final_state"][key]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap() / unit)
                    .collect()
            };
            for (key, unit) in [("gamma", 1.0), ("M", 1e-300)] {
                let (a, b) = (values(&copy, key, unit), values(&reference, key, 1.0));
                for (x, y) in a.iter().zip(&b) {
                    assert!((x - y).abs() <= 1e-8, "{method} {key}: {a:?} {b:?}");
                }
            }
            let drift = |v: &serde_json::Value| v["integrals"]["H1"]["max_rel_drift"].as_f64();
            let (d, d0) = (drift(&copy).unwrap(), drift(&reference).unwrap());
            assert!(
                d <= 1e-12 && d0 <= 1e-12,
                "{method}: H1 drifts {d:e} {d0:e}"
            );
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

mod cli_flow {
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
}

mod cli_overflow_and_pipes {
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
}

mod cli_lyapunov {
    //! `routh lyapunov`, run as a user would (issue 36): on the two integrable cases every
    //! exponent is below 0.05 in absolute value at the case's own time, with the divergence
    //! check; the JSON keys; bad options refused with exit code 2.

    use crate::common;
    use common::{assert_exit_2, json_of, routh};

    /// The exponents of `routh lyapunov --json` with `args`, checked against the report's own
    /// divergence and history.
    fn exponents(args: &[&str]) -> (Vec<f64>, serde_json::Value) {
        let mut all = vec!["lyapunov", "--json"];
        all.extend_from_slice(args);
        let v = json_of(&routh(&all));
        let exponents: Vec<f64> = v["exponents"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        (exponents, v)
    }

    /// The default case (t = 100, measured largest |lambda| 0.026) and `cases/chaplygin.toml`
    /// (t = 1000, measured 0.0026): the five exponents on |gamma| = 1 are below 0.05 (they
    /// tend to 0 as ln T / T on the integrable motion); their sum equals the mean divergence to
    /// 1e-10 (Liouville's formula; measured 5.2e-14 and 6.8e-12 at tolerances 1e-12), which is below
    /// 1e-3 (the invariant measure: a bounded oscillation of ln rho over T). The history holds
    /// the 100 renormalisations of the default schedule, the last one the exponents. Negative
    /// control: over t = 5 the largest exponent is 0.55, above 0.05 (the check can fail).
    #[test]
    fn integrable_cases_have_every_exponent_below_0_05() {
        for case in ["cases/default.toml", "cases/chaplygin.toml"] {
            let (exponents, v) = exponents(&["--case", case]);
            assert_eq!(exponents.len(), 5, "{v}");
            assert!(
                exponents.iter().all(|l| l.abs() < 0.05),
                "{case}: {exponents:?}"
            );
            let sum = v["sum_of_exponents"].as_f64().unwrap();
            let divergence = v["divergence_mean"].as_f64().unwrap();
            assert!((sum - exponents.iter().sum::<f64>()).abs() < 1e-15);
            assert!((sum - divergence).abs() < 1e-10, "{sum} {divergence}");
            assert!(divergence.abs() < 1e-3, "{divergence}");
            let times = v["history"]["times"].as_array().unwrap();
            let estimates = v["history"]["exponents"].as_array().unwrap();
            assert_eq!((times.len(), estimates.len()), (100, 100));
            assert_eq!(times.last().unwrap(), &v["t_end"]);
            assert_eq!(estimates.last().unwrap(), &v["exponents"]);
            let dimension = v["kaplan_yorke_dimension"].as_f64().unwrap();
            assert!((4.9..=5.0).contains(&dimension), "{dimension}");
        }
        let (short, _) = exponents(&["--t-end", "5"]);
        assert!(short.iter().any(|l| l.abs() > 0.05), "{short:?}");
    }

    /// The settings come back in the JSON as given, with the command line's overrides.
    #[test]
    fn json_has_the_settings() {
        let (_, v) = exponents(&[
            "--t-end",
            "4",
            "--transient",
            "1",
            "--interval",
            "0.5",
            "--method",
            "vern9",
            "--rtol",
            "1e-10",
            "--atol",
            "1e-11",
        ]);
        for (key, want) in [
            ("t_end", 4.0),
            ("transient", 1.0),
            ("interval", 0.5),
            ("rtol", 1e-10),
            ("atol", 1e-11),
        ] {
            assert_eq!(v[key].as_f64(), Some(want), "{key}: {v}");
        }
        assert_eq!(v["method"], "vern9");
        assert_eq!(v["history"]["times"].as_array().unwrap().len(), 6);
        for key in ["steps", "rejected", "rhs_evals", "elapsed_s", "case"] {
            assert!(v.get(key).is_some(), "JSON lacks {key}");
        }
        let text = routh(&["lyapunov", "--t-end", "2"]);
        let text = String::from_utf8(text.stdout).unwrap();
        for needle in [
            "lambda5",
            "Kaplan-Yorke",
            "mean divergence",
            "<built-in default>",
        ] {
            assert!(text.contains(needle), "{needle}: {text}");
        }
    }

    /// Bad options: exit code 2 and a message naming the option and its rule.
    #[test]
    fn bad_options_are_refused_with_exit_2() {
        assert_exit_2(
            &["lyapunov", "--interval", "-1"],
            "invalid option interval = -1: must be finite, > 0 and <= t_end - transient",
        );
        assert_exit_2(
            &[
                "lyapunov",
                "--t-end",
                "10",
                "--transient",
                "0",
                "--interval",
                "20",
            ],
            "invalid option interval = 20",
        );
        assert_exit_2(
            &["lyapunov", "--interval", "NaN"],
            "invalid option interval = NaN",
        );
        assert_exit_2(
            &["lyapunov", "--t-end", "NaN"],
            "invalid option t_end = NaN",
        );
        assert_exit_2(
            &["lyapunov", "--transient", "100"],
            "invalid option transient = 100: must be finite, >= 0 and < t_end",
        );
        assert_exit_2(
            &["lyapunov", "--transient", "-1"],
            "invalid option transient = -1",
        );
        assert_exit_2(
            &["lyapunov", "--method", "taylor"],
            "invalid option method = taylor: must be dop853, vern9 or rk4",
        );
        assert_exit_2(&["lyapunov", "--rtol", "1"], "invalid option rtol = 1");
        assert_exit_2(
            &["lyapunov", "--case", "no/such/case.toml"],
            "no/such/case.toml",
        );
    }
}

mod sweep_events {
    //! User events in `routh sweep` (issue 34, item 3): planes of the state crossed in a
    //! direction (`[sweep] events`, `--events`), located on every accepted step of every lane
    //! by the one event locator, counted with the time of the first crossing. Checked against
    //! `routh section` with another integrator, lanes against one run at a time, the
    //! directions against each other, bad events refused, and a copy of the case in other
    //! units.

    use crate::common;
    use common::{assert_exit_2, json_of, routh};
    use serde_json::Value;
    use std::path::PathBuf;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("routh-sweep-events-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join(name)
    }

    /// The default body (in units scaled by `mass`, `length` and `time`) at rtol = atol =
    /// 1e-12 to `t_end` (in the unit of `time`), its spin omega = (0.5, 0.2, spin) over
    /// `time`, and the `[sweep]` table `sweep`.
    fn case_in_units(
        name: &str,
        [mass, length, time]: [f64; 3],
        t_end: f64,
        sweep: &str,
    ) -> PathBuf {
        let inertia = mass * length * length;
        let text = format!(
            "[body]\nm = {mass:?}\nR = {length:?}\na = {:?}\nI1 = {:?}\nI3 = {:?}\nG = {:?}\n\
             [initial]\ngamma = [0.0, 0.0, 1.0]\nomega = [{:?}, {:?}, 8.0]\n\
             [integration]\nt_end = {:?}\nrtol = 1e-12\natol = 1e-12\n{sweep}",
            0.3 * length,
            0.4 * inertia,
            0.5 * inertia,
            9.81 * length / (time * time),
            0.5 / time,
            0.2 / time,
            t_end * time,
        );
        let path = scratch(name);
        std::fs::write(&path, text).unwrap();
        path
    }

    fn case(name: &str, t_end: f64, sweep: &str) -> PathBuf {
        case_in_units(name, [1.0, 1.0, 1.0], t_end, sweep)
    }

    const GRID: &str =
        "[sweep]\ntilt = { values = [0.3, 0.8, 1.2] }\nspin = { values = [3.0, 8.0] }\n";

    fn rows(args: &[&str]) -> Vec<Value> {
        let mut all = vec!["sweep", "--json"];
        all.extend_from_slice(args);
        json_of(&routh(&all))["rows"].as_array().unwrap().clone()
    }

    /// The count and first time of `gamma1 = 0` crossings of each run of a sweep (the Taylor
    /// lanes, the default) equal those of `routh section --surface "gamma1 = 0" --direction
    /// both` on the run's case with Vern9 (another integrator and another dense output, one
    /// run at a time): the counts exactly, the first times within 1e-9. Both integrate to
    /// rtol = atol = 1e-12, so the two trajectories differ by about 1e-11 at t <= 10, and a
    /// crossing time by that over |d gamma1/dt| (at least 0.1 at these crossings): 1e-10,
    /// and the locator's own error is 2 ulp of t (4e-15). Negative control: the sections of
    /// `gamma1 = 0.05` have other first times.
    #[test]
    fn crossings_equal_those_of_routh_section_with_another_integrator() {
        let sweep = case("vs-section.toml", 10.0, GRID);
        let rows = rows(&["--case", sweep.to_str().unwrap(), "--events", "gamma1 = 0"]);
        assert_eq!(rows.len(), 6);
        let section = |single: &PathBuf, surface: &str| -> (u64, f64) {
            let out = scratch(&format!(
                "section-{}",
                single.file_stem().unwrap().to_str().unwrap()
            ));
            let _ = std::fs::remove_dir_all(&out);
            let v = json_of(&routh(&[
                "section",
                "--case",
                single.to_str().unwrap(),
                "--surface",
                surface,
                "--direction",
                "both",
                "--initial",
                "1",
                "--method",
                "vern9",
                "--out",
                out.to_str().unwrap(),
                "--json",
            ]));
            let csv = std::fs::read_to_string(out.join("section.csv")).unwrap();
            let first = csv
                .lines()
                .nth(1)
                .map_or(f64::NAN, |l| l.split(',').nth(1).unwrap().parse().unwrap());
            (v["crossings"].as_u64().unwrap(), first)
        };
        let mut worst = 0.0f64;
        for row in &rows {
            assert_eq!(row["status"], "ok", "{row}");
            let tilt = row["tilt"].as_f64().unwrap();
            let spin = row["spin"].as_f64().unwrap();
            let single = scratch(&format!("single-{}.toml", row["run"]));
            std::fs::write(
                &single,
                format!(
                    "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\nG = 9.81\n\
                     [initial]\ngamma = {:?}\nomega = [0.5, 0.2, {spin:?}]\n\
                     [integration]\nt_end = 10.0\nrtol = 1e-12\natol = 1e-12\n",
                    [tilt.sin(), 0.0, tilt.cos()]
                ),
            )
            .unwrap();
            let (count, first) = section(&single, "gamma1 = 0");
            assert!(count >= 2, "run {}: {count} crossings", row["run"]);
            assert_eq!(
                row["event0_count"].as_u64(),
                Some(count),
                "run {}",
                row["run"]
            );
            let t = row["event0_first_t"].as_f64().unwrap();
            worst = worst.max((t - first).abs());
            assert!(
                (t - first).abs() <= 1e-9,
                "run {}: {t} vs {first}",
                row["run"]
            );
            let (_, other) = section(&single, "gamma1 = 0.05");
            assert!((t - other).abs() > 1e-6, "negative control: {t} {other}");
        }
        eprintln!("sweep events vs routh section (vern9): first times within {worst:e}");
    }

    /// The event columns in lanes and one run at a time (`--no-batch`) are the same bit for
    /// bit, the turning points (`events`) watched with the user's events on the same steps,
    /// with both lane methods (DOP853's dense output costs 3 field evaluations on a step
    /// with a crossing: the same in both). Negative control: another tolerance moves the
    /// first times.
    #[test]
    fn event_columns_in_lanes_equal_one_at_a_time_bitwise() {
        let grid =
            "[sweep]\ntilt = { range = [0.05, 1.5], n = 9 }\nspin = { values = [3.0, 8.0] }\n";
        let sweep = case("lanes.toml", 5.0, grid);
        let sweep = sweep.to_str().unwrap();
        let events = "gamma1 = 0,gamma3 = 0.9 up,M1 = 0.5 down";
        for method in ["taylor", "dop853"] {
            let args = [
                "--case",
                sweep,
                "--method",
                method,
                "--events",
                events,
                "--columns",
                "all",
            ];
            let lanes = rows(&args);
            let alone = rows(&[&args[..], &["--no-batch"]].concat());
            assert_eq!(lanes.len(), 18);
            let crossed = lanes
                .iter()
                .filter(|r| r["event0_count"].as_u64() > Some(0))
                .count();
            assert!(crossed > 10, "{method}: {crossed} runs cross gamma1 = 0");
            for (a, b) in lanes.iter().zip(&alone) {
                assert_eq!(a, b, "{method}: run {}", a["run"]);
            }
            let other = rows(&[&args[..], &["--rtol", "1e-8", "--atol", "1e-8"]].concat());
            let moved = lanes
                .iter()
                .zip(&other)
                .filter(|(a, b)| a["event0_first_t"] != b["event0_first_t"])
                .count();
            assert!(moved > 10, "negative control: {moved} first times moved");
        }
    }

    /// gamma1 oscillates (the precession turns gamma about e3): its crossings of 0 alternate
    /// up and down, so `up` counts half of `both` (within one) and `up` plus `down` is
    /// `both`; the first crossing of `both` is the first of `up` or of `down`. Control: a
    /// plane never reached (`gamma3 = -0.99`) counts 0, with no first time.
    #[test]
    fn a_direction_counts_half_the_crossings_of_both() {
        let sweep = case("directions.toml", 10.0, GRID);
        let events = "gamma1 = 0,gamma1 = 0 up,gamma1 = 0 down,gamma3 = -0.99";
        for row in rows(&["--case", sweep.to_str().unwrap(), "--events", events]) {
            let count = |k: usize| row[format!("event{k}_count")].as_u64().unwrap();
            let first = |k: usize| row[format!("event{k}_first_t")].as_f64();
            let (both, up, down) = (count(0), count(1), count(2));
            assert!(both >= 4, "run {}: {both}", row["run"]);
            assert_eq!(up + down, both, "run {}", row["run"]);
            assert!(
                up.abs_diff(down) <= 1,
                "run {}: {up} up, {down} down",
                row["run"]
            );
            let (u, d) = (first(1).unwrap(), first(2).unwrap());
            assert_ne!(u, d);
            assert_eq!(first(0), Some(u.min(d)));
            assert_eq!((count(3), first(3)), (0, None), "run {}", row["run"]);
        }
    }

    /// Bad events exit with code 2 naming the key or the option, before any run, writing no
    /// table: an unknown name, a level that is not finite, a bad direction, a value that is
    /// not a list of texts, too many events, a column of an event the sweep does not have.
    /// Control: a good event writes the table.
    #[test]
    fn bad_events_are_refused_naming_the_key() {
        let out = scratch("refused.csv");
        let _ = std::fs::remove_file(&out);
        let out_arg = out.to_str().unwrap();
        for (listed, expected) in [
            (
                "[\"omega1 = 0\"]",
                "[sweep] key `events` = \"omega1 = 0\": must be NAME = NUMBER",
            ),
            ("[\"gamma1 = inf\"]", "`events` = \"gamma1 = inf\""),
            (
                "[\"gamma1 = 0 sideways\"]",
                "optional direction up, down or both",
            ),
            (
                "\"gamma1 = 0\"",
                "`events` = \"gamma1 = 0\": must be a list",
            ),
            ("[1.0]", "`events` = [1.0]: must be a list"),
        ] {
            let bad = case(
                "bad-events.toml",
                1.0,
                &format!("{GRID}events = {listed}\n"),
            );
            assert_exit_2(
                &["sweep", "--case", bad.to_str().unwrap(), "--out", out_arg],
                expected,
            );
            assert!(!out.exists(), "{listed}");
        }
        let good = case("good-events.toml", 1.0, GRID);
        let good = good.to_str().unwrap();
        let many = vec!["gamma1 = 0"; 33].join(",");
        for (events, expected) in [
            ("gamma1 = inf", "invalid option events = \"gamma1 = inf\""),
            ("gamma1 = 0:up", "invalid option events = \"gamma1 = 0:up\""),
            (
                "gamma1 = 0 left",
                "must be NAME = NUMBER with an optional direction",
            ),
            ("", "invalid option events = \"\""),
            (many.as_str(), "invalid option events = 33 events"),
        ] {
            assert_exit_2(
                &[
                    "sweep", "--case", good, "--events", events, "--out", out_arg,
                ],
                expected,
            );
            assert!(!out.exists(), "{events}");
        }
        assert_exit_2(
            &[
                "sweep",
                "--case",
                good,
                "--events",
                "gamma1 = 0",
                "--columns",
                "event1_count",
                "--out",
                out_arg,
            ],
            "unknown column `event1_count`",
        );
        assert!(!out.exists());
        let run = routh(&[
            "sweep",
            "--case",
            good,
            "--events",
            "gamma1 = 0",
            "--out",
            out_arg,
        ]);
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let header = std::fs::read_to_string(&out).unwrap();
        assert!(header
            .lines()
            .next()
            .unwrap()
            .ends_with(",event0_count,event0_first_t"));
    }

    /// The same sweep written in other units (mass x2, length x2, time x2: gamma and the
    /// events on gamma unchanged, M in m R^2 / T x4, times x2) counts the same crossings at
    /// the times scaled by 2. With DOP853 to 4 ulp: the units differ by powers of two, so
    /// the runs take the same steps in the motion's units (the same final states, to the bit)
    /// and the times agree to an ulp (measured: some equal, some an ulp apart). The Taylor
    /// lanes (the default) take the same steps but sum their series in the other units,
    /// whose rounding differs (final states and times 2e-15 apart, relative, measured):
    /// 1e-12. The `[sweep]` table's `events`
    /// (not the option) is read. Negative control: the M1 event left unscaled crosses
    /// elsewhere.
    #[test]
    fn events_in_other_units_are_the_same_crossings_scaled() {
        let table = |m1: &str, spins: &str| {
            format!(
                "[sweep]\ntilt = {{ values = [0.3, 0.8, 1.2] }}\nspin = {{ values = {spins} }}\n\
                 events = [\"gamma3 = 0.9\", \"gamma1 = 0.1 down\", \"M1 = {m1} up\"]\n"
            )
        };
        let one = case_in_units(
            "units-1.toml",
            [1.0, 1.0, 1.0],
            10.0,
            &table("0.25", "[3.0, 8.0]"),
        );
        let other = case_in_units(
            "units-2.toml",
            [2.0, 2.0, 2.0],
            10.0,
            &table("1.0", "[1.5, 4.0]"),
        );
        let unscaled = case_in_units(
            "units-3.toml",
            [2.0, 2.0, 2.0],
            10.0,
            &table("0.25", "[1.5, 4.0]"),
        );
        for (method, tolerance) in [("dop853", 4.0 * f64::EPSILON), ("taylor", 1e-12)] {
            let rows_of =
                |case: &PathBuf| rows(&["--case", case.to_str().unwrap(), "--method", method]);
            let (a, b, c) = (rows_of(&one), rows_of(&other), rows_of(&unscaled));
            let (mut crossed, mut differ) = ([0; 3], 0);
            for ((a, b), c) in a.iter().zip(&b).zip(&c) {
                for (k, crossed) in crossed.iter_mut().enumerate() {
                    let (count, first) = (format!("event{k}_count"), format!("event{k}_first_t"));
                    let run = format!("{method}, run {}, event {k}", a["run"]);
                    assert_eq!(a[&count], b[&count], "{run}");
                    if let (Some(ta), Some(tb)) = (a[&first].as_f64(), b[&first].as_f64()) {
                        assert!((2.0 * ta - tb).abs() <= tolerance * tb, "{run}: {ta} {tb}");
                        *crossed += 1;
                    }
                    assert_eq!(a[&first].is_null(), b[&first].is_null(), "{run}");
                }
                differ += usize::from(c["event2_first_t"] != b["event2_first_t"]);
            }
            // gamma3 = 0.9 is crossed by the slow spin from the smallest tilt only; the
            // others from every start.
            assert_eq!(crossed, [1, a.len(), a.len()], "{method}");
            assert_eq!(differ, a.len(), "negative control");
        }
    }
}

mod cli_section {
    //! `routh section`, run as a user would (issue 36, item 3): the command the issue asks to
    //! show writes a PNG, an SVG and a CSV of at least 100 crossings on the plane; bad surfaces
    //! refused with exit code 2 and no file.

    use crate::common;
    use common::{assert_exit_2, json_of, routh};

    /// `routh section --surface "gamma1 = 0" --out DIR --json` on the default case (20 runs
    /// over t = 100, DOP853 in lanes at 1e-12): at least 100 crossings in the CSV, each with
    /// |gamma1| <= 1e-10 (Brent's method locates the time to 2 ulp of t, about 3e-14 at
    /// t = 100, and gamma1 moves at most |omega| ~ 8.3 per unit time: 2.5e-13 with round-off,
    /// so 1e-10 has a margin of 400) and gamma1 rising (gamma2 omega3 - gamma3 omega2 > 0);
    /// H1 of each row within 1e-9 relative of the level (the drift of DOP853 at 1e-12 over
    /// t = 100: measured below); the JSON's count and largest distance are the CSV's; the PNG
    /// and SVG are there. Negative control: the CSV's gamma2 column is not on the plane.
    #[test]
    fn default_case_section_writes_png_svg_and_csv() {
        let dir = std::env::temp_dir().join(format!("routh-cli-section-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let out = dir.to_str().unwrap();
        let v = json_of(&routh(&[
            "section",
            "--surface",
            "gamma1 = 0",
            "--out",
            out,
            "--json",
        ]));
        for name in ["section.png", "section.svg", "section.csv"] {
            let size = std::fs::metadata(dir.join(name)).unwrap().len();
            assert!(size > 1000, "{name}: {size} bytes");
        }
        let csv = std::fs::read_to_string(dir.join("section.csv")).unwrap();
        let mut lines = csv.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        assert_eq!(
            &header[..11],
            [
                "run", "t", "gamma1", "gamma2", "gamma3", "M1", "M2", "M3", "omega1", "omega2",
                "omega3"
            ]
        );
        let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
        let rows: Vec<Vec<f64>> = lines
            .map(|l| {
                l.split(',')
                    .map(|c| c.parse().unwrap_or(f64::NAN))
                    .collect()
            })
            .collect();
        assert!(rows.len() >= 100, "{}", rows.len());
        assert_eq!(v["crossings"].as_u64(), Some(rows.len() as u64));
        let level = v["energy"].as_f64().unwrap();
        let (mut largest, mut drift, mut off_plane) = (0.0f64, 0.0f64, 0.0f64);
        for r in &rows {
            largest = largest.max(r[col("gamma1")].abs());
            off_plane = off_plane.max(r[col("gamma2")].abs());
            drift = drift.max(((r[col("H1")] - level) / level).abs());
            let rate = r[col("gamma2")] * r[col("omega3")] - r[col("gamma3")] * r[col("omega2")];
            assert!(rate > 0.0, "{r:?}");
        }
        eprintln!(
            "routh section: {} crossings, |gamma1| <= {largest:e}, drift {drift:e}, {} s",
            rows.len(),
            v["elapsed_s"]
        );
        assert!(largest <= 1e-10, "{largest}");
        assert_eq!(v["max_surface_value"].as_f64(), Some(largest));
        assert!(drift < 1e-9, "{drift}");
        assert!(v["max_energy_drift"].as_f64().unwrap() < 1e-9);
        assert!(off_plane > 0.1);
        assert_eq!(v["surface"], "gamma1 = 0");
        assert_eq!(v["direction"], "up");
        assert_eq!(v["files"].as_array().unwrap().len(), 3);
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Malformed surfaces, directions and axes: exit code 2, the option named, no directory
    /// written.
    #[test]
    fn bad_surfaces_are_refused_with_exit_2() {
        let dir =
            std::env::temp_dir().join(format!("routh-cli-section-bad-{}", std::process::id()));
        let out = dir.to_str().unwrap();
        for surface in [
            "gamma1",
            "omega1 = 0",
            "gamma1 = x",
            "gamma1 = inf",
            "= 0",
            "",
        ] {
            assert_exit_2(
                &["section", "--surface", surface, "--out", out],
                "invalid option surface",
            );
        }
        assert_exit_2(
            &[
                "section",
                "--surface",
                "gamma1 = 0",
                "--direction",
                "left",
                "--out",
                out,
            ],
            "invalid option direction = \"left\": must be up, down or both",
        );
        assert_exit_2(
            &[
                "section",
                "--surface",
                "gamma1 = 0",
                "--axes",
                "gamma3",
                "--out",
                out,
            ],
            "invalid option axes",
        );
        assert_exit_2(
            &[
                "section",
                "--surface",
                "gamma1 = 0",
                "--initial",
                "0",
                "--out",
                out,
            ],
            "invalid option initial = 0",
        );
        assert_exit_2(
            &[
                "section",
                "--surface",
                "gamma1 = 0",
                "--method",
                "taylor",
                "--out",
                out,
            ],
            "invalid option method = taylor",
        );
        assert!(!dir.exists());
    }
}

mod cli_simulate {
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
                "simulate", "--t-end", "1", "--method", "auto", "--rtol", tol, "--atol", tol,
                "--json",
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
}

mod cli_sweep {
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
        crate::common::json_of(&routh(&all))
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
            // The default columns locate no turning point (whose dense output would cost
            // DOP853 3 more field evaluations each): the same count.
            assert_eq!(row["rhs_evals"], sim["rhs_evals"], "run {}", row["run"]);
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
        let v = sweep_json(&["--case", case.to_str().unwrap(), "--columns", "nutation"]);
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
        let other = rows[0]["period_events"].as_f64().unwrap()
            - rows[6]["period_quadrature"].as_f64().unwrap();
        assert!(other.abs() > 1e-3, "negative control: {other}");
    }

    /// Every column of the table before `--columns` (issue 34), written out here as the
    /// README listed them: `--columns all` gives exactly this table.
    const ALL_COLUMNS: &str =
        "run,spin,tilt,t_end,rtol,atol,method,status,message,steps,rejected,rhs_evals,\
        final_gamma1,final_gamma2,final_gamma3,final_M1,final_M2,final_M3,\
        H1_initial,H1_final,H1_drift,H2_initial,H2_final,H2_drift,H3_initial,H3_final,H3_drift,\
        H4_initial,H4_final,H4_drift,K_initial,K_final,K_drift,theta_min,theta_max,\
        period_events,period_quadrature,period_difference,precession_events,\
        precession_quadrature,precession_difference";

    /// The CSV header and rows of `routh sweep` on `case` with `args`.
    fn sweep_csv(case: &Path, args: &[&str]) -> (String, Vec<String>) {
        let mut all = vec!["sweep", "--case", case.to_str().unwrap()];
        all.extend_from_slice(args);
        let out = routh(&all);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout).unwrap();
        let mut lines = text.lines().map(str::to_string);
        let header = lines.next().unwrap();
        (header, lines.collect())
    }

    /// A table holds the columns asked for, in the table's order whatever the order asked:
    /// `all` is the old table (compared with the names written out above), the default is the
    /// final state and the integrals, a group or a single name adds its columns, the
    /// `[sweep]` key chooses them and `--columns` overrides it. The values of a column do not
    /// depend on the others asked (the same doubles, tolerance zero).
    #[test]
    fn a_table_holds_the_columns_asked_for() {
        let sweep = "[sweep]\ntilt = { values = [0.4, 0.9] }\nspin = { values = [4.0] }\n";
        let case = case_file("columns.toml", [0.0, 0.0, 1.0], [0.5, 0.2, 8.0], 3.0, sweep);
        let (all, all_rows) = sweep_csv(&case, &["--columns", "all"]);
        assert_eq!(all, ALL_COLUMNS);
        let names: Vec<&str> = ALL_COLUMNS.split(',').collect();
        let keep = |pred: &dyn Fn(&str) -> bool| -> String {
            names
                .iter()
                .copied()
                .filter(|n| pred(n))
                .collect::<Vec<_>>()
                .join(",")
        };
        let always = |n: &str| names[..12].contains(&n);
        let integral = |n: &str| {
            ["_initial", "_final", "_drift"]
                .iter()
                .any(|e| n.ends_with(e))
                && !n.starts_with("final_")
        };
        let (default, default_rows) = sweep_csv(&case, &[]);
        assert_eq!(
            default,
            keep(&|n| always(n) || n.starts_with("final_") || integral(n))
        );
        let (quad, _) = sweep_csv(&case, &["--columns", "period_events,quadrature"]);
        assert_eq!(
            quad,
            keep(&|n| always(n)
                || [
                    "period_events",
                    "period_quadrature",
                    "precession_quadrature"
                ]
                .contains(&n))
        );
        // Each column of the default table has the values of the same column of `all`.
        for (a, d) in all_rows.iter().zip(&default_rows) {
            let a: Vec<&str> = a.split(',').collect();
            for (i, cell) in d.split(',').enumerate() {
                let name = default.split(',').nth(i).unwrap();
                let j = names.iter().position(|n| *n == name).unwrap();
                if name != "rhs_evals" {
                    assert_eq!(cell, a[j], "{name}");
                }
            }
        }
        // The `[sweep]` key, and `--columns` over it.
        let listed = case_file(
            "columns-listed.toml",
            [0.0, 0.0, 1.0],
            [0.5, 0.2, 8.0],
            3.0,
            &format!("{sweep}columns = [\"events\", \"final_M3\"]\n"),
        );
        let (header, _) = sweep_csv(&listed, &[]);
        assert_eq!(
            header,
            keep(&|n| always(n)
                || n == "final_M3"
                || n.starts_with("theta_")
                || n.ends_with("_events"))
        );
        assert_eq!(sweep_csv(&listed, &["--columns", "all"]).0, ALL_COLUMNS);
    }

    /// What is not asked is not computed. The turning points: located only when asked, DOP853
    /// (asked for: the default, the Taylor lanes, evaluates its series without the field)
    /// prepares its dense output on their steps (3 field evaluations each), so `rhs_evals` is
    /// larger with `events` than without (and equal to `routh simulate`'s without, in
    /// `every_run_equals_routh_simulate`). The quadrature: for a body that is not a Routh
    /// sphere the row says why there is none only when a quadrature column is asked.
    #[test]
    fn columns_not_asked_are_not_computed() {
        let case = case_file(
            "not-asked.toml",
            [0.0, 0.0, 1.0],
            [0.5, 0.2, 8.0],
            5.0,
            "[sweep]\ntilt = { values = [0.5] }\n\"body.I2\" = { values = [0.4, 0.45] }\n",
        );
        let case = case.to_str().unwrap();
        let dop853 = ["--case", case, "--method", "dop853", "--columns"];
        let plain = sweep_json(&[&dop853[..], &["final"]].concat());
        let events = sweep_json(&[&dop853[..], &["final,events"]].concat());
        let quadrature = sweep_json(&["--case", case, "--columns", "quadrature"]);
        for i in 0..2 {
            let (p, e) = (&plain["rows"][i], &events["rows"][i]);
            assert_eq!(p["final_M3"], e["final_M3"]);
            assert!(e["rhs_evals"].as_u64() > p["rhs_evals"].as_u64(), "{p} {e}");
            assert_eq!(p["message"], "", "{p}");
        }
        let q = &quadrature["rows"];
        assert_eq!(q[0]["message"], "", "I1 = I2: a quadrature");
        assert!(q[0]["period_quadrature"].is_f64());
        assert!(
            q[1]["message"].as_str().unwrap().contains("no quadrature"),
            "{}",
            q[1]
        );
    }

    /// A name that is neither a column nor a group is refused before any run (exit 2),
    /// naming the option or key and the name, and listing the groups and the columns.
    #[test]
    fn unknown_columns_are_refused_listing_the_valid_ones() {
        let sweep = "[sweep]\ntilt = { values = [0.4] }\n";
        let case = case_file(
            "bad-columns.toml",
            [0.0, 0.0, 1.0],
            [0.5, 0.2, 8.0],
            1.0,
            sweep,
        );
        let case = case.to_str().unwrap();
        for expected in [
            "--columns",
            "`theta`",
            "nutation",
            "final_gamma1",
            "precession_difference",
        ] {
            assert_exit_2(
                &["sweep", "--case", case, "--columns", "final,theta"],
                expected,
            );
        }
        for (listed, expected) in [
            (
                "[\"final\", \"bogus\"]",
                "`columns` = \"bogus\": unknown column `bogus`",
            ),
            ("\"all\"", "`columns` = \"all\": must be a list"),
        ] {
            let bad = case_file(
                "bad-columns-listed.toml",
                [0.0, 0.0, 1.0],
                [0.5, 0.2, 8.0],
                1.0,
                &format!("{sweep}columns = {listed}\n"),
            );
            assert_exit_2(&["sweep", "--case", bad.to_str().unwrap()], expected);
        }
        // Control: valid names run.
        assert!(
            routh(&["sweep", "--case", case, "--columns", "events,final_M1"])
                .status
                .success()
        );
    }

    /// `--resume` continues a table with the columns it was written with, and refuses other
    /// columns, naming those that differ (CSV and Parquet). Control: the same columns resume.
    #[test]
    fn resume_refuses_a_table_of_other_columns() {
        let case = case_file(
            "resume-columns.toml",
            [0.0, 0.0, 1.0],
            [0.5, 0.2, 8.0],
            1.0,
            "[sweep]\ntilt = { values = [0.4, 0.5] }\n",
        );
        let case = case.to_str().unwrap();
        for ext in ["csv", "parquet"] {
            let table = scratch(&format!("resume-columns.{ext}"));
            let target = table.to_str().unwrap();
            let written = routh(&["sweep", "--case", case, "--out", target]);
            assert!(
                written.status.success(),
                "{}",
                String::from_utf8_lossy(&written.stderr)
            );
            assert_exit_2(
                &[
                    "sweep",
                    "--case",
                    case,
                    "--out",
                    target,
                    "--resume",
                    "--columns",
                    "all",
                ],
                "asked for only: theta_min",
            );
            assert_exit_2(
                &[
                    "sweep",
                    "--case",
                    case,
                    "--out",
                    target,
                    "--resume",
                    "--columns",
                    "final",
                ],
                "the file's only: H1_initial",
            );
            let again = sweep_json(&["--case", case, "--out", target, "--resume"]);
            assert_eq!(
                (again["resumed"].as_u64(), again["ran"].as_u64()),
                (Some(2), Some(0)),
                "{ext}"
            );
        }
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
            100.0,
            // Long enough (about a second in the Taylor lanes) that the signal comes halfway.
            "[sweep]\ntilt = { range = [0.3, 1.4], n = 1500 }\nspin = { values = [3.0, 5.0] }\n",
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
        let tmp = stopped.with_file_name(format!(".stopped.csv.tmp-{}-0", child.id()));
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
            !kept.is_empty() && kept.len() < 3000,
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
        assert_eq!(v["ran"], 3000 - kept.len());
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
}

mod diagram_cli {
    //! `routh diagram` run as a user would: the JSON keys, the files written, exit code 2 with a
    //! message on bad input.

    use crate::common;
    use common::{assert_exit_2, routh};

    /// Run `routh diagram` with `args`, `--out dir` and `--json`; the parsed JSON.
    fn diagram_json(args: &[&str], dir: &std::path::Path) -> serde_json::Value {
        let mut all = vec!["diagram", "--out", dir.to_str().unwrap(), "--json"];
        all.extend_from_slice(args);
        let out = routh(&all);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).unwrap()
    }

    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("routh-diagram-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    /// The JSON at H3 = 1 (the default body's top spin below Routh's threshold) has the critical
    /// curves with their stability types and points, the focus–focus point with its integrals and
    /// state, and the monodromy with its loop and the integer matrix [[1, -1], [0, 1]]; every file
    /// it lists exists and is not empty.
    #[test]
    fn json_has_the_required_keys_and_files() {
        let dir = temp_dir("keys");
        let v = diagram_json(&["--h3", "1", "--tilts", "120", "--grid", "24"], &dir);
        let curves = v["critical_curves"].as_array().unwrap();
        assert!(curves.len() >= 2);
        for c in curves {
            assert!(c["stability"].is_string());
            let points = c["points"].as_array().unwrap();
            assert!(!points.is_empty());
            for key in ["H1", "H3", "K", "theta", "state", "stability"] {
                assert!(points[0].get(key).is_some(), "curve point lacks {key}");
            }
        }
        let ff = v["focus_focus"].as_array().unwrap();
        assert_eq!(ff.len(), 1);
        for key in ["H1", "H3", "K", "state"] {
            assert!(ff[0].get(key).is_some(), "focus_focus lacks {key}");
        }
        assert_eq!(ff[0]["H3"], 1.0);
        let m = &v["monodromy"];
        assert!(m["loop"].as_array().unwrap().len() >= 64);
        for key in ["H1", "H3", "K", "period", "advance", "rotation_number"] {
            assert!(m["loop"][0].get(key).is_some(), "loop point lacks {key}");
        }
        assert_eq!(m["matrix"], serde_json::json!([[1, -1], [0, 1]]));
        let files = v["files"].as_array().unwrap();
        for stem in [
            "diagram.png",
            "diagram.svg",
            "diagram_sleeping_top.png",
            "diagram_rotation_number.svg",
            "diagram_curves.csv",
            "diagram_loop.csv",
            "diagram_tori.csv",
        ] {
            assert!(
                files.iter().any(|f| f.as_str().unwrap().ends_with(stem)),
                "{stem} not listed"
            );
            let size = std::fs::metadata(dir.join(stem)).unwrap().len();
            assert!(size > 100, "{stem}: {size} bytes");
        }
        let curves_csv = std::fs::read_to_string(dir.join("diagram_curves.csv")).unwrap();
        assert!(curves_csv.starts_with("branch,stability,theta,K,H1,H3"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// At the default case's own H3 (fast spin) there is no focus–focus point: the list is empty
    /// and the monodromy null, and the case's value has one torus.
    #[test]
    fn default_plane_has_no_focus_focus_point() {
        let dir = temp_dir("default");
        let v = diagram_json(&["--tilts", "60", "--grid", "12"], &dir);
        assert_eq!(v["focus_focus"].as_array().unwrap().len(), 0);
        assert!(v["monodromy"].is_null());
        assert_eq!(v["case_in_plane"], true);
        assert_eq!(v["case_value"]["intervals"].as_array().unwrap().len(), 1);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// Bad input: exit 2 with the option or key named, no panic, nothing written.
    #[test]
    fn bad_input_exits_2() {
        let dir = temp_dir("bad");
        let out = dir.to_str().unwrap().to_string();
        assert_exit_2(&["diagram", "--h3", "nan", "--out", &out], "h3");
        assert_exit_2(&["diagram", "--h3", "inf", "--out", &out], "h3");
        assert_exit_2(&["diagram", "--tilts", "1", "--out", &out], "tilts");
        assert_exit_2(&["diagram", "--grid", "100000", "--out", &out], "grid");
        assert_exit_2(
            &["diagram", "--loop-points", "3", "--out", &out],
            "loop_points",
        );
        assert!(!dir.exists(), "a refused run created {}", dir.display());
        let case =
            std::env::temp_dir().join(format!("routh-diagram-asym-{}.toml", std::process::id()));
        std::fs::write(
        &case,
        "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI2 = 0.45\nI3 = 0.5\n[initial]\ngamma = [0.0, 0.0, 1.0]\nomega = [0.0, 0.0, 1.0]\n",
    )
    .unwrap();
        assert_exit_2(
            &["diagram", "--case", case.to_str().unwrap(), "--out", &out],
            "I1 = I2",
        );
        std::fs::remove_file(&case).unwrap();
        let file = std::env::temp_dir().join(format!("routh-diagram-file-{}", std::process::id()));
        std::fs::write(&file, "x").unwrap();
        assert_exit_2(
            &[
                "diagram",
                "--tilts",
                "20",
                "--grid",
                "4",
                "--out",
                file.to_str().unwrap(),
            ],
            "routh-diagram-file",
        );
        std::fs::remove_file(&file).unwrap();
    }
}

mod steady_and_diagram_scales {
    //! Issue 33: the sizes `steady` and `diagram` accept are bounded before any work, and the
    //! numbers they print are named for what they are, each checked against an independent
    //! computation.

    use crate::common;
    use common::{assert_exit_2, routh};
    use routh::case::Case;
    use std::time::{Duration, Instant};

    /// A coarse resolution of `diagram`, for runs that check keys and refusals.
    const QUICK: [&str; 6] = ["--tilts", "20", "--grid", "4", "--loop-points", "8"];

    use crate::common::json_of as json;

    /// The default case with its omega replaced by `(0, 0, spin)`.
    fn spinning(name: &str, spin: &str) -> std::path::PathBuf {
        let text = std::fs::read_to_string(format!("{}/cases/default.toml", common::ROOT)).unwrap();
        let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
        let spun = text.replace(
            "omega = [0.5, 0.2, 8.0]",
            &format!("omega = [0.0, 0.0, {spin}]"),
        );
        std::fs::write(&path, spun).unwrap();
        path
    }

    /// `--h3 1e300` ran without end; spins of 1e80 and 1e100 are beyond the range of f64 in
    /// the body's units (their squares above 1e150). Each is refused within 5 s (a generous bound for a loaded machine:
    /// the refusal is made before any work, in milliseconds) with exit 2 and a message naming
    /// the option, the value and the rule. Negative control: the largest H3 the message states
    /// is accepted.
    #[test]
    fn huge_h3_and_spins_are_refused_quickly() {
        let dir = std::env::temp_dir().join(format!("routh-scales-{}", std::process::id()));
        let out = dir.to_str().unwrap().to_string();
        let started = Instant::now();
        assert_exit_2(
            &["diagram", "--h3", "1e300", "--out", &out],
            "invalid option h3 = 1e300",
        );
        assert_exit_2(
            &["diagram", "--h3", "-1e300", "--out", &out],
            "Routh's threshold",
        );
        for (spin, printed) in [("1e80", "e79"), ("1e100", "e99")] {
            // The spin printed is omega3 of the case's state: the value to a few ulp.
            let case = spinning(&format!("spin_{spin}.toml"), spin);
            let out = routh(&["steady", "--case", case.to_str().unwrap()]);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{err}");
            assert!(
                err.contains("the spin omega3 = ") && err.contains(printed),
                "{err}"
            );
            assert!(
                err.contains("the rule: the rate of the motion at most 1e75"),
                "{err}"
            );
        }
        assert!(
            started.elapsed() < Duration::from_secs(5),
            "{:?}",
            started.elapsed()
        );
        assert!(!dir.exists(), "a refused run created {}", dir.display());
        let err = String::from_utf8(routh(&["diagram", "--h3", "1e300"]).stderr).unwrap();
        let limit: f64 = err
            .split("|H3| <= ")
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        let h3 = format!("{}", 0.999 * limit);
        let args = [
            &["diagram", "--h3", &h3, "--out", &out, "--json"],
            &QUICK[..],
        ]
        .concat();
        let value = json(&routh(&args));
        for spin in value["vertical_spins"].as_array().unwrap() {
            assert_eq!(spin["stability"], "elliptic");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// `steady --json`: Routh's threshold as a number or `null` with the reason (beside the old
    /// `threshold_spin`, 0 where there is none), one verdict per motion, and the precession of
    /// the symmetry axis in space beside the body-frame rate. The axis's rate is checked by
    /// kinematics from the state alone: e3 turns in space at `omega x e3` (body components),
    /// so its azimuth about the upward vertical `-gamma` turns at
    /// `((-gamma) x e3) . (omega x e3) / |gamma x e3|^2`, to 1e-12 relative (a few roundings).
    /// Negative control: the body-frame rate `precession` does not pass that check.
    #[test]
    fn steady_json_names_its_numbers() {
        let v = json(&routh(&["steady", "--json"]));
        let body = Case::default_case().unwrap().body("").unwrap();
        assert_eq!(v["routh_threshold"], v["threshold_spin"]);
        assert!(v["no_threshold"].is_null());
        let vertical = v["vertical"].as_array().unwrap();
        assert_eq!(
            vertical[0]["routh_threshold"],
            vertical[0]["threshold_spin"]
        );
        assert!(vertical[1]["routh_threshold"].is_null());
        assert_eq!(vertical[1]["threshold_spin"], 0.0);
        assert!(vertical[1]["no_threshold"]
            .as_str()
            .unwrap()
            .contains("below"));
        for spin in vertical {
            assert_eq!(spin["verdict"]["decision"], "stable");
            assert!(spin["verdict"]["q_accuracy"].as_f64().unwrap() > 0.0);
        }
        let precessions = v["precessions"].as_array().unwrap();
        assert!(precessions.len() >= 20);
        for p in precessions {
            let gamma: Vec<f64> = serde_json::from_value(p["state"]["gamma"].clone()).unwrap();
            let m: Vec<f64> = serde_json::from_value(p["state"]["M"].clone()).unwrap();
            let state = routh::State::new(
                [gamma[0], gamma[1], gamma[2]],
                [m[0], m[1], m[2]],
                routh::state::Normalise::Reject,
            )
            .unwrap();
            let w = state.omega(&body);
            let up = [-gamma[0], -gamma[1], -gamma[2]];
            let cross = |a: [f64; 3], b: [f64; 3]| {
                [
                    a[1] * b[2] - a[2] * b[1],
                    a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0],
                ]
            };
            let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            let e3 = [0.0, 0.0, 1.0];
            let across = cross(up, e3);
            let rate = dot(across, cross(w, e3)) / dot(across, across);
            let axis = p["axis_precession"].as_f64().unwrap();
            assert!(
                (axis - rate).abs() <= 1e-12 * rate.abs(),
                "{axis} vs {rate}"
            );
            let body_rate = p["precession"].as_f64().unwrap();
            assert!((body_rate - rate).abs() > 1e-3 * rate.abs());
            assert!(p["omega_t_accuracy"].as_f64().unwrap() >= 0.0);
        }
        // The text names both rates.
        let text = String::from_utf8(routh(&["steady"]).stdout).unwrap();
        assert!(
            text.contains("dphi/dt: the symmetry axis e3 about the upward vertical"),
            "{text}"
        );
    }

    /// `diagram --json`: labelled eigenvalues beside the old pairs (equal, and at a steady
    /// precession `re^2 - im^2 = Q''/2` of the reduced equation to 1e-7, as the library's
    /// test), the monodromy's basis, convention and orientation (the loop's signed area in the
    /// plane (K, H1), by the shoelace formula, is positive: counter-clockwise, as stated), and
    /// without `--out` the directory it wrote to, in the JSON and on standard error.
    #[test]
    fn diagram_json_names_its_numbers_and_where_it_wrote() {
        let dir = std::env::temp_dir().join(format!("routh-no-out-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_routh"))
            .current_dir(&dir)
            .args([
                "diagram",
                "--h3",
                "1",
                "--tilts",
                "60",
                "--grid",
                "12",
                "--loop-points",
                "32",
            ])
            .arg("--json")
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        let v = json(&out);
        assert_eq!(v["out_from"], "default");
        let written = std::path::PathBuf::from(v["out"].as_str().unwrap());
        assert_eq!(written, dir.canonicalize().unwrap().join("diagram"));
        assert!(
            err.contains("no --out given") && err.contains(&written.display().to_string()),
            "{err}"
        );
        for file in v["files"].as_array().unwrap() {
            assert!(dir.join(file.as_str().unwrap()).exists(), "{file}");
        }
        let points = v["critical_curves"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|c| c["points"].as_array().unwrap().clone());
        for p in points.chain(v["vertical_spins"].as_array().unwrap().clone()) {
            let pairs = p["eigenvalues"].as_array().unwrap();
            let labelled = p["spectrum"].as_array().unwrap();
            assert_eq!(pairs.len(), labelled.len());
            for (pair, l) in pairs.iter().zip(labelled) {
                assert_eq!((&pair[0], &pair[1]), (&l["re"], &l["im"]));
            }
            let theta = p["theta"].as_f64().unwrap();
            if theta > 0.0 && theta < std::f64::consts::PI {
                let (re, im) = (
                    labelled[0]["re"].as_f64().unwrap(),
                    labelled[0]["im"].as_f64().unwrap(),
                );
                let half = 0.5 * p["q_second_derivative"].as_f64().unwrap();
                assert!((re * re - im * im - half).abs() <= 1e-7 * half.abs());
                assert!(p["axis_precession"].is_number());
            } else {
                assert!(p["axis_precession"].is_null());
            }
        }
        let m = &v["monodromy"];
        assert!(m["basis"][0]
            .as_str()
            .unwrap()
            .starts_with("b1 = (t, phi) = (0, 2 pi)"));
        assert!(m["convention"]
            .as_str()
            .unwrap()
            .contains("columns are the images"));
        assert!(m["orientation"]
            .as_str()
            .unwrap()
            .starts_with("counter-clockwise"));
        let lp = m["loop"].as_array().unwrap();
        let area: f64 = lp
            .windows(2)
            .map(|w| {
                let (k0, h0) = (w[0]["K"].as_f64().unwrap(), w[0]["H1"].as_f64().unwrap());
                let (k1, h1) = (w[1]["K"].as_f64().unwrap(), w[1]["H1"].as_f64().unwrap());
                k0 * h1 - k1 * h0
            })
            .sum();
        assert!(area > 0.0, "{area}");
        // Negative control: with --out nothing is said on standard error.
        let with_out = std::process::Command::new(env!("CARGO_BIN_EXE_routh"))
            .current_dir(&dir)
            .args(["diagram", "--out", "given"])
            .args(QUICK)
            .output()
            .unwrap();
        assert!(with_out.status.success() && with_out.stderr.is_empty());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

mod plot {
    //! `routh plot` and `routh animate`, run as a user would: the files exist, are not empty, have
    //! the promised dimensions; bad input exits with code 2 and a message.

    use routh::case::{Case, Overrides};
    use routh::integrate::Method;
    use routh::table::{simulate_full, Table};
    use std::path::{Path, PathBuf};
    use std::process::Output;

    use crate::common;
    use common::{assert_exit_2, routh};

    /// The samples of `routh plot --method METHOD --t-end T_END --samples SAMPLES` on `case`
    /// (its simulation, `routh::table::simulate_full`).
    fn plotted(case: &Case, method: Method, t_end: f64, samples: usize) -> Table {
        let overrides = Overrides {
            method: Some(method),
            t_end: Some(t_end),
            ..Overrides::default()
        };
        simulate_full(case, &overrides, samples).unwrap()
    }

    /// The figure size promised by `routh::plot::SIZE`.
    const WIDTH: u32 = 960;
    const HEIGHT: u32 = 640;
    const FIGURES: [&str; 4] = ["theta", "contact_path", "integral_drift", "gamma_trace"];

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("routh-plot-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn ok(out: &Output) -> String {
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "failed: {err}");
        String::from_utf8(out.stdout.clone()).unwrap()
    }

    /// Width and height from the IHDR chunk, after checking the PNG signature.
    fn png_dimensions(bytes: &[u8]) -> (u32, u32) {
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
        assert_eq!(&bytes[12..16], b"IHDR");
        let word = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
        (word(16), word(20))
    }

    /// The JSON list of files written, checked against the expected names.
    fn written(stdout: &str, dir: &Path, names: &[&str], ext: &str) -> Vec<PathBuf> {
        let v: serde_json::Value = serde_json::from_str(stdout).unwrap();
        let files: Vec<PathBuf> = v["files"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| PathBuf::from(f.as_str().unwrap()))
            .collect();
        let expected: Vec<PathBuf> = names
            .iter()
            .map(|n| dir.join(format!("{n}.{ext}")))
            .collect();
        assert_eq!(files, expected);
        files
    }

    /// Run `routh plot` on a short simulation of the default case into a fresh directory.
    fn plot_default_case(format: &str) -> Vec<PathBuf> {
        let dir = scratch(format);
        let out = routh(&[
            "plot",
            "--out",
            dir.to_str().unwrap(),
            "--format",
            format,
            "--t-end",
            "3",
            "--samples",
            "301",
            "--json",
        ]);
        written(&ok(&out), &dir, &FIGURES, format)
    }

    #[test]
    fn png_figures_have_the_promised_size() {
        for file in plot_default_case("png") {
            let bytes = std::fs::read(&file).unwrap();
            // A blank 960x640 RGB image compresses to under 1 kB; axes, labels and curves add more.
            assert!(
                bytes.len() > 8_000,
                "{}: {} bytes",
                file.display(),
                bytes.len()
            );
            assert_eq!(
                png_dimensions(&bytes),
                (WIDTH, HEIGHT),
                "{}",
                file.display()
            );
        }
    }

    #[test]
    fn svg_figures_have_the_promised_size() {
        for file in plot_default_case("svg") {
            let text = std::fs::read_to_string(&file).unwrap();
            assert!(
                text.len() > 5_000,
                "{}: {} bytes",
                file.display(),
                text.len()
            );
            let head = &text[..text.find('>').unwrap()];
            assert!(head.contains(&format!("width=\"{WIDTH}\"")), "{head}");
            assert!(head.contains(&format!("height=\"{HEIGHT}\"")), "{head}");
            assert!(text.contains("<text"), "labels are text elements");
            assert!(text.contains("<polyline"), "curves are drawn");
        }
    }

    #[test]
    fn plots_from_simulate_csv_files_and_compares_two() {
        let dir = scratch("csv");
        let (full, coarse) = (dir.join("full.csv"), dir.join("coarse.csv"));
        let simulate = |file: &Path, tol: &str, extra: &[&str]| {
            let mut args = vec![
                "simulate",
                "--t-end",
                "2",
                "--samples",
                "101",
                "--rtol",
                tol,
                "--atol",
                tol,
                "--out",
                file.to_str().unwrap(),
            ];
            args.extend(extra);
            ok(&routh(&args));
        };
        simulate(&full, "1e-12", &["--full"]);
        simulate(&coarse, "1e-6", &[]);
        let figures = dir.join("figures");
        let out = routh(&[
            "plot",
            "--csv",
            full.to_str().unwrap(),
            "--compare",
            coarse.to_str().unwrap(),
            "--out",
            figures.to_str().unwrap(),
            "--json",
        ]);
        let mut names = FIGURES.to_vec();
        names.push("difference");
        for file in written(&ok(&out), &figures, &names, "png") {
            assert_eq!(
                png_dimensions(&std::fs::read(&file).unwrap()),
                (WIDTH, HEIGHT)
            );
        }
        // A reduced CSV has no positions: the path figure is skipped, with the reason.
        let out = routh(&[
            "plot",
            "--csv",
            coarse.to_str().unwrap(),
            "--out",
            figures.to_str().unwrap(),
            "--json",
        ]);
        let v: serde_json::Value = serde_json::from_str(&ok(&out)).unwrap();
        assert_eq!(v["files"].as_array().unwrap().len(), 3);
        assert!(v["skipped"][0].as_str().unwrap().contains("--full"), "{v}");
    }

    #[test]
    fn simulated_table_matches_the_simulate_full_csv() {
        // `routh plot` without --csv simulates through routh::table::simulate_full; it must give
        // the columns and values of `routh simulate --full` with the same `--method` (the CSV
        // prints shortest round-trip decimals, so equal values parse back exactly).
        let dir = scratch("table");
        let case = Case::default_case().unwrap();
        let mut tables = vec![];
        for method in [Method::Dop853, Method::Vern9] {
            let file = dir.join(format!("full-{method}.csv"));
            ok(&routh(&[
                "simulate",
                "--full",
                "--t-end",
                "2",
                "--samples",
                "51",
                "--method",
                &method.to_string(),
                "--out",
                file.to_str().unwrap(),
            ]));
            let from_csv = Table::read_csv(&file).unwrap();
            let simulated = plotted(&case, method, 2.0, 51);
            assert_eq!(from_csv.names(), simulated.names());
            for name in simulated.names() {
                let (a, b) = (
                    from_csv.column(name).unwrap(),
                    simulated.column(name).unwrap(),
                );
                for (x, y) in a.iter().zip(b) {
                    assert!(
                        x == y || (x.is_nan() && y.is_nan()),
                        "{method} {name}: {x} vs {y}"
                    );
                }
            }
            tables.push(simulated);
        }
        // Negative control: the method is honoured, so the two methods' tables differ (within
        // the tolerances, not bit for bit).
        assert_ne!(
            tables[0].column("gamma3").unwrap(),
            tables[1].column("gamma3").unwrap()
        );
    }

    #[test]
    fn animate_writes_a_self_contained_page() {
        let dir = scratch("animate");
        let out = routh(&[
            "animate",
            "--out",
            dir.to_str().unwrap(),
            "--t-end",
            "2",
            "--samples",
            "3001",
            "--json",
        ]);
        let files = written(&ok(&out), &dir, &["animation"], "html");
        let page = std::fs::read_to_string(&files[0]).unwrap();
        // three.js (~570 kB) and 3001 samples of 16 columns as base64 float32 (~5.3 bytes each):
        // every sample is embedded (the page used to keep at most 1500).
        assert!(page.contains("(3001 samples"), "all samples embedded");
        let t_column = page
            .split("\"t\":\"")
            .nth(1)
            .and_then(|rest| rest.split('"').next())
            .expect("the t column is embedded");
        assert_eq!(
            t_column.len(),
            (4 * 3001usize).div_ceil(3) * 4,
            "3001 float32"
        );
        assert!(
            (570_000..1_000_000).contains(&page.len()),
            "{} bytes",
            page.len()
        );
        for needle in [
            "<canvas",
            "WebGLRenderer",
            "\"columns\":{",
            "requestAnimationFrame",
        ] {
            assert!(page.contains(needle), "page lacks {needle}");
        }
        // The radius recovered from the samples is the default case's R = 1.
        let after = page
            .split("\"radius\":")
            .nth(1)
            .expect("the radius is embedded");
        let radius: f64 = after.split(',').next().unwrap().parse().unwrap();
        assert!((radius - 1.0).abs() < 1e-9, "R = {radius}");
        // Self-contained: no external script, style sheet or image (the browser test in
        // tests/browser checks that the page makes no request at all).
        for needle in ["__DATA__", "__SOURCE__", "<script src", "<link", "<img"] {
            assert!(!page.contains(needle), "page contains {needle}");
        }
    }

    #[test]
    fn bad_input_exits_2_with_a_message() {
        let dir = scratch("bad");
        let out = dir.to_str().unwrap();
        assert_exit_2(&["plot", "--out", out, "--format", "gif"], "gif");
        assert_exit_2(
            &["plot", "--out", out, "--csv", "/nonexistent.csv"],
            "/nonexistent.csv",
        );
        assert_exit_2(&["plot", "--out", out, "--samples", "1"], "samples");
        assert_exit_2(&["plot", "--out", out, "--t-end", "-1"], "t_end");
        let garbage = dir.join("garbage.csv");
        std::fs::write(&garbage, "t,gamma1\n0,abc\n").unwrap();
        assert_exit_2(
            &["plot", "--out", out, "--csv", garbage.to_str().unwrap()],
            "line 2",
        );
        assert_exit_2(
            &["animate", "--out", out, "--csv", garbage.to_str().unwrap()],
            "line 2",
        );
        let reduced = dir.join("reduced.csv");
        std::fs::write(&reduced, "t,gamma1,gamma2,gamma3\n0,0,0,1\n1,0,0,1\n").unwrap();
        assert_exit_2(
            &["animate", "--out", out, "--csv", reduced.to_str().unwrap()],
            "--full",
        );
        assert!(
            std::fs::read_dir(&dir).unwrap().count() == 2,
            "no figure written on error"
        );
    }

    #[test]
    fn quadrature_beside_the_integrator() {
        // `routh exact` samples at the times of `routh plot`/`simulate`; the difference figure is
        // drawn, and the two solutions agree to the integrator's tolerance (1e-12 per unit time;
        // 1e-9 allows the growth over t = 2 at |omega| ~ 8).
        let dir = scratch("exact");
        let quadrature = dir.join("quadrature.csv");
        ok(&routh(&[
            "exact",
            "--t",
            "2",
            "--samples",
            "101",
            "--out",
            quadrature.to_str().unwrap(),
        ]));
        let out = routh(&[
            "plot",
            "--t-end",
            "2",
            "--samples",
            "101",
            "--compare",
            quadrature.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
            "--json",
        ]);
        let mut names = FIGURES.to_vec();
        names.push("difference");
        written(&ok(&out), &dir, &names, "png");
        let exact = Table::read_csv(&quadrature).unwrap();
        let simulated = plotted(&Case::default_case().unwrap(), Method::Dop853, 2.0, 101);
        for name in ["gamma1", "gamma2", "gamma3", "M1", "M2", "M3"] {
            let worst = exact
                .column(name)
                .unwrap()
                .iter()
                .zip(simulated.column(name).unwrap())
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(worst < 1e-9, "{name}: {worst:e}");
        }
    }
}

mod exact_scaling {
    //! `routh exact` in other units and with bounded output (issue 33): the reproducers as a user
    //! types them. The numerics behind them are tested in the library
    //! (`crates/routh/tests/sphere/quadrature.rs`, module `exact_in_any_units`).

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
}

mod megno {
    //! `routh megno`, run as a user would (issue 36, items 2 and 4): on the two integrable cases
    //! the mean MEGNO is near 2 at their own times; the JSON keys; a chart of regimes writes its
    //! CSV, PNG and SVG, with every point of an integrable case regular and both regimes on a
    //! Chaplygin top; bad options refused with exit code 2 and no file.

    use crate::common;
    use common::{assert_exit_2, json_of, routh};

    /// `routh megno --json` with `args`.
    fn megno(args: &[&str]) -> serde_json::Value {
        let mut all = vec!["megno", "--json"];
        all.extend_from_slice(args);
        json_of(&routh(&all))
    }

    /// The default case (t = 100) and `cases/chaplygin.toml` (t = 1000) move on tori: `<Y>`
    /// within 0.3 of 2 at their own times (measured 1.957 and 1.991: the deficit `ln t / t` of a
    /// torus; `routh_ball::megno`'s tests hold them to 0.1 and 0.02). The history holds at most
    /// 100 entries at increasing times, the last the result; `Y` and the FLI come with it.
    /// Negative controls: over t = 5 the default case's `<Y>` is 1.32, more than 0.3 from 2
    /// (the weight `s` of MEGNO still damps the start), and the Chaplygin top of
    /// `cases/chaplygin_top.toml` is chaotic, `<Y>` = 19 at its t = 500.
    #[test]
    fn integrable_cases_have_mean_megno_near_two() {
        for case in ["cases/default.toml", "cases/chaplygin.toml"] {
            let v = megno(&["--case", case]);
            let mean = v["mean_megno"].as_f64().unwrap();
            assert!((mean - 2.0).abs() < 0.3, "{case}: {v}");
            let times = v["history"]["times"].as_array().unwrap();
            let means = v["history"]["mean_megno"].as_array().unwrap();
            assert!(times.len() <= 100 && times.len() > 50, "{}", times.len());
            assert_eq!(means.len(), times.len());
            assert_eq!(times.last().unwrap(), &v["t_end"]);
            assert_eq!(means.last().unwrap(), &v["mean_megno"]);
            for key in [
                "megno",
                "fli",
                "steps",
                "rejected",
                "rhs_evals",
                "elapsed_s",
                "case",
            ] {
                assert!(v.get(key).is_some(), "JSON lacks {key}");
            }
        }
        let short = megno(&["--t-end", "5"])["mean_megno"].as_f64().unwrap();
        assert!((short - 2.0).abs() > 0.3, "{short}");
        let top = megno(&["--case", "cases/chaplygin_top.toml"])["mean_megno"]
            .as_f64()
            .unwrap();
        assert!(top > 5.0, "{top}");
        let text = String::from_utf8(routh(&["megno", "--t-end", "2"]).stdout).unwrap();
        for needle in ["mean MEGNO", "FLI", "<built-in default>"] {
            assert!(text.contains(needle), "{needle}: {text}");
        }
    }

    /// The CSV of a chart in `dir`: its header and rows of cells.
    fn chart_csv(dir: &std::path::Path) -> (Vec<String>, Vec<Vec<String>>) {
        let csv = std::fs::read_to_string(dir.join("chart.csv")).unwrap();
        let mut lines = csv.lines();
        let header = lines.next().unwrap().split(',').map(String::from).collect();
        let rows = lines
            .map(|l| l.split(',').map(String::from).collect())
            .collect();
        (header, rows)
    }

    /// A chart of the default case over tilt x spin (3 x 2 points, t = 100): every point is a
    /// Routh sphere on a torus, so every `<Y>` is regular, within 0.3 of 2 (measured 1.89 to
    /// 1.97). A chart of the Chaplygin top over tilt x spin (6 x 5 points, t = 200) has both
    /// regimes (measured: 2 chaotic, 27 regular, 1 below 1) and the JSON's counts are the CSV's.
    /// Each writes `chart.csv` (the keys of --x and --y, `mean_megno`, `megno`, `fli`, `regime`, `message`),
    /// `chart.png` and `chart.svg`.
    #[test]
    fn charts_write_csv_png_and_svg() {
        let base = std::env::temp_dir().join(format!("routh-cli-chart-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&base);
        let (sphere, top) = (base.join("sphere"), base.join("top"));
        let v = megno(&[
            "--x",
            "tilt=0.2:0.6:3",
            "--y",
            "spin=6:10:2",
            "--out",
            sphere.to_str().unwrap(),
        ]);
        let (header, rows) = chart_csv(&sphere);
        assert_eq!(
            header,
            [
                "tilt",
                "spin",
                "mean_megno",
                "megno",
                "fli",
                "regime",
                "message"
            ]
        );
        assert_eq!(rows.len(), 6);
        for row in &rows {
            let mean: f64 = row[2].parse().unwrap();
            assert!((mean - 2.0).abs() < 0.3, "{row:?}");
            assert_eq!(row[5], "regular");
        }
        assert_eq!(v["regimes"]["regular"], 6);
        assert_eq!(v["points"], 6);
        for name in ["chart.png", "chart.svg", "chart.csv"] {
            let size = std::fs::metadata(sphere.join(name)).unwrap().len();
            assert!(size > 300, "{name}: {size} bytes");
        }
        let v = megno(&[
            "--case",
            "cases/chaplygin_top.toml",
            "--t-end",
            "200",
            "--x",
            "tilt=0.2:1.5:6",
            "--y",
            "spin=0.5:4:5",
            "--out",
            top.to_str().unwrap(),
        ]);
        let (_, rows) = chart_csv(&top);
        let count = |regime: &str| rows.iter().filter(|r| r[5] == regime).count();
        assert_eq!(rows.len(), 30);
        assert!(count("chaotic") > 0 && count("regular") > 0, "{v}");
        for regime in ["periodic", "regular", "chaotic", "failed"] {
            assert_eq!(v["regimes"][regime], count(regime), "{regime}: {v}");
        }
        assert_eq!(v["x"]["key"], "tilt");
        assert_eq!(v["files"].as_array().unwrap().len(), 3);
        let _ = std::fs::remove_dir_all(&base);
    }

    /// Bad options: exit code 2, the option named with its rule, and no directory written.
    #[test]
    fn bad_options_are_refused_with_exit_2() {
        let dir = std::env::temp_dir().join(format!("routh-cli-chart-bad-{}", std::process::id()));
        let out = dir.to_str().unwrap();
        fn chart<'a>(x: &'a str, y: &'a str, out: &'a str) -> Vec<&'a str> {
            vec!["megno", "--x", x, "--y", y, "--out", out]
        }
        for (x, rule) in [
            ("height=0:1:3", "KEY must be a quantity of [sweep]"),
            ("tilt", "must be KEY=FROM:TO:N"),
            ("tilt=0:1", "must be KEY=FROM:TO:N"),
            ("tilt=a:1:3", "FROM and TO must be numbers"),
            ("tilt=1:0:3", "FROM < TO"),
            ("tilt=0:inf:3", "finite"),
            ("tilt=0:1:1", "N must be an integer from 2 to 1000"),
            ("tilt=0:1:1001", "N must be an integer from 2 to 1000"),
        ] {
            assert_exit_2(&chart(x, "spin=1:2:2", out), "invalid option x");
            assert_exit_2(&chart(x, "spin=1:2:2", out), rule);
        }
        assert_exit_2(
            &chart("tilt=0:1:2", "tilt=0:1:2", out),
            "invalid option y = tilt: must be another quantity",
        );
        assert_exit_2(
            &chart("tilt=0:1:2", "gamma1=0:0.5:2", out),
            "sets the same initial quantity as another key",
        );
        assert_exit_2(
            &chart("body.I1=-1:0.4:2", "spin=1:2:2", out),
            "makes the case invalid",
        );
        assert_exit_2(&["megno", "--x", "tilt=0:1:2"], "invalid option y");
        assert_exit_2(&["megno", "--y", "tilt=0:1:2"], "invalid option x");
        assert_exit_2(&["megno", "--out", out], "invalid option out");
        assert_exit_2(
            &["megno", "--method", "taylor"],
            "invalid option method = taylor: must be dop853, vern9 or rk4",
        );
        assert_exit_2(
            &chart("tilt=0:1:2", "spin=1:2:2", out)
                .into_iter()
                .chain(["--method", "taylor"])
                .collect::<Vec<_>>(),
            "invalid option method = taylor",
        );
        assert_exit_2(&["megno", "--t-end", "NaN"], "t_end");
        assert!(!dir.exists(), "{dir:?} was written");
    }
}
