//! Every refusal of a case file names the table, the key, the value and the rule, including
//! the TOML parser's type and length errors, whose own text names neither the key nor the
//! value (issue 33: "in [initial]: invalid length 2, expected an array of length 3").

use super::{Case, DEFAULT_CASE};
#[cfg(feature = "sweep")]
use crate::sweep::spec::Spec;

/// The default case with the line that starts with `key =` in `[table]` replaced by
/// `key = value` (appended to the table when the key is not written there).
fn with(table: &str, key: &str, value: &str) -> String {
    let mut lines: Vec<String> = DEFAULT_CASE.lines().map(str::to_string).collect();
    let start = lines
        .iter()
        .position(|l| l.trim() == format!("[{table}]"))
        .unwrap();
    let end = lines[start + 1..]
        .iter()
        .position(|l| l.starts_with('['))
        .map_or(lines.len(), |i| start + 1 + i);
    let line = format!("{key} = {value}");
    match (start + 1..end).find(|&i| lines[i].starts_with(&format!("{key} ="))) {
        Some(i) => lines[i] = line,
        None => lines.insert(end, line),
    }
    lines.join("\n")
}

/// The message of the refusal of `text`.
fn refusal(text: &str) -> String {
    Case::parse(text, "case.toml").unwrap_err().to_string()
}

/// A wrong type for every key of [body], [initial] and [integration], and a wrong length
/// for every array: the message names the table, the key, the value as written and the
/// parser's rule.
#[test]
fn type_and_length_errors_name_table_key_and_value() {
    let cases = [
        (
            "body",
            "m",
            "\"heavy\"",
            "invalid type: string \"heavy\", expected f64",
        ),
        ("body", "R", "[1.0]", "invalid type: sequence, expected f64"),
        (
            "body",
            "a",
            "true",
            "invalid type: boolean `true`, expected f64",
        ),
        ("body", "I1", "{ x = 1 }", "expected f64"),
        (
            "body",
            "I2",
            "\"0.4\"",
            "invalid type: string \"0.4\", expected f64",
        ),
        ("body", "I3", "false", "expected f64"),
        ("body", "G", "\"earth\"", "expected f64"),
        (
            "initial",
            "gamma",
            "[0.0, 1.0]",
            "invalid length 2, expected an array of length 3",
        ),
        (
            "initial",
            "gamma",
            "[0.0, 0.0, 0.0, 1.0]",
            "invalid length 4, expected fewer elements in array",
        ),
        (
            "initial",
            "gamma",
            "\"up\"",
            "expected an array of length 3",
        ),
        (
            "initial",
            "omega",
            "[1.0]",
            "invalid length 1, expected an array of length 3",
        ),
        ("initial", "omega", "[1.0, 2.0, \"x\"]", "expected f64"),
        ("initial", "normalize", "1", "expected a boolean"),
        ("integration", "t_end", "\"long\"", "expected f64"),
        ("integration", "rtol", "[1e-12]", "expected f64"),
        ("integration", "atol", "true", "expected f64"),
        ("integration", "max_steps", "-5", "expected usize"),
        ("integration", "max_steps", "1.5", "expected usize"),
    ];
    for (table, key, value, rule) in cases {
        let e = refusal(&with(table, key, value));
        let shown: toml::Value =
            toml::from_str::<toml::Table>(&format!("v = {value}")).unwrap()["v"].clone();
        let want = format!("case file case.toml: in [{table}]: invalid {key} = {shown}: ");
        assert!(
            e.starts_with(&want),
            "{table}.{key} = {value}: {e}\n(wanted {want})"
        );
        assert!(e.contains(rule), "{table}.{key} = {value}: {e}");
    }
    // The array keys M and com, which the default case does not write.
    let m_instead = with("initial", "omega", "[1.0, 2.0]").replace("omega =", "M =");
    let e = refusal(&m_instead);
    assert!(
        e.contains("in [initial]: invalid M = [1.0, 2.0]: invalid length 2"),
        "{e}"
    );
    let com = with("body", "a", "0.3").replace("a = 0.3", "com = [0.0, 0.1]");
    let e = refusal(&com);
    assert!(
        e.contains("in [body]: invalid com = [0.0, 0.1]: invalid length 2"),
        "{e}"
    );
    // Control: the default case is read.
    Case::parse(DEFAULT_CASE, "case.toml").unwrap();
}

/// Errors that are not one entry's keep the parser's text, which names the key: a missing
/// key, and an unknown one (named with its value as well).
#[test]
fn missing_and_unknown_keys_are_named() {
    let e = refusal(&DEFAULT_CASE.replace("R = 1.0\n", ""));
    assert!(e.ends_with("in [body]: missing field `R`"), "{e}");
    let e = refusal(&with("integration", "steps", "10"));
    assert!(
        e.contains("in [integration]: invalid steps = 10: unknown field `steps`"),
        "{e}"
    );
}

/// The `[sweep]` table's own checks name the key, the value and the rule for wrong types
/// and lengths as well.
#[cfg(feature = "sweep")]
#[test]
fn sweep_type_errors_name_key_and_value() {
    let cases = [
        (
            "samples = \"many\"\ntilt = { range = [0.1, 0.2] }",
            "`samples` = \"many\"",
            "must be an integer",
        ),
        (
            "seed = 1.5\nsamples = 4\ntilt = { range = [0.1, 0.2] }",
            "`seed` = 1.5",
            "must be an integer",
        ),
        (
            "design = 3\nsamples = 4\ntilt = { range = [0.1, 0.2] }",
            "`design` = 3",
            "must be \"sobol\"",
        ),
        ("tilt = 0.3", "`tilt` = 0.3", "expected { values = [...] }"),
        (
            "tilt = { values = [0.1, \"x\"] }",
            "`tilt` = { values = [0.1, \"x\"] }",
            "expected f64",
        ),
        ("spin = { range = [1.0], n = 3 }", "`spin`", "range"),
        (
            "spin = { range = [1.0, 2.0], n = \"3\" }",
            "`spin`",
            "expected i64",
        ),
    ];
    for (text, named, rule) in cases {
        let table: toml::Table = text.parse().unwrap();
        let e = Spec::parse(&table).unwrap_err().to_string();
        assert!(
            e.starts_with(&format!("[sweep] key {named}")),
            "{text}: {e}"
        );
        assert!(e.contains(rule), "{text}: {e}");
    }
    // Control: a valid table is read.
    let table: toml::Table = "tilt = { range = [0.1, 0.2], n = 3 }".parse().unwrap();
    Spec::parse(&table).unwrap();
}
