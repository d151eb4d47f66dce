//! `routh audit`: check every computable claim of sections 2.1 to 4 of the paper at random
//! points and print the verdicts (issue 4). Exits 0 whenever the audit ran, whatever the
//! verdicts.

use super::ReportStream;
use clap::Args as ClapArgs;
use routh::audit::claims::{audit, Sample};
use routh::audit::report::{markdown, table};
use routh::output::write_atomic;
use routh::AppError;
use std::path::PathBuf;

/// Options of `routh audit`.
#[derive(ClapArgs, Debug)]
pub struct Args {
    /// Number of random phase-space points per claim (1 to 100000: the audit of 20 points
    /// takes about 1.5 s).
    #[arg(long, default_value_t = 20)]
    pub points: usize,
    /// Seed of the SplitMix64 generator of the points.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print a JSON array of {id, label, statement, status, residual, note} instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Also write a markdown report, equation by equation, to this file (`-`: standard
    /// output, and then the table or the JSON goes to standard error).
    #[arg(long, value_name = "FILE")]
    pub markdown: Option<PathBuf>,
}

/// Run the audit and print or write its report.
pub fn run(args: Args) -> routh::AppResult<()> {
    let sample = Sample::new(args.seed, args.points)?;
    let stream = ReportStream::beside([args.markdown.as_deref()]);
    let verdicts = audit(&sample);
    if let Some(path) = &args.markdown {
        let text = markdown(&verdicts, &sample);
        write_atomic(path, |w| {
            w.write_all(text.as_bytes()).map_err(AppError::io(path))
        })?;
    }
    stream.print(&verdicts, args.json, |v| table(v))
}
