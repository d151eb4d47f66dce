//! Integration of a case along the field (mg-eq), with the integrals (int-g), (raus-int)
//! tracked at every step, dense-output samples, and optional projection onto their level set.

use crate::auto;
use crate::ball::AsBall;
use crate::body::Body;
use crate::error::{Number, Result, RouthError};
use crate::integrals::{Integrals, ALL_INTEGRAL_DIMENSIONS, ALL_INTEGRAL_NAMES};
use crate::integrate::taylor::Var;
use crate::integrate::{
    check_samples, drive, stepper, Control, Drive, EventFn, Method, OdeSystem, OnSample, Options,
    Projection, Stepper, Stop,
};
use crate::projection::LevelSet;
use crate::state::Point;
use crate::units::{Dimension, Units};
use serde::Serialize;
use std::cell::RefCell;

/// Settings of one simulation, validated when built: a value of this type holds no invalid
/// setting (the rules of [`SettingsBuilder::build`], the one check of settings of the
/// library, the commands, the sweep, case files and Python), so a run takes it as it is.
/// Built from the defaults by [`Settings::builder`], or from other settings by
/// [`Settings::to_builder`] (a case's, say, with the command line's overrides).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Settings {
    method: Method,
    t_end: f64,
    rtol: f64,
    atol: f64,
    project: bool,
    project_every: usize,
    samples: usize,
    max_steps: usize,
}

impl Settings {
    /// The defaults ([`Settings::default`]) to change and build.
    pub fn builder() -> SettingsBuilder {
        Settings::default().to_builder()
    }

    /// These settings to change and build again.
    pub fn to_builder(self) -> SettingsBuilder {
        SettingsBuilder { unchecked: self }
    }

    /// The integrator.
    pub fn method(&self) -> Method {
        self.method
    }

    /// Final time (the start is t = 0).
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// Relative tolerance (DOP853).
    pub fn rtol(&self) -> f64 {
        self.rtol
    }

    /// Absolute tolerance, on gamma and on M in the case's units.
    pub fn atol(&self) -> f64 {
        self.atol
    }

    /// Project onto the level set of the integrals after each step.
    pub fn project(&self) -> bool {
        self.project
    }

    /// With `project`, project after every `project_every`-th accepted step only (at least
    /// 1: every step). The drift of the integrals between two projections is that of as many
    /// steps, so every 10th step keeps nearly all of the accuracy that projection gains, at a
    /// tenth of its cost (BENCHMARKS.md, "Work-precision"). Samples are
    /// projected whatever the step.
    pub fn project_every(&self) -> usize {
        self.project_every
    }

    /// Number of equally spaced dense-output samples on [0, t_end] (including both ends):
    /// 0, or 2 to [`MAX_SAMPLES`].
    pub fn samples(&self) -> usize {
        self.samples
    }

    /// Most steps DOP853 may attempt (accepted and rejected), and most steps of RK4.
    pub fn max_steps(&self) -> usize {
        self.max_steps
    }

    /// The times of the [`Settings::samples`]: equally spaced on `[0, t_end]`, the last one
    /// `t_end` itself (none without samples).
    pub fn sample_times(&self) -> Vec<f64> {
        (0..self.samples)
            .map(|i| {
                if i + 1 == self.samples {
                    self.t_end
                } else {
                    self.t_end * i as f64 / (self.samples - 1) as f64
                }
            })
            .collect()
    }
}

/// [`Settings`] being built: any values, checked once, by [`SettingsBuilder::build`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use]
pub struct SettingsBuilder {
    unchecked: Settings,
}

impl SettingsBuilder {
    /// The integrator ([`Settings::method`]).
    pub fn method(mut self, method: Method) -> Self {
        self.unchecked.method = method;
        self
    }

    /// Final time ([`Settings::t_end`]).
    pub fn t_end(mut self, t_end: f64) -> Self {
        self.unchecked.t_end = t_end;
        self
    }

    /// Relative and absolute tolerance ([`Settings::rtol`], [`Settings::atol`]).
    pub fn tolerances(mut self, rtol: f64, atol: f64) -> Self {
        self.unchecked.rtol = rtol;
        self.unchecked.atol = atol;
        self
    }

    /// Projection, after every `every`-th step ([`Settings::project`],
    /// [`Settings::project_every`]).
    pub fn projection(mut self, project: bool, every: usize) -> Self {
        self.unchecked.project = project;
        self.unchecked.project_every = every;
        self
    }

    /// Number of samples ([`Settings::samples`]).
    pub fn samples(mut self, samples: usize) -> Self {
        self.unchecked.samples = samples;
        self
    }

    /// Most steps ([`Settings::max_steps`]).
    pub fn max_steps(mut self, max_steps: usize) -> Self {
        self.unchecked.max_steps = max_steps;
        self
    }

    /// The settings, if valid: t_end finite and >= 0, the tolerances by
    /// [`check_tolerances`], max_steps >= 1, samples at most [`MAX_SAMPLES`],
    /// project_every >= 1, the steps of RK4 at most max_steps, samples 0 or >= 2, and a
    /// positive t_end with samples (their times distinct: t_end / (samples - 1) a normal f64).
    /// The first violation, in this order, is the error, naming the option.
    pub fn build(self) -> Result<Settings> {
        let settings = self.unchecked;
        check_option(
            "t_end",
            settings.t_end,
            settings.t_end.is_finite() && settings.t_end >= 0.0,
            "must be finite and >= 0",
        )?;
        check_tolerances(settings.rtol, settings.atol)?;
        if settings.max_steps == 0 {
            return Err(RouthError::Option {
                name: "max_steps",
                value: "0".into(),
                rule: "must be >= 1",
            });
        }
        if settings.samples > MAX_SAMPLES {
            return Err(RouthError::Option {
                name: "samples",
                value: settings.samples.to_string(),
                rule: "must be at most 10000000 (MAX_SAMPLES)",
            });
        }
        if settings.project_every == 0 {
            return Err(RouthError::Option {
                name: "project_every",
                value: "0".into(),
                rule: "must be at least 1 (project after every step)",
            });
        }
        if let Method::Rk4 { steps } = settings.method {
            if steps > settings.max_steps {
                return Err(RouthError::Option {
                    name: "method rk4:<steps>",
                    value: steps.to_string(),
                    rule: "must not exceed max_steps (--max-steps, default 10000000)",
                });
            }
        }
        if settings.samples == 1 {
            return Err(RouthError::Option {
                name: "samples",
                value: "1".into(),
                rule: "must be 0 or >= 2 (the samples include both ends)",
            });
        }
        if settings.samples >= 2 {
            check_option(
                "t_end",
                settings.t_end,
                settings.t_end / (settings.samples - 1) as f64 >= f64::MIN_POSITIVE,
                "must be > 0 when samples are asked for (samples >= 2): t_end = 0 makes the \
                 span [0, t_end] empty, and samples need distinct times (t_end / (samples - 1) \
                 at least the smallest normal f64, 2.2250738585072014e-308)",
            )?;
        }
        Ok(settings)
    }
}

/// The largest number of samples of one run (their times take 8 bytes each in memory, the
/// CSV about 300 bytes each on disk: 3 GB).
pub const MAX_SAMPLES: usize = 10_000_000;

/// The default limit of steps of one integration (`--max-steps`, `max_steps` in
/// `[integration]`): about 40 s of DOP853 on this machine; a run that needs more is stopped
/// with a message naming the limit.
pub const DEFAULT_MAX_STEPS: usize = 10_000_000;

/// The drift of one integral along the trajectory.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Drift {
    /// Value at t = 0.
    pub initial: f64,
    /// Value at t_end.
    #[serde(rename = "final")]
    pub last: f64,
    /// `max_t |H(t) - H(0)| / |H(0)|` over all step ends and samples; where `H(0) = 0`,
    /// `max_t |H(t)|` in the unit of H's dimension (of R, m and the motion's time:
    /// [`Units::of_dimension`]), so that the same motion in other units drifts as much.
    pub max_rel_drift: f64,
    /// What the drift is measured in: `|H(0)|`, or the unit where `H(0) = 0`.
    #[serde(skip)]
    scale: f64,
}

impl Drift {
    /// The drift of an integral worth `initial` at t = 0, whose dimension has the unit
    /// `unit()` in the units of the motion (of its body and initial state: [`Units::of`],
    /// [`Units::of_dimension`]; asked for only where `initial = 0`).
    pub fn start(initial: f64, unit: impl FnOnce() -> f64) -> Drift {
        Drift {
            initial,
            last: initial,
            max_rel_drift: 0.0,
            scale: if initial == 0.0 {
                unit()
            } else {
                initial.abs()
            },
        }
    }

    /// What the drift is measured in: `|H(0)|`, or the unit of H's dimension where `H(0) = 0`.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// The integral is worth `h` at a step end or sample.
    #[inline]
    pub fn observe(&mut self, h: f64) {
        self.last = h;
        self.max_rel_drift = self
            .max_rel_drift
            .max((h - self.initial).abs() / self.scale);
    }
}

/// What a simulation reports.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// The method, as `dop853` or `rk4:<steps>`.
    pub method: String,
    /// Final time.
    pub t_end: f64,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Evaluations of the field.
    pub rhs_evals: usize,
    /// Whether states were projected onto the level set of the integrals.
    pub projected: bool,
    /// Projected after every how many steps ([`Settings::project_every`]).
    pub project_every: usize,
    /// The initial state.
    pub initial_state: Point,
    /// The state reached at t_end (or where the run ended).
    pub final_state: Point,
    /// Drift of each integral of the ball's model, by name (H1, H2, H3, H4, K, MM, Mgamma;
    /// see [`Integrals`]).
    pub integrals: std::collections::BTreeMap<&'static str, Drift>,
    /// Wall time of the integration in seconds, measured with [`std::time::Instant`] inside
    /// [`run`]: the steps, the tracking of the integrals, the projections and the samples
    /// (including the time spent in `on_sample`), without process start-up or case parsing.
    /// NaN (`null` in JSON) on wasm32, which has no clock ([`Stopwatch`]).
    pub elapsed_s: f64,
}

/// The wall clock of [`Summary::elapsed_s`]. WebAssembly without a host (wasm32-unknown-unknown,
/// the explorer page's target) has no clock in `std`: `Instant::now` panics there, so a run
/// compiled for it reports NaN and the page times it itself (`performance.now()`).
struct Stopwatch {
    #[cfg(not(target_arch = "wasm32"))]
    start: std::time::Instant,
}

impl Stopwatch {
    fn start() -> Self {
        Stopwatch {
            #[cfg(not(target_arch = "wasm32"))]
            start: std::time::Instant::now(),
        }
    }

    /// Seconds since [`Stopwatch::start`] (NaN on wasm32).
    fn seconds(&self) -> f64 {
        #[cfg(not(target_arch = "wasm32"))]
        return self.start.elapsed().as_secs_f64();
        #[cfg(target_arch = "wasm32")]
        return f64::NAN;
    }
}

/// The drift of the integrals along a run: their values at the start, at the last state seen,
/// and the largest relative change (the `integrals` of a [`Summary`]).
pub struct DriftTracker {
    drift: [Option<Drift>; 7],
}

impl DriftTracker {
    /// Starts at `x0`.
    pub fn new(body: &impl AsBall, x0: &[f64; 6]) -> Self {
        let units = std::cell::OnceCell::new();
        let unit = |d: Dimension| {
            units
                .get_or_init(|| Units::of_motion(body, x0))
                .of_dimension(d)
        };
        let initial = Integrals::at(body, x0).all();
        DriftTracker {
            drift: std::array::from_fn(|i| {
                initial[i].map(|h| Drift::start(h, || unit(ALL_INTEGRAL_DIMENSIONS[i])))
            }),
        }
    }

    /// Looks at the state `x`.
    pub fn observe(&mut self, body: &impl AsBall, x: &[f64; 6]) {
        let now = Integrals::at(body, x).all();
        for (drift, h) in self.drift.iter_mut().zip(now) {
            if let (Some(drift), Some(h)) = (drift.as_mut(), h) {
                drift.observe(h);
            }
        }
    }

    /// The drift of each integral so far.
    pub fn report(&self) -> std::collections::BTreeMap<&'static str, Drift> {
        ALL_INTEGRAL_NAMES
            .into_iter()
            .zip(self.drift)
            .filter_map(|(name, drift)| Some((name, drift?)))
            .collect()
    }
}

/// The reduced phase-space part `(gamma, M)` of a (possibly extended) state.
pub fn reduced<const N: usize>(y: &[f64; N]) -> [f64; 6] {
    std::array::from_fn(|i| y[i])
}

/// Project the reduced part of a (possibly extended) state onto `level`, if given.
pub fn project_onto<const N: usize>(level: Option<&LevelSet>, y: &mut [f64; N]) {
    if let Some(level) = level {
        let mut x = reduced(y);
        level.project(&mut x);
        y[..6].copy_from_slice(&x);
    }
}

/// The projection of the step ends of a run: [`project_onto`] `level` after every
/// `every`-th call (the calls counted from 1; every call for `every = 1`, none without a
/// level). [`Settings::project_every`].
pub fn project_every<const N: usize>(
    level: Option<&LevelSet>,
    every: usize,
) -> impl Fn(&mut [f64; N]) + '_ {
    let calls = std::cell::Cell::new(0usize);
    move |y: &mut [f64; N]| {
        calls.set(calls.get() + 1);
        if calls.get() % every.max(1) == 0 {
            project_onto(level, y);
        }
    }
}

impl Default for Settings {
    /// The one set of defaults of the library, the CLI and Python: DOP853 at
    /// rtol = atol = 1e-12 over [0, 100], no projection, no samples.
    fn default() -> Self {
        Settings {
            method: Method::Dop853,
            t_end: 100.0,
            rtol: 1e-12,
            atol: 1e-12,
            project: false,
            project_every: 1,
            samples: 0,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }
}

/// The largest relative tolerance accepted: above it the integrals drift by whole percents
/// (rtol = 1 lets H2 drift by 40 % over the default case) and the run is not a solution.
pub const MAX_RTOL: f64 = 1e-2;
/// The smallest relative tolerance accepted, 2.2e-14 (about 100 machine epsilons, 99.1):
/// the rounding of each step's update is of the order of a few epsilons of the state, so a
/// smaller local error target is not what the controller can verify. The rule's message
/// prints this value as it is (a test holds them together).
pub const MIN_RTOL: f64 = 2.2e-14;
/// The smallest absolute tolerance accepted, 1e-150: the step control's norms are sums of
/// squares of `error / (atol + rtol |y|)` (Hairer's), which leave the range of f64 (1e308)
/// when a component that starts at 0 is weighed by an atol below about 1e-154 (with
/// atol = 1e-200 or 1e-320 the first step size came out 0).
pub const MIN_ATOL: f64 = 1e-150;

/// Fail with [`RouthError::Option`] unless `ok`.
pub fn check_option(name: &'static str, value: f64, ok: bool, rule: &'static str) -> Result<()> {
    if ok {
        Ok(())
    } else {
        Err(RouthError::Option {
            name,
            value: Number(value).to_string(),
            rule,
        })
    }
}

/// The rule of the tolerances: rtol finite in [[`MIN_RTOL`], [`MAX_RTOL`]); atol finite and
/// at least [`MIN_ATOL`].
pub fn check_tolerances(rtol: f64, atol: f64) -> Result<()> {
    check_option(
        "rtol",
        rtol,
        rtol.is_finite() && rtol > 0.0,
        "must be finite and > 0",
    )?;
    check_option(
        "rtol",
        rtol,
        rtol < MAX_RTOL,
        "must be < 1e-2: a larger relative tolerance lets the integrals drift by whole percents",
    )?;
    check_option(
        "rtol",
        rtol,
        rtol >= MIN_RTOL,
        "must be >= 2.2e-14 (about 100 machine epsilons): below it the step's own rounding \
         exceeds the error the controller asks for",
    )?;
    check_option(
        "atol",
        atol,
        atol.is_finite() && atol > 0.0,
        "must be finite and > 0",
    )?;
    check_option(
        "atol",
        atol,
        atol >= MIN_ATOL,
        "must be >= 1e-150 (the step control squares error / atol: below it those squares \
         leave the range of f64 and the first step size becomes 0)",
    )
}

/// Integrate `sys`, whose state starts with the reduced phase-space point `(gamma, M)`
/// (further components, such as the orientation of the full motion, follow it), from
/// `y0` over `[0, t_end]`. `on_sample(t, y)` receives the equally spaced samples; the
/// integrals are tracked on the reduced part at every step end and sample. A failed
/// integration is an error ([`RouthError::Integrate`]); [`integrate_observed`] tells more
/// (and takes a callback with an error of its own, one that writes a file, say).
pub fn run<S: OdeSystem<N>, const N: usize>(
    body: &impl AsBall,
    sys: &S,
    y0: [f64; N],
    settings: &Settings,
    on_sample: &mut dyn FnMut(f64, &[f64; N]) -> Result<()>,
) -> Result<Summary> {
    integrate_observed(body, sys, y0, settings, None, on_sample, &mut |_| {})?.summary()
}

/// What [`integrate_observed`] and [`integrate_span`] return: the summary, how the run
/// stopped (with the integrator's failure, if any: then the summary holds the state reached),
/// and the time and state reached.
#[derive(Debug, Clone)]
pub struct Observed<const N: usize> {
    /// The summary of the run (up to the failure, if any).
    pub summary: Summary,
    /// How the driver stopped; [`Stop::Failed`] with the integrator's error if it failed.
    pub stop: Stop,
    /// The time reached.
    pub t: f64,
    /// The (whole, possibly extended) state reached.
    pub y: [f64; N],
}

impl<const N: usize> Observed<N> {
    /// The summary of a run that reached its end, or the integrator's failure as an error.
    pub fn summary(self) -> Result<Summary> {
        match self.stop {
            Stop::Failed(e) => Err(e.into()),
            _ => Ok(self.summary),
        }
    }
}

/// The interval and the sample times of [`integrate_span`].
#[derive(Debug, Clone, Copy)]
pub struct Span<'a, const N: usize> {
    /// Start time.
    pub t0: f64,
    /// The state at `t0`.
    pub y0: [f64; N],
    /// End time (before `t0`: backward in time).
    pub t1: f64,
    /// Times where the state is reported, strictly monotone from `t0` towards `t1`, within
    /// the span.
    pub samples: &'a [f64],
}

/// The per-step observer of [`integrate_span`]: `on_step(t, y, stepper)` after each accepted
/// step, with the (projected) step end and the stepper (for its dense output on the step); it
/// may stop the run after the step or within it ([`Control`]).
pub type StepObserver<'a, E, const N: usize> =
    dyn FnMut(f64, &[f64; N], &dyn Stepper<N>) -> std::result::Result<Control<N>, E> + 'a;

/// The one simulation loop behind [`run`] and [`crate::problem::Problem`]: [`integrate_span`]
/// over `[0, settings.t_end()]` with `settings.samples()` equally spaced samples,
/// `on_step(stepper)` called after each step. `E` is the error type of `on_sample`, as in
/// [`integrate_span`]. The settings were checked when built; nothing is checked again here.
#[allow(clippy::too_many_arguments)]
pub fn integrate_observed<S: OdeSystem<N>, E: From<RouthError>, const N: usize>(
    body: &impl AsBall,
    sys: &S,
    y0: [f64; N],
    settings: &Settings,
    event: Option<EventFn<'_, N>>,
    on_sample: &mut OnSample<'_, E, N>,
    on_step: &mut dyn FnMut(&dyn Stepper<N>),
) -> std::result::Result<Observed<N>, E> {
    let times = settings.sample_times();
    let span = Span {
        t0: 0.0,
        y0,
        t1: settings.t_end,
        samples: &times,
    };
    integrate_span(
        body,
        sys,
        &span,
        settings,
        event,
        on_sample,
        &mut |_, _, stepper| {
            on_step(stepper);
            Ok(Control::Continue)
        },
    )
}

/// Integrate `sys`, whose state starts with the reduced phase-space point `(gamma, M)`, over
/// `span` (either direction) with the method, tolerances, projection and step limit of
/// `settings` (its `t_end` and `samples` are not used; the rest was checked when it was
/// built): the one use of the library's driver
/// [`drive`] by `simulate`, [`crate::problem::Problem`], the sweep and Python.
///
/// After each accepted step, as in [`drive`]: a non-finite state ends the run with
/// [`IntegrateError::NonFinite`](crate::integrate::IntegrateError::NonFinite);
/// `on_step(t, y, stepper)` sees the (projected) step end and may stop the run, possibly at a
/// time within the step ([`Control::StopAt`]); the samples up to the end (projected, with
/// `settings.project()`) go to `on_sample`; the integrals are tracked at the samples and the
/// step end. `event` stops the run at its first sign change (as in [`drive`]). A span that is
/// not finite, invalid samples ([`check_samples`]) and errors of the callbacks are errors; a
/// failure of the integrator is reported in [`Observed::stop`] ([`Stop::Failed`]) with the
/// state reached. The callbacks' error type `E` (the library's [`RouthError`], or one holding
/// it, such as the front ends' `AppError`) is the error type of the result.
#[allow(clippy::too_many_arguments)]
pub fn integrate_span<S: OdeSystem<N>, E: From<RouthError>, const N: usize>(
    body: &impl AsBall,
    sys: &S,
    span: &Span<'_, N>,
    settings: &Settings,
    event: Option<EventFn<'_, N>>,
    on_sample: &mut OnSample<'_, E, N>,
    on_step: &mut StepObserver<'_, E, N>,
) -> std::result::Result<Observed<N>, E> {
    let Span {
        t0,
        y0,
        t1,
        samples,
    } = *span;
    if !(t1 - t0).is_finite() {
        return Err(RouthError::Option {
            name: "t_span",
            value: format!("({t0}, {t1})"),
            rule: "must be finite (t0, t1 and t1 - t0)",
        }
        .into());
    }
    check_samples(t0, t1, samples).map_err(RouthError::from)?;
    let start = Stopwatch::start();
    let x0 = reduced(&y0);
    let level = settings.project.then(|| LevelSet::through(body, &x0));
    let project = |y: &mut [f64; N]| project_onto(level.as_ref(), y);
    let project_step = project_every(level.as_ref(), settings.project_every);
    let opts = Options::new(settings.rtol, settings.atol)
        .and_then(|opts| opts.with_max_steps(settings.max_steps))
        .map_err(RouthError::from)?;
    let method = auto::resolve(
        settings.method,
        settings.rtol.min(settings.atol),
        settings.project,
    );
    let mut stepper = stepper(method, sys, t0, y0, t1, &opts).map_err(RouthError::from)?;
    let plan = Drive {
        samples,
        project: level
            .is_some()
            .then_some(&project_step as Projection<'_, N>),
        event,
    };
    let drift = RefCell::new(DriftTracker::new(body, &x0));
    // The point where a step ended, tracked after the samples of its step, which `drive`
    // reports after `on_step`.
    let mut step_end = None;
    let outcome = drive(
        stepper.as_mut(),
        &plan,
        &mut |s, y| {
            let mut y = *y;
            project(&mut y);
            drift.borrow_mut().observe(body, &reduced(&y));
            on_sample(s, &y)
        },
        &mut |t, y, stepper| {
            if let Some(end) = step_end.take() {
                drift.borrow_mut().observe(body, &reduced(&end));
            }
            let control = on_step(t, y, stepper)?;
            step_end = Some(match control {
                Control::StopAt { y, .. } => y,
                Control::Continue | Control::Stop => *y,
            });
            Ok(control)
        },
    )?;
    let mut drift = drift.into_inner();
    if let Some(end) = step_end {
        drift.observe(body, &reduced(&end));
    }
    let stats = outcome.stats;
    Ok(Observed {
        summary: Summary {
            method: method.to_string(),
            t_end: t1,
            steps: stats.steps,
            rejected: stats.rejected,
            rhs_evals: stats.rhs_evals,
            projected: settings.project,
            project_every: settings.project_every,
            initial_state: Point::from_array(&x0),
            final_state: Point::from_array(&reduced(&outcome.y)),
            integrals: drift.report(),
            elapsed_s: start.seconds(),
        },
        stop: outcome.stop,
        t: outcome.t,
        y: outcome.y,
    })
}

/// The reduced field (mg-eq) of a body as an [`OdeSystem`].
#[derive(Debug, Clone, Copy)]
pub struct ReducedSystem<'a, B = Body>(pub &'a B);

impl<B: AsBall> OdeSystem<6> for ReducedSystem<'_, B> {
    type Kernels = crate::kernels::BallKernels;

    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; 6]) -> [f64; 6] {
        crate::field::vector_field(self.0, y)
    }

    /// The same field with `omega` in the form for series
    /// ([`OmegaForm::Determinant`](crate::field::OmegaForm)): fewer convolutions per order.
    fn record(&self, _t: Var, y: &[Var; 6]) -> Option<[Var; 6]> {
        use crate::field::{vector_field_in, OmegaForm};
        Some(vector_field_in(OmegaForm::Determinant, self.0, y))
    }

    /// gamma dimensionless, M in the motion's unit of angular momentum ([`Units::of_reduced`]).
    fn units(&self, y0: &[f64; 6]) -> crate::integrate::RunUnits<6> {
        Units::of_reduced(self.0, y0)
    }
}

/// The reduced field (mg-eq) for the batched integrator: the one generic
/// [`crate::field::vector_field`], on lanes or on `f64`.
impl<B: AsBall> crate::batch::Field<6> for ReducedSystem<'_, B> {
    #[inline(always)]
    fn eval<D: crate::scalar::Scalar>(&self, y: &[D; 6]) -> [D; 6] {
        crate::field::vector_field(self.0, y)
    }

    /// As the one-at-a-time run's ([`Units::of_reduced`]).
    fn units(&self, y0: &[f64; 6]) -> crate::integrate::RunUnits<6> {
        Units::of_reduced(self.0, y0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The option, value and rule of the error of `builder.build()`.
    fn refused(builder: SettingsBuilder) -> (&'static str, String, &'static str) {
        match builder.build() {
            Err(RouthError::Option { name, value, rule }) => (name, value, rule),
            other => panic!("not refused as an option: {other:?}"),
        }
    }

    #[test]
    fn each_invalid_value_is_refused_when_built() {
        let b = Settings::builder();
        let (name, value, rule) = refused(b.t_end(f64::NAN));
        assert_eq!(
            (name, value.as_str(), rule),
            ("t_end", "NaN", "must be finite and >= 0")
        );
        assert_eq!(refused(b.t_end(-1.0)).0, "t_end");
        let (name, value, rule) = refused(b.tolerances(1.0, 1e-12));
        assert_eq!((name, value.as_str()), ("rtol", "1"));
        assert_eq!(
            rule,
            "must be < 1e-2: a larger relative tolerance lets the integrals drift by whole percents"
        );
        assert_eq!(refused(b.tolerances(MAX_RTOL, 1e-12)).0, "rtol");
        let (name, value, rule) = refused(b.tolerances(1e-20, 1e-12));
        assert_eq!((name, value.as_str()), ("rtol", "1e-20"));
        assert!(rule.starts_with("must be >= 2.2e-14"), "{rule}");
        assert_eq!(
            refused(b.tolerances(f64::NAN, 1e-12)).2,
            "must be finite and > 0"
        );
        assert_eq!(refused(b.tolerances(1e-12, 0.0)).0, "atol");
        let (name, value, rule) = refused(b.samples(1));
        assert_eq!(
            (name, value.as_str(), rule),
            (
                "samples",
                "1",
                "must be 0 or >= 2 (the samples include both ends)"
            )
        );
        let (name, _, rule) = refused(b.samples(MAX_SAMPLES + 1));
        assert_eq!(
            (name, rule),
            ("samples", "must be at most 10000000 (MAX_SAMPLES)")
        );
        let (name, value, rule) = refused(b.projection(true, 0));
        assert_eq!(
            (name, value.as_str(), rule),
            (
                "project_every",
                "0",
                "must be at least 1 (project after every step)"
            )
        );
        let (name, value, rule) = refused(b.method(Method::Rk4 { steps: 11 }).max_steps(10));
        assert_eq!(
            (name, value.as_str(), rule),
            (
                "method rk4:<steps>",
                "11",
                "must not exceed max_steps (--max-steps, default 10000000)"
            )
        );
        let (name, value, rule) = refused(b.max_steps(0));
        assert_eq!(
            (name, value.as_str(), rule),
            ("max_steps", "0", "must be >= 1")
        );
        // The first violation in the order of the rules is the one reported.
        assert_eq!(refused(b.t_end(f64::NAN).tolerances(1.0, 0.0)).0, "t_end");
        assert_eq!(refused(b.tolerances(1.0, 0.0).samples(1)).0, "rtol");
        // Controls: the defaults and the edges of each rule are accepted.
        assert_eq!(b.build().unwrap(), Settings::default());
        b.t_end(0.0).build().unwrap();
        let edge = b
            .t_end(1.0)
            .tolerances(MIN_RTOL, MIN_ATOL)
            .samples(MAX_SAMPLES)
            .projection(true, 1)
            .method(Method::Rk4 { steps: 10 })
            .max_steps(10)
            .build()
            .unwrap();
        assert_eq!(edge.rtol(), MIN_RTOL);
        assert_eq!(edge.to_builder().samples(2).build().unwrap().samples(), 2);
    }

    /// Regression (issue 33): `--rtol 2.2e-14`, the bound the message printed, was refused
    /// (the bound was 100 epsilons, 2.220446049250313e-14). The bound and the number in each
    /// rule are one value: the rule prints the constant exactly, and the constant is accepted
    /// while the next smaller f64 is not.
    #[test]
    fn the_printed_bounds_are_the_bounds() {
        let b = Settings::builder();
        for (bound, name, below) in [
            (MIN_RTOL, "rtol", b.tolerances(MIN_RTOL.next_down(), 1e-12)),
            (MIN_ATOL, "atol", b.tolerances(1e-12, MIN_ATOL.next_down())),
        ] {
            let (refused_name, _, rule) = refused(below);
            assert_eq!(refused_name, name);
            assert!(
                rule.starts_with(&format!("must be >= {bound:e} ")),
                "{rule}"
            );
        }
        b.tolerances(2.2e-14, 1e-150).build().unwrap();
    }

    /// Regression (issue 33): `--atol 1e-320` ended in "step size too small at t = 0: h = 0";
    /// a tolerance f64 cannot resolve is now refused when the settings are built, naming it.
    #[test]
    fn an_unresolvable_atol_is_refused_when_built() {
        for atol in [1e-320, 5e-324, 1e-200, 9.9e-151] {
            let (name, value, rule) = refused(Settings::builder().tolerances(1e-12, atol));
            assert_eq!((name, value), ("atol", Number(atol).to_string()));
            assert!(rule.contains("leave the range of f64"), "{rule}");
        }
    }

    /// Regression (issue 33): `--t-end 0 --samples 2` blamed "samples = 0", a value never
    /// given (the sample times 0 and 0 were not distinct); the cause, t_end, is named.
    #[test]
    fn samples_on_an_empty_span_blame_t_end() {
        for (t_end, samples) in [(0.0, 2), (0.0, 1000), (1e-310, 2)] {
            let (name, value, rule) = refused(Settings::builder().t_end(t_end).samples(samples));
            assert_eq!((name, value), ("t_end", Number(t_end).to_string()));
            assert!(
                rule.contains("t_end = 0 makes the span [0, t_end] empty"),
                "{rule}"
            );
        }
        // Controls: no samples on an empty span, or samples on a span of 1e-300.
        Settings::builder().t_end(0.0).samples(0).build().unwrap();
        Settings::builder()
            .t_end(1e-300)
            .samples(1000)
            .build()
            .unwrap();
    }
}
