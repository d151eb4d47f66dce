//! Projection of a state back onto the level set of the integrals, after each integration
//! step (Hairer, Lubich, Wanner, *Geometric Numerical Integration*, section IV.4).
//!
//! The constraints are `H4 = (gamma, gamma)`, Jellett's `H3` and Routh's `K` (for the Routh
//! sphere), (M, M) and (M, gamma) (for the Chaplygin ball), and the energy `H1`, held at their values at the start. A simplified Newton iteration moves
//! the state along the span of the constraint gradients (automatic differentiation of the
//! functions of [`crate::integrals`]): `x <- x - J^T (J J^T)^{-1} (C(x) - c0)`.

use crate::ball::{AsBall, Ball, Model};
use crate::differential::{partials, seeded, Dual6};
use crate::integrals::{
    area_integral, energy, geometric, jellett, momentum_squared, routh_integral,
};
use nalgebra::{DMatrix, DVector};

/// Iterations of the simplified Newton method: the residual after one integration step is
/// ~1e-14 relative, and each iteration squares it, so two reach round-off.
const NEWTON_ITERATIONS: usize = 2;

/// The level set `{C_i(x) = c_i}` of the integrals through a starting state.
#[derive(Debug, Clone)]
pub struct LevelSet {
    ball: Ball,
    targets: Vec<f64>,
}

impl LevelSet {
    /// The level set through `x0`: H4, the integrals of the ball's model and H1 at their
    /// values there.
    pub fn through(body: &impl AsBall, x0: &[f64; 6]) -> Self {
        let mut level = LevelSet {
            ball: body.ball(),
            targets: Vec::new(),
        };
        level.targets = level
            .constraints(&x0.map(Dual6::from))
            .iter()
            .map(|c| c.re)
            .collect();
        level
    }

    fn constraints(&self, x: &[Dual6; 6]) -> Vec<Dual6> {
        let ball = &self.ball;
        let mut c = vec![geometric(x)];
        match ball.model() {
            Model::RouthSphere => {
                if let Ok(body) = ball.axial_body("Routh's integrals") {
                    c.push(jellett(&body, x));
                    c.push(routh_integral(&body, x));
                }
            }
            Model::Chaplygin => {
                c.push(momentum_squared(x));
                c.push(area_integral(x));
            }
            Model::General => {}
        }
        c.push(energy(ball, x));
        c
    }

    /// Move `x` onto the level set (in place).
    pub fn project(&self, x: &mut [f64; 6]) {
        let n = self.targets.len();
        let at_start = self.constraints(&seeded(x));
        let jac = DMatrix::from_fn(n, 6, |i, j| partials(&at_start[i])[j]);
        let Some(gram) = (&jac * jac.transpose()).cholesky() else {
            return;
        };
        for iteration in 0..NEWTON_ITERATIONS {
            let values = if iteration == 0 {
                at_start.clone()
            } else {
                self.constraints(&x.map(Dual6::from))
            };
            let residual = DVector::from_fn(n, |i, _| values[i].re - self.targets[i]);
            let step = jac.transpose() * gram.solve(&residual);
            for (xi, si) in x.iter_mut().zip(step.iter()) {
                *xi -= si;
            }
        }
    }
}
