//! Operations of a bivector on functions at a point: Hamiltonian vector fields `P dF`
//! (ham-vp), brackets `{F, G} = (P dF, dG)` (geom-eq), the numerical rank, the Casimir test
//! `P dC = 0`, and the least-squares decomposition of a field on Hamiltonian fields (ob-vp).
//! Gradients of F, G, C come from automatic differentiation of the integrals' own code.

use super::{norm, Bivector, Matrix6};
use crate::differential::{gradient, Dual6};
use nalgebra::{DMatrix, DVector, SMatrix};

/// Relative tolerance of the numerical rank: singular values below `RANK_TOLERANCE * s_max`
/// count as zero. The entries carry round-off of about 1e-16 of their size, so a structural
/// zero singular value comes out near 1e-15 s_max; the genuine ones at the audit's points
/// (away from the singular sets) exceed 1e-4 s_max. 1e-8 separates the two by orders.
pub const RANK_TOLERANCE: f64 = 1e-8;

/// The entries `P_ij(x)` in `f64`.
pub fn matrix_at<P: Bivector>(p: &P, x: &[f64; 6]) -> Matrix6<f64> {
    p.entries(x)
}

/// `P v` for a covector `v` (the components of dF).
pub fn apply(p: &Matrix6<f64>, v: &[f64; 6]) -> [f64; 6] {
    std::array::from_fn(|i| (0..6).map(|j| p[i][j] * v[j]).sum())
}

/// The Hamiltonian vector field `P dF` at `x` (ham-vp): `(P dF)_i = {x_i, F}`.
pub fn hamiltonian_field<P: Bivector>(
    p: &P,
    f: impl Fn(&[Dual6; 6]) -> Dual6,
    x: &[f64; 6],
) -> [f64; 6] {
    apply(&matrix_at(p, x), &gradient(f, x).1)
}

/// The bracket `{F, G} = (P dG, dF) = sum_ij dF_i P_ij dG_j` at `x`, with its scale
/// `|dF| |P| |dG|` (Frobenius norm of P) for relative statements.
pub fn bracket<P: Bivector>(
    p: &P,
    f: impl Fn(&[Dual6; 6]) -> Dual6,
    g: impl Fn(&[Dual6; 6]) -> Dual6,
    x: &[f64; 6],
) -> (f64, f64) {
    let m = matrix_at(p, x);
    let df = gradient(f, x).1;
    let dg = gradient(g, x).1;
    let value = df.iter().zip(apply(&m, &dg)).map(|(a, b)| a * b).sum();
    (value, norm(&df) * norm(m.iter().flatten()) * norm(&dg))
}

/// The relative Casimir defect `|P dC| / (|P| |dC|)` at `x`: zero iff C is a Casimir there.
pub fn casimir_defect<P: Bivector>(p: &P, c: impl Fn(&[Dual6; 6]) -> Dual6, x: &[f64; 6]) -> f64 {
    let m = matrix_at(p, x);
    let dc = gradient(c, x).1;
    norm(&apply(&m, &dc)) / (norm(m.iter().flatten()) * norm(&dc)).max(f64::MIN_POSITIVE)
}

/// The singular values of `P(x)`, largest first.
pub fn singular_values<P: Bivector>(p: &P, x: &[f64; 6]) -> [f64; 6] {
    let m = matrix_at(p, x);
    let matrix = SMatrix::<f64, 6, 6>::from_fn(|i, j| m[i][j]);
    let mut s: [f64; 6] = matrix.singular_values().into();
    s.sort_by(|a, b| b.total_cmp(a));
    s
}

/// The numerical rank of `P(x)`: the number of singular values above
/// [`RANK_TOLERANCE`] times the largest.
pub fn numerical_rank<P: Bivector>(p: &P, x: &[f64; 6]) -> usize {
    let s = singular_values(p, x);
    s.iter().filter(|&&v| v > RANK_TOLERANCE * s[0]).count()
}

/// A least-squares decomposition `X = sum_a c_a Y_a` of a vector on given vectors.
#[derive(Debug, Clone, PartialEq)]
pub struct Decomposition {
    /// The coefficients `c_a`.
    pub coefficients: Vec<f64>,
    /// The relative residual `|X - sum_a c_a Y_a| / |X|`.
    pub residual: f64,
}

/// Decompose `x` on the span of `basis` by least squares (SVD), as in (ob-vp), (g-eq1),
/// (g-eq2), (g-eq3): the coefficients and the relative residual.
pub fn decompose(x: &[f64; 6], basis: &[[f64; 6]]) -> Decomposition {
    let a = DMatrix::from_fn(6, basis.len(), |i, j| basis[j][i]);
    let b = DVector::from_column_slice(x);
    let c = a
        .clone()
        .svd(true, true)
        .solve(&b, 1e-14)
        .expect("SVD with both factors");
    let fitted = &a * &c;
    Decomposition {
        residual: (b - fitted).norm() / norm(x).max(f64::MIN_POSITIVE),
        coefficients: c.iter().copied().collect(),
    }
}

/// The relative residual `|X - sum_a c_a P dH_a| / max(|X|, sum_a |c_a| |P dH_a|)` of a
/// decomposition with given coefficients `c_a` of given Hamiltonian fields `P dH_a` at a
/// point: relative to the largest of the vectors that cancel.
pub fn decomposition_defect(x: &[f64; 6], terms: &[(f64, [f64; 6])]) -> f64 {
    let rest: [f64; 6] =
        std::array::from_fn(|i| x[i] - terms.iter().map(|(c, y)| c * y[i]).sum::<f64>());
    let scale = terms
        .iter()
        .map(|(c, y)| c.abs() * norm(y))
        .fold(norm(x), f64::max);
    norm(&rest) / scale.max(f64::MIN_POSITIVE)
}
