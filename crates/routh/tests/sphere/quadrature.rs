//! The exact solution by quadrature (routh-sphere): against integration, reference values of high precision, and its own decisions near the poles, the separatrices and the equilibria.
//!
//! One test binary, one module a topic (issue 32: few binaries, each named after what it proves).

mod exact_decisions {
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
    use routh::state::{Normalise, Point, State};
    use routh::steady::routh_threshold;
    use routh::RouthError;

    /// DOP853 at rtol 1e-13 (atol 1e-15) from `x0` to `t`: at t = 10 its global error on these
    /// motions is below 1e-9 (at most 4.6e-10 on the random states of the property test, against
    /// rtol 3e-16; docs/quadrature.md, section 7), below the 1e-8 compared here.
    fn dop853(body: &Body, x0: &State, t: f64) -> Point {
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
        let rate = exact.reduction.precession_rate(x0.gamma()[2]);
        let (s, c) = (10.0 * rate).sin_cos();
        let g = x0.gamma();
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
        // the tests above and in tests/sphere/quadrature.rs): at t = 10 the quadrature must solve every
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
                    let axis = matches!(&e, RouthError::Singular { reason, .. } if reason.contains("axis"));
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
                            let rate = exact.reduction.precession_rate(x0.gamma()[2]);
                            let (s, c) = (10.0 * rate).sin_cos();
                            let g = x0.gamma();
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
}

mod exact_sweep {
    //! Issue 14, "What it must show": the quadrature solves every regular motion of a sweep of
    //! initial conditions and agrees with DOP853 at t = 10 to 1e-8 (a subset of 240 of the 2,000
    //! cases of `benches/exact_sweep.rs`, with the same generator).

    use crate::sweep_cases as exact_sweep;

    use exact_sweep::{cases, distance, dop853, quadrature, Outcome, AGREEMENT, T};

    #[test]
    fn sweep_of_240_initial_conditions_is_solved_and_agrees_with_dop853() {
        let (mut worst, mut separatrices, mut refused) = (0.0_f64, vec![], vec![]);
        for case in cases(240, 14) {
            match quadrature(&case) {
                Outcome::Solved(state) => {
                    let d = distance(&state, &dop853(&case, T));
                    assert!(d < AGREEMENT, "{case:?}: {d:e}");
                    worst = worst.max(d);
                }
                Outcome::Separatrix(reason) => separatrices.push(format!("{case:?}: {reason}")),
                Outcome::Refused(reason) => refused.push(format!("{case:?}: {reason}")),
            }
        }
        println!("worst {worst:.1e}; separatrices {separatrices:?}; refused {refused:?}");
        // A random initial condition lands on a separatrix (a set of measure zero) with
        // probability zero: no case may be refused, for any reason.
        assert!(separatrices.is_empty() && refused.is_empty());
    }
}

mod solutions {
    //! The exact solution by quadrature against the DOP853 integrator, the nutation period
    //! against the integrator's events, and the degenerate cases.

    // The DOP853 reference of the sweep of issue 14.
    #[allow(dead_code)]
    use crate::sweep_cases as exact_sweep;

    use exact_sweep::dop853_at;
    use routh::body::Body;
    use routh::case::Case;
    use routh::field::vector_field;
    use routh::integrate::{solve, Options, Stop};
    use routh::quadrature::{ExactSolution, Motion, Reduction};
    use routh::state::{Normalise, Point, State};
    use routh::RouthError;
    use std::f64::consts::PI;

    /// Largest difference of the components of two states, relative to the size of each half.
    fn distance(a: &Point, b: &Point) -> f64 {
        let rel = |x: &[f64; 3], y: &[f64; 3]| {
            let scale = x.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(1e-300);
            x.iter()
                .zip(y)
                .fold(0.0_f64, |m, (p, q)| m.max((p - q).abs()))
                / scale
        };
        rel(&a.gamma, &b.gamma).max(rel(&a.m, &b.m))
    }

    fn default_case() -> (Body, State) {
        let case = Case::default_case().unwrap();
        (case.body("").unwrap(), case.initial)
    }

    #[test]
    fn state_at_zero_is_the_initial_state() {
        let (body, x0) = default_case();
        let exact = ExactSolution::new(&body, &x0).unwrap();
        let d = distance(&exact.state_at(0.0), &x0.point());
        assert!(d < 1e-12, "{d:e}");
    }

    /// The test cases: the default case and four others.
    fn cases() -> Vec<(&'static str, Body, State)> {
        let (body, x0) = default_case();
        let tilted = |theta: f64, phi: f64| {
            let (s, c) = theta.sin_cos();
            [s * phi.cos(), s * phi.sin(), c]
        };
        let state = |body: &Body, gamma, omega| {
            State::from_omega(body, gamma, omega, Normalise::Rescale).unwrap()
        };
        let bottom = Body::new(2.0, 0.5, 0.1, 0.05, 0.05, 0.08, 9.81).unwrap();
        let free = Body::new(1.0, 1.0, 0.2, 0.6, 0.6, 0.8, 0.0).unwrap();
        let flipped = Body::new(1.5, 1.0, -0.25, 0.5, 0.5, 0.4, 9.81).unwrap();
        vec![
            ("default: top-heavy, tilt 0.3, gravity", body, x0),
            (
                "small tilt 0.05, centre of mass below, gravity",
                bottom,
                state(&bottom, tilted(PI - 0.05, 0.4), [0.3, -0.1, 3.0]),
            ),
            (
                "large tilt 1.3, no gravity",
                free,
                state(&free, tilted(1.3, -1.0), [1.0, 0.5, 4.0]),
            ),
            (
                "large tilt 2.0, a < 0 (centre of mass above at gamma3 < 0), gravity",
                flipped,
                state(&flipped, tilted(2.0, 2.5), [2.0, -1.0, 6.0]),
            ),
            (
                "small tilt 0.1, top-heavy, slow spin below Routh's threshold",
                body,
                state(&body, tilted(0.1, 0.0), [0.2, 0.0, 1.5]),
            ),
        ]
    }

    #[test]
    fn quadrature_agrees_with_dop853_at_10_periods_and_t_1000() {
        for (name, body, x0) in cases() {
            let exact = ExactSolution::new(&body, &x0).unwrap();
            let period = exact.period().expect("a nutation");
            // At 10 periods DOP853 at rtol = 1e-13 is accurate to well below 1e-9.
            let d10 = distance(
                &exact.state_at(10.0 * period),
                &dop853_at(&body, &x0, 10.0 * period, 1e-13),
            );
            // At t = 1000 (hundreds of periods) the integrator's own global error at rtol = 1e-13
            // reaches 2e-9 to 1e-7 (the last case passes near the unstable vertical spin); it
            // falls steadily with rtol toward the quadrature (1e-7, 9e-9, 1.1e-9, 6.9e-10 at
            // rtol = 1e-13, 1e-14, 1e-15, 5e-16 for that case; docs/quadrature.md), so the 1e-9
            // comparison uses rtol = 5e-16.
            let d1000 = distance(
                &exact.state_at(1000.0),
                &dop853_at(&body, &x0, 1000.0, 5e-16),
            );
            println!("{name}: T = {period}, at 10 T: {d10:.2e}, at t = 1000: {d1000:.2e}");
            assert!(d10 < 1e-9, "{name}: {d10:e}");
            assert!(d1000 < 1e-9, "{name}: {d1000:e}");
        }
    }

    #[test]
    fn wrong_integrals_disagree_with_dop853() {
        // Negative control: the same comparison fails for a quadrature of a perturbed state.
        let (body, x0) = default_case();
        let mut perturbed = x0;
        let mut moved = perturbed.point();
        moved.m[2] *= 1.0 + 1e-7;
        perturbed = State::of_point(&moved, Normalise::Reject).unwrap();
        let exact = ExactSolution::new(&body, &perturbed).unwrap();
        let d = distance(&exact.state_at(100.0), &dop853_at(&body, &x0, 100.0, 1e-13));
        assert!(d > 1e-7, "{d:e}");
    }

    #[test]
    fn reduced_equation_matches_the_field() {
        // Q(u0) = (du/dt)^2 and the precession rate from the field at the initial states.
        for (name, body, x0) in cases() {
            let red = Reduction::of_state(&body, &x0).unwrap();
            let x = x0.to_array();
            let f = vector_field(&body, &x);
            let u = x[2];
            let q = red.q(u);
            assert!(
                (q - f[2] * f[2]).abs() < 1e-12 * red.q_scale(u),
                "{name}: {q} vs {}",
                f[2] * f[2]
            );
            let psi_dot = (x[0] * f[1] - x[1] * f[0]) / (x[0] * x[0] + x[1] * x[1]);
            let rate = red.precession_rate(u);
            assert!(
                (psi_dot - rate).abs() < 1e-12 * rate.abs().max(1.0),
                "{name}: {psi_dot} vs {rate}"
            );
        }
    }

    /// The time between successive zeros of d gamma3/dt located by DOP853 (rtol = 1e-13).
    fn event_times(body: &Body, x0: &State, count: usize) -> Vec<f64> {
        let opts = Options::new(1e-13, 1e-15).unwrap();
        let field = |_t: f64, x: &[f64; 6]| vector_field(body, x);
        let tilt_rate = |_t: f64, x: &[f64; 6]| vector_field(body, x)[2];
        let (mut t, mut y) = (0.0, x0.to_array());
        let mut times = vec![];
        while times.len() < count {
            // Leave the previous event behind before looking for the next one.
            if !times.is_empty() {
                (_, y, t, _) =
                    solve(&field, t, y, t + 1e-3, &opts, None, None, &mut |_, _| {}).unwrap();
            }
            let (stop, ye, te, _) = solve(
                &field,
                t,
                y,
                t + 1e3,
                &opts,
                None,
                Some(&tilt_rate),
                &mut |_, _| {},
            )
            .unwrap();
            assert_eq!(stop, Stop::Event);
            times.push(te);
            (t, y) = (te, ye);
        }
        times
    }

    #[test]
    fn period_equals_time_between_turning_point_events() {
        for (name, body, x0) in cases() {
            let period = ExactSolution::new(&body, &x0).unwrap().period().unwrap();
            let times = event_times(&body, &x0, 5);
            for w in times.windows(3) {
                // Events alternate between the two turning points: two of them per period.
                let rel = ((w[2] - w[0]) - period).abs() / period;
                println!(
                    "{name}: T = {period}, events {:.16}: {rel:.2e}",
                    w[2] - w[0]
                );
                assert!(rel < 1e-10, "{name}: {rel:e}");
            }
            // Negative control: the time between consecutive events is half a period.
            assert!(((times[1] - times[0]) - period).abs() > 0.1 * period);
        }
    }

    #[test]
    fn steady_motion_is_a_rotation_about_the_axis() {
        // A steady precession (double root of Q) from the stationary motions: reported as steady,
        // and its uniform rotation agrees with the integrator.
        let body = Body::default();
        let steady = routh::steady::steady_precessions(&body, 1.0, 8.0).unwrap()[0];
        let exact = ExactSolution::new(&body, &steady.state).unwrap();
        assert!(matches!(exact.motion, Motion::Steady { .. }));
        assert_eq!(exact.period(), None);
        let (u1, u2) = exact.turning_points();
        assert_eq!(u1, u2);
        let d = distance(
            &exact.state_at(20.0),
            &dop853_at(&body, &steady.state, 20.0, 1e-13),
        );
        assert!(d < 1e-9, "{d:e}");
    }

    #[test]
    fn sleeping_top_on_the_axis_is_steady_even_when_unstable() {
        // gamma = e3 with omega along e3: the angle psi is undefined; the state is an equilibrium
        // of (mg-eq), whether above Routh's threshold or below it.
        let body = Body::default();
        for spin in [1.0, 8.0] {
            let x0 = State::from_omega(&body, [0.0, 0.0, 1.0], [0.0, 0.0, spin], Normalise::Reject)
                .unwrap();
            let exact = ExactSolution::new(&body, &x0).unwrap();
            assert!(matches!(exact.motion, Motion::Steady { u, .. } if u == 1.0));
            assert_eq!(exact.state_at(123.4), x0.point());
        }
    }

    #[test]
    fn motion_through_the_axis_agrees_with_dop853() {
        // gamma = e3 with a horizontal angular velocity: the nutation reaches the pole, where sin
        // theta = 0 and psi is undefined, once per period; the reconstruction stays finite and
        // smooth through it.
        let body = Body::default();
        let x0 =
            State::from_omega(&body, [0.0, 0.0, 1.0], [0.4, 0.1, 8.0], Normalise::Reject).unwrap();
        let exact = ExactSolution::new(&body, &x0).unwrap();
        let Motion::Nutation(nut) = &exact.motion else {
            panic!("a nutation expected");
        };
        assert!(nut.through_top && nut.u2 == 1.0);
        assert!(distance(&exact.state_at(0.0), &x0.point()) < 1e-13);
        for t in [0.3, nut.period, 10.0 * nut.period + 0.1, 100.0] {
            let q = exact.state_at(t);
            assert!(q.gamma.iter().chain(&q.m).all(|v| v.is_finite()));
            let d = distance(&q, &dop853_at(&body, &x0, t, 1e-13));
            println!("through the axis, t = {t}: {d:.2e}");
            assert!(d < 1e-8, "t = {t}: {d:e}");
        }
    }

    /// A point on the homoclinic orbit of the unstable vertical spin at `spin` (below Routh's
    /// threshold), at `gamma3 = u`: the same integrals, omega_n from `(du/dt)^2 = Q(u)`.
    pub(super) fn on_separatrix(body: &Body, spin: f64, u: f64) -> State {
        let top = routh::steady::vertical_spin_state(body, 1.0, spin).unwrap();
        let red = Reduction::of_state(body, &top).unwrap();
        let s = (1.0 - u * u).sqrt();
        let q = red.q(u);
        assert!(q > 0.0);
        let (gamma, omega) = red.omega(u, s, 0.0, q.sqrt() / s, red.jellett_quotient(u));
        State::from_omega(body, gamma, omega, Normalise::Rescale).unwrap()
    }

    #[test]
    fn separatrix_is_reported_not_nan() {
        let body = Body::default();
        let spin = 0.5 * routh::steady::routh_threshold(&body, 1.0);
        let x0 = on_separatrix(&body, spin, 0.9);
        match ExactSolution::new(&body, &x0) {
            Err(RouthError::Separatrix { u_max, reason, .. }) => {
                assert!(u_max > 0.999, "{u_max}");
                assert!(reason.contains("double root") || reason.contains("separatrix"));
            }
            other => panic!("expected a separatrix error, got {other:?}"),
        }
    }

    #[test]
    fn near_separatrix_has_a_long_period_that_still_agrees() {
        // Negative control of the separatrix detection: slightly off the homoclinic orbit the
        // period is long but finite, and the quadrature still agrees with the integrator.
        let body = Body::default();
        let spin = 0.5 * routh::steady::routh_threshold(&body, 1.0);
        let mut x0 = on_separatrix(&body, spin, 0.9);
        let mut moved = x0.point();
        moved.m[0] *= 1.2;
        x0 = State::of_point(&moved, Normalise::Reject).unwrap();
        let exact = ExactSolution::new(&body, &x0).unwrap();
        let period = exact.period().unwrap();
        let separated = ExactSolution::new(&body, &on_separatrix(&body, spin, 0.5));
        assert!(separated.is_err());
        let d = distance(
            &exact.state_at(period),
            &dop853_at(&body, &x0, period, 1e-13),
        );
        println!("near the separatrix: T = {period}, {d:.2e}");
        assert!(d < 1e-8, "{d:e}");
    }

    #[test]
    fn asymmetric_body_is_refused() {
        let body = Body::new(1.0, 1.0, 0.3, 0.4, 0.45, 0.5, 9.81).unwrap();
        let x0 =
            State::from_omega(&body, [0.0, 0.6, 0.8], [0.1, 0.2, 3.0], Normalise::Reject).unwrap();
        assert!(matches!(
            ExactSolution::new(&body, &x0),
            Err(RouthError::NotSymmetric { .. })
        ));
    }

    #[test]
    fn negative_times_agree_with_backward_integration() {
        for (name, body, x0) in cases() {
            let exact = ExactSolution::new(&body, &x0).unwrap();
            let d = distance(&exact.state_at(-7.3), &dop853_at(&body, &x0, -7.3, 1e-13));
            assert!(d < 1e-10, "{name}: {d:e}");
        }
    }

    #[test]
    fn period_agrees_with_gauss_legendre_in_the_substituted_variable() {
        // An independent rule for T = 2 int_0^pi (du/dsigma) / sqrt(Q(u(sigma))) dsigma, with Q
        // itself (no divided differences): Gauss-Legendre on [0, pi], 100 and 200 nodes. Q loses
        // digits near the turning points, so agreement to 1e-9 is what this rule can show.
        use routh::quadrature::gauss::GaussLegendre;
        for (name, body, x0) in cases() {
            let exact = ExactSolution::new(&body, &x0).unwrap();
            let Motion::Nutation(nut) = &exact.motion else {
                panic!("{name}: a nutation expected");
            };
            let half = 0.5 * (nut.u2 - nut.u1);
            let mid = 0.5 * (nut.u2 + nut.u1);
            let period = |n: usize| {
                let integrand = |x: f64| {
                    let sigma = std::f64::consts::PI * x;
                    let q = exact.reduction.q(mid - half * sigma.cos());
                    half * sigma.sin() / q.sqrt()
                };
                2.0 * std::f64::consts::PI * GaussLegendre::new(n).integrate(integrand)
            };
            let (t100, t200) = (period(100), period(200));
            let rel = (t200 - nut.period).abs() / nut.period;
            // This rule evaluates Q itself near the turning points, where it is a small difference
            // of larger terms, so the rule has an error of its own: its change from 100 to 200
            // nodes (9e-10 on the small-tilt case, 1e-10 or less on the others). T must agree
            // within 1e-9 or within four times that change, whichever is larger.
            let allowed = 1e-9_f64.max(4.0 * (t200 - t100).abs() / nut.period);
            println!(
                "{name}: T = {}, Gauss-Legendre {t100} {t200}: {rel:.1e} (allowed {allowed:.1e})",
                nut.period
            );
            assert!(rel < allowed, "{name}: {rel:e}");
        }
    }
}

mod quadrature_reference {
    //! The exact solution by quadrature against stored numbers of an earlier version: a change
    //! that only reorganises the arithmetic (hoisting, fewer automatic-differentiation passes)
    //! must leave the nutation period and the advance per period equal to round-off, the error
    //! estimates nearly equal, and the same decisions (steady, nutation, which refusal).
    //!
    //! The data file `tests/data/quadrature_reference.csv` was written by this test in its write
    //! mode on commit 1276152 (before the quadrature was made cheaper, issue 13, and before the
    //! field was written with exact identities, issue 12):
    //! `ROUTH_WRITE_QUADRATURE_REFERENCE=1 cargo test -p routh --test sphere quadrature:: quadrature_reference`.
    //! 31 lines were rewritten by issue 33 (every other line still agrees with the stored one;
    //! the rewrite kept the stored line wherever the new one agrees with it to this test's
    //! tolerances, and took the new one elsewhere): the two states built on the separatrix of
    //! the vertical spin (`off 0`) are refused as separatrices (their turning point at the pole
    //! has Q' within its round-off of 0) instead of by a singular quadrature; and the steady
    //! precessions (`steady ... off ...`, 29 lines) have new estimates, the distance of the state
    //! from the relative equilibrium bounded by the tilt's amplitude (the local quadratic of Q
    //! with the round-off of Q' and of du/dt) instead of the residual of the field (which
    //! underestimated it: a state 1e-13 off was 1.1e-13 off DOP853 at t = 1 with an estimate
    //! of 2.8e-14) or the width of the search (which overestimated it 1000 times), and the
    //! rates of the states 1e-13 off move by up to 3e-13 (the fit weighs gamma and M in the
    //! problem's units).
    //! 19 more lines were rewritten (the same rule) when gamma's normalisation was made free of
    //! overflow (issue 33: the largest component divided out first, so a unit gamma may move by
    //! an ulp) and the steady precessions were found in the motion's units: the states near the
    //! separatrix (lines 266 to 303), whose period moves by d(period)/d(state) times an ulp, up
    //! to 5e-5 relative for a state 1e-12 off it, and 15 others within 1e-13 in value whose
    //! estimates moved by more than 1 %.

    // Only the generator of the states is used here.
    #[allow(dead_code)]
    use crate::sweep_cases as exact_sweep;

    use routh::body::Body;
    use routh::quadrature::{ExactSolution, Motion, Reduction};
    use routh::state::{Normalise, State};
    use routh::steady::{routh_threshold, steady_precessions, vertical_spin_state};
    use routh::RouthError;

    const DATA: &str = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/quadrature_reference.csv"
    );

    /// The period and the advance must agree to this, relative (the advance relative to
    /// `max(|advance|, 1)`): both are sums of a few hundred samples, each a short chain of
    /// operations of relative round-off a few eps; reordering that arithmetic moves them by a
    /// few eps times the condition of the sums, measured below 1e-15, so 1e-13 leaves a margin of
    /// 100 and still catches any change of what is computed (the negative control moves the
    /// state by 1e-11 and is seen).
    const AGREEMENT: f64 = 1e-13;
    /// The error estimates must agree to this, relative: the sensitivity estimate is the
    /// difference of two solutions of level sets 1e4 round-offs apart, about 1e-12 relative, so a
    /// round-off change of 1e-16 in each moves it by 1e-4 relative.
    const ESTIMATE_AGREEMENT: f64 = 1e-2;
    /// Estimates below this (relative accuracies under 64 eps) are the round-off of the field
    /// itself, e.g. the residual of a steady precession, which any rewrite of the field's formula
    /// moves by O(1) of itself (the exact identities of issue 12 moved one from 2.49e-17 to
    /// 2.43e-17): their differences are taken relative to this floor.
    const ESTIMATE_FLOOR: f64 = 64.0 * f64::EPSILON;

    fn state(body: &Body, gamma: [f64; 3], omega: [f64; 3]) -> State {
        State::from_omega(body, gamma, omega, Normalise::Rescale).unwrap()
    }

    /// The states: 200 of issue 14's sweep (random bodies, tilts over (0, pi), spins 0.1 to 30,
    /// gravity on and off, centre of mass up and down); 60 near the poles (turning points
    /// 1e-6 .. 1e-15 from either pole, above and below Routh's threshold); 48 near the
    /// separatrix of the unstable vertical spin (on it, and 10^-12 .. 10^-1 off it); 48 near
    /// steady precessions (on them, and 10^-13 .. 10^-2 off them).
    fn states() -> Vec<(String, Body, State)> {
        let mut out: Vec<(String, Body, State)> = exact_sweep::cases(200, 13)
            .into_iter()
            .enumerate()
            .map(|(i, c)| (format!("sweep {i}"), c.body, c.state))
            .collect();
        for a in [0.3, -0.3] {
            let body = Body::new(1.0, 1.0, a, 0.4, 0.4, 0.5, 9.81).unwrap();
            for pole in [1.0_f64, -1.0] {
                let threshold = routh_threshold(&body, if a * pole > 0.0 { pole } else { -pole });
                for factor in [0.5, 1.1, 3.0] {
                    for gap in [1e-6, 1e-9, 1e-12, 1e-14, 1e-15] {
                        let theta = (2.0_f64 * gap).sqrt();
                        let spin = factor * threshold.max(1.0);
                        let gamma = [theta.sin(), 0.0, pole * theta.cos()];
                        out.push((
                            format!("pole a {a} p {pole} spin {factor} gap {gap:e}"),
                            body,
                            state(&body, gamma, [0.0, theta * spin, spin]),
                        ));
                    }
                }
            }
        }
        let body = Body::default();
        for factor in [0.3, 0.5, 0.8] {
            let spin = factor * routh_threshold(&body, 1.0);
            let top = vertical_spin_state(&body, 1.0, spin).unwrap();
            let red = Reduction::of_state(&body, &top).unwrap();
            for u in [0.9_f64, 0.5, -0.2, -0.7] {
                let q = red.q(u);
                if q <= 0.0 {
                    continue;
                }
                let s = (1.0 - u * u).sqrt();
                let (gamma, omega) = red.omega(u, s, 0.0, q.sqrt() / s, red.jellett_quotient(u));
                let on = state(&body, gamma, omega);
                for off in [0.0, 1e-12, 1e-8, 1e-4, 1e-1] {
                    let mut x = on;
                    let mut moved = x.point();
                    moved.m[0] *= 1.0 + off;
                    x = State::of_point(&moved, Normalise::Reject).unwrap();
                    out.push((format!("separatrix spin {spin} u {u} off {off:e}"), body, x));
                }
            }
        }
        for (theta, spin) in [(0.3, 8.0), (1.0, 8.0), (1.3, 5.0), (2.5, 6.0)] {
            for (k, p) in steady_precessions(&body, theta, spin)
                .unwrap()
                .into_iter()
                .enumerate()
            {
                for off in [0.0, 1e-13, 1e-10, 1e-7, 1e-4, 1e-2] {
                    let mut x = p.state;
                    let mut moved = x.point();
                    moved.m[0] += off * (1.0 + moved.m[0].abs());
                    x = State::of_point(&moved, Normalise::Reject).unwrap();
                    out.push((format!("steady {theta} {spin} {k} off {off:e}"), body, x));
                }
            }
        }
        out
    }

    /// What the quadrature gives for one state, as one line of the data file.
    fn outcome(body: &Body, x: &State) -> String {
        match ExactSolution::new(body, x) {
            Ok(exact) => match &exact.motion {
                Motion::Nutation(n) => format!(
                    "nutation,{:e},{:e},{:e},{:e}",
                    n.period, n.advance, n.period_error, n.advance_error
                ),
                Motion::Steady { precession, .. } => {
                    format!("steady,{precession:e},0,{:e},0", exact.accuracy.initial)
                }
            },
            Err(e) => {
                let kind = match e {
                    RouthError::Separatrix { .. } => "separatrix",
                    RouthError::Singular { .. } => "singular",
                    _ => "other",
                };
                format!("{kind},0,0,0,0")
            }
        }
    }

    /// The fields of a line: kind and four numbers.
    fn parse(line: &str) -> (String, [f64; 4]) {
        let mut fields = line.split(',');
        let kind = fields.next().unwrap().to_string();
        let numbers = std::array::from_fn(|_| fields.next().unwrap().parse().unwrap());
        (kind, numbers)
    }

    /// Relative differences of (value 1, value 2) and of the two estimates between two lines.
    fn differences(a: [f64; 4], b: [f64; 4]) -> ([f64; 2], [f64; 2]) {
        let rel = |x: f64, y: f64, floor: f64| (x - y).abs() / x.abs().max(y.abs()).max(floor);
        (
            [rel(a[0], b[0], f64::MIN_POSITIVE), rel(a[1], b[1], 1.0)],
            [
                rel(a[2], b[2], ESTIMATE_FLOOR),
                rel(a[3], b[3], ESTIMATE_FLOOR),
            ],
        )
    }

    #[test]
    fn exact_solution_equals_the_stored_one_to_round_off() {
        let states = states();
        let lines: Vec<String> = states.iter().map(|(_, b, x)| outcome(b, x)).collect();
        if std::env::var_os("ROUTH_WRITE_QUADRATURE_REFERENCE").is_some() {
            std::fs::write(DATA, lines.join("\n") + "\n").unwrap();
            return;
        }
        let data = std::fs::read_to_string(DATA).expect(DATA);
        let stored: Vec<&str> = data.lines().collect();
        assert_eq!(stored.len(), states.len());
        let (mut worst, mut worst_estimate) = (0.0_f64, 0.0_f64);
        let mut kinds = std::collections::BTreeMap::new();
        for ((label, _, _), (line, old)) in states.iter().zip(lines.iter().zip(&stored)) {
            let (kind, new) = parse(line);
            let (old_kind, old) = parse(old);
            assert_eq!(kind, old_kind, "{label}: {line} against {old:?}");
            *kinds.entry(kind).or_insert(0) += 1;
            let (values, estimates) = differences(new, old);
            for d in values {
                assert!(d <= AGREEMENT, "{label}: {line} against {old:?}: {d:e}");
                worst = worst.max(d);
            }
            for d in estimates {
                assert!(
                    d <= ESTIMATE_AGREEMENT,
                    "{label}: estimates {line} against {old:?}: {d:e}"
                );
                worst_estimate = worst_estimate.max(d);
            }
        }
        println!(
            "{} states {kinds:?}: worst relative difference {worst:.1e}, of the estimates \
         {worst_estimate:.1e}",
            states.len()
        );
        // The data must hold every kind of decision, or the comparison of refusals is empty.
        for kind in ["nutation", "steady", "separatrix"] {
            assert!(
                kinds.get(kind).copied().unwrap_or(0) > 0,
                "{kind}: {kinds:?}"
            );
        }
        // Negative control: states moved by 1e-11 relative (the momentum) change the period or
        // the advance by more than AGREEMENT against the stored numbers.
        let moved = states
            .iter()
            .zip(&stored)
            .take(20)
            .filter(|(_, old)| old.starts_with("nutation"))
            .filter(|((_, body, x), old)| {
                let mut moved = x.point();
                moved.m = moved.m.map(|m| m * (1.0 + 1e-11));
                let x = State::of_point(&moved, Normalise::Reject).unwrap();
                let (_, new) = parse(&outcome(body, &x));
                let (values, _) = differences(new, parse(old).1);
                values[0].max(values[1]) > AGREEMENT
            })
            .count();
        assert!(moved >= 10, "only {moved} of 20 moved states seen");
    }
}

mod exact_in_any_units {
    //! Issue 33: the exact solution answers the same whatever the units. The same motion in
    //! other units (masses, lengths and times scaled) has the same solution, converted; the
    //! reproducers (the default case with m, I1, I3 scaled by 1e12 called steady; m = 3e6 alone
    //! called steady; m = 1e30 answering another omega; a slender body near the axis 4e-3 off
    //! with an estimate of 1e-12) agree with DOP853 within the estimate, or are refused; and the
    //! precession of the symmetry axis in space agrees with the motion in space integrated.

    // The DOP853 reference of the sweep of issue 14.
    #[allow(dead_code)]
    use crate::sweep_cases as exact_sweep;

    use exact_sweep::{against_dop853, distance, dop853_at};
    use proptest::prelude::*;
    use proptest::test_runner::{RngSeed, TestCaseError};
    use routh::body::Body;
    use routh::integrate::{solve_dense, Options};
    use routh::motion::{initial_full, quaternion, rotate, FullMotion, FULL_DIM};
    use routh::quadrature::{ExactSolution, Motion};
    use routh::state::{Normalise, Point, State};
    use routh::steady::{routh_threshold, steady_precessions};
    use routh::units::{scaled_body, scaled_point, scaled_state, Units};
    use routh::RouthError;
    use std::f64::consts::{PI, TAU};

    pub(super) fn state(body: &Body, gamma: [f64; 3], omega: [f64; 3]) -> State {
        State::from_omega(body, gamma, omega, Normalise::Rescale).unwrap()
    }

    /// The same motion in other units: the body and the state scaled in mass by `k`, length by
    /// `l` and time by `s` (the library's [`scaled_body`] and [`scaled_state`]).
    pub(super) fn scaled(body: &Body, x: &State, factors: [f64; 3]) -> (Body, State) {
        (
            scaled_body(body, factors).unwrap(),
            scaled_state(x, factors).unwrap(),
        )
    }

    /// The relative difference of two numbers against `scale`.
    fn off(a: f64, b: f64, scale: f64) -> f64 {
        (a - b).abs() / scale
    }

    /// How far the solution of the copy (in units scaled by `factors`) is from the original's,
    /// converted: the largest relative difference of the turning points, the period, the
    /// advances, the steady rate and the states at three times, or why they cannot be compared.
    fn copy_difference(
        original: &ExactSolution,
        copy: &ExactSolution,
        factors: [f64; 3],
    ) -> Result<f64, String> {
        let s = factors[2];
        let (lo, hi) = original.turning_points();
        let (clo, chi) = copy.turning_points();
        let mut worst = off(lo, clo, 1.0).max(off(hi, chi, 1.0));
        match (&original.motion, &copy.motion) {
            (Motion::Nutation(a), Motion::Nutation(b)) => {
                worst = worst
                    .max(off(b.period, s * a.period, s * a.period))
                    .max(off(a.advance, b.advance, a.advance.abs().max(1.0)))
                    .max(off(
                        a.axis_advance,
                        b.axis_advance,
                        a.axis_advance.abs().max(1.0),
                    ));
            }
            (
                Motion::Steady {
                    precession: a,
                    initial,
                    ..
                },
                Motion::Steady { precession: b, .. },
            ) => {
                // Against the rate of the motion, |omega|, where the precession is near 0.
                let spin = initial.omega(&original.body);
                let scale = a.abs().max(spin.iter().fold(0.0, |m, w| m.max(w.abs())));
                worst = worst.max(off(s * b, *a, scale));
            }
            (a, b) => return Err(format!("{a:?} against {b:?}")),
        }
        let period = original.period().unwrap_or(1.0);
        for t in [0.0, 0.37 * period, 2.9 * period] {
            let converted = scaled_point(&original.state_at(t), factors);
            worst = worst.max(distance(&copy.state_at(s * t), &converted));
        }
        Ok(worst)
    }

    /// The largest difference of the solutions of the default case and of its copies in decimal
    /// units (by 1e12, 3e6: see `copy_difference`): each copy is the original up to the
    /// rounding of its numbers, a few eps, which the quadrature carries to the period and the
    /// states with the condition of the motion (measured: at most 2.2e-14 here, and 2.9e-13 on
    /// random motions away from the separatrices; near Routh's threshold the condition made
    /// 1.8e-12, which is why the property test copies by powers of two).
    const COPY_AGREEMENT: f64 = 1e-12;

    /// The largest difference of the solutions of a copy in units scaled by powers of two (see
    /// `random_factors`): the copy is the same problem to the bit, made dimensionless into the
    /// same numbers (`Units::binary`), so the solutions are one (measured: 0 on all 160 cases
    /// of the property test); 4 eps allows a rounding in the conversion back.
    const EXACT_COPY_AGREEMENT: f64 = 4.0 * f64::EPSILON;

    /// DOP853's own error beside its measured spread (rtol 1e-13 against 1e-12): the distance
    /// is relative to |M| and gamma of size 1, rounded to a few eps in each state; 1e-12 is
    /// above that and far below the errors the test is about (4e-3 for the slender body).
    const DOP853_FLOOR: f64 = 1e-12;

    /// Where a random state starts.
    #[derive(Debug, Clone, Copy)]
    pub(super) enum Start {
        /// gamma uniform on the sphere, omega of any direction, 0.1 to 20 rates of the fall.
        Anywhere,
        /// gamma within 1e-9 to 1e-3 of a pole, omega of any direction.
        NearTheAxis,
        /// The top-heavy vertical spin at 0.9 to 1.1 times Routh's threshold, tipped by 1e-9 to
        /// 1e-3 (in gamma and in the horizontal omega).
        NearTheThreshold,
    }

    /// A random Routh sphere in its own units (m = R = 1; I1 from 0.05 to 1, I3 / I1 from 1e-3,
    /// slender, to 2, flat, the triangle inequality's limit; a of either sign; G = 9.81 or 0)
    /// and a random state of a random `Start`.
    pub(super) fn random_problem() -> impl Strategy<Value = (Body, State, Start)> {
        let unit = || [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0];
        (
            (
                -1.3f64..0.0,
                -3.0f64..2f64.log10(),
                0.05f64..0.8,
                any::<bool>(),
            ),
            (any::<bool>(), 0usize..3, any::<bool>()),
            (unit(), unit(), -1.0f64..1.3, -9.0f64..-3.0, 0.9f64..1.1),
        )
            .prop_map(
                |((log_i1, log_ratio, a, up), (gravity, kind, top), (g, w, log_w, log_near, f))| {
                    let start =
                        [Start::Anywhere, Start::NearTheAxis, Start::NearTheThreshold][kind];
                    let i1 = 10f64.powf(log_i1);
                    let i3 = (i1 * 10f64.powf(log_ratio)).min(2.0 * i1);
                    let sign = if up { 1.0 } else { -1.0 };
                    // The threshold exists for the top-heavy pole, with gravity.
                    let gravity = gravity || matches!(start, Start::NearTheThreshold);
                    let g_value = if gravity { 9.81 } else { 0.0 };
                    let body = Body::new(1.0, 1.0, sign * a, i1, i1, i3, g_value).unwrap();
                    let pole = if top { 1.0 } else { -1.0 };
                    let near = 10f64.powf(log_near);
                    let size = 10f64.powf(log_w) * g_value.sqrt().max(1.0);
                    let (gamma, omega) = match start {
                        Start::Anywhere => {
                            let norm = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
                            let gamma = if norm > 1e-3 { g } else { [0.0, 0.0, 1.0] };
                            (gamma, w.map(|c| c * size))
                        }
                        Start::NearTheAxis => {
                            ([near * g[0], near * g[1], pole], w.map(|c| c * size))
                        }
                        Start::NearTheThreshold => {
                            let pole = sign;
                            let spin = f * routh_threshold(&body, pole);
                            (
                                [near * g[0], near * g[1], pole],
                                [near * w[0], near * w[1], spin],
                            )
                        }
                    };
                    (body, state(&body, gamma, omega), start)
                },
            )
    }

    /// Scale factors of mass (`2^-100` to `2^100`, 1e-30 to 1e30), length (`4^-16` to `4^16`,
    /// 2e-10 to 4e9) and time (`2^-17` to `2^17`, 8e-6 to 1.3e5): powers of two (of four for
    /// the length, whose square root the time unit takes), so that the copy is the original
    /// problem exactly, not one rounded into other significands. (A copy by 1e12 is another
    /// problem, a few eps away, whose difference measures the condition of the motion, up to
    /// 1.8e-12 near Routh's threshold; those copies are checked on the default case, whose
    /// condition is known: `the_scaled_default_case_is_the_default_case`.)
    pub(super) fn random_factors() -> impl Strategy<Value = [f64; 3]> {
        (-100i32..=100, -16i32..=16, -17i32..=17)
            .prop_map(|(k, l, s)| [2f64.powi(k), 4f64.powi(l), 2f64.powi(s)])
    }

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: 160,
            failure_persistence: None,
            rng_seed: RngSeed::Fixed(33),
            ..ProptestConfig::default()
        })]

        /// Issue 33, item 7 for `exact`: a random body and state (see `random_problem`) and its
        /// copy in units scaled by `factors`. (a) The copy's solution is the original's,
        /// converted, within `EXACT_COPY_AGREEMENT`, or both are refused alike. (b) The original's state at 4 units of time of its motion
        /// agrees with DOP853 at rtol 1e-13 within its error estimate plus DOP853's error (its
        /// spread against rtol 1e-12, and `DOP853_FLOOR`). A refusal is allowed; an answer
        /// whose estimate does not cover its error is not.
        #[test]
        fn exact_agrees_with_its_scaled_copy_and_with_dop853(
            (body, x0, start) in random_problem(),
            factors in random_factors(),
        ) {
            let label = format!("{start:?} {body:?} {x0:?} copied by {factors:?}");
            let (copy_body, copy_x0) = scaled(&body, &x0, factors);
            let t = 4.0 * Units::of(&body, &x0.omega(&body)).time();
            match (
                ExactSolution::new(&body, &x0),
                ExactSolution::new(&copy_body, &copy_x0),
            ) {
                (Ok(original), Ok(copy)) => {
                    let d = copy_difference(&original, &copy, factors)
                        .map_err(|e| TestCaseError::fail(format!("{label}: {e}")))?;
                    prop_assert!(d <= EXACT_COPY_AGREEMENT, "{}: {:e}", label, d);
                    if let Ok(estimate) = original.accuracy.checked_error_at(t) {
                        let reference = dop853_at(&body, &x0, t, 1e-13);
                        let spread = distance(&reference, &dop853_at(&body, &x0, t, 1e-12));
                        let d = distance(&original.state_at(t), &reference);
                        prop_assert!(
                            d <= estimate + spread + DOP853_FLOOR,
                            "{}: at t = {}: {:e} off DOP853, estimate {:e}, spread {:e}",
                            label, t, d, estimate, spread
                        );
                    }
                }
                (Err(a), Err(b)) => prop_assert_eq!(
                    std::mem::discriminant(&a),
                    std::mem::discriminant(&b),
                    "{}: {} against {}",
                    label,
                    a,
                    b
                ),
                (a, b) => prop_assert!(false, "{}: {:?} against {:?}", label, a.err(), b.err()),
            }
        }
    }

    #[test]
    fn a_copy_off_by_1e_6_is_seen() {
        // Negative control of `exact_agrees_with_its_scaled_copy_and_with_dop853` and of
        // `the_scaled_default_case_is_the_default_case`: a copy whose M1 is off by 1e-6
        // (relative) differs by far more than `COPY_AGREEMENT` plus the estimates.
        let body = default_body(1.0, 0.4, 0.5);
        let x0 = default_state(&body);
        let factors = [1e20, 1e-7, 3e3];
        let (copy_body, mut copy_x0) = scaled(&body, &x0, factors);
        let mut moved = copy_x0.point();
        moved.m[0] *= 1.0 + 1e-6;
        copy_x0 = State::of_point(&moved, Normalise::Reject).unwrap();
        let (original, copy) = (
            ExactSolution::new(&body, &x0).unwrap(),
            ExactSolution::new(&copy_body, &copy_x0).unwrap(),
        );
        let d = copy_difference(&original, &copy, factors).unwrap();
        let horizon = 2.9 * original.period().unwrap();
        let estimates =
            original.accuracy.error_at(horizon) + copy.accuracy.error_at(factors[2] * horizon);
        assert!(
            d > 1e3 * (COPY_AGREEMENT + estimates),
            "{d:e} {estimates:e}"
        );
    }

    #[test]
    fn the_scaled_default_case_is_the_default_case() {
        // The brief's reproducer: the default case with m, I1 and I3 multiplied by 1e12 (and,
        // beside it, lengths by 1e3 and times by 1e-2) is the default case converted, to
        // `COPY_AGREEMENT`: turning points, period, advances and the states at three times.
        let body = default_body(1.0, 0.4, 0.5);
        let x0 = default_state(&body);
        let original = ExactSolution::new(&body, &x0).unwrap();
        for factors in [[1e12, 1.0, 1.0], [1e12, 1e3, 1e-2], [3e6, 1.0, 1.0]] {
            let (copy_body, copy_x0) = scaled(&body, &x0, factors);
            let copy = ExactSolution::new(&copy_body, &copy_x0).unwrap();
            let d = copy_difference(&original, &copy, factors).unwrap();
            println!("copied by {factors:?}: {d:.1e}");
            assert!(d <= COPY_AGREEMENT, "{factors:?}: {d:e}");
        }
    }

    /// Issue 33, last item: the default case in units of mass 2^-997 (m = 7.5e-301) and 2^997
    /// with lengths 2^-332 (m = 1.3e300, R = 1.1e-100), and in the decimal units 1e-300 and
    /// 1e300 with 1e-100: outside the absolute range of the inertia (`1.6e-51 ..= 5.5e51`)
    /// that refused them before, now solved as the default case: within
    /// `EXACT_COPY_AGREEMENT` for powers of two, `COPY_AGREEMENT` for decimal factors.
    #[test]
    fn the_default_case_far_outside_the_old_inertia_range_is_the_default_case() {
        let body = default_body(1.0, 0.4, 0.5);
        let x0 = default_state(&body);
        let original = ExactSolution::new(&body, &x0).unwrap();
        for (factors, agreement) in [
            ([2f64.powi(-997), 1.0, 1.0], EXACT_COPY_AGREEMENT),
            ([2f64.powi(997), 2f64.powi(-332), 1.0], EXACT_COPY_AGREEMENT),
            ([1e-300, 1.0, 1.0], COPY_AGREEMENT),
            ([1e300, 1e-100, 1.0], COPY_AGREEMENT),
        ] {
            let (copy_body, copy_x0) = scaled(&body, &x0, factors);
            let copy = ExactSolution::new(&copy_body, &copy_x0).unwrap();
            let d = copy_difference(&original, &copy, factors).unwrap();
            println!("copied by {factors:?}: {d:.1e}");
            assert!(d <= agreement, "{factors:?}: {d:e}");
        }
    }

    /// The default case's body (m = 1, R = 1, a = 0.3, I1 = 0.4, I3 = 0.5, G = 9.81) with `m`,
    /// `I1` and `I3` given.
    pub(super) fn default_body(m: f64, i1: f64, i3: f64) -> Body {
        Body::new(m, 1.0, 0.3, i1, i1, i3, 9.81).unwrap()
    }

    /// The default case's initial state.
    pub(super) fn default_state(body: &Body) -> State {
        state(
            body,
            [0.29552020666133955, 0.0, 0.955336489125606],
            [0.5, 0.2, 8.0],
        )
    }

    /// The slender body (I3 = 1e-3, I1 = 0.4, a = 0.3, m = R = 1, G = 9.81) and states whose
    /// motion passes near the axis, found by a random search of gamma near a pole with a small
    /// horizontal omega: before, at t = 10 the first was answered 4.4e-3 off DOP853 with an
    /// estimate of 4e-14, the second 4.2e-2 (1.6e-3 already at t = 0) with 3e-13, the third
    /// 1.9e-4 with 5e-13; the fourth is the brief's kind of state (solved before too).
    pub(super) fn slender_near_the_axis() -> Vec<(Body, State)> {
        let body = default_body(1.0, 0.4, 1e-3);
        [
            (
                [
                    4.175577106056063e-8,
                    4.249650434038295e-8,
                    -0.9999999999999982,
                ],
                [
                    -0.43778984752882133,
                    -0.43487429485788676,
                    -3.52284269692387,
                ],
            ),
            (
                [
                    6.490452279229124e-8,
                    -2.2986657939955927e-7,
                    -0.9999999999999715,
                ],
                [0.5572349845651151, 0.437312074621152, -11.392373083582696],
            ),
            (
                [
                    -1.9426541508143366e-5,
                    5.341675569705452e-5,
                    -0.9999999983846298,
                ],
                [0.4155198152602237, -0.489663405954145, -0.6763631673942698],
            ),
            ([0.001, 0.0, 0.9999995], [0.01, 0.0, 8.0]),
        ]
        .into_iter()
        .map(|(gamma, omega)| (body, state(&body, gamma, omega)))
        .collect()
    }

    #[test]
    fn reproducers_agree_with_dop853_within_the_estimate() {
        // The exact state at t = 0.5, 2 and 10 against DOP853 at rtol 1e-13, whose own error is
        // measured by its distance from DOP853 at rtol 1e-12 (`spread`): the difference must be
        // within the estimate plus that spread. The estimate is the error with the factor 1:
        // it bounds the error (measured: where the difference stands above twice the spread it
        // is at most 0.6 of the estimate).
        let scaled = default_body(1e12, 0.4e12, 0.5e12);
        let heavy = default_body(3e6, 0.4, 0.5);
        // m = 3e6: DOP853 stops converging beyond t = 3 (the field is rounded to 3e-9 there,
        // see `a_state_that_does_not_fix_its_omega_is_refused`).
        let (short, long): (&[f64], &[f64]) = (&[0.5, 2.0], &[0.5, 2.0, 10.0]);
        let mut cases = vec![
            (
                "m, I1, I3 scaled by 1e12",
                scaled,
                default_state(&scaled),
                long,
            ),
            ("m = 3e6", heavy, default_state(&heavy), short),
        ];
        cases.extend(
            slender_near_the_axis()
                .into_iter()
                .map(|(body, x0)| ("slender near the axis", body, x0, long)),
        );
        let mut worst_ratio = 0.0_f64;
        for (name, body, x0, times) in &cases {
            let exact = ExactSolution::new(body, x0).expect(name);
            let Motion::Nutation(_) = &exact.motion else {
                panic!("{name}: a nutation expected, got {:?}", exact.motion);
            };
            for &t in *times {
                let (d, estimate, spread) = against_dop853(name, body, x0, &exact, t);
                if d > 2.0 * spread {
                    worst_ratio = worst_ratio.max(d / estimate);
                }
            }
        }
        println!("worst difference / estimate above the spread: {worst_ratio:.2}");
        // The scaled copy is the default case: its period, converted (here the same units of
        // time), is the default's.
        let default = default_body(1.0, 0.4, 0.5);
        let period = |b: &Body| ExactSolution::new(b, &default_state(b)).unwrap().period();
        let (p, q) = (period(&scaled).unwrap(), period(&default).unwrap());
        assert!((p - q).abs() < 1e-12 * q, "{p} {q}");
        // Negative control: the old answer for the scaled copy, a steady rotation at the rate of
        // psi at the start, is far from DOP853.
        let exact = ExactSolution::new(&scaled, &default_state(&scaled)).unwrap();
        let x0 = default_state(&scaled);
        let rate = exact.reduction.precession_rate(x0.gamma()[2]);
        let (s, c) = (2.0 * rate).sin_cos();
        let turned = Point {
            gamma: [
                c * x0.gamma()[0] - s * x0.gamma()[1],
                s * x0.gamma()[0] + c * x0.gamma()[1],
                x0.gamma()[2],
            ],
            m: [
                c * x0.m()[0] - s * x0.m()[1],
                s * x0.m()[0] + c * x0.m()[1],
                x0.m()[2],
            ],
        };
        assert!(distance(&turned, &dop853_at(&scaled, &x0, 2.0, 1e-13)) > 1e-3);
    }

    #[test]
    fn a_state_that_does_not_fix_its_omega_is_refused() {
        // m = 1e30 with I1 = 0.4, I3 = 0.5: I_Q has the condition 4e30, so the state's M holds
        // no digit of the spin about r, and `exact --t 0` printed omega = [-1.62, 0.2, -1.01]
        // for the case's (0.5, 0.2, 8). Now refused, naming omega.
        let body = default_body(1e30, 0.4, 0.5);
        let x0 = default_state(&body);
        let omega = x0.omega(&body);
        // The state itself has lost the input's omega: the refusal is the only answer.
        assert!((omega[0] - 0.5).abs() > 0.1, "{omega:?}");
        match ExactSolution::new(&body, &x0) {
            Err(RouthError::Singular { formula, .. }) => assert!(formula.contains("omega")),
            other => panic!("expected a refusal, got {:?}", other.map(|e| e.motion)),
        }
        // Negative control: m = 3e6, where omega keeps 8 digits, is solved.
        let heavy = default_body(3e6, 0.4, 0.5);
        assert!(ExactSolution::new(&heavy, &default_state(&heavy)).is_ok());
    }

    /// The change of the azimuth of the symmetry axis e3 in space (fixed frame, z up, from x
    /// toward y) from `start` to `start + span` along the motion in space (`FullMotion`)
    /// integrated by DOP853 at rtol 1e-13, unwrapped on samples 256 times a unit of `step`, and
    /// the same modulo 2 pi (from its two ends only).
    fn axis_azimuth(body: &Body, x0: &State, step: f64, [start, span]: [f64; 2]) -> (f64, f64) {
        let opts = Options::new(1e-13, 1e-15).unwrap();
        let n = (256.0 * span / step).ceil() as usize;
        let times: Vec<f64> = (0..=n)
            .map(|i| start + span * i as f64 / n as f64)
            .collect();
        let t_end = start + span;
        let mut azimuths = vec![];
        solve_dense(
            &FullMotion { body },
            0.0,
            initial_full(x0),
            t_end,
            &opts,
            None,
            &times,
            &mut |_, y: &[f64; FULL_DIM]| {
                let axis = rotate(&quaternion(y), &[0.0, 0.0, 1.0]);
                azimuths.push(axis[1].atan2(axis[0]));
            },
        )
        .expect("integration");
        let mut unwrapped = 0.0;
        for w in azimuths.windows(2) {
            unwrapped += (w[1] - w[0] + PI).rem_euclid(TAU) - PI;
        }
        (unwrapped, azimuths[azimuths.len() - 1] - azimuths[0])
    }

    #[test]
    fn precession_of_the_axis_in_space_agrees_with_the_motion_in_space() {
        // The azimuth of e3 in space, integrated with the orientation (`FullMotion`), against the
        // quadrature's `axis_advance` over 5 periods (a nutation) or its rate over 5 time units
        // (a steady motion). Tolerance 1e-8 rad: DOP853 at rtol 1e-13 follows the orientation to
        // about 1e-11 over these runs, and the quadrature's advance to about 1e-13 (measured: at
        // most 1.4e-12 rad apart).
        let default = default_body(1.0, 0.4, 0.5);
        let bottom = Body::new(2.0, 0.5, 0.1, 0.05, 0.05, 0.08, 9.81).unwrap();
        let (slender, near_axis) = slender_near_the_axis()[3];
        let nutations = [
            ("default case", default, default_state(&default)),
            (
                "tilt 0.05 from the bottom pole",
                bottom,
                state(
                    &bottom,
                    [0.05_f64.sin(), 0.0, -0.05_f64.cos()],
                    [0.3, -0.1, 3.0],
                ),
            ),
            ("slender near the axis", slender, near_axis),
            (
                "through the axis",
                default,
                state(&default, [0.0, 0.0, 1.0], [0.4, 0.1, 8.0]),
            ),
        ];
        for (name, body, x0) in nutations {
            let exact = ExactSolution::new(&body, &x0).expect(name);
            let Motion::Nutation(nut) = &exact.motion else {
                panic!("{name}: a nutation expected");
            };
            // From half a period on (a start on the axis has no azimuth).
            let span = [0.5 * nut.period, 5.0 * nut.period];
            let (unwrapped, wrapped) = axis_azimuth(&body, &x0, nut.period, span);
            let expected = 5.0 * nut.axis_advance;
            // Through the axis the azimuth jumps by pi at each passage: modulo 2 pi only.
            let d = if nut.through_top || nut.through_bottom {
                assert_eq!(nut.axis_mean_rate(), None);
                ((wrapped - expected).rem_euclid(TAU) + PI).rem_euclid(TAU) - PI
            } else {
                let rate = nut.axis_mean_rate().unwrap();
                assert!((rate * nut.period - nut.axis_advance).abs() < 1e-12);
                unwrapped - expected
            };
            println!(
                "{name}: axis advance {} per period {}, measured {:.2e} off over 5 periods",
                nut.axis_advance, nut.period, d
            );
            assert!(d.abs() < 1e-8, "{name}: {d:e}");
            // Negative control: the advance of psi (the vertical in the body frame) is another
            // number: off by more than 0.1 rad per period.
            assert!(
                ((nut.advance - nut.axis_advance + PI).rem_euclid(TAU) - PI).abs() > 0.1,
                "{name}"
            );
        }
        // A steady precession: the rate of the axis against the measured slope.
        let steady = steady_precessions(&default, 1.0, 8.0).unwrap()[0];
        let exact = ExactSolution::new(&default, &steady.state).unwrap();
        let rate = exact.axis_precession_rate().expect("off the axis");
        let (unwrapped, _) = axis_azimuth(&default, &steady.state, 1.0, [0.0, 5.0]);
        println!(
            "steady: axis rate {rate}, psi rate {}, measured {:.2e} off",
            steady.precession,
            unwrapped - 5.0 * rate
        );
        assert!((unwrapped - 5.0 * rate).abs() < 1e-8);
        assert!((steady.precession - rate).abs() > 0.1);
        // The vertical spin has no azimuth of the axis.
        let spin = state(&default, [0.0, 0.0, 1.0], [0.0, 0.0, 8.0]);
        assert_eq!(
            ExactSolution::new(&default, &spin)
                .unwrap()
                .axis_precession_rate(),
            None
        );
    }
}

mod exact_near_rest {
    //! Issue 33, item 8: the crash the `numerics_exact` fuzz target found, a state nearly at rest
    //! with gamma nearly horizontal whose `ExactSolution::state_at(0)` was NaN, and its
    //! neighbours (subnormal components of gamma, M tiny, subnormal or 0, gamma exactly
    //! horizontal), each against DOP853 and against its copies in other units.

    // The DOP853 reference of the sweep of issue 14.
    #[allow(dead_code)]
    use crate::sweep_cases as exact_sweep;

    use exact_sweep::{against_dop853, distance, dop853_at};
    use routh::body::Body;
    use routh::quadrature::{ExactSolution, Motion};
    use routh::state::{Normalise, Point, State};
    use routh::units::{scaled_body, scaled_point, scaled_state};

    /// The fuzzer's body: m = R = 0.1, a = 0.0609375, I1 = I2 = I3 = G = 607.84 (its moments
    /// 6e5 times m R^2: the motion is slow, the period 47.5).
    fn fuzz_body() -> Body {
        Body::new(0.1, 0.1, 0.0609375, 607.84, 607.84, 607.84, 607.84).unwrap()
    }

    fn state(gamma: [f64; 3], m: [f64; 3]) -> State {
        State::new(gamma, m, Normalise::Reject).unwrap()
    }

    /// The state at `t` against DOP853 ([`against_dop853`]): at t > 0 the ball has fallen and
    /// M has the size it has along the motion, the size `distance` measures against.
    fn agrees_with_dop853(name: &str, body: &Body, x0: &State, exact: &ExactSolution, t: f64) {
        against_dop853(name, body, x0, exact, t);
    }

    /// The fuzzer's input (the artifact was lost; these are its numbers to the digits kept in
    /// docs/reliability.md): gamma = (-1, 3.56e-318, 1.62e-321), M of 1e-156. The motion falls
    /// from gamma3 = 0 past the bottom pole at a distance `1 - |gamma3|` of 3.2e-315, a
    /// subnormal number, by which the pole's part of psi was divided (`1 / gap` overflowed, and
    /// `inf * 0` made every state NaN); and `1 / |omega|^2` overflowed in the fit of psi at the
    /// start. Now the passage is one through the axis (the two are the same state in f64) and
    /// the start is at rest in f64 (its M, 1e-156, is below the round-off of the M of 1 that the
    /// motion reaches). Tolerances: against DOP853 the estimate plus DOP853's spread; at t = 0
    /// gamma to 4 eps (the quadrature's phase round-off) and M to 4 eps of the largest M along
    /// the motion (that at t = 10 is below it: a stricter scale).
    #[test]
    fn fuzz_crash_nearly_at_rest_with_gamma_horizontal_is_solved() {
        let body = fuzz_body();
        let x0 = state(
            [-1.0, 3.56e-318, 1.62e-321],
            [5.4e-162, 1.38e-156, 5.38e-156],
        );
        let exact = ExactSolution::new(&body, &x0).unwrap();
        let Motion::Nutation(nutation) = &exact.motion else {
            panic!("a nutation expected, got {:?}", exact.motion);
        };
        assert!(
            nutation.through_bottom && nutation.u2 == 0.0,
            "{nutation:?}"
        );
        assert!(exact.accuracy.initial < 1e-14, "{:?}", exact.accuracy);
        let at_zero = exact.state_at(0.0);
        let later = dop853_at(&body, &x0, 10.0, 1e-13);
        let m_scale = later.m.iter().fold(0.0_f64, |s, v| s.max(v.abs()));
        for i in 0..3 {
            assert!(
                (at_zero.gamma[i] - x0.gamma()[i]).abs() <= 4.0 * f64::EPSILON,
                "{at_zero:?}"
            );
            assert!(
                (at_zero.m[i] - x0.m()[i]).abs() <= 4.0 * f64::EPSILON * m_scale,
                "{at_zero:?} against {m_scale:e}"
            );
        }
        for t in [1.0, 10.0, 30.0] {
            agrees_with_dop853("the fuzzer's input", &body, &x0, &exact, t);
        }
        // Its copies in units scaled by powers of two are the same dimensionless problem to the
        // bit (the units are rounded to powers of two): the same states, converted, to 1 ulp of
        // the conversion; in units of other significands within the estimate.
        for (factors, tolerance) in [
            (
                [2f64.powi(40), 2f64.powi(-9), 2f64.powi(5)],
                4.0 * f64::EPSILON,
            ),
            (
                [2f64.powi(-60), 2f64.powi(20), 2f64.powi(-12)],
                4.0 * f64::EPSILON,
            ),
            ([1e12, 3e-4, 7.0], 1e-12),
        ] {
            let [_, _, s] = factors;
            let copy = scaled_body(&body, factors).unwrap();
            let x = scaled_state(&x0, factors).unwrap();
            let other = ExactSolution::new(&copy, &x).unwrap();
            for t in [0.0, 10.0] {
                let back = scaled_point(&other.state_at(s * t), factors.map(f64::recip));
                let d = distance(&back, &exact.state_at(t));
                assert!(d <= tolerance, "{factors:?}, t = {t}: {d:e}");
            }
        }
        // Negative control: the state of the same phase a quarter turn about e3 away is far
        // from DOP853.
        let turned = exact.state_at(10.0);
        let turned = Point {
            gamma: [-turned.gamma[1], turned.gamma[0], turned.gamma[2]],
            m: [-turned.m[1], turned.m[0], turned.m[2]],
        };
        assert!(distance(&turned, &later) > 0.1);
    }

    /// The timeout the `numerics_exact` fuzz target found next (`timeout-25e242b7...`, run alone
    /// it did not end): gamma = (-1.03e16, 9.81, -5.26e173) rescaled to (-2e-158, 2e-173, -1),
    /// a start 1.9e-316 from the bottom pole in `x = 1 + gamma3`, whose search for the turning
    /// points stepped by `1e-8 x` = 0 (underflow) and never moved. Now a start within `AXIS_GAP`
    /// (1.2e-63) of the pole is searched from the pole: the motion (omega = (-0.048, 1, 2.5e-304):
    /// the ball rolls over) passes through both poles, in 2.5 ms. Tolerances as above.
    #[test]
    fn fuzz_timeout_start_a_subnormal_distance_from_the_pole_is_solved() {
        let body = Body::new(
            0.09999999999999998,
            0.09999694824236938,
            0.028627450980457048,
            1.0,
            1.0,
            1.0,
            1.0,
        )
        .unwrap();
        let x0 = State::from_omega(
            &body,
            [-1.0278803855410308e16, 9.81, -5.255279918644342e173],
            [-0.04823529411764707, 1.0, 2.5067199836690693e-304],
            Normalise::Rescale,
        )
        .unwrap();
        let exact = ExactSolution::new(&body, &x0).unwrap();
        let Motion::Nutation(nutation) = &exact.motion else {
            panic!("a nutation expected, got {:?}", exact.motion);
        };
        assert!(
            nutation.through_top && nutation.through_bottom,
            "{nutation:?}"
        );
        let at_zero = exact.state_at(0.0);
        for i in 0..3 {
            assert!(
                (at_zero.gamma[i] - x0.gamma()[i]).abs() <= 16.0 * f64::EPSILON,
                "{at_zero:?}"
            );
        }
        for t in [1.0, 5.0] {
            agrees_with_dop853("start 1.9e-316 from the pole", &body, &x0, &exact, t);
        }
    }

    /// The crash the `numerics_exact` fuzz target found next (`crash-6d7bf1b5...`: "period inf"):
    /// m = 1.3e-321, R = 8.6e9, I = 1, no gravity, gamma horizontal, omega = (2.2e-308, 0, 0)
    /// across it: the ball rolls over at the rate 2.2e-308, and its period 2 pi / |omega| =
    /// 2.8e308 is beyond f64 (the dimensionless period, 2 pi, times the unit of time, 4.5e307).
    /// Now refused with that cause. Negative control: the same motion spinning 1e8 times faster
    /// is solved, with the period `2 pi / |omega|` of the free isotropic ball (the mass is
    /// 1e-301 of I / R^2) to 1e-12.
    #[test]
    fn fuzz_crash_period_beyond_f64_is_refused_with_its_cause() {
        let body = Body::new(1.265e-321, 8589934592.0, 1.0, 1.0, 1.0, 1.0, 0.0).unwrap();
        let start = |spin: f64| {
            State::from_omega(
                &body,
                [-1.7074873093401245e-286, 7.418415965917065e-68, 0.0],
                [spin, 0.0, 0.0],
                Normalise::Rescale,
            )
            .unwrap()
        };
        let refusal = ExactSolution::new(&body, &start(f64::MIN_POSITIVE)).unwrap_err();
        assert!(
            matches!(refusal, routh::RouthError::Overflow { quantity, .. } if quantity == "the nutation period"),
            "{refusal}"
        );
        let spin = 1e8 * f64::MIN_POSITIVE;
        let period = ExactSolution::new(&body, &start(spin))
            .unwrap()
            .period()
            .unwrap();
        let expected = std::f64::consts::TAU / spin;
        assert!(
            (period / expected - 1.0).abs() < 1e-12,
            "{period:e} {expected:e}"
        );
    }

    /// Neighbours of the fuzzer's input: gamma exactly horizontal or with subnormal
    /// components, M exactly 0, subnormal, or of 1e-300, in either direction of gamma: each is
    /// solved and agrees with DOP853 within the estimate (as above), and the same state at rest
    /// (M = 0) gives the same states to the round-off of the motion's M (4 eps of it, the
    /// estimate's own scale at these times).
    #[test]
    fn hostile_neighbours_of_the_state_at_rest_agree_with_dop853() {
        let body = fuzz_body();
        let tiny = f64::MIN_POSITIVE * f64::EPSILON;
        let cases = [
            ("horizontal, at rest", [-1.0, 0.0, 0.0], [0.0; 3]),
            (
                "horizontal, M subnormal",
                [-1.0, 0.0, 0.0],
                [tiny, 3.0 * tiny, -tiny],
            ),
            (
                "subnormal gamma2, gamma3, at rest",
                [-1.0, 3.56e-318, 1.62e-321],
                [0.0; 3],
            ),
            (
                "subnormal gamma3 < 0, M 1e-300",
                [0.0, 1.0, -1.62e-321],
                [1e-300, 0.0, 2e-300],
            ),
            (
                "gamma3 = -0, M 1e-200",
                [0.0, -1.0, -0.0],
                [0.0, 1e-200, -1e-200],
            ),
            (
                "M 1e-156 toward -gamma2",
                [1.0, -3.56e-318, 1.62e-321],
                [0.0, -1e-156, 5e-156],
            ),
        ];
        for (name, gamma, m) in cases {
            let x0 = state(gamma, m);
            let exact = ExactSolution::new(&body, &x0).expect(name);
            let at_rest = state(gamma, [0.0; 3]);
            let still = ExactSolution::new(&body, &at_rest).expect(name);
            for t in [0.0, 1.0, 10.0] {
                let s = exact.state_at(t);
                assert!(s.to_array().iter().all(|v| v.is_finite()), "{name}: {s:?}");
            }
            for t in [1.0, 10.0] {
                agrees_with_dop853(name, &body, &x0, &exact, t);
                let d = distance(&still.state_at(t), &exact.state_at(t));
                assert!(
                    d <= 4.0 * f64::EPSILON,
                    "{name}, t = {t}: {d:e} from at rest"
                );
            }
        }
    }
}

mod exact_unresolved {
    //! A state whose estimated error is above the refusal already at t = 0 is refused with that
    //! cause (`RouthError::Unresolved`), not as a time beyond a horizon of 0: the fuzzer's body
    //! nearly at rest with M = 1e-10 (estimated 2.7e-4 at t = 0).

    use routh::body::Body;
    use routh::quadrature::ExactSolution;
    use routh::state::{Normalise, State};
    use routh::RouthError;

    #[test]
    fn a_state_unresolved_at_the_start_is_refused_with_that_cause() {
        let body = Body::new(0.1, 0.1, 0.0609375, 607.84, 607.84, 607.84, 607.84).unwrap();
        let x0 = State::new([-1.0, 0.0, 0.0], [0.0, 1e-10, 1e-10], Normalise::Reject).unwrap();
        let exact = ExactSolution::new(&body, &x0).unwrap();
        let initial = exact.accuracy.error_at(0.0);
        assert!(initial > 1e-6, "estimate {initial:e} at t = 0");
        match exact.accuracy.checked_error_at(1.0) {
            Err(RouthError::Unresolved { error, .. }) => {
                assert_eq!(error, initial);
                let message = RouthError::Unresolved {
                    tolerance: 1e-6,
                    error,
                }
                .to_string();
                assert!(message.contains("already at t = 0"), "{message}");
            }
            other => panic!("{other:?} with the estimate {initial:e} at t = 0"),
        }
        // The control: the same body at a resolvable state answers.
        let resolved = State::new([-1.0, 0.0, 0.0], [0.0, 1.0, 1.0], Normalise::Reject).unwrap();
        let exact = ExactSolution::new(&body, &resolved).unwrap();
        assert!(exact.accuracy.checked_error_at(1.0).is_ok());
    }
}

mod exact_numbers {
    //! Issue 34: `ExactSolution::nutation_numbers`, the period and the advance alone (what a
    //! sweep's `quadrature` columns use), is `ExactSolution::new` bit for bit: the same period
    //! and advance of a nutation, `None` for a steady motion, and the same error, with the same
    //! text, exactly when `new` errs. On random bodies and states anywhere, near the poles,
    //! near Routh's threshold, near the steady precessions and near the separatrix of the
    //! vertical spin, slender (I3 / I1 down to 1e-3) and flat, each in units scaled by powers of
    //! two (masses 2^+-100, lengths 4^+-16, times 2^+-17), by decimal factors or not at all.

    use super::exact_in_any_units::{
        default_body, default_state, random_factors, random_problem, scaled, slender_near_the_axis,
        state,
    };
    use super::solutions::on_separatrix;
    use proptest::prelude::*;
    use proptest::test_runner::{RngSeed, TestCaseError, TestRunner};
    use routh::body::Body;
    use routh::quadrature::{ExactSolution, Motion, NutationNumbers, Reduction};
    use routh::state::{Normalise, State};
    use routh::steady::{routh_threshold, steady_precessions};
    use routh::RouthError;

    /// Random cases of the property test (each one body and state, compared once).
    const CASES: u32 = 3000;

    /// Why the numbers `numbers` differ from those of the solution `exact`, if they do: the
    /// period and the advance compared by their bits, the errors by their text.
    fn difference(
        exact: &Result<ExactSolution, RouthError>,
        numbers: &Result<NutationNumbers, RouthError>,
    ) -> Option<String> {
        let bits = |v: Option<f64>| v.map(f64::to_bits);
        match (exact, numbers) {
            (Ok(exact), Ok(numbers)) => {
                let advance = match &exact.motion {
                    Motion::Nutation(nut) => Some(nut.advance),
                    Motion::Steady { .. } => None,
                };
                (bits(exact.period()) != bits(numbers.period)
                    || bits(advance) != bits(numbers.advance))
                .then(|| {
                    format!(
                        "period {:?} against {:?}, advance {advance:?} against {:?}",
                        exact.period(),
                        numbers.period,
                        numbers.advance
                    )
                })
            }
            (Err(a), Err(b)) => {
                (a.to_string() != b.to_string()).then(|| format!("{a} against {b}"))
            }
            (a, b) => Some(format!(
                "{:?} against {:?}",
                a.as_ref().err(),
                b.as_ref().err()
            )),
        }
    }

    /// The comparison of `ExactSolution::new` and `nutation_numbers` at one body and state.
    fn compare(body: &Body, x0: &State) -> Option<String> {
        difference(
            &ExactSolution::new(body, x0),
            &ExactSolution::nutation_numbers(body, x0),
        )
    }

    /// A random Routh sphere of `random_problem`'s range (m = R = 1; I1 from 0.05 to 1, I3 / I1
    /// from 1e-3 to 2; a of either sign; G = 9.81).
    fn random_body() -> impl Strategy<Value = Body> {
        (
            -1.3f64..0.0,
            -3.0f64..2f64.log10(),
            0.05f64..0.8,
            any::<bool>(),
        )
            .prop_map(|(log_i1, log_ratio, a, up)| {
                let i1 = 10f64.powf(log_i1);
                let i3 = (i1 * 10f64.powf(log_ratio)).min(2.0 * i1);
                let a = if up { a } else { -a };
                Body::new(1.0, 1.0, a, i1, i1, i3, 9.81).unwrap()
            })
    }

    /// A steady precession at a random tilt and spin ([`steady_precessions`]), its omega moved
    /// by a relative 1e-16 to 1e-3 (or not at all).
    fn near_a_steady_precession() -> impl Strategy<Value = Option<(Body, State)>> {
        (
            random_body(),
            0.05f64..3.09,
            -20.0f64..20.0,
            any::<bool>(),
            prop_oneof![Just(0.0), -16.0f64..-3.0],
            [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0],
        )
            .prop_map(|(body, theta, spin, far, log_off, dir)| {
                let precessions = steady_precessions(&body, theta, spin).ok()?;
                let steady = if far {
                    precessions.last()
                } else {
                    precessions.first()
                }?;
                let off = if log_off == 0.0 {
                    0.0
                } else {
                    10f64.powf(log_off)
                };
                let omega = steady.state.omega(&body);
                let size = omega.iter().fold(0.0f64, |m, w| m.max(w.abs()));
                let moved = std::array::from_fn(|i| omega[i] + off * size * dir[i]);
                Some((body, state(&body, steady.state.gamma(), moved)))
            })
    }

    /// A point of the homoclinic orbit of the unstable top-heavy vertical spin (a spin of 0.1
    /// to 0.95 of Routh's threshold, a > 0), its omega moved by a relative 1e-16 to 1e-4 (or
    /// not at all): on either side of the separatrix, or on it within round-off.
    fn near_the_separatrix() -> impl Strategy<Value = Option<(Body, State)>> {
        (
            random_body(),
            0.1f64..0.95,
            -0.9f64..0.99,
            prop_oneof![Just(0.0), -16.0f64..-4.0],
            [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0],
        )
            .prop_map(|(body, fraction, u, log_off, dir)| {
                let body = Body::new(
                    1.0,
                    1.0,
                    body.a().abs(),
                    body.i1(),
                    body.i1(),
                    body.i3(),
                    9.81,
                )
                .unwrap();
                let spin = fraction * routh_threshold(&body, 1.0);
                let on = separatrix_point(&body, spin, u)?;
                let off = if log_off == 0.0 {
                    0.0
                } else {
                    10f64.powf(log_off)
                };
                let omega = on.omega(&body);
                let size = omega.iter().fold(0.0f64, |m, w| m.max(w.abs()));
                let moved = std::array::from_fn(|i| omega[i] + off * size * dir[i]);
                Some((body, state(&body, on.gamma(), moved)))
            })
    }

    /// `on_separatrix`, or `None` where it would panic (no motion at `u`).
    fn separatrix_point(body: &Body, spin: f64, u: f64) -> Option<State> {
        let top = routh::steady::vertical_spin_state(body, 1.0, spin).ok()?;
        let red = Reduction::of_state(body, &top).ok()?;
        let s = (1.0 - u * u).sqrt();
        let q = red.q(u);
        if q.is_nan() || q <= 0.0 {
            return None;
        }
        let (gamma, omega) = red.omega(u, s, 0.0, q.sqrt() / s, red.jellett_quotient(u));
        State::from_omega(body, gamma, omega, Normalise::Rescale).ok()
    }

    /// A random case: `random_problem`'s (anywhere, near a pole, near Routh's threshold), near
    /// a steady precession or near the separatrix, in its own units, in units scaled by powers
    /// of two (`random_factors`: huge and tiny), or by decimal factors (another problem, a few
    /// eps away, with its own decisions).
    fn random_case() -> impl Strategy<Value = Option<(Body, State)>> {
        let motion = prop_oneof![
            3 => random_problem().prop_map(|(body, x0, _)| Some((body, x0))),
            1 => near_a_steady_precession(),
            1 => near_the_separatrix(),
        ];
        let factors = prop_oneof![
            2 => Just([1.0; 3]),
            2 => random_factors(),
            1 => (-30.0f64..30.0, -8.0f64..8.0, -5.0f64..5.0)
                .prop_map(|(k, l, s)| [10f64.powf(k), 10f64.powf(l), 10f64.powf(s)]),
        ];
        (motion, factors).prop_map(|(motion, factors)| {
            let (body, x0) = motion?;
            Some(scaled(&body, &x0, factors))
        })
    }

    /// `nutation_numbers` is `new`'s period and advance, or its error, bit for bit, on `CASES`
    /// random cases; each kind of outcome (nutation, steady, refusal) is met.
    #[test]
    fn nutation_numbers_are_those_of_the_exact_solution_bit_for_bit() {
        let config = ProptestConfig {
            cases: CASES,
            failure_persistence: None,
            rng_seed: RngSeed::Fixed(34),
            ..ProptestConfig::default()
        };
        // Nutations, steady motions, refusals, and cases not built (no steady precession at
        // the tilt, no motion at the point of the separatrix).
        let outcomes = std::cell::RefCell::new([0usize; 4]);
        let result = TestRunner::new(config).run(&random_case(), |case| {
            let Some((body, x0)) = case else {
                outcomes.borrow_mut()[3] += 1;
                return Ok(());
            };
            if let Some(difference) = compare(&body, &x0) {
                return Err(TestCaseError::fail(format!(
                    "{body:?} {x0:?}: {difference}"
                )));
            }
            outcomes.borrow_mut()[match ExactSolution::nutation_numbers(&body, &x0) {
                Ok(NutationNumbers {
                    period: Some(_), ..
                }) => 0,
                Ok(_) => 1,
                Err(_) => 2,
            }] += 1;
            Ok(())
        });
        let outcomes = outcomes.into_inner();
        println!(
            "{CASES} cases: {} nutations, {} steady, {} refused, {} not built",
            outcomes[0], outcomes[1], outcomes[2], outcomes[3]
        );
        if let Err(e) = result {
            panic!("{e}");
        }
        assert!(outcomes[..3].iter().all(|&n| n >= 20), "{outcomes:?}");
    }

    #[test]
    fn nutation_numbers_of_the_reproducers_are_those_of_the_exact_solution() {
        // The slender body near the axis, the default case in decimal units, a separatrix, a
        // vertical spin, a start nearly at rest, a state that does not fix its omega and a
        // period beyond f64: nutations, steady motions and each kind of refusal.
        let mut cases = slender_near_the_axis();
        let body = default_body(1.0, 0.4, 0.5);
        let x0 = default_state(&body);
        cases.push((body, x0));
        cases.push(scaled(&body, &x0, [1e12, 1e3, 1e-2]));
        let spin = 0.5 * routh_threshold(&Body::default(), 1.0);
        cases.push((Body::default(), on_separatrix(&Body::default(), spin, 0.9)));
        cases.push((body, state(&body, [0.0, 0.0, 1.0], [0.0, 0.0, 20.0])));
        let heavy = default_body(1e30, 0.4, 0.5);
        cases.push((heavy, default_state(&heavy)));
        let fuzz = Body::new(0.1, 0.1, 0.0609375, 607.84, 607.84, 607.84, 607.84).unwrap();
        cases.push((
            fuzz,
            State::new([-1.0, 0.0, 0.0], [0.0, 1e-160, 1e-160], Normalise::Reject).unwrap(),
        ));
        let free = Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 0.0).unwrap();
        cases.push((
            free,
            state(&free, [0.6, 0.0, 0.8], [2.2e-308, 0.0, 2.2e-308]),
        ));
        let mut outcomes = [0; 3];
        for (body, x0) in &cases {
            if let Some(difference) = compare(body, x0) {
                panic!("{body:?} {x0:?}: {difference}");
            }
            outcomes[match ExactSolution::nutation_numbers(body, x0) {
                Ok(NutationNumbers {
                    period: Some(_), ..
                }) => 0,
                Ok(_) => 1,
                Err(_) => 2,
            }] += 1;
        }
        println!(
            "{} cases: {outcomes:?} nutations, steady, refused",
            cases.len()
        );
        assert!(outcomes.iter().all(|&n| n > 0), "{outcomes:?}");
    }

    #[test]
    fn a_comparison_with_another_state_fails() {
        // Negative control of the bitwise comparison: the numbers of the default case against
        // the solution of the same state with M1 moved by one ulp, by 1e-12, and against a
        // refusal (a separatrix), each differ.
        let body = default_body(1.0, 0.4, 0.5);
        let x0 = default_state(&body);
        let numbers = ExactSolution::nutation_numbers(&body, &x0);
        assert_eq!(difference(&ExactSolution::new(&body, &x0), &numbers), None);
        for moved in [f64::EPSILON, 1e-12] {
            let mut other = x0;
            let mut point = other.point();
            point.m[0] *= 1.0 + moved;
            other = State::of_point(&point, Normalise::Reject).unwrap();
            let found = difference(&ExactSolution::new(&body, &other), &numbers);
            println!("M1 moved by {moved:e}: {found:?}");
            assert!(found.is_some(), "M1 moved by {moved:e}");
        }
        let spin = 0.5 * routh_threshold(&Body::default(), 1.0);
        let separatrix = on_separatrix(&Body::default(), spin, 0.9);
        assert!(difference(&ExactSolution::new(&Body::default(), &separatrix), &numbers).is_some());
        assert!(difference(
            &ExactSolution::new(&Body::default(), &separatrix),
            &ExactSolution::nutation_numbers(&Body::default(), &separatrix)
        )
        .is_none());
    }
}
