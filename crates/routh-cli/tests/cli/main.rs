//! The command-line tool as a user runs it: every command, its options, files and messages.
//!
//! One test binary of several modules (issue 32: few binaries, each named after what it proves).

mod batch_sweep;
mod cli_audit;
mod cli_exact_steady;
mod cli_flow;
mod cli_overflow_and_pipes;
mod cli_simulate;
mod cli_sweep;
#[path = "../common/mod.rs"]
mod common;
mod diagram_cli;
mod plot;
