//! The Poincaré section of a case as the front ends report it (`routh section`, Python's
//! `routh.section`): the crossings of the runs from the case's state and from a family on its
//! energy level ([`energy_family`]) with a plane `NAME = NUMBER` ([`crate::surface`]), by
//! [`ball_section`]; their table (the run, then the columns of `routh simulate`'s CSV) and
//! the summary (the number of crossings, how far they lie from the plane and from the
//! energy level, the work).

use crate::ball::Ball;
use crate::error::AppResult as Result;
use crate::integrate::section::Point;
use crate::integrate::Direction;
use crate::problem::Plane;
use crate::row::{write_csv_file, Cell};
use crate::run::{Run, Work};
use crate::simulate::Settings;
use crate::surface::{component_names, direction_name};
use crate::table::{sample_cells, sample_columns};
use routh_ball::section::{ball_section, energy_family, BallSection};
use serde::Serialize;
use std::path::Path;
use std::time::Instant;

/// The summary of a section.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    /// The case, the integrator, the final time of each run and the tolerances.
    #[serde(flatten)]
    pub run: Run,
    /// The plane, `NAME = NUMBER`.
    pub surface: String,
    /// The crossings that count: `up`, `down` or `both`.
    pub direction: &'static str,
    /// The initial states on the energy level (the case's first).
    pub initial_states: usize,
    /// The number of crossings of all the runs.
    pub crossings: usize,
    /// The energy H1 of the level.
    pub energy: f64,
    /// The largest `|NAME - NUMBER|` over the crossings.
    pub max_surface_value: f64,
    /// The unit of the plane's component (1 for gamma, the motion's unit of angular momentum
    /// for M).
    pub surface_unit: f64,
    /// `max_surface_value / surface_unit`: the distance from the plane in the motion's units.
    pub max_relative_surface_value: f64,
    /// The largest relative drift of H1 from the level over the crossings.
    pub max_energy_drift: f64,
    /// The work of all the runs.
    #[serde(flatten)]
    pub work: Work,
}

/// The plane as `NAME = NUMBER`.
pub fn surface_text(plane: &Plane) -> String {
    format!(
        "{} = {}",
        component_names()[plane.component()],
        plane.value()
    )
}

/// The section of the motions of `ball` on the energy level of `x0`: the runs from `initial`
/// states ([`energy_family`]: `x0` first) with `settings`, crossing `plane` in
/// `direction` ([`ball_section`]); the initial states, the section and its summary.
pub fn section(
    ball: &Ball,
    x0: &[f64; 6],
    settings: &Settings,
    plane: &Plane,
    direction: Direction,
    initial: usize,
) -> Result<(Vec<[f64; 6]>, BallSection, Report)> {
    let start = Instant::now();
    let starts = energy_family(ball, x0, initial)?;
    let s = ball_section(ball, &starts, settings, plane, direction)?;
    let report = Report {
        run: Run::of(settings, settings.t_end()),
        surface: surface_text(plane),
        direction: direction_name(direction),
        initial_states: starts.len(),
        crossings: s.points.len(),
        energy: s.energy,
        max_surface_value: s.max_surface_value,
        surface_unit: s.surface_unit,
        max_relative_surface_value: s.max_surface_value / s.surface_unit,
        max_energy_drift: s.max_energy_drift,
        work: Work::of(&s.stats, start),
    };
    Ok((starts, s, report))
}

/// The columns of the table of crossings: `run`, then those of `routh simulate`'s CSV
/// ([`sample_columns`]: `t`, the state, omega, the integrals).
pub fn columns() -> Vec<&'static str> {
    std::iter::once("run")
        .chain(sample_columns(false))
        .collect()
}

/// The cells of one crossing, in the order of [`columns`].
pub fn cells(ball: &Ball, point: &Point<6>) -> Vec<Cell> {
    std::iter::once(Cell::Int(Some(point.run as u64)))
        .chain(sample_cells(ball, point.t, &point.y))
        .collect()
}

/// The table of the crossings `points` of `ball` as CSV into `path`, written whole or not
/// at all ([`write_csv_file`]).
pub fn write_csv(path: &Path, ball: &Ball, points: &[Point<6>]) -> Result<()> {
    write_csv_file(path, &columns(), points.iter().map(|p| cells(ball, p)))
}
