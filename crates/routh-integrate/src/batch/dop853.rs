//! DOP853 in lanes: Hairer's `dop853.f` step (the stages of [`crate::tableau`],
//! the 5th/3rd-order error estimate) applied to `L` runs at once, each lane with its own
//! [`StepControl`] (time, step size, rejections, end time), refilled from a [`Queue`] as
//! soon as its run ends (`Runs`).
//!
//! Every operation of a lane is the operation of [`crate::Dop853`] on that run,
//! in the same order: the stages and the error norm run on [`Lanes`] (element-wise `f64`
//! arithmetic), the step control ([`Law::Dop853`]) and the compensated update run lane by
//! lane in `f64`, in the same code as the one-at-a-time stepper's. A lane is bitwise the
//! one-at-a-time integrator (see the module [`crate::batch`]).

use super::lanes::{lane_of, set_lane};
use super::runs::{LaneMethod, Queue, Runs};
use super::{Field, Job, Lanes};
use crate::pair::DenseCache;
use crate::scalar::Scalar;
use crate::tableau::{dense_at, dense_rows, A, B, BHH, ER};
use crate::taylor::tape::{All, Compiled, Isa, Sets};
use crate::{
    rk_start, scaled_error, Clock, IntegrateError, Law, OdeSystem, Options, Stats, StepControl,
    Stepper,
};

/// The most lanes the batched methods take ([`lanes`], [`super::taylor::lanes`]): the size of
/// a queue's table of lanes.
pub const LANES: usize = 8;

/// The number of lanes [`integrate_in_lanes`] uses on this CPU: 8 with AVX-512 (one register
/// of doubles), 4 otherwise (one AVX2 register, two SSE2 registers): on an AVX2 Zen 3 the
/// 8 lanes of two registers took 1.17x (1e-12) and 1.09x (1e-8) the time of 4 on the
/// throughput benchmark, as 4 lanes were faster in the SSE2 build too (BENCHMARKS.md,
/// "Sweeps"); with AVX-512, 8 lanes were 1.02x faster than 4 (2026-11-25).
pub fn lanes() -> usize {
    width(Isa::detect())
}

/// The number of lanes of [`lanes`] with the instruction set `isa`.
const fn width(isa: Isa) -> usize {
    match isa {
        Isa::Avx512 => 8,
        Isa::Avx2Fma | Isa::Baseline => 4,
    }
}

/// [`integrate`] in [`lanes`] lanes.
pub fn integrate_in_lanes<F: Field<N>, Q: Queue<N>, const N: usize>(
    field: &F,
    opts: &Options,
    queue: &mut Q,
) {
    use Isa::{Avx2Fma, Avx512, Baseline};
    // Only the sets that run each width here are compiled in (`Compiled`, from `width`).
    if lanes() == 8 {
        type Eight =
            Compiled<{ width(Avx512) == 8 }, { width(Avx2Fma) == 8 }, { width(Baseline) == 8 }>;
        integrate_among::<F, Q, N, 8, Eight>(Isa::detect(), field, opts, queue)
    } else {
        type Four =
            Compiled<{ width(Avx512) == 4 }, { width(Avx2Fma) == 4 }, { width(Baseline) == 4 }>;
        integrate_among::<F, Q, N, 4, Four>(Isa::detect(), field, opts, queue)
    }
}

/// The stages of a step: 0..=11, the derivative at the step end (12), the three stages of
/// the dense output (13..=15).
type Stages<T, const N: usize> = [[T; N]; 16];

/// `y + h * sum_j A[ROW][j] * k[j]` over the listed `cols`, summed left to right (the order of
/// [`crate::Dop853`]).
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

/// The field on one lane in `f64`, as an [`OdeSystem`]: the start of a run in lanes, and the
/// one-at-a-time runs of a field ([`crate::section`]).
pub(crate) struct OneLane<'f, F>(pub(crate) &'f F);

impl<F: Field<N>, const N: usize> OdeSystem<N> for OneLane<'_, F> {
    type Kernels = crate::taylor::Interpreted;

    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; N]) -> [f64; N] {
        self.0.eval(y)
    }

    fn units(&self, y0: &[f64; N]) -> crate::RunUnits<N> {
        self.0.units(y0)
    }
}

/// DOP853 in lanes: the stages of every lane (structure of arrays); the lanes' states and
/// step control are `Runs`'.
struct Dop853Lanes<'f, F, const N: usize, const L: usize> {
    field: &'f F,
    opts: Options,
    /// The scales of the components of each lane's run ([`crate::Scales`]).
    scales: [Lanes<L>; N],
    /// `f(y)`, the first stage of the next step.
    f: [Lanes<L>; N],
    k: Stages<Lanes<L>, N>,
}

/// Integrates the runs of `queue` with DOP853 (`opts` as for
/// [`crate::Dop853`]), `L` at a time in lanes; each lane's run is bitwise the
/// one-at-a-time integration. Returns when the queue is empty and every lane has ended; a run
/// that fails ends with its failure in [`Stop::Failed`](crate::Stop::Failed) and does
/// not disturb the other lanes.
pub fn integrate<F: Field<N>, Q: Queue<N>, const N: usize, const L: usize>(
    field: &F,
    opts: &Options,
    queue: &mut Q,
) {
    integrate_on::<F, Q, N, L>(Isa::detect(), field, opts, queue)
}

/// [`integrate`] with the loop of the lanes compiled for the instruction set `isa` (one this
/// CPU has, [`Isa::available`]; `integrate` takes the widest): the same numbers, bit for bit,
/// in every set (tests/batch.rs).
pub fn integrate_on<F: Field<N>, Q: Queue<N>, const N: usize, const L: usize>(
    isa: Isa,
    field: &F,
    opts: &Options,
    queue: &mut Q,
) {
    integrate_among::<F, Q, N, L, All>(isa, field, opts, queue)
}

/// [`integrate_on`] with the copies of the loop for the sets `C` only ([`Compiled`]).
fn integrate_among<F: Field<N>, Q: Queue<N>, const N: usize, const L: usize, C: Sets>(
    isa: Isa,
    field: &F,
    opts: &Options,
    queue: &mut Q,
) {
    let zero = [Lanes::splat(0.0); N];
    let mut method = Dop853Lanes::<F, N, L> {
        field,
        opts: *opts,
        scales: [Lanes::splat(1.0); N],
        f: zero,
        k: [zero; 16],
    };
    Runs::integrate::<C, _, _>(isa, &mut method, queue);
}

impl<F: Field<N>, const N: usize, const L: usize> LaneMethod<N, L> for Dop853Lanes<'_, F, N, L> {
    /// As [`crate::Dop853::new`]: `f(t0, y0)` and the same initial step.
    fn start(&mut self, l: usize, job: &Job<N>) -> Result<StepControl, (IntegrateError, Stats)> {
        let one = OneLane(self.field);
        let start = rk_start(&one, job.t0, job.y0, job.t_end, &self.opts, Law::Dop853, 8);
        let start = start.map_err(|e| {
            let stats = Stats {
                rhs_evals: 1,
                ..Stats::default()
            };
            (e, stats)
        })?;
        set_lane(&mut self.f, l, &start.f0);
        set_lane(
            &mut self.scales,
            l,
            &std::array::from_fn(|i| start.scales.of(i)),
        );
        Ok(start.control)
    }

    /// The checks before an attempt and its size ([`StepControl::attempt`]).
    #[inline(always)]
    fn prepare(&mut self, runs: &mut Runs<N, L>, l: usize) -> Result<(), IntegrateError> {
        match runs.control[l].as_mut() {
            Some(control) => control.attempt().map(|_| ()),
            None => Ok(()),
        }
    }

    /// One attempted step in every busy lane: the stages and error norms on all lanes at
    /// once, then lane by lane the judgement of its step control and the update as in
    /// [`crate::Dop853::step`].
    #[inline(always)]
    fn step<Q: Queue<N>>(&mut self, runs: &mut Runs<N, L>, queue: &mut Q) {
        // A free lane steps by 0 from its last state: finite numbers, ignored.
        let h = Lanes(std::array::from_fn(|l| {
            runs.control[l].map_or(0.0, |c| c.h_try())
        }));
        self.k[0] = self.f;
        let inc = stages(self.field, h, &runs.y, &mut self.k);
        let k = &self.k;
        let (rtol, atol) = (self.opts.rtol(), self.opts.atol());
        let (mut err5, mut err3) = (Lanes::splat(0.0), Lanes::splat(0.0));
        for i in 0..N {
            let (y_new, s) = (runs.y[i] + h * inc[i], self.scales[i]);
            let sk = runs.y[i].abs().max(y_new.abs()) * s * rtol + atol;
            let e3 = (inc[i] - k[0][i] * BHH[0] - k[8][i] * BHH[8] - k[11][i] * BHH[11]) * s;
            err3 = err3 + (e3 / sk) * (e3 / sk);
            let e5 = k[0][i] * ER[0]
                + k[5][i] * ER[5]
                + k[6][i] * ER[6]
                + k[7][i] * ER[7]
                + k[8][i] * ER[8]
                + k[9][i] * ER[9]
                + k[10][i] * ER[10]
                + k[11][i] * ER[11];
            let e5 = e5 * s;
            err5 = err5 + (e5 / sk) * (e5 / sk);
        }
        let accepted: [bool; L] = std::array::from_fn(|l| {
            runs.control[l].as_mut().is_some_and(|control| {
                control.count_evals(11);
                control.judge(scaled_error(err5.0[l], err3.0[l], h.0[l], N))
            })
        });
        let mut y_acc = runs.y;
        for l in (0..L).filter(|&l| accepted[l]) {
            let delta = std::array::from_fn(|i| h.0[l] * inc[i].0[l]);
            let y = runs.add(l, &delta, self.opts.compensated());
            set_lane(&mut y_acc, l, &y);
        }
        if !accepted.contains(&true) {
            return;
        }
        let f_new = self.field.eval(&y_acc);
        for l in (0..L).filter(|&l| accepted[l]) {
            self.accept(runs, l, &y_acc, &f_new, queue);
        }
    }
}

impl<F: Field<N>, const N: usize, const L: usize> Dop853Lanes<'_, F, N, L> {
    /// Lane `l`'s step is accepted with the new state in `y_acc` and its derivative in
    /// `f_new`: the run moves to the step end ([`StepControl::advance`]), the step is shown
    /// to the queue, and the run ends on a failure or at `t_end`.
    fn accept<Q: Queue<N>>(
        &mut self,
        runs: &mut Runs<N, L>,
        l: usize,
        y_acc: &[Lanes<L>; N],
        f_new: &[Lanes<L>; N],
        queue: &mut Q,
    ) {
        let Some(control) = runs.control[l].as_mut() else {
            return;
        };
        control.count_evals(1);
        let y = lane_of(y_acc, l);
        let f = lane_of(f_new, l);
        let last = match control.advance(y.iter().chain(f.iter()).all(|v| v.is_finite())) {
            Ok(last) => last,
            Err(e) => return runs.end(l, Some(e), self, queue),
        };
        let control = *control;
        let y_prev = lane_of(&runs.y, l);
        set_lane(&mut runs.y, l, &y);
        set_lane(&mut self.f, l, &f);
        set_lane(&mut self.k[12], l, &f);
        let view = LaneStep {
            field: self.field,
            k: &self.k,
            lane: l,
            control,
            y_prev,
            y,
            cont: DenseCache::new(),
        };
        queue.step(l, &view);
        let dense_evals = view.cont.evals();
        if let Some(control) = runs.control[l].as_mut() {
            control.count_evals(dense_evals);
        }
        if last {
            runs.end(l, None, self, queue);
        }
    }
}

/// One accepted step of one lane, as a [`Stepper`] shows it to an observer: its ends, its
/// state and its 7th-order dense output (built on the first call, with three `f64` field
/// evaluations, as [`crate::Dop853`] builds it).
struct LaneStep<'b, F, const N: usize, const L: usize> {
    field: &'b F,
    k: &'b Stages<Lanes<L>, N>,
    lane: usize,
    /// The lane's step control after the step.
    control: StepControl,
    y_prev: [f64; N],
    y: [f64; N],
    /// The dense-output coefficients of the step, built on the first request.
    cont: DenseCache<[[f64; N]; 8]>,
}

impl<F: Field<N>, const N: usize, const L: usize> LaneStep<'_, F, N, L> {
    /// Hairer's `CONT` array of the step (`CONTD8` coefficients), in the order of
    /// [`crate::Dop853`].
    fn dense_coefficients(&self) -> [[f64; N]; 8] {
        let (h, y) = (self.control.h_last(), &self.y_prev);
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
        dense_rows(y, &self.y, h, &k)
    }
}

impl<F: Field<N>, const N: usize, const L: usize> Stepper<N> for LaneStep<'_, F, N, L> {
    /// A step seen from outside cannot step on (the batch steps the lanes): does nothing
    /// and says whether the run has reached its end.
    fn step(&mut self) -> Result<bool, IntegrateError> {
        Ok(self.control.done())
    }

    fn clock(&self) -> Clock {
        self.control.clock().with_evals(self.cont.evals())
    }

    fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// The 7th-order continuous extension of the step at `t`, as
    /// [`crate::Dop853`] evaluates it.
    fn dense(&self, t: f64) -> [f64; N] {
        let cont = self.cont.get(3, || self.dense_coefficients());
        dense_at(&cont, (t - self.control.t_prev()) / self.control.h_last())
    }

    /// Replaces the state this view shows (the lane itself is not changed: a batch does not
    /// project).
    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
    }
}
