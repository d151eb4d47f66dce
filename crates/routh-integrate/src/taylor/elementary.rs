//! The natural logarithm and exponential of the Taylor step size ([`super::taylor_step`]) in
//! plain arithmetic on the bits of a double: no call into the C library and no branch (the
//! special values are chosen by selects), so that the step sizes of the lanes of a batch are
//! computed side by side in vector registers, and one lane gives the same bits as the
//! one-at-a-time integrator. (The library's `pow`, one call per lane and root, took 5 to 8 %
//! of a run in 8 lanes: BENCHMARKS.md, "Sweeps".) Both are within a few units in the last
//! place of the library's `ln` and `exp` (the tests below; the step size needs far less).

/// `ln 2` in two parts (fdlibm's split): `LN_2_HI` has 32 significant bits, so that `n LN_2_HI`
/// is exact for the exponents `|n| < 2^21` met here, and `LN_2_HI + LN_2_LO` is `ln 2` to
/// about 1e-26 (`0.693147180369123816490` and `1.90821492927058770002e-10`).
const LN_2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
const LN_2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);

/// `1.5 * 2^52`: `x + ROUND - ROUND` is `x` rounded to an integer (to even) for `|x| < 2^51`,
/// and the low bits of `x + ROUND` hold that integer.
const ROUND: f64 = 6_755_399_441_055_744.0;

/// `2^54`, which lifts a subnormal to a normal double.
const TWO_54: f64 = 18_014_398_509_481_984.0;

/// `2^m` for an integer `m` (as a double) with `-1022 <= m <= 1023`: the exponent field
/// `m + 1023` in the low bits of `m + 1023 + 2^52`, shifted into place.
#[inline(always)]
pub(crate) fn two_to(m: f64) -> f64 {
    f64::from_bits((m + (1023.0 + 4_503_599_627_370_496.0)).to_bits() << 52)
}

/// `ln x`: `-inf` at 0, `inf` at `inf`, NaN below 0 and at NaN.
///
/// `x = 2^e m` with `m` in `[sqrt(2)/2, sqrt(2))` (a subnormal `x` scaled by `2^54` first),
/// `ln m = 2 atanh(s)`, `s = (m - 1) / (m + 1)`, `|s| <= 0.172`, by its series to `s^23`
/// (the next term is below `2^-60` of the sum), and `ln x = e ln 2 + ln m`.
#[inline(always)]
pub fn ln(x: f64) -> f64 {
    let tiny = x < f64::MIN_POSITIVE;
    let bits = (if tiny { x * TWO_54 } else { x }).to_bits();
    // The biased exponent as a double: its 11 bits in the low bits of 2^52.
    let biased =
        f64::from_bits(0x4330_0000_0000_0000 | ((bits >> 52) & 0x7ff)) - 4_503_599_627_370_496.0;
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    let big = m > std::f64::consts::SQRT_2;
    let m = if big { 0.5 * m } else { m };
    let e = biased - if tiny { 1023.0 + 54.0 } else { 1023.0 } + if big { 1.0 } else { 0.0 };
    let f = m - 1.0;
    let s = f / (2.0 + f);
    let z = s * s;
    let series = [23.0, 21.0, 19.0, 17.0, 15.0, 13.0, 11.0, 9.0, 7.0, 5.0, 3.0]
        .iter()
        .fold(0.0, |acc, &d| (acc + 1.0 / d) * z);
    let ln_m = 2.0 * s + 2.0 * s * series;
    let value = e * LN_2_HI + (e * LN_2_LO + ln_m);
    if x == 0.0 {
        f64::NEG_INFINITY
    } else if x == f64::INFINITY {
        f64::INFINITY
    } else if x > 0.0 {
        value
    } else {
        f64::NAN
    }
}

/// The coefficients `1 / k!` of the series of [`exp`], `k = 0 ..= 14` (each the one before
/// divided by `k`, rounded: within `k` ulp of `1 / k!`, far below what the terms `r^k / k!`
/// they multiply can show).
const INVERSE_FACTORIALS: [f64; 15] = {
    let mut c = [1.0; 15];
    let mut k = 1;
    while k < 15 {
        c[k] = c[k - 1] / k as f64;
        k += 1;
    }
    c
};

/// `e^y`: `inf` above about 709.78, 0 below about -745.13 (subnormal between), NaN at NaN.
///
/// `y = n ln 2 + r`, `n` the integer nearest `y / ln 2`, `|r| <= 0.347`, `e^r` by its series to
/// `r^14 / 14!` (below `2^-57` of the sum) in Horner's form with the coefficients
/// [`INVERSE_FACTORIALS`] (a chain of multiplications and additions: nested divisions by `k`,
/// before, were the longest latency of the step of the Taylor lanes), times `2^n` in two
/// factors (so that neither leaves the range of the exponent; the product overflows or
/// underflows as it should).
#[inline(always)]
pub fn exp(y: f64) -> f64 {
    let y = y.clamp(-1100.0, 1100.0);
    let n = (y * std::f64::consts::LOG2_E + ROUND) - ROUND;
    let r = (y - n * LN_2_HI) - n * LN_2_LO;
    let series = INVERSE_FACTORIALS[..14]
        .iter()
        .rev()
        .fold(INVERSE_FACTORIALS[14], |acc, &c| acc * r + c);
    let half = (0.5 * n + ROUND) - ROUND;
    series * two_to(half) * two_to(n - half)
}

#[cfg(test)]
mod tests {
    use super::{exp, ln};
    use proptest::prelude::*;

    /// Units in the last place between `a` and `b`, both finite.
    fn ulps(a: f64, b: f64) -> f64 {
        (a - b).abs() / (f64::EPSILON * b.abs().max(f64::MIN_POSITIVE))
    }

    /// The special values, as the library's `ln` and `exp` give them. Negative control: `ln`
    /// of a value near 1 is not `ln` of its neighbour two ulps away.
    #[test]
    fn special_values_are_those_of_the_library() {
        assert_eq!(ln(0.0), f64::NEG_INFINITY);
        assert_eq!(ln(f64::INFINITY), f64::INFINITY);
        for x in [-1.0, -f64::MIN_POSITIVE, f64::NEG_INFINITY, f64::NAN] {
            assert!(ln(x).is_nan(), "ln({x})");
        }
        assert_eq!(ln(1.0), 0.0);
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(exp(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp(710.0), f64::INFINITY);
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp(-746.0), 0.0);
        assert!(exp(f64::NAN).is_nan());
        assert!(exp(-740.0) > 0.0 && exp(-740.0) < f64::MIN_POSITIVE);
        // At the edge of overflow: the largest `y` whose library `exp` is finite, and the next.
        let edge = 709.782_712_893_384_f64;
        let beyond = f64::from_bits(edge.to_bits() + 1);
        assert!(edge.exp().is_finite() && beyond.exp().is_infinite());
        assert!(ulps(exp(edge), edge.exp()) <= 2.0, "{:e}", exp(edge));
        assert_eq!(exp(beyond), f64::INFINITY);
        assert_ne!(ln(1.0 + 4e-16), ln(1.0));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        /// `ln` within 2 ulp of the library's over every positive double, subnormals
        /// included (the exponent and the 52 bits of the mantissa drawn uniformly), relative
        /// to `max(|ln x|, 1)`: the absolute error of `ln m` near `m = 1` is what matters to
        /// a step size, whose log is then divided by the order.
        #[test]
        fn ln_is_the_library_s_to_2_ulp(bits in 1u64..0x7ff0_0000_0000_0000) {
            let x = f64::from_bits(bits);
            let (ours, lib) = (ln(x), x.ln());
            prop_assert!((ours - lib).abs() <= 2.0 * f64::EPSILON * lib.abs().max(1.0),
                "ln({x:e}) = {ours:e}, library {lib:e}");
        }

        /// `exp` within 2 ulp of the library's over the whole range where it is a normal
        /// double, within two units of the smallest subnormal below it, and infinite where
        /// the library's is.
        #[test]
        fn exp_is_the_library_s_to_2_ulp(y in -745.2f64..709.8) {
            let (ours, lib) = (exp(y), y.exp());
            if lib.is_infinite() {
                prop_assert_eq!(ours, lib, "exp({})", y);
            } else if lib >= f64::MIN_POSITIVE {
                prop_assert!(ulps(ours, lib) <= 2.0, "exp({y}) = {ours:e}, library {lib:e}");
            } else {
                prop_assert!((ours - lib).abs() <= 2.0 * 4.9e-324, "exp({y}) = {ours:e}, library {lib:e}");
            }
        }
    }
}
