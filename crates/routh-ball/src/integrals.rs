//! First integrals of (m-eq)/(mg-eq) and the densities of invariant measures.
//!
//! Every ball ([`Ball`]) has the energy H1 and H4 = (gamma, gamma); the Routh sphere
//! ([`Model::RouthSphere`]) adds Jellett's H3, Routh's K, H2 and the density 1/g of (rho); the
//! Chaplygin ball ([`Model::Chaplygin`]) adds (M, M), (M, gamma) and Chaplygin's density. All
//! are written once, generic over [`Scalar`], so their gradients come from automatic
//! differentiation of this same code (see [`crate::differential`]).

use crate::ball::{AsBall, Ball, Model};
use crate::body::Body;
use crate::scalar::{dot, split, Scalar};
use crate::units::Dimension;
use serde::Serialize;

/// Energy integral (int-g): `H1 = (M, omega) + 2U`, twice the total energy. With `G = 0`
/// it is the `H1 = (M, omega)` of (int).
#[inline]
pub fn energy<D: Scalar>(body: &impl AsBall, x: &[D; 6]) -> D {
    let ball = body.ball();
    let (gamma, m_vec) = split(x);
    energy_of(
        &ball,
        &gamma,
        &m_vec,
        &ball.angular_velocity(&gamma, &m_vec),
    )
}

/// [`energy`] at `(gamma, M)` whose angular velocity is `omega` (so that [`Integrals::at`]
/// solves (om-m) once for H1 and K).
#[inline(always)]
fn energy_of<D: Scalar>(ball: &Ball, gamma: &[D; 3], m_vec: &[D; 3], omega: &[D; 3]) -> D {
    dot(m_vec, omega) + ball.potential(gamma) * 2.0
}

/// Jellett's integral (int): `H3 = (M, r)`.
#[inline]
pub fn jellett<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    let (gamma, m_vec) = split(x);
    dot(&m_vec, &body.contact_vector(&gamma))
}

/// The geometric integral (int): `H4 = (gamma, gamma)`.
#[inline]
pub fn geometric<D: Scalar>(x: &[D; 6]) -> D {
    x[0] * x[0] + x[1] * x[1] + x[2] * x[2]
}

/// Routh's integral (raus-int): `K = g(gamma) omega3`, with g of (rho). An integral only
/// for the dynamically symmetric body I1 = I2.
#[inline]
pub fn routh_integral<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    let (gamma, m_vec) = split(x);
    routh_integral_of(body, &gamma, &body.angular_velocity(&gamma, &m_vec))
}

/// [`routh_integral`] at gamma with the angular velocity `omega`.
#[inline(always)]
fn routh_integral_of<D: Scalar>(body: &Body, gamma: &[D; 3], omega: &[D; 3]) -> D {
    body.routh_g(gamma) * omega[2]
}

/// The quadratic integral in the form printed after (raus-int),
/// `H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2`, valid with and without gravity (I1 = I2).
#[inline]
pub fn quadratic_integral<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    quadratic_of(
        body,
        energy(body, x),
        routh_integral(body, x),
        jellett(body, x),
    )
}

/// H2 of [`quadratic_integral`] from the values `h1`, `k` and `h3` of H1, K and H3 (so that
/// [`Integrals::at`] computes each once).
#[inline]
fn quadratic_of<D: Scalar>(body: &Body, h1: D, k: D, h3: D) -> D {
    h1 * body.i1() + k * k * ((body.i3() - body.i1()) / body.i1())
        - h3 * h3 * (body.m() / body.i1())
}

/// The quadratic integral in the form of (int), `H2 = (M, M) - m r^2 H1`, for the free
/// rolling (m-eq) (with `G = 0`, H1 = (M, omega)).
#[inline]
pub fn quadratic_integral_free<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    let (gamma, m_vec) = split(x);
    let r = body.contact_vector(&gamma);
    let omega = body.angular_velocity(&gamma, &m_vec);
    dot(&m_vec, &m_vec) - dot(&r, &r) * dot(&m_vec, &omega) * body.m()
}

/// Chaplygin's integral `(M, M)` of the ball with its centre of mass at the geometric centre
/// ([`Model::Chaplygin`]): with `r = R gamma`, the rolling term `m dr/dt x (omega x r)` of
/// (m-eq) is `-m R (dgamma/dt, com) omega` (the identity of [`crate::field`]), zero for
/// `com = 0`, and so is the torque of gravity: `dM/dt = M x omega`, orthogonal to M
/// (Chaplygin 1903; Borisov, Mamaev, Regul. Chaotic Dyn. 7 (2002), section 3.1).
#[inline]
pub fn momentum_squared<D: Scalar>(x: &[D; 6]) -> D {
    let (_, m_vec) = split(x);
    dot(&m_vec, &m_vec)
}

/// Chaplygin's area integral `(M, gamma)` of the Chaplygin ball (same references as
/// [`momentum_squared`]).
#[inline]
pub fn area_integral<D: Scalar>(x: &[D; 6]) -> D {
    let (gamma, m_vec) = split(x);
    dot(&m_vec, &gamma)
}

/// Density `det(I_Q)^{-1/2}` of the invariant measure of the Chaplygin ball, with I_Q of
/// (om-m): Chaplygin's density `(1 - D (gamma, A gamma))^{-1/2}`, `A = (I + D E)^{-1}`,
/// `D = m R^2` (Borisov, Mamaev, Regul. Chaotic Dyn. 7 (2002), section 3.1), times the
/// constant `det(I + D E)^{-1/2}` on `|gamma| = 1`, by the matrix determinant lemma. The
/// condition `div(rho X) = 0` is checked by automatic differentiation in the tests.
#[inline]
pub fn chaplygin_density<D: Scalar>(ball: &Ball, x: &[D; 6]) -> D {
    ball.inertia_determinant(&[x[0], x[1], x[2]]).sqrt().recip()
}

/// Density `1/g(gamma)` of the invariant measure (rho).
#[inline]
pub fn measure_density<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    body.routh_g(&[x[0], x[1], x[2]]).recip()
}

/// The integrals tracked along a trajectory; the first five in the order of the CSV columns.
///
/// Which are integrals is decided by [`Ball::model`]. For the Routh sphere (I1 = I2, centre of
/// mass on e3) H1, H2, H3, H4, K. For a body with I1 != I2 (the remark after (raus-int), after
/// \[bm02\]) Jellett's H3 and Routh's K are not; with the centre of mass on e3 the quadratic
/// integral survives without gravity in the form (int) `M^2 - m r^2 H1` (which equals the H2
/// of [`quadratic_integral`] when I1 = I2, claim `H2.relation` of the audit). The Chaplygin
/// ball has (M, M) and (M, gamma) instead (its H2 of (int) is `(M, M) - m R^2 H1`, not
/// tracked separately). Any other ball has only H1 and H4.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Integrals {
    /// Energy H1 (int-g).
    #[serde(rename = "H1")]
    pub h1: f64,
    /// Quadratic integral H2; `None` where there is none.
    #[serde(rename = "H2")]
    pub h2: Option<f64>,
    /// Jellett's H3; `None` unless the Routh sphere.
    #[serde(rename = "H3")]
    pub h3: Option<f64>,
    /// H4 = (gamma, gamma).
    #[serde(rename = "H4")]
    pub h4: f64,
    /// Routh's K = g omega3; `None` unless the Routh sphere.
    #[serde(rename = "K")]
    pub k: Option<f64>,
    /// (M, M) of the Chaplygin ball ([`momentum_squared`]); `None` for other balls.
    #[serde(rename = "MM", skip_serializing_if = "Option::is_none")]
    pub mm: Option<f64>,
    /// (M, gamma) of the Chaplygin ball ([`area_integral`]); `None` for other balls.
    #[serde(rename = "Mgamma", skip_serializing_if = "Option::is_none")]
    pub m_gamma: Option<f64>,
}

/// Names of the integrals written as CSV columns, in the order of [`Integrals::values`].
pub const INTEGRAL_NAMES: [&str; 5] = ["H1", "H2", "H3", "H4", "K"];

/// Names of all tracked integrals, in the order of [`Integrals::all`].
pub const ALL_INTEGRAL_NAMES: [&str; 7] = ["H1", "H2", "H3", "H4", "K", "MM", "Mgamma"];

/// The dimension of each of [`ALL_INTEGRAL_NAMES`]: the unit in which a drift from zero is
/// measured ([`crate::simulate::Drift`]; the dimensions proved by scaling in the tests).
pub const ALL_INTEGRAL_DIMENSIONS: [Dimension; 7] = [
    Dimension::ENERGY,
    Dimension::MOMENTUM_SQUARED,
    Dimension::MOMENTUM_LENGTH,
    Dimension::NONE,
    Dimension::MOMENTUM,
    Dimension::MOMENTUM_SQUARED,
    Dimension::MOMENTUM,
];

impl Integrals {
    /// Evaluate the integrals of the ball's model at `x`.
    pub fn at(body: &impl AsBall, x: &[f64; 6]) -> Self {
        let ball = body.ball();
        let model = ball.model();
        let routh = match model {
            Model::RouthSphere => ball.axial_body("Routh's integrals").ok(),
            _ => None,
        };
        let (gamma, m_vec) = split(x);
        let omega = ball.angular_velocity(&gamma, &m_vec);
        let h1 = energy_of(&ball, &gamma, &m_vec, &omega);
        let (h3, k) = match &routh {
            Some(body) => (
                Some(jellett(body, x)),
                Some(routh_integral_of(body, &gamma, &omega)),
            ),
            None => (None, None),
        };
        let h2 = match (&routh, k, h3) {
            (Some(body), Some(k), Some(h3)) => Some(quadratic_of(body, h1, k, h3)),
            _ if ball.gravity() == 0.0 && model == Model::General => ball
                .axial_body("the quadratic integral (int)")
                .ok()
                .map(|body| quadratic_integral_free(&body, x)),
            _ => None,
        };
        let chaplygin = model == Model::Chaplygin;
        Integrals {
            h1,
            h2,
            h3,
            h4: geometric(x),
            k,
            mm: chaplygin.then(|| momentum_squared(x)),
            m_gamma: chaplygin.then(|| area_integral(x)),
        }
    }

    /// The values of the CSV columns, in the order of [`INTEGRAL_NAMES`] (`None` where not an
    /// integral).
    pub fn values(&self) -> [Option<f64>; 5] {
        [Some(self.h1), self.h2, self.h3, Some(self.h4), self.k]
    }

    /// All values, in the order of [`ALL_INTEGRAL_NAMES`] (`None` where not an integral).
    pub fn all(&self) -> [Option<f64>; 7] {
        [
            Some(self.h1),
            self.h2,
            self.h3,
            Some(self.h4),
            self.k,
            self.mm,
            self.m_gamma,
        ]
    }
}
