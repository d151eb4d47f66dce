//! Integration of a case along the field (mg-eq), with the integrals (int-g), (raus-int)
//! tracked at every step, dense-output samples, and optional projection onto their level set.

use crate::ball::AsBall;
use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrals::{Integrals, ALL_INTEGRAL_NAMES};
use crate::integrate::taylor::Var;
use crate::integrate::{
    drive, stepper, Control, Drive, EventFn, IntegrateError, Method, OdeSystem, Options,
    Projection, Stepper, Stop,
};
use crate::projection::LevelSet;
use crate::state::State;
use serde::Serialize;
use std::cell::RefCell;
use std::time::Instant;

/// Settings of one simulation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Settings {
    /// The integrator.
    pub method: Method,
    /// Final time (the start is t = 0).
    pub t_end: f64,
    /// Relative tolerance (DOP853).
    pub rtol: f64,
    /// Absolute tolerance (DOP853).
    pub atol: f64,
    /// Project onto the level set of the integrals after each step.
    pub project: bool,
    /// Number of equally spaced dense-output samples on [0, t_end] (including both ends),
    /// at most [`MAX_SAMPLES`].
    pub samples: usize,
    /// Most steps DOP853 may attempt (accepted and rejected), and most steps of RK4.
    pub max_steps: usize,
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
    /// `max_t |H(t) - H(0)| / |H(0)|` over all step ends and samples (absolute if H(0) = 0).
    pub max_rel_drift: f64,
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
    /// The initial state.
    pub initial_state: State,
    /// The state at t_end.
    pub final_state: State,
    /// Drift of each integral of the ball's model, by name (H1, H2, H3, H4, K, MM, Mgamma;
    /// see [`Integrals`]).
    pub integrals: std::collections::BTreeMap<&'static str, Drift>,
    /// Wall time of the integration in seconds, measured with [`std::time::Instant`] inside
    /// [`run`]: the steps, the tracking of the integrals, the projections and the samples
    /// (including the time spent in `on_sample`), without process start-up or case parsing.
    pub elapsed_s: f64,
}

/// The drift of the integrals along a run: their values at the start, at the last state seen,
/// and the largest relative change (the `integrals` of a [`Summary`]).
pub struct DriftTracker {
    initial: [Option<f64>; 7],
    max: [f64; 7],
    last: [Option<f64>; 7],
}

impl DriftTracker {
    /// Starts at `x0`.
    pub fn new(body: &impl AsBall, x0: &[f64; 6]) -> Self {
        let initial = Integrals::at(body, x0).all();
        DriftTracker {
            initial,
            max: [0.0; 7],
            last: initial,
        }
    }

    /// Looks at the state `x`.
    pub fn observe(&mut self, body: &impl AsBall, x: &[f64; 6]) {
        self.last = Integrals::at(body, x).all();
        for i in 0..7 {
            if let (Some(h0), Some(h)) = (self.initial[i], self.last[i]) {
                let scale = if h0 == 0.0 { 1.0 } else { h0.abs() };
                self.max[i] = self.max[i].max((h - h0).abs() / scale);
            }
        }
    }

    /// The drift of each integral so far.
    pub fn report(&self) -> std::collections::BTreeMap<&'static str, Drift> {
        (0..7)
            .filter_map(|i| {
                Some((
                    ALL_INTEGRAL_NAMES[i],
                    Drift {
                        initial: self.initial[i]?,
                        last: self.last[i]?,
                        max_rel_drift: self.max[i],
                    },
                ))
            })
            .collect()
    }
}

/// The reduced phase-space part of a (possibly extended) state.
fn reduced<const N: usize>(y: &[f64; N]) -> [f64; 6] {
    std::array::from_fn(|i| y[i])
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
            samples: 0,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }
}

/// The one validation of the time span and tolerances (used by [`validate`] and by case
/// files): t_end finite and >= 0; rtol, atol finite and > 0. Each violation names the option.
pub fn validate_span(t_end: f64, rtol: f64, atol: f64) -> Result<()> {
    let bad = |name: &'static str, value: f64, rule: &'static str| {
        Err(RouthError::Option {
            name,
            value: value.to_string(),
            rule,
        })
    };
    if !(t_end.is_finite() && t_end >= 0.0) {
        return bad("t_end", t_end, "must be finite and >= 0");
    }
    if !(rtol.is_finite() && rtol > 0.0) {
        return bad("rtol", rtol, "must be finite and > 0");
    }
    if !(atol.is_finite() && atol > 0.0) {
        return bad("atol", atol, "must be finite and > 0");
    }
    Ok(())
}

/// Validate the settings ([`validate_span`] and the sample count); each violation names the
/// option.
pub fn validate(settings: &Settings) -> Result<()> {
    validate_span(settings.t_end, settings.rtol, settings.atol)?;
    if settings.samples > MAX_SAMPLES {
        return Err(RouthError::Option {
            name: "samples",
            value: settings.samples.to_string(),
            rule: "must be at most 10000000 (MAX_SAMPLES)",
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
    Ok(())
}

/// Integrate `sys`, whose state starts with the reduced phase-space point `(gamma, M)`
/// (further components, such as the orientation of the full motion, follow it), from
/// `y0` over `[0, t_end]`. `on_sample(t, y)` receives the equally spaced samples; the
/// integrals are tracked on the reduced part at every step end and sample. A failed
/// integration is an error ([`RouthError::Integrate`]); [`integrate_observed`] tells more.
pub fn run<S: OdeSystem<N>, const N: usize>(
    body: &impl AsBall,
    sys: &S,
    y0: [f64; N],
    settings: &Settings,
    on_sample: &mut dyn FnMut(f64, &[f64; N]) -> Result<()>,
) -> Result<Summary> {
    let observed = integrate_observed(body, sys, y0, settings, None, on_sample, &mut |_| {})?;
    match observed.failure {
        Some(e) => Err(e.into()),
        None => Ok(observed.summary),
    }
}

/// What [`integrate_observed`] returns: the summary, how the run stopped, the time reached,
/// and the integrator's failure (then the summary holds the state reached).
#[derive(Debug, Clone)]
pub struct Observed<const N: usize> {
    /// The summary of the run (up to the failure, if any).
    pub summary: Summary,
    /// How the driver stopped (meaningless after a failure).
    pub stop: Stop<N>,
    /// The time reached.
    pub t: f64,
    /// The integrator's error, if it failed.
    pub failure: Option<IntegrateError>,
}

/// The one simulation loop behind [`run`] and [`crate::problem::Problem`]: as [`run`], with an
/// optional event function and `on_step(stepper)` called after each step (for its dense
/// output). Invalid settings and errors of `on_sample` are errors; a failure of the
/// integrator is reported in [`Observed::failure`] with the state reached.
#[allow(clippy::too_many_arguments)]
pub fn integrate_observed<S: OdeSystem<N>, const N: usize>(
    body: &impl AsBall,
    sys: &S,
    y0: [f64; N],
    settings: &Settings,
    event: Option<EventFn<'_, N>>,
    on_sample: &mut dyn FnMut(f64, &[f64; N]) -> Result<()>,
    on_step: &mut dyn FnMut(&dyn Stepper<N>),
) -> Result<Observed<N>> {
    validate(settings)?;
    let start = Instant::now();
    let x0 = reduced(&y0);
    let level = settings.project.then(|| LevelSet::through(body, &x0));
    let project = |y: &mut [f64; N]| {
        if let Some(level) = &level {
            let mut x = reduced(y);
            level.project(&mut x);
            y[..6].copy_from_slice(&x);
        }
    };
    let times: Vec<f64> = (0..settings.samples)
        .map(|i| {
            if i + 1 == settings.samples {
                settings.t_end
            } else {
                settings.t_end * i as f64 / (settings.samples - 1) as f64
            }
        })
        .collect();
    let opts = Options {
        rtol: settings.rtol,
        atol: settings.atol,
        max_steps: settings.max_steps,
        ..Options::default()
    };
    let mut stepper = stepper(settings.method, sys, 0.0, y0, settings.t_end, &opts)?;
    let plan = Drive {
        samples: &times,
        project: level.is_some().then_some(&project as Projection<'_, N>),
        event,
    };
    let drift = RefCell::new(DriftTracker::new(body, &x0));
    let outcome = drive(
        stepper.as_mut(),
        &plan,
        &mut |t, y| {
            drift.borrow_mut().observe(body, &reduced(y));
            on_sample(t, y)
        },
        &mut |_, y, stepper| {
            drift.borrow_mut().observe(body, &reduced(y));
            on_step(stepper);
            Ok(Control::Continue)
        },
    );
    let (stop, t, y_end, failure) = match outcome {
        Ok(o) if o.y.iter().all(|v| v.is_finite()) => (o.stop, o.t, o.y, None),
        Ok(o) => (o.stop, o.t, o.y, Some(IntegrateError::NonFinite { t: o.t })),
        Err(RouthError::Integrate(e)) => (Stop::Reached, stepper.t(), *stepper.y(), Some(e)),
        Err(other) => return Err(other),
    };
    let stats = stepper.stats();
    Ok(Observed {
        summary: Summary {
            method: settings.method.resolve(settings.rtol.min(settings.atol)).to_string(),
            t_end: settings.t_end,
            steps: stats.steps,
            rejected: stats.rejected,
            rhs_evals: stats.rhs_evals,
            projected: settings.project,
            initial_state: State::from_array(&x0),
            final_state: State::from_array(&reduced(&y_end)),
            integrals: drift.into_inner().report(),
            elapsed_s: start.elapsed().as_secs_f64(),
        },
        stop,
        t,
        failure,
    })
}

/// The reduced field (mg-eq) of a body as an [`OdeSystem`].
#[derive(Debug, Clone, Copy)]
pub struct ReducedSystem<'a, B = Body>(pub &'a B);

impl<B: AsBall> OdeSystem<6> for ReducedSystem<'_, B> {
    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; 6]) -> [f64; 6] {
        crate::field::vector_field(self.0, y)
    }

    fn record(&self, _t: Var, y: &[Var; 6]) -> Option<[Var; 6]> {
        Some(crate::field::vector_field(self.0, y))
    }
}
