//! Issue 35: `routh simulate` on a case with a `[contact]` table: the tippe top of
//! `cases/tippe_top.toml` inverts, the tops of the published conditions do not, the table of
//! samples has the contact's columns, `law = "rolling"` is the default to the bit, the rubber
//! ball of `cases/rubber.toml` keeps its energy and its constraint, and every bad contact is
//! refused with exit code 2 and its reason.

use crate::common::{assert_exit_2, json_of, routh, ROOT};
use routh::contact::rubber::COLUMN_NAMES as RUBBER_COLUMNS;
use routh::contact::sliding::OBSERVATION_NAMES;
use routh::table::STATE_COLUMN_NAMES;
use std::path::PathBuf;

/// `cases/tippe_top.toml` with `edit` applied to its text, written to a fresh file.
fn tippe_top_with(name: &str, edit: impl Fn(String) -> String) -> PathBuf {
    case_with("tippe_top", name, edit)
}

/// `cases/<case>.toml` with `edit` applied to its text, written to a fresh file `name`.
fn case_with(case: &str, name: &str, edit: impl Fn(String) -> String) -> PathBuf {
    let text = std::fs::read_to_string(format!("{ROOT}/cases/{case}.toml")).unwrap();
    let dir = std::env::temp_dir().join(format!("routh-contact-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, edit(text)).unwrap();
    path
}

/// `routh simulate` of `cases/<case>.toml` to t = 1 with `samples` samples written to a CSV
/// file: its text and the summary printed.
fn samples_of(case: &str, samples: &str) -> (String, String) {
    let dir = std::env::temp_dir().join(format!("routh-{case}-csv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("samples.csv");
    let out = routh(&[
        "simulate",
        "--case",
        &format!("cases/{case}.toml"),
        "--t-end",
        "1",
        "--samples",
        samples,
        "--out",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    (text, String::from_utf8_lossy(&out.stdout).into_owned())
}

/// The must-show from the command line: the tippe top of the case file rises from
/// R - a = 0.7 to R + a = 1.3 (within 1e-3 at t = 20, as the library's test), Jellett's
/// integral drifts by less than 1e-9 and H1 + the friction's work by less than 1e-9. The same
/// top spun at omega3 = 6 stays below the centre (height < R = 1) all along, and one with
/// I1 = 0.6 (I1/I3 = 1.5) more than 0.1 R below R + a (a partial inversion).
#[test]
fn the_tippe_top_of_the_case_file_inverts() {
    let json = json_of(&routh(&[
        "simulate",
        "--case",
        "cases/tippe_top.toml",
        "--json",
    ]));
    assert_eq!(json["status"], "ok");
    let height = json["final_state"]["height"].as_f64().unwrap();
    assert!((height - 1.3).abs() < 1e-3, "{height}");
    assert!(json["initial_state"]["height"].as_f64().unwrap() < 0.71);
    assert!(
        json["balance"]["jellett"].as_f64().unwrap() < 1e-9,
        "{json}"
    );
    assert!(
        json["balance"]["energy_balance"].as_f64().unwrap() < 1e-9,
        "{json}"
    );
    for (name, from, to, bound) in [
        (
            "slow.toml",
            "omega = [0.0, 0.0, 20.0]",
            "omega = [0.0, 0.0, 6.0]",
            1.0,
        ),
        ("oblate.toml", "I1 = 0.37", "I1 = 0.6", 1.2),
    ] {
        let case = tippe_top_with(name, |t| t.replace(from, to));
        let json = json_of(&routh(&[
            "simulate",
            "--case",
            case.to_str().unwrap(),
            "--json",
        ]));
        let highest = json["balance"]["height_range"][1].as_f64().unwrap();
        assert!(highest < bound, "{name}: {highest}");
    }
}

/// The CSV of a sliding run: the contact's columns (height, slip speed, normal force,
/// Jellett, H1, work) after the state, one row per sample, the first row's height R - a cos 0.1
/// to 1e-15 (the height of the case's initial tilt, exact but for rounding).
#[test]
fn the_samples_have_the_contact_columns() {
    let (text, summary) = samples_of("tippe_top", "11");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header, OBSERVATION_NAMES);
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 11);
    let column = header.iter().position(|&n| n == "height").unwrap();
    let first: f64 = rows[0].split(',').nth(column).unwrap().parse().unwrap();
    assert!(
        (first - (1.0 - 0.3 * 0.1_f64.cos())).abs() < 1e-15,
        "{first}"
    );
    assert!(
        summary.contains("contact  sliding, viscous friction"),
        "{summary}"
    );
}

/// `law = "rolling"` written out is the default, to the bit: the default case with and
/// without `[contact] law = "rolling"` gives the same final state, integrals and work.
#[test]
fn rolling_written_out_is_the_default_to_the_bit() {
    let text = std::fs::read_to_string(format!("{ROOT}/cases/default.toml")).unwrap();
    let dir = std::env::temp_dir().join(format!("routh-contact-rolling-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let case = dir.join("rolling.toml");
    std::fs::write(&case, format!("{text}\n[contact]\nlaw = \"rolling\"\n")).unwrap();
    let run = |case: &str| {
        let mut json = json_of(&routh(&[
            "simulate", "--case", case, "--t-end", "5", "--json",
        ]));
        json.as_object_mut().unwrap().remove("elapsed_s");
        json
    };
    assert_eq!(run("cases/default.toml"), run(case.to_str().unwrap()));
}

/// Bad contacts and states of a sliding case are refused with exit code 2 and their reason,
/// never run: an unknown law or friction, a missing or negative mu, friction keys under the
/// rolling law, a velocity with the rolling law or with a vertical part, a sliding case given
/// to a command that integrates only the rolling law, and `--full`.
#[test]
fn bad_contacts_are_refused() {
    let refused = |name: &str, from: &str, to: &str, expected: &str| {
        let case = tippe_top_with(name, |t| t.replace(from, to));
        assert_exit_2(&["simulate", "--case", case.to_str().unwrap()], expected);
    };
    refused(
        "law.toml",
        "law = \"sliding\"",
        "law = \"magnetic\"",
        "unknown law = \"magnetic\"",
    );
    refused(
        "friction.toml",
        "\"viscous\"",
        "\"dry\"",
        "unknown friction = \"dry\"; known: \"viscous\", \"coulomb\"",
    );
    let coulomb = tippe_top_with("coulomb.toml", |t| t.replace("\"viscous\"", "\"coulomb\""));
    assert_exit_2(
        &[
            "simulate",
            "--case",
            coulomb.to_str().unwrap(),
            "--method",
            "taylor",
        ],
        "is not available with Coulomb's friction",
    );
    refused(
        "mu.toml",
        "mu = 0.3",
        "mu = -0.3",
        "invalid option mu = -0.3",
    );
    refused("nomu.toml", "mu = 0.3", "", "law = \"sliding\" needs `mu`");
    refused(
        "rolling.toml",
        "law = \"sliding\"",
        "law = \"rolling\"",
        "`friction` and `mu` belong to law = \"sliding\"",
    );
    refused(
        "velocity.toml",
        "[contact]\nlaw = \"sliding\"\nfriction = \"viscous\"\nmu = 0.3",
        "",
        "`velocity` belongs to a sliding contact",
    );
    refused(
        "vertical.toml",
        "velocity = [0.0, 0.0, 0.0]",
        "velocity = [0.0, 0.0, 1.0]",
        "is not horizontal",
    );
    assert_exit_2(
        &["steady", "--case", "cases/tippe_top.toml"],
        "is integrated by `routh simulate` (every law) and `routh sweep`",
    );
    let coulomb = tippe_top_with("coulomb-full.toml", |t| {
        t.replace("friction = \"viscous\"", "friction = \"coulomb\"")
    });
    assert_exit_2(
        &["simulate", "--case", coulomb.to_str().unwrap(), "--full"],
        "viscous friction only",
    );
}

/// The rubber ball of `cases/rubber.toml` from the command line: H1 and H4 drift by less than
/// 1e-9 over t = 5 at the default tolerances (1e-12 per step over a few hundred steps), the
/// constraint's residual `max |omega . gamma| / |omega|` is below 1e-9, the rolling law's H3
/// and K are not reported (not integrals of the rubber ball), and F is not either (gravity,
/// centre of mass off the centre); the CSV has the state, omega and the rubber ball's columns,
/// its twist column zero to 1e-9 of |omega| (about 5).
#[test]
fn the_rubber_ball_keeps_its_energy_and_its_constraint() {
    let json = json_of(&routh(&[
        "simulate",
        "--case",
        "cases/rubber.toml",
        "--t-end",
        "5",
        "--json",
    ]));
    let integrals = json["integrals"].as_object().unwrap();
    let names: Vec<&str> = integrals.keys().map(|k| k.as_str()).collect();
    assert_eq!(names, ["H1", "H4"], "{json}");
    for (name, d) in integrals {
        assert!(
            d["max_rel_drift"].as_f64().unwrap() < 1e-9,
            "{name}: {json}"
        );
    }
    assert!(json["twist"].as_f64().unwrap() < 1e-9, "{json}");
    let (text, summary) = samples_of("rubber", "5");
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let want: Vec<&str> = std::iter::once("t")
        .chain(STATE_COLUMN_NAMES)
        .chain(RUBBER_COLUMNS)
        .collect();
    assert_eq!(header, want);
    let twist = header.iter().position(|&n| n == "twist").unwrap();
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 5);
    for row in rows {
        let value: f64 = row.split(',').nth(twist).unwrap().parse().unwrap();
        assert!(value.abs() < 5e-9, "{row}");
    }
    assert!(summary.contains("contact  rubber"), "{summary}");
}

/// Bad rubber cases are refused with exit code 2 and their reason, never run or changed: an
/// initial omega with a part along gamma (omega . gamma = 1e-6, above 1e-12 |omega|),
/// friction keys and a velocity under the rubber law, the other commands, `--full` and
/// `--project`. Control: the case as written runs (the test above).
#[test]
fn bad_rubber_cases_are_refused() {
    let refused = |name: &str, from: &str, to: &str, expected: &str| {
        let case = case_with("rubber", name, |t| t.replace(from, to));
        assert_exit_2(&["simulate", "--case", case.to_str().unwrap()], expected);
    };
    refused(
        "rubber-twist.toml",
        "omega = [-4.0, 1.0, 3.0]",
        "omega = [-4.0, 1.0, 3.00000125]",
        "the rubber ball does not twist: omega . gamma = 1.0000000",
    );
    refused(
        "rubber-mu.toml",
        "law = \"rubber\"",
        "law = \"rubber\"\nmu = 0.3",
        "`friction` and `mu` belong to law = \"sliding\"; law = \"rubber\" has no friction",
    );
    refused(
        "rubber-velocity.toml",
        "omega = [-4.0, 1.0, 3.0]",
        "omega = [-4.0, 1.0, 3.0]\nvelocity = [0.0, 0.0, 0.0]",
        "`velocity` belongs to a sliding contact",
    );
    for command in ["exact", "steady", "sweep", "lyapunov"] {
        assert_exit_2(
            &[command, "--case", "cases/rubber.toml"],
            "[contact] law = \"rubber\" is integrated by `routh simulate`",
        );
    }
    assert_exit_2(
        &["simulate", "--case", "cases/rubber.toml", "--full"],
        "full",
    );
    assert_exit_2(
        &["simulate", "--case", "cases/rubber.toml", "--project"],
        "is not available for the rubber ball",
    );
}

/// `routh sweep` of the tippe top over `contact.mu` and the spin (issue 35 item 5): the CSV
/// has the contact's columns (`transitions` ... `work_final`) and the final state's gamma
/// (its `final_M` empty: the sliding state has no M), every run ends `ok`, the spun top with
/// friction turns upside down (`tilt_final` > 3) and the frictionless one does not (< 0.3);
/// `--json` gives the same rows; the rolling law's columns are refused with exit code 2.
#[test]
fn a_sweep_of_the_sliding_top_over_mu() {
    let case = tippe_top_with("sweep.toml", |text| {
        text + "\n[sweep]\n\"contact.mu\" = { values = [0.0, 0.3] }\nspin = { values = [20.0] }\n"
    });
    let dir = case.parent().unwrap().to_path_buf();
    let csv = dir.join("sweep.csv");
    let out = routh(&[
        "sweep",
        "--case",
        case.to_str().unwrap(),
        "--out",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    for name in [
        "contact.mu",
        "spin",
        "final_gamma3",
        "transitions",
        "tilt_final",
        "work_final",
    ] {
        assert!(header.contains(&name), "{name}: {header:?}");
    }
    assert!(!header.contains(&"H1_drift"), "{header:?}");
    let column =
        |row: &[&str], name: &str| row[header.iter().position(|h| *h == name).unwrap()].to_string();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2);
    for row in &rows {
        assert_eq!(column(row, "status"), "ok");
        assert_eq!(column(row, "final_M1"), "");
        let mu: f64 = column(row, "contact.mu").parse().unwrap();
        let tilt: f64 = column(row, "tilt_final").parse().unwrap();
        assert!(
            if mu > 0.0 { tilt > 3.0 } else { tilt < 0.3 },
            "{mu}: {tilt}"
        );
    }
    let json = json_of(&routh(&[
        "sweep",
        "--case",
        case.to_str().unwrap(),
        "--json",
    ]));
    let first = &json["rows"][1];
    assert_eq!(
        first["tilt_final"].as_f64().unwrap(),
        column(&rows[1], "tilt_final").parse::<f64>().unwrap()
    );
    assert_exit_2(
        &[
            "sweep",
            "--case",
            case.to_str().unwrap(),
            "--columns",
            "integrals",
        ],
        "is not one of a sweep of law = \"sliding\"",
    );
}

/// `routh inversion` on a 3 x 3 plane of the built-in tippe top: its table, PNG and SVG are
/// written, the JSON counts every point once and the agreement with the published conditions
/// is a share; an alpha outside (0, 1) and a case of the rolling law are refused with exit
/// code 2 and the reason.
#[test]
fn the_inversion_region_from_the_command_line() {
    let dir = std::env::temp_dir().join(format!("routh-inversion-{}", std::process::id()));
    let out = routh(&[
        "inversion",
        "--alpha",
        "0.2:0.4:3",
        "--ratio",
        "0.7:1.3:3",
        "--out",
        dir.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json_of(&out);
    let region = &v["regions"][0];
    let c = &region["counts"];
    let total: u64 = ["upright", "partial", "inverted", "failed"]
        .iter()
        .map(|k| c[k].as_u64().unwrap())
        .sum();
    assert_eq!(total, 9, "{v}");
    assert_eq!(region["spin"], 20.0);
    let share = region["agreement"].as_f64().unwrap();
    assert!((0.0..=1.0).contains(&share), "{v}");
    assert_ne!(v["method"], "auto", "the method that ran: {v}");
    for name in ["region.csv", "region.png", "region.svg"] {
        let size = std::fs::metadata(dir.join(name)).unwrap().len();
        assert!(size > 500, "{name}: {size} bytes");
    }
    let csv = std::fs::read_to_string(dir.join("region.csv")).unwrap();
    assert!(csv.starts_with("alpha,ratio,tilt_final,lambda,lambda_thres,predicted,outcome"));
    assert_eq!(csv.lines().count(), 10);
    assert_exit_2(&["inversion", "--alpha", "0.5:1.2:3"], "(0, 1)");
    assert_exit_2(
        &[
            "inversion",
            "--case",
            "cases/default.toml",
            "--ratio",
            "0.7:1.3:3",
        ],
        "needs [contact] law = \"sliding\"",
    );
}

/// `routh plot` of the tippe top (issue 35 item 5): theta, the height of the centre of mass,
/// the slip speed, the normal force, the balances and the trace of gamma, each a PNG of the
/// figure's size; the same from the CSV of `routh simulate`; the rubber ball refused.
#[test]
fn the_plots_of_a_sliding_run() {
    let dir = std::env::temp_dir().join(format!("routh-plot-contact-{}", std::process::id()));
    let out = routh(&[
        "plot",
        "--case",
        "cases/tippe_top.toml",
        "--t-end",
        "8",
        "--samples",
        "400",
        "--out",
        dir.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json_of(&out);
    let names: Vec<String> = v["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let path = PathBuf::from(f.as_str().unwrap());
            assert!(std::fs::metadata(&path).unwrap().len() > 10_000, "{path:?}");
            path.file_stem().unwrap().to_string_lossy().into_owned()
        })
        .collect();
    assert_eq!(
        names,
        [
            "theta",
            "height",
            "slip_speed",
            "normal_force",
            "balance",
            "gamma_trace"
        ]
    );
    let (csv, _) = samples_of("tippe_top", "100");
    let path = dir.join("samples.csv");
    std::fs::write(&path, csv).unwrap();
    let from_csv = routh(&[
        "plot",
        "--csv",
        path.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(
        from_csv.status.success(),
        "{}",
        String::from_utf8_lossy(&from_csv.stderr)
    );
    assert_exit_2(&["plot", "--case", "cases/rubber.toml"], "law = \"rubber\"");
}
