//! Stationary motions: Routh's threshold against the double root of Q and against the
//! eigenvalues of the Jacobian; steady precessions against the integrator.

use routh::body::Body;
use routh::field::vector_field;
use routh::integrate::{solve, Options};
use routh::quadrature::Reduction;
use routh::state::State;
use routh::steady::{
    max_real_eigenvalue, routh_threshold, steady_precessions, vertical_spin, vertical_spin_state,
};

/// Bodies with the centre of mass above the geometric centre at gamma3 = `pole`.
fn top_heavy() -> Vec<(Body, f64)> {
    vec![
        (Body::default(), 1.0),
        (
            Body::new(2.0, 0.5, -0.1, 0.05, 0.05, 0.08, 9.81).unwrap(),
            -1.0,
        ),
        (Body::new(1.0, 1.0, 0.6, 0.3, 0.3, 0.2, 3.0).unwrap(), 1.0),
    ]
}

#[test]
fn threshold_is_the_double_root_of_q_second_derivative() {
    // Q''(pole) from automatic differentiation of Q vanishes at Routh's w_c and has the
    // closed form -2 [(C + m R l)^2 w^2 - 4 m G a p (A + m l^2)] / (A + m l^2)^2.
    for (body, pole) in top_heavy() {
        let wc = routh_threshold(&body, pole);
        assert!(wc > 0.0);
        let l = body.radius + body.a * pole;
        let inertia = body.i1 + body.m * l * l;
        for w in [0.0, 0.5 * wc, wc, 1.5 * wc] {
            let state = vertical_spin_state(&body, pole, w).unwrap();
            let (q, dq, q2) = Reduction::of_state(&body, &state)
                .unwrap()
                .q_derivatives(pole);
            let closed = -2.0
                * ((body.i3 + body.m * body.radius * l).powi(2) * w * w
                    - 4.0 * body.m * body.gravity * body.a * pole * inertia)
                / (inertia * inertia);
            let scale = 8.0 * body.m * body.gravity * body.a.abs() / inertia;
            assert!(
                q.abs() < 1e-13 * scale && dq.abs() < 1e-13 * scale,
                "{q} {dq}"
            );
            assert!(
                (q2 - closed).abs() < 1e-12 * scale,
                "w = {w}: {q2} vs {closed}"
            );
        }
    }
}

/// Whether the Jacobian at the vertical spin has an eigenvalue off the imaginary axis. The
/// tolerance 1e-7: below the threshold the real pair grows like sqrt(w_c - w), about 1e-4 at
/// 1e-8 below it, while above it the computed real parts are below 1e-20 here.
fn unstable_by_jacobian(body: &Body, pole: f64, w: f64) -> bool {
    let state = vertical_spin_state(body, pole, w).unwrap();
    max_real_eigenvalue(body, &state, 0.0).unwrap().0 > 1e-7
}

#[test]
fn threshold_agrees_with_the_jacobian_eigenvalues_by_bisection() {
    for (body, pole) in top_heavy() {
        let wc = routh_threshold(&body, pole);
        let (mut lo, mut hi) = (0.5 * wc, 2.0 * wc);
        assert!(unstable_by_jacobian(&body, pole, lo) && !unstable_by_jacobian(&body, pole, hi));
        while hi - lo > 1e-12 * wc {
            let mid = 0.5 * (lo + hi);
            if unstable_by_jacobian(&body, pole, mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let rel = (0.5 * (lo + hi) - wc).abs() / wc;
        println!(
            "w_c = {wc}: bisection of the eigenvalues {}: {rel:.2e}",
            0.5 * (lo + hi)
        );
        assert!(rel < 1e-8, "{rel:e}");
        // Negative control: a threshold 1e-6 off is told apart.
        assert!(unstable_by_jacobian(&body, pole, wc * (1.0 - 1e-6)));
    }
}

#[test]
fn both_stability_tests_agree_on_vertical_spins() {
    for (body, pole) in top_heavy() {
        let wc = routh_threshold(&body, pole);
        for factor in [0.0, 0.3, 0.9, 1.1, 3.0] {
            let v = vertical_spin(&body, pole, factor * wc).unwrap();
            assert!(v.centre_of_mass_above);
            assert_eq!(v.stability.stable_by_q, factor > 1.0);
            assert_eq!(v.stability.stable_by_jacobian, factor > 1.0);
        }
        // The other pole has the centre of mass below: stable at every spin, no threshold.
        for w in [0.0, 0.1, 5.0] {
            let v = vertical_spin(&body, -pole, w).unwrap();
            assert!(!v.centre_of_mass_above && v.threshold_spin == 0.0);
            assert!(v.stability.stable_by_q && v.stability.stable_by_jacobian);
        }
    }
}

#[test]
fn steady_precessions_keep_their_tilt_under_the_integrator() {
    let body = Body::default();
    let opts = Options {
        rtol: 1e-13,
        atol: 1e-15,
        ..Options::default()
    };
    let field = |_t: f64, x: &[f64; 6]| vector_field(&body, x);
    let mut count = 0;
    for theta in [0.3, 1.0, 2.0] {
        for spin in [2.0, 8.0] {
            for p in steady_precessions(&body, theta, spin).unwrap() {
                count += 1;
                let t = 3.0;
                let (_, y, _, _) = solve(
                    &field,
                    0.0,
                    p.state.to_array(),
                    t,
                    &opts,
                    None,
                    None,
                    &mut |_, _| {},
                )
                .unwrap();
                // The exact motion is the rotation about e3 by precession * t.
                let (s, c) = (p.precession * t).sin_cos();
                let g = p.state.gamma;
                let expected = [c * g[0] - s * g[1], s * g[0] + c * g[1], g[2]];
                let err = (0..3).fold(0.0_f64, |m, i| m.max((y[i] - expected[i]).abs()));
                assert!(err < 1e-9, "theta {theta} spin {spin}: {err:e}");
                assert_eq!(
                    p.stability.stable_by_q, p.stability.stable_by_jacobian,
                    "{p:?}"
                );
            }
        }
    }
    assert!(count >= 6);
}

#[test]
fn both_stability_tests_agree_on_steady_precessions() {
    // A scan of tilts and spins for three bodies. Every tilted steady motion found is stable by
    // both tests (unstable ones are the vertical spins below the threshold, tested above).
    let (mut stable, mut unstable) = (0, 0);
    for (body, _) in top_heavy() {
        for k in 1..40 {
            let theta = 0.08 * k as f64;
            for spin in [0.0, 0.1, 0.5, 1.5, 3.0] {
                for p in steady_precessions(&body, theta, spin).unwrap() {
                    assert_eq!(
                        p.stability.stable_by_q, p.stability.stable_by_jacobian,
                        "{p:?}"
                    );
                    if p.stability.stable_by_q {
                        stable += 1;
                    } else {
                        unstable += 1;
                    }
                }
            }
        }
    }
    println!("steady precessions: {stable} stable, {unstable} unstable");
    assert!(stable > 600);
}

#[test]
fn a_non_steady_state_changes_its_tilt() {
    // Negative control of the steady-precession condition: omega_t off the root.
    let body = Body::default();
    let p = steady_precessions(&body, 1.0, 8.0).unwrap()[0];
    let omega = p.state.omega(&body);
    let off = State::from_omega(
        &body,
        p.state.gamma,
        [omega[0] * 1.01, omega[1], omega[2]],
        routh::state::Normalise::Reject,
    )
    .unwrap();
    let (_, dq, _) = Reduction::of_state(&body, &off)
        .unwrap()
        .q_derivatives(p.state.gamma[2]);
    assert!(dq.abs() > 1e-3, "{dq}");
}

#[test]
fn growth_rate_below_threshold_is_the_root_of_q_second_derivative_over_8() {
    // Near the pole, u = p - theta^2 / 2 + ..., so (du/dt)^2 = Q(u) ~ Q''(p) (u - p)^2 / 2 gives
    // thetadot^2 = Q''(p) theta^2 / 8: below the threshold the Jacobian has the real pair
    // +-sqrt(Q''(p) / 8). Two independent computations of the same number.
    for (body, pole) in top_heavy() {
        let wc = routh_threshold(&body, pole);
        for factor in [0.0, 0.5, 0.9] {
            let v = vertical_spin(&body, pole, factor * wc).unwrap();
            let predicted = (v.stability.q_second_derivative / 8.0).sqrt();
            let rate = v.stability.max_real_eigenvalue;
            assert!(
                (rate - predicted).abs() < 1e-9 * predicted,
                "{rate} vs {predicted}"
            );
        }
    }
}

#[test]
fn spectral_abscissa_terminates_on_structured_matrices() {
    // Regression: nalgebra's unbounded Schur iteration cycled forever on a vertical-spin
    // Jacobian during the threshold bisection. Blocks of rotations (eigenvalues +-2i, +-i),
    // a real eigenvalue 0.5 and an exact zero: the abscissa is 0.5 to round-off.
    let mut j = nalgebra::SMatrix::<f64, 6, 6>::zeros();
    j[(0, 1)] = -2.0;
    j[(1, 0)] = 2.0;
    j[(2, 2)] = 0.5;
    j[(3, 4)] = 1.0;
    j[(4, 3)] = -1.0;
    let abscissa = routh::steady::spectral_abscissa(&j).unwrap();
    assert!((abscissa - 0.5).abs() < 1e-14, "{abscissa}");
    for w in [0.1, 1.0, 2.7556608402825384, 8.0] {
        let state = vertical_spin_state(&Body::default(), 1.0, w).unwrap();
        assert!(max_real_eigenvalue(&Body::default(), &state, 0.0).is_ok());
    }
}
