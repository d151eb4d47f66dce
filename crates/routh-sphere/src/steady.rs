//! Stationary motions of the Routh sphere (I1 = I2) and their linear stability, judged twice:
//! from the reduced equation `(du/dt)^2 = Q(u)` of [`crate::quadrature::reduction`] (a double
//! root of Q is stable when `Q'' < 0` there: nearby levels of the integrals give small
//! nutations) and, independently, from the eigenvalues of the Jacobian of the field (mg-eq)
//! by automatic differentiation.
//!
//! * The vertical spin `gamma = (0, 0, p)`, `p = +-1`, `omega = (0, 0, w)`: an equilibrium of
//!   (mg-eq). With `l = R + a p` (the distance from the centre of mass to the contact point),
//!   `Q''(p) = -2 [(C + m R l)^2 w^2 - 4 m G a p (A + m l^2)] / (A + m l^2)^2`, which gives
//!   Routh's criterion: when the centre of mass is above the geometric centre (`a p > 0`) the
//!   spin is stable if and only if `w^2 > 4 m G a p (A + m l^2) / (C + m R l)^2`; below it
//!   (`a p <= 0`) it is stable at every spin rate.
//! * Steady motions at constant tilt `0 < theta < pi`: `omega_n = 0`, Q with a double root at
//!   `u = cos theta`. For given `u` and spin `omega3`, `Q'(u) = 0` is a quadratic equation in
//!   `omega_t`, with zero, one or two roots; the state precesses about e3 at
//!   `dpsi/dt = u omega_t / s - omega3` and is an equilibrium in the frame rotating with it, where
//!   the linearisation is `J - (dpsi/dt) L` with `L x = (e3 x gamma, e3 x M)`.
//!
//! **Units.** Each computation is made dimensionless once, at its entry, in the units
//! `(R, m, T)` of its motion ([`Units`]: `T = 1 / max(sqrt(G / R), |omega3|)`), and its
//! results are converted back at the API. Every tolerance below is relative to a quantity of
//! the motion in those units, so that a body and its state scaled in mass, length or time get
//! the same answer (issue 33: the absolute `max(1.0)` of the eigenvalue test called a vertical
//! spin at 0.98 of Routh's threshold stable for m = 1e6 and unstable for m = 1: the Jacobian's
//! norm in the variables (gamma, M) grows with the mass, its eigenvalues do not).
//!
//! **One verdict.** Each criterion decides only outside its accuracy ([`Verdict`]): Q'' outside
//! its round-off, the eigenvalues outside [`EIGENVALUE_TOLERANCE`]. Where one of them cannot
//! decide, or they disagree (within about 1e-11 of Routh's threshold, where the growth rate
//! `sqrt(Q'' / 8)` is below the eigenvalues' tolerance while Q'' is above its round-off), the
//! answer is "undecided within the accuracy", with both margins.
//!
//! **Precession in space.** `dpsi/dt` is the rate of the azimuth of gamma about e3 in the body
//! frame. The symmetry axis e3 turns about the upward vertical of the fixed frame
//! ([`crate::motion`]: z up, gamma the downward normal in the body frame) at
//! `dphi/dt = -omega_t / sin theta` ([`axis_precession`]): with Euler angles (phi about the
//! upward vertical, the nutation `pi - theta` between e3 and it, the proper rotation psi_E),
//! the part of omega across e3 is `dphi/dt` times the upward vertical's horizontal part,
//! which is minus that of gamma; and `omega3 = dpsi_E/dt - u dphi/dt`, the body rate being
//! `dpsi/dt = -dpsi_E/dt`.

use crate::body::Body;
use crate::differential::jacobian;
use crate::error::{Result, RouthError};
use crate::field::vector_field;
use crate::quadrature::reduction::omega_round_off;
use crate::quadrature::Reduction;
use crate::state::{Normalise, State};
use crate::units::Units;
use nalgebra::{Complex, DMatrix, SMatrix, Schur};
use serde::Serialize;

/// Relative size of the largest real part of the Jacobian's eigenvalues below which they
/// count as imaginary, against the Frobenius norm of the Jacobian in the units of the motion
/// (`(R, m, T)`: the norm is then a rate of the motion, unchanged when the body is scaled, so
/// the test is scale-free): the zero eigenvalues of the integrals form Jordan blocks, whose
/// computed eigenvalues scatter by about sqrt(machine epsilon) = 1.5e-8 of the norm; 1e-6
/// leaves a margin of 70.
pub const EIGENVALUE_TOLERANCE: f64 = 1e-6;

/// Multiple of the round-off scale of Q'' (machine epsilon times the sum of the magnitudes of
/// the second derivatives of the terms of Q, [`Reduction::q_curvature_scale`]: relative to
/// the terms themselves, so scale-free) within which the sign of Q'' is not decided. The
/// closed form of Q'' at the vertical spins agrees with the computed one to 1e-12 of the
/// scale of its gravity term (tests); 1e3 epsilons is 2.2e-13 of the sum of the terms.
pub const CURVATURE_EPSILONS: f64 = 1e3;

/// A stationary motion with its stability by the two methods, in the body's units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stability {
    /// `Q''` at the double root of Q (stable when negative).
    pub q_second_derivative: f64,
    /// Stable by the sign of Q'' (`Q'' < 0`, whatever its round-off: [`Verdict`] weighs it).
    pub stable_by_q: bool,
    /// Largest real part of the eigenvalues of the linearisation.
    pub max_real_eigenvalue: f64,
    /// Stable by the eigenvalues (all on the imaginary axis within the tolerance
    /// [`Verdict::eigenvalue_tolerance`]).
    pub stable_by_jacobian: bool,
}

/// The decision of the two criteria together.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Decision {
    /// Stable by both, each outside its accuracy.
    Stable,
    /// Unstable by both, each outside its accuracy.
    Unstable,
    /// Q'' within its round-off, or the two criteria disagree: not decided within the
    /// accuracy of the computation.
    Undecided,
}

impl Decision {
    /// The words of the decision: "stable", "unstable", "undecided within the accuracy".
    pub fn words(self) -> &'static str {
        match self {
            Decision::Stable => "stable",
            Decision::Unstable => "unstable",
            Decision::Undecided => "undecided within the accuracy",
        }
    }
}

/// The one answer of the two criteria of a [`Stability`], with the margins each decides
/// outside of (in the body's units).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Verdict {
    /// Stable, unstable or undecided.
    pub decision: Decision,
    /// `|Q''|` at most this is within its accuracy: its sign decides nothing
    /// ([`curvature_accuracy`]).
    pub q_accuracy: f64,
    /// Real parts at most this count as zero ([`EIGENVALUE_TOLERANCE`] times the norm of the
    /// linearisation): a growth rate below it is not seen by the eigenvalues.
    pub eigenvalue_tolerance: f64,
}

impl Verdict {
    /// The decision of `stability`: each criterion's where it is outside its accuracy, the
    /// same for both; else undecided.
    fn of(stability: &Stability, q_accuracy: f64, eigenvalue_tolerance: f64) -> Verdict {
        let by_q =
            (stability.q_second_derivative.abs() > q_accuracy).then_some(stability.stable_by_q);
        let decision = match by_q {
            Some(true) if stability.stable_by_jacobian => Decision::Stable,
            Some(false) if !stability.stable_by_jacobian => Decision::Unstable,
            _ => Decision::Undecided,
        };
        Verdict {
            decision,
            q_accuracy,
            eigenvalue_tolerance,
        }
    }
}

/// The vertical spin about the symmetry axis.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VerticalSpin {
    /// gamma3 = +1 or -1.
    pub gamma3: f64,
    /// Whether the centre of mass is above the geometric centre (`a gamma3 > 0`).
    pub centre_of_mass_above: bool,
    /// Where the centre of mass is, from the sign of `a gamma3`: "above" or "below" the
    /// geometric centre, or "at the geometric centre" when a = 0.
    pub centre_of_mass: &'static str,
    /// The spin rate omega3.
    pub spin: f64,
    /// Routh's threshold |omega3| above which the spin is stable, and 0 where there is none
    /// (kept as it was; [`VerticalSpin::routh_threshold`] says `None` and why).
    pub threshold_spin: f64,
    /// Routh's threshold |omega3| above which the spin is stable, `None` where there is none.
    pub routh_threshold: Option<f64>,
    /// Why there is no threshold ([`missing_threshold`]), `None` where there is one.
    pub no_threshold: Option<&'static str>,
    /// Stability at `spin`.
    pub stability: Stability,
    /// The one answer of the two criteria.
    pub verdict: Verdict,
    /// The state.
    pub state: State,
}

/// A steady motion at constant tilt.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SteadyPrecession {
    /// The tilt theta (gamma3 = cos theta).
    pub theta: f64,
    /// The spin omega3.
    pub spin: f64,
    /// The component omega_t of omega along the horizontal projection of gamma.
    pub omega_t: f64,
    /// The round-off of omega_t (that of `Q'(cos theta)` over its slope in omega_t): an
    /// omega_t of this size is zero within the accuracy (the slow precession of a spin far
    /// above Routh's threshold, of relative size `(w_c / omega3)^2`, beyond about 1e7 w_c).
    pub omega_t_accuracy: f64,
    /// The precession rate dpsi/dt of gamma about e3 in the body frame.
    pub precession: f64,
    /// The precession rate dphi/dt of the symmetry axis e3 about the upward vertical in the
    /// fixed frame ([`axis_precession`]).
    pub axis_precession: f64,
    /// Stability.
    pub stability: Stability,
    /// The one answer of the two criteria.
    pub verdict: Verdict,
    /// The state at psi = 0.
    pub state: State,
}

/// Routh's threshold spin rate for the vertical spin at `gamma3 = pole`:
/// `w_c = sqrt(4 m G a p (A + m l^2)) / (C + m R l)`, `l = R + a p`, when `a p > 0`; else 0
/// ([`missing_threshold`] says why). Evaluated with the masses divided by the mass unit `mu`
/// of [`Units`] (`max(m, I_max / R^2)`), `sqrt(4 G a p (A/mu + n l^2) n) / (C/mu + n R l)`,
/// `n = m / mu <= 1`, so that no product of masses and inertias can overflow, nor a quotient
/// by a tiny mass (with m = 6.5e-319 and I = 8.4e-5 the quotient `I / m` was infinite and the
/// threshold NaN; found by the fuzz target `numerics_model`): the one formula that `steady`,
/// `diagram` and Python report. The lengths are divided by the unit of length `len`, R
/// rounded to a power of two ([`Units::binary`]): `G a (A / mu)` is of the size of a length to
/// the fourth, which underflowed to a threshold 0 for R = 1e-100 (the default body in units of
/// length 1e-100, accepted since the inertia about the contact point is inverted in the body's
/// own unit, issue 33). `len` a power of two, every factor is the one before times a power of
/// two: the threshold is unchanged to the bit wherever that one was normal.
pub fn routh_threshold(body: &Body, pole: f64) -> f64 {
    let units = Units::with_rate(body, 0.0);
    let (mu, len) = (units.mass(), units.binary().length());
    let n = body.m() / mu;
    let (radius, a, gravity) = (body.radius() / len, body.a() / len, body.gravity() / len);
    let l = radius + a * pole;
    let lift = 4.0 * gravity * a * pole * (body.i1() / mu / len / len + n * l * l) * n;
    lift.max(0.0).sqrt() / (body.i3() / mu / len / len + n * radius * l)
}

/// Why the vertical spin at `gamma3 = pole` has no Routh threshold (it is stable at every
/// spin rate but zero), or `None` when it has one.
pub fn missing_threshold(body: &Body, pole: f64) -> Option<&'static str> {
    if body.gravity() == 0.0 {
        Some("G = 0: without gravity there is no torque to overcome")
    } else if body.a() == 0.0 {
        Some("a = 0: the centre of mass at the geometric centre, gravity exerts no torque")
    } else if body.a() * pole < 0.0 {
        Some("the centre of mass below the geometric centre: stable at every spin")
    } else {
        None
    }
}

/// The rate `dphi/dt = -omega_t / sin theta` at which the symmetry axis e3 of a steady
/// precession at tilt `theta` turns about the upward vertical of the fixed frame (module
/// docs; checked against the motion in space, [`crate::motion`], by the tests).
pub fn axis_precession(theta: f64, omega_t: f64) -> f64 {
    -omega_t / theta.sin()
}

/// The generator `L` of the rotations about e3, `L x = (e3 x gamma, e3 x M)`: the symmetry
/// of (mg-eq) for I1 = I2, whose orbits the steady motions follow.
pub fn rotation_generator() -> SMatrix<f64, 6, 6> {
    let mut rotation = SMatrix::<f64, 6, 6>::zeros();
    for block in [0, 3] {
        rotation[(block, block + 1)] = -1.0;
        rotation[(block + 1, block)] = 1.0;
    }
    rotation
}

/// The largest real part of the eigenvalues of `J(x) - precession L` (see module docs) and
/// the Frobenius norm of that matrix, computed in the units of the state's motion
/// (`Units::of`) and returned as rates in the body's units: the norm is that of the
/// dimensionless matrix divided by T, so `EIGENVALUE_TOLERANCE * norm` is scale-free.
pub fn max_real_eigenvalue(body: &Body, state: &State, precession: f64) -> Result<(f64, f64)> {
    let units = Units::of(body, &state.omega(body));
    let t = units.time();
    let (max, norm) = spectrum(&units.body(body)?, &units.state(state)?, precession * t)?;
    Ok((max / t, norm / t))
}

/// The largest real part of the eigenvalues of `J(x) - precession L` and its Frobenius norm,
/// in the units of its arguments.
fn spectrum(body: &Body, state: &State, precession: f64) -> Result<(f64, f64)> {
    let (_, mut j) = jacobian(|x| vector_field(body, x), &state.to_array());
    j -= rotation_generator() * precession;
    let max = spectral_abscissa(&j).ok_or_else(|| RouthError::Singular {
        formula: "the eigenvalues of the Jacobian of (mg-eq)",
        reason: format!(
            "the Schur iteration did not converge at {:?}",
            state.to_array()
        ),
    })?;
    Ok((max, j.norm()))
}

/// Iterations allowed to nalgebra's Schur decomposition (a 6x6 matrix needs a few dozen).
const SCHUR_ITERATIONS: usize = 10_000;

/// The largest real part of the eigenvalues of `j`, or `None` if the Schur decomposition does
/// not converge ([`complex_eigenvalues`]).
pub fn spectral_abscissa(j: &SMatrix<f64, 6, 6>) -> Option<f64> {
    complex_eigenvalues(DMatrix::from_column_slice(6, 6, j.as_slice())).map(|values| {
        values
            .iter()
            .fold(f64::NEG_INFINITY, |acc, l| acc.max(l.re))
    })
}

/// The eigenvalues of the square matrix `m`, or `None` if the Schur decomposition does not
/// converge.
///
/// nalgebra's `complex_eigenvalues` iterates without bound, and its shifted QR iteration can
/// cycle forever on the exactly structured Jacobians of the vertical spins (zero blocks, equal
/// moduli). We bound the iterations and, if the plain matrix cycles, decompose the similar
/// matrix `Q^T m Q` for a fixed generic rotation Q: the same eigenvalues, no exact structure.
pub fn complex_eigenvalues(m: DMatrix<f64>) -> Option<Vec<Complex<f64>>> {
    let n = m.nrows();
    let values = |m: DMatrix<f64>| {
        Schur::try_new(m, f64::EPSILON, SCHUR_ITERATIONS)
            .map(|schur| schur.complex_eigenvalues().iter().copied().collect())
    };
    values(m.clone()).or_else(|| {
        let generic = DMatrix::<f64>::from_fn(n, n, |r, c| ((r * 7 + c * 3) % 11) as f64 + 0.5);
        let q = generic.qr().q();
        values(q.transpose() * m * q)
    })
}

/// The largest magnitude of the Jacobian (and of Q, Q', Q'') that the stability analysis
/// takes, in the units of the motion, and of the scales of the motion in the body's units
/// (the rate squared `1 / T^2`, the energy `m R^2 / T^2`) that its results are converted back
/// with: the Schur iteration and the round-off estimates square them, which must stay far
/// below `f64::MAX` (a limit of f64, not of any body).
const LARGEST_MAGNITUDE: f64 = 1e150;

/// Magnitudes outside `[1 / EXTREME, EXTREME]` are named as the cause of an overflow or
/// underflow.
const EXTREME: f64 = 1e50;

/// The dimensionless parameters of `body` (in the units of its motion) and the spin that lie
/// outside `[1 / EXTREME, EXTREME]` in magnitude (the cause of an overflow or underflow), or
/// all of them if none does.
fn extreme_parameters(body: &Body, spin: f64) -> String {
    let all = [
        ("a / R", body.a()),
        ("I1 / (m R^2)", body.i1()),
        ("I3 / (m R^2)", body.i3()),
        ("G T^2 / R", body.gravity()),
        ("the spin omega3 T", spin),
    ];
    let extreme: Vec<String> = all
        .iter()
        .filter(|(_, v)| v.abs() >= EXTREME || (*v != 0.0 && v.abs() <= 1.0 / EXTREME))
        .map(|(name, v)| format!("{name} = {v:e}"))
        .collect();
    if extreme.is_empty() {
        let all: Vec<String> = all.iter().map(|(n, v)| format!("{n} = {v:e}")).collect();
        format!(
            "the parameters in the units of the motion {}",
            all.join(", ")
        )
    } else {
        extreme.join(" and ")
    }
}

/// `value` if it is finite and at most [`LARGEST_MAGNITUDE`]; else the
/// [`RouthError::Overflow`] of `quantity` at `state`, caused by the extreme parameters of the
/// dimensionless `body` and `spin`: an overflow if the value is infinite or large, or if a
/// parameter or the state is large (a NaN from infinity minus infinity), else an underflow (a
/// NaN from 0 / 0).
fn representable(
    body: &Body,
    spin: f64,
    state: &[f64; 6],
    quantity: &'static str,
    value: f64,
) -> Result<f64> {
    if value.is_finite() && value.abs() <= LARGEST_MAGNITUDE {
        return Ok(value);
    }
    let large = [body.i1(), body.i3(), body.gravity(), spin]
        .iter()
        .chain(state)
        .any(|v| v.abs() >= EXTREME);
    let direction = if large || value.is_infinite() || value.abs() > LARGEST_MAGNITUDE {
        "overflow"
    } else {
        "underflow"
    };
    Err(RouthError::Overflow {
        cause: extreme_parameters(body, spin),
        quantity,
        direction,
        value,
    })
}

/// The largest rate `1 / T` of a motion of a body whose inertia unit is `inertia` (`m R^2` of
/// [`Units`]) for which its scales in the body's units, the rate squared `1 / T^2` (that of
/// Q'') and the energy `m R^2 / T^2`, stay at most [`LARGEST_MAGNITUDE`]: a limit of f64.
pub fn largest_rate(inertia: f64) -> f64 {
    (LARGEST_MAGNITUDE / inertia.max(1.0)).sqrt()
}

/// The units of a stationary motion of `body` with spin rate `spin`, refused before any work
/// when its rate exceeds [`largest_rate`].
fn motion_units(body: &Body, spin: f64) -> Result<Units> {
    let units = Units::with_rate(body, spin.abs());
    let limit = largest_rate(units.inertia());
    let rate = 1.0 / units.time();
    if rate <= limit {
        Ok(units)
    } else {
        Err(RouthError::Overflow {
            cause: format!(
                "the spin omega3 = {spin:e} (the rule: the rate of the motion at most \
                 {limit:e} for this body, so that omega3^2 and m R^2 omega3^2 stay below 1e150 \
                 and Q'', the Jacobian of (mg-eq) and their round-off in the range of f64)"
            ),
            quantity: "the scales of the stationary motion in the body's units",
            direction: "overflow",
            value: rate,
        })
    }
}

/// The accuracy of `Q''(u)` of `red` at `state` of `body` (`u = gamma3`): [`CURVATURE_EPSILONS`]
/// machine epsilons of the sum of the magnitudes of the second derivatives of its terms, plus
/// its change under the errors of the integrals that the state fixes
/// ([`Reduction::q_curvature_moved`]), their round-off and that of omega, which the state fixes
/// only to the conditioning of I_Q ([`omega_round_off`]): with I3 = 6.6e-5 (I1 = 0.03,
/// m = R = 1) to 7.5e-12, which moved Q'' = 1.75e-3 of a steady precession 0.01 from a pole by
/// 2.6e-12 between copies in other units, 30 times the round-off of its terms.
pub fn curvature_accuracy(red: &Reduction, body: &Body, state: &State) -> f64 {
    let u = state.gamma()[2];
    let (_, errors) = red.frames_of_state(state, omega_round_off(body, state));
    CURVATURE_EPSILONS * f64::EPSILON * red.q_curvature_scale(u) + red.q_curvature_moved(u, errors)
}

/// The stability of the stationary motion `state` of the dimensionless `body` rotating at
/// `precession` (0 for a vertical spin), in the units of `body`, and its verdict.
fn stability(body: &Body, state: &State, precession: f64) -> Result<(Stability, Verdict)> {
    let spin = state.omega(body)[2];
    let u = state.gamma()[2];
    let red = Reduction::of_state(body, state)?;
    let (_, _, q2) = red.q_derivatives(u);
    if !q2.is_finite() {
        representable(
            body,
            spin,
            &state.to_array(),
            "the second derivative Q''(gamma3) of the reduced potential",
            q2,
        )?;
    }
    let q_accuracy = curvature_accuracy(&red, body, state);
    let jacobian_norm = jacobian(|x| vector_field(body, x), &state.to_array())
        .1
        .norm();
    representable(
        body,
        spin,
        &state.to_array(),
        "the Jacobian of (mg-eq) at the steady motion",
        jacobian_norm,
    )?;
    let (max_re, norm) = spectrum(body, state, precession)?;
    let tolerance = EIGENVALUE_TOLERANCE * norm;
    let stability = Stability {
        q_second_derivative: q2,
        stable_by_q: q2 < 0.0,
        max_real_eigenvalue: max_re,
        stable_by_jacobian: max_re <= tolerance,
    };
    let verdict = Verdict::of(&stability, q_accuracy, tolerance);
    Ok((stability, verdict))
}

/// A stability and its verdict computed in `units` (rates in 1 / T), in the body's units.
fn stability_back((s, v): (Stability, Verdict), units: &Units) -> (Stability, Verdict) {
    let rate = 1.0 / units.time();
    (
        Stability {
            q_second_derivative: s.q_second_derivative * rate * rate,
            max_real_eigenvalue: s.max_real_eigenvalue * rate,
            ..s
        },
        Verdict {
            q_accuracy: v.q_accuracy * rate * rate,
            eigenvalue_tolerance: v.eigenvalue_tolerance * rate,
            ..v
        },
    )
}

/// Where the centre of mass of the vertical spin at `gamma3 = pole` lies: "above" or
/// "below" the geometric centre (the sign of `a pole`), or "at the geometric centre" (a = 0).
pub fn centre_of_mass(body: &Body, pole: f64) -> &'static str {
    match (body.a() * pole).partial_cmp(&0.0) {
        Some(std::cmp::Ordering::Greater) => "above",
        Some(std::cmp::Ordering::Less) => "below",
        _ => "at the geometric centre",
    }
}

/// Fail with the parameter named when the inertia about the contact point `I_Q = I + m r^2 -
/// m r r^T` (om-m) of `body` cannot be inverted: `omega = I_Q^{-1} M` (computed in the body's
/// unit of inertia, `Ball::inertia_unit`, so that no unit of the problem makes it overflow)
/// would come out NaN, or `m R^2` itself is beyond f64. Tried with an angular momentum of the
/// body's own scale, `M = m R^2 (1, 1, 1)` per unit time.
pub fn require_finite_inertia(body: &Body) -> Result<()> {
    let scale = body.m() * body.radius() * body.radius();
    let omega: [f64; 3] = body.angular_velocity(&[0.6, 0.0, 0.8], &[scale; 3]);
    if scale.is_finite() && omega.iter().all(|w: &f64| w.is_finite()) {
        Ok(())
    } else {
        Err(RouthError::Parameter {
            name: "m",
            value: body.m(),
            rule: "too large for the size of the ball: the inertia about the contact point \
                   I_Q = I + m |r|^2 - m r r^T cannot be inverted in f64 (m R^2 beyond f64, \
                   or too large against the moments)",
        })
    }
}

/// The state of the vertical spin at `gamma3 = pole` (+1 or -1) with spin rate `spin`.
pub fn vertical_spin_state(body: &Body, pole: f64, spin: f64) -> Result<State> {
    State::from_omega(body, [0.0, 0.0, pole], [0.0, 0.0, spin], Normalise::Reject)
}

/// The vertical spin at `gamma3 = pole` with spin rate `spin`, and its stability, computed
/// in the units of its motion (module docs).
pub fn vertical_spin(body: &Body, pole: f64, spin: f64) -> Result<VerticalSpin> {
    body.require_symmetric("the stationary motions")?;
    require_finite_inertia(body)?;
    if pole.abs() != 1.0 {
        return Err(RouthError::Option {
            name: "pole",
            value: pole.to_string(),
            rule: "must be +1 or -1",
        });
    }
    let units = motion_units(body, spin)?;
    let scaled = units.body(body)?;
    let t = units.time();
    let state = vertical_spin_state(&scaled, pole, spin * t)?;
    let (stability, verdict) = stability_back(stability(&scaled, &state, 0.0)?, &units);
    let no_threshold = missing_threshold(body, pole);
    let threshold = routh_threshold(body, pole);
    Ok(VerticalSpin {
        gamma3: pole,
        centre_of_mass_above: body.a() * pole > 0.0,
        centre_of_mass: centre_of_mass(body, pole),
        spin,
        threshold_spin: if no_threshold.is_none() {
            threshold
        } else {
            0.0
        },
        routh_threshold: no_threshold.is_none().then_some(threshold),
        no_threshold,
        stability,
        verdict,
        state: units.state_back(&state)?,
    })
}

/// The relative round-off, in machine epsilons of the largest sample, below which the
/// coefficient of `x^2` of a sampled quadratic counts as zero (its samples are computed with a
/// round-off of a few epsilons of their terms): relative to the samples, so scale-free.
const QUADRATIC_NOISE_EPSILONS: f64 = 64.0;

/// The relative precision of the coefficient of `x^2` of a widened fit from which it fixes
/// the far root well enough for Newton's steps: a ratio of the fit's own coefficients
/// (relative to its largest sample), so scale-free.
pub const RESOLVED_PRECISION: f64 = 1e-3;
/// Newton steps on the function itself after the fit (each doubles the correct digits).
const NEWTON_STEPS: usize = 3;

/// The real roots of a function known to be a quadratic polynomial (the condition of steady
/// precession: `Q'(cos theta)` in omega_t here, Routh's K in the diagram's Wronskian).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadraticRoots {
    /// The roots, ascending (none, one or two).
    pub roots: Vec<f64>,
    /// The round-off of each root (in the same order): that of the samples over the slope
    /// there. A root of the size of its round-off is zero within the accuracy.
    pub accuracies: Vec<f64>,
    /// `Some(bound)` when the coefficient of `x^2` is not resolved by the samples (to
    /// `RESOLVED_PRECISION`): a far root, if any, is not in `roots`, and lies beyond about
    /// `|x| = bound` (the sum of the roots is `-a1 / a2`, with `|a2|` below the resolution).
    pub unresolved: Option<f64>,
}

/// The roots of the quadratic `f` from its samples at `-w`, `0`, `w` (`f` returns each value
/// with its round-off; coefficients scaled to at most 1, so that the discriminant cannot
/// overflow; roots without cancellation, the larger from `-(a1 + sign(a1) sqrt(disc)) / 2`, the
/// other from the product), each refined by Newton steps on `f` itself, which remove the
/// round-off of the fitted coefficients. A far root that the samples fix to worse than
/// `RESOLVED_PRECISION` (the coefficient of `x^2` within the round-off: the steady precession
/// at theta = pi/2 needs omega_t ~ 13 / m, and for m = 1e-30 the fit printed 8.1e31 for
/// 1.3e31, for m = 1e-300 2.7e31 for 1.3e301) is not listed (`unresolved`). The one solver of
/// the steady-precession quadratic, for [`steady_precessions`] and the energy-momentum
/// diagram (`diagram::precession_spins`).
pub fn sampled_quadratic_roots(
    f: impl Fn(f64) -> Result<(f64, f64)>,
    w: f64,
) -> Result<QuadraticRoots> {
    let (f0, n0) = f(0.0)?;
    // The coefficients of the quadratic in `x / scale`, relative to its largest sample, and
    // the round-off of the coefficient of `x^2` (from that of the samples) in the same units.
    let fit = |scale: f64| -> Result<([f64; 3], f64, f64)> {
        let ((fm, nm), (fp, np)) = (f(-scale)?, f(scale)?);
        let size = fm.abs().max(f0.abs()).max(fp.abs());
        let size = if size > 0.0 { size } else { 1.0 };
        let (fm, c0, fp) = (fm / size, f0 / size, fp / size);
        let noise = QUADRATIC_NOISE_EPSILONS * f64::EPSILON + 2.0 * nm.max(np).max(n0) / size;
        Ok(([0.5 * (fp + fm) - c0, 0.5 * (fp - fm), c0], size, noise))
    };
    let (coefficients, size, noise) = fit(w)?;
    // Newton's method on f from `x`, with the slope of the fit at `scale`; the root and its
    // round-off, that of the samples (`noise size`) over the slope.
    let refine = |x: f64, [a2, a1, _]: [f64; 3], size: f64, scale: f64| -> Result<(f64, f64)> {
        let slope = |root: f64| (2.0 * a2 * root / scale + a1) * size / scale;
        let mut root = scale * x;
        for _ in 0..NEWTON_STEPS {
            let step = f(root)?.0 / slope(root);
            if step.is_finite() {
                root -= step;
            }
        }
        Ok((root, noise * size / slope(root).abs()))
    };
    let [a2, a1, a0] = coefficients;
    let mut roots = vec![];
    let mut unresolved = None;
    if a2.abs() * RESOLVED_PRECISION < noise {
        // The far root lies beyond |x| ~ |a1| / |a2|, fixed by the samples to worse than
        // `RESOLVED_PRECISION`: not listed; the near one is that of the linear part.
        unresolved = Some(w * a1.abs() * RESOLVED_PRECISION / noise);
        if a1.abs() > noise {
            roots.push(refine(-a0 / a1, coefficients, size, w)?);
        }
    } else {
        let disc = a1 * a1 - 4.0 * a2 * a0;
        if disc >= 0.0 {
            let big = -0.5 * (a1 + a1.signum() * disc.sqrt());
            roots.push(refine(big / a2, coefficients, size, w)?);
            if big != 0.0 {
                roots.push(refine(a0 / big, coefficients, size, w)?);
            }
        }
    }
    roots.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok(QuadraticRoots {
        accuracies: roots.iter().map(|r| r.1).collect(),
        roots: roots.into_iter().map(|r| r.0).collect(),
        unresolved,
    })
}

/// The state at tilt theta (psi = 0) with `omega = (omega_t, 0, spin)`.
fn tilted_state(body: &Body, theta: f64, omega_t: f64, spin: f64) -> Result<State> {
    let (s, u) = theta.sin_cos();
    State::from_omega(body, [s, 0.0, u], [omega_t, 0.0, spin], Normalise::Reject)
}

/// The steady precessions at one tilt that the samples resolve, and where an unlisted one
/// would be.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TiltPrecessions {
    /// The resolved steady precessions (zero, one or two), ascending in omega_t.
    pub precessions: Vec<SteadyPrecession>,
    /// `Some(bound)` when a far root of the quadratic is beyond the resolution of its samples
    /// (omega_t of order 1 / m for a tiny mass m): a steady precession with `|omega_t|`
    /// beyond about `bound`, if one exists, is not in `precessions`.
    pub unlisted_beyond: Option<f64>,
}

/// The steady motions at tilt `theta` in (0, pi) with spin rate `spin`: the roots omega_t of
/// the quadratic `Q'(cos theta) = 0` (zero, one or two), each with its stability. A far root
/// beyond the resolution of the samples is left out: [`precessions_at_tilt`] says where it
/// would be.
pub fn steady_precessions(body: &Body, theta: f64, spin: f64) -> Result<Vec<SteadyPrecession>> {
    Ok(precessions_at_tilt(body, theta, spin)?.precessions)
}

/// [`steady_precessions`] with the bound beyond which an unlisted far steady precession lies.
///
/// The roots omega_t are found in the units of the motion ([`Units`]), from samples of
/// `Q'(cos theta)` at `omega_t T = -1, 0, 1`, and converted back; every decision of
/// [`sampled_quadratic_roots`] is relative to the samples, so the roots are scale-free. (In
/// the body's units the reduction's terms carry powers of m R^2: for m = 1e25, R = 2.3e7 the
/// slope overflowed and the motion was refused, while its copy in other units was solved;
/// tests/sphere/scaling.rs.) The stability of each is judged in the units of the motion too.
pub fn precessions_at_tilt(body: &Body, theta: f64, spin: f64) -> Result<TiltPrecessions> {
    body.require_symmetric("the stationary motions")?;
    require_finite_inertia(body)?;
    if !(theta > 0.0 && theta < std::f64::consts::PI) {
        return Err(RouthError::Option {
            name: "theta",
            value: theta.to_string(),
            rule: "must lie in (0, pi); the vertical spins are separate",
        });
    }
    let units = motion_units(body, spin)?;
    let t = units.time();
    let scaled = units.body(body)?;
    let u = theta.cos();
    let slope = |omega_t: f64| -> Result<(f64, f64)> {
        let state = tilted_state(&scaled, theta, omega_t, spin * t)?;
        let red = Reduction::of_state(&scaled, &state)?;
        let value = red.q_derivatives(u).1;
        if value.is_finite() {
            Ok((value, f64::EPSILON * red.q_slope_scale(u)))
        } else {
            representable(
                &scaled,
                spin * t,
                &state.to_array(),
                "the slope Q'(cos theta) of the condition of steady precession",
                value,
            )
            .map(|v| (v, 0.0))
        }
    };
    // A far root that the samples do not resolve (`unresolved`: omega_t beyond about 1e3 / T
    // over the relative round-off of Q') is not listed; where the quadratic is linear (a = 0
    // at theta = pi/2) there is none.
    let roots = sampled_quadratic_roots(slope, 1.0)?;
    let precessions = roots
        .roots
        .into_iter()
        .zip(roots.accuracies)
        .map(|(omega_t, omega_t_accuracy)| {
            let (omega_t, omega_t_accuracy) = (omega_t / t, omega_t_accuracy / t);
            let state = tilted_state(body, theta, omega_t, spin)?;
            let precession = u * omega_t / theta.sin() - spin;
            let judged = stability(&scaled, &units.state(&state)?, precession * t)?;
            let (stability, verdict) = stability_back(judged, &units);
            Ok(SteadyPrecession {
                theta,
                spin,
                omega_t,
                omega_t_accuracy,
                precession,
                axis_precession: axis_precession(theta, omega_t),
                stability,
                verdict,
                state,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(TiltPrecessions {
        precessions,
        unlisted_beyond: roots.unresolved.map(|bound| bound / t),
    })
}
