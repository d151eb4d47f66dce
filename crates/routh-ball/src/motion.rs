//! The motion in space: the orientation and the position of the ball, rebuilt from the
//! reduced state (gamma, M) of (mg-eq) with the no-slip constraint (rel-ch).
//!
//! # Frames and signs
//!
//! * **Body frame**: origin at the centre of mass, principal axes, e3 the symmetry axis (as in
//!   [`crate::body`]). `gamma` is the unit normal of the plane pointing *into* the plane;
//!   `r = R gamma + a e3` goes from the centre of mass to the contact point.
//! * **Space frame**: fixed, right-handed, `z` up; the plane is `z = 0`; the ball is above it.
//! * **Orientation**: the unit quaternion `q = (qw, qx, qy, qz)` of the rotation `Q` that takes
//!   body components to space components, `v_space = Q v_body`. Hence the downward vertical
//!   satisfies `Q gamma = (0, 0, -1)`, i.e. `gamma = Q^T (0, 0, -1)`.
//!
//! # Reconstruction equations
//!
//! * Kinematics of the rigid body: `dQ/dt = Q [omega]x` with omega in the body frame, i.e.
//!   `dq/dt = q * (0, omega) / 2` (quaternion product), plus a term that vanishes on
//!   `|q| = 1` and restores the norm against integration error
//!   ([`QUATERNION_RESTORING_FRACTION`]). Then `d(Q^T e)/dt = (Q^T e) x omega`
//!   for a fixed space vector e: with `e = -e_z` this is the `dgamma/dt = gamma x omega` of
//!   (m-eq), which the tests check.
//! * No slip (rel-ch): the velocity of the centre of mass is `v = -omega x r = r x omega` in the
//!   body frame, `V = Q (r x omega)` in space. Its vertical part is
//!   `-(gamma, r x omega) = a (gamma x omega)_3 = d(R + a gamma3)/dt`, so the height of the
//!   centre of mass is not integrated but read off gamma: `z = (r, gamma) = R + a gamma3`.
//!   The horizontal part `(V_x, V_y)` is integrated.
//! * The contact point in space is `X_com + Q r`; its height is `z - (r, gamma) = 0`.
//!
//! The extended state is `y = (gamma, M, q, x, y)`, 12 numbers ([`FULL_DIM`]). The reduced part
//! is integrated by the same field [`vector_field`] as the reduced system, so its solution is
//! identical to the reduced one; q and (x, y) are driven by it and do not feed back.

use crate::ball::AsBall;
use crate::body::Body;
use crate::field::vector_field;
use crate::integrate::{OdeSystem, RunUnits};
use crate::scalar::cross;
use crate::state::{Point, State};
use crate::units::Units;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// The number of components of the extended state `(gamma, M, q, x, y)`.
pub const FULL_DIM: usize = 12;

/// Names of the columns of [`full_columns`], as written by `routh simulate --full`.
pub const FULL_COLUMN_NAMES: [&str; 9] = [
    "qw",
    "qx",
    "qy",
    "qz",
    "x",
    "y",
    "z",
    "contact_x",
    "contact_y",
];

/// The rate `k` at which the quaternion equation pulls `|q|` back to 1, as a fraction of the
/// motion's rate `1 / T` (the time T of [`Units::of`] at the current state, rounded to a power
/// of two, so that a copy of the motion in other units has the same `k T`): the term
/// `-k (|q|^2 - 1) q` added to `q' = q * (0, omega) / 2` vanishes on the unit sphere, so it
/// leaves the motion unchanged, and off it makes `e = |q|^2 - 1` obey `e' = -2k e (1 + e)`
/// up to the integration error. Without it DOP853 at tolerance 1e-12 lets `|q| - 1` drift
/// linearly to 1.3e-12 at t = 100 (default case); with k = 1 (1/8 of the default case's
/// rate 1/T = 8 s^-1) it stays below 5e-13, with no projection needed in any driver. An
/// eighth of the motion's rate is slow beside it, so it adds no stiffness.
pub const QUATERNION_RESTORING_FRACTION: f64 = 0.125;

/// The equations of motion of the full system: the reduced field (mg-eq) together with the
/// quaternion kinematics and the horizontal velocity of the centre of mass from (rel-ch).
#[derive(Debug, Clone, Copy)]
pub struct FullMotion<'a, B = Body> {
    /// The rolling body.
    pub body: &'a B,
}

impl<B: AsBall> OdeSystem<FULL_DIM> for FullMotion<'_, B> {
    type Kernels = crate::integrate::taylor::Interpreted;

    /// The time derivative of the extended state `y = (gamma, M, q, x, y)`.
    fn rhs(&self, _t: f64, y: &[f64; FULL_DIM]) -> [f64; FULL_DIM] {
        let x: [f64; 6] = std::array::from_fn(|i| y[i]);
        let reduced = vector_field(self.body, &x);
        let state = Point::from_array(&x);
        let omega = state.omega(self.body);
        let q = quaternion(y);
        let q_dot = quaternion_rate(&q, &omega, Units::of(self.body, &omega).binary().time());
        let r = self.body.ball().contact_vector(&state.gamma);
        let velocity = rotate(&q, &cross(&r, &omega));
        let mut dy = [0.0; FULL_DIM];
        dy[..6].copy_from_slice(&reduced);
        dy[6..10].copy_from_slice(&[q_dot.w, q_dot.i, q_dot.j, q_dot.k]);
        dy[10] = velocity[0];
        dy[11] = velocity[1];
        dy
    }

    /// The reduced state's units ([`Units::of_reduced`]), 1 for the quaternion, R (rounded
    /// to a power of two) for the position of the contact point.
    fn units(&self, y0: &[f64; FULL_DIM]) -> RunUnits<FULL_DIM> {
        let reduced = Units::of_reduced(self.body, &std::array::from_fn(|i| y0[i]));
        let r = Units::with_rate(self.body, 0.0).binary().length();
        let mut components = [1.0; FULL_DIM];
        components[..6].copy_from_slice(&reduced.components);
        components[10] = r;
        components[11] = r;
        RunUnits {
            time: reduced.time,
            components,
        }
    }
}

/// `dq/dt = q * (0, omega) / 2 - k (|q|^2 - 1) q` for the body-frame angular velocity
/// `omega`, `k` [`QUATERNION_RESTORING_FRACTION`] of the motion's rate `1 / time` (the
/// module's kinematics): of the rolling ball and of the sliding one
/// ([`crate::contact::sliding::SlidingMotion`]).
pub fn quaternion_rate(q: &Quaternion<f64>, omega: &[f64; 3], time: f64) -> Quaternion<f64> {
    let k = QUATERNION_RESTORING_FRACTION / time;
    q * Quaternion::new(0.0, omega[0], omega[1], omega[2]) * 0.5
        - q * (k * (q.norm_squared() - 1.0))
}

/// The quaternion `(qw, qx, qy, qz)` stored in `y[6..10]`.
pub fn quaternion(y: &[f64; FULL_DIM]) -> Quaternion<f64> {
    Quaternion::new(y[6], y[7], y[8], y[9])
}

/// `Q v` for the rotation of the quaternion `q` (normalised first, so that the small drift of
/// `|q|` during integration does not scale the vector).
pub fn rotate(q: &Quaternion<f64>, v: &[f64; 3]) -> [f64; 3] {
    let rotated = UnitQuaternion::from_quaternion(*q) * Vector3::new(v[0], v[1], v[2]);
    [rotated.x, rotated.y, rotated.z]
}

/// The orientation chosen for a body-frame normal `gamma`: `Q = Rz(psi) Rx(theta) Rz(phi)`
/// (z-x-z Euler angles, body to space) with
///
/// * `theta = arccos(-gamma3)`, the angle between body e3 and space e_z,
/// * `phi = atan2(-gamma1, -gamma2)`, so that `Q gamma = (0, 0, -1)`,
/// * the yaw rule `psi = 0`: the line of nodes (where the body's e1-e2 plane meets the
///   horizontal) lies along space x.
///
/// At `gamma = +-e3`, where phi is undetermined, `atan2(0, 0) = 0` picks `phi = 0`.
pub fn orientation_for(gamma: &[f64; 3]) -> UnitQuaternion<f64> {
    let theta = (-gamma[2]).clamp(-1.0, 1.0).acos();
    let phi = (-gamma[0]).atan2(-gamma[1]);
    UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta)
        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi)
}

/// The extended initial state of a reduced state: the orientation of [`orientation_for`]
/// and the centre of mass above the origin of the plane.
pub fn initial_full(state: &State) -> [f64; FULL_DIM] {
    let q = orientation_for(&state.gamma());
    let mut y = [0.0; FULL_DIM];
    y[..6].copy_from_slice(&state.to_array());
    y[6..10].copy_from_slice(&[q.w, q.i, q.j, q.k]);
    y
}

/// The columns added by `--full` at a sample `y`: the quaternion, the centre of mass
/// `(x, y, z)` with `z = (r, gamma)`, and the contact point `(x, y)` on the plane.
pub fn full_columns(body: &impl AsBall, y: &[f64; FULL_DIM]) -> [f64; 9] {
    let gamma = [y[0], y[1], y[2]];
    let r = body.ball().contact_vector(&gamma);
    let height = crate::scalar::dot(&r, &gamma);
    let q = quaternion(y);
    let to_contact = rotate(&q, &r);
    [
        y[6],
        y[7],
        y[8],
        y[9],
        y[10],
        y[11],
        height,
        y[10] + to_contact[0],
        y[11] + to_contact[1],
    ]
}

/// The space position at `y` of the material point with body coordinates `point` (relative
/// to the centre of mass): `X_com + Q point`, with the height of the centre of mass
/// `(r, gamma)`.
pub fn material_point(body: &impl AsBall, y: &[f64; FULL_DIM], point: &[f64; 3]) -> [f64; 3] {
    let columns = full_columns(body, y);
    let offset = rotate(&quaternion(y), point);
    [
        columns[4] + offset[0],
        columns[5] + offset[1],
        columns[6] + offset[2],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::state::Normalise;

    #[test]
    fn initial_orientation_maps_gamma_to_down() {
        let body = Body::default();
        for gamma in [
            [0.29552020666133955, 0.0, 0.955336489125606],
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
            [0.6, -0.48, 0.64],
        ] {
            let state = State::from_omega(&body, gamma, [0.1, 0.2, 0.3], Normalise::Reject)
                .expect("valid state");
            let y = initial_full(&state);
            let down = rotate(&quaternion(&y), &gamma);
            for (d, e) in down.iter().zip([0.0, 0.0, -1.0]) {
                assert!((d - e).abs() < 1e-15, "{gamma:?} -> {down:?}");
            }
            // The yaw rule psi = 0: the line of nodes is space x, so Q e3 has no x component.
            let axis = rotate(&quaternion(&y), &[0.0, 0.0, 1.0]);
            assert!(axis[0].abs() < 1e-15, "{gamma:?}: Q e3 = {axis:?}");
            let contact = full_columns(&body, &y);
            assert!((contact[6] - (body.radius() + body.a() * gamma[2])).abs() < 1e-15);
        }
    }
}
