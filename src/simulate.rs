//! Integration of a case along the field (mg-eq), with the integrals (int-g), (raus-int)
//! tracked at every step, dense-output samples, and optional projection onto their level set.

use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrals::{Integrals, INTEGRAL_NAMES};
use crate::integrate::{rk4, Dop853, Method, OdeSystem, Options, Stats};
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
    /// Number of equally spaced dense-output samples on [0, t_end] (including both ends),
    /// at most [`MAX_SAMPLES`].
    pub samples: usize,
    /// Most steps DOP853 may attempt (accepted and rejected), and most steps of RK4.
    pub max_steps: usize,
}

/// The largest number of samples of one run (their times take 8 bytes each in memory, the
/// CSV about 300 bytes each on disk: 3 GB).
pub const MAX_SAMPLES: usize = 10_000_000;

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
    /// Drift of each integral, by name (H1, H2, H3, H4, K; H2 and K only for I1 = I2).
    pub integrals: std::collections::BTreeMap<&'static str, Drift>,
    /// Wall time of the integration in seconds, measured with [`std::time::Instant`] inside
    /// [`run`]: the steps, the tracking of the integrals, the projections and the samples
    /// (including the time spent in `on_sample`), without process start-up or case parsing.
    pub elapsed_s: f64,
}

struct DriftTracker {
    initial: [Option<f64>; 5],
    max: [f64; 5],
    last: [Option<f64>; 5],
}

impl DriftTracker {
    fn new(body: &Body, x0: &[f64; 6]) -> Self {
        let initial = Integrals::at(body, x0).values();
        DriftTracker {
            initial,
            max: [0.0; 5],
            last: initial,
        }
    }

    fn observe(&mut self, body: &Body, x: &[f64; 6]) {
        self.last = Integrals::at(body, x).values();
        for i in 0..5 {
            if let (Some(h0), Some(h)) = (self.initial[i], self.last[i]) {
                let scale = if h0 == 0.0 { 1.0 } else { h0.abs() };
                self.max[i] = self.max[i].max((h - h0).abs() / scale);
            }
        }
    }

    fn report(&self) -> std::collections::BTreeMap<&'static str, Drift> {
        (0..5)
            .filter_map(|i| {
                Some((
                    INTEGRAL_NAMES[i],
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
    body: &Body,
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
    let mut drift = DriftTracker::new(body, &x0);
    let times: Vec<f64> = (0..settings.samples)
        .map(|i| {
            if i + 1 == settings.samples {
                settings.t_end
            } else {
                settings.t_end * i as f64 / (settings.samples - 1) as f64
            }
        })
        .collect();
    let mut next = 0;
    let mut emit = |t: f64, y: &[f64; N], drift: &mut DriftTracker| -> Result<()> {
        drift.observe(body, &reduced(y));
        on_sample(t, y)
    };
    while next < times.len() && times[next] == 0.0 {
        emit(0.0, &y0, &mut drift)?;
        next += 1;
    }
    let (y_end, stats) = match settings.method {
        Method::Dop853 => {
            let opts = Options {
                rtol: settings.rtol,
                atol: settings.atol,
                max_steps: settings.max_steps,
                ..Options::default()
            };
            let mut solver =
                Dop853::new(sys, 0.0, y0, settings.t_end, &opts).map_err(integrate_error)?;
            if settings.t_end == 0.0 {
                (y0, Stats::default())
            } else {
                loop {
                    let done = solver.step().map_err(integrate_error)?;
                    if level.is_some() {
                        let mut y = *solver.y();
                        project(&mut y);
                        solver.set_state(y);
                    }
                    drift.observe(body, &reduced(solver.y()));
                    let t = solver.t();
                    while next < times.len() && times[next] <= t {
                        let y = if times[next] == t {
                            *solver.y()
                        } else {
                            solver.dense(times[next])
                        };
                        emit(times[next], &y, &mut drift)?;
                        next += 1;
                    }
                    if done {
                        break (*solver.y(), solver.stats());
                    }
                }
            }
        }
        Method::Rk4 { steps } => {
            let h = settings.t_end / steps as f64;
            let mut y = y0;
            let mut stats = Stats::default();
            for n in 0..steps {
                let t0 = n as f64 * h;
                let t1 = if n + 1 == steps {
                    settings.t_end
                } else {
                    t0 + h
                };
                let (mut y1, s) = rk4(sys, t0, y, t1, 1, |_, _| {});
                project(&mut y1);
                stats.steps += s.steps;
                stats.rhs_evals += s.rhs_evals;
                drift.observe(body, &reduced(&y1));
                while next < times.len() && times[next] <= t1 {
                    let ys = if times[next] == t1 {
                        y1
                    } else {
                        rk4(sys, t0, y, times[next], 1, |_, _| {}).0
                    };
                    emit(times[next], &ys, &mut drift)?;
                    next += 1;
                }
                y = y1;
            }
            (y, stats)
        }
    };
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

fn integrate_error(e: crate::integrate::IntegrateError) -> RouthError {
    match e {
        crate::integrate::IntegrateError::TooManySteps { .. } => RouthError::Integrate(format!(
            "{e} (raise the limit with --max-steps or max_steps in [integration])"
        )),
        _ => RouthError::Integrate(e.to_string()),
    }
}

/// The reduced field (mg-eq) of a body as an [`OdeSystem`].
#[derive(Debug, Clone, Copy)]
pub struct ReducedSystem<'a>(pub &'a Body);

impl OdeSystem<6> for ReducedSystem<'_> {
    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; 6]) -> [f64; 6] {
        crate::field::vector_field(self.0, y)
    }
}
