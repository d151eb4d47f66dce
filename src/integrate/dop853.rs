//! The DOP853 integrator: explicit Runge–Kutta 8(5,3) of Dormand & Prince with
//! the step-size control and 7th-order dense output of Hairer's `dop853.f`.

use std::cell::Cell;

use super::compensated::compensated_add;
use super::tableau::{dense_at, dense_rows, A, B, BHH, C, ER};
use super::{
    check_start, drive, Control, Drive, IntegrateError, OdeSystem, Options, Stats, Stepper,
};

/// Rounding unit used in the step-size-too-small test (Hairer's `UROUND`).
const UROUND: f64 = 2.3e-16;

/// The checks before an attempted step of the adaptive Runge–Kutta loops (DOP853, Vern9), as
/// in Hairer's `dop853.f`: a non-finite `h`, the step budget `max_steps` (accepted and
/// rejected), a step below the round-off of `t`; then `h` shortened to land on `t_end` when
/// the step would pass or nearly reach it. Returns the step to attempt and whether it is the
/// last.
pub(crate) fn next_attempt(
    t: f64,
    h: f64,
    t_end: f64,
    posneg: f64,
    stats: &Stats,
    max_steps: usize,
) -> Result<(f64, bool), IntegrateError> {
    if !h.is_finite() {
        return Err(IntegrateError::NonFinite { t });
    }
    if stats.steps + stats.rejected >= max_steps {
        return Err(IntegrateError::TooManySteps { t, max_steps });
    }
    if 0.1 * h.abs() <= t.abs() * UROUND {
        return Err(IntegrateError::StepSizeTooSmall { t, h });
    }
    if (t + 1.01 * h - t_end) * posneg > 0.0 {
        Ok((t_end - t, true))
    } else {
        Ok((h, false))
    }
}

/// The options of `steps` equal steps from `t0` to `t_end` without error control: the step
/// as the initial step, a budget of `steps` steps. `steps = 0` is refused
/// ([`IntegrateError::InvalidOption`]).
pub(crate) fn fixed_step_options(
    t0: f64,
    t_end: f64,
    steps: usize,
) -> Result<Options, IntegrateError> {
    if steps == 0 {
        return Err(IntegrateError::InvalidOption {
            name: "steps",
            value: 0.0,
            rule: "must be > 0",
        });
    }
    let h = (t_end - t0) / steps as f64;
    Ok(Options {
        h_init: (h != 0.0).then_some(h),
        max_steps: steps,
        ..Options::default()
    })
}

/// Safety factor of the step-size prediction.
const SAFE: f64 = 0.9;
/// Lower bound `FAC1` of `h_new / h`.
const FAC1: f64 = 0.333;
/// Upper bound `FAC2` of `h_new / h`.
const FAC2: f64 = 6.0;
/// Exponent `1/8 - 0.2 beta` of the controller with Lund stabilisation `beta = 0`.
const EXPO1: f64 = 1.0 / 8.0;

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

/// Adaptive explicit Runge–Kutta 8(5,3) of Dormand & Prince (DOP853), with the
/// 7th-order dense output.
///
/// A faithful port of the core of Hairer's `dop853.f` (scalar tolerances):
/// the same stages, the combined 5th/3rd-order error estimate
/// `err = err5^2 / sqrt(err5^2 + 0.01 err3^2)`, the same controller
/// (`fac1 = 0.333`, `fac2 = 6`, safety 0.9, `beta = 0`) and the same initial
/// step guess, so step counts agree with the published code. The stiffness
/// detection of `dop853.f` is not implemented. One departure: the update
/// `y + h sum b_i k_i` is summed with compensation ([`compensated_add`]), which
/// removes the accumulated rounding of long runs. All state lives inline in the
/// struct; a step performs no heap allocation.
pub struct Dop853<'a, S, const N: usize> {
    sys: &'a S,
    t: f64,
    y: [f64; N],
    /// Rounding residue of the compensated update (zero after [`set_state`](Self::set_state)).
    carry: [f64; N],
    /// `f(t, y)` for the current (possibly projected) state.
    f: [f64; N],
    t_prev: f64,
    y_prev: [f64; N],
    /// Step end as computed by the last accepted step, before any `set_state`.
    y_raw: [f64; N],
    /// Stages of the last accepted step (stage 12 = `f(t, y_raw)`).
    k: Stages<N>,
    /// Size of the last accepted step.
    h_last: f64,
    /// Proposed size of the next step.
    h: f64,
    t_end: f64,
    posneg: f64,
    hmax: f64,
    rtol: f64,
    atol: f64,
    max_steps: usize,
    compensated: bool,
    /// Every step accepted with the same size ([`Dop853::fixed_steps`]): no error control.
    fixed: bool,
    facold: f64,
    reject: bool,
    done: bool,
    /// Dense-output coefficients of the last accepted step, built on demand.
    cont: Cell<Option<[[f64; N]; 8]>>,
    stats: Cell<Stats>,
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
        opts.validate()?;
        check_start(t0, &y0, t_end)?;
        let f0 = sys.rhs(t0, &y0);
        let mut stats = Stats {
            rhs_evals: 1,
            ..Stats::default()
        };
        if f0.iter().any(|v| !v.is_finite()) {
            return Err(IntegrateError::NonFinite { t: t0 });
        }
        let posneg = if t_end >= t0 { 1.0 } else { -1.0 };
        let hmax = opts.h_max.unwrap_or((t_end - t0).abs());
        let done = t_end == t0;
        let h = match opts.h_init {
            Some(h) => h.abs().copysign(posneg),
            None if done => 0.0,
            None => {
                stats.rhs_evals += 1;
                hinit(sys, t0, &y0, &f0, posneg, hmax, opts, 8)
            }
        };
        let mut k = [[0.0; N]; 16];
        k[12] = f0;
        Ok(Dop853 {
            sys,
            t: t0,
            y: y0,
            carry: [0.0; N],
            f: f0,
            t_prev: t0,
            y_prev: y0,
            y_raw: y0,
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
            fixed: false,
            facold: 1e-4,
            reject: false,
            done,
            cont: Cell::new(None),
            stats: Cell::new(stats),
        })
    }

    /// `steps` equal steps of `sys` from `(t0, y0)` to `t_end`, each accepted without error
    /// control, the last landing on `t_end`: the method's own order 8, for convergence
    /// studies. The dense output and the driver work as for the adaptive steps.
    ///
    /// Fails as [`Dop853::new`] does, and with [`IntegrateError::InvalidOption`] for
    /// `steps = 0`.
    pub fn fixed_steps(
        sys: &'a S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        steps: usize,
    ) -> Result<Self, IntegrateError> {
        let mut solver = Self::new(sys, t0, y0, t_end, &fixed_step_options(t0, t_end, steps)?)?;
        solver.fixed = true;
        Ok(solver)
    }

    /// Performs one accepted step (rejected attempts are repeated internally)
    /// and returns `Ok(true)` once `t_end` is reached; the last step lands
    /// exactly on `t_end`. After that, further calls do nothing and return
    /// `Ok(true)`.
    ///
    /// Errors: [`IntegrateError::StepSizeTooSmall`] when `0.1 |h| <= |t| * 2.3e-16`,
    /// [`IntegrateError::TooManySteps`] when `max_steps` attempts were made,
    /// [`IntegrateError::NonFinite`] when the step size, the new state or its
    /// derivative is not finite. After a failed call only [`t`](Self::t),
    /// [`y`](Self::y) and [`stats`](Self::stats) remain meaningful.
    pub fn step(&mut self) -> Result<bool, IntegrateError> {
        if self.done {
            return Ok(true);
        }
        let mut stats = self.stats.get();
        let result = self.attempt_until_accepted(&mut stats);
        self.stats.set(stats);
        result
    }

    fn attempt_until_accepted(&mut self, stats: &mut Stats) -> Result<bool, IntegrateError> {
        let (facc1, facc2) = (1.0 / FAC1, 1.0 / FAC2);
        let mut h = self.h;
        loop {
            let (h_try, last) =
                next_attempt(self.t, h, self.t_end, self.posneg, stats, self.max_steps)?;
            h = h_try;
            self.k[0] = self.f;
            let inc = stages(self.sys, self.t, h, &self.y, &mut self.k);
            stats.rhs_evals += 11;
            let mut y_new = [0.0; N];
            let (mut err, mut err2) = (0.0, 0.0);
            let k = &self.k;
            for i in 0..N {
                y_new[i] = self.y[i] + h * inc[i];
                let sk = self.atol + self.rtol * self.y[i].abs().max(y_new[i].abs());
                let e3 = inc[i] - BHH[0] * k[0][i] - BHH[8] * k[8][i] - BHH[11] * k[11][i];
                err2 += (e3 / sk) * (e3 / sk);
                let e5 = ER[0] * k[0][i]
                    + ER[5] * k[5][i]
                    + ER[6] * k[6][i]
                    + ER[7] * k[7][i]
                    + ER[8] * k[8][i]
                    + ER[9] * k[9][i]
                    + ER[10] * k[10][i]
                    + ER[11] * k[11][i];
                err += (e5 / sk) * (e5 / sk);
            }
            let mut deno = err + 0.01 * err2;
            if deno <= 0.0 {
                deno = 1.0;
            }
            err = h.abs() * err * (1.0 / (N as f64 * deno)).sqrt();
            let fac11 = err.powf(EXPO1);
            let fac = facc2.max(facc1.min(fac11 / SAFE));
            let mut h_new = if self.fixed { h } else { h / fac };
            if err <= 1.0 || self.fixed {
                let t_new = if last { self.t_end } else { self.t + h };
                let mut carry = self.carry;
                if self.compensated {
                    y_new = self.y;
                    compensated_add(&mut y_new, &mut carry, &std::array::from_fn(|i| h * inc[i]));
                }
                let f_new = self.sys.rhs(t_new, &y_new);
                stats.rhs_evals += 1;
                if y_new.iter().chain(f_new.iter()).any(|v| !v.is_finite()) {
                    return Err(IntegrateError::NonFinite { t: t_new });
                }
                stats.steps += 1;
                self.facold = err.max(1e-4);
                self.k[12] = f_new;
                self.t_prev = self.t;
                self.y_prev = self.y;
                self.t = t_new;
                self.y = y_new;
                self.carry = carry;
                self.y_raw = y_new;
                self.f = f_new;
                self.h_last = h;
                self.cont.set(None);
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
            h /= facc1.min(fac11 / SAFE);
            self.reject = true;
            stats.rejected += 1;
        }
    }

    /// Hairer's `CONT` array of the last accepted step (`CONTD8` coefficients).
    fn dense_coefficients(&self) -> [[f64; N]; 8] {
        let h = self.h_last;
        let (t, y) = (self.t_prev, &self.y_prev);
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
        let mut stats = self.stats.get();
        stats.rhs_evals += 3;
        self.stats.set(stats);
        dense_rows(y, &self.y_raw, h, &k)
    }
}

impl<S: OdeSystem<N>, const N: usize> Stepper<N> for Dop853<'_, S, N> {
    fn step(&mut self) -> Result<bool, IntegrateError> {
        Dop853::step(self)
    }

    /// Current time.
    fn t(&self) -> f64 {
        self.t
    }

    fn t_end(&self) -> f64 {
        self.t_end
    }

    /// Start time of the last accepted step (`t0` before the first step).
    fn t_prev(&self) -> f64 {
        self.t_prev
    }

    // The size of the last accepted step is `h_last`; `h` is the proposal for the next one.
    #[allow(clippy::misnamed_getters)]
    fn h(&self) -> f64 {
        self.h_last
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
        if self.stats.get().steps == 0 {
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
        dense_at(&cont, (t - self.t_prev) / self.h_last)
    }

    /// Replaces the current state after a step (e.g. a projection onto
    /// invariant manifolds). Recomputes the derivative used as first stage of
    /// the next step (one right-hand-side call). The dense output of the last
    /// step is unaffected and still interpolates the unprojected step.
    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
        self.carry = [0.0; N];
        self.f = self.sys.rhs(self.t, &self.y);
        let mut stats = self.stats.get();
        stats.rhs_evals += 1;
        self.stats.set(stats);
    }

    /// Work counters so far.
    fn stats(&self) -> Stats {
        self.stats.get()
    }
}

/// Integrates `sys` from `(t0, y0)` to `t_end` with `n` equal DOP853 steps
/// without error control ([`Dop853::fixed_steps`] through the one driver [`drive`]), for
/// convergence-order studies; returns `y(t_end)`.
pub fn fixed_step_solve<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    n: usize,
) -> Result<[f64; N], IntegrateError> {
    let mut solver = Dop853::fixed_steps(sys, t0, y0, t_end, n)?;
    let outcome = drive::<_, IntegrateError, N>(
        &mut solver,
        &Drive::default(),
        &mut |_, _| Ok(()),
        &mut |_, _, _| Ok(Control::Continue),
    )?;
    Ok(outcome.y)
}
