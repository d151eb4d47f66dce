//! Running a sweep: the case of each run, one run as `routh simulate` does it plus the
//! nutation from events and from the quadrature, and many runs on a pool of threads,
//! handed to a writer chunk by chunk. With DOP853 or the Taylor method the runs of one body
//! are integrated together in SIMD lanes ([`crate::batch`]), whose arithmetic is that of the
//! one-at-a-time integrator: the rows are the same, bit for bit, only faster.

use super::columns::{Columns, MAX_EVENTS};
use super::contact;
use super::crossings::{self, Watch};
use super::design::Design;
use super::record::{columns, NutationQuadrature, Row, RunSettings, Status};
use super::spec::{refuse, Quantity, Refusal, Spec};
use super::table::{not_this_sweep, TableWriter};
use crate::ball::Ball;
use crate::batch::{self, Job, Queue, LANES};
use crate::body::Body;
use crate::case::{Case, CaseValues, Overrides, SlidingStart};
use crate::error::{AppError, AppResult as Result, FileError, RouthError};
use crate::integrate::{Method, Options, Outcome, Stepper, Stop};
use crate::quadrature::ExactSolution;
use crate::row::Kind;
use crate::simulate::{integrate_observed, DriftTracker, ReducedSystem, Settings, Summary};
use crate::state::{Point, State};
use crate::surface::SurfaceEvent;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{channel, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The most worker threads per available core ([`pool`]): the runs are computation, so more
/// threads than cores only share them (and 10,000 threads of one process slow the machine).
pub const MAX_THREADS_PER_CORE: usize = 4;

/// How often [`Sweep::execute`] looks at the stop flag while waiting for rows: a stop is
/// obeyed within this time plus the writing of the rows done.
const POLL: Duration = Duration::from_millis(50);

/// Where the rows go as their runs end, a few at a time: `(position in the list of runs, row)`,
/// from any thread.
type Sink<'s> = &'s (dyn Fn(Vec<(usize, Row)>) + Sync);

/// How many rows of runs done in lanes are handed to the [`Sink`] together: one handover per
/// row woke the waiting writer thread once per run (a tenth of a one-thread sweep's time in
/// the kernel's futex calls), while a stop still hands over every row done at once.
const ROWS_PER_HANDOVER: usize = 64;

/// A pool of `threads` worker threads (0: one per core), at most [`MAX_THREADS_PER_CORE`]
/// per available core (`std::thread::available_parallelism`), refused above with the rule.
pub fn pool(threads: usize) -> Result<rayon::ThreadPool> {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    if threads > MAX_THREADS_PER_CORE * cores {
        return Err(RouthError::Option {
            name: "threads",
            value: format!("{threads} ({cores} cores available)"),
            rule: "must be at most 4 per available core (the runs are computation: more threads \
                   than cores only share them)",
        }
        .into());
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| {
            RouthError::Option {
                name: "threads",
                value: format!("{threads} ({e})"),
                rule: "the thread pool must start",
            }
            .into()
        })
}

/// A sweep ready to run: the base case, the design, the settings of every run.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// The case file's text (stored in the output's metadata).
    pub case_text: String,
    source: String,
    base: CaseValues,
    /// The runs whose cases were validated when the sweep was built: only they can run.
    checked: std::ops::Range<u64>,
    /// The ball of every run when no key of `[body]` is swept (built and validated once), and
    /// its [`Body`] when it is a Routh sphere.
    fixed: Option<(Ball, Option<Body>)>,
    design: Design,
    /// The settings of every run.
    pub settings: Settings,
    /// The columns of the table: only what they need is computed ([`Columns`]).
    pub columns: Columns,
    /// The user's events, located along every run when their columns are asked for.
    pub events: Vec<SurfaceEvent>,
    /// The runs slide (`[contact] law = "sliding"`): each is [`contact::row`]'s.
    sliding: bool,
    /// Integrate the runs of one body together in SIMD lanes ([`crate::batch`]) when the
    /// method is DOP853 or Taylor (the default, `true`); `false` runs them one at a time. The rows are
    /// the same, bit for bit: only the speed differs.
    pub batch: bool,
}

/// A run waiting for a lane: its position in the list of runs, its number and initial state.
struct Pending {
    position: usize,
    k: u64,
    initial: State,
    x0: [f64; 6],
}

/// A run in a lane: what [`integrate_observed`] tracks along a run (the drift of the
/// integrals when its columns are asked for; the wall time; the events are the lane's
/// [`Watch`]).
struct InLane<'b> {
    run: &'b Pending,
    drift: Option<DriftTracker>,
    start: Instant,
}

/// The runs of one body fed to the batched integrator, each reduced to its row as
/// [`Sweep::run`] does it.
struct LaneQueue<'b, I> {
    sweep: &'b Sweep,
    body: &'b Body,
    pending: I,
    lanes: [Option<InLane<'b>>; LANES],
    /// The events watched in each lane (when asked for), allocated once for all its runs.
    watches: [Option<Watch<'b>>; LANES],
    /// The rows done and not yet handed to `sink`.
    done: Vec<(usize, Row)>,
    sink: Sink<'b>,
    stop: &'b AtomicBool,
}

impl<I> LaneQueue<'_, I> {
    /// Hand the rows done to the sink.
    fn hand_over(&mut self) {
        if !self.done.is_empty() {
            (self.sink)(std::mem::take(&mut self.done));
        }
    }
}

impl<'b, I: Iterator<Item = &'b Pending>> Queue<6> for LaneQueue<'b, I> {
    fn next(&mut self, lane: usize) -> Option<Job<6>> {
        if self.stop.load(Ordering::Relaxed) {
            return None;
        }
        let run = self.pending.next()?;
        let columns = &self.sweep.columns;
        self.lanes[lane] = Some(InLane {
            run,
            drift: columns
                .tracks_integrals()
                .then(|| DriftTracker::new(self.body, &run.x0)),
            start: Instant::now(),
        });
        if let Some(watch) = self.watches[lane].as_mut() {
            watch.start(&run.x0);
        }
        Some(Job {
            t0: 0.0,
            y0: run.x0,
            t_end: self.sweep.settings.t_end(),
        })
    }

    /// As the observer of [`Sweep::run`]: the drift at the step end, then the events.
    fn step(&mut self, lane: usize, step: &dyn Stepper<6>) {
        if let Some(run) = self.lanes[lane].as_mut() {
            if let Some(drift) = run.drift.as_mut() {
                drift.observe(self.body, step.y());
            }
            if let Some(watch) = self.watches[lane].as_mut() {
                watch.observe(step);
            }
        }
    }

    fn end(&mut self, lane: usize, end: Outcome<6>) {
        let Some(done) = self.lanes[lane].take() else {
            return;
        };
        let (sweep, run) = (self.sweep, done.run);
        let row = match end.stop {
            Stop::Failed(e) => sweep.failed(run.k, RouthError::from(e).to_string()),
            _ => {
                let summary = Summary {
                    method: sweep.settings.method().to_string(),
                    t_end: sweep.settings.t_end(),
                    steps: end.stats.steps,
                    rejected: end.stats.rejected,
                    rhs_evals: end.stats.rhs_evals,
                    projected: false,
                    project_every: 1,
                    initial_state: Point::from_array(&run.x0),
                    final_state: Point::from_array(&end.y),
                    integrals: done.drift.map(|d| d.report()).unwrap_or_default(),
                    elapsed_s: done.start.elapsed().as_secs_f64(),
                };
                let watch = self.watches[lane].as_ref();
                sweep.finished(run.k, self.body, &run.initial, summary, watch)
            }
        };
        self.done.push((run.position, row));
        if self.done.len() >= ROWS_PER_HANDOVER || self.stop.load(Ordering::Relaxed) {
            self.hand_over();
        }
    }
}

/// How [`Sweep::execute`] ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Completion {
    /// Every requested run was done.
    Finished,
    /// Stopped on request; the runs done so far were handed to the writer.
    Stopped,
}

/// The rows of [`Sweep::execute`] on their way to its writer, in the order of the runs: the
/// rows that wait for an earlier run, those ready, and the writer (`None` once `execute` has
/// returned: the rows of runs abandoned by a stop are dropped).
struct InOrder<W> {
    writer: Option<W>,
    waiting: BTreeMap<usize, Row>,
    ready: Vec<Row>,
    next: usize,
    chunk: usize,
    /// The first write that failed (no row is written after it).
    error: Option<AppError>,
}

impl<W: TableWriter> InOrder<W> {
    fn new(writer: W, chunk: usize) -> Self {
        InOrder {
            writer: Some(writer),
            waiting: BTreeMap::new(),
            ready: Vec::new(),
            next: 0,
            chunk: chunk.max(1),
            error: None,
        }
    }

    /// Take the rows `done` (with their positions) and write every `chunk` rows ready; an
    /// error is kept, and returned as `Err(())`, and no row is written after it.
    fn take(&mut self, done: Vec<(usize, Row)>) -> std::result::Result<(), ()> {
        if self.writer.is_none() || self.error.is_some() {
            return Err(());
        }
        for (position, row) in done {
            if position >= self.next {
                self.waiting.entry(position).or_insert(row);
            }
        }
        while let Some(row) = self.waiting.remove(&self.next) {
            self.ready.push(row);
            self.next += 1;
            if self.ready.len() == self.chunk {
                self.write()?;
            }
        }
        Ok(())
    }

    /// Write the rows ready.
    fn write(&mut self) -> std::result::Result<(), ()> {
        let Some(writer) = self.writer.as_mut() else {
            return Err(());
        };
        if !self.ready.is_empty() {
            if let Err(e) = writer.write(&self.ready) {
                self.error = Some(e);
                return Err(());
            }
            self.ready.clear();
        }
        Ok(())
    }

    /// The end of [`Sweep::execute`]: the error of a failed write, or the rows ready written
    /// (after a stop, the rows waiting for an abandoned run too, in order) and the writer
    /// handed back.
    fn close(&mut self, stopped: bool) -> Result<(Completion, W)> {
        if stopped {
            let waiting = std::mem::take(&mut self.waiting);
            self.ready.extend(waiting.into_values());
        }
        let _ = self.write();
        if let Some(e) = self.error.take() {
            self.writer = None;
            return Err(e);
        }
        let writer = self.writer.take().expect("the writer is taken once");
        let completion = if stopped {
            Completion::Stopped
        } else {
            Completion::Finished
        };
        Ok((completion, writer))
    }
}

/// What `routh sweep --method auto` (the default) runs: `(tol_min, method)` rows, the first
/// with `min(rtol, atol) >= tol_min` wins. A sweep's own choice (not
/// `routh_ball::auto::AUTO_TABLE`, which is for one run), measured on whole sweeps by
/// `python3 bench/sweep_methods.py` (BENCHMARKS.md, "The sweep's default method"): from 1e-6
/// to 1e-13 the Taylor lanes' error is 1 to 3 times the tolerance where DOP853's is 800 to
/// 7,500 times, and they do as many runs per second (0.94x at 1e-6) to 3.8x as many (1e-13):
/// at equal error they are faster everywhere.
pub const SWEEP_AUTO_TABLE: [(f64, Method); 1] = [(0.0, Method::Taylor)];

/// The method a sweep runs for `method` at the tolerance `tol`: [`SWEEP_AUTO_TABLE`] for
/// [`Method::Auto`] (the rows then name the method that ran, and `routh simulate` with that
/// method gives the same numbers), the method itself otherwise.
pub fn resolve(method: Method, tol: f64) -> Method {
    method.resolve_in(tol, &SWEEP_AUTO_TABLE)
}

impl Sweep {
    /// A sweep of the case `text` (read from `source`), whose `[sweep]` table is checked, with
    /// every run's case built and validated before any run starts: a bad table or a value
    /// that makes a body or a state invalid is refused, naming the key and the value. The
    /// settings of every run are the case's (no projection, no samples) with `overrides`
    /// applied ([`Overrides::applied_to`], as `routh simulate` builds its own), the method
    /// then [`resolve`]d for the tolerances. The columns of the table are `columns`, else the
    /// `[sweep]` key `columns`, else [`Columns::default`]; the user's events are `events`,
    /// else the `[sweep]` key `events` ([`crossings::from_toml`]), else none (at most
    /// [`MAX_EVENTS`]).
    pub fn new(
        text: &str,
        source: &str,
        overrides: Overrides,
        columns: Option<Columns>,
        events: Option<Vec<SurfaceEvent>>,
    ) -> Result<Self> {
        Self::for_runs(text, source, overrides, columns, events, 0, None)
    }

    /// The sweep of [`Sweep::new`] whose runs `start <= run < stop` (`stop` by default the
    /// number of runs) alone are validated and may run ([`Sweep::rows`]): one chunk of a sweep
    /// split between processes (Dask) checks its own runs, not every run of the sweep.
    pub fn for_runs(
        text: &str,
        source: &str,
        overrides: Overrides,
        columns: Option<Columns>,
        events: Option<Vec<SurfaceEvent>>,
        start: u64,
        stop: Option<u64>,
    ) -> Result<Self> {
        let case = Case::parse_any_contact(text, source)?;
        if case.rubber.is_some() {
            return Err(FileError::Case {
                file: source.to_string(),
                message: "[contact] law = \"rubber\" is integrated by `routh simulate` only \
                          (so far): `routh sweep` runs the rolling and the sliding laws"
                    .into(),
            }
            .into());
        }
        let sliding = case.sliding.is_some();
        let asked = overrides.applied_to(&case).build()?;
        let tol = asked.rtol().min(asked.atol());
        let method = match &case.sliding {
            Some(start) => start.model.method(asked.method(), tol)?,
            None => resolve(asked.method(), tol),
        };
        let settings = asked.to_builder().method(method).build()?;
        let mut table: toml::Table = case.extra_table("sweep")?.ok_or_else(|| FileError::Case {
            file: source.to_string(),
            message: "no [sweep] table: `routh sweep` needs one (see cases/sweep.toml)".into(),
        })?;
        let refused = |e: Refusal| FileError::Case {
            file: source.to_string(),
            message: e.to_string(),
        };
        let listed_events = table.remove("events");
        let events = match (events, listed_events) {
            (Some(events), _) => events,
            (None, Some(listed)) => crossings::from_toml(&listed).map_err(refused)?,
            (None, None) => Vec::new(),
        };
        if sliding && !events.is_empty() {
            return Err(FileError::Case {
                file: source.to_string(),
                message: "events: a sweep of [contact] law = \"sliding\" has no user events \
                          (so far: they are planes of the rolling law's state)"
                    .into(),
            }
            .into());
        }
        if events.len() > MAX_EVENTS {
            return Err(RouthError::Option {
                name: "events",
                value: format!("{} events", events.len()),
                rule: "must be at most 32 (each has two columns)",
            }
            .into());
        }
        let listed = table.remove("columns");
        let columns = match (columns, listed) {
            (Some(columns), _) => columns
                .of_events(events.len())
                .map_err(|e| FileError::Case {
                    file: source.to_string(),
                    message: format!("--columns: {e}; this sweep has {} events", events.len()),
                })?,
            (None, Some(listed)) => Columns::from_toml(&listed)
                .and_then(|c| {
                    c.of_events(events.len())
                        .map_err(|e| refuse("columns", format!("\"{}\"", e.name), &e.to_string()))
                })
                .map_err(refused)?,
            (None, None) => Columns::default()
                .of_events(events.len())
                .expect("the default names no single event column"),
        };
        let columns = columns.of_law(sliding).map_err(|e| FileError::Case {
            file: source.to_string(),
            message: format!("columns: {e}"),
        })?;
        let design = Spec::parse(&table).and_then(Design::new).map_err(refused)?;
        let base = CaseValues::read(&case.document, source)?;
        let sweeps_body = design
            .spec()
            .axes
            .iter()
            .any(|axis| matches!(axis.quantity, Quantity::Body(_)));
        let fixed = (!sweeps_body).then(|| (case.ball, case.body("routh sweep").ok()));
        let stop = stop.unwrap_or(design.runs());
        if start > stop || stop > design.runs() {
            return Err(RouthError::Option {
                name: "start, stop",
                value: format!("{start}, {stop}"),
                rule: "need 0 <= start <= stop <= the number of runs",
            }
            .into());
        }
        let sweep = Sweep {
            case_text: text.to_string(),
            source: source.to_string(),
            base,
            checked: start..stop,
            fixed,
            design,
            settings,
            columns,
            events,
            sliding,
            batch: true,
        };
        sweep
            .checked
            .clone()
            .into_par_iter()
            .try_for_each(|k| match sweep.sliding {
                true => sweep.sliding_of(k).map(|_| ()),
                false => sweep.case_of(k).map(|_| ()),
            })
            .map_err(refused)?;
        Ok(sweep)
    }

    /// The number of runs.
    pub fn runs(&self) -> u64 {
        self.design.runs()
    }

    /// The names of the swept quantities (their columns).
    pub fn names(&self) -> Vec<String> {
        self.design.spec().names()
    }

    /// The design.
    pub fn design(&self) -> &Design {
        &self.design
    }

    /// Check that `values` (the swept values and settings read from row `run` of the existing
    /// table `path`) are those of run `run` of this sweep, bit for bit.
    pub fn check_resumed_row(&self, path: &Path, run: u64, values: &[f64]) -> Result<()> {
        if run >= self.runs() {
            return Err(not_this_sweep(
                path,
                format!("run {run} is not a run of this sweep"),
            ));
        }
        let s = self.run_settings();
        let expected: Vec<f64> = self
            .design()
            .point(run)
            .into_iter()
            .chain([s.t_end, s.rtol, s.atol])
            .collect();
        if values
            .iter()
            .map(|v| v.to_bits())
            .ne(expected.iter().map(|v| v.to_bits()))
        {
            return Err(not_this_sweep(
                path,
                format!("run {run} has the values {values:?}, this sweep {expected:?} (swept quantities, t_end, rtol, atol)"),
            ));
        }
        Ok(())
    }

    /// The settings as written in each row.
    pub fn run_settings(&self) -> RunSettings {
        RunSettings {
            t_end: self.settings.t_end(),
            rtol: self.settings.rtol(),
            atol: self.settings.atol(),
            method: self.settings.method().to_string(),
            columns: self.columns,
        }
    }

    /// The columns of the table ([`columns`] of the swept quantities and [`Sweep::columns`]).
    pub fn table_columns(&self) -> Vec<(String, Kind)> {
        columns(&self.names(), &self.columns)
    }

    /// The events watched along the runs of `body` (the turning points and the user's
    /// events, each when its columns are asked for), `None` when there are none.
    fn watch<'b>(&'b self, body: &'b Body) -> Option<Watch<'b>> {
        let turning = self.columns.locates_turning_points();
        let events: &[SurfaceEvent] = if self.columns.locates_user_events() {
            &self.events
        } else {
            &[]
        };
        (turning || !events.is_empty()).then(|| Watch::new(body, turning, events))
    }

    /// The case's values of run `k`: the base case with the swept values put in.
    fn values_of(&self, k: u64) -> std::result::Result<CaseValues, Refusal> {
        let values = self.design.point(k);
        let mut case = self.base;
        for (axis, &v) in self.design.spec().axes.iter().zip(&values) {
            let done = match axis.quantity {
                Quantity::Body(key) => case.set_body(key, v),
                Quantity::Tilt => {
                    case.set_gamma(0, v.sin());
                    case.set_gamma(1, 0.0);
                    case.set_gamma(2, v.cos());
                    Ok(())
                }
                Quantity::Spin => case.set_omega(2, v),
                Quantity::Omega(i) => case.set_omega(i, v),
                Quantity::Gamma(i) => {
                    case.set_gamma(i, v);
                    Ok(())
                }
                Quantity::Mu => case.set_mu(v),
            };
            done.map_err(|rule| refuse(&axis.name, v, &rule))?;
        }
        Ok(case)
    }

    /// A value of run `k` that makes its case invalid (`e`), refused naming the swept values.
    fn invalid(&self, k: u64, e: AppError) -> Refusal {
        let named: Vec<String> = self
            .names()
            .iter()
            .zip(self.design.point(k))
            .map(|(n, v)| format!("{n} = {v}"))
            .collect();
        refuse(
            &named.join(", "),
            format!("(run {k})"),
            &format!("makes the case invalid: {e}"),
        )
    }

    /// The case's values, the validated ball and initial state of run `k`.
    fn built(&self, k: u64) -> std::result::Result<(CaseValues, Ball, State), Refusal> {
        let values = self.values_of(k)?;
        let ball = match &self.fixed {
            Some((ball, _)) => *ball,
            None => values.ball(&self.source).map_err(|e| self.invalid(k, e))?,
        };
        let state = values
            .state(&ball, &self.source)
            .map_err(|e| self.invalid(k, e))?;
        Ok((values, ball, state))
    }

    /// The validated ball and initial state of run `k`, as the case file with the run's
    /// values put in would give them; an invalid one is refused naming the swept values.
    pub fn case_of(&self, k: u64) -> std::result::Result<(Ball, State), Refusal> {
        self.built(k).map(|(_, ball, state)| (ball, state))
    }

    /// The sliding ball and its validated initial state of run `k` of a sweep of the sliding
    /// contact (as [`Sweep::case_of`], the contact's own checks added: a ball that would
    /// leave the plane at once is refused).
    pub fn sliding_of(&self, k: u64) -> std::result::Result<SlidingStart, Refusal> {
        let (values, ball, state) = self.built(k)?;
        values
            .sliding(&ball, &state)
            .map_err(|e| self.invalid(k, e))?
            .ok_or_else(|| {
                refuse(
                    "[contact] law",
                    "(not \"sliding\")",
                    "needs a sliding contact",
                )
            })
    }

    /// A row of run `k` that could not be done, with the reason.
    fn failed(&self, k: u64, message: String) -> Row {
        Row {
            run: k,
            values: self.design.point(k),
            status: Status::Failed,
            message,
            summary: None,
            events: None,
            quadrature: None,
            user_events: Vec::new(),
            sliding: None,
        }
    }

    /// The body of run `k` and its initial state.
    fn start(&self, k: u64) -> Result<(Body, State)> {
        let (ball, initial) = self.case_of(k).map_err(|e| FileError::Case {
            file: self.source.clone(),
            message: e.to_string(),
        })?;
        let body = match &self.fixed {
            Some((_, Some(body))) => *body,
            _ => ball.axial_body("routh sweep")?,
        };
        Ok((body, initial))
    }

    /// The row of run `k` whose integration gave `summary` and whose events `watch` saw:
    /// with the quadrature's nutation when its columns are asked for and the body is a Routh
    /// sphere.
    fn finished(
        &self,
        k: u64,
        body: &Body,
        initial: &State,
        summary: Summary,
        watch: Option<&Watch>,
    ) -> Row {
        let (quadrature, message) = if !self.columns.solves_quadrature() {
            (None, String::new())
        } else if body.is_symmetric() {
            match ExactSolution::nutation_numbers(body, initial) {
                Ok(numbers) => (
                    Some(NutationQuadrature {
                        period: numbers.period,
                        precession: numbers.advance,
                    }),
                    String::new(),
                ),
                Err(e) => (None, format!("no quadrature: {e}")),
            }
        } else {
            (
                None,
                "no quadrature: the body is not a Routh sphere (I1 != I2)".into(),
            )
        };
        Row {
            run: k,
            values: self.design.point(k),
            status: Status::Reached,
            message,
            summary: Some(summary),
            events: watch.and_then(Watch::nutation),
            quadrature,
            user_events: watch.map_or_else(Vec::new, |w| w.crossings().to_vec()),
            sliding: None,
        }
    }

    /// Run number `k`: the integration of `routh simulate` on the run's case (the same
    /// numbers, bit for bit), the turning points and the user's events along it and the quadrature when the body
    /// is a Routh sphere, each when its columns are asked for; in a sweep of the sliding
    /// contact, the sliding run of `routh simulate` ([`contact::row`]). A failure (or a
    /// panic) becomes a row with status `failed`.
    pub fn run(&self, k: u64) -> Row {
        let attempt = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            if self.sliding {
                let start = self.sliding_of(k).map_err(|e| FileError::Case {
                    file: self.source.clone(),
                    message: e.to_string(),
                })?;
                return contact::row(k, self.design.point(k), &start, &self.settings);
            }
            let (body, initial) = self.start(k)?;
            let x0 = initial.to_array();
            let mut watch = self.watch(&body);
            if let Some(watch) = watch.as_mut() {
                watch.start(&x0);
            }
            let observed = integrate_observed(
                &body,
                &ReducedSystem(&body),
                x0,
                &self.settings,
                None,
                &mut |_, _| Ok::<_, AppError>(()),
                &mut |step| {
                    if let Some(watch) = watch.as_mut() {
                        watch.observe(step);
                    }
                },
            )?;
            let summary = observed.summary()?;
            Ok::<_, AppError>(self.finished(k, &body, &initial, summary, watch.as_ref()))
        }));
        match attempt {
            Ok(Ok(row)) => row,
            Ok(Err(e)) => self.failed(k, e.to_string()),
            Err(panic) => self.failed(
                k,
                format!(
                    "internal error (panic): {}",
                    panic
                        .downcast_ref::<String>()
                        .cloned()
                        .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                        .unwrap_or_default()
                ),
            ),
        }
    }

    /// Whether the runs go through the batched integrator ([`crate::batch`]): asked for
    /// ([`Sweep::batch`]), DOP853 or Taylor, and a time span to integrate.
    fn in_lanes(&self) -> bool {
        self.batch
            && !self.sliding
            && matches!(self.settings.method(), Method::Dop853 | Method::Taylor)
            && self.settings.t_end() > 0.0
    }

    /// The runs `runs` (on this thread), whose positions in the list of runs start at `first`,
    /// the runs of each body together in lanes of the batched DOP853 ([`batch::lanes`]) or
    /// Taylor method ([`batch::taylor::lanes`]): each row bitwise the row of [`Sweep::run`],
    /// handed to `sink` as its run ends. Once `stop` is set no run starts. Should the batch
    /// panic, its runs are run one at a time (where a panicking run is a failed row; a row
    /// handed over twice is the same row).
    fn run_in_lanes(&self, runs: &[u64], first: usize, stop: &AtomicBool, sink: Sink<'_>) {
        let attempt = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let mut bodies: Vec<(Body, Vec<Pending>)> = Vec::new();
            let mut refused = Vec::new();
            for (position, &k) in (first..).zip(runs) {
                match self.start(k) {
                    Err(e) => refused.push((position, self.failed(k, e.to_string()))),
                    Ok((body, initial)) => {
                        let run = Pending {
                            position,
                            k,
                            initial,
                            x0: initial.to_array(),
                        };
                        match bodies.iter_mut().find(|(b, _)| *b == body) {
                            Some((_, group)) => group.push(run),
                            None => bodies.push((body, vec![run])),
                        }
                    }
                }
            }
            if !refused.is_empty() {
                sink(refused);
            }
            let opts = Options::new(self.settings.rtol(), self.settings.atol())
                .and_then(|opts| opts.with_max_steps(self.settings.max_steps()))?;
            for (body, group) in &bodies {
                let mut queue = LaneQueue {
                    sweep: self,
                    body,
                    pending: group.iter(),
                    lanes: std::array::from_fn(|_| None),
                    watches: std::array::from_fn(|_| self.watch(body)),
                    done: Vec::with_capacity(ROWS_PER_HANDOVER),
                    sink,
                    stop,
                };
                let sys = ReducedSystem(body);
                match self.settings.method() {
                    Method::Taylor => batch::taylor::integrate(&sys, &opts, &mut queue)?,
                    _ => batch::integrate_in_lanes(&sys, &opts, &mut queue),
                }
                queue.hand_over();
            }
            Ok::<_, AppError>(())
        }));
        if !matches!(attempt, Ok(Ok(()))) {
            for (position, &k) in (first..).zip(runs) {
                if stop.load(Ordering::Relaxed) {
                    return;
                }
                sink(vec![(position, self.run(k))]);
            }
        }
    }

    /// The runs `runs`, whose positions in the list of runs start at `first`, on the current
    /// rayon pool, each row handed to `sink` with its position as its run ends: in lanes
    /// ([`Sweep::run_in_lanes`], in pieces of a few hundred runs) or one run at a time. Each
    /// worker thread takes the next piece in the order of `runs` as soon as it is free (no
    /// barrier between pieces, no thread idle while another has work), so that the runs end
    /// nearly in order and the rows that wait for their turn are at most about a piece per
    /// thread. Once `stop` is set no run starts.
    fn run_many(&self, runs: &[u64], first: usize, stop: &AtomicBool, sink: Sink<'_>) {
        let threads = rayon::current_num_threads();
        let lanes = self.in_lanes();
        let piece = if lanes {
            (runs.len() / (4 * threads)).clamp(4 * LANES, 512)
        } else {
            1
        };
        let next = AtomicUsize::new(0);
        let work = || loop {
            let start = next.fetch_add(1, Ordering::Relaxed) * piece;
            if start >= runs.len() || stop.load(Ordering::Relaxed) {
                return;
            }
            let part = &runs[start..(start + piece).min(runs.len())];
            if lanes {
                self.run_in_lanes(part, first + start, stop, sink);
            } else {
                sink(vec![(first + start, self.run(part[0]))]);
            }
        };
        rayon::scope(|s| {
            for _ in 1..threads {
                s.spawn(|_| work());
            }
            work();
        });
    }

    /// Run the runs `todo` on `pool` (made by [`pool`]) and write their rows with `writer`,
    /// in the order of `todo`, `chunk` rows at a time; the writer is handed back with how the
    /// sweep ended. The worker threads write the rows themselves ([`InOrder`]): whichever
    /// worker ends the run that the next row waits for writes the rows ready, so that a
    /// sweep on `n` threads uses `n` cores, writing included (a writer thread of its own took
    /// a fifth of a core beside a one-thread sweep, and kept two threads at 1.55x one). The
    /// runs end nearly in order ([`Sweep::run_many`]), so that a few pieces of rows wait in
    /// memory for their turn. This thread waits and polls `stop` (every [`POLL`]): once it
    /// is set no new run starts, the rows of every run ended so far are written (in the
    /// order of `todo`), and the result is [`Completion::Stopped`] at once; the runs still
    /// in progress are abandoned (their threads end after them, their rows are dropped), so
    /// that a stop is obeyed within a fraction of a second however long a run is. A write
    /// that fails stops the runs and is the error returned.
    pub fn execute<W: TableWriter + 'static>(
        self: &Arc<Self>,
        todo: Vec<u64>,
        pool: &rayon::ThreadPool,
        chunk: usize,
        stop: &Arc<AtomicBool>,
        writer: W,
    ) -> Result<(Completion, W)> {
        if let Some(k) = todo.iter().find(|k| !self.checked.contains(k)) {
            return Err(RouthError::Option {
                name: "run",
                value: k.to_string(),
                rule: "must lie within the runs the sweep was built for",
            }
            .into());
        }
        let order = Arc::new(Mutex::new(InOrder::new(writer, chunk)));
        // Set by this thread when `stop` is, and by a worker whose write failed.
        let halt = Arc::new(AtomicBool::new(false));
        let (running, ended) = channel::<()>();
        let (sweep, shared, flag) = (Arc::clone(self), Arc::clone(&order), Arc::clone(&halt));
        pool.spawn(move || {
            let sink = |done: Vec<(usize, Row)>| {
                let mut order = shared.lock().unwrap_or_else(|e| e.into_inner());
                if order.take(done).is_err() {
                    flag.store(true, Ordering::Relaxed);
                }
            };
            sweep.run_many(&todo, 0, &flag, &sink);
            // The runs are over: `ended` is disconnected.
            drop(running);
        });
        loop {
            let finished = matches!(
                ended.recv_timeout(POLL),
                Err(RecvTimeoutError::Disconnected)
            );
            let stopped = stop.load(Ordering::Relaxed);
            if stopped {
                halt.store(true, Ordering::Relaxed);
            }
            let mut order = order.lock().unwrap_or_else(|e| e.into_inner());
            if order.error.is_some() || stopped || finished {
                return order.close(stopped);
            }
        }
    }

    /// The rows of the runs `start <= run < stop`, in order, computed on a [`pool`] of
    /// `threads` threads (0: one per core); they must lie within the runs validated when the
    /// sweep was built ([`Sweep::for_runs`]).
    pub fn rows(&self, start: u64, stop: u64, threads: usize) -> Result<Vec<Row>> {
        if start > stop || start < self.checked.start || stop > self.checked.end {
            return Err(RouthError::Option {
                name: "start, stop",
                value: format!("{start}, {stop}"),
                rule: if self.checked == (0..self.runs()) {
                    "need 0 <= start <= stop <= the number of runs"
                } else {
                    "need start <= stop within the runs the sweep was built for"
                },
            }
            .into());
        }
        let pool = pool(threads)?;
        let todo: Vec<u64> = (start..stop).collect();
        let rows = Mutex::new(vec![None; todo.len()]);
        let sink = |done: Vec<(usize, Row)>| {
            let mut rows = rows.lock().unwrap_or_else(|e| e.into_inner());
            for (position, row) in done {
                rows[position] = Some(row);
            }
        };
        pool.install(|| self.run_many(&todo, 0, &AtomicBool::new(false), &sink));
        Ok(rows
            .into_inner()
            .unwrap_or_else(|e| e.into_inner())
            .into_iter()
            .flatten()
            .collect())
    }
}
