//! The robustness properties of issue 10, shared by the fuzz targets (`fuzz/`, run by
//! `cargo fuzz`) and their short proptest version (`tests/fuzz_properties.rs`, run by CI):
//! every entry point takes arbitrary input without panicking, and whatever it accepts gives
//! finite numbers. Each function panics when a property fails.

#![allow(dead_code)]

use routh::body::Body;
use routh::case::Case;
use routh::integrals::Integrals;
use routh::quadrature::ExactSolution;
use routh::state::{Normalise, Point, State};
use routh::table::{Table, OPTIONAL_COLUMNS};
use routh::AsBall;

/// Values that sit on the edges of the rules and of f64.
const SPECIAL: [f64; 16] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    1e-300,
    1e300,
    f64::MIN_POSITIVE,
    f64::MAX,
    f64::EPSILON,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e-8,
    1e8,
    9.81,
];

/// Numbers from bytes, 9 bytes each: the first byte picks raw f64 bits (0..64), a special
/// value (64..128), or a value of moderate size `x * 10^k`, x in [-1, 1), k in -4..=4.
pub fn decode_f64s(data: &[u8]) -> Vec<f64> {
    data.chunks_exact(9)
        .map(|chunk| {
            let bits = u64::from_le_bytes(chunk[1..].try_into().unwrap());
            match chunk[0] {
                0..64 => f64::from_bits(bits),
                64..128 => SPECIAL[bits as usize % SPECIAL.len()],
                tag => {
                    let unit = (bits >> 11) as f64 / (1u64 << 53) as f64;
                    (2.0 * unit - 1.0) * 10f64.powi(i32::from(tag % 9) - 4)
                }
            }
        })
        .collect()
}

fn all_finite(values: &[f64]) -> bool {
    values.iter().all(|v| v.is_finite())
}

fn state_finite(state: &Point) -> bool {
    all_finite(&state.to_array())
}

/// The field and the integrals at an accepted state are finite.
pub fn field_and_integrals_finite(body: &(impl AsBall + std::fmt::Debug), state: &State) {
    let x = state.to_array();
    let field = routh::field::vector_field(body, &x);
    assert!(
        all_finite(&field),
        "field {field:?} at {state:?} of {body:?}"
    );
    for value in Integrals::at(body, &x).values().into_iter().flatten() {
        assert!(
            value.is_finite(),
            "integral {value} at {state:?} of {body:?}"
        );
    }
    assert!(
        all_finite(&state.omega(body)),
        "omega at {state:?} of {body:?}"
    );
}

/// The case parser on arbitrary text.
pub fn case_text(text: &str) {
    match Case::parse(text, "fuzz.toml") {
        Ok(case) => {
            let b = case.ball;
            assert!(all_finite(&[b.m(), b.radius(), b.gravity()]));
            assert!(all_finite(&b.inertia()) && all_finite(&b.com()));
            assert!(state_finite(&case.initial.point()));
            field_and_integrals_finite(&b, &case.initial);
            let i = case.integration;
            assert!(i.t_end().is_finite() && i.t_end() >= 0.0 && i.max_steps() >= 1);
            routh::case::check_tolerances(i.rtol(), i.atol()).unwrap();
        }
        Err(e) => assert!(e.to_string().contains("fuzz.toml"), "{e}"),
    }
}

/// The CSV reader of `plot` and `animate` on arbitrary text.
pub fn csv_text(text: &str) {
    let Ok(table) = Table::parse_csv(text, "fuzz.csv") else {
        return;
    };
    assert!(table.len() >= 2);
    for name in table.names() {
        let column = table.column(name).unwrap();
        if !OPTIONAL_COLUMNS.contains(&name.as_str()) {
            assert!(all_finite(column), "column {name}: {column:?}");
        }
    }
    let t = table.column("t").unwrap();
    assert!(t.windows(2).all(|w| w[0] < w[1]), "t: {t:?}");
    let _ = routh::plot::standard_plots(&table);
    if let Ok(page) = routh::animate::html(&table) {
        let data_nan = [",NaN", "[NaN", ":NaN"].iter().any(|p| page.contains(p));
        assert!(!data_nan, "the page's data hold a NaN");
    }
}

/// What the numerical entry points are run on ([`numerics`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parts {
    /// The field, the integrals and the steady motions: the model, fast (fuzz target
    /// `numerics_model`).
    Model,
    /// The exact solution only (fuzz target `numerics_exact`): slow where the input reaches
    /// the quadrature, whose work is bounded per nutation (docs/reliability.md).
    Exact,
    /// Both (the proptest version).
    All,
}

/// The numerical entry points on arbitrary numbers: a body (m, R, a, I1, I2, I3, G; I2 is
/// set to I1 when the ninth number is negative, to reach the Routh sphere often), gamma,
/// omega, a time and a tilt; `parts` says which entry points are run on an accepted body and
/// state (the field and integrals are checked by every part).
pub fn numerics(values: &[f64], parts: Parts) {
    let Some(&[m, r, a, i1, i2, i3, g, sym, g1, g2, g3, w1, w2, w3, t, tilt]) = values.get(..16)
    else {
        return;
    };
    let i2 = if sym < 0.0 { i1 } else { i2 };
    let Ok(body) = Body::new(m, r, a, i1, i2, i3, g) else {
        return;
    };
    if routh::range::check_body(&body).is_err() {
        return;
    }
    let Ok(state) = State::from_omega(&body, [g1, g2, g3], [w1, w2, w3], Normalise::Rescale) else {
        return;
    };
    if routh::range::check_state(&body, &state).is_err() {
        return;
    }
    field_and_integrals_finite(&body, &state);
    if !body.is_symmetric() {
        return;
    }
    if parts != Parts::Model {
        exact(&body, &state, t);
    }
    if parts != Parts::Exact {
        steady(&body, state.omega(&body)[2], tilt);
    }
}

/// The exact solution, where it exists, gives finite states at finite times.
fn exact(body: &Body, state: &State, t: f64) {
    let Ok(solution) = ExactSolution::new(body, state) else {
        return;
    };
    let (low, high) = solution.turning_points();
    assert!(
        low.is_finite() && high.is_finite(),
        "turning points {low}, {high}"
    );
    if let Some(period) = solution.period() {
        assert!(period.is_finite() && period > 0.0, "period {period}");
    }
    // The command refuses a non-finite t; a finite one is kept within the range tried.
    let t = if t.is_finite() {
        t.clamp(-1e6, 1e6)
    } else {
        0.0
    };
    for time in [0.0, 1.0, t] {
        let s = solution.state_at(time);
        assert!(
            state_finite(&s),
            "state at t = {time}: {s:?} from {state:?} of {body:?}"
        );
    }
}

/// The steady motions, where they exist, are finite.
fn steady(body: &Body, spin: f64, tilt: f64) {
    for pole in [1.0, -1.0] {
        if let Ok(v) = routh::steady::vertical_spin(body, pole, spin) {
            assert!(
                all_finite(&[v.threshold_spin, v.stability.q_second_derivative])
                    && state_finite(&v.state.point()),
                "vertical spin {v:?} of {body:?}"
            );
        }
    }
    let theta = tilt.rem_euclid(std::f64::consts::PI);
    if let Ok(list) = routh::steady::steady_precessions(body, theta, spin) {
        for p in list {
            assert!(
                all_finite(&[p.omega_t, p.precession, p.stability.q_second_derivative])
                    && state_finite(&p.state.point()),
                "steady precession {p:?} of {body:?}"
            );
        }
    }
}
