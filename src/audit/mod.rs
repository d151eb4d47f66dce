//! The audit of the paper's claims (issue 4): the generic checks, the registry of claims of
//! sections 2.1 to 4, and the rendering of the verdicts as a table, JSON or a markdown report.

pub mod brackets;
pub mod checks;
pub mod claims;
pub mod report;
