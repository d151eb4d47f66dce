//! The step control of one trajectory, the one place that decides, for every one-step method
//! and every run, whether an attempted step is accepted, the size of the next step, where the
//! last step is cut to land on `t_end`, when a run is refused (step budget, step below the
//! round-off of `t`, non-finite numbers) and when it is done.
//!
//! A [`StepControl`] is the clock of one run: its time, the proposal for the next step, the
//! attempt under way, the rejection memory and the work counters. The one-at-a-time steppers
//! ([`Dop853`](super::Dop853), [`Vern9`](super::Vern9), [`Taylor`](super::Taylor)) hold one
//! and are stepped by the one driver [`drive`](super::drive); each lane of the batched
//! integrators ([`crate::batch`]) holds one, so that a lane's steps, rejections, end and
//! failure are decided by the same code, operation for operation, as the one-at-a-time run's
//! (the lanes are bitwise the one-at-a-time runs). The methods only compute: the stages or
//! the series of an attempt, its error, its new state.
//!
//! An attempt of a Runge–Kutta pair, in this order:
//! 1. [`StepControl::attempt`]: the checks of Hairer's `dop853.f` on the proposal (finite,
//!    within the step budget, above the round-off of `t`) and the cut to land on `t_end`;
//! 2. the method computes the attempt and its scaled error `err`;
//! 3. [`StepControl::judge`]: accepted when `err <= 1`, and the next step size by the
//!    method's [`Law`], limited to `h_max` and, after a rejection, to the step just taken;
//! 4. on acceptance, [`StepControl::advance`]: the run moves to the end of the step (refused
//!    when the new state is not finite).
//!
//! A Taylor step is never rejected: [`StepControl::budget`] before the expansion, then
//! [`StepControl::series_step`] turns the step of the series into the step taken (limited to
//! `h_max`, cut to land on `t_end`, refused below the round-off of `t`),
//! [`StepControl::check_increment`] and [`StepControl::advance`].

use super::{IntegrateError, Options, Stats};

/// Rounding unit of the step-size-too-small test (Hairer's `UROUND`).
pub(crate) const UROUND: f64 = 2.3e-16;
/// Safety factor of the step-size prediction.
const SAFE: f64 = 0.9;
/// Lower bound `FAC1` of `h_new / h`.
const FAC1: f64 = 0.333;
/// Upper bound `FAC2` of `h_new / h`.
const FAC2: f64 = 6.0;
/// Exponent `1/8 - 0.2 beta` of DOP853's controller with Lund stabilisation `beta = 0`.
const DOP853_EXPO: f64 = 1.0 / 8.0;
/// Exponent `1 / (q + 1)` of Verner's controller, `q = 8` the order of the embedded solution.
const VERN9_EXPO: f64 = 1.0 / 9.0;

/// How the next step size follows from an attempt of size `h` with scaled error `err`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Law {
    /// Hairer's `dop853.f`: `fac = clamp(err^(1/8) / 0.9, 1/6, 1/0.333)`, `h_new = h / fac`;
    /// after a rejection `h / min(1/0.333, err^(1/8) / 0.9)`.
    Dop853,
    /// Verner 9(8): `fac = clamp(0.9 err^(-1/9), 0.333, 6)`, `h_new = h fac`; after a
    /// rejection `h min(fac, 1)`.
    Vern9,
    /// Equal steps without error control: every attempt accepted, the size kept.
    Fixed,
    /// The step of a Taylor series ([`StepControl::series_step`]), never rejected.
    Series,
}

/// The options of `steps` equal steps from `t0` to `t_end` without error control: the step
/// as the initial step, a budget of `steps` steps. `steps = 0`, and a step that is not
/// finite, are refused ([`IntegrateError::InvalidOption`]).
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
    let opts = Options::default().with_max_steps(steps)?;
    if h == 0.0 {
        Ok(opts)
    } else {
        opts.with_h_init(h)
    }
}

/// The clock of a run as its stepper shows it ([`Stepper`](super::Stepper)): the time, the
/// end, the last step and the work counters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clock {
    /// Current time (the end of the last step).
    pub t: f64,
    /// Start of the last accepted step (`t0` before the first step).
    pub t_prev: f64,
    /// The end of the integration interval.
    pub t_end: f64,
    /// Size of the last accepted step (signed; `0` before the first).
    pub h: f64,
    /// Work counters so far.
    pub stats: Stats,
}

impl Clock {
    /// The same clock with `n` more evaluations of the field (those of a dense output, which
    /// the step control does not count).
    pub fn with_evals(mut self, n: usize) -> Clock {
        self.stats.rhs_evals += n;
        self
    }
}

/// The step control of one run (see the module documentation).
#[derive(Debug, Clone, Copy)]
pub struct StepControl {
    law: Law,
    t: f64,
    t_prev: f64,
    t_end: f64,
    /// `+1` forward, `-1` backward.
    posneg: f64,
    hmax: f64,
    max_steps: usize,
    /// The proposal for the next attempt (after a rejection, the reduced size).
    h: f64,
    /// The attempt under way (cut to land on `t_end`).
    h_try: f64,
    /// Size of the last accepted step (`0` before the first).
    h_last: f64,
    /// The attempt under way lands on `t_end`.
    last: bool,
    /// The last attempt was rejected.
    reject: bool,
    /// `t_end` is reached.
    done: bool,
    stats: Stats,
}

impl StepControl {
    /// The control of a run from `t0` to `t_end` (either direction) with the step limits of
    /// `opts` (`h_max`, by default `|t_end - t0|`, and `max_steps`), before its first step.
    /// The first proposal is `opts.h_init()` in the direction of integration, or else
    /// `guess(posneg, hmax)` (Hairer's `HINIT`, say); none when `t_end = t0`, which is done at
    /// once. The options are valid as built ([`Options`]); the times are checked by the stepper
    /// (`check_start`).
    pub fn new(
        law: Law,
        t0: f64,
        t_end: f64,
        opts: &Options,
        guess: impl FnOnce(f64, f64) -> f64,
    ) -> Self {
        let posneg = if t_end >= t0 { 1.0 } else { -1.0 };
        let hmax = opts.h_max().unwrap_or((t_end - t0).abs());
        let done = t_end == t0;
        let h = match opts.h_init() {
            Some(h) => h.abs().copysign(posneg),
            None if done => 0.0,
            None => guess(posneg, hmax),
        };
        StepControl {
            law,
            t: t0,
            t_prev: t0,
            t_end,
            posneg,
            hmax,
            max_steps: opts.max_steps(),
            h,
            h_try: 0.0,
            h_last: 0.0,
            last: false,
            reject: false,
            done,
            stats: Stats::default(),
        }
    }

    /// The law of the next step size.
    pub fn law(&self) -> Law {
        self.law
    }

    /// Current time (the end of the last accepted step).
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Start of the last accepted step (`t0` before the first step).
    pub fn t_prev(&self) -> f64 {
        self.t_prev
    }

    /// The end of the integration interval.
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// Size of the attempt under way (signed; set by [`StepControl::attempt`] or
    /// [`StepControl::series_step`]).
    pub fn h_try(&self) -> f64 {
        self.h_try
    }

    /// Size of the last accepted step (signed; `0` before the first).
    pub fn h_last(&self) -> f64 {
        self.h_last
    }

    /// `t_end` is reached: no further step.
    pub fn done(&self) -> bool {
        self.done
    }

    /// Work counters so far (field evaluations as counted by the method,
    /// [`StepControl::count_evals`]).
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// The clock of the run: [`StepControl::t`], [`StepControl::t_prev`],
    /// [`StepControl::t_end`], [`StepControl::h_last`] and [`StepControl::stats`].
    pub fn clock(&self) -> Clock {
        Clock {
            t: self.t,
            t_prev: self.t_prev,
            t_end: self.t_end,
            h: self.h_last,
            stats: self.stats,
        }
    }

    /// Counts `n` evaluations of the field.
    #[inline(always)]
    pub fn count_evals(&mut self, n: usize) {
        self.stats.rhs_evals += n;
    }

    /// Refuses an attempt beyond the budget of `max_steps` attempts (accepted and rejected).
    #[inline(always)]
    pub fn budget(&self) -> Result<(), IntegrateError> {
        if self.stats.steps + self.stats.rejected >= self.max_steps {
            return Err(IntegrateError::TooManySteps {
                t: self.t,
                max_steps: self.max_steps,
            });
        }
        Ok(())
    }

    /// The next attempt of a Runge–Kutta pair, as in Hairer's `dop853.f`: the proposal is
    /// refused when it is not finite ([`IntegrateError::NonFinite`]), beyond the step budget
    /// ([`IntegrateError::TooManySteps`]) or when `0.1 |h| <= |t| 2.3e-16`
    /// ([`IntegrateError::StepSizeTooSmall`]); then cut to `t_end - t` when
    /// `t + 1.01 h` passes `t_end` (the last step). Returns the size of the attempt.
    #[inline(always)]
    pub fn attempt(&mut self) -> Result<f64, IntegrateError> {
        let (t, h) = (self.t, self.h);
        if !h.is_finite() {
            return Err(IntegrateError::NonFinite { t });
        }
        self.budget()?;
        if 0.1 * h.abs() <= t.abs() * UROUND {
            return Err(IntegrateError::StepSizeTooSmall { t, h });
        }
        self.last = (t + 1.01 * h - self.t_end) * self.posneg > 0.0;
        self.h_try = if self.last { self.t_end - t } else { h };
        Ok(self.h_try)
    }

    /// The attempt of a Taylor series whose step (unsigned, from its coefficients) is `h`:
    /// limited to `h_max` in the direction of integration, refused when NaN
    /// ([`IntegrateError::NonFinite`]); cut to `t_end - t` when `t + 1.01 h` reaches
    /// `t_end` (the last step), otherwise refused when `0.1 |h| <= |t| 2.3e-16`
    /// ([`IntegrateError::StepSizeTooSmall`]). Returns the size of the attempt (signed). The
    /// step budget is checked before the expansion ([`StepControl::budget`]).
    #[inline(always)]
    pub fn series_step(&mut self, h: f64) -> Result<f64, IntegrateError> {
        let t = self.t;
        let h = h.min(self.hmax) * self.posneg;
        if h.is_nan() {
            return Err(IntegrateError::NonFinite { t });
        }
        self.last = (t + 1.01 * h - self.t_end) * self.posneg >= 0.0;
        if self.last {
            self.h_try = self.t_end - t;
        } else if 0.1 * h.abs() <= t.abs() * UROUND {
            return Err(IntegrateError::StepSizeTooSmall { t, h });
        } else {
            self.h_try = h;
        }
        Ok(self.h_try)
    }

    /// Judges the attempt under way by its scaled error `err` (accepted when `err <= 1`;
    /// always under [`Law::Fixed`]) and sets the next proposal by the [`Law`]: after an
    /// accepted step that is not the last, limited to `h_max` and, right after a rejection,
    /// to the size of the step just taken; after a rejection, the reduced size (counted in
    /// [`Stats::rejected`]). `true` when accepted; then [`StepControl::advance`] follows.
    #[inline(always)]
    pub fn judge(&mut self, err: f64) -> bool {
        let h = self.h_try;
        let (accepted, mut h_new) = match self.law {
            Law::Fixed | Law::Series => (true, h),
            Law::Dop853 => {
                let fac11 = err.powf(DOP853_EXPO);
                if err <= 1.0 {
                    (true, h / (1.0 / FAC2).max((1.0 / FAC1).min(fac11 / SAFE)))
                } else {
                    (false, h / (1.0 / FAC1).min(fac11 / SAFE))
                }
            }
            Law::Vern9 => {
                let fac = (SAFE * err.powf(-VERN9_EXPO)).clamp(FAC1, FAC2);
                if err <= 1.0 {
                    (true, h * fac)
                } else {
                    (false, h * fac.min(1.0))
                }
            }
        };
        if !accepted {
            self.h = h_new;
            self.reject = true;
            self.stats.rejected += 1;
            return false;
        }
        if !self.last {
            if h_new.abs() > self.hmax {
                h_new = self.posneg * self.hmax;
            }
            if self.reject {
                h_new = self.posneg * h_new.abs().min(h.abs());
            }
            self.reject = false;
        }
        self.h = h_new;
        true
    }

    /// The end of the attempt under way: `t_end` for the last step, else `t + h`.
    #[inline(always)]
    pub fn t_next(&self) -> f64 {
        if self.last {
            self.t_end
        } else {
            self.t + self.h_try
        }
    }

    /// Refuses the increment of a series step that is not finite
    /// ([`IntegrateError::NonFinite`] at the start of the step).
    #[inline(always)]
    pub fn check_increment(&self, finite: bool) -> Result<(), IntegrateError> {
        if finite {
            Ok(())
        } else {
            Err(IntegrateError::NonFinite { t: self.t })
        }
    }

    /// The accepted attempt becomes the last step: the run moves to its end, which is
    /// refused when the new state (or its derivative) is not `finite`
    /// ([`IntegrateError::NonFinite`] at the end of the step). `true` when `t_end` is reached.
    #[inline(always)]
    pub fn advance(&mut self, finite: bool) -> Result<bool, IntegrateError> {
        let t_new = self.t_next();
        if !finite {
            return Err(IntegrateError::NonFinite { t: t_new });
        }
        self.stats.steps += 1;
        self.t_prev = self.t;
        self.t = t_new;
        self.h_last = self.h_try;
        self.done = self.last;
        Ok(self.last)
    }
}

#[cfg(test)]
mod tests {
    use super::{Law, StepControl};
    use crate::{IntegrateError, Options};

    /// The control of a run from 0 to `t_end` whose first proposal is `h` (as the initial
    /// guess: a series step does not use it, and may give 0).
    fn control(law: Law, t_end: f64, h: f64, max_steps: usize) -> StepControl {
        let opts = Options::default().with_max_steps(max_steps).unwrap();
        StepControl::new(law, 0.0, t_end, &opts, |_, _| h)
    }

    /// Hairer's rules, checked by hand: a step of 0.3 towards 1 is accepted at err = 1 with
    /// the next size `0.3 / max(1/6, min(1/0.333, 1/0.9))`; a rejection at err = 256 reduces
    /// the step by `min(1/0.333, 256^(1/8) / 0.9)` and the step after it may not grow; the
    /// attempt whose `1.01 h` passes the end is cut to the rest and is the last. Negative
    /// control: err just above 1 is rejected.
    #[test]
    fn runge_kutta_attempts_follow_dop853_f() {
        let mut c = control(Law::Dop853, 1.0, 0.3, 100);
        assert_eq!(c.attempt(), Ok(0.3));
        assert!(c.judge(1.0));
        assert_eq!(c.advance(true), Ok(false));
        assert_eq!((c.t(), c.t_prev(), c.h_last()), (0.3, 0.0, 0.3));
        let h = 0.3 / (1.0_f64 / 0.9);
        assert_eq!(c.attempt(), Ok(h));
        assert!(!c.judge(256.0), "rejected");
        assert_eq!(c.stats().rejected, 1);
        let reduced = h / (1.0 / 0.333_f64).min(256.0_f64.powf(1.0 / 8.0) / 0.9);
        assert_eq!(c.attempt(), Ok(reduced));
        assert!(c.judge(1e-30), "accepted");
        assert_eq!(c.advance(true), Ok(false));
        assert_eq!(
            c.attempt(),
            Ok(reduced),
            "no growth right after a rejection"
        );
        assert!(c.judge(1e-30));
        assert_eq!(c.advance(true), Ok(false));
        let rest = 1.0 - c.t();
        assert_eq!(
            c.attempt(),
            Ok(rest),
            "6 x the step passes the end: cut to the rest"
        );
        assert!(c.judge(1e-30));
        assert_eq!(c.advance(true), Ok(true));
        assert!(c.done());
        assert_eq!(
            (c.t(), c.stats().steps),
            (1.0, 4),
            "the last step lands on t_end"
        );
        let mut n = control(Law::Dop853, 1.0, 0.3, 100);
        n.attempt().unwrap();
        assert!(
            !n.judge(1.0 + 1e-15),
            "negative control: rejected just above 1"
        );
    }

    /// The refusals, each with its data: the budget of attempts, a step below the round-off
    /// of `t`, a non-finite proposal, a non-finite state at the step end and a non-finite
    /// series increment at its start.
    #[test]
    fn refusals_name_their_reason() {
        let mut c = control(Law::Dop853, 1.0, 0.1, 1);
        c.attempt().unwrap();
        assert!(!c.judge(1e3));
        assert_eq!(
            c.attempt(),
            Err(IntegrateError::TooManySteps {
                t: 0.0,
                max_steps: 1
            })
        );
        let far = |law| {
            let opts = Options::default().with_h_init(1.0).unwrap();
            StepControl::new(law, 1e20, 2e20, &opts, |_, _| 0.0)
        };
        let too_small = IntegrateError::StepSizeTooSmall { t: 1e20, h: 1.0 };
        assert_eq!(far(Law::Fixed).attempt(), Err(too_small.clone()));
        assert_eq!(far(Law::Series).series_step(1.0), Err(too_small));
        let mut nan = StepControl::new(Law::Dop853, 0.0, 1.0, &Options::default(), |_, _| f64::NAN);
        assert_eq!(nan.attempt(), Err(IntegrateError::NonFinite { t: 0.0 }));
        let mut c = control(Law::Vern9, 1.0, 0.1, 10);
        c.attempt().unwrap();
        assert!(c.judge(0.5));
        assert_eq!(c.advance(false), Err(IntegrateError::NonFinite { t: 0.1 }));
        let mut s = control(Law::Series, 1.0, 0.1, 10);
        assert_eq!(
            s.check_increment(false),
            Err(IntegrateError::NonFinite { t: 0.0 })
        );
        assert_eq!(s.check_increment(true), Ok(()));
        assert_eq!(
            s.series_step(f64::INFINITY),
            Ok(1.0),
            "limited by h_max = 1"
        );
    }

    /// A series step lands on `t_end` when `t + 1.01 h` reaches it exactly, a Runge–Kutta
    /// attempt only when it passes it (the two rules of the published codes); backward runs
    /// take steps of negative size.
    #[test]
    fn the_last_step_is_cut_to_land_on_t_end() {
        let mut s = control(Law::Series, 1.01, 0.0, 10);
        assert_eq!(s.series_step(1.0), Ok(1.01), "reaches t_end: the last step");
        let mut r = control(Law::Dop853, 1.01, 1.0, 10);
        assert_eq!(r.attempt(), Ok(1.0), "does not pass t_end: not the last");
        let mut back = StepControl::new(Law::Series, 0.0, -1.0, &Options::default(), |_, _| 0.0);
        assert_eq!(back.series_step(0.25), Ok(-0.25));
        assert_eq!(back.advance(true), Ok(false));
        assert_eq!(
            back.series_step(10.0),
            Ok(-0.75),
            "cut to the rest, backward"
        );
        assert_eq!(back.advance(true), Ok(true));
        assert_eq!(back.t(), -1.0);
    }
}
