//! Bad and unusual inputs to the command-line tool: exit codes, messages, signals, files never half-written.
//!
//! One test binary of several modules (issue 32: few binaries, each named after what it proves).

#[path = "../common/mod.rs"]
mod common;
mod reliability;
