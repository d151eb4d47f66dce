//! The claims registry: every computable claim of sections 2.1 to 4 of the paper, with its id,
//! its equation label, a one-line statement and a check that evaluates it at random points
//! (the claims themselves live in [`super::integrals`] and [`super::brackets`], their common
//! setting in [`super::claim`], re-exported here).

pub use super::claim::{
    body, field_of, free_body, generic_first, generic_firsts, h4, of, Claim, Outcome, Sample,
    Status, Verdict, CONSTANT_ALPHA, GENERIC_ALPHA, GENERIC_BETA, THRESHOLD, USER_ALPHA, USER_BETA,
};
pub use super::integrals::printed_h2_gravity;

/// Run every claim of [`registry`].
pub fn audit(sample: &Sample) -> Vec<Verdict> {
    registry().iter().map(|c| c.verdict(sample)).collect()
}

/// The claim with the given id.
pub fn find(id: &str) -> Option<Claim> {
    registry().into_iter().find(|c| c.id == id)
}

/// All claims, in the order of the paper.
pub fn registry() -> Vec<Claim> {
    let mut claims = super::integrals::claims();
    claims.extend(super::brackets::claims());
    claims
}
