//! The exact solution by quadrature against the DOP853 integrator, the nutation period
//! against the integrator's events, and the degenerate cases.

use routh::body::Body;
use routh::case::Case;
use routh::field::vector_field;
use routh::integrals::{energy, jellett, routh_integral};
use routh::integrate::{solve, Options, Stop};
use routh::quadrature::{ExactSolution, Motion};
use routh::state::{Normalise, State};
use routh::RouthError;

/// DOP853 at rtol = atol = 1e-13 from `x0` to `t`.
fn integrate(body: &Body, x0: &State, t: f64) -> State {
    let opts = Options {
        rtol: 1e-13,
        atol: 1e-13,
        ..Options::default()
    };
    let field = |_t: f64, x: &[f64; 6]| vector_field(body, x);
    let (_, y, _, _) = solve(&field, 0.0, x0.to_array(), t, &opts, None, None, &mut |_, _| {})
        .expect("integration");
    State::from_array(&y)
}

/// Largest difference of the components of two states, relative to the size of each half.
fn distance(a: &State, b: &State) -> f64 {
    let rel = |x: &[f64; 3], y: &[f64; 3]| {
        let scale = x.iter().fold(0.0_f64, |m, v| m.max(v.abs())).max(1e-300);
        x.iter().zip(y).fold(0.0_f64, |m, (p, q)| m.max((p - q).abs())) / scale
    };
    rel(&a.gamma, &b.gamma).max(rel(&a.m, &b.m))
}

fn default_case() -> (Body, State) {
    let case = Case::default_case().unwrap();
    (case.body, case.initial)
}

#[test]
fn state_at_zero_is_the_initial_state() {
    let (body, x0) = default_case();
    let exact = ExactSolution::new(&body, &x0).unwrap();
    let d = distance(&exact.state_at(0.0), &x0);
    assert!(d < 1e-12, "{d:e}");
}

#[test]
fn default_case_agrees_with_dop853() {
    let (body, x0) = default_case();
    let exact = ExactSolution::new(&body, &x0).unwrap();
    let period = exact.period().unwrap();
    for t in [0.37, 10.0 * period, 1000.0] {
        let d = distance(&exact.state_at(t), &integrate(&body, &x0, t));
        println!("t = {t}: {d:e}");
    }
}
