//! What the reports of `routh lyapunov`, `routh megno` and `routh section` say of their run,
//! written once for the three: its case, integrator, final time and tolerances ([`Run`]) and the work it took
//! ([`Work`]). Each report flattens the two into its own JSON object, so that the keys
//! (`case`, `method`, `t_end`, `rtol`, `atol`, `steps`, `rejected`, `rhs_evals`,
//! `elapsed_s`) are those of one object.

use crate::integrate::Stats;
use crate::simulate::Settings;
use serde::Serialize;
use std::time::Instant;

/// The case and the settings of a run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Run {
    /// The case file (or `<built-in default>`); absent for a body and a state given as such
    /// (Python).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub case: Option<String>,
    /// The integrator.
    pub method: String,
    /// The final time.
    pub t_end: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
}

impl Run {
    /// The run of `integration` to `t_end`, without a case.
    pub fn of(integration: &Settings, t_end: f64) -> Self {
        Run {
            case: None,
            method: integration.method().to_string(),
            t_end,
            rtol: integration.rtol(),
            atol: integration.atol(),
        }
    }
}

/// The work of a run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Work {
    /// Accepted steps (of every run: a spectrum's intervals, a section's initial states).
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Field evaluations (of the tangent flow: each one of the state and its tangent vectors
    /// together).
    pub rhs_evals: usize,
    /// Wall-clock time of the run, in seconds.
    pub elapsed_s: f64,
}

impl Work {
    /// The work counted in `stats`, from `start` to now.
    pub fn of(stats: &Stats, start: Instant) -> Self {
        Work {
            steps: stats.steps,
            rejected: stats.rejected,
            rhs_evals: stats.rhs_evals,
            elapsed_s: start.elapsed().as_secs_f64(),
        }
    }
}
