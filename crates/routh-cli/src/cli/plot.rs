//! `routh plot`: the standard figures of a trajectory (theta(t), the paths on the plane, the
//! drift of the integrals, the trace of (gamma1, gamma2); of a sliding contact, the height of
//! the centre of mass, the slip speed, the normal force and the balances), from a simulation
//! of a case or from a CSV file written by `routh simulate`; optionally the difference against
//! a second CSV.

use routh::case::{Case, Overrides};
use routh::integrate::Method;
use routh::plot::{difference_plot, standard_plots, Format};
use routh::table::{simulate_full, Table};
use routh::{AppError, AppResult as Result, RouthError};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Samples of the simulation behind the figures when `--samples` is not given.
const DEFAULT_SAMPLES: usize = 2001;

/// The most samples of a simulation behind the figures (about 30 columns of 8 bytes each are
/// kept in memory: 240 MB).
const MAX_SAMPLES: usize = 1_000_000;

/// Where the samples come from: a simulation of a case, or a CSV file of `routh simulate`.
#[derive(clap::Args, Debug)]
pub struct Source {
    /// Case file (TOML); the built-in default case when omitted.
    #[arg(long, conflicts_with = "csv")]
    pub case: Option<PathBuf>,
    /// Draw from this CSV file of `routh simulate` (use `--full` for the paths) instead of
    /// simulating.
    #[arg(long)]
    pub csv: Option<PathBuf>,
    /// Final time of the simulation (default: the case's t_end).
    #[arg(long, allow_negative_numbers = true, conflicts_with = "csv")]
    pub t_end: Option<f64>,
    /// Number of equally spaced samples of the simulation (2 to 1000000).
    #[arg(long, default_value_t = DEFAULT_SAMPLES, conflicts_with = "csv")]
    pub samples: usize,
    /// Integrator of the simulation, as `routh simulate --method` takes it.
    #[arg(long, default_value = "dop853", value_parser = super::integration::parse_method, conflicts_with = "csv")]
    pub method: Method,
}

impl Source {
    /// The table of samples: read from `--csv`, or simulated with the full motion.
    pub fn table(&self) -> Result<Table> {
        if let Some(path) = &self.csv {
            return Table::read_csv(path);
        }
        let case = Case::load_any_contact(self.case.as_deref())?;
        if case.rubber.is_some() {
            return Err(RouthError::Option {
                name: "case",
                value: case.source.clone(),
                rule: "is of [contact] law = \"rubber\": `routh plot` draws the rolling and the \
                       sliding laws (so far); `routh simulate --out` writes the rubber ball's samples",
            }
            .into());
        }
        if !(2..=MAX_SAMPLES).contains(&self.samples) {
            return Err(RouthError::Option {
                name: "samples",
                value: self.samples.to_string(),
                rule: "must be between 2 and 1000000 (a figure's points are kept in memory)",
            }
            .into());
        }
        let overrides = Overrides {
            method: Some(self.method),
            t_end: self.t_end,
            ..Overrides::default()
        };
        simulate_full(&case, &overrides, self.samples)
    }
}

/// Options of `routh plot`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Where the samples come from.
    #[command(flatten)]
    pub source: Source,
    /// A second CSV sampled at the same times (for example the quadrature solution of
    /// `routh exact`): also draw `difference.<ext>`, this file minus the first table.
    #[arg(long)]
    pub compare: Option<PathBuf>,
    /// Directory for the figures (created if missing).
    #[arg(long, default_value = "plots")]
    pub out: PathBuf,
    /// Image format: png or svg.
    #[arg(long, default_value = "png")]
    pub format: Format,
    /// Print the list of files written as JSON.
    #[arg(long)]
    pub json: bool,
}

/// What `routh plot` reports.
#[derive(Serialize)]
pub struct Written {
    /// The files written.
    pub files: Vec<PathBuf>,
    /// Figures left out, with the reason.
    pub skipped: Vec<String>,
}

/// Create the output directory, naming it in the error. `-` is refused: it names standard
/// output elsewhere, which cannot hold files (`./-` is a directory named `-`).
pub fn create_dir(dir: &Path) -> Result<()> {
    if dir == Path::new("-") {
        return Err(RouthError::Option {
            name: "out",
            value: "-".into(),
            rule: "names a directory for the files, not standard output (`./-` for a directory \
                   named -)",
        }
        .into());
    }
    std::fs::create_dir_all(dir).map_err(AppError::io(dir))
}

/// Print the files written (and figures skipped), as JSON or as lines.
pub fn report(written: &Written, json: bool) -> Result<()> {
    if json {
        super::print_json(written)?;
        return Ok(());
    }
    for file in &written.files {
        outln!("wrote {}", file.display())?;
    }
    for reason in &written.skipped {
        outln!("skipped {reason}")?;
    }
    Ok(())
}

/// The last component of a path, for titles.
fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

/// Run the command.
pub fn run(args: Args) -> Result<()> {
    let table = args.source.table()?;
    let (mut plots, skipped) = standard_plots(&table)?;
    if let Some(path) = &args.compare {
        let other = Table::read_csv(path)?;
        let this = match &args.source.csv {
            Some(csv) => file_name(csv),
            None => args.source.method.to_string().to_uppercase(),
        };
        plots.push(difference_plot(&other, &table, (&file_name(path), &this))?);
    }
    create_dir(&args.out)?;
    let files = plots
        .iter()
        .map(|plot| plot.render(&args.out, args.format))
        .collect::<Result<_>>()?;
    report(&Written { files, skipped }, args.json)?;
    Ok(())
}
