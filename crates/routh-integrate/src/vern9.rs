//! Verner's "most efficient" 9(8) Runge–Kutta pair with its 9th-order interpolant
//! (J. H. Verner, "Numerically optimal Runge–Kutta pairs with interpolants", Numer.
//! Algorithms 53 (2010) 383–396; coefficients in [`super::vern9_tableau`]).
//!
//! Sixteen stages per step (the 16th only for the error estimate), local extrapolation
//! (the step advances with the 9th-order solution), an error estimate from the embedded
//! 8th-order solution, the step control of every method
//! ([`StepControl`](super::StepControl), with the step-size law [`Law::Vern9`]: exponent
//! 1/9), the initial step of [`Dop853`](super::Dop853) and the bookkeeping of its run
//! ([`RkRun`]: compensated summation of the update, projection, dense output on demand). The
//! interpolant costs nine more right-hand-side calls, made only when a step's dense output is
//! first asked for. A [`Stepper`]: it runs in the one driver [`drive`](super::drive);
//! [`RungeKutta::fixed_steps`] takes equal steps without error control (for convergence-order
//! studies) through the same step code.

use super::control::{Clock, Law};
use super::pair::{rk_start, RkRun, RkStart, RungeKutta};
use super::vern9_tableau::{A, B, C, E, R, STAGES, STEP_STAGES};
use super::{IntegrateError, OdeSystem, Options, Stepper};

/// Stage derivatives `k_0 .. k_25`.
type Stages<const N: usize> = [[f64; N]; STAGES];

/// `y + h * sum_j a_sj k_j` over the nonzero entries of row `s` of [`A`], as
/// `(y + h * sum_{j < l} a_sj k_j) + (h a_sl) k_l` with `l` the last stage of the row (the
/// rows are in increasing `j`): the stages are a chain (each stage's field waits for the
/// stage before), and this way only one product and one sum wait for the last stage instead
/// of two of each (5 % less time per step, BENCHMARKS.md; the same sum, rounded differently).
#[inline(always)]
fn stage_state<const N: usize>(y: &[f64; N], h: f64, k: &Stages<N>, s: usize) -> [f64; N] {
    let Some((&(last, a_last), earlier)) = A[s].split_last() else {
        return *y;
    };
    let mut acc = [0.0; N];
    for &(j, a) in earlier {
        for i in 0..N {
            acc[i] += a * k[j][i];
        }
    }
    let ha = h * a_last;
    std::array::from_fn(|i| (y[i] + h * acc[i]) + ha * k[last][i])
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
    /// The field, step control, state and interpolant stages of the run ([`RkRun`]: stages
    /// 17..=25 of the last accepted step, computed on the first dense request).
    run: RkRun<'a, S, [[f64; N]; STAGES - 17], N>,
    /// Stages of the last accepted step (`k[16] = f(t, y)` at its end before any projection).
    k: Stages<N>,
}

impl<'a, S: OdeSystem<N>, const N: usize> Vern9<'a, S, N> {
    /// Prepares an integration of `sys` from `(t0, y0)` towards `t_end` (forward or
    /// backward). The initial step is `opts.h_init()` or else Hairer's `HINIT` guess for
    /// order 9. Errors as for [`Dop853::new`](super::Dop853::new).
    pub fn new(
        sys: &'a S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        opts: &Options,
    ) -> Result<Self, IntegrateError> {
        rk_start(sys, t0, y0, t_end, opts, Law::Vern9, Self::ORDER).map(Self::from_start)
    }
}

impl<'a, S: OdeSystem<N>, const N: usize> RungeKutta<'a, S, N> for Vern9<'a, S, N> {
    const ORDER: i32 = 9;

    fn from_start(start: RkStart<'a, S, N>) -> Self {
        let mut k = [[0.0; N]; STAGES];
        k[16] = start.f0;
        Vern9 {
            k,
            run: RkRun::new(start),
        }
    }
}

impl<S: OdeSystem<N>, const N: usize> Vern9<'_, S, N> {
    fn advance(&mut self) -> Result<bool, IntegrateError> {
        let run = &mut self.run;
        if run.ctl.done() {
            return Ok(true);
        }
        let fixed = run.ctl.law() == Law::Fixed;
        loop {
            let h = run.ctl.attempt()?;
            let t = run.ctl.t();
            let k = &mut self.k;
            k[0] = run.f;
            // The last stage only serves the error estimate (B[15] = 0).
            let used = if fixed { STEP_STAGES - 1 } else { STEP_STAGES };
            stages(run.sys, t, h, &run.y, k, 1..used);
            run.ctl.count_evals(used - 1);
            let inc = weighted(&B, k);
            let err = if fixed {
                0.0
            } else {
                let est = weighted(&E, k);
                let mut err = 0.0;
                for i in 0..N {
                    let (s, sk) = run.weight(i, run.y[i] + h * inc[i]);
                    let e = est[i] * s;
                    err += (e / sk) * (e / sk);
                }
                h.abs() * (err / N as f64).sqrt()
            };
            if !run.ctl.judge(err) {
                continue;
            }
            let last = run.accept(&std::array::from_fn(|i| h * inc[i]))?;
            self.k[16] = run.f;
            return Ok(last);
        }
    }

    /// Stages 17..=25 of the last accepted step (nine field evaluations).
    fn interpolant_stages(&self) -> [[f64; N]; STAGES - 17] {
        let run = &self.run;
        let mut k = self.k;
        let (t_prev, h) = (run.ctl.t_prev(), run.ctl.h_last());
        stages(run.sys, t_prev, h, &run.y_prev, &mut k, 17..STAGES);
        let mut extra = [[0.0; N]; STAGES - 17];
        extra.copy_from_slice(&k[17..]);
        extra
    }
}

impl<S: OdeSystem<N>, const N: usize> Stepper<N> for Vern9<'_, S, N> {
    /// One accepted step; `Ok(true)` once `t_end` is reached (the last step lands exactly on
    /// it). Errors as for [`Dop853`](super::Dop853)'s step.
    fn step(&mut self) -> Result<bool, IntegrateError> {
        self.advance()
    }

    fn clock(&self) -> Clock {
        self.run.clock()
    }

    /// Current state.
    fn y(&self) -> &[f64; N] {
        &self.run.y
    }

    /// Evaluates the 9th-order interpolant of the last accepted step `[t_prev, t]` at `t`.
    ///
    /// It interpolates the step as integrated, from the state at `t_prev`, before any
    /// [`set_state`](Self::set_state). The first call after a step computes the nine extra
    /// stages of the interpolant (nine right-hand-side calls); later calls on the same step
    /// are free. Before the first step it returns the initial state.
    fn dense(&self, t: f64) -> [f64; N] {
        let Some(extra) = self.run.dense(STAGES - 17, || self.interpolant_stages()) else {
            return self.run.y;
        };
        let (t_prev, h) = (self.run.ctl.t_prev(), self.run.ctl.h_last());
        let mut k = self.k;
        k[17..].copy_from_slice(&extra);
        let theta = (t - t_prev) / h;
        let mut acc = [0.0; N];
        for (j, r) in R.iter().enumerate() {
            let bj = theta * r.iter().rev().fold(0.0, |p, &c| p * theta + c);
            if bj != 0.0 {
                for i in 0..N {
                    acc[i] += bj * k[j][i];
                }
            }
        }
        std::array::from_fn(|i| self.run.y_prev[i] + h * acc[i])
    }

    /// Replaces the current state after a step (e.g. a projection). Recomputes the first
    /// stage of the next step (one right-hand-side call) and clears the summation residue.
    fn set_state(&mut self, y: [f64; N]) {
        self.run.set_state(y);
    }
}
