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
//!
//! **Relative to a pole.** Near a pole `p = +-1` the terms of Q vanish like `x = 1 - p u`,
//! while H1 and H3 are O(1): written with them, Q near the pole is a difference of O(1)
//! numbers, and a motion passing near the axis (a level set near that of the vertical spin)
//! is fixed by the integrals only to their round-off over x. Q is therefore written in each
//! hemisphere with the parameters of its pole ([`PoleFrame`]): Jellett's remainder at the
//! pole `n_p = N(p)` and the energy above the vertical spin of the same K,
//! `e_p = H1 - 2 m G (R + a p) - C (K / g(p))^2`, both computed from the state as sums of
//! terms that vanish at the vertical spin (so with a round-off of eps times those small
//! terms), and the differences `N(u) - n_p`, `g(u)^2 - g(p)^2` in closed form with the factor
//! x taken out:
//!
//! ```text
//! N(u) = n_p + C K x J(x),   J(x) = (h_p/g_p - h/g) / x
//!      = [h_p^2 A m R^2 (2 - x) + A C p R (h_p + h)] / (g g_p (h_p g + h g_p)),
//! H1 - 2 m G (R + a u) - C omega3^2 = e_p + 2 m G a p x + C K^2 (g^2 - g_p^2) / (g^2 g_p^2),
//! g^2 - g_p^2 = x [A m R^2 (2 - x) - C m p R (h_p + h)],   h = h_p - p R x,   s^2 = x (2 - x).
//! ```

use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrals::{energy, jellett, routh_integral};
use crate::quadrature::divided::DividedDifferences;
use crate::scalar::{lift, Real, Scalar};
use crate::state::State;
use num_dual::{
    first_derivative, second_derivative, second_partial_derivative, third_partial_derivative_vec,
};

/// The smallest moment of inertia, relative to m R^2, for which the reduction is computed: with
/// `g^2 >= A C`, `g''` stays below about `(m R^2)^2 / (A C)^(3/2)`, i.e. 1e180 (m R^2)^-1 at
/// this ratio, far inside the range of f64.
const MIN_MOMENT_RATIO: f64 = 1e-60;
/// Absolute round-off of the parameters of Q computed from a state, in machine epsilons of
/// the sum of the magnitudes of their terms. Here and in the quadrature the round-off is
/// estimated, not bounded: a few epsilons per sum of terms, errors of independent samples
/// adding in quadrature (docs/quadrature.md, section 5).
pub const INTEGRAL_EPSILONS: f64 = 2.0;

/// The relative error with which a state fixes its angular velocity, `omega = I_Q^-1 M`
/// (om-m): `eps` times the condition number of `I_Q = I + m (|r|^2 - r r^T)`, whose
/// eigenvalues lie between `min(I1, I3)` and `max(I1, I3) + m |r|^2` (a ratio of moments:
/// the same in any units). About 5 eps for the default body; 2.8e-9 with m = 3e6 (the state
/// fixes the spin about r, `(I omega, r) / |r|`, only to the rounding of the much larger
/// `m |r|^2 |omega|`), and more than 1 with m = 1e30, where omega computed from M came out
/// [-1.62, 0.2, -1.01] for the case's (0.5, 0.2, 8).
pub fn omega_round_off(body: &Body, state: &State) -> f64 {
    let r = body.contact_vector(&state.gamma());
    let r2: f64 = r.iter().map(|c| c * c).sum();
    let (smallest, largest) = (body.i1().min(body.i3()), body.i1().max(body.i3()));
    f64::EPSILON * (largest + body.m() * r2) / smallest
}

/// The sum of the terms.
fn sum<D: Scalar>(terms: [D; 5]) -> D {
    terms.iter().fold(lift::<D>(0.0), |acc, &t| acc + t)
}

/// The values of the three integrals that fix a nutation: energy H1 (int-g), Jellett's H3
/// (int) and Routh's K (raus-int), for a dynamically symmetric body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reduction {
    /// The body (I1 = I2 checked). The fields are private: the frames of the poles are
    /// derived from the others, and changing one alone would leave them stale.
    body: Body,
    /// Energy H1 = (M, omega) + 2U.
    h1: f64,
    /// Jellett's integral H3 = (M, r).
    h3: f64,
    /// Routh's integral K = g omega3.
    k: f64,
    /// The level set relative to the top (`gamma3 = 1`) and bottom (`gamma3 = -1`) poles: Q
    /// at `u >= 0` is written with the first, at `u < 0` with the second.
    frames: [PoleFrame; 2],
    /// The constants of the body at each pole, in the same order.
    geometry: [PoleGeometry; 2],
}

/// The constants of the body at a pole `p = +-1` that every evaluation of Q in its frame
/// uses (the terms of `g(u)^2 - g_p^2`, `J(x)` and Q of the module docs), computed once per
/// reduction with the same operations, in the same order, as where they are used.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PoleGeometry {
    /// `h_p = R p + a`.
    hp: f64,
    /// `p R`, the rate at which `h` falls with `x`.
    pr: f64,
    /// `g_p = g(p)`.
    gp: f64,
    /// `g_p^2` (as `g_p * g_p`).
    gp2: f64,
    /// `A m R^2` and `C m p R`, the coefficients of `g^2 - g_p^2`.
    amr2: f64,
    cmpr: f64,
    /// `h_p^2 A m R^2` and `A C p R`, the coefficients of the numerator of `J(x)`.
    jellett_even: f64,
    jellett_odd: f64,
    /// `2 m G a p`, the coefficient of the potential's term of Q.
    lift: f64,
}

impl PoleGeometry {
    /// `h = h_p - p R x`, the height `R u + a` at `x = 1 - p u`.
    fn height<D: Scalar>(&self, x: D) -> D {
        -x * self.pr + self.hp
    }

    fn new(b: &Body, pole: f64) -> Self {
        let hp = b.radius() * pole + b.a();
        let gp = (b.i1() * b.i3() + b.i3() * b.m() * hp * hp).sqrt();
        PoleGeometry {
            hp,
            pr: pole * b.radius(),
            gp,
            gp2: gp * gp,
            amr2: b.i1() * b.m() * b.radius() * b.radius(),
            cmpr: b.i3() * b.m() * pole * b.radius(),
            jellett_even: hp * hp * b.i1() * b.m() * b.radius() * b.radius(),
            jellett_odd: b.i1() * b.i3() * pole * b.radius(),
            lift: 2.0 * b.m() * b.gravity() * b.a() * pole,
        }
    }
}

/// The parameters of a level set relative to a pole `p = +-1` (module docs): with K they fix
/// Q, and they are small for a motion near the vertical spin at that pole.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoleFrame {
    /// Jellett's remainder at the pole, `n_p = N(p) = H3 - C (R p + a) K / g(p)`.
    pub remainder: f64,
    /// The energy above the vertical spin at the pole with the same K,
    /// `e_p = H1 - 2 m G (R + a p) - C (K / g(p))^2`.
    pub excess: f64,
}

/// The index of the frame of pole `p` in `Reduction::frames` (top first).
pub(super) fn frame_index(pole: f64) -> usize {
    usize::from(pole < 0.0)
}

/// The pole whose frame writes Q at `u` (the top one for `u >= 0`).
fn pole_of(u: f64) -> f64 {
    if u >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

impl Reduction {
    /// The reduction at given values of the integrals; fails unless I1 = I2.
    pub fn new(body: &Body, h1: f64, h3: f64, k: f64) -> Result<Self> {
        body.require_symmetric("the quadrature")?;
        // Q'' involves g'' ~ (m R^2)^2 / g^3 with g^2 >= A C: moments far below m R^2 make it
        // overflow, and 0 * inf in its derivatives gives NaN (found by fuzzing: I3 = 7e-304,
        // m R^2 = 10).
        let scale = body.m() * body.radius() * body.radius();
        if !(body.i1().min(body.i3()) >= MIN_MOMENT_RATIO * scale) {
            return Err(RouthError::Singular {
                formula: "Routh's g(u) of (rho) and its derivatives",
                reason: format!(
                    "I1 = {:e} or I3 = {:e} is below {MIN_MOMENT_RATIO:e} m R^2 = {:e}: the \
                     derivatives of g overflow",
                    body.i1(),
                    body.i3(),
                    MIN_MOMENT_RATIO * scale
                ),
            });
        }
        let mut red = Reduction {
            body: *body,
            h1,
            h3,
            k,
            frames: [PoleFrame {
                remainder: 0.0,
                excess: 0.0,
            }; 2],
            geometry: [1.0, -1.0].map(|pole| PoleGeometry::new(body, pole)),
        };
        for pole in [1.0, -1.0] {
            let (hp, gp) = red.at_pole(pole);
            let spin = k / gp;
            red.frames[frame_index(pole)] = PoleFrame {
                remainder: h3 - body.i3() * hp * spin,
                excess: h1
                    - 2.0 * body.m() * body.gravity() * (body.radius() + body.a() * pole)
                    - body.i3() * spin * spin,
            };
        }
        Ok(red)
    }

    /// The reduction through a state: its H1, H3, K, and the parameters of both poles
    /// computed from the state without cancellation ([`Reduction::frames_of_state`]).
    pub fn of_state(body: &Body, state: &State) -> Result<Self> {
        let x = state.to_array();
        let mut red = Self::new(
            body,
            energy(body, &x),
            jellett(body, &x),
            routh_integral(body, &x),
        )?;
        let (frames, _) = red.frames_of_state(state, 0.0);
        red.frames = frames;
        Ok(red)
    }

    /// The body.
    pub fn body(&self) -> &Body {
        &self.body
    }

    /// The energy H1 = (M, omega) + 2U (int-g).
    pub fn h1(&self) -> f64 {
        self.h1
    }

    /// Jellett's integral H3 = (M, r) (int).
    pub fn h3(&self) -> f64 {
        self.h3
    }

    /// Routh's integral K = g omega3 (raus-int).
    pub fn k(&self) -> f64 {
        self.k
    }

    /// The parameters of the level set relative to the pole `pole`.
    pub fn frame(&self, pole: f64) -> PoleFrame {
        self.frames[frame_index(pole)]
    }

    /// The reduction with the parameters `[K, n_top, e_top, n_bottom, e_bottom]` (H1 and H3
    /// from the top frame).
    pub fn with_parameters(&self, parameters: [f64; 5]) -> Self {
        let [k, n_top, e_top, n_bottom, e_bottom] = parameters;
        let b = &self.body;
        let (hp, gp) = self.at_pole(1.0);
        let spin = k / gp;
        Reduction {
            body: self.body,
            h1: e_top + 2.0 * b.m() * b.gravity() * (b.radius() + b.a()) + b.i3() * spin * spin,
            h3: n_top + b.i3() * hp * spin,
            k,
            frames: [
                PoleFrame {
                    remainder: n_top,
                    excess: e_top,
                },
                PoleFrame {
                    remainder: n_bottom,
                    excess: e_bottom,
                },
            ],
            geometry: self.geometry,
        }
    }

    /// The parameters `[K, n_top, e_top, n_bottom, e_bottom]` that fix Q.
    pub fn parameters(&self) -> [f64; 5] {
        let [top, bottom] = self.frames;
        [
            self.k,
            top.remainder,
            top.excess,
            bottom.remainder,
            bottom.excess,
        ]
    }

    /// `h_p = R p + a` and `g_p = g(p)` at a pole.
    fn at_pole(&self, pole: f64) -> (f64, f64) {
        let geo = self.geometry(pole);
        (geo.hp, geo.gp)
    }

    /// The constants of the body at the pole `pole`.
    fn geometry(&self, pole: f64) -> &PoleGeometry {
        &self.geometry[frame_index(pole)]
    }

    /// The frames of both poles from a state, each term vanishing at the vertical spin
    /// (module docs), and the absolute round-off of `[K, n_top, e_top, n_bottom, e_bottom]`:
    /// `INTEGRAL_EPSILONS` machine epsilons of the sum of the magnitudes of the terms of each.
    /// With `omega` from the state, `N(u0) = A R (omega1 gamma1 + omega2 gamma2)` and
    ///
    /// ```text
    /// n_p = A R (omega1 gamma1 + omega2 gamma2) - C g(u0) omega3 x0 J(x0),
    /// e_p = A (omega1^2 + omega2^2) + m |omega x r|^2 - 2 m G a p x0
    ///       - C omega3^2 (g(u0)^2 - g_p^2) / g_p^2,
    /// ```
    ///
    /// with `x0 = 1 - p gamma3` taken from the horizontal part of gamma near the pole,
    /// `(gamma1^2 + gamma2^2) / (1 + p gamma3)`. With `omega_error` > 0, the relative error of
    /// omega from the state ([`omega_round_off`]), the errors hold its propagation too: it
    /// moves the terms linear in omega (K, `n_p`) by that fraction and those quadratic in
    /// omega (the kinetic and spin terms of `e_p`) by twice it.
    pub fn frames_of_state(&self, state: &State, omega_error: f64) -> ([PoleFrame; 2], [f64; 5]) {
        let b = &self.body;
        let gamma = state.gamma();
        let omega = state.omega(b);
        let r = b.contact_vector(&gamma);
        let norm = |v: [f64; 3]| v.iter().map(|c| c * c).sum::<f64>().sqrt();
        let cross = [
            omega[1] * r[2] - omega[2] * r[1],
            omega[2] * r[0] - omega[0] * r[2],
            omega[0] * r[1] - omega[1] * r[0],
        ];
        let rolling = cross.iter().map(|c| c * c).sum::<f64>() * b.m();
        let rolling_noise = 2.0 * b.m() * norm(cross) * norm(omega) * norm(r);
        let horizontal = gamma[0] * gamma[0] + gamma[1] * gamma[1];
        let tangential = b.i1() * b.radius() * (omega[0] * gamma[0] + omega[1] * gamma[1]);
        let tangential_noise =
            b.i1() * b.radius() * ((omega[0] * gamma[0]).abs() + (omega[1] * gamma[1]).abs());
        let kinetic = b.i1() * (omega[0] * omega[0] + omega[1] * omega[1]);
        let e = INTEGRAL_EPSILONS * f64::EPSILON;
        let mut frames = [PoleFrame {
            remainder: 0.0,
            excess: 0.0,
        }; 2];
        let mut errors = [
            e * (self.k.abs() + self.routh_g(gamma[2]) * omega[2].abs())
                + omega_error * self.k.abs(),
            0.0,
            0.0,
            0.0,
            0.0,
        ];
        for pole in [1.0, -1.0] {
            let x0 = if pole * gamma[2] > 0.0 {
                horizontal / (1.0 + pole * gamma[2])
            } else {
                1.0 - pole * gamma[2]
            };
            let (_, gp) = self.at_pole(pole);
            let (g2_change, g) = self.g_change(pole, x0);
            let shift = b.i3() * g * omega[2] * x0 * self.jellett_divided(pole, x0);
            let lift = 2.0 * b.m() * b.gravity() * b.a() * pole * x0;
            let spin_change = b.i3() * omega[2] * omega[2] * g2_change / (gp * gp);
            let i = frame_index(pole);
            frames[i] = PoleFrame {
                remainder: tangential - shift,
                excess: kinetic + rolling - lift - spin_change,
            };
            errors[1 + 2 * i] = (e + omega_error) * (tangential_noise + shift.abs());
            errors[2 + 2 * i] = e * (kinetic + rolling + lift.abs() + spin_change.abs())
                + e * rolling_noise
                + 2.0 * omega_error * (kinetic + rolling + spin_change.abs());
        }
        (frames, errors)
    }

    /// `g(u)^2 - g_p^2 = x [A m R^2 (2 - x) - C m p R (h_p + h)]` and `g(u)` at `x = 1 - p u`.
    fn g_change<D: Real>(&self, pole: f64, x: D) -> (D, D) {
        let geo = self.geometry(pole);
        g_change_at(geo, x, geo.height(x))
    }

    /// `J(x) = (h_p / g_p - h / g) / x` at `x = 1 - p u` (module docs), without cancellation:
    /// rationalised where h and h_p have the same sign, directly where they do not (then x is
    /// not small).
    pub fn jellett_divided<D: Real>(&self, pole: f64, x: D) -> D {
        let geo = self.geometry(pole);
        let h = geo.height(x);
        let (_, g) = g_change_at(geo, x, h);
        jellett_divided_at(geo, x, h, g)
    }

    /// Routh's g of (rho) as a function of `u = gamma3` on the unit sphere,
    /// `g(u) = sqrt(A C + A m R^2 (1 - u^2) + C m (R u + a)^2)` (the same function as
    /// [`Body::routh_g`], written in u so that it can be differentiated at the poles).
    pub fn routh_g<D: Scalar>(&self, u: D) -> D {
        let b = &self.body;
        let (s2, h) = (lift::<D>(1.0) - u * u, u * b.radius() + b.a());
        (s2 * (b.i1() * b.m() * b.radius() * b.radius())
            + h * h * (b.i3() * b.m())
            + b.i1() * b.i3())
        .sqrt()
    }

    /// The spin `omega3 = K / g(u)` of (raus-int).
    pub fn spin<D: Scalar>(&self, u: D) -> D {
        self.routh_g(u).recip() * self.k
    }

    /// The spin `omega3 = K / g` at `x = 1 - p u` from the pole `p`, with g from x
    /// (`g^2 = g_p^2 + (g^2 - g_p^2)(x)`): near the pole u itself rounds `1 - u^2` to a relative
    /// error `eps / x`, and a slender body's g changes on the small scale
    /// `C (A + m h_p^2) / (A m R^2)` of x (with I3 = 1e-4 that made the rate of psi near the
    /// pole jitter by 1e-13, and its series fail).
    pub fn spin_in_frame(&self, pole: f64, x: f64) -> f64 {
        let (_, g) = self.g_change(pole, x);
        self.k / g
    }

    /// Jellett's remainder `N(u) = H3 - C (R u + a) omega3 = A R s omega_t`, as
    /// `n_p + C K x J(x)` in the frame of the pole of u's hemisphere.
    pub fn jellett_remainder<D: Real>(&self, u: D) -> D {
        let pole = pole_of(u.re());
        self.jellett_remainder_in_frame(pole, -u * pole + 1.0)
    }

    /// `N` at `x = 1 - p u` from the pole `p`.
    pub fn jellett_remainder_in_frame<D: Real>(&self, pole: f64, x: D) -> D {
        x * self.jellett_divided(pole, x) * (self.body.i3() * self.k) + self.frame(pole).remainder
    }

    /// `Q(u) = (du/dt)^2`, the reduced equation of the tilt (module docs).
    pub fn q<D: Real>(&self, u: D) -> D {
        sum(self.q_terms(u))
    }

    /// `Q` at `x = 1 - p u` in the frame of the pole `p`: accurate near the pole, where u
    /// itself rounds x to a relative error `eps / x`.
    pub fn q_in_frame<D: Real>(&self, pole: f64, x: D) -> D {
        sum(self.q_terms_in_frame(pole, x, self.frame_parameters(pole)))
    }

    /// `Q` at `x = 1 - p u` anywhere in `[0, 2]`: in the frame of the pole `p` on its
    /// hemisphere (`x <= 1`), in that of the other pole at `2 - x` (exact) beyond.
    pub fn q_from_pole(&self, pole: f64, x: f64) -> f64 {
        if x <= 1.0 {
            self.q_in_frame(pole, x)
        } else {
            self.q_in_frame(-pole, 2.0 - x)
        }
    }

    /// The terms whose sum is `Q(u)`; their magnitudes set the round-off scale of `Q`.
    pub fn q_terms<D: Real>(&self, u: D) -> [D; 5] {
        self.q_terms_at(u, self.parameters().map(lift))
    }

    /// `[K, n_p, e_p]` of the frame of pole `p`.
    fn frame_parameters<D: Scalar>(&self, pole: f64) -> [D; 3] {
        let f = self.frame(pole);
        [self.k, f.remainder, f.excess].map(lift)
    }

    /// The terms of `Q(u)` at the parameters `[K, n_top, e_top, n_bottom, e_bottom]`.
    fn q_terms_at<D: Real>(&self, u: D, parameters: [D; 5]) -> [D; 5] {
        let pole = pole_of(u.re());
        let i = 1 + 2 * frame_index(pole);
        self.q_terms_in_frame(
            pole,
            -u * pole + 1.0,
            [parameters[0], parameters[i], parameters[i + 1]],
        )
    }

    /// The terms of `Q` at `x = 1 - p u` from the parameters `[K, n_p, e_p]` of the pole `p`
    /// (module docs): each vanishes with x or with the parameters, so near the pole they are
    /// small and Q carries no cancellation of O(1) numbers.
    fn q_terms_in_frame<D: FrameScalar>(&self, pole: f64, x: D, parameters: [D; 3]) -> [D; 5] {
        let b = &self.body;
        let geo = self.geometry(pole);
        let [k, remainder, excess] = parameters;
        let (ai, r) = (b.i1(), b.radius());
        let h = geo.height(x);
        let s2 = x * (-x + 2.0);
        let (g2_change, g) = g_change_at(geo, x, h);
        let w3 = k / g;
        let n = x * D::jellett_divided_at(geo, x, h, g) * k * b.i3() + remainder;
        let inertia = (s2 * (r * r) + h * h) * b.m() + ai;
        let rolling = w3 * s2 * r - n * h / (ai * r);
        [
            s2 * excess / inertia,
            s2 * x * geo.lift / inertia,
            s2 * k * k * g2_change / (g * g * geo.gp2) * b.i3() / inertia,
            -(n * n) / (ai * r * r) / inertia,
            -(rolling * rolling * b.m()) / inertia,
        ]
    }

    /// The partial derivatives of Q at `u` with respect to the parameters
    /// `[K, n_top, e_top, n_bottom, e_bottom]`, by automatic differentiation (those of the
    /// other pole's frame are 0).
    pub fn q_integral_gradient(&self, u: f64) -> [f64; 5] {
        let values = self.parameters();
        std::array::from_fn(|i| {
            first_derivative(
                |x| {
                    let mut at = values.map(lift);
                    at[i] = x;
                    sum(self.q_terms_at(lift(u), at))
                },
                values[i],
            )
            .1
        })
    }

    /// The round-off bound of `Q(u)` computed from parameters that carry the absolute errors
    /// `integral_errors` (of `[K, n_top, e_top, n_bottom, e_bottom]`,
    /// [`Reduction::frames_of_state`]): the rounding of its own terms, `eps sum |terms|`, plus
    /// `sum |dQ/dp_i| err_i`.
    pub fn q_noise(&self, u: f64, integral_errors: [f64; 5]) -> f64 {
        let grad = self.q_integral_gradient(u);
        f64::EPSILON * self.q_scale(u)
            + grad
                .iter()
                .zip(integral_errors)
                .map(|(g, e)| g.abs() * e)
                .sum::<f64>()
    }

    /// The round-off bound of `Q'(u)` computed from parameters that carry the absolute errors
    /// `integral_errors` (as in [`Reduction::q_noise`]): the rounding of the slopes of its own
    /// terms, `eps` [`Reduction::q_slope_scale`], plus `sum |d2Q/du dp_i| err_i` (by
    /// automatic differentiation in u and each parameter).
    pub fn q_slope_noise(&self, u: f64, integral_errors: [f64; 5]) -> f64 {
        let values = self.parameters();
        let moved: f64 = (0..5)
            .map(|i| {
                let (_, _, _, mixed) = second_partial_derivative(
                    |(v, p)| {
                        let mut at = values.map(lift);
                        at[i] = p;
                        sum(self.q_terms_at(v, at))
                    },
                    (u, values[i]),
                );
                mixed.abs() * integral_errors[i]
            })
            .sum();
        f64::EPSILON * self.q_slope_scale(u) + moved
    }

    /// How far the absolute errors `integral_errors` of the parameters
    /// `[K, n_top, e_top, n_bottom, e_bottom]` ([`Reduction::frames_of_state`], with the error
    /// of omega from the state or without) move `Q''(u)`: `sum |d3Q/du2 dp_i| err_i` (by
    /// automatic differentiation, twice in u and once in each parameter), as
    /// [`Reduction::q_slope_noise`] does for `Q'`.
    pub fn q_curvature_moved(&self, u: f64, integral_errors: [f64; 5]) -> f64 {
        let values = self.parameters();
        let at: Vec<f64> = std::iter::once(u).chain(values).collect();
        (0..5)
            .map(|i| {
                let (.., mixed) = third_partial_derivative_vec(
                    |x| sum(self.q_terms_at(x[0], std::array::from_fn(|j| x[1 + j]))),
                    &at,
                    0,
                    0,
                    1 + i,
                );
                mixed.abs() * integral_errors[i]
            })
            .sum()
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
        first_derivative(|v| self.q_terms(v), u)
            .iter()
            .map(|(_, slope)| slope.abs())
            .sum()
    }

    /// The round-off scales of `Q` and of `dQ/dx` at `x = 1 - p u` in the frame of pole `p`.
    pub fn q_scales_in_frame(&self, pole: f64, x: f64) -> (f64, f64) {
        let parameters = self.frame_parameters(pole);
        first_derivative(
            |v| self.q_terms_in_frame(pole, v, parameters.map(|p: f64| lift(p))),
            x,
        )
        .iter()
        .fold((0.0, 0.0), |(value, slope), (t, dt)| {
            (value + t.abs(), slope + dt.abs())
        })
    }

    /// `Q` at the points `[x0, x1, x2]` (`x = 1 - p u`) in the frame of pole `p`, with its
    /// divided differences there, `Q[x0, x1]`, `Q[x1, x2]` and `Q[x0, x1, x2]`, each by the
    /// Leibniz rule ([`DividedDifferences`]): without the cancellation of `Q(x1) - Q(x0)`
    /// however close the points, and in one evaluation of the terms of Q. Also the round-off
    /// scale of each part: the sum of the magnitudes of that part of the terms (at equal
    /// points those of [`Reduction::q_scales_in_frame`] and half those of
    /// [`Reduction::q_curvature_scale`]).
    pub fn q_divided_differences_in_frame(
        &self,
        pole: f64,
        points: [f64; 3],
    ) -> (DividedDifferences, DividedDifferences) {
        let terms = self.q_terms_in_frame(
            pole,
            DividedDifferences::variable(points),
            self.frame_parameters(pole),
        );
        (sum(terms), sum(terms.map(DividedDifferences::magnitudes)))
    }

    /// The round-off scale of `Q''` at `u`: the sum of the magnitudes of the second
    /// derivatives of the terms of `Q`.
    pub fn q_curvature_scale(&self, u: f64) -> f64 {
        second_derivative(|v| self.q_terms(v), u)
            .iter()
            .map(|(_, _, curvature)| curvature.abs())
            .sum()
    }

    /// Jellett's quotient `N(u) / (1 - u^2) = omega_t / (A R s)`, for `|u| < 1`.
    pub fn jellett_quotient(&self, u: f64) -> f64 {
        let pole = pole_of(u);
        let x = 1.0 - pole * u;
        self.jellett_remainder_in_frame(pole, x) / (x * (2.0 - x))
    }

    /// The precession rate `dpsi/dt = u N(u) / (A R (1 - u^2)) - omega3` (module docs),
    /// from Jellett's quotient `N / (1 - u^2)` and the spin omega3.
    pub fn precession_from_quotient(&self, u: f64, quotient: f64, spin: f64) -> f64 {
        u * quotient / (self.body.i1() * self.body.radius()) - spin
    }

    /// The precession rate `dpsi/dt` at `|u| < 1`.
    pub fn precession_rate(&self, u: f64) -> f64 {
        self.precession_from_quotient(u, self.jellett_quotient(u), self.spin(u))
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
        self.omega_with_spin(u, s, psi, omega_n, quotient, self.spin(u))
    }

    /// [`Reduction::omega`] with the spin omega3 given (from a distance to the pole more
    /// accurate than u's, [`Reduction::spin_in_frame`]).
    pub fn omega_with_spin(
        &self,
        u: f64,
        s: f64,
        psi: f64,
        omega_n: f64,
        quotient: f64,
        spin: f64,
    ) -> ([f64; 3], [f64; 3]) {
        let omega_t = s * quotient / (self.body.i1() * self.body.radius());
        let (sp, cp) = psi.sin_cos();
        let gamma = [s * cp, s * sp, u];
        let omega = [
            omega_t * cp - omega_n * sp,
            omega_t * sp + omega_n * cp,
            spin,
        ];
        (gamma, omega)
    }
}

/// A number the terms of Q in a pole's frame are written over ([`Reduction::q_terms_in_frame`]):
/// field arithmetic, and `J(x)`, whose form depends on the sign of `h h_p` (of the real part of
/// one number, or at each point of [`DividedDifferences`]).
trait FrameScalar: Scalar {
    /// [`jellett_divided_at`].
    fn jellett_divided_at(geo: &PoleGeometry, x: Self, h: Self, g: Self) -> Self;
}

impl<D: Real> FrameScalar for D {
    #[inline(always)]
    fn jellett_divided_at(geo: &PoleGeometry, x: Self, h: Self, g: Self) -> Self {
        jellett_divided_at(geo, x, h, g)
    }
}

impl FrameScalar for DividedDifferences {
    /// Where `h h_p > 0` at every point, the rationalised form by the Leibniz rule. Elsewhere
    /// the values are those of [`jellett_divided_at`] at each point, and the differences
    /// follow from those of `y = x J = h_p/g_p - h/g` (the differences of `-h/g`, without
    /// cancellation) by the Leibniz rule for `x J`, solved for those of J at the point farther
    /// from the pole: `y[xa, xb] = x(xa) J[xa, xb] + x[xa, xb] J(xb)` and
    /// `y[x0, x1, x2] = x(x0) J[x0, x1, x2] + x[x0, x1] J[x1, x2] + x[x0, x1, x2] J(x2)`, or the
    /// same with the points in reverse order (divided differences are symmetric). That point
    /// is one where `h h_p <= 0`, at least `1 + p a / R` from the pole; dividing by a point
    /// near the pole instead would bring back the cancellation of the direct form there.
    #[inline(always)]
    fn jellett_divided_at(geo: &PoleGeometry, x: Self, h: Self, g: Self) -> Self {
        if h.values.iter().all(|&h| h * geo.hp > 0.0) {
            return jellett_rationalised(geo, x, h, g);
        }
        let values: [f64; 3] =
            std::array::from_fn(|i| jellett_divided_at(geo, x.values[i], h.values[i], g.values[i]));
        let y = jellett_times_x(geo, h, g);
        let ([x0, x1, x2], [j0, j1, j2]) = (x.values, values);
        let solve = |y: f64, slope: f64, (xa, ja): (f64, f64), (xb, jb): (f64, f64)| {
            if xa.abs() >= xb.abs() {
                (y - slope * jb) / xa
            } else {
                (y - slope * ja) / xb
            }
        };
        let first = [
            solve(y.first[0], x.first[0], (x0, j0), (x1, j1)),
            solve(y.first[1], x.first[1], (x1, j1), (x2, j2)),
        ];
        let second = if x0.abs() >= x2.abs() {
            (y.second - x.first[0] * first[1] - x.second * j2) / x0
        } else {
            (y.second - x.first[1] * first[0] - x.second * j0) / x2
        };
        DividedDifferences {
            values,
            first,
            second,
        }
    }
}

/// `g(u)^2 - g_p^2 = x [A m R^2 (2 - x) - C m p R (h_p + h)]` and `g(u)` at `x = 1 - p u`,
/// `h = h_p - p R x`, with the constants of the pole.
#[inline(always)]
fn g_change_at<D: Scalar>(geo: &PoleGeometry, x: D, h: D) -> (D, D) {
    let change = x * ((-x + 2.0) * geo.amr2 - (h + geo.hp) * geo.cmpr);
    (change, (change + geo.gp2).sqrt())
}

/// `J(x)` of [`Reduction::jellett_divided`] at `x = 1 - p u` with `h` and `g = g(u)` there:
/// rationalised where h and h_p have the same sign, directly where they do not (then x is not
/// small).
#[inline(always)]
fn jellett_divided_at<D: Real>(geo: &PoleGeometry, x: D, h: D, g: D) -> D {
    if h.re() * geo.hp > 0.0 {
        jellett_rationalised(geo, x, h, g)
    } else {
        jellett_times_x(geo, h, g) / x
    }
}

/// `J(x) = [h_p^2 A m R^2 (2 - x) + A C p R (h_p + h)] / (g g_p (h_p g + h g_p))` (module
/// docs): no cancellation where h and h_p have the same sign.
#[inline(always)]
fn jellett_rationalised<D: Scalar>(geo: &PoleGeometry, x: D, h: D, g: D) -> D {
    let (hp, gp) = (geo.hp, geo.gp);
    ((-x + 2.0) * geo.jellett_even + (h + hp) * geo.jellett_odd) / (g * gp * (g * hp + h * gp))
}

/// `x J(x) = h_p / g_p - h / g`, a difference of O(1) numbers near the pole.
#[inline(always)]
fn jellett_times_x<D: Scalar>(geo: &PoleGeometry, h: D, g: D) -> D {
    g.recip() * (-h) + geo.hp / geo.gp
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn divided_differences_of_q_are_its_derivatives_and_secants() {
        // Q by the Leibniz rule against Q itself, in both frames, for bodies with a of either
        // sign (so that `h h_p` changes sign inside [0, 2] and both forms of J(x) meet in one
        // evaluation), from the pole to past the other pole: at three equal points the
        // differences are Q' and Q''/2 (automatic differentiation); at points 0.2 apart they
        // are the secants of the values, which lose a few ulps of the sizes of Q there.
        // Tolerance: 1e-12 of the round-off scales of Q and Q' (`q_scales_in_frame`, and |Q''|
        // for Q''), 1e-11 of that of Q over the spacing for the secants.
        for (a, i3) in [(0.3, 0.5), (-0.6, 1e-3), (0.9, 0.8)] {
            let body = Body::new(1.0, 1.0, a, 0.4, 0.4, i3, 9.81).unwrap();
            let state = State::new(
                [0.3, 0.1, 0.9],
                [0.5, -0.2, 8.0],
                crate::state::Normalise::Rescale,
            )
            .unwrap();
            let red = Reduction::of_state(&body, &state).unwrap();
            for pole in [1.0, -1.0] {
                for x in [0.0, 1e-9, 0.3, 1.1, 1.5] {
                    let q = |x: f64| red.q_in_frame(pole, x);
                    let (_, slope, curvature) = second_derivative(|v| red.q_in_frame(pole, v), x);
                    let (scale, slope_scale) = red.q_scales_in_frame(pole, x);
                    // The round-off scale of Q'' ([`Reduction::q_curvature_scale`]) is NaN at
                    // u = -0.7 for the body with a = -0.6: Q'' and those of Q and Q' instead.
                    let curvature_scale = curvature.abs() + slope_scale + scale;
                    let (at, scales) = red.q_divided_differences_in_frame(pole, [x; 3]);
                    assert!(
                        (scales.values[0] - scale).abs() <= 1e-15 * scale,
                        "{a} {pole}"
                    );
                    assert!((scales.first[0] - slope_scale).abs() <= 1e-12 * slope_scale);
                    assert_eq!(at.values[0], q(x), "{a} {pole} {x}");
                    assert!(
                        (at.first[0] - slope).abs() <= 1e-12 * slope_scale,
                        "{a} {pole} {x}: {at:?} {slope}"
                    );
                    assert!(
                        (at.second - 0.5 * curvature).abs() <= 1e-12 * curvature_scale,
                        "{a} {pole} {x}: {at:?} {curvature}"
                    );
                    let points = [x, x + 0.2, x + 0.4];
                    let (apart, _) = red.q_divided_differences_in_frame(pole, points);
                    let secant = (q(points[1]) - q(points[0])) / 0.2;
                    let secants = (q(points[2]) - q(points[1])) / 0.2;
                    let noise = 1e-11 * scale / 0.2;
                    assert!((apart.first[0] - secant).abs() <= noise, "{a} {pole} {x}");
                    assert!(
                        (apart.second - (secants - secant) / 0.4).abs() <= noise / 0.4,
                        "{a} {pole} {x}"
                    );
                }
            }
        }
        // Negative control: the differences of another level set differ.
        let state = State::new(
            [0.3, 0.1, 0.9],
            [0.5, -0.2, 8.0],
            crate::state::Normalise::Rescale,
        )
        .unwrap();
        let red = Reduction::of_state(&Body::default(), &state).unwrap();
        let moved = red.with_parameters(red.parameters().map(|p| p * 1.001));
        let at = |r: &Reduction| {
            r.q_divided_differences_in_frame(1.0, [0.1, 0.3, 0.5])
                .0
                .second
        };
        assert!((at(&red) - at(&moved)).abs() > 1e-6 * at(&red).abs());
    }
}
