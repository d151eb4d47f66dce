//! The rolling body: parameters, the contact vector r, the inertia tensor about the contact
//! point I_Q of (om-m), and Routh's function g of (rho).
//!
//! Conventions (the paper's variables, made explicit). The body frame is attached to the
//! ball at its centre of mass, its axes principal; e3 is the symmetry axis. `gamma` is the
//! unit normal of the plane *pointing from the ball's centre into the plane* (downwards), so
//! the contact point is the geometric centre plus `R gamma`. The vector from the centre of
//! mass to the contact point is `r = R gamma + a e3`, hence the centre of mass sits at
//! `-a e3` from the geometric centre: with `a > 0` it lies on the side of `-e3`, and the
//! height of the centre of mass above the plane is `(r, gamma) = R + a gamma3` on `|gamma| = 1`.

use crate::error::{Result, RouthError};
use crate::scalar::{dot, Scalar};
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
    /// inequalities of principal moments.
    pub fn validate(&self) -> Result<()> {
        let named = [
            ("m", self.m),
            ("R", self.radius),
            ("a", self.a),
            ("I1", self.i1),
            ("I2", self.i2),
            ("I3", self.i3),
            ("G", self.gravity),
        ];
        for (name, value) in named {
            if !value.is_finite() {
                return Err(RouthError::Parameter {
                    name,
                    value,
                    rule: "must be finite",
                });
            }
        }
        for (name, value) in [
            ("m", self.m),
            ("R", self.radius),
            ("I1", self.i1),
            ("I2", self.i2),
            ("I3", self.i3),
        ] {
            if value <= 0.0 {
                return Err(RouthError::Parameter {
                    name,
                    value,
                    rule: "must be > 0",
                });
            }
        }
        if self.gravity < 0.0 {
            return Err(RouthError::Parameter {
                name: "G",
                value: self.gravity,
                rule: "must be >= 0",
            });
        }
        if self.a.abs() >= self.radius {
            return Err(RouthError::Parameter {
                name: "a",
                value: self.a,
                rule: "must satisfy |a| < R (the centre of mass lies inside the ball)",
            });
        }
        let (i1, i2, i3) = (self.i1, self.i2, self.i3);
        for (ok, rule) in [
            (i1 + i2 >= i3, "I1 + I2 >= I3"),
            (i2 + i3 >= i1, "I2 + I3 >= I1"),
            (i3 + i1 >= i2, "I3 + I1 >= I2"),
        ] {
            if !ok {
                return Err(RouthError::Triangle { rule, i1, i2, i3 });
            }
        }
        Ok(())
    }

    /// Whether the body is dynamically symmetric, I1 = I2 (the Routh sphere).
    pub fn is_symmetric(&self) -> bool {
        self.i1 == self.i2
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

    /// The vector from the centre of mass to the contact point, `r = (R gamma1, R gamma2, R gamma3 + a)`.
    #[inline(always)]
    pub fn contact_vector<D: Scalar>(&self, gamma: &[D; 3]) -> [D; 3] {
        [
            gamma[0] * self.radius,
            gamma[1] * self.radius,
            gamma[2] * self.radius + self.a,
        ]
    }

    /// Angular momentum about the contact point (om-m): `M = I_Q omega`,
    /// `I_Q = I + m r^2 E - m r (x) r`.
    #[inline(always)]
    pub fn angular_momentum<D: Scalar>(&self, gamma: &[D; 3], omega: &[D; 3]) -> [D; 3] {
        let r = self.contact_vector(gamma);
        let r2 = dot(&r, &r);
        let ro = dot(&r, omega);
        let inertia = [self.i1, self.i2, self.i3];
        std::array::from_fn(|i| omega[i] * inertia[i] + (omega[i] * r2 - r[i] * ro) * self.m)
    }

    /// Angular velocity `omega = I_Q^{-1} M` of (om-m), in closed form with one division.
    ///
    /// `I_Q = A - m r r^T` with the diagonal `A = diag(A_1, A_2, A_3)`, `A_i = I_i + m r^2`.
    /// Sherman-Morrison gives
    /// `omega = A^{-1} M + m (A^{-1} r)(r, A^{-1} M) / (1 - m (r, A^{-1} r))`.
    /// Multiplying through by `det A = A_1 A_2 A_3` clears the three divisions by `A_i`:
    /// with the cofactors `B_i = det A / A_i` (`B_1 = A_2 A_3`, ...), `b = (B_i r_i)` and
    /// `c = (B_i M_i)`,
    ///
    /// `omega = (D c + m (r, c) b) / (D det A)`, `D = det A - m (r, b) = det I_Q`
    ///
    /// (the matrix determinant lemma). `D > 0` because each `m r_i^2 / A_i < r_i^2 / r^2`.
    /// About 45 floating-point operations and a single division, instead of a general 3x3
    /// solve or a division per `A_i` (16 ns instead of 18 for the whole field, BENCHMARKS.md).
    /// `D det A` is of the size of `A_i^6`: finite and normal for `A_i` between 1e-50 and 1e50.
    #[inline(always)]
    pub fn angular_velocity<D: Scalar>(&self, gamma: &[D; 3], m_vec: &[D; 3]) -> [D; 3] {
        let r = self.contact_vector(gamma);
        let mr2 = dot(&r, &r) * self.m;
        let a = [mr2 + self.i1, mr2 + self.i2, mr2 + self.i3];
        let cofactor = [a[1] * a[2], a[0] * a[2], a[0] * a[1]];
        let det_a = a[0] * cofactor[0];
        let b: [D; 3] = std::array::from_fn(|i| r[i] * cofactor[i]);
        let c: [D; 3] = std::array::from_fn(|i| m_vec[i] * cofactor[i]);
        let det_iq = det_a - dot(&r, &b) * self.m;
        let coupling = dot(&r, &c) * self.m;
        let scale = (det_iq * det_a).recip();
        std::array::from_fn(|i| (c[i] * det_iq + b[i] * coupling) * scale)
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

    /// Potential energy of gravity `U = m G (r, gamma)`: m G times the height of the centre of
    /// mass above the plane. The paper prints `U = -m g (r, gamma)`; with gamma pointing into
    /// the plane, only the `+` sign pulls the ball toward the plane (see the README).
    #[inline(always)]
    pub fn potential<D: Scalar>(&self, gamma: &[D; 3]) -> D {
        let r = self.contact_vector(gamma);
        dot(&r, gamma) * (self.m * self.gravity)
    }

    /// `dU/dgamma = m G (2 R gamma + a e3)`, the gradient of [`Body::potential`]
    /// (checked against automatic differentiation of `potential` in the tests).
    #[inline(always)]
    pub fn potential_gradient<D: Scalar>(&self, gamma: &[D; 3]) -> [D; 3] {
        let k = self.m * self.gravity;
        [
            gamma[0] * (2.0 * self.radius * k),
            gamma[1] * (2.0 * self.radius * k),
            gamma[2] * (2.0 * self.radius * k) + self.a * k,
        ]
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
