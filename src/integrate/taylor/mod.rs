//! The Taylor-series method with the adaptive order and step size of Jorba & Zou.
//!
//! A. Jorba, M. Zou, "A software package for the numerical integration of ODEs by means of
//! high-order Taylor methods", Experimental Mathematics 14 (2005) 99–117, sect. 3.2–3.3.
//!
//! The field is recorded once into an expression [`Tape`] through the [`Scalar`](crate::scalar::Scalar)
//! trait ([`OdeSystem::record`]); each step expands the solution through the current state
//! into its Taylor series `y(t + s) = sum_{k=0..p} y^[k] s^k` by the recurrences of [`tape`],
//! then:
//! * **order** (Jorba–Zou): with the tolerance `eps` of the step (`atol` when
//!   `rtol ||y||_inf <= atol`, otherwise `rtol`: absolute or relative error control),
//!   `p = ceil(-ln(eps) / 2 + 1)`; 15 at `eps = 1e-12`, 20 at `eps = 2.2e-16`;
//! * **step size** (Jorba–Zou): `rho = min((c / ||y^[p-1]||_inf)^(1/(p-1)), (c / ||y^[p]||_inf)^(1/p))`
//!   with `c = 1` (absolute) or `c = ||y||_inf` (relative) estimates the radius of
//!   convergence from the last two terms, and `h = rho / e^2`, times the safety factor
//!   `exp(-0.7 / (p - 1))` of heyoka (F. Biscani, D. Izzo, MNRAS 504 (2021) 2614–2628, which
//!   follows Jorba–Zou). Then the last term is about `(h / rho)^p = e^(-2p) < eps`. No step is
//!   rejected;
//! * **update**: `y + sum_{k=1..p} y^[k] h^k` (Horner), added with compensation
//!   ([`compensated_add`]);
//! * **dense output**: the series itself, evaluated at `s = t - t_prev` (order `p`, accurate to
//!   the tolerance over the whole step).
//!
//! Cost per step: `p` passes over the tape, the pass of order `k` costing `O(1)` per linear
//! operation and `O(k)` per product, quotient or square root: `O(n_ops p^2)` in all
//! (`n_nonlinear p^2 / 2` multiply-adds dominate); measured in `benches/taylor.rs`. One step
//! counts `p` right-hand-side evaluations in [`Stats::rhs_evals`] (one pass of the tape per
//! order).

pub mod tape;

pub use tape::{Tape, Var};

use super::compensated::compensated_add;
use super::{check_start, IntegrateError, OdeSystem, Options, Stats, Stepper};

/// Rounding unit of the step-size-too-small test.
pub(crate) const UROUND: f64 = 2.3e-16;

/// The Jorba–Zou order for the tolerance `eps`: `ceil(-ln(eps) / 2 + 1)`, at least 2.
pub fn jorba_zou_order(eps: f64) -> usize {
    ((-eps.ln() / 2.0 + 1.0).ceil() as usize).max(2)
}

/// The highest order of a run with these tolerances (the Jorba–Zou order of the smaller).
pub fn max_order(rtol: f64, atol: f64) -> usize {
    jorba_zou_order(rtol.min(atol))
}

/// The Jorba–Zou order of a step from the state `y` (at most `max_order`): the tolerance of
/// the step is `atol` when `rtol ||y||_inf <= atol` (absolute error control), else `rtol`.
pub fn step_order<const N: usize>(y: &[f64; N], rtol: f64, atol: f64, max_order: usize) -> usize {
    let size = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let eps = if rtol * size <= atol { atol } else { rtol };
    jorba_zou_order(eps).min(max_order)
}

/// The Jorba–Zou step size (unsigned) for a series of order `p` whose coefficient `y_i^[k]`
/// is `coefficient(i, k)` (see the module documentation).
pub fn jorba_zou_step<const N: usize>(
    coefficient: impl Fn(usize, usize) -> f64,
    p: usize,
    rtol: f64,
    atol: f64,
) -> f64 {
    let norm = |k: usize| (0..N).map(|i| coefficient(i, k).abs()).fold(0.0, f64::max);
    let scale = if rtol * norm(0) <= atol { 1.0 } else { norm(0) };
    let radius = |k: usize| (scale / norm(k)).powf(1.0 / k as f64);
    let rho = radius(p - 1).min(radius(p));
    rho * (-2.0 - 0.7 / (p - 1) as f64).exp()
}

/// How the order and step are chosen.
#[derive(Debug, Clone, Copy)]
enum Control {
    /// Jorba–Zou with these tolerances.
    Adaptive { rtol: f64, atol: f64, hmax: f64 },
    /// A fixed order and a fixed step (convergence studies).
    Fixed { order: usize, h: f64 },
}

/// Taylor-series integrator of adaptive order and step (see the module documentation).
pub struct Taylor<const N: usize> {
    tape: Tape<N>,
    t: f64,
    y: [f64; N],
    /// Rounding residue of the compensated update (zero after [`Stepper::set_state`]).
    carry: [f64; N],
    t_prev: f64,
    /// Order of the last accepted step.
    p_last: usize,
    h_last: f64,
    t_end: f64,
    posneg: f64,
    control: Control,
    max_steps: usize,
    compensated: bool,
    done: bool,
    stats: Stats,
}

impl<const N: usize> Taylor<N> {
    /// Prepares an integration of `sys` from `(t0, y0)` towards `t_end` (forward or backward),
    /// with the Jorba–Zou order and step for `opts.rtol`, `opts.atol` (`opts.h_init` is not
    /// used: the first step comes from the series as every other). Records the field of `sys`
    /// once; fails with [`IntegrateError::Unsupported`] if `sys` cannot be recorded
    /// ([`OdeSystem::record`]), and as [`Dop853::new`](super::Dop853::new) otherwise.
    pub fn new<S: OdeSystem<N> + ?Sized>(
        sys: &S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        opts: &Options,
    ) -> Result<Self, IntegrateError> {
        opts.validate()?;
        let hmax = opts.h_max.unwrap_or((t_end - t0).abs());
        let max_order = max_order(opts.rtol, opts.atol);
        let control = Control::Adaptive {
            rtol: opts.rtol,
            atol: opts.atol,
            hmax,
        };
        Self::build(sys, t0, y0, t_end, control, max_order, opts)
    }

    /// Prepares `steps` equal steps of the fixed order `order` from `(t0, y0)` to `t_end` (for
    /// convergence-order studies and negative controls).
    pub fn fixed<S: OdeSystem<N> + ?Sized>(
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
        let control = Control::Fixed {
            order,
            h: (t_end - t0) / steps as f64,
        };
        let opts = Options {
            max_steps: steps,
            ..Options::default()
        };
        Self::build(sys, t0, y0, t_end, control, order, &opts)
    }

    fn build<S: OdeSystem<N> + ?Sized>(
        sys: &S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        control: Control,
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
            t: t0,
            y: y0,
            carry: [0.0; N],
            t_prev: t0,
            p_last: 0,
            h_last: 0.0,
            t_end,
            posneg: if t_end >= t0 { 1.0 } else { -1.0 },
            control,
            max_steps: opts.max_steps,
            compensated: opts.compensated,
            done: t_end == t0,
            stats: Stats::default(),
        })
    }

    /// The recorded field.
    pub fn tape(&self) -> &Tape<N> {
        &self.tape
    }

    /// The Jorba–Zou step size (unsigned) for the series just expanded to order `p`.
    fn jorba_zou_step(&self, p: usize, rtol: f64, atol: f64) -> f64 {
        jorba_zou_step::<N>(|i, k| self.tape.state_coefficient(i, k), p, rtol, atol)
    }

    /// The order for the current state.
    fn order(&self) -> usize {
        match self.control {
            Control::Fixed { order, .. } => order,
            Control::Adaptive { rtol, atol, .. } => {
                step_order(&self.y, rtol, atol, self.tape.max_order())
            }
        }
    }

    fn advance(&mut self) -> Result<bool, IntegrateError> {
        if self.done {
            return Ok(true);
        }
        if self.stats.steps >= self.max_steps {
            return Err(IntegrateError::TooManySteps {
                t: self.t,
                max_steps: self.max_steps,
            });
        }
        let p = self.order();
        self.tape.expand(self.t, &self.y, p);
        self.stats.rhs_evals += p;
        let mut h = match self.control {
            Control::Fixed { h, .. } => h,
            Control::Adaptive { rtol, atol, hmax } => {
                self.jorba_zou_step(p, rtol, atol).min(hmax) * self.posneg
            }
        };
        if h.is_nan() {
            return Err(IntegrateError::NonFinite { t: self.t });
        }
        let last = (self.t + 1.01 * h - self.t_end) * self.posneg >= 0.0;
        if last {
            h = self.t_end - self.t;
        } else if 0.1 * h.abs() <= self.t.abs() * UROUND {
            return Err(IntegrateError::StepSizeTooSmall { t: self.t, h });
        }
        let mut delta = [0.0; N];
        for (i, d) in delta.iter_mut().enumerate() {
            let c = self.tape.state_series(i, p);
            let mut acc = c[p];
            for k in (1..p).rev() {
                acc = acc * h + c[k];
            }
            *d = acc * h;
        }
        if delta.iter().any(|v| !v.is_finite()) {
            return Err(IntegrateError::NonFinite { t: self.t });
        }
        if self.compensated {
            compensated_add(&mut self.y, &mut self.carry, &delta);
        } else {
            (0..N).for_each(|i| self.y[i] += delta[i]);
        }
        self.t_prev = self.t;
        self.t = if last { self.t_end } else { self.t + h };
        self.h_last = h;
        self.p_last = p;
        self.stats.steps += 1;
        self.done = last;
        Ok(last)
    }
}

impl<const N: usize> Stepper<N> for Taylor<N> {
    /// One step; `Ok(true)` once `t_end` is reached (the last step lands exactly on it).
    fn step(&mut self) -> Result<bool, IntegrateError> {
        self.advance()
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn t_end(&self) -> f64 {
        self.t_end
    }

    fn t_prev(&self) -> f64 {
        self.t_prev
    }

    fn h(&self) -> f64 {
        self.h_last
    }

    fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// The Taylor series of the last step, `sum_k y^[k] (t - t_prev)^k`, from the state at
    /// `t_prev` (before any [`set_state`](Stepper::set_state) of its end); the initial state
    /// before the first step.
    fn dense(&self, t: f64) -> [f64; N] {
        if self.stats.steps == 0 {
            return self.y;
        }
        let s = t - self.t_prev;
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

    fn stats(&self) -> Stats {
        self.stats
    }
}
