//! Contact laws other than rolling without slipping: the same ball on another contact with
//! the plane. The rolling law of the paper is the rest of this crate ([`crate::field`]); this
//! module holds the other laws: [`rubber`], the ball that rolls without slipping or twisting
//! (the state is the rolling law's `(gamma, M)`, the field (mg-eq) plus the couple about the
//! normal that keeps `(omega, gamma) = 0`), and [`sliding`], the ball that stays on the plane
//! while its contact point slips against a viscous friction force (the tippe top of
//! Rauch-Wojciechowski and Rutstam).
//!
//! A law is chosen by [`Contact`] (a case file's `[contact]` table), validated when built.

pub mod rubber;
pub mod sliding;

use crate::error::{Number, Result, RouthError};
use serde::Serialize;

/// The contact law of a ball with the plane, validated when built ([`Contact::sliding`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "law", rename_all = "lowercase")]
pub enum Contact {
    /// Rolling without slipping: the paper's system (mg-eq), the default.
    Rolling,
    /// Rolling without slipping or twisting: `(omega, gamma) = 0` added to the constraint
    /// ([`rubber`]).
    Rubber,
    /// The ball stays on the plane and its contact point may slip, against the viscous
    /// friction `F = -mu N v_P` ([`sliding`]).
    Sliding {
        /// The friction law (viscous: the only one so far).
        friction: Friction,
        /// The coefficient mu >= 0 of `F = -mu N v_P`, of the dimension of time over length
        /// (a slip speed `1 / mu` makes the friction equal to the normal force).
        mu: f64,
    },
}

/// The friction force of a sliding contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Friction {
    /// `F = -mu N v_P` (Rauch-Wojciechowski and Rutstam, SIGMA 10 (2014) 017, eq. (5)).
    Viscous,
}

impl Contact {
    /// The law's name in a case file (`law = "..."`).
    pub fn law(&self) -> &'static str {
        match self {
            Contact::Rolling => "rolling",
            Contact::Rubber => "rubber",
            Contact::Sliding { .. } => "sliding",
        }
    }

    /// The viscous sliding contact of coefficient `mu`, if finite and `>= 0` (`mu = 0`: a
    /// frictionless plane).
    pub fn sliding(mu: f64) -> Result<Self> {
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(RouthError::Option {
                name: "mu",
                value: Number(mu).to_string(),
                rule: "must be finite and >= 0 (the coefficient of the viscous friction \
                       F = -mu N v_P)",
            });
        }
        Ok(Contact::Sliding {
            friction: Friction::Viscous,
            mu,
        })
    }
}
