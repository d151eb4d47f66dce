//! Command-line interface: one module per command. Errors become a message on stderr and
//! exit code 2; clap's own usage errors also exit 2. Every command writes its output (text,
//! JSON, CSV rows) through one writer of standard output, [`write_out`] (the macros `out!` and
//! `outln!`, used as `print!` and `println!`), whose errors end the command like any other:
//! a reader that closed the pipe early (`routh exact | head -1`) ends it quietly with exit
//! code 0, another write error (a full disk) with exit code 2. A command's report goes to
//! standard error instead when one of its files goes to standard output ([`ReportStream`]).

/// `print!` through [`write_out`]: returns its error.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::cli::write_out(format_args!($($arg)*))
    };
}

/// `println!` through [`write_out`]: returns its error.
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::cli::write_out(format_args!("{}\n", format_args!($($arg)*)))
    };
}

mod animate;
mod audit;
mod case_file;
mod diagram;
mod exact;
mod explore;
mod flow;
mod integration;
mod inversion;
mod lyapunov;
mod megno;
mod plot;
mod section;
mod simulate;
mod steady;
mod sweep;

use clap::{Parser, Subcommand};
use routh::output::is_standard_output;
use routh::{AppError, AppResult, FileError};
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

/// The name of standard output in error messages.
pub const STANDARD_OUTPUT: &str = "standard output";

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
    /// Write the explorer: one self-contained HTML page that computes in the browser (the
    /// library compiled to WebAssembly), with sliders for the body and the initial state.
    Explore(explore::Args),
    /// Check every computable claim of the paper's sections 2.1 to 4.
    Audit(audit::Args),
    /// The exact motion by quadrature: turning points, nutation period, state at any time.
    Exact(exact::Args),
    /// The stationary motions of the case's body and their stability (Routh's threshold).
    Steady(steady::Args),
    /// The energy-momentum diagram of the case's body: critical curves, number of tori,
    /// focus-focus points and their monodromy, the sleeping tops (PNG, SVG, CSV).
    Diagram(diagram::Args),
    /// The Lyapunov exponents of a case on |gamma| = 1 (QR method on the variational
    /// equations): their convergence, the Kaplan–Yorke dimension, the divergence check.
    Lyapunov(lyapunov::Args),
    /// The fast indicators MEGNO and FLI of a case on |gamma| = 1; with --x and --y, a chart
    /// of regimes over a plane of two quantities (CSV, PNG, SVG).
    Megno(megno::Args),
    /// The Poincaré section of a case's motions on its energy level through a plane
    /// `NAME = NUMBER` (CSV, PNG, SVG).
    Section(section::Args),
    /// Many runs of a case over the quantities of its [sweep] table (grid or random design),
    /// one row per run, written to CSV or Parquet.
    Sweep(sweep::Args),
    /// The tippe top's inversion region over (a / R, I1 / I3) at one or more spins, beside the
    /// published conditions (CSV, PNG, SVG).
    Inversion(inversion::Args),
}

/// A number in a text summary: as `{}` prints it between 1e-4 and 1e6 (and zero, and the
/// non-finite values), else in scientific notation, the shortest digits that read back to it
/// (a mass of 1e-300 is `1e-300`, not 300 digits).
pub struct Readable(pub f64);

impl std::fmt::Display for Readable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if x == 0.0 || !x.is_finite() || (1e-4..1e6).contains(&x.abs()) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

/// `value` as pretty JSON, ending with a newline. Serialising the output structs (plain
/// numbers, strings, maps with string keys) cannot fail; a NaN or an infinity, which JSON
/// cannot hold, is written as `null`.
pub fn json<T: serde::Serialize>(value: &T) -> String {
    serde_json::to_string_pretty(value).expect("serialisable output") + "\n"
}

/// Print `value` as pretty JSON on stdout ([`write_out`]).
pub fn print_json<T: serde::Serialize>(value: &T) -> AppResult<()> {
    out!("{}", json(value))
}

/// The stream of a command's report (its text summary or table, or its JSON): standard
/// output, or standard error when one of the command's files goes to standard output (`-`, or
/// a file that standard output is open on: `/dev/stdout`, the target of `> FILE`; see
/// [`is_standard_output`]): one stream per destination. The one place where `simulate`,
/// `exact` (and `--flow`) and `audit` decide it.
pub struct ReportStream {
    /// Whether the report goes to standard error.
    on_standard_error: bool,
}

impl ReportStream {
    /// The stream of the report of a command writing `files` (`None`: a file not asked for).
    /// Asked before any file is written: a file that standard output is redirected to is
    /// replaced by the new one, which standard output is not open on.
    pub fn beside<'a>(files: impl IntoIterator<Item = Option<&'a Path>>) -> Self {
        ReportStream {
            on_standard_error: files.into_iter().flatten().any(is_standard_output),
        }
    }

    /// Print the report of `value`: as JSON with `json`, else as `text(value)`.
    pub fn print<T: serde::Serialize>(
        &self,
        value: &T,
        json: bool,
        text: impl FnOnce(&T) -> String,
    ) -> AppResult<()> {
        let report = if json { self::json(value) } else { text(value) };
        if self.on_standard_error {
            eprint!("{report}");
            Ok(())
        } else {
            out!("{report}")
        }
    }
}

/// Write on standard output: the one path of the commands' output. Where `print!` would panic
/// on a write error, this returns it, naming standard output.
pub fn write_out(text: std::fmt::Arguments) -> AppResult<()> {
    std::io::stdout()
        .lock()
        .write_fmt(text)
        .map_err(AppError::io(Path::new(STANDARD_OUTPUT)))
}

/// Whether `e` is a write to standard output (`--out -` included) whose reader has gone.
fn closed_pipe(e: &AppError) -> bool {
    matches!(e, AppError::File(FileError::Io { path, source })
        if source.kind() == std::io::ErrorKind::BrokenPipe
            && (path == Path::new(STANDARD_OUTPUT) || path == Path::new("-")))
}

/// Parse the arguments, run the command, map errors to exit code 2.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Err(e) = routh::output::remove_temporaries_on_signal() {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    let result: AppResult<()> = match cli.command {
        Command::Simulate(args) => simulate::run_command(args),
        Command::Plot(args) => plot::run(args),
        Command::Animate(args) => animate::run(args),
        Command::Explore(args) => explore::run(args),
        Command::Audit(args) => audit::run(args),
        Command::Exact(args) => match args.flow {
            Some(field) => flow::run(&args, field),
            None => exact::run(args),
        },
        Command::Steady(args) => steady::run(args),
        Command::Sweep(args) => sweep::run(args),
        Command::Diagram(args) => diagram::run(args),
        Command::Lyapunov(args) => lyapunov::run(args),
        Command::Megno(args) => megno::run(args),
        Command::Section(args) => section::run(args),
        Command::Inversion(args) => inversion::run(args),
    };
    let flushed = result.and_then(|()| {
        std::io::stdout()
            .flush()
            .map_err(AppError::io(Path::new(STANDARD_OUTPUT)))
    });
    match flushed {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if closed_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
