//! Sweeps: many runs of one case with some quantities varied (the body's parameters, the
//! initial tilt, spin, omega or gamma), on a grid or a random design, run in parallel, each
//! run reduced to one row (final state, integrals and drift, work, status, the nutation from
//! events and from the quadrature), written as CSV or Parquet as the runs finish.
//!
//! * [`spec`]: the `[sweep]` table and its checks;
//! * [`design`]: the grid, Sobol, Latin hypercube and uniform designs;
//! * [`turning`]: theta min and max, the nutation period and the precession from events;
//! * [`record`]: the row of a run and the columns;
//! * [`runner`]: the case of each run and the parallel execution;
//! * [`table`]: the CSV and Parquet writers, stop and resume.

pub mod design;
#[cfg(feature = "parquet")]
pub mod parquet;
pub mod record;
pub mod runner;
pub mod spec;
pub mod table;
pub mod turning;

pub use runner::{Completion, Overrides, Sweep};
