//! The nutation of the tilt between its turning points, its period, the advance of the
//! precession angle per period, and the state at any time in a cost independent of t.
//!
//! On a nutation `u1 <= u = gamma3 <= u2` the substitution
//! `u = (u1 + u2)/2 - (u2 - u1)/2 cos sigma` removes the inverse-square-root singularities of
//! `dt = du / sqrt(Q(u))` at the turning points: with `Q(u) = (u - u1)(u2 - u) P(u)`,
//! `dt/dsigma = f(sigma) = 1 / sqrt(P(u(sigma)))`, an analytic, even, 2 pi-periodic function
//! of sigma (one period of sigma is one nutation: up on `(0, pi)`, down on `(pi, 2 pi)`).
//! Its cosine series `f = c0/2 + sum c_k cos k sigma`, computed from samples at the Chebyshev
//! (midpoint) nodes `sigma_j = (j + 1/2) pi / n`, converges geometrically; it integrates in
//! closed form, `t(sigma) = c0 sigma / 2 + sum c_k sin(k sigma) / k`, so the period is
//! `T = pi c0` and t(sigma) is inverted by Newton's method. The precession angle is the
//! integral of `dpsi/dt f(sigma)` in the same way, with advance `pi b0` per period, and so is
//! the azimuth phi of the symmetry axis e3 in space (`docs/quadrature.md`, section 3).
//!
//! **Units.** [`ExactSolution::new`] makes the problem dimensionless once, at its entry, in the
//! units of [`Units`] (R, m and T, the faster of the fall and the spin, each rounded to a
//! power of two so that the conversion is exact), and converts every
//! result back at its API: so each tolerance, threshold and decision below is taken in those
//! units, where the scales of the problem are 1, and the same motion written in other units
//! gets the same answer.

use crate::body::Body;
use crate::differential::jacobian;
use crate::error::{Result, RouthError};
use crate::field::vector_field;
use crate::integrate::brent;
use crate::quadrature::panels::{Piecewise, Sample};
use crate::quadrature::reduction::{frame_index, omega_round_off, Reduction};
use crate::state::{Point, State};
use crate::steady::{max_real_eigenvalue, require_finite_inertia, EIGENVALUE_TOLERANCE};
use crate::units::Units;
use std::f64::consts::{PI, TAU};

/// Most samples spent on the panels of one nutation (a count: the same in any units); a level
/// set that needs more lies within
/// the resolution of f64 of a separatrix (or passes the axis closer than psi can be followed).
/// Bisection toward a near-singularity at distance epsilon costs about
/// `2 PANEL_NODES log2(1/epsilon)` samples, so this allows epsilon down to 1e-30. In the fuzz
/// build (`cfg(fuzzing)`, set by `cargo fuzz`) a tenth: the inputs that exhaust it are refused
/// sooner, by the same code (docs/reliability.md, Fuzzing).
const SAMPLE_BUDGET: usize = if cfg!(fuzzing) { 640 } else { 6400 };
/// Above this width `u2 - u1` the cofactor P is computed from first divided differences of Q
/// (accurate over long intervals), below it from the second derivative (no cancellation). A
/// width in `u = gamma3`, a cosine: dimensionless.
const WIDE_NUTATION: f64 = 1.0 / 16.0;
/// First step of the outward search for the turning points, relative to the distance x0 of
/// the start from the pole (x is dimensionless, and known to its relative round-off).
const FIRST_SEARCH_STEP: f64 = 1e-8;
/// Largest step of that search in x (dimensionless; Q is smooth; a pair of roots closer than
/// this is not sought).
const MAX_SEARCH_STEP: f64 = 1.0 / 128.0;
/// A state is a relative equilibrium when the part of the field (mg-eq) not tangent to the
/// rotations about e3 is below this many machine epsilons of `|J| |x|` (the round-off scale of
/// the field: J is its Jacobian, x the state). Both are taken in the problem's units, where
/// gamma and M are dimensionless: in any other units `|x|` mixes gamma (1) with M (of the size
/// of m R^2 / T), and the test answered "steady" for the default case with m, I scaled by 1e12.
const RELATIVE_EQUILIBRIUM_EPSILONS: f64 = 64.0;
/// A turning point is a double root of Q (a separatrix) when the round-off of Q moves it by
/// more than `1 / SEPARATRIX_MARGIN` of its distance to the other root of the local quadratic
/// of Q (a ratio of two distances in u: dimensionless): the round-off is an estimate of its
/// typical size, not a bound, and a double root within a few such sizes cannot be told from a
/// separatrix.
const SEPARATRIX_MARGIN: f64 = 16.0;

/// A nutation: the tilt oscillates between `u1` and `u2`, the whole state is periodic up to
/// a rotation about e3 by `advance` per period. Its public numbers are in the problem's units;
/// it is computed in the dimensionless problem of `units` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Nutation {
    /// The reduction of the dimensionless problem.
    reduction: Reduction,
    /// The units of the problem, in which `reduction` is dimensionless.
    units: Units,
    /// Lower turning point of gamma3 = cos theta.
    pub u1: f64,
    /// Upper turning point of gamma3.
    pub u2: f64,
    /// Whether the upper turning point is the pole gamma3 = 1 (the motion crosses the axis).
    pub through_top: bool,
    /// Whether the lower turning point is the pole gamma3 = -1.
    pub through_bottom: bool,
    /// `1 - u2` and `1 + u1`, accurate near the poles (see `Turning`).
    gap_top: f64,
    gap_bottom: f64,
    /// `u2 - u1`, to the relative round-off of the turning points' distances from the pole
    /// (see `Turnings`).
    width: f64,
    /// Nutation period T, in the problem's units of time.
    pub period: f64,
    /// Advance per period of the precession angle psi: the azimuth of gamma (the vertical)
    /// about e3 in the body frame, measured from e1 toward e2 (radians). Not the precession of
    /// the symmetry axis in space (`axis_advance`). For a motion through the axis, that of the
    /// continuation with a signed sin theta: the azimuth itself jumps by pi at each passage.
    pub advance: f64,
    /// Advance per period of the azimuth phi of the symmetry axis e3 in space (the fixed frame,
    /// z up, measured from x toward y, radians): `dphi/dt = -N(u) / (A R (1 - u^2))`
    /// (docs/quadrature.md, section 3). For a motion through the axis the azimuth jumps by pi
    /// at each passage (the axis passes through the vertical): the advance is then defined
    /// modulo 2 pi only, and given in `[0, 2 pi)`.
    pub axis_advance: f64,
    /// Number of samples (Chebyshev nodes of all panels) kept.
    pub nodes: usize,
    /// Estimated relative error of the period: the truncation and round-off of its series and
    /// the round-off of the turning points.
    pub period_error: f64,
    /// Estimated absolute error of the advance per period (radians).
    pub advance_error: f64,
    /// `dt/dsigma`, `dpsi/dsigma` and `dphi/dsigma` (less their pole parts) on `[0, pi]`, in
    /// the dimensionless problem.
    series: Piecewise,
    /// Whether the cofactor is that of a narrow nutation: `u2 - u1 <= WIDE_NUTATION`.
    narrow: bool,
    /// The round-off scale of `dQ/dx` at the upper and at the lower turning point, in the
    /// frame of the top and of the bottom pole ([`Reduction::q_scales_in_frame`]): part of the
    /// round-off of every sample of a wide nutation's cofactor, computed once.
    end_slope_scales: [f64; 2],
    /// Phase sigma of the initial state.
    sigma0: f64,
    /// The size of M (dimensionless) against which the relative error of M is measured: that
    /// of the initial state, or the largest along the nutation for a start at rest in f64
    /// (see `Nutation::new`).
    momentum_scale: f64,
    /// The poles `p = +-1` the motion does not pass through, each with the strength
    /// `c_p = p N(p) f(p) / (2 A R)` of the part of `dpsi/dsigma` singular there (that of
    /// `dphi/dsigma` is `-p c_p`; see `pole_angles`).
    poles: Vec<(f64, f64)>,
    /// psi - Psi(sigma) on the initial period.
    psi_ref: f64,
}

/// The motion of a given initial state, solved by quadrature.
// One `Motion` per solution, built once: boxing the nutation would cost an indirection on
// every state evaluation and save nothing that matters.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum Motion {
    /// A steady motion: theta constant, the state rotating about e3 at the constant rate
    /// `precession` (a double root of Q; on the axis, the vertical spin).
    Steady {
        /// gamma3 = cos theta.
        u: f64,
        /// d psi / dt, in radians per unit of the problem's time: the rate of the azimuth of
        /// gamma about e3 in the body frame, not the precession of the symmetry axis in space
        /// ([`ExactSolution::axis_precession_rate`]).
        precession: f64,
        /// The initial state.
        initial: State,
    },
    /// A nutation between two turning points.
    Nutation(Nutation),
}

/// The nutation period and the advance of the precession angle per period of the motion
/// through one initial state, in the problem's units: [`ExactSolution::nutation_numbers`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct NutationNumbers {
    /// The nutation period ([`Nutation::period`]); `None` for a steady motion.
    pub period: Option<f64>,
    /// The advance per period of the precession angle psi ([`Nutation::advance`]); `None`
    /// for a steady motion.
    pub advance: Option<f64>,
}

/// The decision of [`ExactSolution::decide`], in the dimensionless problem.
// One per solution, moved once (as `Motion`): boxing the nutation would save nothing.
#[allow(clippy::large_enum_variant)]
enum Decision {
    /// A steady motion at `gamma3 = u`, rotating at `precession` (per unit of the
    /// dimensionless time), with its accuracy.
    Steady {
        u: f64,
        precession: f64,
        accuracy: Accuracy,
    },
    /// A nutation, its series solved, with what its error estimate needs.
    Nutation(Solved),
}

/// A nutation as decided, with the numbers of the decision that its error estimate
/// ([`ExactSolution::sensitivity`]) and its accuracy use.
struct Solved {
    /// The series, period and advance; not yet the phase of the initial state.
    nutation: Nutation,
    /// The pole of the initial state's hemisphere.
    pole: f64,
    /// The middle of the nutation in `x = 1 - pole u`, and in u.
    x_mid: f64,
    mid: f64,
    /// The round-off of the integrals ([`Reduction::frames_of_state`]).
    errors: [f64; 5],
    /// The relative error of the period from the round-off of the turning points.
    root_error: f64,
    /// The relative error of omega fixed by the state (`omega_round_off`).
    conditioning: f64,
    /// `d gamma3 / dt` at the start.
    udot0: f64,
}

/// The exact solution of (mg-eq) for the Routh sphere through one initial state, all its
/// numbers in the problem's units (those of the body and the state given).
#[derive(Debug, Clone, PartialEq)]
pub struct ExactSolution {
    /// The body.
    pub body: Body,
    /// The integrals that fix the motion, in the problem's units (the decisions are taken on
    /// those of the dimensionless problem, which the nutation holds).
    pub reduction: Reduction,
    /// Steady motion or nutation.
    pub motion: Motion,
    /// How the error of the computed state grows with t.
    pub accuracy: Accuracy,
}

/// The estimated relative error of the state at time t,
/// `(initial + drift |t|) exp(growth |t|)`.
///
/// A nutation: the period and the advance carry relative errors (truncation, round-off of the
/// samples, round-off of the turning points), so the phase error grows like `|t| / T` times
/// the period's error: per period the state is off by its speed times `T dT/T` plus its
/// horizontal size times the error of the advance, and `drift` is that divided by T. A stable relative equilibrium: its distance from
/// the state (`initial`) and the error of its rate. An unstable one: that distance times
/// `exp(lambda |t|)`, lambda the largest real part of the eigenvalues of the linearisation.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Accuracy {
    /// Relative error at t = 0 and for |t| within one period.
    pub initial: f64,
    /// Growth of the relative error per unit of the problem's time.
    pub drift: f64,
    /// Exponential growth rate (unstable relative equilibria), per unit of the problem's time.
    pub growth: f64,
}

impl Accuracy {
    /// This accuracy of a dimensionless problem (rates per its unit of time `time`) in the
    /// problem's units: the rates divided by `time`.
    fn in_time_unit(self, time: f64) -> Self {
        Accuracy {
            initial: self.initial,
            drift: self.drift / time,
            growth: self.growth / time,
        }
    }

    /// The estimated relative error above which a state is reported with a warning (relative:
    /// the same in any units).
    pub const WARNING: f64 = 1e-8;
    /// The estimated relative error above which a state is refused (`RouthError::Horizon`).
    /// The estimate is conservative: on the test cases the measured error is 3 to 30 times
    /// smaller (docs/quadrature.md, section 5).
    pub const REFUSAL: f64 = 1e-6;

    /// The estimated relative error at `t`, or `RouthError::Horizon` if it exceeds
    /// [`Accuracy::REFUSAL`] (`RouthError::Unresolved` if it does so already at t = 0).
    pub fn checked_error_at(&self, t: f64) -> Result<f64> {
        let error = self.error_at(t);
        let initial = self.error_at(0.0);
        if initial > Self::REFUSAL {
            Err(RouthError::Unresolved {
                tolerance: Self::REFUSAL,
                error: initial,
            })
        } else if error <= Self::REFUSAL {
            Ok(error)
        } else {
            Err(RouthError::Horizon {
                t,
                horizon: self.horizon(Self::REFUSAL),
                tolerance: Self::REFUSAL,
                error,
            })
        }
    }

    /// The estimated relative error of the state at time `t`.
    pub fn error_at(&self, t: f64) -> f64 {
        let e = (self.initial + self.drift * t.abs()) * (self.growth * t.abs()).exp();
        if e.is_nan() {
            f64::INFINITY
        } else {
            e
        }
    }

    /// The largest |t| at which the estimated error stays below `tolerance` (bisection on the
    /// monotone `error_at`, bracketed from the time `1 / (drift + growth)` in which the error
    /// changes: a time of the problem, so the search is the same in any units).
    pub fn horizon(&self, tolerance: f64) -> f64 {
        if self.error_at(0.0) > tolerance {
            return 0.0;
        }
        if self.drift == 0.0 && self.growth == 0.0 {
            return f64::INFINITY;
        }
        let mut hi = (self.drift + self.growth).recip();
        while hi.is_finite() && self.error_at(hi) <= tolerance {
            hi *= 2.0;
        }
        if !hi.is_finite() {
            return f64::INFINITY;
        }
        let mut lo = 0.0;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if self.error_at(mid) <= tolerance {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    }
}

/// Rotation of a state about e3 by `angle` (a symmetry of (mg-eq) when I1 = I2).
fn rotated(state: &State, angle: f64) -> Point {
    let (s, c) = angle.sin_cos();
    let rot = |v: [f64; 3]| [c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]];
    Point {
        gamma: rot(state.gamma()),
        m: rot(state.m()),
    }
}

/// The rate of the azimuth phi of the symmetry axis e3 in space at `state`,
/// `dphi/dt = -(omega1 gamma1 + omega2 gamma2) / (gamma1^2 + gamma2^2)` (docs/quadrature.md,
/// section 3); `None` on the axis (gamma = +-e3), where e3 is vertical.
fn axis_rate(body: &Body, state: &State) -> Option<f64> {
    let (gamma, omega) = (state.gamma(), state.omega(body));
    let horizontal = gamma[0] * gamma[0] + gamma[1] * gamma[1];
    (horizontal > 0.0).then(|| -(omega[0] * gamma[0] + omega[1] * gamma[1]) / horizontal)
}

/// The Euclidean norm, without underflow or overflow of the squares of its components.
fn norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |n, &c| n.hypot(c))
}

/// A turning point u of Q and its distance `gap = 1 - |u|` from the pole on its side, found
/// in that variable near the pole: there u itself carries an absolute rounding of `eps`,
/// a relative error `eps / gap` of `1 - |u|`, which the poles of `dpsi/dt` at `u = +-1`
/// turn into an error of the precession angle.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Turning {
    u: f64,
    gap: f64,
}

/// The two turning points of a nutation and its width `u2 - u1`, all found in the distance
/// `x = 1 - p u` from the pole p of the initial state's hemisphere ([`turning_points`]), so
/// that the width of a nutation near that pole carries the relative round-off of x, not the
/// absolute rounding `eps` of u (1e-4 relative for a nutation of width 1e-12 at the pole).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Turnings {
    lower: Turning,
    upper: Turning,
    width: f64,
    /// The first step of the search: a nutation through a turning point at `x0` whose other
    /// turning point lies closer than this is not separated from it (see
    /// `ExactSolution::unresolved_nutation`).
    first_step: f64,
}

/// Below this distance from a pole a turning point is refined in the distance itself.
const NEAR_POLE: f64 = 1.0 / 8.0;
/// Below this distance `x = 1 - |u|` from its pole a turning point is the pole: the motion
/// passes the axis at the angle `theta_min = sqrt(2 x)`, here `eps^2`, and its Jellett remainder
/// `n_p`, of order `A R theta_min` times the rate of the tilt, adds to `omega_t` a part
/// `n_p / (A R sin theta)` that is below `eps` of that rate (times the bounded ratio
/// `sqrt((A + m h_p^2) / A)`, at most 1e5 where [`omega_round_off`] accepts the body) wherever
/// `sin theta > eps`, i.e. except within the time `eps T` of the passage, the resolution of the
/// phase itself: the motion through the axis is then the same state in f64. Above it the gap
/// and `1 / gap` stay far inside the normal range. Below it they did not: a state nearly at
/// rest (M of 1e-160 in the problem's units, gamma horizontal) fell past the bottom pole at a
/// gap of 3.2e-315, a subnormal number with 29 significant bits, and the closed form of the
/// pole's part of psi (`Nutation::pole_angles`) divided by it: `1 / gap` overflowed, and
/// `inf * 0` made the advance and every state NaN. A distance in x, a cosine: dimensionless.
const AXIS_GAP: f64 = 0.5 * (f64::EPSILON * f64::EPSILON) * (f64::EPSILON * f64::EPSILON);

/// The distance `x0 = 1 - p gamma3` of gamma from the pole p, from the horizontal part of
/// gamma in p's own hemisphere (where `1 - p gamma3` would round x0 to `eps` absolute).
fn distance_from_pole(gamma: &[f64; 3], pole: f64) -> f64 {
    if pole * gamma[2] > 0.0 {
        (gamma[0] * gamma[0] + gamma[1] * gamma[1]) / (1.0 + pole * gamma[2])
    } else {
        1.0 - pole * gamma[2]
    }
}

/// The pole of the hemisphere of gamma (the top one at the equator).
fn pole_of_hemisphere(gamma: &[f64; 3]) -> f64 {
    if gamma[2] >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// The turning points of Q met by going from `x0 = 1 - p u0` toward the pole p and away
/// from it, in x ([`Reduction::q_from_pole`]): a geometric search for the first sign change
/// from a first step `FIRST_SEARCH_STEP min(x0, 1)` (relative to x0, which carries a relative
/// round-off: a nutation 1e-13 from the pole spans 1e-12 in x, 8,000 roundings of u, and a
/// first step of 1e-8 in u, as before, stepped over it and took it for steady), refined by
/// Brent's method; a far turning point within `NEAR_POLE` of the other pole is refined again
/// in the distance from that pole.
fn turning_points(red: &Reduction, pole: f64, x0: f64) -> Result<Turnings> {
    let q = |x: f64| red.q_from_pole(pole, x);
    // A start closer to the pole than `AXIS_GAP` is on the axis in f64, and searched from
    // there: the step relative to x0 underflowed to 0 for a start at x0 = 1.9e-316 (a fuzz
    // input), and the search never moved.
    let first_step = if x0 > AXIS_GAP {
        FIRST_SEARCH_STEP * x0.min(1.0)
    } else {
        FIRST_SEARCH_STEP * FIRST_SEARCH_STEP
    };
    let near = frame_root(&q, x0, -1.0, first_step)?;
    let far = frame_root(&q, x0, 1.0, first_step)?;
    let near_turning = Turning {
        u: pole * (1.0 - near),
        gap: near,
    };
    let far_gap = refine_gap(red, -pole, 2.0 - far);
    let far_turning = Turning {
        u: -pole * (1.0 - far_gap),
        gap: far_gap,
    };
    let width = if far_gap < NEAR_POLE {
        2.0 - near - far_gap
    } else {
        far - near
    };
    let (lower, upper) = if pole > 0.0 {
        (far_turning, near_turning)
    } else {
        (near_turning, far_turning)
    };
    Ok(Turnings {
        lower,
        upper,
        width,
        first_step,
    })
}

/// The root of `q` (Q in x) met by going from x0 in direction `dir` (-1 toward the pole,
/// where x ends at 0; +1 away from it, to x = 2); x0 itself when Q is not positive there
/// and at the first step.
fn frame_root(q: &impl Fn(f64) -> f64, x0: f64, dir: f64, first_step: f64) -> Result<f64> {
    let end = 1.0 + dir;
    let (mut prev, mut step) = (x0, first_step);
    loop {
        let cur = if (end - prev).abs() <= step {
            end
        } else {
            prev + dir * step
        };
        if q(cur) < 0.0 {
            if prev == x0 && q(x0) <= 0.0 {
                return Ok(x0);
            }
            return brent(q, prev, cur, 0.0, 200).ok_or_else(|| RouthError::Singular {
                formula: "the reduced equation (du/dt)^2 = Q(u)",
                reason: format!("no turning point refined in x = 1 - p u in [{prev}, {cur}]"),
            });
        }
        if cur == end {
            return Ok(end);
        }
        prev = cur;
        step = (2.0 * step).min(MAX_SEARCH_STEP);
    }
}

/// The distance `gap` of a turning point from the pole `pole`, refined in the frame of that
/// pole when it is below `NEAR_POLE` ([`Reduction::q_in_frame`]): Q > 0 toward the nutation
/// (larger gap), Q < 0 toward the pole (at the pole `Q = -c N(p)^2 < 0` unless the motion
/// passes through the axis, `N(p) = 0`, and the pole is the turning point).
fn refine_gap(red: &Reduction, pole: f64, gap: f64) -> f64 {
    if !(gap < NEAR_POLE) {
        return gap;
    }
    let q = |v: f64| red.q_in_frame(pole, v);
    let mut inner = gap * (1.0 + 1e-6) + 4.0 * f64::EPSILON;
    while !(q(inner) > 0.0) && inner < NEAR_POLE {
        inner *= 2.0;
    }
    let outer = [gap * (1.0 - 1e-6), 0.0]
        .into_iter()
        .find(|&v| v < inner && q(v) < 0.0);
    match outer {
        Some(outer) if q(inner) > 0.0 => brent(q, outer, inner, 0.0, 200).unwrap_or(gap),
        _ => gap,
    }
}

/// How far a state is from a relative equilibrium (a steady motion rotating about e3 at a
/// constant rate Omega, `X(x) = Omega L x`, `L x = (e3 x gamma, e3 x M)`): the component of the
/// field (mg-eq) orthogonal to `L x`, relative to `|J| |x|`, with the fitted Omega. Only in the
/// units of the problem ([`Units`]), where gamma and M, and the components of the field, are
/// numbers of the same scale: `|x|` and the fit of Omega add them.
fn relative_equilibrium_residual(body: &Body, state: &State) -> (f64, f64) {
    let x = state.to_array();
    let (field, jac) = jacobian(|y| vector_field(body, y), &x);
    let lx = [-x[1], x[0], 0.0, -x[4], x[3], 0.0];
    let ll: f64 = lx.iter().map(|v| v * v).sum();
    let along: f64 = field.iter().zip(&lx).map(|(a, b)| a * b).sum();
    let omega = if ll > 0.0 { along / ll } else { 0.0 };
    let residual = field
        .iter()
        .zip(&lx)
        .map(|(f, l)| (f - omega * l).powi(2))
        .sum::<f64>()
        .sqrt();
    // |x| >= |gamma| = 1 and J != 0 (dgamma/dt = gamma x I_Q^-1 M): no division by 0.
    let size = x.iter().map(|v| v * v).sum::<f64>().sqrt();
    (residual / (jac.norm() * size), omega)
}

impl ExactSolution {
    /// Solve the motion through `initial` by quadrature (body with I1 = I2).
    ///
    /// Decisions, each from a test that scales with the problem (docs/quadrature.md, section 5):
    /// * a relative equilibrium to round-off (the field orthogonal to the rotations about e3
    ///   below `RELATIVE_EQUILIBRIUM_EPSILONS` of its round-off scale) is steady, stable or not;
    /// * otherwise the nutation between the turning points of Q is solved; if the whole of it
    ///   lies within the round-off of Q (the tilt oscillation cannot be resolved) it is steady
    ///   when Q'' < 0 there (a stable relative equilibrium, the error bounded by the unresolved
    ///   amplitude), and a separatrix when Q'' >= 0;
    /// * a turning point that the round-off of Q (from its own terms and from the integrals)
    ///   moves by more than its distance to the next root of the local quadratic of Q
    ///   (`Q'^2 <= noise |Q''|`), or where Q' is within its round-off of 0, is a double root:
    ///   a separatrix;
    /// * a state that fixes its angular velocity only to more than `Accuracy::REFUSAL`
    ///   (`omega_round_off`: the moments far below `m R^2`) is refused; below that, its
    ///   error of omega makes the estimated error grow with t.
    ///
    /// The body and the state are made dimensionless here, once ([`Units`], rounded to powers
    /// of two so that the conversion is exact: the state of a motion 1e-12 off a separatrix,
    /// rounded into units of other significands, had its period moved by 2.5e-5), the motion
    /// is decided and solved in those units, and its numbers are converted back: times
    /// multiplied by T, rates divided by T; angles and gamma as they are.
    pub fn new(body: &Body, initial: &State) -> Result<Self> {
        require_finite_inertia(body)?;
        let units = Units::of(body, &initial.omega(body)).binary();
        let (motion, accuracy) = Self::solve(&units.body(body)?, &units.state(initial)?, units)?;
        let reduction = Reduction::of_state(body, initial)?;
        let motion = match motion {
            Motion::Steady { u, precession, .. } => Motion::Steady {
                u,
                precession: precession / units.time(),
                initial: *initial,
            },
            nutation => nutation,
        };
        Ok(ExactSolution {
            body: *body,
            reduction,
            motion,
            accuracy: accuracy.in_time_unit(units.time()),
        })
    }

    /// The nutation period and the advance per period of the precession angle of the motion
    /// through `initial`: bit for bit `ExactSolution::new(body, initial)`'s
    /// [`ExactSolution::period`] and [`Nutation::advance`] (both `None` for a steady motion),
    /// and its error, with the same text, exactly when `new` errs. The same decision and the
    /// same series, without what only the states and the error estimate need (the nutation
    /// solved again with moved integrals, the phase of the initial state, the probes of the
    /// accuracy): about half the cost of `new` (on the default case 38 us against 79 us,
    /// `benches/quadrature.rs`, on a loaded machine where they took 0.28 ms and 0.54 ms before
    /// the cofactor came from divided differences of Q, `Nutation::cofactor_with_noise`).
    /// What the `quadrature` columns of a sweep use.
    pub fn nutation_numbers(body: &Body, initial: &State) -> Result<NutationNumbers> {
        require_finite_inertia(body)?;
        let units = Units::of(body, &initial.omega(body)).binary();
        let decision = Self::decide(&units.body(body)?, &units.state(initial)?, units)?;
        // `new` builds this too, and refuses what it refuses.
        Reduction::of_state(body, initial)?;
        Ok(match decision {
            Decision::Steady { .. } => NutationNumbers {
                period: None,
                advance: None,
            },
            Decision::Nutation(solved) => NutationNumbers {
                period: Some(solved.nutation.period),
                advance: Some(solved.nutation.advance),
            },
        })
    }

    /// The motion through `initial` of the dimensionless problem (`body` and `initial` in
    /// `units`: R = m = 1, and the faster of the fall and the spin 1) and its accuracy, in
    /// those units; a nutation reports its own numbers in the problem's units ([`Nutation`]).
    fn solve(body: &Body, initial: &State, units: Units) -> Result<(Motion, Accuracy)> {
        let Solved {
            mut nutation,
            pole,
            x_mid,
            mid,
            errors,
            root_error,
            conditioning,
            udot0,
        } = match Self::decide(body, initial, units)? {
            Decision::Steady {
                u,
                precession,
                accuracy,
            } => {
                let steady = Motion::Steady {
                    u,
                    precession,
                    initial: *initial,
                };
                return Ok((steady, accuracy));
            }
            Decision::Nutation(solved) => solved,
        };
        nutation.start_at(initial, udot0);
        match Self::sensitivity(&nutation, (pole, x_mid), mid, errors) {
            Some((period, advance)) => {
                nutation.period_error += period;
                nutation.advance_error += advance;
            }
            None => {
                nutation.period_error += root_error;
                nutation.advance_error += root_error * nutation.advance.abs();
            }
        }
        // The state moves at `velocity` (relative sizes: gamma against 1, M against the size
        // of M of the initial state), so a time error dt = T dT/T per period moves it by
        // `velocity dt`; an error of psi rotates its horizontal part. Both vary along the
        // nutation: their largest values at the turning points, the quarter phases and the
        // widest tilt are taken.
        let states = nutation.probes();
        let m_size = nutation.momentum_scale;
        let (mut velocity, mut horizontal) = (0.0_f64, 0.0_f64);
        for x in &states {
            let field = vector_field(body, x);
            velocity = velocity.max(norm(&field[..3]) + norm(&field[3..]) / m_size);
            horizontal = horizontal.max(norm(&x[..2]) + norm(&x[3..5]) / m_size);
        }
        let period = nutation.cycle();
        let per_period =
            velocity * period * nutation.period_error + horizontal * nutation.advance_error;
        // The error of omega from the state moves it at that relative error of its speed.
        let accuracy = Accuracy {
            initial: per_period,
            drift: per_period / period + conditioning * velocity,
            growth: 0.0,
        };
        Ok((Motion::Nutation(nutation), accuracy))
    }

    /// The decision of [`ExactSolution::solve`] (steady, nutation or separatrix) and, for a
    /// nutation, its series, period and advance ([`Nutation::series`]) with what the error
    /// estimate needs; not the phase of the initial state nor the error estimate. The one
    /// place of the decision: [`ExactSolution::new`] and [`ExactSolution::nutation_numbers`]
    /// both take it from here.
    fn decide(body: &Body, initial: &State, units: Units) -> Result<Decision> {
        let conditioning = omega_round_off(body, initial);
        if !(conditioning <= Accuracy::REFUSAL) {
            return Err(RouthError::Singular {
                formula: "omega = I_Q^-1 M (om-m)",
                reason: format!(
                    "the state fixes omega only to {conditioning:.1e} (relative): the moments \
                     I1 = {:e}, I3 = {:e} are too small beside m |r|^2 for the digits of M",
                    body.i1(),
                    body.i3()
                ),
            });
        }
        let red = Reduction::of_state(body, initial)?;
        // Its error of omega (`conditioning`) is counted in the drift of the estimate.
        let (_, errors) = red.frames_of_state(initial, 0.0);
        let u0 = initial.gamma()[2];
        let steady = |u: f64, precession: f64, accuracy: Accuracy| Decision::Steady {
            u,
            precession,
            accuracy,
        };
        let omega = initial.omega(body);
        let udot0 = initial.gamma()[0] * omega[1] - initial.gamma()[1] * omega[0];
        // A nutation within the round-off `noise` of Q whose turning points the search did not
        // separate beyond `searched`: steady, with the error of `unresolved_nutation`. du/dt at
        // the start is bounded with its round-off: that of its two products, and the error of
        // omega.
        let unresolved = |searched: f64, noise: f64| {
            let horizontal = initial.gamma()[0].hypot(initial.gamma()[1]);
            let udot_bound = udot0.abs()
                + f64::EPSILON * (initial.gamma()[0] * omega[1]).abs()
                + f64::EPSILON * (initial.gamma()[1] * omega[0]).abs()
                + conditioning * horizontal * omega[0].hypot(omega[1]).hypot(omega[2]);
            Self::unresolved_nutation(
                &red,
                u0,
                [searched, udot_bound],
                [noise, red.q_slope_noise(u0, errors)],
                conditioning,
            )
        };
        let (deviation, omega_fit) = relative_equilibrium_residual(body, initial);
        if deviation <= RELATIVE_EQUILIBRIUM_EPSILONS * f64::EPSILON {
            let (lambda, norm) = max_real_eigenvalue(body, initial, omega_fit)?;
            // `norm` is that of the Jacobian, a rate in the units of the motion
            // ([`max_real_eigenvalue`]): the tolerance is relative, as in `steady`.
            let unstable = lambda > EIGENVALUE_TOLERANCE * norm;
            let accuracy = if unstable {
                Accuracy {
                    initial: deviation,
                    drift: 0.0,
                    growth: lambda,
                }
            } else {
                // The residual of the field is not the distance from the relative
                // equilibrium: that is the residual over the nutation's frequency, up to
                // `|J|` over it larger (5 times for the default body: a state 1e-13 off a
                // steady precession was 1e-13 off DOP853 at t = 1 with an estimate of 3e-14).
                // Off the axis the tilt's amplitude is bounded as for an unresolved nutation.
                let own = Accuracy {
                    initial: deviation,
                    drift: (deviation + conditioning) * omega_fit.abs(),
                    growth: 0.0,
                };
                match unresolved(0.0, red.q_noise(u0, errors)) {
                    Ok((_, bound)) if u0.abs() < 1.0 => Accuracy {
                        initial: own.initial.max(bound.initial),
                        drift: own.drift.max(bound.drift),
                        growth: 0.0,
                    },
                    _ => own,
                }
            };
            return Ok(steady(u0, omega_fit, accuracy));
        }
        let pole = pole_of_hemisphere(&initial.gamma());
        let x0 = distance_from_pole(&initial.gamma(), pole);
        let turnings = turning_points(&red, pole, x0)?;
        let (u1, u2, width) = (turnings.lower.u, turnings.upper.u, turnings.width);
        let mid = 0.5 * (u1 + u2);
        // The middle in x: `x = 1 - p u` of the turning point on the pole's side plus half
        // the width (u itself rounds it to eps).
        let x_mid = if pole > 0.0 {
            turnings.upper.gap
        } else {
            turnings.lower.gap
        } + 0.5 * width;
        let noise_mid = red.q_noise(mid, errors).max(red.q_noise(u0, errors));
        if red.q_from_pole(pole, x_mid).max(red.q_from_pole(pole, x0)) <= 4.0 * noise_mid {
            // The search separates turning points only beyond its first step.
            return unresolved(width + turnings.first_step, noise_mid)
                .map(|(rate, accuracy)| steady(u0, rate, accuracy));
        }
        let turnings = Turnings {
            lower: turnings.lower.snapped(-1.0),
            upper: turnings.upper.snapped(1.0),
            ..turnings
        };
        let mut root_error = 0.0;
        for u in [u1, u2] {
            let (_, dq, q2) = red.q_derivatives(u);
            let noise = red.q_noise(u, errors);
            let slope_noise = red.q_slope_noise(u, errors);
            let shift = noise / dq.abs();
            // Near u_i, Q = Q' (u - u_i) + Q''/2 (u - u_i)^2 has its other root at
            // -2 Q'/Q'' from u_i; when the round-off of Q moves u_i by more than that
            // (Q'^2 <= noise |Q''|) the two roots are one double root within the accuracy of
            // the integrals: the level set is a separatrix, and which side the motion lies on
            // is not decided by the integrals. So is a turning point where Q' is within its
            // own round-off of 0: at a pole through which the motion passes (`n_p = 0`) every
            // term of Q vanishes with its round-off, and only that of Q' tells the homoclinic
            // orbit of the vertical spin (Q'(p) = 0) from a motion through the axis.
            if !(dq * dq > SEPARATRIX_MARGIN * noise * q2.abs())
                || !(dq.abs() > SEPARATRIX_MARGIN * slope_noise)
            {
                return Err(RouthError::Separatrix {
                    u_min: u1,
                    u_max: u2,
                    reason: format!(
                        "Q has a double root at the turning point {u} within the accuracy of \
                         the integrals (dQ/du = {dq:e} with round-off {slope_noise:e}, \
                         d2Q/du2 = {q2:e}, round-off of Q {noise:e})"
                    ),
                });
            }
            root_error += shift / width;
        }
        let nutation = Nutation::series(red, &turnings, units)?;
        Ok(Decision::Nutation(Solved {
            nutation,
            pole,
            x_mid,
            mid,
            errors,
            root_error,
            conditioning,
            udot0,
        }))
    }

    /// How much the round-off of the integrals changes the period and the advance: the
    /// nutation is solved again with its parameters (K and those of both poles,
    /// [`Reduction::frames_of_state`]) moved by `k` times their round-off, each in the
    /// direction that raises Q at the middle of the nutation (or, for the frame of the other
    /// hemisphere, at the turning point in it), and the changes divided by `k`
    /// (`k` up to 1e4, so that they stand above the round-off of the quadrature, and small
    /// enough that the move stays below a tenth of Q there). The relative change of T and the
    /// absolute change of the advance, or `None` if the moved level set cannot be solved.
    fn sensitivity(
        nutation: &Nutation,
        (pole, x_mid): (f64, f64),
        mid: f64,
        errors: [f64; 5],
    ) -> Option<(f64, f64)> {
        let red = &nutation.reduction;
        let grad = red.q_integral_gradient(mid);
        let shift: f64 = grad.iter().zip(errors).map(|(g, e)| g.abs() * e).sum();
        let k = (0.1 * red.q_from_pole(pole, x_mid) / shift).min(1e4);
        if !(k > 0.0) {
            return None;
        }
        let ends = [nutation.u2, nutation.u1].map(|u| red.q_integral_gradient(u));
        let parameters = red.parameters();
        let other = red.with_parameters(std::array::from_fn(|i| {
            let slope = std::iter::once(grad[i])
                .chain(ends.iter().map(|g| g[i]))
                .find(|g| *g != 0.0)
                .unwrap_or(1.0);
            parameters[i] + k * errors[i] * slope.signum()
        }));
        let turnings = turning_points(&other, pole, x_mid).ok()?;
        let turnings = Turnings {
            lower: turnings.lower.snapped(-1.0),
            upper: turnings.upper.snapped(1.0),
            ..turnings
        };
        // Only the period and the advance are compared: the series alone, without the phase
        // of the initial state.
        let alt = Nutation::series(other, &turnings, nutation.units).ok()?;
        Some((
            (alt.period - nutation.period).abs() / (k * nutation.period),
            (alt.advance - nutation.advance).abs() / k,
        ))
    }

    /// A nutation whose whole amplitude lies within the round-off `noise` of Q near `u0`: a
    /// stable relative equilibrium when `Q''(u0) < 0` (the rate `dpsi/dt` at u0, the error
    /// bounded by the amplitude of the nutation, seen in gamma, and the rate's error by its
    /// change over that amplitude and the relative error `conditioning` of omega); otherwise
    /// the state lies on a separatrix within that round-off. The amplitude is bounded twice,
    /// and the smaller bound taken: by the width `searched` of the turning points found plus
    /// the amplitude that Q cannot resolve, `sqrt(8 noise / |Q''|)`; and by the roots of the
    /// local quadratic `udot0^2 + Q' (u - u0) + Q''/2 (u - u0)^2`, within
    /// `2 sqrt(Q'^2 + 2 |Q''| udot0^2) / |Q''|` of u0, with `|Q'|` raised by its round-off
    /// `slope_noise` and `udot0` bounded by `udot_bound`: Q' and du/dt carry the round-off of
    /// the state, where Q carries its square (a state 1e-11 from the steady precession of a
    /// spin of 1e6 had the first bound 1e-8, and an error of 2e-3 estimated at t = 0.01).
    fn unresolved_nutation(
        red: &Reduction,
        u0: f64,
        [searched, udot_bound]: [f64; 2],
        [noise, slope_noise]: [f64; 2],
        conditioning: f64,
    ) -> Result<(f64, Accuracy)> {
        let (_, q1, q2) = red.q_derivatives(u0);
        let slope = q1.abs() + slope_noise;
        let local =
            2.0 * (slope * slope + 2.0 * q2.abs() * udot_bound * udot_bound).sqrt() / q2.abs();
        let du = (searched + (8.0 * noise / q2.abs()).sqrt()).min(local);
        if !(q2 < 0.0) {
            return Err(RouthError::Separatrix {
                u_min: u0 - du,
                u_max: u0 + du,
                reason: format!(
                    "the state is within the round-off of Q ({noise:e}) of an unstable \
                     relative equilibrium (Q'' = {q2:e} >= 0)"
                ),
            });
        }
        let s = (1.0 - u0 * u0).max(0.0).sqrt();
        // A change du of gamma3 moves gamma by du / sin(theta), at most sqrt(2 du) at a pole.
        let gamma_error = (du / s).min((2.0 * du).sqrt());
        let rate = |u: f64| {
            if u.abs() < 1.0 {
                red.precession_rate(u)
            } else {
                0.0
            }
        };
        let lo = (u0 - du).max(-1.0 + f64::EPSILON);
        let hi = (u0 + du).min(1.0 - f64::EPSILON);
        let rate_error = (rate(hi) - rate(lo)).abs() + conditioning * rate(u0).abs();
        Ok((
            rate(u0),
            Accuracy {
                initial: gamma_error,
                drift: rate_error,
                growth: 0.0,
            },
        ))
    }

    /// The state at time `t` (any real t; the cost does not depend on t).
    pub fn state_at(&self, t: f64) -> Point {
        match &self.motion {
            Motion::Steady {
                precession,
                initial,
                ..
            } => rotated(initial, precession * t),
            Motion::Nutation(nut) => nut.state_at(t),
        }
    }

    /// The rate of the azimuth phi of the symmetry axis e3 in space (the fixed frame, z up,
    /// measured from x toward y) of a steady motion, in radians per unit of the problem's time:
    /// `dphi/dt = -(omega1 gamma1 + omega2 gamma2) / (gamma1^2 + gamma2^2)` (docs/quadrature.md,
    /// section 3), constant along it. `None` for a nutation (see [`Nutation::axis_advance`])
    /// and for the vertical spin, whose axis is vertical and has no azimuth.
    pub fn axis_precession_rate(&self) -> Option<f64> {
        match &self.motion {
            Motion::Steady { initial, .. } => axis_rate(&self.body, initial),
            Motion::Nutation(_) => None,
        }
    }

    /// The turning points (u_min, u_max) of gamma3 = cos theta (equal for a steady motion).
    pub fn turning_points(&self) -> (f64, f64) {
        match &self.motion {
            Motion::Steady { u, .. } => (*u, *u),
            Motion::Nutation(nut) => (nut.u1, nut.u2),
        }
    }

    /// The nutation period; `None` for a steady motion.
    pub fn period(&self) -> Option<f64> {
        match &self.motion {
            Motion::Steady { .. } => None,
            Motion::Nutation(nut) => Some(nut.period),
        }
    }
}

/// Where a phase sigma puts the tilt: u, `1 - u` and `1 + u` (from the distances to the
/// turning points, without the rounding of u), the signed sin theta, `(du/dt) / s * f`, and
/// whether u is on the half of the nutation next to the upper turning point.
struct Phase {
    u: f64,
    one_minus: f64,
    one_plus: f64,
    s: f64,
    udot_over_s_times_f: f64,
    upper: bool,
}

impl Turning {
    /// The pole itself when the turning point is the pole (a motion through the axis,
    /// `N(p) = 0`), or passes it closer than f64 can tell from one through it (`AXIS_GAP`).
    /// The gap of a turning point near the pole is found in the frame of the pole, to its
    /// relative round-off however small: a motion that passes at 1e-6 rad from the axis near
    /// the unstable vertical spin (a gap of 5e-13) is not one through the axis, and taking it
    /// for one (as when gaps below 1e-12 were snapped) puts its start 1e-6 off, an error that
    /// the instability amplifies to O(1) at t = 20.
    fn snapped(self, pole: f64) -> Self {
        if self.gap < AXIS_GAP {
            Turning { u: pole, gap: 0.0 }
        } else {
            self
        }
    }
}

impl Phase {
    /// The pole `p = +-1` itself (outside the nutation, where P is continued to find the
    /// strengths of the poles of the rate), on the side of its turning point.
    fn at_pole(pole: f64) -> Self {
        Phase {
            u: pole,
            one_minus: 1.0 - pole,
            one_plus: 1.0 + pole,
            s: 0.0,
            udot_over_s_times_f: 0.0,
            upper: pole > 0.0,
        }
    }

    /// The pole of u's hemisphere, the distance `x = 1 - p u` from it and `1 + p u`.
    fn nearest_pole(&self) -> (f64, f64, f64) {
        if self.one_minus <= self.one_plus {
            (1.0, self.one_minus, self.one_plus)
        } else {
            (-1.0, self.one_plus, self.one_minus)
        }
    }

    /// The spin omega3 at the phase, from its distance to the nearest pole.
    fn spin(&self, red: &Reduction) -> f64 {
        let (pole, x, _) = self.nearest_pole();
        red.spin_in_frame(pole, x)
    }

    /// `1 - p u` for a pole `p = +-1`.
    fn one_minus_pole(&self, pole: f64) -> f64 {
        if pole > 0.0 {
            self.one_minus
        } else {
            self.one_plus
        }
    }
}

impl Nutation {
    /// The nutation of the dimensionless problem of `red` (in `units`) between `turnings`: its
    /// series, period, advances and their errors from the series alone, all that depends on
    /// the level set and not on the state on it. The phase of a state on it is set by
    /// [`Nutation::start_at`] (until then `sigma0`, `momentum_scale` and `psi_ref` are 0).
    fn series(red: Reduction, turnings: &Turnings, units: Units) -> Result<Self> {
        let (lower, upper) = (turnings.lower, turnings.upper);
        let (u1, u2) = (lower.u, upper.u);
        let mut nut = Nutation {
            reduction: red,
            units,
            u1,
            u2,
            gap_bottom: lower.gap,
            gap_top: upper.gap,
            width: turnings.width,
            through_top: upper.gap == 0.0,
            through_bottom: lower.gap == 0.0,
            period: 0.0,
            advance: 0.0,
            axis_advance: 0.0,
            nodes: 0,
            period_error: 0.0,
            advance_error: 0.0,
            series: Piecewise::default(),
            narrow: turnings.width <= WIDE_NUTATION,
            end_slope_scales: [(1.0, upper.gap), (-1.0, lower.gap)]
                .map(|(pole, gap)| red.q_scales_in_frame(pole, gap).1),
            sigma0: 0.0,
            momentum_scale: 0.0,
            psi_ref: 0.0,
            poles: vec![],
        };
        // The rate `dpsi/dt = N(u) / (2 A R) [1/(1 - u) - 1/(1 + u)] - omega3` has poles at
        // u = +-1, outside the nutation but close to it when the motion passes near the axis:
        // they would make psi turn too fast for a cosine series. Their parts
        // `c_p / (1 - p u)` with `c_p = p N(p) f(p) / (2 A R)` are subtracted from the samples
        // and integrated in closed form (`pole_angles`); the remainder is smooth. So are those
        // of `dphi/dt = -N(u) / (2 A R) [1/(1 - u) + 1/(1 + u)]`, `-p c_p / (1 - p u)`.
        for (pole, through) in [(1.0, nut.through_top), (-1.0, nut.through_bottom)] {
            let (p, _) = nut.cofactor_with_noise(&Phase::at_pole(pole));
            if !through && p > 0.0 && p.is_finite() {
                let strength = pole * red.frame(pole).remainder
                    / (2.0 * red.body().i1() * red.body().radius())
                    / p.sqrt();
                nut.poles.push((pole, strength));
            }
        }
        let built = Piecewise::build(SAMPLE_BUDGET, |sigma, rho| nut.sample(sigma, rho))?;
        let series = match built {
            Ok(series) => series,
            Err(unresolved) => {
                let n = unresolved.samples;
                return Err(if unresolved.time_converged {
                    RouthError::Singular {
                        formula: "the precession angles psi (of gamma) and phi (of the axis)",
                        reason: format!(
                            "the motion passes so close to the axis (gamma3 up to {u2}, down to \
                             {u1}) that they turn too fast to resolve with {n} samples"
                        ),
                    }
                } else {
                    RouthError::Separatrix {
                        u_min: u1,
                        u_max: u2,
                        reason: format!(
                            "dt/dsigma is not resolved with {n} samples (period > {:.6e}): \
                             the level set is within the resolution of f64 of a separatrix",
                            2.0 * unresolved.partial_time
                        ),
                    }
                });
            }
        };
        nut.nodes = series.nodes;
        let period = series.full_integral(0);
        nut.period = period * units.time();
        if !nut.period.is_finite() {
            // The period in the problem's units is beyond f64 (a fuzz input: no gravity, a
            // spin of 2.2e-308 rad/s, whose period 6.3 T is 2.8e308 s), and so is every time
            // of the motion: refused with its cause, not answered with an infinite period.
            return Err(RouthError::Overflow {
                cause: format!(
                    "the slowness of the motion (its unit of time T = {:e}, the faster of the \
                     fall sqrt(R / G) and the spin 1 / |omega|, times the period {period:e} in \
                     units of T)",
                    units.time()
                ),
                quantity: "the nutation period",
                direction: "overflow",
                value: nut.period,
            });
        }
        let [psi_poles, phi_poles] = nut.pole_angles(TAU);
        nut.advance = series.full_integral(1) + psi_poles;
        // The series follow the continuation with a signed sin theta through a pole, where the
        // azimuth itself turns by pi.
        let continued = series.full_integral(2) + phi_poles;
        nut.axis_advance = match u8::from(nut.through_top) + u8::from(nut.through_bottom) {
            0 => continued,
            passages => (continued + f64::from(passages) * PI).rem_euclid(TAU),
        };
        // T and the advance are twice the half integrals: their errors are twice the
        // truncation plus the round-off of the samples.
        nut.period_error = 2.0 * (series.truncation[0] + series.noise[0]) / period;
        nut.advance_error = 2.0 * (series.truncation[1] + series.noise[1]);
        nut.series = series;
        Ok(nut)
    }

    /// Set the phase of `initial` (dimensionless, on the level set of the series) moving at
    /// `udot0 = d gamma3 / dt`: `sigma0`, the scale of M and `psi_ref`.
    fn start_at(&mut self, initial: &State, udot0: f64) {
        let nut = self;
        let red = nut.reduction;
        let half = 0.5 * nut.width;
        // The phase of the initial state from both `cos sigma0 = (mid - u0) / half` and
        // `sin sigma0 = f(sigma0) (du/dt)0 / half`: near a turning point, where u0 fixes sigma0
        // only to the square root of its error, the rate du/dt fixes it well.
        // The distances of u0 from the turning points, from that of u0 from the pole of its
        // hemisphere (taken from the horizontal part of gamma) less the gap of the turning
        // point on that side, and the width.
        let pole = pole_of_hemisphere(&initial.gamma());
        let gap = if pole > 0.0 {
            nut.gap_top
        } else {
            nut.gap_bottom
        };
        let near = (distance_from_pole(&initial.gamma(), pole) - gap).clamp(0.0, nut.width);
        let (above, below) = if pole > 0.0 {
            (near, nut.width - near)
        } else {
            (nut.width - near, near)
        };
        let cos0 = (above - below) / (2.0 * half);
        let sigma0 = 2.0 * below.sqrt().atan2(above.sqrt());
        let mut sigma0 = if udot0 < 0.0 { TAU - sigma0 } else { sigma0 };
        for _ in 0..3 {
            let (f, _) = nut.series.value_and_integral(0, sigma0);
            sigma0 = (udot0 * f / half).atan2(cos0).rem_euclid(TAU);
        }
        nut.sigma0 = sigma0;
        // A start whose M is within the round-off of the largest M along the nutation (a
        // state nearly at rest: M of 1e-160 beside the 1 it reaches as it falls) is at rest
        // in f64: no state of the motion resolves the digits of its M, which the phase's
        // round-off alone moves by `eps` of that largest M. Its relative errors are measured
        // against the scale of M in the motion, as for a start at rest (M = 0), not against
        // its own M, against which the state at t = 0 was 1e141 off.
        let largest = nut
            .probes()
            .iter()
            .map(|x| norm(&x[3..]))
            .fold(0.0, f64::max);
        let start = norm(&initial.m());
        let at_rest = !(start > f64::EPSILON * largest);
        nut.momentum_scale = if at_rest { largest } else { start };
        // psi_ref: the rotation about e3 that takes the state of phase sigma0 at psi = 0 to
        // the initial state, fitted on the horizontal parts of gamma and of omega / |omega|
        // (so it is defined on the axis too, where gamma has no horizontal part; a start at
        // rest fits gamma alone). Each omega is divided by |omega| before the products: its
        // square underflowed for that start, and `1 / |omega|^2` overflowed.
        let (model_gamma, model_omega) = nut.gamma_omega(nut.sigma0, 0.0);
        let cross_dot =
            |a: [f64; 3], b: [f64; 3]| (a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]);
        let (y1, x1) = cross_dot(model_gamma, initial.gamma());
        let (y2, x2) = if at_rest {
            (0.0, 0.0)
        } else {
            let omega = initial.omega(red.body());
            let unit = |v: [f64; 3]| v.map(|c| c / norm(&omega));
            cross_dot(unit(model_omega), unit(omega))
        };
        nut.psi_ref = (y1 + y2).atan2(x1 + x2);
    }

    /// The states (as `[gamma, M]`) of the nutation at its turning points, its quarter phases,
    /// its widest tilt (gamma3 = 0, or the turning point nearest to it) and the initial phase,
    /// at psi = 0: where the speed of the state and the sizes of M and of its horizontal parts
    /// are largest, and the start.
    fn probes(&self) -> [[f64; 6]; 6] {
        let (u1, u2) = (self.u1, self.u2);
        let widest = (0.5 * (u1 + u2) / (0.5 * self.width))
            .clamp(-1.0, 1.0)
            .acos();
        [0.0, 0.5 * PI, PI, 1.5 * PI, widest, self.sigma0].map(|sigma| {
            let (gamma, omega) = self.gamma_omega(sigma, 0.0);
            Point {
                gamma,
                m: self.reduction.body().angular_momentum(&gamma, &omega),
            }
            .to_array()
        })
    }

    /// `P(u) = Q(u) / ((u - u1)(u2 - u))` as minus the second divided difference
    /// `Q[u1, u, u2]`, which is smooth in u for any u1, u2: the turning points are roots of Q
    /// only to its round-off, and dividing Q by `(u - u1)(u2 - u)` (or Q' from the nearer
    /// turning point, as before) would make P jump by that round-off over `(u2 - u1)^2`
    /// between the two halves of the nutation, a jump no series resolves. Computed without
    /// dividing Q by a small distance:
    ///
    /// * a wide nutation (`u2 - u1 > WIDE_NUTATION`): `(Q[u1, u] - Q[u, u2]) / (u2 - u1)`. On
    ///   the half of the nutation next to `u2` the near difference `Q[u, u2]` is the mean of
    ///   `dQ/dx` between the turning point and u in the frame of the top pole
    ///   (`x = 1 - u` from the phase, [`Reduction::q_in_frame`]), and the far one is
    ///   `Q(u) / (u - u1)`, which takes `Q(u1) = 0`: u1 is a root of Q, and `u - u1` is at
    ///   least half the width. Near the pole of a motion passing close to the axis P is small
    ///   (1e-10: a root of Q lies just beyond the turning point), and the mean of Q' over the
    ///   whole nutation, which was used for `Q[u1, u]`, left a round-off of `eps` times its
    ///   O(1) values there. The half next to `u1` is the mirror image in the frame of the
    ///   bottom pole. The two formulas differ by the round-off of Q at the turning points,
    ///   and they meet at `sigma = pi/2`, the boundary between the two sides of the panels.
    /// * a narrow one: `Q[u1, u, u2]` itself, whose round-off does not grow as `u2 - u1`
    ///   shrinks (the first form loses the digits of `u2 - u1`), in the distance from the
    ///   nearer pole.
    ///
    /// The divided differences by the Leibniz rule
    /// ([`Reduction::q_divided_differences_in_frame`]), one evaluation of Q each: exact but for
    /// round-off, however close a singularity of Q lies (the means of Q' and Q'' by
    /// Gauss-Legendre rules that they replace were bisected toward it, and an 8-point rule over
    /// a narrow nutation of a slender body next to the pole, I3 = 1e-3, left P 1e-3 off). Also
    /// returns the relative round-off of P: `eps` times the magnitudes of the terms of Q and
    /// of their slopes (curvatures), against P.
    fn cofactor_with_noise(&self, phase: &Phase) -> (f64, f64) {
        let red = &self.reduction;
        let width = self.width;
        if !self.narrow {
            // x: the distance of u from the pole on the phase's side; x_end that of the
            // turning point there; far: the distance of u from the other turning point.
            let (pole, x, x_end, far) = if phase.upper {
                (
                    1.0,
                    phase.one_minus,
                    self.gap_top,
                    phase.one_plus - self.gap_bottom,
                )
            } else {
                (
                    -1.0,
                    phase.one_plus,
                    self.gap_bottom,
                    phase.one_minus - self.gap_top,
                )
            };
            // At [x_end, x, x]: `Q[x_end, x]`, Q(x), and the round-off scales of Q and of Q'
            // at x.
            let (q, scales) = red.q_divided_differences_in_frame(pole, [x_end, x, x]);
            let p = (q.values[1] / far + q.first[0]) / width;
            let end_slope_scale = self.end_slope_scales[frame_index(pole)];
            (
                p,
                f64::EPSILON * (scales.values[1] / far + scales.first[1] + end_slope_scale)
                    / (width * p.abs()),
            )
        } else {
            // In the distance x from the pole nearer to the nutation (x = 1 - p u, so
            // `Q[u1, u, u2] = Q[x1, x, x2]`), with the turning points at its gap and the gap
            // plus the width, and x from the phase: u itself rounds x to `eps`, which moved P
            // by 4e-13 at each rounding of u (I3 = 1e-4, a nutation 1.8e-12 from the pole,
            // where Q'' changes on the scale 1e-4 of x) and stopped the series.
            let (pole, near, x) = if self.gap_top <= self.gap_bottom {
                (1.0, self.gap_top, phase.one_minus)
            } else {
                (-1.0, self.gap_bottom, phase.one_plus)
            };
            let far = near + width;
            let (q, scales) = red.q_divided_differences_in_frame(pole, [near, x, far]);
            let p = -q.second;
            // The round-off scale of Q'' over the nutation: `Q[x1, x, x2] = Q''(xi) / 2`.
            (p, f64::EPSILON * 2.0 * scales.second / p.abs())
        }
    }

    /// The two integrands at phase sigma in `[0, pi]` (`rho = pi - sigma`; sigma is exact
    /// below pi/2, rho above) with their round-off: `dt/dsigma = f = P^(-1/2)` and
    /// `dpsi/dsigma = rate f` less the pole parts `c_p / (1 - p u)`.
    fn sample(&self, sigma: f64, rho: f64) -> Result<Sample> {
        let red = &self.reduction;
        let phase = if sigma <= 0.5 * PI {
            self.phase(sigma, false)
        } else {
            let (hc, hs) = (0.5 * rho).sin_cos();
            self.phase_of_half_angle(hs, hc)
        };
        let (p, p_noise) = self.cofactor_with_noise(&phase);
        if p.is_nan() || p <= 0.0 {
            return Err(RouthError::Singular {
                formula: "the reduced equation (du/dt)^2 = Q(u)",
                reason: format!(
                    "Q / ((u - u1)(u2 - u)) = {p:e} <= 0 at gamma3 = {} between the turning \
                     points {} and {}",
                    phase.u, self.u1, self.u2
                ),
            });
        }
        let f = p.sqrt().recip();
        let f_noise = 0.5 * f * p_noise;
        let (quotient, quotient_scale) = self.jellett_quotient(&phase);
        let b = red.body();
        let ar = b.i1() * b.radius();
        // `rate f` less the pole parts `sum strength(p, c_p) / (1 - p u)`, and its round-off
        // from that of the rate (`rate_noise`), of f, and of the difference of two large
        // numbers near a pole, which rounds both.
        let angle = |rate: f64, rate_noise: f64, strength: &dyn Fn(f64, f64) -> f64| {
            let singular: f64 = self
                .poles
                .iter()
                .map(|&(pole, c)| strength(pole, c) / phase.one_minus_pole(pole))
                .sum();
            let difference_noise = 2.0 * f64::EPSILON * ((rate * f).abs() + singular.abs());
            (
                rate * f - singular,
                rate.abs() * f_noise + rate_noise * f + difference_noise,
            )
        };
        // dpsi/dt, rounded in its two terms and in those of Jellett's quotient.
        let spin = phase.spin(red);
        let (psi, psi_noise) = angle(
            red.precession_from_quotient(phase.u, quotient, spin),
            f64::EPSILON * (((phase.u * quotient).abs() + quotient_scale) / ar + spin.abs()),
            &|_, c| c,
        );
        // dphi/dt = -N / (A R (1 - u^2)), rounded in the terms of Jellett's quotient.
        let (phi, phi_noise) = angle(
            -quotient / ar,
            f64::EPSILON * quotient_scale / ar,
            &|pole, c| -pole * c,
        );
        Ok(Sample {
            values: [f, psi, phi],
            noise: [f_noise, psi_noise, phi_noise],
        })
    }

    /// Jellett's quotient `N(u) / (1 - u^2)` and the sum of the magnitudes of its terms (its
    /// round-off scale), with `N = n_p + C K x J(x)` in the frame of the pole of u's
    /// hemisphere ([`Reduction::jellett_remainder_in_frame`]; not that of the phase's half of
    /// the nutation: on the far half of a nutation near the top pole the bottom frame made N,
    /// 1e-13 there, a difference of O(1) numbers, and the advance carried an error of
    /// `eps / gap`, 1e-3 rad at a gap of 1e-13) and `1 - u^2` from the phase's
    /// accurate `1 - u` and `1 + u` (near a pole, u itself rounds 1 - u to a relative error of
    /// `eps / (1 - u)`, which the pole amplifies). Through a pole `p`, where `N(p) = 0`, the
    /// factor x is divided out exactly: `N / (1 - u^2) = C K J(x) / (1 + p u)`.
    fn jellett_quotient(&self, phase: &Phase) -> (f64, f64) {
        let red = &self.reduction;
        let (pole, x, other) = phase.nearest_pole();
        let through = if pole > 0.0 {
            self.through_top
        } else {
            self.through_bottom
        };
        let divided = red.jellett_divided(pole, x) * (red.body().i3() * red.k());
        if through {
            (divided / other, (divided / other).abs())
        } else {
            let remainder = red.frame(pole).remainder;
            let sine2 = x * other;
            (
                (divided * x + remainder) / sine2,
                ((divided * x).abs() + remainder.abs()) / sine2,
            )
        }
    }

    /// The parts of psi and of phi from the poles subtracted from the series:
    /// `sum_p c_p J_p(sigma)` and `-sum_p p c_p J_p(sigma)` with
    /// `J_p(sigma) = int_0^sigma dsigma' / (1 - p u(sigma'))`, `1 - p u = a + b cos sigma`,
    /// `a = 1 - p mid`, `b = p half`, in closed form
    /// `J = 2 / sqrt(a^2 - b^2) atan(sqrt((a - b)/(a + b)) tan(sigma/2))` (plus pi past
    /// sigma = pi), with `a - b = 1 - p u2`, `a + b = 1 - p u1` computed without cancellation.
    fn pole_angles(&self, sigma: f64) -> [f64; 2] {
        self.poles.iter().fold([0.0; 2], |[psi, phi], &(pole, c)| {
            let part = {
                let (minus, plus) = if pole > 0.0 {
                    (self.gap_top, self.gap_top + self.width)
                } else {
                    (self.gap_bottom + self.width, self.gap_bottom)
                };
                let root = (minus * plus).sqrt();
                let turns = (sigma / TAU).floor();
                let local = sigma - turns * TAU;
                let mut j = ((minus / plus).sqrt() * (0.5 * local).tan()).atan();
                if local > PI {
                    j += PI;
                }
                c * 2.0 * (j + turns * PI) / root
            };
            [psi + part, phi - pole * part]
        })
    }

    /// The tilt at phase `sigma` (in `[0, 2 pi)`); `odd` says the phase is in an odd
    /// period, where the signed sin theta of a motion through a pole has the opposite sign.
    fn phase(&self, sigma: f64, odd: bool) -> Phase {
        let flip = if odd { -1.0 } else { 1.0 };
        let (hs, hc) = (0.5 * sigma).sin_cos();
        self.phase_of_half_angle(flip * hs, flip * hc)
    }

    /// The tilt at the phase whose half angle has sine `hs` and cosine `hc`.
    fn phase_of_half_angle(&self, hs: f64, hc: f64) -> Phase {
        let half = 0.5 * self.width;
        let d1 = 2.0 * half * hs * hs;
        let d2 = 2.0 * half * hc * hc;
        let u = if d1 <= d2 { self.u1 + d1 } else { self.u2 - d2 };
        let root = (2.0 * half).sqrt();
        // sin theta = c_top c_bot with c_top^2 = 1 - u, c_bot^2 = 1 + u; at a pole crossed
        // by the motion the factor is taken with the sign of cos(sigma/2) (sin(sigma/2)),
        // which makes s, psi and omega smooth through the axis.
        let (c_top, r_top) = if self.through_top {
            (root * hc, 1.0 / root)
        } else {
            let c = (self.gap_top + d2).sqrt();
            (c, hc / c)
        };
        let (c_bot, r_bot) = if self.through_bottom {
            (root * hs, 1.0 / root)
        } else {
            let c = (self.gap_bottom + d1).sqrt();
            (c, hs / c)
        };
        Phase {
            u,
            one_minus: self.gap_top + d2,
            one_plus: self.gap_bottom + d1,
            s: c_top * c_bot,
            udot_over_s_times_f: 2.0 * half * r_top * r_bot,
            upper: d1 > d2,
        }
    }

    /// gamma and omega at phase sigma (any real), the precession angle offset by `psi_shift`.
    fn gamma_omega(&self, sigma: f64, psi_shift: f64) -> ([f64; 3], [f64; 3]) {
        let turns = (sigma / TAU).floor();
        let local = sigma - turns * TAU;
        let odd = turns.rem_euclid(2.0) == 1.0;
        let phase = self.phase(local, odd);
        let (f, _) = self.series.value_and_integral(0, local);
        let (_, psi) = self.series.value_and_integral(1, local);
        let [poles, _] = self.pole_angles(local);
        let psi = psi + poles;
        let psi = psi_shift + psi + (turns * self.advance).rem_euclid(TAU);
        self.reduction.omega_with_spin(
            phase.u,
            phase.s,
            psi,
            phase.udot_over_s_times_f / f,
            self.jellett_quotient(&phase).0,
            phase.spin(&self.reduction),
        )
    }

    /// The period in the units of the dimensionless problem.
    fn cycle(&self) -> f64 {
        self.series.full_integral(0)
    }

    /// The mean rate of the azimuth of the symmetry axis in space, `axis_advance / period`
    /// (radians per unit of the problem's time); `None` for a motion through the axis, whose
    /// azimuth jumps by pi at each passage and has an advance defined modulo 2 pi only.
    pub fn axis_mean_rate(&self) -> Option<f64> {
        (!(self.through_top || self.through_bottom)).then(|| self.axis_advance / self.period)
    }

    /// The state at time t (in the problem's units) after the initial state.
    pub fn state_at(&self, t: f64) -> Point {
        let period = self.cycle();
        let (_, t0) = self.series.value_and_integral(0, self.sigma0);
        let total = t0 + t / self.units.time();
        let turns = (total / period).floor();
        let tau = (total - turns * period).clamp(0.0, period);
        let sigma = self.series.invert_time(tau) + turns * TAU;
        let (gamma, omega) = self.gamma_omega(sigma, self.psi_ref);
        self.units.point_back(&Point {
            gamma,
            m: self.reduction.body().angular_momentum(&gamma, &omega),
        })
    }
}
