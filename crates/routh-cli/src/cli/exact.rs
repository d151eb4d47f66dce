//! `routh exact`: the motion of a case by quadrature (no step-by-step integration): turning
//! points, nutation period, precession advance, and the state at a time or at samples.

use routh::case::{check_option, Case};
use routh::integrals::{energy, jellett, routh_integral};
use routh::output::write_atomic;
use routh::quadrature::{Accuracy, ExactSolution, Motion};
use routh::table::csv_header;
use routh::{AppError, AppResult as Result, Body, State};
use serde::Serialize;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Samples written to CSV when `--out` is given without `--samples`.
const DEFAULT_CSV_SAMPLES: usize = 1001;
/// The estimated relative error of a reported state above which `routh exact` warns.
const ACCURACY_TOLERANCE: f64 = Accuracy::WARNING;

/// Options of `routh exact`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Case file (TOML); the built-in default case when omitted.
    #[arg(long)]
    pub case: Option<PathBuf>,
    /// The time of the reported state (default: the case's t_end).
    #[arg(long = "t", allow_negative_numbers = true)]
    pub time: Option<f64>,
    /// Number of equally spaced samples on [0, t] written as CSV (to `--out`, else stdout).
    #[arg(long)]
    pub samples: Option<usize>,
    /// CSV file for the samples (written atomically).
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
    motion: &'static str,
    theta_min: f64,
    theta_max: f64,
    gamma3_min: f64,
    gamma3_max: f64,
    period: Option<f64>,
    precession_advance_per_period: Option<f64>,
    precession_rate: Option<f64>,
    passes_through_axis: bool,
    chebyshev_nodes: Option<usize>,
    t: f64,
    gamma: [f64; 3],
    #[serde(rename = "M")]
    m: [f64; 3],
    omega: [f64; 3],
    #[serde(rename = "H1")]
    h1: f64,
    #[serde(rename = "H3")]
    h3: f64,
    #[serde(rename = "K")]
    k: f64,
    /// Estimated relative error of the state at t (see `Accuracy`).
    error_estimate: f64,
    /// The largest |t| at which the estimated error stays below `ACCURACY_TOLERANCE` (None:
    /// no limit).
    horizon: Option<f64>,
    /// The samples on [0, t] when asked for with `--json` and without `--out`.
    #[serde(skip_serializing_if = "Option::is_none")]
    samples: Option<Vec<Sample>>,
}

/// One sample of `routh exact --samples N --json`.
#[derive(Serialize)]
struct Sample {
    t: f64,
    gamma: [f64; 3],
    #[serde(rename = "M")]
    m: [f64; 3],
    omega: [f64; 3],
}

/// The columns of `routh exact` samples after the shared state columns ([`csv_header`]).
pub(super) const EXACT_COLUMNS: [&str; 4] = ["theta", "H1", "H3", "K"];

pub(super) fn csv_row(body: &Body, t: f64, state: &State) -> String {
    let x = state.to_array();
    let omega = state.omega(body);
    let values = x.iter().chain(&omega).copied().chain([
        state.gamma[2].clamp(-1.0, 1.0).acos(),
        energy(body, &x),
        jellett(body, &x),
        routh_integral(body, &x),
    ]);
    values.fold(t.to_string(), |row, v| format!("{row},{v}"))
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
    Summary {
        case: case.source.clone(),
        motion,
        theta_min: u_max.clamp(-1.0, 1.0).acos(),
        theta_max: u_min.clamp(-1.0, 1.0).acos(),
        gamma3_min: u_min,
        gamma3_max: u_max,
        period: exact.period(),
        precession_advance_per_period: advance,
        precession_rate: rate,
        passes_through_axis: through,
        chebyshev_nodes: nodes,
        t,
        gamma: state.gamma,
        m: state.m,
        omega: state.omega(body),
        h1: red.h1(),
        h3: red.h3(),
        k: red.k(),
        error_estimate: exact.accuracy.error_at(t),
        horizon: Some(exact.accuracy.horizon(ACCURACY_TOLERANCE)).filter(|h| h.is_finite()),
        samples: None,
    }
}

fn print_text(s: &Summary) -> Result<()> {
    outln!("case: {}", s.case)?;
    outln!("motion: {}", s.motion)?;
    outln!(
        "tilt theta in [{}, {}] (gamma3 in [{}, {}])",
        s.theta_min,
        s.theta_max,
        s.gamma3_min,
        s.gamma3_max
    )?;
    match (s.period, s.precession_advance_per_period, s.precession_rate) {
        (Some(period), Some(advance), _) => {
            outln!("nutation period T = {period}")?;
            outln!("precession advance per period = {advance}")?;
        }
        (_, _, Some(rate)) => outln!("steady: precession rate dpsi/dt = {rate}")?,
        _ => {}
    }
    if s.passes_through_axis {
        outln!("the motion passes through the symmetry axis (sin theta = 0) once per period")?;
    }
    outln!("integrals: H1 = {}, H3 = {}, K = {}", s.h1, s.h3, s.k)?;
    outln!(
        "estimated relative error at t: {:.1e} (below {ACCURACY_TOLERANCE:e} for |t| <= {})",
        s.error_estimate,
        s.horizon
            .map_or("any t".to_string(), |h| format!("{h:.6e}"))
    )?;
    outln!("state at t = {:?}:", s.t)?;
    outln!("  gamma = {:?}", s.gamma)?;
    outln!("  M     = {:?}", s.m)?;
    outln!("  omega = {:?}", s.omega)?;
    Ok(())
}

/// Run `routh exact`.
pub fn run(args: Args) -> Result<()> {
    if let Some(field) = args.flow {
        return super::flow::run(&args, field);
    }
    let case = Case::load(args.case.as_deref())?;
    let t = args.time.unwrap_or(case.integration.t_end);
    check_option("t", t, t.is_finite(), "must be finite")?;
    if let Some(n) = args.samples {
        check_option("samples", n as f64, n >= 2, "must be >= 2")?;
    }
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
    let samples = args
        .samples
        .or(args.out.as_ref().map(|_| DEFAULT_CSV_SAMPLES));
    let times = |n: usize| (0..n).map(move |i| t * i as f64 / (n - 1) as f64);
    let mut s = summary(&case, &body, &exact, t);
    match (samples, &args.out) {
        (Some(n), Some(path)) => write_atomic(path, |w: &mut dyn Write| {
            write_csv(w, &body, &exact, times(n), path)
        })?,
        (Some(n), None) if args.json => {
            s.samples = Some(
                times(n)
                    .map(|ti| {
                        let state = exact.state_at(ti);
                        Sample {
                            t: ti,
                            gamma: state.gamma,
                            m: state.m,
                            omega: state.omega(&body),
                        }
                    })
                    .collect(),
            );
        }
        (Some(n), None) => {
            return write_csv(
                &mut std::io::stdout().lock(),
                &body,
                &exact,
                times(n),
                Path::new(super::STANDARD_OUTPUT),
            );
        }
        (None, _) => {}
    }
    if args.json {
        super::print_json(&s)?;
    } else {
        print_text(&s)?;
    }
    Ok(())
}

/// The samples at `times` as CSV rows after the header.
fn write_csv(
    w: &mut dyn Write,
    body: &Body,
    exact: &ExactSolution,
    times: impl Iterator<Item = f64>,
    path: &Path,
) -> Result<()> {
    let io = AppError::io(path);
    writeln!(w, "{}", csv_header(&EXACT_COLUMNS)).map_err(&io)?;
    for ti in times {
        writeln!(w, "{}", csv_row(body, ti, &exact.state_at(ti))).map_err(&io)?;
    }
    Ok(())
}
