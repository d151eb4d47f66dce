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
    Sample { seed, count: 8 }
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
        let hamiltonian =
            move |y: &[Dual6; 6]| energy(&b, y) * ratio[0] + quadratic_integral(&b, y) * ratio[1];
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
        let v = find("eq-cf").unwrap().verdict(&Sample { seed, count: 3 });
        assert_eq!(v.status, Status::OkWithinAnsatz, "{}", v.note);
        assert!(v.residual.unwrap() > 1e-2, "{:?}", v.residual);
        assert!(v.note.contains("decided within the ansatz"));
    }
}
