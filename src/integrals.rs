//! First integrals of (m-eq)/(mg-eq) and the density of the invariant measure (rho).
//!
//! All are written once, generic over [`Scalar`], so their gradients come from automatic
//! differentiation of this same code (see [`crate::differential`]).

use crate::body::Body;
use crate::scalar::{dot, split, Scalar};
use serde::Serialize;

/// Energy integral (int-g): `H1 = (M, omega) + 2U`, twice the total energy. With `G = 0`
/// it is the `H1 = (M, omega)` of (int).
#[inline]
pub fn energy<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    let (gamma, m_vec) = split(x);
    let omega = body.angular_velocity(&gamma, &m_vec);
    dot(&m_vec, &omega) + body.potential(&gamma) * 2.0
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
    body.routh_g(&gamma) * body.angular_velocity(&gamma, &m_vec)[2]
}

/// The quadratic integral in the form printed after (raus-int),
/// `H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2`, valid with and without gravity (I1 = I2).
#[inline]
pub fn quadratic_integral<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    let k = routh_integral(body, x);
    let h3 = jellett(body, x);
    energy(body, x) * body.i1 + k * k * ((body.i3 - body.i1) / body.i1)
        - h3 * h3 * (body.m / body.i1)
}

/// The quadratic integral in the form of (int), `H2 = (M, M) - m r^2 H1`, for the free
/// rolling (m-eq) (with `G = 0`, H1 = (M, omega)).
#[inline]
pub fn quadratic_integral_free<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    let (gamma, m_vec) = split(x);
    let r = body.contact_vector(&gamma);
    let omega = body.angular_velocity(&gamma, &m_vec);
    dot(&m_vec, &m_vec) - dot(&r, &r) * dot(&m_vec, &omega) * body.m
}

/// Density `1/g(gamma)` of the invariant measure (rho).
#[inline]
pub fn measure_density<D: Scalar>(body: &Body, x: &[D; 6]) -> D {
    body.routh_g(&[x[0], x[1], x[2]]).recip()
}

/// The integrals tracked along a trajectory, in the order of the CSV columns.
///
/// For the Routh sphere (I1 = I2) all five are integrals. For a body with I1 != I2 (the
/// remark after (raus-int), after [bm02]) Jellett's H3 and Routh's K are not; the quadratic
/// integral survives without gravity in the form (int) `M^2 - m r^2 H1` (which equals the
/// H2 of [`quadratic_integral`] when I1 = I2, claim `H2.relation` of the audit).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Integrals {
    /// Energy H1 (int-g).
    #[serde(rename = "H1")]
    pub h1: f64,
    /// Quadratic integral H2; `None` for I1 != I2 with gravity, where there is none.
    #[serde(rename = "H2")]
    pub h2: Option<f64>,
    /// Jellett's H3; `None` for I1 != I2, where it is not an integral.
    #[serde(rename = "H3")]
    pub h3: Option<f64>,
    /// H4 = (gamma, gamma).
    #[serde(rename = "H4")]
    pub h4: f64,
    /// Routh's K = g omega3; `None` for I1 != I2, where it is not an integral.
    #[serde(rename = "K")]
    pub k: Option<f64>,
}

/// Names of the tracked integrals, in the order of [`Integrals::values`].
pub const INTEGRAL_NAMES: [&str; 5] = ["H1", "H2", "H3", "H4", "K"];

impl Integrals {
    /// Evaluate all tracked integrals at `x`.
    pub fn at(body: &Body, x: &[f64; 6]) -> Self {
        let symmetric = body.is_symmetric();
        let h2 = if symmetric {
            Some(quadratic_integral(body, x))
        } else {
            (body.gravity == 0.0).then(|| quadratic_integral_free(body, x))
        };
        Integrals {
            h1: energy(body, x),
            h2,
            h3: symmetric.then(|| jellett(body, x)),
            h4: geometric(x),
            k: symmetric.then(|| routh_integral(body, x)),
        }
    }

    /// The values in the order of [`INTEGRAL_NAMES`] (`None` where not an integral).
    pub fn values(&self) -> [Option<f64>; 5] {
        [Some(self.h1), self.h2, self.h3, Some(self.h4), self.k]
    }
}
