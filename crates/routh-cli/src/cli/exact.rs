//! `routh exact`: the motion of a case by quadrature (no step-by-step integration): turning
//! points, nutation period, precession advance, and the state at a time or at samples. Its
//! options, checks, CSV samples and text lines also serve `routh exact --flow` ([`super::flow`]).

use super::case_file::CaseFile;
use super::ReportStream;
use routh::case::{check_option, Case};
use routh::diagram::Value;
use routh::integrals::{energy, jellett, routh_integral};
use routh::output::write_atomic;
use routh::quadrature::{Accuracy, ExactSolution, Motion};
use routh::row::{csv_line, Cell};
use routh::simulate::MAX_SAMPLES;
use routh::table::csv_header;
use routh::{AppError, AppResult as Result, Body, Point};
use serde::Serialize;
use std::fmt::Write as _;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Samples written to CSV when `--out` is given without `--samples`.
const DEFAULT_CSV_SAMPLES: usize = 1001;
/// The estimated relative error of a reported state above which `routh exact` warns.
const ACCURACY_TOLERANCE: f64 = Accuracy::WARNING;

/// Options of `routh exact`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub case: CaseFile,
    /// The time of the reported state (default: the case's t_end).
    #[arg(long = "t", allow_negative_numbers = true)]
    pub time: Option<f64>,
    /// Number of equally spaced samples on [0, t] written as CSV (to `--out`, else stdout).
    #[arg(long)]
    pub samples: Option<usize>,
    /// CSV file for the samples (written atomically; `-` for standard output, where the
    /// summary then goes to standard error).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the summary as JSON (with `--samples` and no `--out`, the samples inside it).
    #[arg(long)]
    pub json: bool,
    /// Instead of the motion, the flow of a Hamiltonian field of the first bracket (p-br):
    /// X1 = P dH1, X2 = P dH2 or Xhat2 = P dK (section 3.2; docs/flows.md).
    #[arg(long, value_name = "X1|X2|Xhat2")]
    pub flow: Option<routh::poisson::flows::Field>,
    /// With --flow: the beta of the bracket, (cond), (cond2) or the conformal P_f (cham-vp).
    #[arg(
        long,
        value_name = "cond|cond2|conformal",
        default_value = "cond",
        requires = "flow"
    )]
    pub condition: routh::poisson::flows::Condition,
    /// With --flow: the constant alpha of the bracket.
    #[arg(
        long,
        default_value_t = 1.0,
        requires = "flow",
        allow_negative_numbers = true
    )]
    pub alpha: f64,
}

/// The summary printed by `routh exact`.
#[derive(Serialize)]
struct Summary {
    case: String,
    /// The motion of the tilt.
    #[serde(flatten)]
    tilt: Tilt,
    /// Why a number of the tilt is null.
    #[serde(flatten)]
    tilt_null_reasons: TiltNullReasons,
    /// The precession of the symmetry axis in space.
    #[serde(flatten)]
    axis: AxisPrecession,
    passes_through_axis: bool,
    chebyshev_nodes: Option<usize>,
    /// The state at t.
    #[serde(flatten)]
    state: Sample,
    /// The integrals' values.
    #[serde(flatten)]
    integrals: Value,
    /// Estimated relative error of the state at t (see `Accuracy`).
    error_estimate: f64,
    /// The largest |t| at which the estimated error stays below `ACCURACY_TOLERANCE` (None:
    /// no limit).
    horizon: Option<f64>,
    /// The samples on [0, t] when asked for with `--json` and without `--out`.
    #[serde(skip_serializing_if = "Option::is_none")]
    samples: Option<Vec<Sample>>,
}

/// The motion of the tilt theta (gamma3 = cos theta) that `routh exact` and `routh exact
/// --flow` report.
#[derive(Serialize)]
pub(super) struct Tilt {
    /// `nutation` (theta oscillates) or `steady` (theta constant).
    pub(super) motion: &'static str,
    pub(super) theta_min: f64,
    pub(super) theta_max: f64,
    pub(super) gamma3_min: f64,
    pub(super) gamma3_max: f64,
    /// The period of theta.
    pub(super) period: Option<f64>,
    /// The advance per period of theta of the azimuth psi of gamma (the vertical) about e3 in
    /// the body frame (for `routh exact --flow`, of phi = atan2(gamma1, gamma2)): not the
    /// precession of the symmetry axis in space (`axis_precession_*` of `routh exact`).
    pub(super) precession_advance_per_period: Option<f64>,
    /// The rate of that azimuth when theta is constant.
    pub(super) precession_rate: Option<f64>,
}

/// Why `period`, `precession_advance_per_period` or `precession_rate` of `routh exact` is
/// null (each key present only when its number is).
#[derive(Serialize)]
struct TiltNullReasons {
    #[serde(skip_serializing_if = "Option::is_none")]
    period_null_reason: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    precession_advance_per_period_null_reason: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    precession_rate_null_reason: Option<&'static str>,
}

/// The precession of the symmetry axis e3 in space: its azimuth in the fixed frame (z up,
/// measured from x toward y), in radians and radians per unit time. A key `<key>_null_reason`
/// says why a number is null (present only then).
#[derive(Serialize)]
struct AxisPrecession {
    /// The constant rate of a steady motion.
    axis_precession_rate: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axis_precession_rate_null_reason: Option<&'static str>,
    /// The advance per nutation period (in [0, 2 pi) for a motion through the axis, where it
    /// is defined modulo 2 pi only).
    axis_precession_advance_per_period: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axis_precession_advance_per_period_null_reason: Option<&'static str>,
    /// The mean rate: the advance per period over the period (a nutation), the rate (a steady
    /// motion).
    axis_precession_mean_rate: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axis_precession_mean_rate_null_reason: Option<&'static str>,
}

/// `why` when `value` is null.
fn null_reason(value: Option<f64>, why: &'static str) -> Option<&'static str> {
    value.is_none().then_some(why)
}

/// Why the axis of a steady motion has no rate: it is vertical.
const VERTICAL_AXIS: &str = "the symmetry axis is vertical (gamma on the axis): it has no azimuth";

impl AxisPrecession {
    fn of(exact: &ExactSolution) -> Self {
        let (rate, advance, mean) = match &exact.motion {
            Motion::Steady { .. } => {
                let rate = exact.axis_precession_rate();
                (rate, None, rate)
            }
            Motion::Nutation(nut) => (None, Some(nut.axis_advance), nut.axis_mean_rate()),
        };
        let steady = matches!(exact.motion, Motion::Steady { .. });
        AxisPrecession {
            axis_precession_rate: rate,
            axis_precession_rate_null_reason: null_reason(
                rate,
                if steady {
                    VERTICAL_AXIS
                } else {
                    "a nutation has no constant rate; see axis_precession_advance_per_period and \
                     axis_precession_mean_rate"
                },
            ),
            axis_precession_advance_per_period: advance,
            axis_precession_advance_per_period_null_reason: null_reason(
                advance,
                "a steady motion has no nutation period; see axis_precession_rate",
            ),
            axis_precession_mean_rate: mean,
            axis_precession_mean_rate_null_reason: null_reason(
                mean,
                if steady {
                    VERTICAL_AXIS
                } else {
                    "the motion passes through the axis, where the axis is vertical and its \
                     azimuth jumps by pi: the advance is defined modulo 2 pi only"
                },
            ),
        }
    }
}

/// The state at a time: one sample of `routh exact --samples N --json`, and the state that
/// `routh exact` and `routh exact --flow` report.
#[derive(Serialize)]
pub(super) struct Sample {
    pub(super) t: f64,
    gamma: [f64; 3],
    #[serde(rename = "M")]
    m: [f64; 3],
    omega: [f64; 3],
}

impl Sample {
    /// The state `state` at time `t`, with its angular velocity.
    pub(super) fn new(body: &Body, t: f64, state: &Point) -> Self {
        Sample {
            t,
            gamma: state.gamma,
            m: state.m,
            omega: state.omega(body),
        }
    }
}

/// The columns of `routh exact` samples after the shared state columns ([`csv_header`]).
const EXACT_COLUMNS: [&str; 4] = ["theta", "H1", "H3", "K"];

/// The cells of a sample: t, the state, omega and the [`EXACT_COLUMNS`].
fn csv_cells(body: &Body, t: f64, state: &Point) -> Vec<Cell> {
    let x = state.to_array();
    let omega = state.omega(body);
    std::iter::once(t)
        .chain(x)
        .chain(omega)
        .chain([
            state.gamma[2].clamp(-1.0, 1.0).acos(),
            energy(body, &x),
            jellett(body, &x),
            routh_integral(body, &x),
        ])
        .map(|v| Cell::Float(Some(v)))
        .collect()
}

fn summary(case: &Case, body: &Body, exact: &ExactSolution, t: f64) -> Summary {
    let state = exact.state_at(t);
    let (u_min, u_max) = exact.turning_points();
    let red = &exact.reduction;
    let (motion, advance, rate, through, nodes) = match &exact.motion {
        Motion::Steady { precession, .. } => ("steady", None, Some(*precession), false, None),
        Motion::Nutation(nut) => (
            "nutation",
            Some(nut.advance),
            None,
            nut.through_top || nut.through_bottom,
            Some(nut.nodes),
        ),
    };
    let period = exact.period();
    Summary {
        case: case.source.clone(),
        tilt: Tilt {
            motion,
            theta_min: u_max.clamp(-1.0, 1.0).acos(),
            theta_max: u_min.clamp(-1.0, 1.0).acos(),
            gamma3_min: u_min,
            gamma3_max: u_max,
            period,
            precession_advance_per_period: advance,
            precession_rate: rate,
        },
        tilt_null_reasons: TiltNullReasons {
            period_null_reason: null_reason(period, "a steady motion: theta is constant"),
            precession_advance_per_period_null_reason: null_reason(
                advance,
                "a steady motion has no nutation period; see precession_rate",
            ),
            precession_rate_null_reason: null_reason(
                rate,
                "a nutation has no constant rate; see precession_advance_per_period",
            ),
        },
        axis: AxisPrecession::of(exact),
        passes_through_axis: through,
        chebyshev_nodes: nodes,
        state: Sample::new(body, t, &state),
        integrals: Value {
            h1: red.h1(),
            h3: red.h3(),
            k: red.k(),
        },
        error_estimate: exact.accuracy.error_at(t),
        horizon: Some(exact.accuracy.horizon(ACCURACY_TOLERANCE)).filter(|h| h.is_finite()),
        samples: None,
    }
}

fn summary_text(s: &Summary) -> String {
    let mut text = String::new();
    let _ = writeln!(text, "case: {}", s.case);
    let _ = writeln!(text, "motion: {}", s.tilt.motion);
    tilt_text(
        &mut text,
        &s.tilt,
        [
            "nutation period T",
            "precession advance per period (azimuth of gamma in the body frame)",
            "steady: precession rate dpsi/dt (azimuth of gamma in the body frame)",
        ],
    );
    let axis = &s.axis;
    let mut line = |name: &str, value: Option<f64>, why: Option<&str>| {
        let _ = match (value, why) {
            (Some(v), _) => writeln!(text, "{name} = {v}"),
            (None, Some(why)) => writeln!(text, "{name}: none ({why})"),
            (None, None) => Ok(()),
        };
    };
    line(
        "symmetry axis in space: precession rate dphi/dt",
        axis.axis_precession_rate,
        None,
    );
    line(
        "symmetry axis in space: advance per period",
        axis.axis_precession_advance_per_period,
        None,
    );
    line(
        "symmetry axis in space: mean precession rate",
        axis.axis_precession_mean_rate,
        axis.axis_precession_mean_rate_null_reason,
    );
    if s.passes_through_axis {
        let _ = writeln!(
            text,
            "the motion passes through the symmetry axis (sin theta = 0) once per period"
        );
    }
    integrals_text(&mut text, &s.integrals);
    let _ = writeln!(
        text,
        "estimated relative error at t: {:.1e} (below {ACCURACY_TOLERANCE:e} for |t| <= {})",
        s.error_estimate,
        s.horizon
            .map_or("any t".to_string(), |h| format!("{h:.6e}"))
    );
    state_text(&mut text, format_args!("{:?}", s.state.t), &s.state);
    text
}

/// The lines of the tilt: its range (theta in [min, max], gamma3 = cos theta in [min, max]),
/// then the period and the precession's advance, or the precession's rate, each after its
/// name in `names`. (Lines written to a `String`, which cannot fail.)
pub(super) fn tilt_text(text: &mut String, s: &Tilt, names: [&str; 3]) {
    let _ = writeln!(
        text,
        "tilt theta in [{}, {}] (gamma3 in [{}, {}])",
        s.theta_min, s.theta_max, s.gamma3_min, s.gamma3_max
    );
    let [period_name, advance_name, rate_name] = names;
    let _ = match (s.period, s.precession_advance_per_period, s.precession_rate) {
        (Some(period), Some(advance), _) => {
            writeln!(text, "{period_name} = {period}\n{advance_name} = {advance}")
        }
        (_, _, Some(rate)) => writeln!(text, "{rate_name} = {rate}"),
        _ => Ok(()),
    };
}

/// The line of the integrals' values.
pub(super) fn integrals_text(text: &mut String, v: &Value) {
    let _ = writeln!(text, "integrals: H1 = {}, H3 = {}, K = {}", v.h1, v.h3, v.k);
}

/// The lines of the state (its time `t` as the caller prints it).
pub(super) fn state_text(text: &mut String, t: std::fmt::Arguments, s: &Sample) {
    let _ = writeln!(
        text,
        "state at t = {t}:\n  gamma = {:?}\n  M     = {:?}\n  omega = {:?}",
        s.gamma, s.m, s.omega
    );
}

impl Args {
    /// The time of the reported state (`--t`, else the case's t_end), checked with
    /// `--samples` (bounded before any work, by the bound of `routh simulate`).
    pub(super) fn checked_time(&self, case: &Case) -> Result<f64> {
        let t = self.time.unwrap_or(case.integration.t_end());
        check_option("t", t, t.is_finite(), "must be finite")?;
        if let Some(n) = self.samples {
            check_option(
                "samples",
                n as f64,
                (2..=MAX_SAMPLES).contains(&n),
                "must be >= 2 and at most 10000000 (MAX_SAMPLES, as for routh simulate)",
            )?;
        }
        Ok(t)
    }

    /// The stream of the summary of `routh exact` (or `--flow`): standard error when the
    /// samples go to standard output by `--out` ([`ReportStream`]), as in `routh simulate`, so
    /// that standard output holds the CSV alone. Asked before the samples are written.
    pub(super) fn report_stream(&self) -> ReportStream {
        ReportStream::beside([self.out.as_deref()])
    }

    /// The number of CSV samples: `--samples`, else [`DEFAULT_CSV_SAMPLES`] with `--out`.
    pub(super) fn csv_samples(&self) -> Option<usize> {
        self.samples
            .or(self.out.as_ref().map(|_| DEFAULT_CSV_SAMPLES))
    }
}

/// Run `routh exact` without `--flow`.
pub fn run(args: Args) -> Result<()> {
    let case = args.case.load()?;
    let t = args.checked_time(&case)?;
    let body = case.body("routh exact")?;
    let exact = ExactSolution::new(&body, &case.initial)?;
    let error = exact.accuracy.checked_error_at(t)?;
    if error > ACCURACY_TOLERANCE {
        eprintln!(
            "warning: the estimated relative error at t = {t:e} is {error:.1e}, above \
             {ACCURACY_TOLERANCE:e} (for |t| <= {:.6e}); the phase error grows like t times the \
             error of the period",
            exact.accuracy.horizon(ACCURACY_TOLERANCE)
        );
    }
    let mut s = summary(&case, &body, &exact, t);
    let stream = args.report_stream();
    let state_at = |ti: f64| exact.state_at(ti);
    match (args.csv_samples(), &args.out) {
        (Some(n), Some(path)) => write_samples(Some(path), &body, t, n, state_at)?,
        (Some(n), None) if args.json => {
            s.samples = Some(
                sample_times(t, n)
                    .map(|ti| Sample::new(&body, ti, &exact.state_at(ti)))
                    .collect(),
            );
        }
        (Some(n), None) => return write_samples(None, &body, t, n, state_at),
        (None, _) => {}
    }
    stream.print(&s, args.json, summary_text)
}

/// `n` equally spaced times on [0, t].
fn sample_times(t: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |i| t * i as f64 / (n - 1) as f64)
}

/// The states at `n` equally spaced times on [0, t] as CSV: the header and one row a time,
/// to `out` (written atomically), else to standard output.
pub(super) fn write_samples(
    out: Option<&Path>,
    body: &Body,
    t: f64,
    n: usize,
    state_at: impl Fn(f64) -> Point,
) -> Result<()> {
    let path = out.unwrap_or(Path::new(super::STANDARD_OUTPUT));
    let write_rows = |w: &mut dyn Write| -> Result<()> {
        let io = AppError::io(path);
        writeln!(w, "{}", csv_header(&EXACT_COLUMNS)).map_err(&io)?;
        for ti in sample_times(t, n) {
            writeln!(w, "{}", csv_line(&csv_cells(body, ti, &state_at(ti)))).map_err(&io)?;
        }
        Ok(())
    };
    match out {
        Some(path) => write_atomic(path, write_rows),
        None => write_rows(&mut std::io::stdout().lock()),
    }
}
