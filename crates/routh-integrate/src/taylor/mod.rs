//! The Taylor-series method with the adaptive order and step size of Jorba & Zou.
//!
//! A. Jorba, M. Zou, "A software package for the numerical integration of ODEs by means of
//! high-order Taylor methods", Experimental Mathematics 14 (2005) 99–117, sect. 3.2–3.3.
//!
//! The field is recorded once into an expression [`Tape`] through the [`Scalar`](crate::scalar::Scalar)
//! trait ([`OdeSystem::record`]); each step expands the solution through the current state
//! into its Taylor series `y(t + s) = sum_{k=0..p} y^[k] s^k` by the recurrences of [`tape`],
//! then:
//! * **order** ([`taylor_order`]): with the tolerance `eps` of the step ([`step_tolerance`]:
//!   `atol` when `rtol ||y||_inf <= atol`, otherwise `rtol`: absolute or relative error
//!   control), `p = ceil(-ln(eps) / u + 1)` with `u = 2` (Jorba–Zou) for `eps < 1e-12` and
//!   `u = 1.5` above, where our cost per step makes larger steps of higher order cheaper
//!   ([`step_exponent`], which gives the cost model and the measurements); 16 at
//!   `eps = 1e-13`, 20 at `eps = 2.2e-16`, 20 at `eps = 1e-12`;
//! * **step size** ([`taylor_step`]): `rho = min((c / ||y^[p-1]||_inf)^(1/(p-1)), (c / ||y^[p]||_inf)^(1/p))`
//!   with `c = 1` (absolute) or `c = ||y||_inf` (relative) estimates the radius of
//!   convergence from the last two terms (Jorba–Zou), and `h = rho / e^u`, times the safety
//!   factor `exp(-0.7 / (p - 1))` of heyoka (F. Biscani, D. Izzo, MNRAS 504 (2021)
//!   2614–2628, which follows Jorba–Zou). Then the last term is about
//!   `(h / rho)^p = e^(-u p) < eps`. No step is rejected. For `eps < 1e-12` these are
//!   heyoka's rules, and our steps are heyoka's;
//! * **update**: `y + sum_{k=1..p} y^[k] h^k` (Horner), added with compensation
//!   ([`compensated_add`]);
//! * **dense output**: the series itself, evaluated at `s = t - t_prev` (order `p`, accurate to
//!   the tolerance over the whole step).
//!
//! Cost per step: `p` passes over the tape, the pass of order `k` costing `O(1)` per linear
//! operation and `O(k)` per product, quotient or square root: `O(n_ops p^2)` in all
//! (`n_nonlinear p^2 / 2` multiply-adds). A pass sums the terms of orders `1 .. k-1` of all
//! convolutions first, independent of each other (`convolution`), then runs the chain of
//! operations that need order `k` (`recurrence`), as straight-line generated code for the
//! tapes of the model families (`codegen`, `kernels`): `0.105 + 0.046 p + 0.0024 p^2` us a
//! step on the default case (`benches/taylor.rs`, BENCHMARKS.md). One step
//! counts `p` right-hand-side evaluations in [`Stats::rhs_evals`] (one pass of the tape per
//! order).

pub mod codegen;
pub mod coefficient;
mod convolution;
pub(crate) mod elementary;
pub mod kernels;
pub mod recurrence;
pub mod tape;

pub use kernels::{Interpreted, Kernels};
pub use tape::{Tape, Var};

use super::compensated::compensated_add;
use super::control::{Clock, Law, StepControl};
use super::{check_start, IntegrateError, OdeSystem, Options, Scales, Stepper};

/// The tolerance of a step from a state of size `size = ||y||_inf`: `(eps, scale)` with
/// `eps = atol`, `scale = 1` (absolute control) when `rtol size <= atol`, otherwise
/// `eps = rtol`, `scale = size` (relative control). `eps` gives the order
/// ([`taylor_order`]), `scale` the radius of convergence ([`taylor_step`]).
pub fn step_tolerance(rtol: f64, atol: f64, size: f64) -> (f64, f64) {
    if rtol * size <= atol {
        (atol, 1.0)
    } else {
        (rtol, size)
    }
}

/// The tolerance below which the order and step are Jorba–Zou's ([`step_exponent`]).
pub const JORBA_ZOU_BELOW: f64 = 1e-12;

/// The exponent `u` of the step `h = rho e^(-u)` for the tolerance `eps`: 1.5 for
/// `eps >= 1e-12`, Jorba–Zou's 2 below ([`JORBA_ZOU_BELOW`]).
///
/// Jorba–Zou (A. Jorba, M. Zou, Experimental Math. 14 (2005) 99–117, sect. 3.2) take the
/// step `h = rho e^(-u)`, `rho` the radius of convergence, and the order `p = -ln(eps) / u`,
/// so that the last term `(h / rho)^p = eps`; if a step of order `p` costs `c2 p^2`, the cost
/// per unit time `e^u p^2 / rho` is smallest at `u = 2`. Our step costs more per order at
/// low orders: in time per step at t = 1000 (default case, docs/benchmarks-history.md, "Cost of a
/// Taylor step against its order"), `c0 + c1 p + c2 p^2` with `c0 = 0.105 us`,
/// `c1 = 0.046 us`, `c2 = 0.0024 us` (1.02 us at p = 12, 1.46 us at p = 16, 1.98 us at p = 20;
/// the same proportions as before the histories of `tape`, at less than half the cost).
/// The cost per unit time `e^u (c0 + c1 L / u + c2 L^2 / u^2) / rho`, `L = -ln(eps)`, is then
/// smallest near `u = 1.4` for `eps` from 1e-8 to 1e-15 (13 % below `u = 2` at 1e-10). Measured
/// on the three cases of the work-precision benchmark (t = 1000): `u = 1.5` takes
/// 16 to 36 % less time than `u = 2` at each tolerance 1e-4 .. 1e-12 and reaches each error
/// from 1e-5 to 1e-9 in 13 to 26 % less (again after the histories: at tol 1e-10, 10.8 against
/// 13.1 ms on default for a smaller error), but its error does not fall below 2e-11 at tol
/// 1e-13 .. 1e-15, where `u = 2` reaches 3e-12 .. 2e-11 (a floor of round-off, not of
/// truncation: it does not move with the tolerance; `u = 1.25` and `1.75` do no better).
/// Hence 1.5 down to 1e-12 and Jorba–Zou's 2 below, where the floor matters.
pub fn step_exponent(eps: f64) -> f64 {
    if eps >= JORBA_ZOU_BELOW {
        1.5
    } else {
        2.0
    }
}

/// The order for the tolerance `eps`: `ceil(-ln(eps) / u + 1)`, `u` of [`step_exponent`], at
/// least 2: Jorba–Zou's `ceil(-ln(eps) / 2 + 1)` below 1e-12 (16 at `eps = 1e-13`, 20 at
/// `eps = 2.2e-16`), 20 at `eps = 1e-12`, 14 at `eps = 1e-8`.
pub fn taylor_order(eps: f64) -> usize {
    ((-eps.ln() / step_exponent(eps) + 1.0).ceil() as usize).max(2)
}

/// The step (unsigned) for the tolerance `eps` of a series of order `p >= 2` whose last two
/// coefficients have the norms `norm_p_minus_1 = ||y^[p-1]||_inf` and
/// `norm_p = ||y^[p]||_inf`, for the `scale` of [`step_tolerance`]: `rho = min((scale /
/// norm_p_minus_1)^(1/(p-1)), (scale / norm_p)^(1/p))` estimates the radius of convergence
/// (Jorba–Zou), and the step is `rho e^(-u - 0.7 / (p - 1))`, `u` of [`step_exponent`] (with
/// the safety factor `e^(-0.7 / (p - 1))` of heyoka: F. Biscani, D. Izzo, MNRAS 504 (2021)
/// 2614–2628). At the order of [`taylor_order`] the last term is then about
/// `e^(-u p) <= eps e^(-u)`. Computed as `exp(min(ln(scale / norm_p_minus_1) / (p - 1),
/// ln(scale / norm_p) / p) - u - 0.7 / (p - 1))` with the `ln` and `exp` of [`elementary`]
/// (a norm of 0 gives an infinite root, which the other root bounds; NaN only if both roots
/// are NaN): a pure function of these numbers without a branch or a library call, so that a
/// batch of lanes computes it for all lanes at once, bitwise as one lane alone.
#[inline(always)]
pub fn taylor_step(eps: f64, p: usize, scale: f64, norm_p_minus_1: f64, norm_p: f64) -> f64 {
    let p = p as f64;
    let log_root = |norm: f64, k: f64| elementary::ln(scale / norm) / k;
    let log_rho = log_root(norm_p_minus_1, p - 1.0).min(log_root(norm_p, p));
    elementary::exp(log_rho - step_exponent(eps) - 0.7 / (p - 1.0))
}

/// The adaptive order and step for the tolerances `rtol`, `atol` ([`step_tolerance`],
/// [`taylor_order`], [`taylor_step`]), with the orders (which depend on the tolerance alone)
/// computed once: [`step_tolerance`] chooses one of two tolerances, so there are two orders
/// (each at most the tape's). The same numbers as those functions at every step, without
/// their logarithm and ceiling (taken by the one-at-a-time method and by each lane of the
/// batched one).
#[derive(Debug, Clone, Copy)]
pub(crate) struct SeriesRule {
    rtol: f64,
    atol: f64,
    /// The order under absolute control (`eps = atol`), then under relative control
    /// (`eps = rtol`).
    orders: [usize; 2],
}

impl SeriesRule {
    /// The rule for `rtol`, `atol`, with orders at most `max_order`.
    pub(crate) fn new(rtol: f64, atol: f64, max_order: usize) -> Self {
        let order = |eps: f64| taylor_order(eps).min(max_order);
        SeriesRule {
            rtol,
            atol,
            orders: [order(atol), order(rtol)],
        }
    }

    /// The order of a step from a state of size `size = ||y||_inf` (that of `eps = atol`, the
    /// first, which is also the second if `rtol = atol`).
    pub(crate) fn order(&self, size: f64) -> usize {
        let (eps, _) = step_tolerance(self.rtol, self.atol, size);
        self.orders[usize::from(eps != self.atol)]
    }

    /// The step (unsigned, [`taylor_step`]) of a series of order `p` from a state of size
    /// `size`, whose last two coefficients have the norms `norm_p_minus_1` and `norm_p`.
    #[inline(always)]
    ///
    /// The norms are of the series in the units of `scales` (their components' units), and the
    /// step is computed in its unit of time `T`: the coefficient of order `k` times `T^k`, the
    /// step from it times `T`, both exact (`T` a power of two), so that a motion written in
    /// other units gets the same steps to the bit.
    pub(crate) fn step<const N: usize>(
        &self,
        p: usize,
        size: f64,
        norm_p_minus_1: f64,
        norm_p: f64,
        scales: &Scales<N>,
    ) -> f64 {
        let (eps, scale) = step_tolerance(self.rtol, self.atol, size);
        let order = p as i32;
        let in_t = |norm: f64, k: i32| scales.in_time_unit(norm, k);
        let h = taylor_step(
            eps,
            p,
            scale,
            in_t(norm_p_minus_1, order - 1),
            in_t(norm_p, order),
        );
        scales.in_time_unit(h, 1)
    }
}

/// How the order and step are chosen.
#[derive(Debug, Clone, Copy)]
enum Regime {
    /// Jorba–Zou with the tolerances of this rule.
    Adaptive(SeriesRule),
    /// A fixed order and a fixed step (convergence studies).
    Fixed { order: usize, h: f64 },
}

/// Taylor-series integrator of adaptive order and step (see the module documentation).
pub struct Taylor<const N: usize, K = Interpreted> {
    tape: Tape<N, f64, K>,
    /// Time, step sizes, end and counters of the run ([`Law::Series`]).
    ctl: StepControl,
    y: [f64; N],
    /// Rounding residue of the compensated update (zero after [`Stepper::set_state`]).
    carry: [f64; N],
    /// Order of the last accepted step.
    p_last: usize,
    control: Regime,
    compensated: bool,
    /// The scales of the components ([`OdeSystem::units`] at `y0`), in which the state and
    /// the series are sized.
    scales: Scales<N>,
}

impl<const N: usize, K: Kernels> Taylor<N, K> {
    /// Prepares an integration of `sys` from `(t0, y0)` towards `t_end` (forward or backward),
    /// with the Jorba–Zou order and step for `opts.rtol()`, `opts.atol()` (`opts.h_init()` is
    /// not used: the first step comes from the series as every other). Records the field of `sys`
    /// once; fails with [`IntegrateError::Unsupported`] if `sys` cannot be recorded
    /// ([`OdeSystem::record`]), and as [`Dop853::new`](super::Dop853::new) otherwise.
    pub fn new<S: OdeSystem<N, Kernels = K> + ?Sized>(
        sys: &S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        opts: &Options,
    ) -> Result<Self, IntegrateError> {
        let max_order = taylor_order(opts.rtol().min(opts.atol()));
        let control = Regime::Adaptive(SeriesRule::new(opts.rtol(), opts.atol(), max_order));
        Self::build(sys, t0, y0, t_end, control, max_order, opts)
    }

    /// Prepares `steps` equal steps of the fixed order `order` from `(t0, y0)` to `t_end` (for
    /// convergence-order studies and negative controls).
    pub fn fixed<S: OdeSystem<N, Kernels = K> + ?Sized>(
        sys: &S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        order: usize,
        steps: usize,
    ) -> Result<Self, IntegrateError> {
        for (name, value) in [("order", order), ("steps", steps)] {
            if value == 0 {
                return Err(IntegrateError::InvalidOption {
                    name,
                    value: 0.0,
                    rule: "must be > 0",
                });
            }
        }
        let control = Regime::Fixed {
            order,
            h: (t_end - t0) / steps as f64,
        };
        let opts = Options::default().with_max_steps(steps)?;
        Self::build(sys, t0, y0, t_end, control, order, &opts)
    }

    fn build<S: OdeSystem<N, Kernels = K> + ?Sized>(
        sys: &S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        control: Regime,
        max_order: usize,
        opts: &Options,
    ) -> Result<Self, IntegrateError> {
        check_start(t0, &y0, t_end)?;
        let tape = Tape::record(sys, max_order).ok_or(IntegrateError::Unsupported {
            method: "taylor",
            reason: "the system's field is not recorded through Scalar (OdeSystem::record)",
        })?;
        Ok(Taylor {
            tape,
            ctl: StepControl::new(Law::Series, t0, t_end, opts, |_, _| 0.0),
            y: y0,
            carry: [0.0; N],
            p_last: 0,
            control,
            compensated: opts.compensated(),
            scales: Scales::of_units(&sys.units(&y0)),
        })
    }

    /// The recorded field.
    pub fn tape(&self) -> &Tape<N, f64, K> {
        &self.tape
    }

    /// The step size (unsigned, [`taylor_step`]) for the series just expanded to order `p`.
    fn step_size(&self, p: usize, rule: &SeriesRule) -> f64 {
        let norm = |k: usize| {
            self.scales
                .max_norm((0..N).map(|i| self.tape.state_coefficient(i, k)))
        };
        rule.step(p, norm(0), norm(p - 1), norm(p), &self.scales)
    }

    /// The order for the current state.
    fn order(&self) -> usize {
        match self.control {
            Regime::Fixed { order, .. } => order,
            Regime::Adaptive(rule) => rule.order(self.scales.max_norm(self.y.iter().copied())),
        }
    }

    /// One step: the series expanded to the order of the current state, its step turned
    /// into the step taken by the [`StepControl`], the update.
    fn advance(&mut self) -> Result<bool, IntegrateError> {
        if self.ctl.done() {
            return Ok(true);
        }
        self.ctl.budget()?;
        let p = self.order();
        self.tape.expand(self.ctl.t(), &self.y, p);
        self.ctl.count_evals(p);
        let h = self.ctl.series_step(match self.control {
            Regime::Fixed { h, .. } => h.abs(),
            Regime::Adaptive(rule) => self.step_size(p, &rule),
        })?;
        let mut delta = [0.0; N];
        for (i, d) in delta.iter_mut().enumerate() {
            let c = self.tape.state_series(i, p);
            let mut acc = c[p];
            for k in (1..p).rev() {
                acc = acc * h + c[k];
            }
            *d = acc * h;
        }
        self.ctl
            .check_increment(delta.iter().all(|v| v.is_finite()))?;
        if self.compensated {
            compensated_add(&mut self.y, &mut self.carry, &delta);
        } else {
            (0..N).for_each(|i| self.y[i] += delta[i]);
        }
        self.p_last = p;
        self.ctl.advance(true)
    }
}

impl<const N: usize, K: Kernels> Stepper<N> for Taylor<N, K> {
    /// One step; `Ok(true)` once `t_end` is reached (the last step lands exactly on it).
    fn step(&mut self) -> Result<bool, IntegrateError> {
        self.advance()
    }

    fn clock(&self) -> Clock {
        self.ctl.clock()
    }

    fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// The Taylor series of the last step, `sum_k y^[k] (t - t_prev)^k`, from the state at
    /// `t_prev` (before any [`set_state`](Stepper::set_state) of its end); the initial state
    /// before the first step.
    fn dense(&self, t: f64) -> [f64; N] {
        if self.ctl.stats().steps == 0 {
            return self.y;
        }
        let s = t - self.ctl.t_prev();
        std::array::from_fn(|i| {
            let c = self.tape.state_series(i, self.p_last);
            c.iter().rev().fold(0.0, |acc, &ck| acc * s + ck)
        })
    }

    /// Replaces the current state (a projection) and clears the summation residue.
    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
        self.carry = [0.0; N];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rule computed once is bitwise [`taylor_order`] of [`step_tolerance`] and
    /// [`taylor_step`] at every step (tolerance zero: the same expressions, evaluated once),
    /// over 20,000 random tolerances, sizes, norms and orders: `rtol` above, equal to and
    /// below `atol`, sizes on both sides of `atol / rtol`, NaN and infinite sizes and norms, a
    /// zero norm, orders at and away from the rule's own, tapes of lower order than the
    /// tolerance asks for. Control: the two rules of a pair of different tolerances differ.
    #[test]
    fn the_rule_computed_once_is_the_order_and_step_of_every_step() {
        let mut rng = crate::sampling::SplitMix64::new(13);
        let mut uniform = |lo: f64, hi: f64| rng.uniform(lo, hi);
        let specials = [f64::NAN, f64::INFINITY, 0.0];
        for n in 0..20_000 {
            let rtol = 10f64.powf(uniform(-16.0, -2.0));
            let atol = match n % 3 {
                0 => rtol,
                _ => 10f64.powf(uniform(-16.0, -2.0)),
            };
            let max_order = if n % 7 == 0 { 8 } else { 40 };
            let rule = SeriesRule::new(rtol, atol, max_order);
            let mut size = atol / rtol * 10f64.powf(uniform(-3.0, 3.0));
            let mut norms = [
                10f64.powf(uniform(-30.0, 5.0)),
                10f64.powf(uniform(-30.0, 5.0)),
            ];
            match n % 50 {
                0..=2 => size = specials[n % 50],
                3..=5 => norms[0] = specials[n % 50 - 3],
                6..=8 => norms[1] = specials[n % 50 - 6],
                _ => {}
            }
            let (eps, scale) = step_tolerance(rtol, atol, size);
            let order = taylor_order(eps).min(max_order);
            assert_eq!(
                rule.order(size),
                order,
                "rtol {rtol}, atol {atol}, size {size}"
            );
            for p in [order, order + 1, (order - 1).max(2)] {
                let want = taylor_step(eps, p, scale, norms[0], norms[1]);
                let got = rule.step(p, size, norms[0], norms[1], &Scales::<1>::one());
                assert_eq!(
                    got.to_bits(),
                    want.to_bits(),
                    "{rtol} {atol} {size} {norms:?} {p}"
                );
            }
        }
        let rule = SeriesRule::new(1e-12, 1e-6, 40);
        assert_ne!(rule.order(1.0), rule.order(1e9));
        assert_ne!(
            rule.step(14, 1.0, 1.0, 1.0, &Scales::<1>::one()).to_bits(),
            rule.step(14, 1e9, 1.0, 1.0, &Scales::<1>::one()).to_bits()
        );
    }
}
