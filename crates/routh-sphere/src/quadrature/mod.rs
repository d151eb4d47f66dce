//! The exact solution of (mg-eq) for the Routh sphere (I1 = I2) by quadrature.
//!
//! With the energy H1 (int-g), Jellett's H3 (int) and Routh's K (raus-int) fixed, the tilt
//! obeys `(d gamma3/dt)^2 = Q(gamma3)` ([`reduction`]); the motion is a nutation between two
//! turning points, periodic up to a rotation about the symmetry axis, and the state at any
//! time costs the same as at the start ([`nutation`]). The derivation is in
//! `docs/quadrature.md`.

pub mod divided;
pub mod gauss;
pub mod nutation;
pub mod panels;
pub mod reduction;

pub use nutation::{Accuracy, ExactSolution, Motion, Nutation, NutationNumbers};
pub use reduction::Reduction;
