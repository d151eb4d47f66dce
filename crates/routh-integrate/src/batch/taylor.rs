//! The Taylor method in lanes: the one recorded [`Tape`] of the field expanded for `L` runs
//! at once ([`Tape`] over [`Lanes`]: coefficient `k` of a slot for the `L` runs side by side,
//! the convolutions vectorised across the runs, AVX-512 or AVX2 chosen at run time), each
//! lane with its own order and [`StepControl`] (time, step size, end time), refilled from a
//! [`Queue`] as soon as its run ends (`Runs`).
//!
//! Each lane does the arithmetic of the one-at-a-time [`Taylor`](crate::Taylor)
//! on its run, operation for operation: the same recurrences on the same tape (a lane of a
//! `Tape<N, Lanes<L>>` is bitwise an `f64` tape: [`Coefficient`]), a lane's tape cleared
//! when its run starts (as a new tape), the same order ([`taylor_order`] of
//! [`step_tolerance`](crate::taylor::step_tolerance)) and step size
//! ([`taylor_step`](crate::taylor::taylor_step)) from the lane's own coefficients
//! (the same `SeriesRule`), the same step control ([`Law::Series`]), Horner sum and
//! compensated update. A lane is therefore **bitwise** the one-at-a-time run: the same
//! steps, orders, field passes, dense output and final state (tests/batch.rs, 1024 runs).
//! The lanes of one pass of the tape share its order, the highest of their orders: the
//! coefficients of the orders below are those of a shorter expansion, bit for bit.

use super::lanes::{lane_of, set_lane};
use super::runs::{LaneMethod, Queue, Runs};
use super::{Job, Lanes};
use crate::taylor::coefficient::Coefficient;
use crate::taylor::tape::{All, Compiled, Isa, Sets};
use crate::taylor::{taylor_order, Kernels, SeriesRule, Tape};
use crate::{Clock, IntegrateError, Law, OdeSystem, Options, Scales, Stats, StepControl, Stepper};
use std::marker::PhantomData;

/// The Taylor method in lanes: the system (for the units of each run), the tape with the
/// coefficients of every lane and each lane's order; the lanes' states and step control are
/// `Runs`'.
struct TaylorLanes<'s, S: ?Sized, const N: usize, const L: usize, K, C> {
    sys: &'s S,
    tape: Tape<N, Lanes<L>, K>,
    opts: Options,
    rule: SeriesRule,
    /// The scales of the components of each lane's run ([`Scales`]).
    scales: [Scales<N>; L],
    /// The order of each lane's step under way, then of its last accepted step (0: free).
    order: [usize; L],
    /// The instruction sets whose expansions of the tape (and copies of the loop) are
    /// compiled in ([`Compiled`]).
    sets: PhantomData<C>,
}

/// The number of lanes [`integrate`] uses on this CPU: 8 with AVX-512 (one register of
/// doubles) and with AVX2 (two registers: two independent chains of operations in flight,
/// taylor8 1.15x taylor4 on an AVX2 Zen 3, BENCHMARKS.md "Sweeps"), 4 with the baseline (two
/// SSE2 registers; eight lanes would be four registers an operation of its sixteen).
pub fn lanes() -> usize {
    width(Isa::detect())
}

/// The number of lanes of [`lanes`] with the instruction set `isa`.
const fn width(isa: Isa) -> usize {
    match isa {
        Isa::Baseline => 4,
        Isa::Avx2Fma | Isa::Avx512 => 8,
    }
}

/// Integrates the runs of `queue` with the Taylor method (`opts` as for
/// [`Taylor::new`](crate::Taylor::new)), in [`lanes`] lanes; each lane's run is
/// bitwise the one-at-a-time integration. Returns when the queue is empty and every lane has
/// ended. A system that cannot be recorded ([`OdeSystem::record`]) is refused before any run
/// starts; a run that fails ends with its failure in
/// [`Stop::Failed`](crate::Stop::Failed) and does not disturb the other lanes.
pub fn integrate<S: OdeSystem<N> + ?Sized, Q: Queue<N>, const N: usize>(
    sys: &S,
    opts: &Options,
    queue: &mut Q,
) -> Result<(), IntegrateError> {
    use Isa::{Avx2Fma, Avx512, Baseline};
    // Only the sets that run each width here are compiled in (`Compiled`, from `width`).
    if lanes() == 8 {
        type Eight =
            Compiled<{ width(Avx512) == 8 }, { width(Avx2Fma) == 8 }, { width(Baseline) == 8 }>;
        integrate_among::<S, Q, N, 8, Eight>(Isa::detect(), sys, opts, queue)
    } else {
        type Four =
            Compiled<{ width(Avx512) == 4 }, { width(Avx2Fma) == 4 }, { width(Baseline) == 4 }>;
        integrate_among::<S, Q, N, 4, Four>(Isa::detect(), sys, opts, queue)
    }
}

/// [`integrate`] in `L` lanes.
pub fn integrate_in<S: OdeSystem<N> + ?Sized, Q: Queue<N>, const N: usize, const L: usize>(
    sys: &S,
    opts: &Options,
    queue: &mut Q,
) -> Result<(), IntegrateError> {
    integrate_in_on::<S, Q, N, L>(Isa::detect(), sys, opts, queue)
}

/// [`integrate_in`] with the loop of the lanes compiled for the instruction set `isa` (one
/// this CPU has, [`Isa::available`]; the expansion of the tape keeps its own, the widest):
/// the same numbers, bit for bit, in every set (tests/batch.rs).
pub fn integrate_in_on<S: OdeSystem<N> + ?Sized, Q: Queue<N>, const N: usize, const L: usize>(
    isa: Isa,
    sys: &S,
    opts: &Options,
    queue: &mut Q,
) -> Result<(), IntegrateError> {
    integrate_among::<S, Q, N, L, All>(isa, sys, opts, queue)
}

/// [`integrate_in_on`] with the copies of the loop and of the tape's expansion for the sets
/// `C` only ([`Compiled`]; the tape's own set, [`Isa::detect`], one of them).
fn integrate_among<S, Q, const N: usize, const L: usize, C: Sets>(
    isa: Isa,
    sys: &S,
    opts: &Options,
    queue: &mut Q,
) -> Result<(), IntegrateError>
where
    S: OdeSystem<N> + ?Sized,
    Q: Queue<N>,
{
    let max_order = taylor_order(opts.rtol().min(opts.atol()));
    let tape = Tape::record(sys, max_order).ok_or(IntegrateError::Unsupported {
        method: "taylor",
        reason: "the system's field is not recorded through Scalar (OdeSystem::record)",
    })?;
    let mut method = TaylorLanes::<S, N, L, S::Kernels, C> {
        sys,
        tape: tape.with_coefficients(),
        opts: *opts,
        rule: SeriesRule::new(opts.rtol(), opts.atol(), max_order),
        scales: [Scales::one(); L],
        order: [0; L],
        sets: PhantomData,
    };
    Runs::integrate::<C, _, _>(isa, &mut method, queue);
    Ok(())
}

impl<S, const N: usize, const L: usize, K: Kernels, C: Sets> LaneMethod<N, L>
    for TaylorLanes<'_, S, N, L, K, C>
where
    S: OdeSystem<N> + ?Sized,
{
    /// As [`Taylor::new`](crate::Taylor::new): the lane's tape as new, the scales of its run.
    fn start(&mut self, l: usize, job: &Job<N>) -> Result<StepControl, (IntegrateError, Stats)> {
        self.tape.clear_lane(l);
        self.scales[l] = Scales::of_units(&self.sys.units(&job.y0));
        Ok(StepControl::new(
            Law::Series,
            job.t0,
            job.t_end,
            &self.opts,
            |_, _| 0.0,
        ))
    }

    /// The step budget ([`StepControl::budget`]) and the order of the lane's step from its
    /// state, as [`Taylor`](crate::Taylor)'s.
    #[inline(always)]
    fn prepare(&mut self, runs: &mut Runs<N, L>, l: usize) -> Result<(), IntegrateError> {
        if let Some(control) = &runs.control[l] {
            control.budget()?;
        }
        self.order[l] = (self.rule).order(self.scales[l].max_norm(lane_of(&runs.y, l).into_iter()));
        Ok(())
    }

    /// The tape of a lane that failed, which may hold NaN, is cleared.
    fn release(&mut self, l: usize, failed: bool) {
        if failed {
            self.tape.clear_lane(l);
        }
    }

    /// One step in every busy lane: the tape expanded for all lanes at once to the highest
    /// of their orders, then lane by lane the step of its series turned into the step taken
    /// by its step control ([`StepControl::series_step`]) and the update of
    /// [`Taylor`](crate::Taylor)'s step; the Horner sums on all lanes at once. A
    /// free lane takes the time and state of a busy one (finite numbers, ignored).
    #[inline(always)]
    fn step<Q: Queue<N>>(&mut self, runs: &mut Runs<N, L>, queue: &mut Q) {
        let Some(busy) = runs.control.iter().position(Option::is_some) else {
            return;
        };
        let (t_busy, y_busy) = (
            runs.control[busy].map_or(0.0, |c| c.t()),
            lane_of(&runs.y, busy),
        );
        for l in 0..L {
            if runs.control[l].is_none() {
                set_lane(&mut runs.y, l, &y_busy);
                self.order[l] = 0;
            }
        }
        let order = self.order;
        let top = order.into_iter().max().unwrap_or(0);
        let t = Lanes(std::array::from_fn(|l| {
            runs.control[l].map_or(t_busy, |c| c.t())
        }));
        self.tape.expand_among::<C>(t, &runs.y, top);
        // The norms of the series' orders 0, p - 1 and p, of all lanes at once when the busy
        // lanes share their order (`max_norm` lane by lane: the same maxima in the same order).
        let same = (0..L).all(|l| runs.control[l].is_none() || order[l] == top);
        let scales: [Lanes<L>; N] =
            std::array::from_fn(|i| Lanes(std::array::from_fn(|l| self.scales[l].of(i))));
        let norms = |k: usize| {
            (0..N).fold(Lanes::splat(0.0), |m, i| {
                m.max(self.tape.state_coefficient(i, k).abs() * scales[i])
            })
        };
        // The step sizes of the series: of all lanes side by side in one loop without a
        // branch or a call (`taylor_step`) when they share their order (those of the free
        // lanes are ignored), otherwise lane by lane.
        let mut series = [0.0; L];
        if same {
            let [n0, n1, n2] = [norms(0), norms(top - 1), norms(top)];
            for (l, h) in series.iter_mut().enumerate() {
                *h = self
                    .rule
                    .step(top, n0.0[l], n1.0[l], n2.0[l], &self.scales[l]);
            }
        } else {
            for l in (0..L).filter(|&l| runs.control[l].is_some()) {
                let p = order[l];
                let [n0, n1, n2] = [0, p - 1, p].map(|k| {
                    let c = (0..N).map(|i| self.tape.state_coefficient(i, k).0[l]);
                    self.scales[l].max_norm(c)
                });
                series[l] = self.rule.step(p, n0, n1, n2, &self.scales[l]);
            }
        }
        let mut h = [0.0; L];
        let mut failure: [Option<IntegrateError>; L] = std::array::from_fn(|_| None);
        for l in 0..L {
            let Some(control) = runs.control[l].as_mut() else {
                continue;
            };
            control.count_evals(order[l]);
            match control.series_step(series[l]) {
                Ok(hl) => h[l] = hl,
                Err(e) => failure[l] = Some(e),
            }
        }
        let delta = self.increments(&order, &Lanes(h));
        for l in 0..L {
            let Some(control) = runs.control[l] else {
                continue;
            };
            let d = lane_of(&delta, l);
            // Read in place, not taken: writing `None` back cost a stalled copy per lane.
            let checked = match &failure[l] {
                Some(e) => Err(e.clone()),
                None => control.check_increment(d.iter().all(|v| v.is_finite())),
            };
            if let Err(e) = checked {
                runs.end(l, Some(e), self, queue);
                continue;
            }
            let y = runs.add(l, &d, self.opts.compensated());
            set_lane(&mut runs.y, l, &y);
            let Some(control) = runs.control[l].as_mut() else {
                continue;
            };
            let last = control.advance(true) == Ok(true);
            let view = LaneStep {
                tape: &self.tape,
                lane: l,
                control: *control,
                p: order[l],
                y,
            };
            queue.step(l, &view);
            if last {
                runs.end(l, None, self, queue);
            }
        }
    }
}

impl<S: ?Sized, const N: usize, const L: usize, K: Kernels, C> TaylorLanes<'_, S, N, L, K, C> {
    /// The increments `sum_{k=1..p} y^[k] h^k` of all lanes at once, each by Horner's rule
    /// from its own order `p = order[l]` down (the sums of
    /// [`Taylor`](crate::Taylor), lane by lane).
    #[inline(always)]
    fn increments(&self, order: &[usize; L], h: &Lanes<L>) -> [Lanes<L>; N] {
        let top = order.iter().copied().max().unwrap_or(0);
        let c = |i: usize, k: usize| self.tape.state_coefficient(i, k);
        let mut acc: [Lanes<L>; N] = std::array::from_fn(|i| c(i, top));
        if order.iter().all(|&p| p == top) {
            // Every lane of the same order (the usual case: the order depends only on which
            // tolerance governs): the same sums without the choice per lane, the components
            // side by side (independent chains of multiply and add).
            for k in (1..top).rev() {
                for (i, a) in acc.iter_mut().enumerate() {
                    *a = *a * *h + c(i, k);
                }
            }
        } else {
            for k in (1..top).rev() {
                for (i, a) in acc.iter_mut().enumerate() {
                    let (ck, next) = (c(i, k), *a * *h + c(i, k));
                    *a = Lanes(std::array::from_fn(|l| match k.cmp(&order[l]) {
                        std::cmp::Ordering::Less => next.0[l],
                        std::cmp::Ordering::Equal => ck.0[l],
                        std::cmp::Ordering::Greater => a.0[l],
                    }));
                }
            }
        }
        acc.map(|a| a * *h)
    }
}

/// One accepted step of one lane, as a [`Stepper`] shows it to an observer: its ends, its
/// state and its dense output, the lane's Taylor series (as
/// [`Taylor`](crate::Taylor)'s).
struct LaneStep<'b, const N: usize, const L: usize, K> {
    tape: &'b Tape<N, Lanes<L>, K>,
    lane: usize,
    /// The lane's step control after the step.
    control: StepControl,
    /// The order of the step.
    p: usize,
    y: [f64; N],
}

impl<const N: usize, const L: usize, K: Kernels> Stepper<N> for LaneStep<'_, N, L, K> {
    /// A step seen from outside cannot step on (the batch steps the lanes): does nothing
    /// and says whether the run has reached its end.
    fn step(&mut self) -> Result<bool, IntegrateError> {
        Ok(self.control.done())
    }

    fn clock(&self) -> Clock {
        self.control.clock()
    }

    fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// The lane's Taylor series of the step, `sum_k y^[k] (t - t_prev)^k`, as
    /// [`Taylor`](crate::Taylor) evaluates it.
    fn dense(&self, t: f64) -> [f64; N] {
        let s = t - self.control.t_prev();
        std::array::from_fn(|i| {
            let c = self.tape.state_series(i, self.p);
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
}
