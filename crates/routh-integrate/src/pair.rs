//! What the adaptive Runge–Kutta pairs ([`Dop853`](super::Dop853), [`Vern9`](super::Vern9))
//! share, written once: the start of a run ([`rk_start`]: the checks, `f(t0, y0)`, Hairer's
//! initial step [`hinit`]), the trait [`RungeKutta`] that also gives them equal steps, and the
//! bookkeeping of a run ([`RkRun`]: the clock, the state and its field, the compensated
//! update, the projection, the dense output built on demand). The methods themselves only
//! compute: the stages of an attempt, its error, its increment and their interpolant.

use std::cell::Cell;

use super::compensated::compensated_add;
use super::control::{fixed_step_options, Clock, Law, StepControl};
use super::{check_start, IntegrateError, OdeSystem, Options, Scales};

/// Hairer's initial step size guess `HINIT` for a method of order `order`, given
/// `f0 = f(t, y)` (one right-hand-side call), made in the run's units (`scales`, [`Scales`]):
/// the components measured in their units and time in its unit `T`, so that a motion
/// written in other units gets the same guess (Hairer's formula mixes rates of the first and
/// second order, `max(||f'|| / ||y||, ||f|| / ||y||)`, so it depends on the unit of time it is
/// evaluated in). With every unit 1, Hairer's code, operation for operation.
#[allow(clippy::too_many_arguments)] // Hairer's argument list
pub fn hinit<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    f0: &[f64; N],
    posneg: f64,
    hmax: f64,
    opts: &Options,
    scales: &Scales<N>,
    order: i32,
) -> f64 {
    let unit = scales.time();
    let sk = |i: usize| opts.atol() + opts.rtol() * (y[i].abs() * scales.of(i));
    let (mut dnf, mut dny) = (0.0, 0.0);
    for i in 0..N {
        dnf += (f0[i] * unit * scales.of(i) / sk(i)).powi(2);
        dny += (y[i] * scales.of(i) / sk(i)).powi(2);
    }
    // The guesses in units of T, then in time.
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1.0e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = (h * unit).min(hmax).copysign(posneg);
    let mut y1 = [0.0; N];
    for i in 0..N {
        y1[i] = y[i] + h * f0[i];
    }
    let f1 = sys.rhs(t + h, &y1);
    let mut der2 = 0.0;
    for i in 0..N {
        der2 += ((f1[i] - f0[i]) * unit * scales.of(i) / sk(i)).powi(2);
    }
    der2 = der2.sqrt() / (h / unit);
    let der12 = der2.abs().max(dnf.sqrt());
    let h1 = unit
        * if der12 <= 1e-15 {
            1.0e-6_f64.max((h / unit).abs() * 1.0e-3)
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
    /// The scales of the components ([`OdeSystem::units`] at `y0`).
    pub(crate) scales: Scales<N>,
}

/// The start of a run of a Runge–Kutta pair of `order` under `law` from `(t0, y0)` to
/// `t_end`, for the steppers and the lanes: the checks of the arguments, `f(t0, y0)` (refused
/// when not finite: [`IntegrateError::NonFinite`]) and the run's [`StepControl`], its first
/// step `opts.h_init()` or Hairer's `HINIT` for a method of order `order` (the evaluations
/// counted: one, two with `HINIT`).
pub(crate) fn rk_start<'a, S: OdeSystem<N>, const N: usize>(
    sys: &'a S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    opts: &Options,
    law: Law,
    order: i32,
) -> Result<RkStart<'a, S, N>, IntegrateError> {
    check_start(t0, &y0, t_end)?;
    let f0 = sys.rhs(t0, &y0);
    if f0.iter().any(|v| !v.is_finite()) {
        return Err(IntegrateError::NonFinite { t: t0 });
    }
    let scales = Scales::of_units(&sys.units(&y0));
    let mut guessed = false;
    let mut control = StepControl::new(law, t0, t_end, opts, |posneg, hmax| {
        guessed = true;
        hinit(sys, t0, &y0, &f0, posneg, hmax, opts, &scales, order)
    });
    control.count_evals(1 + usize::from(guessed));
    Ok(RkStart {
        sys,
        y0,
        f0,
        control,
        opts: *opts,
        scales,
    })
}

/// The adaptive Runge–Kutta pairs ([`Dop853`](super::Dop853), [`Vern9`](super::Vern9)): built
/// from their start under a step-size [`Law`], and so with equal steps by the same code.
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

/// The data `C` of a step's dense output (the coefficients of its interpolant, its extra
/// stages), built at the first request after the step and kept for the later ones, and the
/// field evaluations spent on it (counted beside [`StepControl::stats`]).
pub(crate) struct DenseCache<C> {
    data: Cell<Option<C>>,
    evals: Cell<usize>,
}

impl<C: Copy> DenseCache<C> {
    /// Empty, nothing spent.
    pub(crate) fn new() -> Self {
        DenseCache {
            data: Cell::new(None),
            evals: Cell::new(0),
        }
    }

    /// The data of the step: `build()` at the first call after [`DenseCache::clear`] (it costs
    /// `evals` field evaluations, counted), the copy kept after it.
    pub(crate) fn get(&self, evals: usize, build: impl FnOnce() -> C) -> C {
        if let Some(data) = self.data.get() {
            return data;
        }
        let data = build();
        self.evals.set(self.evals.get() + evals);
        self.data.set(Some(data));
        data
    }

    /// Forgets the data: a new step.
    pub(crate) fn clear(&self) {
        self.data.set(None);
    }

    /// The field evaluations spent on the data so far.
    pub(crate) fn evals(&self) -> usize {
        self.evals.get()
    }
}

/// The run of a Runge–Kutta pair: its field, step control and options, the state and the
/// field there (the first stage of the next step), the rounding residue of the compensated
/// update, the state at the start of the last step and the data `C` of its dense output. The
/// [`Stepper`](super::Stepper) bookkeeping of [`Dop853`](super::Dop853) and
/// [`Vern9`](super::Vern9), written once; all of it inline, no heap allocation.
pub(crate) struct RkRun<'a, S, C, const N: usize> {
    pub(crate) sys: &'a S,
    /// Time, step sizes, acceptance, end and counters of the run.
    pub(crate) ctl: StepControl,
    pub(crate) opts: Options,
    /// The scales of the components, in which the error is measured.
    scales: Scales<N>,
    /// Current state (after [`RkRun::set_state`], if called).
    pub(crate) y: [f64; N],
    /// `f(t, y)` for the current (possibly projected) state: the first stage of the next step.
    pub(crate) f: [f64; N],
    /// The state at the start of the last accepted step.
    pub(crate) y_prev: [f64; N],
    /// Rounding residue of the compensated update (zero after [`RkRun::set_state`]).
    carry: [f64; N],
    /// The data of the dense output of the last accepted step.
    dense: DenseCache<C>,
}

impl<'a, S: OdeSystem<N>, C: Copy, const N: usize> RkRun<'a, S, C, N> {
    /// The run from its start, before its first step.
    pub(crate) fn new(start: RkStart<'a, S, N>) -> Self {
        RkRun {
            sys: start.sys,
            ctl: start.control,
            opts: start.opts,
            scales: start.scales,
            y: start.y0,
            f: start.f0,
            y_prev: start.y0,
            carry: [0.0; N],
            dense: DenseCache::new(),
        }
    }

    /// The scale `s_i` of component `i` and its weight `atol + rtol max(|y_i|, |y_new|) s_i`
    /// in the error of an attempt whose new value there is `y_new` (Hairer's `SK`, in the
    /// component's units): the error `e_i` of the component counts as `e_i s_i / SK`.
    #[inline(always)]
    pub(crate) fn weight(&self, i: usize, y_new: f64) -> (f64, f64) {
        let s = self.scales.of(i);
        let size = self.y[i].abs().max(y_new.abs()) * s;
        (s, self.opts.atol() + self.opts.rtol() * size)
    }

    /// The accepted attempt with the increment `delta = h sum b_i k_i` becomes the last step:
    /// the update `y + delta` (summed with compensation, [`compensated_add`], or plainly, as
    /// [`Options::compensated`] says), the field at the step end (one evaluation), the step
    /// control moved on ([`StepControl::advance`], which refuses a state or field that is not
    /// finite, leaving the run as it was), and the dense output's data forgotten. `true` when
    /// `t_end` is reached.
    #[inline(always)]
    pub(crate) fn accept(&mut self, delta: &[f64; N]) -> Result<bool, IntegrateError> {
        let t_new = self.ctl.t_next();
        let mut y_new = self.y;
        let mut carry = self.carry;
        if self.opts.compensated() {
            compensated_add(&mut y_new, &mut carry, delta);
        } else {
            (0..N).for_each(|i| y_new[i] += delta[i]);
        }
        let f_new = self.sys.rhs(t_new, &y_new);
        self.ctl.count_evals(1);
        let finite = y_new.iter().chain(f_new.iter()).all(|v| v.is_finite());
        let last = self.ctl.advance(finite)?;
        self.y_prev = self.y;
        self.y = y_new;
        self.carry = carry;
        self.f = f_new;
        self.dense.clear();
        Ok(last)
    }

    /// The clock of the run, the field evaluations of the dense output counted.
    pub(crate) fn clock(&self) -> Clock {
        self.ctl.clock().with_evals(self.dense.evals())
    }

    /// The data of the dense output of the last accepted step (built by `build` at the first
    /// call after the step, at the cost of `evals` field evaluations); `None` before the first
    /// step, where the dense output is the initial state.
    pub(crate) fn dense(&self, evals: usize, build: impl FnOnce() -> C) -> Option<C> {
        (self.ctl.stats().steps > 0).then(|| self.dense.get(evals, build))
    }

    /// Replaces the current state after a step (e.g. a projection onto invariant manifolds):
    /// the field there is evaluated again (one evaluation, the first stage of the next step)
    /// and the summation residue cleared. The dense output of the last step is unaffected.
    pub(crate) fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
        self.carry = [0.0; N];
        self.f = self.sys.rhs(self.ctl.t(), &self.y);
        self.ctl.count_evals(1);
    }
}
