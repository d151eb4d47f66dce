//! The mathematics of the Routh sphere (a [`Body`](routh_ball::Body): I1 = I2, the centre of
//! mass on the symmetry axis): the exact solution by quadrature ([`quadrature`]), the steady
//! motions and Routh's threshold ([`steady`]), the Poisson brackets and their checks
//! ([`poisson`]), the audit of the paper's claims ([`audit`]) and the energy-momentum diagram
//! as numbers ([`diagram`]). No figures and no files: those are the front ends'.
#![warn(missing_docs)]
// Checks are written `!(x <= limit)` on purpose, so that a NaN fails them too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod audit;
pub mod diagram;
pub mod poisson;
pub mod quadrature;
pub mod steady;

pub(crate) use routh_ball::{ball, body, error, field, integrals, problem, simulate, state, units};
pub(crate) use routh_integrate::{self as integrate, differential, sampling, scalar};
