//! When `exact` may call a state steady, when it must solve the motion, and when it must
//! refuse: the reproducers of issue 10 (wrong "steady" verdicts near the vertical spin) and of
//! issue 14 (false "near a separatrix" refusals of regular nutations near the axis), and a
//! property test over 500 random states against DOP853.

// The DOP853 reference and the distance of the sweep of issue 14.
#[allow(dead_code)]
use crate::sweep_cases as exact_sweep;

use exact_sweep::{distance, dop853_at};
use routh::body::Body;
use routh::quadrature::{ExactSolution, Motion};
use routh::state::{Normalise, State};
use routh::steady::routh_threshold;
use routh::RouthError;

/// DOP853 at rtol 1e-13 (atol 1e-15) from `x0` to `t`: at t = 10 its global error on these
/// motions is below 1e-9 (at most 4.6e-10 on the random states of the property test, against
/// rtol 3e-16; docs/quadrature.md, section 7), below the 1e-8 compared here.
fn dop853(body: &Body, x0: &State, t: f64) -> State {
    dop853_at(body, x0, t, 1e-13)
}

fn state(body: &Body, gamma: [f64; 3], omega: [f64; 3]) -> State {
    State::from_omega(body, gamma, omega, Normalise::Rescale).unwrap()
}

fn tilt(theta: f64) -> [f64; 3] {
    [theta.sin(), 0.0, theta.cos()]
}

#[test]
fn below_routh_threshold_a_small_tilt_is_not_steady() {
    // Issue 10: gamma = (sin 1e-6, 0, cos 1e-6), omega = (0, 0, 2) (below the threshold
    // 2.7557) was called steady; DOP853 leaves the axis: gamma = (0.5187, -0.1501, 0.8417) at
    // t = 20. The quadrature must not call it steady. This state lies so close to the
    // homoclinic orbit that H1, H3, K (round-off 1e-16) fix its distance from it only to 1e-4
    // relative, and it was refused as a separatrix; the parameters of the top pole computed
    // from the state without cancellation (docs/quadrature.md, section 5) fix it to 1e-12,
    // and it is solved: 6.8e-11 off DOP853 at rtol 1e-14 at t = 20, where the instability
    // (eigenvalue 0.816) has amplified the start's round-off 1.2e7 times.
    let body = Body::default();
    let x0 = state(&body, tilt(1e-6), [0.0, 0.0, 2.0]);
    let reference = dop853(&body, &x0, 20.0);
    assert!(
        (reference.gamma[2] - 0.8417).abs() < 1e-3,
        "{:?}",
        reference.gamma
    );
    let exact = ExactSolution::new(&body, &x0).unwrap();
    assert!(!matches!(exact.motion, Motion::Steady { .. }));
    assert!(exact.accuracy.checked_error_at(20.0).is_ok());
    let d = distance(&exact.state_at(20.0), &dop853_at(&body, &x0, 20.0, 1e-14));
    // 1e-8: the criterion (DOP853 at rtol 1e-14 is within 1e-10 of itself at rtol
    // 3e-16 here).
    assert!(d < 1e-8, "{d:e}");
}

#[test]
fn above_routh_threshold_a_small_nutation_is_solved_not_steady() {
    // Issue 10: gamma = (0.001, 0, 0.9999995), omega = (0, 0, 5) was called steady while it
    // nutates (theta from 0.0010 to 0.0012), 1.8e-3 off at t = 10.
    let body = Body::default();
    let x0 = state(&body, [0.001, 0.0, 0.9999995], [0.0, 0.0, 5.0]);
    let exact = ExactSolution::new(&body, &x0).unwrap();
    let Motion::Nutation(nut) = &exact.motion else {
        panic!("a nutation expected, got {:?}", exact.motion);
    };
    let theta_max = nut.u1.acos();
    assert!((theta_max - 0.0012).abs() < 1e-4, "{theta_max}");
    let d = distance(&exact.state_at(10.0), &dop853(&body, &x0, 10.0));
    // The nutation's amplitude in gamma is 2e-4: 1e-9 shows that it is resolved.
    assert!(d < 1e-9, "{d:e}");
    // Negative control: the old verdict, a uniform rotation, is 1e-4 off.
    let Motion::Nutation(_) = exact.motion else {
        unreachable!()
    };
    let rate = exact.reduction.precession_rate(x0.gamma[2]);
    let (s, c) = (10.0 * rate).sin_cos();
    let g = x0.gamma;
    let rotated = [c * g[0] - s * g[1], s * g[0] + c * g[1], g[2]];
    let steady_error = (0..3).fold(0.0_f64, |m, i| {
        m.max((rotated[i] - dop853(&body, &x0, 10.0).gamma[i]).abs())
    });
    assert!(steady_error > 1e-5, "{steady_error:e}");
}

#[test]
fn regular_nutations_near_the_axis_are_solved_in_few_nodes() {
    // Issue 14: the default case at tilts 0.02, 0.0357, 0.05, 0.1, 0.15 was refused as "near a
    // separatrix" after seconds: the convergence test asked the series of dpsi/dsigma for a
    // tail below 2e-14 |b0|, below the round-off floor of its samples (1.3e-14, with |b0| =
    // 0.41 < |b1| = 0.50), and the DCT's own round-off grew with n. DOP853 shows a regular
    // nutation, period 0.96858 at tilt 0.1.
    let body = Body::default();
    for theta in [0.02, 0.0357, 0.05, 0.1, 0.15] {
        let x0 = state(&body, tilt(theta), [0.5, 0.2, 8.0]);
        let exact = ExactSolution::new(&body, &x0).unwrap();
        let Motion::Nutation(nut) = &exact.motion else {
            panic!("tilt {theta}: a nutation expected");
        };
        assert!(nut.nodes <= 1024, "tilt {theta}: {} nodes", nut.nodes);
        if theta == 0.1 {
            assert!((nut.period - 0.96858).abs() < 1e-5, "{}", nut.period);
        }
        let d = distance(&exact.state_at(10.0), &dop853(&body, &x0, 10.0));
        println!(
            "tilt {theta}: T = {}, {} nodes, {d:.1e}",
            nut.period, nut.nodes
        );
        assert!(d < 1e-9, "tilt {theta}: {d:e}");
    }
}

#[test]
fn huge_times_are_refused_with_the_horizon() {
    // Issue 10: `exact --t 1e300` printed a pinned state. The phase error grows like t times
    // the period's error: beyond the horizon the state is refused.
    let body = Body::default();
    let x0 = state(&body, tilt(0.3), [0.5, 0.2, 8.0]);
    let exact = ExactSolution::new(&body, &x0).unwrap();
    let horizon = exact.accuracy.horizon(routh::quadrature::Accuracy::REFUSAL);
    assert!(horizon > 1e3 && horizon < 1e12, "{horizon:e}");
    assert!(exact.accuracy.checked_error_at(0.5 * horizon).is_ok());
    for t in [2.0 * horizon, 1e300, -1e300] {
        assert!(matches!(
            exact.accuracy.checked_error_at(t),
            Err(RouthError::Horizon { .. })
        ));
    }
}

/// SplitMix64: a small deterministic generator for the property test.
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    fn unit(&mut self) -> [f64; 3] {
        let z = self.between(-1.0, 1.0);
        let phi = self.between(0.0, std::f64::consts::TAU);
        let s = (1.0 - z * z).sqrt();
        [s * phi.cos(), s * phi.sin(), z]
    }
}

#[test]
fn exact_agrees_with_dop853_or_refuses_on_500_random_states() {
    // 400 states: random bodies (gravity or not, centre of mass up or down), gamma uniform on
    // the sphere, omega with components log-uniform from 0.03 to 30; 100 states within 1e-3
    // of the top-heavy vertical spin, 50 above and 50 below Routh's threshold. All are
    // regular values (none is steady or on a separatrix to round-off: those are decided by
    // the tests above and in tests/quadrature.rs): at t = 10 the quadrature must solve every
    // one and agree with DOP853 to 1e-8 (issue 14), and its error estimate must not be far
    // below the measured error.
    let mut rng = Random(20261123);
    let mut cases = vec![];
    for _ in 0..400 {
        let radius = rng.between(0.5, 2.0);
        let a = rng.between(-0.6, 0.6) * radius;
        let i1 = rng.between(0.2, 1.0);
        let i3 = rng.between(0.2, 1.9) * i1;
        let gravity = if rng.next() < 0.25 { 0.0 } else { 9.81 };
        let body = Body::new(
            rng.between(0.5, 2.0),
            radius,
            a,
            i1,
            i1,
            i3.min(2.0 * i1),
            gravity,
        )
        .unwrap();
        let size = 10f64.powf(rng.between(-1.5, 1.5));
        let omega = rng.unit().map(|w| w * size);
        cases.push((body, state(&body, rng.unit(), omega), "random"));
    }
    let body = Body::default();
    let threshold = routh_threshold(&body, 1.0);
    for i in 0..100 {
        let spin = if i < 50 {
            threshold * rng.between(1.01, 4.0)
        } else {
            threshold * rng.between(0.05, 0.99)
        };
        let offset = rng.unit().map(|v| v * 1e-3 * rng.next());
        let gamma = [offset[0], offset[1], 1.0];
        let omega = [
            1e-3 * rng.between(-1.0, 1.0),
            1e-3 * rng.between(-1.0, 1.0),
            spin,
        ];
        let label = if i < 50 {
            "above threshold"
        } else {
            "below threshold"
        };
        cases.push((body, state(&body, gamma, omega), label));
    }
    let (mut agreed, mut refused, mut worst, mut worst_ratio) = (0, vec![], 0.0_f64, 0.0_f64);
    for (body, x0, label) in &cases {
        let outcome = ExactSolution::new(body, x0).and_then(|exact| {
            let estimate = exact.accuracy.checked_error_at(10.0)?;
            Ok((exact.state_at(10.0), estimate))
        });
        match outcome {
            Ok((q, estimate)) => {
                let d = distance(&q, &dop853(body, x0, 10.0));
                assert!(d < 1e-8, "{label}: {body:?} {x0:?}: {d:e}");
                // The estimate must not be below the error: checked on the 100 states near the
                // vertical spin, whose errors (up to 5e-10) stand above that of DOP853 at rtol
                // 1e-15 (about 1e-12; at rtol 1e-13 up to 4.6e-10 on the random states).
                if *label != "random" {
                    let fine = distance(&q, &dop853_at(body, x0, 10.0, 1e-15));
                    assert!(
                        fine <= estimate + 1e-11,
                        "{label}: {x0:?}: {fine:e} > estimate {estimate:e}"
                    );
                    if fine > 1e-11 {
                        worst_ratio = worst_ratio.max(fine / estimate);
                    }
                }
                worst = worst.max(d);
                agreed += 1;
            }
            Err(e) => {
                // A separatrix, a horizon, or a motion passing so near the axis (without
                // crossing it) that psi turns faster than 8192 nodes resolve.
                let axis =
                    matches!(&e, RouthError::Singular { reason, .. } if reason.contains("axis"));
                assert!(
                    axis || matches!(
                        e,
                        RouthError::Separatrix { .. } | RouthError::Horizon { .. }
                    ),
                    "{label}: {e}"
                );
                refused.push(format!("{label}: {e}"));
            }
        }
    }
    println!(
        "agreed {agreed}, worst {worst:.1e}, worst measured/estimated near the vertical spin \
         {worst_ratio:.2}; refused {}:",
        refused.len()
    );
    for r in &refused {
        println!("  {r}");
    }
    // Measured (seed 20261123): all 500 agree, worst 5.0e-10 (a state below the threshold);
    // near the vertical spin the measured error is at most 0.18 of the estimate. Before the parameters of the poles (docs/quadrature.md, section 5) 8 of the 50
    // below the threshold were refused with the horizon (estimated error at t = 10 of 1.1e-6
    // to 1.1e-5) and 5 others agreed only to 1.4e-8 .. 2.0e-8: they pass within about 1e-5
    // of the axis, where H1 and H3 (O(1) numbers) fixed the level set only to their round-off
    // over the distance from the pole. Before the piecewise series (issue 14) 49 of these 50
    // were refused as separatrices after seconds.
    assert!(refused.is_empty(), "{refused:?}");
    assert_eq!(agreed, 500);
}

#[test]
fn nutations_within_1e_10_to_1e_15_of_the_pole_agree_with_dop853() {
    // A turning point 1e-13 from the pole with the spin 1.1 times Routh's threshold and a
    // vertical omega was called steady and answered 1.4e-6 off DOP853 at t = 10 with an
    // estimate of 8.8e-11: the search for the turning points stepped 1e-8 in u from a start at
    // a turning point, over the whole nutation (1e-12 wide), and found none. Then the far half
    // of such a nutation computed N (1e-13) in the other pole's frame, a difference of O(1)
    // numbers, which put an error of eps / gap, 1e-3 rad at gap 1e-13, into the advance.
    // Tilts sqrt(2 gap), gap 1e-10 .. 1e-15, at the pole with the centre of mass above it
    // (spins 1.01, 1.1, 2 times its threshold) and at the one with it below (spins 1.1 and 2
    // times the other pole's threshold), the body with a = 0.3 and its mirror a = -0.3, the
    // horizontal omega 0 or +-theta: agreement with DOP853 at rtol 1e-15 to 1e-12 at t = 10
    // (measured: at most 1.1e-15, the round-off of the state; DOP853 at rtol 1e-15 is within
    // about 1e-14 of itself at rtol 3e-16 here), and the estimate not below the error beyond
    // that floor.
    let mut worst = 0.0_f64;
    for a in [0.3, -0.3] {
        let body = Body::new(1.0, 1.0, a, 0.4, 0.4, 0.5, 9.81).unwrap();
        for pole in [1.0_f64, -1.0] {
            let above = a * pole > 0.0;
            let threshold = routh_threshold(&body, if above { pole } else { -pole });
            let factors: &[f64] = if above {
                &[1.01, 1.1, 2.0]
            } else {
                &[1.1, 2.0]
            };
            for &factor in factors {
                for gap in [1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15] {
                    for side in [0.0, 1.0, -1.0] {
                        let theta = (2.0_f64 * gap).sqrt();
                        let gamma = [theta.sin(), 0.0, pole * theta.cos()];
                        let spin = factor * threshold;
                        let x0 = state(&body, gamma, [0.0, side * theta * spin, spin]);
                        let label = format!("a {a} pole {pole} spin {factor} w_c gap {gap:e}");
                        let exact = ExactSolution::new(&body, &x0).expect(&label);
                        let Motion::Nutation(_) = &exact.motion else {
                            panic!("{label}: a nutation expected, got {:?}", exact.motion);
                        };
                        let estimate = exact.accuracy.checked_error_at(10.0).expect(&label);
                        let reference = dop853_at(&body, &x0, 10.0, 1e-15);
                        let d = distance(&exact.state_at(10.0), &reference);
                        assert!(d < 1e-12, "{label}: {d:e}");
                        assert!(d <= estimate + 1e-14, "{label}: {d:e} > {estimate:e}");
                        worst = worst.max(d);
                        // Negative control: the old verdict, a uniform rotation at the
                        // precession rate of the start, is far off.
                        let rate = exact.reduction.precession_rate(x0.gamma[2]);
                        let (s, c) = (10.0 * rate).sin_cos();
                        let g = x0.gamma;
                        let turned = [c * g[0] - s * g[1], s * g[0] + c * g[1], g[2]];
                        let steady_error = (0..3).fold(0.0_f64, |m, i| {
                            m.max((turned[i] - reference.gamma[i]).abs())
                        });
                        assert!(
                            steady_error > 1e3 * d.max(1e-15),
                            "{label}: {steady_error:e}"
                        );
                    }
                }
            }
        }
    }
    println!("worst {worst:.1e}");
}
