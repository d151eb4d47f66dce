//! Command-line interface: one module per command. Errors become a message on stderr and
//! exit code 2; clap's own usage errors also exit 2.

mod animate;
mod audit;
mod diagram;
mod exact;
mod flow;
mod plot;
mod simulate;
mod steady;
mod sweep;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// The Routh sphere: simulation, exact quadrature, Poisson geometry.
#[derive(Parser)]
#[command(name = "routh", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Integrate a case along (mg-eq) and report the drift of the integrals.
    Simulate(simulate::Args),
    /// Draw the figures of a trajectory (PNG or SVG): theta(t), the paths on the plane, the
    /// drift of the integrals, the trace of (gamma1, gamma2).
    Plot(plot::Args),
    /// Write the 3D viewer of the rolling ball: one self-contained HTML page.
    Animate(animate::Args),
    /// Check every computable claim of the paper's sections 2.1 to 4.
    Audit(audit::Args),
    /// The exact motion by quadrature: turning points, nutation period, state at any time.
    Exact(exact::Args),
    /// The stationary motions of the case's body and their stability (Routh's threshold).
    Steady(steady::Args),
    /// The energy-momentum diagram of the case's body: critical curves, number of tori,
    /// focus-focus points and their monodromy, the sleeping tops (PNG, SVG, CSV).
    Diagram(diagram::Args),
    /// Many runs of a case over the quantities of its [sweep] table (grid or random design),
    /// one row per run, written to CSV or Parquet.
    Sweep(sweep::Args),
}

/// `value` as pretty JSON, ending with a newline. Serialising the output structs (plain
/// numbers, strings, maps with string keys) cannot fail; a NaN or an infinity, which JSON
/// cannot hold, is written as `null`.
pub fn json<T: serde::Serialize>(value: &T) -> String {
    serde_json::to_string_pretty(value).expect("serialisable output") + "\n"
}

/// Print `value` as pretty JSON on stdout. A reader that closed the pipe early (`routh audit
/// --json | head -c 10`) ends the process quietly with exit code 0, as `print!` would panic;
/// any other write error is reported with exit code 2.
pub fn print_json<T: serde::Serialize>(value: &T) {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    if let Err(e) = out
        .write_all(json(value).as_bytes())
        .and_then(|()| out.flush())
    {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("error: standard output: {e}");
        std::process::exit(2);
    }
}

/// Parse the arguments, run the command, map errors to exit code 2.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Err(e) = routh::output::remove_temporaries_on_signal() {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    let result: routh::Result<()> = match cli.command {
        Command::Simulate(args) => simulate::run_command(args),
        Command::Plot(args) => plot::run(args),
        Command::Animate(args) => animate::run(args),
        Command::Audit(args) => audit::run(args),
        Command::Exact(args) => exact::run(args),
        Command::Steady(args) => steady::run(args),
        Command::Sweep(args) => sweep::run(args),
        Command::Diagram(args) => diagram::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
