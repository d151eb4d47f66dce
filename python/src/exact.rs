//! The class `ExactSolution`: the motion of the Routh sphere by quadrature (the library's
//! `quadrature::ExactSolution`), the state at any array of times.

use crate::body::PyBody;
use crate::convert::{check_size, columns, phase_point, python_error, times, vector};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use routh_core::quadrature::{ExactSolution, Motion};
use routh_core::State;

/// Times evaluated between two checks for Ctrl-C (a state costs about a microsecond).
const CHUNK: usize = 1 << 16;

/// The exact solution of (mg-eq) through `x0` for a Routh sphere (I1 = I2), by quadrature:
/// with the energy H1, Jellett's H3 and Routh's K fixed, the tilt `gamma3 = cos theta`
/// nutates between two turning points with period `period`, and the whole state is periodic up
/// to a rotation about e3 by `precession_advance` per period (`docs/quadrature.md`). Call it
/// with a time or an array of times (any real numbers, also negative; the cost does not grow
/// with t) to get the state, shape `(6,)` or `(6, len(t))`, as `Solution.sol`.
///
/// `ValueError` for I1 != I2, an invalid `x0`, or a motion on a separatrix (where the period
/// diverges). Angles in radians, times in the units of the body. Picklable (rebuilt from
/// `body` and `x0`).
#[pyclass(name = "ExactSolution", module = "routh", frozen)]
pub struct PyExact {
    x0: State,
    inner: ExactSolution,
}

#[pymethods]
impl PyExact {
    #[new]
    fn new(py: Python<'_>, body: PyRef<'_, PyBody>, x0: &Bound<'_, PyAny>) -> PyResult<Self> {
        let x0 = phase_point("x0", &vector::<6>("x0", x0)?)?;
        let body = body.inner;
        let inner = py
            .detach(|| ExactSolution::new(&body, &x0))
            .map_err(python_error)?;
        Ok(PyExact { x0, inner })
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let e = slf.get();
        let args = (
            PyBody {
                inner: e.inner.body,
            },
            e.x0.to_array().to_vec(),
        );
        Ok((slf.get_type().into_any(), args.into_pyobject(slf.py())?))
    }

    /// The state at `t` (a number or a 1-D array of times).
    fn __call__<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let (ts, single) = times("t", t)?;
        check_size("t", ts.len() as u128, 6)?;
        let mut rows = Vec::with_capacity(ts.len());
        for chunk in ts.chunks(CHUNK) {
            py.detach(|| rows.extend(chunk.iter().map(|&t| self.inner.state_at(t).to_array())));
            py.check_signals()?;
        }
        columns(py, &rows, single)
    }

    /// The body.
    #[getter]
    fn body(&self) -> PyBody {
        PyBody {
            inner: self.inner.body,
        }
    }

    /// The initial state.
    #[getter]
    fn x0<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.x0.to_array())
    }

    /// `"steady"` (constant tilt, a double root of Q, or the vertical spin) or `"nutation"`.
    #[getter]
    fn motion(&self) -> &'static str {
        match self.inner.motion {
            Motion::Steady { .. } => "steady",
            Motion::Nutation(_) => "nutation",
        }
    }

    /// The turning points `(gamma3_min, gamma3_max)` of gamma3 = cos theta (equal for a steady
    /// motion).
    #[getter]
    fn turning_points(&self) -> (f64, f64) {
        self.inner.turning_points()
    }

    /// The range `(theta_min, theta_max)` of the tilt theta in radians.
    #[getter]
    fn theta_range(&self) -> (f64, f64) {
        let (u_min, u_max) = self.inner.turning_points();
        (u_max.clamp(-1.0, 1.0).acos(), u_min.clamp(-1.0, 1.0).acos())
    }

    /// The nutation period T (None for a steady motion).
    #[getter]
    fn period(&self) -> Option<f64> {
        self.inner.period()
    }

    /// The advance of the precession angle psi (the rotation of the state about e3) per
    /// period, radians (None for a steady motion).
    #[getter]
    fn precession_advance(&self) -> Option<f64> {
        match &self.inner.motion {
            Motion::Steady { .. } => None,
            Motion::Nutation(n) => Some(n.advance),
        }
    }

    /// The mean precession rate d psi/dt (radians per unit time): the constant rate of a steady
    /// motion, `precession_advance / period` for a nutation.
    #[getter]
    fn precession_rate(&self) -> f64 {
        match &self.inner.motion {
            Motion::Steady { precession, .. } => *precession,
            Motion::Nutation(n) => n.advance / n.period,
        }
    }

    /// Whether the motion passes through the symmetry axis (a turning point is a pole).
    #[getter]
    fn passes_through_axis(&self) -> bool {
        match &self.inner.motion {
            Motion::Steady { .. } => false,
            Motion::Nutation(n) => n.through_top || n.through_bottom,
        }
    }

    /// Chebyshev nodes of the series of one period (None for a steady motion).
    #[getter]
    fn nodes(&self) -> Option<usize> {
        match &self.inner.motion {
            Motion::Steady { .. } => None,
            Motion::Nutation(n) => Some(n.nodes),
        }
    }

    /// The integrals that fix the motion, `{H1, H3, K}`.
    #[getter]
    fn integrals<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let red = &self.inner.reduction;
        let dict = PyDict::new(py);
        dict.set_item("H1", red.h1())?;
        dict.set_item("H3", red.h3())?;
        dict.set_item("K", red.k())?;
        Ok(dict)
    }

    fn __repr__(&self) -> String {
        let period = self
            .period()
            .map_or("None".to_string(), |p| format!("{p:?}"));
        format!(
            "ExactSolution(motion={:?}, turning_points={:?}, period={period})",
            self.motion(),
            self.turning_points(),
        )
    }
}
