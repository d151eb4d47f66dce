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
    body, find, free_body, generic_first, h4, of, printed_h2_gravity, Sample, Status, THRESHOLD,
    USER_ALPHA, USER_BETA,
};
use routh::differential::Dual6;
use routh::field::vector_field;
use routh::integrals::{
    energy, jellett, measure_density, quadratic_integral, quadratic_integral_free, routh_integral,
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

const SAMPLE: Sample = Sample { seed: 7, count: 5 };

fn points() -> Vec<[f64; 6]> {
    SAMPLE.points(&body())
}

/// Run the registry's check of `id` and compare the verdict with `expected`.
fn assert_verdict(id: &str, expected: Status) {
    let claim = find(id).unwrap_or_else(|| panic!("no claim {id}"));
    let v = claim.verdict(&SAMPLE);
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
        dot(&m, &m) - dot(&r, &r) * energy(&b, x) * (1.1 * b.m)
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
    let same_sign = |x: &[Dual6; 6]| printed_h2_gravity(&b, x);
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
    let b = Body {
        i2: 0.45,
        ..free_body()
    };
    let wrong = |x: &[Dual6; 6]| quadratic_integral_free(&Body { m: 1.1 * b.m, ..b }, x);
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
    let wrong =
        |x: &[f64; 6]| coefficients_scaled(g_eq1_coefficients(&p, &[x[0], x[1], x[2]]).to_vec(), 1);
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
    let wrong = |p: &FirstBracket, s: &[f64; 4], b: f64, r: Reading| energy_spherical(p, s, -b, r);
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
        field_decomposition(&p, &wrong, &[energy], &SAMPLE.points_jellett_zero(&p.body)),
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
            find(id).unwrap().verdict(&SAMPLE).status,
            Status::Ok,
            "{id}"
        );
    }
}
