//! The Taylor method in lanes: the one recorded [`Tape`] of the field expanded for `L` runs
//! at once ([`Tape`] over [`Lanes`]: coefficient `k` of a slot for the `L` runs side by side,
//! the convolutions vectorised across the runs, AVX-512 or AVX2 chosen at run time), each
//! lane with its own time, order, step size and end time, refilled from a [`Queue`] as soon
//! as its run ends.
//!
//! Each lane does the arithmetic of the one-at-a-time [`Taylor`](crate::integrate::Taylor)
//! on its run, operation for operation: the same recurrences on the same tape (a lane of a
//! `Tape<N, Lanes<L>>` is bitwise an `f64` tape: [`Coefficient`]), a lane's tape cleared
//! when its run starts (as a new tape), the same order ([`taylor_order`] of
//! [`step_tolerance`]) and step size ([`taylor_step`]) from the lane's own coefficients, the same Horner sum, checks and
//! compensated update. A lane is therefore **bitwise** the one-at-a-time run: the same steps,
//! orders, field passes, dense output and final state (tests/batch_taylor.rs, 1024 runs).
//! The lanes of one pass of the tape share its order, the highest of their orders: the
//! coefficients of the orders below are those of a shorter expansion, bit for bit.

use super::lanes::{lane_of, set_lane};
use super::{Job, LaneEnd, Lanes, Queue};
use crate::integrate::compensated::compensated_add;
use crate::integrate::taylor::tape::{Coefficient, Isa};
use crate::integrate::taylor::{max_norm, step_tolerance, taylor_order, taylor_step, Tape, UROUND};
use crate::integrate::{check_start, IntegrateError, OdeSystem, Options, Stats, Stepper};

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
    /// Order of the step under way, then of the last accepted step.
    p: usize,
    /// Size of the last accepted step.
    h: f64,
    stats: Stats,
}

/// The lanes' states (structure of arrays), their tape and bookkeeping.
struct Batch<const N: usize, const L: usize> {
    tape: Tape<N, Lanes<L>>,
    opts: Options,
    y: [Lanes<L>; N],
    carry: [Lanes<L>; N],
    lanes: [Lane; L],
    /// The queue has no run left.
    drained: bool,
}

/// The number of lanes [`integrate`] uses on this CPU: 8 with AVX-512 (one register of
/// doubles), 4 otherwise (AVX2, or two SSE2 registers).
pub fn lanes() -> usize {
    Isa::detect().doubles().max(4)
}

/// Integrates the runs of `queue` with the Taylor method (`opts` as for
/// [`Taylor::new`](crate::integrate::Taylor::new)), in [`lanes`] lanes; each lane's run is
/// bitwise the one-at-a-time integration. Returns when the queue is empty and every lane has
/// ended. Invalid options, and a system that cannot be recorded
/// ([`OdeSystem::record`]), are refused before any run starts; a run that fails ends with
/// its failure in [`LaneEnd::failure`] and does not disturb the other lanes.
pub fn integrate<S: OdeSystem<N> + ?Sized, Q: Queue<N>, const N: usize>(
    sys: &S,
    opts: &Options,
    queue: &mut Q,
) -> Result<(), IntegrateError> {
    if lanes() == 8 {
        integrate_in::<S, Q, N, 8>(sys, opts, queue)
    } else {
        integrate_in::<S, Q, N, 4>(sys, opts, queue)
    }
}

/// [`integrate`] in `L` lanes.
pub fn integrate_in<S: OdeSystem<N> + ?Sized, Q: Queue<N>, const N: usize, const L: usize>(
    sys: &S,
    opts: &Options,
    queue: &mut Q,
) -> Result<(), IntegrateError> {
    opts.validate()?;
    let tape = Tape::record(sys, taylor_order(opts.rtol.min(opts.atol))).ok_or(
        IntegrateError::Unsupported {
            method: "taylor",
            reason: "the system's field is not recorded through Scalar (OdeSystem::record)",
        },
    )?;
    let zero = [Lanes::splat(0.0); N];
    let mut batch = Batch::<N, L> {
        tape: tape.with_coefficients(),
        opts: *opts,
        y: zero,
        carry: zero,
        lanes: [Lane::default(); L],
        drained: false,
    };
    while batch.ready(queue) {
        batch.step(queue);
    }
    Ok(())
}

impl<const N: usize, const L: usize> Batch<N, L> {
    /// Fills every free lane from the queue and prepares every busy lane's step (its order;
    /// the runs that cannot step on end); `false` when no lane is busy any more. A free lane
    /// takes the time and state of a busy one (finite numbers, ignored).
    fn ready<Q: Queue<N>>(&mut self, queue: &mut Q) -> bool {
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
                let lane = &mut self.lanes[l];
                if lane.stats.steps >= self.opts.max_steps {
                    let e = IntegrateError::TooManySteps {
                        t: lane.t,
                        max_steps: self.opts.max_steps,
                    };
                    self.end(l, Some(e), queue);
                    continue;
                }
                let y = lane_of(&self.y, l);
                let (eps, _) =
                    step_tolerance(self.opts.rtol, self.opts.atol, max_norm(y.iter().copied()));
                lane.p = taylor_order(eps).min(self.tape.max_order());
                break;
            }
        }
        let free: [bool; L] = std::array::from_fn(|l| !self.lanes[l].busy);
        let Some(busy) = (0..L).find(|&l| !free[l]) else {
            return false;
        };
        for l in (0..L).filter(|&l| free[l]) {
            let y = lane_of(&self.y, busy);
            set_lane(&mut self.y, l, &y);
            self.lanes[l].t = self.lanes[busy].t;
            self.lanes[l].p = 0;
        }
        true
    }

    /// Starts `job` in lane `l` as [`Taylor::new`](crate::integrate::Taylor::new) does (the
    /// same checks; the lane's tape as new); a run that cannot start, or that has nothing to
    /// do (`t_end = t0`), ends at once.
    fn start<Q: Queue<N>>(&mut self, l: usize, job: Job<N>, queue: &mut Q) {
        self.lanes[l] = Lane {
            busy: true,
            t: job.t0,
            t_prev: job.t0,
            t_end: job.t_end,
            posneg: if job.t_end >= job.t0 { 1.0 } else { -1.0 },
            hmax: self.opts.h_max.unwrap_or((job.t_end - job.t0).abs()),
            ..Lane::default()
        };
        self.tape.clear_lane(l);
        set_lane(&mut self.carry, l, &[0.0; N]);
        match check_start(job.t0, &job.y0, job.t_end) {
            Err(e) => self.end(l, Some(e), queue),
            Ok(()) => {
                set_lane(&mut self.y, l, &job.y0);
                if job.t_end == job.t0 {
                    self.end(l, None, queue);
                }
            }
        }
    }

    /// Ends the run of lane `l` and frees the lane (its tape cleared after a failure, which
    /// may have left NaN in it).
    fn end<Q: Queue<N>>(&mut self, l: usize, failure: Option<IntegrateError>, queue: &mut Q) {
        let lane = &mut self.lanes[l];
        lane.busy = false;
        if failure.is_some() {
            self.tape.clear_lane(l);
        }
        queue.end(l, LaneEnd::of(lane.t, &self.y, l, lane.stats, failure));
    }

    /// One step in every busy lane: the tape expanded for all lanes at once to the highest
    /// of their orders, then lane by lane the step size, the checks and the update of
    /// [`Taylor`](crate::integrate::Taylor)'s step; the Horner sums on all lanes at once.
    fn step<Q: Queue<N>>(&mut self, queue: &mut Q) {
        let busy: [bool; L] = std::array::from_fn(|l| self.lanes[l].busy);
        let order: [usize; L] = std::array::from_fn(|l| self.lanes[l].p);
        let top = order.into_iter().max().unwrap_or(0);
        let t = Lanes(std::array::from_fn(|l| self.lanes[l].t));
        self.tape.expand(t, &self.y, top);
        let (rtol, atol) = (self.opts.rtol, self.opts.atol);
        let mut h = [0.0; L];
        let mut last = [false; L];
        let mut failure: [Option<IntegrateError>; L] = std::array::from_fn(|_| None);
        for l in (0..L).filter(|&l| busy[l]) {
            let lane = &mut self.lanes[l];
            let p = lane.p;
            lane.stats.rhs_evals += p;
            let norm = |k: usize| max_norm((0..N).map(|i| self.tape.state_coefficient(i, k).0[l]));
            let (eps, scale) = step_tolerance(rtol, atol, norm(0));
            let mut hl =
                taylor_step(eps, p, scale, norm(p - 1), norm(p)).min(lane.hmax) * lane.posneg;
            if hl.is_nan() {
                failure[l] = Some(IntegrateError::NonFinite { t: lane.t });
                continue;
            }
            last[l] = (lane.t + 1.01 * hl - lane.t_end) * lane.posneg >= 0.0;
            if last[l] {
                hl = lane.t_end - lane.t;
            } else if 0.1 * hl.abs() <= lane.t.abs() * UROUND {
                failure[l] = Some(IntegrateError::StepSizeTooSmall { t: lane.t, h: hl });
                continue;
            }
            h[l] = hl;
        }
        let delta = self.increments(&order, &Lanes(h));
        for l in (0..L).filter(|&l| busy[l]) {
            if let Some(e) = failure[l].take() {
                self.end(l, Some(e), queue);
                continue;
            }
            let d = lane_of(&delta, l);
            if d.iter().any(|v| !v.is_finite()) {
                let e = IntegrateError::NonFinite { t: self.lanes[l].t };
                self.end(l, Some(e), queue);
                continue;
            }
            let mut y = lane_of(&self.y, l);
            if self.opts.compensated {
                let mut carry = lane_of(&self.carry, l);
                compensated_add(&mut y, &mut carry, &d);
                set_lane(&mut self.carry, l, &carry);
            } else {
                (0..N).for_each(|i| y[i] += d[i]);
            }
            set_lane(&mut self.y, l, &y);
            let lane = &mut self.lanes[l];
            lane.t_prev = lane.t;
            lane.t = if last[l] { lane.t_end } else { lane.t + h[l] };
            lane.h = h[l];
            lane.stats.steps += 1;
            let view = LaneStep {
                tape: &self.tape,
                lane: l,
                run: *lane,
                y,
            };
            queue.step(l, &view);
            if last[l] {
                self.end(l, None, queue);
            }
        }
    }

    /// The increments `sum_{k=1..p} y^[k] h^k` of all lanes at once, each by Horner's rule
    /// from its own order `p = order[l]` down (the sums of
    /// [`Taylor`](crate::integrate::Taylor), lane by lane).
    fn increments(&self, order: &[usize; L], h: &Lanes<L>) -> [Lanes<L>; N] {
        let top = order.iter().copied().max().unwrap_or(0);
        std::array::from_fn(|i| {
            let c = |k: usize| self.tape.state_coefficient(i, k);
            let mut acc = c(top);
            for k in (1..top).rev() {
                let (ck, next) = (c(k), acc * *h + c(k));
                acc = Lanes(std::array::from_fn(|l| match k.cmp(&order[l]) {
                    std::cmp::Ordering::Less => next.0[l],
                    std::cmp::Ordering::Equal => ck.0[l],
                    std::cmp::Ordering::Greater => acc.0[l],
                }));
            }
            acc * *h
        })
    }
}

/// One accepted step of one lane, as a [`Stepper`] shows it to an observer: its ends, its
/// state and its dense output, the lane's Taylor series (as
/// [`Taylor`](crate::integrate::Taylor)'s).
struct LaneStep<'b, const N: usize, const L: usize> {
    tape: &'b Tape<N, Lanes<L>>,
    lane: usize,
    run: Lane,
    y: [f64; N],
}

impl<const N: usize, const L: usize> Stepper<N> for LaneStep<'_, N, L> {
    /// A step seen from outside cannot step on (the batch steps the lanes): does nothing
    /// and says whether the run has reached its end.
    fn step(&mut self) -> Result<bool, IntegrateError> {
        Ok(self.run.t == self.run.t_end)
    }

    fn t(&self) -> f64 {
        self.run.t
    }

    fn t_end(&self) -> f64 {
        self.run.t_end
    }

    fn t_prev(&self) -> f64 {
        self.run.t_prev
    }

    fn h(&self) -> f64 {
        self.run.h
    }

    fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// The lane's Taylor series of the step, `sum_k y^[k] (t - t_prev)^k`, as
    /// [`Taylor`](crate::integrate::Taylor) evaluates it.
    fn dense(&self, t: f64) -> [f64; N] {
        let s = t - self.run.t_prev;
        std::array::from_fn(|i| {
            let c = self.tape.state_series(i, self.run.p);
            c.iter()
                .rev()
                .fold(0.0, |acc, ck| acc * s + ck.lane(self.lane))
        })
    }

    /// Replaces the state this view shows (the lane itself is not changed: a batch does not
    /// project).
    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
    }

    fn stats(&self) -> Stats {
        self.run.stats
    }
}
