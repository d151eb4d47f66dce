//! `routh simulate`: integrate a case and report the integrals' drift; optionally write
//! dense-output samples to CSV.

use routh::case::Case;
use routh::integrals::{Integrals, INTEGRAL_NAMES};
use routh::integrate::{Method, OdeSystem};
use routh::motion::{full_columns, initial_full, FullMotion, FULL_COLUMN_NAMES};
use routh::output::write_atomic;
use routh::simulate::{run, ReducedSystem, Settings, Summary};
use routh::table::csv_header;
use routh::{Result, RouthError};
use std::path::PathBuf;

/// Samples written to CSV when `--out` is given without `--samples`.
const DEFAULT_CSV_SAMPLES: usize = 1001;

/// Options of `routh simulate`; each overrides the case file.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Case file (TOML); the built-in default case when omitted.
    #[arg(long)]
    pub case: Option<PathBuf>,
    /// Final time.
    #[arg(long, allow_hyphen_values = true)]
    pub t_end: Option<f64>,
    /// Relative tolerance of DOP853.
    #[arg(long, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// Absolute tolerance of DOP853.
    #[arg(long, allow_hyphen_values = true)]
    pub atol: Option<f64>,
    /// Integrator: `dop853` (adaptive, 8th order) or `rk4` / `rk4:<steps>` (fixed step).
    #[arg(long, default_value = "dop853", value_parser = parse_method)]
    pub method: Method,
    /// Project onto the level set of the integrals (|gamma| = 1, H3, K, H1) after each step.
    #[arg(long)]
    pub project: bool,
    /// Number of equally spaced dense-output samples on [0, t_end] written to `--out`.
    #[arg(long)]
    pub samples: Option<usize>,
    /// CSV file for the samples (written atomically).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Also rebuild the motion in space: add the orientation quaternion (qw, qx, qy, qz), the
    /// centre of mass (x, y, z) and the contact point (contact_x, contact_y) to the CSV.
    #[arg(long)]
    pub full: bool,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
}

pub fn parse_method(s: &str) -> std::result::Result<Method, String> {
    s.parse()
        .map_err(|e: routh::integrate::ParseMethodError| e.to_string())
}

/// The settings of a case with the command-line overrides applied.
pub fn settings(case: &Case, args: &Args, samples: usize) -> Settings {
    Settings {
        method: args.method,
        t_end: args.t_end.unwrap_or(case.integration.t_end),
        rtol: args.rtol.unwrap_or(case.integration.rtol),
        atol: args.atol.unwrap_or(case.integration.atol),
        project: args.project,
        samples,
    }
}

/// One CSV row: t, gamma, M, omega and the integrals (empty where not an integral).
pub fn csv_row(case: &Case, t: f64, x: &[f64; 6]) -> String {
    let omega = case
        .ball
        .angular_velocity(&[x[0], x[1], x[2]], &[x[3], x[4], x[5]]);
    let mut row = format!("{t}");
    for v in x.iter().chain(&omega) {
        row.push_str(&format!(",{v}"));
    }
    for v in Integrals::at(&case.ball, x).values() {
        row.push(',');
        if let Some(v) = v {
            row.push_str(&v.to_string());
        }
    }
    row
}

/// Run the command.
pub fn run_command(args: Args) -> Result<()> {
    let case = Case::load(args.case.as_deref())?;
    let samples = match (args.samples, &args.out) {
        (Some(n), _) => n,
        (None, Some(_)) => DEFAULT_CSV_SAMPLES,
        (None, None) => 0,
    };
    let settings = settings(&case, &args, samples);
    let summary = if args.full {
        let extra = |y: &[f64; 12]| full_columns(&case.ball, y).to_vec();
        let header = FULL_COLUMN_NAMES.join(",");
        let system = FullMotion { body: &case.ball };
        execute(
            &case,
            &args,
            &settings,
            &system,
            initial_full(&case.initial),
            &header,
            extra,
        )?
    } else {
        let system = ReducedSystem(&case.ball);
        execute(
            &case,
            &args,
            &settings,
            &system,
            case.initial.to_array(),
            "",
            |_| Vec::new(),
        )?
    };
    if args.json {
        super::print_json(&summary);
    } else {
        print_summary(&case, &summary, args.out.as_ref());
    }
    Ok(())
}

/// Run the simulation of `system` from `y0` (whose first six components are the reduced
/// state), writing the CSV when `--out` is given: the reduced columns, then the columns of
/// `extra_header` with the values of `extra`.
fn execute<S: OdeSystem<N>, const N: usize>(
    case: &Case,
    args: &Args,
    settings: &Settings,
    system: &S,
    y0: [f64; N],
    extra_header: &str,
    extra: impl Fn(&[f64; N]) -> Vec<f64>,
) -> Result<Summary> {
    let Some(path) = &args.out else {
        return run(&case.ball, system, y0, settings, &mut |_, _| Ok(()));
    };
    let mut summary = None;
    write_atomic(path, |w| {
        let io = |source| RouthError::Io {
            path: path.clone(),
            source,
        };
        let separator = if extra_header.is_empty() { "" } else { "," };
        let header = csv_header(&INTEGRAL_NAMES);
        writeln!(w, "{header}{separator}{extra_header}").map_err(io)?;
        summary = Some(run(&case.ball, system, y0, settings, &mut |t, y| {
            let x: [f64; 6] = std::array::from_fn(|i| y[i]);
            let mut row = csv_row(case, t, &x);
            for v in extra(y) {
                row.push_str(&format!(",{v}"));
            }
            writeln!(w, "{row}").map_err(io)
        })?);
        Ok(())
    })?;
    Ok(summary.expect("run returned a summary"))
}

fn print_summary(case: &Case, s: &Summary, out: Option<&PathBuf>) {
    println!("routh simulate: {}", case.source);
    let b = &case.ball;
    let [i1, i2, i3] = b.inertia;
    match case.body("") {
        Ok(body) => println!(
            "  body     m = {}, R = {}, a = {}, I = ({i1}, {i2}, {i3}), G = {}",
            b.m, b.radius, body.a, b.gravity
        ),
        Err(_) => println!(
            "  body     m = {}, R = {}, com = {:?}, I = ({i1}, {i2}, {i3}), G = {}",
            b.m, b.radius, b.com, b.gravity
        ),
    }
    println!(
        "  method   {}{}",
        s.method,
        if s.projected {
            " with projection onto the integrals"
        } else {
            ""
        }
    );
    println!("  t_end    {}", s.t_end);
    println!(
        "  work     {} steps ({} rejected), {} field evaluations in {:.3} s",
        s.steps, s.rejected, s.rhs_evals, s.elapsed_s
    );
    println!(
        "  gamma(t_end) = [{:.15}, {:.15}, {:.15}]",
        s.final_state.gamma[0], s.final_state.gamma[1], s.final_state.gamma[2]
    );
    println!(
        "  M(t_end)     = [{:.15}, {:.15}, {:.15}]",
        s.final_state.m[0], s.final_state.m[1], s.final_state.m[2]
    );
    println!("  integral        initial value   max relative drift");
    for name in INTEGRAL_NAMES {
        match s.integrals.get(name) {
            Some(d) => println!(
                "  {name:<4} {:>24.15e}   {:.3e}",
                d.initial, d.max_rel_drift
            ),
            None => println!("  {name:<4} {:>24}   (not an integral: I1 != I2)", "-"),
        }
    }
    if let Some(path) = out {
        println!("  samples written to {}", path.display());
    }
}
