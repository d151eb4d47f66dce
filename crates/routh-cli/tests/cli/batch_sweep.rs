//! `routh sweep` in SIMD lanes (the default with DOP853) against `routh sweep --no-batch`
//! (one run at a time): every row is the same, bit for bit (serde_json writes the shortest
//! decimal that reads back to the same f64, so equal JSON numbers are equal doubles), on a
//! grid that mixes bodies (runs of one body share lanes), fails some runs (max steps) and
//! has more runs than lanes. Tolerance zero: the lanes do the one-at-a-time arithmetic.

use crate::common;
use common::routh;

fn sweep_rows(case: &str, extra: &[&str]) -> Vec<serde_json::Value> {
    let mut args = vec!["sweep", "--json", "--case", case, "--threads", "2"];
    args.extend_from_slice(extra);
    let out = routh(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    json["rows"].as_array().unwrap().clone()
}

/// 25 tilts x 2 spins x 2 offsets = 100 runs (two bodies, interleaved in the grid), with
/// max_steps low enough that the fastest spins fail: the rows in lanes and one at a time are
/// equal, failures included (same message). Negative control: the rows at another tolerance
/// differ.
#[test]
fn sweep_rows_in_lanes_equal_one_at_a_time_bitwise() {
    rows_in_lanes_equal_one_at_a_time("dop853", "150");
}

/// The same with `--method taylor` (the Taylor lanes of `routh::batch::taylor`), max_steps
/// set so that the fastest spins fail (the runs take 8 to 150 steps at rtol 1e-10 with the
/// order rule of `taylor::step_exponent`; 120 fails the fast spins only).
#[test]
fn taylor_sweep_rows_in_lanes_equal_one_at_a_time_bitwise() {
    rows_in_lanes_equal_one_at_a_time("taylor", "120");
}

fn rows_in_lanes_equal_one_at_a_time(method: &str, max_steps: &str) {
    let dir = std::env::temp_dir().join(format!("routh-batch-sweep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let case = dir.join(format!("grid-{method}.toml"));
    std::fs::write(
        &case,
        "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\nG = 9.81\n\
         [initial]\ngamma = [0.0, 0.0, 1.0]\nomega = [0.5, 0.2, 8.0]\n\
         [integration]\nt_end = 4.0\nrtol = 1e-10\natol = 1e-10\n\
         [sweep]\ntilt = { range = [0.05, 1.5], n = 25 }\nspin = { values = [3.0, 40.0] }\n\
         \"body.a\" = { values = [0.1, 0.3] }\n",
    )
    .unwrap();
    let case = case.to_str().unwrap();
    let limit = ["--max-steps", max_steps, "--method", method];
    let lanes = sweep_rows(case, &limit);
    let alone = sweep_rows(case, &[&limit[..], &["--no-batch"]].concat());
    assert_eq!(lanes.len(), 100);
    let failed = lanes.iter().filter(|r| r["status"] == "failed").count();
    assert!(
        (1..100).contains(&failed),
        "{failed} runs failed: the grid should fail some, not all"
    );
    for (a, b) in lanes.iter().zip(&alone) {
        assert_eq!(a, b, "run {}", a["run"]);
    }
    let other = sweep_rows(case, &[&limit[..], &["--rtol", "1e-9"]].concat());
    let differ = lanes
        .iter()
        .zip(&other)
        .filter(|(a, b)| a["status"] == "ok" && a["final_M3"] != b["final_M3"])
        .count();
    assert!(differ > 40, "negative control: {differ} rows differ");
}
