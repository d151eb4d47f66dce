//! The motion in space rebuilt from the reduced state (src/motion.rs, docs/motion.md): the
//! constraints hold along the reconstruction, and two motions with a closed-form answer come
//! out as derived.
//!
//! All integrations use DOP853 at rtol = atol = 1e-12, without projection: the quaternion keeps
//! its unit norm through the restoring term of `FullMotion`.

use routh::integrate::{solve_dense, OdeSystem, Options};
use routh::motion::{
    full_columns, initial_full, material_point, quaternion, rotate, FullMotion, FULL_DIM,
};
use routh::scalar::cross;
use routh::state::Normalise;
use routh::{Body, State};

type Sample = (f64, [f64; FULL_DIM]);

const TOLERANCE: f64 = 1e-12;

/// Dense samples of `system` from `y0` at the given times.
fn samples_of(
    system: &impl OdeSystem<FULL_DIM>,
    y0: [f64; FULL_DIM],
    times: &[f64],
) -> Vec<Sample> {
    let opts = Options {
        rtol: TOLERANCE,
        atol: TOLERANCE,
        ..Options::default()
    };
    let mut out = Vec::with_capacity(times.len());
    let t_end = *times.last().expect("at least one sample");
    solve_dense(system, 0.0, y0, t_end, &opts, None, times, &mut |t, y| {
        out.push((t, *y))
    })
    .expect("integration succeeds");
    out
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|c| c * c).sum::<f64>().sqrt()
}

fn default_start() -> (Body, [f64; FULL_DIM]) {
    let body = Body::default();
    let state = State::from_omega(
        &body,
        [0.29552020666133955, 0.0, 0.955336489125606],
        [0.5, 0.2, 8.0],
        Normalise::Reject,
    )
    .unwrap();
    (body, initial_full(&state))
}

/// Half-width of the difference stencil and the stencil offsets.
const H: f64 = 1e-3;
const STENCIL: [f64; 4] = [-2.0 * H, -H, H, 2.0 * H];

/// Sample times: centres `k * spacing` (k = 1..=n), each with its four stencil points.
fn stencil_times(n: usize, spacing: f64) -> Vec<f64> {
    let mut times = vec![0.0];
    for k in 1..=n {
        let c = k as f64 * spacing;
        times.extend([
            c + STENCIL[0],
            c + STENCIL[1],
            c,
            c + STENCIL[2],
            c + STENCIL[3],
        ]);
    }
    times
}

/// Largest velocity, relative to the speed of the centre of mass, of the material point that
/// is at the contact at each stencil centre: the fourth-order central difference of
/// `X_com(t) + Q(t) r0`, r0 frozen at the centre.
///
/// Error budget at H = 1e-3: truncation H^4 |p^(5)| / 30 ~ 1e-12 * 8^5 / 30 ~ 1e-9 at most
/// for |omega| ~ 8; round-off 1e-16 * 10 / H ~ 1e-12. Measured: 3.5e-10, the same within 5%
/// for H from 1e-4 to 1e-3, so it is the integrator's error (positions of ~10 m to rtol
/// 1e-12, over steps of a few 1e-2), not the differencing.
fn contact_velocity_residual(body: &Body, samples: &[Sample]) -> f64 {
    let mut worst: f64 = 0.0;
    for group in samples[1..].chunks(5) {
        let centre = &group[2].1;
        let r0 = body.contact_vector(&[centre[0], centre[1], centre[2]]);
        let p: Vec<[f64; 3]> = group
            .iter()
            .map(|(_, y)| material_point(body, y, &r0))
            .collect();
        let velocity: [f64; 3] = std::array::from_fn(|i| {
            (p[0][i] - 8.0 * p[1][i] + 8.0 * p[3][i] - p[4][i]) / (12.0 * H)
        });
        let com: Vec<[f64; 3]> = group
            .iter()
            .map(|(_, y)| material_point(body, y, &[0.0; 3]))
            .collect();
        let com_velocity: [f64; 3] = std::array::from_fn(|i| {
            (com[0][i] - 8.0 * com[1][i] + 8.0 * com[3][i] - com[4][i]) / (12.0 * H)
        });
        worst = worst.max(norm(&velocity) / norm(&com_velocity));
    }
    worst
}

#[test]
fn material_contact_point_is_at_rest() {
    let (body, y0) = default_start();
    let motion = FullMotion { body: &body };
    let samples = samples_of(&motion, y0, &stencil_times(40, 0.25));
    let residual = contact_velocity_residual(&body, &samples);
    assert!(residual < 1e-8, "relative contact velocity {residual:e}");

    // Negative control: the reconstruction with the sign of the no-slip velocity flipped.
    let slipping = |t: f64, y: &[f64; FULL_DIM]| {
        let mut dy = motion.rhs(t, y);
        dy[10] = -dy[10];
        dy[11] = -dy[11];
        dy
    };
    let samples = samples_of(&slipping, y0, &stencil_times(40, 0.25));
    let residual = contact_velocity_residual(&body, &samples);
    assert!(residual > 0.1, "negative control: {residual:e}");
}

#[test]
fn reconstruction_agrees_with_gamma_and_height() {
    let (body, y0) = default_start();
    let times: Vec<f64> = (0..=400).map(|k| k as f64 * 0.25).collect();
    let samples = samples_of(&FullMotion { body: &body }, y0, &times);
    let mut worst_down: f64 = 0.0;
    let mut worst_height: f64 = 0.0;
    let mut worst_norm: f64 = 0.0;
    for (_, y) in &samples {
        let gamma = [y[0], y[1], y[2]];
        let down = rotate(&quaternion(y), &gamma);
        worst_down = worst_down.max(norm(&[down[0], down[1], down[2] + 1.0]));
        let columns = full_columns(&body, y);
        let r = body.contact_vector(&gamma);
        worst_height = worst_height.max((columns[6] - (body.radius + body.a * gamma[2])).abs());
        // The contact point is on the plane: z_com + (Q r)_z = 0.
        worst_height = worst_height.max((columns[6] + rotate(&quaternion(y), &r)[2]).abs());
        worst_norm = worst_norm.max((quaternion(y).norm() - 1.0).abs());
    }
    // gamma (reduced field) and Q^T (0, 0, -1) (quaternion kinematics) are integrated
    // independently; over t = 100 at 1e-12 they agree to about 1e-12 per unit time.
    assert!(worst_down < 1e-9, "|Q gamma + e_z| = {worst_down:e}");
    assert!(worst_height < 1e-9, "height residual {worst_height:e}");
    assert!(worst_norm < 1e-12, "|q| - 1 = {worst_norm:e}");
}

#[test]
fn homogeneous_ball_rolls_straight_at_constant_omega() {
    // a = 0, I1 = I2 = I3: every omega stays constant (docs/motion.md), and the centre moves
    // with the constant velocity V = Q0 (r0 x omega0), |V| = |omega x r|.
    let body = Body::new(1.3, 0.8, 0.0, 0.35, 0.35, 0.35, 9.81).unwrap();
    let omega0 = [1.0, -2.0, 3.0];
    let state = State::from_omega(&body, [0.6, 0.0, 0.8], omega0, Normalise::Reject).unwrap();
    let y0 = initial_full(&state);
    let r0 = body.contact_vector(&state.gamma);
    let velocity = rotate(&quaternion(&y0), &cross(&r0, &omega0));
    assert!(velocity[2].abs() < 1e-15, "the velocity is horizontal");
    let speed = norm(&cross(&omega0, &r0));
    let times: Vec<f64> = (0..=100).map(|k| k as f64 * 0.1).collect();
    let samples = samples_of(&FullMotion { body: &body }, y0, &times);
    for (t, y) in &samples {
        let omega = State::from_array(&std::array::from_fn(|i| y[i])).omega(&body);
        assert!(
            norm(&[
                omega[0] - omega0[0],
                omega[1] - omega0[1],
                omega[2] - omega0[2]
            ]) < 1e-10
        );
        let c = full_columns(&body, y);
        let offset = [c[4] - velocity[0] * t, c[5] - velocity[1] * t];
        assert!(
            norm(&offset) < 1e-10 * (1.0 + speed * t),
            "t = {t}: {offset:?}"
        );
        // z = (r, gamma) = R |gamma|^2: exact up to the drift of |gamma|.
        assert!((c[6] - body.radius).abs() < 1e-11);
    }
    let (t_end, y_end) = samples.last().unwrap();
    let travelled = norm(&[y_end[10], y_end[11]]);
    assert!((travelled - speed * t_end).abs() < 1e-9 * speed * t_end);
}

/// The spin about e3 of the steady motion with `gamma3 = cos theta` and rate `mu` about
/// gamma: `omega = mu gamma + lambda e3` with lambda from the balance of moments
/// (docs/motion.md, "Steady motion").
fn steady_lambda(body: &Body, gamma3: f64, mu: f64) -> f64 {
    let (m, r, a) = (body.m, body.radius, body.a);
    let height = r + a * gamma3;
    (m * body.gravity * a - mu * mu * ((body.i3 - body.i1) * gamma3 - m * a * height))
        / (mu * (body.i3 + m * r * height))
}

/// The largest deviation of gamma3 from its start and of the distance between the centre of
/// mass and the predicted circle centre from the predicted radius |R lambda / mu - a| sin theta.
fn steady_deviations(body: &Body, theta: f64, mu: f64, lambda: f64) -> (f64, f64) {
    let gamma = [theta.sin(), 0.0, theta.cos()];
    let omega: [f64; 3] =
        std::array::from_fn(|i| mu * gamma[i] + if i == 2 { lambda } else { 0.0 });
    let state = State::from_omega(body, gamma, omega, Normalise::Reject).unwrap();
    let y0 = initial_full(&state);
    let k = body.radius * lambda / mu - body.a;
    let radius = k.abs() * theta.sin();
    // X_com = C + k n_h with n = Q e3 the symmetry axis in space.
    let axis = rotate(&quaternion(&y0), &[0.0, 0.0, 1.0]);
    let centre = [y0[10] - k * axis[0], y0[11] - k * axis[1]];
    let times: Vec<f64> = (0..=200).map(|k| k as f64 * 0.05).collect();
    let samples = samples_of(&FullMotion { body }, y0, &times);
    let mut tilt: f64 = 0.0;
    let mut circle: f64 = 0.0;
    for (_, y) in &samples {
        tilt = tilt.max((y[2] - gamma[2]).abs());
        circle = circle.max((norm(&[y[10] - centre[0], y[11] - centre[1]]) - radius).abs());
    }
    (tilt, circle)
}

#[test]
fn steady_motion_traces_the_derived_circle() {
    let body = Body::default();
    let (theta, mu) = (1.2_f64, 3.0);
    let lambda = steady_lambda(&body, theta.cos(), mu);
    let (tilt, circle) = steady_deviations(&body, theta, mu, lambda);
    // Ten time units (about five turns of the precession 2 pi / |mu|) at 1e-12.
    assert!(tilt < 1e-9, "gamma3 drift {tilt:e}");
    assert!(circle < 1e-9, "distance from the circle {circle:e}");

    // Negative control: 1% off the derived spin, the tilt oscillates and the path leaves the
    // circle by far more than the tolerance.
    let (tilt, circle) = steady_deviations(&body, theta, mu, 1.01 * lambda);
    assert!(
        tilt > 1e-4 && circle > 1e-4,
        "negative control: {tilt:e}, {circle:e}"
    );
}

#[test]
fn contact_point_circle_radius() {
    // The contact point runs on the circle of radius R |lambda / mu| sin theta about the same
    // centre: check it at one steady motion with mu < 0 (the opposite sense of precession).
    let body = Body::new(2.0, 0.7, -0.25, 0.3, 0.3, 0.45, 3.0).unwrap();
    let (theta, mu) = (0.7_f64, -2.5);
    let lambda = steady_lambda(&body, theta.cos(), mu);
    let gamma = [theta.sin(), 0.0, theta.cos()];
    let omega = [mu * gamma[0], mu * gamma[1], mu * gamma[2] + lambda];
    let state = State::from_omega(&body, gamma, omega, Normalise::Reject).unwrap();
    let y0 = initial_full(&state);
    let axis = rotate(&quaternion(&y0), &[0.0, 0.0, 1.0]);
    let c0 = full_columns(&body, &y0);
    let ratio = body.radius * lambda / mu;
    let centre = [c0[7] - ratio * axis[0], c0[8] - ratio * axis[1]];
    let radius = ratio.abs() * theta.sin();
    let times: Vec<f64> = (0..=100).map(|k| k as f64 * 0.05).collect();
    for (_, y) in samples_of(&FullMotion { body: &body }, y0, &times) {
        let c = full_columns(&body, &y);
        let distance = norm(&[c[7] - centre[0], c[8] - centre[1]]);
        assert!((distance - radius).abs() < 1e-9, "{distance} vs {radius}");
    }
}
