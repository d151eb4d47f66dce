//! `routh megno`, run as a user would (issue 36, items 2 and 4): on the two integrable cases
//! the mean MEGNO is near 2 at their own times; the JSON keys; a chart of regimes writes its
//! CSV, PNG and SVG, with every point of an integrable case regular and both regimes on a
//! Chaplygin top; bad options refused with exit code 2 and no file.

use crate::common;
use common::{assert_exit_2, json_of, routh};

/// `routh megno --json` with `args`.
fn megno(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["megno", "--json"];
    all.extend_from_slice(args);
    json_of(&routh(&all))
}

/// The default case (t = 100) and `cases/chaplygin.toml` (t = 1000) move on tori: `<Y>`
/// within 0.3 of 2 at their own times (measured 1.957 and 1.991: the deficit `ln t / t` of a
/// torus; `routh_ball::megno`'s tests hold them to 0.1 and 0.02). The history holds at most
/// 100 entries at increasing times, the last the result; `Y` and the FLI come with it.
/// Negative controls: over t = 5 the default case's `<Y>` is 1.32, more than 0.3 from 2
/// (the weight `s` of MEGNO still damps the start), and the Chaplygin top of
/// `cases/chaplygin_top.toml` is chaotic, `<Y>` = 19 at its t = 500.
#[test]
fn integrable_cases_have_mean_megno_near_two() {
    for case in ["cases/default.toml", "cases/chaplygin.toml"] {
        let v = megno(&["--case", case]);
        let mean = v["mean_megno"].as_f64().unwrap();
        assert!((mean - 2.0).abs() < 0.3, "{case}: {v}");
        let times = v["history"]["times"].as_array().unwrap();
        let means = v["history"]["mean_megno"].as_array().unwrap();
        assert!(times.len() <= 100 && times.len() > 50, "{}", times.len());
        assert_eq!(means.len(), times.len());
        assert_eq!(times.last().unwrap(), &v["t_end"]);
        assert_eq!(means.last().unwrap(), &v["mean_megno"]);
        for key in [
            "megno",
            "fli",
            "steps",
            "rejected",
            "rhs_evals",
            "elapsed_s",
            "case",
        ] {
            assert!(v.get(key).is_some(), "JSON lacks {key}");
        }
    }
    let short = megno(&["--t-end", "5"])["mean_megno"].as_f64().unwrap();
    assert!((short - 2.0).abs() > 0.3, "{short}");
    let top = megno(&["--case", "cases/chaplygin_top.toml"])["mean_megno"]
        .as_f64()
        .unwrap();
    assert!(top > 5.0, "{top}");
    let text = String::from_utf8(routh(&["megno", "--t-end", "2"]).stdout).unwrap();
    for needle in ["mean MEGNO", "FLI", "<built-in default>"] {
        assert!(text.contains(needle), "{needle}: {text}");
    }
}

/// The CSV of a chart in `dir`: its header and rows of cells.
fn chart_csv(dir: &std::path::Path) -> (Vec<String>, Vec<Vec<String>>) {
    let csv = std::fs::read_to_string(dir.join("chart.csv")).unwrap();
    let mut lines = csv.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (header, rows)
}

/// A chart of the default case over tilt x spin (3 x 2 points, t = 100): every point is a
/// Routh sphere on a torus, so every `<Y>` is regular, within 0.3 of 2 (measured 1.89 to
/// 1.97). A chart of the Chaplygin top over tilt x spin (6 x 5 points, t = 200) has both
/// regimes (measured: 2 chaotic, 27 regular, 1 below 1) and the JSON's counts are the CSV's.
/// Each writes `chart.csv` (the keys of --x and --y, `mean_megno`, `megno`, `fli`, `regime`, `message`),
/// `chart.png` and `chart.svg`.
#[test]
fn charts_write_csv_png_and_svg() {
    let base = std::env::temp_dir().join(format!("routh-cli-chart-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    let (sphere, top) = (base.join("sphere"), base.join("top"));
    let v = megno(&[
        "--x",
        "tilt=0.2:0.6:3",
        "--y",
        "spin=6:10:2",
        "--out",
        sphere.to_str().unwrap(),
    ]);
    let (header, rows) = chart_csv(&sphere);
    assert_eq!(
        header,
        [
            "tilt",
            "spin",
            "mean_megno",
            "megno",
            "fli",
            "regime",
            "message"
        ]
    );
    assert_eq!(rows.len(), 6);
    for row in &rows {
        let mean: f64 = row[2].parse().unwrap();
        assert!((mean - 2.0).abs() < 0.3, "{row:?}");
        assert_eq!(row[5], "regular");
    }
    assert_eq!(v["regimes"]["regular"], 6);
    assert_eq!(v["points"], 6);
    for name in ["chart.png", "chart.svg", "chart.csv"] {
        let size = std::fs::metadata(sphere.join(name)).unwrap().len();
        assert!(size > 300, "{name}: {size} bytes");
    }
    let v = megno(&[
        "--case",
        "cases/chaplygin_top.toml",
        "--t-end",
        "200",
        "--x",
        "tilt=0.2:1.5:6",
        "--y",
        "spin=0.5:4:5",
        "--out",
        top.to_str().unwrap(),
    ]);
    let (_, rows) = chart_csv(&top);
    let count = |regime: &str| rows.iter().filter(|r| r[5] == regime).count();
    assert_eq!(rows.len(), 30);
    assert!(count("chaotic") > 0 && count("regular") > 0, "{v}");
    for regime in ["periodic", "regular", "chaotic", "failed"] {
        assert_eq!(v["regimes"][regime], count(regime), "{regime}: {v}");
    }
    assert_eq!(v["x"]["key"], "tilt");
    assert_eq!(v["files"].as_array().unwrap().len(), 3);
    let _ = std::fs::remove_dir_all(&base);
}

/// Bad options: exit code 2, the option named with its rule, and no directory written.
#[test]
fn bad_options_are_refused_with_exit_2() {
    let dir = std::env::temp_dir().join(format!("routh-cli-chart-bad-{}", std::process::id()));
    let out = dir.to_str().unwrap();
    fn chart<'a>(x: &'a str, y: &'a str, out: &'a str) -> Vec<&'a str> {
        vec!["megno", "--x", x, "--y", y, "--out", out]
    }
    for (x, rule) in [
        ("height=0:1:3", "KEY must be a quantity of [sweep]"),
        ("tilt", "must be KEY=FROM:TO:N"),
        ("tilt=0:1", "must be KEY=FROM:TO:N"),
        ("tilt=a:1:3", "FROM and TO must be numbers"),
        ("tilt=1:0:3", "FROM < TO"),
        ("tilt=0:inf:3", "finite"),
        ("tilt=0:1:1", "N must be an integer from 2 to 1000"),
        ("tilt=0:1:1001", "N must be an integer from 2 to 1000"),
    ] {
        assert_exit_2(&chart(x, "spin=1:2:2", out), "invalid option x");
        assert_exit_2(&chart(x, "spin=1:2:2", out), rule);
    }
    assert_exit_2(
        &chart("tilt=0:1:2", "tilt=0:1:2", out),
        "invalid option y = tilt: must be another quantity",
    );
    assert_exit_2(
        &chart("tilt=0:1:2", "gamma1=0:0.5:2", out),
        "sets the same initial quantity as another key",
    );
    assert_exit_2(
        &chart("body.I1=-1:0.4:2", "spin=1:2:2", out),
        "makes the case invalid",
    );
    assert_exit_2(&["megno", "--x", "tilt=0:1:2"], "invalid option y");
    assert_exit_2(&["megno", "--y", "tilt=0:1:2"], "invalid option x");
    assert_exit_2(&["megno", "--out", out], "invalid option out");
    assert_exit_2(
        &["megno", "--method", "taylor"],
        "invalid option method = taylor: must be dop853, vern9 or rk4",
    );
    assert_exit_2(
        &chart("tilt=0:1:2", "spin=1:2:2", out)
            .into_iter()
            .chain(["--method", "taylor"])
            .collect::<Vec<_>>(),
        "invalid option method = taylor",
    );
    assert_exit_2(&["megno", "--t-end", "NaN"], "t_end");
    assert!(!dir.exists(), "{dir:?} was written");
}
