//! The relative equilibria of the Routh sphere at a fixed value of Jellett's integral H3, and
//! their images in the plane (K, H1) of Routh's integral (raus-int) and the energy (int-g).
//!
//! With the integrals fixed, the tilt obeys `(du/dt)^2 = Q(u)`, u = gamma3
//! ([`crate::quadrature::reduction`]). A relative equilibrium is a motion at constant tilt:
//!
//! * a **steady precession** at `u` in (-1, 1): a double root, `Q(u) = Q'(u) = 0`. Q is affine
//!   in H1, `Q = Q0(u; H3, K) + H1 q1(u)` with `q1 = dQ/dH1 = (1 - u^2)/(A + m |r|^2) > 0`, so the
//!   two conditions give `H1 = -Q0/q1` and the Wronskian condition
//!   `D(K) = Q0'(u) q1(u) - Q0(u) q1'(u) = 0`. `Q0` is a quadratic form in (H3, K) plus the
//!   potential term, so at fixed u and H3, `D` is a quadratic polynomial in K: zero, one or two
//!   steady precessions at every tilt (the two branches), found exactly from three samples of
//!   `D` and polished by Newton's method. Where the discriminant vanishes the two branches meet
//!   (found by bisection in the tilt) and the curve turns;
//! * a **vertical spin** `gamma = (0, 0, p)`, `omega = (0, 0, w)` (p = +-1, the centre of mass
//!   above the geometric centre when `a p > 0`): an equilibrium of (mg-eq). H3 and K are both
//!   linear in w, so at fixed H3 each pole gives one point `w = H3 / H3(w = 1)`.
//!
//! Each point carries its state and its stability type ([`super::stability`]).

use super::stability::{confirmed, labelled, linearise, Eigenvalue, StabilityType};
use super::tori::root;
use super::value::{plane_units, Value};
use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrals::jellett;
use crate::quadrature::Reduction;
use crate::state::{Normalise, State};
use crate::steady::{
    axis_precession, curvature_accuracy, sampled_quadratic_roots, vertical_spin_state,
};
use crate::units::Units;
use serde::Serialize;
use std::f64::consts::PI;

/// A relative equilibrium with its integrals and stability.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RelativeEquilibrium {
    /// The tilt theta (gamma3 = cos theta): 0 or pi for a vertical spin.
    pub theta: f64,
    /// The values of the integrals.
    #[serde(flatten)]
    pub value: Value,
    /// The rate `dpsi/dt` of the rotation of gamma about e3 in the body frame (0 for a
    /// vertical spin).
    pub precession: f64,
    /// The rate `dphi/dt` at which the symmetry axis e3 turns about the upward vertical in
    /// space ([`crate::steady::axis_precession`]); `None` for a vertical spin, whose axis is
    /// the vertical.
    pub axis_precession: Option<f64>,
    /// `Q''(gamma3)`; at a steady precession the reduced eigenvalues are `+-sqrt(Q''/2)`.
    pub q_second_derivative: f64,
    /// The round-off of Q'' ([`crate::steady::curvature_accuracy`]): within it, its sign
    /// decides nothing.
    pub q_accuracy: f64,
    /// The stability type: that of the eigenvalues, confirmed by the sign of Q''
    /// ([`super::stability::confirmed`]; undecided where they disagree).
    pub stability: StabilityType,
    /// The eigenvalues (re, im) of the reduced linearisation, as unlabelled pairs (kept as
    /// they were; [`RelativeEquilibrium::spectrum`] labels them).
    pub eigenvalues: Vec<(f64, f64)>,
    /// The same eigenvalues, labelled `{re, im}`.
    pub spectrum: Vec<Eigenvalue>,
    /// How far the gradients of the integrals are from the rank of a relative equilibrium
    /// ([`super::stability::Linearisation::rank_residual`]).
    pub rank_residual: f64,
    /// The state (psi = 0).
    pub state: State,
}

impl RelativeEquilibrium {
    /// The relative equilibrium through `state` rotating at `precession`, classified in the
    /// units of its motion (`Units::of`) and returned in the body's units, with `state` as
    /// given. In the body's units Q'' and its round-off came out of the reduction with the
    /// powers of m R^2 of its terms: for the copy of a balanced vertical spin with m = 1.3e22,
    /// R = 1e9 the type was "undecided" where the original's was elliptic (tests/sphere/scaling.rs).
    pub fn new(body: &Body, theta: f64, state: State, precession: f64) -> Result<Self> {
        let units = Units::of(body, &state.omega(body));
        let scaled = units.body(body)?;
        let motion = units.state(&state)?;
        let inner = Self::in_units(&scaled, theta, motion, precession * units.time())?;
        Ok(RelativeEquilibrium {
            state,
            ..inner.back(&units)?
        })
    }

    /// [`RelativeEquilibrium::new`] in the units of its arguments.
    fn in_units(body: &Body, theta: f64, state: State, precession: f64) -> Result<Self> {
        let value = Value::of_state(body, &state);
        let lin = linearise(body, &state, precession)?;
        let omega = state.omega(body);
        let horizontal = state.gamma()[0].hypot(state.gamma()[1]);
        let omega_t = (omega[0] * state.gamma()[0] + omega[1] * state.gamma()[1]) / horizontal;
        let red = value.reduction(body)?;
        let u = state.gamma()[2];
        let q_second_derivative = red.q_derivatives(u).2;
        let q_accuracy = curvature_accuracy(&red, body, &state);
        Ok(RelativeEquilibrium {
            theta,
            value,
            precession,
            axis_precession: (horizontal > 0.0).then(|| axis_precession(theta, omega_t)),
            q_second_derivative,
            q_accuracy,
            stability: confirmed(lin.kind, q_second_derivative, q_accuracy),
            spectrum: labelled(&lin.eigenvalues),
            eigenvalues: lin.eigenvalues,
            rank_residual: lin.rank_residual,
            state,
        })
    }

    /// This relative equilibrium computed in `units`, in the body's units (an error only
    /// where its M leaves f64's range there, [`Units::state_back`]).
    pub fn back(&self, units: &Units) -> Result<Self> {
        let rate = 1.0 / units.time();
        let eigenvalues: Vec<(f64, f64)> = self
            .eigenvalues
            .iter()
            .map(|&(re, im)| (re * rate, im * rate))
            .collect();
        Ok(RelativeEquilibrium {
            theta: self.theta,
            value: self.value.back(units),
            precession: self.precession * rate,
            axis_precession: self.axis_precession.map(|p| p * rate),
            q_second_derivative: self.q_second_derivative * rate * rate,
            q_accuracy: self.q_accuracy * rate * rate,
            stability: self.stability,
            spectrum: labelled(&eigenvalues),
            eigenvalues,
            rank_residual: self.rank_residual,
            state: units.state_back(&self.state)?,
        })
    }
}

/// The vertical spin at `gamma3 = pole` (+1 or -1) with Jellett's integral `h3`.
pub fn vertical_spin_at(body: &Body, pole: f64, h3: f64) -> Result<RelativeEquilibrium> {
    let unit = vertical_spin_state(body, pole, 1.0)?;
    let per_spin = jellett(body, &unit.to_array());
    let state = vertical_spin_state(body, pole, h3 / per_spin)?;
    let theta = if pole > 0.0 { 0.0 } else { PI };
    RelativeEquilibrium::new(body, theta, state, 0.0)
}

/// The scale of the spin rate at Jellett's `h3`, `1 / T` of [`plane_units`], used only to
/// condition the sampling of the quadratic D(K): it scales with the body, so the fit (whose
/// decisions are relative to its samples) is scale-free.
fn spin_scale(body: &Body, h3: f64) -> Result<f64> {
    Ok(1.0 / plane_units(body, h3)?.time())
}

/// `Q0(u)`, `Q0'(u)` (Q at H1 = 0) and `q1(u)`, `q1'(u)` (the coefficient of H1).
fn affine_parts(body: &Body, h3: f64, k: f64, u: f64) -> Result<[f64; 4]> {
    let (q0, dq0, _) = Reduction::new(body, 0.0, h3, k)?.q_derivatives(u);
    let (qa, dqa, _) = Reduction::new(body, 1.0, h3, k)?.q_derivatives(u);
    Ok([q0, dq0, qa - q0, dqa - dq0])
}

/// The Wronskian `D(K) = Q0' q1 - Q0 q1'` at tilt `u`; zero at a steady precession.
fn wronskian(body: &Body, h3: f64, k: f64, u: f64) -> Result<f64> {
    let [q0, dq0, q1, dq1] = affine_parts(body, h3, k, u)?;
    Ok(dq0 * q1 - q0 * dq1)
}

/// The coefficients `(c2, c1, c0)` of `D(K) = c2 x^2 + c1 x + c0`, `x = K / w`, from its values
/// at `x = -1, 0, 1`, and the scale `w`.
fn wronskian_quadratic(body: &Body, h3: f64, u: f64) -> Result<([f64; 3], f64)> {
    let g = Reduction::new(body, 0.0, h3, 0.0)?.routh_g(u);
    let w = g * spin_scale(body, h3)?;
    let (dm, d0, dp) = (
        wronskian(body, h3, -w, u)?,
        wronskian(body, h3, 0.0, u)?,
        wronskian(body, h3, w, u)?,
    );
    Ok(([0.5 * (dp + dm) - d0, 0.5 * (dp - dm), d0], w))
}

/// The discriminant of `D(K)` at tilt `u`, relative to its coefficients (negative: no steady
/// precession at this tilt).
fn discriminant(body: &Body, h3: f64, u: f64) -> Result<f64> {
    let ([c2, c1, c0], _) = wronskian_quadratic(body, h3, u)?;
    Ok((c1 * c1 - 4.0 * c2 * c0) / (c1 * c1 + (4.0 * c2 * c0).abs()).max(f64::MIN_POSITIVE))
}

/// The values K of Routh's integral of the steady precessions at tilt `u` = cos theta in
/// (-1, 1) with Jellett's `h3`: the real roots of `D(K)`, ascending (none, one or two).
pub fn precession_spins(body: &Body, h3: f64, u: f64) -> Result<Vec<f64>> {
    let g = Reduction::new(body, 0.0, h3, 0.0)?.routh_g(u);
    // A root beyond the resolution of D's samples (`unresolved`) lies outside any window of
    // the diagram: it is left out.
    // The round-off of D: a few epsilons of its value (`sampled_quadratic_roots` adds them).
    let d = |k: f64| wronskian(body, h3, k, u).map(|d| (d, 0.0));
    Ok(sampled_quadratic_roots(d, g * spin_scale(body, h3)?)?.roots)
}

/// The steady precession at tilt `theta` in (0, pi) with integrals `h3` and `k` (a root of
/// [`precession_spins`]): its energy `H1 = -Q0/q1`, state and stability.
pub fn steady_precession_at(
    body: &Body,
    h3: f64,
    theta: f64,
    k: f64,
) -> Result<RelativeEquilibrium> {
    let (s, u) = theta.sin_cos();
    let [q0, _, q1, _] = affine_parts(body, h3, k, u)?;
    let red = Reduction::new(body, -q0 / q1, h3, k)?;
    let (gamma, omega) = red.omega(u, s, 0.0, 0.0, red.jellett_quotient(u));
    let state = State::from_omega(body, gamma, omega, Normalise::Reject)?;
    RelativeEquilibrium::new(body, theta, state, red.precession_rate(u))
}

/// A piece of a critical curve of steady precessions with one stability type, ordered by
/// the tilt.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CriticalCurve {
    /// The number of the continuous branch the piece belongs to (pieces of one branch that
    /// differ in stability type share it).
    pub branch: usize,
    /// The stability type of its points (a piece ends where the type changes; the next piece
    /// starts at its last point, so that the curve is drawn without a gap).
    pub stability: StabilityType,
    /// The points, ordered by the tilt.
    pub points: Vec<RelativeEquilibrium>,
}

impl CriticalCurve {
    /// This curve computed in `units`, in the body's units.
    pub fn back(&self, units: &Units) -> Result<Self> {
        Ok(CriticalCurve {
            branch: self.branch,
            stability: self.stability,
            points: self
                .points
                .iter()
                .map(|p| p.back(units))
                .collect::<Result<_>>()?,
        })
    }
}

/// The tilt between `a` (real roots) and `b` (none) where the discriminant of D vanishes.
fn fold_tilt(body: &Body, h3: f64, a: f64, b: f64) -> Result<f64> {
    root(
        |theta| discriminant(body, h3, theta.cos()).unwrap_or(f64::NAN),
        a,
        b,
        "the fold of the steady precessions",
    )
}

/// The least sin(theta) of the steady precessions computed. Near a pole the two branches of
/// D(K) = 0 merge into the vertical spin (a double root), so K is found to about
/// `eps / sin^2 theta` and the state, built from K, is a relative equilibrium only to that
/// accuracy: measured on the default body, the part of the field (mg-eq) across the symmetry
/// orbit is 2e-12 of the field at theta = 0.1, 1e-11 at 0.03, 3e-8 at 0.003. Within 0.05 rad
/// (2.9 degrees) of the poles the curves are left out; the vertical spins at their ends are
/// computed exactly ([`vertical_spin_at`]).
pub const POLE_GAP: f64 = 0.05;

/// The steady precessions at `samples` tilts equally spaced in `[asin POLE_GAP, pi - asin
/// POLE_GAP]`, with the folds where two branches meet refined and added: for each tilt, the
/// spins K ascending.
fn precession_table(body: &Body, h3: f64, samples: usize) -> Result<Vec<(f64, Vec<f64>)>> {
    let mut table: Vec<(f64, Vec<f64>)> = vec![];
    let first = POLE_GAP.asin();
    for i in 0..samples {
        let theta = first + (PI - 2.0 * first) * i as f64 / (samples - 1) as f64;
        let spins = precession_spins(body, h3, theta.cos())?;
        if let Some((prev_theta, prev)) = table.last() {
            if prev.len() != spins.len() && prev.len().max(spins.len()) == 2 {
                let (with, without) = if prev.len() == 2 {
                    (*prev_theta, theta)
                } else {
                    (theta, *prev_theta)
                };
                // A fold when the discriminant changes sign; when the leading coefficient does,
                // a root runs off to infinity instead and there is nothing to join.
                let leading = |theta: f64| -> Result<f64> {
                    Ok(wronskian_quadratic(body, h3, theta.cos())?.0[0])
                };
                if leading(with)? * leading(without)? > 0.0 {
                    let fold = fold_tilt(body, h3, with, without)?;
                    let ([c2, c1, _], w) = wronskian_quadratic(body, h3, fold.cos())?;
                    let double = -0.5 * c1 / c2 * w;
                    table.push((fold, vec![double, double]));
                }
            }
        }
        table.push((theta, spins));
    }
    Ok(table)
}

/// The critical curves of the steady precessions at Jellett's `h3`, sampled at `samples`
/// tilts (plus the folds), split into pieces of one stability type.
///
/// The roots of D(K) at successive tilts are joined into continuous branches by the pairing
/// that moves them least; a root that jumps by more than a quarter of `k_limit` starts a new
/// branch. Points with `|K| > k_limit` are left out (the branch breaks there): where the
/// leading coefficient of D(K) vanishes, one root runs off to infinite spin and comes back from
/// the other side.
pub fn critical_curves(
    body: &Body,
    h3: f64,
    samples: usize,
    k_limit: f64,
) -> Result<Vec<CriticalCurve>> {
    body.require_symmetric("the relative equilibria")?;
    if samples < 2 {
        return Err(RouthError::Option {
            name: "samples",
            value: samples.to_string(),
            rule: "the critical curves need at least 2 tilts",
        });
    }
    let jump = 0.25 * k_limit;
    let mut branches: Vec<Vec<(f64, f64)>> = vec![];
    let mut open: Vec<usize> = vec![];
    for (theta, spins) in precession_table(body, h3, samples)? {
        let spins: Vec<f64> = spins.into_iter().filter(|k| k.abs() <= k_limit).collect();
        let last = |b: usize| branches[b].last().map_or(f64::NAN, |p| p.1);
        // Join each root to the open branch nearest to it, the nearest pairs first.
        let mut candidates: Vec<(f64, usize, usize)> = open
            .iter()
            .flat_map(|&b| spins.iter().enumerate().map(move |(j, &k)| (b, j, k)))
            .map(|(b, j, k)| ((last(b) - k).abs(), b, j))
            .filter(|&(d, _, _)| d <= jump)
            .collect();
        candidates.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut pairs: Vec<(usize, usize)> = vec![];
        for (_, b, j) in candidates {
            if pairs.iter().all(|&(pb, pj)| pb != b && pj != j) {
                pairs.push((b, j));
            }
        }
        let mut next = vec![];
        for (j, &k) in spins.iter().enumerate() {
            let branch = match pairs.iter().find(|&&(_, jj)| jj == j) {
                Some(&(b, _)) => b,
                None => {
                    branches.push(vec![]);
                    branches.len() - 1
                }
            };
            branches[branch].push((theta, k));
            next.push(branch);
        }
        open = next;
    }
    let mut curves: Vec<CriticalCurve> = vec![];
    for (branch, points) in branches.iter().enumerate() {
        let mut piece: Option<CriticalCurve> = None;
        for &(theta, k) in points {
            let point = steady_precession_at(body, h3, theta, k)?;
            match &mut piece {
                Some(curve) if curve.stability == point.stability => curve.points.push(point),
                _ => {
                    let mut start: Vec<RelativeEquilibrium> = vec![];
                    if let Some(curve) = piece.take() {
                        start.extend(curve.points.last().cloned());
                        curves.push(curve);
                    }
                    let stability = point.stability;
                    start.push(point);
                    piece = Some(CriticalCurve {
                        branch,
                        stability,
                        points: start,
                    });
                }
            }
        }
        curves.extend(piece);
    }
    Ok(curves)
}
