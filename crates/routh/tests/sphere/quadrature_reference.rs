//! The exact solution by quadrature against stored numbers of an earlier version: a change
//! that only reorganises the arithmetic (hoisting, fewer automatic-differentiation passes)
//! must leave the nutation period and the advance per period equal to round-off, the error
//! estimates nearly equal, and the same decisions (steady, nutation, which refusal).
//!
//! The data file `tests/data/quadrature_reference.csv` was written by this test in its write
//! mode on commit 1276152 (before the quadrature was made cheaper, issue 13, and before the
//! field was written with exact identities, issue 12):
//! `ROUTH_WRITE_QUADRATURE_REFERENCE=1 cargo test -p routh --test sphere quadrature_reference`.

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
                x.m[0] *= 1.0 + off;
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
                x.m[0] += off * (1.0 + x.m[0].abs());
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
            let mut x = *x;
            x.m = x.m.map(|m| m * (1.0 + 1e-11));
            let (_, new) = parse(&outcome(body, &x));
            let (values, _) = differences(new, parse(old).1);
            values[0].max(values[1]) > AGREEMENT
        })
        .count();
    assert!(moved >= 10, "only {moved} of 20 moved states seen");
}
