//! The ball that stays on the plane while its contact point slips: the tippe top with viscous
//! friction (S. Rauch-Wojciechowski and N. Rutstam, "Dynamics of the tippe top: properties of
//! numerical solutions versus the dynamical equations", and SIGMA 10 (2014) 017, "Dynamics of
//! an inverting tippe top"), for any [`Ball`] of this crate.
//!
//! # The equations of motion
//!
//! The conventions are those of [`crate::ball`]: body frame at the centre of mass along the
//! principal axes, `com` the centre of mass relative to the geometric centre, `gamma` the unit
//! normal of the plane pointing into it, `r = R gamma - com` from the centre of mass to the
//! contact point, the height of the centre of mass `h = (r, gamma) = R - (com, gamma)`.
//! Written in the body frame, with `'` the rate of change of the components:
//!
//! - the state `x = (gamma, omega, v, W)`: the angular velocity `omega`, the velocity `v` of
//!   the centre of mass (all three body components, the vertical one fixed by the constraint
//!   below), and `W`, the work of friction so far (an extra quadrature);
//! - the forces at the contact point: the normal force `N` (upward, `-N gamma`) and the
//!   friction `F = -mu N v_P`, `v_P = v + omega x r` the velocity of the material point of
//!   contact (the slip); gravity `m G gamma` at the centre of mass;
//! - Newton: `m (v' + omega x v) = m G gamma - N gamma + F`;
//! - Euler about the centre of mass, `L = I omega`: `L' + omega x L = r x (F - N gamma)`;
//! - Poisson: `gamma' = gamma x omega` (gamma is fixed in space).
//!
//! `N` is not a state: it is the force that keeps the ball on the plane. The height constraint
//! `h = R - (com, gamma)` gives, by `gamma' = gamma x omega`, the vertical velocity
//! `(v, gamma) = (com, gamma x omega)` (down is `+gamma`), which is `(v_P, gamma) = 0`:
//! the contact point does not leave the plane (`(omega x r, gamma) = -(com, gamma x omega)`
//! since `r x gamma = -com x gamma`). Its second derivative, by Newton's law along gamma
//! (`d/dt (v, gamma) = G - N/m + (F, gamma)/m`, the terms of `omega x v` cancel) and by Euler's
//! law for `omega'`, is linear in `N`:
//!
//! `G - N/m = (com, (gamma x omega) x omega) + (com x gamma, omega')`,
//! `omega' = I^{-1} (L x omega + r x (F - N gamma))`,
//!
//! with `F = -mu N v_P`, `(F, gamma) = 0` on the constraint. With `k = com x gamma`,
//! `a = I^{-1} k` and `r x gamma = -k`, solved for `N`:
//!
//! `N = (G - (com, (gamma x omega) x omega) - (a, L x omega)) / (1/m + (a, k) - mu (a, r x v_P))`
//!
//! ([`Sliding::normal_force`]). For the ball at rest, upright, `N = m G`. The denominator is
//! `1/m + (k, I^{-1} k) > 0` without friction; friction can drive it to zero (Painlevé's
//! paradox), where `N` changes sign through infinity. A state where `N` would become negative
//! (the ball would leave the plane) ends the run there: the sign change of `N` is an event of
//! the one locator ([`crate::integrate::drive`]).
//!
//! Off the constraint, `(F, gamma) = -mu N (v_P, gamma)` makes
//! `d/dt (v_P, gamma) = -(mu N / m) (v_P, gamma)`: the constraint manifold is invariant and
//! attracting, and its residual is tracked ([`Balance::vertical_slip`]).
//!
//! # What is conserved, and what is lost
//!
//! - Jellett's integral `J = (L, r)` (equal to H3 = (M, r) of the rolling law, since
//!   `M = L + m r x (omega x r)`): `J' = (L x omega + r x P, r) + (L, R gamma x omega)
//!   = (L x omega, r - R gamma) = -(L x omega, com)`, zero when `com` is on e3 and I1 = I2
//!   (the Routh sphere: the third component of `L x omega` is `(I2 - I1) omega1 omega2`) and
//!   when `com = 0`, whatever the force `P` at the contact point ([`Sliding::has_jellett`]).
//! - The energy, written as the rolling law's H1 (twice the energy),
//!   `H1 = m |v|^2 + (omega, I omega) + 2 U`: its rate is twice the power of the contact force
//!   at the contact point, `H1' = 2 (F - N gamma, v_P) = -2 mu N |v_P|^2 <= 0` while
//!   `N >= 0`. The state's last component integrates `W' = 2 mu N |v_P|^2`, so that
//!   `H1 + W` is constant: the loss of energy is the work of friction, measured along the run.
//!
//! With zero slip, `M = I_Q omega` and `H1` is that of the rolling law; as `mu` grows the slip
//! decays at the rate `mu N / m` and the motion approaches the paper's system (mg-eq).
//!
//! Written once, generic over [`Scalar`]: `f64` for the steps, dual numbers for Jacobians and
//! for the derivatives along the field that check the derivation (the tests), the Taylor
//! method's tape ([`OdeSystem::record`]).

use super::coulomb::Transition;
use super::{Contact, Friction};
use crate::ball::{AsBall, Ball};
use crate::error::{Number, Result, RouthError};
use crate::integrate::taylor::Var;
use crate::integrate::{
    drive, stepper, Control, Drive, Method, OdeSystem, Options, RunUnits, Stop,
};
use crate::scalar::{cross, dot, lift, Scalar};
use crate::simulate::{Drift, Settings};
use crate::state::{Normalise, State, UNIT_TOLERANCE};
use crate::units::{Dimension, Units};
use serde::Serialize;
use std::time::Instant;

/// The dimension of the state `x = (gamma, omega, v, W)`.
pub const DIM: usize = 10;

/// A ball on the plane with a slipping contact: the ball, the friction law and `mu`, valid
/// when built ([`Sliding::new`], [`Sliding::with_friction`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sliding {
    ball: Ball,
    friction: Friction,
    mu: f64,
}

/// Which way the friction of a field evaluation points, decided on the `f64` state (a
/// dual number or a series cannot be compared): the friction per unit of normal force
/// `phi`, `F = -N phi` ([`Sliding::friction_per_normal`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Heading {
    /// As the law says at the state: `mu v_P` (viscous), `mu v_P / |v_P|` (Coulomb).
    Law,
    /// Coulomb's `mu v_P / sigma` with the signed slip speed `sigma = sign |v_P|`: with
    /// `sign = -1` past the instant where the slip stops, the field continued smoothly
    /// through it (the friction keeps its direction), so that the stop is a simple zero
    /// of a smooth function ([`crate::contact::coulomb`]).
    Signed(f64),
    /// `mu d`, `d` a unit vector: Coulomb's friction where the slip is zero to round-off
    /// and its direction is that of the slip about to start.
    Along([f64; 3]),
}

/// The parts `(gamma, omega, v)` of a state.
#[inline(always)]
fn parts<D: Scalar>(x: &[D; DIM]) -> ([D; 3], [D; 3], [D; 3]) {
    ([x[0], x[1], x[2]], [x[3], x[4], x[5]], [x[6], x[7], x[8]])
}

/// `com` as constants of the scalar type.
#[inline(always)]
fn constant<D: Scalar>(c: [f64; 3]) -> [D; 3] {
    c.map(lift)
}

impl Sliding {
    /// The ball `ball` sliding with the viscous friction coefficient `mu` (finite, `>= 0`:
    /// the rule of [`Contact::sliding`]).
    pub fn new(ball: &impl AsBall, mu: f64) -> Result<Self> {
        Self::with_friction(ball, Friction::Viscous, mu)
    }

    /// The ball `ball` sliding with the friction law `friction` of coefficient `mu`
    /// (finite, `>= 0`: the rule of [`Contact::sliding`]).
    pub fn with_friction(ball: &impl AsBall, friction: Friction, mu: f64) -> Result<Self> {
        Contact::sliding(friction, mu)?;
        Ok(Sliding {
            ball: ball.ball(),
            friction,
            mu,
        })
    }

    /// The friction law.
    pub fn friction(&self) -> Friction {
        self.friction
    }

    /// The ball.
    pub fn ball(&self) -> Ball {
        self.ball
    }

    /// The friction coefficient mu (`F = -mu N v_P` viscous, `|F| = mu N` Coulomb).
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// The method that runs `asked` at the tolerance `tol` under this friction: `auto` as one
    /// run of the rolling law picks it ([`crate::auto::resolve`]) for the viscous friction, by
    /// [`super::coulomb::method`] for Coulomb's (which refuses the Taylor method and RK4).
    pub fn method(&self, asked: Method, tol: f64) -> Result<Method> {
        match self.friction {
            Friction::Viscous => Ok(crate::auto::resolve(asked, tol, false)),
            Friction::Coulomb => super::coulomb::method(asked, tol),
        }
    }

    /// Whether Jellett's integral [`Sliding::jellett`] is an integral: the centre of mass on
    /// e3 with I1 = I2 (the Routh sphere), or at the geometric centre.
    pub fn has_jellett(&self) -> bool {
        use crate::ball::Model;
        self.ball.model() == Model::RouthSphere || self.ball.is_chaplygin()
    }

    /// The velocity of the material point of contact, `v_P = v + omega x r` (the slip).
    #[inline(always)]
    pub fn slip_velocity<D: Scalar>(&self, x: &[D; DIM]) -> [D; 3] {
        let (gamma, omega, v) = parts(x);
        let spin = cross(&omega, &self.ball.contact_vector(&gamma));
        std::array::from_fn(|i| v[i] + spin[i])
    }

    /// The friction per unit of normal force, `phi` with `F = -N phi`: `mu v_P` (viscous),
    /// `mu v_P / |v_P|` (Coulomb, while it slips), as `heading` says ([`Heading`]).
    #[inline(always)]
    pub fn friction_per_normal<D: Scalar>(&self, slip: &[D; 3], heading: Heading) -> [D; 3] {
        let mu = self.mu;
        match (self.friction, heading) {
            (Friction::Viscous, _) => slip.map(|s| s * mu),
            (Friction::Coulomb, Heading::Along(d)) => d.map(|c| lift(c * mu)),
            (Friction::Coulomb, Heading::Law) => {
                let per_speed = dot(slip, slip).sqrt().recip() * mu;
                slip.map(|s| s * per_speed)
            }
            (Friction::Coulomb, Heading::Signed(sign)) => {
                let per_speed = dot(slip, slip).sqrt().recip() * (mu * sign);
                slip.map(|s| s * per_speed)
            }
        }
    }

    /// The normal force N that keeps the ball on the plane (the module's formula), with the
    /// friction of the law at the state ([`Heading::Law`]).
    #[inline(always)]
    pub fn normal_force<D: Scalar>(&self, x: &[D; DIM]) -> D {
        self.normal_force_heading(x, Heading::Law)
    }

    /// [`Sliding::normal_force`] with the friction directed as `heading` says.
    #[inline(always)]
    pub fn normal_force_heading<D: Scalar>(&self, x: &[D; DIM], heading: Heading) -> D {
        let slip = self.slip_velocity(x);
        self.normal_force_with(x, &self.friction_per_normal(&slip, heading))
    }

    /// [`Sliding::normal_force`] with the friction per unit of normal force `phi` computed
    /// already.
    #[inline(always)]
    fn normal_force_with<D: Scalar>(&self, x: &[D; DIM], phi: &[D; 3]) -> D {
        let ball = &self.ball;
        let (gamma, omega, _) = parts(x);
        let com = constant::<D>(ball.com());
        let inertia = ball.inertia();
        let moment: [D; 3] = std::array::from_fn(|i| omega[i] * inertia[i]);
        let k = cross(&com, &gamma);
        let a: [D; 3] = std::array::from_fn(|i| k[i] / inertia[i]);
        let r = ball.contact_vector(&gamma);
        let centripetal = cross(&cross(&gamma, &omega), &omega);
        let numerator =
            -dot(&com, &centripetal) - dot(&a, &cross(&moment, &omega)) + ball.gravity();
        let denominator = dot(&a, &k) - dot(&a, &cross(&r, phi)) + ball.m().recip();
        numerator / denominator
    }

    /// The field `x' = X(x)` of the module's equations, with the friction of the law at the
    /// state ([`Heading::Law`]).
    #[inline(always)]
    pub fn field<D: Scalar>(&self, x: &[D; DIM]) -> [D; DIM] {
        self.field_heading(x, Heading::Law)
    }

    /// [`Sliding::field`] with the friction directed as `heading` says.
    #[inline(always)]
    pub fn field_heading<D: Scalar>(&self, x: &[D; DIM], heading: Heading) -> [D; DIM] {
        let ball = &self.ball;
        let (gamma, omega, v) = parts(x);
        let slip = self.slip_velocity(x);
        let phi = self.friction_per_normal(&slip, heading);
        let normal = self.normal_force_with(x, &phi);
        // The contact force P = -N (gamma + phi): the normal force and the friction.
        let force: [D; 3] = std::array::from_fn(|i| -normal * (gamma[i] + phi[i]));
        let inertia = ball.inertia();
        let moment: [D; 3] = std::array::from_fn(|i| omega[i] * inertia[i]);
        let gyroscopic = cross(&moment, &omega);
        let torque = cross(&ball.contact_vector(&gamma), &force);
        let gamma_dot = cross(&gamma, &omega);
        let transport = cross(&v, &omega);
        let per_mass = ball.m().recip();
        // Twice the power of the friction, -2 (F, v_P) = 2 N (phi, v_P).
        let power = normal * dot(&phi, &slip) * 2.0;
        [
            gamma_dot[0],
            gamma_dot[1],
            gamma_dot[2],
            (gyroscopic[0] + torque[0]) / inertia[0],
            (gyroscopic[1] + torque[1]) / inertia[1],
            (gyroscopic[2] + torque[2]) / inertia[2],
            transport[0] + gamma[0] * ball.gravity() + force[0] * per_mass,
            transport[1] + gamma[1] * ball.gravity() + force[1] * per_mass,
            transport[2] + gamma[2] * ball.gravity() + force[2] * per_mass,
            power,
        ]
    }

    /// The energy as the rolling law's H1, twice the energy:
    /// `m |v|^2 + (omega, I omega) + 2 U`.
    #[inline]
    pub fn energy<D: Scalar>(&self, x: &[D; DIM]) -> D {
        let ball = &self.ball;
        let (gamma, omega, v) = parts(x);
        let inertia = ball.inertia();
        let moment: [D; 3] = std::array::from_fn(|i| omega[i] * inertia[i]);
        dot(&v, &v) * ball.m() + dot(&moment, &omega) + ball.potential(&gamma) * 2.0
    }

    /// Jellett's integral `J = (L, r)`, `L = I omega` (the rolling law's H3).
    #[inline]
    pub fn jellett<D: Scalar>(&self, x: &[D; DIM]) -> D {
        let (gamma, omega, _) = parts(x);
        let inertia = self.ball.inertia();
        let moment: [D; 3] = std::array::from_fn(|i| omega[i] * inertia[i]);
        dot(&moment, &self.ball.contact_vector(&gamma))
    }

    /// The vertical slip `(v_P, gamma)`, zero on the constraint.
    #[inline]
    pub fn vertical_slip<D: Scalar>(&self, x: &[D; DIM]) -> D {
        let (gamma, _, _) = parts(x);
        dot(&self.slip_velocity(x), &gamma)
    }

    /// The height of the centre of mass above the plane, `(r, gamma)`.
    #[inline]
    pub fn height<D: Scalar>(&self, x: &[D; DIM]) -> D {
        let (gamma, _, _) = parts(x);
        dot(&self.ball.contact_vector(&gamma), &gamma)
    }

    /// The state at t = 0 from gamma (checked as [`State::from_omega`] checks it), omega and
    /// the horizontal velocity `velocity` of the centre of mass (body frame, orthogonal to
    /// gamma within [`UNIT_TOLERANCE`] of `|velocity| + R |omega|`): its vertical part is the
    /// constraint's, `(com, gamma x omega) gamma`, and W = 0. Refused when N <= 0 there (the
    /// ball would leave the plane at once).
    pub fn initial(
        &self,
        gamma: [f64; 3],
        omega: [f64; 3],
        velocity: [f64; 3],
        normalise: Normalise,
    ) -> Result<[f64; DIM]> {
        let gamma = State::from_omega(&self.ball, gamma, omega, normalise)?.gamma();
        if velocity.iter().any(|c| !c.is_finite()) {
            return Err(RouthError::State(format!(
                "velocity = {velocity:?}: must be finite"
            )));
        }
        let norm = |u: &[f64; 3]| dot(u, u).sqrt();
        let scale = norm(&velocity) + self.ball.radius() * norm(&omega);
        let vertical = dot(&velocity, &gamma);
        if !(vertical.abs() <= UNIT_TOLERANCE * scale) {
            return Err(RouthError::State(format!(
                "velocity = {velocity:?} of the centre of mass is not horizontal: \
                 (velocity, gamma) = {} (the contact keeps the ball on the plane, so the \
                 vertical velocity follows from gamma and omega; give the horizontal part)",
                Number(vertical)
            )));
        }
        let rise = dot(&self.ball.com(), &cross(&gamma, &omega));
        let v: [f64; 3] = std::array::from_fn(|i| velocity[i] + gamma[i] * rise);
        let x = [
            gamma[0], gamma[1], gamma[2], omega[0], omega[1], omega[2], v[0], v[1], v[2], 0.0,
        ];
        let normal = match self.friction {
            Friction::Viscous => self.normal_force(&x),
            Friction::Coulomb => super::coulomb::initial_normal_force(self, &x),
        };
        if !(normal > 0.0) {
            return Err(RouthError::State(format!(
                "the normal force N = {} at t = 0 is not positive: the ball would leave the \
                 plane",
                Number(normal)
            )));
        }
        Ok(x)
    }

    /// The quantities a user reads at the state `x`, time `t` (the normal force of the law
    /// at the state: [`Sliding::normal_force`]).
    pub fn observe(&self, t: f64, x: &[f64; DIM]) -> Observation {
        self.observe_with(t, x, self.normal_force(x))
    }

    /// [`Sliding::observe`] with the normal force `normal` (of the phase a run is in:
    /// [`super::coulomb`]).
    pub fn observe_with(&self, t: f64, x: &[f64; DIM], normal: f64) -> Observation {
        let (gamma, omega, velocity) = parts(x);
        let slip = self.slip_velocity(x);
        Observation {
            t,
            gamma,
            omega,
            velocity,
            height: self.height(x),
            slip_speed: dot(&slip, &slip).sqrt(),
            normal_force: normal,
            jellett: self.jellett(x),
            energy: self.energy(x),
            work: x[9],
        }
    }
}

/// The units of a run of the sliding ball from `y0`: the motion's time T
/// (`1 / max(sqrt(G / R), |omega|, |v| / R)`), gamma dimensionless, omega in `1 / T`, v in
/// `R / T`, W in the unit of energy, rounded to powers of two ([`Units::binary`]).
impl OdeSystem<DIM> for Sliding {
    type Kernels = crate::integrate::taylor::Interpreted;

    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; DIM]) -> [f64; DIM] {
        self.field(y)
    }

    /// The viscous field; none under Coulomb's friction (not smooth where the slip stops).
    fn record(&self, _t: Var, y: &[Var; DIM]) -> Option<[Var; DIM]> {
        (self.friction == Friction::Viscous).then(|| self.field(y))
    }

    fn units(&self, y0: &[f64; DIM]) -> RunUnits<DIM> {
        let units = self.problem_units(y0);
        let (w, s, e) = (
            units.time().recip(),
            units.length() / units.time(),
            units.energy(),
        );
        RunUnits {
            time: units.time(),
            components: [1.0, 1.0, 1.0, w, w, w, s, s, s, e],
        }
    }
}

impl Sliding {
    /// The units of a motion from `y0` (R, m and the time of its spin or of its rolling speed
    /// over R, rounded to powers of two: [`Units::with_rate`], [`Units::binary`]).
    pub(super) fn problem_units(&self, y0: &[f64; DIM]) -> Units {
        let (_, omega, v) = parts(y0);
        let speed = dot(&v, &v).sqrt() / self.ball.radius();
        let rate = dot(&omega, &omega).sqrt().max(speed);
        Units::with_rate(&self.ball, rate).binary()
    }
}

/// What a user reads of a state of the sliding ball: a row of `routh simulate`'s table.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Observation {
    /// The time.
    pub t: f64,
    /// The unit normal of the plane, body frame.
    pub gamma: [f64; 3],
    /// The angular velocity, body frame.
    pub omega: [f64; 3],
    /// The velocity of the centre of mass, body frame.
    pub velocity: [f64; 3],
    /// The height of the centre of mass above the plane.
    pub height: f64,
    /// The slip speed `|v_P|`.
    pub slip_speed: f64,
    /// The normal force N.
    pub normal_force: f64,
    /// Jellett's `(L, r)`.
    pub jellett: f64,
    /// The energy as H1 (twice the energy).
    pub energy: f64,
    /// The work of friction W so far (as H1: twice the work), so that `energy + work` is
    /// constant.
    pub work: f64,
}

/// The names of the columns of an [`Observation`], in the order of [`Observation::values`].
pub const OBSERVATION_NAMES: [&str; 17] = [
    "t",
    "gamma1",
    "gamma2",
    "gamma3",
    "omega1",
    "omega2",
    "omega3",
    "v1",
    "v2",
    "v3",
    "height",
    "slip_speed",
    "normal_force",
    "jellett",
    "H1",
    "work",
    "H1_plus_work",
];

impl Observation {
    /// The state `x = (gamma, omega, v, W)` observed.
    pub fn state(&self) -> [f64; DIM] {
        let ([g1, g2, g3], [w1, w2, w3], [v1, v2, v3]) = (self.gamma, self.omega, self.velocity);
        [g1, g2, g3, w1, w2, w3, v1, v2, v3, self.work]
    }

    /// The values, in the order of [`OBSERVATION_NAMES`].
    pub fn values(&self) -> [f64; 17] {
        let [g1, g2, g3] = self.gamma;
        let [w1, w2, w3] = self.omega;
        let [v1, v2, v3] = self.velocity;
        [
            self.t,
            g1,
            g2,
            g3,
            w1,
            w2,
            w3,
            v1,
            v2,
            v3,
            self.height,
            self.slip_speed,
            self.normal_force,
            self.jellett,
            self.energy,
            self.work,
            self.energy + self.work,
        ]
    }
}

/// How the balances of a run held: the largest changes over its step ends and samples.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Balance {
    /// `max |J - J(0)| / |J(0)|` (in the unit of J's dimension if `J(0) = 0`: [`Drift`]);
    /// `None` where Jellett's `(L, r)` is not an integral ([`Sliding::has_jellett`]).
    pub jellett: Option<f64>,
    /// `max |(H1 + W) - H1(0)| / |H1(0)|` (in the unit of energy if `H1(0) = 0`: [`Drift`]):
    /// the energy balance, loss = friction work.
    pub energy_balance: f64,
    /// The largest increase of H1 between consecutive step ends, relative to `|H1(0)|` (or
    /// the unit of energy, as the balance) (zero when the energy never increases).
    pub energy_increase: f64,
    /// `max |(v_P, gamma)|` over `R / T` (the motion's speed): the residual of the constraint.
    pub vertical_slip: f64,
    /// The smallest normal force seen.
    pub min_normal_force: f64,
    /// The lowest and highest height of the centre of mass seen.
    pub height_range: [f64; 2],
}

/// What a run of the sliding ball reports.
#[derive(Debug, Clone, Serialize)]
pub struct SlidingSummary {
    /// The method, as `dop853`.
    pub method: String,
    /// `ok` (t_end reached) or `event` (the normal force vanished: the ball leaves the plane).
    pub status: &'static str,
    /// A sentence saying how the run ended.
    pub message: String,
    /// The time reached.
    pub t: f64,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Evaluations of the field.
    pub rhs_evals: usize,
    /// The friction law, `viscous` or `coulomb`.
    pub friction: &'static str,
    /// The friction coefficient mu.
    pub mu: f64,
    /// The switches between sliding and rolling, in time order (Coulomb's friction only:
    /// [`super::coulomb`]).
    pub transitions: Vec<Transition>,
    /// The initial state.
    pub initial_state: Observation,
    /// The state reached.
    pub final_state: Observation,
    /// The balances over the run.
    pub balance: Balance,
    /// Wall time of the integration in seconds.
    pub elapsed_s: f64,
}

/// The running [`Balance`] of a run.
struct Tracker {
    model: Sliding,
    first: Observation,
    /// Jellett's integral, where it is one.
    jellett: Option<Drift>,
    /// The energy plus the friction's work, which stays H1(0).
    energy: Drift,
    last_energy: f64,
    /// `R / T`, the speed of the residual of the constraint.
    speed: f64,
    balance: Balance,
}

impl Tracker {
    /// Starts at `y0`, observed as `first`.
    fn new(model: &Sliding, first: Observation, y0: &[f64; DIM]) -> Self {
        let units = model.problem_units(y0);
        let unit = |d: Dimension| move || units.of_dimension(d);
        let jellett = Drift::start(first.jellett, unit(Dimension::MOMENTUM_LENGTH));
        Tracker {
            model: *model,
            first,
            jellett: model.has_jellett().then_some(jellett),
            energy: Drift::start(first.energy, unit(Dimension::ENERGY)),
            last_energy: first.energy,
            speed: model.ball.radius() / units.time(),
            balance: Balance {
                jellett: model.has_jellett().then_some(0.0),
                energy_balance: 0.0,
                energy_increase: 0.0,
                vertical_slip: 0.0,
                min_normal_force: first.normal_force,
                height_range: [first.height; 2],
            },
        }
    }

    /// The state `y`, observed as `now`.
    fn observe(&mut self, now: &Observation, y: &[f64; DIM]) {
        let b = &mut self.balance;
        if let Some(j) = self.jellett.as_mut() {
            j.observe(now.jellett);
            b.jellett = Some(j.max_rel_drift);
        }
        self.energy.observe(now.energy + now.work);
        b.energy_balance = self.energy.max_rel_drift;
        b.energy_increase = b
            .energy_increase
            .max((now.energy - self.last_energy) / self.energy.scale());
        self.last_energy = now.energy;
        b.vertical_slip = b
            .vertical_slip
            .max(self.model.vertical_slip(y).abs() / self.speed);
        b.min_normal_force = b.min_normal_force.min(now.normal_force);
        b.height_range = [
            b.height_range[0].min(now.height),
            b.height_range[1].max(now.height),
        ];
    }
}

/// The callback of [`run`]'s samples: the observation at each sample time.
pub type OnObservation<'a, E> = dyn FnMut(&Observation) -> std::result::Result<(), E> + 'a;

/// A callback of samples with the observation and `N` more numbers of the state there (the
/// motion in space: [`run_in_space`]).
pub type OnState<'a, E, const N: usize> =
    dyn FnMut(&Observation, &[f64; N]) -> std::result::Result<(), E> + 'a;

/// Integrate the sliding ball from `y0` ([`Sliding::initial`]) with the method, tolerances,
/// samples, span and step limit of `settings` (projection is refused: the sliding ball has
/// no level set of integrals to project onto), through the one driver ([`drive`]), until
/// `t_end` or until the normal force vanishes (an event located by the one locator: the
/// ball would leave the plane); under Coulomb's friction, through its phases of sliding and
/// rolling ([`super::coulomb`]). `on_sample` receives the observations at the samples; the
/// balances are tracked at every step end. A failure of the integrator is an error.
pub fn run<E: From<RouthError>>(
    model: &Sliding,
    y0: [f64; DIM],
    settings: &Settings,
    on_sample: &mut OnObservation<'_, E>,
) -> std::result::Result<SlidingSummary, E> {
    let start = Instant::now();
    let (method, opts) = plan(model, settings)?;
    match model.friction {
        Friction::Viscous => {
            let end = viscous(model, model, y0, method, &opts, settings, &mut |now, _| {
                on_sample(now)
            })?;
            Ok(summarise(model, method, end, start))
        }
        Friction::Coulomb => {
            let first = super::coulomb::first_observation(model, &y0);
            let mut tracker = Tracker::new(model, first, &y0);
            let end = super::coulomb::integrate(
                model,
                y0,
                method,
                &opts,
                settings,
                on_sample,
                &mut |now, y| tracker.observe(now, y),
            )?;
            tracker.observe(&end.last, &end.outcome.y);
            let ending = Ending {
                stop: end.outcome.stop,
                t: end.outcome.t,
                stats: end.outcome.stats,
                last: end.last,
                transitions: end.transitions,
                tracker,
            };
            Ok(summarise(model, method, ending, start))
        }
    }
}

/// [`run`] with the motion in space ([`SlidingMotion`]): `on_sample` receives each sample's
/// observation and the columns of [`motion_columns`] (the orientation, the centre of mass and
/// the contact point in space). Viscous friction only, so far (Coulomb's phases would each
/// need the motion added).
pub fn run_in_space<E: From<RouthError>>(
    model: &Sliding,
    y0: [f64; DIM],
    settings: &Settings,
    on_sample: &mut OnState<'_, E, 9>,
) -> std::result::Result<SlidingSummary, E> {
    if model.friction != Friction::Viscous {
        return Err(RouthError::Option {
            name: "full",
            value: "true".into(),
            rule: "is available for the viscous friction only (so far): under Coulomb's \
                   friction the motion in space is not rebuilt",
        }
        .into());
    }
    let start = Instant::now();
    let (method, opts) = plan(model, settings)?;
    let sys = SlidingMotion(model);
    let end = viscous(
        model,
        &sys,
        sys.initial(&y0),
        method,
        &opts,
        settings,
        &mut |now, y| on_sample(now, &motion_columns(model, y)),
    )?;
    Ok(summarise(model, method, end, start))
}

/// The method and the options of a run with `settings` (its projection refused).
fn plan(model: &Sliding, settings: &Settings) -> Result<(Method, Options)> {
    if settings.project() {
        return Err(RouthError::Option {
            name: "project",
            value: "true".into(),
            rule: "is not available for the sliding contact (its energy is not an integral: \
                   there is no level set to project onto)",
        });
    }
    let opts = Options::new(settings.rtol(), settings.atol())
        .and_then(|opts| opts.with_max_steps(settings.max_steps()))?;
    let method = model.method(settings.method(), settings.rtol().min(settings.atol()))?;
    Ok((method, opts))
}

/// How a run ended: the driver's stop, time and work, the last observation, the switches and
/// the balances.
struct Ending {
    stop: Stop,
    t: f64,
    stats: crate::integrate::Stats,
    last: Observation,
    transitions: Vec<Transition>,
    tracker: Tracker,
}

/// The run of `sys` under the viscous friction of `model`, `sys`'s state starting with the
/// sliding ball's (`y[..DIM]`; the motion in space may follow), from `y0`: the one driver
/// with the normal force's zero as its event, the balances tracked at every step end, the
/// samples handed to `on_sample` with the whole state.
fn viscous<S: OdeSystem<N>, E: From<RouthError>, const N: usize>(
    model: &Sliding,
    sys: &S,
    y0: [f64; N],
    method: Method,
    opts: &Options,
    settings: &Settings,
    on_sample: &mut OnState<'_, E, N>,
) -> std::result::Result<Ending, E> {
    let part = |y: &[f64; N]| -> [f64; DIM] { std::array::from_fn(|i| y[i]) };
    let x0 = part(&y0);
    let mut tracker = Tracker::new(model, model.observe(0.0, &x0), &x0);
    let times = settings.sample_times();
    let mut stepper =
        stepper(method, sys, 0.0, y0, settings.t_end(), opts).map_err(RouthError::from)?;
    let leaves = |_: f64, y: &[f64; N]| model.normal_force(&part(y));
    let plan = Drive {
        samples: &times,
        project: None,
        event: Some(&leaves),
    };
    let outcome = drive(
        stepper.as_mut(),
        &plan,
        &mut |t, y| on_sample(&model.observe(t, &part(y)), y),
        &mut |t, y, _| {
            let x = part(y);
            tracker.observe(&model.observe(t, &x), &x);
            Ok(Control::Continue)
        },
    )?;
    if let Stop::Failed(e) = &outcome.stop {
        return Err(RouthError::from(e.clone()).into());
    }
    let x = part(&outcome.y);
    let last = model.observe(outcome.t, &x);
    tracker.observe(&last, &x);
    Ok(Ending {
        stop: outcome.stop,
        t: outcome.t,
        stats: outcome.stats,
        last,
        transitions: Vec::new(),
        tracker,
    })
}

/// The summary of a run that ended as `end`, begun at `start`.
fn summarise(model: &Sliding, method: Method, end: Ending, start: Instant) -> SlidingSummary {
    let (status, message) = match &end.stop {
        Stop::Event => (
            "event",
            format!(
                "the normal force vanished at t = {}: the ball leaves the plane",
                end.t
            ),
        ),
        Stop::Stopped => ("ok", format!("stopped at t = {}", end.t)),
        _ => ("ok", format!("t_end = {} reached", end.t)),
    };
    SlidingSummary {
        method: method.to_string(),
        status,
        message,
        t: end.t,
        steps: end.stats.steps,
        rejected: end.stats.rejected,
        rhs_evals: end.stats.rhs_evals,
        friction: model.friction.name(),
        mu: model.mu,
        transitions: end.transitions,
        initial_state: end.tracker.first,
        final_state: end.last,
        balance: end.tracker.balance,
        elapsed_s: start.elapsed().as_secs_f64(),
    }
}

/// The number of components of [`SlidingMotion`]'s state.
pub const MOTION_DIM: usize = DIM + 6;

/// The sliding ball with its motion in space (as [`crate::motion::FullMotion`] for the
/// rolling ball): the state `(gamma, omega, v, W, q, X, Y)`, the quaternion of the rotation
/// body to space (its kinematics [`crate::motion::quaternion_rate`]) and the horizontal
/// position of the centre of mass, `(X, Y)' = (Q v)_xy` (its height is `(r, gamma)`). The
/// first [`DIM`] components are integrated by the sliding field itself and do not depend on
/// the others.
#[derive(Debug, Clone, Copy)]
pub struct SlidingMotion<'a>(pub &'a Sliding);

impl SlidingMotion<'_> {
    /// The state with the orientation of [`crate::motion::orientation_for`] of `x0`'s gamma
    /// and the centre of mass above the origin.
    pub fn initial(&self, x0: &[f64; DIM]) -> [f64; MOTION_DIM] {
        let q = crate::motion::orientation_for(&[x0[0], x0[1], x0[2]]);
        let mut y = [0.0; MOTION_DIM];
        y[..DIM].copy_from_slice(x0);
        y[DIM..DIM + 4].copy_from_slice(&[q.w, q.i, q.j, q.k]);
        y
    }
}

impl OdeSystem<MOTION_DIM> for SlidingMotion<'_> {
    type Kernels = crate::integrate::taylor::Interpreted;

    fn rhs(&self, _t: f64, y: &[f64; MOTION_DIM]) -> [f64; MOTION_DIM] {
        let x: [f64; DIM] = std::array::from_fn(|i| y[i]);
        let (_, omega, v) = parts(&x);
        let q = nalgebra::Quaternion::new(y[DIM], y[DIM + 1], y[DIM + 2], y[DIM + 3]);
        let time = self.0.problem_units(&x).time();
        let q_dot = crate::motion::quaternion_rate(&q, &omega, time);
        let velocity = crate::motion::rotate(&q, &v);
        let mut dy = [0.0; MOTION_DIM];
        dy[..DIM].copy_from_slice(&self.0.field(&x));
        dy[DIM..DIM + 4].copy_from_slice(&[q_dot.w, q_dot.i, q_dot.j, q_dot.k]);
        dy[DIM + 4] = velocity[0];
        dy[DIM + 5] = velocity[1];
        dy
    }

    /// The sliding state's units, 1 for the quaternion, R (a power of two) for the position.
    fn units(&self, y0: &[f64; MOTION_DIM]) -> RunUnits<MOTION_DIM> {
        let inner = self.0.units(&std::array::from_fn(|i| y0[i]));
        let length = self
            .0
            .problem_units(&std::array::from_fn(|i| y0[i]))
            .length();
        let mut components = [1.0; MOTION_DIM];
        components[..DIM].copy_from_slice(&inner.components);
        components[DIM + 4] = length;
        components[DIM + 5] = length;
        RunUnits {
            time: inner.time,
            components,
        }
    }
}

/// The columns of the motion in space at `y` (of [`SlidingMotion`]), named as the rolling
/// ball's ([`crate::motion::FULL_COLUMN_NAMES`]): the quaternion, the centre of mass `(X, Y,
/// z)` with `z = (r, gamma)`, and the contact point `(x, y)` on the plane.
pub fn motion_columns(model: &Sliding, y: &[f64; MOTION_DIM]) -> [f64; 9] {
    let gamma = [y[0], y[1], y[2]];
    let r = model.ball.contact_vector(&gamma);
    let q = nalgebra::Quaternion::new(y[DIM], y[DIM + 1], y[DIM + 2], y[DIM + 3]);
    let to_contact = crate::motion::rotate(&q, &r);
    let (x, yy) = (y[DIM + 4], y[DIM + 5]);
    [
        q.w,
        q.i,
        q.j,
        q.k,
        x,
        yy,
        dot(&r, &gamma),
        x + to_contact[0],
        yy + to_contact[1],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Body;
    use crate::differential::{partials, seeded};
    use num_dual::DualSVec64;

    type Dual = DualSVec64<DIM>;

    /// The motion in space of the tippe top (t = 8, 4001 samples): the orientation,
    /// integrated by the kinematics alone, takes the body-frame normal gamma, integrated by the
    /// sliding field alone, to the downward vertical (1e-9: two integrations at 1e-12 over
    /// 8 time units), |q| stays 1 (1e-10), the centre's horizontal path is the integral of
    /// the sampled velocity `Q v` (trapezoid rule, 1e-3 of R: h^2 T |V''| / 12 is about 3e-4),
    /// and the run ends where the run without the motion does (its height to 1e-8).
    #[test]
    fn the_motion_in_space_agrees_with_the_sliding_state() {
        let body = Body::new(1.0, 1.0, 0.3, 0.37, 0.37, 0.4, 9.81).unwrap();
        let model = Sliding::new(&body, 0.3).unwrap();
        let tilt = 0.1_f64;
        let y0 = model
            .initial(
                [tilt.sin(), 0.0, -tilt.cos()],
                [0.0, 0.0, 20.0],
                [0.0; 3],
                Normalise::Reject,
            )
            .unwrap();
        let settings = Settings::builder()
            .t_end(8.0)
            .tolerances(1e-12, 1e-12)
            .samples(4001)
            .build()
            .unwrap();
        let mut seen = Vec::new();
        let with = run_in_space::<RouthError>(&model, y0, &settings, &mut |now, space| {
            seen.push((*now, *space));
            Ok(())
        })
        .unwrap();
        let without = run::<RouthError>(&model, y0, &settings, &mut |_| Ok(())).unwrap();
        assert!((with.final_state.height - without.final_state.height).abs() <= 1e-8);
        let mut path = [0.0; 2];
        for (k, (now, space)) in seen.iter().enumerate() {
            let q = nalgebra::Quaternion::new(space[0], space[1], space[2], space[3]);
            assert!((q.norm() - 1.0).abs() <= 1e-10, "{k}: |q| = {}", q.norm());
            let down = crate::motion::rotate(&q, &now.gamma);
            assert!(
                down[0].abs() <= 1e-9 && down[1].abs() <= 1e-9 && (down[2] + 1.0).abs() <= 1e-9,
                "{k}: {down:?}"
            );
            if k > 0 {
                let (before, space_before) = &seen[k - 1];
                let qb = nalgebra::Quaternion::new(
                    space_before[0],
                    space_before[1],
                    space_before[2],
                    space_before[3],
                );
                let (va, vb) = (
                    crate::motion::rotate(&qb, &before.velocity),
                    crate::motion::rotate(&q, &now.velocity),
                );
                let h = now.t - before.t;
                for i in 0..2 {
                    path[i] += 0.5 * h * (va[i] + vb[i]);
                }
            }
            assert!(
                (path[0] - space[4]).abs() <= 1e-3 && (path[1] - space[5]).abs() <= 1e-3,
                "{k}: {path:?} {space:?}"
            );
            assert_eq!(space[6], now.height);
        }
    }

    /// The derivative of `h` along the field at `x`, by automatic differentiation of `h`.
    fn along(model: &Sliding, h: impl Fn(&[Dual; DIM]) -> Dual, x: &[f64; DIM]) -> f64 {
        let gradient = partials(&h(&seeded(x)));
        let field = model.field(x);
        gradient.iter().zip(&field).map(|(g, f)| g * f).sum()
    }

    /// States on the constraint: tilts from the low position to the inverted one, spins of
    /// both signs and a wobble, horizontal velocities of the centre of mass along and across;
    /// those where the ball stays on the plane (N > 0: [`Sliding::initial`] refuses the
    /// others), at least half of the 24.
    fn states(model: &Sliding) -> Vec<[f64; DIM]> {
        let mut out = Vec::new();
        for tilt in [0.1_f64, 1.0, 2.0, 3.0] {
            let gamma = [tilt.sin(), 0.0, -tilt.cos()];
            for omega in [[0.3, -0.7, 20.0], [1.5, 0.2, -6.0]] {
                // Horizontal: orthogonal to gamma.
                for velocity in [[0.0; 3], [tilt.cos(), 0.0, tilt.sin()], [0.0, -2.0, 0.0]] {
                    out.extend(
                        model
                            .initial(gamma, omega, velocity, Normalise::Reject)
                            .ok(),
                    );
                }
            }
        }
        assert!(out.len() >= 12, "{} states", out.len());
        out
    }

    /// The derivation checked by differentiating the integrals along the field it gives
    /// (independent of the hand-derived formula for N): on the constraint, Jellett's (L, r)
    /// and H1 + W are constant and the vertical slip stays zero, and H1 decreases at
    /// `2 mu N |v_P|^2`. Tolerance 1e-12 of each quantity's scale over the motion's time
    /// (its value over T, T = 1 / |omega|): the rates are sums of products of size
    /// `J / T` evaluated in f64, so a few hundred ulp. Negative control: with I1 != I2 the
    /// rate of (L, r) is not zero but `-(L x omega, com)` (measured -6.3e-3 at the state
    /// taken), as derived, to 1e-12.
    #[test]
    fn the_field_keeps_jellett_the_constraint_and_the_energy_balance() {
        for mu in [0.0, 0.3, 3.0] {
            let model = Sliding::new(
                &Body::new(1.0, 1.0, 0.3, 0.37, 0.37, 0.4, 9.81).unwrap(),
                mu,
            )
            .unwrap();
            assert!(model.has_jellett());
            for x in states(&model) {
                let rate = dot(&[x[3], x[4], x[5]], &[x[3], x[4], x[5]]).sqrt();
                let j = model.jellett(&x).abs() + 0.4 * rate;
                let e = model.energy(&x).abs();
                let dj = along(&model, |y| model.jellett(y), &x);
                assert!(dj.abs() <= 1e-12 * j * rate, "dJ/dt = {dj:e} at {x:?}");
                let dc = along(&model, |y| model.vertical_slip(y), &x);
                assert!(dc.abs() <= 1e-12 * rate * rate, "d(v_P, gamma)/dt = {dc:e}");
                let balance = along(&model, |y| model.energy(y) + y[9], &x);
                assert!(
                    balance.abs() <= 1e-12 * e * rate,
                    "d(H1 + W)/dt = {balance:e}"
                );
                let loss = along(&model, |y| model.energy(y), &x);
                let slip = model.slip_velocity(&x);
                let want = -2.0 * mu * model.normal_force(&x) * dot(&slip, &slip);
                assert!(
                    (loss - want).abs() <= 1e-12 * e * rate,
                    "{loss:e} vs {want:e}"
                );
            }
        }
        let ball = Ball::new(1.0, 1.0, [0.3, 0.37, 0.4], [0.0, 0.0, -0.3], 9.81).unwrap();
        let model = Sliding::new(&ball, 0.3).unwrap();
        assert!(!model.has_jellett());
        let x = states(&model)[3];
        let dj = along(&model, |y| model.jellett(y), &x);
        let omega = [x[3], x[4], x[5]];
        let moment = [0.3 * omega[0], 0.37 * omega[1], 0.4 * omega[2]];
        let want = -dot(&cross(&moment, &omega), &ball.com());
        assert!(want.abs() > 1e-3, "{want:e}");
        assert!(
            (dj - want).abs() <= 1e-12 * want.abs(),
            "{dj:e} vs {want:e}"
        );
    }

    /// The upright ball at rest presses on the plane with its weight, N = m G, to a few ulp;
    /// so does the Chaplygin ball in any position (com = 0: no lever arm).
    #[test]
    fn a_ball_at_rest_weighs_m_g() {
        let body = Body::new(2.0, 1.0, 0.3, 0.37, 0.37, 0.4, 9.81).unwrap();
        let model = Sliding::new(&body, 0.3).unwrap();
        let x = model
            .initial([0.0, 0.0, -1.0], [0.0; 3], [0.0; 3], Normalise::Reject)
            .unwrap();
        assert!((model.normal_force(&x) - 2.0 * 9.81).abs() <= 4.0 * f64::EPSILON * 19.62);
        let ball = Ball::new(2.0, 1.0, [0.3, 0.37, 0.4], [0.0; 3], 9.81).unwrap();
        let model = Sliding::new(&ball, 0.3).unwrap();
        let x = model
            .initial([0.6, 0.0, 0.8], [0.0; 3], [0.0; 3], Normalise::Reject)
            .unwrap();
        assert!((model.normal_force(&x) - 2.0 * 9.81).abs() <= 4.0 * f64::EPSILON * 19.62);
    }

    /// A ball that would leave the plane stops there, with that reason: the Routh sphere
    /// (a = 0.3) on a frictionless plane (mu = 0), spun at 10 about a horizontal axis across
    /// its symmetry axis, its centre of mass low, whirls its centre of mass up and over (its
    /// kinetic energy 20 exceeds the rise of the potential, m G 2a = 5.9), where the
    /// centripetal pull `a omega^2` exceeds G = 9.81 (over the top, N = m (G - a omega^2)):
    /// the run ends as an event before t = 0.5 (half a turn at about 8 to 10 rad/s), where
    /// N = 0 to 1e-9 of m G (the locator's zero, to about 2 ulp of t, times the rate of N,
    /// of order m a omega^3). Control: spun at 3 (kinetic energy 1.8, it rocks back) it
    /// reaches t_end.
    #[test]
    fn a_ball_that_would_leave_the_plane_stops_there() {
        let body = Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).unwrap();
        let model = Sliding::new(&body, 0.0).unwrap();
        let settings = Settings::builder().t_end(1.0).build().unwrap();
        let end = |spin: f64| {
            let y0 = model
                .initial(
                    [0.0, 0.0, -1.0],
                    [0.0, spin, 0.0],
                    [0.0; 3],
                    Normalise::Reject,
                )
                .unwrap();
            run::<RouthError>(&model, y0, &settings, &mut |_| Ok(())).unwrap()
        };
        let s = end(10.0);
        assert_eq!(s.status, "event", "{}", s.message);
        assert!(
            s.message.contains("the ball leaves the plane"),
            "{}",
            s.message
        );
        assert!(s.t < 0.5, "{}", s.t);
        assert!(
            s.final_state.normal_force.abs() < 1e-9 * 9.81,
            "{:e}",
            s.final_state.normal_force
        );
        let s = end(3.0);
        assert_eq!((s.status, s.t), ("ok", 1.0), "{}", s.message);
    }

    /// Refused when built, with the reason: a friction coefficient that is not finite and
    /// at least 0, a velocity of the centre of mass with a vertical part, a state whose normal
    /// force is not positive (no gravity, at rest: N = 0). Controls: mu = 0 and a horizontal
    /// velocity are accepted.
    #[test]
    fn invalid_contacts_and_states_are_refused() {
        let body = Body::new(1.0, 1.0, 0.3, 0.37, 0.37, 0.4, 9.81).unwrap();
        for mu in [f64::NAN, -1.0, f64::INFINITY] {
            let message = Sliding::new(&body, mu).unwrap_err().to_string();
            assert!(message.starts_with("invalid option mu = "), "{message}");
        }
        let model = Sliding::new(&body, 0.0).unwrap();
        let gamma = [0.0, 0.0, -1.0];
        let message = model
            .initial(gamma, [0.0, 0.0, 1.0], [1.0, 0.0, 0.5], Normalise::Reject)
            .unwrap_err()
            .to_string();
        assert!(message.contains("is not horizontal"), "{message}");
        model
            .initial(gamma, [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], Normalise::Reject)
            .unwrap();
        let free = Sliding::new(&body.without_gravity(), 0.3).unwrap();
        let message = free
            .initial(gamma, [0.0; 3], [0.0; 3], Normalise::Reject)
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("the ball would leave the plane"),
            "{message}"
        );
    }
}
