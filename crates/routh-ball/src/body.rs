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
use serde::Serialize;

/// Parameters of the ball: mass m, radius R, offset a of the centre of mass, principal
/// moments I1, I2, I3 about the centre of mass, gravitational acceleration G.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Body {
    /// Mass m > 0.
    pub m: f64,
    /// Radius R > 0.
    #[serde(rename = "R")]
    pub radius: f64,
    /// Signed distance a from the geometric centre to the centre of mass, |a| < R; the centre
    /// of mass is at `-a e3` from the geometric centre.
    pub a: f64,
    /// Principal moment I1 > 0.
    #[serde(rename = "I1")]
    pub i1: f64,
    /// Principal moment I2 > 0 (the Routh sphere has I2 = I1; a case file may omit it).
    #[serde(rename = "I2")]
    pub i2: f64,
    /// Principal moment I3 > 0 about the symmetry axis.
    #[serde(rename = "I3")]
    pub i3: f64,
    /// Gravitational acceleration G >= 0 (0: the free rolling of (m-eq)).
    #[serde(rename = "G")]
    pub gravity: f64,
}

impl Body {
    /// A validated body; see [`Body::validate`] for the rules.
    pub fn new(
        m: f64,
        radius: f64,
        a: f64,
        i1: f64,
        i2: f64,
        i3: f64,
        gravity: f64,
    ) -> Result<Self> {
        let body = Body {
            m,
            radius,
            a,
            i1,
            i2,
            i3,
            gravity,
        };
        body.validate()?;
        Ok(body)
    }

    /// Check the rules: all finite; m, R, I1, I2, I3 > 0; G >= 0; |a| < R; the triangle
    /// inequalities of principal moments (the rules of every ball,
    /// [`check_parameters`], with the offset a for the centre of mass).
    pub fn validate(&self) -> Result<()> {
        check_parameters(
            &[
                ("m", self.m),
                ("R", self.radius),
                ("a", self.a),
                ("I1", self.i1),
                ("I2", self.i2),
                ("I3", self.i3),
                ("G", self.gravity),
            ],
            &self.ball(),
            || {
                if self.a.abs() >= self.radius {
                    return Err(RouthError::Parameter {
                        name: "a",
                        value: self.a,
                        rule: "must satisfy |a| < R (the centre of mass lies inside the ball)",
                    });
                }
                Ok(())
            },
        )
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
                i1: self.i1,
                i2: self.i2,
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
    #[inline(always)]
    pub fn routh_g<D: Scalar>(&self, gamma: &[D; 3]) -> D {
        let horizontal = gamma[0] * gamma[0] + gamma[1] * gamma[1];
        let h = gamma[2] * self.radius + self.a;
        (horizontal * (self.i1 * self.m * self.radius * self.radius)
            + h * h * (self.i3 * self.m)
            + self.i1 * self.i3)
            .sqrt()
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
        Ball {
            m: self.m,
            radius: self.radius,
            inertia: [self.i1, self.i2, self.i3],
            com: [0.0, 0.0, -self.a],
            gravity: self.gravity,
        }
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
                com: self.com,
            });
        }
        let [i1, i2, i3] = self.inertia;
        Ok(Body {
            m: self.m,
            radius: self.radius,
            a: -self.com[2],
            i1,
            i2,
            i3,
            gravity: self.gravity,
        })
    }
}

impl Default for Body {
    /// The body of the built-in default case `cases/default.toml`.
    fn default() -> Self {
        Body {
            m: 1.0,
            radius: 1.0,
            a: 0.3,
            i1: 0.4,
            i2: 0.4,
            i3: 0.5,
            gravity: 9.81,
        }
    }
}
