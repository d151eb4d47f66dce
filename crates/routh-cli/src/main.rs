//! The `routh` command-line tool: see `routh --help`.

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
