//! The audit of the paper's claims (the library's `audit`), as a list of records.

use crate::convert::{bad_argument, record};
use pyo3::prelude::*;
use routh_core::audit::claim::MAX_POINTS;
use routh_core::audit::claims::{audit as run_audit, Sample};

/// Check every computable claim of sections 2.1 to 4 of the paper at `points` random
/// phase-space points (SplitMix64 with `seed`), as `routh audit --json`: a list of dicts with
/// `id`, `label` (the equation label), `statement`, `status` (`"OK"`, `"FAIL"`,
/// `"NOT-CHECKED"` or `"OK-WITHIN-ANSATZ"`), `residual` (the largest relative residual, None
/// when not checked; for `"OK-WITHIN-ANSATZ"` the margin of a non-existence claim) and `note`. The interpreter lock is released while it runs.
#[pyfunction]
#[pyo3(signature = (points = 20, seed = 1))]
pub fn audit<'py>(py: Python<'py>, points: i64, seed: u64) -> PyResult<Bound<'py, PyAny>> {
    let sample = usize::try_from(points)
        .ok()
        .and_then(|count| Sample::new(seed, count).ok())
        .ok_or_else(|| bad_argument("points", format!("{points} must lie in [1, {MAX_POINTS}]")))?;
    let verdicts = py.detach(|| run_audit(&sample));
    record(py, &verdicts)
}
