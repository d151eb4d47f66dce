//! The batched DOP853 and Taylor method ([`routh::batch`], [`routh::batch::taylor`]) against
//! the one-at-a-time DOP853 and Taylor method ([`routh::integrate::Dop853`],
//! [`routh::integrate::Taylor`] through [`routh::integrate::drive`]): each lane is bitwise
//! the one-at-a-time integration (the same operations in the same order), so the tolerance
//! of every comparison here is zero: equal bits of every step end, of the dense output in the
//! middle of every step, of the final state, and equal counters.

use routh::batch::{self, Job, LaneEnd, Queue, LANES};
use routh::integrate::taylor::tape::Isa;
use routh::integrate::{
    drive, Control, Dop853, Drive, IntegrateError, Method, Options, Stats, Stepper, Taylor,
};
use routh::simulate::ReducedSystem;
use routh::state::{Normalise, State};
use routh::Body;

/// What is recorded of a run: per accepted step its end time, its state and the dense output
/// in its middle; then the end.
#[derive(Debug, Clone, PartialEq)]
struct Record {
    steps: Vec<(f64, [f64; 6], [f64; 6])>,
    end: Option<(f64, [f64; 6], Stats, Option<IntegrateError>)>,
}

fn look(step: &dyn Stepper<6>) -> (f64, [f64; 6], [f64; 6]) {
    let mid = 0.5 * (step.t_prev() + step.t());
    (step.t(), *step.y(), step.dense(mid))
}

/// A queue of jobs that records every run by its job number.
struct Recorder {
    jobs: Vec<Job<6>>,
    next: usize,
    in_lane: [Option<usize>; LANES],
    records: Vec<Record>,
}

impl Recorder {
    fn new(jobs: Vec<Job<6>>) -> Self {
        let records = vec![
            Record {
                steps: Vec::new(),
                end: None
            };
            jobs.len()
        ];
        Recorder {
            jobs,
            next: 0,
            in_lane: [None; LANES],
            records,
        }
    }
}

impl Queue<6> for Recorder {
    fn next(&mut self, lane: usize) -> Option<Job<6>> {
        let job = *self.jobs.get(self.next)?;
        self.in_lane[lane] = Some(self.next);
        self.next += 1;
        Some(job)
    }

    fn step(&mut self, lane: usize, step: &dyn Stepper<6>) {
        let j = self.in_lane[lane].unwrap();
        self.records[j].steps.push(look(step));
    }

    fn end(&mut self, lane: usize, end: LaneEnd<6>) {
        let j = self.in_lane[lane].take().unwrap();
        self.records[j].end = Some((end.t, end.y, end.stats, end.failure));
    }
}

/// The runs of `queue` in lanes of `method` (DOP853 or Taylor), as `routh sweep` runs them.
fn integrate(
    method: Method,
    body: &Body,
    opts: &Options,
    queue: &mut Recorder,
) -> Result<(), IntegrateError> {
    integrate_on(Isa::detect(), method, body, opts, queue)
}

/// The runs of `queue` in lanes of `method` (`LANES` for DOP853, those of
/// [`batch::taylor::lanes`] for Taylor: 8 with AVX-512, else 4), the loop of the lanes
/// compiled for `isa`.
fn integrate_on(
    isa: Isa,
    method: Method,
    body: &Body,
    opts: &Options,
    queue: &mut Recorder,
) -> Result<(), IntegrateError> {
    let sys = ReducedSystem(body);
    match method {
        Method::Dop853 => batch::integrate_on::<_, _, 6, LANES>(isa, &sys, opts, queue),
        Method::Taylor if batch::taylor::lanes() == 8 => {
            batch::taylor::integrate_in_on::<_, _, 6, 8>(isa, &sys, opts, queue)
        }
        Method::Taylor => batch::taylor::integrate_in_on::<_, _, 6, 4>(isa, &sys, opts, queue),
        other => panic!("no lanes for {other}"),
    }
}

/// The runs in lanes.
fn in_lanes(method: Method, body: &Body, jobs: &[Job<6>], opts: &Options) -> Vec<Record> {
    let mut queue = Recorder::new(jobs.to_vec());
    integrate(method, body, opts, &mut queue).unwrap();
    assert!(
        queue.in_lane.iter().all(Option::is_none),
        "a lane never ended"
    );
    queue.records
}

/// The same run one at a time, recorded the same way.
fn one_at_a_time(method: Method, body: &Body, job: &Job<6>, opts: &Options) -> Record {
    let sys = ReducedSystem(body);
    let mut record = Record {
        steps: Vec::new(),
        end: None,
    };
    let stepper: Result<Box<dyn Stepper<6>>, _> = match method {
        Method::Dop853 => {
            Dop853::new(&sys, job.t0, job.y0, job.t_end, opts).map(|s| Box::new(s) as _)
        }
        Method::Taylor => {
            Taylor::new(&sys, job.t0, job.y0, job.t_end, opts).map(|s| Box::new(s) as _)
        }
        other => panic!("no lanes for {other}"),
    };
    let mut stepper = match stepper {
        Ok(s) => s,
        Err(e) => {
            record.end = Some((job.t0, job.y0, Stats::default(), Some(e)));
            return record;
        }
    };
    let outcome = drive(
        stepper.as_mut(),
        &Drive::default(),
        &mut |_, _| Ok::<_, IntegrateError>(()),
        &mut |_, _, s| {
            // `drive` shows a zero-length span (t_end = t0) as one step that made no step;
            // the batch ends such a run at once.
            if s.stats().steps > 0 {
                record.steps.push(look(s));
            }
            Ok(Control::Continue)
        },
    );
    let failure = outcome.err();
    record.end = Some((stepper.t(), *stepper.y(), stepper.stats(), failure));
    record
}

/// The default body's default initial spin, omega = (0.5, 0.2, 8), at tilt `tilt`.
fn tilted(body: &Body, tilt: f64) -> [f64; 6] {
    State::from_omega(
        body,
        [tilt.sin(), 0.0, tilt.cos()],
        [0.5, 0.2, 8.0],
        Normalise::Reject,
    )
    .unwrap()
    .to_array()
}

/// `n` tilts spread over (0.05, 1.5), ends excluded.
fn tilts(n: usize) -> Vec<f64> {
    (0..n)
        .map(|j| 0.05 + 1.45 * (j as f64 + 0.5) / n as f64)
        .collect()
}

/// `n` runs of `body` from t = 0 to `t_end`, tilts spread over (0.05, 1.5).
fn runs(body: &Body, n: usize, t_end: f64) -> Vec<Job<6>> {
    tilts(n)
        .into_iter()
        .map(|tilt| Job {
            t0: 0.0,
            y0: tilted(body, tilt),
            t_end,
        })
        .collect()
}

fn options(tol: f64) -> Options {
    Options {
        rtol: tol,
        atol: tol,
        ..Options::default()
    }
}

/// Bitwise equality of two records (f64 `==` would let -0.0 pass for 0.0 and fail on NaN).
fn same_bits(a: &Record, b: &Record) -> bool {
    let bits = |x: &[f64; 6]| x.map(f64::to_bits);
    a.steps.len() == b.steps.len()
        && a.steps.iter().zip(&b.steps).all(|(p, q)| {
            p.0.to_bits() == q.0.to_bits() && bits(&p.1) == bits(&q.1) && bits(&p.2) == bits(&q.2)
        })
        && match (&a.end, &b.end) {
            (Some(e), Some(f)) => {
                e.0.to_bits() == f.0.to_bits()
                    && bits(&e.1) == bits(&f.1)
                    && e.2 == f.2
                    && e.3 == f.3
            }
            _ => false,
        }
}

/// 1024 runs of the default body, tilts in (0.05, 1.5), to t = 10 at rtol = atol = 1e-12,
/// in lanes of `method`: every lane is bitwise the one-at-a-time run (every step end, the
/// dense output in every step, the final state, the counters). Tolerance zero, because the
/// lanes do the same floating-point operations in the same order. Negative control: the
/// one-at-a-time runs without compensated summation (one rounding per step moved) differ in
/// the last bits for most runs (more than `min_differ`), so the comparison sees a single
/// rounding.
fn lanes_are_bitwise_the_one_at_a_time_run_on_1024_runs(method: Method, min_differ: usize) {
    let body = Body::default();
    let opts = options(1e-12);
    let jobs = runs(&body, 1024, 10.0);
    let lanes = in_lanes(method, &body, &jobs, &opts);
    let plain = Options {
        compensated: false,
        ..opts
    };
    let mut differ = 0;
    for (j, (job, record)) in jobs.iter().zip(&lanes).enumerate() {
        let alone = one_at_a_time(method, &body, job, &opts);
        assert!(alone.end.as_ref().unwrap().3.is_none(), "run {j} failed");
        assert!(
            same_bits(record, &alone),
            "run {j}: lanes differ from one at a time"
        );
        if !same_bits(record, &one_at_a_time(method, &body, job, &plain)) {
            differ += 1;
        }
    }
    assert!(
        differ > min_differ,
        "negative control: only {differ} of 1024 runs differ"
    );
}

#[test]
fn lanes_are_bitwise_the_one_at_a_time_dop853_on_1024_runs() {
    lanes_are_bitwise_the_one_at_a_time_run_on_1024_runs(Method::Dop853, 900);
}

/// The Taylor lanes (4 or 8, as this CPU has AVX2 or AVX-512): bitwise the one-at-a-time
/// [`Taylor`] run, the same orders and steps; its compensated update moves fewer roundings
/// than DOP853's (fewer, longer steps), hence the lower bound of the control.
#[test]
fn lanes_are_bitwise_the_one_at_a_time_taylor_on_1024_runs() {
    lanes_are_bitwise_the_one_at_a_time_run_on_1024_runs(Method::Taylor, 500);
}

/// The loop of the lanes compiled for each instruction set this CPU has (the baseline, AVX2
/// with FMA, AVX-512: `Runs::integrate`): every lane is bitwise its one-at-a-time run in
/// each (64 runs to t = 10 at 1e-12; tolerance zero, as above: the sets differ in the width
/// of the registers, not in the operations). The negative control is
/// `the_comparison_sees_a_different_run`.
#[test]
fn lanes_are_bitwise_the_one_at_a_time_runs_under_every_instruction_set() {
    let body = Body::default();
    let opts = options(1e-12);
    let jobs = runs(&body, 64, 10.0);
    let sets = [Isa::Baseline, Isa::Avx2Fma, Isa::Avx512];
    for method in [Method::Dop853, Method::Taylor] {
        let alone: Vec<Record> = jobs
            .iter()
            .map(|job| one_at_a_time(method, &body, job, &opts))
            .collect();
        for isa in sets.into_iter().filter(|isa| isa.available()) {
            let mut queue = Recorder::new(jobs.clone());
            integrate_on(isa, method, &body, &opts, &mut queue).unwrap();
            for (j, (record, alone)) in queue.records.iter().zip(&alone).enumerate() {
                assert!(same_bits(record, alone), "{method} under {isa:?}: run {j}");
            }
        }
    }
}

/// Lanes of different orders side by side: with `rtol = atol / 3` a lane's order is that of
/// `atol` while its state's norm is at most 3 and that of `rtol` above (`step_tolerance`),
/// and runs of spin 2 and 8 alternate in the queue, so that busy lanes of both orders step
/// together (the Horner sums then choose per lane). Every run is bitwise its one-at-a-time
/// [`Taylor`] run (tolerance zero, as above). The control: runs of both orders occur (the
/// mean order per step, field evaluations over steps, spans a whole order).
#[test]
fn taylor_lanes_of_different_orders_are_bitwise_the_one_at_a_time_runs() {
    let body = Body::default();
    let opts = Options {
        rtol: 1e-10 / 3.0,
        atol: 1e-10,
        ..Options::default()
    };
    let jobs: Vec<Job<6>> = tilts(64)
        .into_iter()
        .enumerate()
        .map(|(j, tilt)| {
            let spin = if j % 2 == 0 { 2.0 } else { 8.0 };
            let y0 = State::from_omega(
                &body,
                [tilt.sin(), 0.0, tilt.cos()],
                [0.5, 0.2, spin],
                Normalise::Reject,
            )
            .unwrap()
            .to_array();
            Job {
                t0: 0.0,
                y0,
                t_end: 5.0,
            }
        })
        .collect();
    let lanes = in_lanes(Method::Taylor, &body, &jobs, &opts);
    let mut orders = std::collections::BTreeSet::new();
    for (j, (job, record)) in jobs.iter().zip(&lanes).enumerate() {
        let alone = one_at_a_time(Method::Taylor, &body, job, &opts);
        let (_, _, stats, failure) = alone.end.as_ref().unwrap();
        assert!(failure.is_none(), "run {j} failed");
        assert!(
            same_bits(record, &alone),
            "run {j}: lanes differ from one at a time"
        );
        orders.insert(stats.rhs_evals * 1000 / stats.steps);
    }
    // Runs entirely of one order and entirely of the next start side by side in the first
    // lanes (the queue alternates them).
    let (low, high) = (orders.first().unwrap(), orders.last().unwrap());
    assert!(
        high - low >= 1000,
        "control: not two orders apart, {orders:?}"
    );
}

/// Each lane keeps its own end time and direction: runs to different ends, forward and
/// backward, with one that has nothing to do (t_end = t0), mixed in one batch, are each
/// bitwise their one-at-a-time run.
#[test]
fn each_lane_keeps_its_own_end_time() {
    for method in [Method::Dop853, Method::Taylor] {
        each_lane_keeps_its_own_end_time_with(method);
    }
}

fn each_lane_keeps_its_own_end_time_with(method: Method) {
    let body = Body::default();
    let opts = options(1e-10);
    let jobs: Vec<Job<6>> = tilts(37)
        .into_iter()
        .enumerate()
        .map(|(j, tilt)| Job {
            t0: 0.25 * (j % 3) as f64,
            y0: tilted(&body, tilt),
            t_end: match j % 5 {
                0 => -3.0,
                1 => 0.25 * (j % 3) as f64,
                _ => 0.5 + j as f64 * 0.3,
            },
        })
        .collect();
    let lanes = in_lanes(method, &body, &jobs, &opts);
    for (j, (job, record)) in jobs.iter().zip(lanes).enumerate() {
        assert!(
            same_bits(&record, &one_at_a_time(method, &body, job, &opts)),
            "{method} run {j}"
        );
    }
}

/// A lane that fails does not disturb the others: in a batch of 64 runs, one runs far past
/// the others and hits max_steps, one starts from a NaN state, one from an infinite time;
/// each failure is the one-at-a-time integrator's (the same error, time and counters), and
/// every other run is bitwise its one-at-a-time run and the run of a batch without the
/// failing ones.
#[test]
fn a_failing_lane_does_not_disturb_the_others() {
    for method in [Method::Dop853, Method::Taylor] {
        a_failing_lane_does_not_disturb_the_others_with(method);
    }
}

fn a_failing_lane_does_not_disturb_the_others_with(method: Method) {
    let body = Body::default();
    let opts = Options {
        max_steps: 400,
        ..options(1e-10)
    };
    let good = runs(&body, 61, 5.0);
    let mut jobs = good.clone();
    jobs.insert(
        3,
        Job {
            t_end: 1000.0,
            ..good[3]
        },
    );
    jobs.insert(
        10,
        Job {
            y0: [f64::NAN; 6],
            ..good[0]
        },
    );
    jobs.insert(
        20,
        Job {
            t_end: f64::INFINITY,
            ..good[0]
        },
    );
    let mixed = in_lanes(method, &body, &jobs, &opts);
    let clean = in_lanes(method, &body, &good, &opts);
    for (slot, kind) in [(3, "max_steps"), (10, "NaN"), (20, "infinite t_end")] {
        let failure = mixed[slot].end.as_ref().unwrap().3.clone();
        assert!(failure.is_some(), "{kind}: should fail");
        assert_eq!(
            failure,
            one_at_a_time(method, &body, &jobs[slot], &opts)
                .end
                .unwrap()
                .3,
            "{method} {kind}"
        );
    }
    assert!(matches!(
        mixed[3].end.as_ref().unwrap().3,
        Some(IntegrateError::TooManySteps { max_steps: 400, .. })
    ));
    let survivors: Vec<&Record> = mixed
        .iter()
        .enumerate()
        .filter(|(slot, _)| ![3, 10, 20].contains(slot))
        .map(|(_, r)| r)
        .collect();
    assert_eq!(survivors.len(), good.len());
    for (j, (record, job)) in survivors.iter().zip(&good).enumerate() {
        assert!(record.end.as_ref().unwrap().3.is_none(), "run {j} failed");
        assert!(same_bits(record, &clean[j]), "{method} run {j} disturbed");
        assert!(
            same_bits(record, &one_at_a_time(method, &body, job, &opts)),
            "{method} run {j}"
        );
    }
}

/// Negative control of the harness: a lane is compared with the one-at-a-time run of its
/// neighbour's tilt, and with its own run at another tolerance; both must be seen to differ.
/// For the Taylor lanes also: a lane fed another state (its neighbour's, perturbed in the
/// last bit of M3) differs from its own one-at-a-time run.
#[test]
fn the_comparison_sees_a_different_run() {
    let body = Body::default();
    let opts = options(1e-12);
    let jobs = runs(&body, 16, 10.0);
    for method in [Method::Dop853, Method::Taylor] {
        let lanes = in_lanes(method, &body, &jobs, &opts);
        for j in 0..15 {
            assert!(!same_bits(
                &lanes[j],
                &one_at_a_time(method, &body, &jobs[j + 1], &opts)
            ));
            assert!(!same_bits(
                &lanes[j],
                &one_at_a_time(method, &body, &jobs[j], &options(1e-11))
            ));
        }
    }
    let mut fed: Vec<Job<6>> = jobs.clone();
    fed[5].y0[5] = f64::from_bits(fed[5].y0[5].to_bits() + 1);
    let lanes = in_lanes(Method::Taylor, &body, &fed, &opts);
    assert!(!same_bits(
        &lanes[5],
        &one_at_a_time(Method::Taylor, &body, &jobs[5], &opts)
    ));
    assert!(same_bits(
        &lanes[6],
        &one_at_a_time(Method::Taylor, &body, &jobs[6], &opts)
    ));
}

/// Invalid options are refused before any run starts, as by the one-at-a-time integrator.
#[test]
fn invalid_options_are_refused_before_any_run() {
    let body = Body::default();
    let mut queue = Recorder::new(vec![Job {
        t0: 0.0,
        y0: tilted(&body, 0.3),
        t_end: 1.0,
    }]);
    let bad = options(-1e-10);
    for method in [Method::Dop853, Method::Taylor] {
        let err = integrate(method, &body, &bad, &mut queue);
        assert!(matches!(
            err,
            Err(IntegrateError::InvalidOption { name: "rtol", .. })
        ));
        assert_eq!(queue.next, 0, "no run should have started");
    }
}
