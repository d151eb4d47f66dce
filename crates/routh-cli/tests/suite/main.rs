//! The tests of the command-line tool, one test binary (each binary of its own linked the
//! library again). Run one module with `cargo test -p routh-cli --test suite cli::`.

mod common {
    //! Running the `routh` binary from the integration tests, as a user would.

    // Each test binary compiles this module and uses a subset of it.
    #![allow(dead_code)]

    use std::process::{Command, Output, Stdio};

    /// The repository's root: the working directory of every run of the binary, so that the
    /// paths of the README (`cases/default.toml`) work as a user types them.
    pub const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

    /// `command` run from the repository's root ([`ROOT`]).
    pub fn at_root(mut command: Command) -> Command {
        command.current_dir(ROOT);
        command
    }

    /// The `routh` binary of this build, to be run from the repository's root.
    pub fn command() -> Command {
        at_root(Command::new(env!("CARGO_BIN_EXE_routh")))
    }

    /// Run `routh` with `args` and collect its output.
    pub fn routh(args: &[&str]) -> Output {
        command().args(args).output().expect("the binary runs")
    }

    /// The JSON that a successful run printed on standard output (the run's stderr in the
    /// message when it failed).
    pub fn json_of(out: &Output) -> serde_json::Value {
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).expect("JSON on stdout")
    }

    /// The names in `dir`, sorted.
    pub fn listing(dir: &std::path::Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    /// Run `routh` with `args` and check that it fails as bad input should: exit code 2, a
    /// message containing `expected` on stderr, and no panic.
    pub fn assert_exit_2(args: &[&str], expected: &str) {
        let out = routh(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains(expected),
            "{args:?}: `{err}` lacks `{expected}`"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }

    /// Run `command` with its standard output a stream whose reader has gone before the command
    /// writes (as `command | head -0`: every write fails with EPIPE), and collect its exit status
    /// and stderr. The reader is closed before the command starts: dropping a pipe's reader after
    /// the spawn raced with the command's first write (a fast command, on a loaded machine, could
    /// write into the pipe's buffer first, go on, and print its summary to stderr). A connected
    /// socket pair stands in for the pipe (`std::io::pipe` is younger than the crate's MSRV).
    pub fn with_closed_stdout(mut command: Command) -> Output {
        let (reader, writer) = std::os::unix::net::UnixStream::pair().expect("a socket pair");
        drop(reader);
        command
            .stdout(Stdio::from(std::os::fd::OwnedFd::from(writer)))
            .stderr(Stdio::piped())
            .output()
            .expect("the binary runs")
    }
}

mod cli;
mod contact;
mod reliability;
