//! The class `HamiltonianFlow`: the flows of the Hamiltonian fields X1 = P dH1, X2 = P dH2,
//! Xhat2 = P dK of the first bracket (p-br) by the theta quadrature of section 3.2 (the
//! library's `poisson::flows`, as `routh exact --flow`).

use crate::body::PyBody;
use crate::convert::{
    bad_argument, check_size, columns, phase_point, python_error, states, times, vector,
};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use routh_core::poisson::flows::{vector_field, Condition, Field, Flow};

/// The flow of `flow` (`"X1"`, `"X2"` or `"Xhat2"`) of the first bracket (p-br) with constant
/// `alpha` (finite, nonzero) and beta chosen by `condition` (`"cond"`, `"cond2"` or
/// `"conformal"`), from `x0`, by quadrature (docs/flows.md). Call it with a time or an array of
/// times (any sign) for the state, shape `(6,)` or `(6, len(t))`; `field(x)` is the vector
/// field `P dH` itself (by automatic differentiation), for checks with another integrator.
/// Needs I1 = I2; `ValueError` otherwise, for bad names, or at a singular initial point.
/// Picklable.
#[pyclass(name = "HamiltonianFlow", module = "routh", frozen)]
pub struct PyFlow {
    body: routh_core::Body,
    x0: [f64; 6],
    field: Field,
    condition: Condition,
    alpha: f64,
    inner: Flow,
}

#[pymethods]
impl PyFlow {
    #[new]
    #[pyo3(signature = (body, x0, flow, condition = "cond", alpha = 1.0))]
    fn new(
        py: Python<'_>,
        body: PyRef<'_, PyBody>,
        x0: &Bound<'_, PyAny>,
        flow: &str,
        condition: &str,
        alpha: f64,
    ) -> PyResult<Self> {
        let x0 = phase_point("x0", &vector::<6>("x0", x0)?)?.to_array();
        let field: Field = flow.parse().map_err(|e| bad_argument("flow", e))?;
        let condition: Condition = condition
            .parse()
            .map_err(|e| bad_argument("condition", e))?;
        if !(alpha.is_finite() && alpha != 0.0) {
            return Err(bad_argument(
                "alpha",
                format!("{alpha} must be finite and nonzero"),
            ));
        }
        let body = body.inner;
        let bracket = condition.bracket(body, alpha);
        let inner = py
            .detach(|| Flow::new(bracket, field, &x0))
            .map_err(python_error)?;
        Ok(PyFlow {
            body,
            x0,
            field,
            condition,
            alpha,
            inner,
        })
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let f = slf.get();
        let args = (
            PyBody { inner: f.body },
            f.x0.to_vec(),
            f.field.name(),
            f.condition.name(),
            f.alpha,
        );
        Ok((slf.get_type().into_any(), args.into_pyobject(slf.py())?))
    }

    /// The state `(gamma, M)` at `t` (a number or a 1-D array of times).
    fn __call__<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let (ts, single) = times("t", t)?;
        check_size("t", ts.len() as u128, 6)?;
        let rows: Vec<[f64; 6]> =
            py.detach(|| ts.iter().map(|&t| self.inner.state_at(t)).collect());
        columns(py, &rows, single)
    }

    /// The vector field `P dH` at `x` (`(6,)` or `(6, k)`, finite; not checked for |gamma| = 1).
    fn field<'py>(&self, py: Python<'py>, x: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let (points, single) = states::<6>("x", x)?;
        let bracket = self.inner.bracket;
        let field = self.field;
        let rows: Vec<[f64; 6]> = py.detach(|| {
            points
                .iter()
                .map(|p| vector_field(&bracket, field, p))
                .collect()
        });
        columns(py, &rows, single)
    }

    /// `(theta_min, theta_max)` of the flow, radians.
    #[getter]
    fn theta_range(&self) -> (f64, f64) {
        let [lo, hi] = self.inner.shape().theta;
        (lo, hi)
    }

    /// The period of theta (None when theta is constant).
    #[getter]
    fn period(&self) -> Option<f64> {
        self.inner.shape().period
    }

    /// The advance of phi per period of theta (None when theta is constant).
    #[getter]
    fn precession_advance(&self) -> Option<f64> {
        self.inner.shape().advance
    }

    /// The rate of phi when theta is constant (None otherwise).
    #[getter]
    fn precession_rate(&self) -> Option<f64> {
        self.inner.shape().rate
    }

    /// Jellett's value `b = (M, r)`, a Casimir of the bracket.
    #[getter]
    fn b(&self) -> f64 {
        self.inner.b
    }

    /// The energy H1, constant along the three flows.
    #[getter]
    fn energy(&self) -> f64 {
        self.inner.energy
    }
}
