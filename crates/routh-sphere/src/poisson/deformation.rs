//! The trivial deformation of (cond2): a vector field Z with `P = L_Z P0`, where P is the first
//! bracket (p-br) under (cond2) and P0 the Lie-Poisson bivector of e*(3). The paper asserts
//! that Z exists ("P is a trivial deformation of P0") without giving it. Constructed here
//! (derivation in `docs/audit.md`, claim `cond2.trivial-deformation`) in the form
//!
//! `Z = (0, C(gamma) M + d(gamma) + (gamma, M) w(gamma))`:
//!
//! 1. **The gamma-M block**: `(L_Z P0)^{gamma_i M_j} = -(Gamma0 C^T)_ij` with
//!    `Gamma0 y = y x gamma`, so the rows of C are `c_n = t_n x gamma`, `t_n` the column
//!    `{gamma_i, M_n}` of P (tangent to the sphere, since `(gamma, gamma)` is a Casimir of P).
//! 2. **The momentum block**: for `Phi(gamma, c)` with `c = (gamma, M)` the Casimir of P0,
//!    `(L_Phi P0)^{M_i M_j} = eps_ijk Phi_k - D_i Phi_j + D_j Phi_i` (D of
//!    [`super::sphere_gauge`]) and the other blocks vanish; the rest `R = P - L_{CM} P0` lives in
//!    the momentum block and is affine in c, `R = R0(gamma) + c R1(gamma)`, so d and w solve the
//!    gauge equation for `R0` and `R1`.
//!
//! The Lie derivative is `(L_Z P)^{ij} = Z^k d_k P^{ij} - P^{kj} d_k Z^i - P^{ik} d_k Z^j`, with the
//! Jacobian of Z and the derivatives of P by automatic differentiation ([`lie_derivative`]).

use super::first::FirstBracket;
use super::lie_poisson::LiePoisson;
use super::sphere_gauge::{axial_vector, Gauge};
use super::{Bivector, Jet, Matrix6};
use crate::differential::{jacobian, Dual6};
use crate::scalar::{cross, dot, split, Real};

/// The Lie derivative `L_Z P` at `x` of a bivector P along a vector field Z (both written for
/// dual numbers: the Jacobian of Z and the first derivatives of P by automatic differentiation).
pub fn lie_derivative<P: Bivector>(
    z: impl Fn(&[Dual6; 6]) -> [Dual6; 6],
    p: &P,
    x: &[f64; 6],
) -> Matrix6<f64> {
    let (value, dz) = jacobian(z, x);
    let jet = Jet::at(p, x);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..6)
                .map(|k| {
                    value[k] * jet.derivative[k][i][j]
                        - jet.value[k][j] * dz[(i, k)]
                        - jet.value[i][k] * dz[(j, k)]
                })
                .sum()
        })
    })
}

/// The field Z of the trivial deformation `P = L_Z P0` for a first bracket P (meant for
/// (cond2); for another bracket the construction runs and the check says whether it holds).
#[derive(Debug, Clone, Copy)]
pub struct TrivialDeformation {
    /// The bracket P.
    pub bracket: FirstBracket,
}

impl TrivialDeformation {
    /// The part `(0, C(gamma) M)` fixed by the gamma-M block (step 1 above).
    pub fn linear_field<D: Real>(&self, x: &[D; 6]) -> [D; 6] {
        let (gamma, m) = split(x);
        let p = self.bracket.entries(x);
        let c: [D; 3] = std::array::from_fn(|n| {
            let t = [p[0][3 + n], p[1][3 + n], p[2][3 + n]];
            dot(&cross(&t, &gamma), &m)
        });
        let zero = x[0] * 0.0;
        [zero, zero, zero, c[0], c[1], c[2]]
    }

    /// The rest `R = P - L_{CM} P0` at `(gamma, M)` as the defect vector of its momentum block
    /// (see [`axial_vector`]), and the largest entry of its other blocks relative to `|P|`
    /// (zero by step 1).
    pub fn rest(&self, x: &[f64; 6]) -> ([f64; 3], f64) {
        let p = self.bracket.entries(x);
        let lie = lie_derivative(|y| self.linear_field(y), &LiePoisson, x);
        let r: Matrix6<f64> = std::array::from_fn(|i| std::array::from_fn(|j| p[i][j] - lie[i][j]));
        let mm = std::array::from_fn(|i| std::array::from_fn(|j| r[3 + i][3 + j]));
        let scale = super::norm(p.iter().flatten()).max(f64::MIN_POSITIVE);
        let other = (0..6)
            .flat_map(|i| (0..6).map(move |j| (i, j)))
            .filter(|&(i, j)| i < 3 || j < 3)
            .map(|(i, j)| r[i][j].abs())
            .fold(0.0, f64::max);
        (axial_vector(&mm), other / scale)
    }

    /// The parts `(R0, R1)` of the rest at the unit vector gamma: `R` at `M = 0` and the change
    /// of `R` from `M = 0` to `M = gamma` (`c = 1`).
    pub fn rest_parts(&self, gamma: &[f64; 3]) -> ([f64; 3], [f64; 3]) {
        let r0 = self.rest(&[gamma[0], gamma[1], gamma[2], 0.0, 0.0, 0.0]).0;
        let r = self
            .rest(&[gamma[0], gamma[1], gamma[2], gamma[0], gamma[1], gamma[2]])
            .0;
        (r0, std::array::from_fn(|i| r[i] - r0[i]))
    }

    /// The solutions `(d, w)` of the gauge equation for R0 and R1 along the meridian of gamma.
    pub fn gauges(&self, gamma: &[f64; 3]) -> (Gauge, Gauge) {
        let singular = self.singular_latitude();
        let complex = self.singularities();
        (
            Gauge::solve(|g| self.rest_parts(g).0, gamma, singular, &complex),
            Gauge::solve(|g| self.rest_parts(g).1, gamma, singular, &complex),
        )
    }

    /// The latitude where the rest is singular: the zero of the denominator
    /// `(I1 - I3) gamma3 + a m (r, gamma)` of the beta of (cond2) if it lies in (-1, 1), else -1
    /// (no real singular latitude: every meridian quadrature starts at the pole gamma3 = 1).
    fn singular_latitude(&self) -> f64 {
        let b = &self.bracket.body;
        let den = b.i1() - b.i3() + b.a() * b.a() * b.m();
        let z = -b.a() * b.m() * b.radius() / den;
        if z.abs() < 1.0 {
            z
        } else {
            -1.0
        }
    }

    /// Complex singularities in `z = gamma3` of the rest on a meridian: the zeros of
    /// `g^2(z)` (see [`super::second_reduction::quadratic_roots`]).
    fn singularities(&self) -> Vec<(f64, f64)> {
        let b = &self.bracket.body;
        let (m, r, a, i1, i3) = (b.m(), b.radius(), b.a(), b.i1(), b.i3());
        super::second_reduction::quadratic_roots(
            m * r * r * (i3 - i1),
            2.0 * i3 * m * r * a,
            i1 * m * r * r + i3 * m * a * a + i1 * i3,
        )
    }

    /// The field Z at x: `(0, C M + d + (gamma, M) w)`, d and w as first-order jets.
    pub fn field<D: Real>(&self, x: &[D; 6]) -> [D; 6] {
        let (d, w) = self.gauges(&[x[0].re(), x[1].re(), x[2].re()]);
        let (gamma, m) = split(x);
        let c = dot(&gamma, &m);
        let (d, w) = (d.field(&gamma), w.field(&gamma));
        let mut z = self.linear_field(x);
        for i in 0..3 {
            z[3 + i] += d[i] + c * w[i];
        }
        z
    }
}
