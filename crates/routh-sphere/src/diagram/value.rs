//! A value (H1, H3, K) of the integrals: a point of the energy–momentum diagram, and the
//! units of the diagram's plane at one H3 ([`plane_units`]), shared by
//! the relative equilibria ([`super::relative_equilibria`]), the count of tori
//! ([`super::tori`]) and the monodromy ([`super::monodromy`]).

use crate::body::Body;
use crate::error::Result;
use crate::integrals::{energy, jellett, routh_integral};
use crate::quadrature::Reduction;
use crate::state::State;
use crate::steady::vertical_spin_state;
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

/// The spin rate of the faster vertical spin at Jellett's `h3` (`|h3 / H3(w = 1)|`, H3
/// linear in the spin at each pole).
pub fn plane_rate(body: &Body, h3: f64) -> Result<f64> {
    [1.0, -1.0].into_iter().try_fold(0.0_f64, |rate, pole| {
        let unit = vertical_spin_state(body, pole, 1.0)?;
        Ok(rate.max((h3 / jellett(body, &unit.to_array())).abs()))
    })
}

/// The units of the plane at Jellett's `h3` ([`Units::with_rate`] with [`plane_rate`]): in
/// them the faster of the fall and the vertical spins is 1.
pub fn plane_units(body: &Body, h3: f64) -> Result<Units> {
    Ok(Units::with_rate(body, plane_rate(body, h3)?))
}
