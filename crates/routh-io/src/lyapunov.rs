//! The Lyapunov exponents of a case as the front ends report them (`routh lyapunov`): the
//! spectrum of the case's motion on `|gamma| = 1` ([`lyapunov_spectrum`]),
//! its convergence, the Kaplan–Yorke dimension and the divergence check, with the settings
//! of the run.

use crate::ball::AsBall;
use crate::case::Case;
use crate::error::AppResult as Result;
use routh_ball::lyapunov::{lyapunov_spectrum, LyapunovSettings};
use serde::Serialize;
use std::time::Instant;

/// The running estimates of the exponents at each renormalisation after the transient.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct History {
    /// The times of the renormalisations.
    pub times: Vec<f64>,
    /// The exponents averaged from the transient's end to each time (one list of five a
    /// time).
    pub exponents: Vec<Vec<f64>>,
}

/// The report of one spectrum: the settings, the exponents and their checks.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    /// The case file (or `<built-in default>`); absent for a body and a state given as such
    /// (Python).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub case: Option<String>,
    /// The integrator.
    pub method: String,
    /// The final time.
    pub t_end: f64,
    /// The time after which the exponents are averaged.
    pub transient: f64,
    /// The time between two renormalisations of the tangent vectors.
    pub interval: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// The five exponents on `|gamma| = 1`, in the order of the Gram–Schmidt vectors (the
    /// largest first once they have converged).
    pub exponents: Vec<f64>,
    /// The Kaplan–Yorke dimension of the exponents.
    pub kaplan_yorke_dimension: f64,
    /// The time average of the divergence of the field over `[transient, t_end]`.
    pub divergence_mean: f64,
    /// The sum of the exponents: equal to `divergence_mean` (Liouville's formula), up to the
    /// integration error.
    pub sum_of_exponents: f64,
    /// The convergence of the estimates.
    pub history: History,
    /// Accepted steps of all the intervals' runs.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Field evaluations (each one of the state and the five tangent vectors together).
    pub rhs_evals: usize,
    /// Wall-clock time of the run, in seconds.
    pub elapsed_s: f64,
}

/// The spectrum of the motion of `case` with `settings`, reported.
pub fn report_case(case: &Case, settings: &LyapunovSettings) -> Result<Report> {
    let mut report = report(&case.ball, &case.initial.to_array(), settings)?;
    report.case = Some(case.source.clone());
    Ok(report)
}

/// The spectrum of the motion of `ball` from `x0 = (gamma, M)` with `settings`, reported
/// (without a case).
pub fn report(ball: &impl AsBall, x0: &[f64; 6], settings: &LyapunovSettings) -> Result<Report> {
    let start = Instant::now();
    let spectrum = lyapunov_spectrum(ball, x0, settings)?;
    let (integration, schedule) = (settings.integration(), settings.schedule());
    Ok(Report {
        case: None,
        method: integration.method().to_string(),
        t_end: schedule.t_end(),
        transient: schedule.transient(),
        interval: schedule.interval(),
        rtol: integration.rtol(),
        atol: integration.atol(),
        sum_of_exponents: spectrum.exponents.iter().sum(),
        kaplan_yorke_dimension: spectrum.kaplan_yorke_dimension,
        divergence_mean: spectrum.divergence_mean,
        history: History {
            times: spectrum.history.iter().map(|e| e.t).collect(),
            exponents: spectrum.history.into_iter().map(|e| e.exponents).collect(),
        },
        exponents: spectrum.exponents,
        steps: spectrum.stats.steps,
        rejected: spectrum.stats.rejected,
        rhs_evals: spectrum.stats.rhs_evals,
        elapsed_s: start.elapsed().as_secs_f64(),
    })
}
