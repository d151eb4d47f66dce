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
//! [`crate::differential`] module with dual numbers for exact Jacobians and divergences, the
//! Taylor method with its tape-recording scalar, the batched lanes with SIMD lanes.
//!
//! # The field by exact identities
//!
//! [`vector_field`] computes the right-hand side of (mg-eq) in a shorter but identical form,
//!
//! `dM/dt = M x omega - m R (dgamma/dt, com) omega - m G gamma x com`,
//!
//! by two identities of vector algebra:
//! 1. `a x (b x c) = b (a, c) - c (a, b)` with `a = R dgamma/dt`, `b = omega`, `c = r`, and
//!    `(dgamma/dt, omega) = (gamma x omega, omega) = 0`, `(dgamma/dt, gamma) = 0`: the rolling
//!    term is `m R (dgamma/dt, r) omega = -m R (dgamma/dt, com) omega`, a scalar times omega;
//! 2. `dU/dgamma = m G (2 R gamma - com)` and `gamma x gamma = 0`: the torque is
//!    `gamma x dU/dgamma = -m G gamma x com`, linear in gamma.
//!
//! Both are identities of polynomials in `(gamma, omega)` (no use of `|gamma| = 1` or of any
//! integral), and `omega` is the same function of `x` in both forms, so the two forms are the
//! same function on all of R^6, not only on the physical sphere `|gamma| = 1`: the Jacobians,
//! the divergence and the Poisson checks that automatic differentiation takes of this code
//! are those of (mg-eq) as the paper writes it. In floating point the two forms differ by
//! round-off only (`tests/field_identities.rs` compares them, values and dual-number
//! Jacobians). The short form has fewer operations: the Taylor method's tape of the default
//! case has 42 instead of 56, 32 instead of 40 of them products (its steps 16 % cheaper); in
//! the `f64` code the latency is unchanged (docs/benchmarks-history.md, "The field by exact identities").
//!
//! # Omega in two forms
//!
//! `omega = I_Q^{-1} M` has two closed forms ([`OmegaForm`]), the same function: by cofactors
//! with one division ([`Ball::angular_velocity`], for numbers: `f64`, dual numbers, lanes) and
//! by the coupling `q = N / D` of Sherman-Morrison as two polynomials in `m r^2` and a quotient
//! by each `I_i + m r^2` ([`Ball::angular_velocity_by_determinant`], for the Taylor method's
//! tape, where a quotient of series costs one convolution as a product does). The tape of the
//! default case then has 29 convolutions instead of 44 (docs/benchmarks-history.md, "Omega by quotients"
//! and "Omega by the determinant"; DOP853 keeps the cofactors, with which it is 12 % faster one
//! run at a time: "Omega by reciprocals"). The two agree to round-off, values and Jacobians
//! (`tests/field_identities.rs`); each integrator's numbers are those of its own form, bit for
//! bit across lanes and threads.

use crate::ball::{AsBall, Ball};
use crate::scalar::{cross, lift, split, Scalar};

/// The field X(x) of (mg-eq) at `x = (gamma, M)`, for a [`Ball`] or a [`crate::Body`], with
/// `omega` in the form for numbers ([`Ball::angular_velocity`]).
#[inline(always)]
pub fn vector_field<D: Scalar>(body: &impl AsBall, x: &[D; 6]) -> [D; 6] {
    vector_field_in(OmegaForm::Cofactors, body, x)
}

/// Which of two equal closed forms of `omega = I_Q^{-1} M` (om-m) the field computes: the same
/// function in different arithmetic (they agree to round-off).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OmegaForm {
    /// [`Ball::angular_velocity`]: one division (numbers: `f64`, dual numbers, lanes).
    Cofactors,
    /// [`Ball::angular_velocity_by_determinant`]: fewer convolutions, a division for the
    /// coupling and one for each component (truncated power series: the Taylor method's tape).
    Determinant,
}

impl OmegaForm {
    /// `omega = I_Q^{-1} v` (om-m) of the ball at `gamma`, in this form (`v = M`: the angular
    /// velocity; any other vector `v` of the same unit: `I_Q^{-1} v`).
    #[inline(always)]
    pub fn angular_velocity<D: Scalar>(self, ball: &Ball, gamma: &[D; 3], v: &[D; 3]) -> [D; 3] {
        match self {
            OmegaForm::Cofactors => ball.angular_velocity(gamma, v),
            OmegaForm::Determinant => ball.angular_velocity_by_determinant(gamma, v),
        }
    }
}

/// [`vector_field`] with `omega` in the form `form`.
#[inline(always)]
pub fn vector_field_in<D: Scalar>(form: OmegaForm, body: &impl AsBall, x: &[D; 6]) -> [D; 6] {
    ball_field(&body.ball(), x, form)
}

/// (mg-eq) in the form of the module's documentation. The constants `-m R com` and
/// `-m G com` are products of parameters, made in `f64` arithmetic, so that every scalar type
/// (and the Taylor tape, which folds the zero components of an axial `com`) sees the same
/// numbers; the products by them are by constants, not of variables, and are written as plain
/// products (a fused multiply-add by a constant would be a product of two series on the
/// tape, and would not fold a zero). The one product of variables per component, `s omega_i`,
/// is fused with the sum it enters.
#[inline(always)]
fn ball_field<D: Scalar>(ball: &Ball, x: &[D; 6], form: OmegaForm) -> [D; 6] {
    let (gamma, m_vec) = split(x);
    let omega = form.angular_velocity(ball, &gamma, &m_vec);
    let gamma_dot = cross(&gamma, &omega);
    // Identity 1: m R dgamma/dt x (omega x r) = s omega, s = (dgamma/dt, -m R com).
    let roll = ball.com().map(|c| -(ball.m() * ball.radius()) * c);
    let s = gamma_dot[0] * roll[0] + gamma_dot[1] * roll[1] + gamma_dot[2] * roll[2];
    // Identity 2: gamma x dU/dgamma = gamma x (-m G com).
    let pull = ball.com().map(|c| lift(-(ball.m() * ball.gravity()) * c));
    let torque = cross(&gamma, &pull);
    let gyroscopic = cross(&m_vec, &omega);
    [
        gamma_dot[0],
        gamma_dot[1],
        gamma_dot[2],
        s.mul_add(omega[0], gyroscopic[0] + torque[0]),
        s.mul_add(omega[1], gyroscopic[1] + torque[1]),
        s.mul_add(omega[2], gyroscopic[2] + torque[2]),
    ]
}
