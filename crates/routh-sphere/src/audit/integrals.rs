//! The claims of section 2 about the integrals and the invariant measure: (int), (mg-eq),
//! (int-g), (raus-int), (rho). See [`super::claim`] for the points, the residuals and the
//! threshold.

use super::checks::{self, Function};
use super::claim::{body, field_of, free_body, h4, of, Claim, Outcome, Potential, Sample};
use crate::body::Body;
use crate::differential::Dual6;
use crate::field::vector_field;
use crate::integrals::{
    energy, jellett, measure_density, quadratic_integral, quadratic_integral_free, routh_integral,
};
use crate::scalar::{dot, split, Scalar};

/// The printed quadratic integral with gravity (int-g) with the printed constant `g` (of
/// either sign: the body's own G >= 0 is not used),
/// `H2 = M^2 - m r^2 (omega, M) - 2 m g (a I1 gamma3 - m R^2 gamma^2 (a^2 + gamma^2 R^2))`.
pub fn printed_h2_gravity<D: Scalar>(body: &Body, g: f64, x: &[D; 6]) -> D {
    let (gamma, _) = split(x);
    let g2 = dot(&gamma, &gamma);
    let inner = gamma[2] * (body.a() * body.i1())
        - g2 * (g2 * (body.radius() * body.radius()) + body.a() * body.a())
            * (body.m() * body.radius() * body.radius());
    quadratic_integral_free(body, x) - inner * (2.0 * body.m() * g)
}

/// The printed (int-g) H2 with `g = G` against the field whose potential is `sign m G (r, gamma)`:
/// the printed H2 evaluated with `g = -sign G`, since the field with `U = -m g (r, gamma)` is our
/// field with `G -> -G` ([`Potential::Printed`]).
fn int_g_outcome(s: &Sample, sign: f64) -> Outcome {
    let b = body();
    let potential = if sign > 0.0 {
        Potential::Ours(b)
    } else {
        Potential::Printed(b)
    };
    let h2 = |x: &[Dual6; 6]| printed_h2_gravity(&b, -sign * b.gravity(), x);
    let mismatched = checks::conservation(
        &field_of(b),
        &[&|x: &[Dual6; 6]| printed_h2_gravity(&b, b.gravity(), x)],
        &s.points(&b),
    );
    Outcome::checked(
        checks::conservation(&potential.field(), &[&h2], &s.points(&b)),
        format!("field with U = {}m G (r, gamma), G = 9.81, H2 printed with g = {}G: max |X(H2)|/(|dH2||X|); the term m R^2 gamma^2 (a^2 + gamma^2 R^2) is constant on |gamma| = 1, so H2 = M^2 - m r^2 (omega, M) + 2 I1 U + const; the printed H2 with g = G against our field U = +mG(r, gamma) leaves {mismatched:.1e}", if sign > 0.0 { "+" } else { "-" }, if sign > 0.0 { "-" } else { "" })
    )
}

/// The claims about the integrals, in the order of the paper.
pub fn claims() -> Vec<Claim> {
    vec![
        Claim {
            id: "m-eq.integrals",
            label: "int",
            statement: "H1 = (M, omega), H2 = M^2 - m r^2 H1, H3 = (M, r), H4 = (gamma, gamma) are integrals of (m-eq)",
            check: |s| {
                let b = free_body();
                let hs: [Function; 4] = [&of(b, energy), &of(b, quadratic_integral_free), &of(b, jellett), &h4];
                Outcome::checked(checks::conservation(&field_of(b), &hs, &s.points(&b)), "max |X(H)|/(|dH||X|), G = 0")
            },
        },
        Claim {
            id: "mg-eq.integrals",
            label: "mg-eq",
            statement: "with gravity H3, H4, K = g omega3 and H1 = (omega, M) + 2U stay integrals",
            check: |s| {
                let worst = [Potential::Ours(body()), Potential::Printed(body())]
                    .iter()
                    .map(|&u| {
                        let hs: [Function; 4] = [&u.integral(energy), &u.integral(jellett), &u.integral(routh_integral), &h4];
                        checks::conservation(&u.field(), &hs, &s.points(&u.body()))
                    })
                    .fold(0.0, f64::max);
                Outcome::checked(worst, "max |X(H)|/(|dH||X|) for U = +mG(r,gamma) (ours) and U = -mG(r,gamma) (printed), the same U in field and H1")
            },
        },
        Claim {
            id: "int-g.H2",
            label: "int-g",
            statement: "H2 = M^2 - m r^2 (omega, M) - 2 m g (a I1 gamma3 - m R^2 gamma^2 (a^2 + gamma^2 R^2)) is an integral of (mg-eq) with the printed U = -m g (r, gamma)",
            check: |s| int_g_outcome(s, -1.0),
        },
        Claim {
            id: "int-g.H2.physical",
            label: "int-g",
            statement: "with U = +m G (r, gamma) (gamma pointing into the plane) the integral is (int-g)'s H2 with G -> -G",
            check: |s| int_g_outcome(s, 1.0),
        },
        Claim {
            id: "H2.relation",
            label: "raus-int",
            statement: "H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2 (K = g omega3)",
            check: |s| {
                let b = free_body();
                let lhs = |x: &[f64; 6]| quadratic_integral_free(&b, x);
                let rhs = |x: &[f64; 6]| quadratic_integral(&b, x);
                Outcome::checked(checks::identity(&lhs, &rhs, &s.points(&b)), "max |lhs - rhs|/max(|lhs|,|rhs|), G = 0")
            },
        },
        Claim {
            id: "H2.triaxial",
            label: "raus-int",
            statement: "with I1 != I2 the quadratic integral H2 survives, the linear K = g omega3 does not",
            check: |s| {
                let b = Body::new(1.3, 0.8, 0.25, 0.4, 0.45, 0.55, 0.0).expect("a triaxial body of the audit satisfies the rules");
                let pts = s.points(&b);
                let quadratic = checks::conservation(&field_of(b), &[&of(b, quadratic_integral_free)], &pts);
                let linear = checks::conservation(&field_of(b), &[&of(b, routh_integral)], &pts);
                let residual = if linear > 1e-6 { quadratic } else { 1.0 };
                Outcome::checked(residual, format!("I2 = 0.45, G = 0: H2 = M^2 - m r^2 H1 conserved to {quadratic:.1e}; K = g omega3 (with I1) broken by {linear:.1e} (residual 1 if K were conserved)"))
            },
        },
        Claim {
            id: "rho.measure",
            label: "rho",
            statement: "mu = g^{-1}(gamma) dgamma dM is invariant: div(X/g) = 0, with and without gravity",
            check: |s| {
                let worst = [body(), free_body()]
                    .iter()
                    .map(|&b| {
                        checks::invariant_measure(&|y| vector_field(&b, y), &of(b, measure_density), &s.points(&b))
                    })
                    .fold(0.0, f64::max);
                Outcome::checked(worst, "max |div(X/g)| / |d(X/g)| (Frobenius norm of the Jacobian)")
            },
        },
    ]
}
