//! The flows of the commuting Hamiltonian vector fields of the first bracket, end of section
//! 3.2: `X1 = P dH1`, `X2 = P dH2` and `X^2 = P dK` (K = g omega3, the Routh integral written
//! `H^2` in (raus-int)) for the bracket P of (p-br) with constant alpha and the beta of (cond)
//! or (cond2), found, as the paper says they "can easily be", by the quadrature in theta.
//!
//! On the symplectic leaf `H4 = 1`, `b = (M, r)` of P, the change of momenta (p-map) with
//! `c = 0` and the spherical coordinates (sph-coord) are canonical coordinates
//! `(phi, theta, p_phi, p_theta)`, in which, by the corrected (int-sph2) (V with
//! `R^2 cos^2 theta`) and with gravity `2U(theta) = 2 m G (R + a cos theta)` added,
//!
//! ```text
//! H1 = A p_phi^2 + B p_theta^2 + b C p_phi + b^2 V + 2U,    K = -alpha I1 p_phi,
//! H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) b^2     (the form after (raus-int)).
//! ```
//!
//! A, B, C, V, U depend on theta only (alpha is constant, beta a function of gamma3), so
//! `p_phi` is constant along all three flows, and a Hamiltonian `H = c1 H1 + F(K)` gives
//! `dtheta/dt = 2 c1 B p_theta`, `dphi/dt = c1 (2 A p_phi + b C) - alpha I1 F'(K)` with
//! `c1 = 1, F = 0` for X1, `c1 = I1, F' = 2 (I3 - I1) K / I1` for X2 and `c1 = 0, F' = 1`
//! for X^2. With `Phi(theta) = E - A p_phi^2 - b C p_phi - b^2 V - 2U` (`E = H1`),
//! `p_theta^2 = Phi/B`, so theta moves between two simple zeros `theta_- < theta_+` of Phi:
//! `dt = dtheta / (2 c1 sqrt(B Phi))`. The substitution
//! `theta = (theta_+ + theta_-)/2 - (theta_+ - theta_-)/2 cos s` removes the inverse square
//! roots at the turning points: `dt/ds = 1/(2 c1 sqrt(B G))` with
//! `G = Phi / ((theta - theta_-)(theta_+ - theta))`, analytic in s; one period of theta is
//! `s in [0, 2 pi)`. The time and the angle phi are integrals over s (composite Gauss-Legendre),
//! the state at time t is found by Newton's method on `t(s)`, and `(phi, theta, p_phi, p_theta)`
//! goes back to `(gamma, M)` through (sph-coord) and the inverse of (p-map).
//!
//! Where the quadrature refuses: P is singular on the poles `sin theta = 0` (sph-coord and
//! (p-br) divide by `gamma1^2 + gamma2^2`), where beta is infinite ((cond): `gamma3 = 0`) and,
//! for the flow, where beta vanishes (B = 0: the theta motion approaches that latitude in
//! infinite time). A trajectory whose theta interval reaches one of these sets is refused with
//! [`RouthError::Singular`] naming it.

use super::first::{Alpha, Beta, FirstBracket};
use super::hamiltonian::hamiltonian_field;
use super::reduction::{abcv, from_spherical, spherical, unit_normal, PoissonMap};
use super::Reading;
use crate::differential::Dual6;
use crate::error::{Result, RouthError};
use crate::integrals::{energy, jellett, quadratic_integral, routh_integral};
use crate::integrate::brent;
use crate::scalar::Scalar;
use std::f64::consts::PI;
use std::str::FromStr;

/// One of the three Hamiltonian vector fields of section 3.2.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    /// `X1 = P dH1`, H1 the energy (int-g).
    X1,
    /// `X2 = P dH2`, `H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2`.
    X2,
    /// `X^2 = P dK`, K = g omega3 of (raus-int).
    XHat2,
}

impl Field {
    /// The name on the command line: `X1`, `X2`, `Xhat2`.
    pub fn name(&self) -> &'static str {
        match self {
            Field::X1 => "X1",
            Field::X2 => "X2",
            Field::XHat2 => "Xhat2",
        }
    }

    /// The Hamiltonian of the field, written once for any scalar (its gradient by AD).
    pub fn hamiltonian<D: Scalar>(&self, body: &routh_ball::Body, x: &[D; 6]) -> D {
        match self {
            Field::X1 => energy(body, x),
            Field::X2 => quadratic_integral(body, x),
            Field::XHat2 => routh_integral(body, x),
        }
    }

    /// `(c1, F'(K))` of the Hamiltonian `c1 H1 + F(K) + const` (see the module documentation).
    fn weights(&self, body: &routh_ball::Body, k: f64) -> (f64, f64) {
        match self {
            Field::X1 => (1.0, 0.0),
            Field::X2 => (body.i1(), 2.0 * (body.i3() - body.i1()) * k / body.i1()),
            Field::XHat2 => (0.0, 1.0),
        }
    }
}

/// Error of parsing a [`Field`] or a [`Condition`] name.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} {given:?}: expected {expected}")]
pub struct ParseNameError {
    /// What was parsed.
    pub what: &'static str,
    /// The text given.
    pub given: String,
    /// The accepted names.
    pub expected: &'static str,
}

impl FromStr for Field {
    type Err = ParseNameError;

    fn from_str(s: &str) -> std::result::Result<Self, Self::Err> {
        match s {
            "X1" => Ok(Field::X1),
            "X2" => Ok(Field::X2),
            "Xhat2" => Ok(Field::XHat2),
            _ => Err(ParseNameError {
                what: "flow",
                given: s.into(),
                expected: "X1, X2 or Xhat2",
            }),
        }
    }
}

/// The special choice of beta under which the field X decomposes on the Hamiltonian fields.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Condition {
    /// (cond): `beta = alpha g (1 + a/(R gamma3))`, X = g1 X1 + g2 X2 (g-eq1).
    Cond,
    /// (cond2): X = g^1 X1 + g^2 X^2 (g-eq2), P compatible with P0.
    Cond2,
    /// The bivector P_f of the conformally Hamiltonian form (cham-vp): `alpha = -R`,
    /// `beta = -g (r, I r)/(gamma, I r)` (a function of gamma3 on the sphere, so the same
    /// quadrature applies); at b = 0, X = -1/(2 beta) P_f dH1. The given alpha is ignored.
    Conformal,
}

impl Condition {
    /// The first bracket (p-br) with constant alpha and this beta.
    pub fn bracket(&self, body: routh_ball::Body, alpha: f64) -> FirstBracket {
        match self {
            Condition::Cond => FirstBracket::new(body, Alpha::constant(alpha), Beta::Cond),
            Condition::Cond2 => FirstBracket::new(body, Alpha::constant(alpha), Beta::Cond2),
            Condition::Conformal => FirstBracket::conformal(body),
        }
    }

    /// The name on the command line: `cond`, `cond2`.
    pub fn name(&self) -> &'static str {
        match self {
            Condition::Cond => "cond",
            Condition::Cond2 => "cond2",
            Condition::Conformal => "conformal",
        }
    }
}

impl FromStr for Condition {
    type Err = ParseNameError;

    fn from_str(s: &str) -> std::result::Result<Self, Self::Err> {
        match s {
            "cond" => Ok(Condition::Cond),
            "cond2" => Ok(Condition::Cond2),
            "conformal" => Ok(Condition::Conformal),
            _ => Err(ParseNameError {
                what: "condition",
                given: s.into(),
                expected: "cond, cond2 or conformal",
            }),
        }
    }
}

/// The Hamiltonian vector field `P dH` at x, H the field's Hamiltonian, dH by automatic
/// differentiation: the right-hand side integrated step by step to check the quadrature.
pub fn vector_field(bracket: &FirstBracket, field: Field, x: &[f64; 6]) -> [f64; 6] {
    let body = bracket.body;
    hamiltonian_field(bracket, |y: &[Dual6; 6]| field.hamiltonian(&body, y), x)
}

/// The first and the largest number of Chebyshev (midpoint) nodes of the cosine series; the
/// number doubles until the series has converged.
const FIRST_NODES: usize = 64;
const MAX_NODES: usize = 2048;
/// The series has converged when its last quarter of coefficients is below this fraction of
/// `c0` (an analytic integrand converges geometrically; a slow one means a nearly double root
/// of Phi or a zero of B just outside the interval, as near a separatrix).
const CONVERGED: f64 = 1e-13;
/// The largest tail accepted at the round-off floor: the error of t(s) is a few times the
/// tail times `c0`, so 1e-10 keeps the state within about 1e-9 of the flow over ten periods.
const FLOOR: f64 = 1e-10;
/// Step of the outward scan for the turning points (rad); a zero of Phi, or a zero or pole of
/// beta, is bracketed by it and then located by Brent's method.
const SCAN_STEP: f64 = 1e-3;
/// Distance from the poles (rad) within which the scan stops: (sph-coord) is singular there.
const POLE_MARGIN: f64 = 1e-6;

/// The theta motion of X1 or X2: `dt/ds` and `dphi/ds` as cosine series in s.
#[derive(Debug, Clone)]
struct Oscillation {
    /// `theta_-`, `theta_+`.
    theta: [f64; 2],
    /// Cosine coefficients `c_k` of `dt/ds = c0/2 + sum c_k cos k s`.
    time: Vec<f64>,
    /// Cosine coefficients of `dphi/ds`.
    angle: Vec<f64>,
    /// The time and the phi integral from `s = 0` (theta at `theta_-`) to the initial point.
    t0: f64,
    phi0: f64,
    /// Period of theta and the advance of phi over it.
    period: f64,
    advance: f64,
}

impl Oscillation {
    /// `[t(s), phi(s)]` from `s = 0`: the series integrated term by term.
    fn integrals(&self, s: f64) -> [f64; 2] {
        [&self.time, &self.angle].map(|c| {
            c[1..]
                .iter()
                .enumerate()
                .fold(0.5 * c[0] * s, |sum, (k, ck)| {
                    sum + ck * ((k + 1) as f64 * s).sin() / (k + 1) as f64
                })
        })
    }

    /// `dt/ds` at s.
    fn time_rate(&self, s: f64) -> f64 {
        self.time[1..]
            .iter()
            .enumerate()
            .fold(0.5 * self.time[0], |sum, (k, ck)| {
                sum + ck * ((k + 1) as f64 * s).cos()
            })
    }
}

/// What theta does along the flow.
#[derive(Debug, Clone)]
enum Motion {
    /// theta is constant (X^2, or a steady motion of X1, X2); phi turns at this rate.
    Fixed { rate: f64 },
    /// theta oscillates between two turning points.
    Oscillating(Oscillation),
}

/// The flow of one of the fields from an initial point, by the theta quadrature.
#[derive(Debug, Clone)]
pub struct Flow {
    /// The bracket.
    pub bracket: FirstBracket,
    /// The field.
    pub field: Field,
    map: PoissonMap,
    /// The Jellett value `b = (M, r)`, a Casimir of P.
    pub b: f64,
    /// The energy `E = H1`, constant along the three flows (they commute).
    pub energy: f64,
    /// The initial point `(phi, theta, p_phi, p_theta)`.
    pub start: [f64; 4],
    /// `c1` and the constant phi rate `-alpha I1 F'(K)` of the Hamiltonian.
    c1: f64,
    drift: f64,
    motion: Motion,
}

/// A summary of the theta motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape {
    /// `[theta_min, theta_max]`.
    pub theta: [f64; 2],
    /// The period of theta (None when theta is constant).
    pub period: Option<f64>,
    /// The advance of phi per period of theta.
    pub advance: Option<f64>,
    /// The rate of phi when theta is constant.
    pub rate: Option<f64>,
}

impl Flow {
    /// The flow of `field` of `bracket` from `x0` (|gamma| = 1, off the singular sets).
    pub fn new(bracket: FirstBracket, field: Field, x0: &[f64; 6]) -> Result<Self> {
        let body = bracket.body;
        body.require_symmetric("the flows of the first bracket")?;
        let map = PoissonMap { bracket, c: 0.0 };
        let start = spherical(&map.image(x0));
        if start.iter().any(|v| !v.is_finite())
            || !bracket.alpha_beta(&unit_normal(&start)).1.is_finite()
        {
            return Err(singular(
                "the change of momenta (p-map) at the initial point",
            ));
        }
        let b = jellett(&body, x0);
        let alpha = bracket.alpha.at(&unit_normal(&start));
        let (c1, f_prime) = field.weights(&body, routh_integral(&body, x0));
        let mut flow = Flow {
            bracket,
            field,
            map,
            b,
            energy: energy(&body, x0),
            start,
            c1,
            drift: -alpha * body.i1() * f_prime,
            motion: Motion::Fixed { rate: 0.0 },
        };
        flow.motion = flow.theta_motion(flow.energy)?;
        Ok(flow)
    }

    /// The state `(gamma, M)` at time t (any sign), at a cost independent of t.
    pub fn state_at(&self, t: f64) -> [f64; 6] {
        let [phi0, theta0, p_phi, p_theta0] = self.start;
        let sph = match &self.motion {
            Motion::Fixed { rate } => [phi0 + rate * t, theta0, p_phi, p_theta0],
            Motion::Oscillating(osc) => {
                let tau = osc.t0 + t;
                let turns = (tau / osc.period).floor();
                let s = phase(osc, tau - turns * osc.period);
                let [lower, upper] = osc.theta;
                let (w, mid) = (0.5 * (upper - lower), 0.5 * (upper + lower));
                let theta = mid - w * s.cos();
                let b = self.phi_and_b(self.energy, theta).1;
                let p_theta = w * s.sin() / (osc.time_rate(s) * 2.0 * self.c1 * b);
                let phi = phi0 + osc.integrals(s)[1] - osc.phi0 + turns * osc.advance;
                [phi, theta, p_phi, p_theta]
            }
        };
        self.map.preimage(&from_spherical(&sph), self.b)
    }

    /// The shape of the theta motion: its range, period and the advance or rate of phi.
    pub fn shape(&self) -> Shape {
        match &self.motion {
            Motion::Fixed { rate } => Shape {
                theta: [self.start[1]; 2],
                period: None,
                advance: None,
                rate: Some(*rate),
            },
            Motion::Oscillating(osc) => Shape {
                theta: osc.theta,
                period: Some(osc.period),
                advance: Some(osc.advance),
                rate: None,
            },
        }
    }

    /// `Phi(theta) = E - A p_phi^2 - b C p_phi - b^2 V - 2U` and `B(theta)`, with A, B, C, V of
    /// the corrected (int-sph2) ([`abcv`]).
    ///
    /// Near the poles the terms of `A p_phi^2 + b C p_phi + b^2 V` grow like `1/sin^2 theta`
    /// and cancel to a small Phi (the turning points sit on that centrifugal barrier), so Phi is
    /// evaluated in the equal, cancellation-free form obtained by completing the square with
    /// `g^2 = I3 (I1 + m h^2) + I1 m R^2 sin^2 theta` (h = R cos theta + a):
    /// `Phi = E - 2U - alpha^2 I1 p_phi^2 + b^2 m/(I1 I3) - D^2/(R^2 sin^2 theta)`,
    /// `D = alpha sqrt(I3) h p_phi + b g/(I1 sqrt(I3))`. [`Flow::phi_defect`] checks that
    /// the two forms agree.
    fn phi_and_b(&self, e: f64, theta: f64) -> (f64, f64) {
        let body = &self.bracket.body;
        let sph = [self.start[0], theta, self.start[2], 0.0];
        let gamma = unit_normal(&sph);
        let [_, bb, _, _] = abcv(&self.bracket, &sph, Reading::Corrected);
        let (p, b) = (self.start[2], self.b);
        let alpha = self.bracket.alpha.at(&gamma);
        let h = body.radius() * gamma[2] + body.a();
        let sqrt_i3 = body.i3().sqrt();
        let d = alpha * sqrt_i3 * h * p + b * body.routh_g(&gamma) / (body.i1() * sqrt_i3);
        let sin = theta.sin();
        (
            e - 2.0 * body.potential(&gamma) - alpha * alpha * body.i1() * p * p
                + b * b * body.m() / (body.i1() * body.i3())
                - d * d / (body.radius() * body.radius() * sin * sin),
            bb,
        )
    }

    /// The relative difference at theta between `Flow::phi_and_b`'s Phi and Phi written
    /// with A, C, V of (int-sph2) as printed in the corrected form,
    /// `E - A p_phi^2 - b C p_phi - b^2 V - 2U`, relative to the largest of these terms.
    pub fn phi_defect(&self, theta: f64) -> f64 {
        let sph = [self.start[0], theta, self.start[2], 0.0];
        let [a, _, c, v] = abcv(&self.bracket, &sph, Reading::Corrected);
        let (p, b) = (self.start[2], self.b);
        let u2 = 2.0 * self.bracket.body.potential(&unit_normal(&sph));
        let terms = [self.energy, a * p * p, b * c * p, b * b * v, u2];
        let direct = terms[0] - terms[1] - terms[2] - terms[3] - terms[4];
        let scale = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        (direct - self.phi_and_b(self.energy, theta).0).abs() / scale
    }

    /// `dphi/dt` at theta.
    fn phi_rate(&self, theta: f64) -> f64 {
        let sph = [self.start[0], theta, self.start[2], 0.0];
        let [a, _, c, _] = abcv(&self.bracket, &sph, Reading::Corrected);
        self.c1 * (2.0 * a * self.start[2] + self.b * c) + self.drift
    }

    fn beta(&self, theta: f64) -> f64 {
        let gamma = unit_normal(&[self.start[0], theta, 0.0, 0.0]);
        self.bracket.alpha_beta(&gamma).1
    }

    fn theta_motion(&self, e: f64) -> Result<Motion> {
        let theta0 = self.start[1];
        if self.c1 == 0.0 {
            return Ok(Motion::Fixed {
                rate: self.phi_rate(theta0),
            });
        }
        let lower = self.turning_point(e, -1.0)?;
        let upper = self.turning_point(e, 1.0)?;
        let w = 0.5 * (upper - lower);
        if w <= 1e-12 * PI {
            return Ok(Motion::Fixed {
                rate: self.phi_rate(theta0),
            });
        }
        let [time, angle] = self.series(e, [lower, upper])?;
        let mut osc = Oscillation {
            theta: [lower, upper],
            period: PI * time[0],
            advance: PI * angle[0],
            time,
            angle,
            t0: 0.0,
            phi0: 0.0,
        };
        let mid = 0.5 * (upper + lower);
        let rising = self.c1 * self.start[3] >= 0.0;
        let sin_s0 = ((theta0 - lower).max(0.0) * (upper - theta0).max(0.0)).sqrt() / w;
        let s0 = sin_s0.atan2((mid - theta0) / w);
        let s0 = if rising { s0 } else { 2.0 * PI - s0 };
        [osc.t0, osc.phi0] = osc.integrals(s0);
        Ok(Motion::Oscillating(osc))
    }

    /// The turning point of theta from the initial point in direction `dir`, refusing the
    /// singular sets on the way.
    fn turning_point(&self, e: f64, dir: f64) -> Result<f64> {
        let theta0 = self.start[1];
        let beta0 = self.beta(theta0);
        let (mut a, mut fa) = (theta0, self.phi_and_b(e, theta0).0);
        loop {
            let b = a + dir * SCAN_STEP;
            if !(POLE_MARGIN..=PI - POLE_MARGIN).contains(&b) {
                return Err(singular(&format!(
                    "theta reaches the pole sin theta = 0 (from theta = {theta0}), where (sph-coord) and (p-br) are singular"
                )));
            }
            let beta = self.beta(b);
            if !(beta * beta0 > 0.0) || !beta.is_finite() {
                return Err(singular(&format!(
                    "theta reaches a zero or a pole of beta near theta = {b} (gamma3 = {}) from theta = {theta0}",
                    b.cos()
                )));
            }
            let fb = self.phi_and_b(e, b).0;
            if fb < 0.0 {
                if fa <= 0.0 {
                    return Ok(a);
                }
                return brent(|t| self.phi_and_b(e, t).0, a, b, 0.0, 200)
                    .ok_or_else(|| singular("Phi(theta) is not finite near a turning point"));
            }
            (a, fa) = (b, fb);
        }
    }

    /// `[dt/ds, dphi/ds]` at s in `(0, pi)`.
    fn rates(&self, e: f64, [lower, upper]: [f64; 2], s: f64) -> [f64; 2] {
        let theta = 0.5 * (upper + lower) - 0.5 * (upper - lower) * s.cos();
        let (phi, b) = self.phi_and_b(e, theta);
        let g = phi / ((theta - lower) * (upper - theta));
        let dt = 1.0 / (2.0 * self.c1 * (b * g).sqrt());
        [dt, self.phi_rate(theta) * dt]
    }

    /// The cosine series of `dt/ds` and `dphi/ds` (even, 2 pi-periodic, analytic in s) from
    /// their values at the midpoint nodes `s_j = (j + 1/2) pi / n`.
    ///
    /// n doubles from [`FIRST_NODES`] while the largest coefficient of the last quarter (the
    /// tail, relative to `c0`) decreases. It stops at [`CONVERGED`], or where the tail stops
    /// decreasing: there it has reached the round-off floor of the integrand, which grows
    /// with n (the nodes nearest the turning points see `Phi`, computed with an absolute
    /// error of round-off times its largest terms, divided by `(theta - theta_-)`), and the
    /// series with the smallest tail is kept if that tail is below [`FLOOR`].
    fn series(&self, e: f64, theta: [f64; 2]) -> Result<[Vec<f64>; 2]> {
        let mut n = FIRST_NODES;
        let mut best: Option<(f64, [Vec<f64>; 2])> = None;
        loop {
            let nodes: Vec<f64> = (0..n).map(|j| (j as f64 + 0.5) * PI / n as f64).collect();
            let values: Vec<[f64; 2]> = nodes.iter().map(|&s| self.rates(e, theta, s)).collect();
            if values.iter().flatten().any(|v| !v.is_finite()) {
                return Err(singular(&format!(
                    "dt/dtheta is not finite inside theta in [{}, {}]",
                    theta[0], theta[1]
                )));
            }
            let coefficients = [0, 1].map(|i| {
                (0..n)
                    .map(|k| {
                        2.0 / n as f64
                            * nodes
                                .iter()
                                .zip(&values)
                                .map(|(s, v)| v[i] * (k as f64 * s).cos())
                                .sum::<f64>()
                    })
                    .collect::<Vec<f64>>()
            });
            let tail = coefficients[0][3 * n / 4..]
                .iter()
                .fold(0.0f64, |m, c| m.max(c.abs()))
                / coefficients[0][0].abs();
            if tail <= CONVERGED {
                return Ok(coefficients);
            }
            let stalled = best.as_ref().is_some_and(|(t, _)| tail >= *t);
            if !stalled {
                best = Some((tail, coefficients));
            }
            if stalled || n >= MAX_NODES {
                return match best {
                    Some((t, c)) if t <= FLOOR => Ok(c),
                    _ => Err(singular(&format!(
                        "the theta quadrature does not converge with {n} nodes (tail {tail:.1e} of dt/ds): a nearly double root of Phi or a zero of B near theta in [{}, {}]",
                        theta[0], theta[1]
                    ))),
                };
            }
            n *= 2;
        }
    }
}

/// The phase `s in [0, 2 pi]` with `t(s) = tau`, `0 <= tau < T`: Newton's method on the
/// increasing `t(s)`, kept inside a shrinking bracket.
fn phase(osc: &Oscillation, tau: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 2.0 * PI);
    let mut s = 2.0 * PI * tau / osc.period;
    for _ in 0..100 {
        let defect = osc.integrals(s)[0] - tau;
        if defect > 0.0 {
            hi = s;
        } else {
            lo = s;
        }
        let next = s - defect / osc.time_rate(s);
        let next = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
        if (next - s).abs() <= 4.0 * f64::EPSILON * PI {
            return next;
        }
        s = next;
    }
    s
}

fn singular(reason: &str) -> RouthError {
    RouthError::Singular {
        formula: "the flow of the first bracket (p-br)",
        reason: reason.into(),
    }
}
