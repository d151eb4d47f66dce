//! The classical Runge–Kutta method of order 4 with fixed steps.

use super::compensated::compensated_add;
use super::{OdeSystem, Stats};

/// Integrates `sys` from `(t0, y0)` to `t_end` (forward or backward) with
/// `steps` equal steps of the classical Runge–Kutta method of order 4 (the update summed with
/// compensation, see [`compensated_add`]), calling
/// `observer(t, &y)` after every step (not at `t0`). The last step ends exactly
/// at `t_end`. Returns the final state and the work counters (4 right-hand-side
/// calls per step). With `steps == 0` nothing is integrated and `y0` is returned.
pub fn rk4<S: OdeSystem<N>, const N: usize>(
    sys: &S,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    steps: usize,
    mut observer: impl FnMut(f64, &[f64; N]),
) -> ([f64; N], Stats) {
    let mut y = y0;
    if steps == 0 {
        return (y, Stats::default());
    }
    let h = (t_end - t0) / steps as f64;
    let mut carry = [0.0; N];
    let shifted = |y: &[f64; N], k: &[f64; N], c: f64| {
        let mut out = [0.0; N];
        for i in 0..N {
            out[i] = y[i] + c * k[i];
        }
        out
    };
    for n in 0..steps {
        let t = t0 + n as f64 * h;
        let k1 = sys.rhs(t, &y);
        let k2 = sys.rhs(t + 0.5 * h, &shifted(&y, &k1, 0.5 * h));
        let k3 = sys.rhs(t + 0.5 * h, &shifted(&y, &k2, 0.5 * h));
        let k4 = sys.rhs(t + h, &shifted(&y, &k3, h));
        let delta = std::array::from_fn(|i| h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]));
        compensated_add(&mut y, &mut carry, &delta);
        let t_next = if n + 1 == steps {
            t_end
        } else {
            t0 + (n + 1) as f64 * h
        };
        observer(t_next, &y);
    }
    let stats = Stats {
        steps,
        rejected: 0,
        rhs_evals: 4 * steps,
    };
    (y, stats)
}
