//! [`Lanes`]: `L` doubles operated on element by element, a [`Scalar`] for the field (m-eq),
//! (mg-eq) evaluated at `L` states at once.
//!
//! Each operation is the `f64` operation applied lane by lane, written as a plain loop over a
//! fixed-size array, which LLVM turns into SIMD instructions on stable Rust: the loop of the
//! lanes (`runs::Runs::integrate`) and the Taylor expansion are compiled for AVX-512, AVX2 or
//! the baseline (two doubles per SSE2 register) and chosen at run time. Lane `l` of a result is therefore bitwise the `f64` result of the
//! same operation on lane `l` of the operands: the generic field run on `Lanes<L>` gives, in
//! each lane, exactly the `f64` field. [`Scalar::mul_add`] makes the same choice as the `f64`
//! implementation (fused where the target has a fused multiply-add instruction, else a
//! product and a sum), so that this holds in every build.

use crate::scalar::Scalar;
use crate::taylor::coefficient::Coefficient;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `L` doubles, one per trajectory of a batch (structure of arrays: a state of dimension `N`
/// is `[Lanes<L>; N]`, component `i` of the `L` trajectories side by side).
///
/// Aligned to 64 bytes, a cache line: eight lanes are then one line and one aligned AVX-512
/// register, and no load of them straddles two lines (with the 8 bytes of `f64` alone, the
/// coefficients of the batched Taylor method and the stages of the batched DOP853 began
/// anywhere in a line: in CPU time on the 1024-run benchmark of BENCHMARKS.md, 8 Taylor lanes
/// took 1.54x and 8 DOP853 lanes 1.10x as long; the same numbers bit for bit). Fewer lanes
/// are padded to the line (4 lanes: 1 % slower here, on a machine with AVX-512 that runs 8).
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(align(64))]
pub struct Lanes<const L: usize>(pub [f64; L]);

impl<const L: usize> Lanes<L> {
    /// Every lane equal to `c`.
    #[inline(always)]
    pub fn splat(c: f64) -> Self {
        Lanes([c; L])
    }

    /// `f` applied to each lane.
    #[inline(always)]
    pub fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Lanes(self.0.map(f))
    }

    /// `f` applied to each pair of lanes.
    #[inline(always)]
    pub fn zip(self, other: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        Lanes(std::array::from_fn(|l| f(self.0[l], other.0[l])))
    }

    /// The absolute value of each lane.
    #[inline(always)]
    pub fn abs(self) -> Self {
        self.map(f64::abs)
    }

    /// The lane-wise maximum, as [`f64::max`] (a NaN lane yields the other operand).
    #[inline(always)]
    pub fn max(self, other: Self) -> Self {
        self.zip(other, f64::max)
    }
}

/// Lane-wise binary operators, with a `Lanes` or an `f64` (broadcast) on the right.
macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const L: usize> $trait for Lanes<L> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: Self) -> Self {
                self.zip(rhs, |a, b| a $op b)
            }
        }

        impl<const L: usize> $trait<f64> for Lanes<L> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, rhs: f64) -> Self {
                self.map(|a| a $op rhs)
            }
        }
    };
}

lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl<const L: usize> Neg for Lanes<L> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|a| -a)
    }
}

impl<const L: usize> Scalar for Lanes<L> {
    #[inline(always)]
    fn from_f64(c: f64) -> Self {
        Lanes::splat(c)
    }

    #[inline(always)]
    fn sqrt(self) -> Self {
        self.map(f64::sqrt)
    }

    #[inline(always)]
    fn recip(self) -> Self {
        self.map(f64::recip)
    }

    /// Lane by lane what `f64` does ([`Scalar::mul_add`] for `f64`): fused with a fused
    /// multiply-add instruction, a product and a sum without one.
    #[inline(always)]
    fn mul_add(self, a: Self, b: Self) -> Self {
        Lanes(std::array::from_fn(|l| {
            Scalar::mul_add(self.0[l], a.0[l], b.0[l])
        }))
    }
}

/// Lane `l` of a state in lanes.
#[inline(always)]
pub fn lane_of<const N: usize, const L: usize>(v: &[Lanes<L>; N], l: usize) -> [f64; N] {
    std::array::from_fn(|i| v[i].0[l])
}

/// Writes `x` into lane `l` of a state in lanes.
#[inline(always)]
pub fn set_lane<const N: usize, const L: usize>(v: &mut [Lanes<L>; N], l: usize, x: &[f64; N]) {
    for (vi, &xi) in v.iter_mut().zip(x) {
        vi.0[l] = xi;
    }
}

/// Lanes as the coefficients of a Taylor [`Tape`](crate::taylor::Tape): `L` runs
/// expanded at once, each lane bitwise an `f64` tape's.
impl<const L: usize> Coefficient for Lanes<L> {
    const WIDTH: usize = L;

    #[inline(always)]
    fn fused_mul_add(self, a: Self, b: Self) -> Self {
        Lanes(std::array::from_fn(|l| self.0[l].mul_add(a.0[l], b.0[l])))
    }

    #[inline(always)]
    fn lane(&self, l: usize) -> f64 {
        self.0[l]
    }

    #[inline(always)]
    fn set_lane(&mut self, l: usize, v: f64) {
        self.0[l] = v;
    }
}

#[cfg(test)]
mod tests {
    use super::Lanes;
    use crate::scalar::Scalar;

    /// Each lane of each operation is bitwise the `f64` operation on that lane, on values
    /// that round differently (thirds, huge, tiny, subnormal, negative zero). Negative
    /// control: the comparison of bits sees a single rounding moved (`(a + b) + c` against
    /// `a + (b + c)` differ in lane 3).
    #[test]
    fn each_lane_is_the_f64_operation() {
        let a = Lanes([1.0 / 3.0, -7.1e300, 2.5e-310, 0.1, -0.0, 3.0]);
        let b = Lanes([3.0, 1e-10, 1e10, 0.7, 5.0, -1.0 / 7.0]);
        let c = Lanes([-1.0, 2.0, 1e-300, -0.07, 0.0, 1e-17]);
        for l in 0..6 {
            let (x, y, z) = (a.0[l], b.0[l], c.0[l]);
            assert_eq!((a + b).0[l].to_bits(), (x + y).to_bits());
            assert_eq!((a - b).0[l].to_bits(), (x - y).to_bits());
            assert_eq!((a * b).0[l].to_bits(), (x * y).to_bits());
            assert_eq!((a / b).0[l].to_bits(), (x / y).to_bits());
            assert_eq!((a * 0.3).0[l].to_bits(), (x * 0.3).to_bits());
            assert_eq!((-a).0[l].to_bits(), (-x).to_bits());
            assert_eq!(b.abs().sqrt().0[l].to_bits(), y.abs().sqrt().to_bits());
            assert_eq!(b.recip().0[l].to_bits(), Scalar::recip(y).to_bits());
            assert_eq!(
                a.mul_add(b, c).0[l].to_bits(),
                Scalar::mul_add(x, y, z).to_bits()
            );
        }
        assert_ne!(
            ((a + b) + c).0[3].to_bits(),
            (a + (b + c)).0[3].to_bits(),
            "negative control"
        );
    }
}
