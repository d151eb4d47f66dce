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
        properties::numerics(&properties::decode_f64s(&bytes), true);
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
        ], true);
    }
}

/// Negative control: the finiteness check does fail where the range checks would have
/// refused the input (m = 1e300 overflows the inverse of the inertia).
#[test]
#[should_panic(expected = "at State")]
fn the_finiteness_check_fails_on_an_overflowing_body() {
    let body = routh::Body {
        m: 1e300,
        ..routh::Body::default()
    };
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
    let refusal = routh::steady::vertical_spin(&body, 1.0, -1.1732762318796806e-125).unwrap_err();
    assert!(
        refusal.to_string().contains("derivatives of g overflow"),
        "{refusal}"
    );
    let bytes: &[u8] = &[
        196, 196, 196, 196, 0, 215, 0, 255, 255, 255, 247, 255, 255, 255, 255, 255, 255, 255, 255,
        255, 65, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
        255, 255, 255, 255, 255, 255, 255, 255, 0, 2, 255, 255, 255, 255, 11, 255, 0, 0, 0, 0, 0,
        0, 198, 33, 42, 0, 0, 35, 196, 33, 196, 196, 196, 196, 255, 165, 165, 165, 165, 255, 0, 0,
        0, 0, 0, 0, 7, 255, 255, 255, 255, 32, 0, 0, 0, 0, 0, 198, 33, 0, 0, 0, 0, 0, 7, 255, 255,
        255, 255, 32, 0, 0, 0, 0, 0, 198, 33, 42, 0, 0, 35, 196, 33, 196, 196, 196, 196, 255, 165,
        165, 165, 165, 255, 0, 215, 0, 255, 255, 255, 255, 0, 215, 196, 255, 196, 0, 196, 196, 0,
        38, 10, 255,
    ];
    properties::numerics(&properties::decode_f64s(bytes), true);
    // Negative control: a moment at the limit is accepted.
    let sane = routh::Body {
        i3: 1e-59 * 10.0,
        ..body
    };
    assert!(routh::quadrature::Reduction::new(&sane, 1.0, 0.0, 0.0).is_ok());
}

/// The timeout the `numerics` fuzz target found (1.5 s, docs/reliability.md): a body of mass
/// 1000 with a = 0.993 R, whose Q has a singularity 0.005 beyond gamma3 = -1, at rest
/// (omega 1e-309) with gamma horizontal. Every sample of the quadrature bisected its
/// Gauss-Legendre rule toward the singularity; the work is now bounded (`WORK_BUDGET`) and
/// the motion refused with the reason. No panic, no NaN.
#[test]
fn fuzz_timeout_near_singular_body_is_refused() {
    let bytes: &[u8] = &[
        196, 196, 196, 196, 0, 215, 0, 239, 255, 255, 247, 255, 255, 255, 255, 255, 255, 255, 255,
        255, 255, 65, 49, 255, 255, 35, 255, 255, 255, 245, 255, 255, 255, 255, 255, 255, 255, 255,
        147, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
        255, 255, 255, 255, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 27,
        0, 0, 0, 0, 0, 0, 0, 255, 251, 255, 255, 255, 0, 0, 0, 36, 255, 248, 255, 255, 255, 255,
        40, 0, 0, 0, 0, 17, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 25, 0, 0, 0, 0, 0,
        20, 20, 147, 147, 147, 20, 20, 147, 163, 147, 147, 147, 0, 215, 0, 255, 255, 255, 255, 255,
        0, 196, 255, 196, 0, 196, 10, 255,
    ];
    let values = properties::decode_f64s(bytes);
    properties::numerics(&values, true);
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
