//! The Routh sphere's Poisson geometry and the audit of the paper's claims (routh-sphere): brackets, Schouten brackets, Hamiltonian flows, the conformal factor, the constructions.
//!
//! One test binary, one module a topic (issue 32: few binaries, each named after what it proves).

mod audit_claims {
    //! One test per claim of the audit registry (its verdict at a few points), and for each check a
    //! negative control: the same check function applied to a perturbed formula (a flipped sign, a
    //! changed factor, a wrong choice of alpha or beta) must exceed the threshold, so that every
    //! check can fail. Five points per check keep the suite fast in debug mode.

    use routh::audit::brackets::{
        cond2_bracket, cond_bracket, field_decomposition, generic_second, int_sph2_defect,
        int_sph_defect, jellett_squared, p_map_defect, printed_second, theta_defect, third,
    };
    use routh::audit::checks;
    use routh::audit::claims::{
        body, find, free_body, generic_first, h4, of, printed_h2_gravity, Sample, Status,
        THRESHOLD, USER_ALPHA, USER_BETA,
    };
    use routh::differential::Dual6;
    use routh::field::vector_field;
    use routh::integrals::{
        energy, jellett, measure_density, quadratic_integral, quadratic_integral_free,
        routh_integral,
    };
    use routh::poisson::first::{
        g_eq1_coefficients, g_eq2_coefficients, Beta, FirstBracket, FirstForm, UserFunction,
    };
    use routh::poisson::lie_poisson::LiePoisson;
    use routh::poisson::reduction::{energy_spherical, integrals_in_l, theta_rate, PoissonMap};
    use routh::poisson::second::{g_eq3_coefficients, g_eq3_coefficients_h1};
    use routh::poisson::{Bivector, Matrix6, Reading};
    use routh::scalar::{dot, split, Real};
    use routh::Body;

    /// The fixed sample of these tests.
    fn sample() -> Sample {
        Sample::new(7, 5).unwrap()
    }

    fn points() -> Vec<[f64; 6]> {
        sample().points(&body())
    }

    /// Run the registry's check of `id` and compare the verdict with `expected`.
    fn assert_verdict(id: &str, expected: Status) {
        let claim = find(id).unwrap_or_else(|| panic!("no claim {id}"));
        let v = claim.verdict(&sample());
        assert_eq!(
            v.status, expected,
            "{id}: residual {:?}, note {}",
            v.residual, v.note
        );
    }

    /// A negative control: the residual of a perturbed formula must exceed the threshold.
    fn assert_fails(what: &str, residual: f64) {
        assert!(
            residual > THRESHOLD,
            "negative control {what} passed: {residual:e}"
        );
    }

    /// A bivector with one entry (and its mirror) scaled and shifted: `P_ij -> f P_ij + c`.
    struct Tweaked<P> {
        inner: P,
        entry: (usize, usize),
        factor: f64,
        shift: f64,
    }

    impl<P: Bivector> Bivector for Tweaked<P> {
        fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
            let mut m = self.inner.entries(x);
            let (i, j) = self.entry;
            m[i][j] = m[i][j] * self.factor + self.shift;
            m[j][i] = -m[i][j];
            m
        }
    }

    /// The bracket `{M1, M2}` scaled by 1.1.
    fn scaled<P: Bivector>(inner: P) -> Tweaked<P> {
        Tweaked {
            inner,
            entry: (3, 4),
            factor: 1.1,
            shift: 0.0,
        }
    }

    fn coefficients_scaled(c: Vec<f64>, k: usize) -> Vec<f64> {
        let mut c = c;
        c[k] *= 1.1;
        c
    }

    #[test]
    fn m_eq_integrals() {
        assert_verdict("m-eq.integrals", Status::Ok);
        let b = free_body();
        let wrong = |x: &[Dual6; 6]| {
            let (gamma, m) = split(x);
            let r = b.contact_vector(&gamma);
            dot(&m, &m) - dot(&r, &r) * energy(&b, x) * (1.1 * b.m())
        };
        assert_fails(
            "H2 with m r^2 -> 1.1 m r^2",
            checks::conservation(&|x| vector_field(&b, x), &[&wrong], &points()),
        );
    }

    #[test]
    fn mg_eq_integrals() {
        assert_verdict("mg-eq.integrals", Status::Ok);
        let b = body();
        let half_potential = |x: &[Dual6; 6]| energy(&b, x) - b.potential(&[x[0], x[1], x[2]]);
        assert_fails(
            "H1 = (M, omega) + U",
            checks::conservation(&|x| vector_field(&b, x), &[&half_potential], &points()),
        );
    }

    #[test]
    fn int_g_h2_printed_and_physical() {
        assert_verdict("int-g.H2", Status::Ok);
        assert_verdict("int-g.H2.physical", Status::Ok);
        let b = body();
        let same_sign = |x: &[Dual6; 6]| printed_h2_gravity(&b, b.gravity(), x);
        assert_fails(
            "printed H2 with g = G against U = +mG(r, gamma)",
            checks::conservation(&|x| vector_field(&b, x), &[&same_sign], &points()),
        );
    }

    #[test]
    fn h2_relation() {
        assert_verdict("H2.relation", Status::Ok);
        let b = free_body();
        let lhs = |x: &[f64; 6]| quadratic_integral_free(&b, x);
        let rhs = |x: &[f64; 6]| quadratic_integral(&b, x) + 0.1 * jellett(&b, x).powi(2);
        assert_fails(
            "m/I1 H3^2 -> (m/I1 - 0.1) H3^2",
            checks::identity(&lhs, &rhs, &points()),
        );
    }

    #[test]
    fn h2_triaxial() {
        assert_verdict("H2.triaxial", Status::Ok);
        let b = Body::new(1.3, 0.8, 0.25, 0.4, 0.45, 0.55, 0.0).unwrap();
        let heavier =
            Body::new(1.1 * b.m(), b.radius(), b.a(), b.i1(), b.i2(), b.i3(), 0.0).unwrap();
        let wrong = |x: &[Dual6; 6]| quadratic_integral_free(&heavier, x);
        assert_fails(
            "H2 with m -> 1.1 m, I1 != I2",
            checks::conservation(&|x| vector_field(&b, x), &[&wrong], &points()),
        );
    }

    #[test]
    fn rho_measure() {
        assert_verdict("rho.measure", Status::Ok);
        let b = body();
        let g = |x: &[Dual6; 6]| b.routh_g(&[x[0], x[1], x[2]]);
        assert_fails(
            "density g instead of 1/g",
            checks::invariant_measure(&|y| vector_field(&b, y), &g, &points()),
        );
        assert!(
            checks::invariant_measure(&|y| vector_field(&b, y), &of(b, measure_density), &points())
                <= THRESHOLD
        );
    }

    #[test]
    fn p_br_jacobi() {
        assert_verdict("p-br.jacobi", Status::Ok);
        assert_fails(
            "{M1, M2} x 1.1",
            checks::jacobi(&scaled(generic_first(body())), &points()),
        );
        let user = FirstBracket::new(body(), USER_ALPHA, USER_BETA);
        assert_fails(
            "user alpha, beta with {M1, M2} x 1.1",
            checks::jacobi(&scaled(user), &points()),
        );
    }

    /// The first-order jet of a user-supplied function carries exact first derivatives through
    /// compositions: `d sin(x1 x2) = cos(x1 x2) (x2, x1)`. (A wrong derivative could not be caught by
    /// the Jacobi identity: (p-br) is Poisson for every alpha(gamma1/gamma2), so at a point any
    /// value and slope belong to some admissible alpha.)
    #[test]
    fn user_function_carries_exact_first_derivatives() {
        let f = UserFunction {
            value: f64::sin,
            derivative: f64::cos,
        };
        let x = [0.3, 2.0, 0.0, 0.0, 0.0, 0.0];
        let (v, d) = routh::differential::gradient(|y| f.at(y[0] * y[1]), &x);
        assert_eq!(v, 0.6f64.sin());
        assert_eq!(d[0], 0.6f64.cos() * 2.0);
        assert_eq!(d[1], 0.6f64.cos() * 0.3);
        assert_eq!(f.at(0.6), 0.6f64.sin());
    }

    #[test]
    fn p_bv_matrix_printed_fails_and_corrected_holds() {
        assert_verdict("p-bv.matrix", Status::Fail);
        assert_verdict("p-bv.matrix.corrected", Status::Ok);
        let p = generic_first(body());
        assert_fails(
            "corrected matrix vs (p-br) with {M1, M2} x 1.1",
            checks::same_bivector(
                &p.with_form(FirstForm::MatrixCorrected),
                &scaled(p),
                &points(),
            ),
        );
    }

    #[test]
    fn p_br_casimirs() {
        assert_verdict("p-br.casimirs", Status::Ok);
        let b = body();
        assert_fails(
            "{M1, M2} x 1.1",
            checks::casimirs(
                &scaled(generic_first(b)),
                &[&h4, &of(b, jellett)],
                &points(),
            ),
        );
    }

    #[test]
    fn p_br_involution() {
        assert_verdict("p-br.involution", Status::Ok);
        let b = free_body();
        assert_fails(
            "{M1, M2} x 1.1",
            checks::involution(
                &scaled(generic_first(b)),
                &of(b, energy),
                &of(b, quadratic_integral_free),
                &points(),
            ),
        );
    }

    #[test]
    fn p_br_rank() {
        assert_verdict("p-br.rank", Status::Ok);
        let full = Tweaked {
            inner: generic_first(body()),
            entry: (0, 1),
            factor: 1.0,
            shift: 0.5,
        };
        assert_fails(
            "{gamma1, gamma2} = 0.5 (rank 6)",
            checks::rank(&full, 4, &points()),
        );
    }

    #[test]
    fn p_br_degenerate_printed_fails_and_swapped_holds() {
        assert_verdict("p-br.degenerate", Status::Fail);
        assert_verdict("p-br.degenerate.corrected", Status::Ok);
        let at_beta0 = FirstBracket::new(
            body(),
            routh::audit::claims::GENERIC_ALPHA,
            Beta::Gamma3([0.0; 3]),
        );
        let shifted = Tweaked {
            inner: at_beta0,
            entry: (2, 3),
            factor: 1.0,
            shift: 0.3,
        };
        assert_fails(
            "{gamma3, M1} = 0.3 at beta = 0",
            checks::casimirs(&shifted, &[&|x: &[Dual6; 6]| x[2]], &points()),
        );
    }

    #[test]
    fn g_eq1() {
        assert_verdict("g-eq1", Status::Ok);
        let p = cond_bracket(body());
        let wrong = |x: &[f64; 6]| {
            coefficients_scaled(g_eq1_coefficients(&p, &[x[0], x[1], x[2]]).to_vec(), 1)
        };
        assert_fails(
            "g2 x 1.1",
            field_decomposition(&p, &wrong, &[energy, quadratic_integral], &points()),
        );
        let generic = FirstBracket {
            beta: Beta::Gamma3([1.1, -0.3, 0.4]),
            ..p
        };
        let printed = |x: &[f64; 6]| g_eq1_coefficients(&p, &[x[0], x[1], x[2]]).to_vec();
        assert_fails(
            "beta not of (cond)",
            field_decomposition(&generic, &printed, &[energy, quadratic_integral], &points()),
        );
    }

    #[test]
    fn cond2_compatible() {
        assert_verdict("cond2.compatible", Status::Ok);
        assert_fails(
            "beta of (cond) instead of (cond2)",
            checks::compatibility(&LiePoisson, &cond_bracket(body()), &points()),
        );
    }

    #[test]
    fn g_eq2() {
        assert_verdict("g-eq2", Status::Ok);
        let p = cond2_bracket(body());
        let wrong = |x: &[f64; 6]| coefficients_scaled(g_eq2_coefficients(&p, x).to_vec(), 0);
        assert_fails(
            "g^1 x 1.1",
            field_decomposition(&p, &wrong, &[energy, routh_integral], &points()),
        );
    }

    #[test]
    fn p_map_e3() {
        assert_verdict("p-map.e3", Status::Ok);
        let map = PoissonMap {
            bracket: generic_first(body()),
            c: 0.0,
        };
        let other = FirstBracket {
            beta: Beta::Gamma3([0.9, 0.1, 0.0]),
            ..map.bracket
        };
        assert_fails(
            "bracket with another beta than the map",
            p_map_defect(&other, &map, &points()),
        );
    }

    fn cond_map() -> PoissonMap {
        PoissonMap {
            bracket: cond_bracket(free_body()),
            c: 0.0,
        }
    }

    #[test]
    fn int_sph_printed_fails_and_corrected_holds() {
        assert_verdict("int-sph", Status::Fail);
        assert_verdict("int-sph.corrected", Status::Ok);
        let wrong =
            |p: &FirstBracket, y: &[f64; 6], b: f64, r: Reading| integrals_in_l(p, y, 1.1 * b, r);
        let [h1, h2] = int_sph_defect(&cond_map(), &wrong, Reading::Corrected, &points());
        assert_fails("b -> 1.1 b in H1", h1);
        assert_fails("b -> 1.1 b in H2", h2);
    }

    #[test]
    fn int_sph2_printed_fails_and_corrected_holds() {
        assert_verdict("int-sph2", Status::Fail);
        assert_verdict("int-sph2.corrected", Status::Ok);
        let wrong =
            |p: &FirstBracket, s: &[f64; 4], b: f64, r: Reading| energy_spherical(p, s, -b, r);
        assert_fails(
            "b -> -b",
            int_sph2_defect(&cond_map(), &wrong, Reading::Corrected, &points()),
        );
    }

    #[test]
    fn theta_quadrature_printed_fails_and_corrected_holds() {
        assert_verdict("theta-quadrature", Status::Fail);
        assert_verdict("theta-quadrature.corrected", Status::Ok);
        let wrong = |p: &FirstBracket, s: &[f64; 4]| 1.1 * theta_rate(p, s);
        let [rate, _] = theta_defect(&cond_map(), &wrong, Reading::Corrected, &points());
        assert_fails("rate x 1.1", rate);
    }

    #[test]
    fn p_f_conformal() {
        assert_verdict("P_f.conformal", Status::Ok);
        let p = FirstBracket::conformal(body());
        let wrong = |x: &[f64; 6]| vec![0.5 / p.alpha_beta(&[x[0], x[1], x[2]]).1];
        assert_fails(
            "+1/(2 beta)",
            field_decomposition(
                &p,
                &wrong,
                &[energy],
                &sample().points_jellett_zero(&p.body),
            ),
        );
    }

    #[test]
    fn p_bv2_involution() {
        assert_verdict("p-bv2.involution", Status::Ok);
        let b = free_body();
        let p = scaled(generic_second(b));
        assert_fails(
            "{M1, M2}' x 1.1",
            checks::casimirs(&p, &[&h4, &of(b, routh_integral)], &points()),
        );
        assert_fails(
            "{M1, M2}' x 1.1",
            checks::involution(&p, &of(b, energy), &of(b, jellett), &points()),
        );
    }

    #[test]
    fn p_bv2_jacobi() {
        assert_verdict("p-bv2.jacobi", Status::Ok);
        assert_fails(
            "generic alpha_i",
            checks::jacobi(&generic_second(body()), &points()),
        );
    }

    #[test]
    fn p2_rank() {
        assert_verdict("P2.rank", Status::Ok);
        assert_fails(
            "P'' (rank 2) tested for rank 4",
            checks::rank(&third(body()), 4, &points()),
        );
    }

    #[test]
    fn g_eq3_printed_fails_and_corrected_holds() {
        assert_verdict("g-eq3", Status::Fail);
        assert_verdict("g-eq3.corrected", Status::Ok);
        let p = printed_second(body());
        let printed = |x: &[f64; 6]| g_eq3_coefficients(&p, &[x[0], x[1], x[2]]).to_vec();
        assert!(
            field_decomposition(
                &p,
                &printed,
                &[quadratic_integral, jellett_squared],
                &points()
            ) <= THRESHOLD
        );
        let wrong = |x: &[f64; 6]| {
            coefficients_scaled(g_eq3_coefficients_h1(&p, &[x[0], x[1], x[2]]).to_vec(), 1)
        };
        assert_fails(
            "g'2 x 1.1",
            field_decomposition(&p, &wrong, &[energy, jellett_squared], &points()),
        );
    }

    #[test]
    fn p3_rank_printed_fails_and_rank_two_holds() {
        assert_verdict("P3.rank", Status::Fail);
        assert_verdict("P3.rank.corrected", Status::Ok);
        assert_fails(
            "P' (rank 4) tested for rank 2",
            checks::rank(&printed_second(body()), 2, &points()),
        );
    }

    #[test]
    fn the_non_existence_statement_is_decided_within_the_ansatz() {
        assert_verdict("eq-cf", Status::OkWithinAnsatz);
    }

    #[test]
    fn every_claim_is_tested_and_ids_are_unique() {
        let ids: Vec<&str> = routh::audit::claims::registry()
            .iter()
            .map(|c| c.id)
            .collect();
        let mut sorted = ids.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), ids.len(), "duplicate ids");
        for required in [
            "m-eq.integrals",
            "mg-eq.integrals",
            "int-g.H2",
            "H2.relation",
            "H2.triaxial",
            "rho.measure",
            "p-br.jacobi",
            "p-bv.matrix",
            "p-br.casimirs",
            "p-br.involution",
            "p-br.rank",
            "p-br.degenerate",
            "g-eq1",
            "cond2.compatible",
            "g-eq2",
            "p-map.e3",
            "int-sph",
            "int-sph2",
            "theta-quadrature",
            "P_f.conformal",
            "p-bv2.involution",
            "p-bv2.jacobi",
            "g-eq3",
            "P2.rank",
            "eq-cf",
        ] {
            assert!(ids.contains(&required), "missing claim {required}");
        }
        for id in ids.iter().filter(|id| id.ends_with(".corrected")) {
            assert_eq!(
                find(id).unwrap().verdict(&sample()).status,
                Status::Ok,
                "{id}"
            );
        }
    }
}

mod audit_constructions {
    //! The two existence claims that the audit decides by construction: the change of momenta that
    //! takes the second bracket P' of (p-bv2) to e*(3) (`p-bv2.e3`), and the field Z with
    //! `P = L_Z P0` under (cond2) (`cond2.trivial-deformation`). Each holds to round-off (the
    //! audit's threshold 1e-10: the residuals are relative to the terms that cancel, round-off and
    //! the 24-node meridian quadratures leave about 1e-15), and each check fails on a perturbed
    //! construction and on a bracket for which the claim is false.

    use routh::audit::brackets::{
        cond2_bracket, cond_bracket, deformation_defect, generic_second, p_map_defect,
        printed_second,
    };
    use routh::audit::claims::{body, find, Sample, Status, THRESHOLD};
    use routh::differential::Dual6;
    use routh::integrals::routh_integral;
    use routh::poisson::deformation::TrivialDeformation;
    use routh::poisson::reduction::MomentumMap;
    use routh::poisson::second_reduction::SecondMap;
    use routh::scalar::Real;

    /// The fixed sample of these tests.
    fn sample() -> Sample {
        Sample::new(11, 6).unwrap()
    }

    fn points() -> Vec<[f64; 6]> {
        sample().points(&body())
    }

    fn assert_fails(what: &str, residual: f64) {
        assert!(
            residual > THRESHOLD,
            "negative control {what} passed: {residual:e}"
        );
    }

    /// The claim holds at 10 points for three seeds, to 1e-13 (round-off and the meridian
    /// quadratures leave 1e-16 to 2e-14).
    fn assert_holds_to_round_off(id: &str) {
        for seed in [1, 2, 3] {
            let v = find(id).unwrap().verdict(&Sample::new(seed, 10).unwrap());
            assert_eq!(v.status, Status::Ok, "{id}: {:?} {}", v.residual, v.note);
            assert!(v.residual.unwrap() < 1e-13, "{id}: {:?}", v.residual);
        }
    }

    /// The map of the second bracket with its correction `K v` scaled by `factor`.
    struct ScaledGauge {
        map: SecondMap,
        factor: f64,
    }

    impl MomentumMap for ScaledGauge {
        fn image<D: Real>(&self, x: &[D; 6]) -> [D; 6] {
            let linear = self.map.linear_part(x);
            let full = self.map.image(x);
            std::array::from_fn(|i| linear[i] + (full[i] - linear[i]) * self.factor)
        }
    }

    #[test]
    fn the_second_bracket_reduces_to_e3() {
        assert_holds_to_round_off("p-bv2.e3");
        let map = SecondMap {
            bracket: printed_second(body()),
        };
        assert!(p_map_defect(&map.bracket, &map, &points()) <= THRESHOLD);
        for factor in [0.0, 1.01] {
            assert_fails(
                &format!("correction K v scaled by {factor}"),
                p_map_defect(&map.bracket, &ScaledGauge { map, factor }, &points()),
            );
        }
        let generic = SecondMap {
            bracket: generic_second(body()),
        };
        assert_fails(
            "the construction for generic alpha_i (P' not Poisson)",
            p_map_defect(&generic.bracket, &generic, &points()),
        );
    }

    /// The image satisfies `(L, gamma) = kappa K` with one constant kappa: the e*(3) Casimir is a
    /// function of the Casimir K of P', as a Poisson map between the leaves requires.
    #[test]
    fn the_e3_casimir_is_a_multiple_of_k() {
        let map = SecondMap {
            bracket: printed_second(body()),
        };
        let ratios: Vec<f64> = points()
            .iter()
            .filter(|x| x[2] > -map.bracket.body.a() / map.bracket.body.radius())
            .map(|x| {
                let y = map.image(x);
                (y[0] * y[3] + y[1] * y[4] + y[2] * y[5]) / routh_integral(&map.bracket.body, x)
            })
            .collect();
        assert!(ratios.len() >= 2);
        for r in &ratios {
            assert!(
                (r - ratios[0]).abs() <= 1e-12 * ratios[0].abs().max(1.0),
                "{ratios:?}"
            );
        }
    }

    #[test]
    fn the_cond2_bracket_is_a_trivial_deformation() {
        assert_holds_to_round_off("cond2.trivial-deformation");
        let z = TrivialDeformation {
            bracket: cond2_bracket(body()),
        };
        let without_w = |y: &[Dual6; 6]| {
            let full = z.field(y);
            let (d, _) = z.gauges(&[y[0].re, y[1].re, y[2].re]);
            let linear = z.linear_field(y);
            let gamma = [y[0], y[1], y[2]];
            let d = d.field(&gamma);
            std::array::from_fn(|i| if i < 3 { full[i] } else { linear[i] + d[i - 3] })
        };
        assert_fails(
            "Z without its (gamma, M) w part",
            deformation_defect(&without_w, &z.bracket, &points()),
        );
        let linear = |y: &[Dual6; 6]| z.linear_field(y);
        assert_fails(
            "Z = C M only",
            deformation_defect(&linear, &z.bracket, &points()),
        );
        // Under (cond) P is not compatible with P0 (cond2.compatible's control), so no Z exists:
        // the same construction must fail there.
        let cond = TrivialDeformation {
            bracket: cond_bracket(body()),
        };
        assert_fails(
            "the construction under (cond)",
            deformation_defect(&|y| cond.field(y), &cond.bracket, &points()),
        );
    }
}

mod eq_cf {
    //! The search for the conformally Hamiltonian form (eq-cf) (`poisson::conformal_search`): the
    //! decision for the real field of (mg-eq), an independent check of the machinery against the
    //! printed (g-eq1), and negative controls in which a solution exists and must be found.
    //!
    //! Tolerances: a consistent system leaves a relative residual of 1e-15 to 2e-12 with momenta
    //! spanning R^3 (up to 3e-10 on the plane (M, r) = 0); the decision threshold
    //! [`CONSISTENCY`] = 1e-8 sits above both; the inconsistent systems of the real field leave 0.1
    //! or more, so the decision tests ask for 1e-2.

    use routh::audit::brackets::cond_bracket;
    use routh::audit::claims::{body, find, free_body, generic_first, Sample, Status};
    use routh::body::Body;
    use routh::differential::Dual6;
    use routh::field::vector_field;
    use routh::integrals::{energy, quadratic_integral};
    use routh::poisson::conformal_search::{
        decide, minimax_ratio, random_momenta, sections, unknowns_of, Decision, Foliation, Section,
        CONSISTENCY,
    };
    use routh::poisson::first::{g_eq1_coefficients, FirstBracket};
    use routh::poisson::hamiltonian::hamiltonian_field;
    use routh::poisson::schouten::jacobi_defect;
    use routh::poisson::Bivector;
    use routh::scalar::dot;

    /// Eight gammas of the audit's sampler (away from the singular sets of the printed formulas,
    /// which the field does not have, so that the controls with (p-br) can use the same points).
    fn gammas(b: &Body, seed: u64) -> Vec<[f64; 3]> {
        Sample::new(seed, 8)
            .unwrap()
            .points(b)
            .iter()
            .map(|x| [x[0], x[1], x[2]])
            .collect()
    }

    fn field_of(b: Body) -> impl Fn(&[f64; 6]) -> [f64; 6] {
        move |x| vector_field(&b, x)
    }

    /// The field X of (mg-eq) has no (eq-cf) form with constant F_a for any of the paper's three
    /// foliations, for three bodies (the audit's with and without gravity, the default case's)
    /// (other seeds: the audit test below): the margin is above 1e-2 (measured 0.1 to 1), seven orders above round-off, and
    /// the rank decisions of the null spaces have gaps below 1e-10 (measured 1e-15 to 3e-12).
    #[test]
    fn the_field_has_no_conformally_hamiltonian_form_with_constant_f() {
        for b in [body(), free_body(), Body::default()] {
            for seed in [3] {
                for foliation in Foliation::ALL {
                    let s = sections(
                        &b,
                        &field_of(b),
                        foliation,
                        &gammas(&b, seed),
                        &random_momenta(seed),
                    );
                    for section in &s {
                        assert!(
                            section.gap() < 1e-10,
                            "{foliation:?}: gap {:e}",
                            section.gap()
                        );
                    }
                    let decision = decide(&s);
                    assert!(
                        decision.margin() > 1e-2,
                        "{b:?} {foliation:?}: {decision:?}"
                    );
                    let expected_no_ratio = foliation == Foliation::Third;
                    assert_eq!(
                        matches!(decision, Decision::NoRatio { .. }),
                        expected_no_ratio,
                        "{decision:?}"
                    );
                }
            }
        }
    }

    /// For the first and second foliations each gamma alone admits a ratio (the residual of the
    /// single-gamma search is at round-off, below 1e-10), so the obstruction is that the ratio
    /// varies with gamma; for the first it is the ratio g2/g1 of the printed (g-eq1) (audit claim
    /// `g-eq1`: X = g1 P dH1 + g2 P dH2 under (cond)), found to 1e-8 relative: an independent
    /// check of the search against the paper.
    #[test]
    fn each_gamma_has_its_ratio_and_the_first_is_that_of_g_eq1() {
        for b in [body(), Body::default()] {
            let p = cond_bracket(b);
            for foliation in [Foliation::First, Foliation::Second] {
                let s = sections(
                    &b,
                    &field_of(b),
                    foliation,
                    &gammas(&b, 5),
                    &random_momenta(5),
                );
                for section in &s {
                    let (ratio, residual) = minimax_ratio(std::slice::from_ref(section));
                    assert!(residual < 1e-10, "{foliation:?} {residual:e}");
                    if foliation == Foliation::First {
                        let [g1, g2] = g_eq1_coefficients(&p, &section.gamma);
                        let found = ratio[1] / ratio[0];
                        assert!(
                            (found - g2 / g1).abs() < 1e-8 * (g2 / g1).abs(),
                            "{found} against {}",
                            g2 / g1
                        );
                    }
                }
            }
        }
    }

    /// The known solution of a control and the search: the decision is [`Decision::Consistent`],
    /// the known bivector solves every section's system with the known ratio (defect below
    /// 1e-12), and the least-squares solution with that ratio is the known one (relative distance
    /// below the square root of the residual bound). With `unique`, the ratio found is the known
    /// one (to 1e-6) and no other ratio works.
    fn assert_found(
        s: &[Section],
        known: &dyn Fn(&[f64; 3]) -> Vec<f64>,
        ratio: &[f64],
        residual_bound: f64,
        unique: bool,
    ) {
        let decision = decide(s);
        let Decision::Consistent {
            ratio: found,
            residual,
        } = &decision
        else {
            panic!("no solution found: {decision:?}");
        };
        assert!(*residual < residual_bound, "{residual:e}");
        if unique {
            let norm = ratio.iter().map(|v| v * v).sum::<f64>().sqrt();
            let sign = found[0].signum() * ratio[0].signum();
            for (f, r) in found.iter().zip(ratio) {
                assert!(
                    (f * sign - r / norm).abs() < 1e-6,
                    "{found:?} against {ratio:?}"
                );
            }
        }
        for section in s {
            assert!(section.residual(ratio) < residual_bound);
            let defect = section.defect(&known(&section.gamma), ratio);
            assert!(defect < 1e-12, "known solution: defect {defect:e}");
            let distance = section.distance_to_solution(&known(&section.gamma), ratio);
            assert!(
                distance < residual_bound.sqrt(),
                "not the solution: {distance:e}"
            );
        }
    }

    /// Negative control 1 (section 3, the conformally Hamiltonian form): on the Jellett level
    /// b = (M, r) = 0, X = -(1/(2 beta)) P_f dH1 (audit claim `P_f.conformal`), so with the momenta
    /// on that plane the search must find F = H1 (ratio (1, 0)) with the bivector
    /// -(1/(2 beta)) P_f: a conformal factor that is a function of gamma, absorbed at each gamma.
    /// Residual bound 1e-8 ([`CONSISTENCY`]: on the plane round-off leaves up to 3e-10). On the
    /// plane the ratio is not unique (the minimax search returns another consistent one), so only
    /// F = H1 with its bivector is asserted.
    #[test]
    fn negative_control_on_the_jellett_zero_level_finds_p_f() {
        let b = body();
        let pf = FirstBracket::conformal(b);
        let field = field_of(b);
        let s: Vec<Section> = gammas(&b, 1)
            .iter()
            .map(|gamma| {
                let r = b.contact_vector(gamma);
                let on_plane: Vec<[f64; 3]> = random_momenta(9)
                    .iter()
                    .map(|m| {
                        let k = dot(m, &r) / dot(&r, &r);
                        std::array::from_fn(|i| m[i] - k * r[i])
                    })
                    .collect();
                Section::new(&b, &field, Foliation::First, gamma, &on_plane)
            })
            .collect();
        let known = |gamma: &[f64; 3]| {
            let c = -0.5 / pf.alpha_beta(gamma).1;
            unknowns_of(|y| pf.entries(y).map(|row| row.map(|v| v * c)), gamma)
        };
        assert_found(&s, &known, &[1.0, 0.0], CONSISTENCY, false);
    }

    /// Negative control 2: X replaced by the Hamiltonian field P dF of the first bracket (p-br) with
    /// the audit's generic alpha, beta, for F = H1, H2 and H1 + 0.5 H2: the search finds the ratio
    /// (1, 0), (0, 1), (1, 0.5) and the bivector P itself (residual below 1e-10, measured 1e-13),
    /// which is Poisson ([P, P] = 0 to 1e-13 relative, round-off 1e-16): the machinery finds a
    /// solution where one exists, with its Schouten bracket.
    #[test]
    fn negative_control_a_hamiltonian_field_of_p_br_is_found() {
        let b = body();
        let p = generic_first(b);
        let known = |gamma: &[f64; 3]| unknowns_of(|y| p.entries(y), gamma);
        for ratio in [[1.0, 0.0], [0.0, 1.0], [1.0, 0.5]] {
            let hamiltonian = move |y: &[Dual6; 6]| {
                energy(&b, y) * ratio[0] + quadratic_integral(&b, y) * ratio[1]
            };
            let field = move |x: &[f64; 6]| hamiltonian_field(&p, hamiltonian, x);
            let gs = gammas(&b, 2);
            let s = sections(&b, &field, Foliation::First, &gs, &random_momenta(2));
            assert_found(&s, &known, &ratio, 1e-10, true);
            for g in &gs {
                let defect = jacobi_defect(&p, &[g[0], g[1], g[2], 0.3, -0.7, 1.1]);
                assert!(defect < 1e-13, "[P, P]: {defect:e}");
            }
        }
    }

    /// Negative control 3, of the decision itself: a Hamiltonian field of (p-br) whose ratio varies
    /// with gamma, X = P d(H1) + gamma3 P dH2 (not of the form (eq-cf) with constant F_a), is
    /// rejected, and multiplying a solvable field by a conformal factor c(gamma) keeps it solvable.
    #[test]
    fn negative_control_a_varying_ratio_is_rejected_and_a_conformal_factor_is_absorbed() {
        let b = body();
        let p = generic_first(b);
        let gs = gammas(&b, 6);
        let varying = move |x: &[f64; 6]| {
            let h1 = hamiltonian_field(&p, |y| energy(&b, y), x);
            let h2 = hamiltonian_field(&p, |y| quadratic_integral(&b, y), x);
            std::array::from_fn(|i| h1[i] + x[2] * h2[i])
        };
        let decision = decide(&sections(
            &b,
            &varying,
            Foliation::First,
            &gs,
            &random_momenta(6),
        ));
        assert!(
            matches!(decision, Decision::RatioVaries { residual, .. } if residual > 1e-3),
            "{decision:?}"
        );
        let scaled = move |x: &[f64; 6]| {
            let c = 1.0 + 0.5 * x[2] + x[0] * x[1];
            hamiltonian_field(&p, |y| energy(&b, y), x).map(|v| v * c)
        };
        let decision = decide(&sections(
            &b,
            &scaled,
            Foliation::First,
            &gs,
            &random_momenta(6),
        ));
        assert!(
            matches!(decision, Decision::Consistent { residual, .. } if residual < 1e-10),
            "{decision:?}"
        );
    }

    /// The audit's verdict: OK-WITHIN-ANSATZ with a margin above 1e-2 for two seeds.
    #[test]
    fn the_audit_decides_eq_cf_within_the_ansatz() {
        for seed in [1, 2] {
            let v = find("eq-cf")
                .unwrap()
                .verdict(&Sample::new(seed, 3).unwrap());
            assert_eq!(v.status, Status::OkWithinAnsatz, "{}", v.note);
            assert!(v.residual.unwrap() > 1e-2, "{:?}", v.residual);
            assert!(v.note.contains("decided within the ansatz"));
        }
    }
}

mod flows {
    //! The flows of X1 = P dH1, X2 = P dH2, X^2 = P dK of the first bracket (section 3.2) by the
    //! theta quadrature ([`routh::poisson::flows`]), against DOP853 on the field P dH (dH by
    //! automatic differentiation of the integrals' own code) from the same initial point; and the
    //! conformally Hamiltonian form at b = 0: the trajectory of X (time t) and that of P_f dH1
    //! (time tau) are one curve with dtau = -(1/(2 beta)) dt, i.e. dt = -2 beta dtau.
    //!
    //! Tolerance 1e-9 (relative to |x|) at t = 10 for both: DOP853 at rtol = atol = 1e-13 over ten
    //! time units leaves about 1e-11, the quadrature (cosine series converged to 1e-12 of dt/ds,
    //! turning points to round-off) about 1e-11; the worst case measured is 4.0e-11.

    use routh::audit::claims::{body, free_body, Sample};
    use routh::field::vector_field as real_field;
    use routh::integrals::{energy, jellett};
    use routh::integrate::{solve, Options};
    use routh::poisson::first::FirstBracket;
    use routh::poisson::flows::{vector_field, Condition, Field, Flow};
    use routh::poisson::hamiltonian::hamiltonian_field;
    use routh::RouthError;

    const TOLERANCE: f64 = 1e-9;

    fn dop853<const N: usize>(f: impl Fn(&[f64; N]) -> [f64; N], x0: [f64; N], t: f64) -> [f64; N] {
        let sys = |_t: f64, y: &[f64; N]| f(y);
        let opts = Options::new(1e-13, 1e-13).unwrap();
        solve(&sys, 0.0, x0, t, &opts, None, None, &mut |_, _| {})
            .unwrap()
            .1
    }

    fn distance(a: &[f64], b: &[f64]) -> f64 {
        let d: f64 = a.iter().zip(b).map(|(u, v)| (u - v).powi(2)).sum();
        (d / b.iter().map(|v| v * v).sum::<f64>()).sqrt()
    }

    fn cases() -> Vec<(routh::Body, Condition, Field)> {
        let mut out = Vec::new();
        for b in [free_body(), body()] {
            for c in [Condition::Cond, Condition::Cond2, Condition::Conformal] {
                for f in [Field::X1, Field::X2, Field::XHat2] {
                    out.push((b, c, f));
                }
            }
        }
        out
    }

    /// Random initial points (the audit's sampler: |gamma_i| >= 0.15, |M_i| <= 2); those whose
    /// theta interval reaches a singular set of the bracket are refused with `Singular`, and at
    /// least five per case must be solved.
    #[test]
    fn quadrature_agrees_with_dop853_at_t_10_forward_and_backward() {
        for (b, condition, field) in cases() {
            let bracket = condition.bracket(b, 0.8);
            let mut solved = 0;
            for x0 in Sample::new(3, 20).unwrap().points(&b) {
                let flow = match Flow::new(bracket, field, &x0) {
                    Ok(flow) => flow,
                    Err(RouthError::Singular { .. }) => continue,
                    Err(e) => panic!("unexpected error {e}"),
                };
                solved += 1;
                for k in 1..10 {
                    let d = flow.phi_defect(0.1 * k as f64 * std::f64::consts::PI);
                    assert!(d < 1e-14, "Phi in the completed-square form: {d:e}");
                }
                let d0 = distance(&flow.state_at(0.0), &x0);
                assert!(d0 < 1e-12, "{d0:e}");
                for t in [10.0, -10.0] {
                    let step = dop853(|y| vector_field(&bracket, field, y), x0, t);
                    let d = distance(&flow.state_at(t), &step);
                    assert!(
                        d < TOLERANCE,
                        "{condition:?} {field:?} G = {}: {d:e} at t = {t}",
                        b.gravity()
                    );
                }
            }
            assert!(solved >= 5, "{condition:?} {field:?}: only {solved} solved");
        }
    }

    /// The default case (a fast top, tilt 0.3, gamma2 = 0): all three fields under both
    /// conditions, alpha = 1 as in `routh exact --flow`.
    #[test]
    fn default_case_flows_agree_with_dop853() {
        let case = routh::case::Case::load(None).unwrap();
        let x0 = case.initial.to_array();
        for condition in [Condition::Cond, Condition::Cond2] {
            let bracket = condition.bracket(case.body("the flows").unwrap(), 1.0);
            for field in [Field::X1, Field::X2, Field::XHat2] {
                let flow = Flow::new(bracket, field, &x0).unwrap();
                let step = dop853(|y| vector_field(&bracket, field, y), x0, 10.0);
                let d = distance(&flow.state_at(10.0), &step);
                assert!(d < TOLERANCE, "{condition:?} {field:?}: {d:e}");
            }
        }
    }

    /// Negative controls: the same comparison fails for the field of another alpha, of the other
    /// condition, or at another time.
    #[test]
    fn quadrature_comparison_can_fail() {
        let b = free_body();
        let x0 = Sample::new(3, 20)
            .unwrap()
            .points(&b)
            .into_iter()
            .find(|x| Flow::new(Condition::Cond2.bracket(b, 0.8), Field::X1, x).is_ok())
            .unwrap();
        let flow = Flow::new(Condition::Cond2.bracket(b, 0.8), Field::X1, &x0).unwrap();
        let at = flow.state_at(10.0);
        for (bracket, t) in [
            (Condition::Cond2.bracket(b, 0.8 * 1.001), 10.0),
            (Condition::Cond.bracket(b, 0.8), 10.0),
            (Condition::Cond2.bracket(b, 0.8), 10.01),
        ] {
            let step = dop853(|y| vector_field(&bracket, Field::X1, y), x0, t);
            assert!(distance(&at, &step) > TOLERANCE);
        }
    }

    /// Under (cond) beta is infinite at gamma3 = 0: a motion whose theta interval contains the
    /// equator is refused, naming it.
    #[test]
    fn a_flow_through_the_singular_set_is_refused() {
        let b = free_body();
        let bracket = Condition::Cond.bracket(b, 0.8);
        let x0 = [0.6, 0.79, 0.1f64.sin(), 0.3, -0.2, 0.4];
        let norm = (x0[0] * x0[0] + x0[1] * x0[1] + x0[2] * x0[2]).sqrt();
        let x0 = [
            x0[0] / norm,
            x0[1] / norm,
            x0[2] / norm,
            x0[3],
            x0[4],
            x0[5],
        ];
        match Flow::new(bracket, Field::X1, &x0) {
            Err(RouthError::Singular { reason, .. }) => {
                assert!(reason.contains("beta"), "{reason}")
            }
            other => panic!("expected a refusal, got {other:?}"),
        }
    }

    /// At b = (M, r) = 0, X = -1/(2 beta) P_f dH1 with the P_f of (cham-vp): integrate
    /// `dx/dtau = P_f dH1`, `dt/dtau = -2 beta` (so that `dx/dt = -1/(2 beta) P_f dH1 = X`) and
    /// compare x(tau) with the trajectory of X at t(tau), at 20 points along each of four
    /// trajectories, with and without gravity (tau up to 5/|beta(0)|, so that t reaches about 10).
    /// Negative control: `dt/dtau = +2 beta`.
    #[test]
    fn conformal_form_at_b_zero_is_the_same_curve_with_the_time_change() {
        let worst = conformal_defect(-1.0, &free_body()).max(conformal_defect(-1.0, &body()));
        assert!(worst < TOLERANCE, "{worst:e}");
        assert!(conformal_defect(1.0, &free_body()) > TOLERANCE);
    }

    /// The same at b = 0 with the quadrature: the theta quadrature of P_f dH1 (beta of P_f is a
    /// function of gamma3) taken at tau, against the motion X by DOP853 at
    /// `t(tau) = -2 int beta dtau` (the time change itself by composite Gauss-Legendre along the
    /// quadrature's trajectory, 40 panels of 20 nodes on [0, tau]).
    #[test]
    fn conformal_quadrature_with_the_time_change_is_the_motion_at_b_zero() {
        let rule = routh::quadrature::gauss::GaussLegendre::new(20);
        for b in [free_body(), body()] {
            let pf = Condition::Conformal.bracket(b, 0.0);
            for x0 in Sample::new(9, 6).unwrap().points_jellett_zero(&b) {
                let Ok(flow) = Flow::new(pf, Field::X1, &x0) else {
                    continue;
                };
                let beta = |x: &[f64; 6]| pf.alpha_beta(&[x[0], x[1], x[2]]).1;
                let tau = 2.0 / beta(&x0).abs();
                let panels = 40;
                let h = tau / panels as f64;
                let t: f64 = (0..panels)
                    .map(|k| {
                        -2.0 * h * rule.integrate(|u| beta(&flow.state_at((k as f64 + u) * h)))
                    })
                    .sum();
                let x = dop853(|y| real_field(&b, y), x0, t);
                let d = distance(&flow.state_at(tau), &x);
                assert!(d < TOLERANCE, "G = {}: {d:e}", b.gravity());
            }
        }
    }

    /// The largest distance between the two curves with `dt/dtau = 2 sign beta`.
    fn conformal_defect(sign: f64, b: &routh::Body) -> f64 {
        let pf = FirstBracket::conformal(*b);
        let h1 = |y: &[routh::differential::Dual6; 6]| energy(b, y);
        let mut worst = 0.0f64;
        for x0 in Sample::new(5, 4).unwrap().points_jellett_zero(b) {
            assert!(jellett(b, &x0).abs() < 1e-14);
            let augmented = |z: &[f64; 7]| {
                let x = [z[0], z[1], z[2], z[3], z[4], z[5]];
                let y = hamiltonian_field(&pf, h1, &x);
                let beta = pf.alpha_beta(&[x[0], x[1], x[2]]).1;
                [y[0], y[1], y[2], y[3], y[4], y[5], sign * 2.0 * beta]
            };
            let z0 = [x0[0], x0[1], x0[2], x0[3], x0[4], x0[5], 0.0];
            let beta0 = pf.alpha_beta(&[x0[0], x0[1], x0[2]]).1;
            let tau_end = 5.0 / beta0.abs();
            for k in 1..=20 {
                let z = dop853(augmented, z0, tau_end * k as f64 / 20.0);
                let x = dop853(|y| real_field(b, y), x0, z[6]);
                worst = worst.max(distance(&z[..6], &x));
            }
        }
        worst
    }
}

mod schouten {
    //! The Schouten bracket against known cases: the Lie-Poisson bivector of e*(3) is Poisson, a
    //! hand-made non-Poisson bivector gives the trivector derived by hand, and the bracket is
    //! symmetric and bilinear on bivectors.

    use routh::audit::claims::{body, generic_first, Sample};
    use routh::poisson::lie_poisson::LiePoisson;
    use routh::poisson::schouten::{jacobi_defect, schouten, TRIPLES};
    use routh::poisson::{Bivector, Jet, Matrix6};
    use routh::scalar::{lift, Real};

    fn points() -> Vec<[f64; 6]> {
        Sample::new(11, 10).unwrap().points(&body())
    }

    #[test]
    fn lie_poisson_bivector_of_e3_is_poisson() {
        // The entries are linear, so [P0, P0] is a sum of a few products of O(1) numbers: exact up
        // to one rounding each, 1e-14 absolute is far above that.
        for x in points() {
            let jet = Jet::at(&LiePoisson, &x);
            let t = schouten(&jet, &jet);
            assert!(
                t.iter().all(|v| v.abs() < 1e-14),
                "[P0, P0] = {t:?} at {x:?}"
            );
        }
    }

    /// `{x1, x2} = x4`, `{x3, x4} = 1` (1-based), all other brackets of coordinates zero.
    ///
    /// By hand: the only non-zero derivative is `d P^{12} / dx4 = 1`, and the only bracket with x4
    /// is `P^{34} = 1`, so the Jacobiator `J^{ijk} = sum_cyc sum_l P^{il} d_l P^{jk}` has the single
    /// non-zero term `P^{34} d_4 P^{12} = 1` in the component (1, 2, 3):
    /// `{x3, {x1, x2}} = {x3, x4} = 1`. Hence `[P, P]^{123} = 2 J^{123} = 2` and the other 19
    /// components vanish, at every point.
    struct NotPoisson;

    impl Bivector for NotPoisson {
        fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
            let mut p = [[lift::<D>(0.0); 6]; 6];
            p[0][1] = x[3];
            p[1][0] = -x[3];
            p[2][3] = lift(1.0);
            p[3][2] = lift(-1.0);
            p
        }
    }

    #[test]
    fn a_non_poisson_bivector_gives_the_trivector_derived_by_hand() {
        for x in points() {
            let jet = Jet::at(&NotPoisson, &x);
            for (t, [i, j, k]) in schouten(&jet, &jet).iter().zip(TRIPLES) {
                let expected = if [i, j, k] == [0, 1, 2] { 2.0 } else { 0.0 };
                assert_eq!(*t, expected, "[P, P]^{{{i}{j}{k}}} at {x:?}");
            }
            assert!(jacobi_defect(&NotPoisson, &x) > 0.1);
        }
    }

    #[test]
    fn twenty_distinct_triples() {
        let mut t = TRIPLES.to_vec();
        t.dedup();
        assert_eq!(t.len(), 20);
        assert!(TRIPLES.iter().all(|[i, j, k]| i < j && j < k && *k < 6));
    }

    /// `P0 + P` of the first bracket, for the bilinearity test.
    struct Sum;

    impl Bivector for Sum {
        fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
            let a = LiePoisson.entries(x);
            let b = generic_first(body()).entries(x);
            std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] + b[i][j]))
        }
    }

    #[test]
    fn schouten_bracket_is_symmetric_and_bilinear_on_bivectors() {
        // [P0 + P, P0 + P] = [P0, P0] + 2 [P0, P] + [P, P]; each side is a sum of terms of size
        // |P| |dP| ~ 1e1, so 1e-12 absolute is round-off with a margin.
        for x in points() {
            let p0 = Jet::at(&LiePoisson, &x);
            let p = Jet::at(&generic_first(body()), &x);
            let s = Jet::at(&Sum, &x);
            let (pq, qp) = (schouten(&p0, &p), schouten(&p, &p0));
            let (pp, p0p0, ss) = (schouten(&p, &p), schouten(&p0, &p0), schouten(&s, &s));
            for n in 0..20 {
                assert!((pq[n] - qp[n]).abs() < 1e-12);
                assert!((ss[n] - (p0p0[n] + 2.0 * pq[n] + pp[n])).abs() < 1e-12);
            }
        }
    }
}
