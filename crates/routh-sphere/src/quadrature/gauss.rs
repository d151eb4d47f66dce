//! Gauss-Legendre quadrature on [0, 1]: nodes and weights by Newton's method on the Legendre
//! polynomial P_n (three-term recurrence), from Chebyshev-like initial guesses.

use std::f64::consts::PI;
use std::sync::OnceLock;

/// An n-point Gauss-Legendre rule on [0, 1], exact for polynomials of degree 2n - 1.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussLegendre {
    /// Nodes in (0, 1).
    pub nodes: Vec<f64>,
    /// Weights, summing to 1.
    pub weights: Vec<f64>,
}

/// The rules of up to this many nodes are computed once per process ([`GaussLegendre::new`]).
const CACHED: usize = 65;

/// The rules computed so far, by number of nodes, shared by every thread: computing one costs
/// Newton's method at each node, copying it two short vectors.
static RULES: [OnceLock<GaussLegendre>; CACHED] = [const { OnceLock::new() }; CACHED];

impl GaussLegendre {
    /// The n-point rule (n >= 1); computed once per process for `n < 65`, then copied.
    pub fn new(n: usize) -> Self {
        match RULES.get(n) {
            Some(rule) => rule.get_or_init(|| Self::compute(n)).clone(),
            None => Self::compute(n),
        }
    }

    /// The n-point rule, by Newton's method.
    fn compute(n: usize) -> Self {
        let mut nodes = Vec::with_capacity(n);
        let mut weights = Vec::with_capacity(n);
        for i in 0..n {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (p, d) = legendre(n, x);
                dp = d;
                let dx = p / d;
                x -= dx;
                if dx.abs() <= 1e-16 {
                    break;
                }
            }
            nodes.push(0.5 * (1.0 - x));
            weights.push(1.0 / ((1.0 - x * x) * dp * dp));
        }
        GaussLegendre { nodes, weights }
    }

    /// The integral of `f` over [0, 1].
    pub fn integrate(&self, f: impl Fn(f64) -> f64) -> f64 {
        self.nodes
            .iter()
            .zip(&self.weights)
            .map(|(x, w)| w * f(*x))
            .sum()
    }
}

/// A Gauss-Legendre rule loses its geometric convergence when a singularity of the
/// integrand lies near the interval: with the singularity on the Bernstein ellipse of
/// parameter rho, the relative error of the n-point rule is about `rho^(-2n)`. Sub-intervals
/// are bisected until that is at most this, below the round-off of f64 (rho at least 2.26
/// for 24 nodes, 11.5 for 8): a relative error, so the test holds in any units.
const SINGULARITY_ERROR: f64 = 1e-17;
/// Deepest bisection toward a singularity.
const MAX_DEPTH: u32 = 40;

impl GaussLegendre {
    /// The mean `(1/(b - a)) int_a^b f` of a function analytic except at the complex points
    /// `singularities` (`(re, im)`): sub-intervals bisected toward the singularities until
    /// each lies outside the Bernstein ellipse of every piece whose `rho^(-2n)` is
    /// `SINGULARITY_ERROR` ([`GaussLegendre::min_rho`]). Also returns the number of pieces
    /// (the work: `n` evaluations of f each).
    pub fn mean_avoiding(
        &self,
        a: f64,
        b: f64,
        singularities: &[(f64, f64)],
        f: &impl Fn(f64) -> f64,
    ) -> (f64, usize) {
        let min_rho = self.min_rho();
        let near = |a: f64, b: f64| {
            singularities
                .iter()
                .any(|&z| bernstein_rho(a, b, z) < min_rho)
        };
        let piece = |a: f64, b: f64| self.integrate(|tau| f(a + tau * (b - a)));
        self.mean_at_depth(a, b, &near, &piece, 0)
    }

    /// The smallest Bernstein parameter of a singularity for which this rule's error,
    /// `rho^(-2n)`, is at most `SINGULARITY_ERROR`.
    pub fn min_rho(&self) -> f64 {
        SINGULARITY_ERROR.powf(-0.5 / self.nodes.len() as f64)
    }

    /// The mean over `[a, b]`, bisected while `near(a, b)` (a singularity too close), each
    /// piece's by `piece`.
    fn mean_at_depth(
        &self,
        a: f64,
        b: f64,
        near: &impl Fn(f64, f64) -> bool,
        piece: &impl Fn(f64, f64) -> f64,
        depth: u32,
    ) -> (f64, usize) {
        if !near(a, b) || depth >= MAX_DEPTH || a == b {
            return (piece(a, b), 1);
        }
        let m = 0.5 * (a + b);
        let (left, n_left) = self.mean_at_depth(a, m, near, piece, depth + 1);
        let (right, n_right) = self.mean_at_depth(m, b, near, piece, depth + 1);
        (0.5 * (left + right), n_left + n_right)
    }
}

/// The parameter rho of the Bernstein ellipse of `[a, b]` through the complex point `z`:
/// `|w + sqrt(w^2 - 1)|` with `w = (z - c) / h` (the root of larger modulus).
pub fn bernstein_rho(a: f64, b: f64, z: (f64, f64)) -> f64 {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    if h == 0.0 {
        return f64::INFINITY;
    }
    let (x, y) = ((z.0 - c) / h, z.1 / h);
    // w^2 - 1 and its square root.
    let (re, im) = (x * x - y * y - 1.0, 2.0 * x * y);
    let r = re.hypot(im);
    let (sr, si) = (
        (0.5 * (r + re)).max(0.0).sqrt(),
        (0.5 * (r - re)).max(0.0).sqrt(),
    );
    let si = if im < 0.0 { -si } else { si };
    let plus = (x + sr).hypot(y + si);
    let minus = (x - sr).hypot(y - si);
    plus.max(minus)
}

/// `P_n(x)` and `P_n'(x)`.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 2..=n {
        let k = k as f64;
        (p0, p1) = (p1, ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k);
    }
    (p1, n as f64 * (x * p1 - p0) / (x * x - 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bisection_toward_a_branch_point_keeps_the_mean_accurate() {
        // sqrt(x + 0.01) on [0, 1]: a branch point 0.01 from the interval, rho = 1.22, where
        // one 24-point rule is off by 1e-7; bisected toward it, by less than 1e-14.
        let rule = GaussLegendre::new(24);
        let f = |x: f64| (x + 0.01).sqrt();
        let exact = 2.0 / 3.0 * (1.01f64.powf(1.5) - 0.01f64.powf(1.5));
        let plain = rule.integrate(f);
        let (avoiding, pieces) = rule.mean_avoiding(0.0, 1.0, &[(-0.01, 0.0)], &f);
        assert!(pieces > 1 && pieces < 40, "{pieces}");
        assert!((avoiding - exact).abs() < 1e-14, "{avoiding} {exact}");
        assert!((plain - exact).abs() > 1e-9, "{plain} {exact}");
        assert!((bernstein_rho(-1.0, 1.0, (2.0, 0.0)) - (2.0 + 3f64.sqrt())).abs() < 1e-14);
    }

    #[test]
    fn rule_is_exact_for_degree_2n_minus_1_and_not_2n() {
        let rule = GaussLegendre::new(10);
        let exact = |d: i32| 1.0 / (d as f64 + 1.0);
        for d in 0..20 {
            let v = rule.integrate(|x| x.powi(d));
            assert!((v - exact(d)).abs() < 1e-15, "degree {d}: {v}");
        }
        // Negative control: degree 2n is not integrated exactly.
        assert!((rule.integrate(|x| x.powi(20)) - exact(20)).abs() > 1e-12);
    }
}
