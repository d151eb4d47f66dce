//! The model of a rolling ball (routh-ball): the field against automatic differentiation, the integrals and the invariant measure, the motion in space, runs, case files, properties of hostile inputs.
//!
//! One test binary of several modules (issue 32: few binaries, each named after what it proves).

mod ball;
mod case_file;
mod field_identities;
mod fuzz_properties;
mod model_integrals;
mod motion;
mod problem;
#[path = "../support/properties.rs"]
mod properties;
mod simulate;
