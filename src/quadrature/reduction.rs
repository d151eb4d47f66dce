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
use crate::error::{Result, RouthError};
use crate::integrals::{energy, jellett, routh_integral};
use crate::scalar::{lift, Scalar};
use crate::state::State;
use num_dual::{first_derivative, second_derivative, Dual64};

/// The smallest moment of inertia, relative to m R^2, for which the reduction is computed: with
/// `g^2 >= A C`, `g''` stays below about `(m R^2)^2 / (A C)^(3/2)`, i.e. 1e180 (m R^2)^-1 at
/// this ratio, far inside the range of f64.
const MIN_MOMENT_RATIO: f64 = 1e-60;

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
        // Q'' involves g'' ~ (m R^2)^2 / g^3 with g^2 >= A C: moments far below m R^2 make it
        // overflow, and 0 * inf in its derivatives gives NaN (found by fuzzing: I3 = 7e-304,
        // m R^2 = 10).
        let scale = body.m * body.radius * body.radius;
        if !(body.i1.min(body.i3) >= MIN_MOMENT_RATIO * scale) {
            return Err(RouthError::Singular {
                formula: "Routh's g(u) of (rho) and its derivatives",
                reason: format!(
                    "I1 = {:e} or I3 = {:e} is below {MIN_MOMENT_RATIO:e} m R^2 = {:e}: the \
                     derivatives of g overflow",
                    body.i1,
                    body.i3,
                    MIN_MOMENT_RATIO * scale
                ),
            });
        }
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
        self.routh_g_with_sine(lift::<D>(1.0) - u * u, u * self.body.radius + self.body.a)
    }

    /// `g` from `s2 = sin^2 theta` and `h = R u + a`.
    fn routh_g_with_sine<D: Scalar>(&self, s2: D, h: D) -> D {
        let b = &self.body;
        (s2 * (b.i1 * b.m * b.radius * b.radius) + h * h * (b.i3 * b.m) + b.i1 * b.i3).sqrt()
    }

    /// The spin `omega3 = K / g(u)` of (raus-int).
    pub fn spin<D: Scalar>(&self, u: D) -> D {
        self.routh_g(u).recip() * self.k
    }

    /// Jellett's remainder `N(u) = H3 - C (R u + a) omega3 = A R s omega_t`.
    pub fn jellett_remainder<D: Scalar>(&self, u: D) -> D {
        self.remainder_at(u, lift(self.h3), lift(self.k))
    }

    /// `N(u)` at given values of H3 and K (generic, so that its dependence on the integrals can
    /// be differentiated).
    fn remainder_at<D: Scalar>(&self, u: D, h3: D, k: D) -> D {
        let b = &self.body;
        h3 - k / self.routh_g(u) * (u * b.radius + b.a) * b.i3
    }

    /// `Q(u) = (du/dt)^2`, the reduced equation of the tilt (module docs).
    pub fn q<D: Scalar>(&self, u: D) -> D {
        self.q_terms(u)
            .iter()
            .fold(crate::scalar::lift::<D>(0.0), |acc, &t| acc + t)
    }

    /// The terms whose sum is `Q(u)`; their magnitudes set the round-off scale of `Q`.
    pub fn q_terms<D: Scalar>(&self, u: D) -> [D; 4] {
        self.q_terms_at(u, [lift(self.h1), lift(self.h3), lift(self.k)])
    }

    /// The terms of `Q(u)` at given values `[H1, H3, K]` of the integrals.
    fn q_terms_at<D: Scalar>(&self, u: D, integrals: [D; 3]) -> [D; 4] {
        self.q_terms_with_sine(u, lift::<D>(1.0) - u * u, integrals)
    }

    /// `Q` at `u = pole (1 - gap)` with `sin^2 theta = gap (2 - gap)` computed from the gap,
    /// not from u: near a pole u rounds `1 - |u|` to a relative error `eps / gap`.
    pub fn q_near_pole(&self, pole: f64, gap: f64) -> f64 {
        let u = pole * (1.0 - gap);
        self.q_terms_with_sine(u, gap * (2.0 - gap), [self.h1, self.h3, self.k])
            .iter()
            .sum()
    }

    /// The terms of `Q` at `u` with `s2 = 1 - u^2` given.
    fn q_terms_with_sine<D: Scalar>(&self, u: D, s2: D, integrals: [D; 3]) -> [D; 4] {
        let b = &self.body;
        let [h1, h3, k] = integrals;
        let (ai, r) = (b.i1, b.radius);
        let h = u * r + b.a;
        let w3 = k / self.routh_g_with_sine(s2, h);
        let n = h3 - w3 * h * b.i3;
        let inertia = (s2 * (r * r) + h * h) * b.m + ai;
        let rolling = w3 * s2 * r - n * h / (ai * r);
        [
            s2 * (h1 - (u * b.a + r) * (2.0 * b.m * b.gravity)) / inertia,
            -(s2 * w3 * w3 * b.i3) / inertia,
            -(n * n) / (ai * r * r) / inertia,
            -(rolling * rolling * b.m) / inertia,
        ]
    }

    /// The partial derivatives `dQ/dH1, dQ/dH3, dQ/dK` at `u`, by automatic differentiation.
    pub fn q_integral_gradient(&self, u: f64) -> [f64; 3] {
        let values = [self.h1, self.h3, self.k];
        std::array::from_fn(|i| {
            first_derivative(
                |x| {
                    let mut at = values.map(lift);
                    at[i] = x;
                    self.q_terms_at(lift(u), at)
                        .iter()
                        .fold(lift::<Dual64>(0.0), |acc, &t| acc + t)
                },
                values[i],
            )
            .1
        })
    }

    /// The round-off bound of `Q(u)` computed from integrals that carry the absolute errors
    /// `integral_errors` (of H1, H3, K): the rounding of its own terms,
    /// `eps sum |terms|`, plus `sum |dQ/dH_i| err_i`. Near a pole the terms of Q vanish like
    /// `1 - u^2` while Jellett's remainder N is a difference of O(1) numbers: this second part
    /// is what decides how well the integrals fix a motion that passes near the axis.
    pub fn q_noise(&self, u: f64, integral_errors: [f64; 3]) -> f64 {
        let grad = self.q_integral_gradient(u);
        f64::EPSILON * self.q_scale(u)
            + grad
                .iter()
                .zip(integral_errors)
                .map(|(g, e)| g.abs() * e)
                .sum::<f64>()
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

    /// The complex points `(re, im)` where Q (and N) are not analytic: the zeros of
    /// `g(u)^2 = (C - A) m R^2 u^2 + 2 C m R a u + A C + A m R^2 + C m a^2` (branch points of
    /// g) and of the inertia `A + m |r|^2 = A + m (R^2 + a^2) + 2 m R a u` (a pole). Gauss-
    /// Legendre rules over u bisect toward them ([`crate::quadrature::gauss`]).
    pub fn singularities(&self) -> Vec<(f64, f64)> {
        let b = &self.body;
        let (ai, c, m, r, a) = (b.i1, b.i3, b.m, b.radius, b.a);
        let mut points = vec![];
        if a != 0.0 {
            points.push((-(ai + m * (r * r + a * a)) / (2.0 * m * r * a), 0.0));
        }
        let (q2, q1, q0) = (
            (c - ai) * m * r * r,
            2.0 * c * m * r * a,
            ai * c + ai * m * r * r + c * m * a * a,
        );
        if q2 == 0.0 {
            if q1 != 0.0 {
                points.push((-q0 / q1, 0.0));
            }
        } else {
            let disc = q1 * q1 - 4.0 * q2 * q0;
            if disc >= 0.0 {
                // Without cancellation: the root of larger magnitude first, the other from
                // the product of the roots q0 / q2.
                let big = -0.5 * (q1 + q1.signum() * disc.sqrt());
                points.push((big / q2, 0.0));
                if big != 0.0 {
                    points.push((q0 / big, 0.0));
                }
            } else {
                let im = (-disc).sqrt() / (2.0 * q2).abs();
                points.push((-q1 / (2.0 * q2), im));
            }
        }
        points.retain(|z| z.0.is_finite() && z.1.is_finite());
        points
    }

    /// The round-off scale of `Q''` at `u`: the sum of the magnitudes of the second
    /// derivatives of the terms of `Q`.
    pub fn q_curvature_scale(&self, u: f64) -> f64 {
        (0..4)
            .map(|i| second_derivative(|v| self.q_terms(v)[i], u).2.abs())
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
