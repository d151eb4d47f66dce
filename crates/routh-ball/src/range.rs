//! The range of f64 in which a body and a state can be computed with: a parameter or a
//! state whose inertia, energy or field overflows (or underflows to a singular inertia) is
//! refused with the quantity and its cause named, before any integration sees a NaN.
//!
//! The inverse of the inertia about the contact point (om-m) is computed in closed form
//! ([`crate::Ball::angular_velocity`]) through `det I_Q det A`, of the size of `A_i^6` with
//! `A_i = I_i + m r^2`: in the units of the problem it would be finite and normal only for
//! `A_i` between 1.6e-51 and 5.5e51, an absolute range that refused the default body in units
//! of mass 1e-300 (m = 1e-300 with its moments) and solved it with m = 1. It is computed instead
//! in the body's own unit of inertia k ([`crate::Ball::inertia_unit`], `max(m R^2, I_max)`
//! rounded to a power of two, so that omega is unchanged to the bit), where every `A_i / k`
//! lies between `0.7 / MAX_CONDITION` and 8 (`A_i <= I_max + 4 m R^2`, `k` within a factor
//! `sqrt 2` of `max(m R^2, I_max)`): what remains to check is relative, the condition number
//! [`MAX_CONDITION`], and what no choice of units can help: k a normal f64 (checked by
//! [`crate::Ball::new`]), `m r^2 / k` finite (a radius whose square is beyond f64) and the
//! weight `m G (R + |com|)` finite.

use crate::ball::AsBall;
use crate::error::{Result, RouthError};
use crate::integrals::Integrals;
use crate::state::State;

/// The largest condition number `(I_max + m r_max^2) / I_min` of the inertia about the contact
/// point accepted. `I_Q = I + m (r^2 - r r^T)` has the eigenvalue of about `m r^2 + I` across
/// the contact vector r and only about I along it: `M = I_Q omega` holds omega's component
/// along r in a part of M of relative size `I_min / (m r^2)`, so that the rounding of M (one
/// epsilon) leaves omega with a relative error of epsilon times this ratio: 2.2e-6 at the
/// bound. Beyond, the cancellation in `det I_Q` grows until omega is not finite (m = 1e40 for
/// the default body), a failure caused by the ratio of m r^2 to the moments, not by the spin.
pub const MAX_CONDITION: f64 = 1e10;

/// Check that the body's inertia about the contact point can be inverted in f64 at every
/// tilt, in the body's unit of inertia k ([`MAX_CONDITION`]: the parameter that breaks it
/// named, m or the smallest moment; `m r^2 / k` finite), and that its weight times its height
/// is finite. Relative but for these: a body and its copy in other units are accepted
/// together.
pub fn check_body(body: &impl AsBall) -> Result<()> {
    let body = &body.ball();
    let scaled = body.scaled_inertia();
    let moments = scaled.inertia;
    let offset = norm(&body.com());
    let r_max = body.radius() + offset;
    let largest_moment = moments.iter().fold(0.0_f64, |a, &b| a.max(b));
    let smallest_moment = moments.iter().fold(f64::INFINITY, |a, &b| a.min(b));
    let largest = largest_moment + scaled.m * r_max * r_max;
    if !largest.is_finite() {
        return Err(RouthError::Overflow {
            cause: format!(
                "m = {:?}, R = {:?}, com = {:?}, I = {:?}",
                body.m(),
                body.radius(),
                body.com(),
                body.inertia()
            ),
            quantity: "the inertia about the contact point in the body's unit of inertia, \
                       (I + m r^2) / max(m R^2, I_max),",
            direction: "overflow",
            value: largest,
        });
    }
    let condition = largest / smallest_moment;
    if !(condition <= MAX_CONDITION) {
        // The larger of the two factors of the ratio: the mass against the moments, or the
        // moments against each other.
        let heavy = largest / largest_moment >= largest_moment / smallest_moment;
        let (name, value) = if heavy {
            ("m", body.m())
        } else {
            let i = moments
                .iter()
                .position(|&v| v == smallest_moment)
                .unwrap_or(0);
            (["I1", "I2", "I3"][i], body.inertia()[i])
        };
        return Err(RouthError::Parameter {
            name,
            value,
            rule: "makes the inertia about the contact point I_Q = I + m (r^2 - r r^T) too \
                   ill-conditioned for f64: (I_max + m (R + |com|)^2) / I_min must be at most \
                   1e10 (MAX_CONDITION), or the state's M = I_Q omega loses omega along the \
                   contact vector r in its rounding (relative error 2.2e-16 times that ratio)",
        });
    }
    let weight = body.m() * body.gravity() * r_max;
    if !weight.is_finite() {
        return Err(RouthError::Overflow {
            cause: format!(
                "m = {:?}, G = {:?}, R + |com| = {r_max:?}",
                body.m(),
                body.gravity()
            ),
            quantity: "the potential energy m G (r, gamma)",
            direction: "overflow",
            value: weight,
        });
    }
    Ok(())
}

/// Check that the state's angular velocity, energy and the integrals are finite (the body
/// already checked by [`check_body`]).
pub fn check_state(body: &impl AsBall, state: &State) -> Result<()> {
    let body = &body.ball();
    let omega = state.omega(body);
    let spin = norm(&omega);
    let momentum = norm(&state.m());
    let cause = || {
        if spin.is_finite() {
            format!("the spin |omega| = {spin:.3e}")
        } else {
            format!("the angular momentum |M| = {momentum:.3e}")
        }
    };
    if !spin.is_finite() {
        return Err(RouthError::Overflow {
            cause: cause(),
            quantity: "the angular velocity omega = I_Q^-1 M",
            direction: "overflow",
            value: spin,
        });
    }
    let x = state.to_array();
    let values = Integrals::at(body, &x).values();
    // The same state turning at a unit spin: an integral that overflows there too does so
    // because of the body's size (H2 grows as the square of its inertia), not of the spin.
    let at_unit_spin = (spin > 0.0).then(|| {
        let m = state.m().map(|c| c / spin);
        Integrals::at(body, &[x[0], x[1], x[2], m[0], m[1], m[2]]).values()
    });
    for (i, (name, value)) in crate::integrals::INTEGRAL_NAMES
        .iter()
        .zip(values)
        .enumerate()
    {
        if let Some(v) = value.filter(|v| !v.is_finite()) {
            let by_size = at_unit_spin.is_some_and(|u| u[i].is_some_and(|v| !v.is_finite()));
            return Err(RouthError::Overflow {
                cause: if by_size {
                    format!(
                        "the body's size (its unit of inertia max(m R^2, I_max) = {:.3e}, \
                         m = {:e}, R = {:e}; at any spin)",
                        body.inertia_unit(),
                        body.m(),
                        body.radius()
                    )
                } else {
                    cause()
                },
                quantity: integral_meaning(name),
                direction: "overflow",
                value: v,
            });
        }
    }
    let field = crate::field::vector_field(body, &x);
    if let Some(v) = field.iter().find(|v| !v.is_finite()) {
        return Err(RouthError::Overflow {
            cause: cause(),
            quantity: "the field (mg-eq)",
            direction: "overflow",
            value: *v,
        });
    }
    Ok(())
}

/// The Euclidean length, without overflow of the squares.
fn norm(v: &[f64; 3]) -> f64 {
    v[0].hypot(v[1]).hypot(v[2])
}

fn integral_meaning(name: &str) -> &'static str {
    match name {
        "H1" => "the energy H1",
        "H2" => "the integral H2",
        "H3" => "Jellett's integral H3",
        "H4" => "the integral H4 = |gamma|^2",
        _ => "Routh's integral K",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::state::Normalise;
    use crate::Body;

    #[test]
    fn a_huge_spin_names_the_energy() {
        let body = Body::default();
        let state = State::from_omega(&body, [0.0, 0.0, 1.0], [0.0, 0.0, 1e200], Normalise::Reject)
            .unwrap();
        let e = check_state(&body, &state).unwrap_err().to_string();
        assert!(
            e.contains("the spin |omega| = 1.000e200") && e.contains("energy"),
            "{e}"
        );
        let fine = State::from_omega(&body, [0.0, 0.0, 1.0], [0.0, 0.0, 1e100], Normalise::Reject)
            .unwrap();
        check_state(&body, &fine).unwrap();
    }

    /// An integral beyond f64 because of the body's size (the default body in units of
    /// length 1e100: H2 has the size of its inertia squared, 1e400, at any spin) blames the
    /// body, not the spin (it blamed "the spin |omega| = 8"); the same body turning at 1e-200
    /// rad/s is refused the same way, and a huge spin of the default body still names the spin.
    #[test]
    fn an_integral_beyond_f64_by_the_body_s_size_names_the_body() {
        let l = 1e100;
        let body = Body::new(
            1.0,
            l,
            0.3 * l,
            0.4 * l * l,
            0.4 * l * l,
            0.5 * l * l,
            9.81 * l,
        )
        .unwrap();
        for omega in [[0.5, 0.2, 8.0], [5e-201, 2e-201, 8e-200]] {
            let state =
                State::from_omega(&body, [0.0, 0.0, 1.0], omega, Normalise::Reject).unwrap();
            let e = check_state(&body, &state).unwrap_err().to_string();
            assert!(
                e.contains("the body's size") && e.contains("R = 1e100") && !e.contains("spin |"),
                "{e}"
            );
        }
    }

    /// A huge mass with the default moments is refused by the ratio of `m r^2` to the moments,
    /// with m named; the same body in units of mass 1e300 or 1e-300 (every mass and moment
    /// scaled, outside the absolute range `1.6e-51 ..= 5.5e51` of the inertia refused before
    /// issue 33's last item) is accepted, as the default body is: the checks are relative.
    /// Only a unit of inertia beyond f64 (m R^2 = 1e400) is refused absolutely, by
    /// `Ball::new`, with the quantity named.
    #[test]
    fn a_huge_mass_names_the_inertia() {
        let with_mass = |m| Body::new(m, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).unwrap();
        let e = check_body(&with_mass(1e300)).unwrap_err().to_string();
        assert!(e.contains("m = 1e300") && e.contains("inertia"), "{e}");
        check_body(&with_mass(1e9)).unwrap();
        for k in [1e300, 1e-300, 1.0] {
            let copy = Body::new(k, 1.0, 0.3, 0.4 * k, 0.4 * k, 0.5 * k, 9.81).unwrap();
            check_body(&copy).unwrap();
        }
        let e = Body::new(1.0, 1e200, 0.3, 0.4, 0.4, 0.5, 9.81)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("unit of inertia") && e.contains("overflow"),
            "{e}"
        );
    }

    /// Regression (issue 33): m = 1e40 in the default case blamed "the spin omega3 = inf"
    /// (the spin is 8): `det I_Q`, of relative size `I / (m r^2)`, cancelled to nothing. The
    /// parameter that makes I_Q ill-conditioned is named with the rule: m when `m r^2`
    /// dominates, the smallest moment when it is tiny; the same body in other units (every
    /// mass and moment by 1e30) is accepted, the ratio having no units.
    #[test]
    fn an_ill_conditioned_inertia_names_its_cause() {
        let body = |m, i3| Body::new(m, 1.0, 0.3, 0.4, 0.4, i3, 9.81).unwrap();
        for (b, name, value) in [
            (body(1e40, 0.5), "m", 1e40),
            (body(1e10, 0.5), "m", 1e10),
            (body(1.0, 1e-12), "I3", 1e-12),
        ] {
            let name = format!("{name} = {}", crate::error::Number(value));
            let e = check_body(&b).unwrap_err().to_string();
            assert!(
                e.starts_with(&format!("invalid body parameter {name}: makes the inertia"))
                    && e.contains("at most 1e10"),
                "{e}"
            );
        }
        check_body(&body(1e9, 0.5)).unwrap();
        check_body(&body(1.0, 1e-9)).unwrap();
        check_body(&Body::new(1e30, 1.0, 0.3, 0.4e30, 0.4e30, 0.5e30, 9.81).unwrap()).unwrap();
    }
}
