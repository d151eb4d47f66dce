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

use crate::error::{Result, RouthError};
use crate::scalar::{dot, Scalar};
use serde::Serialize;

/// The relative tolerance that decides which model a ball is: two moments are equal when
/// `|I1 - I2| <= MODEL_TOLERANCE * max(I1, I2)`, a component of `com` vanishes when
/// `|com_i| <= MODEL_TOLERANCE * R`. About 5000 ulp: parameters typed in a case file or
/// computed by a short formula land inside it, a physically different body does not.
pub const MODEL_TOLERANCE: f64 = 1e-12;

/// Parameters of the general unbalanced ball. The fields are private: a value is built by
/// [`Ball::new`] (or [`Ball::without_gravity`] of a valid ball), so that every ball satisfies
/// the rules.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Ball {
    /// Mass m > 0.
    m: f64,
    /// Radius R > 0.
    #[serde(rename = "R")]
    radius: f64,
    /// Principal moments (I1, I2, I3) about the centre of mass, each > 0, satisfying the
    /// triangle inequalities.
    #[serde(rename = "I")]
    inertia: [f64; 3],
    /// Position of the centre of mass relative to the geometric centre, body frame,
    /// `|com| < R`.
    com: [f64; 3],
    /// Gravitational acceleration G >= 0 (0: the free rolling of (m-eq)).
    #[serde(rename = "G")]
    gravity: f64,
    /// The body's unit of inertia k, a power of two ([`Ball::inertia_unit`]), in which
    /// `I_Q^{-1}` is computed; a function of the other fields, made once by [`Ball::new`].
    #[serde(skip)]
    unit: f64,
}

/// The parameters of `I_Q` in the body's unit of inertia k ([`Ball::scaled_inertia`]):
/// `m / k`, `I / k` and `1 / k`, exact (k is a power of two).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScaledInertia {
    /// `m / k`.
    pub m: f64,
    /// `(I1, I2, I3) / k`.
    pub inertia: [f64; 3],
    /// `1 / k`, by which M is multiplied to be in the same unit.
    pub per_unit: f64,
    /// k.
    pub unit: f64,
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

/// Types that describe a rolling ball: [`Ball`] itself, and the views of a ball in other
/// parameters (the Routh sphere's, in [`crate::body`]).
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

/// The elementary symmetric polynomial `e_k` of `values` (`e_0 = 1`, and 0 for `k` beyond their
/// number), by the recurrence `e_j(v_1 .. v_i) = e_j(v_1 .. v_{i-1}) + v_i e_{j-1}(v_1 .. v_{i-1})`.
fn elementary_symmetric(values: &[f64], k: usize) -> f64 {
    let mut e = vec![0.0; k + 1];
    e[0] = 1.0;
    for &v in values {
        for j in (1..=k).rev() {
            e[j] += v * e[j - 1];
        }
    }
    e[k]
}

/// `|x| <= MODEL_TOLERANCE * scale`.
fn negligible(x: f64, scale: f64) -> bool {
    x.abs() <= MODEL_TOLERANCE * scale
}

/// The rules of every ball's parameters, in the order in which a violation is reported:
/// the `named` values finite; m, R, I1, I2, I3 > 0; G >= 0; `centre` (the rule of where the
/// centre of mass lies, in the parameters of the caller); the triangle inequalities of the
/// principal moments.
pub(crate) fn check_parameters(
    named: &[(&'static str, f64)],
    m: f64,
    radius: f64,
    inertia: [f64; 3],
    gravity: f64,
    centre: impl FnOnce() -> Result<()>,
) -> Result<()> {
    for &(name, value) in named {
        if !value.is_finite() {
            return Err(RouthError::Parameter {
                name,
                value,
                rule: "must be finite",
            });
        }
    }
    let [i1, i2, i3] = inertia;
    for (name, value) in [("m", m), ("R", radius), ("I1", i1), ("I2", i2), ("I3", i3)] {
        if value <= 0.0 {
            return Err(RouthError::Parameter {
                name,
                value,
                rule: "must be > 0",
            });
        }
    }
    if gravity < 0.0 {
        return Err(RouthError::Parameter {
            name: "G",
            value: gravity,
            rule: "must be >= 0",
        });
    }
    centre()?;
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

impl Ball {
    /// A validated ball: com finite and |com| < R; then the rules of every ball
    /// (`check_parameters`): m, R, I1, I2, I3, G finite; m, R, I1, I2, I3 > 0; G >= 0; the
    /// triangle inequalities of principal moments. The error names the first rule broken, in
    /// that order.
    pub fn new(
        m: f64,
        radius: f64,
        inertia: [f64; 3],
        com: [f64; 3],
        gravity: f64,
    ) -> Result<Self> {
        let mut ball = Ball {
            m,
            radius,
            inertia,
            com,
            gravity,
            unit: 1.0,
        };
        ball.validate()?;
        ball.unit = ball.unit_of_inertia()?;
        Ok(ball)
    }

    /// The body's unit of inertia, `max(m R^2, I_max)` (the unit of [`crate::units::Units`]:
    /// `max(m, I_max / R^2) R^2`) rounded to the nearest power of two k, from the logarithms
    /// so that `m R^2` never overflows. Every `A_i = I_i + m r^2` is within a few factors of 2
    /// of it at the top (`r <= 2 R`) and at most [`crate::range::MAX_CONDITION`] times larger
    /// than the smallest moment, so the products of up to six `A_i / k` in the inverse of
    /// `I_Q / k` are finite and normal for every body whose condition number is accepted,
    /// whatever its units. Refused only when k itself is not a normal f64 (the scale of the
    /// inertia beyond 2^1023 or below 2^-1022: not a body's inertia that f64 can hold).
    fn unit_of_inertia(&self) -> Result<f64> {
        let largest_moment = self.inertia.iter().fold(0.0_f64, |a, &b| a.max(b));
        let exponent = (self.m.log2() + 2.0 * self.radius.log2())
            .max(largest_moment.log2())
            .round();
        if !(f64::MIN_EXP as f64 - 1.0..f64::MAX_EXP as f64).contains(&exponent) {
            return Err(RouthError::Overflow {
                cause: format!(
                    "m = {:?}, R = {:?}, I = {:?}",
                    self.m, self.radius, self.inertia
                ),
                quantity: "the body's unit of inertia max(m R^2, I_max) (a normal f64, \
                           2^-1022 to 2^1023, in which the inertia about the contact point is \
                           inverted),",
                direction: if exponent > 0.0 {
                    "overflow"
                } else {
                    "underflow"
                },
                value: 2f64.powf(exponent),
            });
        }
        Ok(2f64.powi(exponent as i32))
    }

    /// The body's unit of inertia k: `max(m R^2, I_max)` rounded to the nearest power of two
    /// (1 for the default body). `omega = I_Q^{-1} M` is computed as `(I_Q / k)^{-1} (M / k)`
    /// ([`Ball::angular_velocity`], [`Ball::angular_velocity_by_determinant`]), so that its
    /// intermediates (up to the sixth power of the inertia) have the size of the body's
    /// dimensionless inertia, not of its units.
    #[inline]
    pub fn inertia_unit(&self) -> f64 {
        self.unit
    }

    /// The parameters of `I_Q = I + m (r^2 - r r^T)` in the unit k ([`Ball::inertia_unit`]):
    /// `m / k`, `I / k`, `1 / k`. The one place where the scaling is made: every closed form
    /// of `I_Q^{-1}` takes its parameters from here. k being a power of two, each is exact
    /// (barring subnormals), and so is every product and sum of the closed forms made of them:
    /// each intermediate is the one of the unscaled formula times a power of two, and omega,
    /// of degree 0 in k, is the unscaled formula's to the bit wherever neither overflows nor
    /// underflows (`tests/suite/model.rs`, `omega_in_the_unit_of_inertia_is_the_old_formula_to_the_bit`).
    #[inline(always)]
    pub fn scaled_inertia(&self) -> ScaledInertia {
        self.inertia_in(self.unit)
    }

    /// The parameters of `I_Q` in the unit of inertia `unit` (a power of two, for the
    /// division to be exact): [`Ball::scaled_inertia`] in another unit. In the unit 1 the
    /// closed forms of `I_Q^{-1}` are, operation for operation, those in the problem's units
    /// (each product by 1 is exact): the formula before the body's unit, kept for the tests
    /// that compare with it.
    #[inline(always)]
    pub fn inertia_in(&self, unit: f64) -> ScaledInertia {
        let per_unit = unit.recip();
        ScaledInertia {
            m: self.m * per_unit,
            inertia: self.inertia.map(|i| i * per_unit),
            per_unit,
            unit,
        }
    }

    /// Check the rules of [`Ball::new`] on the parameters it is building.
    fn validate(&self) -> Result<()> {
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
        check_parameters(
            &[
                ("m", self.m),
                ("R", self.radius),
                ("I1", i1),
                ("I2", i2),
                ("I3", i3),
                ("G", self.gravity),
            ],
            self.m,
            self.radius,
            self.inertia,
            self.gravity,
            || Ok(()),
        )
    }

    /// Mass m > 0.
    #[inline]
    pub fn m(&self) -> f64 {
        self.m
    }

    /// Radius R > 0.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Principal moments (I1, I2, I3) about the centre of mass, each > 0, satisfying the
    /// triangle inequalities.
    #[inline]
    pub fn inertia(&self) -> [f64; 3] {
        self.inertia
    }

    /// Position of the centre of mass relative to the geometric centre, body frame,
    /// `|com| < R`.
    #[inline]
    pub fn com(&self) -> [f64; 3] {
        self.com
    }

    /// Gravitational acceleration G >= 0 (0: the free rolling of (m-eq)).
    #[inline]
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// The same ball without gravity, G = 0: the free rolling of (m-eq). Valid as the ball
    /// is: G = 0 keeps G >= 0, and no other rule involves G.
    pub fn without_gravity(&self) -> Ball {
        Ball {
            gravity: 0.0,
            ..*self
        }
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
    /// solve or a division per `A_i` (BENCHMARKS.md). The form for numbers (`f64`, dual
    /// numbers, lanes); series take [`Ball::angular_velocity_by_determinant`].
    ///
    /// `D det A` is of the size of `A_i^6`, finite and normal in f64 only for `A_i` between
    /// 1e-51 and 5e51: the inverse is taken of `I_Q / k` in the body's unit of inertia k
    /// ([`Ball::scaled_inertia`]), where the `A_i / k` are within [`crate::range::MAX_CONDITION`]
    /// of 1, so that a body in any units is inverted as its copy with `m R^2 = 1` is.
    /// `omega = (I_Q / k)^{-1} (M / k)`, with the factor `1 / k` of M folded into the one
    /// division (`M` times the cofactors of `A / k` over `D det A / k^6` times k: one product
    /// instead of three); every step is the unscaled one's times a power of two, so omega is
    /// the unscaled formula's to the bit for a body where that one is finite and normal.
    #[inline(always)]
    pub fn angular_velocity<D: Scalar>(&self, gamma: &[D; 3], m_vec: &[D; 3]) -> [D; 3] {
        self.angular_velocity_in(&self.scaled_inertia(), gamma, m_vec)
    }

    /// [`Ball::angular_velocity`] with the inertia in the unit of `scaled`
    /// ([`Ball::inertia_in`]).
    #[inline(always)]
    pub fn angular_velocity_in<D: Scalar>(
        &self,
        scaled: &ScaledInertia,
        gamma: &[D; 3],
        m_vec: &[D; 3],
    ) -> [D; 3] {
        let r = self.contact_vector(gamma);
        let mr2 = dot(&r, &r) * scaled.m;
        let a: [D; 3] = std::array::from_fn(|i| mr2 + scaled.inertia[i]);
        let cofactor = [a[1] * a[2], a[0] * a[2], a[0] * a[1]];
        let det_a = a[0] * cofactor[0];
        let b: [D; 3] = std::array::from_fn(|i| r[i] * cofactor[i]);
        let c: [D; 3] = std::array::from_fn(|i| m_vec[i] * cofactor[i]);
        let det_iq = det_a - dot(&r, &b) * scaled.m;
        let coupling = dot(&r, &c) * scaled.m;
        let scale = (det_iq * det_a * scaled.unit).recip();
        std::array::from_fn(|i| c[i].mul_add(det_iq, b[i] * coupling) * scale)
    }

    /// The same `omega = I_Q^{-1} M` as [`Ball::angular_velocity`], by Sherman-Morrison with
    /// the coupling cleared of its denominators:
    ///
    /// `omega_i = (M_i + q r_i) / A_i`, `q = m (r, A^{-1} M) / (1 - m (r, A^{-1} r)) = N / D`,
    ///
    /// `A_i = I_i + rho`, `rho = m r^2`, both parts of `q` multiplied by `prod_G A_G` over the
    /// groups `G` of equal moments (`I_1 = I_2` on the Routh sphere: `{1, 2}` and `{3}`, so
    /// `n = 2` groups). With `x_G = m sum_{i in G} r_i^2` (so `rho = sum_G x_G`),
    /// `t_G = sum_{i in G} r_i M_i` and `e_k(I_{-G})` the elementary symmetric polynomials of
    /// the other groups' moments:
    ///
    /// `N = m sum_{j=0}^{n-1} rho^j sum_G t_G e_{n-1-j}(I_{-G})`,
    /// `D = e_n(I) + sum_{j=0}^{n-2} rho^j sum_G x_G I_G e_{n-2-j}(I_{-G})`
    ///
    /// (the top power `rho^n` of `prod_G A_G` cancels against `sum_G x_G prod_{H != G} A_H`,
    /// and the rest of that sum against the lower powers: `D = det I_Q / prod_G A_G^(|G| - 1)`,
    /// a sum of positive terms, so no cancellation; for the Routh sphere
    /// `D = I_1 I_3 + x_1 I_1 + x_3 I_3`, for a ball of one moment `D = I`). Both are
    /// polynomials in `rho` evaluated by Horner, with coefficients that are sums of `x_G` and
    /// `t_G` by constants: on a truncated power series (the Taylor method's tape, where a
    /// product or a quotient of two series costs one convolution and a product by a constant
    /// none) `n - 1` products for `N`, `max(n - 2, 0)` for `D`, one quotient for `q`, and per
    /// component one product and one quotient: on the Routh sphere's tape 14 products and
    /// quotients of series in 12 convolutions (`r_1^2 + r_2^2` and `r_1 M_1 + r_2 M_2` fused
    /// in pairs), against 17 in 15 for the quotients of `(r, A^{-1} r)` and `(r, A^{-1} M)` by
    /// each group's `A_G` (the form before, docs/benchmarks-history.md, "Omega by the determinant"). In `f64` its
    /// divisions cost more than the cofactors' one, hence two forms ([`crate::field`]); they
    /// agree to round-off (`tests/field_identities.rs`).
    ///
    /// Computed, as [`Ball::angular_velocity`], in the body's unit of inertia k
    /// ([`Ball::scaled_inertia`]): `omega = (I_Q / k)^{-1} (M / k)`, with m, the moments and M
    /// divided by k (`N`, of degree `n + 1` in the inertia, would overflow for `A_i` beyond
    /// 1e77 otherwise). Exact in powers of two: the series are the unscaled formula's to the
    /// bit; for k = 1 (the default body) the products by `1 / k` are folded away on the tape.
    #[inline(always)]
    pub fn angular_velocity_by_determinant<D: Scalar>(
        &self,
        gamma: &[D; 3],
        m_vec: &[D; 3],
    ) -> [D; 3] {
        self.angular_velocity_by_determinant_in(&self.scaled_inertia(), gamma, m_vec)
    }

    /// [`Ball::angular_velocity_by_determinant`] with the inertia in the unit of `scaled`
    /// ([`Ball::inertia_in`]).
    #[inline(always)]
    pub fn angular_velocity_by_determinant_in<D: Scalar>(
        &self,
        scaled: &ScaledInertia,
        gamma: &[D; 3],
        m_vec: &[D; 3],
    ) -> [D; 3] {
        let ScaledInertia {
            m: mass,
            inertia,
            per_unit,
            ..
        } = *scaled;
        let m_vec: [D; 3] = std::array::from_fn(|i| m_vec[i] * per_unit);
        let m_vec = &m_vec;
        let r = self.contact_vector(gamma);
        // The groups of equal moments, by their first index.
        let first: [usize; 3] =
            std::array::from_fn(|i| (0..i).find(|&j| inertia[j] == inertia[i]).unwrap_or(i));
        let groups: Vec<usize> = (0..3).filter(|&g| first[g] == g).collect();
        let n = groups.len();
        // sum_{i in G} u_i v_i, fused.
        let group_sum = |g: usize, u: &[D; 3], v: &[D; 3]| {
            (0..3)
                .filter(|&i| first[i] == g)
                .fold(None, |acc: Option<D>, i| {
                    Some(match acc {
                        None => u[i] * v[i],
                        Some(a) => u[i].mul_add(v[i], a),
                    })
                })
                .expect("a group has its first index")
        };
        let x: Vec<D> = groups
            .iter()
            .map(|&g| group_sum(g, &r, &r) * mass)
            .collect();
        let t: Vec<D> = groups.iter().map(|&g| group_sum(g, &r, m_vec)).collect();
        let rho = x[1..].iter().fold(x[0], |acc, &v| acc + v);
        // The moment of each group, and e_k of those of the groups other than the one at `skip`.
        let moments: Vec<f64> = groups.iter().map(|&g| inertia[g]).collect();
        let e = |k: usize, skip: usize| -> f64 {
            let others: Vec<f64> = (0..n).filter(|&h| h != skip).map(|h| moments[h]).collect();
            elementary_symmetric(&others, k)
        };
        // sum_G w_G c_G, the sum of series by constants (plain products: no convolution).
        let combine = |w: &[D], c: &dyn Fn(usize) -> f64| {
            (1..n).fold(w[0] * c(0), |acc, g| acc + w[g] * c(g))
        };
        // Horner in rho over the coefficients 0 ..= top.
        let horner = |top: usize, coefficient: &dyn Fn(usize) -> D| {
            (0..top)
                .rev()
                .fold(coefficient(top), |acc, j| acc.mul_add(rho, coefficient(j)))
        };
        let numerator = horner(n - 1, &|j| combine(&t, &|g| e(n - 1 - j, g))) * mass;
        let constant = D::from_f64(elementary_symmetric(&moments, n));
        let denominator = if n < 2 {
            constant
        } else {
            horner(n - 2, &|j| combine(&x, &|g| moments[g] * e(n - 2 - j, g))) + constant
        };
        let q = numerator / denominator;
        std::array::from_fn(|i| r[i].mul_add(q, m_vec[i]) / (rho + inertia[first[i]]))
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

#[cfg(test)]
mod tests {
    use super::{elementary_symmetric, Ball};

    /// [`Ball::new`], the one way to a ball, refuses every broken rule with its message, the
    /// first in the order of the rules (a NaN anywhere, a mass <= 0, the centre of mass on or
    /// outside the sphere, G < 0, a triangle inequality), and keeps the parameters of a valid
    /// ball, serialised under the keys m, R, I, com, G.
    #[test]
    fn a_ball_exists_only_with_valid_parameters() {
        let (i, com) = ([0.4, 0.4, 0.5], [0.0, 0.0, -0.3]);
        let refused = |m, inertia, com, gravity| {
            Ball::new(m, 1.0, inertia, com, gravity)
                .unwrap_err()
                .to_string()
        };
        let prefix = "invalid body parameter ";
        for (message, want) in [
            (refused(f64::NAN, i, com, 9.81), "m = NaN: must be finite"),
            (
                refused(1.0, [0.4, f64::NAN, 0.5], com, 9.81),
                "I2 = NaN: must be finite",
            ),
            (
                refused(1.0, i, [0.0, f64::NAN, 0.0], 9.81),
                "com[1] = NaN: must be finite",
            ),
            (refused(1.0, i, com, f64::NAN), "G = NaN: must be finite"),
            (refused(-1.0, i, com, 9.81), "m = -1: must be > 0"),
            (refused(0.0, i, com, 9.81), "m = 0: must be > 0"),
            (refused(1.0, i, com, -9.81), "G = -9.81: must be >= 0"),
            (
                refused(-1.0, i, [0.0, 0.0, -1.5], 9.81),
                "|com| = 1.5: must satisfy |com| < R (the centre of mass lies inside the ball)",
            ),
            (
                refused(1.0, i, [0.0, 1.0, 0.0], 9.81),
                "|com| = 1: must satisfy |com| < R (the centre of mass lies inside the ball)",
            ),
        ] {
            assert_eq!(message, format!("{prefix}{want}"));
        }
        assert_eq!(
            refused(1.0, [0.1, 0.1, 0.5], com, 9.81),
            "principal moments of inertia violate the triangle inequality I1 + I2 >= I3: \
             I1 = 0.1, I2 = 0.1, I3 = 0.5"
        );
        let ball = Ball::new(1.0, 1.0, i, com, 9.81).unwrap();
        assert_eq!(
            (
                ball.m(),
                ball.radius(),
                ball.inertia(),
                ball.com(),
                ball.gravity()
            ),
            (1.0, 1.0, i, com, 9.81)
        );
        assert_eq!(
            serde_json::to_string(&ball).unwrap(),
            r#"{"m":1.0,"R":1.0,"I":[0.4,0.4,0.5],"com":[0.0,0.0,-0.3],"G":9.81}"#
        );
    }

    /// `e_k` against the sums of products written out: exact in binary (small integers), so
    /// tolerance zero; `e_0 = 1` and `e_k = 0` beyond the number of values.
    #[test]
    fn elementary_symmetric_polynomials_are_the_sums_of_products() {
        let v = [2.0, 3.0, 5.0];
        let want = [
            1.0,
            2.0 + 3.0 + 5.0,
            2.0 * 3.0 + 2.0 * 5.0 + 3.0 * 5.0,
            30.0,
            0.0,
        ];
        for (k, w) in want.into_iter().enumerate() {
            assert_eq!(elementary_symmetric(&v, k), w, "e_{k}");
        }
        assert_eq!(elementary_symmetric(&[], 0), 1.0);
        assert_eq!(elementary_symmetric(&[7.0], 1), 7.0);
    }
}
