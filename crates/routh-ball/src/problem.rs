//! A problem and its solution as plain values: a [`Problem`] (the ball, the initial state,
//! the time span [0, t_end] and the [`Settings`]) is solved into a [`Solution`] (samples,
//! final state, work counters, the integrals and their drift, events, a status with a
//! message) and, on request, a [`DenseSolution`] that evaluates the state at any time of
//! the span, as SciPy's `OdeSolution`. All are `Clone + Send + Sync + Serialize`, so that
//! thousands of them can be built, sent to threads and written out.

use crate::ball::Ball;
use crate::error::{Number, Result, RouthError};
use crate::integrate::{Stats, Stepper, Stop};
use crate::simulate::{integrate_observed, Drift, ReducedSystem, Settings};
use crate::state::{Point, State};
use serde::Serialize;
use std::collections::BTreeMap;

/// A plane `x[component] = value` of the reduced phase space `x = (gamma, M)`: the event of
/// a [`Problem`] (the run stops at the first sign change of `x[component] - value`, located
/// on the dense output) and the surface of a Poincaré section ([`crate::section`]). Validated
/// when built ([`Plane::new`]): its fields are private, so no plane names a component outside
/// (gamma, M) or a level that is not finite.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Plane {
    component: usize,
    value: f64,
}

impl Plane {
    /// The plane `x[component] = value`: `component` 0 to 5 (gamma1, gamma2, gamma3, M1, M2,
    /// M3), `value` finite, else [`RouthError::Option`] naming the plane.
    pub fn new(component: usize, value: f64) -> Result<Self> {
        if component > 5 || !value.is_finite() {
            return Err(RouthError::Option {
                name: "plane",
                value: format!("x[{component}] = {}", Number(value)),
                rule: "must be a component 0 to 5 of (gamma, M) equal to a finite number",
            });
        }
        Ok(Plane { component, value })
    }

    /// The index into `x = (gamma1, gamma2, gamma3, M1, M2, M3)`, 0 to 5.
    pub fn component(&self) -> usize {
        self.component
    }

    /// The level crossed.
    pub fn value(&self) -> f64 {
        self.value
    }

    /// `x[component] - value`: the function whose sign changes where a run crosses the plane.
    pub fn level(&self, x: &[f64; 6]) -> f64 {
        x[self.component] - self.value
    }
}

/// A problem: integrate the field (mg-eq) of `ball` from `initial` over `[0, settings.t_end()]`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Problem {
    /// The ball.
    pub ball: Ball,
    /// The state at t = 0.
    pub initial: State,
    /// Method, tolerances, time span, projection, samples.
    pub settings: Settings,
    /// Stop at the first crossing, if given.
    pub event: Option<Plane>,
}

/// How a run ended, as its user sees it: the one status of a [`Solution`], a row of the
/// sweep and a Python run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Status {
    /// t_end was reached.
    Reached,
    /// The (terminal) event was found.
    Event,
    /// The integration failed (the message says why); the solution holds what was reached.
    Failed,
}

impl Status {
    /// The word of a table cell: `ok` (t_end reached), `event`, `failed`.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Reached => "ok",
            Status::Event => "event",
            Status::Failed => "failed",
        }
    }
}

/// A state at a time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// The time.
    pub t: f64,
    /// The state there.
    pub state: Point,
}

/// The solution of a [`Problem`].
#[derive(Debug, Clone, Serialize)]
pub struct Solution {
    /// How the run ended.
    pub status: Status,
    /// A sentence saying how it ended.
    pub message: String,
    /// The time reached.
    pub t: f64,
    /// The samples of the settings (equally spaced on [0, t_end], both ends included).
    pub samples: Vec<Sample>,
    /// The state at the end.
    pub final_state: Point,
    /// Work counters.
    pub stats: Stats,
    /// The integrals of the ball's model and their drift over step ends and samples.
    pub integrals: BTreeMap<&'static str, Drift>,
    /// The events found (at most one: the run stops there).
    pub events: Vec<Sample>,
}

/// The state at any time of the span covered by a run, from the dense output of each step.
///
/// Each step is stored as the values of its dense output at the 8 Chebyshev points of the
/// second kind and evaluated by barycentric interpolation (Berrut, Trefethen, SIAM Rev. 46
/// (2004)). The dense output of DOP853 (degree 7 in the step fraction) and of RK4 (degree 3)
/// are polynomials of degree at most 7, so this reproduces them to round-off.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(bound(serialize = "[f64; N]: Serialize"))]
pub struct DenseSolution<const N: usize = 6> {
    /// Step boundaries `t_0 < t_1 < ... < t_n` (or decreasing for a backward run).
    pub times: Vec<f64>,
    /// For step i, the states at its 8 Chebyshev points.
    pub nodes: Vec<[[f64; N]; DENSE_NODES]>,
}

/// Number of interpolation nodes per step.
pub const DENSE_NODES: usize = 8;

/// The Chebyshev points of the second kind on [0, 1], `(1 - cos(pi j / 7)) / 2`.
fn chebyshev_fraction(j: usize) -> f64 {
    0.5 * (1.0 - (std::f64::consts::PI * j as f64 / (DENSE_NODES - 1) as f64).cos())
}

impl<const N: usize> Default for DenseSolution<N> {
    fn default() -> Self {
        DenseSolution {
            times: Vec::new(),
            nodes: Vec::new(),
        }
    }
}

impl<const N: usize> DenseSolution<N> {
    /// Append the last accepted step of `stepper` (its dense output on `[t_prev, t]`).
    pub fn record(&mut self, stepper: &(impl Stepper<N> + ?Sized)) {
        let (ta, tb) = (stepper.t_prev(), stepper.t());
        if self.times.is_empty() {
            self.times.push(ta);
        }
        self.times.push(tb);
        self.nodes.push(std::array::from_fn(|j| {
            stepper.dense(ta + (tb - ta) * chebyshev_fraction(j))
        }));
    }

    /// The state at `t`, which must lie in the span covered (else an
    /// [`RouthError::Option`] naming `t`).
    pub fn at(&self, t: f64) -> Result<[f64; N]> {
        let (first, last) = match (self.times.first(), self.times.last()) {
            (Some(&a), Some(&b)) if self.times.len() > 1 => (a, b),
            _ => return Err(self.outside(t)),
        };
        let dir = if last >= first { 1.0 } else { -1.0 };
        if !((t - first) * dir >= 0.0 && (last - t) * dir >= 0.0) {
            return Err(self.outside(t));
        }
        let i = self.times[1..]
            .partition_point(|&b| (b - t) * dir < 0.0)
            .min(self.nodes.len() - 1);
        let (ta, tb) = (self.times[i], self.times[i + 1]);
        let nodes = &self.nodes[i];
        if tb == ta {
            return Ok(nodes[0]);
        }
        let s = (t - ta) / (tb - ta);
        let mut num = [0.0; N];
        let mut den = 0.0;
        for (j, node) in nodes.iter().enumerate() {
            let d = s - chebyshev_fraction(j);
            if d == 0.0 {
                return Ok(*node);
            }
            let sign = if j % 2 == 0 { 1.0 } else { -1.0 };
            let half = if j == 0 || j == DENSE_NODES - 1 {
                0.5
            } else {
                1.0
            };
            let w = sign * half / d;
            den += w;
            for (n, v) in num.iter_mut().zip(node) {
                *n += w * v;
            }
        }
        Ok(num.map(|v| v / den))
    }

    fn outside(&self, t: f64) -> RouthError {
        RouthError::Option {
            name: "t",
            value: t.to_string(),
            rule: "must lie within the span of the solution",
        }
    }
}

impl Problem {
    /// Solve the problem; see [`Problem::solve_dense`].
    pub fn solve(&self) -> Result<Solution> {
        self.run(None)
    }

    /// Solve the problem and keep the dense output of every step.
    ///
    /// An invalid event is an error (the settings were checked when built); a failed integration is a [`Solution`] with
    /// [`Status::Failed`] and the message, holding what was reached.
    pub fn solve_dense(&self) -> Result<(Solution, DenseSolution)> {
        let mut dense = DenseSolution::default();
        let solution = self.run(Some(&mut dense))?;
        Ok((solution, dense))
    }

    fn run(&self, mut dense: Option<&mut DenseSolution>) -> Result<Solution> {
        let event = self
            .event
            .map(|plane| move |_: f64, x: &[f64; 6]| plane.level(x));
        let event_ref = event.as_ref().map(|g| g as &dyn Fn(f64, &[f64; 6]) -> f64);
        let mut samples = Vec::new();
        let run = integrate_observed::<_, RouthError, 6>(
            &self.ball,
            &ReducedSystem(&self.ball),
            self.initial.to_array(),
            &self.settings,
            event_ref,
            &mut |t, x| {
                samples.push(Sample {
                    t,
                    state: Point::from_array(x),
                });
                Ok(())
            },
            &mut |stepper| {
                if let Some(d) = dense.as_deref_mut() {
                    d.record(stepper);
                }
            },
        )?;
        let (status, message, events) = match &run.stop {
            Stop::Failed(e) => (Status::Failed, e.to_string(), Vec::new()),
            Stop::Event => (
                Status::Event,
                format!("the event was found at t = {}", run.t),
                vec![Sample {
                    t: run.t,
                    state: Point::from_array(&run.y),
                }],
            ),
            Stop::Reached | Stop::Stopped => (
                Status::Reached,
                format!("t_end = {} was reached", self.settings.t_end()),
                Vec::new(),
            ),
        };
        Ok(Solution {
            status,
            message,
            t: run.t,
            samples,
            final_state: run.summary.final_state,
            stats: Stats {
                steps: run.summary.steps,
                rejected: run.summary.rejected,
                rhs_evals: run.summary.rhs_evals,
            },
            integrals: run.summary.integrals,
            events,
        })
    }
}
