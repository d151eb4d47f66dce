//! A value (H1, H3, K) of the integrals: a point of the energy–momentum diagram, shared by
//! the relative equilibria ([`super::relative_equilibria`]), the count of tori
//! ([`super::tori`]) and the monodromy ([`super::monodromy`]).

use crate::body::Body;
use crate::error::Result;
use crate::integrals::{energy, jellett, routh_integral};
use crate::quadrature::Reduction;
use crate::state::State;
use crate::units::Units;
use serde::Serialize;

/// A value of the integrals (H1, H3, K) (the fourth, H4 = (gamma, gamma), is 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Value {
    /// Energy H1 (int-g).
    #[serde(rename = "H1")]
    pub h1: f64,
    /// Jellett's integral H3 (int).
    #[serde(rename = "H3")]
    pub h3: f64,
    /// Routh's integral K (raus-int).
    #[serde(rename = "K")]
    pub k: f64,
}

impl Value {
    /// The values of H1, H3, K at a state.
    pub fn of_state(body: &Body, state: &State) -> Self {
        let x = state.to_array();
        Value {
            h1: energy(body, &x),
            h3: jellett(body, &x),
            k: routh_integral(body, &x),
        }
    }

    /// This value in `units`: `H1 T^2 / (m R^2)`, `H3 T / (m R^3)`, `K T / (m R^2)`.
    pub fn in_units(&self, units: &Units) -> Value {
        Value {
            h1: self.h1 / units.energy(),
            h3: jellett_in_units(self.h3, units),
            k: self.k / units.momentum(),
        }
    }

    /// A value computed in `units`, in the body's units.
    pub fn back(&self, units: &Units) -> Value {
        Value {
            h1: self.h1 * units.energy(),
            h3: self.h3 * units.momentum() * units.length(),
            k: self.k * units.momentum(),
        }
    }

    /// The reduction `(du/dt)^2 = Q(u)` at this value.
    pub fn reduction(&self, body: &Body) -> Result<Reduction> {
        Reduction::new(body, self.h1, self.h3, self.k)
    }
}

/// Jellett's H3 = (M, r), an angular momentum times a length, in `units`: `H3 T / (m R^3)`.
pub fn jellett_in_units(h3: f64, units: &Units) -> f64 {
    h3 / units.momentum() / units.length()
}
