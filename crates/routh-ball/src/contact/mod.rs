//! Contact laws other than rolling without slipping: the same ball on another contact with
//! the plane. The rolling law of the paper is the rest of this crate ([`crate::field`]); this
//! module holds the other laws: [`rubber`], the ball that rolls without slipping or twisting
//! (the state is the rolling law's `(gamma, M)`, the field (mg-eq) plus the couple about the
//! normal that keeps `(omega, gamma) = 0`), [`sliding`], the ball that stays on the plane
//! while its contact point slips against a friction force (the tippe top of
//! Rauch-Wojciechowski and Rutstam), [`coulomb`], the run of a ball under Coulomb's friction
//! that switches between sliding and rolling, and [`reaction`], the force of the plane on the
//! rolling ball.
//!
//! A law is chosen by [`Contact`] (a case file's `[contact]` table), validated when built.

pub mod coulomb;
pub mod reaction;
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
    /// The ball stays on the plane and its contact point may slip, against the friction
    /// `friction` ([`sliding`]).
    Sliding {
        /// The friction law.
        friction: Friction,
        /// The coefficient mu >= 0: of `F = -mu N v_P` (viscous; of the dimension of time
        /// over length: a slip speed `1 / mu` makes the friction equal to the normal force),
        /// or of `|F| <= mu N` (Coulomb; dimensionless).
        mu: f64,
    },
}

/// The friction force of a sliding contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Friction {
    /// `F = -mu N v_P` (Rauch-Wojciechowski and Rutstam, SIGMA 10 (2014) 017, eq. (5)).
    Viscous,
    /// `F = -mu N v_P / |v_P|` while the contact slips; when the slip stops and the
    /// friction that rolling needs is at most `mu N`, the ball rolls (the paper's system)
    /// until it needs more ([`coulomb`]).
    Coulomb,
}

impl Friction {
    /// The law's name in a case file (`friction = "..."`).
    pub fn name(&self) -> &'static str {
        match self {
            Friction::Viscous => "viscous",
            Friction::Coulomb => "coulomb",
        }
    }

    /// The law of the name `name`, or `None`.
    pub fn named(name: &str) -> Option<Friction> {
        [Friction::Viscous, Friction::Coulomb]
            .into_iter()
            .find(|f| f.name() == name)
    }
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

    /// The sliding contact with the friction `friction` of coefficient `mu`, if finite and
    /// `>= 0` (`mu = 0`: a frictionless plane).
    pub fn sliding(friction: Friction, mu: f64) -> Result<Self> {
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(RouthError::Option {
                name: "mu",
                value: Number(mu).to_string(),
                rule: match friction {
                    Friction::Viscous => {
                        "must be finite and >= 0 (the coefficient of the viscous friction \
                         F = -mu N v_P)"
                    }
                    Friction::Coulomb => {
                        "must be finite and >= 0 (the coefficient of Coulomb's friction \
                         |F| <= mu N)"
                    }
                },
            });
        }
        Ok(Contact::Sliding { friction, mu })
    }
}
