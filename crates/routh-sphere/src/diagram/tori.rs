//! The number of tori of a value (H1, H3, K): the connected components of the level set
//! `{H1, H3, K fixed, (gamma, gamma) = 1}` in the phase space (gamma, M).
//!
//! At a point of the level set with `|gamma3| < 1`, Routh's K fixes omega3, Jellett's H3 the
//! component omega_t along the horizontal direction of gamma, and the energy the square of the
//! remaining component, `omega_n^2 (1 - u^2) = Q(u)` ([`crate::quadrature::reduction`]). So the
//! level set lies over `{u : Q(u) >= 0}`, two points (omega_n of either sign) over every
//! gamma with `Q(u) > 0`, one where `Q(u) = 0`; the azimuth psi of gamma is free. Over a maximal
//! interval `[u1, u2]` of `Q >= 0` with simple roots at its ends, the two sheets join at both
//! ends: a circle in (u, omega_n) times the circle of psi, one torus. An end at a pole
//! (`Q(+-1) = 0`, `Q'(+-1) != 0`: the motion passes over the axis) gives a torus too (the
//! rotations about e3 act freely there, since omega_n != 0). `Q(+-1) <= 0` always (at a pole
//! Q is minus a sum of squares). Hence, at a regular value:
//!
//! **number of tori = number of maximal intervals of (-1, 1) where Q > 0.**
//!
//! Computed exactly from the critical points of Q: the roots of Q' in (-1, 1) (sign changes of
//! Q' on [`CRITICAL_POINT_SAMPLES`] tilts, refined by bisection) cut [-1, 1] into pieces on
//! which Q is monotone; each piece whose value rises from `<= 0` to `> 0` starts one interval.
//! The value is critical (a relative equilibrium on the level set) when Q has a double root:
//! a critical point of Q in (-1, 1) with `|Q| <= CRITICAL_TOLERANCE` times its round-off scale,
//! or a pole with both `Q` and `Q'` that small (a vertical spin).
//!
//! [`integrate_level_set`] checks a count independently: it integrates (mg-eq) with DOP853 from
//! points sampled on the level set and records the range of gamma3 each trajectory covers.

use super::value::{plane_rate, Value};
use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrate::{brent, Method};
use crate::problem::{Problem, Status};
use crate::quadrature::Reduction;
use crate::simulate::Settings;
use crate::state::{Normalise, State};
use crate::units::Units;
use serde::Serialize;
use std::f64::consts::PI;

/// Tilts (uniform in theta, denser in u near the poles) at which the sign of Q' is sampled.
/// Two roots of Q' closer than pi/4096 in theta would be missed: a local maximum and minimum
/// of Q that close differ by less than the round-off of Q except within 1e-7 of a cusp of the
/// critical set (checked by the integration in the tests).
pub const CRITICAL_POINT_SAMPLES: usize = 4096;

/// Multiple of the round-off scale of Q (the sum of the magnitudes of its terms times the
/// machine epsilon) below which a value of Q at a critical point counts as zero: a double
/// root, a critical value.
pub const CRITICAL_TOLERANCE: f64 = 1e3 * f64::EPSILON;

/// The level set of a value: the intervals of gamma3 of its tori, or critical.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TorusCount {
    /// The value.
    #[serde(flatten)]
    pub value: Value,
    /// The intervals `[u1, u2]` of gamma3 over which the tori lie, ascending.
    pub intervals: Vec<(f64, f64)>,
    /// Whether the value is critical (a double root of Q: the level set contains a relative
    /// equilibrium and is not a union of tori).
    pub critical: bool,
}

impl TorusCount {
    /// The number of tori (`None` at a critical value).
    pub fn tori(&self) -> Option<usize> {
        (!self.critical).then_some(self.intervals.len())
    }
}

/// The root of `f` in `[a, b]` where `f(a)` and `f(b)` have opposite signs (Brent's method to
/// full precision).
pub(crate) fn root(f: impl Fn(f64) -> f64, a: f64, b: f64, what: &'static str) -> Result<f64> {
    brent(f, a, b, 0.0, 200).ok_or_else(|| RouthError::Singular {
        formula: what,
        reason: format!("no root refined in [{a}, {b}]"),
    })
}

/// Halvings of the first tilt step toward each pole ([`critical_points`]): down to
/// `pi / 4096 / 2^48`, about 3e-18, below which `1 - |u|` is not resolved in f64.
const POLE_HALVINGS: i32 = 48;

/// The critical points of Q in (-1, 1), ascending: sign changes of Q' on
/// [`CRITICAL_POINT_SAMPLES`] equal steps of the tilt, and on steps halved toward each pole
/// ([`POLE_HALVINGS`]), where a motion within the first step of the axis has a critical point
/// and its neighbour closer than one step (the minimum of Q at an unstable steady precession
/// 4e-4 from the lower pole and the maximum beside it were both in the first step, and the
/// count called the critical value regular; tests/sphere/scaling.rs).
fn critical_points(red: &Reduction) -> Result<Vec<f64>> {
    let slope = |u: f64| red.q_derivatives(u).1;
    let step = PI / CRITICAL_POINT_SAMPLES as f64;
    let near_poles = (1..=POLE_HALVINGS).map(|k| step * 0.5f64.powi(k));
    let mut angles: Vec<f64> = (0..=CRITICAL_POINT_SAMPLES)
        .map(|i| PI * (1.0 - i as f64 / CRITICAL_POINT_SAMPLES as f64))
        .chain(near_poles.clone())
        .chain(near_poles.map(|d| PI - d))
        .collect();
    angles.sort_by(|a, b| b.total_cmp(a));
    // The halvings below the resolution of u give the poles themselves again: kept once.
    let mut tilts: Vec<f64> = angles.iter().map(|t| t.cos()).collect();
    tilts.dedup();
    let slopes: Vec<f64> = tilts.iter().map(|&u| slope(u)).collect();
    let mut points = vec![];
    for i in 0..tilts.len() - 1 {
        let (a, b) = (tilts[i], tilts[i + 1]);
        if slopes[i] == 0.0 && i > 0 {
            points.push(a);
        } else if slopes[i] * slopes[i + 1] < 0.0 {
            points.push(root(slope, a, b, "the critical points of Q")?);
        }
    }
    Ok(points)
}

/// What the turning points are roots of.
const TURNING: &str = "the turning points of Q";

/// Whether `q` is zero within the tolerance at `u`: against the round-off of Q's terms and
/// that of `u` itself, one ulp of which moves each term by its slope (the slopes cancel in
/// `Q'` at a critical point, not in the round-off). Near a pole the terms of Q vanish like
/// `1 - u^2` while their slopes do not, so the terms alone understate the round-off there:
/// the steady precession at tilt 0.01 of a balanced ball (a = 0, I1 = I3) left Q = 5e-21
/// above its double root, far above `q_scale` epsilons, and the count called its value
/// regular, with a torus of width 1.5e-10 (found by tests/sphere/scaling.rs).
fn negligible(red: &Reduction, u: f64, q: f64) -> bool {
    q.abs() <= CRITICAL_TOLERANCE * (red.q_scale(u) + u.abs() * red.q_slope_scale(u))
}

/// The tori of the value `value` of the body (I1 = I2), from the intervals where Q > 0,
/// computed in the units of the value's motion ([`value_units`]; in the body's units the
/// reduction's terms carry powers of m R^2 that overflow for large bodies) and returned with
/// `value` as given.
pub fn torus_count(body: &Body, value: Value) -> Result<TorusCount> {
    let units = value_units(body, value)?;
    let count = count_in_units(&units.body(body)?, value.in_units(&units))?;
    Ok(TorusCount { value, ..count })
}

/// The units of the motions of `value`: [`Units::with_rate`] with the fastest of the rates
/// its integrals give, that of the vertical spins of its H3 ([`plane_rate`]), `|K| / (m R^2)`
/// and `sqrt(|H1| / (m R^2))` (each scales as a rate with the body, so the count is
/// scale-free).
pub fn value_units(body: &Body, value: Value) -> Result<Units> {
    let inertia = Units::with_rate(body, 0.0).inertia();
    let rate = plane_rate(body, value.h3)?
        .max(value.k.abs() / inertia)
        .max((value.h1.abs() / inertia).sqrt());
    if !rate.is_finite() {
        return Err(RouthError::Singular {
            formula: "the units of a value of the integrals",
            reason: format!(
                "the rate of its motion is not finite at H1 = {}, H3 = {}, K = {}",
                value.h1, value.h3, value.k
            ),
        });
    }
    Ok(Units::with_rate(body, rate))
}

/// [`torus_count`] in the units of its arguments.
fn count_in_units(body: &Body, value: Value) -> Result<TorusCount> {
    let red = value.reduction(body)?;
    let mut nodes = vec![-1.0];
    nodes.extend(critical_points(&red)?);
    nodes.push(1.0);
    let values: Vec<f64> = nodes.iter().map(|&u| red.q(u)).collect();
    if values.iter().any(|v| !v.is_finite()) {
        return Err(RouthError::Singular {
            formula: "the reduced equation (du/dt)^2 = Q(u)",
            reason: format!(
                "Q is not finite at H1 = {}, H3 = {}, K = {}",
                value.h1, value.h3, value.k
            ),
        });
    }
    let interior_double = nodes[1..nodes.len() - 1]
        .iter()
        .zip(&values[1..])
        .any(|(&u, &q)| negligible(&red, u, q));
    let pole_double = [0, nodes.len() - 1].into_iter().any(|i| {
        let u = nodes[i];
        let (q, dq, _) = red.q_derivatives(u);
        negligible(&red, u, q) && dq.abs() <= CRITICAL_TOLERANCE * red.q_slope_scale(u)
    });
    let q = |u: f64| red.q(u);
    let mut intervals = vec![];
    let mut start = None;
    for i in 0..nodes.len() - 1 {
        let (a, b) = (nodes[i], nodes[i + 1]);
        let (qa, qb) = (values[i], values[i + 1]);
        if qa <= 0.0 && qb > 0.0 {
            start = Some(if qa == 0.0 {
                a
            } else {
                root(q, a, b, TURNING)?
            });
        }
        if qa > 0.0 && qb <= 0.0 {
            let end = if qb == 0.0 {
                b
            } else {
                root(q, a, b, TURNING)?
            };
            intervals.extend(start.take().map(|s| (s, end)));
        }
    }
    Ok(TorusCount {
        value,
        intervals,
        critical: interior_double || pole_double,
    })
}

/// A point of the level set of `red` at tilt `u` (where `Q(u) > 0`, `|u| < 1`), azimuth `psi`
/// and the sign `sign` of omega_n.
pub fn level_set_point(body: &Body, red: &Reduction, u: f64, psi: f64, sign: f64) -> Result<State> {
    let s = (1.0 - u * u).sqrt();
    let omega_n = sign * red.q(u).max(0.0).sqrt() / s;
    let (gamma, omega) = red.omega(u, s, psi, omega_n, red.jellett_quotient(u));
    State::from_omega(body, gamma, omega, Normalise::Reject)
}

/// One trajectory of the check by integration.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Excursion {
    /// The interval of Q > 0 the starting point lies over.
    pub start_interval: usize,
    /// The least and greatest gamma3 sampled along the trajectory.
    pub range: (f64, f64),
}

/// Integrate (mg-eq) (DOP853, rtol = atol = 1e-11) over `t_end` from `per_interval` points of
/// the level set over each interval of `count` (tilts spread over the interval, azimuths and
/// signs of omega_n alternating), sampling gamma3 `samples` times.
pub fn integrate_level_set(
    body: &Body,
    count: &TorusCount,
    per_interval: usize,
    t_end: f64,
    samples: usize,
) -> Result<Vec<Excursion>> {
    let red = count.value.reduction(body)?;
    let mut out = vec![];
    for (index, &(u1, u2)) in count.intervals.iter().enumerate() {
        for j in 0..per_interval {
            let fraction = (j as f64 + 0.5) / per_interval as f64;
            let u = u1 + (u2 - u1) * fraction;
            let sign = if j % 2 == 0 { 1.0 } else { -1.0 };
            let initial = level_set_point(body, &red, u, 2.0 * PI * fraction, sign)?;
            let settings = Settings::builder()
                .method(Method::Dop853)
                .t_end(t_end)
                .tolerances(1e-11, 1e-11)
                .samples(samples)
                .build()?;
            let solution = Problem {
                ball: crate::ball::AsBall::ball(body),
                initial,
                settings,
                event: None,
            }
            .solve()?;
            if solution.status != Status::Reached {
                return Err(RouthError::Singular {
                    formula: "the integration of the level set",
                    reason: solution.message,
                });
            }
            let range = solution
                .samples
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
                    (lo.min(s.state.gamma[2]), hi.max(s.state.gamma[2]))
                });
            out.push(Excursion {
                start_interval: index,
                range,
            });
        }
    }
    Ok(out)
}
