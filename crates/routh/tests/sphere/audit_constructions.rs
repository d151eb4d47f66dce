//! The two existence claims that the audit decides by construction: the change of momenta that
//! takes the second bracket P' of (p-bv2) to e*(3) (`p-bv2.e3`), and the field Z with
//! `P = L_Z P0` under (cond2) (`cond2.trivial-deformation`). Each holds to round-off (the
//! audit's threshold 1e-10: the residuals are relative to the terms that cancel, round-off and
//! the 24-node meridian quadratures leave about 1e-15), and each check fails on a perturbed
//! construction and on a bracket for which the claim is false.

use routh::audit::brackets::{
    cond2_bracket, cond_bracket, deformation_defect, generic_second, p_map_defect, printed_second,
};
use routh::audit::claims::{body, find, Sample, Status, THRESHOLD};
use routh::differential::Dual6;
use routh::integrals::routh_integral;
use routh::poisson::deformation::TrivialDeformation;
use routh::poisson::reduction::MomentumMap;
use routh::poisson::second_reduction::SecondMap;
use routh::scalar::Real;

const SAMPLE: Sample = Sample { seed: 11, count: 6 };

fn points() -> Vec<[f64; 6]> {
    SAMPLE.points(&body())
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
        let v = find(id).unwrap().verdict(&Sample { seed, count: 10 });
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
        .filter(|x| x[2] > -map.bracket.body.a / map.bracket.body.radius)
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
