//! `routh sweep`: many runs of a case over the quantities of its `[sweep]` table, one row per
//! run, written as the runs finish; Ctrl-C or SIGTERM stop it cleanly and `--resume` goes on.

use super::integration::{parse_method, Integration};
use routh::integrate::Method;
use routh::surface::parse_events;
use routh::sweep::open;
use routh::sweep::record::Row;
use routh::sweep::table::{Resumed, TableWriter};
use routh::sweep::{pool, Columns, Completion, Sweep};
use routh::{AppResult as Result, FileError, RouthError};
use std::io::IsTerminal;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Instant;

/// The exit code of a sweep stopped by Ctrl-C or SIGTERM (128 + SIGINT, the shell's
/// convention), after its table is written.
const STOPPED_EXIT_CODE: i32 = 130;

/// Runs per chunk (each chunk is run in parallel and written as one row group): about a
/// hundredth of the sweep, at least 64 and at most 4096 runs.
fn chunk(runs: u64) -> usize {
    (runs / 100).clamp(64, 4096) as usize
}

/// Options of `routh sweep`; the tolerances and t_end override the case file for every run.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Case file (TOML) with a [sweep] table.
    #[arg(long)]
    pub case: PathBuf,
    /// The final time, tolerances and step limit of every run.
    #[command(flatten)]
    pub integration: Integration,
    /// Integrator: `auto` (the default), `dop853`, `vern9`, `taylor` or `rk4` /
    /// `rk4:<steps>`; `auto` picks by the sweep's own measured table (`SWEEP_AUTO_TABLE`: the
    /// Taylor lanes, with an error near the tolerance and the most runs per second from 1e-6
    /// to 1e-13) and the rows name the method that ran.
    #[arg(long, default_value = "auto", value_parser = parse_method)]
    pub method: Method,
    /// Worker threads (default, or 0: one per core; at most 4 per available core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// The table: FILE.parquet or FILE.csv; without it the rows go to stdout as CSV (or in the
    /// JSON).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// The columns of the table, comma-separated: groups `final`, `integrals`, `events`,
    /// `quadrature`, `nutation` (events, quadrature and their differences), `user_events`
    /// (the crossings of `--events`), `all`, or single
    /// columns (`period_quadrature`, `event0_count`, ...); only what they need is computed.
    /// Default: the `[sweep]` table's `columns`, else `final,integrals,user_events` (the last
    /// empty without events; before, every column: `all`).
    /// `run`, the swept quantities, the settings, status, message and work are always in.
    #[arg(long, value_parser = parse_columns)]
    pub columns: Option<Columns>,
    /// The user's events, comma-separated, each a plane of the state and an optional
    /// direction, `NAME = NUMBER [up|down|both]` (default both), NAME one of gamma1 gamma2
    /// gamma3 M1 M2 M3: `--events "gamma3 = 0.9,M1 = 0.5 up"`. Their crossings along each run
    /// (which goes on to t_end) are counted, with the time of the first: the columns
    /// `event{k}_count`, `event{k}_first_t` (group `user_events`, in the default columns).
    /// Default: the `[sweep]` table's `events`, else none.
    #[arg(long)]
    pub events: Option<String>,
    /// Continue a stopped sweep: keep the rows of `--out` and run only the missing runs (a
    /// last row cut short is dropped, and said, and its run done again).
    #[arg(long)]
    pub resume: bool,
    /// Print the summary and every row as JSON.
    #[arg(long)]
    pub json: bool,
    /// Integrate the runs one at a time instead of together in SIMD lanes (DOP853 and Taylor;
    /// the rows are the same bit for bit, only the speed differs).
    #[arg(long)]
    pub no_batch: bool,
}

/// The columns of `--columns`: names and groups separated by commas.
fn parse_columns(list: &str) -> std::result::Result<Columns, String> {
    Columns::parse(list.split(',')).map_err(|e| e.to_string())
}

/// Writes the rows to stdout as CSV.
struct Stdout {
    settings: routh::sweep::record::RunSettings,
}

impl TableWriter for Stdout {
    fn write(&mut self, rows: &[Row]) -> Result<()> {
        let mut text = String::new();
        for row in rows {
            row.write_csv_line(&self.settings, &mut text);
            text.push('\n');
        }
        outln!("{}", text.trim_end_matches('\n'))
    }

    fn finish(self: Box<Self>) -> Result<()> {
        Ok(())
    }
}

/// Where a sweep's rows go as they are written (by its worker threads, [`Sweep::execute`]):
/// the table (unless only `--json` is asked for), the rows of `--json`, the counts of the
/// summary and the progress bar.
struct Output {
    table: Option<Box<dyn TableWriter>>,
    /// The columns' names and the settings of `--json`'s rows, when it is asked for.
    json: Option<(Vec<String>, routh::sweep::record::RunSettings)>,
    json_rows: Vec<serde_json::Map<String, serde_json::Value>>,
    ran: u64,
    failed: u64,
    bar: indicatif::ProgressBar,
}

impl TableWriter for Output {
    fn write(&mut self, rows: &[Row]) -> Result<()> {
        if let Some(table) = self.table.as_mut() {
            table.write(rows)?;
        }
        self.ran += rows.len() as u64;
        self.failed += rows
            .iter()
            .filter(|r| r.status == routh::sweep::record::Status::Failed)
            .count() as u64;
        if let Some((names, settings)) = &self.json {
            self.json_rows.extend(rows.iter().map(|r| {
                let cells = r.cells(settings);
                names
                    .iter()
                    .cloned()
                    .zip(cells.iter().map(|c| c.to_json()))
                    .collect::<serde_json::Map<_, _>>()
            }));
        }
        self.bar.inc(rows.len() as u64);
        Ok(())
    }

    fn finish(self: Box<Self>) -> Result<()> {
        self.bar.finish_and_clear();
        match self.table {
            Some(table) => table.finish(),
            None => Ok(()),
        }
    }
}

/// Run `routh sweep`.
pub fn run(args: Args) -> Result<()> {
    let text = std::fs::read_to_string(&args.case).map_err(|e| FileError::Case {
        file: args.case.display().to_string(),
        message: format!("cannot read: {e}"),
    })?;
    let source = args.case.display().to_string();
    let pool = pool(args.threads.unwrap_or(0))?;
    if args.resume && args.out.is_none() {
        return Err(RouthError::Option {
            name: "resume",
            value: "true".into(),
            rule: "needs --out FILE (the table to continue)",
        }
        .into());
    }
    let overrides = args.integration.overrides(args.method);
    let events = args
        .events
        .as_deref()
        .map(|list| parse_events(list, "events"))
        .transpose()?;
    let mut sweep = Sweep::new(&text, &source, overrides, args.columns, events)?;
    sweep.batch = !args.no_batch;
    let sweep = Arc::new(sweep);
    let names: Vec<String> = sweep.table_columns().into_iter().map(|c| c.0).collect();
    let (table, resumed): (Box<dyn TableWriter>, Resumed) = match &args.out {
        Some(path) => open(path, &sweep, args.resume)?,
        None => {
            if !args.json {
                outln!("{}", names.join(","))?;
            }
            (
                Box::new(Stdout {
                    settings: sweep.run_settings(),
                }),
                Default::default(),
            )
        }
    };
    let done = resumed.done;
    if let (Some(partial), Some(path)) = (&resumed.dropped, &args.out) {
        eprintln!(
            "routh sweep: dropped the last row of {}, cut short ({partial}): its run is done again",
            path.display()
        );
    }
    let todo: Vec<u64> = (0..sweep.runs()).filter(|k| !done.contains(k)).collect();
    let stop = Arc::new(AtomicBool::new(false));
    routh::output::stop_on_signal(stop.clone());
    let bar = if std::io::stderr().is_terminal() {
        let bar = indicatif::ProgressBar::new(sweep.runs());
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{bar:40} {pos}/{len} runs, {per_sec}, ETA {eta}",
            )
            .expect("a valid template"),
        );
        bar.set_position(done.len() as u64);
        bar
    } else {
        indicatif::ProgressBar::hidden()
    };
    let output = Output {
        table: (args.out.is_some() || !args.json).then_some(table),
        json: args.json.then(|| (names, sweep.run_settings())),
        json_rows: Vec::new(),
        ran: 0,
        failed: 0,
        bar,
    };
    let start = Instant::now();
    let (completion, mut output) =
        sweep.execute(todo, &pool, chunk(sweep.runs()), &stop, output)?;
    let (ran, failed) = (output.ran, output.failed);
    let json_rows = std::mem::take(&mut output.json_rows);
    Box::new(output).finish()?;
    let elapsed = start.elapsed().as_secs_f64();
    let stopped = completion == Completion::Stopped;
    if args.json {
        super::print_json(&serde_json::json!({
            "case": source,
            "runs": sweep.runs(),
            "resumed": done.len(),
            "dropped_partial_row": resumed.dropped,
            "ran": ran,
            "failed": failed,
            "stopped": stopped,
            "elapsed_s": elapsed,
            "out": args.out,
            "rows": json_rows,
        }))?;
    } else if args.out.is_some() {
        outln!("routh sweep: {source}")?;
        outln!(
            "  {ran} runs in {elapsed:.3} s ({:.1} runs/s), {failed} failed, {} resumed, of {}",
            ran as f64 / elapsed.max(1e-9),
            done.len(),
            sweep.runs()
        )?;
        if let Some(path) = &args.out {
            outln!("  table written to {}", path.display())?;
        }
    }
    if stopped {
        eprintln!(
            "routh sweep: stopped after {} of {} runs; the finished rows are in the table: run \
             again with --resume to complete it",
            done.len() as u64 + ran,
            sweep.runs()
        );
        std::process::exit(STOPPED_EXIT_CODE);
    }
    Ok(())
}
