//! The Lyapunov exponents of a ball on |gamma| = 1 (the library's `lyapunov`, the JSON of
//! `routh lyapunov`).

use crate::ball::Rolling;
use crate::convert::{phase_point, python_error, record, vector};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use routh_core::integrate::{Method, ParseMethodError};
use routh_core::lyapunov::{report, LyapunovSettings};
use routh_core::simulate::Settings;

/// The five Lyapunov exponents of the motion of `body` (a `Body` or a `Ball`) from `x0` on
/// |gamma| = 1 over `[0, t_end]`, by the QR method on the variational equations, as a dict with
/// the keys of `routh lyapunov --json` (without `case`): `exponents`,
/// `kaplan_yorke_dimension`, `divergence_mean`, `sum_of_exponents`, `history` (`times` and
/// `exponents`), the settings and the work. `transient` defaults to `t_end / 10`, `interval`
/// to `(t_end - transient) / 100`; `method` is "dop853", "vern9" or "rk4:<steps>" (steps per
/// interval). Bad arguments raise `ValueError` naming them. The interpreter lock is released
/// while it is computed.
#[pyfunction]
#[pyo3(signature = (body, x0, t_end = 100.0, *, transient = None, interval = None, method = "dop853", rtol = 1e-12, atol = 1e-12))]
#[allow(clippy::too_many_arguments)]
pub fn lyapunov<'py>(
    py: Python<'py>,
    body: &Bound<'py, PyAny>,
    x0: &Bound<'py, PyAny>,
    t_end: f64,
    transient: Option<f64>,
    interval: Option<f64>,
    method: &str,
    rtol: f64,
    atol: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let body = Rolling::extract("body", body)?;
    let x0 = phase_point("x0", &vector::<6>("x0", x0)?)?.to_array();
    let method: Method = method
        .parse()
        .map_err(|e: ParseMethodError| PyValueError::new_err(e.to_string()))?;
    let integration = Settings::builder()
        .method(method)
        .t_end(t_end)
        .tolerances(rtol, atol)
        .build()
        .map_err(python_error)?;
    let settings = LyapunovSettings::new(integration, transient, interval).map_err(python_error)?;
    let r = py
        .detach(|| report(&body, &x0, &settings))
        .map_err(python_error)?;
    record(py, &r)
}
