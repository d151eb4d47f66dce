//! The DOP853 integrator: explicit Runge–Kutta 8(5,3) of Dormand & Prince with
//! the step-size control and 7th-order dense output of Hairer's `dop853.f`.

use std::convert::Infallible;

use super::control::{Clock, Law};
use super::pair::{rk_start, RkRun, RkStart, RungeKutta};
use super::tableau::{dense_at, dense_rows, A, B, BHH, C, ER};
use super::{drive, Control, Drive, IntegrateError, OdeSystem, Options, Stepper};

/// Stage buffer: stages 0..=12 of a step and the three dense-output stages.
type Stages<const N: usize> = [[f64; N]; 16];

/// `y + h * sum_j A[ROW][j] * k[j]` over the listed `cols`, summed left to right.
#[inline(always)]
fn combine<const ROW: usize, const M: usize, const N: usize>(
    y: &[f64; N],
    h: f64,
    k: &Stages<N>,
    cols: [usize; M],
) -> [f64; N] {
    let mut out = [0.0; N];
    for i in 0..N {
        let mut acc = A[ROW][cols[0]] * k[cols[0]][i];
        for &j in &cols[1..] {
            acc += A[ROW][j] * k[j][i];
        }
        out[i] = y[i] + h * acc;
    }
    out
}

/// Computes stages 1..=11 of a step from `(t, y)` with `k[0] = f(t, y)` given
/// (11 right-hand-side calls) and returns the increment `sum_i b_i k_i`.
#[inline(always)]
fn stages<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t: f64,
    h: f64,
    y: &[f64; N],
    k: &mut Stages<N>,
) -> [f64; N] {
    let mut y1 = [0.0; N];
    for i in 0..N {
        y1[i] = y[i] + h * A[1][0] * k[0][i];
    }
    k[1] = sys.rhs(t + C[1] * h, &y1);
    k[2] = sys.rhs(t + C[2] * h, &combine::<2, 2, N>(y, h, k, [0, 1]));
    k[3] = sys.rhs(t + C[3] * h, &combine::<3, 2, N>(y, h, k, [0, 2]));
    k[4] = sys.rhs(t + C[4] * h, &combine::<4, 3, N>(y, h, k, [0, 2, 3]));
    k[5] = sys.rhs(t + C[5] * h, &combine::<5, 3, N>(y, h, k, [0, 3, 4]));
    k[6] = sys.rhs(t + C[6] * h, &combine::<6, 4, N>(y, h, k, [0, 3, 4, 5]));
    k[7] = sys.rhs(t + C[7] * h, &combine::<7, 5, N>(y, h, k, [0, 3, 4, 5, 6]));
    k[8] = sys.rhs(
        t + C[8] * h,
        &combine::<8, 6, N>(y, h, k, [0, 3, 4, 5, 6, 7]),
    );
    k[9] = sys.rhs(
        t + C[9] * h,
        &combine::<9, 7, N>(y, h, k, [0, 3, 4, 5, 6, 7, 8]),
    );
    k[10] = sys.rhs(
        t + C[10] * h,
        &combine::<10, 8, N>(y, h, k, [0, 3, 4, 5, 6, 7, 8, 9]),
    );
    k[11] = sys.rhs(
        t + h,
        &combine::<11, 9, N>(y, h, k, [0, 3, 4, 5, 6, 7, 8, 9, 10]),
    );
    let mut inc = [0.0; N];
    for i in 0..N {
        inc[i] = B[0] * k[0][i]
            + B[5] * k[5][i]
            + B[6] * k[6][i]
            + B[7] * k[7][i]
            + B[8] * k[8][i]
            + B[9] * k[9][i]
            + B[10] * k[10][i]
            + B[11] * k[11][i];
    }
    inc
}

/// DOP853's scaled error of an attempt of size `h` in dimension `n` from the sums of squares
/// of its scaled 5th- and 3rd-order error estimates: `|h| err5 / sqrt(n (err5 + 0.01 err3))`
/// (Hairer's `dop853.f`; the denominator 1 when it vanishes).
#[inline(always)]
pub(crate) fn scaled_error(err5: f64, err3: f64, h: f64, n: usize) -> f64 {
    let mut deno = err5 + 0.01 * err3;
    if deno <= 0.0 {
        deno = 1.0;
    }
    h.abs() * err5 * (1.0 / (n as f64 * deno)).sqrt()
}

/// Adaptive explicit Runge–Kutta 8(5,3) of Dormand & Prince (DOP853), with the
/// 7th-order dense output.
///
/// A faithful port of the core of Hairer's `dop853.f` (scalar tolerances):
/// the same stages, the combined 5th/3rd-order error estimate
/// `err = err5^2 / sqrt(err5^2 + 0.01 err3^2)`, the same controller
/// (`fac1 = 0.333`, `fac2 = 6`, safety 0.9, `beta = 0`: [`Law::Dop853`] of the step control
/// [`StepControl`](super::StepControl), shared with the batched lanes) and the same initial
/// step guess, so step counts agree with the published code. The stiffness
/// detection of `dop853.f` is not implemented. One departure: the update
/// `y + h sum b_i k_i` is summed with compensation
/// ([`compensated_add`](super::compensated::compensated_add)), which
/// removes the accumulated rounding of long runs. All state lives inline in the
/// struct; a step performs no heap allocation.
pub struct Dop853<'a, S, const N: usize> {
    /// The field, step control, state and dense-output coefficients of the run ([`RkRun`]).
    run: RkRun<'a, S, [[f64; N]; 8], N>,
    /// Step end as computed by the last accepted step, before any `set_state`.
    y_raw: [f64; N],
    /// Stages of the last accepted step (stage 12 = `f(t, y_raw)`).
    k: Stages<N>,
}

impl<'a, S: OdeSystem<N>, const N: usize> Dop853<'a, S, N> {
    /// Prepares an integration of `sys` from `(t0, y0)` towards `t_end`, which may
    /// lie before `t0` (backward integration). The initial step is
    /// `opts.h_init()` or else Hairer's `HINIT` guess. Evaluates `f(t0, y0)`.
    ///
    /// Fails with [`IntegrateError::InvalidOption`] for non-finite `t0`, `t_end`,
    /// and with [`IntegrateError::NonFinite`] if `y0` or `f(t0, y0)` is not finite.
    pub fn new(
        sys: &'a S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        opts: &Options,
    ) -> Result<Self, IntegrateError> {
        rk_start(sys, t0, y0, t_end, opts, Law::Dop853, Self::ORDER).map(Self::from_start)
    }
}

impl<'a, S: OdeSystem<N>, const N: usize> RungeKutta<'a, S, N> for Dop853<'a, S, N> {
    const ORDER: i32 = 8;

    fn from_start(start: RkStart<'a, S, N>) -> Self {
        let mut k = [[0.0; N]; 16];
        k[12] = start.f0;
        Dop853 {
            y_raw: start.y0,
            k,
            run: RkRun::new(start),
        }
    }
}

impl<S: OdeSystem<N>, const N: usize> Dop853<'_, S, N> {
    /// Performs one accepted step (rejected attempts are repeated internally)
    /// and returns `Ok(true)` once `t_end` is reached; the last step lands
    /// exactly on `t_end`. After that, further calls do nothing and return
    /// `Ok(true)`. The attempts, their acceptance and the failures are those of the
    /// [`StepControl`](super::StepControl).
    ///
    /// Errors: [`IntegrateError::StepSizeTooSmall`] when `0.1 |h| <= |t| * 2.3e-16`,
    /// [`IntegrateError::TooManySteps`] when `max_steps` attempts were made,
    /// [`IntegrateError::NonFinite`] when the step size, the new state or its
    /// derivative is not finite. After a failed call only [`t`](Self::t),
    /// [`y`](Self::y) and [`stats`](Self::stats) remain meaningful.
    pub fn step(&mut self) -> Result<bool, IntegrateError> {
        let run = &mut self.run;
        if run.ctl.done() {
            return Ok(true);
        }
        loop {
            let h = run.ctl.attempt()?;
            let t = run.ctl.t();
            self.k[0] = run.f;
            let inc = stages(run.sys, t, h, &run.y, &mut self.k);
            run.ctl.count_evals(11);
            let (mut err5, mut err3) = (0.0, 0.0);
            let k = &self.k;
            for i in 0..N {
                let (s, sk) = run.weight(i, run.y[i] + h * inc[i]);
                let e3 = (inc[i] - BHH[0] * k[0][i] - BHH[8] * k[8][i] - BHH[11] * k[11][i]) * s;
                err3 += (e3 / sk) * (e3 / sk);
                let e5 = ER[0] * k[0][i]
                    + ER[5] * k[5][i]
                    + ER[6] * k[6][i]
                    + ER[7] * k[7][i]
                    + ER[8] * k[8][i]
                    + ER[9] * k[9][i]
                    + ER[10] * k[10][i]
                    + ER[11] * k[11][i];
                let e5 = e5 * s;
                err5 += (e5 / sk) * (e5 / sk);
            }
            if !run.ctl.judge(scaled_error(err5, err3, h, N)) {
                continue;
            }
            let last = run.accept(&std::array::from_fn(|i| h * inc[i]))?;
            self.k[12] = run.f;
            self.y_raw = run.y;
            return Ok(last);
        }
    }

    /// Hairer's `CONT` array of the last accepted step (`CONTD8` coefficients).
    fn dense_coefficients(&self) -> [[f64; N]; 8] {
        let run = &self.run;
        let h = run.ctl.h_last();
        let (t, y) = (run.ctl.t_prev(), &run.y_prev);
        let mut k = self.k;
        k[13] = run.sys.rhs(
            t + C[13] * h,
            &combine::<13, 8, N>(y, h, &k, [0, 6, 7, 8, 9, 10, 11, 12]),
        );
        k[14] = run.sys.rhs(
            t + C[14] * h,
            &combine::<14, 8, N>(y, h, &k, [0, 5, 6, 7, 10, 11, 12, 13]),
        );
        k[15] = run.sys.rhs(
            t + C[15] * h,
            &combine::<15, 8, N>(y, h, &k, [0, 5, 6, 7, 8, 12, 13, 14]),
        );
        dense_rows(y, &self.y_raw, h, &k)
    }
}

impl<S: OdeSystem<N>, const N: usize> Stepper<N> for Dop853<'_, S, N> {
    fn step(&mut self) -> Result<bool, IntegrateError> {
        Dop853::step(self)
    }

    fn clock(&self) -> Clock {
        self.run.clock()
    }

    /// Current state.
    fn y(&self) -> &[f64; N] {
        &self.run.y
    }

    /// Evaluates the 7th-order continuous extension of the last accepted step
    /// `[t_prev, t]` at `t` (extrapolates outside that interval).
    ///
    /// The interpolant describes the step as integrated, from the state at
    /// `t_prev` to the step end before any [`set_state`](Self::set_state).
    /// Its coefficients are built at the first call after a step, which costs
    /// three right-hand-side calls (Hairer's stages 14–16); later calls on the
    /// same step are free. Before the first step it returns the initial state.
    fn dense(&self, t: f64) -> [f64; N] {
        match self.run.dense(3, || self.dense_coefficients()) {
            Some(cont) => {
                let ctl = &self.run.ctl;
                dense_at(&cont, (t - ctl.t_prev()) / ctl.h_last())
            }
            None => self.run.y,
        }
    }

    /// Replaces the current state after a step (e.g. a projection onto
    /// invariant manifolds). Recomputes the derivative used as first stage of
    /// the next step (one right-hand-side call). The dense output of the last
    /// step is unaffected and still interpolates the unprojected step.
    fn set_state(&mut self, y: [f64; N]) {
        self.run.set_state(y);
    }
}

/// Integrates `sys` from `(t0, y0)` to `t_end` with `n` equal DOP853 steps
/// without error control ([`RungeKutta::fixed_steps`] through the one driver [`drive`]), for
/// convergence-order studies; returns `y(t_end)`.
pub fn fixed_step_solve<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    n: usize,
) -> Result<[f64; N], IntegrateError> {
    let mut solver: Dop853<S, N> = RungeKutta::fixed_steps(sys, t0, y0, t_end, n)?;
    let Ok(outcome) = drive::<_, Infallible, N>(
        &mut solver,
        &Drive::default(),
        &mut |_, _| Ok(()),
        &mut |_, _, _| Ok(Control::Continue),
    );
    Ok(outcome.into_result()?.y)
}
