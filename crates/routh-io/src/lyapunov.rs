//! The Lyapunov exponents of a case as the front ends report them (`routh lyapunov`): the
//! spectrum of the case's motion on `|gamma| = 1` ([`lyapunov_spectrum`]),
//! its convergence, the Kaplan–Yorke dimension and the divergence check, with the settings
//! of the run.

use crate::ball::AsBall;
use crate::case::Case;
use crate::error::AppResult as Result;
use crate::run::{Run, Work};
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
    /// The case, the integrator, the final time and the tolerances.
    #[serde(flatten)]
    pub run: Run,
    /// The time after which the exponents are averaged.
    pub transient: f64,
    /// The time between two renormalisations of the tangent vectors.
    pub interval: f64,
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
    /// The work of all the intervals' runs.
    #[serde(flatten)]
    pub work: Work,
}

/// The spectrum of the motion of `case` with `settings`, reported.
pub fn report_case(case: &Case, settings: &LyapunovSettings) -> Result<Report> {
    let mut report = report(&case.ball, &case.initial.to_array(), settings)?;
    report.run.case = Some(case.source.clone());
    Ok(report)
}

/// The spectrum of the motion of `ball` from `x0 = (gamma, M)` with `settings`, reported
/// (without a case).
pub fn report(ball: &impl AsBall, x0: &[f64; 6], settings: &LyapunovSettings) -> Result<Report> {
    let start = Instant::now();
    let spectrum = lyapunov_spectrum(ball, x0, settings)?;
    let (integration, schedule) = (settings.integration(), settings.schedule());
    Ok(Report {
        run: Run::of(integration, schedule.t_end()),
        transient: schedule.transient(),
        interval: schedule.interval(),
        sum_of_exponents: spectrum.exponents.iter().sum(),
        kaplan_yorke_dimension: spectrum.kaplan_yorke_dimension,
        divergence_mean: spectrum.divergence_mean,
        history: History {
            times: spectrum.history.iter().map(|e| e.t).collect(),
            exponents: spectrum.history.into_iter().map(|e| e.exponents).collect(),
        },
        exponents: spectrum.exponents,
        work: Work::of(&spectrum.stats, start),
    })
}
