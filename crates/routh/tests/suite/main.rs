//! The integration tests of the integrators and the model, one test binary (each binary
//! links the library and instantiates its integrators again); those of the Routh sphere's
//! mathematics are the binary `sphere`, built beside this one on the second core. Run one
//! module with `cargo test -p routh --test suite integrators::`.

#[path = "../support/properties.rs"]
mod properties;

mod contact;
mod integrators;
mod model;
