//! The nutation of the tilt between its turning points, its period, the advance of the
//! precession angle per period, and the state at any time in a cost independent of t.
//!
//! On a nutation `u1 <= u = gamma3 <= u2` the substitution
//! `u = (u1 + u2)/2 - (u2 - u1)/2 cos sigma` removes the inverse-square-root singularities of
//! `dt = du / sqrt(Q(u))` at the turning points: with `Q(u) = (u - u1)(u2 - u) P(u)`,
//! `dt/dsigma = f(sigma) = 1 / sqrt(P(u(sigma)))`, an analytic, even, 2 pi-periodic function
//! of sigma (one period of sigma is one nutation: up on `(0, pi)`, down on `(pi, 2 pi)`).
//! Its cosine series `f = c0/2 + sum c_k cos k sigma`, computed from samples at the Chebyshev
//! (midpoint) nodes `sigma_j = (j + 1/2) pi / n`, converges geometrically; it integrates in
//! closed form, `t(sigma) = c0 sigma / 2 + sum c_k sin(k sigma) / k`, so the period is
//! `T = pi c0` and t(sigma) is inverted by Newton's method. The precession angle is the
//! integral of `dpsi/dt f(sigma)` in the same way, with advance `pi b0` per period.

use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrate::brent;
use crate::quadrature::gauss::GaussLegendre;
use crate::quadrature::reduction::Reduction;
use crate::state::State;
use num_dual::first_derivative;
use std::f64::consts::{PI, TAU};

/// First number of Chebyshev nodes tried for the series of `dt/dsigma`.
const FIRST_NODES: usize = 32;
/// Most nodes tried; a series that needs more is taken as a sign of a separatrix.
const MAX_NODES: usize = 8192;
/// A series has converged when its last quarter of coefficients is below this, relative to c0.
const SERIES_TOLERANCE: f64 = 2e-14;
/// Turning points closer than this to a pole are snapped to it (a motion through the axis).
const POLE_SNAP: f64 = 1e-12;
/// A nutation with `u2 - u1` below this is reported as a steady motion: the round-off of Q
/// (relative 1e-16 of its terms) leaves no accuracy in the shape of so small a nutation.
pub const STEADY_AMPLITUDE: f64 = 1e-6;
/// Gauss-Legendre nodes for the divided differences of Q (see `Nutation::cofactor`).
const DIVIDED_DIFFERENCE_NODES: usize = 24;
/// First step of the outward search for the turning points.
const FIRST_SEARCH_STEP: f64 = 1e-8;
/// Largest step of that search (Q is smooth; a pair of roots closer than this is not sought).
const MAX_SEARCH_STEP: f64 = 1.0 / 128.0;

/// A cosine series `c0/2 + sum_k c_k cos(k sigma)` and its integral from 0.
#[derive(Debug, Clone, PartialEq)]
struct CosineSeries(Vec<f64>);

impl CosineSeries {
    /// The series interpolating `samples` at the nodes `(j + 1/2) pi / n` (a DCT-II).
    fn from_samples(samples: &[f64]) -> Self {
        let n = samples.len();
        let coef = (0..n)
            .map(|k| {
                let sum: f64 = samples
                    .iter()
                    .enumerate()
                    .map(|(j, v)| v * (k as f64 * (j as f64 + 0.5) * PI / n as f64).cos())
                    .sum();
                2.0 * sum / n as f64
            })
            .collect();
        CosineSeries(coef)
    }

    /// Whether the last quarter of the coefficients is negligible against `c0`.
    fn converged(&self) -> bool {
        let n = self.0.len();
        let tail = self.0[3 * n / 4..]
            .iter()
            .fold(0.0_f64, |m, c| m.max(c.abs()));
        tail <= SERIES_TOLERANCE * self.0[0].abs()
    }

    /// The mean over one period, `c0 / 2`.
    fn mean(&self) -> f64 {
        0.5 * self.0[0]
    }

    /// The value and the integral from 0 at `sigma`.
    fn value_and_integral(&self, sigma: f64) -> (f64, f64) {
        let (sin1, cos1) = sigma.sin_cos();
        let (mut sk, mut ck) = (0.0, 1.0);
        let mut value = self.mean();
        let mut integral = self.mean() * sigma;
        for (k, c) in self.0.iter().enumerate().skip(1) {
            (sk, ck) = (sk * cos1 + ck * sin1, ck * cos1 - sk * sin1);
            value += c * ck;
            integral += c * sk / k as f64;
        }
        (value, integral)
    }
}

/// A nutation: the tilt oscillates between `u1` and `u2`, the whole state is periodic up to
/// a rotation about e3 by `advance` per period.
#[derive(Debug, Clone, PartialEq)]
pub struct Nutation {
    reduction: Reduction,
    /// Lower turning point of gamma3 = cos theta.
    pub u1: f64,
    /// Upper turning point of gamma3.
    pub u2: f64,
    /// Whether the upper turning point is the pole gamma3 = 1 (the motion crosses the axis).
    pub through_top: bool,
    /// Whether the lower turning point is the pole gamma3 = -1.
    pub through_bottom: bool,
    /// Nutation period T.
    pub period: f64,
    /// Advance of the precession angle psi per period.
    pub advance: f64,
    /// Number of Chebyshev nodes used.
    pub nodes: usize,
    time: CosineSeries,
    angle: CosineSeries,
    rule: GaussLegendre,
    /// Phase sigma of the initial state.
    sigma0: f64,
    /// psi - Psi(sigma) on the initial period.
    psi_ref: f64,
}

/// The motion of a given initial state, solved by quadrature.
#[derive(Debug, Clone, PartialEq)]
pub enum Motion {
    /// A steady motion: theta constant, the state rotating about e3 at the constant rate
    /// `precession` (a double root of Q; on the axis, the vertical spin).
    Steady {
        /// gamma3 = cos theta.
        u: f64,
        /// d psi / dt.
        precession: f64,
        /// The initial state.
        initial: State,
    },
    /// A nutation between two turning points.
    Nutation(Nutation),
}

/// The exact solution of (mg-eq) for the Routh sphere through one initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactSolution {
    /// The body.
    pub body: Body,
    /// The integrals that fix the motion.
    pub reduction: Reduction,
    /// Steady motion or nutation.
    pub motion: Motion,
}

/// Rotation of a state about e3 by `angle` (a symmetry of (mg-eq) when I1 = I2).
fn rotated(state: &State, angle: f64) -> State {
    let (s, c) = angle.sin_cos();
    let rot = |v: [f64; 3]| [c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]];
    State {
        gamma: rot(state.gamma),
        m: rot(state.m),
    }
}

/// The turning point of Q met by going from `u0` in direction `dir` (+1 or -1): a geometric
/// search for the first sign change, refined by Brent's method.
fn turning_point(red: &Reduction, u0: f64, dir: f64) -> Result<f64> {
    let q = |u: f64| red.q(u);
    let end = dir;
    let (mut prev, mut step) = (u0, FIRST_SEARCH_STEP);
    loop {
        let cur = if (end - prev).abs() <= step {
            end
        } else {
            prev + dir * step
        };
        let qc = q(cur);
        if qc < 0.0 {
            if prev == u0 && q(u0) <= 0.0 {
                return Ok(u0);
            }
            return brent(q, prev, cur, 0.0, 200).ok_or_else(|| RouthError::Singular {
                formula: "the reduced equation (du/dt)^2 = Q(u)",
                reason: format!("no turning point refined in [{prev}, {cur}]"),
            });
        }
        if cur == end {
            return Ok(end);
        }
        prev = cur;
        step = (2.0 * step).min(MAX_SEARCH_STEP);
    }
}

impl ExactSolution {
    /// Solve the motion through `initial` by quadrature (body with I1 = I2).
    pub fn new(body: &Body, initial: &State) -> Result<Self> {
        let red = Reduction::of_state(body, initial)?;
        let omega = initial.omega(body);
        let g = initial.gamma;
        let u0 = g[2];
        let udot0 = g[0] * omega[1] - g[1] * omega[0];
        let norm_omega = omega.iter().map(|w| w * w).sum::<f64>().sqrt();
        let (_, dq0, _) = red.q_derivatives(u0);
        let slope_scale = red.q_slope_scale(u0).max(f64::MIN_POSITIVE);
        let steady = |u: f64| {
            Ok(ExactSolution {
                body: *body,
                reduction: red,
                motion: Motion::Steady {
                    u,
                    precession: if u.abs() < 1.0 {
                        red.precession_rate(u)
                    } else {
                        0.0
                    },
                    initial: *initial,
                },
            })
        };
        if udot0.abs() <= 1e-12 * norm_omega && dq0.abs() <= 1e-10 * slope_scale {
            return steady(u0);
        }
        let mut u1 = turning_point(&red, u0, -1.0)?;
        let mut u2 = turning_point(&red, u0, 1.0)?;
        if u2 - u1 <= STEADY_AMPLITUDE {
            return steady(u0);
        }
        let through_top = 1.0 - u2 <= POLE_SNAP;
        let through_bottom = u1 + 1.0 <= POLE_SNAP;
        if through_top {
            u2 = 1.0;
        }
        if through_bottom {
            u1 = -1.0;
        }
        for u in [u1, u2] {
            let (_, dq, _) = red.q_derivatives(u);
            if dq.abs() * (u2 - u1) <= 1e-12 * red.q_scale(u) {
                return Err(RouthError::Separatrix {
                    u_min: u1,
                    u_max: u2,
                    reason: format!(
                        "Q has a double root at the turning point {u} (dQ/du = {dq:e})"
                    ),
                });
            }
        }
        let nutation = Nutation::new(red, u1, u2, through_top, through_bottom, initial, udot0)?;
        Ok(ExactSolution {
            body: *body,
            reduction: red,
            motion: Motion::Nutation(nutation),
        })
    }

    /// The state at time `t` (any real t; the cost does not depend on t).
    pub fn state_at(&self, t: f64) -> State {
        match &self.motion {
            Motion::Steady {
                precession,
                initial,
                ..
            } => rotated(initial, precession * t),
            Motion::Nutation(nut) => nut.state_at(&self.body, t),
        }
    }

    /// The turning points (u_min, u_max) of gamma3 = cos theta (equal for a steady motion).
    pub fn turning_points(&self) -> (f64, f64) {
        match &self.motion {
            Motion::Steady { u, .. } => (*u, *u),
            Motion::Nutation(nut) => (nut.u1, nut.u2),
        }
    }

    /// The nutation period; `None` for a steady motion.
    pub fn period(&self) -> Option<f64> {
        match &self.motion {
            Motion::Steady { .. } => None,
            Motion::Nutation(nut) => Some(nut.period),
        }
    }
}

/// Where a phase sigma puts the tilt: u, the signed sin theta, and `(du/dt) / s * f`.
struct Phase {
    u: f64,
    s: f64,
    udot_over_s_times_f: f64,
}

impl Nutation {
    fn new(
        red: Reduction,
        u1: f64,
        u2: f64,
        through_top: bool,
        through_bottom: bool,
        initial: &State,
        udot0: f64,
    ) -> Result<Self> {
        let mut nut = Nutation {
            reduction: red,
            u1,
            u2,
            through_top,
            through_bottom,
            period: 0.0,
            advance: 0.0,
            nodes: 0,
            time: CosineSeries(vec![]),
            angle: CosineSeries(vec![]),
            rule: GaussLegendre::new(DIVIDED_DIFFERENCE_NODES),
            sigma0: 0.0,
            psi_ref: 0.0,
        };
        let half = 0.5 * (u2 - u1);
        let mut n = FIRST_NODES;
        loop {
            let mut dt = Vec::with_capacity(n);
            let mut dpsi = Vec::with_capacity(n);
            for j in 0..n {
                let sigma = (j as f64 + 0.5) * PI / n as f64;
                let phase = nut.phase(sigma, false);
                let p = nut.cofactor(phase.u);
                if p.is_nan() || p <= 0.0 {
                    return Err(RouthError::Singular {
                        formula: "the reduced equation (du/dt)^2 = Q(u)",
                        reason: format!(
                            "Q / ((u - u1)(u2 - u)) = {p:e} <= 0 at gamma3 = {} between the \
                             turning points {u1} and {u2}",
                            phase.u
                        ),
                    });
                }
                let f = p.sqrt().recip();
                let quotient = nut.jellett_quotient(phase.u);
                dt.push(f);
                dpsi.push(red.precession_from_quotient(phase.u, quotient) * f);
            }
            let time = CosineSeries::from_samples(&dt);
            let angle = CosineSeries::from_samples(&dpsi);
            if time.converged() && angle.converged() {
                nut.nodes = n;
                nut.period = TAU * time.mean();
                nut.advance = TAU * angle.mean();
                nut.time = time;
                nut.angle = angle;
                break;
            }
            if n >= MAX_NODES && time.converged() {
                return Err(RouthError::Singular {
                    formula: "the precession angle psi",
                    reason: format!(
                        "the motion passes so close to the axis (gamma3 up to {u2}, down to \
                         {u1}) that psi turns too fast to resolve with {n} nodes"
                    ),
                });
            }
            if n >= MAX_NODES {
                return Err(RouthError::Separatrix {
                    u_min: u1,
                    u_max: u2,
                    reason: format!(
                        "the series of dt/dsigma does not converge with {n} nodes (period > {:.6e})",
                        TAU * time.mean()
                    ),
                });
            }
            n *= 2;
        }
        // The phase of the initial state from both `cos sigma0 = (mid - u0) / half` and
        // `sin sigma0 = f(sigma0) (du/dt)0 / half`: near a turning point, where u0 fixes sigma0
        // only to the square root of its error, the rate du/dt fixes it well.
        let cos0 = (0.5 * (u1 + u2) - initial.gamma[2]) / half;
        let mut sigma0 = if udot0 < 0.0 {
            TAU - cos0.clamp(-1.0, 1.0).acos()
        } else {
            cos0.clamp(-1.0, 1.0).acos()
        };
        for _ in 0..3 {
            let (f, _) = nut.time.value_and_integral(sigma0);
            sigma0 = (udot0 * f / half).atan2(cos0).rem_euclid(TAU);
        }
        nut.sigma0 = sigma0;
        // psi_ref: the rotation about e3 that takes the state of phase sigma0 at psi = 0 to
        // the initial state, fitted on the horizontal parts of gamma and omega (so it is
        // defined on the axis too, where gamma has no horizontal part).
        let (model_gamma, model_omega) = nut.gamma_omega(nut.sigma0, 0.0);
        let omega = initial.omega(&red.body);
        let w2 = omega
            .iter()
            .map(|w| w * w)
            .sum::<f64>()
            .max(f64::MIN_POSITIVE);
        let cross_dot = |a: [f64; 3], b: [f64; 3], w: f64| {
            (
                w * (a[0] * b[1] - a[1] * b[0]),
                w * (a[0] * b[0] + a[1] * b[1]),
            )
        };
        let (y1, x1) = cross_dot(model_gamma, initial.gamma, 1.0);
        let (y2, x2) = cross_dot(model_omega, omega, 1.0 / w2);
        nut.psi_ref = (y1 + y2).atan2(x1 + x2);
        Ok(nut)
    }

    /// `P(u) = Q(u) / ((u - u1)(u2 - u))`, with the factor of the nearer turning point
    /// divided out exactly: `Q(u) / (u - u1) = int_0^1 Q'(u1 + tau (u - u1)) d tau` (as
    /// `Q(u1) = 0`), by Gauss-Legendre quadrature of the derivative from automatic
    /// differentiation. Dividing Q itself would lose the digits that cancel in Q near a root.
    fn cofactor(&self, u: f64) -> f64 {
        let slope = |from: f64| {
            self.rule
                .integrate(|tau| self.reduction.q_derivatives(from + tau * (u - from)).1)
        };
        if u - self.u1 <= self.u2 - u {
            slope(self.u1) / (self.u2 - u)
        } else {
            -slope(self.u2) / (u - self.u1)
        }
    }

    /// Jellett's quotient `N(u) / (1 - u^2)`; near a pole `p` that the motion passes through,
    /// where `N(p) = 0`, with the factor `u - p` divided out exactly as in `cofactor`:
    /// `N(u) / (1 - u^2) = -int_0^1 N'(p + tau (u - p)) d tau / (u + p)`.
    fn jellett_quotient(&self, u: f64) -> f64 {
        let red = &self.reduction;
        let pole = if self.through_top && u > 0.0 {
            1.0
        } else if self.through_bottom && u < 0.0 {
            -1.0
        } else {
            return red.jellett_quotient(u);
        };
        let slope = self.rule.integrate(|tau| {
            first_derivative(|v| red.jellett_remainder(v), pole + tau * (u - pole)).1
        });
        -slope / (u + pole)
    }

    /// The tilt at phase `sigma` (in `[0, 2 pi)`); `odd` says the phase is in an odd
    /// period, where the signed sin theta of a motion through a pole has the opposite sign.
    fn phase(&self, sigma: f64, odd: bool) -> Phase {
        let half = 0.5 * (self.u2 - self.u1);
        let flip = if odd { -1.0 } else { 1.0 };
        let (hs, hc) = (0.5 * sigma).sin_cos();
        let (hs, hc) = (flip * hs, flip * hc);
        let d1 = 2.0 * half * hs * hs;
        let d2 = 2.0 * half * hc * hc;
        let u = if d1 <= d2 { self.u1 + d1 } else { self.u2 - d2 };
        let root = (2.0 * half).sqrt();
        // sin theta = c_top c_bot with c_top^2 = 1 - u, c_bot^2 = 1 + u; at a pole crossed
        // by the motion the factor is taken with the sign of cos(sigma/2) (sin(sigma/2)),
        // which makes s, psi and omega smooth through the axis.
        let (c_top, r_top) = if self.through_top {
            (root * hc, 1.0 / root)
        } else {
            let c = (1.0 - self.u2 + d2).sqrt();
            (c, hc / c)
        };
        let (c_bot, r_bot) = if self.through_bottom {
            (root * hs, 1.0 / root)
        } else {
            let c = (1.0 + self.u1 + d1).sqrt();
            (c, hs / c)
        };
        Phase {
            u,
            s: c_top * c_bot,
            udot_over_s_times_f: 2.0 * half * r_top * r_bot,
        }
    }

    /// gamma and omega at phase sigma (any real), the precession angle offset by `psi_shift`.
    fn gamma_omega(&self, sigma: f64, psi_shift: f64) -> ([f64; 3], [f64; 3]) {
        let turns = (sigma / TAU).floor();
        let local = sigma - turns * TAU;
        let odd = turns.rem_euclid(2.0) == 1.0;
        let phase = self.phase(local, odd);
        let (f, _) = self.time.value_and_integral(local);
        let (_, psi) = self.angle.value_and_integral(local);
        let psi = psi_shift + psi + (turns * self.advance).rem_euclid(TAU);
        self.reduction.omega(
            phase.u,
            phase.s,
            psi,
            phase.udot_over_s_times_f / f,
            self.jellett_quotient(phase.u),
        )
    }

    /// The phase sigma in `[0, 2 pi)` with `t(sigma) = tau` for `tau` in `[0, T)`: safeguarded
    /// Newton iteration on the monotone function t(sigma).
    fn invert_time(&self, tau: f64) -> f64 {
        let (mut lo, mut hi) = (0.0, TAU);
        let mut sigma = TAU * tau / self.period;
        for _ in 0..100 {
            let (f, t) = self.time.value_and_integral(sigma);
            let r = t - tau;
            if r > 0.0 {
                hi = sigma;
            } else {
                lo = sigma;
            }
            let next = sigma - r / f;
            let next = if next > lo && next < hi {
                next
            } else {
                0.5 * (lo + hi)
            };
            let converged = (next - sigma).abs() <= 4.0 * f64::EPSILON * TAU;
            sigma = next;
            if converged {
                break;
            }
        }
        sigma
    }

    /// The state at time t after the initial state.
    pub fn state_at(&self, body: &Body, t: f64) -> State {
        let (_, t0) = self.time.value_and_integral(self.sigma0);
        let total = t0 + t;
        let turns = (total / self.period).floor();
        let tau = (total - turns * self.period).clamp(0.0, self.period);
        let sigma = self.invert_time(tau) + turns * TAU;
        let (gamma, omega) = self.gamma_omega(sigma, self.psi_ref);
        State {
            gamma,
            m: body.angular_momentum(&gamma, &omega),
        }
    }
}
