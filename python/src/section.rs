//! The Poincaré section of a ball's motions on one energy level (the library's `section`, the
//! JSON of `routh section` and the crossings as arrays).

use crate::ball::Rolling;
use crate::convert::{columns, phase_point, python_error, record, vector};
use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use routh_core::integrate::{Method, ParseMethodError};
use routh_core::section::section as ball_section;
use routh_core::simulate::Settings;
use routh_core::surface::{parse_direction, parse_surface};
use routh_core::AsBall;

/// The crossings of the motions of `body` (a `Body` or a `Ball`) on the energy level of `x0`
/// with the plane `surface` ("NAME = NUMBER", NAME one of gamma1 gamma2 gamma3 M1 M2 M3) in
/// `direction` ("up", "down" or "both"), over `[0, t_end]` from `initial` states (`x0` first,
/// then other tilts with the spin rescaled onto the level; as `routh section`). Returns a dict
/// with the keys of `routh section --json` (without `case`, `axes`, `out`, `files`) and the
/// arrays `run` (the index of each crossing's initial state), `t` (its time), `x` (the
/// states, shape `(6, k)`) and `initial_states_x` (shape `(6, n)`). `method` is "dop853" (in
/// SIMD lanes), "vern9" or "rk4:<steps>". Bad arguments raise `ValueError` naming them. The
/// interpreter lock is released while it is computed.
#[pyfunction]
#[pyo3(signature = (body, x0, surface, t_end = 100.0, *, direction = "up", initial = 20, method = "dop853", rtol = 1e-12, atol = 1e-12))]
#[allow(clippy::too_many_arguments)]
pub fn section<'py>(
    py: Python<'py>,
    body: &Bound<'py, PyAny>,
    x0: &Bound<'py, PyAny>,
    surface: &str,
    t_end: f64,
    direction: &str,
    initial: usize,
    method: &str,
    rtol: f64,
    atol: f64,
) -> PyResult<Bound<'py, PyAny>> {
    let ball = Rolling::extract("body", body)?.ball();
    let x0 = phase_point("x0", &vector::<6>("x0", x0)?)?.to_array();
    let crossing = parse_surface(surface, "surface").map_err(python_error)?;
    let direction = parse_direction(direction, "direction").map_err(python_error)?;
    let method: Method = method
        .parse()
        .map_err(|e: ParseMethodError| PyValueError::new_err(e.to_string()))?;
    let settings = Settings::builder()
        .method(method)
        .t_end(t_end)
        .tolerances(rtol, atol)
        .build()
        .map_err(python_error)?;
    let (starts, found, report) = py
        .detach(|| ball_section(&ball, &x0, &settings, &crossing, direction, initial))
        .map_err(python_error)?;
    let out = record(py, &report)?;
    let dict = out.cast::<PyDict>()?;
    let runs: Vec<i64> = found.points.iter().map(|p| p.run as i64).collect();
    let times: Vec<f64> = found.points.iter().map(|p| p.t).collect();
    let states: Vec<[f64; 6]> = found.points.iter().map(|p| p.y).collect();
    dict.set_item("run", PyArray1::from_vec(py, runs))?;
    dict.set_item("t", PyArray1::from_vec(py, times))?;
    dict.set_item("x", columns(py, &states, false)?)?;
    dict.set_item("initial_states_x", columns(py, &starts, false)?)?;
    Ok(out)
}
