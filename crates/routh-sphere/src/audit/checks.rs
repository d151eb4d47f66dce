//! The generic checks of the claims audit. Each takes the formula under test as a parameter
//! (a bivector, a field, an integral, coefficients), evaluates it at the given points and
//! returns the largest relative residual; the claims registry applies them to the printed
//! formulas, and the negative controls of the tests apply the same functions to perturbed ones.
//!
//! Every residual is relative, so that round-off gives about 1e-16 whatever the units:
//! the scale of each is stated with the function.

use crate::differential::{gradient, jacobian, Dual6};
use crate::poisson::hamiltonian::{
    bracket, casimir_defect, decompose, decomposition_defect, hamiltonian_field, singular_values,
    Decomposition, RANK_TOLERANCE,
};
use crate::poisson::schouten::{compatibility_defect, jacobi_defect};
use crate::poisson::{norm, Bivector, Matrix6};

/// A function on the phase space, written for dual numbers (gradients by AD).
pub type Function<'a> = &'a dyn Fn(&[Dual6; 6]) -> Dual6;

/// The largest value of `f` over the points (0 for no points); a NaN counts as infinite, so
/// that a formula evaluated at its singular set can never pass.
pub fn worst(points: &[[f64; 6]], f: impl Fn(&[f64; 6]) -> f64) -> f64 {
    points.iter().map(f).fold(0.0, nan_is_worst)
}

/// Conservation: `max |X(H)| / (|dH| |X|)` over the points and the integrals.
pub fn conservation(
    field: &dyn Fn(&[f64; 6]) -> [f64; 6],
    integrals: &[Function],
    points: &[[f64; 6]],
) -> f64 {
    worst(points, |x| {
        let v = field(x);
        integrals
            .iter()
            .map(|h| {
                let dh = gradient(h, x).1;
                let rate: f64 = dh.iter().zip(&v).map(|(a, b)| a * b).sum();
                rate.abs() / (norm(&dh) * norm(&v)).max(f64::MIN_POSITIVE)
            })
            .fold(0.0, f64::max)
    })
}

/// An invariant measure with density rho (rho): `div(rho X) = 0`, relative
/// `max |div(rho X)| / |d(rho X)|` (Frobenius norm of the Jacobian of `rho X`).
pub fn invariant_measure(
    field: &dyn Fn(&[Dual6; 6]) -> [Dual6; 6],
    density: Function,
    points: &[[f64; 6]],
) -> f64 {
    worst(points, |x| {
        let (_, j) = jacobian(|y| field(y).map(|c| c * density(y)), x);
        j.trace().abs() / j.norm().max(f64::MIN_POSITIVE)
    })
}

/// An identity `lhs = rhs` of functions: `max_x |lhs - rhs| / max_x max(|lhs|, |rhs|)`, the
/// defect relative to the size the two sides reach over the sample. Normalising by the
/// sample's largest value rather than pointwise keeps the residual meaningful where both sides
/// pass through zero (a quadratic integral such as `M^2 - m r^2 H1` is indefinite), where a
/// pointwise ratio would measure only the cancellation.
pub fn identity(
    lhs: &dyn Fn(&[f64; 6]) -> f64,
    rhs: &dyn Fn(&[f64; 6]) -> f64,
    points: &[[f64; 6]],
) -> f64 {
    let pairs: Vec<(f64, f64)> = points.iter().map(|x| (lhs(x), rhs(x))).collect();
    let scale = pairs
        .iter()
        .map(|(l, r)| l.abs().max(r.abs()))
        .fold(0.0, f64::max);
    let defect = pairs
        .iter()
        .map(|(l, r)| (l - r).abs())
        .fold(0.0, nan_is_worst);
    defect / scale.max(f64::MIN_POSITIVE)
}

/// `max(a, b)` with a NaN counting as infinite.
fn nan_is_worst(a: f64, b: f64) -> f64 {
    if b.is_nan() {
        f64::INFINITY
    } else {
        a.max(b)
    }
}

/// Equality of two bivectors: `max |P - Q| / max(|P|, |Q|)` (Frobenius norms).
pub fn same_bivector<P: Bivector, Q: Bivector>(p: &P, q: &Q, points: &[[f64; 6]]) -> f64 {
    worst(points, |x| matrix_distance(&p.entries(x), &q.entries(x)))
}

/// `|A - B| / max(|A|, |B|)` for two 6x6 matrices (Frobenius norms).
pub fn matrix_distance(a: &Matrix6<f64>, b: &Matrix6<f64>) -> f64 {
    let diff: Vec<f64> = a
        .iter()
        .flatten()
        .zip(b.iter().flatten())
        .map(|(u, v)| u - v)
        .collect();
    let scale = norm(a.iter().flatten()).max(norm(b.iter().flatten()));
    norm(&diff) / scale.max(f64::MIN_POSITIVE)
}

/// The Jacobi identity `[P, P] = 0` of (geom-eq): the largest relative Schouten defect
/// `max_ijk |[P, P]^{ijk}| / (2 |P| |dP|)`.
pub fn jacobi<P: Bivector>(p: &P, points: &[[f64; 6]]) -> f64 {
    worst(points, |x| jacobi_defect(p, x))
}

/// Compatibility `[P, Q] = 0`: `max_ijk |[P, Q]^{ijk}| / (|P| |dQ| + |Q| |dP|)`.
pub fn compatibility<P: Bivector, Q: Bivector>(p: &P, q: &Q, points: &[[f64; 6]]) -> f64 {
    worst(points, |x| compatibility_defect(p, q, x))
}

/// Casimirs `P dC = 0` of (geom-eq): `max |P dC| / (|P| |dC|)` over points and functions.
pub fn casimirs<P: Bivector>(p: &P, functions: &[Function], points: &[[f64; 6]]) -> f64 {
    worst(points, |x| {
        functions
            .iter()
            .map(|c| casimir_defect(p, c, x))
            .fold(0.0, f64::max)
    })
}

/// Involution `{F, G} = 0` of (geom-eq): `max |{F, G}| / (|dF| |P| |dG|)`.
pub fn involution<P: Bivector>(p: &P, f: Function, g: Function, points: &[[f64; 6]]) -> f64 {
    worst(points, |x| {
        let (value, scale) = bracket(p, f, g, x);
        value.abs() / scale.max(f64::MIN_POSITIVE)
    })
}

/// Rank `rank P = r`: the largest `s_{r+1} / s_1` (singular values, largest first) when the
/// numerical rank (tolerance [`RANK_TOLERANCE`]) is r at every point; 1 when the rank is
/// below r somewhere (`s_r / s_1 <= RANK_TOLERANCE`), which no round-off can produce.
pub fn rank<P: Bivector>(p: &P, r: usize, points: &[[f64; 6]]) -> f64 {
    worst(points, |x| {
        let s = singular_values(p, x);
        if r > 0 && s[r - 1] <= RANK_TOLERANCE * s[0] {
            1.0
        } else {
            s.get(r).map_or(0.0, |v| v / s[0])
        }
    })
}

/// Coefficients `c_a(x)` of a decomposition, one per Hamiltonian.
pub type Coefficients<'a> = &'a dyn Fn(&[f64; 6]) -> Vec<f64>;

/// A decomposition `X = sum_a c_a P dH_a` with given coefficients (ob-vp), (g-eq1), (g-eq2),
/// (g-eq3), (cham-vp): `max |X - sum_a c_a P dH_a| / max(|X|, |c_a P dH_a|)` (see
/// [`decomposition_defect`]).
pub fn decomposition<P: Bivector>(
    field: &dyn Fn(&[f64; 6]) -> [f64; 6],
    p: &P,
    coefficients: Coefficients,
    hamiltonians: &[Function],
    points: &[[f64; 6]],
) -> f64 {
    worst(points, |x| {
        let fitted: Vec<(f64, [f64; 6])> = coefficients(x)
            .into_iter()
            .zip(hamiltonians)
            .map(|(c, h)| (c, hamiltonian_field(p, h, x)))
            .collect();
        decomposition_defect(&field(x), &fitted)
    })
}

/// The least-squares decomposition of X on the fields `P dH_a` (ob-vp), compared with given
/// coefficients: `[fit, deviation]`, the largest relative residual of the fit
/// `|X - sum_a c_a^fit P dH_a| / |X|` (zero iff X lies in the span) and the largest relative
/// distance `|c - c^fit| / |c^fit|` of the given coefficients from the fitted ones.
pub fn least_squares_fit<P: Bivector>(
    field: &dyn Fn(&[f64; 6]) -> [f64; 6],
    p: &P,
    coefficients: Coefficients,
    hamiltonians: &[Function],
    points: &[[f64; 6]],
) -> [f64; 2] {
    let per_point: Vec<Decomposition> = points
        .iter()
        .map(|x| {
            let basis: Vec<[f64; 6]> = hamiltonians
                .iter()
                .map(|h| hamiltonian_field(p, h, x))
                .collect();
            decompose(&field(x), &basis)
        })
        .collect();
    let fit = per_point.iter().map(|d| d.residual).fold(0.0, f64::max);
    let deviation = points
        .iter()
        .zip(&per_point)
        .map(|(x, d)| {
            let given = coefficients(x);
            let diff: Vec<f64> = given
                .iter()
                .zip(&d.coefficients)
                .map(|(a, b)| a - b)
                .collect();
            norm(&diff) / norm(&d.coefficients).max(f64::MIN_POSITIVE)
        })
        .fold(0.0, f64::max);
    [fit, deviation]
}
