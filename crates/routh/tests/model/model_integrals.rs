//! The integrals of (m-eq)/(mg-eq) and the invariant measure (rho), checked by automatic
//! differentiation of the same code that simulates.
//!
//! Tolerance: the derivative of an integral along the field is a sum of products of size
//! |dH| |X| ~ 1e2 at these points; cancellation to zero leaves round-off of a few 1e-14 of
//! that scale. We require |X(H)| <= 1e-12 * |dH| |X|, two orders above round-off and ten
//! orders below the value a wrong field gives (see the negative control).

use routh::differential::{divergence, gradient, lie_derivative, Dual6};
use routh::field::vector_field;
use routh::integrals::{
    energy, geometric, jellett, measure_density, quadratic_integral, quadratic_integral_free,
    routh_integral,
};
use routh::sampling::SplitMix64;
use routh::Body;

type Integral = fn(&Body, &[Dual6; 6]) -> Dual6;

fn bodies() -> [Body; 3] {
    [
        Body::default(),
        Body {
            gravity: 0.0,
            ..Body::default()
        },
        Body::new(2.0, 0.7, -0.25, 0.3, 0.3, 0.45, 3.0).unwrap(),
    ]
}

fn relative_rate(h: impl Fn(&[Dual6; 6]) -> Dual6, field: &[f64; 6], x: &[f64; 6]) -> f64 {
    let (_, dh) = gradient(&h, x);
    let scale = dh.iter().map(|v| v * v).sum::<f64>().sqrt()
        * field.iter().map(|v| v * v).sum::<f64>().sqrt();
    lie_derivative(h, field, x).abs() / scale.max(1e-300)
}

const CONSERVED: [(&str, Integral); 5] = [
    ("H1", energy),
    ("H2", quadratic_integral),
    ("H3", jellett),
    ("K", routh_integral),
    ("H4", |_, x| geometric(x)),
];

#[test]
fn integrals_are_constant_along_the_field_at_20_random_points() {
    for body in bodies() {
        let mut rng = SplitMix64::new(7);
        for _ in 0..20 {
            let x = rng.phase_point(3.0, 0.0, 0.0);
            let field = vector_field(&body, &x);
            for (name, h) in CONSERVED {
                let rate = relative_rate(|y| h(&body, y), &field, &x);
                assert!(
                    rate < 1e-12,
                    "{name} not conserved for {body:?} at {x:?}: {rate:e}"
                );
            }
            if body.gravity == 0.0 {
                let rate = relative_rate(|y| quadratic_integral_free(&body, y), &field, &x);
                assert!(rate < 1e-12, "H2 of (int) not conserved at {x:?}: {rate:e}");
            }
        }
    }
}

#[test]
fn field_divided_by_g_is_divergence_free() {
    // div(X/g) = 0 is the invariant measure (rho). Each term of the divergence is of size
    // |dX| ~ 1e1; round-off leaves ~1e-14, so 1e-11 absolute is a safe, still sharp bound.
    for body in bodies() {
        let mut rng = SplitMix64::new(11);
        for _ in 0..20 {
            let x = rng.phase_point(3.0, 0.0, 0.0);
            let div = divergence(
                |y| vector_field(&body, y).map(|c| c * measure_density(&body, y)),
                &x,
            );
            assert!(div.abs() < 1e-11, "div(X/g) = {div:e} at {x:?}");
            let plain = divergence(|y| vector_field(&body, y), &x);
            assert!(
                plain.abs() > 1e-6,
                "negative control: div X itself is not zero ({plain:e})"
            );
        }
    }
}

/// A deliberately wrong field: `2 X(m) - X(1.5 m)`, the field with the rolling term
/// weighted by the wrong mass.
fn wrong_field(body: &Body, x: &[Dual6; 6]) -> [Dual6; 6] {
    let right = vector_field(body, x);
    let gyro_only = vector_field(
        &Body {
            m: body.m * 1.5,
            ..*body
        },
        x,
    );
    std::array::from_fn(|i| right[i] * 2.0 - gyro_only[i])
}

#[test]
fn negative_control_a_wrong_field_breaks_the_integrals_and_the_measure() {
    let body = Body::default();
    let mut rng = SplitMix64::new(3);
    for _ in 0..20 {
        let x = rng.phase_point(3.0, 0.0, 0.0);
        let field: [f64; 6] = std::array::from_fn(|i| {
            let dual = wrong_field(&body, &x.map(Dual6::from));
            dual[i].re
        });
        let worst = CONSERVED[..4]
            .iter()
            .map(|(_, h)| relative_rate(|y| h(&body, y), &field, &x))
            .fold(0.0, f64::max);
        assert!(
            worst > 1e-6,
            "a wrong field passed the integral check: {worst:e}"
        );
        let div = divergence(
            |y| wrong_field(&body, y).map(|c| c * measure_density(&body, y)),
            &x,
        );
        assert!(
            div.abs() > 1e-8,
            "a wrong field passed the measure check: {div:e}"
        );
    }
}

#[test]
fn potential_gradient_matches_automatic_differentiation() {
    let body = Body::default();
    let mut rng = SplitMix64::new(5);
    for _ in 0..20 {
        let x = rng.phase_point(1.0, 0.0, 0.0);
        let (_, du) = gradient(|y| body.potential(&[y[0], y[1], y[2]]), &x);
        let hand = body.potential_gradient(&[x[0], x[1], x[2]]);
        for i in 0..3 {
            assert!((du[i] - hand[i]).abs() < 1e-13 * (1.0 + hand[i].abs()));
        }
    }
}

#[test]
fn without_spin_the_centre_of_mass_below_the_centre_is_the_stable_equilibrium() {
    // With a > 0 the centre of mass sits at -a e3 from the geometric centre, so at
    // gamma = (0, 0, -1) (e3 pointing up) it is below the centre: height R - a. The Jacobian of
    // the field there must have no eigenvalue with positive real part (1e-9: the exact
    // eigenvalues are imaginary or zero, the rest is round-off of the eigen-solver), while at
    // gamma = (0, 0, 1) (centre of mass above, height R + a) one eigenvalue is real and
    // positive, sqrt(m G a R / (I1 + m (R + a)^2))-like, here > 1.
    use routh::differential::jacobian;
    let body = Body::default();
    let spectrum = |g3: f64| {
        let x = [0.0, 0.0, g3, 0.0, 0.0, 0.0];
        let (_, j) = jacobian(|y| vector_field(&body, y), &x);
        routh::steady::spectral_abscissa(&j).expect("the Schur decomposition converges")
    };
    assert!(
        spectrum(-1.0) < 1e-9,
        "bottom-heavy rest is unstable: {}",
        spectrum(-1.0)
    );
    assert!(
        spectrum(1.0) > 1.0,
        "top-heavy rest is stable: {}",
        spectrum(1.0)
    );
    assert!(body.potential(&[0.0, 0.0, -1.0]) < body.potential(&[0.0, 0.0, 1.0]));
}

#[test]
fn angular_velocity_inverts_the_inertia_tensor_about_the_contact_point() {
    // omega = I_Q^{-1} M is computed in closed form (Sherman-Morrison over det A, one
    // division); M = I_Q omega is computed from the definition (om-m). The round trip is exact
    // up to round-off: I_Q has condition number below 1e2 here, so 1e-14 relative leaves a
    // margin over the ~1e-16 of each operation. Three distinct moments test the general case.
    let asymmetric = Body::new(1.5, 0.8, 0.2, 0.3, 0.35, 0.5, 9.81).unwrap();
    let mut rng = SplitMix64::new(11);
    for body in bodies().into_iter().chain([asymmetric]) {
        for _ in 0..20 {
            let x = rng.phase_point(3.0, 0.0, 0.0);
            let gamma = [x[0], x[1], x[2]];
            let m_vec = [x[3], x[4], x[5]];
            let omega = body.angular_velocity(&gamma, &m_vec);
            let back = body.angular_momentum(&gamma, &omega);
            let norm = m_vec.iter().map(|v| v * v).sum::<f64>().sqrt();
            let error = (0..3)
                .map(|i| (back[i] - m_vec[i]).abs())
                .fold(0.0, f64::max);
            assert!(
                error <= 1e-14 * norm,
                "I_Q omega != M for {body:?} at {x:?}: {error:e}"
            );
            // Negative control: omega at a different gamma is not the inverse.
            let other = body.angular_velocity(&[gamma[1], gamma[2], gamma[0]], &m_vec);
            let wrong = body.angular_momentum(&gamma, &other);
            let miss = (0..3)
                .map(|i| (wrong[i] - m_vec[i]).abs())
                .fold(0.0, f64::max);
            assert!(miss > 1e-6 * norm, "the round trip check is not sharp");
        }
    }
}
