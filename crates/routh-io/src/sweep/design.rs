//! Designs of experiments: the point of run number k, computed from k alone (so a sweep can
//! be split into chunks, resumed, or spread over machines without changing any run).
//!
//! * the grid: the Cartesian product of the axes, the last axis varying fastest;
//! * Sobol's sequence in base 2 with the direction numbers of S. Joe and F. Y. Kuo,
//!   "Constructing Sobol sequences with better two-dimensional projections", SIAM J. Sci.
//!   Comput. 30 (2008) 2635–2654 (file `new-joe-kuo-6.21201`, its first 15 dimensions),
//!   optionally digitally shifted (XOR with random bits drawn from the seed), which keeps its
//!   net properties;
//! * a Latin hypercube: per axis, a random permutation of the `samples` strata;
//! * independent uniform points.

use super::spec::{refuse, Plan, Points, RandomDesign, Spec};
use crate::sampling::SplitMix64;

/// Bits of the Sobol points (the points are multiples of 2^-BITS).
const BITS: u32 = 32;

/// The Joe–Kuo parameters of dimensions 2 to 15: degree s, coefficients a, initial m_i.
/// Dimension 1 is the van der Corput sequence (all m_i = 1).
const JOE_KUO: [(u32, u32, &[u32]); 14] = [
    (1, 0, &[1]),
    (2, 1, &[1, 3]),
    (3, 1, &[1, 3, 1]),
    (3, 2, &[1, 1, 1]),
    (4, 1, &[1, 1, 3, 3]),
    (4, 4, &[1, 3, 5, 13]),
    (5, 2, &[1, 1, 5, 5, 17]),
    (5, 4, &[1, 1, 5, 5, 5]),
    (5, 7, &[1, 1, 7, 11, 19]),
    (5, 11, &[1, 1, 5, 1, 1]),
    (5, 13, &[1, 1, 1, 3, 11]),
    (5, 14, &[1, 3, 5, 5, 31]),
    (6, 1, &[1, 3, 3, 9, 7, 49]),
    (6, 13, &[1, 1, 1, 15, 21, 21]),
];

/// The largest number of axes of a Sobol design.
pub const SOBOL_MAX_DIMENSION: usize = JOE_KUO.len() + 1;

/// The direction numbers V_1..V_BITS (scaled by 2^BITS) of one Sobol dimension (`dim` from
/// 0), by the recurrence of Bratley and Fox (ACM TOMS 14, 1988, algorithm 659).
fn directions(dim: usize) -> [u32; BITS as usize] {
    let mut v = [0u32; BITS as usize];
    if dim == 0 {
        for (i, vi) in v.iter_mut().enumerate() {
            *vi = 1 << (BITS - 1 - i as u32);
        }
        return v;
    }
    let (s, a, m) = JOE_KUO[dim - 1];
    let s = s as usize;
    for i in 0..s.min(BITS as usize) {
        v[i] = m[i] << (BITS - 1 - i as u32);
    }
    for i in s..BITS as usize {
        let mut x = v[i - s] ^ (v[i - s] >> s);
        for k in 1..s {
            if (a >> (s - 1 - k)) & 1 == 1 {
                x ^= v[i - k];
            }
        }
        v[i] = x;
    }
    v
}

/// The k-th point of the Sobol sequence of one dimension with directions `v`, as an
/// integer multiple of 2^-BITS: the XOR of the V_b over the set bits b of the Gray code of k.
fn sobol_bits(v: &[u32; BITS as usize], k: u64) -> u32 {
    let gray = k ^ (k >> 1);
    (0..BITS)
        .filter(|b| (gray >> b) & 1 == 1)
        .fold(0u32, |x, b| x ^ v[b as usize])
}

/// The points of a sweep, by run number.
#[derive(Debug, Clone)]
pub struct Design {
    spec: Spec,
    sobol: Vec<[u32; BITS as usize]>,
    shift: Vec<u32>,
    strata: Vec<Vec<u32>>,
}

/// A generator for run `k` of a design with `seed`, independent of the other runs.
fn stream(seed: u64, k: u64, axis: usize) -> SplitMix64 {
    let mut mix = SplitMix64::new(seed ^ 0x5EED_0000_0000_0000);
    let a = mix.next_u64();
    SplitMix64::new(a ^ k.wrapping_mul(0xD1B5_4A32_D192_ED03) ^ ((axis as u64) << 56))
}

impl Design {
    /// The design of a checked `[sweep]` table. Refuses a Sobol design of more than
    /// [`SOBOL_MAX_DIMENSION`] axes and a Latin hypercube of more than 2^32 samples.
    pub fn new(spec: Spec) -> super::spec::Result<Self> {
        let dims = spec.axes.len();
        let mut design = Design {
            spec,
            sobol: Vec::new(),
            shift: Vec::new(),
            strata: Vec::new(),
        };
        if let Plan::Random {
            design: kind,
            samples,
            seed,
        } = design.spec.plan
        {
            match kind {
                RandomDesign::Sobol => {
                    if dims > SOBOL_MAX_DIMENSION {
                        return Err(refuse(
                            "design",
                            "\"sobol\"",
                            &format!(
                                "at most {SOBOL_MAX_DIMENSION} quantities (Joe–Kuo direction \
                                 numbers kept here), not {dims}"
                            ),
                        ));
                    }
                    design.sobol = (0..dims).map(directions).collect();
                    let mut rng = SplitMix64::new(seed);
                    design.shift = (0..dims)
                        .map(|_| {
                            if seed == 0 {
                                0
                            } else {
                                (rng.next_u64() >> 32) as u32
                            }
                        })
                        .collect();
                }
                RandomDesign::Latin => {
                    if samples > u32::MAX as u64 {
                        return Err(refuse(
                            "samples",
                            samples,
                            "a Latin hypercube takes at most 2^32 - 1 samples",
                        ));
                    }
                    design.strata = (0..dims)
                        .map(|axis| {
                            let mut perm: Vec<u32> = (0..samples as u32).collect();
                            let mut rng = stream(seed, u64::MAX, axis);
                            for i in (1..perm.len()).rev() {
                                let j = (rng.next_u64() % (i as u64 + 1)) as usize;
                                perm.swap(i, j);
                            }
                            perm
                        })
                        .collect();
                }
                RandomDesign::Uniform => {}
            }
        }
        Ok(design)
    }

    /// The checked table.
    pub fn spec(&self) -> &Spec {
        &self.spec
    }

    /// The number of runs.
    pub fn runs(&self) -> u64 {
        self.spec.runs()
    }

    /// The unit-cube coordinates of run `k` of a random design, one per axis, in [0, 1).
    fn unit_point(&self, k: u64, design: RandomDesign, samples: u64, seed: u64) -> Vec<f64> {
        let dims = self.spec.axes.len();
        match design {
            RandomDesign::Sobol => (0..dims)
                .map(|d| {
                    (sobol_bits(&self.sobol[d], k) ^ self.shift[d]) as f64 / 2f64.powi(BITS as i32)
                })
                .collect(),
            RandomDesign::Latin => (0..dims)
                .map(|d| {
                    let u = stream(seed, k, d).uniform(0.0, 1.0);
                    (self.strata[d][k as usize] as f64 + u) / samples as f64
                })
                .collect(),
            RandomDesign::Uniform => (0..dims)
                .map(|d| stream(seed, k, d).uniform(0.0, 1.0))
                .collect(),
        }
    }

    /// The values of the swept quantities for run `k` (0 <= k < runs), in the order of the
    /// axes.
    pub fn point(&self, k: u64) -> Vec<f64> {
        match self.spec.plan {
            Plan::Grid => {
                let mut rest = k;
                let mut values = vec![0.0; self.spec.axes.len()];
                for (slot, axis) in values.iter_mut().zip(&self.spec.axes).rev() {
                    if let Points::Values(v) = &axis.points {
                        let len = v.len() as u64;
                        *slot = v[(rest % len) as usize];
                        rest /= len;
                    }
                }
                values
            }
            Plan::Random {
                design,
                samples,
                seed,
            } => self
                .unit_point(k, design, samples, seed)
                .into_iter()
                .zip(&self.spec.axes)
                .map(|(u, axis)| match axis.points {
                    Points::Range { lo, hi, scale } => scale.at(lo, hi, u),
                    Points::Values(_) => unreachable!("a random design has ranges only"),
                })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn design(text: &str) -> Design {
        let table: toml::Table = text.parse().unwrap();
        Design::new(Spec::parse(&table).unwrap()).unwrap()
    }

    /// The first points of the two-dimensional Sobol sequence, known by hand from the
    /// direction numbers V = 1/2, 1/4, ... (dimension 1) and 1/2, 3/4, ... (dimension 2).
    #[test]
    fn sobol_starts_with_the_textbook_points() {
        let d = design(
            "samples = 8\ndesign = \"sobol\"\ngamma1 = { range = [0.0, 1.0] }\ngamma2 = { range = [0.0, 1.0] }",
        );
        let pts: Vec<Vec<f64>> = (0..4).map(|k| d.point(k)).collect();
        assert_eq!(
            pts,
            vec![
                vec![0.0, 0.0],
                vec![0.5, 0.5],
                vec![0.75, 0.25],
                vec![0.25, 0.75]
            ]
        );
    }

    /// Each dimension of Sobol's sequence is a (0, m, 1)-net in base 2: the first 2^m points
    /// put exactly one point in each interval [j/2^m, (j+1)/2^m). A wrong direction number
    /// breaks it (negative control: V_2 = V_1 repeats points among the first four).
    #[test]
    fn each_sobol_dimension_stratifies_dyadic_intervals() {
        let m = 10;
        for dim in 0..SOBOL_MAX_DIMENSION {
            let v = directions(dim);
            let mut seen = vec![false; 1 << m];
            for k in 0u64..(1 << m) {
                let x = sobol_bits(&v, k);
                let cell = (x >> (BITS - m)) as usize;
                assert!(!seen[cell], "dimension {dim}: cell {cell} twice");
                seen[cell] = true;
            }
        }
        let mut bad = directions(1);
        bad[1] = bad[0];
        let cells: std::collections::HashSet<u32> = (0u64..4)
            .map(|k| sobol_bits(&bad, k) >> (BITS - 2))
            .collect();
        assert!(cells.len() < 4, "the broken directions still stratify");
    }

    /// The two-dimensional projections of pairs of dimensions put one point in each
    /// elementary box of a (t, m, 2)-net: with t = 0 for dimensions 1 and 2 (a classical
    /// fact of Sobol's construction), every box [i/2^a, (i+1)/2^a) x [j/2^b, (j+1)/2^b)
    /// with a + b = m holds exactly one of the first 2^m points.
    #[test]
    fn the_first_two_sobol_dimensions_form_a_zero_m_two_net() {
        let m = 8u32;
        let d = design(
            "samples = 256\ngamma1 = { range = [0.0, 1.0] }\ngamma2 = { range = [0.0, 1.0] }",
        );
        let pts: Vec<Vec<f64>> = (0..1u64 << m).map(|k| d.point(k)).collect();
        for a in 0..=m {
            let b = m - a;
            let mut count = vec![0u32; 1 << m];
            for p in &pts {
                let i = (p[0] * (1u64 << a) as f64) as usize;
                let j = (p[1] * (1u64 << b) as f64) as usize;
                count[(i << b) | j] += 1;
            }
            assert!(count.iter().all(|&c| c == 1), "boxes 2^-{a} x 2^-{b}");
        }
    }

    #[test]
    fn latin_puts_one_point_in_each_stratum_of_each_axis() {
        let n = 500;
        let d = design(&format!(
            "samples = {n}\ndesign = \"latin\"\nseed = 3\ntilt = {{ range = [0.0, 2.0] }}\nspin = {{ range = [-1.0, 1.0] }}"
        ));
        // Axes sorted by key: spin, then tilt.
        for (axis, (lo, hi)) in [(-1.0, 1.0), (0.0, 2.0)].into_iter().enumerate() {
            let mut seen = vec![0; n];
            for k in 0..n as u64 {
                let x = d.point(k)[axis];
                assert!(x >= lo && x < hi);
                seen[((x - lo) / (hi - lo) * n as f64) as usize] += 1;
            }
            assert!(seen.iter().all(|&c| c == 1), "axis {axis}");
        }
        // Negative control: uniform points of the same size leave strata empty.
        let u = design(&format!(
            "samples = {n}\ndesign = \"uniform\"\nseed = 3\ntilt = {{ range = [0.0, 2.0] }}"
        ));
        let mut seen = vec![0; n];
        for k in 0..n as u64 {
            seen[(u.point(k)[0] / 2.0 * n as f64) as usize] += 1;
        }
        assert!(seen.contains(&0));
    }

    /// Uniform points: the mean and variance of 20,000 points of [0, 1) within 5 standard
    /// errors of 1/2 and 1/12; a different seed gives different points.
    #[test]
    fn uniform_points_have_the_moments_of_the_uniform_law() {
        let n = 20_000;
        let d = design(&format!(
            "samples = {n}\ndesign = \"uniform\"\nseed = 11\ntilt = {{ range = [0.0, 1.0] }}"
        ));
        let xs: Vec<f64> = (0..n).map(|k| d.point(k)[0]).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64;
        assert!(
            (mean - 0.5).abs() < 5.0 * (1.0 / 12.0 / n as f64).sqrt(),
            "{mean}"
        );
        assert!(
            (var - 1.0 / 12.0).abs() < 5.0 * (1.0 / 180.0 / n as f64).sqrt(),
            "{var}"
        );
        let e = design(&format!(
            "samples = {n}\ndesign = \"uniform\"\nseed = 12\ntilt = {{ range = [0.0, 1.0] }}"
        ));
        assert_ne!(d.point(0), e.point(0));
    }

    #[test]
    fn the_grid_is_the_cartesian_product_with_the_last_axis_fastest() {
        let d = design("tilt = { range = [0.05, 1.5], n = 50 }\nspin = { values = [4.0, 8.0] }\n\"body.a\" = { values = [0.3] }");
        assert_eq!(d.runs(), 100);
        // Axes sorted by key: body.a, spin, tilt.
        assert_eq!(d.point(0), vec![0.3, 4.0, 0.05]);
        assert_eq!(d.point(49), vec![0.3, 4.0, 1.5]);
        assert_eq!(d.point(50), vec![0.3, 8.0, 0.05]);
        let mut all: Vec<Vec<f64>> = (0..100).map(|k| d.point(k)).collect();
        all.sort_by(|a, b| a.partial_cmp(b).unwrap());
        all.dedup();
        assert_eq!(all.len(), 100);
    }

    #[test]
    fn a_log_range_has_equal_ratios() {
        let d = design("\"body.G\" = { range = [0.1, 1000.0], n = 5, scale = \"log\" }");
        let g: Vec<f64> = (0..5).map(|k| d.point(k)[0]).collect();
        for (x, e) in g.iter().zip([0.1, 1.0, 10.0, 100.0, 1000.0]) {
            assert!((x / e - 1.0).abs() < 4.0 * f64::EPSILON, "{x} vs {e}");
        }
    }
}
