//! Verner's "most efficient" 9(8) Runge–Kutta pair with its 9th-order interpolant
//! (J. H. Verner, "Numerically optimal Runge–Kutta pairs with interpolants", Numer.
//! Algorithms 53 (2010) 383–396; coefficients in [`super::vern9_tableau`]).
//!
//! Sixteen stages per step (the 16th only for the error estimate), local extrapolation
//! (the step advances with the 9th-order solution), an error estimate from the embedded
//! 8th-order solution, the step-size controller and initial step of [`Dop853`](super::Dop853)
//! with exponent 1/9, and compensated summation of the update
//! ([`compensated_add`]). The interpolant costs nine more right-hand-side calls, made only
//! when a step's dense output is first asked for. A [`Stepper`]: it runs in the one driver
//! [`drive`](super::drive); [`Vern9::fixed_steps`] takes equal steps without error control
//! (for convergence-order studies) through the same step code.

use std::cell::Cell;

use super::compensated::compensated_add;
use super::dop853::{fixed_step_options, hinit, next_attempt};
use super::vern9_tableau::{A, B, C, E, R, STAGES, STEP_STAGES};
use super::{check_start, IntegrateError, OdeSystem, Options, Stats, Stepper};

/// Safety factor of the step-size prediction.
const SAFE: f64 = 0.9;
/// Bounds of `h_new / h`.
const FAC_MIN: f64 = 0.333;
const FAC_MAX: f64 = 6.0;
/// Exponent `1 / (q + 1)` of the controller, `q = 8` the order of the embedded solution.
const EXPO: f64 = 1.0 / 9.0;

/// Stage derivatives `k_0 .. k_25`.
type Stages<const N: usize> = [[f64; N]; STAGES];

/// `y + h * sum_j a_sj k_j` over the nonzero entries of row `s` of [`A`].
#[inline(always)]
fn stage_state<const N: usize>(y: &[f64; N], h: f64, k: &Stages<N>, s: usize) -> [f64; N] {
    let row = A[s];
    let mut acc = [0.0; N];
    for &(j, a) in row {
        for i in 0..N {
            acc[i] += a * k[j][i];
        }
    }
    let mut out = [0.0; N];
    for i in 0..N {
        out[i] = y[i] + h * acc[i];
    }
    out
}

/// `sum_j w_j k_j` over the stages of the step.
#[inline(always)]
fn weighted<const N: usize>(w: &[f64; STEP_STAGES], k: &Stages<N>) -> [f64; N] {
    let mut acc = [0.0; N];
    for (j, &wj) in w.iter().enumerate() {
        if wj != 0.0 {
            for i in 0..N {
                acc[i] += wj * k[j][i];
            }
        }
    }
    acc
}

/// Stages `first..last` of a step from `(t, y)` with stages below `first` given.
#[inline(always)]
fn stages<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t: f64,
    h: f64,
    y: &[f64; N],
    k: &mut Stages<N>,
    range: std::ops::Range<usize>,
) {
    for s in range {
        k[s] = sys.rhs(t + C[s] * h, &stage_state(y, h, k, s));
    }
}

/// Adaptive Verner 9(8) with its 9th-order interpolant, compensated summation of the update.
pub struct Vern9<'a, S, const N: usize> {
    sys: &'a S,
    t: f64,
    y: [f64; N],
    /// Rounding residue of the compensated update (zero after [`set_state`](Self::set_state)).
    carry: [f64; N],
    /// `f(t, y)` for the current (possibly projected) state: the first stage of the next step.
    f: [f64; N],
    t_prev: f64,
    y_prev: [f64; N],
    /// Stages of the last accepted step (`k[16] = f(t, y)` at its end before any projection).
    k: Stages<N>,
    h_last: f64,
    h: f64,
    t_end: f64,
    posneg: f64,
    hmax: f64,
    rtol: f64,
    atol: f64,
    max_steps: usize,
    compensated: bool,
    reject: bool,
    done: bool,
    /// Equal steps of size `h` without error control ([`Vern9::fixed_steps`]).
    fixed: bool,
    /// Stages 17..=25 of the last accepted step, computed on the first dense request.
    extra: Cell<Option<[[f64; N]; STAGES - 17]>>,
    stats: Cell<Stats>,
}

impl<'a, S: OdeSystem<N>, const N: usize> Vern9<'a, S, N> {
    /// Prepares an integration of `sys` from `(t0, y0)` towards `t_end` (forward or
    /// backward). The initial step is `opts.h_init` or else Hairer's `HINIT` guess for
    /// order 9. Errors as for [`Dop853::new`](super::Dop853::new).
    pub fn new(
        sys: &'a S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        opts: &Options,
    ) -> Result<Self, IntegrateError> {
        opts.validate()?;
        check_start(t0, &y0, t_end)?;
        let f0 = sys.rhs(t0, &y0);
        if f0.iter().any(|v| !v.is_finite()) {
            return Err(IntegrateError::NonFinite { t: t0 });
        }
        let mut stats = Stats {
            rhs_evals: 1,
            ..Stats::default()
        };
        let posneg = if t_end >= t0 { 1.0 } else { -1.0 };
        let hmax = opts.h_max.unwrap_or((t_end - t0).abs());
        let done = t_end == t0;
        let h = match opts.h_init {
            Some(h) => h.abs().copysign(posneg),
            None if done => 0.0,
            None => {
                stats.rhs_evals += 1;
                hinit(sys, t0, &y0, &f0, posneg, hmax, opts, 9)
            }
        };
        let mut k = [[0.0; N]; STAGES];
        k[16] = f0;
        Ok(Vern9 {
            sys,
            t: t0,
            y: y0,
            carry: [0.0; N],
            f: f0,
            t_prev: t0,
            y_prev: y0,
            k,
            h_last: 0.0,
            h,
            t_end,
            posneg,
            hmax,
            rtol: opts.rtol,
            atol: opts.atol,
            max_steps: opts.max_steps,
            compensated: opts.compensated,
            reject: false,
            done,
            fixed: false,
            extra: Cell::new(None),
            stats: Cell::new(stats),
        })
    }

    /// Prepares `steps` equal steps from `(t0, y0)` to `t_end` without error control (for
    /// convergence-order studies); the stages of the error estimate are skipped.
    pub fn fixed_steps(
        sys: &'a S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        steps: usize,
    ) -> Result<Self, IntegrateError> {
        let opts = fixed_step_options(t0, t_end, steps)?;
        let mut solver = Self::new(sys, t0, y0, t_end, &opts)?;
        solver.fixed = true;
        Ok(solver)
    }

    fn advance(&mut self) -> Result<bool, IntegrateError> {
        if self.done {
            return Ok(true);
        }
        let mut stats = self.stats.get();
        let result = self.attempt_until_accepted(&mut stats);
        self.stats.set(stats);
        result
    }

    fn attempt_until_accepted(&mut self, stats: &mut Stats) -> Result<bool, IntegrateError> {
        let mut h = self.h;
        loop {
            let (h_try, last) =
                next_attempt(self.t, h, self.t_end, self.posneg, stats, self.max_steps)?;
            h = h_try;
            let k = &mut self.k;
            k[0] = self.f;
            // The last stage only serves the error estimate (B[15] = 0).
            let used = if self.fixed {
                STEP_STAGES - 1
            } else {
                STEP_STAGES
            };
            stages(self.sys, self.t, h, &self.y, k, 1..used);
            stats.rhs_evals += used - 1;
            let inc = weighted(&B, k);
            let (err, fac) = if self.fixed {
                (0.0, 1.0)
            } else {
                let est = weighted(&E, k);
                let mut err = 0.0;
                for i in 0..N {
                    let y_new = self.y[i] + h * inc[i];
                    let sk = self.atol + self.rtol * self.y[i].abs().max(y_new.abs());
                    err += (est[i] / sk) * (est[i] / sk);
                }
                err = h.abs() * (err / N as f64).sqrt();
                (err, (SAFE * err.powf(-EXPO)).clamp(FAC_MIN, FAC_MAX))
            };
            if err <= 1.0 {
                let t_new = if last { self.t_end } else { self.t + h };
                let mut y_new = self.y;
                let mut carry = self.carry;
                let delta: [f64; N] = std::array::from_fn(|i| h * inc[i]);
                if self.compensated {
                    compensated_add(&mut y_new, &mut carry, &delta);
                } else {
                    (0..N).for_each(|i| y_new[i] += delta[i]);
                }
                let f_new = self.sys.rhs(t_new, &y_new);
                stats.rhs_evals += 1;
                if y_new.iter().chain(f_new.iter()).any(|v| !v.is_finite()) {
                    return Err(IntegrateError::NonFinite { t: t_new });
                }
                stats.steps += 1;
                self.k[16] = f_new;
                self.f = f_new;
                self.t_prev = self.t;
                self.y_prev = self.y;
                self.t = t_new;
                self.y = y_new;
                self.carry = carry;
                self.h_last = h;
                self.extra.set(None);
                let mut h_new = h * fac;
                if last {
                    self.h = h_new;
                    self.done = true;
                    return Ok(true);
                }
                if h_new.abs() > self.hmax {
                    h_new = self.posneg * self.hmax;
                }
                if self.reject {
                    h_new = self.posneg * h_new.abs().min(h.abs());
                }
                self.reject = false;
                self.h = h_new;
                return Ok(false);
            }
            h *= fac.min(1.0);
            self.reject = true;
            stats.rejected += 1;
        }
    }
}

impl<S: OdeSystem<N>, const N: usize> Stepper<N> for Vern9<'_, S, N> {
    /// One accepted step; `Ok(true)` once `t_end` is reached (the last step lands exactly on
    /// it). Errors as for [`Dop853`](super::Dop853)'s step.
    fn step(&mut self) -> Result<bool, IntegrateError> {
        self.advance()
    }

    fn t_end(&self) -> f64 {
        self.t_end
    }

    // The size of the last accepted step is `h_last`; `h` is the proposal for the next one.
    #[allow(clippy::misnamed_getters)]
    fn h(&self) -> f64 {
        self.h_last
    }

    /// Current time.
    fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// Start time of the last accepted step (`t0` before the first step).
    fn t_prev(&self) -> f64 {
        self.t_prev
    }

    /// Work counters so far.
    fn stats(&self) -> Stats {
        self.stats.get()
    }

    /// Evaluates the 9th-order interpolant of the last accepted step `[t_prev, t]` at `t`.
    ///
    /// It interpolates the step as integrated, from the state at `t_prev`, before any
    /// [`set_state`](Self::set_state). The first call after a step computes the nine extra
    /// stages of the interpolant (nine right-hand-side calls); later calls on the same step
    /// are free. Before the first step it returns the initial state.
    fn dense(&self, t: f64) -> [f64; N] {
        if self.stats.get().steps == 0 {
            return self.y;
        }
        let mut k = self.k;
        match self.extra.get() {
            Some(extra) => k[17..].copy_from_slice(&extra),
            None => {
                stages(
                    self.sys,
                    self.t_prev,
                    self.h_last,
                    &self.y_prev,
                    &mut k,
                    17..STAGES,
                );
                let mut stats = self.stats.get();
                stats.rhs_evals += STAGES - 17;
                self.stats.set(stats);
                let mut extra = [[0.0; N]; STAGES - 17];
                extra.copy_from_slice(&k[17..]);
                self.extra.set(Some(extra));
            }
        }
        let theta = (t - self.t_prev) / self.h_last;
        let mut acc = [0.0; N];
        for (j, r) in R.iter().enumerate() {
            let bj = theta * r.iter().rev().fold(0.0, |p, &c| p * theta + c);
            if bj != 0.0 {
                for i in 0..N {
                    acc[i] += bj * k[j][i];
                }
            }
        }
        std::array::from_fn(|i| self.y_prev[i] + self.h_last * acc[i])
    }

    /// Replaces the current state after a step (e.g. a projection). Recomputes the first
    /// stage of the next step (one right-hand-side call) and clears the summation residue.
    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
        self.carry = [0.0; N];
        self.f = self.sys.rhs(self.t, &self.y);
        let mut stats = self.stats.get();
        stats.rhs_evals += 1;
        self.stats.set(stats);
    }
}
