//! Sweeps: many runs of one case with some quantities varied (the body's parameters, the
//! initial tilt, spin, omega or gamma, a sliding contact's mu), on a grid or a random design, run in parallel, each
//! run reduced to one row (work, status, and the columns asked for: final state, integrals
//! and drift, the nutation from events and from the quadrature, the crossings of the user's
//! events; only those are computed),
//! written as CSV or Parquet as the runs finish.
//!
//! * [`spec`]: the `[sweep]` table and its checks;
//! * [`design`]: the grid, Sobol, Latin hypercube and uniform designs;
//! * [`crossings`]: the events watched on every step of a run (the turning points of the
//!   tilt, the user's planes), located by the one event locator;
//! * [`turning`]: theta min and max, the nutation period and the precession from events;
//! * [`columns`]: the columns of a table, their groups, and what each needs computed;
//! * [`record`]: the row of a run and its cells;
//! * [`runner`]: the case of each run and the parallel execution;
//! * [`contact`]: the run and the row of a sweep of the sliding contact (`contact.mu`
//!   sweepable);
//! * [`table`]: what every writer shares, stop and resume; [`csv`] and `parquet` (feature
//!   `parquet`): the writers; [`open`] chooses one by the file's extension.

pub mod columns;
pub mod contact;
pub mod crossings;
pub mod csv;
pub mod design;
#[cfg(feature = "parquet")]
pub mod parquet;
pub mod record;
pub mod runner;
pub mod spec;
pub mod table;
pub mod turning;

pub use columns::Columns;
pub use runner::{pool, Completion, Sweep};

use crate::error::{AppResult as Result, RouthError};
use std::path::Path;
use table::{Resumed, TableWriter};

/// Open the table `target` for `sweep`: CSV or Parquet by the extension. Returns the writer
/// and what is kept of the file (with `resume`).
pub fn open(target: &Path, sweep: &Sweep, resume: bool) -> Result<(Box<dyn TableWriter>, Resumed)> {
    match target.extension().and_then(|e| e.to_str()) {
        Some("csv") => {
            let (t, done) = csv::CsvTable::create(target, sweep, resume)?;
            Ok((Box::new(t), done))
        }
        #[cfg(feature = "parquet")]
        Some("parquet") => {
            let (t, done) = parquet::ParquetTable::create(target, sweep, resume)?;
            Ok((Box::new(t), done))
        }
        #[cfg(not(feature = "parquet"))]
        Some("parquet") => Err(RouthError::Option {
            name: "out",
            value: target.display().to_string(),
            rule: "this build has no Parquet output (built without the feature `parquet`, on by default): write .csv",
        }.into()),
        _ => Err(RouthError::Option {
            name: "out",
            value: target.display().to_string(),
            rule: "must end in .parquet or .csv",
        }
        .into()),
    }
}
