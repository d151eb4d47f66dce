//! Integration of a case along the field (mg-eq), with the integrals (int-g), (raus-int)
//! tracked at every step, dense-output samples, and optional projection onto their level set.

use crate::ball::AsBall;
use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrals::{Integrals, ALL_INTEGRAL_NAMES};
use crate::integrate::{
    drive, Control, Dop853, Drive, IntegrateError, Method, OdeSystem, Options, Projection, Rk4,
    Stepper,
};
use crate::projection::LevelSet;
use crate::state::State;
use serde::Serialize;
use std::time::Instant;

/// Settings of one simulation.
#[derive(Debug, Clone, Copy, PartialEq)]
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
    /// Number of equally spaced dense-output samples on [0, t_end] (including both ends).
    pub samples: usize,
}

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

struct DriftTracker {
    initial: [Option<f64>; 7],
    max: [f64; 7],
    last: [Option<f64>; 7],
}

impl DriftTracker {
    fn new(body: &impl AsBall, x0: &[f64; 6]) -> Self {
        let initial = Integrals::at(body, x0).all();
        DriftTracker {
            initial,
            max: [0.0; 7],
            last: initial,
        }
    }

    fn observe(&mut self, body: &impl AsBall, x: &[f64; 6]) {
        self.last = Integrals::at(body, x).all();
        for i in 0..7 {
            if let (Some(h0), Some(h)) = (self.initial[i], self.last[i]) {
                let scale = if h0 == 0.0 { 1.0 } else { h0.abs() };
                self.max[i] = self.max[i].max((h - h0).abs() / scale);
            }
        }
    }

    fn report(&self) -> std::collections::BTreeMap<&'static str, Drift> {
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

/// Validate the settings; each violation names the option.
pub fn validate(settings: &Settings) -> Result<()> {
    let bad = |name: &'static str, value: f64, rule: &'static str| {
        Err(RouthError::Option {
            name,
            value: value.to_string(),
            rule,
        })
    };
    if !(settings.t_end.is_finite() && settings.t_end >= 0.0) {
        return bad("t_end", settings.t_end, "must be finite and >= 0");
    }
    if !(settings.rtol.is_finite() && settings.rtol > 0.0) {
        return bad("rtol", settings.rtol, "must be finite and > 0");
    }
    if !(settings.atol.is_finite() && settings.atol > 0.0) {
        return bad("atol", settings.atol, "must be finite and > 0");
    }
    if settings.samples == 1 {
        return bad(
            "samples",
            1.0,
            "must be 0 or >= 2 (the samples include both ends)",
        );
    }
    Ok(())
}

/// Integrate `sys`, whose state starts with the reduced phase-space point `(gamma, M)`
/// (further components, such as the orientation of the full motion, follow it), from
/// `y0` over `[0, t_end]`. `on_sample(t, y)` receives the equally spaced samples; the
/// integrals are tracked on the reduced part at every step end and sample.
pub fn run<S: OdeSystem<N>, const N: usize>(
    body: &impl AsBall,
    sys: &S,
    y0: [f64; N],
    settings: &Settings,
    on_sample: &mut dyn FnMut(f64, &[f64; N]) -> Result<()>,
) -> Result<Summary> {
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
    let mut stepper: Box<dyn Stepper<N> + '_> = match settings.method {
        Method::Dop853 => {
            let opts = Options {
                rtol: settings.rtol,
                atol: settings.atol,
                ..Options::default()
            };
            Box::new(Dop853::new(sys, 0.0, y0, settings.t_end, &opts).map_err(integrate_error)?)
        }
        Method::Rk4 { steps } => Box::new(Rk4::new(sys, 0.0, y0, settings.t_end, steps)),
    };
    let plan = Drive {
        samples: &times,
        project: level.is_some().then_some(&project as Projection<'_, N>),
        event: None,
    };
    let drift = std::cell::RefCell::new(DriftTracker::new(body, &x0));
    let outcome = drive(
        stepper.as_mut(),
        &plan,
        &mut |t, y| {
            drift.borrow_mut().observe(body, &reduced(y));
            on_sample(t, y)
        },
        &mut |_, y| {
            drift.borrow_mut().observe(body, &reduced(y));
            Ok(Control::Continue)
        },
    )?;
    let (y_end, stats) = (outcome.y, outcome.stats);
    let drift = drift.into_inner();
    if y_end.iter().any(|v| !v.is_finite()) {
        return Err(RouthError::Integrate(format!(
            "the state became non-finite before t = {}",
            settings.t_end
        )));
    }
    Ok(Summary {
        method: settings.method.to_string(),
        t_end: settings.t_end,
        steps: stats.steps,
        rejected: stats.rejected,
        rhs_evals: stats.rhs_evals,
        projected: settings.project,
        initial_state: State::from_array(&x0),
        final_state: State::from_array(&reduced(&y_end)),
        integrals: drift.report(),
        elapsed_s: start.elapsed().as_secs_f64(),
    })
}

fn integrate_error(e: IntegrateError) -> RouthError {
    RouthError::Integrate(e.to_string())
}

impl From<IntegrateError> for RouthError {
    fn from(e: IntegrateError) -> Self {
        integrate_error(e)
    }
}

/// The reduced field (mg-eq) of a body as an [`OdeSystem`].
#[derive(Debug, Clone, Copy)]
pub struct ReducedSystem<'a, B = Body>(pub &'a B);

impl<B: AsBall> OdeSystem<6> for ReducedSystem<'_, B> {
    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; 6]) -> [f64; 6] {
        crate::field::vector_field(self.0, y)
    }
}
