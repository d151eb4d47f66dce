//! Generic ODE integrators for first-order systems `y' = f(t, y)` of fixed
//! dimension `N` in plain `f64`.
//!
//! * [`Dop853`]: the adaptive explicit Runge–Kutta pair 8(5,3) of Dormand &
//!   Prince with Hairer's error estimator, step-size controller and 7th-order
//!   dense output, following `dop853.f` of Hairer & Wanner;
//! * [`Rk4`], [`rk4`]: the classical fixed-step Runge–Kutta method of order 4,
//!   table-driven, with its own dense output;
//! * [`Stepper`]: what a one-step method offers (a step, the dense output on the
//!   last step, the state, the counters); [`drive`]: the one step loop, with dense
//!   samples, projection onto invariant manifolds, event location and a per-step
//!   observer that can stop the run; [`solve`] and [`solve_dense`] are two uses of it;
//! * [`StepControl`]: the step control of one run (acceptance, next step size by the
//!   method's [`Law`], the last step cut to land on `t_end`, the refusals, the counters),
//!   held by every stepper and by every lane of the batched integrators ([`crate::batch`]):
//!   the one place where steps are decided;
//! * [`Vern9`]: Verner's 9(8) pair with its 9th-order interpolant;
//! * [`Taylor`]: the Taylor-series method of adaptive order and step (Jorba–Zou) on the field
//!   recorded into an expression tape ([`OdeSystem::record`]);
//! * [`Method`] names them, [`stepper`] builds the one chosen (and resolves `auto`);
//! * [`brent`]: a bracketing scalar root finder; [`locate`]: the one event locator (the
//!   crossings of several event functions on a step's dense output).
//!
//! The integrators know nothing of the model: they only see an [`OdeSystem`].

pub mod batch;
pub mod compensated;
pub mod control;
pub mod differential;
mod dop853;
mod event;
mod rk4;
pub mod sampling;
pub mod scalar;
pub mod tableau;
pub mod taylor;
mod vern9;
pub mod vern9_tableau;

use std::fmt;
use std::str::FromStr;

pub use control::{Clock, Law, StepControl};
pub use dop853::{fixed_step_solve, hinit, Dop853, RkStart, RungeKutta};
pub(crate) use dop853::{rk_start, scaled_error};
pub use event::{brent, locate, Crossing, Direction, EventSpec, Unlocated};
pub use rk4::{rk4, Rk4, RK4_A, RK4_B, RK4_C, RK4_DENSE};
pub use taylor::Taylor;
pub use vern9::Vern9;

/// A first-order system `y' = f(t, y)` of fixed dimension `N`, in plain `f64`.
pub trait OdeSystem<const N: usize> {
    /// The generated Taylor kernels among which a tape of this system's field looks for its
    /// shape ([`taylor::Kernels`]); [`taylor::Interpreted`] for none (the tape's interpreter
    /// runs it, as fast as a kernel within about 1.2x).
    type Kernels: taylor::Kernels;

    /// The right-hand side `f(t, y)`.
    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N];

    /// The same field evaluated on tape variables, which records it for the Taylor method
    /// ([`taylor::Tape`]): a system whose field is written generic over
    /// [`Scalar`](crate::scalar::Scalar) returns `Some(field(t, y))`, the same generic code
    /// as [`OdeSystem::rhs`] (or the same function in a closed form cheaper for series, as
    /// [`ReducedSystem`](crate::simulate::ReducedSystem) records it). `None` (the default):
    /// the system cannot be recorded.
    fn record(&self, _t: taylor::Var, _y: &[taylor::Var; N]) -> Option<[taylor::Var; N]> {
        None
    }
}

impl<F, const N: usize> OdeSystem<N> for F
where
    F: Fn(f64, &[f64; N]) -> [f64; N],
{
    type Kernels = taylor::Interpreted;

    #[inline(always)]
    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N] {
        self(t, y)
    }
}

/// Number of steps used by `Method::Rk4` when parsed from the bare name `"rk4"`.
pub const DEFAULT_RK4_STEPS: usize = 10_000;

/// Choice of integration method.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Adaptive DOP853 (see [`Dop853`]).
    Dop853,
    /// Adaptive Verner 9(8) with its interpolant (see [`Vern9`]).
    Vern9,
    /// Taylor series of adaptive order and step (see [`Taylor`]); needs a system that can be
    /// recorded ([`OdeSystem::record`]).
    Taylor,
    /// The fastest of the above for the requested tolerance, by a table that the model
    /// measured ([`Method::resolve_in`]); resolved before [`stepper`] is called.
    Auto,
    /// Classical Runge–Kutta of order 4 with a fixed number of equal steps.
    Rk4 {
        /// Number of equal steps over the whole interval.
        steps: usize,
    },
}

impl Method {
    /// The method that runs for the tolerance `tol` by the `table` of `(tol_min, method)`
    /// rows (the first with `tol >= tol_min` wins; the Taylor method below the last) for
    /// [`Method::Auto`], the method itself otherwise.
    pub fn resolve_in(self, tol: f64, table: &[(f64, Method)]) -> Method {
        match self {
            Method::Auto => table
                .iter()
                .find(|(tol_min, _)| tol >= *tol_min)
                .map_or(Method::Taylor, |&(_, m)| m),
            other => other,
        }
    }
}

/// Error returned when a [`Method`] name cannot be parsed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown integration method {0:?}: expected \"dop853\", \"vern9\", \"taylor\", \"auto\", \"rk4\" or \"rk4:<steps>\" with steps > 0")]
pub struct ParseMethodError(pub String);

impl FromStr for Method {
    type Err = ParseMethodError;

    /// Parses `"dop853"`, `"vern9"`, `"taylor"`, `"auto"`, `"rk4"` (with
    /// [`DEFAULT_RK4_STEPS`] steps) or `"rk4:<steps>"`, ignoring ASCII case.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let lower = s.trim().to_ascii_lowercase();
        match lower.as_str() {
            "dop853" => Ok(Method::Dop853),
            "vern9" => Ok(Method::Vern9),
            "taylor" => Ok(Method::Taylor),
            "auto" => Ok(Method::Auto),
            "rk4" => Ok(Method::Rk4 {
                steps: DEFAULT_RK4_STEPS,
            }),
            other => other
                .strip_prefix("rk4:")
                .and_then(|n| n.parse::<usize>().ok())
                .filter(|&steps| steps > 0)
                .map(|steps| Method::Rk4 { steps })
                .ok_or_else(|| ParseMethodError(s.to_string())),
        }
    }
}

impl serde::Serialize for Method {
    /// As its name, `"dop853"`, `"vern9"`, `"taylor"`, `"auto"` or `"rk4:<steps>"`.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl fmt::Display for Method {
    /// Writes the name that [`FromStr`] parses back.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Method::Dop853 => write!(f, "dop853"),
            Method::Vern9 => write!(f, "vern9"),
            Method::Taylor => write!(f, "taylor"),
            Method::Auto => write!(f, "auto"),
            Method::Rk4 { steps } => write!(f, "rk4:{steps}"),
        }
    }
}

/// The stepper of `method` for `sys` from `(t0, y0)` towards `t_end` with the tolerances and
/// limits of `opts` (RK4 takes its equal steps and ignores `opts`). Errors of the stepper's
/// constructor, and [`IntegrateError::UnresolvedAuto`] for [`Method::Auto`], which names no
/// method until the caller's table resolves it ([`Method::resolve_in`]).
pub fn stepper<'a, S: OdeSystem<N>, const N: usize>(
    method: Method,
    sys: &'a S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    opts: &Options,
) -> Result<Box<dyn Stepper<N> + 'a>, IntegrateError> {
    Ok(match method {
        Method::Dop853 => Box::new(Dop853::new(sys, t0, y0, t_end, opts)?),
        Method::Vern9 => Box::new(Vern9::new(sys, t0, y0, t_end, opts)?),
        Method::Taylor => Box::new(Taylor::new(sys, t0, y0, t_end, opts)?),
        Method::Auto => return Err(IntegrateError::UnresolvedAuto),
        Method::Rk4 { steps } => Box::new(Rk4::new(sys, t0, y0, t_end, steps)),
    })
}

/// Options of the adaptive integrator.
///
/// The local error of component `i` is kept below roughly
/// `atol + rtol * |y_i|` (scalar tolerances, Hairer's `ITOL = 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Relative tolerance (finite, > 0).
    pub rtol: f64,
    /// Absolute tolerance (finite, > 0).
    pub atol: f64,
    /// Initial step size (its sign is ignored); `None` selects it by Hairer's `HINIT`.
    pub h_init: Option<f64>,
    /// Maximal step size; `None` means `|t_end - t0|`.
    pub h_max: Option<f64>,
    /// Maximal number of attempted steps (accepted and rejected).
    pub max_steps: usize,
    /// Sum the update `y + h sum b_i k_i` with compensation ([`compensated::compensated_add`]);
    /// `false` gives the plain sum of the published codes (bit-for-bit comparisons with them).
    pub compensated: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            rtol: 1e-10,
            atol: 1e-10,
            h_init: None,
            h_max: None,
            max_steps: 10_000_000,
            compensated: true,
        }
    }
}

impl Options {
    /// Checks the options: `rtol` and `atol` finite and > 0, `h_init` finite and
    /// nonzero, `h_max` finite and > 0, `max_steps` > 0.
    pub fn validate(&self) -> Result<(), IntegrateError> {
        let positive = |name: &'static str, value: f64| {
            if value.is_finite() && value > 0.0 {
                Ok(())
            } else {
                Err(IntegrateError::InvalidOption {
                    name,
                    value,
                    rule: "must be finite and > 0",
                })
            }
        };
        positive("rtol", self.rtol)?;
        positive("atol", self.atol)?;
        if let Some(h) = self.h_init {
            positive("h_init (absolute value)", h.abs())?;
        }
        if let Some(h) = self.h_max {
            positive("h_max", h)?;
        }
        if self.max_steps == 0 {
            return Err(IntegrateError::InvalidOption {
                name: "max_steps",
                value: 0.0,
                rule: "must be > 0",
            });
        }
        Ok(())
    }
}

/// Work counters of an integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct Stats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (all of them, including rejections of the first step).
    pub rejected: usize,
    /// Calls of the right-hand side, every one counted.
    pub rhs_evals: usize,
}

/// Failures of an integration.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum IntegrateError {
    /// An option or argument violates its rule.
    #[error("invalid option {name} = {value}: {rule}")]
    InvalidOption {
        /// Name of the option or argument.
        name: &'static str,
        /// Its offending value.
        value: f64,
        /// The rule it violates.
        rule: &'static str,
    },
    /// The step size fell below the round-off level of `t`.
    #[error("step size too small at t = {t}: h = {h}")]
    StepSizeTooSmall {
        /// Time reached.
        t: f64,
        /// The step size that was too small.
        h: f64,
    },
    /// More than `max_steps` steps would be needed.
    #[error("more than max_steps = {max_steps} steps needed; stopped at t = {t} (raise the limit with --max-steps or max_steps in [integration])")]
    TooManySteps {
        /// Time reached.
        t: f64,
        /// The limit that was hit.
        max_steps: usize,
    },
    /// The state, its derivative or the step size became NaN or infinite.
    #[error("non-finite state, derivative or step size at t = {t}")]
    NonFinite {
        /// Time at which it was detected.
        t: f64,
    },
    /// [`Method::Auto`] was given to [`stepper`] unresolved: which method runs is the
    /// model's choice, by its measured table ([`Method::resolve_in`]).
    #[error(
        "method auto names no integrator until the model's table resolves it (Method::resolve_in)"
    )]
    UnresolvedAuto,
    /// The method cannot integrate this system.
    #[error("method {method} cannot integrate this system: {reason}")]
    Unsupported {
        /// The method.
        method: &'static str,
        /// Why not.
        reason: &'static str,
    },
}

/// How a successful integration ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stop<const N: usize> {
    /// `t_end` was reached.
    Reached,
    /// The event function vanished at `t` with state `y`.
    Event {
        /// Time of the event.
        t: f64,
        /// State at the event (after projection, if any).
        y: [f64; N],
    },
    /// The per-step observer asked to stop (e.g. on Ctrl-C) after the step ending at `t`.
    Stopped {
        /// Time reached.
        t: f64,
    },
}

/// A one-step method as the driver sees it: the taylor, Verner, DOP853 and RK4 integrators
/// implement it. Field evaluations are counted by the stepper in [`Stats::rhs_evals`], in one
/// place per method.
pub trait Stepper<const N: usize> {
    /// Performs one accepted step (rejected attempts are repeated inside); `Ok(true)` when
    /// the step reached `t_end` (then further calls do nothing and return `Ok(true)`).
    fn step(&mut self) -> Result<bool, IntegrateError>;
    /// The run's clock: its time, its end, its last step and its work counters (for the
    /// adaptive methods, their [`StepControl::clock`]).
    fn clock(&self) -> Clock;
    /// Current state (after [`Stepper::set_state`], if called).
    fn y(&self) -> &[f64; N];
    /// The dense output of the last accepted step `[t_prev, t]` at `t` (the step as
    /// integrated, before any `set_state`); before the first step, the initial state.
    fn dense(&self, t: f64) -> [f64; N];
    /// Replaces the current state after a step (a projection).
    fn set_state(&mut self, y: [f64; N]);

    /// Current time (the end of the last step).
    fn t(&self) -> f64 {
        self.clock().t
    }
    /// The end of the integration interval.
    fn t_end(&self) -> f64 {
        self.clock().t_end
    }
    /// Start of the last accepted step (`t0` before the first step).
    fn t_prev(&self) -> f64 {
        self.clock().t_prev
    }
    /// Size of the last accepted step (signed).
    fn h(&self) -> f64 {
        self.clock().h
    }
    /// Work counters so far.
    fn stats(&self) -> Stats {
        self.clock().stats
    }
}

/// The sample callback of [`drive`]: `on_sample(t, y)` at each requested sample time.
pub type OnSample<'a, E, const N: usize> = dyn FnMut(f64, &[f64; N]) -> Result<(), E> + 'a;

/// The per-step observer of [`drive`]: `on_step(t, y, stepper)` after each accepted step.
pub type OnStep<'a, St, E, const N: usize> =
    dyn FnMut(f64, &[f64; N], &St) -> Result<Control, E> + 'a;

/// What the per-step observer of [`drive`] asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Control {
    /// Go on.
    Continue,
    /// Stop after this step ([`Stop::Stopped`]).
    Stop,
}

/// What [`drive`] does besides stepping: dense samples, a projection after each step, an
/// event function.
#[derive(Clone, Copy)]
pub struct Drive<'a, const N: usize> {
    /// Times where the state is reported, strictly monotone in the direction of integration,
    /// within `[t0, t_end]` (see [`check_samples`]).
    pub samples: &'a [f64],
    /// Projection after each accepted step.
    pub project: Option<Projection<'a, N>>,
    /// The run stops at the first sign change of this function after `t0`.
    pub event: Option<EventFn<'a, N>>,
}

impl<const N: usize> Default for Drive<'_, N> {
    fn default() -> Self {
        Drive {
            samples: &[],
            project: None,
            event: None,
        }
    }
}

/// How a run of [`drive`] ended, the final time and state, and the work counters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome<const N: usize> {
    /// Why it stopped.
    pub stop: Stop<N>,
    /// Final time.
    pub t: f64,
    /// Final state.
    pub y: [f64; N],
    /// Work counters.
    pub stats: Stats,
}

/// The checks of a stepper's start: `t0` and `t_end` finite
/// ([`IntegrateError::InvalidOption`] naming them), `y0` finite ([`IntegrateError::NonFinite`]).
pub(crate) fn check_start<const N: usize>(
    t0: f64,
    y0: &[f64; N],
    t_end: f64,
) -> Result<(), IntegrateError> {
    for (name, value) in [("t0", t0), ("t_end", t_end)] {
        if !value.is_finite() {
            return Err(IntegrateError::InvalidOption {
                name,
                value,
                rule: "must be finite",
            });
        }
    }
    if y0.iter().any(|v| !v.is_finite()) {
        return Err(IntegrateError::NonFinite { t: t0 });
    }
    Ok(())
}

/// Checks that `samples` are finite, strictly monotone in the direction from `t0` to
/// `t_end` and within the closed interval; names the first offending sample.
pub fn check_samples(t0: f64, t_end: f64, samples: &[f64]) -> Result<(), IntegrateError> {
    let dir = if t_end >= t0 { 1.0 } else { -1.0 };
    let mut prev = None;
    for &s in samples {
        let inside = s.is_finite() && (s - t0) * dir >= 0.0 && (t_end - s) * dir >= 0.0;
        let monotone = prev.is_none_or(|p: f64| (s - p) * dir > 0.0);
        if !inside || !monotone {
            return Err(IntegrateError::InvalidOption {
                name: "samples",
                value: s,
                rule: "must be strictly monotone in the direction of integration and within [t0, t_end]",
            });
        }
        prev = Some(s);
    }
    Ok(())
}

/// The step loop: steps `stepper` to its `t_end`.
///
/// After every accepted step, in this order: if `event` changes sign on the step, its zero is
/// located on the dense output by [`locate`] (Brent's method to about 2 ulp of `t`), the
/// state there is projected, the samples before it are reported, `on_step` sees it and the
/// run ends with [`Stop::Event`]; otherwise the step end is projected (`set_state`), the samples up to it
/// are reported through `on_sample` from the dense output (a sample on the step end gets the
/// projected state), and `on_step(t, y, stepper)` sees the step end (and the stepper, for its
/// dense output on the step) and may stop the run. A zero of
/// `event` exactly at `t0` is not an event; samples at `t0` are reported first. Errors of the
/// stepper are converted into `E`; errors of the callbacks end the run.
pub fn drive<St: Stepper<N> + ?Sized, E: From<IntegrateError>, const N: usize>(
    stepper: &mut St,
    run: &Drive<'_, N>,
    on_sample: &mut OnSample<'_, E, N>,
    on_step: &mut OnStep<'_, St, E, N>,
) -> Result<Outcome<N>, E> {
    let (t0, t_end, y0) = (stepper.t(), stepper.t_end(), *stepper.y());
    let dir = if t_end >= t0 { 1.0 } else { -1.0 };
    let samples = run.samples;
    let mut next = 0;
    while next < samples.len() && samples[next] == t0 {
        on_sample(t0, &y0)?;
        next += 1;
    }
    let mut g_prev = run.event.map(|g| g(t0, &y0));
    loop {
        let done = stepper.step()?;
        let t = stepper.t();
        if let (Some(g), Some(g0)) = (run.event, g_prev) {
            let ta = stepper.t_prev();
            let g1 = g(t, stepper.y());
            let found = locate(
                &|s| stepper.dense(s),
                (ta, t),
                &[EventSpec {
                    direction: Direction::Either,
                    terminal: true,
                }],
                &mut |_, s, y| g(s, y),
                &[g0],
                &[g1],
            )
            .map_err(|_| IntegrateError::NonFinite { t })?;
            if let Some(&Crossing { t: te, .. }) = found.first() {
                let mut ye = if te == t {
                    *stepper.y()
                } else {
                    stepper.dense(te)
                };
                if let Some(p) = run.project {
                    p(&mut ye);
                }
                while next < samples.len() && (samples[next] - te) * dir < 0.0 {
                    on_sample(samples[next], &stepper.dense(samples[next]))?;
                    next += 1;
                }
                on_step(te, &ye, stepper)?;
                return Ok(Outcome {
                    stop: Stop::Event { t: te, y: ye },
                    t: te,
                    y: ye,
                    stats: stepper.stats(),
                });
            }
        }
        if let Some(p) = run.project {
            let mut y = *stepper.y();
            p(&mut y);
            // A projection that leaves the state as it is (bit for bit; e.g. one that
            // projects every n-th step only) keeps the stepper's carried state (the field at
            // the step end, the compensation of the update).
            if y.map(f64::to_bits) != stepper.y().map(f64::to_bits) {
                stepper.set_state(y);
            }
        }
        if let Some(g) = run.event {
            g_prev = Some(g(t, stepper.y()));
        }
        while next < samples.len() && (samples[next] - t) * dir <= 0.0 {
            let s = samples[next];
            let y = if s == t {
                *stepper.y()
            } else {
                stepper.dense(s)
            };
            on_sample(s, &y)?;
            next += 1;
        }
        let control = on_step(t, stepper.y(), stepper)?;
        let stop = match (control, done) {
            (Control::Stop, false) => Stop::Stopped { t },
            (_, true) => Stop::Reached,
            (Control::Continue, false) => continue,
        };
        return Ok(Outcome {
            stop,
            t,
            y: *stepper.y(),
            stats: stepper.stats(),
        });
    }
}

/// A projection of the state onto invariant manifolds, applied in place.
pub type Projection<'p, const N: usize> = &'p dyn Fn(&mut [f64; N]);

/// An event function `g(t, y)`; an event is a sign change of `g`.
pub type EventFn<'e, const N: usize> = &'e dyn Fn(f64, &[f64; N]) -> f64;

/// Integrates from `t0` to `t_end` with DOP853 (one use of [`drive`]).
///
/// After every accepted step, `project(&mut y)` (if given) replaces the state
/// through [`Dop853::set_state`], and `observer(t, &y)` is called with the
/// (projected) state at the end of the step; it is not called at `t0`.
///
/// If `event` is given, the first sign change of `event(t, y)` after `t0` is
/// located on the dense output of the step where it occurs (Brent's method to
/// about 2 ulp of `t`); the integration stops there, the event state is
/// projected, passed to `observer` and returned in [`Stop::Event`]. A zero of
/// `event` exactly at `t0` is not an event.
///
/// Returns how it ended, the final state, the final time and the work counters.
#[allow(clippy::too_many_arguments)] // the argument list is the agreed API
pub fn solve<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    opts: &Options,
    project: Option<Projection<'_, N>>,
    event: Option<EventFn<'_, N>>,
    observer: &mut dyn FnMut(f64, &[f64; N]),
) -> Result<(Stop<N>, [f64; N], f64, Stats), IntegrateError> {
    let mut solver = Dop853::new(sys, t0, y0, t_end, opts)?;
    let run = Drive {
        samples: &[],
        project,
        event,
    };
    let outcome = drive(&mut solver, &run, &mut |_, _| Ok(()), &mut |t, y, _| {
        observer(t, y);
        Ok(Control::Continue)
    })?;
    Ok((outcome.stop, outcome.y, outcome.t, outcome.stats))
}

/// Integrates from `t0` to `t_end` with DOP853 and reports the solution at the
/// prescribed `samples` through `on_sample(t, &y)`, using the dense output
/// (a sample falling on a step end gets the projected step-end state); one use of [`drive`].
///
/// `samples` must be strictly monotone in the direction of integration and lie
/// in the closed interval between `t0` and `t_end`; otherwise an
/// [`IntegrateError::InvalidOption`] naming the first offending sample is
/// returned before any integration. `project` is applied after each accepted
/// step as in [`solve`]; the dense output on a step interpolates the
/// unprojected step, starting from the projected state of the previous step.
///
/// Returns the final state (at `t_end`) and the work counters.
#[allow(clippy::too_many_arguments)] // the argument list is the agreed API
pub fn solve_dense<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    opts: &Options,
    project: Option<Projection<'_, N>>,
    samples: &[f64],
    on_sample: &mut dyn FnMut(f64, &[f64; N]),
) -> Result<([f64; N], Stats), IntegrateError> {
    check_samples(t0, t_end, samples)?;
    let mut solver = Dop853::new(sys, t0, y0, t_end, opts)?;
    let run = Drive {
        samples,
        project,
        event: None,
    };
    let outcome = drive(
        &mut solver,
        &run,
        &mut |t, y| {
            on_sample(t, y);
            Ok(())
        },
        &mut |_, _, _| Ok(Control::Continue),
    )?;
    Ok((outcome.y, outcome.stats))
}

/// The examples of the crate's README, compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
