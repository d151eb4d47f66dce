//! The numbers the Taylor coefficients are made of, in one run or in lanes: the one trait
//! the recurrences ([`super::recurrence`]), the histories ([`super::convolution`]), the tape's
//! interpreter and the generated kernels are written over.

use std::fmt;

use crate::scalar::Scalar;

/// The numbers the Taylor coefficients are made of: `f64` (one run) or
/// [`Lanes`](crate::batch::Lanes) (one run per lane, structure of arrays: coefficient `k` of a
/// slot for all lanes side by side, the convolutions vectorised across the lanes). The
/// recurrences of [`Tape::expand`](super::Tape::expand) are written once for every such type, and each lane's
/// arithmetic is that of `f64`, operation for operation: a lane's coefficients are bitwise
/// those of an `f64` tape expanded through the same state.
pub trait Coefficient: Scalar + fmt::Debug + Send + Sync {
    /// The number of runs (lanes) one coefficient carries.
    const WIDTH: usize;
    /// `self * a + b` with one rounding in each lane ([`f64::mul_add`]).
    fn fused_mul_add(self, a: Self, b: Self) -> Self;
    /// Lane `l`.
    fn lane(&self, l: usize) -> f64;
    /// Sets lane `l` to `v`.
    fn set_lane(&mut self, l: usize, v: f64);
}

impl Coefficient for f64 {
    const WIDTH: usize = 1;

    #[inline(always)]
    fn fused_mul_add(self, a: f64, b: f64) -> f64 {
        f64::mul_add(self, a, b)
    }

    #[inline(always)]
    fn lane(&self, _l: usize) -> f64 {
        *self
    }

    #[inline(always)]
    fn set_lane(&mut self, _l: usize, v: f64) {
        *self = v;
    }
}
