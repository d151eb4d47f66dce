//! The field of `src/field.rs`, written with two exact identities of vector algebra, against
//! the literal form of (mg-eq) evaluated independently here,
//!
//! `dM/dt = M x omega + m (R dgamma/dt) x (omega x r) + gamma x dU/dgamma`,
//!
//! with `r` = [`Ball::contact_vector`] and `dU/dgamma` = [`Ball::potential_gradient`] (itself
//! checked against automatic differentiation of [`Ball::potential`] in `tests/ball.rs`): the
//! values and the dual-number Jacobians at random points of R^6 (including `|gamma| != 1`,
//! points near the poles `gamma = +-e3`, huge and tiny momenta), for balls with a general
//! centre of mass, a Routh sphere with its centre of mass below and above the centre, no
//! gravity, `I1 != I2` and a Chaplygin ball. Negative controls: a wrong sign of the rolling
//! term and a form that agrees only on `|gamma| = 1` are caught.
//!
//! Tolerance. The two forms are the same polynomial expression in `(gamma, omega)` (the same
//! `omega`, bit for bit: both call [`Ball::angular_velocity`]), so they differ by round-off
//! only. The literal form cancels terms: its rolling term `R gamma_dot x (omega x r)` is a
//! difference of products of size `B = m R |gamma| |omega|^2 rho`, `rho = R |gamma| + |com|`,
//! whatever the size of the result; its torque a difference of products of size
//! `C = m G |gamma| (2 R |gamma| + |com|)`; the gyroscopic term `M x omega` of size
//! `A = |M| |omega|`. Each form's error in a component is a few ulp of these sizes: the literal
//! rolling term at most about 14 eps B (the roundings of `r`, of two cross products and of
//! `m R`), plus 7 eps B because the computed `gamma_dot` is orthogonal to `omega` and `gamma`
//! only to about 2 ulp, which the identity uses; the short form 6 eps B; the torques about
//! 5 eps C each; the sums 2 eps (A + B + C). Hence the bound `32 eps (A + B + C)` per
//! component (an absolute floor of the smallest normal number covers subnormal results);
//! the observed maximum is printed, and is a few eps. The Jacobians: the same bound with the
//! sizes differentiated by the product rule (`A_j = |d_j M| |omega| + |M| |d_j omega|`, ...),
//! 64 eps for the roundings of the dual parts on top.
//!
//! The two closed forms of `omega` ([`Ball::angular_velocity`] for numbers,
//! [`Ball::angular_velocity_by_determinant`] for the Taylor tape) are compared the same way,
//! values and Jacobians, with a bound scaled by the condition of `I_Q`.

use routh::ball::Ball;
use routh::case::Case;
use routh::differential::{jacobian, Dual6};
use routh::field::vector_field;
use routh::scalar::{cross, dot, lift, split, Scalar};

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;

const EPS: f64 = f64::EPSILON;

/// The literal form of (mg-eq), generic like the library's field.
fn literal<D: Scalar>(ball: &Ball, x: &[D; 6]) -> [D; 6] {
    let (gamma, m_vec) = split(x);
    let r = ball.contact_vector(&gamma);
    let omega = ball.angular_velocity(&gamma, &m_vec);
    let gamma_dot = cross(&gamma, &omega);
    let r_dot = gamma_dot.map(|c| c * ball.radius);
    let rolling = cross(&r_dot, &cross(&omega, &r));
    let gyroscopic = cross(&m_vec, &omega);
    let torque = cross(&gamma, &ball.potential_gradient(&gamma));
    let dm: [D; 3] = std::array::from_fn(|i| gyroscopic[i] + rolling[i] * ball.m + torque[i]);
    [
        gamma_dot[0],
        gamma_dot[1],
        gamma_dot[2],
        dm[0],
        dm[1],
        dm[2],
    ]
}

/// The short form with the sign of the rolling term flipped (negative control).
fn wrong_sign<D: Scalar>(ball: &Ball, x: &[D; 6]) -> [D; 6] {
    let mut f = vector_field(ball, x);
    let (gamma, m_vec) = split(x);
    let omega = ball.angular_velocity(&gamma, &m_vec);
    let gamma_dot = cross(&gamma, &omega);
    let com = ball.com.map(lift::<D>);
    // Subtract the rolling term twice: -m R (gamma_dot, com) omega becomes its opposite.
    let s = dot(&gamma_dot, &com) * (2.0 * ball.m * ball.radius);
    for i in 0..3 {
        f[3 + i] = f[3 + i] + s * omega[i];
    }
    f
}

/// The short form with its torque times `(gamma, gamma)`: the same values on `|gamma| = 1`,
/// not off it, and not the same derivatives anywhere (negative control of "on all of R^6").
fn sphere_only<D: Scalar>(ball: &Ball, x: &[D; 6]) -> [D; 6] {
    let (gamma, _) = split(x);
    let mut f = vector_field(ball, x);
    let free = vector_field(
        &Ball {
            gravity: 0.0,
            ..*ball
        },
        x,
    );
    let norm2 = dot(&gamma, &gamma);
    for i in 3..6 {
        let torque = f[i] - free[i];
        f[i] = free[i] + torque * norm2;
    }
    f
}

fn norm(v: &[f64; 3]) -> f64 {
    dot(v, v).sqrt()
}

/// The sizes `A + B + C` of the terms that the literal form cancels (module documentation).
fn term_size(ball: &Ball, x: &[f64; 6]) -> f64 {
    let (gamma, m_vec) = split(x);
    let omega = ball.angular_velocity(&gamma, &m_vec);
    let (g, w) = (norm(&gamma), norm(&omega));
    let com = norm(&ball.com);
    let rho = ball.radius * g + com;
    let a = norm(&m_vec) * w;
    let b = ball.m * ball.radius * g * w * w * rho;
    let c = ball.m * ball.gravity * g * (2.0 * ball.radius * g + com);
    a + b + c
}

/// The Jacobian of omega (its rows 0 to 2; the others zero) at `x`, by dual numbers through
/// one of its closed forms (`Ball::angular_velocity` or `Ball::angular_velocity_by_determinant`).
fn omega_jacobian(
    ball: &Ball,
    x: &[f64; 6],
    form: fn(&Ball, &[Dual6; 3], &[Dual6; 3]) -> [Dual6; 3],
) -> nalgebra::SMatrix<f64, 6, 6> {
    let (_, d_omega) = jacobian(
        |y| {
            let (g, m) = split(y);
            let w = form(ball, &g, &m);
            [w[0], w[1], w[2], lift(0.0), lift(0.0), lift(0.0)]
        },
        x,
    );
    d_omega
}

/// The sizes of column `j` of the Jacobian: the product rule applied to [`term_size`].
fn jacobian_term_size(ball: &Ball, x: &[f64; 6], j: usize) -> f64 {
    let (gamma, m_vec) = split(x);
    let omega = ball.angular_velocity(&gamma, &m_vec);
    let d_omega = omega_jacobian(ball, x, Ball::angular_velocity);
    let dw = norm(&[d_omega[(0, j)], d_omega[(1, j)], d_omega[(2, j)]]);
    let dg = if j < 3 { 1.0 } else { 0.0 };
    let dm = 1.0 - dg;
    let (g, w, mm) = (norm(&gamma), norm(&omega), norm(&m_vec));
    let com = norm(&ball.com);
    let rho = ball.radius * g + com;
    let a = dm * w + mm * dw;
    let b = ball.m
        * ball.radius
        * (dg * w * w * rho + g * 2.0 * w * dw * rho + g * w * w * ball.radius * dg);
    let c =
        ball.m * ball.gravity * (dg * (2.0 * ball.radius * g + com) + g * 2.0 * ball.radius * dg);
    a + b + c
}

/// The balls of the comparison.
fn balls() -> Vec<(&'static str, Ball)> {
    let default = Case::default_case().unwrap().ball;
    let mut free = default;
    free.gravity = 0.0;
    vec![
        ("default (Routh, com below)", default),
        ("no gravity", free),
        (
            "Routh, com above",
            Ball::new(1.0, 1.0, [0.4, 0.4, 0.5], [0.0, 0.0, 0.5], 9.81).unwrap(),
        ),
        (
            "general com, I1 != I2",
            Ball::new(1.3, 0.8, [0.3, 0.45, 0.5], [0.05, -0.02, -0.1], 9.81).unwrap(),
        ),
        (
            "axial com, I1 != I2",
            Ball::new(2.5, 0.7, [0.2, 0.3, 0.35], [0.0, 0.0, -0.3], 3.0).unwrap(),
        ),
        (
            "Chaplygin",
            Ball::new(1.0, 1.0, [0.3, 0.4, 0.5], [0.0, 0.0, 0.0], 9.81).unwrap(),
        ),
        (
            "equal moments (one group)",
            Ball::new(1.0, 1.0, [0.4, 0.4, 0.4], [0.0, 0.0, -0.3], 9.81).unwrap(),
        ),
        (
            "small heavy ball",
            Ball::new(1e3, 1e-2, [3e-2, 3e-2, 4e-2], [1e-3, 0.0, -4e-3], 9.81).unwrap(),
        ),
    ]
}

/// Random points: gamma a random direction (every fifth near the pole +-e3) times
/// 10^[-3, 3]; M random in each component times 10^[-120, 120].
fn points(count: usize) -> Vec<[f64; 6]> {
    let unit = -1.0f64..1.0;
    let strategy = (
        [unit.clone(), unit.clone(), unit.clone()],
        [unit.clone(), unit.clone(), unit],
        -3.0f64..3.0,
        -120.0f64..120.0,
        0usize..5,
    );
    let mut runner = TestRunner::deterministic();
    (0..count)
        .map(|_| {
            let (g, m, g_exp, m_exp, kind) = strategy.new_tree(&mut runner).unwrap().current();
            let g = if kind == 0 {
                [g[0] * 1e-9, g[1] * 1e-9, g[2].signum()]
            } else {
                g
            };
            let (gs, ms) = (10f64.powf(g_exp), 10f64.powf(m_exp));
            [
                g[0] * gs,
                g[1] * gs,
                g[2] * gs,
                m[0] * ms,
                m[1] * ms,
                m[2] * ms,
            ]
        })
        .collect()
}

/// Largest `|f_i - g_i| / (size + MIN_POSITIVE)` over the components, in eps.
fn discrepancy(f: &[f64], g: &[f64], size: f64) -> f64 {
    f.iter()
        .zip(g)
        .map(|(f, g)| (f - g).abs() / (size + f64::MIN_POSITIVE) / EPS)
        .fold(0.0, f64::max)
}

#[test]
fn the_short_field_equals_the_literal_form_to_round_off() {
    let points = points(1500);
    for (name, ball) in balls() {
        let mut worst = 0.0f64;
        let mut resolvable = 0;
        for x in &points {
            let short = vector_field::<f64>(&ball, x);
            let long = literal::<f64>(&ball, x);
            assert!(short.iter().all(|v| v.is_finite()), "{name} at {x:?}");
            assert_eq!(short[..3], long[..3], "{name}: dgamma/dt at {x:?}");
            let size = term_size(&ball, x);
            let d = discrepancy(&short, &long, size);
            assert!(d <= 32.0, "{name} at {x:?}: {d} eps of {size}");
            worst = worst.max(d);
            // Negative control: the wrong sign changes the result by twice the rolling term;
            // wherever that is above twice the tolerance it must be caught.
            let wrong = wrong_sign::<f64>(&ball, x);
            let change = discrepancy(&wrong, &short, size);
            if change > 64.0 {
                resolvable += 1;
                let caught = discrepancy(&wrong, &long, size);
                assert!(
                    caught > 32.0,
                    "{name} at {x:?}: wrong sign within {caught} eps"
                );
            }
        }
        println!(
            "{name}: largest difference {worst:.2} eps of the terms' size; a wrong sign caught at all {resolvable} of {} points where it changes the field by more than 64 eps",
            points.len()
        );
        // The rolling term, m R (gamma_dot, com) omega, vanishes for com = 0 (Chaplygin) and
        // is below the round-off of the other terms where |M| is tiny (the torque dominates)
        // or gamma_dot is orthogonal to com; at the other points (a third or more) it counts.
        if ball.com != [0.0; 3] {
            assert!(resolvable * 3 >= points.len(), "{name}: {resolvable}");
        }
    }
}

#[test]
fn the_jacobians_agree() {
    let points = points(1000);
    for (name, ball) in balls() {
        let mut worst = 0.0f64;
        let mut resolvable = 0;
        for x in &points {
            let (fs, js) = jacobian(|y| vector_field(&ball, y), x);
            let (fl, jl) = jacobian(|y| literal(&ball, y), x);
            let (_, jw) = jacobian(|y| sphere_only(&ball, y), x);
            assert!(discrepancy(&fs, &fl, term_size(&ball, x)) <= 32.0);
            let mut change = 0.0f64;
            let mut caught = f64::INFINITY;
            for j in 0..6 {
                let size = jacobian_term_size(&ball, x, j);
                let column = |m: &nalgebra::SMatrix<f64, 6, 6>| -> [f64; 6] {
                    std::array::from_fn(|i| m[(i, j)])
                };
                let d = discrepancy(&column(&js), &column(&jl), size);
                assert!(d <= 64.0, "{name} at {x:?}, column {j}: {d} eps of {size}");
                worst = worst.max(d);
                let c = discrepancy(&column(&jw), &column(&js), size);
                if c > change {
                    change = c;
                    caught = discrepancy(&column(&jw), &column(&jl), size);
                }
            }
            // Negative control: the sphere-only form, wherever its Jacobian differs by more
            // than twice the tolerance, is caught.
            if change > 128.0 {
                resolvable += 1;
                assert!(
                    caught > 64.0,
                    "{name} at {x:?}: sphere-only form within {caught}"
                );
            }
        }
        println!(
            "{name}: Jacobians within {worst:.2} eps; the sphere-only form caught at all {resolvable} of {} points where it differs by more than 128 eps",
            points.len()
        );
        // The sphere-only form differs in d/dgamma of the torque, 2 gamma (gamma x -m G com):
        // zero without gravity or without an offset of the centre of mass, and below the
        // round-off of the other terms where |M| is huge.
        if ball.gravity > 0.0 && ball.com != [0.0; 3] {
            assert!(resolvable * 3 >= points.len(), "{name}: {resolvable}");
        }
    }
}

#[test]
fn the_sphere_only_form_agrees_in_value_on_the_sphere() {
    // The negative control of the Jacobians is not a different field on |gamma| = 1: there
    // its values equal the short form's to round-off, so only the Jacobian check (and the
    // values off the sphere) can catch it.
    let ball = Case::default_case().unwrap().ball;
    for x in points(200) {
        let g = norm(&[x[0], x[1], x[2]]);
        let y = [x[0] / g, x[1] / g, x[2] / g, x[3], x[4], x[5]];
        let d = discrepancy(
            &sphere_only::<f64>(&ball, &y),
            &vector_field::<f64>(&ball, &y),
            term_size(&ball, &y),
        );
        assert!(d <= 32.0, "at {y:?}: {d}");
    }
}

#[test]
fn the_two_forms_of_omega_agree_to_round_off() {
    // `omega = I_Q^{-1} M` by cofactors (numbers) and by the determinant (the Taylor tape): the
    // same solution of `I_Q omega = M`, each rounded a few ulp backward. `I_Q = I + m (r^2 E
    // - r r^T)` has its eigenvalues between `I_min` and `I_max + m r^2`, so either form is
    // within `c eps kappa |M| / I_min` of the exact one, `kappa = (I_max + m r^2) / I_min`
    // (the solution's sensitivity to a relative error in `I_Q`). Bound `64 eps kappa |M| / I_min`, the observed maximum
    // printed; the dual parts (the Jacobian of omega) the same with the sizes differentiated
    // (`|d M| = 1` in a momentum column, `d (m r^2) = 2 m R |r|` in a gamma column).
    // Negative controls: `I_2` taken for `I_1` in the determinant form is caught where the moments
    // differ, and `I_3` changed by 1e-10 relative (on every ball) at a third of the points or
    // more: the bound is tight to that.
    let points = points(1500);
    for (name, ball) in balls() {
        let (i_min, i_max) = ball
            .inertia
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), &i| {
                (lo.min(i), hi.max(i))
            });
        let mut worst = 0.0f64;
        let mut worst_dual = 0.0f64;
        let (mut caught, mut nudge_caught) = (0, 0);
        for x in &points {
            let (gamma, m_vec) = split(x);
            let r = ball.contact_vector(&gamma);
            let mr2 = ball.m * dot(&r, &r);
            let kappa = (i_max + mr2) / i_min;
            let size = kappa * norm(&m_vec) / i_min;
            let by_cofactors = ball.angular_velocity(&gamma, &m_vec);
            let by_determinant = ball.angular_velocity_by_determinant(&gamma, &m_vec);
            assert!(
                by_determinant.iter().all(|v| v.is_finite()),
                "{name} at {x:?}"
            );
            let d = discrepancy(&by_cofactors, &by_determinant, size);
            assert!(d <= 64.0, "{name} at {x:?}: {d} eps of {size}");
            worst = worst.max(d);
            let jc = omega_jacobian(&ball, x, Ball::angular_velocity);
            let jr = omega_jacobian(&ball, x, Ball::angular_velocity_by_determinant);
            for j in 0..6 {
                let dm = if j < 3 { 0.0 } else { 1.0 };
                let dmr2 = if j < 3 {
                    2.0 * ball.m * ball.radius * norm(&r)
                } else {
                    0.0
                };
                let dsize =
                    kappa * (dm + norm(&m_vec) * dmr2 / i_min) / i_min + (dmr2 / i_min) * size;
                let col = |m: &nalgebra::SMatrix<f64, 6, 6>| -> [f64; 3] {
                    std::array::from_fn(|i| m[(i, j)])
                };
                let d = discrepancy(&col(&jc), &col(&jr), dsize);
                assert!(
                    d <= 128.0,
                    "{name} at {x:?}, column {j}: {d} eps of {dsize}"
                );
                worst_dual = worst_dual.max(d);
            }
            let mut swapped = ball;
            swapped.inertia[0] = ball.inertia[1];
            let wrong = swapped.angular_velocity_by_determinant(&gamma, &m_vec);
            if discrepancy(&wrong, &by_cofactors, size) > 64.0 {
                caught += 1;
            }
            let mut nudged = ball;
            nudged.inertia[2] *= 1.0 + 1e-10;
            let wrong = nudged.angular_velocity_by_determinant(&gamma, &m_vec);
            if discrepancy(&wrong, &by_cofactors, size) > 64.0 {
                nudge_caught += 1;
            }
        }
        println!(
            "{name}: omega's two forms within {worst:.2} eps, their Jacobians within {worst_dual:.2} eps; I_2 for I_1 caught at {caught}, I_3 (1 + 1e-10) at {nudge_caught} of {} points",
            points.len()
        );
        assert!(nudge_caught * 3 >= points.len(), "{name}: {nudge_caught}");
        if ball.inertia[0] != ball.inertia[1] {
            assert!(caught * 3 >= points.len(), "{name}: {caught}");
        }
    }
}
