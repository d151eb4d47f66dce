//! Many trajectories of one autonomous field advanced together in SIMD lanes.
//!
//! A sweep integrates thousands of runs of the same field (mg-eq) from different initial
//! states. [`dop853::integrate`] keeps `L` of them side by side in [`Lanes`] (structure of
//! arrays: component `i` of the `L` states in one vector) and evaluates the field, written
//! once generic over [`Scalar`], on all `L` at once; [`taylor::integrate`] does the same with
//! the Taylor method, the recorded tape of the field expanded for all lanes at once (its
//! coefficients [`Lanes`], the recurrences written once for `f64` and lanes). Each lane keeps its own time, step size,
//! rejections, counters and end time; when a run ends (or fails) its lane takes the next run
//! of the queue at once, so no lane waits for another's end.
//!
//! The arithmetic of each lane is that of the one-at-a-time
//! [`Dop853`](crate::integrate::Dop853): the same tableau
//! ([`crate::integrate::tableau`]), the same operations in the same order, the same fused
//! multiply-add decisions ([`Lanes`]), the same step-size control, initial step
//! ([`crate::integrate::hinit`]) and compensated update. A lane is therefore **bitwise
//! identical** to the one-at-a-time integrator: the same steps, rejections, field
//! evaluations and final state, to the last bit (tests/batch.rs checks it on 1024 runs). The
//! same holds for the Taylor lanes and [`Taylor`](crate::integrate::Taylor) (see
//! [`taylor`]).

pub mod dop853;
pub mod lanes;
pub mod taylor;

pub use dop853::{integrate, Job, LaneEnd, Queue, LANES};
pub use lanes::Lanes;

use crate::scalar::Scalar;

/// An autonomous field `y' = f(y)` of dimension `N`, written once for every [`Scalar`]: the
/// batch evaluates it on [`Lanes`] (all lanes at once) and on `f64` (one lane: the initial
/// step and the dense output).
pub trait Field<const N: usize> {
    /// `f(y)`.
    fn eval<D: Scalar>(&self, y: &[D; N]) -> [D; N];
}
