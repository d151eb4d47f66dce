//! `routh simulate`: integrate a case and report the integrals' drift; optionally write
//! dense-output samples to CSV.

use super::case_file::CaseFile;
use super::integration::{parse_method, Integration};
use super::{Readable, ReportStream};
use routh::case::{Case, SlidingStart};
use routh::contact::rubber::{RubberSummary, COLUMN_NAMES as RUBBER_COLUMNS};
use routh::contact::sliding::SlidingSummary;
use routh::integrals::INTEGRAL_NAMES;
use routh::integrate::Method;
use routh::output::write_atomic;
use routh::row::{csv_line, Cell};
use routh::simulate::{Drift, Settings, Summary};
use routh::table::{
    rubber_samples, sample_columns, simulate_samples, sliding_columns, sliding_samples,
    STATE_COLUMN_NAMES,
};
use routh::{AppError, AppResult as Result, RouthError};
use std::path::{Path, PathBuf};

/// Samples written to CSV when `--out` is given without `--samples`.
const DEFAULT_CSV_SAMPLES: usize = 1001;

/// Options of `routh simulate`; each overrides the case file.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub case: CaseFile,
    /// The final time, tolerances and step limit.
    #[command(flatten)]
    pub integration: Integration,
    /// Integrator: `dop853` (adaptive, 8th order), `vern9` (adaptive, 9th order), `taylor` (Taylor series, adaptive order and step), `auto` (the fastest for the tolerance, with or without `--project`) or `rk4` / `rk4:<steps>` (fixed step).
    #[arg(long, default_value = "dop853", value_parser = parse_method)]
    pub method: Method,
    /// Project onto the level set of the integrals (|gamma| = 1, H3, K, H1) after each step.
    #[arg(long)]
    pub project: bool,
    /// With `--project`: project after every N-th step only (default 1: every step); about
    /// as accurate for N up to ~10, at a fraction of the projection's cost.
    #[arg(long, value_name = "N", default_value_t = 1, requires = "project")]
    pub project_every: usize,
    /// Number of equally spaced dense-output samples on [0, t_end], both ends included
    /// (2 to 10000000; default 1001 with `--out`). Without `--out` they go to standard output.
    #[arg(long)]
    pub samples: Option<usize>,
    /// CSV file for the samples (written atomically; `-` for standard output, where the
    /// summary then goes to standard error).
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

/// The settings of a case with the command-line overrides applied, validated as they are
/// built ([`Settings`]: the same rules and messages as the sweep's and Python's).
pub fn settings(case: &Case, args: &Args, samples: usize) -> Result<Settings> {
    Ok(args
        .integration
        .overrides(args.method)
        .applied_to(case)
        .projection(args.project, args.project_every)
        .samples(samples)
        .build()?)
}

/// Where the CSV of samples goes: `--out`, or standard output when only `--samples` is given.
fn csv_destination(args: &Args) -> Option<PathBuf> {
    match (&args.out, args.samples) {
        (Some(path), _) => Some(path.clone()),
        (None, Some(_)) => Some(PathBuf::from("-")),
        (None, None) => None,
    }
}

/// Run the command.
pub fn run_command(args: Args) -> Result<()> {
    let case = args.case.load_any_contact()?;
    let out = csv_destination(&args);
    let samples = match (args.samples, &out) {
        (Some(n), _) if n < 2 => {
            return Err(RouthError::Option {
                name: "samples",
                value: n.to_string(),
                rule: "must be >= 2 (the samples include t = 0 and t_end)",
            }
            .into())
        }
        (Some(n), _) => n,
        (None, Some(_)) => DEFAULT_CSV_SAMPLES,
        (None, None) => 0,
    };
    let settings = settings(&case, &args, samples)?;
    let stream = ReportStream::beside([out.as_deref()]);
    if args.full && case.rubber.is_some() {
        return Err(RouthError::Option {
            name: "full",
            value: "true".into(),
            rule: "is not available for [contact] law = \"rubber\" (so far)",
        }
        .into());
    }
    if let Some(start) = &case.rubber {
        let columns: Vec<&str> = std::iter::once("t")
            .chain(STATE_COLUMN_NAMES)
            .chain(RUBBER_COLUMNS)
            .collect();
        let summary = execute(out.as_deref(), &columns, |on_row| {
            rubber_samples(start, &settings, on_row)
        })?;
        return stream.print(&summary, args.json, |s| {
            rubber_text(&case, s, out.as_deref())
        });
    }
    if let Some(start) = &case.sliding {
        let summary = execute(out.as_deref(), &sliding_columns(args.full), |on_row| {
            sliding_samples(start, &settings, args.full, on_row)
        })?;
        return stream.print(&summary, args.json, |s| {
            sliding_text(&case, start, s, out.as_deref())
        });
    }
    let full = args.full;
    let summary = execute(out.as_deref(), &sample_columns(full), |on_row| {
        simulate_samples(&case, &settings, full, on_row)
    })?;
    stream.print(&summary, args.json, |s| {
        summary_text(&case, s, out.as_deref())
    })
}

/// The receiver of the cells of each sample of a run.
type OnRow<'a> = &'a mut dyn FnMut(&[Cell]) -> Result<()>;

/// Run `simulation`, which hands the cells of each sample to its argument, writing them as
/// CSV under the header `columns` to `out` when given (whole or not at all).
fn execute<S>(
    out: Option<&Path>,
    columns: &[&str],
    simulation: impl FnOnce(OnRow<'_>) -> Result<S>,
) -> Result<S> {
    let Some(path) = out else {
        return simulation(&mut |_| Ok(()));
    };
    let mut summary = None;
    write_atomic(path, |w| {
        let io = AppError::io(path);
        writeln!(w, "{}", columns.join(",")).map_err(&io)?;
        let mut on_row = |cells: &[Cell]| writeln!(w, "{}", csv_line(cells)).map_err(&io);
        summary = Some(simulation(&mut on_row)?);
        Ok(())
    })?;
    Ok(summary.expect("the run returned a summary"))
}

/// Where the samples went, as the last line of a summary.
fn samples_line(text: &mut String, out: Option<&Path>) {
    use std::fmt::Write;
    let _ = match out {
        Some(path) if path == Path::new("-") => {
            writeln!(text, "  samples written to standard output")
        }
        Some(path) => writeln!(text, "  samples written to {}", path.display()),
        None => Ok(()),
    };
}

/// The summary of a sliding run as lines of text.
fn sliding_text(
    case: &Case,
    start: &SlidingStart,
    s: &SlidingSummary,
    out: Option<&Path>,
) -> String {
    use std::fmt::Write;
    let mut text = String::new();
    let _ = writeln!(text, "routh simulate: {}", case.source);
    let _ = writeln!(text, "{}", body_line(case));
    let _ = writeln!(
        text,
        "  contact  sliding, viscous friction F = -mu N v_P, mu = {}",
        Readable(start.model.mu())
    );
    let _ = writeln!(text, "  method   {}", s.method);
    let _ = writeln!(text, "  end      {}: {}", s.status, s.message);
    let _ = writeln!(
        text,
        "  work     {} steps ({} rejected), {} field evaluations in {:.3} s",
        s.steps, s.rejected, s.rhs_evals, s.elapsed_s
    );
    let (a, b) = (&s.initial_state, &s.final_state);
    let _ = writeln!(text, "                    initial                 final");
    for (name, x, y) in [
        ("height", a.height, b.height),
        ("slip speed", a.slip_speed, b.slip_speed),
        ("normal force", a.normal_force, b.normal_force),
        ("Jellett (L, r)", a.jellett, b.jellett),
        ("H1", a.energy, b.energy),
        ("friction work", a.work, b.work),
    ] {
        let _ = writeln!(text, "  {name:<15} {x:>22.15e}  {y:>22.15e}");
    }
    let balance = &s.balance;
    let jellett = match balance.jellett {
        Some(d) => format!("{d:.3e}"),
        None => "- (not an integral: I1 != I2 or com off the axis)".into(),
    };
    let _ = writeln!(text, "  Jellett max relative drift       {jellett}");
    let _ = writeln!(
        text,
        "  H1 + work max relative drift     {:.3e}",
        balance.energy_balance
    );
    let _ = writeln!(
        text,
        "  height range                     [{}, {}]",
        balance.height_range[0], balance.height_range[1]
    );
    samples_line(&mut text, out);
    text
}

/// The body, as a line of a summary.
fn body_line(case: &Case) -> String {
    let b = &case.ball;
    let [i1, i2, i3] = b.inertia();
    // The offset a of a Routh sphere, else the centre of mass.
    let centre = if b.is_axial() {
        format!("a = {}", Readable(-b.com()[2]))
    } else {
        format!("com = {:?}", b.com())
    };
    format!(
        "  body     m = {}, R = {}, {centre}, I = ({}, {}, {}), G = {}",
        Readable(b.m()),
        Readable(b.radius()),
        Readable(i1),
        Readable(i2),
        Readable(i3),
        Readable(b.gravity())
    )
}

/// The summary of a rubber run as lines of text: the run's, with the rubber ball's integrals
/// and the residual of the constraint.
fn rubber_text(case: &Case, s: &RubberSummary, out: Option<&Path>) -> String {
    use std::fmt::Write;
    let mut text = String::new();
    let _ = writeln!(text, "routh simulate: {}", case.source);
    let _ = writeln!(text, "{}", body_line(case));
    let _ = writeln!(
        text,
        "  contact  rubber: rolling without slipping or twisting, omega . gamma = 0"
    );
    run_lines(&mut text, &s.run, "");
    integral_lines(
        &mut text,
        &RUBBER_COLUMNS[..3],
        &s.run.integrals,
        "G > 0 and the centre of mass off the centre",
    );
    let _ = writeln!(
        text,
        "  constraint max |omega . gamma| / |omega|   {:.3e}",
        s.twist
    );
    samples_line(&mut text, out);
    text
}

/// The table of the integrals `names` of a run, their initial value and drift, as lines of
/// text; one missing from `integrals` is not an integral, for the reason `why`.
fn integral_lines(
    text: &mut String,
    names: &[&str],
    integrals: &std::collections::BTreeMap<&'static str, Drift>,
    why: &str,
) {
    use std::fmt::Write;
    let _ = writeln!(text, "  integral        initial value   max relative drift");
    for name in names {
        let _ = match integrals.get(name) {
            Some(d) => writeln!(
                text,
                "  {name:<4} {:>24.15e}   {:.3e}",
                d.initial, d.max_rel_drift
            ),
            None => writeln!(text, "  {name:<4} {:>24}   (not an integral: {why})", "-"),
        };
    }
}

/// The method, the time, the work and the final state of a run, as lines of text.
fn run_lines(text: &mut String, s: &Summary, projected: &str) {
    use std::fmt::Write;
    let _ = writeln!(text, "  method   {}{projected}", s.method);
    let _ = writeln!(text, "  t_end    {}", s.t_end);
    let _ = writeln!(
        text,
        "  work     {} steps ({} rejected), {} field evaluations in {:.3} s",
        s.steps, s.rejected, s.rhs_evals, s.elapsed_s
    );
    let [g1, g2, g3] = s.final_state.gamma;
    let _ = writeln!(text, "  gamma(t_end) = [{g1:.15}, {g2:.15}, {g3:.15}]");
    let [m1, m2, m3] = s.final_state.m;
    let _ = writeln!(text, "  M(t_end)     = [{m1:.15}, {m2:.15}, {m3:.15}]");
}

/// The summary as lines of text.
fn summary_text(case: &Case, s: &Summary, out: Option<&Path>) -> String {
    use std::fmt::Write;
    let mut text = String::new();
    let projected = match (s.projected, s.project_every) {
        (false, _) => String::new(),
        (true, 1) => " with projection onto the integrals".to_string(),
        (true, n) => format!(" with projection onto the integrals every {n} steps"),
    };
    let _ = writeln!(text, "routh simulate: {}", case.source);
    let _ = writeln!(text, "{}", body_line(case));
    run_lines(&mut text, s, &projected);
    integral_lines(&mut text, &INTEGRAL_NAMES, &s.integrals, "I1 != I2");
    samples_line(&mut text, out);
    text
}
