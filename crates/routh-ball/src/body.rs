//! The ball with its centre of mass on the e3 axis, in the paper's parameters (m, R, a, I1,
//! I2, I3, G): a [`Ball`] with `com = (0, 0, -a)`, and Routh's function g of (rho), which
//! belongs to the Routh sphere I1 = I2.
//!
//! Conventions (the paper's variables, made explicit). The body frame is attached to the
//! ball at its centre of mass, its axes principal; e3 is the symmetry axis. `gamma` is the
//! unit normal of the plane *pointing from the ball's centre into the plane* (downwards), so
//! the contact point is the geometric centre plus `R gamma`. The vector from the centre of
//! mass to the contact point is `r = R gamma + a e3`, hence the centre of mass sits at
//! `-a e3` from the geometric centre: with `a > 0` it lies on the side of `-e3`, and the
//! height of the centre of mass above the plane is `(r, gamma) = R + a gamma3` on `|gamma| = 1`.

use crate::ball::{check_parameters, AsBall, Ball, Model};
use crate::error::{Result, RouthError};
use crate::scalar::Scalar;
use serde::ser::{Serialize, SerializeStruct, Serializer};

/// Parameters of the ball: mass m, radius R, offset a of the centre of mass, principal
/// moments I1, I2, I3 about the centre of mass, gravitational acceleration G. A view of the
/// [`Ball`] with `com = (0, 0, -a)`, which it holds (private: a value is built by
/// [`Body::new`], [`Ball::axial_body`] or [`Body::default`], so that every body satisfies the
/// rules); serialised and printed in the paper's parameters.
#[derive(Clone, Copy, PartialEq)]
pub struct Body {
    /// The ball, with its centre of mass at `(0, 0, -a)`.
    ball: Ball,
}

impl Body {
    /// A validated body: all finite; m, R, I1, I2, I3 > 0; G >= 0; |a| < R; the triangle
    /// inequalities of principal moments (the rules of every ball, `check_parameters`,
    /// with the offset a for the centre of mass). The error names the first rule broken, in
    /// that order.
    pub fn new(
        m: f64,
        radius: f64,
        a: f64,
        i1: f64,
        i2: f64,
        i3: f64,
        gravity: f64,
    ) -> Result<Self> {
        let inertia = [i1, i2, i3];
        check_parameters(
            &[
                ("m", m),
                ("R", radius),
                ("a", a),
                ("I1", i1),
                ("I2", i2),
                ("I3", i3),
                ("G", gravity),
            ],
            m,
            radius,
            inertia,
            gravity,
            || {
                if a.abs() >= radius {
                    return Err(RouthError::Parameter {
                        name: "a",
                        value: a,
                        rule: "must satisfy |a| < R (the centre of mass lies inside the ball)",
                    });
                }
                Ok(())
            },
        )?;
        Ok(Body {
            ball: Ball::new(m, radius, inertia, [0.0, 0.0, -a], gravity)?,
        })
    }

    /// Mass m > 0.
    #[inline]
    pub fn m(&self) -> f64 {
        self.ball.m()
    }

    /// Radius R > 0.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.ball.radius()
    }

    /// Signed distance a from the geometric centre to the centre of mass, |a| < R; the centre
    /// of mass is at `-a e3` from the geometric centre.
    #[inline]
    pub fn a(&self) -> f64 {
        -self.ball.com()[2]
    }

    /// Principal moment I1 > 0.
    #[inline]
    pub fn i1(&self) -> f64 {
        self.ball.inertia()[0]
    }

    /// Principal moment I2 > 0 (the Routh sphere has I2 = I1; a case file may omit it).
    #[inline]
    pub fn i2(&self) -> f64 {
        self.ball.inertia()[1]
    }

    /// Principal moment I3 > 0 about the symmetry axis.
    #[inline]
    pub fn i3(&self) -> f64 {
        self.ball.inertia()[2]
    }

    /// Gravitational acceleration G >= 0 (0: the free rolling of (m-eq)).
    #[inline]
    pub fn gravity(&self) -> f64 {
        self.ball.gravity()
    }

    /// The same body without gravity, G = 0: the free rolling of (m-eq)
    /// ([`Ball::without_gravity`]).
    pub fn without_gravity(&self) -> Body {
        Body {
            ball: self.ball.without_gravity(),
        }
    }

    /// Whether the body is dynamically symmetric, I1 = I2 within the relative tolerance
    /// [`MODEL_TOLERANCE`](crate::ball::MODEL_TOLERANCE): then it is the Routh sphere ([`Model::RouthSphere`]).
    pub fn is_symmetric(&self) -> bool {
        self.ball().model() == Model::RouthSphere
    }

    /// Fail with a clear message unless I1 = I2; `what` names the computation that needs it.
    pub fn require_symmetric(&self, what: &'static str) -> Result<()> {
        if self.is_symmetric() {
            Ok(())
        } else {
            Err(RouthError::NotSymmetric {
                what,
                i1: self.i1(),
                i2: self.i2(),
            })
        }
    }

    /// The vector from the centre of mass to the contact point, `r = (R gamma1, R gamma2, R gamma3 + a)`
    /// (the [`Ball::contact_vector`] of `com = (0, 0, -a)`).
    #[inline(always)]
    pub fn contact_vector<D: Scalar>(&self, gamma: &[D; 3]) -> [D; 3] {
        self.ball().contact_vector(gamma)
    }

    /// Angular momentum about the contact point (om-m), [`Ball::angular_momentum`].
    #[inline(always)]
    pub fn angular_momentum<D: Scalar>(&self, gamma: &[D; 3], omega: &[D; 3]) -> [D; 3] {
        self.ball().angular_momentum(gamma, omega)
    }

    /// Angular velocity `omega = I_Q^{-1} M` of (om-m), [`Ball::angular_velocity`].
    #[inline(always)]
    pub fn angular_velocity<D: Scalar>(&self, gamma: &[D; 3], m_vec: &[D; 3]) -> [D; 3] {
        self.ball().angular_velocity(gamma, m_vec)
    }

    /// Routh's function of (rho),
    /// `g(gamma) = sqrt(I1 I3 + I1 m R^2 (H4 - gamma3^2) + I3 m (R gamma3 + a)^2)`,
    /// with `H4 - gamma3^2` written as `gamma1^2 + gamma2^2` so that it also holds off the
    /// sphere, where its derivatives are taken. Defined with I1 (the Routh sphere has I1 = I2).
    ///
    /// `g^2` is of the size of an inertia squared: it is computed in the body's unit of inertia
    /// k ([`Ball::scaled_inertia`]), `g = k sqrt(g^2 / k^2)`, so that neither underflows nor
    /// overflows in any units (K = g omega3 of a body of mass 1e-300 was 0). k being a power
    /// of two, this is the unscaled formula's g to the bit wherever that one is normal.
    #[inline(always)]
    pub fn routh_g<D: Scalar>(&self, gamma: &[D; 3]) -> D {
        let scaled = self.ball.scaled_inertia();
        let horizontal = gamma[0] * gamma[0] + gamma[1] * gamma[1];
        let (m, radius) = (scaled.m, self.radius());
        let (i1, i3) = (scaled.inertia[0], scaled.inertia[2]);
        let h = gamma[2] * radius + self.a();
        (horizontal * (i1 * m * radius * radius) + h * h * (i3 * m) + i1 * i3).sqrt() * scaled.unit
    }

    /// Potential energy of gravity `U = m G (r, gamma)`, [`Ball::potential`].
    #[inline(always)]
    pub fn potential<D: Scalar>(&self, gamma: &[D; 3]) -> D {
        self.ball().potential(gamma)
    }

    /// `dU/dgamma = m G (2 R gamma + a e3)`, [`Ball::potential_gradient`].
    #[inline(always)]
    pub fn potential_gradient<D: Scalar>(&self, gamma: &[D; 3]) -> [D; 3] {
        self.ball().potential_gradient(gamma)
    }
}

impl AsBall for Body {
    /// The ball with `com = (0, 0, -a)`.
    #[inline(always)]
    fn ball(&self) -> Ball {
        self.ball
    }
}

/// The paper's keys `m`, `R`, `a`, `I1`, `I2`, `I3`, `G`.
impl Serialize for Body {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let mut s = serializer.serialize_struct("Body", 7)?;
        s.serialize_field("m", &self.m())?;
        s.serialize_field("R", &self.radius())?;
        s.serialize_field("a", &self.a())?;
        s.serialize_field("I1", &self.i1())?;
        s.serialize_field("I2", &self.i2())?;
        s.serialize_field("I3", &self.i3())?;
        s.serialize_field("G", &self.gravity())?;
        s.end()
    }
}

/// In the paper's parameters, named as the accessors.
impl std::fmt::Debug for Body {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Body")
            .field("m", &self.m())
            .field("radius", &self.radius())
            .field("a", &self.a())
            .field("i1", &self.i1())
            .field("i2", &self.i2())
            .field("i3", &self.i3())
            .field("gravity", &self.gravity())
            .finish()
    }
}

/// The view of a ball as a [`Body`]: the conversion lives here, so that [`Ball`] knows
/// nothing of the paper's parameters.
impl Ball {
    /// The ball as a [`Body`] (parameters of the paper, `a = -com3`), if its centre of mass
    /// lies on the e3 axis; `what` names the computation that needs it in the error.
    pub fn axial_body(&self, what: &'static str) -> Result<Body> {
        if !self.is_axial() {
            return Err(RouthError::OffAxis {
                what,
                com: self.com(),
            });
        }
        if self.com()[0] == 0.0 && self.com()[1] == 0.0 {
            // A valid ball with its centre of mass on e3 is a valid body as it is: the rules
            // are the same (`check_parameters`, with |a| = |com| < R), and validating them
            // again cost the sweep's drift tracking, which asks for the body at every step,
            // 5 % of its time.
            return Ok(Body { ball: *self });
        }
        let [i1, i2, i3] = self.inertia();
        Body::new(
            self.m(),
            self.radius(),
            -self.com()[2],
            i1,
            i2,
            i3,
            self.gravity(),
        )
    }
}

impl Default for Body {
    /// The body of the built-in default case `cases/default.toml`.
    fn default() -> Self {
        Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).expect("the default body satisfies the rules")
    }
}

#[cfg(test)]
mod tests {
    use super::Body;
    use crate::ball::{AsBall, Ball};

    /// Every way to a body keeps the rules: [`Body::new`] refuses each broken rule with its
    /// message (a NaN, a mass <= 0, G < 0, the centre of mass on or outside the sphere),
    /// [`Ball::axial_body`] a ball whose centre of mass is off the axis, and the body of a
    /// valid ball, the default and their views as a [`Ball`] are valid, with the parameters
    /// given, serialised under the paper's keys.
    #[test]
    fn a_body_exists_only_with_valid_parameters() {
        let refused = |m, a, gravity| {
            Body::new(m, 1.0, a, 0.4, 0.4, 0.5, gravity)
                .unwrap_err()
                .to_string()
        };
        let prefix = "invalid body parameter ";
        for (message, want) in [
            (refused(f64::NAN, 0.3, 9.81), "m = NaN: must be finite"),
            (refused(1.0, f64::NAN, 9.81), "a = NaN: must be finite"),
            (refused(1.0, 0.3, f64::INFINITY), "G = inf: must be finite"),
            (refused(-1.0, 0.3, 9.81), "m = -1: must be > 0"),
            (refused(1.0, 0.3, -9.81), "G = -9.81: must be >= 0"),
            (
                refused(1.0, -1.0, 9.81),
                "a = -1: must satisfy |a| < R (the centre of mass lies inside the ball)",
            ),
        ] {
            assert_eq!(message, format!("{prefix}{want}"));
        }
        let off_axis = Ball::new(1.0, 1.0, [0.4, 0.4, 0.5], [0.1, 0.0, -0.3], 9.81).unwrap();
        assert_eq!(
            off_axis.axial_body("the test").unwrap_err().to_string(),
            "the test needs the centre of mass on the e3 axis (com = (0, 0, -a)), but \
             com = [0.1, 0.0, -0.3]"
        );
        let ball = Ball::new(1.0, 1.0, [0.4, 0.4, 0.5], [0.0, 0.0, -0.3], 9.81).unwrap();
        let body = ball.axial_body("the test").unwrap();
        assert_eq!(body, Body::default());
        assert_eq!(body.ball(), ball);
        assert_eq!(
            (
                body.m(),
                body.radius(),
                body.a(),
                body.i1(),
                body.i2(),
                body.i3()
            ),
            (1.0, 1.0, 0.3, 0.4, 0.4, 0.5)
        );
        assert_eq!(body.gravity(), 9.81);
        assert_eq!(
            serde_json::to_string(&body).unwrap(),
            r#"{"m":1.0,"R":1.0,"a":0.3,"I1":0.4,"I2":0.4,"I3":0.5,"G":9.81}"#
        );
        assert_eq!(
            format!("{body:?}"),
            "Body { m: 1.0, radius: 1.0, a: 0.3, i1: 0.4, i2: 0.4, i3: 0.5, gravity: 9.81 }"
        );
    }
}
