//! The reproducers of issue 33's messages, as a user runs them: each bad input is refused with
//! exit code 2 and a message naming the key, the value and the rule (the input that caused
//! the failure, not a quantity computed from it); each control beside it runs.

use crate::common;

use common::{assert_exit_2, routh};

/// The default case with `from` replaced by `to`, written to a file of its own; its path.
fn case_with(name: &str, from: &str, to: &str) -> String {
    let text = std::fs::read_to_string(format!("{}/cases/default.toml", common::ROOT)).unwrap();
    assert!(text.contains(from), "{from}");
    let dir = std::env::temp_dir().join(format!("routh-messages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text.replace(from, to)).unwrap();
    path.display().to_string()
}

const GAMMA: &str = "gamma = [0.29552020666133955, 0.0, 0.955336489125606]";

/// The summary of `routh simulate --json` with `args`.
fn simulate_json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["simulate", "--json"];
    all.extend_from_slice(args);
    common::json_of(&routh(&all))
}

/// Reproducer 1: gamma = [1e200, 1e200, 0] with `normalize = true` ran with gamma = [0, 0, 0];
/// it is now normalised without overflow, and a gamma of length 0 is refused.
#[test]
fn a_huge_gamma_is_normalised_and_a_zero_one_refused() {
    let huge = case_with(
        "huge-gamma",
        GAMMA,
        "gamma = [1e200, 1e200, 0.0]\nnormalize = true",
    );
    let summary = simulate_json(&["--case", &huge, "--t-end", "0.1"]);
    let gamma = &summary["initial_state"]["gamma"];
    let half = std::f64::consts::FRAC_1_SQRT_2;
    for (i, want) in [half, half, 0.0].into_iter().enumerate() {
        let got = gamma[i].as_f64().unwrap();
        assert!((got - want).abs() <= 1e-15, "{gamma}");
    }
    let zero = case_with(
        "zero-gamma",
        GAMMA,
        "gamma = [0.0, 0.0, 0.0]\nnormalize = true",
    );
    for command in ["simulate", "exact"] {
        assert_exit_2(
            &[command, "--case", &zero],
            "gamma = [0.0, 0.0, 0.0] has length 0 and cannot be normalised",
        );
    }
}

/// Reproducer 2: m = 1e40 blamed "the spin omega3 = inf" (the spin is 8); the mass, whose
/// m R^2 against the moments makes I_Q singular in f64, is named with the rule.
#[test]
fn a_huge_mass_is_blamed_not_the_spin() {
    let heavy = case_with("heavy", "m = 1.0", "m = 1e40");
    for command in ["simulate", "exact", "steady"] {
        assert_exit_2(
            &[command, "--case", &heavy],
            "invalid body parameter m = 1e40: makes the inertia",
        );
    }
    // Control: the same body in other units (mass and moments by 1e30) runs.
    simulate_json(&["--case", &heavy_copy("heavy-control"), "--t-end", "0.1"]);
}

/// The default case in units of mass 1e30 times larger (m and the moments by 1e30), in the
/// file `name`.toml.
fn heavy_copy(name: &str) -> String {
    let path = case_with(name, "m = 1.0", "m = 1e30");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("I1 = 0.4", "I1 = 0.4e30")
        .replace("I3 = 0.5", "I3 = 0.5e30");
    std::fs::write(&path, text).unwrap();
    path
}

/// Reproducers 3 and 5: `--atol 1e-320` ended in "step size too small at t = 0: h = 0", and
/// `--rtol 2.2e-14`, the bound the message and the README print, was refused. A tolerance
/// below its printed bound is refused naming it; the bound itself runs.
#[test]
fn tolerances_are_refused_by_their_printed_bounds() {
    assert_exit_2(
        &["simulate", "--atol", "1e-320"],
        "invalid option atol = 1e-320",
    );
    assert_exit_2(
        &["simulate", "--atol", "1e-320"],
        "must be >= 1e-150 (the step control squares error / atol",
    );
    assert_exit_2(
        &["simulate", "--rtol", "2.1e-14"],
        "invalid option rtol = 2.1e-14: must be >= 2.2e-14",
    );
    simulate_json(&["--rtol", "2.2e-14", "--atol", "1e-150", "--t-end", "0.1"]);
}

/// Reproducer 4: `--t-end 0 --samples 2` blamed "samples = 0", a value never given; t_end,
/// which makes the span empty, is named with its value.
#[test]
fn samples_on_an_empty_span_name_t_end() {
    assert_exit_2(
        &["simulate", "--t-end", "0", "--samples", "2"],
        "invalid option t_end = 0: must be > 0 when samples are asked for",
    );
    // Control: t_end = 0 without samples runs.
    simulate_json(&["--t-end", "0"]);
}

/// Reproducer 6: type and length errors of a case file name the table, the key, the value
/// and the rule (the parser's own text named neither the key nor the value).
#[test]
fn case_type_errors_name_the_key() {
    let short = case_with("short-gamma", GAMMA, "gamma = [0.0, 1.0]");
    assert_exit_2(
        &["simulate", "--case", &short],
        "in [initial]: invalid gamma = [0.0, 1.0]: invalid length 2, expected an array of length 3",
    );
    let text = case_with("text-m", "m = 1.0", "m = \"one\"");
    assert_exit_2(
        &["exact", "--case", &text],
        "in [body]: invalid m = \"one\": invalid type: string \"one\", expected f64",
    );
}
