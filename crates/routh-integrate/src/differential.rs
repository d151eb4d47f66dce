//! Derivatives of the model by forward-mode automatic differentiation (`num-dual`) of the
//! same generic code that simulates: gradients of integrals, the Jacobian of the field,
//! divergences, and the derivative of a function along the field.

use nalgebra::{SMatrix, SVector};
use num_dual::{gradient as nd_gradient, jacobian as nd_jacobian, DualSVec64};

/// A dual number carrying the six partial derivatives on the phase space.
pub type Dual6 = DualSVec64<6>;

/// The point `x` of any dimension `N` as dual numbers seeded with the unit directions: a
/// function evaluated there carries its value in `.re` and its gradient in `.eps`.
pub fn seeded<const N: usize>(x: &[f64; N]) -> [DualSVec64<N>; N] {
    std::array::from_fn(|i| DualSVec64::from_re(x[i]).derivative(i))
}

/// The gradient part of a dual number computed at a [`seeded`] point (the derivatives it
/// carries, zero for a constant).
pub fn partials<const N: usize>(v: &DualSVec64<N>) -> [f64; N] {
    v.eps
        .unwrap_generic(nalgebra::Const::<N>, nalgebra::Const::<1>)
        .into()
}

/// Gradient of a scalar function on the phase space, with its value.
pub fn gradient(f: impl Fn(&[Dual6; 6]) -> Dual6, x: &[f64; 6]) -> (f64, [f64; 6]) {
    let (v, g) = nd_gradient(|v: SVector<Dual6, 6>| f(&v.into()), &SVector::from(*x));
    (v, g.into())
}

/// Jacobian `J_ij = dF_i/dx_j` of a map of the phase space into itself, with its value.
pub fn jacobian(
    f: impl Fn(&[Dual6; 6]) -> [Dual6; 6],
    x: &[f64; 6],
) -> ([f64; 6], SMatrix<f64, 6, 6>) {
    let (v, j) = nd_jacobian(
        |v: SVector<Dual6, 6>| SVector::from(f(&v.into())),
        &SVector::from(*x),
    );
    (v.into(), j)
}

/// Divergence `sum_i dF_i/dx_i` of a vector field.
pub fn divergence(f: impl Fn(&[Dual6; 6]) -> [Dual6; 6], x: &[f64; 6]) -> f64 {
    jacobian(f, x).1.trace()
}

/// The derivative of `h` along the field `X`: `X(h) = (dh, X)`.
pub fn lie_derivative(h: impl Fn(&[Dual6; 6]) -> Dual6, field: &[f64; 6], x: &[f64; 6]) -> f64 {
    let (_, dh) = gradient(h, x);
    dh.iter().zip(field).map(|(a, b)| a * b).sum()
}
