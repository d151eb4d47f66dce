//! The claims of sections 2.1 to 4 about the Poisson brackets: (p-br), (p-bv), (cond),
//! (cond2), (g-eq1), (g-eq2), (p-map), (int-sph), (int-sph2), P_f, (p-bv2), (g-eq3), P'',
//! (eq-cf). See [`super::claim`] for the points, the residuals and the threshold.

use super::checks::{self, Function};
use super::claim::{
    body, field_of, free_body, generic_first, generic_firsts, h4, of, Claim, Outcome, Potential,
    Sample, CONSTANT_ALPHA, GENERIC_ALPHA, GENERIC_BETA, MAX_POINTS,
};
use crate::body::Body;
use crate::differential::{jacobian, Dual6};
use crate::integrals::{
    energy, jellett, quadratic_integral, quadratic_integral_free, routh_integral,
};
use crate::poisson::conformal_search::{
    decide, random_momenta, sections, Decision, Foliation, Section, MOMENTA, RANK_TOLERANCE,
};
use crate::poisson::deformation::{lie_derivative, TrivialDeformation};
use crate::poisson::first::{
    g_eq1_coefficients, g_eq2_coefficients, Alpha, Beta, FirstBracket, FirstForm,
};
use crate::poisson::lie_poisson::LiePoisson;
use crate::poisson::reduction::{
    energy_spherical, integrals_in_l, pushforward, routh_spherical, spherical, theta_rate,
    theta_rate_squared, MomentumMap, PoissonMap,
};
use crate::poisson::second::{
    g_eq3_coefficients, g_eq3_coefficients_h1, SecondAlphas, SecondBracket,
};
use crate::poisson::second_reduction::SecondMap;
use crate::poisson::{norm, Bivector, Reading};
use crate::scalar::Real;

/// The polar angle `theta = arccos(gamma3/|gamma|)` of (sph-coord).
fn polar_angle<D: Real>(x: &[D; 6]) -> D {
    (x[2] / crate::integrals::geometric(x).sqrt()).acos()
}

/// gamma3 as a function.
fn gamma3(x: &[Dual6; 6]) -> Dual6 {
    x[2]
}

/// gamma1/gamma2 as a function.
fn ratio(x: &[Dual6; 6]) -> Dual6 {
    x[0] / x[1]
}

/// The first bracket under (cond) with the constant alpha.
pub fn cond_bracket(body: Body) -> FirstBracket {
    FirstBracket::new(body, CONSTANT_ALPHA, Beta::Cond)
}

/// The first bracket under (cond2) with the constant alpha.
pub fn cond2_bracket(body: Body) -> FirstBracket {
    FirstBracket::new(body, CONSTANT_ALPHA, Beta::Cond2)
}

/// The generic P' of (p-bv2).
pub fn generic_second(body: Body) -> SecondBracket {
    SecondBracket {
        body,
        alphas: SecondAlphas::Generic([0.9, 0.6, -0.7]),
    }
}

/// The printed rank-4 solution P' of (p-bv2).
pub fn printed_second(body: Body) -> SecondBracket {
    SecondBracket {
        body,
        alphas: SecondAlphas::Printed,
    }
}

/// The third bracket P''.
pub fn third(body: Body) -> SecondBracket {
    SecondBracket {
        body,
        alphas: SecondAlphas::Third([0.9, -0.7]),
    }
}

/// A function on the phase space, owned.
type BoxedFunction<'a> = Box<dyn Fn(&[Dual6; 6]) -> Dual6 + 'a>;

/// An integral of a body, as in [`crate::integrals`].
pub type Integral = fn(&Body, &[Dual6; 6]) -> Dual6;

/// The potentials of the decomposition checks: without gravity (m-eq); with gravity and our
/// `U = +m G (r, gamma)`; with the printed `U = -m g (r, gamma)` (ours with G -> -G).
pub fn decomposition_potentials() -> [Potential; 3] {
    [
        Potential::Ours(free_body()),
        Potential::Ours(body()),
        Potential::Printed(body()),
    ]
}

/// The largest of `check(X, [H_a])` over [`decomposition_potentials`], with the field X and
/// the integrals `H_a` of each (the bivectors and the coefficients do not depend on gravity).
fn over_bodies(
    hamiltonians: &[Integral],
    check: impl Fn(&dyn Fn(&[f64; 6]) -> [f64; 6], &[Function]) -> f64,
) -> f64 {
    decomposition_potentials()
        .iter()
        .map(|u| {
            let hs: Vec<BoxedFunction> = hamiltonians
                .iter()
                .map(|&h| Box::new(u.integral(h)) as BoxedFunction)
                .collect();
            let refs: Vec<Function> = hs.iter().map(|h| h.as_ref()).collect();
            check(&u.field(), &refs)
        })
        .fold(0.0, f64::max)
}

/// A decomposition of the field (ob-vp): `max |X - sum_a c_a P dH_a| / max(|X|, |c_a P dH_a|)` over the points
/// and over [`decomposition_potentials`].
pub fn field_decomposition<P: Bivector>(
    p: &P,
    coefficients: checks::Coefficients,
    hamiltonians: &[Integral],
    points: &[[f64; 6]],
) -> f64 {
    over_bodies(hamiltonians, |field, hs| {
        checks::decomposition(field, p, coefficients, hs, points)
    })
}

/// [`field_decomposition`] as a claim outcome, its note completed by the least-squares fit of X
/// on the same Hamiltonian fields: the fit residual (zero iff a decomposition exists at all)
/// and the distance of the given coefficients from the fitted ones.
fn decomposition_outcome<P: Bivector>(
    p: &P,
    coefficients: checks::Coefficients,
    hamiltonians: &[Integral],
    points: &[[f64; 6]],
    detail: &str,
) -> Outcome {
    let residual = field_decomposition(p, coefficients, hamiltonians, points);
    let fit = over_bodies(hamiltonians, |field, hs| {
        checks::least_squares_fit(field, p, coefficients, hs, points)[0]
    });
    let deviation = over_bodies(hamiltonians, |field, hs| {
        checks::least_squares_fit(field, p, coefficients, hs, points)[1]
    });
    Outcome::checked(
        residual,
        format!("{GRAVITY_NOTE}; least squares on the same fields: fit residual {fit:.1e}, coefficients {deviation:.1e} (relative) from the fitted ones; {detail}"),
    )
}

/// `H3^2 = (M, r)^2`, the Hamiltonian of (g-eq3) (`dH_3^2` read as `d(H3^2)`).
pub fn jellett_squared<D: Real>(body: &Body, x: &[D; 6]) -> D {
    let h3 = jellett(body, x);
    h3 * h3
}

/// The generic alpha, beta of the claims about (p-br) for any alpha, beta.
const GENERIC_NOTE: &str = "alpha = 0.7 + 0.2 t - 0.1 t^2 (t = gamma1/gamma2), beta = 1.1 - 0.3 gamma3 + 0.4 gamma3^2, and alpha = 1.5 + sin t, beta = exp(gamma3)";

/// The largest value of `check` over the generic first brackets [`generic_firsts`].
fn over_generic(check: impl Fn(&FirstBracket) -> f64) -> f64 {
    generic_firsts(body()).iter().map(check).fold(0.0, f64::max)
}

/// What the decomposition residuals measure.
const GRAVITY_NOTE: &str = "max |X - sum c_a P dH_a|/max(|X|, |c_a P dH_a|) for G = 0, for G > 0 with U = +mG(r,gamma) and for the printed U = -mG(r,gamma), H1 = (omega, M) + 2U, H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2 (= (int)'s H2 at G = 0, (int-g)'s up to a constant for the printed U)";

/// The claims about the brackets, in the order of the paper.
pub fn claims() -> Vec<Claim> {
    vec![
        Claim {
            id: "p-br.jacobi",
            label: "p-br",
            statement: "(p-br) is a Poisson bracket for any alpha(gamma1/gamma2), beta(gamma3): [P, P] = 0",
            check: |s| {
                let pts = s.points(&body());
                Outcome::checked(over_generic(|p| checks::jacobi(p, &pts)), format!("max |[P,P]^{{ijk}}|/(2|P||dP|); {GENERIC_NOTE}"))
            },
        },
        Claim {
            id: "p-bv.matrix",
            label: "p-bv",
            statement: "the matrix (p-bv) is the bivector of the brackets (p-br)",
            check: |s| {
                let p = generic_first(body());
                let pts = s.points(&p.body);
                let printed = p.with_form(FirstForm::Matrix);
                let jacobi = checks::jacobi(&printed, &pts);
                Outcome::checked(checks::same_bivector(&printed, &p, &pts), format!("max |P_(p-bv) - P_(p-br)|/|P| (Frobenius); Gamma_beta's `--` read as `-` (as (p-br) has it); the Gamma blocks and M_alpha agree, M_beta's sigma terms carry an extra factor m R; the printed matrix is not Poisson: max |[P,P]|/(2|P||dP|) = {jacobi:.1e}"))
            },
        },
        Claim {
            id: "p-bv.matrix.corrected",
            label: "p-bv",
            statement: "the matrix (p-bv) with m sigma R -> sigma in M_beta is the bivector of (p-br)",
            check: |s| {
                let p = generic_first(body());
                Outcome::checked(checks::same_bivector(&p.with_form(FirstForm::MatrixCorrected), &p, &s.points(&p.body)), "M_beta = (0, M3 - gamma3 u/s - sigma (R gamma3 + a)/g^2, sigma R gamma2/g^2; *, 0, -sigma R gamma1/g^2): the printed entries divided by m R; this bivector is (p-br), Poisson by p-br.jacobi")
            },
        },
        Claim {
            id: "p-br.casimirs",
            label: "p-br",
            statement: "H4 = (gamma, gamma) and H3 = (M, r) are Casimirs of (p-br)",
            check: |s| {
                let pts = s.points(&body());
                let worst = over_generic(|p| checks::casimirs(p, &[&h4, &of(p.body, jellett)], &pts));
                Outcome::checked(worst, format!("max |P dC|/(|P||dC|); {GENERIC_NOTE}"))
            },
        },
        Claim {
            id: "p-br.involution",
            label: "p-br",
            statement: "{H1, H2} = {H1, K} = 0 for any alpha, beta",
            check: |s| {
                let pts = s.points(&body());
                let free = free_body();
                let worst = over_generic(|p| {
                    decomposition_potentials()
                        .iter()
                        .map(|&u| {
                            let h1 = u.integral(energy);
                            checks::involution(p, &h1, &u.integral(quadratic_integral), &pts)
                                .max(checks::involution(p, &h1, &u.integral(routh_integral), &pts))
                        })
                        .fold(checks::involution(p, &of(free, energy), &of(free, quadratic_integral_free), &pts), f64::max)
                });
                Outcome::checked(worst, format!("max |{{H1,F}}|/(|dH1||P||dF|) for F = H2, K: H1, H2 of (int) at G = 0, and H1 = (omega, M) + 2U, H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2 for G = 0 and G > 0 with both signs of U; {GENERIC_NOTE}"))
            },
        },
        Claim {
            id: "p-br.rank",
            label: "p-br",
            statement: "in the generic case rank P = 4",
            check: |s| {
                let pts = s.points(&body());
                Outcome::checked(over_generic(|p| checks::rank(p, 4, &pts)), format!("max s5/s1 of the singular values (1 if the rank is below 4); {GENERIC_NOTE}"))
            },
        },
        Claim {
            id: "p-br.degenerate",
            label: "p-br",
            statement: "at alpha = 0 gamma3 is an extra Casimir, at beta = 0 gamma1/gamma2 is (the printed pairing)",
            check: |s| {
                let b = body();
                let pts = s.points(&b);
                let at_alpha0 = checks::casimirs(&FirstBracket::new(b, Alpha::constant(0.0), GENERIC_BETA), &[&gamma3], &pts);
                let at_beta0 = checks::casimirs(&FirstBracket::new(b, GENERIC_ALPHA, Beta::Gamma3([0.0; 3])), &[&ratio], &pts);
                Outcome::checked(at_alpha0.max(at_beta0), format!("max |P dC|/(|P||dC|): alpha = 0, C = gamma3: {at_alpha0:.1e}; beta = 0, C = gamma1/gamma2: {at_beta0:.1e}"))
            },
        },
        Claim {
            id: "p-br.degenerate.corrected",
            label: "p-br",
            statement: "at alpha = 0 gamma1/gamma2 is an extra Casimir, at beta = 0 gamma3 is (the pairing swapped)",
            check: |s| {
                let b = body();
                let pts = s.points(&b);
                let at_alpha0 = checks::casimirs(&FirstBracket::new(b, Alpha::constant(0.0), GENERIC_BETA), &[&ratio, &h4, &of(b, jellett)], &pts);
                let at_beta0 = checks::casimirs(&FirstBracket::new(b, GENERIC_ALPHA, Beta::Gamma3([0.0; 3])), &[&gamma3, &h4, &of(b, jellett)], &pts);
                let ranks = checks::rank(&FirstBracket::new(b, Alpha::constant(0.0), GENERIC_BETA), 2, &pts)
                    .max(checks::rank(&FirstBracket::new(b, GENERIC_ALPHA, Beta::Gamma3([0.0; 3])), 2, &pts));
                Outcome::checked(at_alpha0.max(at_beta0).max(ranks), format!("max |P dC|/(|P||dC|) with C = H4, H3 and the extra Casimir: alpha = 0, C = gamma1/gamma2: {at_alpha0:.1e}; beta = 0, C = gamma3: {at_beta0:.1e}; rank 2 in both cases (s3/s1 <= {ranks:.1e})"))
            },
        },
        Claim {
            id: "g-eq1",
            label: "g-eq1",
            statement: "under (cond) X = g1 P dH1 + g2 P dH2 with the printed g1, g2",
            check: |s| {
                let p = cond_bracket(body());
                let coef = |x: &[f64; 6]| g_eq1_coefficients(&p, &[x[0], x[1], x[2]]).to_vec();
                decomposition_outcome(&p, &coef, &[energy, quadratic_integral], &s.points(&p.body), "alpha = 0.8")
            },
        },
        Claim {
            id: "cond2.compatible",
            label: "cond2",
            statement: "under (cond2) P is compatible with the Lie-Poisson P0 of e*(3): [P0, P] = 0",
            check: |s| {
                let p = cond2_bracket(body());
                let pts = s.points(&p.body);
                let compatible = checks::compatibility(&LiePoisson, &p, &pts);
                let poisson = checks::jacobi(&p, &pts).max(checks::jacobi(&LiePoisson, &pts));
                Outcome::checked(compatible.max(poisson), format!("max |[P0,P]^{{ijk}}|/(|P0||dP| + |P||dP0|) = {compatible:.1e}; both Poisson: max |[P,P]|, |[P0,P0]| relative = {poisson:.1e}; alpha = 0.8; (cond2) read as beta = alpha g (I1 R gamma3 - I3 (R gamma3 + a))/(R ((I1 - I3) gamma3 + a m (r, gamma))) (the printed numerator misses a closing parenthesis)"))
            },
        },
        Claim {
            id: "g-eq2",
            label: "g-eq2",
            statement: "under (cond2) X = g^1 P dH1 + g^2 P dK (K = g omega3) with the printed g^1, g^2",
            check: |s| {
                let p = cond2_bracket(body());
                let coef = |x: &[f64; 6]| g_eq2_coefficients(&p, x).to_vec();
                decomposition_outcome(&p, &coef, &[energy, routh_integral], &s.points(&p.body), "alpha = 0.8")
            },
        },
        Claim {
            id: "p-map.e3",
            label: "p-map",
            statement: "the change of momenta (p-map) takes (p-br) to the Lie-Poisson bracket (e3) of e*(3)",
            check: |s| {
                let pts = s.points(&body());
                let worst = [0.0, 0.7]
                    .iter()
                    .map(|&c| {
                        let map = PoissonMap { bracket: generic_first(body()), c };
                        p_map_defect(&map.bracket, &map, &pts)
                    })
                    .fold(0.0, f64::max);
                Outcome::checked(worst, "max |J P J^T - P0(gamma, L)|/max(|J|^2 |P|, |P0|) (J the Jacobian of (gamma, M) -> (gamma, L) by AD), generic alpha, beta, c = 0 and c = 0.7; the unbalanced parenthesis read as gamma_i gamma3 (R u - b I1^{-1} (I1 + m h^2)), with which (L, gamma) = c holds identically")
            },
        },
        Claim {
            id: "int-sph",
            label: "int-sph",
            statement: "at c = (gamma, L) = 0 under (cond) H1 and H2 are the printed polynomials in L",
            check: |s| int_sph_outcome(s, Reading::Printed),
        },
        Claim {
            id: "int-sph.corrected",
            label: "int-sph",
            statement: "as int-sph with the b^2 coefficient of H2 equal to (I1 + m r^2)/(I1 R^2 s) - 2m/I1",
            check: |s| int_sph_outcome(s, Reading::Corrected),
        },
        Claim {
            id: "int-sph2",
            label: "int-sph2",
            statement: "in (sph-coord) H1 = A p_phi^2 + B p_theta^2 + b C p_phi + b^2 V and K = -alpha I1 p_phi",
            check: |s| int_sph2_outcome(s, Reading::Printed),
        },
        Claim {
            id: "int-sph2.corrected",
            label: "int-sph2",
            statement: "as int-sph2 with V = (I1 + m (R cos theta + a)^2)/(I1^2 R^2 sin^2 theta)",
            check: |s| int_sph2_outcome(s, Reading::Corrected),
        },
        Claim {
            id: "theta-quadrature",
            label: "int-sph2",
            statement: "along P dH1: dtheta/dt = 2 B p_theta = 2 sqrt(B (E - A c^2 - b c C - b^2 V)), c = -K/(alpha I1)",
            check: |s| theta_outcome(s, Reading::Printed),
        },
        Claim {
            id: "theta-quadrature.corrected",
            label: "int-sph2",
            statement: "the theta quadrature with the corrected V of int-sph2.corrected",
            check: |s| theta_outcome(s, Reading::Corrected),
        },
        Claim {
            id: "P_f.conformal",
            label: "cham-vp",
            statement: "at b = 0, with alpha = -R, beta = -g (r, I r)/(gamma, I r): X = -1/(2 beta) P_f dH1",
            check: |s| {
                let p = FirstBracket::conformal(body());
                let pts = s.points_jellett_zero(&p.body);
                let coef = |x: &[f64; 6]| vec![-0.5 / p.alpha_beta(&[x[0], x[1], x[2]]).1];
                let poisson = checks::jacobi(&p, &pts);
                let outcome = decomposition_outcome(&p, &coef, &[energy], &pts, &format!("at (M, r) = 0; P_f is Poisson: max |[P_f,P_f]|/(2|P_f||dP_f|) = {poisson:.1e}"));
                Outcome { residual: outcome.residual.map(|r| r.max(poisson)), ..outcome }
            },
        },
        Claim {
            id: "p-bv2.involution",
            label: "p-bv2",
            statement: "for any alpha_i(gamma) P' has the Casimirs H4, K = g omega3 and {H1, H3}' = 0",
            check: |s| {
                let p = generic_second(body());
                let b = free_body();
                let pts = s.points(&b);
                let cas = checks::casimirs(&p, &[&h4, &of(b, routh_integral)], &pts);
                let inv = checks::involution(&p, &of(b, energy), &of(b, jellett), &pts);
                Outcome::checked(cas.max(inv), format!("Casimirs max |P'dC|/(|P'||dC|) = {cas:.1e}; max |{{H1,H3}}'|/(|dH1||P'||dH3|) = {inv:.1e}; alpha1 = 0.9 + gamma1 gamma3, alpha2 = 0.6 - gamma2^2, alpha3 = -0.7 + gamma1 gamma2, G = 0"))
            },
        },
        Claim {
            id: "p-bv2.jacobi",
            label: "p-bv2",
            statement: "with the printed alpha_1, alpha_2, alpha_3, [P', P'] = 0",
            check: |s| {
                let p = printed_second(body());
                Outcome::checked(checks::jacobi(&p, &s.points(&p.body)), "max |[P',P']^{ijk}|/(2|P'||dP'|)")
            },
        },
        Claim {
            id: "P2.rank",
            label: "p-bv2",
            statement: "the printed solution P' has rank 4",
            check: |s| {
                let p = printed_second(body());
                Outcome::checked(checks::rank(&p, 4, &s.points(&p.body)), "max s5/s1 (1 if the rank is below 4)")
            },
        },
        Claim {
            id: "g-eq3",
            label: "g-eq3",
            statement: "X = g'1 P' dH1 + g'2 P' d(H3^2) with the printed g'1, g'2",
            check: |s| {
                let p = printed_second(body());
                let coef = |x: &[f64; 6]| g_eq3_coefficients(&p, &[x[0], x[1], x[2]]).to_vec();
                decomposition_outcome(&p, &coef, &[energy, jellett_squared], &s.points(&p.body), "dH_3^2 read as d(H3^2)")
            },
        },
        Claim {
            id: "g-eq3.corrected",
            label: "g-eq3",
            statement: "X = g'1 P' dH2 + g'2 P' d(H3^2) with the printed g'1, g'2 and the quadratic H2 in place of H1",
            check: |s| {
                let p = printed_second(body());
                let pts = s.points(&p.body);
                let printed = |x: &[f64; 6]| g_eq3_coefficients(&p, &[x[0], x[1], x[2]]).to_vec();
                let with_h2 = field_decomposition(&p, &printed, &[quadratic_integral, jellett_squared], &pts);
                let fitted = |x: &[f64; 6]| g_eq3_coefficients_h1(&p, &[x[0], x[1], x[2]]).to_vec();
                let with_h1 = field_decomposition(&p, &fitted, &[energy, jellett_squared], &pts);
                Outcome::checked(with_h2.max(with_h1), format!("H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2 (K a Casimir of P'): {with_h2:.1e}; equivalently with H1 and g'1 = -1/(2 gamma1 alpha3), g'2 = (I1 + m a (R gamma3 + a))/(2 g^2 R I1 (R gamma3 + a)) (least-squares coefficients identified in closed form; the identity gamma1 alpha3 = g^2 (R gamma3 + a)/(I gamma, r) links the two): {with_h1:.1e}; {GRAVITY_NOTE}"))
            },
        },
        Claim {
            id: "P3.rank",
            label: "p-bv2",
            statement: "P'' = P' at gamma1 alpha1 + gamma2 alpha2 = 0 has rank 3 and the Casimir H4",
            check: |s| {
                let p = third(body());
                let pts = s.points(&p.body);
                let rank = checks::rank(&p, 3, &pts);
                let cas = checks::casimirs(&p, &[&h4], &pts);
                Outcome::checked(rank.max(cas), format!("rank test: {rank:.1e} (max s4/s1, 1 if the rank is below 3); H4 Casimir: {cas:.1e}"))
            },
        },
        Claim {
            id: "P3.rank.corrected",
            label: "p-bv2",
            statement: "P'' has rank 2: H4, H3 = (M, r) and K = g omega3 are all Casimirs (a skew matrix has even rank)",
            check: |s| {
                let p = third(body());
                let pts = s.points(&p.body);
                let rank = checks::rank(&p, 2, &pts);
                let cas = checks::casimirs(&p, &[&h4, &of(p.body, jellett), &of(p.body, routh_integral)], &pts);
                Outcome::checked(rank.max(cas), format!("max s3/s1 = {rank:.1e} (1 if the rank is below 2); max |P''dC|/(|P''||dC|) over H4, H3, K = {cas:.1e}; alpha1 = 0.9 + gamma1 gamma3, alpha2 = -gamma1 alpha1/gamma2, alpha3 = -0.7 + gamma1 gamma2"))
            },
        },
        Claim {
            id: "cond2.trivial-deformation",
            label: "cond2",
            statement: "under (cond2) P is a trivial deformation of P0: P = L_Z P0 for some vector field Z",
            check: |s| {
                let z = TrivialDeformation { bracket: cond2_bracket(body()) };
                let pts = s.points(&z.bracket.body);
                let integrability = checks::worst(&pts, |x| {
                    let (d, w) = z.gauges(&[x[0], x[1], x[2]]);
                    d.azimuthal.max(w.azimuthal)
                });
                Outcome::checked(deformation_defect(&|y| z.field(y), &z.bracket, &pts), format!("Z constructed (poisson::deformation): Z = (0, C(gamma) M + d(gamma) + (gamma, M) w(gamma)), rows of C = {{gamma, M_n}}_P x gamma, d and w by the gauge equation on the sphere (meridian quadratures); max |L_Z P0 - P|/max(|L_Z P0|, |P|) (Frobenius, L_Z P0 with the Jacobian of Z and dP0 by AD); integrability of the gauge equation (azimuthal part of the rest) {integrability:.1e}; alpha = 0.8"))
            },
        },
        Claim {
            id: "p-bv2.e3",
            label: "p-bv2",
            statement: "a change of momenta M -> L takes the bracket of P' to the Lie-Poisson bracket of e*(3)",
            check: |s| {
                let map = SecondMap { bracket: printed_second(body()) };
                let pts = s.points(&map.bracket.body);
                let integrability = checks::worst(&pts, |x| map.gauge(&[x[0], x[1], x[2]]).azimuthal);
                Outcome::checked(p_map_defect(&map.bracket, &map, &pts), format!("map constructed (poisson::second_reduction): L = A(gamma) M + K v(gamma), K = g omega3, rows of A from {{L_i, gamma_j}}' = eps_ijk gamma_k, v by the gauge equation on the sphere (meridian quadratures); max |J P' J^T - P0(gamma, L)|/max(|J|^2 |P'|, |P0|) (J the Jacobian of the map by AD), printed alpha_i; integrability of the gauge equation (azimuthal part of the defect) {integrability:.1e}"))
            },
        },
        Claim {
            id: "eq-cf",
            label: "eq-cf",
            statement: "X = g P dF(H1, H2, H3, H4) has no solution with a linear-in-momenta Poisson P of (geom-eq)",
            check: eq_cf_outcome,        },
    ]
}

/// The number of gammas of the (eq-cf) search, whatever the sample's count (one gamma always
/// admits a ratio; eight spread over the sphere exclude a common one by orders).
pub const EQ_CF_GAMMAS: usize = 8;

// A count that [`Sample::new`] accepts, checked when the crate is built.
const _: () = assert!(EQ_CF_GAMMAS >= 1 && EQ_CF_GAMMAS <= MAX_POINTS);

/// The bodies of the (eq-cf) search: the audit's body and the default case's, both with
/// gravity (mg-eq).
pub fn eq_cf_bodies() -> [Body; 2] {
    [body(), Body::default()]
}

/// The (eq-cf) search (poisson::conformal_search) for each body and foliation at
/// [`EQ_CF_GAMMAS`] gammas of the sample's seed: the margin is the smallest
/// [`Decision::margin`], the note gives each decision and the rank gaps.
fn eq_cf_outcome(s: &Sample) -> Outcome {
    let gammas_of = |b: &Body| -> Vec<[f64; 3]> {
        Sample::new(s.seed(), EQ_CF_GAMMAS)
            .expect("EQ_CF_GAMMAS is within MAX_POINTS (asserted at build time)")
            .points(b)
            .iter()
            .map(|x| [x[0], x[1], x[2]])
            .collect()
    };
    let momenta = random_momenta(s.seed());
    let mut margin = f64::INFINITY;
    let mut gap = 0.0f64;
    let mut found = Vec::new();
    for (n, b) in eq_cf_bodies().iter().enumerate() {
        let field = field_of(*b);
        for foliation in Foliation::ALL {
            let sections = sections(b, &field, foliation, &gammas_of(b), &momenta);
            gap = sections.iter().map(Section::gap).fold(gap, f64::max);
            let decision = decide(&sections);
            margin = margin.min(decision.margin());
            found.push(format!(
                "body {}, {}: {}",
                n + 1,
                foliation.name(),
                decision_text(&decision)
            ));
        }
    }
    Outcome::excluded(
        margin,
        format!("decided within the ansatz: P_ij = sum_k a_ijk(gamma) M_k + b_ij(gamma) with any functions a, b (the linear conditions are pointwise in gamma: no degree bound), any conformal factor c(gamma) in place of g, F linear in the integrals (F_a = dF/dH_a constant), the Casimirs and involutive pair of (geom-eq) one of the paper's three choices; at each of {EQ_CF_GAMMAS} gammas the identities in M at {MOMENTA} random momenta, solved by SVD (null spaces at singular values <= {RANK_TOLERANCE:e} s_max; largest gap s_dropped/s_kept {gap:.1e}); residual = the margin, the smallest over bodies and foliations of the residual |Q dF - X|/|X| minimised over the ratios of the F_a (consistent systems leave <= 1e-12); bodies 1 = the audit's, 2 = the default case's, G = 9.81; {}; not decided: F_a varying with the integrals, the other Casimir pairs of (gen-caz)", found.join("; ")),
    )
}

/// A decision in words, for the note.
fn decision_text(decision: &Decision) -> String {
    match decision {
        Decision::NoRatio { residual } => {
            format!("no ratio at some gamma (lifted residual {residual:.2e})")
        }
        Decision::RatioVaries { residual, .. } => {
            format!("no ratio common to the gammas (minimax residual {residual:.2e})")
        }
        Decision::Consistent { residual, ratio } => {
            format!("linear conditions solved by the ratio {ratio:.3?} (residual {residual:.1e}); [P, P] = 0 not tested")
        }
    }
}

/// The reduction (p-map) at c = 0 of the bracket under (cond), without gravity.
fn cond_map() -> PoissonMap {
    PoissonMap {
        bracket: cond_bracket(free_body()),
        c: 0.0,
    }
}

/// What differs in the corrected reading of a formula, for the notes.
fn reading_note(reading: Reading, correction: &str) -> String {
    match reading {
        Reading::Printed => "as printed".into(),
        Reading::Corrected => format!("corrected: {correction}"),
    }
}

fn int_sph_outcome(s: &Sample, reading: Reading) -> Outcome {
    let map = cond_map();
    let [h1, h2] = int_sph_defect(&map, &integrals_in_l, reading, &s.points(&map.bracket.body));
    Outcome::checked(
        h1.max(h2),
        format!("max |H(x) - H_printed(L(x))|/|H|: H1 {h1:.1e}, H2 {h2:.1e} (H1, H2 of (int), G = 0, alpha = 0.8, c = 0); {}", reading_note(reading, "the b^2 coefficient of H2 is (I1 + m r^2)/(I1 R^2 s) - 2m/I1 (printed + 2m/I1); H1 and the rest of H2 as printed")),
    )
}

fn int_sph2_outcome(s: &Sample, reading: Reading) -> Outcome {
    let map = cond_map();
    Outcome::checked(
        int_sph2_defect(&map, &energy_spherical, reading, &s.points(&map.bracket.body)),
        format!("max relative |H - H_printed| over H1 and K, G = 0, alpha = 0.8, c = 0; {}", reading_note(reading, "V = (I1 + m (a^2 + 2aR cos theta + R^2 cos^2 theta))/(I1^2 R^2 sin^2 theta), printed R^2 instead of R^2 cos^2 theta; A, B, C, K as printed")),
    )
}

fn theta_outcome(s: &Sample, reading: Reading) -> Outcome {
    let map = cond_map();
    let [rate, square] = theta_defect(&map, &theta_rate, reading, &s.points(&map.bracket.body));
    Outcome::checked(
        rate.max(square),
        format!("|{{theta, H1}} - 2 B p_theta|/|{{theta, H1}}| = {rate:.1e} (the Hamiltonian rate along P dH1); relative defect of (2 B p_theta)^2 = 4 B (E - A c^2 - b c C - b^2 V) = {square:.1e}; {}", reading_note(reading, "V of int-sph2.corrected")),
    )
}

/// The (p-map) check for the bracket P and the map: `max |J P J^T - P0(gamma, L)| /
/// max(|J|^2 |P|, |P0|)` (Frobenius norms; `|J|^2 |P|` bounds the terms summed in `J P J^T`,
/// large where the map is steep, near `R gamma3 + a = 0` or `gamma1^2 + gamma2^2 = 0`).
pub fn p_map_defect<P: Bivector, F: MomentumMap>(p: &P, map: &F, points: &[[f64; 6]]) -> f64 {
    checks::worst(points, |x| {
        let pushed = pushforward(p, |y| map.image(y), x);
        let target = LiePoisson.entries(&map.image(x));
        let diff: Vec<f64> = pushed
            .iter()
            .flatten()
            .zip(target.iter().flatten())
            .map(|(a, b)| a - b)
            .collect();
        let j = jacobian(|y| map.image(y), x).1.norm();
        let scale =
            (j * j * norm(p.entries(x).iter().flatten())).max(norm(target.iter().flatten()));
        norm(&diff) / scale.max(f64::MIN_POSITIVE)
    })
}

/// The trivial-deformation check: `max |L_Z P0 - P| / max(|L_Z P0|, |P|)` (Frobenius norms) for a
/// field Z, the Lie derivative with the Jacobian of Z by automatic differentiation.
pub fn deformation_defect<P: Bivector>(
    field: &dyn Fn(&[Dual6; 6]) -> [Dual6; 6],
    p: &P,
    points: &[[f64; 6]],
) -> f64 {
    checks::worst(points, |x| {
        checks::matrix_distance(&lie_derivative(field, &LiePoisson, x), &p.entries(x))
    })
}

/// Integrals in the variables `(gamma, L)` and the Jellett value b, as in (int-sph).
pub type InL = dyn Fn(&FirstBracket, &[f64; 6], f64, Reading) -> [f64; 2];

/// The (int-sph) check: the relative defects `[H1, H2]` of `H1(x)`, `H2(x)` of (int) against
/// `integrals(L(x), b)`.
pub fn int_sph_defect(
    map: &PoissonMap,
    integrals: &InL,
    reading: Reading,
    points: &[[f64; 6]],
) -> [f64; 2] {
    let b = map.bracket.body;
    let printed = |k: usize| {
        move |x: &[f64; 6]| integrals(&map.bracket, &map.image(x), jellett(&b, x), reading)[k]
    };
    let h1 = |x: &[f64; 6]| energy(&b, x);
    let h2 = |x: &[f64; 6]| quadratic_integral_free(&b, x);
    [
        checks::identity(&h1, &printed(0), points),
        checks::identity(&h2, &printed(1), points),
    ]
}

/// The energy in the spherical variables `(phi, theta, p_phi, p_theta)` and b, as in (int-sph2).
pub type InSpherical = dyn Fn(&FirstBracket, &[f64; 4], f64, Reading) -> f64;

/// The (int-sph2) check: `H1(x)` against `energy(sph(L(x)), b)` and `K(x)` against
/// `-alpha I1 p_phi`.
pub fn int_sph2_defect(
    map: &PoissonMap,
    energy_sph: &InSpherical,
    reading: Reading,
    points: &[[f64; 6]],
) -> f64 {
    let b = map.bracket.body;
    let sph = |x: &[f64; 6]| spherical(&map.image(x));
    let h1 = |x: &[f64; 6]| energy(&b, x);
    let h1_printed = |x: &[f64; 6]| energy_sph(&map.bracket, &sph(x), jellett(&b, x), reading);
    let k = |x: &[f64; 6]| routh_integral(&b, x);
    let k_printed = |x: &[f64; 6]| routh_spherical(&map.bracket, &sph(x));
    checks::identity(&h1, &h1_printed, points).max(checks::identity(&k, &k_printed, points))
}

/// A rate `dtheta/dt` as a function of the spherical variables, as in the theta quadrature.
pub type ThetaRate = dyn Fn(&FirstBracket, &[f64; 4]) -> f64;

/// The theta-quadrature check: the relative defects of `{theta, H1} = rate(sph)` along the
/// Hamiltonian field P dH1, and of `rate^2 = 4 B (E - A c^2 - b c C - b^2 V)` with `E = H1`,
/// `c = -K/(alpha I1)`.
pub fn theta_defect(
    map: &PoissonMap,
    rate: &ThetaRate,
    reading: Reading,
    points: &[[f64; 6]],
) -> [f64; 2] {
    let b = map.bracket.body;
    let along = |x: &[f64; 6]| {
        crate::poisson::hamiltonian::bracket(&map.bracket, polar_angle::<Dual6>, of(b, energy), x).0
    };
    let printed = |x: &[f64; 6]| rate(&map.bracket, &spherical(&map.image(x)));
    let squared = |x: &[f64; 6]| printed(x).powi(2);
    let quadrature = |x: &[f64; 6]| {
        let c = -routh_integral(&b, x) / (map.bracket.alpha.at(&[x[0], x[1], x[2]]) * b.i1());
        theta_rate_squared(
            &map.bracket,
            &spherical(&map.image(x)),
            energy(&b, x),
            c,
            jellett(&b, x),
            reading,
        )
    };
    [
        checks::identity(&along, &printed, points),
        checks::identity(&squared, &quadrature, points),
    ]
}
