//! `routh explore`: the explorer page, one self-contained HTML file that computes in the
//! browser (the library compiled to WebAssembly, inlined; `routh::explore`).

use super::plot::create_dir;
use routh::explore::{html, WASM};
use routh::output::write_bytes_atomic;
use routh::AppResult as Result;
use serde::Serialize;
use std::path::PathBuf;

/// The file written in the output directory.
pub const FILE_NAME: &str = "explorer.html";

/// Options of `routh explore`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Directory for `explorer.html` (created if missing).
    #[arg(long, default_value = "plots")]
    pub out: PathBuf,
    /// Print the path written and the sizes as JSON.
    #[arg(long)]
    pub json: bool,
}

/// What `--json` prints.
#[derive(Serialize)]
struct Report {
    /// The page written.
    path: PathBuf,
    /// Its size in bytes.
    bytes: usize,
    /// The size of the WebAssembly inlined in it (before base64), in bytes.
    wasm_bytes: usize,
}

/// Run the command.
pub fn run(args: Args) -> Result<()> {
    let page = html()?;
    create_dir(&args.out)?;
    let path = args.out.join(FILE_NAME);
    write_bytes_atomic(&path, page.as_bytes())?;
    let report = Report {
        path: std::path::absolute(&path).unwrap_or(path),
        bytes: page.len(),
        wasm_bytes: WASM.len(),
    };
    if args.json {
        super::print_json(&report)
    } else {
        outln!(
            "wrote {} ({} bytes, {} of WebAssembly inlined)",
            report.path.display(),
            report.bytes,
            report.wasm_bytes
        )
    }
}
