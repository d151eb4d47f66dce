//! The row of one run and the columns of a sweep's table (the same for CSV, Parquet and
//! JSON).

use crate::integrals::INTEGRAL_NAMES;
use crate::simulate::Summary;
use crate::sweep::turning::NutationEvents;

/// The type of a column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Unsigned integer (run number, step counts).
    Int,
    /// Double, null where it does not apply.
    Float,
    /// Text.
    Text,
}

/// One value of a row.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// An unsigned integer, null for a failed run.
    Int(Option<u64>),
    /// A double, null where it does not apply.
    Float(Option<f64>),
    /// Text.
    Text(String),
}

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

/// The settings shared by every run of a sweep, repeated in each row.
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
    /// The turning points found along the run (None if it failed).
    pub events: Option<NutationEvents>,
    /// The quadrature's nutation (None when the body or the motion does not allow it).
    pub quadrature: Option<NutationQuadrature>,
}

/// The fixed columns after `run` and the swept quantities, with their kinds.
fn fixed_columns() -> Vec<(String, Kind)> {
    let mut cols: Vec<(String, Kind)> = [
        ("t_end", Kind::Float),
        ("rtol", Kind::Float),
        ("atol", Kind::Float),
        ("method", Kind::Text),
        ("status", Kind::Text),
        ("message", Kind::Text),
        ("steps", Kind::Int),
        ("rejected", Kind::Int),
        ("rhs_evals", Kind::Int),
    ]
    .into_iter()
    .map(|(n, k)| (n.to_string(), k))
    .collect();
    for name in STATE_NAMES {
        cols.push((format!("final_{name}"), Kind::Float));
    }
    for name in INTEGRAL_NAMES {
        for part in ["initial", "final", "drift"] {
            cols.push((format!("{name}_{part}"), Kind::Float));
        }
    }
    for name in [
        "theta_min",
        "theta_max",
        "period_events",
        "period_quadrature",
        "period_difference",
        "precession_events",
        "precession_quadrature",
        "precession_difference",
    ] {
        cols.push((name.to_string(), Kind::Float));
    }
    cols
}

const STATE_NAMES: [&str; 6] = ["gamma1", "gamma2", "gamma3", "M1", "M2", "M3"];

/// The columns of a sweep whose swept quantities are `swept`: `run`, the swept quantities
/// (named as in `[sweep]`), the settings, status and message, the work, the final state,
/// each integral's initial and final value and maximal relative drift (null where not an
/// integral), and the nutation from events and from the quadrature.
pub fn columns(swept: &[String]) -> Vec<(String, Kind)> {
    let mut cols = vec![("run".to_string(), Kind::Int)];
    cols.extend(swept.iter().map(|n| (n.clone(), Kind::Float)));
    cols.extend(fixed_columns());
    cols
}

/// `a - b` when both exist.
fn difference(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    Some(a? - b?)
}

impl Row {
    /// The row's cells, in the order of [`columns`].
    pub fn cells(&self, settings: &RunSettings) -> Vec<Cell> {
        let mut cells = vec![Cell::Int(Some(self.run))];
        cells.extend(self.values.iter().map(|v| Cell::Float(Some(*v))));
        cells.extend([
            Cell::Float(Some(settings.t_end)),
            Cell::Float(Some(settings.rtol)),
            Cell::Float(Some(settings.atol)),
            Cell::Text(settings.method.clone()),
            Cell::Text(self.status.as_str().to_string()),
            Cell::Text(self.message.clone()),
        ]);
        let s = self.summary.as_ref();
        for count in [
            s.map(|s| s.steps),
            s.map(|s| s.rejected),
            s.map(|s| s.rhs_evals),
        ] {
            cells.push(Cell::Int(count.map(|c| c as u64)));
        }
        let state = s.map(|s| s.final_state.to_array());
        for i in 0..6 {
            cells.push(Cell::Float(state.map(|x| x[i])));
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
        cells
    }
}

impl Row {
    /// The row as one line of CSV (without the line break).
    pub fn csv_line(&self, settings: &RunSettings) -> String {
        let cells: Vec<String> = self.cells(settings).iter().map(Cell::to_csv).collect();
        cells.join(",")
    }
}

impl Cell {
    /// The cell as a JSON value (null for a missing number).
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            Cell::Int(v) => v.map_or(serde_json::Value::Null, Into::into),
            Cell::Float(v) => v
                .and_then(serde_json::Number::from_f64)
                .map_or(serde_json::Value::Null, serde_json::Value::Number),
            Cell::Text(s) => s.clone().into(),
        }
    }

    /// The cell as CSV text: numbers in the shortest form that reads back to the same f64,
    /// empty for null, text quoted when it holds a comma, a quote or a line break.
    pub fn to_csv(&self) -> String {
        match self {
            Cell::Int(v) => v.map(|v| v.to_string()).unwrap_or_default(),
            Cell::Float(v) => v.map(|v| v.to_string()).unwrap_or_default(),
            Cell::Text(s) if s.contains([',', '"', '\n', '\r']) => {
                format!("\"{}\"", s.replace('"', "\"\"").replace(['\n', '\r'], " "))
            }
            Cell::Text(s) => s.clone(),
        }
    }
}
