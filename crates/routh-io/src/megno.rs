//! MEGNO and FLI of a case as the front ends report them (`routh megno`): the indicators of
//! the case's motion on `|gamma| = 1` ([`ball_megno`]), their history and the settings of
//! the run.

use crate::ball::AsBall;
use crate::case::Case;
use crate::error::AppResult as Result;
use crate::integrate::megno::Indicators;
use crate::run::{Run, Work};
use crate::simulate::Settings;
use routh_ball::megno::ball_megno;
use serde::Serialize;
use std::time::Instant;

/// The indicators at up to 100 times of the run ([`crate::integrate::megno::HISTORY`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct History {
    /// The times (step ends).
    pub times: Vec<f64>,
    /// MEGNO `Y(t)`.
    pub megno: Vec<f64>,
    /// Its mean `<Y>(t)`.
    pub mean_megno: Vec<f64>,
    /// `FLI(t)`.
    pub fli: Vec<f64>,
}

impl History {
    fn of(entries: &[Indicators]) -> Self {
        History {
            times: entries.iter().map(|e| e.t).collect(),
            megno: entries.iter().map(|e| e.megno).collect(),
            mean_megno: entries.iter().map(|e| e.mean_megno).collect(),
            fli: entries.iter().map(|e| e.fli).collect(),
        }
    }
}

/// The report of one run: the settings, the indicators at `t_end` and their history.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    /// The case, the integrator, the final time and the tolerances.
    #[serde(flatten)]
    pub run: Run,
    /// MEGNO `Y(t_end)`.
    pub megno: f64,
    /// Its mean `<Y>(t_end)`: about 2 on a torus, 0 on a stable periodic orbit, growing as
    /// `lambda t / 2` in chaos.
    pub mean_megno: f64,
    /// `FLI(t_end) = sup ln |v|`.
    pub fli: f64,
    /// The indicators along the run.
    pub history: History,
    /// The work of the run.
    #[serde(flatten)]
    pub work: Work,
}

/// The indicators of the motion of `case` with `settings`, reported.
pub fn report_case(case: &Case, settings: &Settings) -> Result<Report> {
    let mut report = report(&case.ball, &case.initial.to_array(), settings)?;
    report.run.case = Some(case.source.clone());
    Ok(report)
}

/// The indicators of the motion of `ball` from `x0 = (gamma, M)` with `settings`, reported
/// (without a case).
pub fn report(ball: &impl AsBall, x0: &[f64; 6], settings: &Settings) -> Result<Report> {
    let start = Instant::now();
    let run = ball_megno(ball, x0, settings)?;
    Ok(Report {
        run: Run::of(settings, settings.t_end()),
        megno: run.last.megno,
        mean_megno: run.last.mean_megno,
        fli: run.last.fli,
        history: History::of(&run.history),
        work: Work::of(&run.stats, start),
    })
}
