//! The step loop behind `simulate`: steps of the library's integrators, samples at given times
//! from the continuous extension, events located by Brent's method on it, optional projection
//! onto the level set of the integrals, the drift of the integrals, and a check for Ctrl-C
//! between steps.

use crate::stepper::Stepper;
use pyo3::PyResult;
use routh_core::integrals::{Integrals, INTEGRAL_NAMES};
use routh_core::integrate::{brent, Method, OdeSystem, Stats};
use routh_core::projection::LevelSet;
use routh_core::Body;
use std::collections::BTreeMap;
use std::time::Instant;

/// Steps between two checks for a pending Ctrl-C (a DOP853 step of (mg-eq) takes about a
/// microsecond, so the check runs about every 0.3 ms and costs nothing measurable).
pub const SIGNAL_CHECK_STEPS: usize = 256;

/// Most evaluations of Brent's method for one event.
const EVENT_ITERATIONS: usize = 200;

/// The integration settings of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// The integrator.
    pub method: Method,
    /// Relative tolerance of DOP853.
    pub rtol: f64,
    /// Absolute tolerance of DOP853.
    pub atol: f64,
    /// Project the reduced state onto the level set of the integrals through `x0` after every
    /// step and at every reported state.
    pub project: bool,
}

/// How an event is counted: SciPy's `terminal` (0: never stops, n: stops at the n-th
/// occurrence) and `direction` (> 0: only from negative to positive, < 0: the reverse,
/// 0: both).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EventRule {
    /// Occurrences after which the run stops (0: never).
    pub terminal: usize,
    /// The sign of the crossings that count (0: both).
    pub direction: f64,
}

/// How a run ended.
#[derive(Debug)]
pub enum Ending {
    /// The end of the time span was reached.
    Reached,
    /// A terminal event stopped it.
    Terminal,
    /// The integrator failed, with its message.
    Failed(String),
}

/// The drift of one integral: initial value, last value, largest relative change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drift {
    /// At the start.
    pub initial: f64,
    /// At the last step end or sample.
    pub last: f64,
    /// `max |H - H(t0)| / |H(t0)|` over step ends and samples (absolute when H(t0) = 0).
    pub max_rel_drift: f64,
}

/// What a run produced.
pub struct Run<const N: usize> {
    /// Times of the reported states.
    pub t: Vec<f64>,
    /// The reported states.
    pub y: Vec<[f64; N]>,
    /// Times of each event.
    pub t_events: Vec<Vec<f64>>,
    /// States at each event.
    pub y_events: Vec<Vec<[f64; N]>>,
    /// Step ends `(t, y)` from the start on (after projection), for the dense output; empty
    /// unless asked for.
    pub knots: Vec<(f64, [f64; N])>,
    /// Where the run stopped (the last knot, or the terminal event).
    pub t_last: f64,
    /// The state there.
    pub y_last: [f64; N],
    /// Work counters.
    pub stats: Stats,
    /// How it ended.
    pub ending: Ending,
    /// The drift of each integral the body has.
    pub drift: BTreeMap<&'static str, Drift>,
    /// Wall time of the loop in seconds.
    pub elapsed_s: f64,
}

/// Where states are reported: at the step ends (SciPy's default) or at given times.
pub enum Output<'a> {
    /// At the start and at every step end.
    Steps,
    /// At these times, strictly monotone in the direction of integration, within the span.
    Times(&'a [f64]),
}

/// An event function `g_i(t, y)`, called with the event's index.
pub type EventFunction<'h, const N: usize> =
    &'h mut dyn FnMut(usize, f64, &[f64; N]) -> PyResult<f64>;

/// The hooks of a run into Python: event functions and the Ctrl-C check. Their errors (an
/// exception in an event function, `KeyboardInterrupt`) end the run and are raised.
pub struct Hooks<'h, const N: usize> {
    /// `g_i(t, y)` of event `i`.
    pub event: EventFunction<'h, N>,
    /// The counting rule of each event.
    pub rules: &'h [EventRule],
    /// Called every [`SIGNAL_CHECK_STEPS`] steps.
    pub interrupt: &'h mut dyn FnMut() -> PyResult<()>,
}

struct DriftTracker {
    initial: [Option<f64>; 5],
    last: [Option<f64>; 5],
    max: [f64; 5],
}

impl DriftTracker {
    fn observe(&mut self, body: &Body, y: &[f64]) {
        let x: [f64; 6] = std::array::from_fn(|i| y[i]);
        self.last = Integrals::at(body, &x).values();
        for i in 0..5 {
            if let (Some(h0), Some(h)) = (self.initial[i], self.last[i]) {
                let scale = if h0 == 0.0 { 1.0 } else { h0.abs() };
                self.max[i] = self.max[i].max((h - h0).abs() / scale);
            }
        }
    }

    fn report(&self) -> BTreeMap<&'static str, Drift> {
        (0..5)
            .filter_map(|i| {
                Some((
                    INTEGRAL_NAMES[i],
                    Drift {
                        initial: self.initial[i]?,
                        last: self.last[i]?,
                        max_rel_drift: self.max[i],
                    },
                ))
            })
            .collect()
    }
}

/// The projection of the reduced part of a state onto the level set through `x0`, if asked.
pub struct Projector(Option<LevelSet>);

impl Projector {
    /// The level set through the reduced part of `x0` when `project`.
    pub fn new(body: &Body, x0: &[f64], project: bool) -> Self {
        let x: [f64; 6] = std::array::from_fn(|i| x0[i]);
        Projector(project.then(|| LevelSet::through(body, &x)))
    }

    /// `y` with its reduced part projected.
    pub fn apply<const N: usize>(&self, mut y: [f64; N]) -> [f64; N] {
        if let Some(level) = &self.0 {
            let mut x: [f64; 6] = std::array::from_fn(|i| y[i]);
            level.project(&mut x);
            y[..6].copy_from_slice(&x);
        }
        y
    }
}

/// A crossing of zero by `g` from `g0` to `g1` that counts under `direction`.
fn crosses(g0: f64, g1: f64, direction: f64) -> bool {
    let up = g0 < 0.0 && g1 >= 0.0;
    let down = g0 > 0.0 && g1 <= 0.0;
    (up && direction >= 0.0) || (down && direction <= 0.0)
}

/// Integrate `sys` from `(t0, y0)` to `t1` (either direction) with `settings`, reporting
/// states at `output`, locating the events of `hooks`. Fails only with the error of a hook;
/// a failure of the integrator is returned as [`Ending::Failed`] with what was computed.
#[allow(clippy::too_many_arguments)]
pub fn drive<S: OdeSystem<N>, const N: usize>(
    body: &Body,
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t1: f64,
    settings: &Settings,
    output: Output<'_>,
    keep_knots: bool,
    hooks: Hooks<'_, N>,
) -> PyResult<Run<N>> {
    let start = Instant::now();
    let dir = if t1 >= t0 { 1.0 } else { -1.0 };
    let projector = Projector::new(body, &y0, settings.project);
    let initial = {
        let x: [f64; 6] = std::array::from_fn(|i| y0[i]);
        Integrals::at(body, &x).values()
    };
    let mut drift = DriftTracker {
        initial,
        last: initial,
        max: [0.0; 5],
    };
    let n_events = hooks.rules.len();
    let mut run = Run {
        t: vec![],
        y: vec![],
        t_events: vec![vec![]; n_events],
        y_events: vec![vec![]; n_events],
        knots: vec![],
        t_last: t0,
        y_last: y0,
        stats: Stats::default(),
        ending: Ending::Reached,
        drift: BTreeMap::new(),
        elapsed_s: 0.0,
    };
    let times: &[f64] = match output {
        Output::Steps => {
            run.t.push(t0);
            run.y.push(y0);
            &[]
        }
        Output::Times(times) => times,
    };
    let steps_output = matches!(output, Output::Steps);
    let mut next = 0;
    while next < times.len() && times[next] == t0 {
        run.t.push(t0);
        run.y.push(y0);
        next += 1;
    }
    if keep_knots {
        run.knots.push((t0, y0));
    }
    let mut g_prev = (0..n_events)
        .map(|i| (hooks.event)(i, t0, &y0))
        .collect::<PyResult<Vec<f64>>>()?;
    let mut stepper = match Stepper::new(
        sys,
        settings.method,
        t0,
        y0,
        t1,
        settings.rtol,
        settings.atol,
        None,
    ) {
        Ok(s) => s,
        Err(e) => {
            run.ending = Ending::Failed(e.to_string());
            run.drift = drift.report();
            return Ok(run);
        }
    };
    let mut steps = 0usize;
    loop {
        let ta = stepper.t();
        if ta == t1 {
            break;
        }
        let done = match stepper.step() {
            Ok(done) => done,
            Err(e) => {
                run.ending = Ending::Failed(e.to_string());
                break;
            }
        };
        let tb = stepper.t();
        let y_raw = stepper.y();
        // Events on the unprojected step, in the order of time.
        let mut found: Vec<(f64, usize)> = vec![];
        for (i, (g0, rule)) in g_prev.iter_mut().zip(hooks.rules).enumerate() {
            let g1 = (hooks.event)(i, tb, &y_raw)?;
            if crosses(*g0, g1, rule.direction) {
                let te = if g1 == 0.0 {
                    tb
                } else {
                    let mut failure = None;
                    let scale = ta.abs().max(tb.abs()).max((tb - ta).abs());
                    let located = brent(
                        |s| {
                            let y = stepper.dense(s);
                            match (hooks.event)(i, s, &y) {
                                Ok(g) => g,
                                Err(e) => {
                                    failure.get_or_insert(e);
                                    f64::NAN
                                }
                            }
                        },
                        ta,
                        tb,
                        2.0 * f64::EPSILON * scale,
                        EVENT_ITERATIONS,
                    );
                    if let Some(e) = failure {
                        return Err(e);
                    }
                    match located {
                        Some(te) => te,
                        None => {
                            run.ending = Ending::Failed(format!(
                                "event {i} could not be located in [{ta}, {tb}] (its function \
                                 is not finite there)"
                            ));
                            break;
                        }
                    }
                };
                found.push((te, i));
            }
            *g0 = g1;
        }
        if matches!(run.ending, Ending::Failed(_)) {
            break;
        }
        found.sort_by(|a, b| ((a.0 - ta) * dir).total_cmp(&((b.0 - ta) * dir)));
        let mut stop = None;
        for (te, i) in found {
            let ye = projector.apply(if te == tb { y_raw } else { stepper.dense(te) });
            run.t_events[i].push(te);
            run.y_events[i].push(ye);
            let rule = hooks.rules[i];
            if rule.terminal > 0 && run.t_events[i].len() >= rule.terminal {
                stop = Some((te, ye));
                break;
            }
        }
        let y_end = projector.apply(y_raw);
        let t_until = stop.map_or(tb, |(te, _)| te);
        while next < times.len() && (times[next] - t_until) * dir <= 0.0 {
            let s = times[next];
            let y = if s == tb {
                y_end
            } else {
                projector.apply(stepper.dense(s))
            };
            drift.observe(body, &y);
            run.t.push(s);
            run.y.push(y);
            next += 1;
        }
        if let Some((te, ye)) = stop {
            if steps_output {
                run.t.push(te);
                run.y.push(ye);
            }
            drift.observe(body, &ye);
            (run.t_last, run.y_last) = (te, ye);
            if keep_knots {
                run.knots.push((tb, y_end));
            }
            run.ending = Ending::Terminal;
            break;
        }
        if settings.project {
            stepper.set_state(y_end);
            for (i, g) in g_prev.iter_mut().enumerate() {
                *g = (hooks.event)(i, tb, &y_end)?;
            }
        }
        drift.observe(body, &y_end);
        if steps_output {
            run.t.push(tb);
            run.y.push(y_end);
        }
        if keep_knots {
            run.knots.push((tb, y_end));
        }
        (run.t_last, run.y_last) = (tb, y_end);
        steps += 1;
        if steps % SIGNAL_CHECK_STEPS == 0 {
            (hooks.interrupt)()?;
        }
        if done {
            break;
        }
    }
    run.stats = stepper.stats();
    run.drift = drift.report();
    run.elapsed_s = start.elapsed().as_secs_f64();
    Ok(run)
}
