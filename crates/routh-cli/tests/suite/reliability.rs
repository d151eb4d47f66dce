//! Bad and unusual inputs to the command-line tool: exit codes, messages, signals, files never half-written.
//!
//! One test binary, one module a topic (issue 32: few binaries, each named after what it proves).

mod reproducers {
    //! Regression tests of issue 10, one per reproducer: never a wrong answer with exit 0, never
    //! a lost or clobbered file. Each was observed failing on the commit before the fix (ded9944)
    //! and passes after. The binary under test is `ROUTH_BIN` when set (to run these tests
    //! against another build), else this crate's.

    use std::path::{Path, PathBuf};
    use std::process::{Command, Output, Stdio};
    use std::time::{Duration, Instant};

    use crate::common::{self, listing};

    const DEFAULT: &str = routh::case::DEFAULT_CASE;

    fn binary() -> String {
        std::env::var("ROUTH_BIN").unwrap_or_else(|_| env!("CARGO_BIN_EXE_routh").to_string())
    }

    fn routh(args: &[&str]) -> Output {
        common::at_root(Command::new(binary()))
            .args(args)
            .output()
            .expect("the binary runs")
    }

    /// A fresh scratch directory for one test.
    fn scratch(test: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("routh-reliability-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn text(bytes: &[u8]) -> String {
        String::from_utf8_lossy(bytes).into_owned()
    }

    /// Exit code 2, every `expected` piece in the message, no panic.
    fn refused(out: &Output, expected: &[&str]) {
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        for piece in expected {
            assert!(err.contains(piece), "`{err}` lacks `{piece}`");
        }
        assert!(!err.contains("panicked"), "{err}");
    }

    fn succeeded(out: &Output) -> String {
        assert!(out.status.success(), "{}", text(&out.stderr));
        text(&out.stdout)
    }

    fn case_file(dir: &Path, name: &str, text: &str) -> String {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_string()
    }

    fn edited(old: &str, new: &str) -> String {
        assert!(DEFAULT.contains(old), "the default case lacks {old}");
        DEFAULT.replacen(old, new, 1)
    }

    #[test]
    fn huge_sample_counts_exit_2_before_any_file_is_made() {
        let dir = scratch("huge-samples");
        let out = dir.join("x.csv");
        for n in ["18446744073709551615", "100000000000"] {
            let run = routh(&["simulate", "--samples", n, "--out", out.to_str().unwrap()]);
            refused(&run, &["samples", "10000000"]);
            assert!(listing(&dir).is_empty(), "{n}: left {:?}", listing(&dir));
        }
        let run = routh(&[
            "plot",
            "--samples",
            "18446744073709551615",
            "--out",
            dir.to_str().unwrap(),
        ]);
        refused(&run, &["samples", "1000000"]);
    }

    #[test]
    fn a_device_is_written_into_not_replaced() {
        let run = routh(&["simulate", "--t-end", "1", "--out", "/dev/null"]);
        succeeded(&run);
        use std::os::unix::fs::FileTypeExt;
        let kind = std::fs::metadata("/dev/null").unwrap().file_type();
        assert!(kind.is_char_device(), "/dev/null is no longer a device");
    }

    #[test]
    fn a_symlink_is_written_through_and_stays() {
        let dir = scratch("symlink");
        let target = dir.join("real.csv");
        let link = dir.join("link.csv");
        std::fs::write(&target, "old").unwrap();
        std::os::unix::fs::symlink("real.csv", &link).unwrap();
        succeeded(&routh(&[
            "simulate",
            "--t-end",
            "1",
            "--samples",
            "3",
            "--out",
            link.to_str().unwrap(),
        ]));
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        let csv = std::fs::read_to_string(&target).unwrap();
        assert_eq!(csv.lines().count(), 4, "{csv}");
        assert_eq!(listing(&dir), ["link.csv", "real.csv"]);
    }

    #[test]
    fn a_named_pipe_is_streamed_into() {
        let dir = scratch("fifo");
        let fifo = dir.join("pipe");
        assert!(Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success());
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
        };
        succeeded(&routh(&[
            "simulate",
            "--t-end",
            "1",
            "--samples",
            "5",
            "--out",
            fifo.to_str().unwrap(),
        ]));
        let received = reader.join().unwrap();
        assert_eq!(received.lines().count(), 6, "{received}");
        assert_eq!(listing(&dir), ["pipe"], "no temporary file beside the pipe");
    }

    /// Sends `signal` (as `kill` spells it, e.g. `-INT`) to process `pid`.
    fn send(signal: &str, pid: u32) {
        assert!(Command::new("kill")
            .args([signal, &pid.to_string()])
            .status()
            .unwrap()
            .success());
    }

    /// Start a long `simulate --out`, wait until its temporary file exists, send `signal`, and
    /// check that it ends with the signal and leaves neither the temporary nor the target.
    fn interrupted_run_leaves_nothing(signal: &str, test: &str) {
        let dir = scratch(test);
        let out = dir.join("x.csv");
        let mut child = common::at_root(Command::new(binary()))
            .args([
                "simulate",
                "--t-end",
                "1e6",
                "--samples",
                "1000000",
                "--out",
            ])
            .arg(&out)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let start = Instant::now();
        while !listing(&dir).iter().any(|n| n.contains(".tmp-")) {
            assert!(
                start.elapsed() < Duration::from_secs(20),
                "no temporary file appeared"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        std::thread::sleep(Duration::from_millis(200));
        send(signal, child.id());
        let status = child.wait().unwrap();
        assert!(!status.success(), "{status:?}");
        assert!(
            listing(&dir).is_empty(),
            "{signal}: left {:?}",
            listing(&dir)
        );
    }

    #[test]
    fn sigint_removes_the_temporary_file() {
        interrupted_run_leaves_nothing("-INT", "sigint");
    }

    #[test]
    fn sigterm_removes_the_temporary_file() {
        interrupted_run_leaves_nothing("-TERM", "sigterm");
    }

    #[test]
    fn a_missing_directory_or_a_directory_target_exits_2() {
        let dir = scratch("missing");
        let missing = dir.join("no/such/dir/x.csv");
        refused(
            &routh(&[
                "simulate",
                "--t-end",
                "1",
                "--out",
                missing.to_str().unwrap(),
            ]),
            &["no/such/dir"],
        );
        refused(
            &routh(&["simulate", "--t-end", "1", "--out", dir.to_str().unwrap()]),
            &["directory"],
        );
        assert!(listing(&dir).is_empty());
    }

    #[test]
    fn top_level_keys_and_unknown_tables_are_refused() {
        let dir = scratch("unknown");
        let top = case_file(&dir, "top.toml", &format!("t_end = 5\n{DEFAULT}"));
        refused(
            &routh(&["simulate", "--case", &top]),
            &["`t_end`", "top level", "top.toml"],
        );
        let extra = case_file(&dir, "extra.toml", &format!("{DEFAULT}\n[extra]\nx = 1\n"));
        for command in ["simulate", "exact", "steady"] {
            refused(
                &routh(&[command, "--case", &extra]),
                &["[extra]", "extra.toml"],
            );
        }
        let nested = case_file(
            &dir,
            "nested.toml",
            &edited("[initial]", "[body.more]\nx = 1\n[initial]"),
        );
        refused(
            &routh(&["simulate", "--case", &nested]),
            &["more", "[body]", "nested.toml"],
        );
    }

    #[test]
    fn integration_table_and_g_are_optional_with_the_stated_defaults() {
        let dir = scratch("optional");
        let bare = DEFAULT
            .split("[integration]")
            .next()
            .unwrap()
            .replace("G = 9.81\n", "");
        let bare = case_file(&dir, "bare.toml", &bare);
        let explicit = case_file(&dir, "explicit.toml", DEFAULT);
        for command in ["exact", "steady"] {
            succeeded(&routh(&[command, "--case", &bare]));
        }
        // Same t_end (100), tolerances (1e-12) and G (9.81): the same final state, bit for bit.
        let json = |case: &str| -> serde_json::Value {
            let out = succeeded(&routh(&[
                "simulate", "--case", case, "--t-end", "3", "--json",
            ]));
            serde_json::from_str(&out).unwrap()
        };
        assert_eq!(json(&bare)["final_state"], json(&explicit)["final_state"]);
        let full = succeeded(&routh(&[
            "simulate",
            "--case",
            &bare,
            "--method",
            "rk4:100000",
            "--json",
        ]));
        let full: serde_json::Value = serde_json::from_str(&full).unwrap();
        assert_eq!(full["t_end"], 100.0);
        // Negative control: a different G gives a different motion.
        let moon = case_file(&dir, "moon.toml", &edited("G = 9.81", "G = 1.62"));
        assert_ne!(json(&moon)["final_state"], json(&explicit)["final_state"]);
    }

    #[test]
    fn out_of_range_tolerances_are_refused_with_the_reason() {
        let dir = scratch("tolerances");
        for (rtol, reason) in [
            ("1", "< 1e-2"),
            ("0.01", "< 1e-2"),
            ("1e-15", "100 machine epsilons"),
        ] {
            refused(&routh(&["simulate", "--rtol", rtol]), &["rtol", reason]);
            let case = case_file(
                &dir,
                "tol.toml",
                &edited("rtol = 1e-12", &format!("rtol = {rtol}")),
            );
            refused(
                &routh(&["simulate", "--case", &case]),
                &["rtol", reason, "tol.toml"],
            );
        }
        succeeded(&routh(&["simulate", "--t-end", "1", "--rtol", "1e-13"]));
        succeeded(&routh(&["simulate", "--t-end", "1", "--rtol", "5e-3"]));
    }

    #[test]
    fn max_steps_is_an_option_named_when_hit() {
        refused(
            &routh(&["simulate", "--t-end", "1000", "--max-steps", "100"]),
            &["max_steps = 100", "--max-steps"],
        );
        refused(&routh(&["simulate", "--max-steps", "0"]), &["max_steps"]);
        refused(
            &routh(&["simulate", "--method", "rk4:1000", "--max-steps", "999"]),
            &["rk4", "max_steps"],
        );
        succeeded(&routh(&[
            "simulate",
            "--t-end",
            "10",
            "--max-steps",
            "100000",
        ]));
    }

    #[test]
    fn samples_without_out_go_to_stdout_and_the_summary_to_stderr() {
        let out = routh(&["simulate", "--t-end", "1", "--samples", "5"]);
        let csv = succeeded(&out);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 6, "{csv}");
        assert!(lines[0].starts_with("t,gamma1"));
        assert!(lines[5].starts_with("1,"), "{}", lines[5]);
        assert!(text(&out.stderr).contains("samples written to standard output"));
    }

    #[test]
    fn zero_or_one_sample_is_refused_and_writes_nothing() {
        let dir = scratch("zero-samples");
        let out = dir.join("y.csv");
        for n in ["0", "1"] {
            refused(
                &routh(&["simulate", "--samples", n, "--out", out.to_str().unwrap()]),
                &["samples", ">= 2"],
            );
        }
        assert!(listing(&dir).is_empty());
    }

    #[test]
    fn plot_refuses_csvs_it_cannot_draw() {
        let dir = scratch("plot-csv");
        let figures = dir.join("figures");
        let good = dir.join("good.csv");
        succeeded(&routh(&[
            "simulate",
            "--t-end",
            "1",
            "--samples",
            "3",
            "--full",
            "--out",
            good.to_str().unwrap(),
        ]));
        let good_text = std::fs::read_to_string(&good).unwrap();
        let mut lines: Vec<String> = good_text.lines().map(str::to_string).collect();
        let one_row = lines[..2].join("\n");
        let mut nan = lines.clone();
        let mut cells: Vec<&str> = lines[2].split(',').collect();
        cells[1] = "NaN";
        nan[2] = cells.join(",");
        lines[3].push_str(",7");
        for (name, content, expected) in [
            ("one.csv", one_row, vec!["1 row(s)"]),
            (
                "nan.csv",
                nan.join("\n"),
                vec!["line 3", "column `gamma1`", "NaN"],
            ),
            ("ragged.csv", lines.join("\n"), vec!["line 4", "values for"]),
        ] {
            let path = dir.join(name);
            std::fs::write(&path, content).unwrap();
            for command in ["plot", "animate"] {
                let out = routh(&[
                    command,
                    "--csv",
                    path.to_str().unwrap(),
                    "--out",
                    figures.to_str().unwrap(),
                ]);
                let mut pieces = expected.clone();
                pieces.push(name);
                refused(&out, &pieces);
                assert_eq!(
                    text(&out.stderr).matches(name).count(),
                    1,
                    "the file named once"
                );
            }
        }
        assert!(!figures.exists(), "no figures drawn");
        succeeded(&routh(&[
            "plot",
            "--csv",
            good.to_str().unwrap(),
            "--out",
            figures.to_str().unwrap(),
        ]));
    }

    #[test]
    fn overflow_is_named_with_its_cause() {
        let dir = scratch("overflow");
        let spin = case_file(
            &dir,
            "spin.toml",
            &edited("omega = [0.5, 0.2, 8.0]", "omega = [0.0, 0.0, 1e200]"),
        );
        let heavy = case_file(&dir, "heavy.toml", &edited("m = 1.0", "m = 1e300"));
        for command in ["simulate", "exact", "steady"] {
            refused(
                &routh(&[command, "--case", &spin]),
                &["the spin |omega| = 1.000e200", "energy H1 overflow"],
            );
            refused(
                &routh(&[command, "--case", &heavy]),
                &["m = 1e300", "inertia", "overflow"],
            );
        }
        // Negative control: a large spin whose energy is representable is accepted.
        let fast = case_file(
            &dir,
            "fast.toml",
            &edited("omega = [0.5, 0.2, 8.0]", "omega = [0.0, 0.0, 1e6]"),
        );
        // (exact at t = 0.1: 16,000 periods of the nutation, within the time over which the
        // quadrature keeps its error below 1e-6; t_end = 100 is beyond it, and refused.)
        succeeded(&routh(&["exact", "--case", &fast, "--t", "0.1"]));
        succeeded(&routh(&["steady", "--case", &fast]));
    }

    /// Every command that prints on standard output (text, CSV rows, the list of files written),
    /// with quick arguments; the files some of them write go to `dir`.
    fn printing_commands(dir: &Path) -> Vec<Vec<String>> {
        let sweep = case_file(
            dir,
            "sweep.toml",
            &format!("{DEFAULT}\n[sweep]\nspin = {{ values = [3.0, 5.0] }}\n"),
        );
        let d = dir.to_str().unwrap();
        [
            "simulate --t-end 1",
            "simulate --t-end 1 --samples 5",
            "exact --t 1",
            "exact --t 1 --samples 5",
            "exact --t 1 --flow X1",
            "exact --t 1 --flow X1 --samples 5",
            "steady",
            "audit --points 1",
            "diagram --tilts 8 --grid 8 --loop-points 16 --out DIR/diagram",
            "plot --t-end 1 --samples 10 --format svg --out DIR/plots",
            "animate --t-end 1 --samples 10 --out DIR/plots",
            "sweep --t-end 1 --case SWEEP",
        ]
        .iter()
        .map(|c| {
            c.replace("DIR", d)
                .replace("SWEEP", &sweep)
                .split(' ')
                .map(str::to_string)
                .collect()
        })
        .collect()
    }

    #[test]
    fn plain_text_to_a_closed_pipe_ends_quietly() {
        // The reader has gone before the command writes: every write fails with EPIPE, which ends
        // the command with exit code 0 and nothing on stderr (`print!` panicked with exit code 101
        // before, "failed printing to stdout: Broken pipe").
        let dir = scratch("closed-pipe");
        for args in printing_commands(&dir) {
            let mut command = common::at_root(Command::new(binary()));
            command.args(&args);
            let out = common::with_closed_stdout(command);
            let err = text(&out.stderr);
            assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
            assert!(err.is_empty(), "{args:?}: {err}");
            // Negative control: with a reader, the command prints something (so the closed pipe
            // was written to).
            let printed = succeeded(&routh(&args.iter().map(String::as_str).collect::<Vec<_>>()));
            assert!(!printed.is_empty(), "{args:?} printed nothing");
        }
    }

    #[test]
    fn plain_text_to_a_full_device_exits_2() {
        // Any other write error on standard output (a full disk) is reported with exit code 2,
        // naming standard output (`-` for the samples of `simulate --samples` without `--out`).
        let dir = scratch("full-device");
        let Ok(_) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
            return;
        };
        for args in printing_commands(&dir) {
            let full = std::fs::OpenOptions::new()
                .write(true)
                .open("/dev/full")
                .unwrap();
            let out = common::at_root(Command::new(binary()))
                .args(&args)
                .stdout(full)
                .output()
                .unwrap();
            refused(&out, &["No space left on device"]);
            let err = text(&out.stderr);
            assert!(
                err.contains("error: standard output: ") || err.contains("error: -: "),
                "{args:?}: {err}"
            );
        }
    }

    /// Starts a sweep long enough to be interrupted (3000 runs to t = 100, one thread: about a
    /// second in the Taylor lanes) into
    /// `dir/stopped.csv` and returns once its temporary file holds a row: the case file, the target,
    /// the temporary file and the running child.
    fn running_sweep(dir: &Path) -> (String, PathBuf, PathBuf, std::process::Child) {
        let case = case_file(
        dir,
        "long.toml",
        &format!(
            "{}\n[sweep]\ntilt = {{ range = [0.3, 1.4], n = 1500 }}\nspin = {{ values = [3.0, 5.0] }}\n",
            DEFAULT
        ),
    );
        let target = dir.join("stopped.csv");
        let child = common::at_root(Command::new(binary()))
            .args(["sweep", "--case", &case, "--threads", "1", "--out"])
            .arg(&target)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let tmp = dir.join(format!(".stopped.csv.tmp-{}-0", child.id()));
        let start = Instant::now();
        while std::fs::read_to_string(&tmp).map_or(0, |t| t.lines().count()) < 2 {
            assert!(
                start.elapsed() < Duration::from_secs(120),
                "no rows written"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        (case, target, tmp, child)
    }

    /// SIGINT during a sweep into `--out`: the sweep stops after the runs in progress, the
    /// target holds the finished rows (a complete table, no temporary file left), and `--resume`
    /// completes it to the rows of an uninterrupted sweep. (SIGTERM: `tests/cli_sweep.rs`.)
    #[test]
    fn sigint_stops_a_sweep_and_resume_completes_it() {
        let dir = scratch("sweep-sigint");
        let (case, target, tmp, child) = running_sweep(&dir);
        send("-INT", child.id());
        let out = child.wait_with_output().unwrap();
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(130), "{err}");
        assert!(err.contains("--resume"), "{err}");
        assert!(!tmp.exists(), "the temporary file was left behind");
        let rows = |path: &Path| -> Vec<String> {
            let mut lines: Vec<String> = std::fs::read_to_string(path)
                .unwrap()
                .lines()
                .skip(1)
                .map(str::to_string)
                .collect();
            lines.sort_by_key(|l| l.split(',').next().unwrap().parse::<u64>().unwrap());
            lines
        };
        let kept = rows(&target).len();
        assert!(kept > 0 && kept < 3000, "{kept} rows kept");
        let target_arg = target.to_str().unwrap();
        succeeded(&routh(&[
            "sweep", "--case", &case, "--out", target_arg, "--resume",
        ]));
        let whole = dir.join("whole.csv");
        succeeded(&routh(&[
            "sweep",
            "--case",
            &case,
            "--out",
            whole.to_str().unwrap(),
        ]));
        assert_eq!(rows(&target), rows(&whole));
        assert_eq!(listing(&dir), ["long.toml", "stopped.csv", "whole.csv"]);
    }

    /// A second SIGINT during a sweep (after the first one asked it to stop) ends the process at
    /// once, and the signal handler removes the sweep's temporary file too (it is registered with
    /// the handler's list; before, only the first, graceful stop removed it).
    #[test]
    fn a_second_sigint_during_a_sweep_leaves_no_temporary_file() {
        let dir = scratch("sweep-sigint-twice");
        let (_, _, tmp, child) = running_sweep(&dir);
        for _ in 0..2 {
            send("-INT", child.id());
        }
        let out = child.wait_with_output().unwrap();
        // Ended by the second signal (the default action, after the handler's cleanup), or with
        // 130 if the graceful stop of the first one won the race.
        use std::os::unix::process::ExitStatusExt;
        assert!(
            out.status.signal() == Some(2) || out.status.code() == Some(130),
            "{:?}: {}",
            out.status,
            text(&out.stderr)
        );
        assert!(!tmp.exists(), "the temporary file was left behind");
    }
}

mod bounds {
    //! Issue 33, items 3 and 4: every size bounded before work starts (refused with the key, the
    //! value and the rule, exit 2), SIGTERM obeyed within a second by every long command, and the
    //! output files: temporary names that fit, errors that name the target, `--resume` of a cut
    //! row, one output stream per destination.

    use crate::common;

    use common::{assert_exit_2, command, listing, routh};
    use std::path::{Path, PathBuf};
    use std::process::{Output, Stdio};
    use std::time::{Duration, Instant};

    /// A fresh directory for one test (the tests run in parallel).
    fn scratch(test: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("routh-bounds-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// The default case with `[integration]`'s t_end replaced and `extra` appended, in `dir`.
    fn case_file(dir: &Path, t_end: &str, extra: &str) -> String {
        let default = std::fs::read_to_string(Path::new(common::ROOT).join("cases/default.toml"))
            .unwrap()
            .replace("t_end = 100.0", &format!("t_end = {t_end}"));
        let path = dir.join("case.toml");
        std::fs::write(&path, format!("{default}\n{extra}")).unwrap();
        path.to_str().unwrap().to_string()
    }

    fn succeeded(out: &Output) -> String {
        let err = String::from_utf8_lossy(&out.stderr).into_owned();
        assert!(out.status.success(), "{:?}: {err}", out.status);
        err
    }

    #[test]
    fn audit_points_are_bounded_before_the_points_are_drawn() {
        // Before: a 48 TB allocation, the process aborted.
        assert_exit_2(&["audit", "--points", "1000000000000"], "1000000000000");
        assert_exit_2(&["audit", "--points", "100001"], "between 1 and 100000");
        assert_exit_2(&["audit", "--points", "0"], "points");
    }

    #[test]
    fn diagram_work_is_bounded_before_any_file() {
        // Before: `--grid 5000 --tilts 5000` was accepted and ran for hours (16.7 million cells).
        let dir = scratch("diagram-grid");
        let figures = dir.join("figures");
        for (grid, cells) in [("388", "388 x 258 = 100104 cells"), ("5000", "5000 x 3333")] {
            assert_exit_2(
                &[
                    "diagram",
                    "--grid",
                    grid,
                    "--tilts",
                    "5000",
                    "--out",
                    figures.to_str().unwrap(),
                ],
                &format!("grid = {grid} ({cells}"),
            );
        }
        assert_exit_2(
            &["diagram", "--grid", "388"],
            "at most 100000 cells: grid <= 387",
        );
        assert!(!figures.exists(), "refused before any file");
    }

    #[test]
    fn sweep_threads_are_bounded_by_the_cores() {
        // Before: accepted, and a minute to obey SIGTERM.
        let cores = std::thread::available_parallelism().unwrap().get();
        let too_many = (4 * cores + 1).to_string();
        for n in ["10000", too_many.as_str()] {
            assert_exit_2(
                &["sweep", "--case", "cases/sweep.toml", "--threads", n],
                &format!(
                    "threads = {n} ({cores} cores available): must be at most 4 per available core"
                ),
            );
        }
    }

    #[test]
    fn sweep_grids_and_samples_are_bounded_before_any_value_is_built() {
        let dir = scratch("grid");
        for (sweep, expected) in [
            (
                "tilt = { range = [0.1, 1.0], n = 1000000000000 }",
                "`tilt` = n = 1000000000000: a sweep has at most 1000000 runs",
            ),
            (
                "samples = 9223372036854775807\ntilt = { range = [0.1, 1.0] }",
                "`samples` = 9223372036854775807: a sweep has at most 1000000 runs",
            ),
            (
                "tilt = { range = [0.1, 1.0], n = 2000 }\nspin = { range = [1.0, 9.0], n = 2000 }",
                "a grid of 4000000 runs: spin (2000) x tilt (2000)",
            ),
        ] {
            let case = case_file(&dir, "1.0", &format!("[sweep]\n{sweep}\n"));
            assert_exit_2(&["sweep", "--case", &case], expected);
        }
    }

    #[test]
    fn a_target_name_of_255_bytes_gets_a_temporary_name_that_fits() {
        // Before: `.NAME.tmp-PID-N` was longer than 255 bytes and the write was refused.
        let dir = scratch("long-name");
        for length in [254, 255] {
            let name = format!("{}.csv", "x".repeat(length - 4));
            let target = dir.join(&name);
            succeeded(&routh(&[
                "simulate",
                "--t-end",
                "1",
                "--samples",
                "3",
                "--out",
                target.to_str().unwrap(),
            ]));
            assert_eq!(std::fs::read_to_string(&target).unwrap().lines().count(), 4);
            let sweep_target = dir.join(format!("{}.csv", "s".repeat(length - 4)));
            let case = case_file(&dir, "0.5", "[sweep]\ntilt = { values = [0.2, 0.3] }\n");
            succeeded(&routh(&[
                "sweep",
                "--case",
                &case,
                "--out",
                sweep_target.to_str().unwrap(),
            ]));
            assert_eq!(
                std::fs::read_to_string(&sweep_target)
                    .unwrap()
                    .lines()
                    .count(),
                3
            );
            std::fs::remove_file(&target).unwrap();
            std::fs::remove_file(&sweep_target).unwrap();
        }
        assert_eq!(listing(&dir), ["case.toml"], "no temporary file left");
    }

    #[test]
    fn an_error_about_a_missing_directory_names_the_target() {
        // Before: the sweep's error named its temporary file.
        let target = "missing/dir/x.csv";
        for args in [
            vec!["sweep", "--case", "cases/sweep.toml", "--out", target],
            vec![
                "simulate",
                "--t-end",
                "1",
                "--samples",
                "3",
                "--out",
                target,
            ],
            vec!["audit", "--points", "1", "--markdown", "missing/dir/x.md"],
        ] {
            let out = routh(&args);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
            assert!(err.contains("missing/dir/x."), "{args:?}: {err}");
            assert!(
                !err.contains(".tmp-"),
                "{args:?} names the temporary file: {err}"
            );
        }
    }

    #[test]
    fn resume_drops_a_last_row_cut_short_and_says_so() {
        // Before: a row cut after 14 of its 40 columns was kept and counted as resumed.
        let dir = scratch("resume-cut");
        let case = case_file(
            &dir,
            "0.5",
            "[sweep]\ntilt = { values = [0.1, 0.2, 0.3] }\n",
        );
        let whole = dir.join("whole.csv");
        let cut = dir.join("cut.csv");
        let (whole_arg, cut_arg) = (whole.to_str().unwrap(), cut.to_str().unwrap());
        succeeded(&routh(&["sweep", "--case", &case, "--out", whole_arg]));
        let text = std::fs::read_to_string(&whole).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let columns = lines[0].split(',').count();
        let last: Vec<&str> = lines[3].split(',').take(14).collect();
        std::fs::write(
            &cut,
            format!(
                "{}\n{}\n{}\n{}",
                lines[0],
                lines[1],
                lines[2],
                last.join(",")
            ),
        )
        .unwrap();
        let out = routh(&[
            "sweep", "--case", &case, "--out", cut_arg, "--resume", "--json",
        ]);
        let err = succeeded(&out);
        assert!(
            err.contains(&format!(
                "dropped the last row of {cut_arg}, cut short (line 4 holds 14 of {columns} columns \
                 and no line break)"
            )),
            "{err}"
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["resumed"], 2);
        assert_eq!(v["ran"], 1);
        assert_eq!(v["dropped_partial_row"]["columns"], 14);
        assert_eq!(v["dropped_partial_row"]["line"], 4);
        assert_eq!(
            std::fs::read_to_string(&cut).unwrap(),
            text,
            "the run done again"
        );
        // A cut row before the last is not a stopped sweep's: refused, naming the file.
        std::fs::write(
            &cut,
            format!(
                "{}\n{}\n{}\n{}\n",
                lines[0],
                last.join(","),
                lines[2],
                lines[3]
            ),
        )
        .unwrap();
        assert_exit_2(
            &["sweep", "--case", &case, "--out", cut_arg, "--resume"],
            "a malformed row before the last: line 2 holds 14 of",
        );
    }

    #[test]
    fn one_output_stream_per_destination() {
        // The markdown report on standard output sends the table to standard error.
        let out = routh(&["audit", "--points", "1", "--markdown", "-"]);
        let err = succeeded(&out);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(stdout.starts_with('#'), "markdown expected: {stdout}");
        assert!(!stdout.contains("OK-WITHIN-ANSATZ  "), "{stdout}");
        assert!(err.contains("OK"), "the table on stderr: {err}");
        let out = routh(&["audit", "--points", "1", "--markdown", "-", "--json"]);
        let err = succeeded(&out);
        assert!(
            serde_json::from_str::<serde_json::Value>(&err).is_ok(),
            "{err}"
        );
        // simulate and exact: the CSV of `--out -` on standard output, the summary or JSON on
        // standard error; so too when `--out` names the file standard output is redirected to
        // (before, simulate and exact printed the report into it, over the CSV's old inode).
        let dir = scratch("streams");
        let target = dir.join("x.csv");
        let target_arg = target.to_str().unwrap();
        for (command_args, summary) in [
            (
                vec!["simulate", "--t-end", "1", "--samples", "3"],
                "routh simulate: ",
            ),
            (vec!["exact", "--t", "1", "--samples", "3"], "case: "),
        ] {
            for json in [false, true] {
                let mut args = command_args.clone();
                args.extend(["--out", "-"]);
                if json {
                    args.push("--json");
                }
                let out = routh(&args);
                let err = succeeded(&out);
                let stdout = String::from_utf8_lossy(&out.stdout);
                assert!(stdout.starts_with("t,"), "{args:?}: CSV alone: {stdout}");
                assert_eq!(stdout.lines().count(), 4, "{args:?}: {stdout}");
                match json {
                    true => assert!(
                        serde_json::from_str::<serde_json::Value>(&err).is_ok(),
                        "{args:?}: {err}"
                    ),
                    false => assert!(err.starts_with(summary), "{args:?}: {err}"),
                }
                let mut args = command_args.clone();
                args.extend(["--out", target_arg, "--json"]);
                let redirected = std::fs::File::create(&target).unwrap();
                let out = command().args(&args).stdout(redirected).output().unwrap();
                let err = succeeded(&out);
                assert!(
                    serde_json::from_str::<serde_json::Value>(&err).is_ok(),
                    "{args:?}: the JSON on stderr: {err}"
                );
                let csv = std::fs::read_to_string(&target).unwrap();
                assert!(csv.starts_with("t,") && csv.lines().count() == 4, "{csv}");
            }
        }
        // `-` as the directory of figures is refused, not a directory named `-`.
        for args in [
            vec!["plot", "--out", "-", "--samples", "10", "--t-end", "1"],
            vec!["animate", "--out", "-", "--samples", "10", "--t-end", "1"],
            vec!["diagram", "--out", "-", "--grid", "4", "--tilts", "4"],
        ] {
            assert_exit_2(&args, "out = -");
        }
    }

    /// Start `args` with its files in `dir`, send SIGTERM after half a second, and return how long
    /// it took to end after the signal. The process must end with a failure, leave no temporary
    /// file in `dir`, and leave every file it wrote complete (`complete` checks each).
    fn sigterm_latency(dir: &Path, args: &[&str], complete: impl Fn(&Path)) -> Duration {
        let mut child = command()
            .args(args)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_millis(500));
        assert!(
            child.try_wait().unwrap().is_none(),
            "{args:?} ended before the signal"
        );
        let kill = std::process::Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .unwrap();
        assert!(kill.success());
        let sent = Instant::now();
        let status = child.wait().unwrap();
        let latency = sent.elapsed();
        assert!(!status.success(), "{args:?}: {status:?}");
        let names = listing(dir);
        assert!(
            !names.iter().any(|n| n.contains(".tmp-")),
            "{args:?} left {names:?}"
        );
        for name in names.iter().filter(|n| *n != "case.toml") {
            complete(&dir.join(name));
        }
        latency
    }

    /// SIGTERM is obeyed within a second by every long-running command (the diagram: the largest
    /// accepted, about a minute of work). On an idle machine each
    /// ends within about 0.1 s of the signal (a sweep polls its stop flag every 50 ms, then writes
    /// the rows done; the others end at once from the signal handler); the bound checked, 3 s,
    /// leaves room for a machine loaded by parallel builds (5 on 2 cores when this was written).
    #[test]
    fn sigterm_is_obeyed_within_a_second_by_every_long_command() {
        let dir = scratch("sigterm");
        // Four runs that take hours each, one thread: before, SIGTERM waited for the run.
        let case = case_file(
            &dir,
            "1e9",
            "[sweep]\ntilt = { values = [0.1, 0.2, 0.3, 0.4] }\n",
        );
        let table = dir.join("table.csv");
        let csv = dir.join("x.csv");
        let figures = dir.join("figures");
        let long: [Vec<&str>; 5] = [
            vec![
                "sweep",
                "--case",
                &case,
                "--threads",
                "1",
                "--out",
                table.to_str().unwrap(),
            ],
            vec![
                "simulate",
                "--case",
                &case,
                "--samples",
                "100",
                "--out",
                csv.to_str().unwrap(),
            ],
            vec![
                "exact",
                "--case",
                &case,
                "--t",
                "1e4",
                "--samples",
                "10000000",
                "--out",
                csv.to_str().unwrap(),
            ],
            vec!["audit", "--points", "100000"],
            vec![
                "diagram",
                "--grid",
                "387",
                "--tilts",
                "5000",
                "--loop-points",
                "5000",
                "--out",
                figures.to_str().unwrap(),
            ],
        ];
        // A file left by a stopped command is complete: the sweep's table has whole rows.
        let complete = |path: &Path| {
            if path.is_file() {
                let text = std::fs::read_to_string(path).unwrap();
                assert!(text.ends_with('\n'), "{} cut short", path.display());
                let width = text.lines().next().unwrap().split(',').count();
                assert!(text.lines().all(|l| l.split(',').count() == width));
            }
        };
        for args in &long {
            let latency = sigterm_latency(&dir, args, complete);
            eprintln!("{}: ended {latency:?} after SIGTERM", args[0]);
            assert!(latency < Duration::from_secs(3), "{args:?}: {latency:?}");
        }
    }
}

mod messages {
    //! The reproducers of issue 33's messages, as a user runs them: each bad input is refused with
    //! exit code 2 and a message naming the key, the value and the rule (the input that caused
    //! the failure, not a quantity computed from it); each control beside it runs.

    use crate::common;

    use common::{assert_exit_2, routh};

    /// The default case with `from` replaced by `to`, written to a file of its own; its path.
    fn case_with(name: &str, from: &str, to: &str) -> String {
        let text = std::fs::read_to_string(format!("{}/cases/default.toml", common::ROOT)).unwrap();
        assert!(text.contains(from), "{from}");
        let dir = std::env::temp_dir().join(format!("routh-messages-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, text.replace(from, to)).unwrap();
        path.display().to_string()
    }

    const GAMMA: &str = "gamma = [0.29552020666133955, 0.0, 0.955336489125606]";

    /// The summary of `routh simulate --json` with `args`.
    fn simulate_json(args: &[&str]) -> serde_json::Value {
        let mut all = vec!["simulate", "--json"];
        all.extend_from_slice(args);
        common::json_of(&routh(&all))
    }

    /// Reproducer 1: gamma = [1e200, 1e200, 0] with `normalize = true` ran with gamma = [0, 0, 0];
    /// it is now normalised without overflow, and a gamma of length 0 is refused.
    #[test]
    fn a_huge_gamma_is_normalised_and_a_zero_one_refused() {
        let huge = case_with(
            "huge-gamma",
            GAMMA,
            "gamma = [1e200, 1e200, 0.0]\nnormalize = true",
        );
        let summary = simulate_json(&["--case", &huge, "--t-end", "0.1"]);
        let gamma = &summary["initial_state"]["gamma"];
        let half = std::f64::consts::FRAC_1_SQRT_2;
        for (i, want) in [half, half, 0.0].into_iter().enumerate() {
            let got = gamma[i].as_f64().unwrap();
            assert!((got - want).abs() <= 1e-15, "{gamma}");
        }
        let zero = case_with(
            "zero-gamma",
            GAMMA,
            "gamma = [0.0, 0.0, 0.0]\nnormalize = true",
        );
        for command in ["simulate", "exact"] {
            assert_exit_2(
                &[command, "--case", &zero],
                "gamma = [0.0, 0.0, 0.0] has length 0 and cannot be normalised",
            );
        }
    }

    /// Reproducer 2: m = 1e40 blamed "the spin omega3 = inf" (the spin is 8); the mass, whose
    /// m R^2 against the moments makes I_Q singular in f64, is named with the rule.
    #[test]
    fn a_huge_mass_is_blamed_not_the_spin() {
        let heavy = case_with("heavy", "m = 1.0", "m = 1e40");
        for command in ["simulate", "exact", "steady"] {
            assert_exit_2(
                &[command, "--case", &heavy],
                "invalid body parameter m = 1e40: makes the inertia",
            );
        }
        // Control: the same body in other units (mass and moments by 1e30) runs.
        simulate_json(&["--case", &heavy_copy("heavy-control"), "--t-end", "0.1"]);
    }

    /// The default case in units of mass 1e30 times larger (m and the moments by 1e30), in the
    /// file `name`.toml.
    fn heavy_copy(name: &str) -> String {
        let path = case_with(name, "m = 1.0", "m = 1e30");
        let text = std::fs::read_to_string(&path)
            .unwrap()
            .replace("I1 = 0.4", "I1 = 0.4e30")
            .replace("I3 = 0.5", "I3 = 0.5e30");
        std::fs::write(&path, text).unwrap();
        path
    }

    /// Reproducers 3 and 5: `--atol 1e-320` ended in "step size too small at t = 0: h = 0", and
    /// `--rtol 2.2e-14`, the bound the message and the README print, was refused. A tolerance
    /// below its printed bound is refused naming it; the bound itself runs.
    #[test]
    fn tolerances_are_refused_by_their_printed_bounds() {
        assert_exit_2(
            &["simulate", "--atol", "1e-320"],
            "invalid option atol = 1e-320",
        );
        assert_exit_2(
            &["simulate", "--atol", "1e-320"],
            "must be >= 1e-150 (the step control squares error / atol",
        );
        assert_exit_2(
            &["simulate", "--rtol", "2.1e-14"],
            "invalid option rtol = 2.1e-14: must be >= 2.2e-14",
        );
        simulate_json(&["--rtol", "2.2e-14", "--atol", "1e-150", "--t-end", "0.1"]);
    }

    /// Reproducer 4: `--t-end 0 --samples 2` blamed "samples = 0", a value never given; t_end,
    /// which makes the span empty, is named with its value.
    #[test]
    fn samples_on_an_empty_span_name_t_end() {
        assert_exit_2(
            &["simulate", "--t-end", "0", "--samples", "2"],
            "invalid option t_end = 0: must be > 0 when samples are asked for",
        );
        // Control: t_end = 0 without samples runs.
        simulate_json(&["--t-end", "0"]);
    }

    /// Reproducer 6: type and length errors of a case file name the table, the key, the value
    /// and the rule (the parser's own text named neither the key nor the value).
    #[test]
    fn case_type_errors_name_the_key() {
        let short = case_with("short-gamma", GAMMA, "gamma = [0.0, 1.0]");
        assert_exit_2(
            &["simulate", "--case", &short],
            "in [initial]: invalid gamma = [0.0, 1.0]: invalid length 2, expected an array of length 3",
        );
        let text = case_with("text-m", "m = 1.0", "m = \"one\"");
        assert_exit_2(
            &["exact", "--case", &text],
            "in [body]: invalid m = \"one\": invalid type: string \"one\", expected f64",
        );
    }
}
