//! The stability type of a relative equilibrium, from the eigenvalues of the Jacobian of the
//! field (mg-eq) (automatic differentiation, [`crate::differential`]) restricted to the level
//! set of the integrals and taken modulo the symmetry orbit.
//!
//! A relative equilibrium `x0` moves along the orbit of the rotations about e3 at the rate
//! Omega: `X(x0) = Omega L x0` ([`rotation_generator`]). In the frame rotating with it, `x0` is
//! an equilibrium of `Y = X - Omega L`, with Jacobian `A = J(x0) - Omega L`. Three kinds of
//! directions carry no information about stability and are removed:
//!
//! * **the integrals** H1 (int-g), Jellett's H3 (int), Routh's K (raus-int) and the
//!   Casimir-like H4 = (gamma, gamma): each `F` satisfies `dF(Y) = 0` everywhere (the
//!   rotations preserve them), so `dF A = 0` at `x0`: every gradient is a left null vector of
//!   `A`, and `A` maps the whole space into `W = ker dH1 ∩ ker dH3 ∩ ker dK ∩ ker dH4`, the
//!   tangent space of the level set. We restrict `A` to `W`: its orthonormal basis is the right
//!   singular vectors of the 4 x 6 matrix of the gradients for its smallest singular values,
//!   3 of them at a steady precession (rank 3: dH1 is a combination of the others) and 4 at a
//!   vertical spin (rank 2: at the pole the gradients of H1, H3 and K are parallel). The count
//!   is fixed by the kind of equilibrium rather than by a threshold, because near the poles
//!   the third singular value becomes small too (like sin theta); the largest singular value
//!   taken as zero is reported (`rank_residual`) as a check;
//! * **the symmetry orbit** `xi = L x0`: it lies in `W` (the integrals are invariant) and
//!   `A xi = 0` (the orbit is a line of equilibria of `Y`). We take the quotient `W / xi`,
//!   represented by the orthogonal complement of `xi` in `W`; `A` induces on it the map
//!   `B = E^T A E` (`E` an orthonormal basis of the complement): the component along `xi` of
//!   `A e` is what the quotient forgets. At a vertical spin `xi = 0` and nothing is removed.
//!
//! The quotient `W / xi` is the tangent space at the equilibrium of the reduced system in
//! `(u, du/dt)`, `d^2u/dt^2 = Q'(u)/2` ([`crate::quadrature::reduction`]), and `B` is similar to
//! its linearisation: at a steady precession the two eigenvalues are `+-sqrt(Q''(u)/2)` (a
//! check that the tests make). At a vertical spin `B` is 4 x 4 (the directions gamma1,
//! gamma2, M1, M2): two imaginary pairs (elliptic), or a complex quadruplet `+-a +-ib`
//! (focus–focus, the spin below Routh's threshold).
//!
//! The classification uses the relative tolerance [`TYPE_TOLERANCE`] against the norm of
//! `B`, computed in the units of the motion ([`linearise`]): a pair of eigenvalues whose real
//! and imaginary parts are both above it is focus–focus, only real parts hyperbolic, only
//! imaginary parts elliptic; an eigenvalue below it in modulus (a fold of the critical
//! curves) is degenerate.
//!
//! The type is then checked against Routh's criterion, the sign of `Q''` at the double root
//! ([`confirmed`], the criterion of [`crate::steady`]): elliptic needs `Q'' < 0`, hyperbolic and
//! focus–focus `Q'' > 0`, each outside the round-off of Q''. Where they disagree or Q'' is
//! within its round-off (within about 1e-12 of Routh's threshold spin, where the eigenvalues
//! meet in pairs and split by sqrt(eps)), the type is [`StabilityType::Undecided`].

use crate::body::Body;
use crate::differential::{gradient, jacobian};
use crate::error::{Result, RouthError};
use crate::field::vector_field;
use crate::integrals::{energy, geometric, jellett, routh_integral};
use crate::state::State;
use crate::steady::{complex_eigenvalues, rotation_generator};
use crate::units::Units;
use nalgebra::{Complex, DMatrix, SMatrix};
use serde::Serialize;

/// Relative size (against the norm of the reduced linearisation B, computed in the units of
/// the motion by [`linearise`]: a rate of the motion, the same for every scaled copy of the
/// body, where in the body's variables (gamma, M) it grew with the mass) below which a real
/// part, an imaginary part or a modulus of an eigenvalue counts as zero. Double eigenvalues (at
/// a fold, at Routh's threshold) split by about sqrt(machine epsilon) = 1.5e-8 times the norm
/// under round-off; 1e-6 leaves a margin of 70 over that and still resolves eigenvalues of a
/// millionth of the largest.
pub const TYPE_TOLERANCE: f64 = 1e-6;

/// Relative size (against |x|, in the units of the motion, where gamma and M are both of order
/// one; in the body's variables M alone set |x|) below which the orbit direction `xi = L x`
/// counts as zero (a vertical spin, fixed by the rotations).
pub const RANK_TOLERANCE: f64 = 1e-9;

/// The stability type of a relative equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StabilityType {
    /// All eigenvalues imaginary: nearby motions stay near (nutations about it).
    Elliptic,
    /// A real pair: a saddle of the reduced motion, with homoclinic orbits.
    Hyperbolic,
    /// A complex quadruplet `+-a +-ib` (a vertical spin below Routh's threshold).
    FocusFocus,
    /// A zero eigenvalue (a fold or cusp of the critical curves).
    Degenerate,
    /// The eigenvalues and the sign of Q'' disagree, or Q'' is within its round-off: not
    /// decided within the accuracy (Routh's threshold spin).
    Undecided,
}

impl StabilityType {
    /// The name used in JSON and CSV: `elliptic`, `hyperbolic`, `focus-focus`, `degenerate`,
    /// `undecided`.
    pub fn name(self) -> &'static str {
        match self {
            StabilityType::Elliptic => "elliptic",
            StabilityType::Hyperbolic => "hyperbolic",
            StabilityType::FocusFocus => "focus-focus",
            StabilityType::Degenerate => "degenerate",
            StabilityType::Undecided => "undecided",
        }
    }
}

/// An eigenvalue, labelled: its real part (a growth rate) and its imaginary part (an angular
/// frequency).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Eigenvalue {
    /// The real part.
    pub re: f64,
    /// The imaginary part.
    pub im: f64,
}

/// The eigenvalues `(re, im)` as labelled [`Eigenvalue`]s.
pub fn labelled(eigenvalues: &[(f64, f64)]) -> Vec<Eigenvalue> {
    eigenvalues
        .iter()
        .map(|&(re, im)| Eigenvalue { re, im })
        .collect()
}

/// The reduced linearisation of a relative equilibrium and its type.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Linearisation {
    /// The largest singular value of the gradients of H1, H3, K, H4 taken as zero, relative to
    /// the largest: round-off at a relative equilibrium, of the size of the distance to one
    /// elsewhere (a check that the state is one).
    pub rank_residual: f64,
    /// The eigenvalues (re, im) of the reduced map B on W modulo the symmetry orbit.
    pub eigenvalues: Vec<(f64, f64)>,
    /// The norm of B, the scale of [`TYPE_TOLERANCE`].
    pub norm: f64,
    /// The type.
    pub kind: StabilityType,
}

/// The gradients of H1, H3, K and H4 at `x` (automatic differentiation), as the rows of a
/// 6 x 6 matrix padded with zero rows, so that its singular value decomposition gives the
/// whole right singular basis.
fn integral_gradients(body: &Body, x: &[f64; 6]) -> SMatrix<f64, 6, 6> {
    let rows = [
        gradient(|y| energy(body, y), x).1,
        gradient(|y| jellett(body, y), x).1,
        gradient(|y| routh_integral(body, y), x).1,
        gradient(geometric, x).1,
    ];
    SMatrix::<f64, 6, 6>::from_fn(|r, c| rows.get(r).map_or(0.0, |row| row[c]))
}

/// An orthonormal basis of `W` minus the direction `xi`, and the largest singular value of
/// the gradients taken as zero, relative to the largest (module docs: W has dimension 3 at a
/// steady precession, `xi != 0`, and 4 at a vertical spin, `xi = 0`).
fn reduced_basis(body: &Body, x: &[f64; 6], xi: &[f64; 6]) -> Result<(Vec<[f64; 6]>, f64)> {
    let grads = integral_gradients(body, x);
    let svd = grads.svd(false, true);
    let v_t = svd.v_t.ok_or_else(|| singular(x, "no singular vectors"))?;
    let mut order: Vec<usize> = (0..6).collect();
    order.sort_by(|&i, &j| svd.singular_values[i].total_cmp(&svd.singular_values[j]));
    let largest = svd.singular_values.max();
    let xi_norm = norm(xi);
    let moving = xi_norm > RANK_TOLERANCE * norm(x);
    let dimension = if moving { 3 } else { 4 };
    let residual = svd.singular_values[order[dimension - 1]] / largest;
    let mut kernel: Vec<[f64; 6]> = order[..dimension]
        .iter()
        .map(|&i| std::array::from_fn(|c| v_t[(i, c)]))
        .collect();
    if moving {
        // Remove the orbit direction: Gram-Schmidt against xi, then drop the vector that lost
        // the most (xi lies in W, so one of them becomes zero).
        let unit: [f64; 6] = xi.map(|v| v / xi_norm);
        for v in &mut kernel {
            let along = dot(v, &unit);
            *v = std::array::from_fn(|c| v[c] - along * unit[c]);
        }
        kernel = orthonormalise(kernel);
        kernel.truncate(2);
    }
    Ok((kernel, residual))
}

/// Modified Gram-Schmidt, dropping the vectors that are (numerically) in the span of the
/// earlier ones (left with less than 1e-6 of their unit length: a ratio, scale-free); the
/// longest remaining vectors are taken first.
fn orthonormalise(mut vectors: Vec<[f64; 6]>) -> Vec<[f64; 6]> {
    vectors.sort_by(|a, b| norm(b).total_cmp(&norm(a)));
    let mut basis: Vec<[f64; 6]> = vec![];
    for mut v in vectors {
        for b in &basis {
            let along = dot(&v, b);
            v = std::array::from_fn(|c| v[c] - along * b[c]);
        }
        let n = norm(&v);
        if n > 1e-6 {
            basis.push(v.map(|c| c / n));
        }
    }
    basis
}

fn dot(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    a.iter().zip(b).map(|(p, q)| p * q).sum()
}

fn norm(a: &[f64; 6]) -> f64 {
    dot(a, a).sqrt()
}

fn singular(x: &[f64; 6], reason: &str) -> RouthError {
    RouthError::Singular {
        formula: "the reduced linearisation of a relative equilibrium",
        reason: format!("{reason} at {x:?}"),
    }
}

/// The eigenvalues of the reduced map B (2 x 2 in closed form, 4 x 4 by a bounded Schur
/// iteration, [`complex_eigenvalues`]).
fn eigenvalues(b: &[Vec<f64>], x: &[f64; 6]) -> Result<Vec<Complex<f64>>> {
    match b.len() {
        2 => {
            let half_trace = 0.5 * (b[0][0] + b[1][1]);
            let det = b[0][0] * b[1][1] - b[0][1] * b[1][0];
            let disc = Complex::new(half_trace * half_trace - det, 0.0).sqrt();
            Ok(vec![half_trace + disc, half_trace - disc])
        }
        4 => complex_eigenvalues(DMatrix::from_fn(4, 4, |r, c| b[r][c]))
            .ok_or_else(|| singular(x, "the Schur iteration did not converge")),
        n => Err(singular(
            x,
            &format!(
                "the level set modulo the orbit has dimension {n} (expected 2 at a steady \
                 precession, 4 at a vertical spin): not a relative equilibrium"
            ),
        )),
    }
}

/// The type from the eigenvalues, with the tolerance [`TYPE_TOLERANCE`] times `norm`.
pub fn classify(eigenvalues: &[(f64, f64)], norm: f64) -> StabilityType {
    let tol = TYPE_TOLERANCE * norm.max(f64::MIN_POSITIVE);
    if eigenvalues.iter().any(|&(re, im)| re.hypot(im) <= tol) {
        StabilityType::Degenerate
    } else if eigenvalues
        .iter()
        .any(|&(re, im)| re.abs() > tol && im.abs() > tol)
    {
        StabilityType::FocusFocus
    } else if eigenvalues.iter().any(|&(re, _)| re.abs() > tol) {
        StabilityType::Hyperbolic
    } else {
        StabilityType::Elliptic
    }
}

/// The type `kind` from the eigenvalues checked against Routh's criterion (module docs):
/// kept where the sign of `q_second_derivative` (outside `q_accuracy`) says the same,
/// [`StabilityType::Undecided`] where it does not; a degenerate type is kept.
pub fn confirmed(kind: StabilityType, q_second_derivative: f64, q_accuracy: f64) -> StabilityType {
    let stable_by_q = (q_second_derivative.abs() > q_accuracy).then_some(q_second_derivative < 0.0);
    match (kind, stable_by_q) {
        (StabilityType::Elliptic, Some(true))
        | (StabilityType::Hyperbolic | StabilityType::FocusFocus, Some(false))
        | (StabilityType::Degenerate | StabilityType::Undecided, _) => kind,
        _ => StabilityType::Undecided,
    }
}

/// The reduced linearisation of the relative equilibrium `state` rotating at `precession`
/// (0 for a vertical spin) and its stability type (module docs), computed in the units of the
/// state's motion (`Units::of`: its Jacobian, the singular values of the gradients and the
/// norm of B are then those of one dimensionless problem for every scaled copy of the body,
/// so the relative tolerances are scale-free) and returned with the eigenvalues and the norm
/// as rates in the body's units.
pub fn linearise(body: &Body, state: &State, precession: f64) -> Result<Linearisation> {
    let units = Units::of(body, &state.omega(body));
    let t = units.time();
    let lin = linearise_in_units(&units.body(body)?, &units.state(state)?, precession * t)?;
    Ok(Linearisation {
        eigenvalues: lin
            .eigenvalues
            .iter()
            .map(|&(re, im)| (re / t, im / t))
            .collect(),
        norm: lin.norm / t,
        ..lin
    })
}

/// [`linearise`] in the units of its arguments.
fn linearise_in_units(body: &Body, state: &State, precession: f64) -> Result<Linearisation> {
    let x = state.to_array();
    let (_, j) = jacobian(|y| vector_field(body, y), &x);
    let generator = rotation_generator();
    let a = j - generator * precession;
    let xi: [f64; 6] = (generator * nalgebra::SVector::from(x)).into();
    let (basis, rank_residual) = reduced_basis(body, &x, &xi)?;
    let columns: Vec<[f64; 6]> = basis
        .iter()
        .map(|e| (a * nalgebra::SVector::from(*e)).into())
        .collect();
    let b: Vec<Vec<f64>> = basis
        .iter()
        .map(|row| columns.iter().map(|col| dot(row, col)).collect())
        .collect();
    let size = b.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
    let values: Vec<(f64, f64)> = eigenvalues(&b, &x)?.iter().map(|l| (l.re, l.im)).collect();
    Ok(Linearisation {
        rank_residual,
        kind: classify(&values, size),
        eigenvalues: values,
        norm: size,
    })
}
