//! The reduction of the first bracket to e*(3), section 3.2: the change of momenta (p-map)
//! `M -> L`, the spherical coordinates (sph-coord), the functions A, B, C, V of (int-sph2),
//! the integrals in these variables (int-sph), (int-sph2), and the quadrature for theta.
//!
//! Notation: `s = gamma1^2 + gamma2^2`, `h = R gamma3 + a`, `b = (M, r)` (Jellett),
//! `r^2 = (r, r)`, `u = gamma1 M1 + gamma2 M2`.

use super::first::FirstBracket;
use super::{Bivector, Matrix6, Reading};
use crate::differential::jacobian;
use crate::scalar::{dot, split, Real};

/// The change of momenta (p-map) with the value `c = (L, gamma)` of the e*(3) Casimir.
///
/// Reading of the unbalanced parenthesis: the numerator of the first term of L1 and L2 is
/// `gamma_i gamma3 (R u - b I1^{-1} (I1 + m h^2))`. With this reading `(L, gamma) = c`
/// holds identically (the gamma3 terms cancel because `b = (M, r)`), so c is a free value.
#[derive(Debug, Clone, Copy)]
pub struct PoissonMap {
    /// The bracket (p-br) whose alpha and beta enter the map.
    pub bracket: FirstBracket,
    /// The value c of `(L, gamma)`.
    pub c: f64,
}

/// A change of momenta `(gamma, M) -> (gamma, L)` written once for every scalar type, so that
/// its Jacobian comes from automatic differentiation of the same code.
pub trait MomentumMap {
    /// The image `(gamma, L)` of `x = (gamma, M)`.
    fn image<D: Real>(&self, x: &[D; 6]) -> [D; 6];
}

impl MomentumMap for PoissonMap {
    fn image<D: Real>(&self, x: &[D; 6]) -> [D; 6] {
        PoissonMap::image(self, x)
    }
}

impl PoissonMap {
    /// The image `(gamma, L)` of `x = (gamma, M)`.
    pub fn image<D: Real>(&self, x: &[D; 6]) -> [D; 6] {
        let body = &self.bracket.body;
        let (gamma, m) = split(x);
        let [g1, g2, g3] = gamma;
        let (alpha, beta) = self.bracket.alpha_beta(&gamma);
        let r = body.contact_vector(&gamma);
        let h = r[2];
        let b = dot(&m, &r);
        let ag = alpha * body.routh_g(&gamma);
        let s = g1 * g1 + g2 * g2;
        let u = g1 * m[0] + g2 * m[1];
        let radial =
            g3 * (u * body.radius() - b * ((h * h * body.m() + body.i1()) / body.i1())) / (ag * h);
        let turn = (g2 * m[0] - g1 * m[1]) / beta;
        [
            g1,
            g2,
            g3,
            (g1 * radial + g2 * turn + g1 * self.c) / s,
            (g2 * radial - g1 * turn + g2 * self.c) / s,
            m[2] / ag + b * h * (body.m() / body.i1()) / ag,
        ]
    }

    /// The inverse of [`PoissonMap::image`] on the leaf of the Jellett value `b = (M, r)`: the
    /// point `(gamma, M)` of a point `(gamma, L)` with `(L, gamma) = c`. From (p-map),
    /// `M3 = alpha g L3 - b m h / I1`; `(M, r) = R u + h M3 = b` gives `u = (b - h M3)/R`; and
    /// `L1 gamma2 - L2 gamma1 = (gamma2 M1 - gamma1 M2)/beta` gives the horizontal component
    /// orthogonal to gamma. No division by h: the inverse is regular where the map's
    /// `1/(R gamma3 + a)` is not.
    pub fn preimage<D: Real>(&self, y: &[D; 6], b: D) -> [D; 6] {
        let body = &self.bracket.body;
        let (gamma, l) = split(y);
        let [g1, g2, _] = gamma;
        let (alpha, beta) = self.bracket.alpha_beta(&gamma);
        let h = body.contact_vector(&gamma)[2];
        let m3 = alpha * body.routh_g(&gamma) * l[2] - b * h * (body.m() / body.i1());
        let u = (b - h * m3) / body.radius();
        let turn = (l[0] * g2 - l[1] * g1) * beta;
        let s = g1 * g1 + g2 * g2;
        [
            g1,
            g2,
            gamma[2],
            (g1 * u + g2 * turn) / s,
            (g2 * u - g1 * turn) / s,
            m3,
        ]
    }
}

/// The pushforward `J P J^T` at `x` of a bivector P by a map with Jacobian J (the bracket of
/// the new coordinates), the Jacobian by automatic differentiation of the map's own code.
pub fn pushforward<P: Bivector>(
    p: &P,
    map: impl Fn(&[crate::differential::Dual6; 6]) -> [crate::differential::Dual6; 6],
    x: &[f64; 6],
) -> Matrix6<f64> {
    let (_, j) = jacobian(map, x);
    let pm = p.entries(x);
    std::array::from_fn(|a| {
        std::array::from_fn(|c| {
            (0..6)
                .map(|i| {
                    (0..6)
                        .map(|k| j[(a, i)] * pm[i][k] * j[(c, k)])
                        .sum::<f64>()
                })
                .sum()
        })
    })
}

/// Spherical coordinates (sph-coord) `(phi, theta, p_phi, p_theta)` of a point `(gamma, L)`
/// with `(L, gamma) = 0`: `gamma = (sin phi sin theta, cos phi sin theta, cos theta)`,
/// `L3 = -p_phi`, and `p_theta = -cos phi L1 + sin phi L2` (solving the printed L1, L2).
pub fn spherical(y: &[f64; 6]) -> [f64; 4] {
    let theta = y[2].clamp(-1.0, 1.0).acos();
    let phi = y[0].atan2(y[1]);
    [phi, theta, -y[5], -phi.cos() * y[3] + phi.sin() * y[4]]
}

/// The point `(gamma, L)` of spherical coordinates `(phi, theta, p_phi, p_theta)` as printed in
/// (sph-coord): `L1 = sin phi cos theta / sin theta p_phi - cos phi p_theta`,
/// `L2 = cos phi cos theta / sin theta p_phi + sin phi p_theta`, `L3 = -p_phi` (so that
/// `(L, gamma) = 0`); the inverse of [`spherical`].
pub fn from_spherical(sph: &[f64; 4]) -> [f64; 6] {
    let [phi, theta, p_phi, p_theta] = *sph;
    let (sp, cp) = phi.sin_cos();
    let cot = theta.cos() / theta.sin();
    let [g1, g2, g3] = unit_normal(sph);
    [
        g1,
        g2,
        g3,
        sp * cot * p_phi - cp * p_theta,
        cp * cot * p_phi + sp * p_theta,
        -p_phi,
    ]
}

/// The functions `[A, B, C, V](theta)` of (int-sph2), with alpha and beta of the bracket
/// evaluated at the point `(phi, theta)` of the unit sphere (constant alpha and the beta of
/// (cond) depend on theta only).
///
/// Printed: `V = (I1 + m (a^2 + 2 a R cos theta + R^2)) / (I1^2 R^2 sin^2 theta)`.
/// Corrected: `V = (I1 + m (a^2 + 2 a R cos theta + R^2 cos^2 theta)) / (I1^2 R^2 sin^2 theta)`,
/// i.e. `(I1 + m (R gamma3 + a)^2)/(I1^2 R^2 s)`, the `b^2` term of (int-sph)'s H1; the printed
/// `R^2` instead of `R^2 cos^2 theta` is the `r^2` of B copied into V.
pub fn abcv(bracket: &FirstBracket, sph: &[f64; 4], reading: Reading) -> [f64; 4] {
    let body = &bracket.body;
    let (st, ct) = sph[1].sin_cos();
    let gamma = unit_normal(sph);
    let (alpha, beta) = bracket.alpha_beta(&gamma);
    let (m, rr, a) = (body.m(), body.radius(), body.a());
    let h2 = a * a + 2.0 * a * rr * ct + rr * rr * ct * ct;
    let r2 = a * a + 2.0 * a * rr * ct + rr * rr;
    let g = body.routh_g(&gamma);
    [
        alpha * alpha * (body.i1() + body.i3() * h2 / (rr * rr * st * st)),
        beta * beta / (body.i1() + m * r2),
        2.0 * alpha * g * (rr * ct + a) / (body.i1() * rr * rr * st * st),
        (body.i1()
            + m * match reading {
                Reading::Printed => r2,
                Reading::Corrected => h2,
            })
            / (body.i1() * body.i1() * rr * rr * st * st),
    ]
}

/// (int-sph2): `H1 = A p_phi^2 + B p_theta^2 + b C p_phi + b^2 V` at `(theta, p_phi, p_theta)`
/// and the Jellett value b, with V as printed or corrected (see [`abcv`]).
pub fn energy_spherical(bracket: &FirstBracket, sph: &[f64; 4], b: f64, reading: Reading) -> f64 {
    let [_, _, p_phi, p_theta] = *sph;
    let [a, bb, c, v] = abcv(bracket, sph, reading);
    a * p_phi * p_phi + bb * p_theta * p_theta + b * c * p_phi + b * b * v
}

/// (int-sph2): Routh's integral `H^2 = -alpha I1 p_phi`.
pub fn routh_spherical(bracket: &FirstBracket, sph: &[f64; 4]) -> f64 {
    -bracket.alpha.at(&unit_normal(sph)) * bracket.body.i1() * sph[2]
}

/// The point `gamma = (sin phi sin theta, cos phi sin theta, cos theta)` of (sph-coord).
pub fn unit_normal(sph: &[f64; 4]) -> [f64; 3] {
    let (st, ct) = sph[1].sin_cos();
    [sph[0].sin() * st, sph[0].cos() * st, ct]
}

/// The rate `dtheta/dt = 2 B(theta) p_theta` of the theta quadrature.
pub fn theta_rate(bracket: &FirstBracket, sph: &[f64; 4]) -> f64 {
    2.0 * abcv(bracket, sph, Reading::Printed)[1] * sph[3]
}

/// The square of the theta quadrature's right-hand side,
/// `4 B (E - A c^2 - b c C - b^2 V)` with `E = H1`, `c = -H^2/(alpha I1)` (V as printed or
/// corrected, see [`abcv`]).
pub fn theta_rate_squared(
    bracket: &FirstBracket,
    sph: &[f64; 4],
    e: f64,
    c: f64,
    b: f64,
    reading: Reading,
) -> f64 {
    let [a, bb, cc, v] = abcv(bracket, sph, reading);
    4.0 * bb * (e - a * c * c - b * c * cc - b * b * v)
}

/// (int-sph): `[H1, H2]` in the variables `(gamma, L)` of (p-map) at `c = 0` under (cond),
/// with the Jellett value b.
///
/// Printed: the `b^2` coefficient of H2 is `(I1 + m r^2)/(I1 R^2 s) + 2m/I1`. Corrected:
/// `(I1 + m r^2)/(I1 R^2 s) - 2m/I1` (the sign of `2m/I1` flipped); everything else as printed.
pub fn integrals_in_l(bracket: &FirstBracket, y: &[f64; 6], b: f64, reading: Reading) -> [f64; 2] {
    let body = &bracket.body;
    let gamma = [y[0], y[1], y[2]];
    let l = [y[3], y[4], y[5]];
    let alpha = bracket.alpha.at(&gamma);
    let (m, rr, i1, i3) = (body.m(), body.radius(), body.i1(), body.i3());
    let r = body.contact_vector(&gamma);
    let (h, r2) = (r[2], dot(&r, &r));
    let g = body.routh_g(&gamma);
    let s = gamma[0] * gamma[0] + gamma[1] * gamma[1];
    let turn = l[0] * gamma[1] - l[1] * gamma[0];
    let tail = g * g * h * h * turn * turn / (rr * rr * gamma[2] * gamma[2] * (i1 + m * r2));
    let cross_term = 2.0 * b * alpha * g * h * l[2] / (rr * rr * s);
    [
        alpha * alpha / s * ((g * g - i1 * i3) / (m * rr * rr) * l[2] * l[2] + tail)
            - cross_term / i1
            + b * b * (i1 + m * h * h) / (i1 * i1 * rr * rr * s),
        alpha * alpha / s * (i1 * i3 * r2 / (rr * rr) * l[2] * l[2] + i1 * tail) - cross_term
            + ((i1 + m * r2) / (i1 * rr * rr * s)
                + match reading {
                    Reading::Printed => 2.0 * m / i1,
                    Reading::Corrected => -2.0 * m / i1,
                })
                * b
                * b,
    ]
}
