//! `routh diagram`: the energy–momentum diagram of a case's body at fixed Jellett H3 (the
//! case's, or `--h3`): critical curves by stability type, regions by number of tori,
//! focus–focus points and their monodromy; the sleeping tops in the plane (H3, K). Figures
//! (PNG and SVG), CSV tables and `--json`.

use super::plot::create_dir;
use routh::case::{check_option, Case};
use routh::diagram::figure::{EnergyMomentum, RotationNumberFigure, SleepingTopFigure};
use routh::diagram::{
    largest_h3, sleeping_tops, threshold_h3, torus_count, Diagram, Resolution, TorusCount, Value,
};
use routh::output::write_atomic;
use routh::plot::{render_figure, Figure, Format};
use routh::{AppError, AppResult as Result};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Options of `routh diagram`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Case file (TOML); the built-in default case when omitted. Its body is used, and its
    /// initial state is marked.
    #[arg(long)]
    pub case: Option<PathBuf>,
    /// Jellett's H3 of the plane (K, H1); default: the case's.
    #[arg(long, allow_negative_numbers = true)]
    pub h3: Option<f64>,
    /// Directory for the figures and CSV tables (created if missing); the files are named
    /// diagram*.{png,svg,csv}. Default: `diagram` in the current directory, said on standard
    /// error and in the JSON (`out`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Tilts at which the steady precessions are computed (2 to 5000).
    #[arg(long, default_value_t = Resolution::default().tilts)]
    pub tilts: usize,
    /// Columns of the grid of torus counts (2 to 387; rows: two thirds as many): the grid's
    /// cells are the work of the diagram, at most 100000 (about 40 s; MAX_GRID_CELLS).
    #[arg(long, default_value_t = Resolution::default().grid)]
    pub grid: usize,
    /// Points of the monodromy loop (8 to 5000).
    #[arg(long, default_value_t = Resolution::default().loop_points)]
    pub loop_points: usize,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
}

/// What `routh diagram` reports.
#[derive(Serialize)]
struct Report<'a> {
    case: String,
    body: routh::Body,
    /// Where the plane's H3 comes from: "case" or "option".
    h3_from: &'static str,
    /// The case's own value and its tori.
    case_value: TorusCount,
    /// Whether the case's value lies in the plane drawn (its H3 is the plane's).
    case_in_plane: bool,
    #[serde(flatten)]
    diagram: &'a Diagram,
    /// The sleeping tops in the plane (H3, K).
    sleeping_tops: &'a [routh::diagram::SleepingTop],
    /// The directory the files were written to.
    out: PathBuf,
    /// Where `out` comes from: "option" (`--out`) or "default" (`diagram` in the current
    /// directory, also said on standard error).
    out_from: &'static str,
    files: Vec<PathBuf>,
}

/// The directory used when `--out` is not given.
const DEFAULT_OUT: &str = "diagram";

/// Write a CSV table atomically: a header and rows of numbers or words.
fn write_csv(path: &Path, header: &str, rows: impl Iterator<Item = String>) -> Result<()> {
    write_atomic(path, |w| {
        let io = AppError::io(path);
        writeln!(w, "{header}").map_err(&io)?;
        for row in rows {
            writeln!(w, "{row}").map_err(&io)?;
        }
        Ok(())
    })
}

/// The CSV tables of the diagram.
fn tables(d: &Diagram, dir: &Path) -> Result<Vec<PathBuf>> {
    let mut files = vec![];
    let path = dir.join("diagram_curves.csv");
    write_csv(
        &path,
        "branch,stability,theta,K,H1,H3,precession,Q2",
        d.critical_curves.iter().flat_map(|c| {
            c.points.iter().map(move |p| {
                format!(
                    "{},{},{},{},{},{},{},{}",
                    c.branch,
                    c.stability.name(),
                    p.theta,
                    p.value.k,
                    p.value.h1,
                    p.value.h3,
                    p.precession,
                    p.q_second_derivative
                )
            })
        }),
    )?;
    files.push(path);
    let path = dir.join("diagram_points.csv");
    write_csv(
        &path,
        "kind,gamma3,stability,K,H1,H3",
        d.vertical_spins.iter().map(|p| {
            format!(
                "vertical-spin,{},{},{},{},{}",
                p.state.gamma()[2],
                p.stability.name(),
                p.value.k,
                p.value.h1,
                p.value.h3
            )
        }),
    )?;
    files.push(path);
    let path = dir.join("diagram_tori.csv");
    write_csv(
        &path,
        "K,H1,tori",
        d.tori.tori.iter().zip(&d.tori.h1).flat_map(|(row, h1)| {
            row.iter().zip(&d.tori.k).map(move |(n, k)| {
                format!(
                    "{k},{h1},{}",
                    n.map_or("critical".to_string(), |n| n.to_string())
                )
            })
        }),
    )?;
    files.push(path);
    if let Some(m) = &d.monodromy {
        let path = dir.join("diagram_loop.csv");
        write_csv(
            &path,
            "phi,K,H1,H3,period,advance,W",
            m.points.iter().map(|p| {
                format!(
                    "{},{},{},{},{},{},{}",
                    p.phi,
                    p.value.k,
                    p.value.h1,
                    p.value.h3,
                    p.period,
                    p.advance,
                    p.rotation_number
                )
            }),
        )?;
        files.push(path);
    }
    Ok(files)
}

/// Render a figure in both formats, `dir/stem.png` and `dir/stem.svg`.
pub(super) fn both_formats(figure: &impl Figure, dir: &Path, stem: &str) -> Result<Vec<PathBuf>> {
    [Format::Png, Format::Svg]
        .into_iter()
        .map(|format| {
            let path = dir.join(format!("{stem}.{}", format.extension()));
            render_figure(figure, &path, format)?;
            Ok(path)
        })
        .collect()
}

fn print_text(r: &Report) -> Result<()> {
    let d = r.diagram;
    outln!("case: {}", r.case)?;
    outln!("Jellett H3 = {} (from the {})", d.h3, r.h3_from)?;
    for v in &d.vertical_spins {
        outln!(
            "vertical spin gamma3 = {:+}: K = {}, H1 = {}, {}",
            v.state.gamma()[2].round(),
            v.value.k,
            v.value.h1,
            v.stability.name()
        )?;
    }
    for c in &d.critical_curves {
        outln!(
            "critical curve (branch {}): {} points, {}",
            c.branch,
            c.points.len(),
            c.stability.name()
        )?;
    }
    match &d.monodromy {
        Some(m) => outln!(
            "monodromy around K = {}, H1 = {}: W changes by {} once around ({} points, largest \
             step {:.3}); matrix {:?}",
            m.centre.value.k,
            m.centre.value.h1,
            m.winding,
            m.points.len(),
            m.max_step,
            m.matrix
        )?,
        None => outln!("no focus-focus point at this H3")?,
    }
    match r.case_value.tori() {
        Some(n) => outln!("the case's value: {n} torus/tori")?,
        None => outln!("the case's value is critical")?,
    }
    for f in &r.files {
        outln!("wrote {}", f.display())?;
    }
    Ok(())
}

/// Run `routh diagram`.
pub fn run(args: Args) -> Result<()> {
    let case = Case::load(args.case.as_deref())?;
    let body = case.body("routh diagram")?;
    body.require_symmetric("routh diagram")?;
    if let Some(h3) = args.h3 {
        check_option("h3", h3, h3.is_finite(), "must be finite")?;
    }
    let own = Value::of_state(&body, &case.initial);
    let h3 = args.h3.unwrap_or(own.h3);
    let case_in_plane = h3 == own.h3;
    let resolution = Resolution {
        tilts: args.tilts,
        grid: args.grid,
        loop_points: args.loop_points,
    };
    let marked: Vec<Value> = if case_in_plane { vec![own] } else { vec![] };
    let diagram = Diagram::new(&body, h3, &marked, resolution)?;
    let h3_max = [own.h3.abs(), h3.abs()]
        .into_iter()
        .chain(diagram.vertical_spins.iter().map(|v| v.value.h3.abs()))
        .fold(0.0_f64, f64::max);
    // The lines reach half as far again as the largest of these and of Routh's thresholds
    // (the body's own scales; the units of a body at rest without gravity when all vanish),
    // within the largest |H3| that the diagram resolves.
    let thresholds = [1.0, -1.0]
        .into_iter()
        .map(|pole| threshold_h3(&body, pole))
        .collect::<routh::Result<Vec<_>>>()?;
    let reach = thresholds.into_iter().flatten().fold(h3_max, f64::max);
    let unit = routh::units::Units::with_rate(&body, 0.0);
    let reach = if reach > 0.0 {
        reach
    } else {
        unit.momentum() * unit.length()
    };
    let lines = sleeping_tops(&body, (1.5 * reach).min(largest_h3(&body)?.0), 401)?;
    let (out, out_from) = match &args.out {
        Some(dir) => (dir.clone(), "option"),
        None => (PathBuf::from(DEFAULT_OUT), "default"),
    };
    create_dir(&out)?;
    let mut files = tables(&diagram, &out)?;
    let marks: Vec<(String, Value)> = marked.iter().map(|v| ("case".to_string(), *v)).collect();
    files.extend(both_formats(
        &EnergyMomentum {
            diagram: &diagram,
            marks,
        },
        &out,
        "diagram",
    )?);
    files.extend(both_formats(
        &SleepingTopFigure {
            lines: &lines,
            marks: vec![("case".to_string(), (own.h3, own.k))],
            h3,
        },
        &out,
        "diagram_sleeping_top",
    )?);
    if let Some(m) = &diagram.monodromy {
        files.extend(both_formats(
            &RotationNumberFigure { monodromy: m },
            &out,
            "diagram_rotation_number",
        )?);
    }
    let report = Report {
        case: case.source.clone(),
        body,
        h3_from: if args.h3.is_some() { "option" } else { "case" },
        case_value: torus_count(&body, own)?,
        case_in_plane,
        diagram: &diagram,
        sleeping_tops: &lines,
        out: std::path::absolute(&out).unwrap_or_else(|_| out.clone()),
        out_from,
        files,
    };
    if out_from == "default" {
        eprintln!(
            "routh diagram: no --out given: wrote {} files to {}",
            report.files.len(),
            report.out.display()
        );
    }
    if args.json {
        super::print_json(&report)?;
    } else {
        print_text(&report)?;
    }
    Ok(())
}
