//! Verner's 9(8) pair: the consistency of its tableau (the checks SciPy applies to its own
//! tableaux: row sums, order conditions), its observed order on problems with known solutions,
//! its interpolant, and negative controls that show each check can fail.

use routh::integrate::vern9_tableau::{A, B, C, E, R, STAGES, STEP_STAGES};
use routh::integrate::{Options, RungeKutta, Stepper, Vern9};

/// A rooted tree given by the indices of its children's trees in a list sorted by order.
struct Tree {
    order: usize,
    children: Vec<usize>,
    /// The density gamma(t) = |t| * prod gamma(children).
    gamma: f64,
}

/// All rooted trees with at most `max_order` vertices (486 for order 9), each tree after its
/// subtrees.
fn rooted_trees(max_order: usize) -> Vec<Tree> {
    let mut trees = vec![Tree {
        order: 1,
        children: vec![],
        gamma: 1.0,
    }];
    for n in 2..=max_order {
        // Children multisets: non-increasing sequences of tree indices with orders summing to n - 1.
        let mut stack = vec![(Vec::<usize>::new(), 0usize, usize::MAX)];
        let count = trees.len();
        while let Some((children, sum, max_index)) = stack.pop() {
            if sum == n - 1 {
                let gamma = n as f64 * children.iter().map(|&c| trees[c].gamma).product::<f64>();
                trees.push(Tree {
                    order: n,
                    children,
                    gamma,
                });
                continue;
            }
            let limit = count.min(max_index.saturating_add(1));
            for (c, tree) in trees.iter().enumerate().take(limit) {
                if sum + tree.order < n {
                    let mut next = children.clone();
                    next.push(c);
                    stack.push((next, sum + tree.order, c));
                }
            }
        }
    }
    trees
}

/// Dense lower-triangular Runge–Kutta matrix of the first `s` stages.
fn dense_a(s: usize) -> Vec<Vec<f64>> {
    (0..s)
        .map(|i| {
            let mut row = vec![0.0; s];
            for &(j, a) in A[i] {
                row[j] = a;
            }
            row
        })
        .collect()
}

/// Largest residual `|sum_i w_i Phi_i(t) - scale^|t| / gamma(t)|` over the trees of order at
/// most `order`, where Phi_i is the elementary weight of stage i.
fn order_residual(a: &[Vec<f64>], w: &[f64], order: usize, scale: f64) -> f64 {
    let s = w.len();
    let trees = rooted_trees(order);
    let mut phi: Vec<Vec<f64>> = Vec::with_capacity(trees.len());
    let mut worst: f64 = 0.0;
    for t in &trees {
        let mut p = vec![1.0; s];
        for &c in &t.children {
            for i in 0..s {
                p[i] *= (0..s).map(|j| a[i][j] * phi[c][j]).sum::<f64>();
            }
        }
        let lhs: f64 = (0..s).map(|i| w[i] * p[i]).sum();
        worst = worst.max((lhs - scale.powi(t.order as i32) / t.gamma).abs());
        phi.push(p);
    }
    worst
}

#[test]
fn there_are_486_rooted_trees_up_to_order_9() {
    // OEIS A000081: 1, 1, 2, 4, 9, 20, 48, 115, 286 trees of orders 1..9.
    let trees = rooted_trees(9);
    let per_order: Vec<usize> = (1..=9)
        .map(|n| trees.iter().filter(|t| t.order == n).count())
        .collect();
    assert_eq!(per_order, [1, 1, 2, 4, 9, 20, 48, 115, 286]);
}

#[test]
fn row_sums_equal_nodes() {
    // The nodes are printed to 36 digits and the row sums evaluated in f64 over up to 15
    // terms of size up to ~30: agreement to 1e-14 is round-off.
    for (i, row) in A.iter().enumerate() {
        let sum: f64 = row.iter().map(|&(_, a)| a).sum();
        assert!(
            (sum - C[i]).abs() < 1e-14,
            "stage {i}: row sum {sum} vs c = {}",
            C[i]
        );
    }
}

/// The order conditions are evaluated in f64 with coefficients up to ~30 in size: the residuals
/// of the published tableau are 3e-16 (order 9) and 6e-16 (embedded order 8), so 1e-13 leaves
/// room for round-off only; a violated condition leaves the size of the perturbation times the
/// coefficients (6e-7 for a relative change of 1e-4 in one entry, see the negative control).
const ORDER_TOL: f64 = 1e-13;

#[test]
fn ninth_order_weights_satisfy_the_486_conditions_of_order_9() {
    let a = dense_a(STEP_STAGES);
    let r = order_residual(&a, &B, 9, 1.0);
    println!("order-9 residual {r:e}");
    assert!(r < ORDER_TOL, "{r}");
    // The weights are not of order 10 (the pair is 9(8)): the residual over order 10 is large.
    let r10 = order_residual(&a, &B, 10, 1.0);
    println!("order-10 residual {r10:e}");
    assert!(r10 > 1e-6, "{r10}");
}

#[test]
fn embedded_weights_have_order_8_exactly() {
    let a = dense_a(STEP_STAGES);
    let bhat: Vec<f64> = (0..STEP_STAGES).map(|i| B[i] - E[i]).collect();
    let r8 = order_residual(&a, &bhat, 8, 1.0);
    let r9 = order_residual(&a, &bhat, 9, 1.0);
    println!("embedded: order-8 residual {r8:e}, order-9 residual {r9:e}");
    assert!(r8 < ORDER_TOL, "{r8}");
    assert!(r9 > 1e-6, "{r9}");
}

/// Largest residual of the interpolant's order-9 conditions over theta = 0.1, 0.2, .., 1.
fn interpolant_residual(r: &[[f64; 9]; STAGES]) -> f64 {
    let a = dense_a(STAGES);
    (1..=10)
        .map(|k| {
            let theta = k as f64 / 10.0;
            let w: Vec<f64> = r
                .iter()
                .map(|r| theta * r.iter().rev().fold(0.0, |p, &c| p * theta + c))
                .collect();
            order_residual(&a, &w, 9, theta)
        })
        .fold(0.0, f64::max)
}

/// The coefficients of the b_i(theta) reach 7e3 and alternate in sign: evaluating them at
/// theta near 1 loses about four digits, so the residuals of the published interpolant reach
/// ~1e-12; a perturbation of 1e-8 in one coefficient leaves ~1e-5.
const INTERP_TOL: f64 = 1e-10;

#[test]
fn interpolant_has_order_9_at_every_theta() {
    // b_i(theta) must satisfy sum_i b_i(theta) Phi_i(t) = theta^|t| / gamma(t) for all trees
    // of order <= 9, with the 26 stages (stage 16 is the step end, whose row of A is B).
    let res = interpolant_residual(&R);
    println!("interpolant residual {res:e}");
    assert!(res < INTERP_TOL, "{res}");
    // At theta = 1 the interpolant is the step: b_i(1) = b_i.
    for (i, r) in R.iter().enumerate() {
        let b1: f64 = r.iter().sum();
        let b = B.get(i).copied().unwrap_or(0.0);
        assert!((b1 - b).abs() < 1e-11, "stage {i}: b(1) = {b1}, b = {b}");
    }
    // Negative control: one coefficient changed by 1e-8 relative.
    let mut perturbed = R;
    perturbed[7][4] *= 1.0 + 1e-8;
    let res = interpolant_residual(&perturbed);
    println!("perturbed interpolant residual {res:e}");
    assert!(res > 100.0 * INTERP_TOL, "{res}");
}

#[test]
fn a_perturbed_coefficient_breaks_the_order_conditions() {
    // Negative control: a relative change of 1e-4 in a single entry of A (row 9, which feeds
    // the 9th-order weights) must show in the residuals far above ORDER_TOL.
    let mut a = dense_a(STEP_STAGES);
    a[9][0] *= 1.0 + 1e-4;
    let r = order_residual(&a, &B, 9, 1.0);
    println!("perturbed residual {r:e}");
    assert!(r > 1e3 * ORDER_TOL, "{r}");
    let mut b = B;
    b[8] *= 1.0 + 1e-9;
    let r = order_residual(&dense_a(STEP_STAGES), &b, 9, 1.0);
    assert!(r > 10.0 * ORDER_TOL, "{r}");
}

/// Kepler's problem (gravitational parameter 1) as a first-order system in (q, p).
fn kepler(_t: f64, y: &[f64; 4]) -> [f64; 4] {
    let r3 = (y[0] * y[0] + y[1] * y[1]).powf(1.5);
    [y[2], y[3], -y[0] / r3, -y[1] / r3]
}

/// Start at the pericentre of an orbit of eccentricity `e` and semi-major axis 1: the
/// period is 2 pi and the solution returns to the start.
fn kepler_start(e: f64) -> [f64; 4] {
    [1.0 - e, 0.0, 0.0, ((1.0 + e) / (1.0 - e)).sqrt()]
}

fn max_abs_diff<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn fixed_steps_show_order_9_on_kepler() {
    // Eccentricity 0.5 over one period with 32..128 equal steps: the errors (8e-7 down to
    // 2e-12) stay far above round-off, and a nonlinear problem tests all elementary
    // differentials. Each halving of h must divide the error by about 2^9: the observed
    // exponents are 9.4 and 9.5 (still pre-asymptotic); within 0.6 of 9 excludes order 8.
    let y0 = kepler_start(0.5);
    let period = 2.0 * std::f64::consts::PI;
    let errors: Vec<f64> = [32, 64, 128]
        .iter()
        .map(|&n| {
            let mut s = Vern9::fixed_steps(&kepler, 0.0, y0, period, n).unwrap();
            while !s.step().unwrap() {}
            max_abs_diff(s.y(), &y0)
        })
        .collect();
    let orders: Vec<f64> = errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
    println!("Vern9 fixed-step errors {errors:?}, observed orders {orders:?}");
    for p in orders {
        assert!((p - 9.0).abs() < 0.6, "observed order {p}");
    }
}

#[test]
fn adaptive_steps_meet_the_tolerance_and_the_interpolant_is_accurate() {
    // Kepler with e = 0.6 over 3 periods at tolerances 1e-6..1e-12: the global error at the
    // end must shrink with the tolerance and stay below 1000 x tol (it grows about linearly
    // in time along the orbit); the dense output at 50 points inside the last period, against
    // the solution a period earlier (the same point of the orbit), below 1000 x tol.
    let y0 = kepler_start(0.6);
    let period = 2.0 * std::f64::consts::PI;
    let mut last_err = f64::INFINITY;
    for tol in [1e-6, 1e-8, 1e-10, 1e-12] {
        let opts = Options {
            rtol: tol,
            atol: tol,
            ..Options::default()
        };
        let mut solver = Vern9::new(&kepler, 0.0, y0, 3.0 * period, &opts).unwrap();
        while !solver.step().unwrap() {}
        let err = max_abs_diff(solver.y(), &y0);
        println!("tol {tol:e}: error {err:e}, {:?}", solver.stats());
        assert!(err < 1000.0 * tol, "tol {tol}: error {err}");
        assert!(err < last_err);
        last_err = err;
    }
    // Dense output: one period later the orbit repeats, so y(t + T) = y(t).
    let tol = 1e-12;
    let opts = Options {
        rtol: tol,
        atol: tol,
        ..Options::default()
    };
    let mut reference = Vern9::new(&kepler, 0.0, y0, period, &opts).unwrap();
    let mut first = vec![];
    while !reference.step().unwrap() {
        first.push((reference.t_prev(), reference.t()));
    }
    let mut solver = Vern9::new(&kepler, 0.0, y0, 2.0 * period, &opts).unwrap();
    let mut worst: f64 = 0.0;
    while !solver.step().unwrap() {
        let (ta, tb) = (solver.t_prev(), solver.t());
        if ta >= period {
            let t = 0.5 * (ta + tb);
            // Exact solution at t - period from a fresh integration ending there.
            let mut exact = Vern9::new(&kepler, 0.0, y0, t - period, &opts).unwrap();
            while !exact.step().unwrap() {}
            worst = worst.max(max_abs_diff(&solver.dense(t), exact.y()));
        }
    }
    println!("dense output: worst midpoint error {worst:e}");
    assert!(worst < 1000.0 * tol, "{worst}");
    assert!(!first.is_empty());
}
