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
