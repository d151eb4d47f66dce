//! `routh exact`: the motion of a case by quadrature (no step-by-step integration): turning
//! points, nutation period, precession advance, and the state at a time or at samples.

use routh::case::{check_option, Case};
use routh::integrals::{energy, jellett, routh_integral};
use routh::output::write_atomic;
use routh::quadrature::{ExactSolution, Motion};
use routh::{Result, RouthError, State};
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;

/// Samples written to CSV when `--out` is given without `--samples`.
const DEFAULT_CSV_SAMPLES: usize = 1001;

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
    /// Print the summary as JSON.
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
}

/// The CSV header of `routh exact` samples.
pub(super) const CSV_HEADER: &str =
    "t,gamma1,gamma2,gamma3,M1,M2,M3,omega1,omega2,omega3,theta,H1,H3,K";

pub(super) fn csv_row(case: &Case, t: f64, state: &State) -> String {
    let x = state.to_array();
    let body = &case.body;
    let omega = state.omega(body);
    let values = x.iter().chain(&omega).copied().chain([
        state.gamma[2].clamp(-1.0, 1.0).acos(),
        energy(body, &x),
        jellett(body, &x),
        routh_integral(body, &x),
    ]);
    values.fold(t.to_string(), |row, v| format!("{row},{v}"))
}

fn summary(case: &Case, exact: &ExactSolution, t: f64) -> Summary {
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
        omega: state.omega(&case.body),
        h1: red.h1,
        h3: red.h3,
        k: red.k,
    }
}

fn print_text(s: &Summary) {
    println!("case: {}", s.case);
    println!("motion: {}", s.motion);
    println!(
        "tilt theta in [{}, {}] (gamma3 in [{}, {}])",
        s.theta_min, s.theta_max, s.gamma3_min, s.gamma3_max
    );
    match (s.period, s.precession_advance_per_period, s.precession_rate) {
        (Some(period), Some(advance), _) => {
            println!("nutation period T = {period}");
            println!("precession advance per period = {advance}");
        }
        (_, _, Some(rate)) => println!("steady: precession rate dpsi/dt = {rate}"),
        _ => {}
    }
    if s.passes_through_axis {
        println!("the motion passes through the symmetry axis (sin theta = 0) once per period");
    }
    println!("integrals: H1 = {}, H3 = {}, K = {}", s.h1, s.h3, s.k);
    println!("state at t = {}:", s.t);
    println!("  gamma = {:?}", s.gamma);
    println!("  M     = {:?}", s.m);
    println!("  omega = {:?}", s.omega);
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
    let exact = ExactSolution::new(&case.body, &case.initial)?;
    let samples = args
        .samples
        .or(args.out.as_ref().map(|_| DEFAULT_CSV_SAMPLES));
    if let Some(n) = samples {
        let write_rows = |w: &mut dyn Write| -> Result<()> {
            let io = |source| RouthError::Io {
                path: args.out.clone().unwrap_or_else(|| "<stdout>".into()),
                source,
            };
            writeln!(w, "{CSV_HEADER}").map_err(io)?;
            for i in 0..n {
                let ti = t * i as f64 / (n - 1) as f64;
                writeln!(w, "{}", csv_row(&case, ti, &exact.state_at(ti))).map_err(io)?;
            }
            Ok(())
        };
        match &args.out {
            Some(path) => write_atomic(path, write_rows)?,
            None => write_rows(&mut std::io::stdout().lock())?,
        }
        if args.out.is_none() {
            return Ok(());
        }
    }
    let s = summary(&case, &exact, t);
    if args.json {
        super::print_json(&s);
    } else {
        print_text(&s);
    }
    Ok(())
}
