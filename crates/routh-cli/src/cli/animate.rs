//! `routh animate`: the 3D viewer of the rolling ball, one self-contained HTML page (WebGL,
//! no network at view time), from a simulation of a case or from a CSV file of
//! `routh simulate --full`.

use super::plot::{create_dir, report, Source, Written};
use routh::animate::html;
use routh::output::write_bytes_atomic;
use routh::AppResult as Result;
use std::path::PathBuf;

/// The file written in the output directory.
pub const FILE_NAME: &str = "animation.html";

/// Options of `routh animate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Where the samples come from.
    #[command(flatten)]
    pub source: Source,
    /// Directory for `animation.html` (created if missing).
    #[arg(long, default_value = "plots")]
    pub out: PathBuf,
    /// Print the list of files written as JSON.
    #[arg(long)]
    pub json: bool,
}

/// Run the command.
pub fn run(args: Args) -> Result<()> {
    let page = html(&args.source.table()?)?;
    create_dir(&args.out)?;
    let path = args.out.join(FILE_NAME);
    write_bytes_atomic(&path, page.as_bytes())?;
    report(
        &Written {
            files: vec![path],
            skipped: Vec::new(),
        },
        args.json,
    )
}
