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

use crate::body::Body;
use crate::differential::jacobian;
use crate::error::{Result, RouthError};
use crate::field::vector_field;
use crate::quadrature::Reduction;
use crate::state::{Normalise, State};
use nalgebra::{SMatrix, Schur};
use serde::Serialize;

/// Relative size of the largest real part of the Jacobian's eigenvalues (against the norm of
/// the matrix) below which they count as imaginary: the zero eigenvalues of the integrals form
/// Jordan blocks, whose computed eigenvalues scatter by about sqrt(machine epsilon).
pub const EIGENVALUE_TOLERANCE: f64 = 1e-6;

/// A stationary motion with its stability by the two methods.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stability {
    /// `Q''` at the double root of Q (stable when negative).
    pub q_second_derivative: f64,
    /// Stable by the sign of Q''.
    pub stable_by_q: bool,
    /// Largest real part of the eigenvalues of the linearisation.
    pub max_real_eigenvalue: f64,
    /// Stable by the eigenvalues (all on the imaginary axis within the tolerance).
    pub stable_by_jacobian: bool,
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
    /// Routh's threshold |omega3| above which the spin is stable (0 when the centre of mass is
    /// not above the geometric centre or G = 0).
    pub threshold_spin: f64,
    /// Stability at `spin`.
    pub stability: Stability,
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
    /// The precession rate dpsi/dt of gamma about e3 in the body frame.
    pub precession: f64,
    /// Stability.
    pub stability: Stability,
    /// The state at psi = 0.
    pub state: State,
}

/// Routh's threshold spin rate for the vertical spin at `gamma3 = pole`:
/// `w_c = sqrt(4 m G a p (A + m l^2)) / (C + m R l)`, `l = R + a p`, when `a p > 0`; else 0.
pub fn routh_threshold(body: &Body, pole: f64) -> f64 {
    let l = body.radius() + body.a() * pole;
    let lift = 4.0 * body.m() * body.gravity() * body.a() * pole * (body.i1() + body.m() * l * l);
    lift.max(0.0).sqrt() / (body.i3() + body.m() * body.radius() * l)
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

/// The largest real part of the eigenvalues of `J(x) - precession L` (see module docs).
pub fn max_real_eigenvalue(body: &Body, state: &State, precession: f64) -> Result<(f64, f64)> {
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
/// not converge.
///
/// nalgebra's `complex_eigenvalues` iterates without bound, and its shifted QR iteration can
/// cycle forever on the exactly structured Jacobians of the vertical spins (zero blocks, equal
/// moduli). We bound the iterations and, if the plain matrix cycles, decompose the similar
/// matrix `Q^T j Q` for a fixed generic rotation Q: the same eigenvalues, no exact structure.
pub fn spectral_abscissa(j: &SMatrix<f64, 6, 6>) -> Option<f64> {
    let abscissa = |m: SMatrix<f64, 6, 6>| {
        Schur::try_new(m, f64::EPSILON, SCHUR_ITERATIONS).map(|schur| {
            schur
                .complex_eigenvalues()
                .iter()
                .fold(f64::NEG_INFINITY, |acc, l| acc.max(l.re))
        })
    };
    abscissa(*j).or_else(|| {
        let generic = SMatrix::<f64, 6, 6>::from_fn(|r, c| ((r * 7 + c * 3) % 11) as f64 + 0.5);
        let q = generic.qr().q();
        abscissa(q.transpose() * j * q)
    })
}

/// The largest magnitude of the Jacobian (and of Q, Q', Q'') that the stability analysis
/// takes: the Schur iteration squares the entries, which must stay far below `f64::MAX`.
const LARGEST_MAGNITUDE: f64 = 1e150;

/// Magnitudes outside `[1 / EXTREME, EXTREME]` are named as the cause of an overflow or
/// underflow.
const EXTREME: f64 = 1e50;

/// The body's parameters and the spin that lie outside `[1 / EXTREME, EXTREME]` in magnitude
/// (the cause of an overflow or underflow), or all of them if none does.
fn extreme_parameters(body: &Body, spin: f64) -> String {
    let all = [
        ("m", body.m()),
        ("R", body.radius()),
        ("a", body.a()),
        ("I1", body.i1()),
        ("I3", body.i3()),
        ("G", body.gravity()),
        ("the spin omega3", spin),
    ];
    let extreme: Vec<String> = all
        .iter()
        .filter(|(_, v)| v.abs() >= EXTREME || (*v != 0.0 && v.abs() <= 1.0 / EXTREME))
        .map(|(name, v)| format!("{name} = {v:e}"))
        .collect();
    if extreme.is_empty() {
        let all: Vec<String> = all.iter().map(|(n, v)| format!("{n} = {v:e}")).collect();
        format!("the parameters {}", all.join(", "))
    } else {
        extreme.join(" and ")
    }
}

/// `value` if it is finite and at most [`LARGEST_MAGNITUDE`]; else the
/// [`RouthError::Overflow`] of `quantity` at `state`, caused by the extreme parameters of
/// `body` and `spin`: an overflow if the value is infinite or large, or if a parameter or the
/// state is large (a NaN from infinity minus infinity), else an underflow (a NaN from 0 / 0).
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
    let large = [
        body.m(),
        body.radius(),
        body.i1(),
        body.i3(),
        body.gravity(),
        spin,
    ]
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

fn stability(body: &Body, state: &State, precession: f64) -> Result<Stability> {
    let spin = state.omega(body)[2];
    let red = Reduction::of_state(body, state)?;
    let (_, _, q2) = red.q_derivatives(state.gamma[2]);
    if !q2.is_finite() {
        representable(
            body,
            spin,
            &state.to_array(),
            "the second derivative Q''(gamma3) of the reduced potential",
            q2,
        )?;
    }
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
    let (max_re, norm) = max_real_eigenvalue(body, state, precession)?;
    Ok(Stability {
        q_second_derivative: q2,
        stable_by_q: q2 < 0.0,
        max_real_eigenvalue: max_re,
        stable_by_jacobian: max_re <= EIGENVALUE_TOLERANCE * norm.max(1.0),
    })
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
/// m r r^T` (om-m) of `body` overflows: its determinant is of the size of `(m R^2)^3` times
/// the moments, and `omega = I_Q^{-1} M` would come out NaN.
pub fn require_finite_inertia(body: &Body) -> Result<()> {
    let omega: [f64; 3] = body.angular_velocity(&[0.6, 0.0, 0.8], &[1.0, 1.0, 1.0]);
    if omega.iter().all(|w: &f64| w.is_finite()) {
        Ok(())
    } else {
        Err(RouthError::Parameter {
            name: "m",
            value: body.m(),
            rule: "too large for the size of the ball: the inertia about the contact point \
                   I_Q = I + m |r|^2 - m r r^T overflows (its determinant is of the size of \
                   (m R^2)^3 I1 I2 I3)",
        })
    }
}

/// The state of the vertical spin at `gamma3 = pole` (+1 or -1) with spin rate `spin`.
pub fn vertical_spin_state(body: &Body, pole: f64, spin: f64) -> Result<State> {
    State::from_omega(body, [0.0, 0.0, pole], [0.0, 0.0, spin], Normalise::Reject)
}

/// The vertical spin at `gamma3 = pole` with spin rate `spin`, and its stability.
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
    let state = vertical_spin_state(body, pole, spin)?;
    Ok(VerticalSpin {
        gamma3: pole,
        centre_of_mass_above: body.a() * pole > 0.0,
        centre_of_mass: centre_of_mass(body, pole),
        spin,
        threshold_spin: routh_threshold(body, pole),
        stability: stability(body, &state, 0.0)?,
        state,
    })
}

/// The relative round-off, in machine epsilons of the largest sample, below which the
/// coefficient of `x^2` of a sampled quadratic counts as zero (its samples are computed with a
/// round-off of a few epsilons of their terms).
const QUADRATIC_NOISE_EPSILONS: f64 = 64.0;

/// The relative precision of the coefficient of `x^2` of a widened fit from which it fixes
/// the far root well enough for Newton's steps.
const RESOLVED_PRECISION: f64 = 1e-3;
/// Newton steps on the function itself after the fit (each doubles the correct digits).
const NEWTON_STEPS: usize = 3;

/// The real roots of a function known to be a quadratic polynomial (the condition of steady
/// precession: `Q'(cos theta)` in omega_t here, Routh's K in the diagram's Wronskian).
#[derive(Debug, Clone, PartialEq)]
pub struct QuadraticRoots {
    /// The roots, ascending (none, one or two).
    pub roots: Vec<f64>,
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
    // Newton's method on f from `x`, with the slope of the fit at `scale`.
    let refine = |x: f64, [a2, a1, _]: [f64; 3], size: f64, scale: f64| -> Result<f64> {
        let mut root = scale * x;
        for _ in 0..NEWTON_STEPS {
            let slope = (2.0 * a2 * root / scale + a1) * size / scale;
            let step = f(root)?.0 / slope;
            if slope != 0.0 && step.is_finite() {
                root -= step;
            }
        }
        Ok(root)
    };
    let (coefficients, size, noise) = fit(w)?;
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
    roots.sort_by(f64::total_cmp);
    Ok(QuadraticRoots { roots, unresolved })
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
    let u = theta.cos();
    let slope = |omega_t: f64| -> Result<(f64, f64)> {
        let state = tilted_state(body, theta, omega_t, spin)?;
        let red = Reduction::of_state(body, &state)?;
        let value = red.q_derivatives(u).1;
        if value.is_finite() {
            Ok((value, f64::EPSILON * red.q_slope_scale(u)))
        } else {
            representable(
                body,
                spin,
                &state.to_array(),
                "the slope Q'(cos theta) of the condition of steady precession",
                value,
            )
            .map(|v| (v, 0.0))
        }
    };
    let w = spin
        .abs()
        .max((body.gravity() / body.radius()).sqrt())
        .max(1.0);
    // A far root that the samples do not resolve (`unresolved`: omega_t beyond about 1e3 w
    // over the relative round-off of Q') is not listed; where the quadratic is linear (a = 0
    // at theta = pi/2) there is none.
    let roots = sampled_quadratic_roots(slope, w)?;
    let precessions = roots
        .roots
        .into_iter()
        .map(|omega_t| {
            let state = tilted_state(body, theta, omega_t, spin)?;
            let precession = u * omega_t / theta.sin() - spin;
            Ok(SteadyPrecession {
                theta,
                spin,
                omega_t,
                precession,
                stability: stability(body, &state, precession)?,
                state,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(TiltPrecessions {
        precessions,
        unlisted_beyond: roots.unresolved,
    })
}
