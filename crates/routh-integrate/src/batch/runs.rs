//! The runs of a batch: the [`Queue`] that feeds the lanes, each lane's state (structure of
//! arrays) and [`StepControl`], and the one loop of every method in lanes
//! (`Runs::integrate`): fill the free lanes from the queue, let the step control of each
//! busy lane check its next step, step all lanes at once, end the runs that are done or
//! failed. What a method does in its lanes (its start, the checks before its step, the step
//! itself) is a `LaneMethod`; whether a lane's attempt is accepted, its next step size, the
//! cut at its end time and its failures are decided by the lane's [`StepControl`], the step
//! control of the one-at-a-time steppers.

use super::lanes::{lane_of, set_lane};
use super::Lanes;
use crate::compensated::compensated_add;
use crate::taylor::tape::{Isa, Sets};
use crate::{check_start, IntegrateError, Outcome, Stats, StepControl, Stepper, Stop};

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

/// The runs of a batch and what happens to each: the batch asks for a run whenever a lane is
/// free, shows each accepted step, and hands back the end.
pub trait Queue<const N: usize> {
    /// The next run, for lane `lane`; `None` when there is none left (then it is not asked
    /// again).
    fn next(&mut self, lane: usize) -> Option<Job<N>>;
    /// The run in `lane` made an accepted step; `step` shows it (its time, state and dense
    /// output, as [`crate::drive`] shows a step to its observer).
    fn step(&mut self, lane: usize, step: &dyn Stepper<N>);
    /// The run in `lane` ended ([`Stop::Reached`], or [`Stop::Failed`] with the last accepted
    /// step's time and state, as the one-at-a-time integrator reports it; the counters include
    /// the field evaluations of the dense output asked for by [`Queue::step`]); the lane takes
    /// the next run.
    fn end(&mut self, lane: usize, end: Outcome<N>);
}

/// What a one-step method does in `L` lanes; the lanes' runs and their step control are
/// `Runs`'.
pub(crate) trait LaneMethod<const N: usize, const L: usize> {
    /// Starts `job` in lane `l` (its start checked, its state in the lanes): the method's
    /// own preparation and the run's step control; `Err` when the run cannot start, with the
    /// work it cost.
    fn start(&mut self, l: usize, job: &Job<N>) -> Result<StepControl, (IntegrateError, Stats)>;
    /// Before the next step of the busy lane `l`: the checks of its step control; `Err` ends
    /// the run.
    fn prepare(&mut self, runs: &mut Runs<N, L>, l: usize) -> Result<(), IntegrateError>;
    /// One step (or attempt) of every busy lane at once, the runs that end handed to
    /// `Runs::end`.
    fn step<Q: Queue<N>>(&mut self, runs: &mut Runs<N, L>, queue: &mut Q);
    /// The run of lane `l` ended (`failed`: with a failure).
    fn release(&mut self, _l: usize, _failed: bool) {}
}

/// The lanes' states and rounding carries (structure of arrays) and each lane's step control
/// (`None`: the lane is free).
pub(crate) struct Runs<const N: usize, const L: usize> {
    /// The states of the lanes.
    pub y: [Lanes<L>; N],
    /// The rounding residues of their compensated updates.
    pub carry: [Lanes<L>; N],
    /// The step control of the run in each lane.
    pub control: [Option<StepControl>; L],
    /// The queue has no run left.
    drained: bool,
}

impl<const N: usize, const L: usize> Runs<N, L> {
    /// Integrates the runs of `queue` with `method`, `L` at a time: returns when the queue
    /// is empty and every lane has ended.
    ///
    /// The whole loop (the lanes' steps, norms, step sizes, Horner sums and updates) is
    /// compiled for the instruction set `isa` ([`Isa::detect`] unless a test or benchmark
    /// compares them; one this CPU has: [`Isa::available`]), so that `L` lanes are one or two
    /// registers rather than `L / 2` SSE2 registers. The arithmetic is the same in each (no
    /// contraction into fused multiply-adds: Rust does not contract, and
    /// [`Scalar::mul_add`](crate::scalar::Scalar::mul_add) decides at compile time), so a lane
    /// stays bitwise the one-at-a-time run (tests/batch.rs, under every set).
    ///
    /// Only the copies of the loop for the sets `S` are compiled in
    /// ([`Compiled`](crate::taylor::tape::Compiled)); a set asked for and not compiled runs
    /// in another ([`Sets::run_as`]): the same numbers, at another speed.
    pub fn integrate<S: Sets, M, Q>(isa: Isa, method: &mut M, queue: &mut Q)
    where
        M: LaneMethod<N, L>,
        Q: Queue<N>,
    {
        assert!(isa.available(), "{isa:?} is not available on this CPU");
        let run = S::run_as(isa);
        assert!(
            run.available(),
            "{run:?}, run for {isa:?}, is not available on this CPU"
        );
        #[cfg(target_arch = "x86_64")]
        match run {
            // SAFETY: the CPU has the features each function is compiled for (`available`).
            Isa::Avx512 if S::AVX512 => return unsafe { Self::integrate_avx512(method, queue) },
            Isa::Avx2Fma if S::AVX2 => return unsafe { Self::integrate_avx2_fma(method, queue) },
            _ => {}
        }
        if S::BASELINE {
            Self::integrate_with(method, queue);
        }
    }

    /// [`Runs::integrate`] compiled for AVX-512F and VL (and AVX2, FMA).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    fn integrate_avx512<M: LaneMethod<N, L>, Q: Queue<N>>(method: &mut M, queue: &mut Q) {
        Self::integrate_with(method, queue);
    }

    /// [`Runs::integrate`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn integrate_avx2_fma<M: LaneMethod<N, L>, Q: Queue<N>>(method: &mut M, queue: &mut Q) {
        Self::integrate_with(method, queue);
    }

    /// The loop of [`Runs::integrate`], inlined into each instruction set's copy.
    #[inline(always)]
    fn integrate_with<M: LaneMethod<N, L>, Q: Queue<N>>(method: &mut M, queue: &mut Q) {
        let zero = [Lanes::splat(0.0); N];
        let mut runs = Runs {
            y: zero,
            carry: zero,
            control: [None; L],
            drained: false,
        };
        while runs.fill(method, queue) {
            method.step(&mut runs, queue);
        }
    }

    /// Fills every free lane from the queue and prepares every busy lane's step (ending the
    /// runs that cannot step on); `false` when no lane is busy any more.
    #[inline(always)]
    fn fill<M: LaneMethod<N, L>, Q: Queue<N>>(&mut self, method: &mut M, queue: &mut Q) -> bool {
        let mut any = false;
        for l in 0..L {
            loop {
                if self.control[l].is_none() {
                    match (!self.drained).then(|| queue.next(l)).flatten() {
                        Some(job) => self.start(l, job, method, queue),
                        None => {
                            self.drained = true;
                            break;
                        }
                    }
                    continue;
                }
                match method.prepare(self, l) {
                    Ok(()) => {
                        any = true;
                        break;
                    }
                    Err(e) => self.end(l, Some(e), method, queue),
                }
            }
        }
        any
    }

    /// Starts `job` in lane `l` as the one-at-a-time stepper starts (the same checks); a run
    /// that cannot start, or that has nothing to do (`t_end = t0`), ends at once.
    fn start<M: LaneMethod<N, L>, Q: Queue<N>>(
        &mut self,
        l: usize,
        job: Job<N>,
        method: &mut M,
        queue: &mut Q,
    ) {
        set_lane(&mut self.y, l, &job.y0);
        set_lane(&mut self.carry, l, &[0.0; N]);
        let started = check_start(job.t0, &job.y0, job.t_end)
            .map_err(|e| (e, Stats::default()))
            .and_then(|()| method.start(l, &job));
        match started {
            Ok(control) => {
                self.control[l] = Some(control);
                if control.done() {
                    self.end(l, None, method, queue);
                }
            }
            Err((failure, stats)) => queue.end(
                l,
                Outcome {
                    stop: Stop::Failed(failure),
                    t: job.t0,
                    y: job.y0,
                    stats,
                },
            ),
        }
    }

    /// Ends the run of lane `l` (after its last step or a failure) and frees the lane.
    pub fn end<M: LaneMethod<N, L>, Q: Queue<N>>(
        &mut self,
        l: usize,
        failure: Option<IntegrateError>,
        method: &mut M,
        queue: &mut Q,
    ) {
        let Some(control) = self.control[l].take() else {
            return;
        };
        method.release(l, failure.is_some());
        queue.end(
            l,
            Outcome {
                stop: failure.map_or(Stop::Reached, Stop::Failed),
                t: control.t(),
                y: lane_of(&self.y, l),
                stats: control.stats(),
            },
        );
    }

    /// Lane `l`'s state plus `delta`, summed with compensation ([`compensated_add`], the
    /// lane's carry updated) or plainly, as the one-at-a-time steppers add their increments.
    #[inline(always)]
    pub fn add(&mut self, l: usize, delta: &[f64; N], compensated: bool) -> [f64; N] {
        let mut y = lane_of(&self.y, l);
        if compensated {
            let mut carry = lane_of(&self.carry, l);
            compensated_add(&mut y, &mut carry, delta);
            set_lane(&mut self.carry, l, &carry);
        } else {
            (0..N).for_each(|i| y[i] += delta[i]);
        }
        y
    }
}
