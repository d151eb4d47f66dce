//! Our side of the throughput benchmark (`bench/throughput/run.py` drives it).
//!
//! `batch_throughput MODE TOL T_END REPEAT < states`: reads initial states of the default
//! body (six numbers `gamma1 gamma2 gamma3 M1 M2 M3` a line) from stdin, integrates each to
//! `T_END` at rtol = atol = TOL on one thread, REPEAT times, and prints one JSON object: the
//! minimum wall time of the whole ensemble, the final states, and the summed steps and field
//! evaluations. MODE:
//! * `one`: one run after the other with [`Dop853`] (the sweep's `--no-batch` loop);
//! * `lanes4`, `lanes8`: the batched DOP853 of [`routh::batch`] with 4 or 8 lanes;
//! * `taylor`: one run after the other with [`Taylor`];
//! * `taylor4`, `taylor8`: the batched Taylor method of [`routh::batch::taylor`] with 4 or 8
//!   lanes (the instruction set, AVX-512 or AVX2, chosen at run time; `routh sweep` takes 8
//!   lanes with AVX-512 or AVX2, else 4);
//! * `vern9`: one run after the other with [`Vern9`] (for the reference at 1e-15).
//!
//! `batch_throughput states N`: prints the N initial states of the benchmark, one a line: the
//! default body with omega = (0.5, 0.2, 8) and gamma = (sin tilt, 0, cos tilt), the tilts
//! spread evenly over (0.05, 1.5) (ends excluded), M = I_Q omega (om-m).
//!
//! `cargo bench --bench batch_throughput` (no arguments): our loops on the 1024 runs to
//! t = 10 at 1e-12 and 1e-8, as a table (the peers need `bench/throughput/run.py`).
//!
//! Build with `cargo bench --bench batch_throughput --no-run`.

use routh::batch::{self, Job, Queue};
use routh::integrate::{
    Dop853, IntegrateError, Options, Outcome, Stats, Stepper, Stop, Taylor, Vern9,
};
use routh::simulate::ReducedSystem;
use routh::state::{Normalise, State};
use routh::Body;
use std::io::BufRead;
use std::time::Instant;

/// Collects the final states of the runs in the order of the jobs.
struct Finals {
    jobs: Vec<Job<6>>,
    next: usize,
    in_lane: Vec<usize>,
    finals: Vec<[f64; 6]>,
    stats: Stats,
    failure: Option<IntegrateError>,
}

impl Queue<6> for Finals {
    fn next(&mut self, lane: usize) -> Option<Job<6>> {
        let job = *self.jobs.get(self.next)?;
        self.in_lane[lane] = self.next;
        self.next += 1;
        Some(job)
    }

    fn step(&mut self, _lane: usize, _step: &dyn Stepper<6>) {}

    fn end(&mut self, lane: usize, end: Outcome<6>) {
        self.finals[self.in_lane[lane]] = end.y;
        self.stats.steps += end.stats.steps;
        self.stats.rhs_evals += end.stats.rhs_evals;
        if let Stop::Failed(e) = end.stop {
            self.failure = Some(e);
        }
    }
}

/// The batched DOP853 (`taylor = false`) or Taylor method in `L` lanes.
fn lanes<const L: usize>(
    taylor: bool,
    body: &Body,
    x0: &[[f64; 6]],
    t_end: f64,
    opts: &Options,
) -> Result<(Vec<[f64; 6]>, Stats), IntegrateError> {
    let mut queue = Finals {
        jobs: x0.iter().map(|&y0| Job { t0: 0.0, y0, t_end }).collect(),
        next: 0,
        in_lane: vec![0; L],
        finals: vec![[0.0; 6]; x0.len()],
        stats: Stats::default(),
        failure: None,
    };
    let sys = ReducedSystem(body);
    if taylor {
        batch::taylor::integrate_in::<_, _, 6, L>(&sys, opts, &mut queue)?;
    } else {
        batch::integrate::<_, _, 6, L>(&sys, opts, &mut queue);
    }
    match queue.failure {
        Some(e) => Err(e),
        None => Ok((queue.finals, queue.stats)),
    }
}

/// One run after the other with a stepper that has `new`, `step`, `y` and `stats`.
macro_rules! one_by_one {
    ($stepper:ident, $body:expr, $x0:expr, $t_end:expr, $opts:expr) => {
        (|| {
            let sys = ReducedSystem($body);
            let mut finals = Vec::with_capacity($x0.len());
            let mut total = Stats::default();
            for &y0 in $x0 {
                let mut s = $stepper::new(&sys, 0.0, y0, $t_end, $opts)?;
                while !s.step()? {}
                finals.push(*s.y());
                total.steps += s.stats().steps;
                total.rhs_evals += s.stats().rhs_evals;
            }
            Ok::<_, IntegrateError>((finals, total))
        })()
    };
}

/// The benchmark's initial states: see the module documentation.
fn states(n: usize) -> Vec<[f64; 6]> {
    (0..n)
        .map(|j| {
            let tilt = 0.05 + 1.45 * (j as f64 + 0.5) / n as f64;
            State::from_omega(
                &Body::default(),
                [tilt.sin(), 0.0, tilt.cos()],
                [0.5, 0.2, 8.0],
                Normalise::Reject,
            )
            .expect("a valid state")
            .to_array()
        })
        .collect()
}

type Ensemble = Result<(Vec<[f64; 6]>, Stats), IntegrateError>;

/// The minimum wall time of `repeat` integrations of the ensemble `x0` with `mode`, and the
/// result of the last; `None` for an unknown mode.
fn measure(
    mode: &str,
    tol: f64,
    t_end: f64,
    repeat: usize,
    x0: &[[f64; 6]],
) -> Option<(f64, Ensemble)> {
    let body = Body::default();
    let opts = Options::new(tol, tol).expect("a valid tolerance");
    let mut best = f64::INFINITY;
    let mut result = None;
    for _ in 0..repeat.max(1) {
        let start = Instant::now();
        let r = match mode {
            "one" => one_by_one!(Dop853, &body, x0, t_end, &opts),
            "vern9" => one_by_one!(Vern9, &body, x0, t_end, &opts),
            "taylor" => one_by_one!(Taylor, &body, x0, t_end, &opts),
            "lanes4" => lanes::<4>(false, &body, x0, t_end, &opts),
            "lanes8" => lanes::<8>(false, &body, x0, t_end, &opts),
            "taylor4" => lanes::<4>(true, &body, x0, t_end, &opts),
            "taylor8" => lanes::<8>(true, &body, x0, t_end, &opts),
            _ => return None,
        };
        best = best.min(start.elapsed().as_secs_f64());
        result = Some(r);
    }
    Some((best, result?))
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let usage =
        "usage: batch_throughput [MODE TOL T_END REPEAT < states | states N], MODE one of one, lanes4, lanes8, taylor, taylor4, taylor8, vern9";
    match &args[..] {
        [] => {
            // `cargo bench`: the table of BENCHMARKS.md for our loops, without the peers.
            let x0 = states(1024);
            for tol in [1e-12, 1e-8] {
                for mode in ["one", "lanes4", "lanes8", "taylor", "taylor4", "taylor8"] {
                    let (t, r) = measure(mode, tol, 10.0, 3, &x0).expect("a known mode");
                    let (_, stats) = r.expect("the benchmark runs succeed");
                    println!(
                        "tol {tol:.0e} {mode:7} {t:.3} s  {:.0} runs/s  {} steps  {} field evaluations",
                        x0.len() as f64 / t,
                        stats.steps,
                        stats.rhs_evals
                    );
                }
            }
        }
        [cmd, n] if cmd == "states" => {
            for x in states(n.parse().expect(usage)) {
                println!("{}", x.map(|v| format!("{v:?}")).join(" "));
            }
        }
        [mode, tol, t_end, repeat] => {
            let x0: Vec<[f64; 6]> = std::io::stdin()
                .lock()
                .lines()
                .map(|line| {
                    let v: Vec<f64> = line
                        .expect("stdin")
                        .split_whitespace()
                        .map(|w| w.parse().expect("a number"))
                        .collect();
                    v.try_into().expect("six numbers a line")
                })
                .collect();
            let (best, result) = measure(
                mode,
                tol.parse().expect(usage),
                t_end.parse().expect(usage),
                repeat.parse().expect(usage),
                &x0,
            )
            .expect(usage);
            let json = match result {
                Ok((finals, stats)) => serde_json::json!({
                    "time_s": best,
                    "runs": x0.len(),
                    "steps": stats.steps,
                    "rhs_evals": stats.rhs_evals,
                    "finals": finals,
                }),
                Err(e) => serde_json::json!({ "error": e.to_string() }),
            };
            println!("{json}");
        }
        _ => panic!("{usage}"),
    }
}
