//! The dense output of a run, as SciPy's `OdeSolution`: the state at any time of the span.
//!
//! It is the library's [`DenseSolution`]: each step's own continuous extension (DOP853's of
//! order 7, RK4's of order 3) stored at 8 Chebyshev points and evaluated by barycentric
//! interpolation, which reproduces it to round-off. With projection, each value is projected
//! onto the level set of the integrals through the initial state, as the run's samples are.

use crate::ball::Rolling;
use crate::convert::{bad_argument, check_size, columns, times};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use routh_core::motion::FULL_DIM;
use routh_core::problem::{DenseSolution, DENSE_NODES};
use routh_core::projection::LevelSet;
use routh_core::simulate::{project_onto, reduced};

/// The dense solution of the reduced or of the full motion.
#[derive(Clone)]
enum Steps {
    Reduced(DenseSolution<6>),
    Full(DenseSolution<FULL_DIM>),
}

/// The continuous solution of a `simulate` run: call it with a time or an array of times
/// (within `[t_min, t_max]`) to get the state, shape `(n,)` or `(n, len(t))` (n = 6, or 12
/// with `full=True`). Picklable.
#[pyclass(name = "DenseOutput", module = "routh", frozen)]
pub struct DenseOutput {
    body: Rolling,
    /// The state at the start, for the level set of the projection (None: no projection).
    level: Option<[f64; 6]>,
    steps: Steps,
    t_last: f64,
}

/// The flat values of the nodes of `dense`, step by step, node by node.
fn flat_nodes<const N: usize>(dense: &DenseSolution<N>) -> Vec<f64> {
    dense.nodes.iter().flatten().flatten().copied().collect()
}

/// The dense solution of the step boundaries `times` and the flat `nodes`, if they fit.
fn from_flat<const N: usize>(times: Vec<f64>, nodes: &[f64]) -> Option<DenseSolution<N>> {
    let per_step = N * DENSE_NODES;
    if times.len() < 2 || nodes.len() != per_step * (times.len() - 1) {
        return None;
    }
    Some(DenseSolution {
        times,
        nodes: nodes
            .chunks(per_step)
            .map(|c| std::array::from_fn(|j| std::array::from_fn(|k| c[j * N + k])))
            .collect(),
    })
}

impl DenseOutput {
    /// The dense output of a run (its `t_last` may lie inside the last step: a terminal
    /// event); `project`: the run projected onto the level set through its initial state.
    pub fn new<const N: usize>(
        body: Rolling,
        project: bool,
        dense: DenseSolution<N>,
        y0: &[f64; N],
        t_last: f64,
    ) -> Option<Self> {
        // No step (an empty span, or a failure at the first step): the state at t0 alone.
        let dense = if dense.times.is_empty() {
            DenseSolution {
                times: vec![t_last; 2],
                nodes: vec![[*y0; DENSE_NODES]],
            }
        } else {
            dense
        };
        let flat = flat_nodes(&dense);
        let steps = if N == 6 {
            Steps::Reduced(from_flat(dense.times, &flat)?)
        } else {
            Steps::Full(from_flat(dense.times, &flat)?)
        };
        Some(DenseOutput {
            body,
            level: project.then(|| reduced(y0)),
            steps,
            t_last,
        })
    }

    fn times(&self) -> &[f64] {
        match &self.steps {
            Steps::Reduced(d) => &d.times,
            Steps::Full(d) => &d.times,
        }
    }

    fn dim(&self) -> usize {
        match &self.steps {
            Steps::Reduced(_) => 6,
            Steps::Full(_) => FULL_DIM,
        }
    }

    /// The (projected) states at the times `ts`, each within the span.
    fn evaluate<const N: usize>(&self, dense: &DenseSolution<N>, ts: &[f64]) -> Vec<[f64; N]> {
        let level = self.level.map(|x0| LevelSet::through(&self.body, &x0));
        ts.iter()
            .map(|&t| {
                let mut y = dense.at(t).unwrap_or([f64::NAN; N]);
                project_onto(level.as_ref(), &mut y);
                y
            })
            .collect()
    }
}

#[pymethods]
impl DenseOutput {
    /// Rebuild from the pickled fields (used by pickle).
    #[new]
    fn py_new(
        body: &Bound<'_, PyAny>,
        level: Option<[f64; 6]>,
        times: Vec<f64>,
        nodes: Vec<f64>,
        t_last: f64,
    ) -> PyResult<Self> {
        let steps = if let Some(d) = from_flat(times.clone(), &nodes) {
            Steps::Reduced(d)
        } else if let Some(d) = from_flat(times, &nodes) {
            Steps::Full(d)
        } else {
            return Err(bad_argument(
                "nodes",
                "does not hold 8 states of 6 or 12 numbers per step",
            ));
        };
        Ok(DenseOutput {
            body: Rolling::extract("body", body)?,
            level,
            steps,
            t_last,
        })
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let d = slf.get();
        let py = slf.py();
        let nodes = match &d.steps {
            Steps::Reduced(s) => flat_nodes(s),
            Steps::Full(s) => flat_nodes(s),
        };
        let args = (
            d.body.to_object(py)?,
            d.level,
            d.times().to_vec(),
            nodes,
            d.t_last,
        );
        Ok((slf.get_type().into_any(), args.into_pyobject(py)?))
    }

    /// The start of the span.
    #[getter]
    fn t_min(&self) -> f64 {
        self.times()[0].min(self.t_last)
    }

    /// The end of the span.
    #[getter]
    fn t_max(&self) -> f64 {
        self.times()[0].max(self.t_last)
    }

    /// The step ends (SciPy's `OdeSolution.ts`), from the start on.
    #[getter]
    fn ts<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.times())
    }

    /// The states at the step ends, shape `(n, len(ts))`.
    #[getter]
    fn ys<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        match &self.steps {
            Steps::Reduced(d) => columns(py, &self.evaluate(d, &d.times), false),
            Steps::Full(d) => columns(py, &self.evaluate(d, &d.times), false),
        }
    }

    /// The state at `t` (a number or a 1-D array of times within `[t_min, t_max]`).
    fn __call__<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let (ts, single) = times("t", t)?;
        check_size("t", ts.len() as u128, self.dim())?;
        let (lo, hi) = (self.t_min(), self.t_max());
        if let Some(bad) = ts.iter().find(|&&s| s < lo || s > hi) {
            return Err(bad_argument(
                "t",
                format!("{bad} lies outside the span [{lo}, {hi}] of the solution"),
            ));
        }
        match &self.steps {
            Steps::Reduced(d) => {
                let rows = py.detach(|| self.evaluate(d, &ts));
                columns(py, &rows, single)
            }
            Steps::Full(d) => {
                let rows = py.detach(|| self.evaluate(d, &ts));
                columns(py, &rows, single)
            }
        }
    }
}
