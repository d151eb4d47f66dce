//! `routh.sweep`: the runs of a case's `[sweep]` table (all, or the slice `start:stop`, so
//! that a sweep can be split into chunks for Dask or another engine), as a pyarrow Table
//! with the columns of `routh sweep`, computed with the GIL released.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};
use routh_core::case::Overrides;
use routh_core::integrate::Method;
use routh_core::row::{Cell, Kind};
use routh_core::surface::parse_event;
use routh_core::sweep::{Columns, Sweep};
use std::path::PathBuf;

/// `sweep(path=None, *, text=None, t_end=None, rtol=None, atol=None, method="auto",
/// threads=None, start=0, stop=None, columns=None, events=None)`: run the runs `start <= run < stop` of the
/// sweep in the case file `path` (or the case text `text`), in parallel on `threads` threads
/// (default: one per core), and return a `pyarrow.Table`, one row per run in the order of
/// `run` (call `.to_pandas()` for a DataFrame). `columns` (a list of names and groups, as
/// `routh sweep --columns`: `"final"`, `"integrals"`, `"events"`, `"quadrature"`,
/// `"nutation"`, `"all"`, or single columns) chooses the columns, and only what they need is
/// computed; default: the `[sweep]` table's `columns`, else `["final", "integrals",
/// "user_events"]`. `events` (a list of planes with an optional direction, as `routh sweep
/// --events`: `["gamma3 = 0.9", "M1 = 0.5 up"]`) are the user's events, whose crossings
/// along each run are counted (`event{k}_count`, `event{k}_first_t`, group `user_events`);
/// default: the `[sweep]` table's `events`, else none. The schema's metadata holds the case text
/// (`routh.case`) and the version (`routh.version`). `method="auto"` (the default) runs the
/// sweep's own choice, as `routh sweep` does (the Taylor lanes). Every run gives the numbers of
/// `routh simulate` on its case, whatever the thread count or the slicing.
#[pyfunction]
#[pyo3(signature = (path=None, *, text=None, t_end=None, rtol=None, atol=None, method="auto", threads=None, start=0, stop=None, columns=None, events=None))]
#[allow(clippy::too_many_arguments)]
pub fn sweep<'py>(
    py: Python<'py>,
    path: Option<PathBuf>,
    text: Option<String>,
    t_end: Option<f64>,
    rtol: Option<f64>,
    atol: Option<f64>,
    method: &str,
    threads: Option<usize>,
    start: u64,
    stop: Option<u64>,
    columns: Option<Vec<String>>,
    events: Option<Vec<String>>,
) -> PyResult<Bound<'py, PyAny>> {
    let (text, source) = match (path, text) {
        (Some(p), None) => (
            std::fs::read_to_string(&p).map_err(|e| {
                pyo3::exceptions::PyOSError::new_err(format!("{}: {e}", p.display()))
            })?,
            p.display().to_string(),
        ),
        (None, Some(t)) => (t, "<text>".to_string()),
        _ => {
            return Err(PyValueError::new_err(
                "give exactly one of `path` (a case file) and `text` (its contents)",
            ))
        }
    };
    let method: Method = method
        .parse()
        .map_err(|e: routh_core::integrate::ParseMethodError| {
            PyValueError::new_err(e.to_string())
        })?;
    let columns = columns
        .map(|names| Columns::parse(names.iter().map(String::as_str)))
        .transpose()
        .map_err(|e| PyValueError::new_err(format!("columns: {e}")))?;
    let events = events
        .map(|texts| {
            texts
                .iter()
                .map(|text| parse_event(text, "events"))
                .collect::<Result<Vec<_>, _>>()
        })
        .transpose()
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    let overrides = Overrides {
        method: Some(method),
        t_end,
        rtol,
        atol,
        max_steps: None,
    };
    if threads == Some(0) {
        return Err(PyValueError::new_err("threads must be >= 1"));
    }
    let (names, rows, settings, case_text) = py
        .detach(|| -> Result<_, String> {
            let sweep = Sweep::for_runs(&text, &source, overrides, columns, events, start, stop)
                .map_err(|e| e.to_string())?;
            let stop = stop.unwrap_or(sweep.runs());
            let rows = sweep
                .rows(start, stop, threads.unwrap_or(0))
                .map_err(|e| e.to_string())?;
            Ok((
                sweep.table_columns(),
                rows,
                sweep.run_settings(),
                sweep.case_text.clone(),
            ))
        })
        .map_err(PyValueError::new_err)?;
    let pa = py.import("pyarrow").map_err(|e| {
        PyRuntimeError::new_err(format!(
            "routh.sweep needs pyarrow (pip install pyarrow): {e}"
        ))
    })?;
    let cells: Vec<Vec<Cell>> = rows.iter().map(|r| r.cells(&settings)).collect();
    let arrays = PyList::empty(py);
    let mut labels = Vec::with_capacity(names.len());
    for (i, (name, kind)) in names.into_iter().enumerate() {
        let array = match kind {
            // Numbers go to Arrow as one buffer of little-endian values per column (a Python
            // object per cell cost more than the sweep itself at 10^5 runs).
            Kind::Int | Kind::Float => {
                let mut bytes = Vec::with_capacity(8 * cells.len());
                let mut valid = vec![0u8; cells.len().div_ceil(8)];
                let mut nulls = 0;
                for (j, row) in cells.iter().enumerate() {
                    let value = match &row[i] {
                        Cell::Int(v) => v.map(u64::to_le_bytes),
                        Cell::Float(v) => v.map(f64::to_le_bytes),
                        Cell::Text(_) => {
                            return Err(PyRuntimeError::new_err(format!(
                                "internal error: text in the numeric column {name}"
                            )))
                        }
                    };
                    match value {
                        Some(v) => {
                            bytes.extend_from_slice(&v);
                            valid[j / 8] |= 1 << (j % 8);
                        }
                        None => {
                            bytes.extend_from_slice(&[0; 8]);
                            nulls += 1;
                        }
                    }
                }
                let arrow_type = if kind == Kind::Int {
                    pa.call_method0("uint64")?
                } else {
                    pa.call_method0("float64")?
                };
                let buffer = |b: &[u8]| pa.call_method1("py_buffer", (PyBytes::new(py, b),));
                let validity = if nulls == 0 {
                    py.None().into_bound(py)
                } else {
                    buffer(&valid)?
                };
                let buffers = PyList::new(py, [validity, buffer(&bytes)?])?;
                pa.getattr("Array")?
                    .call_method1("from_buffers", (arrow_type, cells.len(), buffers, nulls))?
            }
            Kind::Text => {
                let values = PyList::empty(py);
                for row in &cells {
                    match &row[i] {
                        Cell::Text(s) => values.append(s)?,
                        Cell::Int(v) => values.append(*v)?,
                        Cell::Float(v) => values.append(*v)?,
                    }
                }
                let kwargs = PyDict::new(py);
                kwargs.set_item("type", pa.call_method0("string")?)?;
                pa.call_method("array", (values,), Some(&kwargs))?
            }
        };
        arrays.append(array)?;
        labels.push(name);
    }
    let metadata = PyDict::new(py);
    metadata.set_item("routh.case", case_text)?;
    metadata.set_item("routh.version", env!("CARGO_PKG_VERSION"))?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("names", labels)?;
    kwargs.set_item("metadata", metadata)?;
    pa.getattr("Table")?
        .call_method("from_arrays", (arrays,), Some(&kwargs))
}
