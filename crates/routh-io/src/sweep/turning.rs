//! The nutation seen along an integrated trajectory: the turning points of the tilt, found
//! as events, give theta min and max, the nutation period and the precession per period,
//! to compare with the quadrature of [`crate::quadrature`].
//!
//! gamma3 = cos theta turns where `d gamma3/dt = (gamma x omega)_3 = gamma1 omega2 -
//! gamma2 omega1` ([`tilt_rate`], mg-eq) changes sign; each sign change between the ends of
//! an accepted step is located on the step's dense output by the integrator's one event
//! locator, with the user's events of the run ([`super::crossings::Watch`]), and handed
//! here ([`TurningPoints::turn`]). A minimum of gamma3 (the largest tilt) marks the start of
//! a nutation period. The precession is the rotation of the state about e3 in the body
//! frame, the angle of (gamma1, gamma2), followed continuously from step to step: the
//! quadrature's "advance per period" is the same angle, since (mg-eq) with I1 = I2 is
//! symmetric under that rotation.

use crate::body::Body;

/// The rate d gamma3/dt at `x = (gamma, M)`: the event function of the turning points.
pub fn tilt_rate(body: &Body, x: &[f64; 6]) -> f64 {
    let gamma = [x[0], x[1], x[2]];
    let omega = body.angular_velocity(&gamma, &[x[3], x[4], x[5]]);
    gamma[0] * omega[1] - gamma[1] * omega[0]
}

/// The angle of (gamma1, gamma2) moved continuously from `previous` (the change between two
/// looks is taken in (-pi, pi]).
fn follow(previous: f64, x: &[f64; 6]) -> f64 {
    let angle = x[1].atan2(x[0]);
    let turn = (angle - previous).rem_euclid(std::f64::consts::TAU);
    previous
        + if turn > std::f64::consts::PI {
            turn - std::f64::consts::TAU
        } else {
            turn
        }
}

/// The turning points of the tilt met so far.
#[derive(Debug, Clone)]
pub struct TurningPoints {
    azimuth: f64,
    gamma3_min: f64,
    gamma3_max: f64,
    first_minimum: Option<(f64, f64)>,
    last_minimum: Option<(f64, f64)>,
    minima: u64,
}

/// What the turning points say about the nutation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NutationEvents {
    /// The smallest tilt theta met (at a turning point or at an end of the run).
    pub theta_min: f64,
    /// The largest tilt theta met.
    pub theta_max: f64,
    /// The mean time between successive largest tilts (None with fewer than two).
    pub period: Option<f64>,
    /// The mean rotation about e3 between successive largest tilts.
    pub precession: Option<f64>,
}

impl TurningPoints {
    /// Start at `x0 = (gamma, M)`.
    pub fn new(x0: &[f64; 6]) -> Self {
        TurningPoints {
            azimuth: x0[1].atan2(x0[0]),
            gamma3_min: x0[2],
            gamma3_max: x0[2],
            first_minimum: None,
            last_minimum: None,
            minima: 0,
        }
    }

    /// A turning point at time `t` and state `x` on the current step: a minimum of gamma3
    /// (the largest tilt) when `minimum` (the tilt rate was negative at the step's start).
    pub fn turn(&mut self, t: f64, x: &[f64; 6], minimum: bool) {
        self.gamma3_min = self.gamma3_min.min(x[2]);
        self.gamma3_max = self.gamma3_max.max(x[2]);
        if minimum {
            let at = (t, follow(self.azimuth, x));
            self.first_minimum.get_or_insert(at);
            self.last_minimum = Some(at);
            self.minima += 1;
        }
    }

    /// The end `y1` of an accepted step (after its turning point, if any).
    pub fn step_end(&mut self, y1: &[f64; 6]) {
        self.azimuth = follow(self.azimuth, y1);
        self.gamma3_min = self.gamma3_min.min(y1[2]);
        self.gamma3_max = self.gamma3_max.max(y1[2]);
    }

    /// The summary of the run.
    pub fn summary(&self) -> NutationEvents {
        let per_period = |f: fn(&(f64, f64)) -> f64| match (self.first_minimum, self.last_minimum) {
            (Some(a), Some(b)) if self.minima >= 2 => {
                Some((f(&b) - f(&a)) / (self.minima - 1) as f64)
            }
            _ => None,
        };
        NutationEvents {
            theta_min: self.gamma3_max.clamp(-1.0, 1.0).acos(),
            theta_max: self.gamma3_min.clamp(-1.0, 1.0).acos(),
            period: per_period(|p| p.0),
            precession: per_period(|p| p.1),
        }
    }
}
