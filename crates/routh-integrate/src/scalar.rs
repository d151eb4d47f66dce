//! The scalar type the model is written in.
//!
//! Every formula of the model (the field (m-eq)/(mg-eq), the integrals (int), (int-g),
//! (raus-int), the density (rho), the bivectors of the `poisson` module) is written once,
//! generic over [`Scalar`]. With `f64` it is the fast simulation code; with the forward-mode
//! dual numbers of `num-dual` the same code yields exact gradients, Jacobians and divergences.
//!
//! [`Scalar`] asks only for what the model needs (field arithmetic, constants, `sqrt`, `recip`
//! and a fused multiply-add), so that other number types of this crate can implement it: a
//! truncated Taylor series (the Taylor series method) or a vector of SIMD lanes (sweeps).

use num_dual::DualNum;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A real scalar: the arithmetic the model is written in.
///
/// Implemented for `f64` and for every `num-dual` number over `f64` (a blanket
/// implementation over [`DualNum`]); a new number type implements these few methods.
pub trait Scalar:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Add<f64, Output = Self>
    + Sub<f64, Output = Self>
    + Mul<f64, Output = Self>
    + Div<f64, Output = Self>
{
    /// The constant `c`.
    fn from_f64(c: f64) -> Self;
    /// The square root.
    fn sqrt(self) -> Self;
    /// The reciprocal `1 / self`.
    fn recip(self) -> Self;
    /// `self * a + b`, fused (one rounding) where the type supports it.
    fn mul_add(self, a: Self, b: Self) -> Self;
}

impl<T: DualNum<Primitive = f64> + Copy> Scalar for T {
    #[inline(always)]
    fn from_f64(c: f64) -> Self {
        T::from(c)
    }

    #[inline(always)]
    fn sqrt(self) -> Self {
        DualNum::sqrt(&self)
    }

    #[inline(always)]
    fn recip(self) -> Self {
        DualNum::recip(&self)
    }

    /// Fused only where the target has a fused multiply-add instruction: without it
    /// (x86-64 without `target-cpu`), `f64::mul_add` is a call to a software `fma`, which
    /// made the default trajectory 30 % slower (BENCHMARKS.md).
    #[inline(always)]
    fn mul_add(self, a: Self, b: Self) -> Self {
        if cfg!(target_feature = "fma") {
            DualNum::mul_add(&self, a, b)
        } else {
            self * a + b
        }
    }
}

/// A [`Scalar`] that is also a `num-dual` number over `f64` (`f64` or a dual number), for
/// the Routh-sphere-specific formulas that need more than field arithmetic (`acos`, `atan2`,
/// the real part `re()`, ...): the Poisson geometry, the quadrature and the audit.
pub trait Real: Scalar + DualNum<Primitive = f64> {}

impl<T: DualNum<Primitive = f64> + Copy> Real for T {}

/// The constant `c` as a scalar of type `D`.
#[inline(always)]
pub fn lift<D: Scalar>(c: f64) -> D {
    D::from_f64(c)
}

/// Euclidean inner product `(u, v)` in R^3, with fused multiply-adds.
#[inline(always)]
pub fn dot<D: Scalar>(u: &[D; 3], v: &[D; 3]) -> D {
    u[0].mul_add(v[0], u[1].mul_add(v[1], u[2] * v[2]))
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
