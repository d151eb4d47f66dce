//! Many trajectories of one autonomous field advanced together in SIMD lanes.
//!
//! A sweep integrates thousands of runs of the same field (mg-eq) from different initial
//! states. [`dop853::integrate`] keeps `L` of them side by side in [`Lanes`] (structure of
//! arrays: component `i` of the `L` states in one vector) and evaluates the field, written
//! once generic over [`Scalar`], on all `L` at once; [`taylor::integrate`] does the same with
//! the Taylor method, the recorded tape of the field expanded for all lanes at once (its
//! coefficients [`Lanes`], the recurrences written once for `f64` and lanes). Each lane keeps
//! its own time, step size, rejections, counters and end time; when a run ends (or fails) its
//! lane takes the next run of the queue at once, so no lane waits for another's end.
//!
//! **One step control.** The lanes have no step control of their own: each lane holds a
//! [`StepControl`](crate::StepControl), the step control of the one-at-a-time
//! steppers that [`drive`](crate::drive) steps, which decides the acceptance of
//! the lane's attempt, its next step size, the cut of its last step onto its end time, its
//! failures and its counters. `runs::Runs::integrate` is the one loop of every method in
//! lanes: it fills the free lanes from the [`Queue`], lets each busy lane's step control
//! check the next step, steps all lanes at once and ends the runs that are done; a method in
//! lanes ([`runs`]' `LaneMethod`: DOP853, Taylor) only computes its stages or its series and
//! error on all lanes, then hands each lane's numbers to its step control. We chose this
//! over making the batch a [`Stepper`](crate::Stepper) driven by
//! [`drive`](crate::drive): `drive` follows one run from its start to its end,
//! while a set of lanes has no common end (a lane is refilled with the next run when its own
//! run ends) and its lanes accept or reject their attempts independently; sharing the
//! per-run state machine keeps the lanes independent and still leaves one place that decides
//! the steps.
//!
//! The arithmetic of each lane is that of the one-at-a-time
//! [`Dop853`](crate::Dop853): the same tableau
//! ([`crate::tableau`]), the same operations in the same order, the same fused
//! multiply-add decisions ([`Lanes`]), the same step control, initial step
//! ([`crate::hinit`]) and compensated update. A lane is therefore **bitwise
//! identical** to the one-at-a-time integrator: the same steps, rejections, field
//! evaluations and final state, to the last bit (tests/batch.rs checks it on 1024 runs). The
//! same holds for the Taylor lanes and [`Taylor`](crate::Taylor) (see
//! [`taylor`]).

pub mod dop853;
pub mod lanes;
pub mod runs;
pub mod taylor;

pub(crate) use dop853::OneLane;
pub use dop853::{integrate, integrate_in_lanes, integrate_on, lanes, LANES};
pub use lanes::Lanes;
pub use runs::{Job, Queue};

use crate::scalar::Scalar;

/// An autonomous field `y' = f(y)` of dimension `N`, written once for every [`Scalar`]: the
/// batch evaluates it on [`Lanes`] (all lanes at once) and on `f64` (one lane: the initial
/// step and the dense output).
pub trait Field<const N: usize> {
    /// `f(y)`.
    fn eval<D: Scalar>(&self, y: &[D; N]) -> [D; N];

    /// The unit of each component for a run from `y0`, as
    /// [`OdeSystem::units`](crate::OdeSystem::units) (the same for a lane and for the
    /// one-at-a-time run); all 1 by default.
    fn units(&self, _y0: &[f64; N]) -> crate::RunUnits<N> {
        crate::RunUnits::one()
    }
}
