//! The row of one run and the columns of a sweep's table (the same for CSV, Parquet and
//! JSON, written through [`crate::row`]).

use crate::contact::sliding::SlidingSummary;
use crate::integrals::INTEGRAL_NAMES;
use crate::row::{csv_line, write_csv_line, Cell, Kind};
use crate::simulate::Summary;
use crate::sweep::columns::{catalogue, event_columns, Columns, MAX_EVENTS};
use crate::sweep::crossings::Crossings;
use crate::sweep::turning::NutationEvents;

/// How a run ended: a sweep's run reaches t_end ([`Status::Reached`], written `ok`) or fails.
pub use crate::problem::Status;

/// The nutation by quadrature (Routh sphere only).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NutationQuadrature {
    /// The nutation period (None for a steady motion).
    pub period: Option<f64>,
    /// The precession advance per period (None for a steady motion).
    pub precession: Option<f64>,
}

/// What every row of a sweep shares: the settings of its runs, repeated in each row, and the
/// columns of its table.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSettings {
    /// Final time.
    pub t_end: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// The method, as `routh simulate` prints it.
    pub method: String,
    /// The columns of the table.
    pub columns: Columns,
}

/// The result of one run.
#[derive(Debug, Clone)]
pub struct Row {
    /// The run number (the index into the design).
    pub run: u64,
    /// The values of the swept quantities, in the order of the axes.
    pub values: Vec<f64>,
    /// Whether the run finished.
    pub status: Status,
    /// Why it failed, or a note (such as why there is no quadrature); empty otherwise.
    pub message: String,
    /// The integration's summary (None if it failed).
    pub summary: Option<Summary>,
    /// The turning points found along the run (None if it failed, or not asked for).
    pub events: Option<NutationEvents>,
    /// The quadrature's nutation (None when the body or the motion does not allow it, or not
    /// asked for).
    pub quadrature: Option<NutationQuadrature>,
    /// The crossings of each user event, in their order (empty if the run failed, or not
    /// asked for).
    pub user_events: Vec<Crossings>,
    /// A sliding run's summary and its final tilt (None for the rolling law, or if it failed).
    pub sliding: Option<SlidingRun>,
}

/// What a sweep's row keeps of a sliding run ([`super::columns::CONTACT_NAMES`]).
#[derive(Debug, Clone)]
pub struct SlidingRun {
    /// The run's summary, as `routh simulate` reports it.
    pub summary: SlidingSummary,
    /// The angle from the downward vertical to the line from the geometric centre to the
    /// centre of mass at the end (None for a centre of mass at the centre).
    pub tilt_final: Option<f64>,
}

/// The columns of a sweep whose swept quantities are `swept` and whose table holds `chosen`:
/// `run`, the swept quantities (named as in `[sweep]`), then the chosen columns of
/// [`catalogue`] in its order, then those of the user events ([`event_columns`]) in theirs.
pub fn columns(swept: &[String], chosen: &Columns) -> Vec<(String, Kind)> {
    let mut cols = vec![("run".to_string(), Kind::Int)];
    cols.extend(swept.iter().map(|n| (n.clone(), Kind::Float)));
    cols.extend(chosen.select(catalogue()).map(|c| (c.name, c.kind)));
    cols.extend(chosen.select_events((0..MAX_EVENTS).flat_map(event_columns)));
    cols
}

/// `a - b` when both exist.
fn difference(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    Some(a? - b?)
}

impl Row {
    /// The row's cells, in the order of [`columns`] for `settings.columns`.
    pub fn cells(&self, settings: &RunSettings) -> Vec<Cell> {
        let mut cells = vec![Cell::Int(Some(self.run))];
        cells.extend(self.values.iter().map(|v| Cell::Float(Some(*v))));
        cells.extend(settings.columns.select(self.catalogue_cells(settings)));
        cells.extend(
            settings
                .columns
                .select_events((0..MAX_EVENTS).flat_map(|k| {
                    let c = self.user_events.get(k);
                    [
                        Cell::Int(c.map(|c| c.count)),
                        Cell::Float(c.and_then(|c| c.first_t)),
                    ]
                })),
        );
        cells
    }

    /// The cells of every column of [`catalogue`], in its order (null where not computed).
    fn catalogue_cells(&self, settings: &RunSettings) -> Vec<Cell> {
        let mut cells = vec![
            Cell::Float(Some(settings.t_end)),
            Cell::Float(Some(settings.rtol)),
            Cell::Float(Some(settings.atol)),
            Cell::Text(settings.method.clone()),
            Cell::Text(self.status.as_str().to_string()),
            Cell::Text(self.message.clone()),
        ];
        let s = self.summary.as_ref();
        let sliding = self.sliding.as_ref();
        let work = |of: fn(&Summary) -> usize, of_sliding: fn(&SlidingSummary) -> usize| {
            s.map(of).or(sliding.map(|r| of_sliding(&r.summary)))
        };
        for count in [
            work(|s| s.steps, |s| s.steps),
            work(|s| s.rejected, |s| s.rejected),
            work(|s| s.rhs_evals, |s| s.rhs_evals),
        ] {
            cells.push(Cell::Int(count.map(|c| c as u64)));
        }
        let state = s.map(|s| s.final_state.to_array());
        let gamma = sliding.map(|r| r.summary.final_state.gamma);
        for i in 0..6 {
            let sliding_part = gamma.filter(|_| i < 3).map(|g| g[i]);
            cells.push(Cell::Float(state.map(|x| x[i]).or(sliding_part)));
        }
        for name in INTEGRAL_NAMES {
            let d = s.and_then(|s| s.integrals.get(name));
            cells.extend([
                Cell::Float(d.map(|d| d.initial)),
                Cell::Float(d.map(|d| d.last)),
                Cell::Float(d.map(|d| d.max_rel_drift)),
            ]);
        }
        let e = self.events;
        let q = self.quadrature;
        let period_e = e.and_then(|e| e.period);
        let period_q = q.and_then(|q| q.period);
        let prec_e = e.and_then(|e| e.precession);
        let prec_q = q.and_then(|q| q.precession);
        cells.extend(
            [
                e.map(|e| e.theta_min),
                e.map(|e| e.theta_max),
                period_e,
                period_q,
                difference(period_e, period_q),
                prec_e,
                prec_q,
                difference(prec_e, prec_q),
            ]
            .map(Cell::Float),
        );
        cells.extend(contact_cells(sliding));
        cells
    }
}

/// The cells of [`super::columns::CONTACT_NAMES`], in its order (null without a sliding run).
fn contact_cells(run: Option<&SlidingRun>) -> Vec<Cell> {
    let s = run.map(|r| &r.summary);
    let b = s.map(|s| s.balance);
    let mut cells = vec![Cell::Int(s.map(|s| s.transitions.len() as u64))];
    cells.extend(
        [
            s.map(|s| s.initial_state.height),
            s.map(|s| s.final_state.height),
            b.map(|b| b.height_range[0]),
            b.map(|b| b.height_range[1]),
            run.and_then(|r| r.tilt_final),
            s.map(|s| s.final_state.slip_speed),
            b.map(|b| b.min_normal_force),
            s.map(|s| s.initial_state.jellett),
            b.and_then(|b| b.jellett),
            b.map(|b| b.energy_balance),
            b.map(|b| b.energy_increase),
            s.map(|s| s.final_state.work),
        ]
        .map(Cell::Float),
    );
    cells
}

impl Row {
    /// The row as one line of CSV (without the line break).
    pub fn csv_line(&self, settings: &RunSettings) -> String {
        csv_line(&self.cells(settings))
    }

    /// [`Row::csv_line`] appended to `out`.
    pub fn write_csv_line(&self, settings: &RunSettings, out: &mut String) {
        write_csv_line(&self.cells(settings), out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row has one cell per column of its table, of the column's kind, whatever the columns:
    /// the cells are chosen by their position in [`catalogue`], so a cell missing there would
    /// shift every later one.
    #[test]
    fn a_row_has_a_cell_for_every_column() {
        let row = Row {
            run: 3,
            values: vec![0.5, 4.0],
            status: Status::Failed,
            message: "no run".into(),
            summary: None,
            events: None,
            quadrature: None,
            user_events: vec![],
            sliding: None,
        };
        let settings = |columns| RunSettings {
            t_end: 1.0,
            rtol: 1e-10,
            atol: 1e-10,
            method: "dop853".into(),
            columns,
        };
        let all = settings(Columns::all());
        assert_eq!(row.catalogue_cells(&all).len(), catalogue().len());
        let swept = ["tilt".to_string(), "spin".to_string()];
        for names in [
            &["all"][..],
            &[],
            &["quadrature", "final_M3"],
            &["event1_first_t", "final_M3"],
        ] {
            let chosen = Columns::parse(names.iter().copied())
                .and_then(|c| c.of_events(2))
                .unwrap();
            let cells = row.cells(&settings(chosen));
            let cols = columns(&swept, &chosen);
            assert_eq!(cells.len(), cols.len(), "{names:?}");
            for ((name, kind), cell) in cols.iter().zip(&cells) {
                let same = matches!(
                    (kind, cell),
                    (Kind::Int, Cell::Int(_))
                        | (Kind::Float, Cell::Float(_))
                        | (Kind::Text, Cell::Text(_))
                );
                assert!(same, "{name}: {cell:?}");
            }
        }
    }
}
