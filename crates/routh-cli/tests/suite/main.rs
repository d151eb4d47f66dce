//! The tests of the command-line tool, one test binary (each binary of its own linked the
//! library again). Run one module with `cargo test -p routh-cli --test suite cli::`.

#[path = "../common/mod.rs"]
mod common;

mod bounds;
mod cli;
mod contact;
mod exact_scaling;
mod megno;
mod messages;
mod reliability;
