//! The stationary motions of the Routh sphere (the library's `steady`): the vertical spins with
//! Routh's threshold and the steady precessions at constant tilt, each with its stability
//! judged twice (the double root of Q, the eigenvalues of the Jacobian).

use crate::body::PyBody;
use crate::convert::{python_error, record};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use routh_core::steady::{
    routh_threshold as threshold, steady_precessions as precessions, vertical_spin as spin_at,
};
use routh_core::State;

/// A record of the library as a dict (the keys of `routh steady --json`), with the state also
/// as the numpy 6-vector `x`.
fn with_state<'py>(
    py: Python<'py>,
    value: &impl serde::Serialize,
    state: &State,
) -> PyResult<Bound<'py, PyAny>> {
    let dict = record(py, value)?;
    dict.cast::<PyDict>()?
        .set_item("x", PyArray1::from_slice(py, &state.to_array()))?;
    Ok(dict)
}

/// The vertical spin at `gamma3 = pole` (+1 or -1) with spin rate `spin` (omega3, rad per unit
/// time) for a Routh sphere (I1 = I2), as a dict: `gamma3`, `centre_of_mass_above`, `spin`,
/// `threshold_spin` (Routh's |omega3| above which it is stable; 0 when the centre of mass is
/// not above the geometric centre or G = 0), `routh_threshold` (the same, None where there is
/// none) and `no_threshold` (why), `stability` (`q_second_derivative`, `stable_by_q`,
/// `max_real_eigenvalue`, `stable_by_jacobian`), `verdict` (`decision`: stable, unstable or
/// undecided within the accuracy; `q_accuracy`, `eigenvalue_tolerance`), `state` and `x`.
#[pyfunction]
pub fn vertical_spin<'py>(
    py: Python<'py>,
    body: PyRef<'py, PyBody>,
    pole: f64,
    spin: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let body = body.inner;
    let v = py
        .detach(|| spin_at(&body, pole, spin))
        .map_err(python_error)?;
    with_state(py, &v, &v.state)
}

/// The steady precessions at tilt `theta` (radians, in (0, pi)) with spin rate `spin` for a
/// Routh sphere: a list of zero, one or two dicts with `theta`, `spin`, `omega_t` (the
/// component of omega along the horizontal projection of gamma) and `omega_t_accuracy`,
/// `precession` (d psi/dt of gamma about e3 in the body), `axis_precession` (d phi/dt of the
/// symmetry axis about the upward vertical in space), `stability` and `verdict` (as in
/// `vertical_spin`), `state` and `x`.
#[pyfunction]
pub fn steady_precessions<'py>(
    py: Python<'py>,
    body: PyRef<'py, PyBody>,
    theta: f64,
    spin: f64,
) -> PyResult<Bound<'py, PyList>> {
    let body = body.inner;
    let list = PyList::empty(py);
    for p in py
        .detach(|| precessions(&body, theta, spin))
        .map_err(python_error)?
    {
        list.append(with_state(py, &p, &p.state)?)?;
    }
    Ok(list)
}

/// Routh's threshold spin rate for the vertical spin at `gamma3 = pole`:
/// `sqrt(4 m G a p (A + m l^2)) / (C + m R l)`, `l = R + a p`, when `a p > 0`; else 0.
#[pyfunction]
pub fn routh_threshold(body: PyRef<'_, PyBody>, pole: f64) -> PyResult<f64> {
    if pole.abs() != 1.0 {
        return Err(python_error(routh_core::RouthError::Option {
            name: "pole",
            value: pole.to_string(),
            rule: "must be +1 or -1",
        }));
    }
    Ok(threshold(&body.inner, pole))
}
