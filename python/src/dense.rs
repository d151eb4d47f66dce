//! The dense output of a run, as SciPy's `OdeSolution`: the state at any time of the span.
//!
//! It keeps the step ends of the run (after projection) and, to evaluate at `t`, takes again
//! the step that covers `t` from its stored start with the stored size: the integrators are
//! deterministic, so this is the same step and its continuous extension (DOP853's of order 7,
//! or the RK4 step of partial length) is the one the run used for its samples. Storage is one
//! state per step; an evaluation costs one step (about 15 evaluations of the field), shared by
//! all the requested times that fall in the same step.

use crate::body::PyBody;
use crate::convert::{bad_argument, check_size, columns, times};
use crate::drive::Projector;
use crate::stepper::Stepper;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use routh_core::integrate::{Method, OdeSystem};
use routh_core::motion::{FullMotion, FULL_DIM};
use routh_core::simulate::ReducedSystem;
use routh_core::Body;

/// The continuous solution of a `simulate` run: call it with a time or an array of times
/// (within `[t_min, t_max]`) to get the state, shape `(n,)` or `(n, len(t))` (n = 6, or 12
/// with `full=True`). Picklable.
#[pyclass(name = "DenseOutput", module = "routh", frozen)]
pub struct DenseOutput {
    body: routh_core::Body,
    method: Method,
    rtol: f64,
    atol: f64,
    /// The state at the start, for the level set of the projection (None: no projection).
    level: Option<Vec<f64>>,
    dim: usize,
    /// Step ends from the start on.
    knots_t: Vec<f64>,
    /// The states there, `dim` numbers each.
    knots_y: Vec<f64>,
    t_last: f64,
}

impl DenseOutput {
    /// The dense output of a run's knots; `t_last` may lie inside the last step (a terminal
    /// event).
    #[allow(clippy::too_many_arguments)]
    pub fn new<const N: usize>(
        body: Body,
        method: Method,
        rtol: f64,
        atol: f64,
        level: Option<&[f64; N]>,
        knots: &[(f64, [f64; N])],
        t_last: f64,
    ) -> Self {
        DenseOutput {
            body,
            method,
            rtol,
            atol,
            level: level.map(|y| y.to_vec()),
            dim: N,
            knots_t: knots.iter().map(|k| k.0).collect(),
            knots_y: knots.iter().flat_map(|k| k.1).collect(),
            t_last,
        }
    }

    fn knot<const N: usize>(&self, i: usize) -> [f64; N] {
        std::array::from_fn(|j| self.knots_y[i * N + j])
    }

    /// The states at the sorted-or-not times `ts` (each within the span).
    fn evaluate<S: OdeSystem<N>, const N: usize>(&self, sys: &S, ts: &[f64]) -> Vec<[f64; N]> {
        let projector = Projector::new(
            &self.body,
            self.level.as_deref().unwrap_or(&[0.0; 6]),
            self.level.is_some(),
        );
        let t0 = self.knots_t[0];
        let dir = if self.t_last >= t0 { 1.0 } else { -1.0 };
        let mut current: Option<(usize, Stepper<'_, N>)> = None;
        ts.iter()
            .map(|&t| {
                // The step i covers [knots_t[i], knots_t[i + 1]] in the direction of time.
                let after = self.knots_t.partition_point(|&k| (k - t) * dir < 0.0);
                if after == 0 || self.knots_t.len() == 1 {
                    return self.knot(0);
                }
                if after < self.knots_t.len() && self.knots_t[after] == t {
                    return self.knot(after);
                }
                let i = (after - 1).min(self.knots_t.len() - 2);
                // The step of a previous time serves if it is step i taken whole (as always,
                // unless the controller rejected the stored size: then start again for t).
                let reusable =
                    matches!(&current, Some((j, s)) if *j == i && s.t() == self.knots_t[i + 1]);
                if !reusable {
                    let (ta, tb) = (self.knots_t[i], self.knots_t[i + 1]);
                    // One RK4 step of the stored size, or the DOP853 step of that size.
                    let method = match self.method {
                        Method::Rk4 { .. } => Method::Rk4 { steps: 1 },
                        other => other,
                    };
                    let stepper = Stepper::new(
                        sys,
                        method,
                        ta,
                        self.knot(i),
                        tb,
                        self.rtol,
                        self.atol,
                        Some(tb - ta),
                    );
                    current = stepper.ok().and_then(|mut s| {
                        while (s.t() - t) * dir < 0.0 && s.step().is_ok_and(|done| !done) {}
                        // A step that failed again leaves no extension covering t.
                        ((s.t() - t) * dir >= 0.0).then_some((i, s))
                    });
                }
                match &mut current {
                    Some((_, s)) => projector.apply(s.dense(t)),
                    None => [f64::NAN; N],
                }
            })
            .collect()
    }
}

#[pymethods]
impl DenseOutput {
    /// Rebuild from the pickled fields (used by pickle).
    #[new]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        body: PyRef<'_, PyBody>,
        method: &str,
        rtol: f64,
        atol: f64,
        level: Option<Vec<f64>>,
        knots_t: Vec<f64>,
        knots_y: Vec<f64>,
        t_last: f64,
    ) -> PyResult<Self> {
        let method: Method = method.parse().map_err(|e| bad_argument("method", e))?;
        let dim = knots_y.len() / knots_t.len().max(1);
        if knots_t.is_empty()
            || knots_y.len() != dim * knots_t.len()
            || !(dim == 6 || dim == FULL_DIM)
        {
            return Err(bad_argument(
                "knots_y",
                "does not hold 6 or 12 numbers per knot",
            ));
        }
        Ok(DenseOutput {
            body: body.inner,
            method,
            rtol,
            atol,
            level,
            dim,
            knots_t,
            knots_y,
            t_last,
        })
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let d = slf.get();
        let py = slf.py();
        let args = (
            PyBody { inner: d.body },
            d.method.to_string(),
            d.rtol,
            d.atol,
            d.level.clone(),
            d.knots_t.clone(),
            d.knots_y.clone(),
            d.t_last,
        );
        Ok((slf.get_type().into_any(), args.into_pyobject(py)?))
    }

    /// The start of the span.
    #[getter]
    fn t_min(&self) -> f64 {
        self.knots_t[0].min(self.t_last)
    }

    /// The end of the span.
    #[getter]
    fn t_max(&self) -> f64 {
        self.knots_t[0].max(self.t_last)
    }

    /// The step ends (SciPy's `OdeSolution.ts`), from the start on.
    #[getter]
    fn ts<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.knots_t)
    }

    /// The states at the step ends, shape `(n, len(ts))`.
    #[getter]
    fn ys<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let (k, dim) = (self.knots_t.len(), self.dim);
        let flat: Vec<f64> = (0..dim)
            .flat_map(|j| (0..k).map(move |i| self.knots_y[i * dim + j]))
            .collect();
        PyArray1::from_vec(py, flat).reshape([dim, k])
    }

    /// The state at `t` (a number or a 1-D array of times within `[t_min, t_max]`).
    fn __call__<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let (ts, single) = times("t", t)?;
        check_size("t", ts.len() as u128, self.dim)?;
        let (lo, hi) = (self.t_min(), self.t_max());
        if let Some(bad) = ts.iter().find(|&&s| s < lo || s > hi) {
            return Err(bad_argument(
                "t",
                format!("{bad} lies outside the span [{lo}, {hi}] of the solution"),
            ));
        }
        let body = self.body;
        if self.dim == 6 {
            let rows = py.detach(|| self.evaluate(&ReducedSystem(&body), &ts));
            columns(py, &rows, single)
        } else {
            let rows = py.detach(|| self.evaluate::<_, FULL_DIM>(&FullMotion { body: &body }, &ts));
            columns(py, &rows, single)
        }
    }
}
