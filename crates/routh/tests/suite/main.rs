//! The integration tests of the library, one test binary (each binary of its own linked the
//! library and instantiated its integrators again: one binary builds in a fraction of the
//! time). Run one module with `cargo test -p routh --test suite quadrature::`.

#[path = "../support/properties.rs"]
mod properties;
#[path = "../support/exact_sweep.rs"]
mod sweep_cases;

mod contact;
mod geometry;
mod integrators;
mod model;
mod quadrature;
mod scaling;
mod steady;
