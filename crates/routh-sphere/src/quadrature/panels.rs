//! Piecewise Chebyshev series of the nutation's integrands `dt/dsigma`, `dpsi/dsigma` and
//! `dphi/dsigma` on `[0, pi]`, bisected adaptively where they vary fast, with their integrals
//! in closed form.
//!
//! The integrands are even and 2 pi-periodic in sigma (they depend on sigma through
//! `u = mid - half cos sigma` only), so `[0, pi]` holds all of one nutation:
//! `F(sigma) = 2 F(pi) - F(2 pi - sigma)` on `(pi, 2 pi)`. Near a separatrix `dt/dsigma`
//! has a complex singularity at a distance `epsilon` from the real axis next to a turning
//! point (`docs/quadrature.md`, section 4): one series over the whole period needs about
//! `1/epsilon` terms, bisection toward the singularity `log2(1/epsilon)` panels of a fixed
//! number of terms each.

use std::f64::consts::PI;
use std::sync::OnceLock;

/// Chebyshev nodes per panel.
pub const PANEL_NODES: usize = 32;
/// The number of integrands: the time, the azimuth psi of gamma in the body frame and the
/// azimuth phi of the symmetry axis in space (see [`crate::quadrature::nutation`]).
pub const INTEGRANDS: usize = 3;
/// The integrands whose convergence decides where a panel is bisected: the time and psi. The
/// third, phi, is carried on their panels (its truncation still counted): its part regular at
/// the poles is `-(psi_reg + omega3 dt/dsigma + sum_p c_p) / u`, made of the first two and of
/// smooth functions of u, so it is resolved where they are; letting it bisect too would move
/// the panels, and the error estimates of the time and psi, of every nutation.
const DECIDING: usize = 2;
/// A panel has converged when its last quarter of coefficients is below this, relative to the
/// largest coefficient (of the panel or of the first panel, whichever is larger), or below the
/// round-off floor of its samples.
const SERIES_TOLERANCE: f64 = 2e-14;
/// Panels narrower than this (in sigma) are not bisected: below it sigma near pi is not
/// resolved by f64 any more.
const MIN_WIDTH: f64 = 1e-13;

/// The values of the integrands at one sigma and their estimated round-off.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// `dt/dsigma`, `dpsi/dsigma` and `dphi/dsigma`.
    pub values: [f64; INTEGRANDS],
    /// Their absolute round-off.
    pub noise: [f64; INTEGRANDS],
}

/// A Chebyshev series `c0/2 + sum_k c_k T_k(x)` on `[-1, 1]` and that of its integral from -1.
#[derive(Debug, Clone, PartialEq)]
struct Chebyshev {
    coef: Vec<f64>,
    integral: Vec<f64>,
}

/// `c0/2 + sum_{k >= 1} c_k T_k(x)` by Clenshaw's recurrence.
fn clenshaw(coef: &[f64], x: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &c in coef.iter().skip(1).rev() {
        (b1, b2) = (c + 2.0 * x * b1 - b2, b1);
    }
    0.5 * coef[0] + x * b1 - b2
}

/// The matrix of the DCT of n samples, row k and column j holding `cos(k (2j + 1) pi / (2n))`
/// taken from the cosines `cos(m pi / (2n))`, `m < 4n`, at `m = k (2j + 1) mod 4n` (exact
/// integer arithmetic, so that no large argument is rounded).
fn dct_matrix(n: usize) -> Vec<f64> {
    let cosines: Vec<f64> = (0..4 * n)
        .map(|m| (m as f64 * PI / (2 * n) as f64).cos())
        .collect();
    (0..n * n)
        .map(|i| cosines[((i / n) * (2 * (i % n) + 1)) % (4 * n)])
        .collect()
}

/// The DCT matrix of `PANEL_NODES` samples and the Chebyshev nodes `cos((j + 1/2) pi / n)`
/// of a panel, computed once per process.
fn panel_tables() -> &'static (Vec<f64>, Vec<f64>) {
    static TABLES: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    TABLES.get_or_init(|| {
        (
            dct_matrix(PANEL_NODES),
            (0..PANEL_NODES)
                .map(|j| ((j as f64 + 0.5) * PI / PANEL_NODES as f64).cos())
                .collect(),
        )
    })
}

impl Chebyshev {
    /// The series interpolating `samples` at `x_j = cos((j + 1/2) pi / n)` (a DCT-II).
    /// `matrix` is [`dct_matrix`] of `samples.len()`.
    fn from_samples(samples: &[f64], matrix: &[f64]) -> Self {
        let n = samples.len();
        let coef: Vec<f64> = matrix
            .chunks_exact(n)
            .map(|row| {
                let sum: f64 = samples.iter().zip(row).map(|(v, c)| v * c).sum();
                2.0 * sum / n as f64
            })
            .collect();
        // `int T_k = T_{k+1} / (2 (k + 1)) - T_{k-1} / (2 (k - 1))`: the integral's
        // coefficients `C_k = (c_{k-1} - c_{k+1}) / (2k)`, C_0 so that it vanishes at -1.
        let at = |k: usize| coef.get(k).copied().unwrap_or(0.0);
        let mut integral: Vec<f64> = (0..=n)
            .map(|k| {
                if k == 0 {
                    0.0
                } else {
                    (at(k - 1) - at(k + 1)) / (2 * k) as f64
                }
            })
            .collect();
        let at_minus_one: f64 = integral
            .iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| if k % 2 == 0 { *c } else { -c })
            .sum();
        integral[0] = -2.0 * at_minus_one;
        Chebyshev { coef, integral }
    }

    /// The largest magnitude of the coefficients.
    fn largest(&self) -> f64 {
        self.coef.iter().fold(0.0_f64, |m, c| m.max(c.abs()))
    }

    /// The largest magnitude of the last quarter of the coefficients: the truncation error.
    fn tail(&self) -> f64 {
        let n = self.coef.len();
        self.coef[3 * n / 4..]
            .iter()
            .fold(0.0_f64, |m, c| m.max(c.abs()))
    }
}

/// One panel `[lo, hi]` of sigma: the series in `x = (sigma - mid) / half_width`, and the
/// integrals of the integrands from 0 to `lo`.
#[derive(Debug, Clone, PartialEq)]
struct Panel {
    lo: f64,
    hi: f64,
    series: [Chebyshev; INTEGRANDS],
    before: [f64; INTEGRANDS],
}

impl Panel {
    fn local(&self, sigma: f64) -> (f64, f64) {
        let half = 0.5 * (self.hi - self.lo);
        (((sigma - self.lo) / half - 1.0).clamp(-1.0, 1.0), half)
    }

    /// The value of integrand `i` and its integral from 0 at `sigma` in the panel.
    fn value_and_integral(&self, i: usize, sigma: f64) -> (f64, f64) {
        let (x, half) = self.local(sigma);
        let s = &self.series[i];
        (
            clenshaw(&s.coef, x),
            self.before[i] + half * clenshaw(&s.integral, x),
        )
    }
}

/// The panels of one half of `[0, pi]` in its own variable x in `[0, pi/2]`: sigma on the
/// left half, `rho = pi - sigma` on the right one, so that both ends 0 and pi, where the
/// near-singularities sit, are represented without the rounding of sigma near pi.
#[derive(Debug, Clone, PartialEq, Default)]
struct Side {
    panels: Vec<Panel>,
    /// The integrals over `[0, pi/2]`.
    total: [f64; INTEGRANDS],
}

impl Side {
    fn panel(&self, x: f64) -> &Panel {
        let k = self.panels.partition_point(|p| p.hi < x);
        &self.panels[k.min(self.panels.len() - 1)]
    }

    fn value_and_integral(&self, i: usize, x: f64) -> (f64, f64) {
        self.panel(x).value_and_integral(i, x)
    }

    /// The x at which the integral of `dt/dsigma` (positive) is `tau`: the panel by bisection
    /// on the integrals, then safeguarded Newton.
    fn invert_time(&self, tau: f64) -> f64 {
        let k = self.panels.partition_point(|p| p.before[0] <= tau);
        let panel = &self.panels[k.saturating_sub(1)];
        let (mut lo, mut hi) = (panel.lo, panel.hi);
        let mut x = 0.5 * (lo + hi);
        for _ in 0..100 {
            let (f, t) = panel.value_and_integral(0, x);
            let r = t - tau;
            if r > 0.0 {
                hi = x;
            } else {
                lo = x;
            }
            let next = x - r / f;
            let next = if next > lo && next < hi {
                next
            } else {
                0.5 * (lo + hi)
            };
            let converged = (next - x).abs() <= 4.0 * f64::EPSILON * PI;
            x = next;
            if converged {
                break;
            }
        }
        x
    }
}

/// The integrands on `[0, pi]`, piecewise, with the error estimates of their integrals.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Piecewise {
    left: Side,
    right: Side,
    /// Estimated truncation error of each half integral `int_0^pi` (the panels' tails times
    /// their widths).
    pub truncation: [f64; INTEGRANDS],
    /// Estimated round-off of each half integral (the samples' round-off times the weights,
    /// independent from sample to sample, so adding in quadrature).
    pub noise: [f64; INTEGRANDS],
    /// Number of samples in the panels kept.
    pub nodes: usize,
}

/// Why the integrands could not be represented.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unresolved {
    /// Whether `dt/dsigma` converged (if so, an angle's integrand did not).
    pub time_converged: bool,
    /// Samples spent.
    pub samples: usize,
    /// The half integral of `dt/dsigma` over the panels kept so far (a lower bound of T/2).
    pub partial_time: f64,
}

/// The state of a build: samples spent, the error sums, the scale of the first panel.
struct Build {
    budget: usize,
    spent: usize,
    truncation: [f64; INTEGRANDS],
    noise2: [f64; INTEGRANDS],
    scale: Option<[f64; INTEGRANDS]>,
    /// The DCT matrix and the Chebyshev nodes ([`panel_tables`]).
    matrix: &'static [f64],
    nodes: &'static [f64],
}

impl Build {
    /// The panels of one side, by bisection from `[0, pi/2]`; `sample(x)` gives the integrands
    /// at the side's variable x. `Ok(Err(_))` when the budget or the resolution of x runs out.
    fn side<E>(
        &mut self,
        mut sample: impl FnMut(f64) -> Result<Sample, E>,
    ) -> Result<std::result::Result<Side, Unresolved>, E> {
        let mut stack = vec![(0.0, 0.5 * PI)];
        let mut panels: Vec<Panel> = vec![];
        while let Some((lo, hi)) = stack.pop() {
            let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
            let mut values: [Vec<f64>; INTEGRANDS] = Default::default();
            let (mut floor, mut square) = ([0.0; INTEGRANDS], [0.0; INTEGRANDS]);
            let xs: Vec<f64> = self.nodes.iter().map(|x| mid + half * x).collect();
            for &x in &xs {
                let s = sample(x)?;
                for i in 0..INTEGRANDS {
                    values[i].push(s.values[i]);
                    floor[i] += s.noise[i];
                    square[i] += s.noise[i] * s.noise[i];
                }
            }
            // x itself is rounded to `eps x`: a sample moves by that times the slope (from the
            // neighbouring sample), which matters in panels narrower than
            // `eps x / SERIES_TOLERANCE` next to a near-singularity.
            for j in 0..PANEL_NODES {
                let k = if j + 1 < PANEL_NODES { j + 1 } else { j - 1 };
                for i in 0..INTEGRANDS {
                    let slope = (values[i][k] - values[i][j]) / (xs[k] - xs[j]);
                    let moved = (slope * f64::EPSILON * xs[j]).abs();
                    floor[i] += moved;
                    square[i] += moved * moved;
                }
            }
            self.spent += PANEL_NODES;
            let series = values
                .each_ref()
                .map(|v| Chebyshev::from_samples(v, self.matrix));
            let global = *self
                .scale
                .get_or_insert(series.each_ref().map(Chebyshev::largest));
            // The coefficients are sums of n samples times 2/n: their noise is at most twice
            // the mean noise of a sample.
            let floor = floor.map(|f| 2.0 * f / PANEL_NODES as f64);
            let converged: [bool; INTEGRANDS] = std::array::from_fn(|i| {
                series[i].tail() <= SERIES_TOLERANCE * series[i].largest().max(global[i]) + floor[i]
            });
            if converged[..DECIDING].iter().all(|&c| c) {
                for i in 0..INTEGRANDS {
                    // The part of the tail above the round-off floor is truncation; the rest
                    // is the samples' round-off, counted (in quadrature) in the noise.
                    self.truncation[i] += 2.0 * half * (series[i].tail() - floor[i]).max(0.0);
                    self.noise2[i] += (2.0 * half / PANEL_NODES as f64).powi(2) * square[i];
                }
                panels.push(Panel {
                    lo,
                    hi,
                    series,
                    before: [0.0; INTEGRANDS],
                });
                continue;
            }
            if hi - lo <= MIN_WIDTH || self.spent + 2 * PANEL_NODES > self.budget {
                return Ok(Err(Unresolved {
                    time_converged: converged[0],
                    samples: self.spent,
                    partial_time: panels
                        .iter()
                        .map(|p| (p.hi - p.lo) * 0.5 * p.series[0].integral_at_one())
                        .sum(),
                }));
            }
            // Right half first: the stack then yields the panels from left to right.
            stack.push((mid, hi));
            stack.push((lo, mid));
        }
        let mut before = [0.0; INTEGRANDS];
        for p in &mut panels {
            p.before = before;
            let half = 0.5 * (p.hi - p.lo);
            for (i, b) in before.iter_mut().enumerate() {
                *b += half * p.series[i].integral_at_one();
            }
        }
        Ok(Ok(Side {
            panels,
            total: before,
        }))
    }
}

impl Piecewise {
    /// Build the panels by bisection of `[0, pi/2]` in sigma and of `[0, pi/2]` in
    /// `rho = pi - sigma`, spending at most `budget` samples; `sample(sigma, rho)` gives the
    /// integrands there (one of the two arguments is exact, the other rounded: sigma on the
    /// left half, rho on the right), or an error, passed on.
    pub fn build<E>(
        budget: usize,
        mut sample: impl FnMut(f64, f64) -> Result<Sample, E>,
    ) -> Result<std::result::Result<Self, Unresolved>, E> {
        let mut build = Build {
            budget,
            spent: 0,
            truncation: [0.0; INTEGRANDS],
            noise2: [0.0; INTEGRANDS],
            scale: None,
            matrix: &panel_tables().0,
            nodes: &panel_tables().1,
        };
        let left = match build.side(|sigma| sample(sigma, PI - sigma))? {
            Ok(side) => side,
            Err(e) => return Ok(Err(e)),
        };
        let right = match build.side(|rho| sample(PI - rho, rho))? {
            Ok(side) => side,
            Err(mut e) => {
                e.partial_time += left.total[0];
                return Ok(Err(e));
            }
        };
        let nodes = (left.panels.len() + right.panels.len()) * PANEL_NODES;
        Ok(Ok(Piecewise {
            left,
            right,
            truncation: build.truncation,
            noise: build.noise2.map(f64::sqrt),
            nodes,
        }))
    }

    /// `int_0^pi` of integrand `i`.
    fn half_integral(&self, i: usize) -> f64 {
        self.left.total[i] + self.right.total[i]
    }

    /// The integral of integrand `i` over one period `[0, 2 pi]`.
    pub fn full_integral(&self, i: usize) -> f64 {
        2.0 * self.half_integral(i)
    }

    /// The value of integrand `i` and its integral from 0 at `sigma` in `[0, pi]`.
    fn on_half(&self, i: usize, sigma: f64) -> (f64, f64) {
        if sigma <= 0.5 * PI {
            self.left.value_and_integral(i, sigma)
        } else {
            let (v, int) = self.right.value_and_integral(i, PI - sigma);
            (v, self.half_integral(i) - int)
        }
    }

    /// The value of integrand `i` and its integral from 0 at `sigma` in `[0, 2 pi]`.
    pub fn value_and_integral(&self, i: usize, sigma: f64) -> (f64, f64) {
        if sigma <= PI {
            self.on_half(i, sigma)
        } else {
            let (v, int) = self.on_half(i, 2.0 * PI - sigma);
            (v, self.full_integral(i) - int)
        }
    }

    /// The sigma in `[0, 2 pi]` at which the integral of `dt/dsigma` (positive) is `tau`, for
    /// `tau` in `[0, T]`.
    pub fn invert_time(&self, tau: f64) -> f64 {
        let half_period = self.half_integral(0);
        if tau > half_period {
            return 2.0 * PI - self.invert_time((2.0 * half_period - tau).max(0.0));
        }
        if tau <= self.left.total[0] {
            self.left.invert_time(tau)
        } else {
            PI - self.right.invert_time((half_period - tau).max(0.0))
        }
    }
}

impl Chebyshev {
    /// The integral over `[-1, 1]` (the integral series at 1).
    fn integral_at_one(&self) -> f64 {
        clenshaw(&self.integral, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smooth_integrand_needs_few_panels_and_integrates_exactly() {
        // f = 1 / (2 - cos sigma): int_0^{2 pi} = 2 pi / sqrt(3).
        let p = Piecewise::build(10_000, |s: f64, _| {
            Ok::<_, ()>(Sample {
                values: [1.0 / (2.0 - s.cos()), s.cos(), s.sin().powi(2)],
                noise: [0.0; INTEGRANDS],
            })
        })
        .unwrap()
        .unwrap();
        assert!(p.nodes <= 2 * PANEL_NODES, "{} nodes", p.nodes);
        let exact = 2.0 * PI / 3f64.sqrt();
        assert!((p.full_integral(0) - exact).abs() < 1e-14);
        assert!(p.full_integral(1).abs() < 1e-14);
        assert!((p.full_integral(2) - PI).abs() < 1e-14);
        // The integral at a point (closed form 2/sqrt 3 atan(sqrt 3 tan(s/2))) and its inverse.
        for s in [0.3, 2.0, 4.0, 6.0] {
            let (_, int) = p.value_and_integral(0, s);
            let mut closed = 2.0 / 3f64.sqrt() * (3f64.sqrt() * (0.5 * s).tan()).atan();
            if s > PI {
                closed += exact;
            }
            assert!((int - closed).abs() < 1e-14, "{s}: {int} {closed}");
            assert!((p.invert_time(int) - s).abs() < 1e-13);
        }
    }

    #[test]
    fn near_singular_integrand_is_resolved_by_bisection_in_few_samples() {
        // f = 1 / sqrt(eps^2 + (sigma - pi)^2) near a separatrix (eps = 1e-8): a single
        // series would need about 1e9 terms; the integral over [0, pi] is asinh(pi / eps).
        let eps = 1e-8;
        let p = Piecewise::build(10_000, |_, d: f64| {
            Ok::<_, ()>(Sample {
                values: [1.0 / (eps * eps + d * d).sqrt(), 1.0, 1.0],
                noise: [0.0; INTEGRANDS],
            })
        })
        .unwrap()
        .unwrap();
        let exact = (PI / eps).asinh();
        assert!(
            (0.5 * p.full_integral(0) - exact).abs() < 1e-12 * exact,
            "{} {exact}",
            0.5 * p.full_integral(0)
        );
        assert!(p.nodes < 3000, "{} nodes", p.nodes);
        // Negative control: a budget of one panel is not enough.
        let r = Piecewise::build(PANEL_NODES, |_, d: f64| {
            Ok::<_, ()>(Sample {
                values: [1.0 / (eps * eps + d * d).sqrt(), 1.0, 1.0],
                noise: [0.0; INTEGRANDS],
            })
        })
        .unwrap();
        assert!(r.is_err());
    }
}
