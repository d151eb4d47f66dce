//! The force of the plane on the rolling ball (the paper's system (mg-eq)): what the contact
//! must supply for the ball to roll without slipping, and so what a friction law must be able
//! to give ([`crate::contact::coulomb`]).
//!
//! With the conventions of [`crate::ball`] (body frame at the centre of mass, `gamma` the unit
//! normal pointing into the plane, `r = R gamma - com`), the centre of mass of a rolling ball
//! moves at `v = r x omega` (the material point of contact at rest, `v + omega x r = 0`), and
//! Newton's law in the body frame gives the contact force
//!
//! `P = m (v' + omega x v) - m G gamma`,
//!
//! with `v'` the rate of `v(gamma, M) = r(gamma) x omega(gamma, M)` along the field (mg-eq),
//! taken by forward automatic differentiation of the same code (a dual number seeded with
//! the field: no hand-derived acceleration). The normal force is `N = -(P, gamma)` (the
//! plane pushes up, `-gamma`), the friction the tangential part `F = P + N gamma`. Euler's law
//! about the centre of mass, `I omega' + omega x I omega = r x P`, is not used and holds by
//! (mg-eq): the tests check it.

use crate::ball::AsBall;
use crate::field::vector_field;
use crate::scalar::{cross, dot, Scalar};
use num_dual::Dual64;

/// The force of the plane on the ball rolling at `x = (gamma, M)`, split into its normal and
/// tangential parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reaction {
    /// The contact force `P` (body frame).
    pub force: [f64; 3],
    /// The normal force `N = -(P, gamma)` (positive: the plane pushes the ball up).
    pub normal: f64,
    /// The friction `F = P + N gamma`, tangent to the plane.
    pub friction: [f64; 3],
}

impl Reaction {
    /// The reaction on `ball` rolling at `x = (gamma, M)` (the module's formula).
    pub fn of(ball: &impl AsBall, x: &[f64; 6]) -> Reaction {
        let b = ball.ball();
        let field = vector_field(ball, x);
        let seeded: [Dual64; 6] = std::array::from_fn(|i| Dual64::new(x[i], field[i]));
        let velocity = centre_velocity(ball, &seeded);
        let v = velocity.map(|c| c.re);
        let acceleration = velocity.map(|c| c.eps);
        let omega = b.angular_velocity(&[x[0], x[1], x[2]], &[x[3], x[4], x[5]]);
        let transport = cross(&omega, &v);
        let gamma = [x[0], x[1], x[2]];
        let force: [f64; 3] = std::array::from_fn(|i| {
            b.m() * (acceleration[i] + transport[i]) - b.m() * b.gravity() * gamma[i]
        });
        let normal = -dot(&force, &gamma);
        Reaction {
            force,
            normal,
            friction: std::array::from_fn(|i| force[i] + normal * gamma[i]),
        }
    }

    /// The size of the friction, `|F|`.
    pub fn friction_size(&self) -> f64 {
        dot(&self.friction, &self.friction).sqrt()
    }
}

/// The velocity of the centre of mass of the ball rolling at `x`, `v = r x omega`.
pub fn centre_velocity<D: Scalar>(ball: &impl AsBall, x: &[D; 6]) -> [D; 3] {
    let b = ball.ball();
    let gamma = [x[0], x[1], x[2]];
    let omega = b.angular_velocity(&gamma, &[x[3], x[4], x[5]]);
    cross(&b.contact_vector(&gamma), &omega)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Ball;
    use crate::state::{Normalise, State};

    /// Random rolling states of a ball with the centre of mass off every axis and three
    /// different moments of inertia (the general ball) and of the Routh sphere.
    fn states() -> Vec<(Ball, [f64; 6])> {
        let balls = [
            Ball::new(1.3, 0.8, [0.2, 0.31, 0.27], [0.05, -0.1, -0.2], 9.81).unwrap(),
            Ball::new(1.0, 1.0, [0.37, 0.37, 0.4], [0.0, 0.0, -0.3], 9.81).unwrap(),
        ];
        let mut out = Vec::new();
        for ball in balls {
            for k in 0..6 {
                let t = k as f64;
                let gamma = [(0.7 * t).sin() * 0.6, (1.3 * t).cos() * 0.5, -0.6];
                let omega = [(2.1 * t).sin() * 3.0, 1.5 - t, 4.0 + (0.4 * t).cos() * 5.0];
                let state = State::from_omega(&ball, gamma, omega, Normalise::Rescale).unwrap();
                out.push((ball, state.to_array()));
            }
        }
        out
    }

    /// Euler's law about the centre of mass, `I omega' + omega x I omega = r x P`, holds for
    /// the reaction derived from Newton's law alone, with `omega'` the rate of omega(gamma, M)
    /// along (mg-eq) by automatic differentiation: a check of the formula against the
    /// paper's system, independent of how P was built. Tolerance 1e-12 of the size of the
    /// terms (`|I omega'| + |omega x I omega|`, sums of a few dozen products in f64).
    /// Negative control: with P's friction dropped, the law fails by the friction's torque
    /// (above 1e-3 of the terms).
    #[test]
    fn the_reaction_obeys_euler_s_law() {
        for (ball, x) in states() {
            let reaction = Reaction::of(&ball, &x);
            let field = vector_field(&ball, &x);
            let seeded: [Dual64; 6] = std::array::from_fn(|i| Dual64::new(x[i], field[i]));
            let gamma = [seeded[0], seeded[1], seeded[2]];
            let omega_dual = ball.angular_velocity(&gamma, &[seeded[3], seeded[4], seeded[5]]);
            let omega = omega_dual.map(|c| c.re);
            let rate = omega_dual.map(|c| c.eps);
            let inertia = ball.inertia();
            let moment: [f64; 3] = std::array::from_fn(|i| inertia[i] * omega[i]);
            let r = ball.contact_vector(&[x[0], x[1], x[2]]);
            let torque = cross(&r, &reaction.force);
            let gyro = cross(&omega, &moment);
            let lhs: [f64; 3] = std::array::from_fn(|i| inertia[i] * rate[i] + gyro[i]);
            let size = lhs.iter().map(|c| c.abs()).sum::<f64>()
                + torque.iter().map(|c| c.abs()).sum::<f64>();
            for i in 0..3 {
                assert!(
                    (lhs[i] - torque[i]).abs() <= 1e-12 * size,
                    "{lhs:?} vs {torque:?}"
                );
            }
            let normal_only: [f64; 3] = std::array::from_fn(|i| -reaction.normal * x[i]);
            let off = cross(&r, &normal_only);
            let miss = (0..3).map(|i| (lhs[i] - off[i]).abs()).fold(0.0, f64::max);
            assert!(miss > 1e-3 * size, "control: {miss:e}");
            assert!(dot(&reaction.friction, &[x[0], x[1], x[2]]).abs() <= 1e-13 * size);
        }
    }

    /// A ball at rest, upright, weighs m G on the plane with no friction (to a few ulp).
    #[test]
    fn a_ball_at_rest_weighs_m_g_without_friction() {
        let ball = Ball::new(2.0, 1.0, [0.37, 0.37, 0.4], [0.0, 0.0, -0.3], 9.81).unwrap();
        let reaction = Reaction::of(&ball, &[0.0, 0.0, -1.0, 0.0, 0.0, 0.0]);
        assert!((reaction.normal - 2.0 * 9.81).abs() <= 4.0 * f64::EPSILON * 19.62);
        assert_eq!(reaction.friction_size(), 0.0);
    }
}
