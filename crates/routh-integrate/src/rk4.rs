//! The classical Runge–Kutta method of order 4 with fixed steps, as a table
//! (Butcher tableau and continuous extension) and a [`Stepper`].

use std::convert::Infallible;

use super::compensated::compensated_add;
use super::{drive, Clock, Control, Drive, IntegrateError, OdeSystem, Stats, Stepper};

/// Nodes `c_i` of the classical Runge–Kutta method.
pub const RK4_C: [f64; 4] = [0.0, 0.5, 0.5, 1.0];
/// The matrix `a_ij` (row i, the stages before it).
pub const RK4_A: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [0.5, 0.0, 0.0],
    [0.0, 0.5, 0.0],
    [0.0, 0.0, 1.0],
];
/// Weights `b_i`.
pub const RK4_B: [f64; 4] = [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0];
/// The continuous extension `b_i(s) = sum_k RK4_DENSE[i][k] s^(k+1)`, `s` in [0, 1], of
/// order 3 (Hairer, Nørsett, Wanner, *Solving ODEs I*, section II.6, eq. (6.7)):
/// `b_1 = s - 3 s^2/2 + 2 s^3/3`, `b_2 = b_3 = s^2 - 2 s^3/3`, `b_4 = -s^2/2 + 2 s^3/3`;
/// `b_i(1) = b_i`.
pub const RK4_DENSE: [[f64; 3]; 4] = [
    [1.0, -1.5, 2.0 / 3.0],
    [0.0, 1.0, -2.0 / 3.0],
    [0.0, 1.0, -2.0 / 3.0],
    [0.0, -0.5, 2.0 / 3.0],
];

/// The classical Runge–Kutta method of order 4 with `steps` equal steps from `t0` to `t_end`
/// (forward or backward); the last step ends exactly at `t_end`. Four right-hand-side calls
/// per step; the dense output uses the stages of the step, no further call.
pub struct Rk4<'a, S, const N: usize> {
    sys: &'a S,
    t0: f64,
    t_end: f64,
    steps: usize,
    done_steps: usize,
    h: f64,
    t: f64,
    y: [f64; N],
    t_prev: f64,
    y_prev: [f64; N],
    /// Rounding residue of the compensated update ([`compensated_add`]; zero after
    /// [`Stepper::set_state`]).
    carry: [f64; N],
    k: [[f64; N]; 4],
    stats: Stats,
}

impl<'a, S: OdeSystem<N>, const N: usize> Rk4<'a, S, N> {
    /// Prepares `steps` equal steps of `sys` from `(t0, y0)` to `t_end`.
    pub fn new(sys: &'a S, t0: f64, y0: [f64; N], t_end: f64, steps: usize) -> Self {
        let h = if steps == 0 {
            0.0
        } else {
            (t_end - t0) / steps as f64
        };
        Rk4 {
            sys,
            t0,
            t_end,
            steps,
            done_steps: 0,
            h,
            t: t0,
            y: y0,
            t_prev: t0,
            y_prev: y0,
            carry: [0.0; N],
            k: [[0.0; N]; 4],
            stats: Stats::default(),
        }
    }
}

impl<S: OdeSystem<N>, const N: usize> Stepper<N> for Rk4<'_, S, N> {
    /// One step; never fails (a state that becomes non-finite is refused by the driver,
    /// [`drive`]).
    fn step(&mut self) -> Result<bool, IntegrateError> {
        if self.done_steps >= self.steps {
            return Ok(true);
        }
        let (t, h, y) = (self.t, self.h, self.y);
        for i in 0..4 {
            let mut yi = y;
            for (j, kj) in self.k.iter().enumerate().take(i) {
                if RK4_A[i][j] != 0.0 {
                    for c in 0..N {
                        yi[c] += h * RK4_A[i][j] * kj[c];
                    }
                }
            }
            self.k[i] = self.sys.rhs(t + RK4_C[i] * h, &yi);
        }
        let mut y_new = y;
        let delta: [f64; N] =
            std::array::from_fn(|c| h * (0..4).fold(0.0, |acc, i| acc + RK4_B[i] * self.k[i][c]));
        compensated_add(&mut y_new, &mut self.carry, &delta);
        self.stats.rhs_evals += 4;
        self.stats.steps += 1;
        self.done_steps += 1;
        self.t_prev = t;
        self.y_prev = y;
        self.t = if self.done_steps == self.steps {
            self.t_end
        } else {
            self.t0 + self.done_steps as f64 * h
        };
        self.y = y_new;
        Ok(self.done_steps == self.steps)
    }

    fn clock(&self) -> Clock {
        Clock {
            t: self.t,
            t_prev: self.t_prev,
            t_end: self.t_end,
            h: self.t - self.t_prev,
            stats: self.stats,
        }
    }

    fn y(&self) -> &[f64; N] {
        &self.y
    }

    fn dense(&self, t: f64) -> [f64; N] {
        if self.stats.steps == 0 {
            return self.y;
        }
        let h = self.h;
        let s = (t - self.t_prev) / h;
        let weights: [f64; 4] = std::array::from_fn(|i| {
            let [d1, d2, d3] = RK4_DENSE[i];
            s * (d1 + s * (d2 + s * d3))
        });
        std::array::from_fn(|c| {
            self.y_prev[c] + h * (0..4).fold(0.0, |acc, i| acc + weights[i] * self.k[i][c])
        })
    }

    fn set_state(&mut self, y: [f64; N]) {
        self.y = y;
        self.carry = [0.0; N];
    }
}

/// Integrates `sys` from `(t0, y0)` to `t_end` (forward or backward) with
/// `steps` equal steps of the classical Runge–Kutta method of order 4, calling
/// `observer(t, &y)` after every step (not at `t0`). The last step ends exactly
/// at `t_end`. Returns the final state and the work counters (4 right-hand-side
/// calls per step); a state that becomes non-finite ends the run there ([`drive`]) and is
/// returned. With `steps == 0` nothing is integrated and `y0` is returned.
pub fn rk4<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    steps: usize,
    mut observer: impl FnMut(f64, &[f64; N]),
) -> ([f64; N], Stats) {
    let mut stepper = Rk4::new(sys, t0, y0, t_end, steps);
    let Ok(outcome) = drive::<_, Infallible, N>(
        &mut stepper,
        &Drive::default(),
        &mut |_, _| Ok(()),
        &mut |t, y, _| {
            observer(t, y);
            Ok(Control::Continue)
        },
    );
    (outcome.y, outcome.stats)
}
