//! DOP853 in lanes: Hairer's `dop853.f` step (the stages of [`crate::integrate::tableau`],
//! the 5th/3rd-order error estimate, the step-size controller) applied to `L` runs at once,
//! each lane with its own time, step size, rejections and end time, refilled from a
//! [`Queue`] as soon as its run ends.
//!
//! Every operation of a lane is the operation of [`crate::integrate::Dop853`] on that run,
//! in the same order: the stages and the error norm run on [`Lanes`] (element-wise `f64`
//! arithmetic), the controller and the compensated update run lane by lane in `f64`. A lane
//! is bitwise the one-at-a-time integrator (see the module [`crate::batch`]).

use std::cell::Cell;

use super::lanes::{lane_of, set_lane};
use super::{Field, Lanes};
use crate::integrate::compensated::compensated_add;
use crate::integrate::tableau::{dense_at, dense_rows, A, B, BHH, ER};
use crate::integrate::{hinit, IntegrateError, OdeSystem, Options, Stats, Stepper};
use crate::scalar::Scalar;

/// The default number of lanes: two AVX2 registers (four SSE2 registers) of doubles, which
/// keeps two independent chains of vector operations in flight (BENCHMARKS.md).
pub const LANES: usize = 8;

/// Hairer's constants of `dop853.f`, the values of [`crate::integrate::Dop853`]: the
/// rounding unit of the step-too-small test.
const UROUND: f64 = 2.3e-16;
/// Safety factor of the step-size prediction.
const SAFE: f64 = 0.9;
/// Lower bound of `h_new / h`.
const FAC1: f64 = 0.333;
/// Upper bound of `h_new / h`.
const FAC2: f64 = 6.0;
/// Exponent `1/8` of the controller (no Lund stabilisation).
const EXPO1: f64 = 1.0 / 8.0;

/// The stages of a step: 0..=11, the derivative at the step end (12), the three stages of
/// the dense output (13..=15).
type Stages<T, const N: usize> = [[T; N]; 16];

/// One run: integrate from `(t0, y0)` to `t_end`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Job<const N: usize> {
    /// Start time.
    pub t0: f64,
    /// Initial state.
    pub y0: [f64; N],
    /// End time (before `t0` integrates backward; equal to `t0` ends at once with no step).
    pub t_end: f64,
}

/// How a run ended: the time and state reached, the counters, and the failure if any (then
/// `t` and `y` are the last accepted step's).
#[derive(Debug, Clone, PartialEq)]
pub struct LaneEnd<const N: usize> {
    /// Time reached (`t_end` unless it failed).
    pub t: f64,
    /// State reached.
    pub y: [f64; N],
    /// Work counters, with the field evaluations of the dense output asked for by
    /// [`Queue::step`], as [`crate::integrate::Dop853`] counts them.
    pub stats: Stats,
    /// Why the run stopped early, as the one-at-a-time integrator reports it.
    pub failure: Option<IntegrateError>,
}

impl<const N: usize> LaneEnd<N> {
    /// The end of the run in lane `l` of the states `y`, at `t` with the counters `stats`.
    pub(super) fn of<const L: usize>(
        t: f64,
        y: &[Lanes<L>; N],
        l: usize,
        stats: Stats,
        failure: Option<IntegrateError>,
    ) -> Self {
        LaneEnd {
            t,
            y: lane_of(y, l),
            stats,
            failure,
        }
    }
}

/// The runs of a batch and what happens to each: the batch asks for a run whenever a lane is
/// free, shows each accepted step, and hands back the end.
pub trait Queue<const N: usize> {
    /// The next run, for lane `lane`; `None` when there is none left (then it is not asked
    /// again).
    fn next(&mut self, lane: usize) -> Option<Job<N>>;
    /// The run in `lane` made an accepted step; `step` shows it (its time, state and dense
    /// output, as [`crate::integrate::drive`] shows a step to its observer).
    fn step(&mut self, lane: usize, step: &dyn Stepper<N>);
    /// The run in `lane` ended; the lane takes the next run.
    fn end(&mut self, lane: usize, end: LaneEnd<N>);
}

/// `y + h * sum_j A[ROW][j] * k[j]` over the listed `cols`, summed left to right (the order of
/// [`crate::integrate::Dop853`]).
#[inline(always)]
fn combine<T: Scalar, const ROW: usize, const M: usize, const N: usize>(
    y: &[T; N],
    h: T,
    k: &Stages<T, N>,
    cols: [usize; M],
) -> [T; N] {
    std::array::from_fn(|i| {
        let mut acc = k[cols[0]][i] * A[ROW][cols[0]];
        for &j in &cols[1..] {
            acc = acc + k[j][i] * A[ROW][j];
        }
        y[i] + h * acc
    })
}

/// Stages 1..=11 of a step of size `h` from `y`, with `k[0] = f(y)` given (11 evaluations);
/// returns the increment `sum_i b_i k_i`.
#[inline(always)]
fn stages<F: Field<N>, T: Scalar, const N: usize>(
    field: &F,
    h: T,
    y: &[T; N],
    k: &mut Stages<T, N>,
) -> [T; N] {
    let h10 = h * A[1][0];
    k[1] = field.eval(&std::array::from_fn(|i| y[i] + h10 * k[0][i]));
    k[2] = field.eval(&combine::<T, 2, 2, N>(y, h, k, [0, 1]));
    k[3] = field.eval(&combine::<T, 3, 2, N>(y, h, k, [0, 2]));
    k[4] = field.eval(&combine::<T, 4, 3, N>(y, h, k, [0, 2, 3]));
    k[5] = field.eval(&combine::<T, 5, 3, N>(y, h, k, [0, 3, 4]));
    k[6] = field.eval(&combine::<T, 6, 4, N>(y, h, k, [0, 3, 4, 5]));
    k[7] = field.eval(&combine::<T, 7, 5, N>(y, h, k, [0, 3, 4, 5, 6]));
    k[8] = field.eval(&combine::<T, 8, 6, N>(y, h, k, [0, 3, 4, 5, 6, 7]));
    k[9] = field.eval(&combine::<T, 9, 7, N>(y, h, k, [0, 3, 4, 5, 6, 7, 8]));
    k[10] = field.eval(&combine::<T, 10, 8, N>(y, h, k, [0, 3, 4, 5, 6, 7, 8, 9]));
    k[11] = field.eval(&combine::<T, 11, 9, N>(
        y,
        h,
        k,
        [0, 3, 4, 5, 6, 7, 8, 9, 10],
    ));
    std::array::from_fn(|i| {
        k[0][i] * B[0]
            + k[5][i] * B[5]
            + k[6][i] * B[6]
            + k[7][i] * B[7]
            + k[8][i] * B[8]
            + k[9][i] * B[9]
            + k[10][i] * B[10]
            + k[11][i] * B[11]
    })
}

/// The field on one lane in `f64`, as an [`OdeSystem`] (for [`hinit`]).
struct OneLane<'f, F>(&'f F);

impl<F: Field<N>, const N: usize> OdeSystem<N> for OneLane<'_, F> {
    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; N]) -> [f64; N] {
        self.0.eval(y)
    }
}

/// The bookkeeping of one lane, in `f64`.
#[derive(Debug, Clone, Copy, Default)]
struct Lane {
    /// A run occupies the lane.
    busy: bool,
    t: f64,
    t_prev: f64,
    t_end: f64,
    posneg: f64,
    hmax: f64,
    /// The proposed (or, after a rejection, the reduced) step size.
    h: f64,
    /// The size of the step being attempted (the proposal cut to land on `t_end`).
    h_try: f64,
    /// The attempt lands on `t_end`.
    last: bool,
    reject: bool,
    stats: Stats,
}

/// The lanes' states and stages (structure of arrays) and their bookkeeping.
struct Batch<'f, F, const N: usize, const L: usize> {
    field: &'f F,
    opts: Options,
    y: [Lanes<L>; N],
    carry: [Lanes<L>; N],
    /// `f(y)`, the first stage of the next step.
    f: [Lanes<L>; N],
    y_prev: [Lanes<L>; N],
    k: Stages<Lanes<L>, N>,
    lanes: [Lane; L],
    /// The queue has no run left.
    drained: bool,
}

/// Integrates the runs of `queue` with DOP853 (`opts` as for
/// [`crate::integrate::Dop853`]), `L` at a time in lanes; each lane's run is bitwise the
/// one-at-a-time integration. Returns when the queue is empty and every lane has ended.
/// Invalid options are refused before any run starts; a run that fails ends with its
/// failure in [`LaneEnd::failure`] and does not disturb the other lanes.
pub fn integrate<F: Field<N>, Q: Queue<N>, const N: usize, const L: usize>(
    field: &F,
    opts: &Options,
    queue: &mut Q,
) -> Result<(), IntegrateError> {
    opts.validate()?;
    let zero = [Lanes::splat(0.0); N];
    let mut batch = Batch::<F, N, L> {
        field,
        opts: *opts,
        y: zero,
        carry: zero,
        f: zero,
        y_prev: zero,
        k: [zero; 16],
        lanes: [Lane::default(); L],
        drained: false,
    };
    while batch.ready(queue) {
        batch.attempt(queue);
    }
    Ok(())
}

impl<F: Field<N>, const N: usize, const L: usize> Batch<'_, F, N, L> {
    /// Fills every free lane from the queue and prepares every busy lane's attempt (ending
    /// the runs that cannot step on); `false` when no lane is busy any more.
    fn ready<Q: Queue<N>>(&mut self, queue: &mut Q) -> bool {
        let mut any = false;
        for l in 0..L {
            loop {
                if !self.lanes[l].busy {
                    match (!self.drained).then(|| queue.next(l)).flatten() {
                        Some(job) => self.start(l, job, queue),
                        None => {
                            self.drained = true;
                            break;
                        }
                    }
                    continue;
                }
                match self.prepare(l) {
                    Ok(()) => {
                        any = true;
                        break;
                    }
                    Err(e) => self.end(l, Some(e), queue),
                }
            }
        }
        any
    }

    /// Starts `job` in lane `l` as [`crate::integrate::Dop853::new`] does (the same checks,
    /// `f(t0, y0)` and the same initial step); a run that cannot start, or that has nothing
    /// to do (`t_end = t0`), ends at once.
    fn start<Q: Queue<N>>(&mut self, l: usize, job: Job<N>, queue: &mut Q) {
        let mut lane = Lane {
            busy: true,
            t: job.t0,
            t_prev: job.t0,
            t_end: job.t_end,
            ..Lane::default()
        };
        set_lane(&mut self.y, l, &job.y0);
        set_lane(&mut self.carry, l, &[0.0; N]);
        let failure = [("t0", job.t0), ("t_end", job.t_end)]
            .into_iter()
            .find(|(_, v)| !v.is_finite())
            .map(|(name, value)| IntegrateError::InvalidOption {
                name,
                value,
                rule: "must be finite",
            })
            .or_else(|| {
                job.y0
                    .iter()
                    .any(|v| !v.is_finite())
                    .then_some(IntegrateError::NonFinite { t: job.t0 })
            });
        if let Some(e) = failure {
            self.lanes[l] = lane;
            return self.end(l, Some(e), queue);
        }
        let f0 = self.field.eval(&job.y0);
        lane.stats.rhs_evals = 1;
        set_lane(&mut self.f, l, &f0);
        if f0.iter().any(|v| !v.is_finite()) {
            self.lanes[l] = lane;
            return self.end(l, Some(IntegrateError::NonFinite { t: job.t0 }), queue);
        }
        lane.posneg = if job.t_end >= job.t0 { 1.0 } else { -1.0 };
        lane.hmax = self.opts.h_max.unwrap_or((job.t_end - job.t0).abs());
        let done = job.t_end == job.t0;
        lane.h = match self.opts.h_init {
            Some(h) => h.abs().copysign(lane.posneg),
            None if done => 0.0,
            None => {
                lane.stats.rhs_evals += 1;
                let one = OneLane(self.field);
                hinit(
                    &one,
                    job.t0,
                    &job.y0,
                    &f0,
                    lane.posneg,
                    lane.hmax,
                    &self.opts,
                    8,
                )
            }
        };
        self.lanes[l] = lane;
        if done {
            self.end(l, None, queue);
        }
    }

    /// The checks before an attempt, in the order of [`crate::integrate::Dop853::step`], and
    /// the attempt's step size (cut to land on `t_end`).
    fn prepare(&mut self, l: usize) -> Result<(), IntegrateError> {
        let lane = &mut self.lanes[l];
        let h = lane.h;
        if !h.is_finite() {
            return Err(IntegrateError::NonFinite { t: lane.t });
        }
        if lane.stats.steps + lane.stats.rejected >= self.opts.max_steps {
            return Err(IntegrateError::TooManySteps {
                t: lane.t,
                max_steps: self.opts.max_steps,
            });
        }
        if 0.1 * h.abs() <= lane.t.abs() * UROUND {
            return Err(IntegrateError::StepSizeTooSmall { t: lane.t, h });
        }
        lane.last = (lane.t + 1.01 * h - lane.t_end) * lane.posneg > 0.0;
        lane.h_try = if lane.last { lane.t_end - lane.t } else { h };
        Ok(())
    }

    /// Ends the run of lane `l` and frees the lane.
    fn end<Q: Queue<N>>(&mut self, l: usize, failure: Option<IntegrateError>, queue: &mut Q) {
        let lane = &mut self.lanes[l];
        lane.busy = false;
        queue.end(l, LaneEnd::of(lane.t, &self.y, l, lane.stats, failure));
    }

    /// One attempted step in every busy lane: the stages and error norms on all lanes at
    /// once, then lane by lane acceptance or rejection as in
    /// [`crate::integrate::Dop853::step`].
    fn attempt<Q: Queue<N>>(&mut self, queue: &mut Q) {
        let busy: [bool; L] = std::array::from_fn(|l| self.lanes[l].busy);
        // A free lane steps by 0 from its last state: finite numbers, ignored.
        let h = Lanes(std::array::from_fn(|l| {
            if busy[l] {
                self.lanes[l].h_try
            } else {
                0.0
            }
        }));
        self.k[0] = self.f;
        let inc = stages(self.field, h, &self.y, &mut self.k);
        let k = &self.k;
        let (rtol, atol) = (self.opts.rtol, self.opts.atol);
        let mut y_new = self.y;
        let (mut err5, mut err3) = (Lanes::splat(0.0), Lanes::splat(0.0));
        for i in 0..N {
            y_new[i] = self.y[i] + h * inc[i];
            let sk = self.y[i].abs().max(y_new[i].abs()) * rtol + atol;
            let e3 = inc[i] - k[0][i] * BHH[0] - k[8][i] * BHH[8] - k[11][i] * BHH[11];
            err3 = err3 + (e3 / sk) * (e3 / sk);
            let e5 = k[0][i] * ER[0]
                + k[5][i] * ER[5]
                + k[6][i] * ER[6]
                + k[7][i] * ER[7]
                + k[8][i] * ER[8]
                + k[9][i] * ER[9]
                + k[10][i] * ER[10]
                + k[11][i] * ER[11];
            err5 = err5 + (e5 / sk) * (e5 / sk);
        }
        let mut accepted = [false; L];
        let mut y_acc = self.y;
        for l in (0..L).filter(|&l| busy[l]) {
            self.lanes[l].stats.rhs_evals += 11;
            if self.control(l, err5.0[l], err3.0[l]) {
                accepted[l] = true;
                let mut y = lane_of(&y_new, l);
                if self.opts.compensated {
                    let mut carry = lane_of(&self.carry, l);
                    y = lane_of(&self.y, l);
                    let delta = std::array::from_fn(|i| h.0[l] * inc[i].0[l]);
                    compensated_add(&mut y, &mut carry, &delta);
                    set_lane(&mut self.carry, l, &carry);
                }
                set_lane(&mut y_acc, l, &y);
            }
        }
        if !accepted.contains(&true) {
            return;
        }
        let f_new = self.field.eval(&y_acc);
        for l in (0..L).filter(|&l| accepted[l]) {
            self.accept(l, &y_acc, &f_new, queue);
        }
    }

    /// The controller of lane `l` given the sums of squares of the 5th- and 3rd-order error
    /// estimates: sets the next step size and says whether the step is accepted.
    fn control(&mut self, l: usize, err5: f64, err3: f64) -> bool {
        let (facc1, facc2) = (1.0 / FAC1, 1.0 / FAC2);
        let lane = &mut self.lanes[l];
        let h = lane.h_try;
        let mut deno = err5 + 0.01 * err3;
        if deno <= 0.0 {
            deno = 1.0;
        }
        let err = h.abs() * err5 * (1.0 / (N as f64 * deno)).sqrt();
        let fac11 = err.powf(EXPO1);
        let fac = facc2.max(facc1.min(fac11 / SAFE));
        let mut h_new = h / fac;
        if err > 1.0 {
            lane.h = h / facc1.min(fac11 / SAFE);
            lane.reject = true;
            lane.stats.rejected += 1;
            return false;
        }
        if !lane.last {
            if h_new.abs() > lane.hmax {
                h_new = lane.posneg * lane.hmax;
            }
            if lane.reject {
                h_new = lane.posneg * h_new.abs().min(h.abs());
            }
            lane.reject = false;
        }
        lane.h = h_new;
        true
    }

    /// Lane `l`'s step is accepted with the new state in `y_acc` and its derivative in
    /// `f_new`: the step is shown to the queue, and the run ends on a failure or at `t_end`.
    fn accept<Q: Queue<N>>(
        &mut self,
        l: usize,
        y_acc: &[Lanes<L>; N],
        f_new: &[Lanes<L>; N],
        queue: &mut Q,
    ) {
        let lane = &mut self.lanes[l];
        let t_new = if lane.last {
            lane.t_end
        } else {
            lane.t + lane.h_try
        };
        lane.stats.rhs_evals += 1;
        let y = lane_of(y_acc, l);
        let f = lane_of(f_new, l);
        if y.iter().chain(f.iter()).any(|v| !v.is_finite()) {
            return self.end(l, Some(IntegrateError::NonFinite { t: t_new }), queue);
        }
        lane.stats.steps += 1;
        lane.t_prev = lane.t;
        lane.t = t_new;
        let y_prev = lane_of(&self.y, l);
        set_lane(&mut self.y_prev, l, &y_prev);
        set_lane(&mut self.y, l, &y);
        set_lane(&mut self.f, l, &f);
        set_lane(&mut self.k[12], l, &f);
        let lane = *lane;
        let view = LaneStep {
            field: self.field,
            k: &self.k,
            lane: l,
            t_prev: lane.t_prev,
            t: lane.t,
            t_end: lane.t_end,
            h: lane.h_try,
            y_prev,
            y,
            stats: lane.stats,
            cont: Cell::new(None),
            dense_evals: Cell::new(0),
        };
        queue.step(l, &view);
        self.lanes[l].stats.rhs_evals += view.dense_evals.get();
        if lane.last {
            self.end(l, None, queue);
        }
    }
}

/// One accepted step of one lane, as a [`Stepper`] shows it to an observer: its ends, its
/// state and its 7th-order dense output (built on the first call, with three `f64` field
/// evaluations, as [`crate::integrate::Dop853`] builds it).
struct LaneStep<'b, F, const N: usize, const L: usize> {
    field: &'b F,
    k: &'b Stages<Lanes<L>, N>,
    lane: usize,
    t_prev: f64,
    t: f64,
    t_end: f64,
    h: f64,
    y_prev: [f64; N],
    y: [f64; N],
    stats: Stats,
    cont: Cell<Option<[[f64; N]; 8]>>,
    dense_evals: Cell<usize>,
}

impl<F: Field<N>, const N: usize, const L: usize> LaneStep<'_, F, N, L> {
    /// Hairer's `CONT` array of the step (`CONTD8` coefficients), in the order of
    /// [`crate::integrate::Dop853`].
    fn dense_coefficients(&self) -> [[f64; N]; 8] {
        let (h, y) = (self.h, &self.y_prev);
        let mut k: Stages<f64, N> = [[0.0; N]; 16];
        for (s, stage) in self.k.iter().enumerate().take(13) {
            k[s] = std::array::from_fn(|i| stage[i].0[self.lane]);
        }
        k[13] = self.field.eval(&combine::<f64, 13, 8, N>(
            y,
            h,
            &k,
            [0, 6, 7, 8, 9, 10, 11, 12],
        ));
        k[14] = self.field.eval(&combine::<f64, 14, 8, N>(
            y,
            h,
            &k,
            [0, 5, 6, 7, 10, 11, 12, 13],
        ));
        k[15] = self.field.eval(&combine::<f64, 15, 8, N>(
            y,
            h,
            &k,
            [0, 5, 6, 7, 8, 12, 13, 14],
        ));
        self.dense_evals.set(self.dense_evals.get() + 3);
        dense_rows(y, &self.y, h, &k)
    }
}

impl<F: Field<N>, const N: usize, const L: usize> Stepper<N> for LaneStep<'_, F, N, L> {
    /// A step seen from outside cannot step on (the batch steps the lanes): does nothing
    /// and says whether the run has reached its end.
    fn step(&mut self) -> Result<bool, IntegrateError> {
        Ok(self.t == self.t_end)
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn t_end(&self) -> f64 {
        self.t_end
    }

    fn t_prev(&self) -> f64 {
        self.t_prev
    }

    fn h(&self) -> f64 {
        self.h
    }

    fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// The 7th-order continuous extension of the step at `t`, as
    /// [`crate::integrate::Dop853`] evaluates it.
    fn dense(&self, t: f64) -> [f64; N] {
        let cont = match self.cont.get() {
            Some(c) => c,
            None => {
                let c = self.dense_coefficients();
                self.cont.set(Some(c));
                c
            }
        };
        dense_at(&cont, (t - self.t_prev) / self.h)
    }

    /// Replaces the state this view shows (the lane itself is not changed: a batch does not
    /// project).
    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
    }

    fn stats(&self) -> Stats {
        let mut stats = self.stats;
        stats.rhs_evals += self.dense_evals.get();
        stats
    }
}
