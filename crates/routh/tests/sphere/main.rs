//! The Routh sphere's mathematics (routh-sphere): the quadrature against integration and reference values, steady motions, Poisson geometry, the audit of the paper's claims, the energy-momentum diagram.
//!
//! One test binary of several modules (issue 32: few binaries, each named after what it proves).

mod audit_claims;
mod audit_constructions;
mod diagram;
mod eq_cf;
mod exact_decisions;
mod exact_sweep;
mod flows;
mod quadrature;
mod quadrature_reference;
mod schouten;
mod steady;
#[path = "../support/exact_sweep.rs"]
mod sweep_cases;
