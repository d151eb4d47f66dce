//! `simulate` on the library's one driver ([`routh_core::simulate::integrate_span`]): this file
//! adds only what SciPy's `solve_ivp` has and the library does not, as an observer of the
//! steps: several events with SciPy's `terminal` counts and `direction`, located on the
//! stepper's dense output by the integrator's one event locator; the states at every step
//! end (SciPy's default output); the dense output of every step; and a check for Ctrl-C
//! between steps.

use pyo3::{PyErr, PyResult};
use routh_core::ball::AsBall;
use routh_core::integrate::{
    locate, Control, Direction, EventSpec, OdeSystem, Stats, Stepper, Stop, Unlocated,
};
use routh_core::problem::{DenseSolution, Status};
use routh_core::projection::LevelSet;
use routh_core::simulate::{integrate_span, project_onto, reduced, Drift, Settings, Span};
use routh_core::RouthError;
use std::cell::RefCell;
use std::collections::BTreeMap;

/// Steps between two checks for a pending Ctrl-C (a DOP853 step of (mg-eq) takes about a
/// microsecond, so the check runs about every 0.3 ms and costs nothing measurable).
pub const SIGNAL_CHECK_STEPS: usize = 256;

/// How an event is counted: SciPy's `terminal` (0: never stops, n: stops at the n-th
/// occurrence) and `direction` (> 0: only from negative to positive, < 0: the reverse,
/// 0: both).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EventRule {
    /// Occurrences after which the run stops (0: never).
    pub terminal: usize,
    /// The sign of the crossings that count (0: both).
    pub direction: f64,
}

/// What a run produced.
pub struct Run<const N: usize> {
    /// Times of the reported states.
    pub t: Vec<f64>,
    /// The reported states.
    pub y: Vec<[f64; N]>,
    /// Times of each event.
    pub t_events: Vec<Vec<f64>>,
    /// States at each event.
    pub y_events: Vec<Vec<[f64; N]>>,
    /// The dense output of every step (empty unless asked for).
    pub dense: DenseSolution<N>,
    /// Where the run stopped (the last step end, or the terminal event).
    pub t_last: f64,
    /// The state there.
    pub y_last: [f64; N],
    /// Work counters.
    pub stats: Stats,
    /// How it ended.
    pub status: Status,
    /// Why it failed (with [`Status::Failed`]).
    pub failure: Option<String>,
    /// The drift of each integral the body has.
    pub drift: BTreeMap<&'static str, Drift>,
    /// Wall time of the integration in seconds.
    pub elapsed_s: f64,
}

/// Where states are reported: at the step ends (SciPy's default) or at given times.
pub enum Output<'a> {
    /// At the start and at every step end.
    Steps,
    /// At these times, strictly monotone in the direction of integration, within the span.
    Times(&'a [f64]),
}

/// An event function `g_i(t, y)`, called with the event's index.
pub type EventFunction<'h, const N: usize> =
    &'h mut dyn FnMut(usize, f64, &[f64; N]) -> PyResult<f64>;

/// The hooks of a run into Python: event functions and the Ctrl-C check. Their errors (an
/// exception in an event function, `KeyboardInterrupt`) end the run and are raised.
pub struct Hooks<'h, const N: usize> {
    /// `g_i(t, y)` of event `i`.
    pub event: EventFunction<'h, N>,
    /// The counting rule of each event.
    pub rules: &'h [EventRule],
    /// Called every [`SIGNAL_CHECK_STEPS`] steps.
    pub interrupt: &'h mut dyn FnMut() -> PyResult<()>,
}

/// The error of a run's callbacks: an exception of a hook, or the library's refusal of the
/// settings or samples as one, raised after the run. The type [`integrate_span`] asks of its
/// callbacks' error is one that converts from [`RouthError`], which `PyErr` cannot here
/// (neither is of this crate).
struct Raised(PyErr);

impl From<RouthError> for Raised {
    fn from(e: RouthError) -> Self {
        Raised(crate::convert::python_error(e))
    }
}

impl From<Raised> for PyErr {
    fn from(raised: Raised) -> Self {
        raised.0
    }
}

/// The events of a run: their previous values, occurrences, the event that could not be
/// located (if any) and the Python hooks.
struct Events<'h, const N: usize> {
    hooks: Hooks<'h, N>,
    g_prev: Vec<f64>,
    t_events: Vec<Vec<f64>>,
    y_events: Vec<Vec<[f64; N]>>,
    /// Why an event could not be located; it ended the run, which failed.
    unlocated: Option<String>,
}

impl<const N: usize> Events<'_, N> {
    /// How the run ended, given the integrator's failure.
    fn ending(&self, failure: Option<String>) -> (Status, Option<String>) {
        let terminal = (self.hooks.rules.iter().zip(&self.t_events))
            .any(|(rule, t)| rule.terminal > 0 && t.len() >= rule.terminal);
        match (self.unlocated.clone().or(failure), terminal) {
            (Some(message), _) => (Status::Failed, Some(message)),
            (None, true) => (Status::Event, None),
            (None, false) => (Status::Reached, None),
        }
    }

    /// How each event is watched on the next step: its direction, and terminal if its next
    /// occurrence is the one that stops the run.
    fn specs(&self) -> Vec<EventSpec> {
        (self.hooks.rules.iter().zip(&self.t_events))
            .map(|(rule, occurred)| EventSpec {
                direction: if rule.direction > 0.0 {
                    Direction::Rising
                } else if rule.direction < 0.0 {
                    Direction::Falling
                } else {
                    Direction::Either
                },
                terminal: rule.terminal > 0 && occurred.len() + 1 >= rule.terminal,
            })
            .collect()
    }

    /// The events on the last step of `stepper`, which ends at `(t, y)` after projection
    /// (`raw`: the step end before it), located by the integrator's one locator, in the
    /// order of time: the run stops at the terminal one, if any, with its (projected) state,
    /// or after the step if an event could not be located.
    fn on_step(
        &mut self,
        stepper: &dyn Stepper<N>,
        t: f64,
        y: &[f64; N],
        raw: &[f64; N],
        project: &dyn Fn([f64; N]) -> [f64; N],
    ) -> Result<Control<N>, PyErr> {
        let g_end = (0..self.g_prev.len())
            .map(|i| (self.hooks.event)(i, t, raw))
            .collect::<PyResult<Vec<f64>>>()?;
        let specs = self.specs();
        let mut failure = None;
        let event = &mut self.hooks.event;
        let located = locate(
            &|s| stepper.dense(s),
            (stepper.t_prev(), t),
            &specs,
            &mut |i, s, x| match event(i, s, x) {
                Ok(g) => g,
                Err(e) => {
                    failure.get_or_insert(e);
                    f64::NAN
                }
            },
            &self.g_prev,
            &g_end,
        );
        if let Some(e) = failure {
            return Err(e);
        }
        let found = match located {
            Ok(found) => found,
            Err(Unlocated { event: i, ta, tb }) => {
                self.unlocated = Some(format!(
                    "event {i} could not be located in [{ta}, {tb}] (its function is not \
                     finite there)"
                ));
                return Ok(Control::Stop);
            }
        };
        for (i, g1) in g_end.into_iter().enumerate() {
            self.g_prev[i] = if raw == y {
                g1
            } else {
                (self.hooks.event)(i, t, y)?
            };
        }
        for crossing in found {
            let te = crossing.t;
            let ye = project(if te == t { *raw } else { stepper.dense(te) });
            self.t_events[crossing.event].push(te);
            self.y_events[crossing.event].push(ye);
            if crossing.terminal {
                return Ok(Control::StopAt { t: te, y: ye });
            }
        }
        Ok(Control::Continue)
    }
}

/// Integrate `sys` from `(t0, y0)` to `t1` (either direction) with `settings`, reporting
/// states at `output`, locating the events of `hooks`, keeping the dense output of every step
/// if `dense`. Fails only with the error of a hook or a span or samples the library refuses;
/// a failure of the integrator is returned as [`Status::Failed`] with what was computed.
#[allow(clippy::too_many_arguments)]
pub fn drive<S: OdeSystem<N>, const N: usize>(
    body: &impl AsBall,
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t1: f64,
    settings: &Settings,
    output: Output<'_>,
    dense: bool,
    hooks: Hooks<'_, N>,
) -> Result<Run<N>, PyErr> {
    let steps_output = matches!(output, Output::Steps);
    let samples = match output {
        Output::Steps => &[][..],
        Output::Times(times) => times,
    };
    // The reported states: the samples, or else the start and every step end.
    let reported = RefCell::new(if steps_output { vec![(t0, y0)] } else { vec![] });
    let g_prev = (0..hooks.rules.len())
        .map(|i| (hooks.event)(i, t0, &y0))
        .collect::<PyResult<Vec<f64>>>()?;
    let n_events = g_prev.len();
    let mut events = Events {
        hooks,
        g_prev,
        t_events: vec![vec![]; n_events],
        y_events: vec![vec![]; n_events],
        unlocated: None,
    };
    let level = settings
        .project()
        .then(|| LevelSet::through(body, &reduced(&y0)));
    let project = |mut y: [f64; N]| {
        project_onto(level.as_ref(), &mut y);
        y
    };
    let mut dense_solution = DenseSolution::default();
    let observed = integrate_span(
        body,
        sys,
        &Span {
            t0,
            y0,
            t1,
            samples,
        },
        settings,
        None,
        &mut |t, y| {
            reported.borrow_mut().push((t, *y));
            Ok::<_, Raised>(())
        },
        &mut |t, y, stepper| {
            if dense {
                dense_solution.record(stepper);
            }
            let raw = if settings.project() {
                stepper.dense(t)
            } else {
                *y
            };
            let next = events
                .on_step(stepper, t, y, &raw, &project)
                .map_err(Raised)?;
            let end = match next {
                Control::Stop => return Ok(next),
                Control::StopAt { t, y } => (t, y),
                Control::Continue => (t, *y),
            };
            if steps_output {
                reported.borrow_mut().push(end);
            }
            if next == Control::Continue && stepper.stats().steps % SIGNAL_CHECK_STEPS == 0 {
                (events.hooks.interrupt)().map_err(Raised)?;
            }
            Ok(next)
        },
    )?;
    let failure = match &observed.stop {
        Stop::Failed(e) => Some(e.to_string()),
        Stop::Reached | Stop::Event | Stop::Stopped => None,
    };
    let (status, failure) = events.ending(failure);
    let reported = reported.into_inner();
    let summary = observed.summary;
    Ok(Run {
        t: reported.iter().map(|r| r.0).collect(),
        y: reported.iter().map(|r| r.1).collect(),
        t_events: events.t_events,
        y_events: events.y_events,
        dense: dense_solution,
        t_last: observed.t,
        y_last: observed.y,
        stats: Stats {
            steps: summary.steps,
            rejected: summary.rejected,
            rhs_evals: summary.rhs_evals,
        },
        status,
        failure,
        drift: summary.integrals,
        elapsed_s: summary.elapsed_s,
    })
}
