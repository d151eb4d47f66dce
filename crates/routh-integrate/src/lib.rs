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
//! * [`brent`]: a bracketing scalar root finder; [`locate_into`]: the one event locator (the
//!   crossings of several event functions on a step's dense output, into a list kept from
//!   step to step), [`locate`] the same into a new list.
//! * [`variational`]: the variational equations of a field written over
//!   [`Scalar`](scalar::Scalar) (the tangent flow by automatic differentiation of the same
//!   field), the monodromy matrix and Floquet multipliers of a periodic orbit.
//! * [`section`]: Poincaré sections, the crossings of many runs (in lanes) with a surface,
//!   located by [`locate`];
//! * [`lyapunov`]: Lyapunov spectra by the QR method on the variational equations, with
//!   their convergence, the Kaplan–Yorke dimension and the average divergence of the field;
//! * [`megno`]: the fast indicators MEGNO (and its mean) and FLI along one orbit.
//!
//! The integrators know nothing of the model: they only see an [`OdeSystem`].

pub mod batch;
pub mod compensated;
pub mod control;
pub mod differential;
mod dop853;
mod event;
pub mod lyapunov;
pub mod megno;
mod pair;
mod rk4;
pub mod sampling;
pub mod scalar;
pub mod section;
pub mod tableau;
pub mod taylor;
pub mod variational;
mod vern9;
pub mod vern9_tableau;

use std::convert::Infallible;
use std::fmt;
use std::str::FromStr;

pub use control::{Clock, Law, StepControl};
pub(crate) use dop853::scaled_error;
pub use dop853::{fixed_step_solve, Dop853};
pub use event::{brent, locate, locate_into, Crossing, Direction, EventSpec, Unlocated};
pub(crate) use pair::rk_start;
pub use pair::{hinit, RkStart, RungeKutta};
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

    /// The units of a run from `y0` ([`RunUnits`]): of each component, in which the absolute
    /// tolerance is measured (the adaptive methods keep the local error of component `i`
    /// below about `(atol + rtol |y_i| / u_i) u_i` and size their Taylor series by
    /// `|y_i| / u_i`), and of time, in which Hairer's initial step guess is made. A system
    /// whose components have scales of their own (a momentum in the units of the motion)
    /// returns them, so that the same motion written in other units is integrated with the
    /// same steps: with units that are powers of two, to the bit (DOP853, Vern9) or to the
    /// rounding of the Taylor method's step formula. All 1 (the default): the units the
    /// components are written in.
    fn units(&self, _y0: &[f64; N]) -> RunUnits<N> {
        RunUnits::one()
    }
}

/// The units of a run ([`OdeSystem::units`]): of time and of each component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunUnits<const N: usize> {
    /// The unit of time.
    pub time: f64,
    /// The unit of each component.
    pub components: [f64; N],
}

impl<const N: usize> RunUnits<N> {
    /// Every unit 1: the units the problem is written in.
    pub fn one() -> Self {
        RunUnits {
            time: 1.0,
            components: [1.0; N],
        }
    }
}

/// The scales of a run: the inverses `1 / u_i` of the units of its components
/// ([`OdeSystem::units`]), by which each component is multiplied to be measured against the
/// absolute tolerance, and the unit of time rounded to a power of two `2^e` (so that times
/// and rates are converted to it exactly). A unit that is not a finite positive number with a
/// finite positive inverse is taken as 1 (that component, or time, is measured in the units
/// it is written in). The one place where the steppers and the lanes turn units into the
/// weights of the error norm, the sizes of the Taylor series and the first step's units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales<const N: usize> {
    inverse: [f64; N],
    /// `e`, the unit of time being `2^e`.
    time_exponent: i32,
}

/// `u` if it and its inverse are finite and positive, else 1.
fn usable(u: f64) -> f64 {
    let inverse = 1.0 / u;
    if u > 0.0 && u.is_finite() && inverse.is_finite() && inverse > 0.0 {
        u
    } else {
        1.0
    }
}

/// `x 2^e`, exact unless the result leaves the normal range (the power applied in parts,
/// so that no factor overflows or underflows on its own).
#[inline(always)]
fn times_power_of_two(mut x: f64, mut e: i32) -> f64 {
    const PART: i32 = 1000;
    while e > PART {
        x *= power_of_two(PART);
        e -= PART;
    }
    while e < -PART {
        x *= power_of_two(-PART);
        e += PART;
    }
    x * power_of_two(e)
}

/// `2^e` for `|e| <= 1000`, made of its exponent's bits ([`taylor::elementary::two_to`]:
/// exactly `2f64.powi(e)`, without the library call, which took 3 % of the Taylor lanes' time
/// at two a lane and step).
#[inline(always)]
fn power_of_two(e: i32) -> f64 {
    debug_assert!(e.abs() <= 1000);
    taylor::elementary::two_to(f64::from(e))
}

impl<const N: usize> Scales<N> {
    /// The scales of a run with the units `units`.
    pub fn of_units(units: &RunUnits<N>) -> Self {
        Scales {
            inverse: units.components.map(|u| 1.0 / usable(u)),
            time_exponent: usable(units.time).log2().round() as i32,
        }
    }

    /// The units the problem is written in (every scale 1).
    pub fn one() -> Self {
        Scales::of_units(&RunUnits::one())
    }

    /// The scale of component `i`, `1 / u_i`.
    #[inline(always)]
    pub fn of(&self, i: usize) -> f64 {
        self.inverse[i]
    }

    /// The unit of time `T = 2^e`.
    pub fn time(&self) -> f64 {
        times_power_of_two(1.0, self.time_exponent)
    }

    /// `x T^k`: a quantity of `k` dimensions of time (or `-k` of rate) in the unit of time,
    /// exactly.
    #[inline(always)]
    pub fn in_time_unit(&self, x: f64, k: i32) -> f64 {
        times_power_of_two(x, k.saturating_mul(self.time_exponent))
    }

    /// `||v / u||_inf`: the largest component of `v` measured in its unit.
    #[inline(always)]
    pub fn max_norm(&self, v: impl Iterator<Item = f64>) -> f64 {
        v.zip(self.inverse)
            .fold(0.0, |m, (x, s)| m.max(x.abs() * s))
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

/// Options of the adaptive integrator, valid once built: [`Options::new`] and the `with_*`
/// setters refuse a value that breaks its rule ([`IntegrateError::InvalidOption`] naming it),
/// so that a stepper never sees invalid options.
///
/// The local error of component `i` is kept below roughly
/// `atol + rtol * |y_i|` (scalar tolerances, Hairer's `ITOL = 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    rtol: f64,
    atol: f64,
    h_init: Option<f64>,
    h_max: Option<f64>,
    max_steps: usize,
    compensated: bool,
}

impl Default for Options {
    /// `rtol = atol = 1e-10`, the initial step by `HINIT`, no step limit but `|t_end - t0|`,
    /// at most 10,000,000 steps, the compensated update.
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

/// `value` when it is finite and > 0, else [`IntegrateError::InvalidOption`] naming `name`.
fn positive(name: &'static str, value: f64) -> Result<f64, IntegrateError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(IntegrateError::InvalidOption {
            name,
            value,
            rule: "must be finite and > 0",
        })
    }
}

impl Options {
    /// The default options with the tolerances `rtol` and `atol` (each finite and > 0).
    pub fn new(rtol: f64, atol: f64) -> Result<Options, IntegrateError> {
        Ok(Options {
            rtol: positive("rtol", rtol)?,
            atol: positive("atol", atol)?,
            ..Options::default()
        })
    }

    /// The same options with the initial step size `h` (its sign is ignored; `|h|` finite and
    /// > 0).
    pub fn with_h_init(self, h: f64) -> Result<Options, IntegrateError> {
        positive("h_init (absolute value)", h.abs())?;
        Ok(Options {
            h_init: Some(h),
            ..self
        })
    }

    /// The same options with the maximal step size `h` (finite and > 0).
    pub fn with_h_max(self, h: f64) -> Result<Options, IntegrateError> {
        Ok(Options {
            h_max: Some(positive("h_max", h)?),
            ..self
        })
    }

    /// The same options with at most `max_steps` attempted steps (> 0).
    pub fn with_max_steps(self, max_steps: usize) -> Result<Options, IntegrateError> {
        if max_steps == 0 {
            return Err(IntegrateError::InvalidOption {
                name: "max_steps",
                value: 0.0,
                rule: "must be > 0",
            });
        }
        Ok(Options { max_steps, ..self })
    }

    /// The same options with the update summed with compensation or not
    /// ([`Options::compensated`]).
    pub fn with_compensated(self, compensated: bool) -> Options {
        Options {
            compensated,
            ..self
        }
    }

    /// Relative tolerance (finite, > 0).
    pub fn rtol(&self) -> f64 {
        self.rtol
    }

    /// Absolute tolerance (finite, > 0).
    pub fn atol(&self) -> f64 {
        self.atol
    }

    /// Initial step size (its sign is ignored); `None` selects it by Hairer's `HINIT`.
    pub fn h_init(&self) -> Option<f64> {
        self.h_init
    }

    /// Maximal step size; `None` means `|t_end - t0|`.
    pub fn h_max(&self) -> Option<f64> {
        self.h_max
    }

    /// Maximal number of attempted steps (accepted and rejected).
    pub fn max_steps(&self) -> usize {
        self.max_steps
    }

    /// Sum the update `y + h sum b_i k_i` with compensation ([`compensated::compensated_add`]);
    /// `false` gives the plain sum of the published codes (bit-for-bit comparisons with them).
    pub fn compensated(&self) -> bool {
        self.compensated
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
    /// The tangent vectors of the Lyapunov exponents ([`lyapunov::spectrum`]) became linearly
    /// dependent: more of them than the dimension of the space the projection leaves them.
    #[error("the tangent vectors became linearly dependent at t = {t} (more vectors than the dimension of the projected tangent space?)")]
    DependentTangents {
        /// Time of the renormalisation that found them dependent.
        t: f64,
    },
    /// The method cannot integrate this system.
    #[error("method {method} cannot integrate this system: {reason}")]
    Unsupported {
        /// The method.
        method: &'static str,
        /// Why not.
        reason: &'static str,
    },
}

/// How a run of [`drive`] ended; the time and state where it ended are the [`Outcome`]'s.
#[derive(Debug, Clone, PartialEq)]
pub enum Stop {
    /// `t_end` was reached.
    Reached,
    /// The event function vanished (the state there projected, if a projection is given).
    Event,
    /// The per-step observer asked to stop: after the step ([`Control::Stop`], e.g. on
    /// Ctrl-C) or within it ([`Control::StopAt`]).
    Stopped,
    /// The stepper failed, or a state was not finite: the run ended at the last step it
    /// reached.
    Failed(IntegrateError),
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
    dyn FnMut(f64, &[f64; N], &St) -> Result<Control<N>, E> + 'a;

/// What the per-step observer of [`drive`] asks for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Control<const N: usize> {
    /// Go on.
    Continue,
    /// Stop after this step ([`Stop::Stopped`]).
    Stop,
    /// Stop at the time `t` within this step, with the state `y` there (e.g. an event the
    /// observer located on the step's dense output, projected as it wishes): the samples
    /// after `t` are not reported and the run ends at `(t, y)` ([`Stop::Stopped`]).
    StopAt {
        /// The time within the step.
        t: f64,
        /// The state there, as the run ends with it.
        y: [f64; N],
    },
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
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome<const N: usize> {
    /// Why it stopped.
    pub stop: Stop,
    /// Final time.
    pub t: f64,
    /// Final state.
    pub y: [f64; N],
    /// Work counters.
    pub stats: Stats,
}

impl<const N: usize> Outcome<N> {
    /// The outcome of a run that did not fail, or its failure ([`Stop::Failed`]) as an error.
    pub fn into_result(self) -> Result<Outcome<N>, IntegrateError> {
        match self.stop {
            Stop::Failed(e) => Err(e),
            _ => Ok(self),
        }
    }
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
/// located on the dense output by [`locate`] (Brent's method to about 2 ulp of `t`) and the
/// state there is projected, and the run ends there ([`Stop::Event`]); otherwise the step end
/// is projected (`set_state`). Then `on_step(t, y, stepper)` sees that point, the event or the
/// step end (and the stepper, for its dense output on the step), and may stop the run after
/// the step or at a time within it ([`Control`]). Then the samples of the step are reported
/// through `on_sample` from the dense output (a sample on the step end gets the projected
/// state): those before the event, or up to the step end, and none after a
/// [`Control::StopAt`]. The observer sees a step before its samples, so that it can end the
/// run within the step. A zero of `event` exactly at `t0` is not an event; samples at `t0` are
/// reported first.
///
/// A failure of the stepper, an event that cannot be located (its function not finite on the
/// step) and a state that is not finite (the event's or the step end's, after projection) end
/// the run with [`Stop::Failed`], at the time and state the stepper reached, without the
/// samples of the failed step. Errors of the callbacks end the run and are returned as they
/// are: they are the only `Err`.
pub fn drive<St: Stepper<N> + ?Sized, E, const N: usize>(
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
    let failed = |stepper: &St, e: IntegrateError| Outcome {
        stop: Stop::Failed(e),
        t: stepper.t(),
        y: *stepper.y(),
        stats: stepper.stats(),
    };
    let mut g_prev = run.event.map(|g| g(t0, &y0));
    loop {
        let done = match stepper.step() {
            Ok(done) => done,
            Err(e) => return Ok(failed(stepper, e)),
        };
        let t = stepper.t();
        let event = match (run.event, g_prev) {
            (Some(g), Some(g0)) => match event_on_step(stepper, g, g0, run.project) {
                Ok(event) => event,
                Err(e) => return Ok(failed(stepper, e)),
            },
            _ => None,
        };
        let (t_seen, y_seen) = match event {
            Some(event) => event,
            None => {
                if let Some(p) = run.project {
                    let mut y = *stepper.y();
                    p(&mut y);
                    // A projection that leaves the state as it is (bit for bit; e.g. one that
                    // projects every n-th step only) keeps the stepper's carried state (the
                    // field at the step end, the compensation of the update).
                    if y.map(f64::to_bits) != stepper.y().map(f64::to_bits) {
                        stepper.set_state(y);
                    }
                }
                if let Some(g) = run.event {
                    g_prev = Some(g(t, stepper.y()));
                }
                (t, *stepper.y())
            }
        };
        if y_seen.iter().any(|v| !v.is_finite()) {
            return Ok(failed(stepper, IntegrateError::NonFinite { t: t_seen }));
        }
        let control = on_step(t_seen, &y_seen, stepper)?;
        let stop_at = match control {
            Control::StopAt { t, y } => Some((t, y)),
            Control::Continue | Control::Stop => None,
        };
        while let Some(&s) = samples.get(next) {
            let on_the_step = match event {
                Some((te, _)) => (s - te) * dir < 0.0,
                None => (s - t) * dir <= 0.0,
            };
            if !on_the_step || stop_at.is_some_and(|(ts, _)| (s - ts) * dir > 0.0) {
                break;
            }
            let y = if s == t {
                *stepper.y()
            } else {
                stepper.dense(s)
            };
            on_sample(s, &y)?;
            next += 1;
        }
        let (stop, t, y) = match (stop_at, event) {
            (Some((ts, ys)), _) => (Stop::Stopped, ts, ys),
            (None, Some((te, ye))) => (Stop::Event, te, ye),
            (None, None) if done => (Stop::Reached, t, y_seen),
            (None, None) if control == Control::Stop => (Stop::Stopped, t, y_seen),
            (None, None) => continue,
        };
        return Ok(Outcome {
            stop,
            t,
            y,
            stats: stepper.stats(),
        });
    }
}

/// The first zero of the event function `g` on the last step of `stepper` (`g0` its value at
/// the step's start), located by [`locate`], and the state there projected by `project`;
/// `None` without a sign change. An event that cannot be located (`g` not finite on the step)
/// is [`IntegrateError::NonFinite`] at the step end.
fn event_on_step<St: Stepper<N> + ?Sized, const N: usize>(
    stepper: &St,
    g: EventFn<'_, N>,
    g0: f64,
    project: Option<Projection<'_, N>>,
) -> Result<Option<(f64, [f64; N])>, IntegrateError> {
    let (ta, t) = (stepper.t_prev(), stepper.t());
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
    Ok(found.first().map(|&Crossing { t: te, .. }| {
        let mut ye = if te == t {
            *stepper.y()
        } else {
            stepper.dense(te)
        };
        if let Some(p) = project {
            p(&mut ye);
        }
        (te, ye)
    }))
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
/// projected, passed to `observer`, and the run ends with [`Stop::Event`] there. A zero of
/// `event` exactly at `t0` is not an event.
///
/// Returns how it ended ([`Stop::Reached`] or [`Stop::Event`]), the final state, the final
/// time and the work counters; a failure of the integrator is the error.
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
) -> Result<(Stop, [f64; N], f64, Stats), IntegrateError> {
    let mut solver = Dop853::new(sys, t0, y0, t_end, opts)?;
    let run = Drive {
        samples: &[],
        project,
        event,
    };
    let Ok(outcome) =
        drive::<_, Infallible, N>(&mut solver, &run, &mut |_, _| Ok(()), &mut |t, y, _| {
            observer(t, y);
            Ok(Control::Continue)
        });
    let outcome = outcome.into_result()?;
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
    let Ok(outcome) = drive::<_, Infallible, N>(
        &mut solver,
        &run,
        &mut |t, y| {
            on_sample(t, y);
            Ok(())
        },
        &mut |_, _, _| Ok(Control::Continue),
    );
    let outcome = outcome.into_result()?;
    Ok((outcome.y, outcome.stats))
}

/// The examples of the crate's README, compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

#[cfg(test)]
mod tests {
    use super::{power_of_two, times_power_of_two};

    /// The powers of two made of their bits are the library's `powi`, bit for bit, over the
    /// whole range they are used in; and `x 2^e` beyond it is applied in exact parts (a
    /// factor 2^2000 then 2^-2000 gives `x` back).
    #[test]
    fn powers_of_two_are_the_library_s_to_the_bit() {
        for e in -1000..=1000 {
            assert_eq!(power_of_two(e).to_bits(), 2f64.powi(e).to_bits(), "2^{e}");
        }
        let x = 0.3_f64;
        let there = times_power_of_two(x * 2f64.powi(-1000), 2000);
        assert_eq!(times_power_of_two(there, -2000), x * 2f64.powi(-1000));
        assert_eq!(times_power_of_two(1.5, 1030), f64::INFINITY);
    }
}
