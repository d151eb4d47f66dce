//! The energy–momentum diagram of the Routh sphere (the library's `diagram`, the JSON of
//! `routh diagram`): the relative equilibria at fixed Jellett H3 with their stability type,
//! the number of tori on a grid of values, the focus–focus points and their monodromy, and
//! the sleeping tops in the plane (H3, K).

use crate::body::PyBody;
use crate::convert::{python_error, record};
use pyo3::prelude::*;
use routh_core::diagram::{sleeping_tops as tops, Diagram, Resolution};

/// The energy–momentum diagram of `body` (a Routh sphere, I1 = I2) in the plane (K, H1) at
/// Jellett's `h3`, as a dict with the keys of `routh diagram --json`: `H3`, `window`,
/// `vertical_spins`, `critical_curves` (each with its `stability` and `points`),
/// `focus_focus` (each with `H1`, `H3`, `K` and the `state`), `monodromy` (`loop`, `matrix`:
/// 2 x 2 integers; None without a focus–focus point) and `tori` (the number of tori on a grid
/// of the window). `tilts`, `grid` and `loop_points` default to those of the command. The
/// interpreter lock is released while it is computed (about a second at the defaults).
#[pyfunction]
#[pyo3(signature = (body, h3, *, tilts=None, grid=None, loop_points=None))]
pub fn diagram<'py>(
    py: Python<'py>,
    body: PyRef<'py, PyBody>,
    h3: f64,
    tilts: Option<usize>,
    grid: Option<usize>,
    loop_points: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let body = body.inner;
    let default = Resolution::default();
    let resolution = Resolution {
        tilts: tilts.unwrap_or(default.tilts),
        grid: grid.unwrap_or(default.grid),
        loop_points: loop_points.unwrap_or(default.loop_points),
    };
    let d = py
        .detach(|| Diagram::new(&body, h3, &[], resolution))
        .map_err(python_error)?;
    record(py, &d)
}

/// The vertical spins of `body` (a Routh sphere) along the lines of the plane (H3, K) for
/// |H3| <= `h3_max`, `samples` points per pole, each a dict with its stability type (Routh's
/// criterion: elliptic above the threshold spin, focus–focus below it).
#[pyfunction]
#[pyo3(signature = (body, h3_max, samples=200))]
pub fn sleeping_tops<'py>(
    py: Python<'py>,
    body: PyRef<'py, PyBody>,
    h3_max: f64,
    samples: usize,
) -> PyResult<Bound<'py, PyAny>> {
    let body = body.inner;
    let list = py
        .detach(|| tops(&body, h3_max, samples))
        .map_err(python_error)?;
    record(py, &list)
}
