//! One step at a time with the library's steppers ([`routh::integrate::Stepper`]): DOP853
//! (adaptive, with its 7th-order continuous extension) or classical RK4 with equal steps (its
//! own continuous extension of order 3). This wrapper only chooses the method and refuses a
//! non-finite state after a step.

use routh_core::integrate::{
    stepper, IntegrateError, Method, OdeSystem, Options, Stats, Stepper as LibraryStepper,
};

/// The integrator of a run.
pub struct Stepper<'a, const N: usize>(Box<dyn LibraryStepper<N> + 'a>);

impl<'a, const N: usize> Stepper<'a, N> {
    /// A stepper from `(t0, y0)` towards `t_end` (either direction). `h_init` is the first
    /// step of DOP853 (`None`: Hairer's guess).
    #[allow(clippy::too_many_arguments)]
    pub fn new<S: OdeSystem<N>>(
        sys: &'a S,
        method: Method,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        rtol: f64,
        atol: f64,
        h_init: Option<f64>,
    ) -> Result<Self, IntegrateError> {
        let opts = Options {
            rtol,
            atol,
            h_init,
            ..Options::default()
        };
        Ok(Stepper(stepper(method, sys, t0, y0, t_end, &opts)?))
    }

    /// One accepted step; `Ok(true)` once `t_end` is reached (at once when `t_end = t0`).
    pub fn step(&mut self) -> Result<bool, IntegrateError> {
        if self.0.t() == self.0.t_end() {
            return Ok(true);
        }
        let done = self.0.step()?;
        if self.0.y().iter().any(|v| !v.is_finite()) {
            return Err(IntegrateError::NonFinite { t: self.0.t() });
        }
        Ok(done)
    }

    /// The current time.
    pub fn t(&self) -> f64 {
        self.0.t()
    }

    /// The current state.
    pub fn y(&self) -> [f64; N] {
        *self.0.y()
    }

    /// Replace the current state (a projection).
    pub fn set_state(&mut self, y: [f64; N]) {
        self.0.set_state(y)
    }

    /// The continuous extension of the last step at `t` (between its ends).
    pub fn dense(&mut self, t: f64) -> [f64; N] {
        self.0.dense(t)
    }

    /// The work counters (every evaluation of the field counted).
    pub fn stats(&self) -> Stats {
        self.0.stats()
    }
}
