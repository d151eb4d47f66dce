//! The Python module `routh`: the body, its field (mg-eq), its integrals (int-g), (raus-int),
//! and the simulation of the Rust library `routh`, with numpy arrays for phase-space points.
//!
//! A phase-space point is the 6-vector `x = (gamma1, gamma2, gamma3, M1, M2, M3)` of the
//! library: `gamma` the unit normal of the plane pointing into it, `M` the angular momentum
//! about the contact point, both in the body frame. Every formula lives in the library; this
//! crate only converts arguments and results. Errors of the library become `ValueError`
//! (bad input) or `RuntimeError` (the integration failed), carrying the library's message.

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use routh_core::case::Case;
use routh_core::field::vector_field;
use routh_core::integrals::Integrals;
use routh_core::integrate::Method;
use routh_core::simulate::{run, Drift, ReducedSystem, Settings, Summary};
use routh_core::state::{Normalise, State};
use routh_core::RouthError;
use std::path::PathBuf;

/// The Python exception for a library error: the integration or a figure failing at run time
/// is a `RuntimeError`, a file that cannot be accessed an `OSError`, everything else (parameters,
/// states, options, case files) a `ValueError`.
fn python_error(e: RouthError) -> PyErr {
    let message = e.to_string();
    match e {
        RouthError::Integrate(_) | RouthError::Plot { .. } => PyRuntimeError::new_err(message),
        RouthError::Io { .. } => PyOSError::new_err(message),
        RouthError::Parameter { .. }
        | RouthError::Triangle { .. }
        | RouthError::NotSymmetric { .. }
        | RouthError::State(_)
        | RouthError::Option { .. }
        | RouthError::Case { .. }
        | RouthError::Singular { .. }
        | RouthError::Separatrix { .. }
        | RouthError::Table { .. } => PyValueError::new_err(message),
    }
}

/// The fixed-length vector `name` of a Python sequence of numbers (a list, tuple or numpy
/// array), or a `ValueError` that names the argument.
fn fixed<const N: usize>(name: &str, v: Vec<f64>) -> PyResult<[f64; N]> {
    let len = v.len();
    v.try_into().map_err(|_| {
        PyValueError::new_err(format!("{name} must have {N} components, but it has {len}"))
    })
}

fn normalise(normalize: bool) -> Normalise {
    if normalize {
        Normalise::Rescale
    } else {
        Normalise::Reject
    }
}

/// The Routh sphere's parameters: mass m, radius R, offset a of the centre of mass (the
/// centre of mass is at `-a e3` from the geometric centre, |a| < R), principal moments
/// I1, I2, I3 about the centre of mass (I2 defaults to I1: the Routh sphere), gravity G.
#[pyclass(name = "Body", module = "routh", frozen)]
struct PyBody {
    inner: routh_core::Body,
}

impl PyBody {
    fn state(&self, x: Vec<f64>) -> PyResult<[f64; 6]> {
        fixed::<6>("x", x)
    }
}

#[pymethods]
impl PyBody {
    /// `Body(m, R, a, I1, I3, G=9.81, I2=None)`; invalid parameters raise `ValueError`
    /// naming the parameter and the rule it breaks.
    #[new]
    #[pyo3(signature = (m, R, a, I1, I3, G = 9.81, I2 = None))]
    #[allow(non_snake_case)]
    fn new(m: f64, R: f64, a: f64, I1: f64, I3: f64, G: f64, I2: Option<f64>) -> PyResult<Self> {
        routh_core::Body::new(m, R, a, I1, I2.unwrap_or(I1), I3, G)
            .map(|inner| PyBody { inner })
            .map_err(python_error)
    }

    /// Mass m.
    #[getter]
    fn m(&self) -> f64 {
        self.inner.m
    }

    /// Radius R.
    #[getter(R)]
    fn radius(&self) -> f64 {
        self.inner.radius
    }

    /// Offset a of the centre of mass.
    #[getter]
    fn a(&self) -> f64 {
        self.inner.a
    }

    /// Principal moment I1.
    #[getter(I1)]
    fn i1(&self) -> f64 {
        self.inner.i1
    }

    /// Principal moment I2.
    #[getter(I2)]
    fn i2(&self) -> f64 {
        self.inner.i2
    }

    /// Principal moment I3 about the symmetry axis.
    #[getter(I3)]
    fn i3(&self) -> f64 {
        self.inner.i3
    }

    /// Gravitational acceleration G.
    #[getter(G)]
    fn gravity(&self) -> f64 {
        self.inner.gravity
    }

    fn __repr__(&self) -> String {
        let b = &self.inner;
        format!(
            "Body(m={:?}, R={:?}, a={:?}, I1={:?}, I3={:?}, G={:?}, I2={:?})",
            b.m, b.radius, b.a, b.i1, b.i3, b.gravity, b.i2
        )
    }

    /// The vector field (mg-eq) at `x = (gamma, M)`, as a numpy array of 6 components. The
    /// field is defined off the sphere |gamma| = 1 too, so `x` is not checked beyond its length.
    fn field<'py>(&self, py: Python<'py>, x: Vec<f64>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let x = self.state(x)?;
        Ok(PyArray1::from_slice(py, &vector_field(&self.inner, &x)))
    }

    /// The angular velocity `omega = I_Q^{-1} M` of (om-m) at `x = (gamma, M)`.
    fn omega<'py>(&self, py: Python<'py>, x: Vec<f64>) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let x = self.state(x)?;
        let omega = State::from_array(&x).omega(&self.inner);
        Ok(PyArray1::from_slice(py, &omega))
    }

    /// The integrals at `x` as a dict `{H1, H2, H3, H4, K}`: energy H1 (int-g), the quadratic
    /// integral H2, Jellett's H3, H4 = |gamma|^2 and Routh's K (raus-int). H2 and K are `None`
    /// unless I1 = I2.
    fn integrals<'py>(&self, py: Python<'py>, x: Vec<f64>) -> PyResult<Bound<'py, PyDict>> {
        let x = self.state(x)?;
        let values = Integrals::at(&self.inner, &x).values();
        let dict = PyDict::new(py);
        for (name, value) in routh_core::integrals::INTEGRAL_NAMES.iter().zip(values) {
            dict.set_item(*name, value)?;
        }
        Ok(dict)
    }

    /// The phase-space point `(gamma, M)` with `M = I_Q omega` (om-m), as a numpy 6-vector.
    /// `gamma` must be a unit vector (`ValueError` otherwise) unless `normalize=True`, which
    /// rescales it.
    #[pyo3(signature = (gamma, omega, normalize = false))]
    fn state_from_omega<'py>(
        &self,
        py: Python<'py>,
        gamma: Vec<f64>,
        omega: Vec<f64>,
        normalize: bool,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let gamma = fixed::<3>("gamma", gamma)?;
        let omega = fixed::<3>("omega", omega)?;
        let state = State::from_omega(&self.inner, gamma, omega, normalise(normalize))
            .map_err(python_error)?;
        Ok(PyArray1::from_slice(py, &state.to_array()))
    }
}

/// Integrate (mg-eq) from `x0` over `[0, t_end]` with the library's `simulate::run`.
///
/// `method` is `"dop853"` (adaptive, `rtol`, `atol`), `"rk4"` or `"rk4:<steps>"` (fixed
/// steps); `project=True` projects onto the level set of the integrals after each step;
/// `samples` equally spaced dense-output samples on `[0, t_end]` (0, or at least 2: both ends
/// are included). Returns a dict with the keys of the library's `Summary` (`method`, `t_end`,
/// `steps`, `rejected`, `rhs_evals`, `projected`, `initial_state`, `final_state` as numpy
/// 6-vectors, `integrals` as `{name: {initial, final, max_rel_drift}}`), plus `t` (shape
/// `(samples,)`) and `x` (shape `(samples, 6)`) when `samples > 0`.
///
/// `x0` must have |gamma| = 1 and be finite (`ValueError`); invalid options raise `ValueError`;
/// a failed integration raises `RuntimeError`. The Python interpreter is released while
/// integrating.
#[pyfunction]
#[pyo3(signature = (body, x0, t_end, rtol = 1e-12, atol = 1e-12, method = "dop853", project = false, samples = 0))]
#[allow(clippy::too_many_arguments)]
fn simulate<'py>(
    py: Python<'py>,
    body: PyRef<'py, PyBody>,
    x0: Vec<f64>,
    t_end: f64,
    rtol: f64,
    atol: f64,
    method: &str,
    project: bool,
    samples: i64,
) -> PyResult<Bound<'py, PyDict>> {
    let x0 = fixed::<6>("x0", x0)?;
    let x0 = State::new(
        [x0[0], x0[1], x0[2]],
        [x0[3], x0[4], x0[5]],
        Normalise::Reject,
    )
    .map_err(python_error)?
    .to_array();
    let method: Method = method
        .parse()
        .map_err(|e: routh_core::integrate::ParseMethodError| {
            PyValueError::new_err(e.to_string())
        })?;
    let samples = usize::try_from(samples).map_err(|_| {
        python_error(RouthError::Option {
            name: "samples",
            value: samples.to_string(),
            rule: "must be 0 or >= 2 (the samples include both ends)",
        })
    })?;
    let settings = Settings {
        method,
        t_end,
        rtol,
        atol,
        project,
        samples,
        max_steps: routh::case::DEFAULT_MAX_STEPS,
    };
    let body = body.inner;
    let (summary, times, states) = py
        .detach(|| {
            let mut times = Vec::with_capacity(samples);
            let mut states = Vec::with_capacity(samples);
            let summary = run(&body, &ReducedSystem(&body), x0, &settings, &mut |t, x| {
                times.push(t);
                states.push(*x);
                Ok(())
            })?;
            Ok((summary, times, states))
        })
        .map_err(python_error)?;
    let dict = summary_dict(py, summary)?;
    if samples > 0 {
        dict.set_item("t", PyArray1::from_vec(py, times))?;
        let n = states.len();
        let flat: Vec<f64> = states.into_iter().flatten().collect();
        let x: Bound<'py, PyArray2<f64>> = PyArray1::from_vec(py, flat).reshape([n, 6])?;
        dict.set_item("x", x)?;
    }
    Ok(dict)
}

/// The library's `Summary` as a dict; the destructuring makes a new field a compile error
/// here rather than a silently missing key.
fn summary_dict(py: Python<'_>, summary: Summary) -> PyResult<Bound<'_, PyDict>> {
    let Summary {
        method,
        t_end,
        steps,
        rejected,
        rhs_evals,
        projected,
        initial_state,
        final_state,
        integrals,
        elapsed_s,
    } = summary;
    let dict = PyDict::new(py);
    dict.set_item("method", method)?;
    dict.set_item("t_end", t_end)?;
    dict.set_item("steps", steps)?;
    dict.set_item("rejected", rejected)?;
    dict.set_item("rhs_evals", rhs_evals)?;
    dict.set_item("projected", projected)?;
    dict.set_item("elapsed_s", elapsed_s)?;
    dict.set_item(
        "initial_state",
        PyArray1::from_slice(py, &initial_state.to_array()),
    )?;
    dict.set_item(
        "final_state",
        PyArray1::from_slice(py, &final_state.to_array()),
    )?;
    let drifts = PyDict::new(py);
    for (name, drift) in integrals {
        let Drift {
            initial,
            last,
            max_rel_drift,
        } = drift;
        let entry = PyDict::new(py);
        entry.set_item("initial", initial)?;
        entry.set_item("final", last)?;
        entry.set_item("max_rel_drift", max_rel_drift)?;
        drifts.set_item(name, entry)?;
    }
    dict.set_item("integrals", drifts)?;
    Ok(dict)
}

/// A case as the tuple `(Body, x0, t_end, rtol, atol)`, x0 a numpy 6-vector.
type CaseTuple<'py> = (PyBody, Bound<'py, PyArray1<f64>>, f64, f64, f64);

fn case_tuple(py: Python<'_>, case: Case) -> CaseTuple<'_> {
    (
        PyBody { inner: case.body },
        PyArray1::from_slice(py, &case.initial.to_array()),
        case.integration.t_end,
        case.integration.rtol,
        case.integration.atol,
    )
}

/// The built-in default case (`cases/default.toml`) as `(Body, x0, t_end, rtol, atol)`.
#[pyfunction]
fn default_case(py: Python<'_>) -> PyResult<CaseTuple<'_>> {
    let case = Case::default_case().map_err(python_error)?;
    Ok(case_tuple(py, case))
}

/// The case file at `path` (TOML, the schema of `routh simulate`) as
/// `(Body, x0, t_end, rtol, atol)`; an unreadable or invalid file raises `ValueError`.
#[pyfunction]
fn load_case(py: Python<'_>, path: PathBuf) -> PyResult<CaseTuple<'_>> {
    let case = Case::from_file(&path).map_err(python_error)?;
    Ok(case_tuple(py, case))
}

/// The nonholonomic Routh sphere: Python access to the Rust library `routh`.
#[pymodule]
fn routh(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add("__version__", env!("CARGO_PKG_VERSION"))?;
    module.add_class::<PyBody>()?;
    module.add_function(wrap_pyfunction!(simulate, module)?)?;
    module.add_function(wrap_pyfunction!(default_case, module)?)?;
    module.add_function(wrap_pyfunction!(load_case, module)?)?;
    Ok(())
}
