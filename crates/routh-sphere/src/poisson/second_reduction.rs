//! The change of momenta `M -> L` that takes the second bracket P' of (p-bv2) to the
//! Lie-Poisson bracket (e3) of e*(3), asserted after (g-eq3) without a formula. Constructed
//! here as (p-map) is for the first bracket (derivation in `docs/audit.md`, claim `p-bv2.e3`):
//!
//! `L = A(gamma) M + K v(gamma)`, `K = g omega3` the Casimir of P'.
//!
//! 1. **The gamma-M block** fixes the rows `a_i` of A modulo the kernel `dK/dM` of the block
//!    `Gamma'` of P': `{L_i, gamma_j}' = eps_ijk gamma_k` reads `Gamma' a_i = e_i x gamma`. The
//!    columns of `Gamma'` give `Gamma' a = sigma (e3 x gamma) + alpha3 tau (e2 x gamma)` with
//!    `sigma = alpha1 a1 + alpha2 a2 - p a3`, `tau = gamma1 a2 - gamma2 a1` (p of
//!    [`SecondBracket::coupling`]); with `e1 x gamma = -(gamma2 (e2 x gamma) + gamma3 (e3 x
//!    gamma))/gamma1` and the gauge `a_13 = a_23 = 0`, `a_3 = (0, 0, -1/p)`, each of `a_1`, `a_2`
//!    is a 2x2 solve ([`SecondMap::rows`]).
//! 2. **The momentum block** of `A M` then misses e*(3) by a defect `K G_ij(gamma)` (a Casimir
//!    times a function of gamma: the defect commutes with every gamma_i by the Jacobi identity,
//!    and it vanishes at K = 0), which `K v` absorbs: v solves the gauge equation of
//!    [`super::sphere_gauge`] for the defect G, computed at each point by pushing P' forward
//!    with the automatic-differentiation Jacobian of `A M` ([`SecondMap::defect`]).
//!
//! The map is local (as (p-map) is): it needs `gamma1 != 0` (the printed alpha_i),
//! `p != 0`, and a meridian from the point to the pole on its side of `R gamma3 + a = 0` where
//! the defect is singular. Its image has `(L, gamma)` a multiple of K (the e*(3) Casimir is a
//! function of P''s).

use super::lie_poisson::LiePoisson;
use super::reduction::{pushforward, MomentumMap};
use super::second::SecondBracket;
use super::sphere_gauge::{axial_vector, Gauge};
use super::Bivector;
use crate::integrals::routh_integral;
use crate::scalar::{lift, split, Real};

/// The change of momenta of the second bracket to e*(3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SecondMap {
    /// The bracket P' (its alpha_i enter the map).
    pub bracket: SecondBracket,
}

impl SecondMap {
    /// The rows `a_i` of `A(gamma)`: `{a_i . M, gamma_j}' = eps_ijk gamma_k` (step 1 above).
    pub fn rows<D: Real>(&self, gamma: &[D; 3]) -> [[D; 3]; 3] {
        let [g1, g2, g3] = *gamma;
        let [a1, a2, a3] = self.bracket.alphas.at(&self.bracket.body, gamma);
        let det = a1 * g1 + a2 * g2;
        let zero = lift::<D>(0.0);
        let row = |sigma: D, tau: D| {
            [
                (sigma * g1 - a2 * tau) / det,
                (a1 * tau + g2 * sigma) / det,
                zero,
            ]
        };
        [
            row(-g3 / g1, -g2 / (g1 * a3)),
            row(zero, a3.recip()),
            [zero, zero, -self.bracket.coupling(gamma).recip()],
        ]
    }

    /// The linear part `(gamma, A(gamma) M)` of the map.
    pub fn linear_part<D: Real>(&self, x: &[D; 6]) -> [D; 6] {
        let (gamma, m) = split(x);
        let a = self.rows(&gamma);
        let l: [D; 3] = std::array::from_fn(|i| a[i][0] * m[0] + a[i][1] * m[1] + a[i][2] * m[2]);
        [gamma[0], gamma[1], gamma[2], l[0], l[1], l[2]]
    }

    /// The defect vector `G` (see [`axial_vector`]) of the momentum block of `A M` at the unit
    /// vector gamma: `{(AM)_i, (AM)_j}' - eps_ijk (AM)_k = K G_ij`, evaluated at `M = e3`.
    pub fn defect(&self, gamma: &[f64; 3]) -> [f64; 3] {
        let x = [gamma[0], gamma[1], gamma[2], 0.0, 0.0, 1.0];
        let pushed = pushforward(&self.bracket, |y| self.linear_part(y), &x);
        let target = LiePoisson.entries(&self.linear_part(&x));
        let k = routh_integral(&self.bracket.body, &x);
        let g: [[f64; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| (pushed[3 + i][3 + j] - target[3 + i][3 + j]) / k)
        });
        axial_vector(&g)
    }

    /// The solution of the gauge equation for [`SecondMap::defect`] along the meridian of gamma.
    pub fn gauge(&self, gamma: &[f64; 3]) -> Gauge {
        let b = &self.bracket.body;
        Gauge::solve(
            |g| self.defect(g),
            gamma,
            -b.a() / b.radius(),
            &self.singularities(),
        )
    }

    /// Complex singularities in `z = gamma3` of the defect on a meridian: the zeros of
    /// `g^2 = I1 m R^2 (1 - z^2) + I3 m (R z + a)^2 + I1 I3` and of
    /// `(I gamma, r) = I1 R (1 - z^2) + I3 z (R z + a)` (denominators of the printed alpha_i),
    /// and `z = 0` (the `1/gamma3` of alpha3).
    fn singularities(&self) -> Vec<(f64, f64)> {
        let b = &self.bracket.body;
        let (m, r, a, i1, i3) = (b.m(), b.radius(), b.a(), b.i1(), b.i3());
        let mut out = vec![(0.0, 0.0)];
        out.extend(quadratic_roots(
            m * r * r * (i3 - i1),
            2.0 * i3 * m * r * a,
            i1 * m * r * r + i3 * m * a * a + i1 * i3,
        ));
        out.extend(quadratic_roots(i3 * r - i1 * r, i3 * a, i1 * r));
        out
    }
}

/// The roots `(re, im)` of `c2 z^2 + c1 z + c0` (one root if `c2 = 0`, none if also `c1 = 0`).
pub fn quadratic_roots(c2: f64, c1: f64, c0: f64) -> Vec<(f64, f64)> {
    if c2 == 0.0 {
        return if c1 == 0.0 {
            vec![]
        } else {
            vec![(-c0 / c1, 0.0)]
        };
    }
    let disc = c1 * c1 - 4.0 * c2 * c0;
    let re = -c1 / (2.0 * c2);
    let half = disc.abs().sqrt() / (2.0 * c2.abs());
    if disc >= 0.0 {
        vec![(re - half, 0.0), (re + half, 0.0)]
    } else {
        vec![(re, -half), (re, half)]
    }
}

impl MomentumMap for SecondMap {
    fn image<D: Real>(&self, x: &[D; 6]) -> [D; 6] {
        let gauge = self.gauge(&[x[0].re(), x[1].re(), x[2].re()]);
        let (gamma, _) = split(x);
        let v = gauge.field(&gamma);
        let k = routh_integral(&self.bracket.body, x);
        let mut y = self.linear_part(x);
        for i in 0..3 {
            y[3 + i] += k * v[i];
        }
        y
    }
}
