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
    let opts = Options {
        rtol: 1e-13,
        atol: 1e-13,
        ..Options::default()
    };
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
        for x0 in (Sample { seed: 3, count: 20 }).points(&b) {
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
                    b.gravity
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
    let x0 = (Sample { seed: 3, count: 20 })
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
        Err(RouthError::Singular { reason, .. }) => assert!(reason.contains("beta"), "{reason}"),
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
        for x0 in (Sample { seed: 9, count: 6 }).points_jellett_zero(&b) {
            let Ok(flow) = Flow::new(pf, Field::X1, &x0) else {
                continue;
            };
            let beta = |x: &[f64; 6]| pf.alpha_beta(&[x[0], x[1], x[2]]).1;
            let tau = 2.0 / beta(&x0).abs();
            let panels = 40;
            let h = tau / panels as f64;
            let t: f64 = (0..panels)
                .map(|k| -2.0 * h * rule.integrate(|u| beta(&flow.state_at((k as f64 + u) * h))))
                .sum();
            let x = dop853(|y| real_field(&b, y), x0, t);
            let d = distance(&flow.state_at(tau), &x);
            assert!(d < TOLERANCE, "G = {}: {d:e}", b.gravity);
        }
    }
}

/// The largest distance between the two curves with `dt/dtau = 2 sign beta`.
fn conformal_defect(sign: f64, b: &routh::Body) -> f64 {
    let pf = FirstBracket::conformal(*b);
    let h1 = |y: &[routh::differential::Dual6; 6]| energy(b, y);
    let mut worst = 0.0f64;
    for x0 in (Sample { seed: 5, count: 4 }).points_jellett_zero(b) {
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
