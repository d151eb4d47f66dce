//! `routh section`: the Poincaré section of a case's motions on its energy level through a
//! plane `NAME = NUMBER` ([`routh::section::section`]): the table of crossings (CSV), a
//! figure of two components of them (PNG and SVG) and the summary, as text or JSON.

use super::case_file::CaseFile;
use super::diagram::both_formats;
use super::integration::{parse_method, Integration};
use super::plot::create_dir;
use super::Readable;
use routh::figure::SectionFigure;
use routh::integrate::Method;
use routh::section::{section, write_csv, Report};
use routh::surface::{component, component_names, parse_direction, parse_surface};
use routh::{AppResult as Result, RouthError};
use serde::Serialize;
use std::path::PathBuf;

/// Options of `routh section`; the integration's override the case file.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub case: CaseFile,
    /// The plane of the section, `NAME = NUMBER`, NAME a component of the state as in `routh
    /// simulate`'s CSV: gamma1, gamma2, gamma3, M1, M2 or M3.
    #[arg(long)]
    pub surface: String,
    /// The crossings that count: `up` (the component increasing through the value), `down`
    /// or `both`.
    #[arg(long, default_value = "up")]
    pub direction: String,
    /// The number of initial states on the case's energy level (1 to 10000): the case's, then
    /// states of other tilts with the case's spin rescaled onto the level (docs/section.md);
    /// a tilt the level cannot reach is left out.
    #[arg(long, default_value_t = 20)]
    pub initial: usize,
    /// The components drawn, `X,Y` (names as for --surface); default: gamma3 and M1 (the
    /// tilt and the momentum across the plane of gamma1 = 0: each torus a closed curve), or
    /// the next of gamma3, M1, gamma2, M2 where one is the surface's component.
    #[arg(long)]
    pub axes: Option<String>,
    /// The final time of each run, tolerances and step limit.
    #[command(flatten)]
    pub integration: Integration,
    /// Integrator: `dop853` (in SIMD lanes), `vern9` or `rk4:<steps>` (one run at a time).
    #[arg(long, default_value = "dop853", value_parser = parse_method)]
    pub method: Method,
    /// Directory of the files section.csv, section.png and section.svg (created if missing);
    /// default: `section` in the current directory.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
}

/// What `routh section` reports: the section's summary and the files.
#[derive(Serialize)]
struct Written {
    #[serde(flatten)]
    report: Report,
    /// The components drawn.
    axes: [&'static str; 2],
    /// The directory of the files.
    out: PathBuf,
    /// The files written.
    files: Vec<PathBuf>,
}

/// The directory used when `--out` is not given.
const DEFAULT_OUT: &str = "section";

/// The components drawn: `text` (`X,Y`), or the first two of gamma3, M1, gamma2, M2 other
/// than the surface's component `surface`.
fn axes(text: Option<&str>, surface: usize) -> Result<[usize; 2]> {
    let Some(text) = text else {
        let mut free = [2, 3, 1, 4].into_iter().filter(|&i| i != surface);
        return Ok([free.next().unwrap_or(2), free.next().unwrap_or(3)]);
    };
    let refused = || RouthError::Option {
        name: "axes",
        value: format!("{text:?}"),
        rule: "must be X,Y with X and Y among gamma1 gamma2 gamma3 M1 M2 M3",
    };
    let (x, y) = text.split_once(',').ok_or_else(refused)?;
    match (component(x.trim()), component(y.trim())) {
        (Some(x), Some(y)) => Ok([x, y]),
        _ => Err(refused().into()),
    }
}

/// Run `routh section`.
pub fn run(args: Args) -> Result<()> {
    let crossing = parse_surface(&args.surface, "surface")?;
    let direction = parse_direction(&args.direction, "direction")?;
    let [x_axis, y_axis] = axes(args.axes.as_deref(), crossing.component())?;
    let case = args.case.load()?;
    let settings = args.integration.settings(args.method, &case)?;
    let x0 = case.initial.to_array();
    let (starts, found, mut report) = section(
        &case.ball,
        &x0,
        &settings,
        &crossing,
        direction,
        args.initial,
    )?;
    report.run.case = Some(case.source.clone());
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    create_dir(&out)?;
    let table = out.join("section.csv");
    write_csv(&table, &case.ball, &found.points)?;
    let names = component_names();
    let figure = SectionFigure {
        title: format!(
            "Poincaré section {} ({}), H1 = {:.6}",
            report.surface, report.direction, report.energy
        ),
        labels: (names[x_axis], names[y_axis]),
        points: found
            .points
            .iter()
            .map(|p| (p.run, p.y[x_axis], p.y[y_axis]))
            .collect(),
        runs: starts.len(),
    };
    let mut files = vec![table];
    files.extend(both_formats(&figure, &out, "section")?);
    let written = Written {
        report,
        axes: [names[x_axis], names[y_axis]],
        out: std::path::absolute(&out).unwrap_or(out),
        files,
    };
    if args.json {
        return super::print_json(&written);
    }
    let r = &written.report;
    outln!(
        "routh section: {} ({}) of {}",
        r.surface,
        r.direction,
        r.run.case.as_deref().unwrap_or_default()
    )?;
    outln!(
        "  {} crossings of {} runs on H1 = {} to t = {} ({}, rtol {}, atol {})",
        r.crossings,
        r.initial_states,
        r.energy,
        Readable(r.run.t_end),
        r.run.method,
        Readable(r.run.rtol),
        Readable(r.run.atol)
    )?;
    outln!(
        "  largest distance from the plane {:e} (unit {:e}), largest relative energy drift {:e}",
        r.max_surface_value,
        r.surface_unit,
        r.max_energy_drift
    )?;
    for f in &written.files {
        outln!("wrote {}", f.display())?;
    }
    Ok(())
}
