//! Poincaré sections of a rolling ball: the crossings of runs of the reduced field (mg-eq)
//! with a plane `x_i = c` of one component of `x = (gamma, M)`, in a direction, computed by
//! the integrator layer ([`crate::integrate::section`]: DOP853 in SIMD lanes, Vern9 and RK4
//! one at a time, every crossing located by the one event locator), from many initial states
//! on one energy level ([`energy_family`]).
//!
//! The runs are not projected (the lanes do not project): each crossing's energy H1 is
//! compared with the level's, and its value of the plane's component with `c`, so that the
//! report says how well each crossing lies on both.

use crate::ball::AsBall;
use crate::error::{Result, RouthError};
use crate::integrals::energy;
use crate::integrate::section::{section, Point, Surface};
use crate::integrate::{Direction, Method, Options, Stats};
use crate::problem::Plane;
use crate::simulate::{ReducedSystem, Settings};
use crate::state::{Normalise, State};
use crate::units::Units;
use std::f64::consts::{FRAC_PI_4, PI};

/// The most initial states of a section ([`energy_family`]).
pub const MAX_INITIAL_STATES: usize = 10_000;

/// `count` initial states on the energy level of `x0 = (gamma, M)` (H1 as at `x0`): `x0`
/// first, then states of other tilts with the spin of `x0` rescaled onto the level.
///
/// State `k` (`1 <= k < count`) has gamma at the tilt `theta_k = theta_max k / count` from
/// e3, at the azimuth of `x0`'s gamma, where `theta_max = 2 theta_0` (`theta_0` the tilt of
/// `x0`), at least pi/4 and at most pi; its angular velocity is `s omega_0` (`omega_0` that of
/// `x0`, in the body frame), with `s > 0` such that H1 is the level's. M is linear in omega at
/// fixed gamma, so H1 is `s^2 T + V` with `V` its value at M = 0 (twice the potential energy,
/// (int-g)) and `T` the rest at `s = 1`: `s = sqrt((H1 - V) / T)`. A tilt at which the level
/// is below `V` (or a ball at rest, `T = 0`) has no such state and is left out: the list may
/// hold fewer than `count` states. `count` must be 1 to [`MAX_INITIAL_STATES`].
pub fn energy_family(ball: &impl AsBall, x0: &[f64; 6], count: usize) -> Result<Vec<[f64; 6]>> {
    if !(1..=MAX_INITIAL_STATES).contains(&count) {
        return Err(RouthError::Option {
            name: "initial",
            value: count.to_string(),
            rule: "must be from 1 to 10000",
        });
    }
    let start = crate::state::Point::from_array(x0);
    let level = energy(ball, x0);
    let omega = start.omega(ball);
    let [g1, g2, g3] = start.gamma;
    let azimuth = if g1 == 0.0 && g2 == 0.0 {
        0.0
    } else {
        g2.atan2(g1)
    };
    let theta_max = (2.0 * g3.clamp(-1.0, 1.0).acos()).clamp(FRAC_PI_4, PI);
    let mut starts = vec![*x0];
    for k in 1..count {
        let theta = theta_max * k as f64 / count as f64;
        let gamma = [
            theta.sin() * azimuth.cos(),
            theta.sin() * azimuth.sin(),
            theta.cos(),
        ];
        let spun = State::from_omega(ball, gamma, omega, Normalise::Rescale)?.to_array();
        let at_rest = [spun[0], spun[1], spun[2], 0.0, 0.0, 0.0];
        let potential = energy(ball, &at_rest);
        let kinetic = energy(ball, &spun) - potential;
        let s = ((level - potential) / kinetic).sqrt();
        if s.is_finite() && s > 0.0 {
            starts.push(std::array::from_fn(|i| {
                if i < 3 {
                    spun[i]
                } else {
                    s * spun[i]
                }
            }));
        }
    }
    Ok(starts)
}

/// A Poincaré section of a ball ([`ball_section`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BallSection {
    /// The crossings, ordered by run and time (`run`: the index into the initial states).
    pub points: Vec<Point<6>>,
    /// The work of all the runs.
    pub stats: Stats,
    /// The energy H1 of the first initial state: the level.
    pub energy: f64,
    /// The largest `|H1 - level| / |level|` over the crossings (0 without crossings).
    pub max_energy_drift: f64,
    /// The largest `|x_i - c|` over the crossings, in the units of the problem.
    pub max_surface_value: f64,
    /// The unit of the plane's component in the run from the first initial state
    /// ([`Units::of_reduced`]: 1 for gamma, the motion's unit of angular momentum for M): the
    /// scale against which `max_surface_value` is small.
    pub surface_unit: f64,
}

/// The crossings of the runs of `ball` from each of `starts` (the first one's energy the
/// level) with the `plane` in `direction`, over `[0, settings.t_end()]` with the
/// method, tolerances and step limit of `settings` (its samples and projection not used).
/// Refused by name ([`RouthError::Option`]): no initial state, a method other than DOP853,
/// Vern9 or RK4 (the Taylor method and
/// `auto`: the section runs the field as written, not its recorded tape).
pub fn ball_section(
    ball: &impl AsBall,
    starts: &[[f64; 6]],
    settings: &Settings,
    plane: &Plane,
    direction: Direction,
) -> Result<BallSection> {
    let Some(first) = starts.first() else {
        return Err(RouthError::Option {
            name: "initial",
            value: "0".into(),
            rule: "a section needs one initial state at least",
        });
    };
    if !matches!(
        settings.method(),
        Method::Dop853 | Method::Vern9 | Method::Rk4 { .. }
    ) {
        return Err(RouthError::Option {
            name: "method",
            value: settings.method().to_string(),
            rule: "must be dop853, vern9 or rk4 for a section",
        });
    }
    let opts =
        Options::new(settings.rtol(), settings.atol())?.with_max_steps(settings.max_steps())?;
    let plane = *plane;
    let g = move |x: &[f64; 6]| plane.level(x);
    let surface = Surface { g: &g, direction };
    let found = section(
        &ReducedSystem(ball),
        starts,
        settings.t_end(),
        settings.method(),
        &opts,
        &surface,
    )?;
    let level = energy(ball, first);
    let largest = |f: &dyn Fn(&Point<6>) -> f64| found.points.iter().map(f).fold(0.0, f64::max);
    Ok(BallSection {
        max_energy_drift: largest(&|p| ((energy(ball, &p.y) - level) / level).abs()),
        max_surface_value: largest(&|p| g(&p.y).abs()),
        surface_unit: Units::of_reduced(ball, first).components[plane.component()],
        energy: level,
        points: found.points,
        stats: found.stats,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lyapunov::tests::routh_sphere;

    /// Every state of the family is on the level to 1e-13 relative (the rescaling's
    /// round-off), on `|gamma| = 1`, and the first is the case's; their tilts differ.
    /// Negative control: the family before rescaling (s = 1) is off the level by far.
    #[test]
    fn the_family_lies_on_one_energy_level() {
        let (body, x) = routh_sphere();
        let family = energy_family(&body, &x, 12).unwrap();
        assert_eq!(family.len(), 12);
        assert_eq!(family[0], x);
        let level = energy(&body, &x);
        for y in &family {
            assert!(((energy(&body, y) - level) / level).abs() < 1e-13);
            assert!((y[0] * y[0] + y[1] * y[1] + y[2] * y[2] - 1.0).abs() < 1e-15);
        }
        assert!(family.windows(2).all(|w| w[0][2] != w[1][2]));
        let unscaled =
            State::from_omega(&body, [0.0, 0.0, 1.0], [0.5, 0.2, 8.0], Normalise::Reject)
                .unwrap()
                .to_array();
        assert!(((energy(&body, &unscaled) - level) / level).abs() > 1e-2);
        assert!(matches!(
            energy_family(&body, &x, 0),
            Err(RouthError::Option {
                name: "initial",
                ..
            })
        ));
    }
}
