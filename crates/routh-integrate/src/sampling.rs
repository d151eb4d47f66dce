//! Reproducible random points of the phase space, for checks at many points (the tests and
//! the claims audit). A SplitMix64 generator: tiny, seedable, and the same on every machine.

/// The SplitMix64 pseudo-random generator (Steele, Lea, Flood 2014).
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator started from `seed`.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform number in [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }

    /// A point of the phase space: gamma uniform on the unit sphere, with
    /// `min_horizontal <= gamma1^2 + gamma2^2` and `|gamma3| >= min_vertical` (to keep away from
    /// the singular sets of formulas with `1/(gamma1^2 + gamma2^2)` or `1/gamma3`), and each
    /// component of M uniform in [-scale, scale].
    pub fn phase_point(&mut self, scale: f64, min_horizontal: f64, min_vertical: f64) -> [f64; 6] {
        loop {
            let z = self.uniform(-1.0, 1.0);
            let phi = self.uniform(0.0, std::f64::consts::TAU);
            let s = (1.0 - z * z).sqrt();
            if s * s < min_horizontal || z.abs() < min_vertical {
                continue;
            }
            return [
                s * phi.cos(),
                s * phi.sin(),
                z,
                self.uniform(-scale, scale),
                self.uniform(-scale, scale),
                self.uniform(-scale, scale),
            ];
        }
    }
}
