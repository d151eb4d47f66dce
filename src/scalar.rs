//! The scalar type the model is written in.
//!
//! Every formula of the model (the field (m-eq)/(mg-eq), the integrals (int), (int-g),
//! (raus-int), the density (rho), the bivectors of the `poisson` module) is written once,
//! generic over [`Scalar`]. With `f64` it is the fast simulation code; with the forward-mode
//! dual numbers of `num-dual` the same code yields exact gradients, Jacobians and divergences.

use num_dual::DualNum;

/// A real scalar: `f64` or a forward-mode dual number over `f64`.
pub trait Scalar: DualNum<Primitive = f64> + Copy {}

impl<T: DualNum<Primitive = f64> + Copy> Scalar for T {}

/// The constant `c` as a scalar of type `D`.
#[inline(always)]
pub fn lift<D: Scalar>(c: f64) -> D {
    D::from(c)
}

/// Euclidean inner product `(u, v)` in R^3.
#[inline(always)]
pub fn dot<D: Scalar>(u: &[D; 3], v: &[D; 3]) -> D {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

/// Vector product `u x v` in R^3.
#[inline(always)]
pub fn cross<D: Scalar>(u: &[D; 3], v: &[D; 3]) -> [D; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// Split a phase-space point `x = (gamma, M)` into its two halves.
#[inline(always)]
pub fn split<D: Scalar>(x: &[D; 6]) -> ([D; 3], [D; 3]) {
    ([x[0], x[1], x[2]], [x[3], x[4], x[5]])
}
