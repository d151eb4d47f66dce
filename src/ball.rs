//! The general unbalanced ball: a ball of radius R rolling without slipping on a horizontal
//! plane, with any principal moments (I1, I2, I3) about its centre of mass and the centre of
//! mass anywhere inside it. This is layer 1 of the design: the model of a rolling ball, its
//! contact vector, its inertia about the contact point (om-m) and the potential of gravity.
//! The field of [`crate::field`] and the integrals H1, H4 of [`crate::integrals`] are written
//! for it; what holds only for special balls (the Routh sphere, the Chaplygin ball) is said by
//! [`Ball::model`].
//!
//! Conventions. The body frame is attached at the centre of mass along the principal axes.
//! `com` is the position of the centre of mass relative to the geometric centre, in the body
//! frame; the paper's Routh sphere has `com = (0, 0, -a)`. `gamma` is the unit normal of the
//! plane pointing into the plane, so the contact point is the geometric centre plus
//! `R gamma`, and the vector from the centre of mass to the contact point is
//! `r = R gamma - com` (the paper's `r = R gamma + a e3`). The height of the centre of mass
//! above the plane is `(r, gamma) = R - (com, gamma)` on `|gamma| = 1`.

use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::scalar::{dot, Scalar};
use serde::Serialize;

/// The relative tolerance that decides which model a ball is: two moments are equal when
/// `|I1 - I2| <= MODEL_TOLERANCE * max(I1, I2)`, a component of `com` vanishes when
/// `|com_i| <= MODEL_TOLERANCE * R`. About 5000 ulp: parameters typed in a case file or
/// computed by a short formula land inside it, a physically different body does not.
pub const MODEL_TOLERANCE: f64 = 1e-12;

/// Parameters of the general unbalanced ball.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Ball {
    /// Mass m > 0.
    pub m: f64,
    /// Radius R > 0.
    #[serde(rename = "R")]
    pub radius: f64,
    /// Principal moments (I1, I2, I3) about the centre of mass, each > 0, satisfying the
    /// triangle inequalities.
    #[serde(rename = "I")]
    pub inertia: [f64; 3],
    /// Position of the centre of mass relative to the geometric centre, body frame,
    /// `|com| < R`.
    pub com: [f64; 3],
    /// Gravitational acceleration G >= 0 (0: the free rolling of (m-eq)).
    #[serde(rename = "G")]
    pub gravity: f64,
}

/// Which integrable case a ball is, decided with [`MODEL_TOLERANCE`]; each states its
/// integrals (see [`crate::integrals::Integrals`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Model {
    /// The Routh sphere: I1 = I2 and the centre of mass on the symmetry axis e3. Integrals
    /// H1, H4, Jellett's H3, Routh's K, H2; invariant measure with density 1/g (rho). (With
    /// `com = 0` it is also a Chaplygin ball, and (M, M), (M, gamma) are integrals too.)
    RouthSphere,
    /// Chaplygin's ball: the centre of mass at the geometric centre, any I1, I2, I3.
    /// Integrals H1, H4, (M, M), (M, gamma); an invariant measure (Chaplygin 1903).
    Chaplygin,
    /// Any other ball: only the energy H1 and H4 = (gamma, gamma) are integrals; the motion
    /// is not integrable in general (Borisov, Mamaev, *Rolling of a rigid body on a plane
    /// and sphere. Hierarchy of dynamics*, Regul. Chaotic Dyn. 7 (2002), section 2).
    General,
}

/// Types that describe a rolling ball: [`Ball`] itself, and [`Body`] (the ball with its centre
/// of mass on the e3 axis, the parameters of the paper).
pub trait AsBall {
    /// The ball.
    fn ball(&self) -> Ball;
}

impl AsBall for Ball {
    #[inline(always)]
    fn ball(&self) -> Ball {
        *self
    }
}

impl<B: AsBall + ?Sized> AsBall for &B {
    #[inline(always)]
    fn ball(&self) -> Ball {
        (**self).ball()
    }
}

/// `|x| <= MODEL_TOLERANCE * scale`.
fn negligible(x: f64, scale: f64) -> bool {
    x.abs() <= MODEL_TOLERANCE * scale
}

impl Ball {
    /// A validated ball; see [`Ball::validate`].
    pub fn new(
        m: f64,
        radius: f64,
        inertia: [f64; 3],
        com: [f64; 3],
        gravity: f64,
    ) -> Result<Self> {
        let ball = Ball {
            m,
            radius,
            inertia,
            com,
            gravity,
        };
        ball.validate()?;
        Ok(ball)
    }

    /// Check the rules: all finite; m, R, I1, I2, I3 > 0; G >= 0; |com| < R; the triangle
    /// inequalities of principal moments (the same rules as [`Body::validate`], with com in
    /// place of a).
    pub fn validate(&self) -> Result<()> {
        for (i, c) in self.com.iter().enumerate() {
            if !c.is_finite() {
                return Err(RouthError::Parameter {
                    name: ["com[0]", "com[1]", "com[2]"][i],
                    value: *c,
                    rule: "must be finite",
                });
            }
        }
        let distance = dot(&self.com, &self.com).sqrt();
        if distance >= self.radius {
            return Err(RouthError::Parameter {
                name: "|com|",
                value: distance,
                rule: "must satisfy |com| < R (the centre of mass lies inside the ball)",
            });
        }
        let [i1, i2, i3] = self.inertia;
        Body {
            m: self.m,
            radius: self.radius,
            a: 0.0,
            i1,
            i2,
            i3,
            gravity: self.gravity,
        }
        .validate()
    }

    /// Which integrable case the ball is (decided with [`MODEL_TOLERANCE`]).
    pub fn model(&self) -> Model {
        let [i1, i2, _] = self.inertia;
        let axial = negligible(self.com[0], self.radius) && negligible(self.com[1], self.radius);
        if axial && negligible(i1 - i2, i1.max(i2)) {
            Model::RouthSphere
        } else if axial && negligible(self.com[2], self.radius) {
            Model::Chaplygin
        } else {
            Model::General
        }
    }

    /// Whether the centre of mass is at the geometric centre (within [`MODEL_TOLERANCE`]):
    /// then Chaplygin's integrals (M, M), (M, gamma) hold, whatever the moments.
    pub fn is_chaplygin(&self) -> bool {
        self.com.iter().all(|&c| negligible(c, self.radius))
    }

    /// Whether the centre of mass lies on the e3 axis (within [`MODEL_TOLERANCE`]).
    pub fn is_axial(&self) -> bool {
        negligible(self.com[0], self.radius) && negligible(self.com[1], self.radius)
    }

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

    /// The vector from the centre of mass to the contact point, `r = R gamma - com`.
    #[inline(always)]
    pub fn contact_vector<D: Scalar>(&self, gamma: &[D; 3]) -> [D; 3] {
        std::array::from_fn(|i| gamma[i] * self.radius - self.com[i])
    }

    /// Angular momentum about the contact point (om-m): `M = I_Q omega`,
    /// `I_Q = I + m r^2 E - m r (x) r`.
    #[inline(always)]
    pub fn angular_momentum<D: Scalar>(&self, gamma: &[D; 3], omega: &[D; 3]) -> [D; 3] {
        let r = self.contact_vector(gamma);
        let r2 = dot(&r, &r);
        let ro = dot(&r, omega);
        std::array::from_fn(|i| omega[i] * self.inertia[i] + (omega[i] * r2 - r[i] * ro) * self.m)
    }

    /// Angular velocity `omega = I_Q^{-1} M` of (om-m), in closed form with one division.
    ///
    /// `I_Q = A - m r r^T` is a diagonal `A = diag(A_1, A_2, A_3)`, `A_i = I_i + m r^2`,
    /// plus a rank-one term, for any `r` (any centre of mass). Sherman-Morrison gives
    /// `omega = A^{-1} M + m (A^{-1} r)(r, A^{-1} M) / (1 - m (r, A^{-1} r))`.
    /// Multiplying through by `det A = A_1 A_2 A_3` clears the three divisions by `A_i`:
    /// with the cofactors `B_i = det A / A_i` (`B_1 = A_2 A_3`, ...), `b = (B_i r_i)` and
    /// `c = (B_i M_i)`,
    ///
    /// `omega = (D c + m (r, c) b) / (D det A)`, `D = det A - m (r, b) = det I_Q`
    ///
    /// (the matrix determinant lemma). `D > 0` because each `m r_i^2 / A_i < r_i^2 / r^2`.
    /// About 45 floating-point operations and a single division, instead of a general 3x3
    /// solve or a division per `A_i` (BENCHMARKS.md). `D det A` is of the size of `A_i^6`:
    /// finite and normal for `A_i` between 1e-50 and 1e50. The form for numbers (`f64`, dual
    /// numbers, lanes); series take [`Ball::angular_velocity_by_quotients`].
    #[inline(always)]
    pub fn angular_velocity<D: Scalar>(&self, gamma: &[D; 3], m_vec: &[D; 3]) -> [D; 3] {
        let r = self.contact_vector(gamma);
        let mr2 = dot(&r, &r) * self.m;
        let a: [D; 3] = std::array::from_fn(|i| mr2 + self.inertia[i]);
        let cofactor = [a[1] * a[2], a[0] * a[2], a[0] * a[1]];
        let det_a = a[0] * cofactor[0];
        let b: [D; 3] = std::array::from_fn(|i| r[i] * cofactor[i]);
        let c: [D; 3] = std::array::from_fn(|i| m_vec[i] * cofactor[i]);
        let det_iq = det_a - dot(&r, &b) * self.m;
        let coupling = dot(&r, &c) * self.m;
        let scale = (det_iq * det_a).recip();
        std::array::from_fn(|i| c[i].mul_add(det_iq, b[i] * coupling) * scale)
    }

    /// The same `omega = I_Q^{-1} M` as [`Ball::angular_velocity`], by Sherman-Morrison with
    /// a quotient by each `A_i`:
    ///
    /// `omega_i = (M_i + q r_i) / A_i`, `q = m (r, A^{-1} M) / (1 - m (r, A^{-1} r))`
    ///
    /// (the denominator is `D / det A > 0`), where the two sums over `i` divide once per
    /// distinct `A_i`: `(r, A^{-1} M) = sum_G (sum_{i in G} r_i M_i) / A_G` over the groups `G`
    /// of equal moments of inertia (`I_1 = I_2` on the Routh sphere: `{1, 2}` and `{3}`), and
    /// `(r, A^{-1} r)` likewise with the squares `r_i^2`, whose sums also make `r^2`. The form
    /// for truncated power series (the Taylor method's tape), where a quotient costs one
    /// convolution, as a product does: 17 convolutions on the Routh sphere's tape (three
    /// squares, three products, eight quotients, three fused products) against 29 for the
    /// cofactors and 21 for the reciprocals `1 / A_i` times `r_i` and `M_i` (the form before,
    /// BENCHMARKS.md, "Omega by quotients"); the whole field's 32 against 44 and 36. In `f64` its
    /// divisions in a row cost more than the products they save, hence two forms
    /// ([`crate::field`]); they agree to round-off (`tests/field_identities.rs`). Each
    /// quotient is finite for `A_i` between 1e-300 and 1e300.
    #[inline(always)]
    pub fn angular_velocity_by_quotients<D: Scalar>(
        &self,
        gamma: &[D; 3],
        m_vec: &[D; 3],
    ) -> [D; 3] {
        let r = self.contact_vector(gamma);
        // The groups of equal moments: the first index of each, and each index's group.
        let first: [usize; 3] = std::array::from_fn(|i| {
            (0..i)
                .find(|&j| self.inertia[j] == self.inertia[i])
                .unwrap_or(i)
        });
        let in_group = |g: usize| (0..3).filter(move |&i| first[i] == g);
        // sum_{i in G} u_i v_i, one fused sum per group (`None` for an index that is not the
        // first of its group).
        let group_sums = |u: &[D; 3], v: &[D; 3]| -> [Option<D>; 3] {
            std::array::from_fn(|g| {
                in_group(g).fold(None, |acc: Option<D>, i| {
                    Some(match acc {
                        None => u[i] * v[i],
                        Some(a) => u[i].mul_add(v[i], a),
                    })
                })
            })
        };
        // The sum of the groups' terms (the group of index 0 is never empty).
        let total = |terms: [Option<D>; 3]| {
            terms
                .into_iter()
                .flatten()
                .reduce(|acc, v| acc + v)
                .expect("the group of the first index")
        };
        let squares = group_sums(&r, &r);
        let mr2 = total(squares) * self.m;
        let a: [D; 3] = std::array::from_fn(|i| mr2 + self.inertia[first[i]]);
        let over_a =
            |sums: [Option<D>; 3]| total(std::array::from_fn(|g| sums[g].map(|v| v / a[g])));
        let rar = over_a(squares);
        let ram = over_a(group_sums(&r, m_vec));
        let q = ram * self.m / (D::from_f64(1.0) - rar * self.m);
        std::array::from_fn(|i| r[i].mul_add(q, m_vec[i]) / a[i])
    }

    /// `det I_Q` of (om-m) (the `D` of [`Ball::angular_velocity`]).
    #[inline]
    pub fn inertia_determinant<D: Scalar>(&self, gamma: &[D; 3]) -> D {
        let r = self.contact_vector(gamma);
        let mr2 = dot(&r, &r) * self.m;
        let a: [D; 3] = std::array::from_fn(|i| mr2 + self.inertia[i]);
        let cofactor = [a[1] * a[2], a[0] * a[2], a[0] * a[1]];
        let b: [D; 3] = std::array::from_fn(|i| r[i] * cofactor[i]);
        a[0] * cofactor[0] - dot(&r, &b) * self.m
    }

    /// Potential energy of gravity `U = m G (r, gamma)`: m G times the height of the centre of
    /// mass above the plane. The paper prints `U = -m g (r, gamma)`; with gamma pointing into
    /// the plane, only the `+` sign pulls the ball toward the plane (see the README).
    #[inline(always)]
    pub fn potential<D: Scalar>(&self, gamma: &[D; 3]) -> D {
        let r = self.contact_vector(gamma);
        dot(&r, gamma) * (self.m * self.gravity)
    }

    /// `dU/dgamma = m G (2 R gamma - com)`, the gradient of [`Ball::potential`]
    /// (checked against automatic differentiation of `potential` in the tests).
    #[inline(always)]
    pub fn potential_gradient<D: Scalar>(&self, gamma: &[D; 3]) -> [D; 3] {
        let k = self.m * self.gravity;
        std::array::from_fn(|i| gamma[i] * (2.0 * self.radius * k) - self.com[i] * k)
    }
}
