//! The integration tests of the Routh sphere's mathematics (the crate routh-sphere through
//! the library): the quadrature, the steady motions, the Poisson geometry and the audit, the
//! answers' copies in other units. One binary beside `suite`, so that the two build on two
//! cores. Run one module with `cargo test -p routh --test sphere quadrature::`.

#[path = "../support/exact_sweep.rs"]
mod sweep_cases;

mod geometry;
mod quadrature;
mod scaling;
mod steady;
