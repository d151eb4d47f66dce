//! The vector field X of the reduced equations of motion (m-eq) and, with gravity, (mg-eq):
//!
//! `dM/dt = M x omega + m dr/dt x (omega x r) + gamma x dU/dgamma`, `dgamma/dt = gamma x omega`,
//!
//! with `omega = I_Q^{-1} M` (om-m), `r = R gamma + a e3`, `dr/dt = R dgamma/dt` and
//! `U = m G (r, gamma)` (the sign that pulls the ball toward the plane; the paper prints
//! `-m g (r, gamma)`, see [`Body::potential`]). With `G = 0` this is (m-eq).
//!
//! Written once, generic over [`Scalar`]: the integrators call it with `f64`, the
//! [`crate::differential`] module with dual numbers for exact Jacobians and divergences.

use crate::body::Body;
use crate::scalar::{cross, split, Scalar};

/// The field X(x) of (mg-eq) at `x = (gamma, M)`.
#[inline(always)]
pub fn vector_field<D: Scalar>(body: &Body, x: &[D; 6]) -> [D; 6] {
    let (gamma, m_vec) = split(x);
    let r = body.contact_vector(&gamma);
    let omega = body.angular_velocity(&gamma, &m_vec);
    let gamma_dot = cross(&gamma, &omega);
    let r_dot = gamma_dot.map(|c| c * body.radius);
    let rolling = cross(&r_dot, &cross(&omega, &r));
    let gyroscopic = cross(&m_vec, &omega);
    let torque = cross(&gamma, &body.potential_gradient(&gamma));
    [
        gamma_dot[0],
        gamma_dot[1],
        gamma_dot[2],
        gyroscopic[0] + rolling[0] * body.m + torque[0],
        gyroscopic[1] + rolling[1] * body.m + torque[1],
        gyroscopic[2] + rolling[2] * body.m + torque[2],
    ]
}
