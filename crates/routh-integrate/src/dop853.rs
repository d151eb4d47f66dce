//! The DOP853 integrator: explicit Runge–Kutta 8(5,3) of Dormand & Prince with
//! the step-size control and 7th-order dense output of Hairer's `dop853.f`.

use std::cell::Cell;

use super::compensated::compensated_add;
use super::control::{fixed_step_options, Clock, Law, StepControl};
use super::tableau::{dense_at, dense_rows, A, B, BHH, C, ER};
use super::{check_start, drive, Control, Drive, IntegrateError, OdeSystem, Options, Stepper};

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

/// Hairer's initial step size guess `HINIT` for a method of order `order`, given
/// `f0 = f(t, y)` (one right-hand-side call).
#[allow(clippy::too_many_arguments)] // Hairer's argument list
pub fn hinit<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    f0: &[f64; N],
    posneg: f64,
    hmax: f64,
    opts: &Options,
    order: i32,
) -> f64 {
    let (mut dnf, mut dny) = (0.0, 0.0);
    for i in 0..N {
        let sk = opts.atol + opts.rtol * y[i].abs();
        dnf += (f0[i] / sk).powi(2);
        dny += (y[i] / sk).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1.0e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = h.min(hmax).copysign(posneg);
    let mut y1 = [0.0; N];
    for i in 0..N {
        y1[i] = y[i] + h * f0[i];
    }
    let f1 = sys.rhs(t + h, &y1);
    let mut der2 = 0.0;
    for i in 0..N {
        let sk = opts.atol + opts.rtol * y[i].abs();
        der2 += ((f1[i] - f0[i]) / sk).powi(2);
    }
    der2 = der2.sqrt() / h;
    let der12 = der2.abs().max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        1.0e-6_f64.max(h.abs() * 1.0e-3)
    } else {
        (0.01 / der12).powf(1.0 / f64::from(order))
    };
    (100.0 * h.abs()).min(h1).min(hmax).copysign(posneg)
}

/// A run of a Runge–Kutta pair at its start ([`RungeKutta::from_start`]): the arguments
/// checked, `f(t0, y0)` evaluated and the run's [`StepControl`] made.
pub struct RkStart<'a, S, const N: usize> {
    pub(crate) sys: &'a S,
    pub(crate) y0: [f64; N],
    pub(crate) f0: [f64; N],
    pub(crate) control: StepControl,
    pub(crate) opts: Options,
}

/// The start of a run of a Runge–Kutta pair of `order` under `law` from `(t0, y0)` to
/// `t_end`, for the steppers and the lanes: the checks of the options and of the arguments,
/// `f(t0, y0)` (refused when not finite: [`IntegrateError::NonFinite`]) and the run's
/// [`StepControl`], its first step `opts.h_init` or Hairer's `HINIT` for a method of order
/// `order` (the evaluations counted: one, two with `HINIT`).
pub(crate) fn rk_start<'a, S: OdeSystem<N>, const N: usize>(
    sys: &'a S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    opts: &Options,
    law: Law,
    order: i32,
) -> Result<RkStart<'a, S, N>, IntegrateError> {
    opts.validate()?;
    check_start(t0, &y0, t_end)?;
    let f0 = sys.rhs(t0, &y0);
    if f0.iter().any(|v| !v.is_finite()) {
        return Err(IntegrateError::NonFinite { t: t0 });
    }
    let mut guessed = false;
    let mut control = StepControl::new(law, t0, t_end, opts, |posneg, hmax| {
        guessed = true;
        hinit(sys, t0, &y0, &f0, posneg, hmax, opts, order)
    });
    control.count_evals(1 + usize::from(guessed));
    Ok(RkStart {
        sys,
        y0,
        f0,
        control,
        opts: *opts,
    })
}

/// The adaptive Runge–Kutta pairs ([`Dop853`], [`Vern9`](super::Vern9)): built from their
/// start under a step-size [`Law`], and so with equal steps by the same code.
pub trait RungeKutta<'a, S: OdeSystem<N> + 'a, const N: usize>: Sized {
    /// The order of Hairer's initial step guess (`HINIT`) for this pair.
    const ORDER: i32;

    /// The stepper from the start of its run.
    fn from_start(start: RkStart<'a, S, N>) -> Self;

    /// `steps` equal steps of `sys` from `(t0, y0)` to `t_end`, each accepted without error
    /// control ([`Law::Fixed`]), the last landing on `t_end`: the method's own order, for
    /// convergence studies. The dense output and the driver work as for the adaptive steps.
    /// Fails as the pair's `new` does, and with [`IntegrateError::InvalidOption`] for
    /// `steps = 0`.
    fn fixed_steps(
        sys: &'a S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        steps: usize,
    ) -> Result<Self, IntegrateError> {
        let opts = fixed_step_options(t0, t_end, steps)?;
        rk_start(sys, t0, y0, t_end, &opts, Law::Fixed, Self::ORDER).map(Self::from_start)
    }
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
/// [`StepControl`], shared with the batched lanes) and the same initial
/// step guess, so step counts agree with the published code. The stiffness
/// detection of `dop853.f` is not implemented. One departure: the update
/// `y + h sum b_i k_i` is summed with compensation ([`compensated_add`]), which
/// removes the accumulated rounding of long runs. All state lives inline in the
/// struct; a step performs no heap allocation.
pub struct Dop853<'a, S, const N: usize> {
    sys: &'a S,
    /// Time, step sizes, acceptance, end and counters of the run.
    ctl: StepControl,
    y: [f64; N],
    /// Rounding residue of the compensated update (zero after [`set_state`](Self::set_state)).
    carry: [f64; N],
    /// `f(t, y)` for the current (possibly projected) state.
    f: [f64; N],
    y_prev: [f64; N],
    /// Step end as computed by the last accepted step, before any `set_state`.
    y_raw: [f64; N],
    /// Stages of the last accepted step (stage 12 = `f(t, y_raw)`).
    k: Stages<N>,
    rtol: f64,
    atol: f64,
    compensated: bool,
    /// Dense-output coefficients of the last accepted step, built on demand.
    cont: Cell<Option<[[f64; N]; 8]>>,
    /// Field evaluations of the dense output (counted beside [`StepControl::stats`]).
    dense_evals: Cell<usize>,
}

impl<'a, S: OdeSystem<N>, const N: usize> Dop853<'a, S, N> {
    /// Prepares an integration of `sys` from `(t0, y0)` towards `t_end`, which may
    /// lie before `t0` (backward integration). The initial step is
    /// `opts.h_init` or else Hairer's `HINIT` guess. Evaluates `f(t0, y0)`.
    ///
    /// Fails with [`IntegrateError::InvalidOption`] for invalid options or
    /// non-finite `t0`, `t_end`, and with [`IntegrateError::NonFinite`] if
    /// `y0` or `f(t0, y0)` is not finite.
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
        let (y, opts) = (start.y0, start.opts);
        let mut k = [[0.0; N]; 16];
        k[12] = start.f0;
        Dop853 {
            sys: start.sys,
            ctl: start.control,
            f: start.f0,
            k,
            y,
            y_prev: y,
            y_raw: y,
            carry: [0.0; N],
            rtol: opts.rtol,
            atol: opts.atol,
            compensated: opts.compensated,
            cont: Cell::new(None),
            dense_evals: Cell::new(0),
        }
    }
}

impl<S: OdeSystem<N>, const N: usize> Dop853<'_, S, N> {
    /// Performs one accepted step (rejected attempts are repeated internally)
    /// and returns `Ok(true)` once `t_end` is reached; the last step lands
    /// exactly on `t_end`. After that, further calls do nothing and return
    /// `Ok(true)`. The attempts, their acceptance and the failures are those of the
    /// [`StepControl`].
    ///
    /// Errors: [`IntegrateError::StepSizeTooSmall`] when `0.1 |h| <= |t| * 2.3e-16`,
    /// [`IntegrateError::TooManySteps`] when `max_steps` attempts were made,
    /// [`IntegrateError::NonFinite`] when the step size, the new state or its
    /// derivative is not finite. After a failed call only [`t`](Self::t),
    /// [`y`](Self::y) and [`stats`](Self::stats) remain meaningful.
    pub fn step(&mut self) -> Result<bool, IntegrateError> {
        if self.ctl.done() {
            return Ok(true);
        }
        loop {
            let h = self.ctl.attempt()?;
            let t = self.ctl.t();
            self.k[0] = self.f;
            let inc = stages(self.sys, t, h, &self.y, &mut self.k);
            self.ctl.count_evals(11);
            let mut y_new = [0.0; N];
            let (mut err5, mut err3) = (0.0, 0.0);
            let k = &self.k;
            for i in 0..N {
                y_new[i] = self.y[i] + h * inc[i];
                let sk = self.atol + self.rtol * self.y[i].abs().max(y_new[i].abs());
                let e3 = inc[i] - BHH[0] * k[0][i] - BHH[8] * k[8][i] - BHH[11] * k[11][i];
                err3 += (e3 / sk) * (e3 / sk);
                let e5 = ER[0] * k[0][i]
                    + ER[5] * k[5][i]
                    + ER[6] * k[6][i]
                    + ER[7] * k[7][i]
                    + ER[8] * k[8][i]
                    + ER[9] * k[9][i]
                    + ER[10] * k[10][i]
                    + ER[11] * k[11][i];
                err5 += (e5 / sk) * (e5 / sk);
            }
            if !self.ctl.judge(scaled_error(err5, err3, h, N)) {
                continue;
            }
            let t_new = self.ctl.t_next();
            let mut carry = self.carry;
            if self.compensated {
                y_new = self.y;
                compensated_add(&mut y_new, &mut carry, &std::array::from_fn(|i| h * inc[i]));
            }
            let f_new = self.sys.rhs(t_new, &y_new);
            self.ctl.count_evals(1);
            let finite = y_new.iter().chain(f_new.iter()).all(|v| v.is_finite());
            let last = self.ctl.advance(finite)?;
            self.k[12] = f_new;
            self.y_prev = self.y;
            self.y = y_new;
            self.carry = carry;
            self.y_raw = y_new;
            self.f = f_new;
            self.cont.set(None);
            return Ok(last);
        }
    }

    /// Hairer's `CONT` array of the last accepted step (`CONTD8` coefficients).
    fn dense_coefficients(&self) -> [[f64; N]; 8] {
        let h = self.ctl.h_last();
        let (t, y) = (self.ctl.t_prev(), &self.y_prev);
        let mut k = self.k;
        k[13] = self.sys.rhs(
            t + C[13] * h,
            &combine::<13, 8, N>(y, h, &k, [0, 6, 7, 8, 9, 10, 11, 12]),
        );
        k[14] = self.sys.rhs(
            t + C[14] * h,
            &combine::<14, 8, N>(y, h, &k, [0, 5, 6, 7, 10, 11, 12, 13]),
        );
        k[15] = self.sys.rhs(
            t + C[15] * h,
            &combine::<15, 8, N>(y, h, &k, [0, 5, 6, 7, 8, 12, 13, 14]),
        );
        self.dense_evals.set(self.dense_evals.get() + 3);
        dense_rows(y, &self.y_raw, h, &k)
    }
}

impl<S: OdeSystem<N>, const N: usize> Stepper<N> for Dop853<'_, S, N> {
    fn step(&mut self) -> Result<bool, IntegrateError> {
        Dop853::step(self)
    }

    fn clock(&self) -> Clock {
        self.ctl.clock().with_evals(self.dense_evals.get())
    }

    /// Current state.
    fn y(&self) -> &[f64; N] {
        &self.y
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
        if self.ctl.stats().steps == 0 {
            return self.y;
        }
        let cont = match self.cont.get() {
            Some(c) => c,
            None => {
                let c = self.dense_coefficients();
                self.cont.set(Some(c));
                c
            }
        };
        dense_at(&cont, (t - self.ctl.t_prev()) / self.ctl.h_last())
    }

    /// Replaces the current state after a step (e.g. a projection onto
    /// invariant manifolds). Recomputes the derivative used as first stage of
    /// the next step (one right-hand-side call). The dense output of the last
    /// step is unaffected and still interpolates the unprojected step.
    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
        self.carry = [0.0; N];
        self.f = self.sys.rhs(self.ctl.t(), &self.y);
        self.ctl.count_evals(1);
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
    let outcome = drive::<_, IntegrateError, N>(
        &mut solver,
        &Drive::default(),
        &mut |_, _| Ok(()),
        &mut |_, _, _| Ok(Control::Continue),
    )?;
    Ok(outcome.y)
}
