//! The classes `Problem` and `Event`, the function `simulate`, and the cases (TOML files of
//! `routh simulate`).

use crate::ball::Rolling;
use crate::convert::{bad_argument, check_size, phase_point, python_error, times, vector};
use crate::dense::DenseOutput;
use crate::drive::{drive, EventRule, Hooks, Output};
use crate::solution::Solution;
use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};
use routh_core::ball::AsBall;
use routh_core::case::Case;
use routh_core::integrate::{Method, OdeSystem};
use routh_core::motion::{initial_full, FullMotion};
use routh_core::simulate::{ReducedSystem, Settings};
use routh_core::State;
use std::path::PathBuf;

/// A named event of the library, evaluated without Python.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Named {
    /// `g = (gamma x omega)_3 * -1 = -d(gamma3)/dt`, which has the sign of `d theta/dt`
    /// (theta the tilt, `gamma3 = cos theta`): zero at the turning points of the nutation.
    ThetaDot,
    /// `g = gamma3 - c`.
    Gamma3(f64),
    /// `g = theta - c`, `theta = arccos(gamma3)` in radians.
    Theta(f64),
}

impl Named {
    fn parse(spec: &str) -> PyResult<Self> {
        let value = |text: &str| {
            text.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    bad_argument(
                        "events",
                        format!("{spec:?}: {text:?} is not a finite number"),
                    )
                })
        };
        match spec.trim().split_once('=') {
            None if spec.trim() == "theta_dot" => Ok(Named::ThetaDot),
            Some((name, v)) if name.trim() == "gamma3" => Ok(Named::Gamma3(value(v)?)),
            Some((name, v)) if name.trim() == "theta" => Ok(Named::Theta(value(v)?)),
            _ => Err(bad_argument(
                "events",
                format!(
                    "unknown named event {spec:?}: expected \"theta_dot\", \"gamma3=<value>\" \
                     or \"theta=<radians>\", or a callable g(t, y)"
                ),
            )),
        }
    }

    fn value(&self, body: &impl AsBall, y: &[f64]) -> f64 {
        let gamma = [y[0], y[1], y[2]];
        match *self {
            Named::ThetaDot => {
                let omega = body.ball().angular_velocity(&gamma, &[y[3], y[4], y[5]]);
                gamma[1] * omega[0] - gamma[0] * omega[1]
            }
            Named::Gamma3(c) => gamma[2] - c,
            Named::Theta(c) => gamma[2].clamp(-1.0, 1.0).acos() - c,
        }
    }
}

#[derive(Debug)]
enum What {
    Named(Named, String),
    Callable(Py<PyAny>),
}

/// An event for `simulate`: a named event of the library or a callable `g(t, y) -> float`
/// (y the numpy state of 6, or 12 with `full=True`), counted where g changes sign.
///
/// Named events (evaluated in Rust, without the interpreter lock): `"theta_dot"`
/// (`g = -d(gamma3)/dt`, the sign of d theta/dt: zero at the turning points of the tilt;
/// `direction=-1` finds the maxima of theta, `+1` its minima), `"gamma3=<value>"`
/// (`g = gamma3 - value`), `"theta=<radians>"` (`g = arccos(gamma3) - value`). `terminal`:
/// `False`, `True` (stop at the first occurrence) or a count n (stop at the n-th);
/// `direction`: as in SciPy (> 0: only crossings from negative to positive, in the order of
/// integration, so backward in time the maxima of theta have direction +1). A plain string
/// or callable may be given to `simulate` instead; a callable's `terminal` and `direction`
/// attributes are read as in SciPy. Picklable (a callable if pickle can pickle it).
#[pyclass(name = "Event", module = "routh", frozen)]
pub struct PyEvent {
    what: What,
    rule: EventRule,
}

fn read_terminal(value: &Bound<'_, PyAny>) -> PyResult<usize> {
    if let Ok(b) = value.extract::<bool>() {
        return Ok(usize::from(b));
    }
    value
        .extract::<usize>()
        .map_err(|_| bad_argument("terminal", "must be a bool or a count >= 0"))
}

fn read_direction(value: f64) -> PyResult<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(bad_argument("direction", format!("{value} is not finite")))
    }
}

#[pymethods]
impl PyEvent {
    #[new]
    #[pyo3(signature = (what, terminal = None, direction = 0.0))]
    fn new(
        what: &Bound<'_, PyAny>,
        terminal: Option<&Bound<'_, PyAny>>,
        direction: f64,
    ) -> PyResult<Self> {
        let what = if let Ok(spec) = what.extract::<String>() {
            What::Named(Named::parse(&spec)?, spec)
        } else if what.is_callable() {
            What::Callable(what.clone().unbind())
        } else {
            return Err(bad_argument(
                "events",
                "an event is a name or a callable g(t, y)",
            ));
        };
        let terminal = match terminal {
            Some(t) => read_terminal(t)?,
            None => 0,
        };
        Ok(PyEvent {
            what,
            rule: EventRule {
                terminal,
                direction: read_direction(direction)?,
            },
        })
    }

    /// The occurrences after which the run stops (0: never).
    #[getter]
    fn terminal(&self) -> usize {
        self.rule.terminal
    }

    /// The sign of the crossings that count (0: both).
    #[getter]
    fn direction(&self) -> f64 {
        self.rule.direction
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let e = slf.get();
        let py = slf.py();
        let what = match &e.what {
            What::Named(_, spec) => spec.clone().into_pyobject(py)?.into_any(),
            What::Callable(f) => f.bind(py).clone(),
        };
        let args = (what, e.rule.terminal, e.rule.direction).into_pyobject(py)?;
        Ok((slf.get_type().into_any(), args))
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let what = match &self.what {
            What::Named(_, spec) => format!("{spec:?}"),
            What::Callable(f) => f.bind(py).repr().map(|r| r.to_string()).unwrap_or_default(),
        };
        format!(
            "Event({what}, terminal={}, direction={})",
            self.rule.terminal, self.rule.direction
        )
    }
}

/// The events of the argument `events`: None, one event or a sequence of them, each an
/// `Event`, a name or a callable (with SciPy's optional `terminal` and `direction`).
fn read_events(py: Python<'_>, events: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<Py<PyEvent>>> {
    let Some(events) = events else {
        return Ok(vec![]);
    };
    let one = |item: &Bound<'_, PyAny>| -> PyResult<Py<PyEvent>> {
        if let Ok(e) = item.cast::<PyEvent>() {
            return Ok(e.clone().unbind());
        }
        let terminal = item.getattr("terminal").ok();
        let direction = match item.getattr("direction") {
            Ok(d) => d
                .extract::<f64>()
                .map_err(|_| bad_argument("direction", "must be a number"))?,
            Err(_) => 0.0,
        };
        Py::new(py, PyEvent::new(item, terminal.as_ref(), direction)?)
    };
    if events.is_instance_of::<PyList>() || events.is_instance_of::<PyTuple>() {
        events.try_iter()?.map(|item| one(&item?)).collect()
    } else {
        Ok(vec![one(events)?])
    }
}

/// An initial-value problem: a body (a `Body` or a `Ball`), the initial state `x0 = (gamma, M)` (6 numbers, finite,
/// |gamma| = 1 within 1e-12), the time span `t_span` (a number `t_end`, meaning `(0, t_end)`,
/// or a pair `(t0, t1)`; `t1 < t0` integrates backward in time), the integrator `method`
/// (`"dop853"`: adaptive, order 8, with `rtol`/`atol`; `"rk4"` or `"rk4:<steps>"`: classical
/// RK4 with that many equal steps), `project` (project onto the level set of the integrals
/// after each step and at every reported state; `project_every = N`: after every N-th step
/// only, as `routh simulate --project-every N`) and `full` (also integrate the orientation
/// quaternion and the position of the centre of mass: the motion in space). Picklable.
#[pyclass(name = "Problem", module = "routh", frozen)]
pub struct PyProblem {
    body: Rolling,
    x0: State,
    t_span: (f64, f64),
    /// The method, the tolerances and the projection (t_end the length of `t_span`),
    /// validated when the problem was made.
    settings: Settings,
    full: bool,
}

/// The span of the argument `t_span`: a number `t_end` (from 0) or a pair `(t0, t1)`.
fn read_span(obj: &Bound<'_, PyAny>) -> PyResult<(f64, f64)> {
    let (values, single) = times("t_span", obj)?;
    match (values.as_slice(), single) {
        ([t_end], true) => Ok((0.0, *t_end)),
        ([t0, t1], false) => Ok((*t0, *t1)),
        _ => Err(PyValueError::new_err(
            "t_span must be a number t_end or a pair (t0, t1)",
        )),
    }
}

impl PyProblem {
    #[allow(clippy::too_many_arguments)]
    fn solve_with<S: OdeSystem<N> + Sync, const N: usize>(
        &self,
        py: Python<'_>,
        sys: &S,
        y0: [f64; N],
        output: &[f64],
        use_steps: bool,
        events: &[Py<PyEvent>],
        dense_output: bool,
    ) -> PyResult<Solution> {
        let rules: Vec<EventRule> = events.iter().map(|e| e.get().rule).collect();
        let kinds: Vec<&What> = events.iter().map(|e| &e.get().what).collect();
        let body = self.body.ball();
        let mut event = |i: usize, t: f64, y: &[f64; N]| -> PyResult<f64> {
            match kinds[i] {
                What::Named(named, _) => Ok(named.value(&body, y)),
                What::Callable(f) => Python::attach(|py| {
                    let value = f.bind(py).call1((t, PyArray1::from_slice(py, y)))?;
                    value.extract::<f64>().map_err(|_| {
                        bad_argument("events", format!("event {i} did not return a number"))
                    })
                }),
            }
        };
        let mut interrupt = || Python::attach(|py| py.check_signals());
        let (t0, t1) = self.t_span;
        let out = if use_steps {
            Output::Steps
        } else {
            Output::Times(output)
        };
        let mut run = py.detach(|| {
            drive(
                &body,
                sys,
                t0,
                y0,
                t1,
                &self.settings,
                out,
                dense_output,
                Hooks {
                    event: &mut event,
                    rules: &rules,
                    interrupt: &mut interrupt,
                },
            )
        })?;
        let dense = std::mem::take(&mut run.dense);
        let sol = if dense_output {
            DenseOutput::new(self.body, self.settings.project(), dense, &y0, run.t_last)
        } else {
            None
        };
        Solution::from_run(
            py,
            &body,
            run,
            self.settings.method().to_string(),
            self.settings.project(),
            self.t_span,
            y0,
            sol,
        )
    }

    /// The sample times of `t_eval` or `samples`, checked; `None` for the step ends.
    fn output_times(
        &self,
        t_eval: Option<&Bound<'_, PyAny>>,
        samples: i64,
    ) -> PyResult<Option<Vec<f64>>> {
        let (t0, t1) = self.t_span;
        let dir = if t1 >= t0 { 1.0 } else { -1.0 };
        let width = if self.full { 13 } else { 7 };
        match (t_eval, samples) {
            (Some(_), s) if s != 0 => Err(PyValueError::new_err(
                "give either t_eval or samples, not both",
            )),
            (Some(t_eval), _) => {
                let (ts, _) = times("t_eval", t_eval)?;
                check_size("t_eval", ts.len() as u128, width)?;
                for (i, &s) in ts.iter().enumerate() {
                    if (s - t0) * dir < 0.0 || (t1 - s) * dir < 0.0 {
                        return Err(bad_argument(
                            "t_eval",
                            format!("t_eval[{i}] = {s} lies outside t_span = ({t0}, {t1})"),
                        ));
                    }
                    if i > 0 && (s - ts[i - 1]) * dir <= 0.0 {
                        return Err(bad_argument(
                            "t_eval",
                            format!(
                                "must be strictly monotone in the direction of t_span, but \
                                 t_eval[{}] = {} and t_eval[{i}] = {s}",
                                i - 1,
                                ts[i - 1]
                            ),
                        ));
                    }
                }
                Ok(Some(ts))
            }
            (None, 0) => Ok(None),
            (None, n) if n < 2 => Err(python_error(routh_core::RouthError::Option {
                name: "samples",
                value: n.to_string(),
                rule: "must be 0 or >= 2 (the samples include both ends)",
            })),
            (None, n) => {
                check_size("samples", n as u128, width)?;
                let n = n as usize;
                Ok(Some(
                    (0..n)
                        .map(|i| {
                            if i + 1 == n {
                                t1
                            } else {
                                t0 + (t1 - t0) * i as f64 / (n - 1) as f64
                            }
                        })
                        .collect(),
                ))
            }
        }
    }
}

#[pymethods]
impl PyProblem {
    #[new]
    #[pyo3(signature = (body, x0, t_span, rtol = 1e-12, atol = 1e-12, method = "dop853", project = false, full = false, project_every = 1))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        body: &Bound<'_, PyAny>,
        x0: &Bound<'_, PyAny>,
        t_span: &Bound<'_, PyAny>,
        rtol: f64,
        atol: f64,
        method: &str,
        project: bool,
        full: bool,
        project_every: i64,
    ) -> PyResult<Self> {
        if project_every < 1 {
            return Err(PyValueError::new_err(format!(
                "project_every = {project_every}: must be at least 1 (project after every step)"
            )));
        }
        let x0 = phase_point("x0", &vector::<6>("x0", x0)?)?;
        let t_span = read_span(t_span)?;
        let method: Method =
            method
                .parse()
                .map_err(|e: routh_core::integrate::ParseMethodError| {
                    PyValueError::new_err(e.to_string())
                })?;
        let settings = Settings::builder()
            .method(method)
            .t_end((t_span.1 - t_span.0).abs())
            .tolerances(rtol, atol)
            .projection(project, project_every as usize)
            .build()
            .map_err(python_error)?;
        Ok(PyProblem {
            body: Rolling::extract("body", body)?,
            x0,
            t_span,
            settings,
            full,
        })
    }

    /// The problem of a case file (TOML, the schema of `routh simulate`; the built-in default
    /// case when `path` is None): its body, initial state, `t_span = (0, t_end)`, rtol, atol, max_steps.
    #[staticmethod]
    #[pyo3(signature = (path = None, full = false))]
    fn from_case(path: Option<PathBuf>, full: bool) -> PyResult<Self> {
        let case = Case::load(path.as_deref()).map_err(python_error)?;
        // The case's [integration] as every command reads it (its max_steps included).
        let settings = case.integration;
        Ok(PyProblem {
            body: Rolling::of_case(&case, "a Python Problem"),
            x0: case.initial,
            t_span: (0.0, settings.t_end()),
            settings,
            full,
        })
    }

    /// The body (a `Body` or a `Ball`).
    #[getter]
    fn body<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.body.to_object(py)
    }

    /// The initial state `(gamma, M)`.
    #[getter]
    fn x0<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.x0.to_array())
    }

    /// The time span `(t0, t1)`.
    #[getter]
    fn t_span(&self) -> (f64, f64) {
        self.t_span
    }

    /// Relative tolerance.
    #[getter]
    fn rtol(&self) -> f64 {
        self.settings.rtol()
    }

    /// Absolute tolerance.
    #[getter]
    fn atol(&self) -> f64 {
        self.settings.atol()
    }

    /// The method, `"dop853"` or `"rk4:<steps>"`.
    #[getter]
    fn method(&self) -> String {
        self.settings.method().to_string()
    }

    /// Whether states are projected onto the level set of the integrals.
    #[getter]
    fn project(&self) -> bool {
        self.settings.project()
    }

    /// Whether the motion in space is integrated too.
    #[getter]
    fn full(&self) -> bool {
        self.full
    }

    /// With `project`: the step ends are projected after every `project_every`-th step
    /// (reported states always).
    #[getter]
    fn project_every(&self) -> usize {
        self.settings.project_every()
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let p = slf.get();
        let py = slf.py();
        let args = (
            p.body.to_object(py)?,
            p.x0.to_array().to_vec(),
            p.t_span,
            p.settings.rtol(),
            p.settings.atol(),
            p.settings.method().to_string(),
            p.settings.project(),
            p.full,
            p.settings.project_every(),
        );
        Ok((slf.get_type().into_any(), args.into_pyobject(py)?))
    }

    fn __repr__(&self) -> String {
        format!(
            "Problem(body={}, x0={:?}, t_span={:?}, rtol={:?}, atol={:?}, method={:?}, project={}, full={}, project_every={})",
            self.body.repr(),
            self.x0.to_array(),
            self.t_span,
            self.settings.rtol(),
            self.settings.atol(),
            self.settings.method().to_string(),
            if self.settings.project() { "True" } else { "False" },
            if self.full { "True" } else { "False" },
            self.settings.project_every()
        )
    }

    /// Integrate the problem (see `simulate`). The interpreter lock is released while the
    /// library integrates (a callable event takes it back for each call); Ctrl-C raises
    /// `KeyboardInterrupt` within a few hundred steps.
    #[pyo3(signature = (t_eval = None, samples = 0, events = None, dense_output = false))]
    fn solve(
        &self,
        py: Python<'_>,
        t_eval: Option<&Bound<'_, PyAny>>,
        samples: i64,
        events: Option<&Bound<'_, PyAny>>,
        dense_output: bool,
    ) -> PyResult<Solution> {
        let output = self.output_times(t_eval, samples)?;
        let events = read_events(py, events)?;
        let (out, use_steps) = match &output {
            Some(ts) => (ts.as_slice(), false),
            None => (&[][..], true),
        };
        let body = self.body.ball();
        if self.full {
            let y0 = initial_full(&self.x0);
            self.solve_with(
                py,
                &FullMotion { body: &body },
                y0,
                out,
                use_steps,
                &events,
                dense_output,
            )
        } else {
            self.solve_with(
                py,
                &ReducedSystem(&body),
                self.x0.to_array(),
                out,
                use_steps,
                &events,
                dense_output,
            )
        }
    }
}

/// Integrate (mg-eq) from `x0` over `t_span` and return a `Solution` (SciPy-like).
///
/// `t_span` is a number `t_end` (from 0) or a pair `(t0, t1)` (backward when `t1 < t0`);
/// the keyword `t_end=` of earlier versions is accepted in its place.
/// States are reported at `t_eval` (strictly monotone, within the span), or at `samples`
/// equally spaced times including both ends, or else at every step end. `events`: see
/// `Event`. `dense_output=True` adds `sol`, the state at any time of the span. `full=True`
/// integrates the motion in space too (y of 12: gamma, M, the quaternion q = (qw, qx, qy, qz)
/// of the rotation body-to-space, the horizontal position (x, y) of the centre of mass), the
/// initial orientation chosen by the rule of `routh simulate --full` (z-x-z Euler angles with
/// psi = 0) and the centre of mass above the origin. Bad arguments raise `ValueError` naming
/// them; a failed integration gives `status = -1` with the message, as in SciPy.
#[pyfunction]
#[pyo3(signature = (body, x0, t_span = None, rtol = 1e-12, atol = 1e-12, method = "dop853", project = false, samples = 0, *, t_eval = None, events = None, dense_output = false, full = false, t_end = None, project_every = 1))]
#[allow(clippy::too_many_arguments)]
pub fn simulate(
    py: Python<'_>,
    body: &Bound<'_, PyAny>,
    x0: &Bound<'_, PyAny>,
    t_span: Option<&Bound<'_, PyAny>>,
    rtol: f64,
    atol: f64,
    method: &str,
    project: bool,
    samples: i64,
    t_eval: Option<&Bound<'_, PyAny>>,
    events: Option<&Bound<'_, PyAny>>,
    dense_output: bool,
    full: bool,
    t_end: Option<&Bound<'_, PyAny>>,
    project_every: i64,
) -> PyResult<Solution> {
    let t_span = match (t_span, t_end) {
        (Some(span), None) | (None, Some(span)) => span,
        _ => {
            return Err(PyValueError::new_err(
                "give the time span once: t_span (or its older name t_end)",
            ))
        }
    };
    PyProblem::new(
        body,
        x0,
        t_span,
        rtol,
        atol,
        method,
        project,
        full,
        project_every,
    )?
    .solve(py, t_eval, samples, events, dense_output)
}

/// A case as the tuple `(body, x0, t_end, rtol, atol)`, the body a `Body` (centre of mass on
/// the e3 axis) or a `Ball`, x0 a numpy 6-vector.
type CaseTuple<'py> = (Bound<'py, PyAny>, Bound<'py, PyArray1<f64>>, f64, f64, f64);

fn case_tuple(py: Python<'_>, case: Case) -> PyResult<CaseTuple<'_>> {
    Ok((
        Rolling::of_case(&case, "a Python Body").to_object(py)?,
        PyArray1::from_slice(py, &case.initial.to_array()),
        case.integration.t_end(),
        case.integration.rtol(),
        case.integration.atol(),
    ))
}

/// The built-in default case (`cases/default.toml`) as `(Body, x0, t_end, rtol, atol)`.
#[pyfunction]
pub fn default_case(py: Python<'_>) -> PyResult<CaseTuple<'_>> {
    let case = Case::default_case().map_err(python_error)?;
    case_tuple(py, case)
}

/// The case file at `path` (TOML, the schema of `routh simulate`) as
/// `(Body, x0, t_end, rtol, atol)`; an unreadable or invalid file raises `ValueError`.
#[pyfunction]
pub fn load_case(py: Python<'_>, path: PathBuf) -> PyResult<CaseTuple<'_>> {
    let case = Case::from_file(&path).map_err(python_error)?;
    case_tuple(py, case)
}
