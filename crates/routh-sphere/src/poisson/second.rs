//! The second and third Poisson brackets, section 4: the bivector P' of (p-bv2) with three
//! functions alpha_i(gamma), its printed rank-4 solution of [P', P'] = 0, the coefficients of
//! (g-eq3), and the third bivector `P'' = P'|_{gamma1 alpha1 + gamma2 alpha2 = 0}`.
//!
//! Notation: `h = R gamma3 + a`, `k = I1 + m h^2`, `u = gamma1 M1 + gamma2 M2`,
//! `w = m^2 (gamma, r) H3 + m (I3 u + I1 gamma3 M3)` with `H3 = (M, r)`, `g = g(gamma)` of (rho).

use super::{from_blocks, Bivector, Matrix6};
use crate::body::Body;
use crate::scalar::{dot, lift, split, Real};

/// The three functions `alpha_i(gamma)` of (p-bv2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SecondAlphas {
    /// Generic smooth test functions `alpha1 = c0 + gamma1 gamma3`, `alpha2 = c1 - gamma2^2`,
    /// `alpha3 = c2 + gamma1 gamma2` (the involution of (p-bv2) is claimed for any alpha_i).
    Generic([f64; 3]),
    /// The printed rank-4 solution of `[P', P'] = 0`.
    Printed,
    /// The third bracket P'': `alpha1 = c0 + gamma1 gamma3`, `alpha2 = -gamma1 alpha1/gamma2`
    /// (so that `gamma1 alpha1 + gamma2 alpha2 = 0`), `alpha3 = c1 + gamma1 gamma2`.
    Third([f64; 2]),
}

impl SecondAlphas {
    /// `[alpha1, alpha2, alpha3]` at gamma.
    pub fn at<D: Real>(&self, body: &Body, gamma: &[D; 3]) -> [D; 3] {
        let [g1, g2, g3] = *gamma;
        match *self {
            SecondAlphas::Generic(c) => [g1 * g3 + c[0], -g2 * g2 + c[1], g1 * g2 + c[2]],
            SecondAlphas::Third(c) => {
                let a1 = g1 * g3 + c[0];
                [a1, -g1 * a1 / g2, g1 * g2 + c[1]]
            }
            SecondAlphas::Printed => {
                let r = body.contact_vector(gamma);
                let h = r[2];
                let k = h * h * body.m() + body.i1();
                let ig_r = g1 * r[0] * body.i1() + g2 * r[1] * body.i2() + g3 * r[2] * body.i3();
                let q =
                    (h * (body.m() * body.a()) + body.i1()) * (body.i1() * body.radius()) / ig_r;
                let s = g1 * g1 + g2 * g2;
                [
                    -k / g1 + g2 * g2 * q / g1,
                    -g2 * q,
                    k / (g1 * g3) - s * q / (g1 * g3),
                ]
            }
        }
    }
}

/// The bivector P' of (p-bv2) with the given alpha_i (P'' with [`SecondAlphas::Third`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SecondBracket {
    /// The body (I1 = I2 assumed).
    pub body: Body,
    /// The functions alpha_i.
    pub alphas: SecondAlphas,
}

impl SecondBracket {
    /// The entry `p = m R (R gamma3 + a)(gamma1 alpha1 + gamma2 alpha2)/(I1 + m (R gamma3 + a)^2)`
    /// of (p-bv2): `{gamma1, M3}' = gamma2 p`, `{gamma2, M3}' = -gamma1 p`.
    pub fn coupling<D: Real>(&self, gamma: &[D; 3]) -> D {
        let b = &self.body;
        let [a1, a2, _] = self.alphas.at(b, gamma);
        let h = gamma[2] * b.radius() + b.a();
        (gamma[0] * a1 + gamma[1] * a2) * h * (b.m() * b.radius()) / (h * h * b.m() + b.i1())
    }
}

impl Bivector for SecondBracket {
    fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
        let b = &self.body;
        let (gamma, m) = split(x);
        let [g1, g2, g3] = gamma;
        let [a1, a2, a3] = self.alphas.at(b, &gamma);
        let r = b.contact_vector(&gamma);
        let h = r[2];
        let u = g1 * m[0] + g2 * m[1];
        let g = b.routh_g(&gamma);
        let w = dot(&gamma, &r) * dot(&m, &r) * (b.m() * b.m())
            + (u * b.i3() + g3 * m[2] * b.i1()) * b.m();
        let p = self.coupling(&gamma);
        let wg = w / (g * g);
        let zero = lift::<D>(0.0);
        from_blocks(
            [
                [-g2 * (a1 + g3 * a3), -g2 * a2 + g3 * g1 * a3, g2 * p],
                [g1 * a1, g1 * a2, -g1 * p],
                [g1 * g2 * a3, -g1 * g1 * a3, zero],
            ],
            [
                -a1 * m[0] - a2 * m[1] + a3 * (g1 * m[2] - g3 * m[0])
                    - a3 * g1 * h * wg * b.radius(),
                p * m[1] + a3 * g1 * g2 * wg * (b.radius() * b.radius()),
                -p * m[0] - a3 * g1 * g1 * wg * (b.radius() * b.radius()),
            ],
        )
    }
}

/// The coefficients `(g'1, g'2)` of (g-eq3) as printed, with the alpha_i of `bracket`:
/// `g'1 = -1/(2 gamma1 alpha3 I1)`,
/// `g'2 = (I1 (I1 + m a (R gamma3 + a)) - m R (gamma, I r)) / (2 g^2 R I1^2 (R gamma3 + a))`.
pub fn g_eq3_coefficients(bracket: &SecondBracket, gamma: &[f64; 3]) -> [f64; 2] {
    let b = &bracket.body;
    let alpha3 = bracket.alphas.at(b, gamma)[2];
    let r = b.contact_vector(gamma);
    let h = r[2];
    let g = b.routh_g(gamma);
    let gamma_ir = dot(gamma, &super::first::inertia_times(b, &r));
    [
        -1.0 / (2.0 * gamma[0] * alpha3 * b.i1()),
        (b.i1() * (b.i1() + b.m() * b.a() * h) - b.m() * b.radius() * gamma_ir)
            / (2.0 * g * g * b.radius() * b.i1() * b.i1() * h),
    ]
}

/// The coefficients of (g-eq3) with the Hamiltonian H1 that make the decomposition
/// `X = g'1 P' dH1 + g'2 P' d(H3^2)` hold (found by least squares, identified in closed form).
///
/// The printed g'1, g'2 of [`g_eq3_coefficients`] are the coefficients of the quadratic
/// `H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2` in place of H1: K is a Casimir of P', and for
/// the printed alpha3, `gamma1 alpha3 = g^2 (R gamma3 + a)/(I gamma, r)`, so
/// `g'1 P' dH2 + g'2 P' d(H3^2) = I1 g'1 P' dH1 + (g'2 - m g'1/I1) P' d(H3^2)`, which are:
/// `g'1 = -1/(2 gamma1 alpha3)`, `g'2 = (I1 + m a (R gamma3 + a))/(2 g^2 R I1 (R gamma3 + a))`.
pub fn g_eq3_coefficients_h1(bracket: &SecondBracket, gamma: &[f64; 3]) -> [f64; 2] {
    let b = &bracket.body;
    let alpha3 = bracket.alphas.at(b, gamma)[2];
    let h = b.radius() * gamma[2] + b.a();
    let g = b.routh_g(gamma);
    [
        -1.0 / (2.0 * gamma[0] * alpha3),
        (b.i1() + b.m() * b.a() * h) / (2.0 * g * g * b.radius() * b.i1() * h),
    ]
}
