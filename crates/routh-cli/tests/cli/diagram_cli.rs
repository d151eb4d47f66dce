//! `routh diagram` run as a user would: the JSON keys, the files written, exit code 2 with a
//! message on bad input.

use crate::common;
use common::{assert_exit_2, routh};

/// Run `routh diagram` with `args`, `--out dir` and `--json`; the parsed JSON.
fn diagram_json(args: &[&str], dir: &std::path::Path) -> serde_json::Value {
    let mut all = vec!["diagram", "--out", dir.to_str().unwrap(), "--json"];
    all.extend_from_slice(args);
    let out = routh(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-diagram-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// The JSON at H3 = 1 (the default body's top spin below Routh's threshold) has the critical
/// curves with their stability types and points, the focus–focus point with its integrals and
/// state, and the monodromy with its loop and the integer matrix [[1, -1], [0, 1]]; every file
/// it lists exists and is not empty.
#[test]
fn json_has_the_required_keys_and_files() {
    let dir = temp_dir("keys");
    let v = diagram_json(&["--h3", "1", "--tilts", "120", "--grid", "24"], &dir);
    let curves = v["critical_curves"].as_array().unwrap();
    assert!(curves.len() >= 2);
    for c in curves {
        assert!(c["stability"].is_string());
        let points = c["points"].as_array().unwrap();
        assert!(!points.is_empty());
        for key in ["H1", "H3", "K", "theta", "state", "stability"] {
            assert!(points[0].get(key).is_some(), "curve point lacks {key}");
        }
    }
    let ff = v["focus_focus"].as_array().unwrap();
    assert_eq!(ff.len(), 1);
    for key in ["H1", "H3", "K", "state"] {
        assert!(ff[0].get(key).is_some(), "focus_focus lacks {key}");
    }
    assert_eq!(ff[0]["H3"], 1.0);
    let m = &v["monodromy"];
    assert!(m["loop"].as_array().unwrap().len() >= 64);
    for key in ["H1", "H3", "K", "period", "advance", "rotation_number"] {
        assert!(m["loop"][0].get(key).is_some(), "loop point lacks {key}");
    }
    assert_eq!(m["matrix"], serde_json::json!([[1, -1], [0, 1]]));
    let files = v["files"].as_array().unwrap();
    for stem in [
        "diagram.png",
        "diagram.svg",
        "diagram_sleeping_top.png",
        "diagram_rotation_number.svg",
        "diagram_curves.csv",
        "diagram_loop.csv",
        "diagram_tori.csv",
    ] {
        assert!(
            files.iter().any(|f| f.as_str().unwrap().ends_with(stem)),
            "{stem} not listed"
        );
        let size = std::fs::metadata(dir.join(stem)).unwrap().len();
        assert!(size > 100, "{stem}: {size} bytes");
    }
    let curves_csv = std::fs::read_to_string(dir.join("diagram_curves.csv")).unwrap();
    assert!(curves_csv.starts_with("branch,stability,theta,K,H1,H3"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// At the default case's own H3 (fast spin) there is no focus–focus point: the list is empty
/// and the monodromy null, and the case's value has one torus.
#[test]
fn default_plane_has_no_focus_focus_point() {
    let dir = temp_dir("default");
    let v = diagram_json(&["--tilts", "60", "--grid", "12"], &dir);
    assert_eq!(v["focus_focus"].as_array().unwrap().len(), 0);
    assert!(v["monodromy"].is_null());
    assert_eq!(v["case_in_plane"], true);
    assert_eq!(v["case_value"]["intervals"].as_array().unwrap().len(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Bad input: exit 2 with the option or key named, no panic, nothing written.
#[test]
fn bad_input_exits_2() {
    let dir = temp_dir("bad");
    let out = dir.to_str().unwrap().to_string();
    assert_exit_2(&["diagram", "--h3", "nan", "--out", &out], "h3");
    assert_exit_2(&["diagram", "--h3", "inf", "--out", &out], "h3");
    assert_exit_2(&["diagram", "--tilts", "1", "--out", &out], "tilts");
    assert_exit_2(&["diagram", "--grid", "100000", "--out", &out], "grid");
    assert_exit_2(
        &["diagram", "--loop-points", "3", "--out", &out],
        "loop_points",
    );
    assert!(!dir.exists(), "a refused run created {}", dir.display());
    let case = std::env::temp_dir().join(format!("routh-diagram-asym-{}.toml", std::process::id()));
    std::fs::write(
        &case,
        "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI2 = 0.45\nI3 = 0.5\n[initial]\ngamma = [0.0, 0.0, 1.0]\nomega = [0.0, 0.0, 1.0]\n",
    )
    .unwrap();
    assert_exit_2(
        &["diagram", "--case", case.to_str().unwrap(), "--out", &out],
        "I1 = I2",
    );
    std::fs::remove_file(&case).unwrap();
    let file = std::env::temp_dir().join(format!("routh-diagram-file-{}", std::process::id()));
    std::fs::write(&file, "x").unwrap();
    assert_exit_2(
        &[
            "diagram",
            "--tilts",
            "20",
            "--grid",
            "4",
            "--out",
            file.to_str().unwrap(),
        ],
        "routh-diagram-file",
    );
    std::fs::remove_file(&file).unwrap();
}
