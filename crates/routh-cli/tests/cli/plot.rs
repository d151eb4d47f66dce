//! `routh plot` and `routh animate`, run as a user would: the files exist, are not empty, have
//! the promised dimensions; bad input exits with code 2 and a message.

use routh::case::Case;
use routh::integrate::Method;
use routh::table::{simulate_full, Table};
use std::path::{Path, PathBuf};
use std::process::Output;

use crate::common;
use common::{assert_exit_2, routh};

/// The figure size promised by `routh::plot::SIZE`.
const WIDTH: u32 = 960;
const HEIGHT: u32 = 640;
const FIGURES: [&str; 4] = ["theta", "contact_path", "integral_drift", "gamma_trace"];

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-plot-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn ok(out: &Output) -> String {
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "failed: {err}");
    String::from_utf8(out.stdout.clone()).unwrap()
}

/// Width and height from the IHDR chunk, after checking the PNG signature.
fn png_dimensions(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR");
    let word = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    (word(16), word(20))
}

/// The JSON list of files written, checked against the expected names.
fn written(stdout: &str, dir: &Path, names: &[&str], ext: &str) -> Vec<PathBuf> {
    let v: serde_json::Value = serde_json::from_str(stdout).unwrap();
    let files: Vec<PathBuf> = v["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| PathBuf::from(f.as_str().unwrap()))
        .collect();
    let expected: Vec<PathBuf> = names
        .iter()
        .map(|n| dir.join(format!("{n}.{ext}")))
        .collect();
    assert_eq!(files, expected);
    files
}

/// Run `routh plot` on a short simulation of the default case into a fresh directory.
fn plot_default_case(format: &str) -> Vec<PathBuf> {
    let dir = scratch(format);
    let out = routh(&[
        "plot",
        "--out",
        dir.to_str().unwrap(),
        "--format",
        format,
        "--t-end",
        "3",
        "--samples",
        "301",
        "--json",
    ]);
    written(&ok(&out), &dir, &FIGURES, format)
}

#[test]
fn png_figures_have_the_promised_size() {
    for file in plot_default_case("png") {
        let bytes = std::fs::read(&file).unwrap();
        // A blank 960x640 RGB image compresses to under 1 kB; axes, labels and curves add more.
        assert!(
            bytes.len() > 8_000,
            "{}: {} bytes",
            file.display(),
            bytes.len()
        );
        assert_eq!(
            png_dimensions(&bytes),
            (WIDTH, HEIGHT),
            "{}",
            file.display()
        );
    }
}

#[test]
fn svg_figures_have_the_promised_size() {
    for file in plot_default_case("svg") {
        let text = std::fs::read_to_string(&file).unwrap();
        assert!(
            text.len() > 5_000,
            "{}: {} bytes",
            file.display(),
            text.len()
        );
        let head = &text[..text.find('>').unwrap()];
        assert!(head.contains(&format!("width=\"{WIDTH}\"")), "{head}");
        assert!(head.contains(&format!("height=\"{HEIGHT}\"")), "{head}");
        assert!(text.contains("<text"), "labels are text elements");
        assert!(text.contains("<polyline"), "curves are drawn");
    }
}

#[test]
fn plots_from_simulate_csv_files_and_compares_two() {
    let dir = scratch("csv");
    let (full, coarse) = (dir.join("full.csv"), dir.join("coarse.csv"));
    let simulate = |file: &Path, tol: &str, extra: &[&str]| {
        let mut args = vec![
            "simulate",
            "--t-end",
            "2",
            "--samples",
            "101",
            "--rtol",
            tol,
            "--atol",
            tol,
            "--out",
            file.to_str().unwrap(),
        ];
        args.extend(extra);
        ok(&routh(&args));
    };
    simulate(&full, "1e-12", &["--full"]);
    simulate(&coarse, "1e-6", &[]);
    let figures = dir.join("figures");
    let out = routh(&[
        "plot",
        "--csv",
        full.to_str().unwrap(),
        "--compare",
        coarse.to_str().unwrap(),
        "--out",
        figures.to_str().unwrap(),
        "--json",
    ]);
    let mut names = FIGURES.to_vec();
    names.push("difference");
    for file in written(&ok(&out), &figures, &names, "png") {
        assert_eq!(
            png_dimensions(&std::fs::read(&file).unwrap()),
            (WIDTH, HEIGHT)
        );
    }
    // A reduced CSV has no positions: the path figure is skipped, with the reason.
    let out = routh(&[
        "plot",
        "--csv",
        coarse.to_str().unwrap(),
        "--out",
        figures.to_str().unwrap(),
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&ok(&out)).unwrap();
    assert_eq!(v["files"].as_array().unwrap().len(), 3);
    assert!(v["skipped"][0].as_str().unwrap().contains("--full"), "{v}");
}

#[test]
fn simulated_table_matches_the_simulate_full_csv() {
    // `routh plot` without --csv simulates through routh::table::simulate_full; it must give
    // the columns and values of `routh simulate --full` with the same `--method` (the CSV
    // prints shortest round-trip decimals, so equal values parse back exactly).
    let dir = scratch("table");
    let case = Case::default_case().unwrap();
    let mut tables = vec![];
    for method in [Method::Dop853, Method::Vern9] {
        let file = dir.join(format!("full-{method}.csv"));
        ok(&routh(&[
            "simulate",
            "--full",
            "--t-end",
            "2",
            "--samples",
            "51",
            "--method",
            &method.to_string(),
            "--out",
            file.to_str().unwrap(),
        ]));
        let from_csv = Table::read_csv(&file).unwrap();
        let simulated = simulate_full(&case, method, 2.0, 51).unwrap();
        assert_eq!(from_csv.names(), simulated.names());
        for name in simulated.names() {
            let (a, b) = (
                from_csv.column(name).unwrap(),
                simulated.column(name).unwrap(),
            );
            for (x, y) in a.iter().zip(b) {
                assert!(
                    x == y || (x.is_nan() && y.is_nan()),
                    "{method} {name}: {x} vs {y}"
                );
            }
        }
        tables.push(simulated);
    }
    // Negative control: the method is honoured, so the two methods' tables differ (within
    // the tolerances, not bit for bit).
    assert_ne!(
        tables[0].column("gamma3").unwrap(),
        tables[1].column("gamma3").unwrap()
    );
}

#[test]
fn animate_writes_a_self_contained_page() {
    let dir = scratch("animate");
    let out = routh(&[
        "animate",
        "--out",
        dir.to_str().unwrap(),
        "--t-end",
        "2",
        "--samples",
        "3001",
        "--json",
    ]);
    let files = written(&ok(&out), &dir, &["animation"], "html");
    let page = std::fs::read_to_string(&files[0]).unwrap();
    // three.js (~570 kB) and 3001 samples of 16 columns as base64 float32 (~5.3 bytes each):
    // every sample is embedded (the page used to keep at most 1500).
    assert!(page.contains("(3001 samples"), "all samples embedded");
    let t_column = page
        .split("\"t\":\"")
        .nth(1)
        .and_then(|rest| rest.split('"').next())
        .expect("the t column is embedded");
    assert_eq!(
        t_column.len(),
        (4 * 3001usize).div_ceil(3) * 4,
        "3001 float32"
    );
    assert!(
        (570_000..1_000_000).contains(&page.len()),
        "{} bytes",
        page.len()
    );
    for needle in [
        "<canvas",
        "WebGLRenderer",
        "\"columns\":{",
        "requestAnimationFrame",
    ] {
        assert!(page.contains(needle), "page lacks {needle}");
    }
    // The radius recovered from the samples is the default case's R = 1.
    let after = page
        .split("\"radius\":")
        .nth(1)
        .expect("the radius is embedded");
    let radius: f64 = after.split(',').next().unwrap().parse().unwrap();
    assert!((radius - 1.0).abs() < 1e-9, "R = {radius}");
    // Self-contained: no external script, style sheet or image (the browser test in
    // tests/browser checks that the page makes no request at all).
    for needle in ["__DATA__", "__SOURCE__", "<script src", "<link", "<img"] {
        assert!(!page.contains(needle), "page contains {needle}");
    }
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let dir = scratch("bad");
    let out = dir.to_str().unwrap();
    assert_exit_2(&["plot", "--out", out, "--format", "gif"], "gif");
    assert_exit_2(
        &["plot", "--out", out, "--csv", "/nonexistent.csv"],
        "/nonexistent.csv",
    );
    assert_exit_2(&["plot", "--out", out, "--samples", "1"], "samples");
    assert_exit_2(&["plot", "--out", out, "--t-end", "-1"], "t_end");
    let garbage = dir.join("garbage.csv");
    std::fs::write(&garbage, "t,gamma1\n0,abc\n").unwrap();
    assert_exit_2(
        &["plot", "--out", out, "--csv", garbage.to_str().unwrap()],
        "line 2",
    );
    assert_exit_2(
        &["animate", "--out", out, "--csv", garbage.to_str().unwrap()],
        "line 2",
    );
    let reduced = dir.join("reduced.csv");
    std::fs::write(&reduced, "t,gamma1,gamma2,gamma3\n0,0,0,1\n1,0,0,1\n").unwrap();
    assert_exit_2(
        &["animate", "--out", out, "--csv", reduced.to_str().unwrap()],
        "--full",
    );
    assert!(
        std::fs::read_dir(&dir).unwrap().count() == 2,
        "no figure written on error"
    );
}

#[test]
fn quadrature_beside_the_integrator() {
    // `routh exact` samples at the times of `routh plot`/`simulate`; the difference figure is
    // drawn, and the two solutions agree to the integrator's tolerance (1e-12 per unit time;
    // 1e-9 allows the growth over t = 2 at |omega| ~ 8).
    let dir = scratch("exact");
    let quadrature = dir.join("quadrature.csv");
    ok(&routh(&[
        "exact",
        "--t",
        "2",
        "--samples",
        "101",
        "--out",
        quadrature.to_str().unwrap(),
    ]));
    let out = routh(&[
        "plot",
        "--t-end",
        "2",
        "--samples",
        "101",
        "--compare",
        quadrature.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--json",
    ]);
    let mut names = FIGURES.to_vec();
    names.push("difference");
    written(&ok(&out), &dir, &names, "png");
    let exact = Table::read_csv(&quadrature).unwrap();
    let simulated =
        simulate_full(&Case::default_case().unwrap(), Method::Dop853, 2.0, 101).unwrap();
    for name in ["gamma1", "gamma2", "gamma3", "M1", "M2", "M3"] {
        let worst = exact
            .column(name)
            .unwrap()
            .iter()
            .zip(simulated.column(name).unwrap())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-9, "{name}: {worst:e}");
    }
}
