//! The reduction of (mg-eq) to one degree of freedom for the Routh sphere I1 = I2
//! (see `docs/quadrature.md` for the derivation step by step).
//!
//! Coordinates: `gamma = (s cos psi, s sin psi, u)` with `u = cos theta = gamma3`,
//! `s = sin theta`; `t = (cos psi, sin psi, 0)` is the horizontal direction of gamma and
//! `n = e3 x t` the horizontal direction orthogonal to it. The angular velocity is split as
//! `omega = omega_t t + omega_n n + omega3 e3`. Write `A = I1 = I2`, `C = I3`,
//! `h = R u + a` (so `r = R s t + h e3`), `|r|^2 = R^2 s^2 + h^2`. Then
//!
//! * Routh's integral (raus-int) `K = g(u) omega3` gives `omega3 = K / g(u)`;
//! * Jellett's integral (int) `H3 = (M, r) = (I omega, r) = A R s omega_t + C omega3 h`
//!   gives `N(u) := A R s omega_t = H3 - C h K / g(u)`;
//! * `dgamma/dt = gamma x omega` gives `du/dt = s omega_n` and
//!   `dpsi/dt = u omega_t / s - omega3 = u N(u) / (A R s^2) - omega3`;
//! * the energy (int-g) `H1 = A (omega_t^2 + omega_n^2) + C omega3^2 + m |omega x r|^2 + 2U`,
//!   `|omega x r|^2 = omega_n^2 |r|^2 + (omega3 R s - omega_t h)^2`, `U = m G (R + a u)`,
//!   multiplied by `s^2`, gives `(du/dt)^2 = Q(u)` with
//!
//! ```text
//! Q(u) = [ s^2 (H1 - 2 m G (R + a u) - C omega3^2) - N^2 / (A R^2)
//!          - m (omega3 R s^2 - N h / (A R))^2 ] / (A + m |r|^2),     s^2 = 1 - u^2.
//! ```
//!
//! `Q` is smooth on `[-1, 1]` (g > 0 there) and `Q(+-1) <= 0`, so the tilt oscillates between
//! two roots of `Q`. `thetadot^2 = Phi(theta) = Q(cos theta) / sin^2 theta`.

use crate::body::Body;
use crate::error::Result;
use crate::integrals::{energy, jellett, routh_integral};
use crate::scalar::{lift, Scalar};
use crate::state::State;
use num_dual::{first_derivative, second_derivative};

/// The values of the three integrals that fix a nutation: energy H1 (int-g), Jellett's H3
/// (int) and Routh's K (raus-int), for a dynamically symmetric body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reduction {
    /// The body (I1 = I2 checked).
    pub body: Body,
    /// Energy H1 = (M, omega) + 2U.
    pub h1: f64,
    /// Jellett's integral H3 = (M, r).
    pub h3: f64,
    /// Routh's integral K = g omega3.
    pub k: f64,
}

impl Reduction {
    /// The reduction at given values of the integrals; fails unless I1 = I2.
    pub fn new(body: &Body, h1: f64, h3: f64, k: f64) -> Result<Self> {
        body.require_symmetric("the quadrature")?;
        Ok(Reduction {
            body: *body,
            h1,
            h3,
            k,
        })
    }

    /// The reduction through a state: its H1, H3, K.
    pub fn of_state(body: &Body, state: &State) -> Result<Self> {
        let x = state.to_array();
        Self::new(
            body,
            energy(body, &x),
            jellett(body, &x),
            routh_integral(body, &x),
        )
    }

    /// Routh's g of (rho) as a function of `u = gamma3` on the unit sphere,
    /// `g(u) = sqrt(A C + A m R^2 (1 - u^2) + C m (R u + a)^2)` (the same function as
    /// [`Body::routh_g`], written in u so that it can be differentiated at the poles).
    pub fn routh_g<D: Scalar>(&self, u: D) -> D {
        let b = &self.body;
        let h = u * b.radius + b.a;
        ((lift::<D>(1.0) - u * u) * (b.i1 * b.m * b.radius * b.radius)
            + h * h * (b.i3 * b.m)
            + b.i1 * b.i3)
            .sqrt()
    }

    /// The spin `omega3 = K / g(u)` of (raus-int).
    pub fn spin<D: Scalar>(&self, u: D) -> D {
        self.routh_g(u).recip() * self.k
    }

    /// Jellett's remainder `N(u) = H3 - C (R u + a) omega3 = A R s omega_t`.
    pub fn jellett_remainder<D: Scalar>(&self, u: D) -> D {
        let b = &self.body;
        lift::<D>(self.h3) - self.spin(u) * (u * b.radius + b.a) * b.i3
    }

    /// `Q(u) = (du/dt)^2`, the reduced equation of the tilt (module docs).
    pub fn q<D: Scalar>(&self, u: D) -> D {
        self.q_terms(u).iter().fold(crate::scalar::lift::<D>(0.0), |acc, &t| acc + t)
    }

    /// The terms whose sum is `Q(u)`; their magnitudes set the round-off scale of `Q`.
    pub fn q_terms<D: Scalar>(&self, u: D) -> [D; 4] {
        let b = &self.body;
        let (ai, r) = (b.i1, b.radius);
        let s2 = lift::<D>(1.0) - u * u;
        let h = u * r + b.a;
        let w3 = self.spin(u);
        let n = self.jellett_remainder(u);
        let inertia = (s2 * (r * r) + h * h) * b.m + ai;
        let rolling = w3 * s2 * r - n * h / (ai * r);
        [
            s2 * (lift::<D>(self.h1) - (u * b.a + r) * (2.0 * b.m * b.gravity)) / inertia,
            -(s2 * w3 * w3 * b.i3) / inertia,
            -(n * n) / (ai * r * r) / inertia,
            -(rolling * rolling * b.m) / inertia,
        ]
    }

    /// `Q(u)`, `Q'(u)`, `Q''(u)` by automatic differentiation.
    pub fn q_derivatives(&self, u: f64) -> (f64, f64, f64) {
        second_derivative(|v| self.q(v), u)
    }

    /// The round-off scale of `Q` at `u`: the sum of the magnitudes of its terms.
    pub fn q_scale(&self, u: f64) -> f64 {
        self.q_terms(u).iter().map(|t| t.abs()).sum()
    }

    /// The round-off scale of `Q'` at `u`: the sum of the magnitudes of the derivatives of
    /// the terms of `Q`. At a pole all terms of `Q` vanish, while their slopes do not, so the
    /// test for a double root at `u` must compare `Q'` with this and not with [`Self::q_scale`].
    pub fn q_slope_scale(&self, u: f64) -> f64 {
        (0..4)
            .map(|i| first_derivative(|v| self.q_terms(v)[i], u).1.abs())
            .sum()
    }

    /// Jellett's quotient `N(u) / (1 - u^2) = omega_t / (A R s)`, for `|u| < 1`.
    pub fn jellett_quotient(&self, u: f64) -> f64 {
        self.jellett_remainder(u) / (1.0 - u * u)
    }

    /// The precession rate `dpsi/dt = u N(u) / (A R (1 - u^2)) - omega3` (module docs),
    /// from Jellett's quotient `N / (1 - u^2)`.
    pub fn precession_from_quotient(&self, u: f64, quotient: f64) -> f64 {
        u * quotient / (self.body.i1 * self.body.radius) - self.spin(u)
    }

    /// The precession rate `dpsi/dt` at `|u| < 1`.
    pub fn precession_rate(&self, u: f64) -> f64 {
        self.precession_from_quotient(u, self.jellett_quotient(u))
    }

    /// gamma and the angular velocity `omega = omega_t t + omega_n n + omega3 e3` at
    /// `gamma = (s cos psi, s sin psi, u)` (s may be negative: the same point as `-s`,
    /// `psi + pi`), with `omega_t = N / (A R s) = s quotient / (A R)` from Jellett's quotient
    /// `N / (1 - u^2)` (finite at a pole the motion passes through) and the given
    /// `omega_n = (du/dt) / s`.
    pub fn omega(
        &self,
        u: f64,
        s: f64,
        psi: f64,
        omega_n: f64,
        quotient: f64,
    ) -> ([f64; 3], [f64; 3]) {
        let omega_t = s * quotient / (self.body.i1 * self.body.radius);
        let (sp, cp) = psi.sin_cos();
        let gamma = [s * cp, s * sp, u];
        let omega = [
            omega_t * cp - omega_n * sp,
            omega_t * sp + omega_n * cp,
            self.spin(u),
        ];
        (gamma, omega)
    }
}
