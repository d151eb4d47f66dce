//! The rubber ball: rolling without slipping and without twisting, for any [`Ball`] of this
//! crate. The contact point does not slip (`v + omega x r = 0`, as for the rolling law) and the
//! ball does not spin about the normal of the plane: `(omega, gamma) = 0` (the "rubber" model of
//! Ehlers and Koiller, "Rubber rolling over a sphere", Regul. Chaotic Dyn. 12 (2007) 127; A. V.
//! Borisov, I. S. Mamaev, "Rolling of a non-homogeneous ball over a sphere without slipping and
//! twisting", Regul. Chaotic Dyn. 12 (2007) 153; "Conservation laws, hierarchy of dynamics and
//! explicit integration of nonholonomic systems", Regul. Chaotic Dyn. 13 (2008) 443,
//! section 1.3, "A heavy body on the plane without slipping and spinning (rubber body)").
//!
//! # The reduced equations
//!
//! The state is the rolling law's `x = (gamma, M)`, `M = I_Q omega` the angular momentum about
//! the contact point (om-m). The no-twist constraint is kept by a reaction couple `lambda gamma`
//! about the normal at the contact point (the contact's friction torque), beside the reaction
//! force at the contact point, which has no moment about it. The rolling law's equations
//! (mg-eq) are the balance of the angular momentum about the contact point; the couple adds to
//! the torque:
//!
//! `M' = X_M(x) + lambda gamma`, `gamma' = gamma x omega`, `omega = I_Q^{-1} M`,
//!
//! with `X_M` the rolling field's `M'` ([`crate::field::vector_field`], not copied here). The
//! multiplier `lambda` is fixed by `d/dt (omega, gamma) = 0`. Since
//! `(omega, gamma') = (omega, gamma x omega) = 0`, this is `(gamma, omega') = 0`, with
//!
//! `omega' = d/dt (I_Q^{-1} M) = I_Q^{-1} (M' - I_Q' omega)`,
//!
//! `I_Q' omega = m (2 (r, r') omega - r' (r, omega) - r (r', omega))`, from
//! `I_Q = I + m (r^2 E - r r^T)` and `r' = R gamma'`; the last term vanishes,
//! `(r', omega) = R (gamma x omega, omega) = 0`. With `u = I_Q^{-1} gamma` (`I_Q` symmetric, so
//! `(gamma, I_Q^{-1} v) = (u, v)`) and `P = X_M - m R (2 (r, gamma') omega - (r, omega) gamma')`
//! (`I_Q` times the rolling law's `omega'`):
//!
//! `(u, P) + lambda (u, gamma) = 0`, `lambda = -(u, P) / (u, gamma)`
//!
//! ([`Rubber::multiplier`]); `(u, gamma) = (gamma, I_Q^{-1} gamma) > 0`, `I_Q` being positive
//! definite. Defined so on all of R^6, the field keeps `(omega, gamma)` constant everywhere,
//! not only at zero: `(omega, gamma)` is a first integral of the field, and the rubber ball's
//! phase space is its zero level (of dimension 5, with |gamma| = 1).
//!
//! # Integrals and measure (checked by its unit tests and the suite's `contact::rubber`)
//!
//! - The energy `H1 = (M, omega) + 2U` of the rolling law (int-g): its rate along the field is
//!   the rolling law's, zero, plus `lambda (gamma, dH1/dM) = 2 lambda (gamma, omega)`, zero on
//!   the constraint (the couple does no work).
//! - `H4 = (gamma, gamma)` and the constraint `(omega, gamma)`.
//! - `F = (M, M)(gamma, gamma) - (M, gamma)^2 + 2 m R (com, gamma) H1`
//!   ([`Rubber::horizontal_momentum`]; `(M, M) - (M, gamma)^2 = |gamma x M|^2` is the square of
//!   the horizontal part of M on |gamma| = 1). Along the field, on the constraint,
//!   `(M, gamma)' = lambda (gamma, gamma)` and `(M, M)' = 2 s (M, omega) - 2 m G (M, gamma x
//!   com) + 2 lambda (M, gamma)`, `s = -m R (gamma', com) = -m R d/dt (com, gamma)` (the
//!   identity of [`crate::field`]); the couple cancels, `(M, omega) = H1 - 2U`, and
//!   `F' = -4 s U - 2 m G (M, gamma x com)`: `F` is an integral when `G = 0` (any inertia, any centre
//!   of mass: the fourth integral of A. V. Bolsinov, A. V. Borisov, I. S. Mamaev, "Rolling of a
//!   ball without spinning on a plane: the absence of an invariant measure in a system with a
//!   complete set of integrals", Regul. Chaotic Dyn. 17 (2012) 571) and when `com = 0` (the
//!   rubber Chaplygin ball, where it is `|gamma x M|^2`) ([`Rubber::has_horizontal_momentum`]).
//! - The rolling law's Jellett H3, Routh's K and H2 are not integrals of the rubber ball: the
//!   couple enters `H3' = lambda (gamma, r)`, the height of the centre of mass times lambda.
//! - An invariant measure: for the rubber Chaplygin ball (`com = 0`) the density
//!   `rho = det(I_Q)^{-1/2} (gamma, I_Q^{-1} gamma)^{1/2}` in `(gamma, M)`
//!   ([`Rubber::density`]). With `D_perp = det(I_Q) (gamma, I_Q^{-1} gamma)`, the determinant
//!   of `I_Q` on the plane orthogonal to gamma (|gamma| = 1), it is `D_perp^{1/2} / det I_Q`;
//!   since `dM = det(I_Q) d omega`, the density is `D_perp^{1/2}` in `(gamma, omega)` on the
//!   constraint, and `D_perp^{-1/2}` in the momenta of the reduced Legendre transform
//!   (`d p = D_perp d omega_perp`): the determinant of the reduced Legendre transform to the
//!   power `p = (b/a - 1)/2 = -1/2` of Ehlers and Koiller for a ball on a plane (`a` infinite).
//!   `div(rho X) = 0` is checked by automatic differentiation, on the constraint (where it
//!   is the invariance of the measure `rho dx / d(omega, gamma)` of the phase space, since
//!   `(omega, gamma)` is an integral of the field on R^6). For a ball with its centre of mass
//!   off the centre there is none of the form `det(I_Q)^p (gamma, I_Q^{-1} gamma)^q` (the
//!   tests fit p and q); Bolsinov, Borisov and Mamaev prove there is none at all without
//!   gravity (the flow has limit cycles).
//!
//! Written once, generic over [`Scalar`]: `f64` for the steps, dual numbers for the checks,
//! the Taylor method's tape ([`OdeSystem::record`], interpreted: no generated kernels).

use crate::ball::{AsBall, Ball};
use crate::error::{Number, Result, RouthError};
use crate::field::{vector_field_in, OmegaForm};
use crate::integrals::{energy, geometric};
use crate::integrate::taylor::{Interpreted, Var};
use crate::integrate::{OdeSystem, OnSample, RunUnits};
use crate::scalar::{dot, split, Scalar};
use crate::simulate::{integrate_observed, Drift, Settings, Summary};
use crate::state::State;
use crate::units::{Dimension, Units};
use serde::Serialize;
use std::collections::BTreeMap;

/// The relative tolerance of the no-twist constraint at t = 0: a state is on it when
/// `|(omega, gamma)| <= TWIST_TOLERANCE |omega|` (scale-free: both sides are rates, so a case
/// in other units is accepted or refused alike). About 5000 ulp: an omega typed in a case file
/// or computed by a short formula orthogonal to gamma lands inside it.
pub const TWIST_TOLERANCE: f64 = 1e-12;

/// The rubber ball: a [`Ball`] rolling without slipping or twisting (the module's equations).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Rubber {
    ball: Ball,
}

impl Rubber {
    /// The ball `ball` with the rubber contact.
    pub fn new(ball: &impl AsBall) -> Self {
        Rubber { ball: ball.ball() }
    }

    /// The ball.
    pub fn ball(&self) -> Ball {
        self.ball
    }

    /// The field `x' = X(x)` of the module's equations, `omega` by cofactors
    /// ([`OmegaForm::Cofactors`]).
    #[inline(always)]
    pub fn field<D: Scalar>(&self, x: &[D; 6]) -> [D; 6] {
        self.field_in(OmegaForm::Cofactors, x)
    }

    /// [`Rubber::field`] with `omega` and `I_Q^{-1} gamma` in the form `form`.
    #[inline(always)]
    pub fn field_in<D: Scalar>(&self, form: OmegaForm, x: &[D; 6]) -> [D; 6] {
        let rolling = vector_field_in(form, &self.ball, x);
        let lambda = self.multiplier_of(form, x, &rolling);
        let gamma = [x[0], x[1], x[2]];
        std::array::from_fn(|i| match i {
            0..=2 => rolling[i],
            _ => lambda.mul_add(gamma[i - 3], rolling[i]),
        })
    }

    /// The multiplier `lambda = -(u, P) / (u, gamma)` of the couple `lambda gamma` that keeps
    /// `(omega, gamma)` constant (the module's formula).
    #[inline]
    pub fn multiplier<D: Scalar>(&self, x: &[D; 6]) -> D {
        let form = OmegaForm::Cofactors;
        self.multiplier_of(form, x, &vector_field_in(form, &self.ball, x))
    }

    /// [`Rubber::multiplier`] from the rolling field `rolling` at `x`.
    #[inline(always)]
    fn multiplier_of<D: Scalar>(&self, form: OmegaForm, x: &[D; 6], rolling: &[D; 6]) -> D {
        let ball = &self.ball;
        let (gamma, m_vec) = split(x);
        let omega = form.angular_velocity(ball, &gamma, &m_vec);
        let u = form.angular_velocity(ball, &gamma, &gamma);
        let gamma_dot = [rolling[0], rolling[1], rolling[2]];
        let r = ball.contact_vector(&gamma);
        let stretch = dot(&r, &gamma_dot) * 2.0;
        let reach = dot(&r, &omega);
        let mr = ball.m() * ball.radius();
        // P = X_M - I_Q' omega, I_Q' omega = m R (2 (r, gamma') omega - (r, omega) gamma').
        let p: [D; 3] = std::array::from_fn(|i| {
            rolling[3 + i] - (omega[i] * stretch - gamma_dot[i] * reach) * mr
        });
        -dot(&u, &p) / dot(&u, &gamma)
    }

    /// The twist `(omega, gamma)`, zero on the constraint.
    #[inline]
    pub fn twist<D: Scalar>(&self, x: &[D; 6]) -> D {
        let (gamma, m_vec) = split(x);
        dot(&self.ball.angular_velocity(&gamma, &m_vec), &gamma)
    }

    /// The twist relative to the rate of the motion, `|(omega, gamma)| / |omega|` (0 at rest):
    /// the residual of the constraint.
    pub fn relative_twist(&self, x: &[f64; 6]) -> f64 {
        let (gamma, m_vec) = split(x);
        let omega = self.ball.angular_velocity(&gamma, &m_vec);
        let twist = dot(&omega, &gamma);
        if twist == 0.0 {
            0.0
        } else {
            twist.abs() / dot(&omega, &omega).sqrt()
        }
    }

    /// `F = (M, M)(gamma, gamma) - (M, gamma)^2 + 2 m R (com, gamma) H1`, an integral when
    /// [`Rubber::has_horizontal_momentum`] (the module's derivation).
    #[inline]
    pub fn horizontal_momentum<D: Scalar>(&self, x: &[D; 6]) -> D {
        let ball = &self.ball;
        let (gamma, m_vec) = split(x);
        let along = dot(&m_vec, &gamma);
        let lever = dot(&gamma, &ball.com().map(crate::scalar::lift::<D>));
        dot(&m_vec, &m_vec) * geometric(x) - along * along
            + lever * energy(ball, x) * (2.0 * ball.m() * ball.radius())
    }

    /// Whether [`Rubber::horizontal_momentum`] is an integral: without gravity, or with the
    /// centre of mass at the geometric centre (within [`crate::ball::MODEL_TOLERANCE`]).
    pub fn has_horizontal_momentum(&self) -> bool {
        self.ball.gravity() == 0.0 || self.ball.is_chaplygin()
    }

    /// The density `det(I_Q)^{-1/2} (gamma, I_Q^{-1} gamma)^{1/2}` of the invariant measure of
    /// the rubber Chaplygin ball (`com = 0`), in `(gamma, M)`; not invariant when the centre of
    /// mass is off the centre (the module's documentation).
    #[inline]
    pub fn density<D: Scalar>(&self, x: &[D; 6]) -> D {
        let gamma = [x[0], x[1], x[2]];
        let u = self.ball.angular_velocity(&gamma, &gamma);
        (dot(&u, &gamma) / self.ball.inertia_determinant(&gamma)).sqrt()
    }

    /// The state `state` as the start of a run, if it satisfies the constraint:
    /// `|(omega, gamma)| <= TWIST_TOLERANCE |omega|` ([`TWIST_TOLERANCE`]); refused otherwise,
    /// never changed.
    pub fn start(&self, state: &State) -> Result<[f64; 6]> {
        let x = state.to_array();
        if !(self.relative_twist(&x) <= TWIST_TOLERANCE) {
            let omega = state.omega(&self.ball);
            return Err(RouthError::State(format!(
                "the rubber ball does not twist: omega . gamma = {} must be 0 (within {} of \
                 |omega| = {}; omega = {omega:?}, gamma = {:?})",
                Number(self.twist(&x)),
                Number(TWIST_TOLERANCE),
                Number(dot(&omega, &omega).sqrt()),
                state.gamma()
            )));
        }
        Ok(x)
    }
}

/// The reduced state of the rubber ball as an [`OdeSystem`]: its field, the tape of its field
/// with `omega` in the form for series (interpreted by the Taylor method), and the units of
/// the rolling law (gamma dimensionless, M in the motion's unit of angular momentum:
/// [`Units::of_reduced`]).
impl OdeSystem<6> for Rubber {
    type Kernels = Interpreted;

    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; 6]) -> [f64; 6] {
        self.field(y)
    }

    fn record(&self, _t: Var, y: &[Var; 6]) -> Option<[Var; 6]> {
        Some(self.field_in(OmegaForm::Determinant, y))
    }

    fn units(&self, y0: &[f64; 6]) -> RunUnits<6> {
        Units::of_reduced(&self.ball, y0)
    }
}

/// What a run of the rubber ball reports: the rolling law's summary, whose `integrals` are
/// those of the rubber ball (H1, H4 and, where it is one, F), and the residual of the
/// constraint.
#[derive(Debug, Clone, Serialize)]
pub struct RubberSummary {
    /// The run: method, steps, states, the drift of the rubber ball's integrals.
    #[serde(flatten)]
    pub run: Summary,
    /// `max |(omega, gamma)| / |omega|` over the step ends and samples.
    pub twist: f64,
}

/// The names of the rubber ball's columns of `routh simulate` (after the state and omega),
/// in the order of [`Rubber::columns`]: its integrals H1, H4 and F, the twist
/// `(omega, gamma)` and the multiplier lambda of the couple.
pub const COLUMN_NAMES: [&str; 5] = ["H1", "H4", "F", "twist", "couple"];

/// How many of [`COLUMN_NAMES`] are integrals (the first).
const INTEGRALS: usize = 3;

impl Rubber {
    /// The values of [`COLUMN_NAMES`] at `x`; F is `None` where it is not an integral
    /// ([`Rubber::has_horizontal_momentum`]).
    pub fn columns(&self, x: &[f64; 6]) -> [Option<f64>; 5] {
        [
            Some(energy(&self.ball, x)),
            Some(geometric(x)),
            self.has_horizontal_momentum()
                .then(|| self.horizontal_momentum(x)),
            Some(self.twist(x)),
            Some(self.multiplier(x)),
        ]
    }
}

/// The dimension of each integral of [`COLUMN_NAMES`] (H1 an energy, H4 a pure number, F a
/// squared momentum: `(M, M)` and `m R (com, gamma) H1` alike; proved by scaling in the tests).
const DIMENSIONS: [Dimension; INTEGRALS] = [
    Dimension::ENERGY,
    Dimension::NONE,
    Dimension::MOMENTUM_SQUARED,
];

/// The dimension of the integral `name` of [`COLUMN_NAMES`].
fn dimension(name: &str) -> Dimension {
    let at = COLUMN_NAMES[..INTEGRALS].iter().position(|&n| n == name);
    DIMENSIONS[at.expect("an integral of COLUMN_NAMES")]
}

/// The integrals of the rubber ball at `x`, by name.
fn integrals(model: &Rubber, x: &[f64; 6]) -> Vec<(&'static str, f64)> {
    COLUMN_NAMES
        .into_iter()
        .zip(model.columns(x))
        .take(INTEGRALS)
        .filter_map(|(name, value)| Some((name, value?)))
        .collect()
}

/// The drift of the rubber ball's integrals and the largest twist along a run.
struct Tracker {
    model: Rubber,
    drift: BTreeMap<&'static str, Drift>,
    twist: f64,
}

impl Tracker {
    fn new(model: &Rubber, x0: &[f64; 6]) -> Self {
        let units = Units::of_motion(&model.ball, x0);
        let drift = integrals(model, x0)
            .into_iter()
            .map(|(name, h)| {
                (
                    name,
                    Drift::start(h, || units.of_dimension(dimension(name))),
                )
            })
            .collect();
        Tracker {
            model: *model,
            drift,
            twist: model.relative_twist(x0),
        }
    }

    fn observe(&mut self, x: &[f64; 6]) {
        for (name, h) in integrals(&self.model, x) {
            let d = self.drift.get_mut(name).expect("tracked from the start");
            d.observe(h);
        }
        self.twist = self.twist.max(self.model.relative_twist(x));
    }
}

/// Integrate the rubber ball from `x0` ([`Rubber::start`]) with the method, tolerances,
/// samples, span and step limit of `settings`, through the rolling law's one loop
/// ([`integrate_observed`]: the one driver). Projection is refused (the level set it projects
/// onto is the rolling law's). `on_sample(t, x)` receives the samples; the integrals and the
/// twist are tracked at the samples and the step ends. A failure of the integrator is an
/// error.
pub fn run<E: From<RouthError>>(
    model: &Rubber,
    x0: [f64; 6],
    settings: &Settings,
    on_sample: &mut OnSample<'_, E, 6>,
) -> std::result::Result<RubberSummary, E> {
    if settings.project() {
        return Err(RouthError::Option {
            name: "project",
            value: "true".into(),
            rule: "is not available for the rubber ball (the projection is onto the rolling \
                   law's integrals H3, K, H1)",
        }
        .into());
    }
    let tracker = std::cell::RefCell::new(Tracker::new(model, &x0));
    let observed = integrate_observed(
        &model.ball,
        model,
        x0,
        settings,
        None,
        &mut |t, x| {
            tracker.borrow_mut().observe(x);
            on_sample(t, x)
        },
        &mut |stepper| tracker.borrow_mut().observe(stepper.y()),
    )?;
    let mut tracker = tracker.into_inner();
    tracker.observe(&observed.y);
    let mut run = observed.summary().map_err(E::from)?;
    run.integrals = tracker.drift;
    Ok(RubberSummary {
        run,
        twist: tracker.twist,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Body;
    use crate::differential::{lie_derivative, Dual6};
    use crate::integrals::{jellett, quadratic_integral, routh_integral};
    use crate::state::{Normalise, Point};

    /// The dimensions of the rubber ball's integrals (`DIMENSIONS`, in which their drift from
    /// zero is measured): each, divided by the unit of its dimension, is the integral of the
    /// dimensionless problem (`Units::ball`, `Units::point`) to 1e-13 relative (a few
    /// roundings; one wrong power would be off by a unit far from 1), F without gravity.
    #[test]
    fn the_integrals_have_their_dimensions() {
        let ball = Ball::new(2.0, 40.0, [1500.0, 1700.0, 2100.0], [3.0, 0.0, -12.0], 0.0).unwrap();
        for x in states(&ball) {
            let units = Units::of(&ball, &Point::from_array(&x).omega(&ball));
            let dimensionless = Rubber::new(&units.ball(&ball).unwrap());
            let y = units.point(&Point::from_array(&x)).to_array();
            let (h, h0) = (Rubber::new(&ball).columns(&x), dimensionless.columns(&y));
            for (i, name) in COLUMN_NAMES[..INTEGRALS].iter().enumerate() {
                let (h, h0) = (h[i].expect("an integral"), h0[i].expect("an integral"));
                let back = h0 * units.of_dimension(dimension(name));
                assert!((back - h).abs() <= 1e-13 * h.abs(), "{name}: {back} {h}");
            }
        }
    }

    /// Seven states on the constraint (|gamma| = 1, omega orthogonal to gamma), of tilts 0.3
    /// to 2.7 and azimuths around the axis, |omega| of 2 to 5.
    fn states(ball: &Ball) -> Vec<[f64; 6]> {
        (0..7)
            .map(|k| {
                let (tilt, azimuth) = (0.3 + 0.4 * k as f64, 1.1 * k as f64);
                let gamma = [
                    tilt.sin() * azimuth.cos(),
                    tilt.sin() * azimuth.sin(),
                    tilt.cos(),
                ];
                let w = [0.7 - 0.2 * k as f64, 1.3, 2.0 + 0.5 * k as f64];
                let along = dot(&w, &gamma);
                let omega = std::array::from_fn(|i| w[i] - along * gamma[i]);
                State::from_omega(ball, gamma, omega, Normalise::Reject)
                    .unwrap()
                    .to_array()
            })
            .collect()
    }

    /// The Routh sphere, the Chaplygin ball and a ball of no symmetry, with gravity and
    /// without.
    fn balls() -> [Ball; 6] {
        let routh = Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81)
            .unwrap()
            .ball();
        let chaplygin = Ball::new(1.0, 1.0, [0.3, 0.4, 0.5], [0.0; 3], 9.81).unwrap();
        let general = Ball::new(1.0, 1.0, [0.3, 0.4, 0.5], [0.05, -0.1, -0.2], 9.81).unwrap();
        [routh, chaplygin, general]
            .map(|b| [b, b.without_gravity()])
            .concat()
            .try_into()
            .unwrap()
    }

    /// The rate of `h` along the rubber field at `x`, by automatic differentiation of `h`.
    fn rate(model: &Rubber, h: impl Fn(&[Dual6; 6]) -> Dual6, x: &[f64; 6]) -> f64 {
        lie_derivative(h, &model.field(x), x)
    }

    /// The derivation checked by differentiating along the field it gives (independently of
    /// the formula for lambda): `(omega, gamma)`, H1 and H4 are constant at every state on the
    /// constraint of every ball, F where [`Rubber::has_horizontal_momentum`]. Tolerance 1e-12
    /// of each quantity's scale over the motion's time (its size times |omega|, here 2 to 5):
    /// the rates are sums of products of that size in f64, a few hundred ulp; measured below
    /// 1e-14. Negative controls, each derived in the module's documentation: F with gravity
    /// and the centre of mass off the centre, and the rolling law's H3, K and H2 on the Routh
    /// sphere, change at rates beyond 1e-6 of their scale (measured: 1e-4 to 1e1).
    #[test]
    fn the_field_keeps_the_twist_the_energy_and_f() {
        for ball in balls() {
            let model = Rubber::new(&ball);
            for x in states(&ball) {
                let omega = ball.angular_velocity(&[x[0], x[1], x[2]], &[x[3], x[4], x[5]]);
                let w = dot(&omega, &omega).sqrt();
                let h1 = energy(&ball, &x).abs();
                let f = model.horizontal_momentum(&x).abs() + h1;
                let checks = [
                    ("twist", rate(&model, |y| model.twist(y), &x), w * w),
                    ("H1", rate(&model, |y| energy(&ball, y), &x), h1 * w),
                    ("H4", rate(&model, geometric, &x), w),
                ];
                for (name, r, scale) in checks {
                    assert!(r.abs() <= 1e-12 * scale, "{name}' = {r:e} for {ball:?}");
                }
                let df = rate(&model, |y| model.horizontal_momentum(y), &x);
                if model.has_horizontal_momentum() {
                    assert!(df.abs() <= 1e-12 * f * w, "F' = {df:e} for {ball:?}");
                } else {
                    assert!(df.abs() > 1e-6 * f * w, "F' = {df:e} for {ball:?}");
                }
            }
        }
        let body = Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).unwrap();
        let model = Rubber::new(&body);
        let x = states(&body.ball())[2];
        for (name, r, scale) in [
            (
                "H3",
                rate(&model, |y| jellett(&body, y), &x),
                jellett(&body, &x),
            ),
            (
                "K",
                rate(&model, |y| routh_integral(&body, y), &x),
                routh_integral(&body, &x),
            ),
            (
                "H2",
                rate(&model, |y| quadratic_integral(&body, y), &x),
                quadratic_integral(&body, &x),
            ),
        ] {
            assert!(
                r.abs() > 1e-6 * scale.abs(),
                "{name}' = {r:e}: an integral?"
            );
        }
    }

    /// The multiplier is the couple the constraint needs: zero where the rolling ball keeps
    /// `(omega, gamma) = 0` by itself (the upright Routh sphere rolling straight, omega
    /// horizontal: the rolling law keeps omega there; measured 0 to round-off), not zero at a
    /// generic state of the constraint.
    #[test]
    fn the_couple_vanishes_where_rolling_needs_none() {
        let body = Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).unwrap();
        let model = Rubber::new(&body);
        let x = State::from_omega(&body, [0.0, 0.0, 1.0], [0.0, 3.0, 0.0], Normalise::Reject)
            .unwrap()
            .to_array();
        assert!(
            model.multiplier(&x).abs() <= 1e-15,
            "{:e}",
            model.multiplier(&x)
        );
        let x = states(&body.ball())[3];
        assert!(
            model.multiplier(&x).abs() > 1e-3,
            "{:e}",
            model.multiplier(&x)
        );
    }

    /// A state off the constraint is refused with the reason, never changed; one on it (to
    /// 1e-13 |omega|, inside [`TWIST_TOLERANCE`]) and the ball at rest are accepted as they
    /// are; the tolerance is scale-free (the same state with omega times 2^20 is refused
    /// alike).
    #[test]
    fn a_twisting_start_is_refused() {
        let body = Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).unwrap();
        let model = Rubber::new(&body);
        let gamma = [0.6, 0.0, 0.8];
        for scale in [1.0, 1048576.0] {
            let omega = [-0.8 * scale, 0.5 * scale, 0.6 * scale + 1e-9 * scale];
            let state = State::from_omega(&body, gamma, omega, Normalise::Reject).unwrap();
            let message = model.start(&state).unwrap_err().to_string();
            assert!(
                message.contains("the rubber ball does not twist: omega . gamma = ")
                    && message.contains("must be 0"),
                "{message}"
            );
            let omega = [-0.8 * scale, 0.5 * scale, 0.6 * scale + 1e-13 * scale];
            let state = State::from_omega(&body, gamma, omega, Normalise::Reject).unwrap();
            assert_eq!(model.start(&state).unwrap(), state.to_array());
        }
        let rest = State::new(gamma, [0.0; 3], Normalise::Reject).unwrap();
        assert_eq!(model.start(&rest).unwrap(), rest.to_array());
    }
}
