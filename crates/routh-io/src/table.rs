//! Tables of samples along a trajectory, column by column: built by simulating a case with
//! the full motion, or read back from a CSV file written by `routh simulate` (a header row of
//! column names, then rows of numbers; an empty cell, as written for H2 and K when I1 != I2,
//! reads as NaN). The plots and the animation draw from a [`Table`].

use crate::ball::Ball;
use crate::case::{Case, Overrides, RubberStart, SlidingStart};
use crate::contact::rubber::{run as run_rubber, RubberSummary};
use crate::contact::sliding::{
    run as run_sliding, run_in_space, Observation, SlidingSummary, OBSERVATION_NAMES,
};
use crate::error::{AppError, AppResult as Result, FileError};
use crate::integrals::{Integrals, INTEGRAL_NAMES};
use crate::integrate::OdeSystem;
use crate::motion::{full_columns, initial_full, FullMotion, FULL_COLUMN_NAMES, FULL_DIM};
use crate::row::Cell;
use crate::simulate::{integrate_observed, ReducedSystem, Settings, Summary};
use crate::state::Point;
use std::path::Path;

/// Names of the reduced-state columns of `routh simulate`, after `t` and before the integrals.
pub const STATE_COLUMN_NAMES: [&str; 9] = [
    "gamma1", "gamma2", "gamma3", "M1", "M2", "M3", "omega1", "omega2", "omega3",
];

/// The CSV header of samples, shared by every command that writes them: `t`, the
/// [`STATE_COLUMN_NAMES`], then the command's own columns `tail` (the integrals of `routh
/// simulate`, the tilt and integrals of `routh exact`, ...).
pub fn csv_header(tail: &[&str]) -> String {
    std::iter::once("t")
        .chain(STATE_COLUMN_NAMES)
        .chain(tail.iter().copied())
        .collect::<Vec<_>>()
        .join(",")
}

/// Columns that may hold empty cells: the integrals that exist only for I1 = I2.
pub const OPTIONAL_COLUMNS: [&str; 2] = ["H2", "K"];

/// The value of one CSV cell of column `name`, or why it cannot be drawn.
fn cell_value(cell: &str, name: &str) -> std::result::Result<f64, String> {
    if cell.is_empty() {
        return if OPTIONAL_COLUMNS.contains(&name) {
            Ok(f64::NAN)
        } else {
            Err("empty cell".into())
        };
    }
    match cell.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!("`{cell}` is not a finite number")),
        Err(_) => Err(format!("`{cell}` is not a number")),
    }
}

/// Named columns of equal length.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Where the table came from, for error messages.
    pub origin: String,
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
}

impl Table {
    /// An empty table with the given column names.
    pub fn new(origin: &str, names: Vec<String>) -> Self {
        let columns = vec![Vec::new(); names.len()];
        Table {
            origin: origin.to_string(),
            names,
            columns,
        }
    }

    /// Append a row; it must have one value per column.
    pub fn push_row(&mut self, row: &[f64]) -> Result<()> {
        if row.len() != self.names.len() {
            return Err(self.error(format!(
                "a row of {} values for {} columns",
                row.len(),
                self.names.len()
            )));
        }
        for (column, &value) in self.columns.iter_mut().zip(row) {
            column.push(value);
        }
        Ok(())
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }

    /// Whether the table has no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The column names, in order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Whether a column of that name exists.
    pub fn has(&self, name: &str) -> bool {
        self.names.iter().any(|n| n == name)
    }

    /// The column `name`, or an error that names it.
    pub fn column(&self, name: &str) -> Result<&[f64]> {
        self.names
            .iter()
            .position(|n| n == name)
            .map(|i| self.columns[i].as_slice())
            .ok_or_else(|| self.error(format!("no column `{name}`")))
    }

    fn error(&self, message: String) -> AppError {
        FileError::Table {
            origin: self.origin.clone(),
            message,
        }
        .into()
    }

    /// Parse CSV text: a header of distinct names, then at least two rows of finite numbers,
    /// one per column, with `t` strictly increasing. An empty cell reads as NaN and is allowed
    /// only in the columns of [`OPTIONAL_COLUMNS`] (written empty when I1 != I2); anything
    /// else that cannot be drawn (a `NaN` or `inf` written out, a ragged row, one row) is
    /// refused with its line and column.
    pub fn parse_csv(text: &str, origin: &str) -> Result<Self> {
        let error = |message: String| {
            AppError::from(FileError::Table {
                origin: origin.to_string(),
                message,
            })
        };
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty());
        let (_, header) = lines
            .next()
            .ok_or_else(|| error("empty file, expected a header row".into()))?;
        let names: Vec<String> = header.split(',').map(|s| s.trim().to_string()).collect();
        for (i, name) in names.iter().enumerate() {
            if name.is_empty() || names[..i].contains(name) {
                return Err(error(format!(
                    "line 1: column {} has an empty or repeated name `{name}`",
                    i + 1
                )));
            }
        }
        let mut table = Table::new(origin, names);
        for (index, line) in lines {
            let line_no = index + 1;
            let cells: Vec<&str> = line.split(',').map(str::trim).collect();
            if cells.len() != table.names.len() {
                return Err(error(format!(
                    "line {line_no}: {} values for {} columns",
                    cells.len(),
                    table.names.len()
                )));
            }
            let row = cells
                .iter()
                .zip(&table.names)
                .map(|(cell, name)| {
                    cell_value(cell, name)
                        .map_err(|why| error(format!("line {line_no}, column `{name}`: {why}")))
                })
                .collect::<Result<Vec<f64>>>()?;
            table.push_row(&row)?;
        }
        if table.len() < 2 {
            return Err(error(format!(
                "{} row(s) of samples, at least 2 are needed to draw",
                table.len()
            )));
        }
        let t = table.column("t")?;
        if let Some(i) = t.windows(2).position(|w| w[1] <= w[0]) {
            return Err(error(format!(
                "column `t` must increase, but row {} has t = {} after t = {}",
                i + 2,
                t[i + 1],
                t[i]
            )));
        }
        Ok(table)
    }

    /// Read a CSV file written by `routh simulate`.
    pub fn read_csv(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|source| FileError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::parse_csv(&text, &path.display().to_string())
    }
}

/// The columns of a sample of `routh simulate`: `t`, the [`STATE_COLUMN_NAMES`], the
/// integrals and, with `full`, the motion in space ([`FULL_COLUMN_NAMES`]).
pub fn sample_columns(full: bool) -> Vec<&'static str> {
    let space: &[&str] = if full { &FULL_COLUMN_NAMES } else { &[] };
    std::iter::once("t")
        .chain(STATE_COLUMN_NAMES)
        .chain(INTEGRAL_NAMES)
        .chain(space.iter().copied())
        .collect()
}

/// The cells of the sample `y` at time `t`, in the order of [`sample_columns`]: the reduced
/// state (the first six components of `y`), omega, the integrals (null where not an integral)
/// and, when `y` holds the motion in space (`FullMotion`'s state), its [`full_columns`].
pub fn sample_cells(ball: &Ball, t: f64, y: &[f64]) -> Vec<Cell> {
    let x: [f64; 6] = std::array::from_fn(|i| y[i]);
    let space = <&[f64; FULL_DIM]>::try_from(y)
        .ok()
        .map(|y| full_columns(ball, y));
    state_values(ball, t, &x)
        .map(Some)
        .chain(Integrals::at(ball, &x).values())
        .chain(space.into_iter().flatten().map(Some))
        .map(Cell::Float)
        .collect()
}

/// `t`, the reduced state `x` and omega: the first columns of every sample of a run of the
/// reduced state ([`STATE_COLUMN_NAMES`]).
fn state_values(ball: &Ball, t: f64, x: &[f64; 6]) -> impl Iterator<Item = f64> {
    let omega = Point::from_array(x).omega(ball);
    std::iter::once(t).chain(*x).chain(omega)
}

/// Simulate `case` with `settings`, with the full motion (the orientation and the path in
/// space) when `full`, and hand the cells of each dense sample ([`sample_cells`]) to `on_row`:
/// the one path of the samples of `routh simulate` and of the figures. Returns the run's
/// summary.
pub fn simulate_samples(
    case: &Case,
    settings: &Settings,
    full: bool,
    on_row: &mut dyn FnMut(&[Cell]) -> Result<()>,
) -> Result<Summary> {
    fn samples<S: OdeSystem<N>, const N: usize>(
        ball: &Ball,
        system: &S,
        y0: [f64; N],
        settings: &Settings,
        on_row: &mut dyn FnMut(&[Cell]) -> Result<()>,
    ) -> Result<Summary> {
        let mut on_sample = |t: f64, y: &[f64; N]| on_row(&sample_cells(ball, t, y));
        let observed = integrate_observed(
            ball,
            system,
            y0,
            settings,
            None,
            &mut on_sample,
            &mut |_| {},
        )?;
        Ok(observed.summary()?)
    }
    let ball = &case.ball;
    if full {
        let system = FullMotion { body: ball };
        samples(ball, &system, initial_full(&case.initial), settings, on_row)
    } else {
        let system = ReducedSystem(ball);
        samples(ball, &system, case.initial.to_array(), settings, on_row)
    }
}

/// Simulate the sliding ball `start` (`[contact] law = "sliding"`) with `settings` and hand the
/// cells of each dense sample to `on_row`, in the columns of
/// [`OBSERVATION_NAMES`](crate::contact::sliding::OBSERVATION_NAMES) (the state, the height of
/// the centre of mass, the slip speed, the normal force, Jellett's integral, the energy and the
/// work of friction), with `full` those of the motion in space after them
/// ([`FULL_COLUMN_NAMES`]: the viscous friction only, [`run_in_space`]): the samples of `routh
/// simulate` for that contact ([`sliding_columns`]). Returns the run's summary.
pub fn sliding_samples(
    start: &SlidingStart,
    settings: &Settings,
    full: bool,
    on_row: &mut dyn FnMut(&[Cell]) -> Result<()>,
) -> Result<SlidingSummary> {
    let model = &start.model;
    let cells = |now: &Observation, space: &[f64]| -> Vec<Cell> {
        now.values()
            .into_iter()
            .chain(space.iter().copied())
            .map(|v| Cell::Float(Some(v)))
            .collect()
    };
    if full {
        return run_in_space(model, start.y0, settings, &mut |now, space| {
            on_row(&cells(now, space))
        });
    }
    run_sliding(model, start.y0, settings, &mut |now| {
        on_row(&cells(now, &[]))
    })
}

/// The columns of [`sliding_samples`].
pub fn sliding_columns(full: bool) -> Vec<&'static str> {
    let space: &[&str] = if full { &FULL_COLUMN_NAMES } else { &[] };
    OBSERVATION_NAMES.iter().chain(space).copied().collect()
}

/// Simulate the rubber ball `start` (`[contact] law = "rubber"`) with `settings` and hand the
/// cells of each dense sample to `on_row`: `t`, the [`STATE_COLUMN_NAMES`] and the rubber
/// ball's [`COLUMN_NAMES`](crate::contact::rubber::COLUMN_NAMES) (its integrals, the twist,
/// the couple; F empty where it is not an integral): the samples of `routh simulate` for that
/// contact. Returns the run's summary.
pub fn rubber_samples(
    start: &RubberStart,
    settings: &Settings,
    on_row: &mut dyn FnMut(&[Cell]) -> Result<()>,
) -> Result<RubberSummary> {
    let model = &start.model;
    let ball = model.ball();
    let mut on_sample = |t: f64, x: &[f64; 6]| {
        let cells: Vec<Cell> = state_values(&ball, t, x)
            .map(Some)
            .chain(model.columns(x))
            .map(Cell::Float)
            .collect();
        on_row(&cells)
    };
    run_rubber(model, start.x0, settings, &mut on_sample)
}

/// Simulate `case` with the full motion (its settings with `overrides` applied, checked as
/// they are built: [`Overrides::applied_to`]) and tabulate `samples` equally spaced samples
/// on [0, t_end]: the columns of [`sample_columns`] (empty integrals as NaN, as a CSV of
/// `routh simulate --full` reads back); of a sliding case, the columns of its samples
/// ([`sliding_columns`], with the motion in space under the viscous friction).
pub fn simulate_full(case: &Case, overrides: &Overrides, samples: usize) -> Result<Table> {
    let settings = overrides.applied_to(case).samples(samples).build()?;
    if let Some(start) = &case.sliding {
        // The motion in space where it is rebuilt (the viscous friction).
        let full = start.model.friction() == crate::contact::Friction::Viscous;
        let names = sliding_columns(full)
            .into_iter()
            .map(str::to_string)
            .collect();
        let mut table = Table::new(&case.source, names);
        sliding_samples(start, &settings, full, &mut |cells| {
            let row: Vec<f64> = cells.iter().map(Cell::to_f64).collect();
            table.push_row(&row)
        })?;
        return Ok(table);
    }
    let names = sample_columns(true)
        .into_iter()
        .map(str::to_string)
        .collect();
    let mut table = Table::new(&case.source, names);
    simulate_samples(case, &settings, true, &mut |cells| {
        let row: Vec<f64> = cells.iter().map(Cell::to_f64).collect();
        table.push_row(&row)
    })?;
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_round_trip_with_empty_cells() {
        let table = Table::parse_csv("t,H2,x\n0,1.5,4\n0.5,,2e-3\n", "test").unwrap();
        assert_eq!(table.len(), 2);
        assert_eq!(table.column("t").unwrap(), &[0.0, 0.5]);
        assert!(table.column("H2").unwrap()[1].is_nan());
        assert_eq!(table.column("x").unwrap()[1], 2e-3);
        assert!(table.column("y").is_err());
    }

    #[test]
    fn bad_csv_names_the_line() {
        let err = Table::parse_csv("t,x\n0,1\n1,abc\n", "f.csv").unwrap_err();
        assert!(err.to_string().contains("line 3"), "{err}");
        let err = Table::parse_csv("t,x\n0,1,2\n", "f.csv").unwrap_err();
        assert!(err.to_string().contains("line 2"), "{err}");
        assert!(Table::parse_csv("x\n1\n2\n", "f.csv").is_err());
        assert!(Table::parse_csv("t,x\n", "f.csv").is_err());
    }

    #[test]
    fn csvs_that_cannot_be_drawn_are_refused_naming_the_file_once() {
        for (text, expected) in [
            ("t,x\n0,1\n", "1 row(s)"),
            (
                "t,x\n0,1\n1,NaN\n",
                "line 3, column `x`: `NaN` is not a finite number",
            ),
            ("t,x\n0,1\n1,inf\n", "column `x`"),
            ("t,x\n0,1\n1,\n", "line 3, column `x`: empty cell"),
            ("t,x\n0,1\n1,2,3\n", "line 3: 3 values for 2 columns"),
            ("t,x\n0,1\n0,2\n", "must increase"),
            ("t,t\n0,1\n1,2\n", "repeated name"),
        ] {
            let e = Table::parse_csv(text, "f.csv").unwrap_err().to_string();
            assert!(e.contains(expected), "{text:?}: {e}");
            assert_eq!(e.matches("f.csv").count(), 1, "{e}");
        }
    }
}
