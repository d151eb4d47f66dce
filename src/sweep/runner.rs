//! Running a sweep: the case of each run, one run as `routh simulate` does it plus the
//! nutation from events and from the quadrature, and many runs on a pool of threads,
//! handed to a writer chunk by chunk.

use super::design::Design;
use super::record::{NutationQuadrature, Row, RunSettings, Status};
use super::spec::{refuse, Quantity, Refusal, Spec};
use super::turning::TurningPoints;
use crate::case::Case;
use crate::error::{Result, RouthError};
use crate::integrate::Method;
use crate::quadrature::{ExactSolution, Motion};
use crate::simulate::{integrate_observed, ReducedSystem, Settings};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// A sweep ready to run: the base case, the design, the settings of every run.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// The case file's text (stored in the output's metadata).
    pub case_text: String,
    source: String,
    base: toml::Table,
    design: Design,
    /// The settings of every run.
    pub settings: Settings,
}

/// The settings given beside the case file (on the command line or in Python); those left
/// `None` come from the case's `[integration]` table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overrides {
    /// The integrator.
    pub method: Method,
    /// Final time.
    pub t_end: Option<f64>,
    /// Relative tolerance.
    pub rtol: Option<f64>,
    /// Absolute tolerance.
    pub atol: Option<f64>,
    /// The most steps of one run (`--max-steps`).
    pub max_steps: Option<usize>,
}

/// How [`Sweep::execute`] ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Completion {
    /// Every requested run was done.
    Finished,
    /// Stopped on request; the runs done so far were handed to the writer.
    Stopped,
}

/// Set `path` (`table.key` or `table.key[i]`) of a case document to `value`.
fn set(
    doc: &mut toml::Table,
    table: &str,
    key: &str,
    index: Option<usize>,
    value: f64,
) -> std::result::Result<(), String> {
    let t = doc
        .get_mut(table)
        .and_then(|t| t.as_table_mut())
        .ok_or_else(|| format!("the case has no [{table}] table"))?;
    match index {
        None => {
            t.insert(key.to_string(), value.into());
        }
        Some(i) => {
            let v = t
                .get_mut(key)
                .and_then(|v| v.as_array_mut())
                .filter(|a| a.len() == 3)
                .ok_or_else(|| format!("needs `{key} = [x, y, z]` in [{table}]"))?;
            v[i] = value.into();
        }
    }
    Ok(())
}

impl Sweep {
    /// A sweep of the case `text` (read from `source`), whose `[sweep]` table is checked, with
    /// every run's case built and validated before any run starts: a bad table or a value
    /// that makes a body or a state invalid is refused, naming the key and the value.
    pub fn new(text: &str, source: &str, overrides: Overrides) -> Result<Self> {
        let case = Case::parse(text, source)?;
        let settings = Settings {
            method: overrides.method,
            t_end: overrides.t_end.unwrap_or(case.integration.t_end),
            rtol: overrides.rtol.unwrap_or(case.integration.rtol),
            atol: overrides.atol.unwrap_or(case.integration.atol),
            project: false,
            samples: 0,
            max_steps: overrides.max_steps.unwrap_or(case.integration.max_steps),
        };
        crate::simulate::validate(&settings)?;
        let table: toml::Table = case.extra_table("sweep")?.ok_or_else(|| RouthError::Case {
            file: source.to_string(),
            message: "no [sweep] table: `routh sweep` needs one (see cases/sweep.toml)".into(),
        })?;
        let refused = |e: Refusal| RouthError::Case {
            file: source.to_string(),
            message: e.to_string(),
        };
        let design = Spec::parse(&table).and_then(Design::new).map_err(refused)?;
        let mut base = case.document;
        base.remove("sweep");
        let sweep = Sweep {
            case_text: text.to_string(),
            source: source.to_string(),
            base,
            design,
            settings,
        };
        (0..sweep.runs())
            .into_par_iter()
            .try_for_each(|k| sweep.case_of(k).map(|_| ()))
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

    /// The settings as written in each row.
    pub fn run_settings(&self) -> RunSettings {
        RunSettings {
            t_end: self.settings.t_end,
            rtol: self.settings.rtol,
            atol: self.settings.atol,
            method: self.settings.method.to_string(),
        }
    }

    /// The case document of run `k`: the base case with the swept values put in.
    pub fn document_of(&self, k: u64) -> std::result::Result<toml::Table, Refusal> {
        let values = self.design.point(k);
        let mut doc = self.base.clone();
        for (axis, &v) in self.design.spec().axes.iter().zip(&values) {
            let done = match axis.quantity {
                Quantity::Body(key) => set(&mut doc, "body", key, None, v),
                Quantity::Tilt => set(&mut doc, "initial", "gamma", Some(0), v.sin())
                    .and_then(|_| set(&mut doc, "initial", "gamma", Some(1), 0.0))
                    .and_then(|_| set(&mut doc, "initial", "gamma", Some(2), v.cos())),
                Quantity::Spin => set(&mut doc, "initial", "omega", Some(2), v),
                Quantity::Omega(i) => set(&mut doc, "initial", "omega", Some(i), v),
                Quantity::Gamma(i) => set(&mut doc, "initial", "gamma", Some(i), v),
            };
            done.map_err(|rule| refuse(&axis.name, v, &rule))?;
        }
        Ok(doc)
    }

    /// The validated case of run `k`; an invalid one is refused naming the swept values.
    pub fn case_of(&self, k: u64) -> std::result::Result<Case, Refusal> {
        let doc = self.document_of(k)?;
        Case::from_document(doc, &self.source).map_err(|e| {
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
        })
    }

    /// Run number `k`: the integration of `routh simulate` on the run's case (the same
    /// numbers, bit for bit), the turning points along it, and the quadrature when the body
    /// is a Routh sphere. A failure (or a panic) becomes a row with status `failed`.
    pub fn run(&self, k: u64) -> Row {
        let values = self.design.point(k);
        let failed = |message: String| Row {
            run: k,
            values: values.clone(),
            status: Status::Failed,
            message,
            summary: None,
            events: None,
            quadrature: None,
        };
        let attempt = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let case = self.case_of(k).map_err(|e| RouthError::Case {
                file: self.source.clone(),
                message: e.to_string(),
            })?;
            let x0 = case.initial.to_array();
            let body = case.body("routh sweep")?;
            let mut turning = TurningPoints::new(&body, &x0);
            let observed = integrate_observed(
                &body,
                &ReducedSystem(&body),
                x0,
                &self.settings,
                None,
                &mut |_, _| Ok(()),
                &mut |step| turning.observe(step),
            )?;
            let summary = match observed.failure {
                Some(e) => return Err(e.into()),
                None => observed.summary,
            };
            let (quadrature, message) = if body.is_symmetric() {
                match ExactSolution::new(&body, &case.initial) {
                    Ok(exact) => {
                        let precession = match &exact.motion {
                            Motion::Nutation(n) => Some(n.advance),
                            Motion::Steady { .. } => None,
                        };
                        (
                            Some(NutationQuadrature {
                                period: exact.period(),
                                precession,
                            }),
                            String::new(),
                        )
                    }
                    Err(e) => (None, format!("no quadrature: {e}")),
                }
            } else {
                (
                    None,
                    "no quadrature: the body is not a Routh sphere (I1 != I2)".into(),
                )
            };
            Ok::<_, RouthError>(Row {
                run: k,
                values: values.clone(),
                status: Status::Ok,
                message,
                summary: Some(summary),
                events: Some(turning.summary()),
                quadrature,
            })
        }));
        match attempt {
            Ok(Ok(row)) => row,
            Ok(Err(e)) => failed(e.to_string()),
            Err(panic) => failed(format!(
                "internal error (panic): {}",
                panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default()
            )),
        }
    }

    /// Run the runs `todo` (in chunks of `chunk` runs, each chunk's runs in parallel on the
    /// current rayon pool), handing each chunk's rows, in the order of `todo`, to `write`.
    /// Between runs `stop` is polled: once it is set no new run starts, the rows done are
    /// written, and the result is [`Completion::Stopped`].
    pub fn execute(
        &self,
        todo: &[u64],
        chunk: usize,
        stop: &AtomicBool,
        write: &mut dyn FnMut(&[Row]) -> Result<()>,
    ) -> Result<Completion> {
        for part in todo.chunks(chunk.max(1)) {
            let rows: Vec<Row> = part
                .par_iter()
                .filter_map(|&k| (!stop.load(Ordering::Relaxed)).then(|| self.run(k)))
                .collect();
            if !rows.is_empty() {
                write(&rows)?;
            }
            if stop.load(Ordering::Relaxed) {
                return Ok(Completion::Stopped);
            }
        }
        Ok(Completion::Finished)
    }

    /// The rows of the runs `start <= run < stop`, in order, computed on a pool of `threads`
    /// threads (0: one per core).
    pub fn rows(&self, start: u64, stop: u64, threads: usize) -> Result<Vec<Row>> {
        if start > stop || stop > self.runs() {
            return Err(RouthError::Option {
                name: "start, stop",
                value: format!("{start}, {stop}"),
                rule: "need 0 <= start <= stop <= the number of runs",
            });
        }
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| RouthError::Option {
                name: "threads",
                value: format!("{threads} ({e})"),
                rule: "the thread pool must start",
            })?;
        let todo: Vec<u64> = (start..stop).collect();
        Ok(pool.install(|| todo.par_iter().map(|&k| self.run(k)).collect()))
    }
}
