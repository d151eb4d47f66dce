//! Divided differences of a formula at three points, by the Leibniz rule: a formula written
//! over [`Scalar`] evaluated on [`DividedDifferences`] gives its values `f(x0), f(x1), f(x2)`,
//! its first divided differences `f[x0, x1], f[x1, x2]` and its second `f[x0, x1, x2]`, each
//! built from those of the operands without subtracting two values of f: so with the
//! round-off of the terms' own slopes and curvatures, however close the points (at equal
//! points they are the derivatives, `f[x, x] = f'(x)`, `f[x, x, x] = f''(x) / 2`). The
//! quadrature takes the cofactor `P = -Q[u1, u, u2]` and the mean slope `Q[x_end, x]` of the
//! nutation from them ([`crate::quadrature::nutation`]), one evaluation of Q each, where the
//! Gauss-Legendre rules of Q' and Q'' took 24 and 64.
//!
//! The values are those of the formula on `f64`, bit for bit. The rules, with `h = 1 / g`,
//! `q = f / g` and `s = sqrt(g)` (`(f g)[x0..xn] = sum_i f[x0..xi] g[xi..xn]`, and the
//! identities `g h = 1`, `q g = f`, `s s = g` solved for the differences of h, q and s):
//!
//! ```text
//! (f g)[x0, x1]     = f[x0, x1] g(x1) + f(x0) g[x0, x1],
//! (f g)[x0, x1, x2] = f[x0, x1, x2] g(x2) + f[x0, x1] g[x1, x2] + f(x0) g[x0, x1, x2],
//! h[x0, x1]         = -g[x0, x1] h(x0) h(x1),
//! h[x0, x1, x2]     = -(g[x0, x1] h[x1, x2] + g[x0, x1, x2] h(x2)) h(x0),
//! q[x0, x1]         = (f[x0, x1] - q(x0) g[x0, x1]) / g(x1),                    q = f / g,
//! q[x0, x1, x2]     = (f[x0, x1, x2] - q(x0) g[x0, x1, x2] - q[x0, x1] g[x1, x2]) / g(x2),
//! s[x0, x1]         = g[x0, x1] / (s(x0) + s(x1)),
//! s[x0, x1, x2]     = (g[x0, x1, x2] - s[x0, x1] s[x1, x2]) / (s(x0) + s(x2)).
//! ```

use crate::scalar::Scalar;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The values of a function at three points `x0, x1, x2` and its divided differences there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DividedDifferences {
    /// `f(x0), f(x1), f(x2)`.
    pub values: [f64; 3],
    /// `f[x0, x1], f[x1, x2]`.
    pub first: [f64; 2],
    /// `f[x0, x1, x2]`.
    pub second: f64,
}

impl DividedDifferences {
    /// The variable x itself at `points`: `x[x0, x1] = 1`, `x[x0, x1, x2] = 0`.
    pub fn variable(points: [f64; 3]) -> Self {
        DividedDifferences {
            values: points,
            first: [1.0, 1.0],
            second: 0.0,
        }
    }

    /// The magnitude of each part: with those of the other terms of a sum, the round-off
    /// scale of the sum's parts.
    pub fn magnitudes(self) -> Self {
        self.map(f64::abs)
    }

    /// Each part mapped by `f` (a linear map: a sum with another's part, a scaling).
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        DividedDifferences {
            values: self.values.map(&f),
            first: self.first.map(&f),
            second: f(self.second),
        }
    }

    /// Each part combined with the same part of `other` by `f` (a sum or a difference).
    fn zip(self, other: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        DividedDifferences {
            values: std::array::from_fn(|i| f(self.values[i], other.values[i])),
            first: std::array::from_fn(|i| f(self.first[i], other.first[i])),
            second: f(self.second, other.second),
        }
    }
}

impl Add for DividedDifferences {
    type Output = Self;
    #[inline(always)]
    fn add(self, other: Self) -> Self {
        self.zip(other, |a, b| a + b)
    }
}

impl Sub for DividedDifferences {
    type Output = Self;
    #[inline(always)]
    fn sub(self, other: Self) -> Self {
        self.zip(other, |a, b| a - b)
    }
}

impl Neg for DividedDifferences {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|a| -a)
    }
}

impl Mul for DividedDifferences {
    type Output = Self;
    /// The Leibniz rule (module docs).
    #[inline(always)]
    fn mul(self, g: Self) -> Self {
        let (f, [g0, g1, g2]) = (self, g.values);
        DividedDifferences {
            values: [f.values[0] * g0, f.values[1] * g1, f.values[2] * g2],
            first: [
                f.first[0] * g1 + f.values[0] * g.first[0],
                f.first[1] * g2 + f.values[1] * g.first[1],
            ],
            second: f.second * g2 + f.first[0] * g.first[1] + f.values[0] * g.second,
        }
    }
}

impl Div for DividedDifferences {
    type Output = Self;
    /// `q = f / g` from the Leibniz rule for `f = q g` (module docs), solved for the
    /// differences of q.
    #[inline(always)]
    fn div(self, g: Self) -> Self {
        let f = self;
        let values: [f64; 3] = std::array::from_fn(|i| f.values[i] / g.values[i]);
        let first = [
            (f.first[0] - values[0] * g.first[0]) / g.values[1],
            (f.first[1] - values[1] * g.first[1]) / g.values[2],
        ];
        DividedDifferences {
            values,
            first,
            second: (f.second - values[0] * g.second - first[0] * g.first[1]) / g.values[2],
        }
    }
}

impl Add<f64> for DividedDifferences {
    type Output = Self;
    #[inline(always)]
    fn add(mut self, c: f64) -> Self {
        self.values = self.values.map(|v| v + c);
        self
    }
}

impl Sub<f64> for DividedDifferences {
    type Output = Self;
    #[inline(always)]
    fn sub(self, c: f64) -> Self {
        self + -c
    }
}

impl Mul<f64> for DividedDifferences {
    type Output = Self;
    #[inline(always)]
    fn mul(self, c: f64) -> Self {
        self.map(|a| a * c)
    }
}

impl Div<f64> for DividedDifferences {
    type Output = Self;
    #[inline(always)]
    fn div(self, c: f64) -> Self {
        self.map(|a| a / c)
    }
}

impl Scalar for DividedDifferences {
    #[inline(always)]
    fn from_f64(c: f64) -> Self {
        DividedDifferences {
            values: [c; 3],
            first: [0.0; 2],
            second: 0.0,
        }
    }

    /// `s = sqrt(g)` (module docs).
    #[inline(always)]
    fn sqrt(self) -> Self {
        let [s0, s1, s2] = self.values.map(f64::sqrt);
        let first = [self.first[0] / (s0 + s1), self.first[1] / (s1 + s2)];
        DividedDifferences {
            values: [s0, s1, s2],
            first,
            second: (self.second - first[0] * first[1]) / (s0 + s2),
        }
    }

    /// `h = 1 / g` (module docs).
    #[inline(always)]
    fn recip(self) -> Self {
        let [h0, h1, h2] = self.values.map(f64::recip);
        let first = [-self.first[0] * h0 * h1, -self.first[1] * h1 * h2];
        DividedDifferences {
            values: [h0, h1, h2],
            first,
            second: -(self.first[0] * first[1] + self.second * h2) * h0,
        }
    }

    /// Not fused: the parts are sums of products.
    #[inline(always)]
    fn mul_add(self, a: Self, b: Self) -> Self {
        self * a + b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The divided differences of f at `points` from its values (distinct points).
    fn by_definition(f: impl Fn(f64) -> f64, [x0, x1, x2]: [f64; 3]) -> (f64, f64) {
        let (f0, f1, f2) = (f(x0), f(x1), f(x2));
        let (d01, d12) = ((f1 - f0) / (x1 - x0), (f2 - f1) / (x2 - x1));
        (d01, (d12 - d01) / (x2 - x0))
    }

    #[test]
    fn the_rules_give_the_divided_differences_of_the_formula() {
        // f = sqrt(1 + x^2) / (2 + x) - 3 x at well separated points: the rules against the
        // definition, which loses only a few ulps there (tolerance 1e-13 of the sizes, 1).
        fn f<D: Scalar>(x: D) -> D {
            (x * x + 1.0).sqrt() / (x + 2.0) - x * 3.0
        }
        let points = [0.1, 0.7, 1.6];
        let dd = f(DividedDifferences::variable(points));
        let (first, second) = by_definition(f::<f64>, points);
        for (i, &x) in points.iter().enumerate() {
            assert_eq!(dd.values[i], f(x));
        }
        assert!((dd.first[0] - first).abs() < 1e-13, "{dd:?} {first}");
        assert!((dd.second - second).abs() < 1e-13, "{dd:?} {second}");
        // Equal points give the derivatives: f = 1 / sqrt(x), f' = -x^(-3/2) / 2,
        // f''/2 = 3/8 x^(-5/2) (to a few ulps).
        let at = DividedDifferences::variable([4.0; 3]).sqrt().recip();
        assert!((at.first[0] + 1.0 / 16.0).abs() < 1e-16, "{at:?}");
        assert!((at.second - 3.0 / 256.0).abs() < 1e-16, "{at:?}");
        // Negative control: the second difference of another function differs.
        let other = by_definition(|x| f(x) + 1e-6 * x * x, points).1;
        assert!((dd.second - other).abs() > 1e-7);
    }

    #[test]
    fn close_points_keep_their_digits_where_the_definition_loses_them() {
        // f = 1 / (1 + x) at 1, 1 + 1e-9, 1 + 2e-9: f[x0, x1, x2] = 1 / ((1 + x0)(1 + x1)(1 + x2))
        // exactly; the rules give it to 1e-15 relative, the definition to no digit at all.
        let points = [1.0, 1.0 + 1e-9, 1.0 + 2e-9];
        let dd = (DividedDifferences::variable(points) + 1.0).recip();
        let exact = 1.0 / points.iter().map(|x| 1.0 + x).product::<f64>();
        assert!(
            (dd.second / exact - 1.0).abs() < 1e-15,
            "{} {exact}",
            dd.second
        );
        let (_, defined) = by_definition(|x| 1.0 / (1.0 + x), points);
        assert!((defined / exact - 1.0).abs() > 1e-3, "{defined} {exact}");
    }
}
