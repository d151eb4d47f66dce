//! `routh inversion`: the tippe top's inversion region over the plane (alpha = a / R,
//! I1 / I3) at one or more initial spins ([`routh::inversion::regions`]): a sweep of the
//! sliding contact whose final tilts are set beside the published conditions (the lines
//! `I1 / I3 = 1 -+ alpha` and Jellett's threshold): `DIR/region.csv`, `region.png` and
//! `region.svg` (with several spins, `region-spin-W.*` for each), and the counts of the
//! outcomes and of their agreement with the conditions, as text or JSON.

use super::diagram::both_formats;
use super::integration::{parse_method, Integration};
use super::plot::create_dir;
use super::{print_json, Readable};
use routh::case::Case;
use routh::figure::InversionFigure;
use routh::integrate::Method;
use routh::inversion::{regions, write_csv, Counts, Region, TIPPE_TOP};
use routh::megno::chart::ChartAxis;
use routh::AppResult as Result;
use serde::Serialize;
use std::path::PathBuf;
use std::time::Instant;

/// Options of `routh inversion`; the integration's override the case file.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Case file (TOML) of a sliding top (`[contact] law = "sliding"`, `[body]` with `a` and
    /// `I1`, `[initial]` with `omega`); the tippe top of cases/tippe_top.toml when omitted.
    #[arg(long)]
    pub case: Option<PathBuf>,
    /// The final time, tolerances and step limit of each run.
    #[command(flatten)]
    pub integration: Integration,
    /// Integrator: `auto` (Vern9 under Coulomb's friction, the fastest for the tolerance
    /// under the viscous one), `dop853`, `vern9`, `taylor` (viscous only) or `rk4:<steps>`.
    #[arg(long, default_value = "auto", value_parser = parse_method)]
    pub method: Method,
    /// The eccentricity alpha = a / R, `FROM:TO:N` (N points, ends included, within (0, 1)).
    #[arg(long, default_value = "0.05:0.6:23")]
    pub alpha: String,
    /// The ratio I1 / I3 (I3 the case's), `FROM:TO:N`.
    #[arg(long, default_value = "0.5:1.6:23")]
    pub ratio: String,
    /// Initial spins omega3, comma-separated, one region each (default: the case's).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub spin: Vec<f64>,
    /// Worker threads (0: one per core).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Directory of the tables and figures (created if missing); default: `inversion`.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
}

/// One region as `routh inversion` reports it.
#[derive(Serialize)]
struct RegionSummary {
    spin: f64,
    points: usize,
    counts: Counts,
    agreement: f64,
    threshold_points: usize,
    files: Vec<PathBuf>,
}

/// What `routh inversion` reports.
#[derive(Serialize)]
struct Written {
    case: String,
    method: String,
    t_end: f64,
    rtol: f64,
    atol: f64,
    alpha: ChartAxis,
    ratio: ChartAxis,
    regions: Vec<RegionSummary>,
    elapsed_s: f64,
    out: PathBuf,
}

/// Run `routh inversion`.
pub fn run(args: Args) -> Result<()> {
    let start = Instant::now();
    let case = match &args.case {
        Some(path) => Case::load_any_contact(Some(path))?,
        None => Case::parse_any_contact(TIPPE_TOP, "<built-in tippe top>")?,
    };
    let settings = args.integration.settings(args.method, &case)?;
    let alpha = ChartAxis::range("alpha", &args.alpha, "alpha")?;
    let ratio = ChartAxis::range("ratio", &args.ratio, "ratio")?;
    let found = regions(&case, &settings, &alpha, &ratio, &args.spin, args.threads)?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("inversion"));
    create_dir(&out)?;
    let several = found.len() > 1;
    let mut summaries = Vec::new();
    for region in &found {
        let stem = if several {
            format!("region-spin-{}", region.spin)
        } else {
            "region".to_string()
        };
        summaries.push(write_region(region, &case, &settings, &out, &stem)?);
    }
    let tol = settings.rtol().min(settings.atol());
    let method = match &case.sliding {
        Some(start) => start.model.method(settings.method(), tol)?,
        None => settings.method(),
    };
    let written = Written {
        case: case.source.clone(),
        method: method.to_string(),
        t_end: settings.t_end(),
        rtol: settings.rtol(),
        atol: settings.atol(),
        alpha,
        ratio,
        regions: summaries,
        elapsed_s: start.elapsed().as_secs_f64(),
        out: std::path::absolute(&out).unwrap_or(out),
    };
    if args.json {
        return print_json(&written);
    }
    outln!(
        "routh inversion: {} over alpha ({} points) x I1/I3 ({} points), {}, t_end = {}",
        written.case,
        written.alpha.n,
        written.ratio.n,
        written.method,
        Readable(written.t_end)
    )?;
    for r in &written.regions {
        let c = r.counts;
        outln!(
            "  spin {}: {} inverted, {} partial, {} upright, {} failed; predicted {}; \
             agreement with the published conditions {:.1} %",
            Readable(r.spin),
            c.inverted,
            c.partial,
            c.upright,
            c.failed,
            c.predicted,
            100.0 * r.agreement
        )?;
        for f in &r.files {
            outln!("wrote {}", f.display())?;
        }
    }
    Ok(())
}

/// The table and the figures of one region, `DIR/STEM.csv`, `.png` and `.svg`.
fn write_region(
    region: &Region,
    case: &Case,
    settings: &routh::simulate::Settings,
    out: &std::path::Path,
    stem: &str,
) -> Result<RegionSummary> {
    let table = out.join(format!("{stem}.csv"));
    write_csv(&table, region)?;
    let figure = InversionFigure {
        title: format!(
            "Tippe top: final tilt at t = {}, spin {} ({})",
            Readable(settings.t_end()),
            Readable(region.spin),
            case.source
        ),
        x: (region.alpha.from, region.alpha.to, region.alpha.n),
        y: (region.ratio.from, region.ratio.to, region.ratio.n),
        points: region
            .points
            .iter()
            .map(|p| (p.alpha, p.ratio, p.tilt_final))
            .collect(),
        threshold: &region.threshold,
    };
    let mut files = vec![table];
    files.extend(both_formats(&figure, out, stem)?);
    let counts = region.counts();
    let judged = region.points.len() - counts.failed;
    Ok(RegionSummary {
        spin: region.spin,
        points: region.points.len(),
        counts,
        agreement: if judged == 0 {
            f64::NAN
        } else {
            counts.agree as f64 / judged as f64
        },
        threshold_points: region.threshold.len(),
        files,
    })
}
