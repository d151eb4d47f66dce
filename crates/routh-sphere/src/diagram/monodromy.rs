//! The monodromy of the tori around a focus–focus value (a vertical spin below Routh's
//! threshold), followed along a closed loop of regular values.
//!
//! On a torus the flow of (mg-eq) and the rotations about e3 commute; the pairs (t, phi) for
//! which "flow for t, then rotate by phi" is the identity form the period lattice. Its basis:
//! `b1 = (0, 2 pi)` (a full turn) and `b2 = (T, -Theta)`, T the nutation period and Theta the
//! advance of the azimuth psi of gamma per period (after T the state is the initial one
//! rotated by Theta). The rotation number is `W = Theta / (2 pi)`; Theta is defined modulo
//! 2 pi, and the lattice is what is smooth in the value.
//!
//! Along a loop `K = K0 + rho_K cos phi`, `H1 = H10 + rho_H sin phi` around the focus–focus
//! value (K0, H10) at fixed H3 (counter-clockwise in the (K, H1) plane), T and Theta come from
//! the quadrature ([`crate::quadrature::ExactSolution`]) at each point, and W is followed
//! continuously: each step adds the integer that makes the change of W smallest. Where W
//! changes by more than [`MAX_STEP`] (modulo 1) between neighbours, points are inserted by
//! bisection of the angle until it does not (so that the choice of the integer is
//! unambiguous). The loop is accepted when every point is a regular value with exactly one
//! torus; it is shrunk otherwise. Once around, W has changed by an integer k, and b2 has become `b2 + k b1`
//! (in the convention `b2 = (T, 2 pi W)`): the monodromy matrix, columns the images of b1 and
//! b2 in the basis (b1, b2), is `[[1, k], [0, 1]]`.
//!
//! The quadrature gives Theta modulo 2 pi (here in [0, 2 pi)); where that representative wraps
//! around is a convention of the formula, the continued W is not. Once around the focus–focus
//! value the continued W does not come back to its value: that is the monodromy.

use super::relative_equilibria::RelativeEquilibrium;
use super::stability::StabilityType;
use super::tori::{level_set_point, torus_count};
use super::value::Value;
use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::quadrature::{ExactSolution, Motion};
use crate::units::Units;
use serde::Serialize;
use std::f64::consts::PI;

/// The largest change of the continued rotation number W between two successive points of
/// the loop: a quarter turn, half the distance at which the integer added would be ambiguous.
pub const MAX_STEP: f64 = 0.25;

/// How many times the loop is halved in size before giving up.
const ATTEMPTS: usize = 6;

/// The most points of one loop (after the refinement).
pub const MAX_LOOP_POINTS: usize = 4096;

/// One value on the loop and its period lattice.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoopPoint {
    /// The angle phi of the loop.
    pub phi: f64,
    /// The value.
    #[serde(flatten)]
    pub value: Value,
    /// The nutation period T.
    pub period: f64,
    /// The advance Theta of psi per period from the quadrature, in [0, 2 pi).
    pub advance: f64,
    /// The rotation number followed continuously along the loop, `Theta / (2 pi) + n`.
    pub rotation_number: f64,
}

/// The monodromy around one focus–focus value.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Monodromy {
    /// The focus–focus relative equilibrium (a vertical spin).
    pub centre: RelativeEquilibrium,
    /// The semi-axes (rho_K, rho_H) of the loop.
    pub radii: (f64, f64),
    /// The values along the loop (counter-clockwise, phi from 0 to 2 pi, the first point
    /// repeated at the end).
    #[serde(rename = "loop")]
    pub points: Vec<LoopPoint>,
    /// The change k of W once around.
    pub winding: i64,
    /// The largest change of W between successive points.
    pub max_step: f64,
    /// The monodromy matrix `[[1, k], [0, 1]]` in the basis (b1, b2) of the period lattice.
    pub matrix: [[i64; 2]; 2],
    /// The basis of the period lattice the matrix is written in ([`LATTICE_BASIS`]).
    pub basis: [&'static str; 2],
    /// How the matrix acts ([`MATRIX_CONVENTION`]).
    pub convention: &'static str,
    /// The direction of the loop ([`LOOP_ORIENTATION`]).
    pub orientation: &'static str,
}

/// The basis of the period lattice in which [`Monodromy::matrix`] is written (module docs):
/// pairs (t, phi) such that flowing for t and then rotating about e3 by phi is the identity.
pub const LATTICE_BASIS: [&str; 2] = [
    "b1 = (t, phi) = (0, 2 pi): one turn of the rotation about e3",
    "b2 = (t, phi) = (T, 2 pi W): the nutation period T with the advance of the azimuth psi \
     of gamma over it, W the rotation number followed continuously along the loop",
];

/// How [`Monodromy::matrix`] acts on the basis [`LATTICE_BASIS`].
pub const MATRIX_CONVENTION: &str = "columns are the images of b1 and b2 after one turn of the \
     loop, written in the basis (b1, b2): b1 -> b1, b2 -> b2 + k b1 with k the change of W";

/// The direction of the monodromy loop.
pub const LOOP_ORIENTATION: &str = "counter-clockwise in the plane (K, H1) (K on the \
     horizontal axis, H1 on the vertical): K = K0 + rho_K cos phi, H1 = H10 + rho_H sin phi, \
     phi increasing";

impl LoopPoint {
    /// This point computed in `units`, in the body's units.
    pub fn back(&self, units: &Units) -> Self {
        LoopPoint {
            value: self.value.back(units),
            period: self.period * units.time(),
            ..*self
        }
    }
}

impl Monodromy {
    /// This monodromy computed in `units`, in the body's units.
    pub fn back(&self, units: &Units) -> Result<Self> {
        Ok(Monodromy {
            centre: self.centre.back(units)?,
            radii: (
                self.radii.0 * units.momentum(),
                self.radii.1 * units.energy(),
            ),
            points: self.points.iter().map(|p| p.back(units)).collect(),
            winding: self.winding,
            max_step: self.max_step,
            matrix: self.matrix,
            basis: self.basis,
            convention: self.convention,
            orientation: self.orientation,
        })
    }
}

/// T and Theta (in [0, 2 pi)) at a value with one torus.
fn lattice(body: &Body, value: Value) -> Result<Option<(f64, f64)>> {
    let count = torus_count(body, value)?;
    let [(u1, u2)] = count.intervals.as_slice() else {
        return Ok(None);
    };
    if count.critical {
        return Ok(None);
    }
    let red = value.reduction(body)?;
    let state = level_set_point(body, &red, 0.5 * (u1 + u2), 0.0, 1.0)?;
    let exact = ExactSolution::new(body, &state)?;
    Ok(match exact.motion {
        Motion::Nutation(nut) => Some((nut.period, nut.advance.rem_euclid(2.0 * PI))),
        Motion::Steady { .. } => None,
    })
}

/// The value at angle `phi` on the loop with semi-axes `radii` around `centre`, with its
/// period and advance (`None` when it is not regular with one torus).
fn loop_value(
    body: &Body,
    centre: Value,
    radii: (f64, f64),
    phi: f64,
) -> Result<Option<(f64, Value, f64, f64)>> {
    let value = Value {
        h1: centre.h1 + radii.1 * phi.sin(),
        h3: centre.h3,
        k: centre.k + radii.0 * phi.cos(),
    };
    Ok(lattice(body, value)?.map(|(period, advance)| (phi, value, period, advance)))
}

/// The distance of two rotation numbers modulo 1.
fn turn_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(1.0);
    d.min(1.0 - d)
}

/// The period lattice along the loop with semi-axes `radii` around the value `centre` (any
/// value, critical or not): `samples` points, more inserted by bisection wherever W changes by
/// more than [`MAX_STEP`] between neighbours (up to [`MAX_LOOP_POINTS`]), W followed
/// continuously; `None` when one of its values is not regular with one torus or the refinement
/// does not settle.
pub fn follow_loop(
    body: &Body,
    centre: Value,
    radii: (f64, f64),
    samples: usize,
) -> Result<Option<Vec<LoopPoint>>> {
    let mut raw = vec![];
    for i in 0..=samples {
        // Offset by half a step so that no point falls on the half-line K = K0 itself.
        let phi = 2.0 * PI * (i as f64 + 0.5) / samples as f64;
        let Some(point) = loop_value(body, centre, radii, phi)? else {
            return Ok(None);
        };
        raw.push(point);
    }
    let mut i = 0;
    while i + 1 < raw.len() {
        let (a, b) = (&raw[i], &raw[i + 1]);
        if turn_distance(a.3 / (2.0 * PI), b.3 / (2.0 * PI)) <= MAX_STEP {
            i += 1;
            continue;
        }
        if raw.len() >= MAX_LOOP_POINTS {
            return Ok(None);
        }
        let Some(point) = loop_value(body, centre, radii, 0.5 * (a.0 + b.0))? else {
            return Ok(None);
        };
        raw.insert(i + 1, point);
    }
    let mut points: Vec<LoopPoint> = vec![];
    for (phi, value, period, advance) in raw {
        let w = advance / (2.0 * PI);
        let rotation_number = match points.last() {
            None => w,
            Some(prev) => w + (prev.rotation_number - w).round(),
        };
        points.push(LoopPoint {
            phi,
            value,
            period,
            advance,
            rotation_number,
        });
    }
    Ok(Some(points))
}

/// The change of the continued rotation number from the first point of a closed loop to the
/// last (the same value), an integer.
pub fn winding(points: &[LoopPoint]) -> i64 {
    match (points.first(), points.last()) {
        (Some(a), Some(b)) => (b.rotation_number - a.rotation_number).round() as i64,
        _ => 0,
    }
}

/// The monodromy around the focus–focus vertical spin `centre`, along a loop of `samples`
/// points whose semi-axes start at `radii` (shrunk or refined until accepted, module docs).
pub fn monodromy(
    body: &Body,
    centre: &RelativeEquilibrium,
    radii: (f64, f64),
    samples: usize,
) -> Result<Monodromy> {
    if centre.stability != StabilityType::FocusFocus {
        return Err(RouthError::Singular {
            formula: "the monodromy",
            reason: format!(
                "the centre (K = {}, H1 = {}) is {}, not focus-focus",
                centre.value.k,
                centre.value.h1,
                centre.stability.name()
            ),
        });
    }
    let mut radii = radii;
    for _ in 0..ATTEMPTS {
        if let Some(points) = follow_loop(body, centre.value, radii, samples)? {
            let winding = winding(&points);
            let max_step = points
                .windows(2)
                .map(|w| (w[1].rotation_number - w[0].rotation_number).abs())
                .fold(0.0, f64::max);
            return Ok(Monodromy {
                centre: centre.clone(),
                radii,
                points,
                winding,
                max_step,
                matrix: [[1, winding], [0, 1]],
                basis: LATTICE_BASIS,
                convention: MATRIX_CONVENTION,
                orientation: LOOP_ORIENTATION,
            });
        }
        // A smaller loop, away from the critical curves.
        radii = (0.5 * radii.0, 0.5 * radii.1);
    }
    Err(RouthError::Singular {
        formula: "the monodromy",
        reason: format!(
            "no loop of regular values with one torus was found around K = {}, H1 = {} \
             (last tried: semi-axes {:?})",
            centre.value.k, centre.value.h1, radii
        ),
    })
}
