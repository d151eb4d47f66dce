//! `routh megno`: the fast indicators MEGNO and FLI of a case's motion on `|gamma| = 1`
//! ([`routh::megno::report_case`]), as text or JSON; with `--x` and `--y`, the chart of
//! regimes of the mean MEGNO over a plane of two quantities of the case
//! ([`routh::megno::chart::chart`]): `DIR/chart.csv`, `chart.png`, `chart.svg`.
//!
//! Named for the indicator it computes, as `lyapunov` is for its exponents: the chart is the
//! same number over a plane of parameters.

use super::case_file::CaseFile;
use super::diagram::both_formats;
use super::integration::{parse_method, Integration};
use super::lyapunov::RunLines;
use super::plot::create_dir;
use super::{print_json, Readable};
use routh::case::Case;
use routh::figure::RegimeChartFigure;
use routh::integrate::Method;
use routh::megno::chart::{chart, write_csv, ChartAxis, RegimeCounts};
use routh::megno::{report_case, Report};
use routh::simulate::Settings;
use routh::{AppResult as Result, RouthError};
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;

/// Options of `routh megno`; the integration's override the case file.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub case: CaseFile,
    /// The final time, tolerances and step limit (of each run of a chart).
    #[command(flatten)]
    pub integration: Integration,
    /// Integrator of the state and its tangent vector: `dop853`, `vern9` or `rk4:<steps>`
    /// (RK4 with that many steps over the run); the Taylor method does not integrate the
    /// tangent flow.
    #[arg(long, default_value = "dop853", value_parser = parse_method)]
    pub method: Method,
    /// The horizontal axis of a chart of regimes, `KEY=FROM:TO:N`: KEY a quantity of a
    /// [sweep] table (body.I1, body.G, tilt, spin, omega1, gamma2, ...), N points from FROM
    /// to TO (2 to 1000); needs --y.
    #[arg(long, allow_hyphen_values = true)]
    pub x: Option<String>,
    /// The vertical axis of the chart, as --x.
    #[arg(long, allow_hyphen_values = true)]
    pub y: Option<String>,
    /// Worker threads of a chart (0: one per core).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Directory of chart.csv, chart.png and chart.svg (created if missing); default: `chart`
    /// in the current directory.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the report as JSON (with the history of the indicators; of a chart, its summary).
    #[arg(long)]
    pub json: bool,
}

/// What `routh megno --x --y` reports: the settings, the axes, the regimes and the files.
#[derive(Serialize)]
struct Written {
    case: String,
    method: String,
    t_end: f64,
    rtol: f64,
    atol: f64,
    x: ChartAxis,
    y: ChartAxis,
    points: usize,
    regimes: RegimeCounts,
    mean_megno_min: f64,
    mean_megno_max: f64,
    elapsed_s: f64,
    out: PathBuf,
    files: Vec<PathBuf>,
}

/// The directory used when `--out` is not given.
const DEFAULT_OUT: &str = "chart";

/// Run `routh megno`.
pub fn run(args: Args) -> Result<()> {
    let case = args.case.load()?;
    let settings = args.integration.settings(args.method, &case)?;
    match (&args.x, &args.y) {
        (Some(x), Some(y)) => {
            let (x, y) = (ChartAxis::parse(x, "x")?, ChartAxis::parse(y, "y")?);
            run_chart(&args, &case, &settings, &x, &y)
        }
        (None, None) if args.out.is_none() => {
            let r = report_case(&case, &settings)?;
            if args.json {
                print_json(&r)
            } else {
                out!("{}", report_text(&r))
            }
        }
        (None, None) => Err(refused("out", "needs --x and --y (the files of a chart)")),
        (Some(_), None) => Err(refused("y", "a chart needs both --x and --y")),
        (None, Some(_)) => Err(refused("x", "a chart needs both --x and --y")),
    }
}

/// An option given without the others it needs.
fn refused(name: &'static str, rule: &'static str) -> routh::AppError {
    RouthError::Option {
        name,
        value: "(missing)".into(),
        rule,
    }
    .into()
}

/// The chart of regimes over `x` and `y`: its files and its summary.
fn run_chart(
    args: &Args,
    case: &Case,
    settings: &Settings,
    x: &ChartAxis,
    y: &ChartAxis,
) -> Result<()> {
    let start = Instant::now();
    let found = chart(case, settings, x, y, args.threads)?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    create_dir(&out)?;
    let table = out.join("chart.csv");
    write_csv(&table, &found)?;
    let values: Vec<f64> = found.points.iter().map(|p| p.mean_megno()).collect();
    let labels = (x.label(), y.label());
    let finite = values.iter().copied().filter(|v| v.is_finite());
    let figure = RegimeChartFigure {
        title: format!(
            "Mean MEGNO <Y> at t = {} ({})",
            Readable(settings.t_end()),
            case.source
        ),
        labels: (&labels.0, &labels.1),
        x: (x.from, x.to, x.n),
        y: (y.from, y.to, y.n),
        points: found
            .points
            .iter()
            .zip(&values)
            .map(|(p, &v)| (p.x, p.y, v))
            .collect(),
    };
    let mut files = vec![table];
    files.extend(both_formats(&figure, &out, "chart")?);
    let written = Written {
        case: case.source.clone(),
        method: settings.method().to_string(),
        t_end: settings.t_end(),
        rtol: settings.rtol(),
        atol: settings.atol(),
        x: x.clone(),
        y: y.clone(),
        points: found.points.len(),
        regimes: found.regimes(),
        mean_megno_min: finite.clone().fold(f64::INFINITY, f64::min),
        mean_megno_max: finite.fold(f64::NEG_INFINITY, f64::max),
        elapsed_s: start.elapsed().as_secs_f64(),
        out: std::path::absolute(&out).unwrap_or(out),
        files,
    };
    if args.json {
        return print_json(&written);
    }
    let r = &written.regimes;
    outln!(
        "routh megno: chart of {} over {} ({} points) x {} ({} points), {}",
        written.case,
        x.key,
        x.n,
        y.key,
        y.n,
        written.method
    )?;
    outln!(
        "  {} periodic or attractor (<Y> < 1), {} regular, {} chaotic (<Y> > 4), {} failed",
        r.periodic,
        r.regular,
        r.chaotic,
        r.failed
    )?;
    for f in &written.files {
        outln!("wrote {}", f.display())?;
    }
    Ok(())
}

/// The report as lines of text (the history only in JSON).
fn report_text(r: &Report) -> String {
    use std::fmt::Write;
    let mut text = RunLines {
        command: "megno",
        run: &r.run,
        work: &r.work,
    }
    .to_string();
    let _ = writeln!(text, "  time     {}", Readable(r.run.t_end));
    let _ = writeln!(
        text,
        "  mean MEGNO <Y> = {:.6}  (2: torus, 0: periodic, large: chaos)",
        r.mean_megno
    );
    let _ = writeln!(text, "  MEGNO Y        = {:.6}", r.megno);
    let _ = writeln!(text, "  FLI            = {:.6}", r.fli);
    text
}
