//! The units of a problem: the radius R, the mass m and a time of the motion, in which a
//! computation that decides something (a threshold, a tolerance, the root of a polynomial) is
//! made dimensionless once, at its entry, so that the same motion written in other units gets
//! the same answer.
//!
//! The reduced equations (mg-eq) are covariant under the three scalings: lengths by `l`
//! (`R, a, com -> l R, ...`, `I -> l^2 I`, `G -> l G`, `M -> l^2 M`), masses by `k`
//! (`m, I, M -> k m, k I, k M`) and times by `s` (`t -> s t`, `omega -> omega / s`,
//! `G -> G / s^2`, `M -> M / s`). In the units `(R, m, T)` a ball has `R = 1`, moments
//! `I / (m R^2)`, offset `a / R` and gravity `G T^2 / R`; a state keeps gamma and has
//! `M T / (m R^2)`. The unit of mass is the body's mass m (then `m = 1` in these units), or
//! `I_max / R^2` when that is larger (a body with `I >> m R^2`: its moments, not its mass, set
//! the size of `I_Q` and of M, and with the unit m its dimensionless moments, up to 1e300 for
//! m = 1e-300, would overflow when multiplied); both scale as a mass, so the dimensionless
//! problem is unchanged by the scalings. The time T is that of the motion: the faster of the
//! fall, `sqrt(R / G)`, and the spin, `1 / |omega|`, so that both the dimensionless gravity
//! and the dimensionless spin are at most 1 and one of them is 1 (T = 1 for a ball at rest
//! without gravity, whose motion has no time).

use crate::ball::{AsBall, Ball};
use crate::body::Body;
use crate::error::Result;
use crate::integrate::RunUnits;
use crate::state::{Normalise, Point, State};

/// The units of length, mass and time of a problem (see the module's documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    length: f64,
    mass: f64,
    time: f64,
}

impl Units {
    /// The units of `ball` moving with angular velocity `omega`: R, m and
    /// `T = 1 / max(sqrt(G / R), |omega|)` (1 when both vanish).
    pub fn of(ball: &impl AsBall, omega: &[f64; 3]) -> Units {
        let ball = ball.ball();
        let spin = omega[0].hypot(omega[1]).hypot(omega[2]);
        Self::with_rate(&ball, spin)
    }

    /// The units of `ball` for a motion whose angular velocity is about `rate` (finite,
    /// at least 0): `T = 1 / max(sqrt(G / R), rate)` (1 when both vanish), the mass
    /// `max(m, I_max / R^2)`.
    pub fn with_rate(ball: &impl AsBall, rate: f64) -> Units {
        let ball = ball.ball();
        // Square roots taken apart, so that neither R / G nor G / R overflows.
        let fall = if ball.gravity() > 0.0 {
            ball.radius().sqrt() / ball.gravity().sqrt()
        } else {
            f64::INFINITY
        };
        let spin = if rate > 0.0 {
            1.0 / rate
        } else {
            f64::INFINITY
        };
        let time = fall.min(spin);
        let largest_moment = ball.inertia().iter().fold(0.0_f64, |a, &b| a.max(b));
        Units {
            length: ball.radius(),
            mass: ball.m().max(largest_moment / ball.radius() / ball.radius()),
            time: if time > 0.0 && time.is_finite() {
                time
            } else {
                1.0
            },
        }
    }

    /// These units rounded to the nearest powers of two: a problem converted to them holds the
    /// same significands with other exponents, so the conversion, and its way back, are exact
    /// (barring underflow and overflow), and a computation made in them gives, to the bit, what
    /// it gives in the problem's own units wherever it does not depend on the units: the same
    /// motion written in other units, where it did, gets the same answer, and nothing else
    /// changes. The scales of the problem are then within a factor sqrt(2) of 1 instead of 1.
    pub fn binary(&self) -> Units {
        let power = |x: f64| 2f64.powi(x.log2().round() as i32);
        Units {
            length: power(self.length),
            mass: power(self.mass),
            time: power(self.time),
        }
    }

    /// The unit of length, R.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// The unit of mass, `max(m, I_max / R^2)`.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The unit of time, T.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The unit of moments of inertia, `m R^2`.
    pub fn inertia(&self) -> f64 {
        self.mass * self.length * self.length
    }

    /// The unit of angular momentum, `m R^2 / T`.
    pub fn momentum(&self) -> f64 {
        self.inertia() / self.time
    }

    /// The unit of energy, `m R^2 / T^2`.
    pub fn energy(&self) -> f64 {
        self.momentum() / self.time
    }

    /// A moment of inertia in these units, `I / (m R^2)` (divided in turn, so that `m R^2`
    /// never overflows).
    fn moment(&self, i: f64) -> f64 {
        i / self.mass / self.length / self.length
    }

    /// A gravity in these units, `G T^2 / R`.
    fn gravity(&self, g: f64) -> f64 {
        g * self.time / self.length * self.time
    }

    /// A ball in these units (`R = m = 1` when the units are its own).
    pub fn ball(&self, ball: &Ball) -> Result<Ball> {
        let l = self.length;
        Ball::new(
            ball.m() / self.mass,
            ball.radius() / l,
            ball.inertia().map(|i| self.moment(i)),
            ball.com().map(|c| c / l),
            self.gravity(ball.gravity()),
        )
    }

    /// A Routh sphere in these units.
    pub fn body(&self, body: &Body) -> Result<Body> {
        Body::new(
            body.m() / self.mass,
            body.radius() / self.length,
            body.a() / self.length,
            self.moment(body.i1()),
            self.moment(body.i2()),
            self.moment(body.i3()),
            self.gravity(body.gravity()),
        )
    }

    /// A point in these units: gamma as it is, `M T / (m R^2)`.
    pub fn point(&self, point: &Point) -> Point {
        Point {
            gamma: point.gamma,
            m: point.m.map(|v| self.moment(v) * self.time),
        }
    }

    /// A state in these units ([`Units::point`]; an error only where M leaves f64's range).
    pub fn state(&self, state: &State) -> Result<State> {
        State::of_point(&self.point(&state.point()), Normalise::Reject)
    }

    /// The units of a run of `ball` from the reduced state `x = (gamma, M)`, in which an
    /// integrator measures its absolute tolerance and makes its first step
    /// ([`OdeSystem::units`]): the time T of the motion from `x`, 1 for gamma and the unit of
    /// angular momentum `m R^2 / T` for M, rounded to powers of two ([`Units::binary`]), so
    /// that the same motion written in other units is integrated with the same steps.
    ///
    /// [`OdeSystem::units`]: crate::integrate::OdeSystem::units
    pub fn of_reduced(ball: &impl AsBall, x: &[f64; 6]) -> RunUnits<6> {
        let units = Units::of_motion(ball, x);
        let p = units.momentum();
        RunUnits {
            time: units.time(),
            components: [1.0, 1.0, 1.0, p, p, p],
        }
    }

    /// The units of a motion of `ball` from the reduced state `x = (gamma, M)` ([`Units::of`]
    /// at its angular velocity), rounded to powers of two ([`Units::binary`]): those of its
    /// integration ([`Units::of_reduced`]) and of the drift of its integrals
    /// ([`crate::simulate::Drift`]).
    pub fn of_motion(ball: &impl AsBall, x: &[f64; 6]) -> Units {
        Units::of(ball, &Point::from_array(x).omega(ball)).binary()
    }

    /// A state of these units back in the problem's units ([`Units::point_back`]; an error
    /// only where M leaves f64's range).
    pub fn state_back(&self, state: &State) -> Result<State> {
        State::of_point(&self.point_back(&state.point()), Normalise::Reject)
    }

    /// A point of these units back in the problem's units: `M (m R^2 / T)`.
    pub fn point_back(&self, point: &Point) -> Point {
        let unit = self.momentum();
        Point {
            gamma: point.gamma,
            m: point.m.map(|v| v * unit),
        }
    }
}

/// The dimension of a quantity of the model: its powers of the unit of angular momentum
/// `m R^2 / T`, of the length R and of the time T (every quantity of the model is a product
/// of these: an energy is a momentum over a time). [`Units::of_dimension`] gives its unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Dimension {
    /// The power of the angular momentum `m R^2 / T`.
    pub momentum: i32,
    /// The power of the length R.
    pub length: i32,
    /// The power of the time T.
    pub time: i32,
}

impl Dimension {
    /// A pure number (gamma, H4).
    pub const NONE: Dimension = Dimension::new(0, 0, 0);
    /// An angular momentum (M, K = g omega3, (M, gamma)).
    pub const MOMENTUM: Dimension = Dimension::new(1, 0, 0);
    /// A squared angular momentum (H2, (M, M)).
    pub const MOMENTUM_SQUARED: Dimension = Dimension::new(2, 0, 0);
    /// An angular momentum times a length (Jellett's H3 = (M, r)).
    pub const MOMENTUM_LENGTH: Dimension = Dimension::new(1, 1, 0);
    /// An energy, a momentum over a time (H1 = (M, omega) + 2U).
    pub const ENERGY: Dimension = Dimension::new(1, 0, -1);

    const fn new(momentum: i32, length: i32, time: i32) -> Dimension {
        Dimension {
            momentum,
            length,
            time,
        }
    }
}

impl Units {
    /// The unit of a quantity of dimension `d` in these units.
    pub fn of_dimension(&self, d: Dimension) -> f64 {
        self.momentum().powi(d.momentum) * self.length.powi(d.length) * self.time.powi(d.time)
    }
}

/// `body` scaled in mass by `k`, in length by `l` and in time by `s` (the scalings of the
/// module docs): the same body in other units.
pub fn scaled_body(body: &Body, [k, l, s]: [f64; 3]) -> Result<Body> {
    Body::new(
        k * body.m(),
        l * body.radius(),
        l * body.a(),
        k * l * l * body.i1(),
        k * l * l * body.i2(),
        k * l * l * body.i3(),
        l / (s * s) * body.gravity(),
    )
}

/// `state` scaled in mass by `k`, in length by `l` and in time by `s`: gamma as it is,
/// `M -> k l^2 M / s`.
pub fn scaled_state(state: &State, factors: [f64; 3]) -> Result<State> {
    State::of_point(&scaled_point(&state.point(), factors), Normalise::Reject)
}

/// `point` scaled as [`scaled_state`] scales a state.
pub fn scaled_point(point: &Point, [k, l, s]: [f64; 3]) -> Point {
    Point {
        gamma: point.gamma,
        m: point.m.map(|v| k * l * l / s * v),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::vector_field;

    /// A Routh sphere and a state scaled in mass by `k`, length by `l` and time by `s`: the
    /// same motion in other units.
    fn scaled(body: &Body, state: &State, factors: [f64; 3]) -> (Body, State) {
        (
            scaled_body(body, factors).unwrap(),
            scaled_state(state, factors).unwrap(),
        )
    }

    fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
        a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= tol * y.abs().max(1.0))
    }

    /// The dimensions of the integrals (`ALL_INTEGRAL_DIMENSIONS`) are theirs: each integral of
    /// a ball in its problem's units, divided by the unit of its dimension, is the integral of
    /// the dimensionless problem (`Units::ball`, `Units::point`), to 1e-13 relative (a few
    /// roundings of each conversion, far below the factor of one wrong power: none of the
    /// units is near 1 here). Over a Routh sphere with and without gravity, a Chaplygin
    /// ball and an axial ball without gravity (H2 of (int)), every integral at least once.
    #[test]
    fn the_integrals_have_their_dimensions() {
        use crate::integrals::{Integrals, ALL_INTEGRAL_DIMENSIONS, ALL_INTEGRAL_NAMES};
        let routh = Body::new(2.0, 40.0, 12.0, 1700.0, 1700.0, 2100.0, 9.81).unwrap();
        let balls = [
            routh.ball(),
            routh.without_gravity().ball(),
            Ball::new(3.0, 0.05, [0.002, 0.003, 0.0045], [0.0; 3], 9.81).unwrap(),
            Ball::new(2.0, 40.0, [1700.0, 1700.0, 2100.0], [0.0, 0.0, -12.0], 0.0).unwrap(),
        ];
        let mut seen = [false; 7];
        for ball in &balls {
            let x = [0.6, 0.0, 0.8, 310.0, -70.0, 1900.0];
            let units = Units::of(ball, &Point::from_array(&x).omega(ball));
            let dimensionless = units.ball(ball).unwrap();
            let y = units.point(&Point::from_array(&x)).to_array();
            let (h, h0) = (
                Integrals::at(ball, &x).all(),
                Integrals::at(&dimensionless, &y).all(),
            );
            for i in 0..7 {
                let (Some(h), Some(h0)) = (h[i], h0[i]) else {
                    continue;
                };
                seen[i] = true;
                let back = h0 * units.of_dimension(ALL_INTEGRAL_DIMENSIONS[i]);
                let name = ALL_INTEGRAL_NAMES[i];
                assert!((back - h).abs() <= 1e-13 * h.abs(), "{name}: {back} {h}");
            }
        }
        assert_eq!(seen, [true; 7]);
    }

    /// Copies of one motion in units from 1e-30 to 1e30 have the same dimensionless body and
    /// state to a few ulp (each scaling is a handful of correctly rounded operations), and
    /// the dimensionless field (mg-eq) is the original one in units of 1 / T: the field is
    /// covariant, so a computation made at the entry in these units cannot see the units.
    #[test]
    fn copies_in_other_units_are_one_dimensionless_problem() {
        let body = Body::default();
        let state = State::from_omega(
            &body,
            [0.3_f64.sin(), 0.0, 0.3_f64.cos()],
            [0.5, 0.2, 8.0],
            crate::state::Normalise::Reject,
        )
        .unwrap();
        for gravity in [true, false] {
            let body = if gravity {
                body
            } else {
                body.without_gravity()
            };
            let units = Units::of(&body, &state.omega(&body));
            let (b0, x0) = (units.body(&body).unwrap(), units.state(&state).unwrap());
            assert_eq!((b0.m(), b0.radius()), (1.0, 1.0));
            let f0 = vector_field(&b0, &x0.to_array());
            let f = vector_field(&body, &state.to_array());
            let t = units.time();
            let back: Vec<f64> = (0..6)
                .map(|i| {
                    if i < 3 {
                        f0[i] / t
                    } else {
                        f0[i] * units.momentum() / t
                    }
                })
                .collect();
            assert!(close(&back, &f, 1e-13), "{back:?} {f:?}");
            for factors in [
                [1e12, 1.0, 1.0],
                [1e-30, 1e10, 1e-5],
                [1e30, 1e-8, 1e7],
                [3.0, 7.0, 0.1],
            ] {
                let (b, x) = scaled(&body, &state, factors);
                let u = Units::of(&b, &x.omega(&b));
                let (b1, x1) = (u.body(&b).unwrap(), u.state(&x).unwrap());
                let p = |b: &Body| {
                    [
                        b.m(),
                        b.radius(),
                        b.a(),
                        b.i1(),
                        b.i2(),
                        b.i3(),
                        b.gravity(),
                    ]
                };
                assert!(close(&p(&b1), &p(&b0), 1e-14), "{factors:?}: {b1:?} {b0:?}");
                assert!(close(&x1.to_array(), &x0.to_array(), 1e-14), "{factors:?}");
                assert!(close(
                    &u.state_back(&x1).unwrap().to_array(),
                    &x.to_array(),
                    1e-14
                ));
            }
        }
    }

    /// The units rounded to powers of two are within a factor sqrt(2) of the units, and a
    /// state converted to them and back is the state to the bit (the conversion only changes
    /// exponents), while the units themselves round M (negative control).
    #[test]
    fn binary_units_convert_exactly() {
        let body = Body::new(3e6, 0.7, 0.2, 0.3, 0.3, 0.45, 9.81).unwrap();
        let state = State::from_omega(
            &body,
            [0.6, 0.0, 0.8],
            [0.3, -0.7, 11.0],
            crate::state::Normalise::Reject,
        )
        .unwrap();
        let units = Units::of(&body, &state.omega(&body));
        let binary = units.binary();
        for (a, b) in [
            (units.length(), binary.length()),
            (units.mass(), binary.mass()),
            (units.time(), binary.time()),
        ] {
            assert_eq!(b, 2f64.powi(b.log2() as i32), "{b}");
            assert!((b / a).log2().abs() <= 0.5, "{a} {b}");
        }
        let there_and_back = |u: &Units| u.state_back(&u.state(&state).unwrap()).unwrap();
        assert_eq!(there_and_back(&binary), state);
        assert_ne!(there_and_back(&units), state);
    }

    /// A state whose M leaves f64's range in other units is refused, not made infinite: the
    /// default state scaled in mass by 1e300 and in time by 1e-10 (M x 1e310). Control: by
    /// 1e290 it is a state, M multiplied by the factor.
    #[test]
    fn a_state_out_of_range_in_other_units_is_refused() {
        let body = Body::default();
        let state = State::from_omega(
            &body,
            [0.6, 0.0, 0.8],
            [0.5, 0.2, 8.0],
            crate::state::Normalise::Reject,
        )
        .unwrap();
        let e = scaled_state(&state, [1e300, 1.0, 1e-10])
            .unwrap_err()
            .to_string();
        assert!(e.contains("non-finite"), "{e}");
        let fine = scaled_state(&state, [1e290, 1.0, 1e-10]).unwrap();
        assert_eq!(fine.gamma(), state.gamma());
        assert!((fine.m()[2] / state.m()[2] / 1e300 - 1.0).abs() < 1e-15);
    }

    /// The time unit is the faster of the fall and the spin, finite and positive for every
    /// valid body, including ones whose G / R overflows, and 1 for a ball at rest without
    /// gravity.
    #[test]
    fn the_time_unit_is_always_finite() {
        let body = Body::new(1.0, 1e-300, 0.0, 1e-301, 1e-301, 1e-301, 1e300).unwrap();
        let t = Units::with_rate(&body, 0.0).time();
        assert!(
            t > 0.0 && t.is_finite() && (t / 1e-300 - 1.0).abs() < 1e-15,
            "{t}"
        );
        assert_eq!(
            Units::with_rate(&Body::default().without_gravity(), 0.0).time(),
            1.0
        );
        assert_eq!(
            Units::with_rate(&Body::default().without_gravity(), 4.0).time(),
            0.25
        );
        let fall = (1.0_f64 / 9.81).sqrt();
        assert!((Units::with_rate(&Body::default(), 1.0).time() - fall).abs() < 1e-16);
    }
}
