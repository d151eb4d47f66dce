//! Poisson geometry of the Routh sphere, sections 2.1 to 4 of the paper: bivector fields on the
//! six-dimensional phase space x = (gamma, M), their Schouten brackets, Hamiltonian vector
//! fields, Casimirs, ranks and the decompositions of the field X on Hamiltonian fields.
//!
//! Convention: a bivector is the matrix of brackets of the coordinates, `P_ij(x) = {x_i, x_j}`
//! with `x = (gamma1, gamma2, gamma3, M1, M2, M3)`; the Hamiltonian vector field of F is
//! `(P dF)_i = sum_j P_ij dF/dx_j = {x_i, F}`, as in (ham-vp) and (g-eq1). Every bivector of the
//! paper has a zero gamma-gamma block, so it is given by the block `Gamma_ij = {gamma_i, M_j}`
//! and the three brackets `{M1, M2}, {M1, M3}, {M2, M3}` (see [`from_blocks`]).
//!
//! Entries are written once, generic over [`Real`]; their first derivatives, which the
//! Schouten bracket needs, come from forward-mode automatic differentiation ([`Jet::at`]).

pub mod conformal_search;
pub mod deformation;
pub mod first;
pub mod flows;
pub mod hamiltonian;
pub mod lie_poisson;
pub mod reduction;
pub mod schouten;
pub mod second;
pub mod second_reduction;
pub mod sphere_gauge;

use crate::differential::Dual6;
use crate::scalar::{lift, Real};

/// Which text of a formula to evaluate: as printed in the paper, or as corrected by the audit
/// (each corrected formula documents what differs from the printed one).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reading {
    /// Exactly as printed.
    Printed,
    /// With the correction found by the audit.
    Corrected,
}

/// A 6x6 matrix as nested arrays, rows first.
pub type Matrix6<D> = [[D; 6]; 6];

/// A bivector field on the phase space: its entries `P_ij(x) = {x_i, x_j}` at any point, for
/// any scalar type (so that dual numbers give the derivatives of the same code).
pub trait Bivector {
    /// The skew-symmetric matrix `P_ij(x)`.
    fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D>;
}

/// The bivector with zero gamma-gamma block, the block `Gamma_ij = {gamma_i, M_j}` and the
/// momentum brackets `m = [{M1, M2}, {M1, M3}, {M2, M3}]`: the block form of (p-bv) and (p-bv2),
/// `P = ((0, Gamma), (-Gamma^T, M))`.
pub fn from_blocks<D: Real>(gamma_block: [[D; 3]; 3], m: [D; 3]) -> Matrix6<D> {
    let zero = lift::<D>(0.0);
    let mut p = [[zero; 6]; 6];
    for i in 0..3 {
        for j in 0..3 {
            p[i][3 + j] = gamma_block[i][j];
            p[3 + j][i] = -gamma_block[i][j];
        }
    }
    for (k, (i, j)) in [(0, 1), (0, 2), (1, 2)].into_iter().enumerate() {
        p[3 + i][3 + j] = m[k];
        p[3 + j][3 + i] = -m[k];
    }
    p
}

/// A bivector and its first derivatives at a point: `value[i][j] = P_ij(x)` and
/// `derivative[l][i][j] = dP_ij/dx_l(x)`, by forward-mode automatic differentiation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet {
    /// The entries `P_ij(x)`.
    pub value: Matrix6<f64>,
    /// The derivatives `dP_ij/dx_l (x)`, indexed `[l][i][j]`.
    pub derivative: [Matrix6<f64>; 6],
}

impl Jet {
    /// Evaluate `p` and its first derivatives at `x` (one pass with six-component duals).
    pub fn at<P: Bivector>(p: &P, x: &[f64; 6]) -> Self {
        let seeded: [Dual6; 6] = std::array::from_fn(|i| Dual6::from_re(x[i]).derivative(i));
        let entries = p.entries(&seeded);
        let mut jet = Jet {
            value: [[0.0; 6]; 6],
            derivative: [[[0.0; 6]; 6]; 6],
        };
        for (i, row) in entries.iter().enumerate() {
            for (j, e) in row.iter().enumerate() {
                jet.value[i][j] = e.re;
                if let Some(eps) = e.eps.0 {
                    for (l, d) in eps.iter().enumerate() {
                        jet.derivative[l][i][j] = *d;
                    }
                }
            }
        }
        jet
    }

    /// Frobenius norm of the entries, `|P|`.
    pub fn norm(&self) -> f64 {
        norm(self.value.iter().flatten())
    }

    /// Frobenius norm of all first derivatives, `|dP|`.
    pub fn derivative_norm(&self) -> f64 {
        norm(self.derivative.iter().flatten().flatten())
    }
}

/// Euclidean norm of a sequence of numbers.
pub fn norm<'a>(values: impl IntoIterator<Item = &'a f64>) -> f64 {
    values.into_iter().map(|v| v * v).sum::<f64>().sqrt()
}
