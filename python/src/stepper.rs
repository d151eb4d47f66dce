//! One step at a time with the library's integrators: DOP853 (adaptive, with its 7th-order
//! continuous extension) or classical RK4 with equal steps (its continuous extension on a step
//! is one RK4 step of the partial length, as in the library's `simulate::run`).

use routh_core::integrate::{rk4, Dop853, IntegrateError, Method, OdeSystem, Options, Stats};

/// The integrator of a run.
pub enum Stepper<'a, S: OdeSystem<N>, const N: usize> {
    /// The library's DOP853.
    Dop853(Box<Dop853<'a, S, N>>),
    /// Fixed-step RK4.
    Rk4(Rk4<'a, S, N>),
}

/// The state of a fixed-step RK4 integration.
pub struct Rk4<'a, S, const N: usize> {
    sys: &'a S,
    t0: f64,
    t_end: f64,
    steps: usize,
    done_steps: usize,
    t: f64,
    y: [f64; N],
    t_prev: f64,
    y_prev: [f64; N],
    stats: Stats,
}

impl<'a, S: OdeSystem<N>, const N: usize> Stepper<'a, S, N> {
    /// A stepper from `(t0, y0)` towards `t_end` (either direction). `h_init` is the first
    /// step of DOP853 (`None`: Hairer's guess).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        sys: &'a S,
        method: Method,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        rtol: f64,
        atol: f64,
        h_init: Option<f64>,
    ) -> Result<Self, IntegrateError> {
        Ok(match method {
            Method::Dop853 => {
                let opts = Options {
                    rtol,
                    atol,
                    h_init,
                    ..Options::default()
                };
                Stepper::Dop853(Box::new(Dop853::new(sys, t0, y0, t_end, &opts)?))
            }
            Method::Rk4 { steps } => Stepper::Rk4(Rk4 {
                sys,
                t0,
                t_end,
                steps,
                done_steps: 0,
                t: t0,
                y: y0,
                t_prev: t0,
                y_prev: y0,
                stats: Stats::default(),
            }),
        })
    }

    /// One accepted step; `Ok(true)` once `t_end` is reached (at once when `t_end = t0`).
    pub fn step(&mut self) -> Result<bool, IntegrateError> {
        match self {
            Stepper::Dop853(d) => d.step(),
            Stepper::Rk4(r) => {
                if r.done_steps == r.steps || r.t == r.t_end {
                    return Ok(true);
                }
                let h = (r.t_end - r.t0) / r.steps as f64;
                r.done_steps += 1;
                let t1 = if r.done_steps == r.steps {
                    r.t_end
                } else {
                    r.t0 + r.done_steps as f64 * h
                };
                let (y1, s) = rk4(r.sys, r.t, r.y, t1, 1, |_, _| {});
                r.stats.steps += s.steps;
                r.stats.rhs_evals += s.rhs_evals;
                (r.t_prev, r.y_prev) = (r.t, r.y);
                (r.t, r.y) = (t1, y1);
                if y1.iter().any(|v| !v.is_finite()) {
                    return Err(IntegrateError::NonFinite { t: t1 });
                }
                Ok(r.done_steps == r.steps)
            }
        }
    }

    /// The current time.
    pub fn t(&self) -> f64 {
        match self {
            Stepper::Dop853(d) => d.t(),
            Stepper::Rk4(r) => r.t,
        }
    }

    /// The current state.
    pub fn y(&self) -> [f64; N] {
        match self {
            Stepper::Dop853(d) => *d.y(),
            Stepper::Rk4(r) => r.y,
        }
    }

    /// Replace the current state (a projection).
    pub fn set_state(&mut self, y: [f64; N]) {
        match self {
            Stepper::Dop853(d) => d.set_state(y),
            Stepper::Rk4(r) => r.y = y,
        }
    }

    /// The continuous extension of the last step at `t` (between its ends).
    pub fn dense(&mut self, t: f64) -> [f64; N] {
        match self {
            Stepper::Dop853(d) => d.dense(t),
            Stepper::Rk4(r) => {
                if t == r.t {
                    return r.y;
                }
                let (y, s) = rk4(r.sys, r.t_prev, r.y_prev, t, 1, |_, _| {});
                r.stats.rhs_evals += s.rhs_evals;
                y
            }
        }
    }

    /// The work counters (every evaluation of the field counted).
    pub fn stats(&self) -> Stats {
        match self {
            Stepper::Dop853(d) => d.stats(),
            Stepper::Rk4(r) => r.stats,
        }
    }
}
