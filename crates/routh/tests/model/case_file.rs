//! The TOML case schema: the default case parses, and each rule of the schema and of the
//! body and state validation gives an error that names the key (or parameter) and the file.

use routh::case::{Case, DEFAULT_CASE};
use routh::{AppError, FileError};

fn with(old: &str, new: &str) -> String {
    assert!(
        DEFAULT_CASE.contains(old),
        "test edits a line that is not in the default case: {old}"
    );
    DEFAULT_CASE.replacen(old, new, 1)
}

fn error_of(text: &str) -> String {
    match Case::parse(text, "cases/test.toml") {
        Ok(_) => panic!("accepted an invalid case:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn default_case_parses_and_i2_defaults_to_i1() {
    let case = Case::default_case().unwrap();
    assert_eq!(case.ball.inertia[1], case.ball.inertia[0]);
    assert_eq!(case.integration.t_end, 100.0);
    let omega = case.initial.omega(&case.ball);
    for (w, expected) in omega.iter().zip([0.5, 0.2, 8.0]) {
        assert!(
            (w - expected).abs() < 1e-14,
            "omega round trip through M = I_Q omega: {w} vs {expected}"
        );
    }
}

#[test]
fn unknown_keys_are_named_with_the_file() {
    let e = error_of(&with("G = 9.81", "G = 9.81\nmass = 2.0"));
    assert!(
        e.contains("mass") && e.contains("cases/test.toml") && e.contains("[body]"),
        "{e}"
    );
    let e = error_of(&with("rtol = 1e-12", "rtol = 1e-12\nmethod = 3"));
    assert!(e.contains("method") && e.contains("[integration]"), "{e}");
}

#[test]
fn missing_fields_are_named() {
    let e = error_of(&with("R = 1.0\n", ""));
    assert!(e.contains("`R`") && e.contains("cases/test.toml"), "{e}");
    let e = error_of(&DEFAULT_CASE.replace("[initial]", "[other]"));
    assert!(
        e.contains("[other]") && e.contains("cases/test.toml"),
        "{e}"
    );
}

#[test]
fn omega_and_m_exactly_one() {
    let e = error_of(&with(
        "omega = [0.5, 0.2, 8.0]",
        "omega = [0.5, 0.2, 8.0]\nM = [1.0, 0.0, 0.0]",
    ));
    assert!(e.contains("exactly one"), "{e}");
    let e = error_of(&with("omega = [0.5, 0.2, 8.0]", ""));
    assert!(e.contains("exactly one"), "{e}");
}

#[test]
fn malformed_toml_is_reported() {
    let e = error_of("[body\nm = 1");
    assert!(
        e.contains("malformed TOML") && e.contains("cases/test.toml"),
        "{e}"
    );
}

#[test]
fn each_body_rule_is_enforced() {
    let cases = [
        ("m = 1.0", "m = 0.0", "m = 0"),
        ("m = 1.0", "m = nan", "must be finite"),
        ("R = 1.0", "R = -1.0", "R = -1"),
        ("a = 0.3", "a = 1.0", "|a| < R"),
        ("a = 0.3", "a = inf", "must be finite"),
        ("I1 = 0.4", "I1 = -0.4", "I1 = -0.4"),
        ("I3 = 0.5", "I3 = 0.9", "I1 + I2 >= I3"),
        ("I3 = 0.5", "I3 = 0.2\nI2 = 0.1", "I2 + I3 >= I1"),
        ("I3 = 0.5", "I3 = 0.5\nI2 = 1.0", "I3 + I1 >= I2"),
        ("I3 = 0.5", "I3 = 0.5\nI2 = 0.0", "I2 = 0"),
        ("G = 9.81", "G = -9.81", "G = -9.81: must be >= 0"),
    ];
    for (old, new, expected) in cases {
        let e = error_of(&with(old, new));
        assert!(
            e.contains(expected),
            "`{new}` gave `{e}`, expected `{expected}`"
        );
    }
}

#[test]
fn state_rules_are_enforced() {
    let e = error_of(&with(
        "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
        "gamma = [0.3, 0.0, 0.955]",
    ));
    assert!(e.contains("not a unit vector"), "{e}");
    let e = error_of(&with("omega = [0.5, 0.2, 8.0]", "omega = [nan, 0.2, 8.0]"));
    assert!(e.contains("non-finite"), "{e}");
    let e = error_of(&with(
        "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
        "gamma = [0.0, 0.0, 0.0]\nnormalize = true",
    ));
    assert!(e.contains("cannot be normalised"), "{e}");
    let ok = Case::parse(
        &with(
            "gamma = [0.29552020666133955, 0.0, 0.955336489125606]",
            "gamma = [0.0, 0.0, 2.0]\nnormalize = true",
        ),
        "x",
    )
    .unwrap();
    assert_eq!(ok.initial.gamma, [0.0, 0.0, 1.0]);
}

#[test]
fn integration_rules_are_enforced() {
    for (old, new, name) in [
        ("t_end = 100.0", "t_end = -1.0", "t_end"),
        ("t_end = 100.0", "t_end = nan", "t_end"),
        ("rtol = 1e-12", "rtol = 0.0", "rtol"),
        ("atol = 1e-12", "atol = -1e-12", "atol"),
    ] {
        let e = error_of(&with(old, new));
        assert!(e.contains(name) && e.contains("invalid option"), "{e}");
    }
}

#[test]
fn missing_file_is_an_error_naming_it() {
    let e = Case::from_file(std::path::Path::new("/nonexistent/case.toml")).unwrap_err();
    assert!(matches!(e, AppError::File(FileError::Case { .. })));
    assert!(e.to_string().contains("/nonexistent/case.toml"));
}
