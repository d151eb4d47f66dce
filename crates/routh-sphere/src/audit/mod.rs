//! The audit of the paper's claims (issue 4): the generic checks, the claims of sections 2.1
//! to 4 with their common setting, the registry, and the rendering of the verdicts as a table,
//! JSON or a markdown report.
//!
//! Layout (no module imports one that imports it back): [`claim`] (the claim, its verdict, the
//! points, the body) and [`checks`] are used by the groups of claims [`integrals`] and
//! [`brackets`]; [`claims`] assembles the registry from the groups; [`report`] renders it.

pub mod brackets;
pub mod checks;
pub mod claim;
pub mod claims;
pub mod integrals;
pub mod report;
