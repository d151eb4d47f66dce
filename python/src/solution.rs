//! The class `Solution`: what `simulate` returns, with the attributes of SciPy's `solve_ivp`
//! result and the library's work counters and drift of the integrals.

use crate::convert::columns;
use crate::dense::DenseOutput;
use crate::drive::Run;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use routh_core::ball::AsBall;
use routh_core::motion::{full_columns, FULL_DIM};
use routh_core::problem::Status;

/// The result of `simulate` (as SciPy's `solve_ivp`): `t` (shape `(k,)`), `y` (shape `(n, k)`,
/// n = 6 for `(gamma, M)`, 12 with `full=True` for `(gamma, M, q, x, y)`), `sol` (a
/// `DenseOutput`, or `None` unless `dense_output=True`), `t_events` and `y_events` (one array
/// per event, shapes `(j,)` and `(j, n)`), `nfev` (evaluations of the field), `njev = nlu = 0`,
/// `status` (0: end of the span reached, 1: a terminal event, -1: the integrator failed),
/// `message`, `success` (`status >= 0`); and `steps`, `rejected`, `method`, `projected`,
/// `elapsed_s` (seconds of the integration), `integrals` (`{name: {initial, final,
/// max_rel_drift}}` over step ends and samples), `t_span`, `y0`, `y_final`, and `space`
/// (with `full=True`: `q` `(4, k)` the orientation quaternion body-to-space, `com` `(3, k)`
/// the centre of mass in space, `contact` `(2, k)` the contact point on the plane; else
/// `None`). Picklable. For the keys of the dict returned by earlier versions, `result[key]`
/// still works (`"x"` is `y.T`, `"rhs_evals"` is `nfev`, `"initial_state"`, `"final_state"`,
/// `"t_end"`).
#[pyclass(name = "Solution", module = "routh", frozen, get_all)]
pub struct Solution {
    t: Py<PyAny>,
    y: Py<PyAny>,
    sol: Py<PyAny>,
    t_events: Py<PyAny>,
    y_events: Py<PyAny>,
    nfev: usize,
    njev: usize,
    nlu: usize,
    status: i32,
    message: String,
    success: bool,
    steps: usize,
    rejected: usize,
    method: String,
    projected: bool,
    elapsed_s: f64,
    integrals: Py<PyAny>,
    t_span: (f64, f64),
    y0: Py<PyAny>,
    y_final: Py<PyAny>,
    space: Py<PyAny>,
}

/// Rows as a numpy array of shape `(k, N)` (SciPy's `y_events`).
fn rows<'py, const N: usize>(
    py: Python<'py>,
    rows: &[[f64; N]],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    PyArray1::from_vec(py, flat).reshape([rows.len(), N])
}

/// The space columns of the full motion at the samples: `q`, `com`, `contact`.
fn space<'py>(
    py: Python<'py>,
    body: &impl AsBall,
    ys: &[[f64; FULL_DIM]],
) -> PyResult<Bound<'py, PyDict>> {
    let cols: Vec<[f64; 9]> = ys.iter().map(|y| full_columns(body, y)).collect();
    let pick = |range: std::ops::Range<usize>| -> Vec<f64> {
        range.flat_map(|i| cols.iter().map(move |c| c[i])).collect()
    };
    let k = cols.len();
    let dict = PyDict::new(py);
    dict.set_item("q", PyArray1::from_vec(py, pick(0..4)).reshape([4, k])?)?;
    dict.set_item("com", PyArray1::from_vec(py, pick(4..7)).reshape([3, k])?)?;
    dict.set_item(
        "contact",
        PyArray1::from_vec(py, pick(7..9)).reshape([2, k])?,
    )?;
    Ok(dict)
}

impl Solution {
    /// The Python result of a run.
    #[allow(clippy::too_many_arguments)]
    pub fn from_run<const N: usize>(
        py: Python<'_>,
        body: &impl AsBall,
        run: Run<N>,
        method: String,
        projected: bool,
        t_span: (f64, f64),
        y0: [f64; N],
        sol: Option<DenseOutput>,
    ) -> PyResult<Self> {
        let (status, message) = match (run.status, &run.failure) {
            (Status::Failed, m) => (
                -1,
                format!("integration failed: {}", m.as_deref().unwrap_or_default()),
            ),
            (Status::Event, _) => (1, "A termination event occurred.".to_string()),
            (Status::Reached, _) => (
                0,
                "The solver successfully reached the end of the integration interval.".to_string(),
            ),
        };
        let integrals = PyDict::new(py);
        for (name, d) in &run.drift {
            let entry = PyDict::new(py);
            entry.set_item("initial", d.initial)?;
            entry.set_item("final", d.last)?;
            entry.set_item("max_rel_drift", d.max_rel_drift)?;
            integrals.set_item(*name, entry)?;
        }
        let t_events = PyList::empty(py);
        for t in &run.t_events {
            t_events.append(PyArray1::from_slice(py, t))?;
        }
        let y_events = PyList::empty(py);
        for y in &run.y_events {
            y_events.append(rows(py, y)?)?;
        }
        let space = if N == FULL_DIM {
            let full: Vec<[f64; FULL_DIM]> = run
                .y
                .iter()
                .map(|y| std::array::from_fn(|i| y[i]))
                .collect();
            space(py, body, &full)?.into_any().unbind()
        } else {
            py.None()
        };
        let y = if run.y.is_empty() {
            PyArray2::<f64>::zeros(py, [N, 0], false).into_any()
        } else {
            columns(py, &run.y, false)?
        };
        Ok(Solution {
            t: PyArray1::from_slice(py, &run.t).into_any().unbind(),
            y: y.unbind(),
            sol: match sol {
                Some(d) => Py::new(py, d)?.into_any(),
                None => py.None(),
            },
            t_events: t_events.into_any().unbind(),
            y_events: y_events.into_any().unbind(),
            nfev: run.stats.rhs_evals,
            njev: 0,
            nlu: 0,
            status,
            message,
            success: status >= 0,
            steps: run.stats.steps,
            rejected: run.stats.rejected,
            method,
            projected,
            elapsed_s: run.elapsed_s,
            integrals: integrals.into_any().unbind(),
            t_span,
            y0: PyArray1::from_slice(py, &y0).into_any().unbind(),
            y_final: PyArray1::from_slice(py, &run.y_last).into_any().unbind(),
            space,
        })
    }
}

#[pymethods]
impl Solution {
    /// Rebuild from the pickled fields, in the order of `__reduce__` (used by pickle).
    #[new]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        t: Py<PyAny>,
        y: Py<PyAny>,
        sol: Py<PyAny>,
        t_events: Py<PyAny>,
        y_events: Py<PyAny>,
        nfev: usize,
        status: i32,
        message: String,
        steps: usize,
        rejected: usize,
        method: String,
        projected: bool,
        elapsed_s: f64,
        integrals: Py<PyAny>,
        t_span: (f64, f64),
        y0: Py<PyAny>,
        y_final: Py<PyAny>,
        space: Py<PyAny>,
    ) -> Self {
        Solution {
            t,
            y,
            sol,
            t_events,
            y_events,
            nfev,
            njev: 0,
            nlu: 0,
            status,
            message,
            success: status >= 0,
            steps,
            rejected,
            method,
            projected,
            elapsed_s,
            integrals,
            t_span,
            y0,
            y_final,
            space,
        }
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let s = slf.get();
        let py = slf.py();
        let items: Vec<Bound<'py, PyAny>> = vec![
            s.t.bind(py).clone(),
            s.y.bind(py).clone(),
            s.sol.bind(py).clone(),
            s.t_events.bind(py).clone(),
            s.y_events.bind(py).clone(),
            s.nfev.into_pyobject(py)?.into_any(),
            s.status.into_pyobject(py)?.into_any(),
            s.message.clone().into_pyobject(py)?.into_any(),
            s.steps.into_pyobject(py)?.into_any(),
            s.rejected.into_pyobject(py)?.into_any(),
            s.method.clone().into_pyobject(py)?.into_any(),
            s.projected.into_pyobject(py)?.to_owned().into_any(),
            s.elapsed_s.into_pyobject(py)?.into_any(),
            s.integrals.bind(py).clone(),
            s.t_span.into_pyobject(py)?.into_any(),
            s.y0.bind(py).clone(),
            s.y_final.bind(py).clone(),
            s.space.bind(py).clone(),
        ];
        Ok((slf.get_type().into_any(), PyTuple::new(py, items)?))
    }

    /// The keys of the dict that `simulate` returned before this class existed.
    fn __getitem__<'py>(slf: &Bound<'py, Self>, key: &str) -> PyResult<Bound<'py, PyAny>> {
        let py = slf.py();
        let s = slf.get();
        match key {
            "t" => Ok(s.t.bind(py).clone()),
            "x" => s.y.bind(py).getattr("T"),
            "rhs_evals" => Ok(s.nfev.into_pyobject(py)?.into_any()),
            "initial_state" => Ok(s.y0.bind(py).clone()),
            "final_state" => Ok(s.y_final.bind(py).clone()),
            "t_end" => Ok(s.t_span.1.into_pyobject(py)?.into_any()),
            "steps" | "rejected" | "projected" | "elapsed_s" | "integrals" | "method" => {
                slf.getattr(key)
            }
            _ => Err(PyKeyError::new_err(key.to_string())),
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "Solution(status={}, message={:?}, t_span={:?}, nfev={}, steps={})",
            self.status, self.message, self.t_span, self.nfev, self.steps
        )
    }
}
