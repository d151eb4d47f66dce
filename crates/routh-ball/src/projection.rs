//! Projection of a state back onto the level set of the integrals, after each integration
//! step (Hairer, Lubich, Wanner, *Geometric Numerical Integration*, section IV.4).
//!
//! The constraints are `H4 = (gamma, gamma)`, Jellett's `H3` and Routh's `K` (for the Routh
//! sphere), (M, M) and (M, gamma) (for the Chaplygin ball), and the energy `H1`, held at their values at the start. A simplified Newton iteration moves
//! the state along the span of the constraint gradients (automatic differentiation of the
//! functions of [`crate::integrals`]): `x <- x - J^T (J J^T)^{-1} (C(x) - c0)`.

use crate::ball::{AsBall, Ball, Model};
use crate::body::Body;
use crate::differential::{partials, seeded};
use crate::integrals::{
    area_integral, energy, geometric, jellett, momentum_squared, routh_integral,
};
use crate::scalar::Scalar;
use nalgebra::{SMatrix, SVector};

/// Iterations of the simplified Newton method at most: the residual after one integration
/// step is ~1e-14 relative, and each iteration squares it, so two reach round-off.
const NEWTON_ITERATIONS: usize = 2;

/// A correction below this (relative to the state) leaves a residual of the size of its
/// square, below round-off: no further iteration.
const CONVERGED: f64 = 1.0 / (1u64 << 26) as f64;

/// The most constraints of a level set: H4, two integrals of the model, H1.
const MAX: usize = 4;

/// The integrals whose level set a state is projected onto, by model.
#[derive(Debug, Clone)]
enum Constraints {
    /// H4, Jellett's H3, Routh's K, H1.
    Routh(Body),
    /// H4, (M, M), (M, gamma), H1.
    Chaplygin,
    /// H4, H1.
    Energy,
}

/// The level set `{C_i(x) = c_i}` of the integrals through a starting state.
#[derive(Debug, Clone)]
pub struct LevelSet {
    ball: Ball,
    constraints: Constraints,
    targets: [f64; MAX],
}

impl LevelSet {
    /// The level set through `x0`: H4, the integrals of the ball's model and H1 at their
    /// values there.
    pub fn through(body: &impl AsBall, x0: &[f64; 6]) -> Self {
        let ball = body.ball();
        let constraints = match ball.model() {
            Model::RouthSphere => match ball.axial_body("Routh's integrals") {
                Ok(body) => Constraints::Routh(body),
                Err(_) => Constraints::Energy,
            },
            Model::Chaplygin => Constraints::Chaplygin,
            Model::General => Constraints::Energy,
        };
        let mut level = LevelSet {
            ball,
            constraints,
            targets: [0.0; MAX],
        };
        level.targets = level.constraints(x0).0;
        level
    }

    /// The constraint functions at `x` and how many there are; the unused places are the
    /// constant zero (no derivatives), and so are their targets.
    fn constraints<D: Scalar>(&self, x: &[D; 6]) -> ([D; MAX], usize) {
        let zero = D::from_f64(0.0);
        let h4 = geometric(x);
        let h1 = energy(&self.ball, x);
        match &self.constraints {
            Constraints::Routh(body) => ([h4, jellett(body, x), routh_integral(body, x), h1], 4),
            Constraints::Chaplygin => ([h4, momentum_squared(x), area_integral(x), h1], 4),
            Constraints::Energy => ([h4, h1, zero, zero], 2),
        }
    }

    /// Move `x` onto the level set (in place): simplified Newton steps
    /// `x <- x - J^T (J J^T)^{-1} (C(x) - c0)` with the Jacobian `J` of the constraints at
    /// the start (automatic differentiation), until the correction is below
    /// 2^-26 relative to `x` (its square is then below round-off) or after two iterations
    /// (`CONVERGED`, `NEWTON_ITERATIONS`); the values after the first step in `f64`. Fixed-size
    /// arithmetic (no allocation): the constraints a model lacks are rows of zeros, with ones
    /// on the diagonal of `J J^T`.
    pub fn project(&self, x: &mut [f64; 6]) {
        let (at_start, n) = self.constraints(&seeded(x));
        let jac = SMatrix::<f64, MAX, 6>::from_fn(|i, j| partials(&at_start[i])[j]);
        let mut gram = jac * jac.transpose();
        for i in n..MAX {
            gram[(i, i)] = 1.0;
        }
        let Some(gram) = gram.cholesky() else {
            return;
        };
        let mut values: [f64; MAX] = at_start.map(|c| c.re);
        for iteration in 0..NEWTON_ITERATIONS {
            if iteration > 0 {
                values = self.constraints(x).0;
            }
            let residual = SVector::<f64, MAX>::from_fn(|i, _| values[i] - self.targets[i]);
            let step = jac.transpose() * gram.solve(&residual);
            let size = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let mut largest = 0.0f64;
            for (xi, si) in x.iter_mut().zip(step.iter()) {
                *xi -= si;
                largest = largest.max(si.abs());
            }
            if !(largest > CONVERGED * size) {
                break;
            }
        }
    }
}
