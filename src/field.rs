//! The vector field X of the reduced equations of motion (m-eq) and, with gravity, (mg-eq),
//! for the general unbalanced [`Ball`]:
//!
//! `dM/dt = M x omega + m dr/dt x (omega x r) + gamma x dU/dgamma`, `dgamma/dt = gamma x omega`,
//!
//! with `omega = I_Q^{-1} M` (om-m), `r = R gamma - com` (the paper's `R gamma + a e3`),
//! `dr/dt = R dgamma/dt` and `U = m G (r, gamma)` (the sign that pulls the ball toward the
//! plane; the paper prints `-m g (r, gamma)`, see [`Ball::potential`]). With `G = 0` this is
//! (m-eq). The rolling equations hold for any inertia and any offset of the centre of mass;
//! the paper writes them for the Routh sphere.
//!
//! Written once, generic over [`Scalar`]: the integrators call it with `f64`, the
//! [`crate::differential`] module with dual numbers for exact Jacobians and divergences.

use crate::ball::{AsBall, Ball};
use crate::scalar::{cross, lift, split, Scalar};

/// The field X(x) of (mg-eq) at `x = (gamma, M)`, for a [`Ball`] or a [`crate::Body`].
#[inline(always)]
pub fn vector_field<D: Scalar>(body: &impl AsBall, x: &[D; 6]) -> [D; 6] {
    ball_field(&body.ball(), x)
}

#[inline(always)]
fn ball_field<D: Scalar>(ball: &Ball, x: &[D; 6]) -> [D; 6] {
    let (gamma, m_vec) = split(x);
    let r = ball.contact_vector(&gamma);
    let omega = ball.angular_velocity(&gamma, &m_vec);
    let gamma_dot = cross(&gamma, &omega);
    let r_dot = gamma_dot.map(|c| c * ball.radius);
    let rolling = cross(&r_dot, &cross(&omega, &r));
    let gyroscopic = cross(&m_vec, &omega);
    let torque = cross(&gamma, &ball.potential_gradient(&gamma));
    [
        gamma_dot[0],
        gamma_dot[1],
        gamma_dot[2],
        rolling[0].mul_add(lift(ball.m), gyroscopic[0] + torque[0]),
        rolling[1].mul_add(lift(ball.m), gyroscopic[1] + torque[1]),
        rolling[2].mul_add(lift(ball.m), gyroscopic[2] + torque[2]),
    ]
}
