//! Gauss-Legendre quadrature on [0, 1]: nodes and weights by Newton's method on the Legendre
//! polynomial P_n (three-term recurrence), from Chebyshev-like initial guesses.

use std::f64::consts::PI;

/// An n-point Gauss-Legendre rule on [0, 1], exact for polynomials of degree 2n - 1.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussLegendre {
    /// Nodes in (0, 1).
    pub nodes: Vec<f64>,
    /// Weights, summing to 1.
    pub weights: Vec<f64>,
}

impl GaussLegendre {
    /// The n-point rule (n >= 1).
    pub fn new(n: usize) -> Self {
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
