//! Points of the reduced phase space x = (gamma, M) of (m-eq).

use crate::ball::AsBall;
use crate::error::{Result, RouthError};
use serde::Serialize;

/// How far from 1 the length of gamma may be before it is rejected (unless normalised).
pub const UNIT_TOLERANCE: f64 = 1e-12;

/// A state of the reduced system, validated when it is built: the unit normal `gamma`
/// (pointing into the plane, body frame) and the angular momentum `M` about the contact point
/// (body frame), all finite, |gamma| = 1 within [`UNIT_TOLERANCE`]. Its fields are private,
/// so that no `State` breaks these rules: it is what a run, a quadrature or a steady motion
/// starts from. A point that a computation reached (an integrator's step, a sample of a
/// quadrature), which keeps |gamma| = 1 only to its own accuracy, is a [`Point`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct State {
    gamma: [f64; 3],
    #[serde(rename = "M")]
    m: [f64; 3],
}

/// A point of the reduced phase space as a computation reached it (the end of a run, a
/// sample of an integrator's dense output or of the exact solution): `gamma` and `M` as they
/// were computed, with no rule of their own (|gamma| = 1 holds to the computation's accuracy).
/// [`State::of_point`] validates one as a start.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Point {
    /// The normal of the plane in the body frame.
    pub gamma: [f64; 3],
    /// The angular momentum about the contact point, (om-m).
    #[serde(rename = "M")]
    pub m: [f64; 3],
}

impl Point {
    /// The point of a phase-space array `[gamma1, gamma2, gamma3, M1, M2, M3]`.
    pub fn from_array(x: &[f64; 6]) -> Self {
        Point {
            gamma: [x[0], x[1], x[2]],
            m: [x[3], x[4], x[5]],
        }
    }

    /// The phase-space point as `[gamma1, gamma2, gamma3, M1, M2, M3]`.
    pub fn to_array(&self) -> [f64; 6] {
        [
            self.gamma[0],
            self.gamma[1],
            self.gamma[2],
            self.m[0],
            self.m[1],
            self.m[2],
        ]
    }

    /// The angular velocity `omega = I_Q^{-1} M` (om-m).
    pub fn omega(&self, body: &impl AsBall) -> [f64; 3] {
        body.ball().angular_velocity(&self.gamma, &self.m)
    }

    /// The time-reversed point (gamma, -M): the field (mg-eq) is reversible under
    /// `(gamma, M, t) -> (gamma, -M, -t)`.
    pub fn reversed(&self) -> Self {
        Point {
            gamma: self.gamma,
            m: self.m.map(|v| -v),
        }
    }
}

impl From<State> for Point {
    fn from(state: State) -> Point {
        Point {
            gamma: state.gamma,
            m: state.m,
        }
    }
}

/// Whether to accept a gamma whose length is not 1 by rescaling it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Normalise {
    /// Reject |gamma| - 1 beyond [`UNIT_TOLERANCE`].
    #[default]
    Reject,
    /// Rescale gamma to unit length (gamma must still be finite and non-zero; any finite size
    /// is rescaled without overflow).
    Rescale,
}

impl State {
    /// A state from gamma and M, validated: all finite, |gamma| = 1 within [`UNIT_TOLERANCE`]
    /// unless `normalise` asks to rescale.
    pub fn new(gamma: [f64; 3], m: [f64; 3], normalise: Normalise) -> Result<Self> {
        let gamma = checked_gamma(gamma, normalise)?;
        check_finite("M", &m)?;
        Ok(State { gamma, m })
    }

    /// A state from gamma and the angular velocity omega, via `M = I_Q omega` (om-m).
    pub fn from_omega(
        body: &impl AsBall,
        gamma: [f64; 3],
        omega: [f64; 3],
        normalise: Normalise,
    ) -> Result<Self> {
        let gamma = checked_gamma(gamma, normalise)?;
        check_finite("omega", &omega)?;
        Ok(State {
            gamma,
            m: body.ball().angular_momentum(&gamma, &omega),
        })
    }

    /// A reached point validated as a state: [`State::new`] of its gamma and M.
    pub fn of_point(point: &Point, normalise: Normalise) -> Result<Self> {
        State::new(point.gamma, point.m, normalise)
    }

    /// A state of a phase-space array `[gamma1, gamma2, gamma3, M1, M2, M3]`, validated
    /// ([`State::new`]).
    pub fn of_array(x: &[f64; 6], normalise: Normalise) -> Result<Self> {
        State::of_point(&Point::from_array(x), normalise)
    }

    /// The unit normal of the plane in the body frame.
    pub fn gamma(&self) -> [f64; 3] {
        self.gamma
    }

    /// The angular momentum about the contact point, (om-m).
    pub fn m(&self) -> [f64; 3] {
        self.m
    }

    /// The same state as a [`Point`] (a record with public fields).
    pub fn point(&self) -> Point {
        Point::from(*self)
    }

    /// The phase-space point as `[gamma1, gamma2, gamma3, M1, M2, M3]`.
    pub fn to_array(&self) -> [f64; 6] {
        self.point().to_array()
    }

    /// The angular velocity `omega = I_Q^{-1} M`.
    pub fn omega(&self, body: &impl AsBall) -> [f64; 3] {
        self.point().omega(body)
    }
}

fn check_finite(name: &str, v: &[f64; 3]) -> Result<()> {
    if v.iter().all(|c| c.is_finite()) {
        Ok(())
    } else {
        Err(RouthError::State(format!(
            "{name} = {v:?} has a non-finite component"
        )))
    }
}

/// `gamma` validated (finite; of unit length within [`UNIT_TOLERANCE`], or rescaled to it
/// with [`Normalise::Rescale`]). The length is computed with the largest component divided
/// out first, so that neither its squares overflow (1e200) nor underflow (1e-200).
fn checked_gamma(gamma: [f64; 3], normalise: Normalise) -> Result<[f64; 3]> {
    check_finite("gamma", &gamma)?;
    let largest = gamma.iter().fold(0.0_f64, |a, c| a.max(c.abs()));
    if largest == 0.0 {
        return Err(RouthError::State(format!(
            "gamma = {gamma:?} has length 0 and cannot be normalised: the normal of the plane \
             must be a non-zero vector"
        )));
    }
    let direction = gamma.map(|c| c / largest);
    let length = direction.iter().map(|c| c * c).sum::<f64>().sqrt();
    match normalise {
        Normalise::Reject if (largest * length - 1.0).abs() > UNIT_TOLERANCE => {
            Err(RouthError::State(format!(
                "gamma = {gamma:?} is not a unit vector: |gamma| - 1 = {:.3e} exceeds {UNIT_TOLERANCE:e} \
                 (normalize = true in a case's [initial] table, or normalize=True in Python, rescales it)",
                largest * length - 1.0
            )))
        }
        Normalise::Reject => Ok(gamma),
        Normalise::Rescale => Ok(direction.map(|c| c / length)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression (issue 33): gamma = [1e200, 1e200, 0] with `normalize = true` ran with
    /// gamma = [0, 0, 0], the sum of its squares having overflowed. Its length is now taken
    /// with the largest component divided out: the direction is kept, to an ulp.
    #[test]
    fn a_huge_or_tiny_gamma_is_normalised_without_overflow() {
        let half = std::f64::consts::FRAC_1_SQRT_2;
        for size in [1e200, 1e-200, f64::MAX, 5e-324] {
            let state = State::new([size, size, 0.0], [0.0; 3], Normalise::Rescale).unwrap();
            for (got, want) in state.gamma().iter().zip([half, half, 0.0]) {
                assert!(
                    (got - want).abs() <= f64::EPSILON,
                    "{size}: {:?}",
                    state.gamma()
                );
            }
        }
        // Controls: a unit gamma is kept, to the bit or to an ulp.
        let unit = [0.0, 0.0, 1.0];
        assert_eq!(
            State::new(unit, [0.0; 3], Normalise::Rescale)
                .unwrap()
                .gamma(),
            unit
        );
        let unit = [0.6, 0.0, 0.8];
        let kept = State::new(unit, [0.0; 3], Normalise::Rescale)
            .unwrap()
            .gamma();
        assert!(
            (0..3).all(|i| (kept[i] - unit[i]).abs() <= f64::EPSILON),
            "{kept:?}"
        );
    }

    /// A gamma of length 0 or with a non-finite component is refused, named with its value
    /// and the rule, whether it is to be normalised or not; so is a huge one not normalised.
    #[test]
    fn a_gamma_of_zero_or_infinite_length_is_refused() {
        for normalise in [Normalise::Rescale, Normalise::Reject] {
            let e = State::new([0.0; 3], [0.0; 3], normalise)
                .unwrap_err()
                .to_string();
            assert!(
                e.contains("gamma = [0.0, 0.0, 0.0] has length 0") && e.contains("non-zero"),
                "{e}"
            );
            let e = State::new([f64::INFINITY, 0.0, 0.0], [0.0; 3], normalise)
                .unwrap_err()
                .to_string();
            assert!(
                e.contains("gamma = [inf, 0.0, 0.0] has a non-finite"),
                "{e}"
            );
        }
        let e = State::new([1e200, 1e200, 0.0], [0.0; 3], Normalise::Reject)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("not a unit vector: |gamma| - 1 = 1.414e200"),
            "{e}"
        );
    }

    /// A reached point becomes a state only by the rules of a state: a gamma 1e-9 off unit
    /// length is refused (naming the rule) unless rescaled, and then only gamma changes; a
    /// non-finite M is refused either way. The state's point is the point, to the bit.
    #[test]
    fn a_point_is_a_state_only_within_the_rules() {
        let point = Point {
            gamma: [0.0, 0.0, 1.0 + 1e-9],
            m: [1.0, -2.0, 3.0],
        };
        let e = State::of_point(&point, Normalise::Reject)
            .unwrap_err()
            .to_string();
        assert!(e.contains("not a unit vector"), "{e}");
        let state = State::of_point(&point, Normalise::Rescale).unwrap();
        assert_eq!(state.gamma(), [0.0, 0.0, 1.0]);
        assert_eq!(state.m(), point.m);
        let unit = Point {
            gamma: [0.6, 0.0, 0.8],
            ..point
        };
        assert_eq!(
            State::of_point(&unit, Normalise::Reject).unwrap().point(),
            unit
        );
        let infinite = Point {
            m: [f64::INFINITY, 0.0, 0.0],
            ..unit
        };
        for normalise in [Normalise::Reject, Normalise::Rescale] {
            let e = State::of_point(&infinite, normalise)
                .unwrap_err()
                .to_string();
            assert!(e.contains("M = [inf, 0.0, 0.0] has a non-finite"), "{e}");
        }
    }
}
