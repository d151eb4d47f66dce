//! The model of a rolling ball (routh-ball): the field against automatic differentiation, the integrals and the invariant measure, the motion in space, runs, case files, properties of hostile inputs.
//!
//! One test binary, one module a topic (issue 32: few binaries, each named after what it proves).

mod ball {
    //! The general unbalanced ball and its models: which integrals each one states, checked by
    //! automatic differentiation of the same field that simulates, with a negative control per
    //! model; the Chaplygin ball integrated over a long time.
    //!
    //! Tolerance of the rates: as in `model_integrals.rs`, `|X(H)| <= 1e-12 |dH| |X|`: round-off
    //! of the cancellation is a few 1e-14 of that scale; a quantity that is not an integral gives
    //! a rate of order 1e-2 to 1 (the negative controls require > 1e-6).

    use routh::ball::MODEL_TOLERANCE;
    use routh::case::Case;
    use routh::differential::{divergence, gradient, lie_derivative, Dual6};
    use routh::field::vector_field;
    use routh::integrals::{
        area_integral, chaplygin_density, energy, geometric, jellett, measure_density,
        momentum_squared, quadratic_integral, routh_integral,
    };
    use routh::integrate::Method;
    use routh::sampling::SplitMix64;
    use routh::scalar::Scalar;
    use routh::simulate::{run, ReducedSystem, Settings};
    use routh::{AsBall, Ball, Body, Model, RouthError};

    fn relative_rate(h: impl Fn(&[Dual6; 6]) -> Dual6, ball: &Ball, x: &[f64; 6]) -> f64 {
        let field = vector_field(ball, x);
        let (_, dh) = gradient(&h, x);
        let scale = dh.iter().map(|v| v * v).sum::<f64>().sqrt()
            * field.iter().map(|v| v * v).sum::<f64>().sqrt();
        lie_derivative(h, &field, x).abs() / scale.max(1e-300)
    }

    fn chaplygin_balls() -> [Ball; 2] {
        [
            Ball::new(1.3, 0.9, [0.3, 0.4, 0.5], [0.0; 3], 9.81).unwrap(),
            Ball::new(0.7, 1.2, [0.05, 0.5, 0.52], [0.0; 3], 0.0).unwrap(),
        ]
    }

    fn general_balls() -> [Ball; 2] {
        [
            Ball::new(1.3, 0.9, [0.3, 0.4, 0.5], [0.1, -0.2, 0.3], 9.81).unwrap(),
            Ball::new(1.0, 1.0, [0.4, 0.4, 0.5], [0.2, 0.0, -0.3], 3.0).unwrap(),
        ]
    }

    /// 20 random points with |M| components up to 3, gamma on the unit sphere.
    fn points(seed: u64) -> Vec<[f64; 6]> {
        let mut rng = SplitMix64::new(seed);
        (0..20).map(|_| rng.phase_point(3.0, 0.0, 0.0)).collect()
    }

    #[test]
    fn models_are_decided_with_a_relative_tolerance() {
        let routh = Body::default().ball();
        assert_eq!(routh.model(), Model::RouthSphere);
        let nearly = Ball::new(
            1.0,
            1.0,
            [0.4, 0.4 * (1.0 + 0.1 * MODEL_TOLERANCE), 0.5],
            [0.3 * 0.1 * MODEL_TOLERANCE, 0.0, -0.3],
            9.81,
        )
        .unwrap();
        assert_eq!(nearly.model(), Model::RouthSphere);
        // Negative controls: beyond the tolerance it is another model.
        let triaxial = Ball::new(
            1.0,
            1.0,
            [0.4, 0.4 * (1.0 + 10.0 * MODEL_TOLERANCE), 0.5],
            routh.com(),
            9.81,
        )
        .unwrap();
        assert_eq!(triaxial.model(), Model::General);
        assert_eq!(chaplygin_balls()[0].model(), Model::Chaplygin);
        for ball in general_balls() {
            assert_eq!(ball.model(), Model::General);
        }
    }

    #[test]
    fn every_ball_conserves_energy_and_h4() {
        let balls = chaplygin_balls()
            .into_iter()
            .chain(general_balls())
            .chain([Body::default().ball()]);
        for ball in balls {
            for x in points(5) {
                for (name, rate) in [
                    ("H1", relative_rate(|y| energy(&ball, y), &ball, &x)),
                    ("H4", relative_rate(geometric, &ball, &x)),
                ] {
                    assert!(rate < 1e-12, "{name} of {ball:?} at {x:?}: {rate:e}");
                }
            }
        }
    }

    #[test]
    fn the_general_ball_has_no_further_integral_of_the_special_cases() {
        // Negative control of the general model: Jellett's (M, r), (M, M), (M, gamma) and
        // Routh's K, integrals of the special cases, all move along the field of a general ball.
        for ball in general_balls() {
            let [i1, i2, i3] = ball.inertia();
            let body = Body::new(
                ball.m(),
                ball.radius(),
                -ball.com()[2],
                i1,
                i2,
                i3,
                ball.gravity(),
            )
            .unwrap();
            let jellett_general = |y: &[Dual6; 6]| {
                let r = ball.contact_vector(&[y[0], y[1], y[2]]);
                y[3] * r[0] + y[4] * r[1] + y[5] * r[2]
            };
            let worst = |h: &dyn Fn(&[Dual6; 6]) -> Dual6| {
                points(9)
                    .iter()
                    .map(|x| relative_rate(h, &ball, x))
                    .fold(0.0, f64::max)
            };
            assert!(worst(&jellett_general) > 1e-6, "(M, r) for {ball:?}");
            assert!(
                worst(&|y| momentum_squared(y)) > 1e-6,
                "(M, M) for {ball:?}"
            );
            assert!(
                worst(&|y| area_integral(y)) > 1e-6,
                "(M, gamma) for {ball:?}"
            );
            assert!(
                worst(&|y| routh_integral(&body, y)) > 1e-6,
                "K for {ball:?}"
            );
        }
    }

    #[test]
    fn chaplygin_ball_integrals_and_invariant_measure() {
        // div(rho X) = 0 with rho = det(I_Q)^{-1/2}: each term of the divergence is of size
        // |dX| ~ 1e1, round-off leaves ~1e-14, so 1e-11 absolute.
        for ball in chaplygin_balls() {
            for x in points(13) {
                for (name, rate) in [
                    ("(M, M)", relative_rate(momentum_squared, &ball, &x)),
                    ("(M, gamma)", relative_rate(area_integral, &ball, &x)),
                ] {
                    assert!(rate < 1e-12, "{name} of {ball:?} at {x:?}: {rate:e}");
                }
                let div = divergence(
                    |y| vector_field(&ball, y).map(|c| c * chaplygin_density(&ball, y)),
                    &x,
                );
                assert!(div.abs() < 1e-11, "div(rho X) = {div:e} at {x:?}");
            }
            // Negative controls: the reciprocal density is not invariant, and (M, M) is not an
            // integral once the centre of mass leaves the centre.
            let x = points(13)[0];
            let wrong = divergence(
                |y| vector_field(&ball, y).map(|c| c * chaplygin_density(&ball, y).recip()),
                &x,
            );
            assert!(
                wrong.abs() > 1e-6,
                "the divergence check is not sharp: {wrong:e}"
            );
            let shifted = Ball::new(
                ball.m(),
                ball.radius(),
                ball.inertia(),
                [0.0, 0.05, 0.0],
                ball.gravity(),
            )
            .unwrap();
            let rate = points(13)
                .iter()
                .map(|x| relative_rate(momentum_squared, &shifted, x))
                .fold(0.0, f64::max);
            assert!(
                rate > 1e-6,
                "(M, M) conserved with com off the centre: {rate:e}"
            );
        }
    }

    #[test]
    fn the_routh_sphere_as_a_ball_keeps_its_integrals_and_measure() {
        // A Routh sphere written with `com` (not `a`) is the same model: its field equals the
        // field of the Body to round-off, and Jellett, Routh, H2 and 1/g are conserved.
        let body = Body::new(2.0, 0.7, -0.25, 0.3, 0.3, 0.45, 3.0).unwrap();
        let ball = Ball::new(2.0, 0.7, [0.3, 0.3, 0.45], [0.0, 0.0, 0.25], 3.0).unwrap();
        assert_eq!(ball.axial_body("test").unwrap(), body);
        for x in points(17) {
            let (f_ball, f_body) = (vector_field(&ball, &x), vector_field(&body, &x));
            for (p, q) in f_ball.iter().zip(f_body) {
                assert!(
                    (p - q).abs() <= 1e-14 * (1.0 + q.abs()),
                    "{f_ball:?} != {f_body:?}"
                );
            }
            for (name, rate) in [
                ("H3", relative_rate(|y| jellett(&body, y), &ball, &x)),
                ("K", relative_rate(|y| routh_integral(&body, y), &ball, &x)),
                (
                    "H2",
                    relative_rate(|y| quadratic_integral(&body, y), &ball, &x),
                ),
            ] {
                assert!(rate < 1e-12, "{name} at {x:?}: {rate:e}");
            }
            let div = divergence(
                |y| vector_field(&ball, y).map(|c| c * measure_density(&body, y)),
                &x,
            );
            assert!(div.abs() < 1e-11, "div(X/g) = {div:e}");
        }
        // Negative control: the same body with its centre of mass moved off the axis loses K.
        let tilted = Ball::new(
            ball.m(),
            ball.radius(),
            ball.inertia(),
            [0.05, 0.0, 0.25],
            ball.gravity(),
        )
        .unwrap();
        let rate = points(17)
            .iter()
            .map(|x| relative_rate(|y| routh_integral(&body, y), &tilted, x))
            .fold(0.0, f64::max);
        assert!(rate > 1e-6, "K conserved off the axis: {rate:e}");
    }

    #[test]
    fn routh_sphere_mathematics_refuses_other_balls() {
        let case = Case::parse(
            &std::fs::read_to_string(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../cases/chaplygin.toml"
            ))
            .unwrap()
            .replace("com = [0.0, 0.0, 0.0]", "com = [0.1, 0.0, 0.0]"),
            "off-axis",
        )
        .unwrap();
        let err = case.body("the quadrature").unwrap_err();
        assert!(matches!(err, RouthError::OffAxis { .. }), "{err}");
        assert!(err.to_string().contains("the quadrature"), "{err}");
        let chaplygin = Case::from_file(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../cases/chaplygin.toml"
        )))
        .unwrap();
        let body = chaplygin.body("the quadrature").unwrap();
        let err = routh::quadrature::ExactSolution::new(&body, &chaplygin.initial).unwrap_err();
        assert!(matches!(err, RouthError::NotSymmetric { .. }), "{err}");
    }

    #[test]
    fn case_files_take_exactly_one_of_a_and_com_inside_the_ball() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../cases/chaplygin.toml"
        ))
        .unwrap();
        for (edit, key) in [
            (
                "com = [0.0, 0.0, 0.0]\na = 0.1",
                "exactly one of the keys `a` and `com`",
            ),
            ("", "exactly one of the keys `a` and `com`"),
            ("com = [0.6, 0.6, 0.6]", "|com|"),
            ("com = [0.0, nan, 0.0]", "com[1]"),
        ] {
            let err = Case::parse(&text.replace("com = [0.0, 0.0, 0.0]", edit), "edited")
                .unwrap_err()
                .to_string();
            assert!(err.contains(key), "{edit:?}: {err}");
        }
    }

    /// The largest relative drift of the integrals of the Chaplygin case over [0, t_end], and the
    /// summary of the run.
    fn chaplygin_drift(t_end: f64, tol: f64, project: bool) -> (f64, routh::simulate::Summary) {
        let case = Case::from_file(std::path::Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../cases/chaplygin.toml"
        )))
        .unwrap();
        assert_eq!(case.ball.model(), Model::Chaplygin);
        let settings = Settings::builder()
            .method(Method::Dop853)
            .t_end(t_end)
            .tolerances(tol, tol)
            .projection(project, 1)
            .build()
            .unwrap();
        let summary = run(
            &case.ball,
            &ReducedSystem(&case.ball),
            case.initial.to_array(),
            &settings,
            &mut |_, _| Ok(()),
        )
        .unwrap();
        assert_eq!(
            summary.integrals.keys().copied().collect::<Vec<_>>(),
            vec!["H1", "H4", "MM", "Mgamma"]
        );
        let worst = summary
            .integrals
            .values()
            .map(|d| d.max_rel_drift)
            .fold(0.0, f64::max);
        (worst, summary)
    }

    #[test]
    fn chaplygin_case_keeps_its_integrals_to_t_1000() {
        // The case as a user runs it for conserved integrals: DOP853 at its tolerance
        // rtol = atol = 1e-12 to t = 1000 (~2e4 steps) *with* projection onto the level set of its
        // integrals (H4, (M, M), (M, gamma), H1) after each step (`--project`): they stay within
        // 1e-10 (the bound; the projection leaves a few ulp per step).
        let (projected, summary) = chaplygin_drift(1000.0, 1e-12, true);
        assert!(projected < 1e-10, "projected: {projected:e}");
        let (first, last) = (summary.initial_state, summary.final_state);
        let moved = (0..3)
            .map(|i| (first.m[i] - last.m[i]).abs())
            .fold(0.0, f64::max);
        assert!(moved > 1e-2, "the ball barely moved: {moved:e}");
        // Without projection the drift at 1e-12 is 1.0e-9 ((M, gamma); H4 3.0e-10), and it is the
        // method's truncation error, not round-off: it grows linearly in t (10.0 times from
        // t = 100 to 1000; a random walk of round-off would grow sqrt(10) = 3.2 times, and would
        // be ~sqrt(2e4) 1e-16 = 1e-14), and it falls with the tolerance (13 times from 1e-12 to
        // 1e-13, as DOP853's error per step, about tol^(8/7)). So 1e-10 without projection takes
        // rtol = 1e-13 (measured 7.5e-11); at 1e-12 the bound is the measured 1.0e-9 with 2x room.
        let (plain, _) = chaplygin_drift(1000.0, 1e-12, false);
        assert!(plain < 2e-9, "unprojected at 1e-12: {plain:e}");
        let (short, _) = chaplygin_drift(100.0, 1e-12, false);
        let growth = plain / short;
        assert!(
            (8.0..12.0).contains(&growth),
            "growth from t = 100 to 1000: {growth}"
        );
        // (Since atol is measured in the motion's units, M in units of m R^2 / T, about 8 here,
        // the weight of M's error is larger than in the user's units: 1.4e-10 at 1e-13.)
        let (tight, _) = chaplygin_drift(1000.0, 1e-13, false);
        assert!(tight < 2e-10, "unprojected at 1e-13: {tight:e}");
        // Negative control: the unprojected drift at 1e-12 is far above the projected one and
        // above the bound, so the bound can fail.
        assert!(
            plain > 1e-10 && plain > 100.0 * projected,
            "{plain:e} vs {projected:e}"
        );
    }
}

mod case_file {
    //! The TOML case schema: the default case parses, and each rule of the schema and of the
    //! body and state validation gives an error that names the key (or parameter) and the file.

    use routh::case::{Case, DEFAULT_CASE};
    use routh::{AppError, FileError};

    fn with(old: &str, new: &str) -> String {
        assert!(
            DEFAULT_CASE.contains(old),
            "test edits a line that is not in the default case: {old}"
        );
        DEFAULT_CASE.replacen(old, new, 1)
    }

    fn error_of(text: &str) -> String {
        match Case::parse(text, "cases/test.toml") {
            Ok(_) => panic!("accepted an invalid case:\n{text}"),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn default_case_parses_and_i2_defaults_to_i1() {
        let case = Case::default_case().unwrap();
        assert_eq!(case.ball.inertia()[1], case.ball.inertia()[0]);
        assert_eq!(case.integration.t_end(), 100.0);
        let omega = case.initial.omega(&case.ball);
        for (w, expected) in omega.iter().zip([0.5, 0.2, 8.0]) {
            assert!(
                (w - expected).abs() < 1e-14,
                "omega round trip through M = I_Q omega: {w} vs {expected}"
            );
        }
    }

    #[test]
    fn unknown_keys_are_named_with_the_file() {
        let e = error_of(&with("G = 9.81", "G = 9.81\nmass = 2.0"));
        assert!(
            e.contains("mass") && e.contains("cases/test.toml") && e.contains("[body]"),
            "{e}"
        );
        let e = error_of(&with("rtol = 1e-12", "rtol = 1e-12\nmethod = 3"));
        assert!(e.contains("method") && e.contains("[integration]"), "{e}");
    }

    #[test]
    fn missing_fields_are_named() {
        let e = error_of(&with("R = 1.0\n", ""));
        assert!(e.contains("`R`") && e.contains("cases/test.toml"), "{e}");
        let e = error_of(&DEFAULT_CASE.replace("[initial]", "[other]"));
        assert!(
            e.contains("[other]") && e.contains("cases/test.toml"),
            "{e}"
        );
    }

    #[test]
    fn omega_and_m_exactly_one() {
        let e = error_of(&with(
            "omega = [0.5, 0.2, 8.0]",
            "omega = [0.5, 0.2, 8.0]\nM = [1.0, 0.0, 0.0]",
        ));
        assert!(e.contains("exactly one"), "{e}");
        let e = error_of(&with("omega = [0.5, 0.2, 8.0]", ""));
        assert!(e.contains("exactly one"), "{e}");
    }

    #[test]
    fn malformed_toml_is_reported() {
        let e = error_of("[body\nm = 1");
        assert!(
            e.contains("malformed TOML") && e.contains("cases/test.toml"),
            "{e}"
        );
    }

    #[test]
    fn each_body_rule_is_enforced() {
        let cases = [
            ("m = 1.0", "m = 0.0", "m = 0"),
            ("m = 1.0", "m = nan", "must be finite"),
            ("R = 1.0", "R = -1.0", "R = -1"),
            ("a = 0.3", "a = 1.0", "|a| < R"),
            ("a = 0.3", "a = inf", "must be finite"),
            ("I1 = 0.4", "I1 = -0.4", "I1 = -0.4"),
            ("I3 = 0.5", "I3 = 0.9", "I1 + I2 >= I3"),
            ("I3 = 0.5", "I3 = 0.2\nI2 = 0.1", "I2 + I3 >= I1"),
            ("I3 = 0.5", "I3 = 0.5\nI2 = 1.0", "I3 + I1 >= I2"),
            ("I3 = 0.5", "I3 = 0.5\nI2 = 0.0", "I2 = 0"),
            ("G = 9.81", "G = -9.81", "G = -9.81: must be >= 0"),
        ];
        for (old, new, expected) in cases {
            let e = error_of(&with(old, new));
            assert!(
                e.contains(expected),
                "`{new}` gave `{e}`, expected `{expected}`"
            );
        }
    }

    #[test]
    fn state_rules_are_enforced() {
        let e = error_of(&with(
            "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
            "gamma = [0.3, 0.0, 0.955]",
        ));
        assert!(e.contains("not a unit vector"), "{e}");
        let e = error_of(&with("omega = [0.5, 0.2, 8.0]", "omega = [nan, 0.2, 8.0]"));
        assert!(e.contains("non-finite"), "{e}");
        let e = error_of(&with(
            "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
            "gamma = [0.0, 0.0, 0.0]\nnormalize = true",
        ));
        assert!(e.contains("cannot be normalised"), "{e}");
        let ok = Case::parse(
            &with(
                "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
                "gamma = [0.0, 0.0, 2.0]\nnormalize = true",
            ),
            "x",
        )
        .unwrap();
        assert_eq!(ok.initial.gamma(), [0.0, 0.0, 1.0]);
    }

    #[test]
    fn integration_rules_are_enforced() {
        for (old, new, name) in [
            ("t_end = 100.0", "t_end = -1.0", "t_end"),
            ("t_end = 100.0", "t_end = nan", "t_end"),
            ("rtol = 1e-12", "rtol = 0.0", "rtol"),
            ("atol = 1e-12", "atol = -1e-12", "atol"),
        ] {
            let e = error_of(&with(old, new));
            assert!(e.contains(name) && e.contains("invalid option"), "{e}");
        }
    }

    #[test]
    fn missing_file_is_an_error_naming_it() {
        let e = Case::from_file(std::path::Path::new("/nonexistent/case.toml")).unwrap_err();
        assert!(matches!(e, AppError::File(FileError::Case { .. })));
        assert!(e.to_string().contains("/nonexistent/case.toml"));
    }
}

mod field_identities {
    //! The field of `src/field.rs`, written with two exact identities of vector algebra, against
    //! the literal form of (mg-eq) evaluated independently here,
    //!
    //! `dM/dt = M x omega + m (R dgamma/dt) x (omega x r) + gamma x dU/dgamma`,
    //!
    //! with `r` = [`Ball::contact_vector`] and `dU/dgamma` = [`Ball::potential_gradient`] (itself
    //! checked against automatic differentiation of [`Ball::potential`] in `tests/ball.rs`): the
    //! values and the dual-number Jacobians at random points of R^6 (including `|gamma| != 1`,
    //! points near the poles `gamma = +-e3`, huge and tiny momenta), for balls with a general
    //! centre of mass, a Routh sphere with its centre of mass below and above the centre, no
    //! gravity, `I1 != I2` and a Chaplygin ball. Negative controls: a wrong sign of the rolling
    //! term and a form that agrees only on `|gamma| = 1` are caught.
    //!
    //! Tolerance. The two forms are the same polynomial expression in `(gamma, omega)` (the same
    //! `omega`, bit for bit: both call [`Ball::angular_velocity`]), so they differ by round-off
    //! only. The literal form cancels terms: its rolling term `R gamma_dot x (omega x r)` is a
    //! difference of products of size `B = m R |gamma| |omega|^2 rho`, `rho = R |gamma| + |com|`,
    //! whatever the size of the result; its torque a difference of products of size
    //! `C = m G |gamma| (2 R |gamma| + |com|)`; the gyroscopic term `M x omega` of size
    //! `A = |M| |omega|`. Each form's error in a component is a few ulp of these sizes: the literal
    //! rolling term at most about 14 eps B (the roundings of `r`, of two cross products and of
    //! `m R`), plus 7 eps B because the computed `gamma_dot` is orthogonal to `omega` and `gamma`
    //! only to about 2 ulp, which the identity uses; the short form 6 eps B; the torques about
    //! 5 eps C each; the sums 2 eps (A + B + C). Hence the bound `32 eps (A + B + C)` per
    //! component (an absolute floor of the smallest normal number covers subnormal results);
    //! the observed maximum is printed, and is a few eps. The Jacobians: the same bound with the
    //! sizes differentiated by the product rule (`A_j = |d_j M| |omega| + |M| |d_j omega|`, ...),
    //! 64 eps for the roundings of the dual parts on top.
    //!
    //! The two closed forms of `omega` ([`Ball::angular_velocity`] for numbers,
    //! [`Ball::angular_velocity_by_determinant`] for the Taylor tape) are compared the same way,
    //! values and Jacobians, with a bound scaled by the condition of `I_Q`.

    use routh::ball::Ball;
    use routh::case::Case;
    use routh::differential::{jacobian, Dual6};
    use routh::field::vector_field;
    use routh::scalar::{cross, dot, lift, split, Scalar};

    use proptest::strategy::{Strategy, ValueTree};
    use proptest::test_runner::TestRunner;

    const EPS: f64 = f64::EPSILON;

    /// The literal form of (mg-eq), generic like the library's field.
    fn literal<D: Scalar>(ball: &Ball, x: &[D; 6]) -> [D; 6] {
        let (gamma, m_vec) = split(x);
        let r = ball.contact_vector(&gamma);
        let omega = ball.angular_velocity(&gamma, &m_vec);
        let gamma_dot = cross(&gamma, &omega);
        let r_dot = gamma_dot.map(|c| c * ball.radius());
        let rolling = cross(&r_dot, &cross(&omega, &r));
        let gyroscopic = cross(&m_vec, &omega);
        let torque = cross(&gamma, &ball.potential_gradient(&gamma));
        let dm: [D; 3] = std::array::from_fn(|i| gyroscopic[i] + rolling[i] * ball.m() + torque[i]);
        [
            gamma_dot[0],
            gamma_dot[1],
            gamma_dot[2],
            dm[0],
            dm[1],
            dm[2],
        ]
    }

    /// The short form with the sign of the rolling term flipped (negative control).
    fn wrong_sign<D: Scalar>(ball: &Ball, x: &[D; 6]) -> [D; 6] {
        let mut f = vector_field(ball, x);
        let (gamma, m_vec) = split(x);
        let omega = ball.angular_velocity(&gamma, &m_vec);
        let gamma_dot = cross(&gamma, &omega);
        let com = ball.com().map(lift::<D>);
        // Subtract the rolling term twice: -m R (gamma_dot, com) omega becomes its opposite.
        let s = dot(&gamma_dot, &com) * (2.0 * ball.m() * ball.radius());
        for i in 0..3 {
            f[3 + i] = f[3 + i] + s * omega[i];
        }
        f
    }

    /// The short form with its torque times `(gamma, gamma)`: the same values on `|gamma| = 1`,
    /// not off it, and not the same derivatives anywhere (negative control of "on all of R^6").
    fn sphere_only<D: Scalar>(ball: &Ball, x: &[D; 6]) -> [D; 6] {
        let (gamma, _) = split(x);
        let mut f = vector_field(ball, x);
        let free = vector_field(&ball.without_gravity(), x);
        let norm2 = dot(&gamma, &gamma);
        for i in 3..6 {
            let torque = f[i] - free[i];
            f[i] = free[i] + torque * norm2;
        }
        f
    }

    fn norm(v: &[f64; 3]) -> f64 {
        dot(v, v).sqrt()
    }

    /// The sizes `A + B + C` of the terms that the literal form cancels (module documentation).
    fn term_size(ball: &Ball, x: &[f64; 6]) -> f64 {
        let (gamma, m_vec) = split(x);
        let omega = ball.angular_velocity(&gamma, &m_vec);
        let (g, w) = (norm(&gamma), norm(&omega));
        let com = norm(&ball.com());
        let rho = ball.radius() * g + com;
        let a = norm(&m_vec) * w;
        let b = ball.m() * ball.radius() * g * w * w * rho;
        let c = ball.m() * ball.gravity() * g * (2.0 * ball.radius() * g + com);
        a + b + c
    }

    /// The Jacobian of omega (its rows 0 to 2; the others zero) at `x`, by dual numbers through
    /// one of its closed forms (`Ball::angular_velocity` or `Ball::angular_velocity_by_determinant`).
    fn omega_jacobian(
        ball: &Ball,
        x: &[f64; 6],
        form: fn(&Ball, &[Dual6; 3], &[Dual6; 3]) -> [Dual6; 3],
    ) -> nalgebra::SMatrix<f64, 6, 6> {
        let (_, d_omega) = jacobian(
            |y| {
                let (g, m) = split(y);
                let w = form(ball, &g, &m);
                [w[0], w[1], w[2], lift(0.0), lift(0.0), lift(0.0)]
            },
            x,
        );
        d_omega
    }

    /// The sizes of column `j` of the Jacobian: the product rule applied to [`term_size`].
    fn jacobian_term_size(ball: &Ball, x: &[f64; 6], j: usize) -> f64 {
        let (gamma, m_vec) = split(x);
        let omega = ball.angular_velocity(&gamma, &m_vec);
        let d_omega = omega_jacobian(ball, x, Ball::angular_velocity);
        let dw = norm(&[d_omega[(0, j)], d_omega[(1, j)], d_omega[(2, j)]]);
        let dg = if j < 3 { 1.0 } else { 0.0 };
        let dm = 1.0 - dg;
        let (g, w, mm) = (norm(&gamma), norm(&omega), norm(&m_vec));
        let com = norm(&ball.com());
        let rho = ball.radius() * g + com;
        let a = dm * w + mm * dw;
        let b = ball.m()
            * ball.radius()
            * (dg * w * w * rho + g * 2.0 * w * dw * rho + g * w * w * ball.radius() * dg);
        let c = ball.m()
            * ball.gravity()
            * (dg * (2.0 * ball.radius() * g + com) + g * 2.0 * ball.radius() * dg);
        a + b + c
    }

    /// The balls of the comparison.
    fn balls() -> Vec<(&'static str, Ball)> {
        let default = Case::default_case().unwrap().ball;
        vec![
            ("default (Routh, com below)", default),
            ("no gravity", default.without_gravity()),
            (
                "Routh, com above",
                Ball::new(1.0, 1.0, [0.4, 0.4, 0.5], [0.0, 0.0, 0.5], 9.81).unwrap(),
            ),
            (
                "general com, I1 != I2",
                Ball::new(1.3, 0.8, [0.3, 0.45, 0.5], [0.05, -0.02, -0.1], 9.81).unwrap(),
            ),
            (
                "axial com, I1 != I2",
                Ball::new(2.5, 0.7, [0.2, 0.3, 0.35], [0.0, 0.0, -0.3], 3.0).unwrap(),
            ),
            (
                "Chaplygin",
                Ball::new(1.0, 1.0, [0.3, 0.4, 0.5], [0.0, 0.0, 0.0], 9.81).unwrap(),
            ),
            (
                "equal moments (one group)",
                Ball::new(1.0, 1.0, [0.4, 0.4, 0.4], [0.0, 0.0, -0.3], 9.81).unwrap(),
            ),
            (
                "small heavy ball",
                Ball::new(1e3, 1e-2, [3e-2, 3e-2, 4e-2], [1e-3, 0.0, -4e-3], 9.81).unwrap(),
            ),
        ]
    }

    /// Random points: gamma a random direction (every fifth near the pole +-e3) times
    /// 10^[-3, 3]; M random in each component times 10^[-120, 120].
    fn points(count: usize) -> Vec<[f64; 6]> {
        let unit = -1.0f64..1.0;
        let strategy = (
            [unit.clone(), unit.clone(), unit.clone()],
            [unit.clone(), unit.clone(), unit],
            -3.0f64..3.0,
            -120.0f64..120.0,
            0usize..5,
        );
        let mut runner = TestRunner::deterministic();
        (0..count)
            .map(|_| {
                let (g, m, g_exp, m_exp, kind) = strategy.new_tree(&mut runner).unwrap().current();
                let g = if kind == 0 {
                    [g[0] * 1e-9, g[1] * 1e-9, g[2].signum()]
                } else {
                    g
                };
                let (gs, ms) = (10f64.powf(g_exp), 10f64.powf(m_exp));
                [
                    g[0] * gs,
                    g[1] * gs,
                    g[2] * gs,
                    m[0] * ms,
                    m[1] * ms,
                    m[2] * ms,
                ]
            })
            .collect()
    }

    /// Largest `|f_i - g_i| / (size + MIN_POSITIVE)` over the components, in eps.
    fn discrepancy(f: &[f64], g: &[f64], size: f64) -> f64 {
        f.iter()
            .zip(g)
            .map(|(f, g)| (f - g).abs() / (size + f64::MIN_POSITIVE) / EPS)
            .fold(0.0, f64::max)
    }

    #[test]
    fn the_short_field_equals_the_literal_form_to_round_off() {
        let points = points(1500);
        for (name, ball) in balls() {
            let mut worst = 0.0f64;
            let mut resolvable = 0;
            for x in &points {
                let short = vector_field::<f64>(&ball, x);
                let long = literal::<f64>(&ball, x);
                assert!(short.iter().all(|v| v.is_finite()), "{name} at {x:?}");
                assert_eq!(short[..3], long[..3], "{name}: dgamma/dt at {x:?}");
                let size = term_size(&ball, x);
                let d = discrepancy(&short, &long, size);
                assert!(d <= 32.0, "{name} at {x:?}: {d} eps of {size}");
                worst = worst.max(d);
                // Negative control: the wrong sign changes the result by twice the rolling term;
                // wherever that is above twice the tolerance it must be caught.
                let wrong = wrong_sign::<f64>(&ball, x);
                let change = discrepancy(&wrong, &short, size);
                if change > 64.0 {
                    resolvable += 1;
                    let caught = discrepancy(&wrong, &long, size);
                    assert!(
                        caught > 32.0,
                        "{name} at {x:?}: wrong sign within {caught} eps"
                    );
                }
            }
            println!(
            "{name}: largest difference {worst:.2} eps of the terms' size; a wrong sign caught at all {resolvable} of {} points where it changes the field by more than 64 eps",
            points.len()
        );
            // The rolling term, m R (gamma_dot, com) omega, vanishes for com = 0 (Chaplygin) and
            // is below the round-off of the other terms where |M| is tiny (the torque dominates)
            // or gamma_dot is orthogonal to com; at the other points (a third or more) it counts.
            if ball.com() != [0.0; 3] {
                assert!(resolvable * 3 >= points.len(), "{name}: {resolvable}");
            }
        }
    }

    #[test]
    fn the_jacobians_agree() {
        let points = points(1000);
        for (name, ball) in balls() {
            let mut worst = 0.0f64;
            let mut resolvable = 0;
            for x in &points {
                let (fs, js) = jacobian(|y| vector_field(&ball, y), x);
                let (fl, jl) = jacobian(|y| literal(&ball, y), x);
                let (_, jw) = jacobian(|y| sphere_only(&ball, y), x);
                assert!(discrepancy(&fs, &fl, term_size(&ball, x)) <= 32.0);
                let mut change = 0.0f64;
                let mut caught = f64::INFINITY;
                for j in 0..6 {
                    let size = jacobian_term_size(&ball, x, j);
                    let column = |m: &nalgebra::SMatrix<f64, 6, 6>| -> [f64; 6] {
                        std::array::from_fn(|i| m[(i, j)])
                    };
                    let d = discrepancy(&column(&js), &column(&jl), size);
                    assert!(d <= 64.0, "{name} at {x:?}, column {j}: {d} eps of {size}");
                    worst = worst.max(d);
                    let c = discrepancy(&column(&jw), &column(&js), size);
                    if c > change {
                        change = c;
                        caught = discrepancy(&column(&jw), &column(&jl), size);
                    }
                }
                // Negative control: the sphere-only form, wherever its Jacobian differs by more
                // than twice the tolerance, is caught.
                if change > 128.0 {
                    resolvable += 1;
                    assert!(
                        caught > 64.0,
                        "{name} at {x:?}: sphere-only form within {caught}"
                    );
                }
            }
            println!(
            "{name}: Jacobians within {worst:.2} eps; the sphere-only form caught at all {resolvable} of {} points where it differs by more than 128 eps",
            points.len()
        );
            // The sphere-only form differs in d/dgamma of the torque, 2 gamma (gamma x -m G com):
            // zero without gravity or without an offset of the centre of mass, and below the
            // round-off of the other terms where |M| is huge.
            if ball.gravity() > 0.0 && ball.com() != [0.0; 3] {
                assert!(resolvable * 3 >= points.len(), "{name}: {resolvable}");
            }
        }
    }

    #[test]
    fn the_sphere_only_form_agrees_in_value_on_the_sphere() {
        // The negative control of the Jacobians is not a different field on |gamma| = 1: there
        // its values equal the short form's to round-off, so only the Jacobian check (and the
        // values off the sphere) can catch it.
        let ball = Case::default_case().unwrap().ball;
        for x in points(200) {
            let g = norm(&[x[0], x[1], x[2]]);
            let y = [x[0] / g, x[1] / g, x[2] / g, x[3], x[4], x[5]];
            let d = discrepancy(
                &sphere_only::<f64>(&ball, &y),
                &vector_field::<f64>(&ball, &y),
                term_size(&ball, &y),
            );
            assert!(d <= 32.0, "at {y:?}: {d}");
        }
    }

    #[test]
    fn the_two_forms_of_omega_agree_to_round_off() {
        // `omega = I_Q^{-1} M` by cofactors (numbers) and by the determinant (the Taylor tape): the
        // same solution of `I_Q omega = M`, each rounded a few ulp backward. `I_Q = I + m (r^2 E
        // - r r^T)` has its eigenvalues between `I_min` and `I_max + m r^2`, so either form is
        // within `c eps kappa |M| / I_min` of the exact one, `kappa = (I_max + m r^2) / I_min`
        // (the solution's sensitivity to a relative error in `I_Q`). Bound `64 eps kappa |M| / I_min`, the observed maximum
        // printed; the dual parts (the Jacobian of omega) the same with the sizes differentiated
        // (`|d M| = 1` in a momentum column, `d (m r^2) = 2 m R |r|` in a gamma column).
        // Negative controls: `I_2` taken for `I_1` in the determinant form is caught where the moments
        // differ, and `I_3` changed by 1e-10 relative (on every ball) at a third of the points or
        // more: the bound is tight to that.
        let points = points(1500);
        for (name, ball) in balls() {
            let (i_min, i_max) = ball
                .inertia()
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(lo, hi), &i| {
                    (lo.min(i), hi.max(i))
                });
            let mut worst = 0.0f64;
            let mut worst_dual = 0.0f64;
            let (mut caught, mut nudge_caught) = (0, 0);
            for x in &points {
                let (gamma, m_vec) = split(x);
                let r = ball.contact_vector(&gamma);
                let mr2 = ball.m() * dot(&r, &r);
                let kappa = (i_max + mr2) / i_min;
                let size = kappa * norm(&m_vec) / i_min;
                let by_cofactors = ball.angular_velocity(&gamma, &m_vec);
                let by_determinant = ball.angular_velocity_by_determinant(&gamma, &m_vec);
                assert!(
                    by_determinant.iter().all(|v| v.is_finite()),
                    "{name} at {x:?}"
                );
                let d = discrepancy(&by_cofactors, &by_determinant, size);
                assert!(d <= 64.0, "{name} at {x:?}: {d} eps of {size}");
                worst = worst.max(d);
                let jc = omega_jacobian(&ball, x, Ball::angular_velocity);
                let jr = omega_jacobian(&ball, x, Ball::angular_velocity_by_determinant);
                for j in 0..6 {
                    let dm = if j < 3 { 0.0 } else { 1.0 };
                    let dmr2 = if j < 3 {
                        2.0 * ball.m() * ball.radius() * norm(&r)
                    } else {
                        0.0
                    };
                    let dsize =
                        kappa * (dm + norm(&m_vec) * dmr2 / i_min) / i_min + (dmr2 / i_min) * size;
                    let col = |m: &nalgebra::SMatrix<f64, 6, 6>| -> [f64; 3] {
                        std::array::from_fn(|i| m[(i, j)])
                    };
                    let d = discrepancy(&col(&jc), &col(&jr), dsize);
                    assert!(
                        d <= 128.0,
                        "{name} at {x:?}, column {j}: {d} eps of {dsize}"
                    );
                    worst_dual = worst_dual.max(d);
                }
                let [i1, i2, i3] = ball.inertia();
                let with_moments = |inertia| {
                    Ball::new(ball.m(), ball.radius(), inertia, ball.com(), ball.gravity()).unwrap()
                };
                let swapped = with_moments([i2, i2, i3]);
                let wrong = swapped.angular_velocity_by_determinant(&gamma, &m_vec);
                if discrepancy(&wrong, &by_cofactors, size) > 64.0 {
                    caught += 1;
                }
                let nudged = with_moments([i1, i2, i3 * (1.0 + 1e-10)]);
                let wrong = nudged.angular_velocity_by_determinant(&gamma, &m_vec);
                if discrepancy(&wrong, &by_cofactors, size) > 64.0 {
                    nudge_caught += 1;
                }
            }
            println!(
            "{name}: omega's two forms within {worst:.2} eps, their Jacobians within {worst_dual:.2} eps; I_2 for I_1 caught at {caught}, I_3 (1 + 1e-10) at {nudge_caught} of {} points",
            points.len()
        );
            assert!(nudge_caught * 3 >= points.len(), "{name}: {nudge_caught}");
            if ball.inertia()[0] != ball.inertia()[1] {
                assert!(caught * 3 >= points.len(), "{name}: {caught}");
            }
        }
    }
}

mod fuzz_properties {
    //! The fuzz targets' properties (`fuzz/`, see docs/reliability.md) on a few hundred random
    //! inputs each, fast enough for every CI run: arbitrary text to the case parser and to the CSV
    //! reader, arbitrary numbers to the field, the integrals, the exact solution and the steady
    //! motions. No panic, and no NaN in what an accepted input gives.

    use crate::properties;

    use proptest::prelude::*;

    /// Case files made of the default case's lines, some edited, dropped or repeated, and lines
    /// with values from the edges of f64: the parser's checks are reached, not only its syntax
    /// errors.
    fn case_like() -> impl Strategy<Value = String> {
        let lines: Vec<String> = routh::case::DEFAULT_CASE
            .lines()
            .map(str::to_string)
            .collect();
        let values = prop::sample::select(vec![
            "0", "-1", "1e300", "1e-300", "nan", "inf", "1e200", "2.0", "\"x\"", "[1, 2]",
        ]);
        let keys = prop::sample::select(vec![
            "m",
            "R",
            "a",
            "I1",
            "I2",
            "I3",
            "G",
            "t_end",
            "rtol",
            "atol",
            "max_steps",
            "x",
            "[extra]",
            "[integration]",
            "omega",
            "gamma",
            "M",
            "normalize",
        ]);
        let n = lines.len();
        prop::collection::vec((0..n + 3, keys, values), 0..6).prop_map(move |edits| {
            let mut out = lines.clone();
            for (at, key, value) in edits {
                let line = if key.starts_with('[') {
                    key.to_string()
                } else {
                    format!("{key} = {value}")
                };
                match at {
                    i if i < out.len() && i < n => out[i] = line,
                    i if i == n => {
                        out.pop();
                    }
                    _ => out.push(line),
                }
            }
            out.join("\n")
        })
    }

    /// CSV text: a header from the simulate columns, then rows of cells of any kind.
    fn csv_like() -> impl Strategy<Value = String> {
        let header = prop::sample::subsequence(
            vec![
                "t", "gamma1", "gamma2", "gamma3", "H1", "H2", "K", "x", "y", "qw", "qx",
            ],
            1..8,
        );
        let cell = prop_oneof![
            (-1e3f64..1e3).prop_map(|v| v.to_string()),
            Just(String::new()),
            Just("NaN".to_string()),
            Just("inf".to_string()),
            Just("1e308".to_string()),
            Just("abc".to_string()),
        ];
        (
            header,
            prop::collection::vec(prop::collection::vec(cell, 0..9), 0..6),
        )
            .prop_map(|(header, rows)| {
                let mut text = header.join(",");
                for (i, row) in rows.iter().enumerate() {
                    text.push('\n');
                    let mut cells = row.clone();
                    if let Some(first) = cells.first_mut() {
                        *first = i.to_string();
                    }
                    text.push_str(&cells.join(","));
                }
                text
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, failure_persistence: None, ..ProptestConfig::default() })]

        #[test]
        fn case_parser_never_panics_and_accepts_only_finite_cases(text in case_like()) {
            properties::case_text(&text);
        }

        #[test]
        fn case_parser_on_arbitrary_text(text in ".{0,200}") {
            properties::case_text(&text);
        }

        #[test]
        fn csv_reader_never_panics_and_accepts_only_drawable_tables(text in csv_like()) {
            properties::csv_text(&text);
        }

        #[test]
        fn numerical_entry_points_on_arbitrary_numbers(bytes in prop::collection::vec(any::<u8>(), 144..160)) {
            properties::numerics(&properties::decode_f64s(&bytes), properties::Parts::All);
        }

        #[test]
        fn numerical_entry_points_near_the_default_body(
            a in -0.99f64..0.99,
            spin in -50.0f64..50.0,
            tilt in 0.0f64..3.2,
            t in 0.0f64..100.0,
            tip in -1e-3f64..1e-3,
        ) {
            // Near the vertical spins (tip small) and at any tilt: the hard places, with the exact
            // solution (these near-steady states took seconds before the quadrature's panels,
            // docs/reliability.md).
            let theta = if tilt > 3.1 { tip } else { tilt };
            properties::numerics(&[
                1.0, 1.0, a, 0.4, 0.4, 0.5, 9.81, -1.0,
                theta.sin(), 0.0, theta.cos(), 0.1 * tip, 0.0, spin, t, tilt,
            ], properties::Parts::All);
        }
    }

    /// Negative control: the finiteness check does fail where the range checks would have
    /// refused the input (m = 1e300 overflows the inverse of the inertia).
    #[test]
    #[should_panic(expected = "at State")]
    fn the_finiteness_check_fails_on_an_overflowing_body() {
        let body = routh::Body::new(1e300, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).unwrap();
        let state = routh::State::new(
            [0.0, 0.6, 0.8],
            [1.0, 2.0, 3.0],
            routh::state::Normalise::Reject,
        )
        .unwrap();
        properties::field_and_integrals_finite(&body, &state);
    }

    /// The crash the `numerics` fuzz target found (docs/reliability.md): a body with
    /// I3 = 7e-304 and m R^2 = 10, for which the AD derivatives of Routh's g overflow and
    /// `steady` reported `Q'' = NaN`. The reduction now refuses such bodies with the reason.
    #[test]
    fn fuzz_crash_tiny_moment_is_refused_not_nan() {
        let body = routh::Body::new(
            999.9695825404498,
            0.09999999999999998,
            0.09999999999999948,
            0.09999999999999998,
            0.09999999999999998,
            7.073954810965889e-304,
            7.268183591365776e-308,
        )
        .unwrap();
        let refusal =
            routh::steady::vertical_spin(&body, 1.0, -1.1732762318796806e-125).unwrap_err();
        assert!(
            refusal.to_string().contains("derivatives of g overflow"),
            "{refusal}"
        );
        let bytes: &[u8] = &[
            196, 196, 196, 196, 0, 215, 0, 255, 255, 255, 247, 255, 255, 255, 255, 255, 255, 255,
            255, 255, 65, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
            255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 2, 255, 255, 255, 255, 11, 255, 0,
            0, 0, 0, 0, 0, 198, 33, 42, 0, 0, 35, 196, 33, 196, 196, 196, 196, 255, 165, 165, 165,
            165, 255, 0, 0, 0, 0, 0, 0, 7, 255, 255, 255, 255, 32, 0, 0, 0, 0, 0, 198, 33, 0, 0, 0,
            0, 0, 7, 255, 255, 255, 255, 32, 0, 0, 0, 0, 0, 198, 33, 42, 0, 0, 35, 196, 33, 196,
            196, 196, 196, 255, 165, 165, 165, 165, 255, 0, 215, 0, 255, 255, 255, 255, 0, 215,
            196, 255, 196, 0, 196, 196, 0, 38, 10, 255,
        ];
        properties::numerics(&properties::decode_f64s(bytes), properties::Parts::All);
        // Negative control: a moment at the limit is accepted.
        let sane = routh::Body::new(
            body.m(),
            body.radius(),
            body.a(),
            body.i1(),
            body.i2(),
            1e-59 * 10.0,
            body.gravity(),
        )
        .unwrap();
        assert!(routh::quadrature::Reduction::new(&sane, 1.0, 0.0, 0.0).is_ok());
    }

    /// The timeout the `numerics` fuzz target found (1.5 s, docs/reliability.md): a body of mass
    /// 1000 with a = 0.993 R, whose Q has a singularity 0.005 beyond gamma3 = -1, at rest
    /// (omega 1e-309) with gamma horizontal. Every sample of the quadrature bisected its
    /// Gauss-Legendre rule toward the singularity; the work was then bounded and the motion
    /// refused with the reason (the cofactor is now one evaluation of Q on divided differences,
    /// docs/quadrature.md, and the motion is still refused, as singular). No panic, no NaN.
    #[test]
    fn fuzz_timeout_near_singular_body_is_refused() {
        let bytes: &[u8] = &[
            196, 196, 196, 196, 0, 215, 0, 239, 255, 255, 247, 255, 255, 255, 255, 255, 255, 255,
            255, 255, 255, 65, 49, 255, 255, 35, 255, 255, 255, 245, 255, 255, 255, 255, 255, 255,
            255, 255, 147, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
            255, 255, 255, 255, 255, 255, 255, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
            255, 255, 255, 27, 0, 0, 0, 0, 0, 0, 0, 255, 251, 255, 255, 255, 0, 0, 0, 36, 255, 248,
            255, 255, 255, 255, 40, 0, 0, 0, 0, 17, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
            0, 25, 0, 0, 0, 0, 0, 20, 20, 147, 147, 147, 20, 20, 147, 163, 147, 147, 147, 0, 215,
            0, 255, 255, 255, 255, 255, 0, 196, 255, 196, 0, 196, 10, 255,
        ];
        let values = properties::decode_f64s(bytes);
        properties::numerics(&values, properties::Parts::All);
        let [m, r, a, i1, _, i3, g] = values[..7].try_into().unwrap();
        let body = routh::Body::new(m, r, a, i1, i1, i3, g).unwrap();
        let state = routh::State::from_omega(
            &body,
            [values[8], values[9], values[10]],
            [values[11], values[12], values[13]],
            routh::state::Normalise::Rescale,
        )
        .unwrap();
        let refusal = routh::quadrature::ExactSolution::new(&body, &state).unwrap_err();
        assert!(
            matches!(refusal, routh::RouthError::Singular { .. }),
            "{refusal}"
        );
    }
}

mod model_integrals {
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
            Body::default().without_gravity(),
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
                if body.gravity() == 0.0 {
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
        let heavier = Body::new(
            body.m() * 1.5,
            body.radius(),
            body.a(),
            body.i1(),
            body.i2(),
            body.i3(),
            body.gravity(),
        )
        .unwrap();
        let gyro_only = vector_field(&heavier, x);
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
}

mod motion {
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
    use routh::{Body, Point, State};

    type Sample = (f64, [f64; FULL_DIM]);

    const TOLERANCE: f64 = 1e-12;

    /// Dense samples of `system` from `y0` at the given times.
    fn samples_of(
        system: &impl OdeSystem<FULL_DIM>,
        y0: [f64; FULL_DIM],
        times: &[f64],
    ) -> Vec<Sample> {
        let opts = Options::new(TOLERANCE, TOLERANCE).unwrap();
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
            worst_height =
                worst_height.max((columns[6] - (body.radius() + body.a() * gamma[2])).abs());
            // The contact point is on the plane: z_com + (Q r)_z = 0.
            worst_height = worst_height.max((columns[6] + rotate(&quaternion(y), &r)[2]).abs());
            worst_norm = worst_norm.max((quaternion(y).norm() - 1.0).abs());
        }
        // gamma (reduced field) and Q^T (0, 0, -1) (quaternion kinematics) are integrated
        // independently; over t = 100 at 1e-12 they agree to about 1e-12 per unit time. |q| - 1
        // stays at the tolerance (1.1e-12 measured, with atol in the motion's units).
        assert!(worst_down < 1e-9, "|Q gamma + e_z| = {worst_down:e}");
        assert!(worst_height < 1e-9, "height residual {worst_height:e}");
        assert!(worst_norm < 2e-12, "|q| - 1 = {worst_norm:e}");
    }

    #[test]
    fn homogeneous_ball_rolls_straight_at_constant_omega() {
        // a = 0, I1 = I2 = I3: every omega stays constant (docs/motion.md), and the centre moves
        // with the constant velocity V = Q0 (r0 x omega0), |V| = |omega x r|.
        let body = Body::new(1.3, 0.8, 0.0, 0.35, 0.35, 0.35, 9.81).unwrap();
        let omega0 = [1.0, -2.0, 3.0];
        let state = State::from_omega(&body, [0.6, 0.0, 0.8], omega0, Normalise::Reject).unwrap();
        let y0 = initial_full(&state);
        let r0 = body.contact_vector(&state.gamma());
        let velocity = rotate(&quaternion(&y0), &cross(&r0, &omega0));
        assert!(velocity[2].abs() < 1e-15, "the velocity is horizontal");
        let speed = norm(&cross(&omega0, &r0));
        let times: Vec<f64> = (0..=100).map(|k| k as f64 * 0.1).collect();
        let samples = samples_of(&FullMotion { body: &body }, y0, &times);
        for (t, y) in &samples {
            let omega = Point::from_array(&std::array::from_fn(|i| y[i])).omega(&body);
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
            assert!((c[6] - body.radius()).abs() < 1e-11);
        }
        let (t_end, y_end) = samples.last().unwrap();
        let travelled = norm(&[y_end[10], y_end[11]]);
        assert!((travelled - speed * t_end).abs() < 1e-9 * speed * t_end);
    }

    /// The spin about e3 of the steady motion with `gamma3 = cos theta` and rate `mu` about
    /// gamma: `omega = mu gamma + lambda e3` with lambda from the balance of moments
    /// (docs/motion.md, "Steady motion").
    fn steady_lambda(body: &Body, gamma3: f64, mu: f64) -> f64 {
        let (m, r, a) = (body.m(), body.radius(), body.a());
        let height = r + a * gamma3;
        (m * body.gravity() * a - mu * mu * ((body.i3() - body.i1()) * gamma3 - m * a * height))
            / (mu * (body.i3() + m * r * height))
    }

    /// The largest deviation of gamma3 from its start and of the distance between the centre of
    /// mass and the predicted circle centre from the predicted radius |R lambda / mu - a| sin theta.
    fn steady_deviations(body: &Body, theta: f64, mu: f64, lambda: f64) -> (f64, f64) {
        let gamma = [theta.sin(), 0.0, theta.cos()];
        let omega: [f64; 3] =
            std::array::from_fn(|i| mu * gamma[i] + if i == 2 { lambda } else { 0.0 });
        let state = State::from_omega(body, gamma, omega, Normalise::Reject).unwrap();
        let y0 = initial_full(&state);
        let k = body.radius() * lambda / mu - body.a();
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
        let ratio = body.radius() * lambda / mu;
        let centre = [c0[7] - ratio * axis[0], c0[8] - ratio * axis[1]];
        let radius = ratio.abs() * theta.sin();
        let times: Vec<f64> = (0..=100).map(|k| k as f64 * 0.05).collect();
        for (_, y) in samples_of(&FullMotion { body: &body }, y0, &times) {
            let c = full_columns(&body, &y);
            let distance = norm(&[c[7] - centre[0], c[8] - centre[1]]);
            assert!((distance - radius).abs() < 1e-9, "{distance} vs {radius}");
        }
    }
}

mod problem {
    //! Problem and Solution as plain values, and the dense solution against the steps.

    use routh::case::Case;
    use routh::integrate::Method;
    use routh::problem::{DenseSolution, Plane, Problem, Solution, Status};
    use routh::simulate::{run, ReducedSystem, Settings};

    fn plain_value<T: Clone + Send + Sync + serde::Serialize>() {}

    fn default_problem(t_end: f64, samples: usize) -> Problem {
        let case = Case::default_case().unwrap();
        Problem {
            ball: case.ball,
            initial: case.initial,
            settings: Settings::builder()
                .method(Method::Dop853)
                .t_end(t_end)
                .tolerances(1e-12, 1e-12)
                .samples(samples)
                .build()
                .unwrap(),
            event: None,
        }
    }

    #[test]
    fn problems_and_solutions_are_plain_values() {
        plain_value::<Problem>();
        plain_value::<Solution>();
        plain_value::<DenseSolution>();
        // Thousands of them go to threads: four here, each solved on its own thread, agree with
        // the same problem solved here (the same code: bit for bit).
        let problems: Vec<Problem> = (0..4).map(|i| default_problem(1.0 + i as f64, 3)).collect();
        let handles: Vec<_> = problems
            .iter()
            .cloned()
            .map(|p| std::thread::spawn(move || p.solve().unwrap()))
            .collect();
        for (p, h) in problems.iter().zip(handles) {
            let there = h.join().unwrap();
            let here = p.solve().unwrap();
            assert_eq!(there.final_state, here.final_state);
            assert_eq!(there.status, Status::Reached);
            let json = serde_json::to_value(&there).unwrap();
            assert_eq!(json["status"], "Reached");
            assert_eq!(json["samples"].as_array().unwrap().len(), 3);
        }
    }

    #[test]
    fn a_solution_is_the_run_of_simulate() {
        let p = default_problem(5.0, 11);
        let s = p.solve().unwrap();
        let mut samples = Vec::new();
        let summary = run(
            &p.ball,
            &ReducedSystem(&p.ball),
            p.initial.to_array(),
            &p.settings,
            &mut |t, x| {
                samples.push((t, *x));
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(s.final_state, summary.final_state);
        assert_eq!(s.stats.steps, summary.steps);
        assert_eq!(s.integrals, summary.integrals);
        for (a, (t, x)) in s.samples.iter().zip(&samples) {
            assert_eq!((a.t, a.state.to_array()), (*t, *x));
        }
    }

    #[test]
    fn the_dense_solution_reproduces_the_dense_output_of_the_steps() {
        // The samples of a run come from the stepper's own dense output on each step; the dense
        // solution stores each step at 8 Chebyshev points and interpolates with degree 7, exact
        // for DOP853's degree-7 interpolant up to round-off of the barycentric formula (1e-12 of
        // |x| ~ 10). Against a run at a tighter tolerance the error is that of DOP853 at 1e-12.
        let p = default_problem(10.0, 101);
        let (s, dense) = p.solve_dense().unwrap();
        assert_eq!(dense.times.len(), s.stats.steps + 1);
        let mut worst: f64 = 0.0;
        for sample in &s.samples {
            let x = dense.at(sample.t).unwrap();
            for (a, b) in x.iter().zip(sample.state.to_array()) {
                worst = worst.max((a - b).abs());
            }
        }
        assert!(worst < 1e-12, "dense solution vs dense output: {worst:e}");
        // At the step ends it is the step's end (unprojected = projected here).
        let end = dense.at(s.t).unwrap();
        assert_eq!(end, s.final_state.to_array());
        // Outside the span it refuses.
        assert!(dense.at(10.5).is_err());
        assert!(dense.at(-0.1).is_err());
        // Negative control: a corrupted node shows.
        let mut bad = dense.clone();
        bad.nodes[3][4][0] += 1e-6;
        let t_mid = 0.5 * (bad.times[3] + bad.times[4]);
        let diff = (bad.at(t_mid).unwrap()[0] - dense.at(t_mid).unwrap()[0]).abs();
        assert!(diff > 1e-8, "{diff:e}");
    }

    #[test]
    fn failure_and_events_are_statuses_with_a_message() {
        // RK4 with two steps over t = 100 blows up: a status, not an error, with the state reached.
        let mut p = default_problem(100.0, 0);
        p.settings = p
            .settings
            .to_builder()
            .method(Method::Rk4 { steps: 2 })
            .build()
            .unwrap();
        let s = p.solve().unwrap();
        assert_eq!(s.status, Status::Failed);
        assert!(s.message.contains("non-finite"), "{}", s.message);
        // An event: gamma1 crosses 0 (the tilt turns), located to round-off.
        let mut p = default_problem(10.0, 0);
        p.event = Some(Plane::new(0, 0.0).unwrap());
        let s = p.solve().unwrap();
        assert_eq!(s.status, Status::Event, "{}", s.message);
        let e = s.events[0];
        assert!(e.t > 0.0 && e.t < 10.0);
        assert!(e.state.gamma[0].abs() < 1e-12, "{:?}", e.state);
        // Negative control: a plane outside (gamma, M), or at a level that is not finite,
        // cannot be built, named in the error.
        for (component, value) in [(6, 0.0), (0, f64::NAN), (5, f64::INFINITY)] {
            let e = Plane::new(component, value).unwrap_err().to_string();
            assert!(e.contains("plane") && e.contains("0 to 5"), "{e}");
        }
    }
}

mod simulate {
    //! Long-time accuracy of `routh::simulate` on the default case: the drift of every integral,
    //! with and without projection, and time reversal.
    //!
    //! These run the integrator for 1000 time units (~1e5 steps): run the suite with
    //! `cargo test` (the README's test command, optimised), where each takes well under a second.

    use routh::case::Case;
    use routh::integrate::Method;
    use routh::simulate::{run, ReducedSystem, Settings, Summary};
    use routh::{Point, State};

    fn simulate(case: &Case, x0: [f64; 6], t_end: f64, project: bool) -> Summary {
        let settings = Settings::builder()
            .method(Method::Dop853)
            .t_end(t_end)
            .tolerances(1e-12, 1e-12)
            .projection(project, 1)
            .build()
            .unwrap();
        run(
            &case.ball,
            &ReducedSystem(&case.ball),
            x0,
            &settings,
            &mut |_, _| Ok(()),
        )
        .unwrap()
    }

    fn worst_drift(summary: &Summary) -> (&'static str, f64) {
        summary
            .integrals
            .iter()
            .map(|(name, d)| (*name, d.max_rel_drift))
            .fold(("", 0.0), |a, b| if b.1 > a.1 { b } else { a })
    }

    #[test]
    fn default_case_to_t_1000_keeps_every_integral_within_2e_10() {
        // The bound: 1e-10 relative over 1000 time units at rtol = atol = 1e-12. The
        // drift grows linearly (truncation bias, ~1.3e-11 per 100 time units for H1), so the
        // bound holds with a margin of 2.5x or more for H1, H3, H4 and K.
        //
        // H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2 is the exception: on this case its terms
        // (24, 16, 65) nearly cancel to |H2| = 24, which amplifies their drifts fourfold to
        // 1.49e-10 relative. SciPy's DOP853 and Hairer's dop853 (C in SciPy 1.17) take the same
        // steps and give the same drift (bench/scipy_dop853.py), so this is the method at this
        // tolerance, not an implementation error; we hold H2 to 2e-10 and report the miss
        // (BENCHMARKS.md).
        //
        // Since issue 33 atol is measured in the motion's units (M in units of m R^2 / T = 8
        // here, where |M| is 4 to 8): the weight of M's error, atol + rtol |M| / 8 in those
        // units, is 2.4x that of the user's units, and the drifts are larger at the same
        // nominal tolerance (measured: H1 3.8e-11, H2 4.3e-10, H3 1.13e-10, H4 5.1e-11, K 9.8e-11
        // over 33,485 steps). The bounds follow: 2e-10, and 6e-10 for H2.
        let case = Case::default_case().unwrap();
        let summary = simulate(&case, case.initial.to_array(), 1000.0, false);
        assert_eq!(
            summary.integrals.len(),
            5,
            "H1, H2, H3, H4 and K are all tracked"
        );
        for (name, drift) in &summary.integrals {
            let bound = if *name == "H2" { 6e-10 } else { 2e-10 };
            assert!(
                drift.max_rel_drift < bound,
                "{name} drifted by {:e}",
                drift.max_rel_drift
            );
        }
        // Negative control: a loose tolerance drifts far beyond the bound, so the bound is sharp.
        let settings = Settings::builder()
            .method(Method::Dop853)
            .t_end(1000.0)
            .tolerances(1e-6, 1e-6)
            .build()
            .unwrap();
        let loose = run(
            &case.ball,
            &ReducedSystem(&case.ball),
            case.initial.to_array(),
            &settings,
            &mut |_, _| Ok(()),
        )
        .unwrap();
        assert!(
            worst_drift(&loose).1 > 1e-8,
            "a loose run did not drift: {:?}",
            worst_drift(&loose)
        );
    }

    #[test]
    fn projection_keeps_every_integral_within_1e_13() {
        // With projection the integrals are reset to their initial values after each step by a
        // Newton iteration that converges to round-off: what remains is the rounding of the
        // integrals' own evaluation, a few 1e-16 relative, far below the 1e-13.
        let case = Case::default_case().unwrap();
        let summary = simulate(&case, case.initial.to_array(), 1000.0, true);
        let (name, drift) = worst_drift(&summary);
        assert!(drift < 1e-13, "{name} drifted by {drift:e} with projection");
    }

    #[test]
    fn time_reversal_recovers_the_start_within_2e_9() {
        // (gamma, M, t) -> (gamma, -M, -t) maps solutions to solutions. Forward to t = 50 and
        // back from the reversed end state returns to the start up to the global error of two
        // runs at 1e-12, amplified by the sensitivity of the flow over 50 time units: 1e-9.
        let case = Case::default_case().unwrap();
        let x0 = case.initial;
        let forward = simulate(&case, x0.to_array(), 50.0, false);
        let back = simulate(
            &case,
            forward.final_state.reversed().to_array(),
            50.0,
            false,
        );
        let end = back.final_state.reversed();
        let scale = x0.to_array().iter().map(|v| v.abs()).fold(0.0, f64::max);
        let error = end
            .to_array()
            .iter()
            .zip(x0.to_array())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
            / scale;
        // 1.05e-9 measured since atol is in the motion's units (2.4x the weight of M's error).
        assert!(error < 2e-9, "time reversal error {error:e}");
        let moved = forward
            .final_state
            .to_array()
            .iter()
            .zip(x0.to_array())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            moved > 1e-2,
            "negative control: the state at t = 50 differs from the start ({moved})"
        );
    }

    #[test]
    fn rk4_converges_to_the_dop853_result_with_order_4() {
        // Fixed-step RK4 on the default case to t = 1: the error against a tight DOP853 run
        // falls by ~2^4 = 16 per halving of the step (allow 13..19: the asymptotic regime).
        let case = Case::default_case().unwrap();
        let x0 = case.initial.to_array();
        let reference = simulate(&case, x0, 1.0, false).final_state.to_array();
        let error = |steps: usize| {
            let settings = Settings::builder()
                .method(Method::Rk4 { steps })
                .t_end(1.0)
                // RK4 takes its equal steps whatever the tolerances: the loosest that validate.
                .tolerances(1e-3, 1e-3)
                .build()
                .unwrap();
            let s = run(
                &case.ball,
                &ReducedSystem(&case.ball),
                x0,
                &settings,
                &mut |_, _| Ok(()),
            )
            .unwrap();
            s.final_state
                .to_array()
                .iter()
                .zip(&reference)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
        };
        let ratio = error(400) / error(800);
        assert!(
            (13.0..19.0).contains(&ratio),
            "RK4 error ratio per halving {ratio}"
        );
    }

    #[test]
    fn samples_are_equally_spaced_and_end_at_t_end() {
        let case = Case::default_case().unwrap();
        let settings = Settings::builder()
            .method(Method::Dop853)
            .t_end(2.0)
            .tolerances(1e-10, 1e-10)
            .samples(5)
            .build()
            .unwrap();
        let mut seen = Vec::new();
        let summary = run(
            &case.ball,
            &ReducedSystem(&case.ball),
            case.initial.to_array(),
            &settings,
            &mut |t, x| {
                seen.push((t, *x));
                Ok(())
            },
        )
        .unwrap();
        let times: Vec<f64> = seen.iter().map(|s| s.0).collect();
        assert_eq!(times, vec![0.0, 0.5, 1.0, 1.5, 2.0]);
        assert_eq!(Point::from_array(&seen[4].1), summary.final_state);
    }

    #[test]
    fn a_triaxial_body_tracks_only_its_integrals() {
        // With I1 != I2 (the remark after (raus-int)) Jellett's H3 and Routh's K are no longer
        // integrals and are not reported; without gravity the quadratic integral (int)
        // M^2 - m r^2 H1 survives and is tracked as H2 (drift at the 1e-10 level of the default
        // tolerance), with gravity there is no H2. Negative control: H3 itself drifts by far more.
        use routh::integrals::jellett;
        let free = routh::Body::new(1.0, 1.0, 0.3, 0.4, 0.45, 0.5, 0.0).unwrap();
        let x0 = State::from_omega(
            &free,
            [0.29552020666133955, 0.0, 0.955336489125606],
            [0.5, 0.2, 8.0],
            routh::state::Normalise::Reject,
        )
        .unwrap();
        let settings = Settings::builder()
            .method(Method::Dop853)
            .t_end(10.0)
            .tolerances(1e-12, 1e-12)
            .build()
            .unwrap();
        let mut h3 = Vec::new();
        let s = run(
            &free,
            &ReducedSystem(&free),
            x0.to_array(),
            &settings.to_builder().samples(101).build().unwrap(),
            &mut |_, x| {
                h3.push(jellett(&free, x));
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(
            s.integrals.keys().copied().collect::<Vec<_>>(),
            vec!["H1", "H2", "H4"]
        );
        assert!(
            s.integrals["H2"].max_rel_drift < 1e-10,
            "{:?}",
            s.integrals["H2"]
        );
        let spread = h3.iter().fold(0.0_f64, |m, v| m.max((v - h3[0]).abs())) / h3[0].abs();
        assert!(
            spread > 1e-6,
            "H3 is not an integral for I1 != I2, yet it moved by only {spread:e}"
        );
        let heavy = routh::Body::new(1.0, 1.0, 0.3, 0.4, 0.45, 0.5, 9.81).unwrap();
        let s = run(
            &heavy,
            &ReducedSystem(&heavy),
            x0.to_array(),
            &settings,
            &mut |_, _| Ok(()),
        )
        .unwrap();
        assert_eq!(
            s.integrals.keys().copied().collect::<Vec<_>>(),
            vec!["H1", "H4"]
        );
    }

    /// The final state at t = 1000 of `settings` on the default case, and its error (max norm,
    /// relative to the reference's) against the quad-precision reference state of the
    /// work-precision benchmark (`bench/work_precision/reference.json`, computed independently
    /// by `bench/work_precision/make_reference.py` in 113-bit arithmetic).
    fn error_at_1000(settings: &Settings) -> f64 {
        let case = Case::default_case().unwrap();
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../bench/work_precision/reference.json"),
        )
        .unwrap();
        let json: serde_json::Value = serde_json::from_str(&text).unwrap();
        let reference: Vec<f64> = json["cases"]["default"]["final"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap().parse().unwrap())
            .collect();
        let summary = run(
            &case.ball,
            &ReducedSystem(&case.ball),
            case.initial.to_array(),
            settings,
            &mut |_, _| Ok(()),
        )
        .unwrap();
        let fin = summary.final_state;
        let x = [fin.gamma, fin.m].concat();
        let size = reference.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        x.iter()
            .zip(&reference)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            / size
    }

    #[test]
    fn projection_every_tenth_step_keeps_the_accuracy_that_projection_gains() {
        // Vern9 at 1e-10 to t = 1000 against the quad-precision reference. Without projection the
        // integrals drift and with them the frequencies of the motion: the phase error grows
        // with time, 4.7e-6 here. Projection after every step holds the integrals and the error
        // falls to ~1e-8; after every 10th step, the drift of 10 steps stays and the error is
        // about the same (1.1e-8 and 5.5e-9 measured). Bounds: 1e-7 for both projected runs
        // (8x above the measurements: round-off moves them by factors of ~2 between builds) and
        // a gain of at least 30 (measured 400 and 850). Negative control: projecting "after every
        // 10^9-th step" (never, in 16,814 steps; only the final state, which is reported as a
        // sample, is projected) has no such gain: it is the drift along the way that projection
        // removes, not the distance of the end state from the level set.
        let settings = |project: bool, project_every: usize| {
            Settings::builder()
                .method(Method::Vern9)
                .t_end(1000.0)
                .tolerances(1e-10, 1e-10)
                .projection(project, project_every)
                .build()
                .unwrap()
        };
        let plain = error_at_1000(&settings(false, 1));
        let every = error_at_1000(&settings(true, 1));
        let tenth = error_at_1000(&settings(true, 10));
        let never = error_at_1000(&settings(true, 1_000_000_000));
        println!(
        "error at t = 1000: plain {plain:.2e}, every step {every:.2e}, every 10th {tenth:.2e}, \
         end only {never:.2e}"
    );
        assert!(every < 1e-7 && tenth < 1e-7, "{every:e} {tenth:e}");
        assert!(plain > 30.0 * every.max(tenth), "{plain:e}");
        assert!(
            never > 30.0 * every.max(tenth),
            "negative control: {never:e}"
        );
    }
}

mod inertia_unit {
    //! Issue 33, last item: `omega = I_Q^{-1} M` is computed in the body's unit of inertia k
    //! (`Ball::inertia_unit`, `max(m R^2, I_max)` rounded to a power of two), as
    //! `(I_Q / k)^{-1} (M / k)`, in both closed forms (cofactors for numbers, the determinant
    //! for the Taylor tape). k being a power of two, every intermediate is the unscaled one
    //! times a power of two: omega is the formula's before, to the bit, for every body in which
    //! that one was finite and normal (the old range `1.6e-51 <= I + m r^2 <= 5.5e51`), and
    //! finite for a body in any units, where the old one overflowed or underflowed.
    //!
    //! Tolerances: zero (bit for bit) wherever the scaling is by powers of two; 4 ulp (relative
    //! 1e-15) between a body and its copy scaled by a decimal factor (1e-300), whose
    //! parameters are each rounded once in the scaling (a relative 1.1e-16 each, carried
    //! through a well-conditioned inverse, condition number below 10 here).

    use routh::sampling::SplitMix64;
    use routh::scalar::{dot, Scalar};
    use routh::units::{scaled_body, scaled_state};
    use routh::{AsBall, Ball, Body, State};

    /// The cofactor form of omega as it was before the body's unit (the code of
    /// `Ball::angular_velocity` in the problem's units, copied literally; `mul_add` and
    /// `recip` those of `Scalar`, as there).
    fn old_cofactors(ball: &Ball, gamma: &[f64; 3], m_vec: &[f64; 3]) -> [f64; 3] {
        let (m, inertia) = (ball.m(), ball.inertia());
        let r = ball.contact_vector(gamma);
        let mr2 = dot(&r, &r) * m;
        let a: [f64; 3] = std::array::from_fn(|i| mr2 + inertia[i]);
        let cofactor = [a[1] * a[2], a[0] * a[2], a[0] * a[1]];
        let det_a = a[0] * cofactor[0];
        let b: [f64; 3] = std::array::from_fn(|i| r[i] * cofactor[i]);
        let c: [f64; 3] = std::array::from_fn(|i| m_vec[i] * cofactor[i]);
        let det_iq = det_a - dot(&r, &b) * m;
        let coupling = dot(&r, &c) * m;
        let scale = Scalar::recip(det_iq * det_a);
        std::array::from_fn(|i| Scalar::mul_add(c[i], det_iq, b[i] * coupling) * scale)
    }

    fn bits(v: [f64; 3]) -> [u64; 3] {
        v.map(f64::to_bits)
    }

    /// Random balls inside the old range (m from 1e-20 to 1e20, R from 1e-5 to 1e5, moments
    /// 0.5 to 1 times m R^2 (the triangle rule holds), the centre of mass anywhere within 0.8 R; one in two with
    /// I1 = I2, so that the determinant form's groups of equal moments are both exercised).
    fn balls(rng: &mut SplitMix64, count: usize) -> Vec<Ball> {
        (0..count)
            .map(|n| {
                let m = 10f64.powf(rng.uniform(-20.0, 20.0));
                let radius = 10f64.powf(rng.uniform(-5.0, 5.0));
                let unit = m * radius * radius;
                let mut moment = || unit * rng.uniform(0.5, 1.0);
                let (i1, i3) = (moment(), moment());
                let i2 = if n % 2 == 0 { i1 } else { moment() };
                let com = [0, 1, 2].map(|_| 0.45 * radius * rng.uniform(-1.0, 1.0));
                Ball::new(m, radius, [i1, i2, i3], com, 9.81).unwrap()
            })
            .collect()
    }

    /// Test 2 of the item: for 400 random balls inside the old range and 10 states each,
    /// the new omega equals the old formula's to the bit, in both forms: the cofactors
    /// against a literal copy of the old code, the determinant against itself in the unit 1
    /// (`Ball::inertia_in(1.0)`: each product by 1 exact, the old operations). 399 of the
    /// 400 have k != 1, so the equality is not that of unchanged code.
    #[test]
    fn omega_in_the_unit_of_inertia_is_the_old_formula_to_the_bit() {
        let mut rng = SplitMix64::new(33);
        let mut scaled = 0;
        for ball in balls(&mut rng, 400) {
            routh::range::check_body(&ball).unwrap();
            let k = ball.inertia_unit();
            assert_eq!(
                k,
                2f64.powi(k.log2() as i32),
                "{ball:?}: k = {k} a power of two"
            );
            scaled += usize::from(k != 1.0);
            let old = ball.inertia_in(1.0);
            for _ in 0..10 {
                let x = rng.phase_point(3.0, 0.0, 0.0);
                let gamma = [x[0], x[1], x[2]];
                let unit = ball.m() * ball.radius() * ball.radius();
                let m_vec = [x[3] * unit, x[4] * unit, x[5] * unit];
                let omega = ball.angular_velocity(&gamma, &m_vec);
                assert!(omega.iter().all(|w| w.is_finite()), "{ball:?}");
                assert_eq!(
                    bits(omega),
                    bits(old_cofactors(&ball, &gamma, &m_vec)),
                    "{ball:?} {x:?}"
                );
                assert_eq!(
                    bits(omega),
                    bits(ball.angular_velocity_in(&old, &gamma, &m_vec))
                );
                assert_eq!(
                    bits(ball.angular_velocity_by_determinant(&gamma, &m_vec)),
                    bits(ball.angular_velocity_by_determinant_in(&old, &gamma, &m_vec)),
                    "{ball:?} {x:?}"
                );
            }
        }
        assert!(scaled >= 390, "{scaled} of 400 balls with k != 1");
    }

    /// The default body in units of mass 2^-997 (m = 7.5e-301) and 2^997 (m = 1.3e300), the
    /// latter also in lengths 2^-332 (R = 1.1e-100, so that `m R^2`, 2^333, keeps the
    /// integrals finite): omega in both forms is the default body's to the bit (scaled by
    /// `1 / s` of the time factor, here 1), and so is Routh's g (times `k l^2`). Test 3, the
    /// negative control: in the problem's units (the unit 1, the old formula) omega of the
    /// same copies is not finite, and g of the copies in mass alone is 0 or infinite.
    #[test]
    fn a_copy_in_other_units_has_the_same_omega_and_the_old_formula_overflows() {
        let body = Body::default();
        let state = State::from_omega(
            &body,
            [0.3_f64.sin(), 0.0, 0.3_f64.cos()],
            [0.5, 0.2, 8.0],
            routh::state::Normalise::Reject,
        )
        .unwrap();
        let omega = state.omega(&body);
        let by_determinant =
            |b: &Body, y: &State| b.ball().angular_velocity_by_determinant(&y.gamma(), &y.m());
        let reference = by_determinant(&body, &state);
        for factors in [
            [2f64.powi(-997), 1.0, 1.0],
            [2f64.powi(997), 1.0, 1.0],
            [2f64.powi(997), 2f64.powi(-332), 1.0],
        ] {
            let copy = scaled_body(&body, factors).unwrap();
            let y = scaled_state(&state, factors).unwrap();
            routh::range::check_body(&copy).unwrap();
            assert_eq!(bits(y.omega(&copy)), bits(omega), "{factors:?}");
            assert_eq!(
                bits(by_determinant(&copy, &y)),
                bits(reference),
                "{factors:?}"
            );
            // Routh's g (of the units of an inertia) in the unit of inertia: the default's times
            // k l^2, to the bit; in the problem's units (the formula before) g^2, of the size
            // of k^2 = 2^-1994 or 2^1994, left f64 (g = 0 or inf, and K = g omega3 with it).
            let [k, l, _] = factors;
            let g = copy.routh_g(&y.gamma());
            assert_eq!(
                g.to_bits(),
                (body.routh_g(&state.gamma()) * k * l * l).to_bits()
            );
            let horizontal = y.gamma()[0] * y.gamma()[0] + y.gamma()[1] * y.gamma()[1];
            let (m, radius, i1, i3) = (copy.m(), copy.radius(), copy.i1(), copy.i3());
            let h = y.gamma()[2] * radius + copy.a();
            let old_g =
                (horizontal * (i1 * m * radius * radius) + h * h * (i3 * m) + i1 * i3).sqrt();
            if l == 1.0 {
                assert!(
                    old_g == 0.0 || old_g.is_infinite(),
                    "{factors:?}: {old_g:e}"
                );
            }
            let ball = copy.ball();
            let old = ball.inertia_in(1.0);
            let before = ball.angular_velocity_in(&old, &y.gamma(), &y.m());
            assert!(
                before.iter().any(|w| !w.is_finite()),
                "{factors:?}: {before:?}"
            );
            assert!(old_cofactors(&ball, &y.gamma(), &y.m())
                .iter()
                .any(|w| !w.is_finite()));
        }
        // A decimal factor: each parameter and M rounded once, omega within 1e-15 |omega|
        // (measured: 1.4e-15 / 8.0 = 1.7e-16 in omega1).
        let factors = [1e-300, 1.0, 1.0];
        let copy = scaled_body(&body, factors).unwrap();
        let y = scaled_state(&state, factors).unwrap();
        let w = y.omega(&copy);
        let size = omega.iter().map(|v| v * v).sum::<f64>().sqrt();
        for i in 0..3 {
            assert!((w[i] - omega[i]).abs() <= 1e-15 * size, "{w:?} {omega:?}");
        }
    }
}
