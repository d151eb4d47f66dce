//! The recurrence of each operation of a [`Tape`](super::Tape) at an order `k >= 1`, from
//! values: the order-0 and order-`k` coefficients of its operands, the order 0 of its result
//! `w0` where the recurrence needs it, and its history `h` ([`super::convolution`]: the terms
//! of orders `1 .. k-1`). Written once and called both by the tape's interpreter (one `match`
//! per operation) and by the generated kernels of [`super::kernels`] (straight-line code, the
//! order-`k` values in registers): the two make the same operations in the same order, so
//! their coefficients are bitwise equal.
//!
//! Products add their two end terms to the history, `a^[0] b^[k] + (a^[k] b^[0] + h)`: the
//! operand recorded last (`b`, the later slot for a product, whose operands are in slot order)
//! waits for one multiply-add only. Fused if `FMA` (see [`mul_add`]).

use super::coefficient::Coefficient;
use super::convolution::mul_add;

/// `a b` at order `k`: `a0 bk + (ak b0 + h)`.
#[inline(always)]
pub fn product<T: Coefficient, const FMA: bool>(a0: T, ak: T, b0: T, bk: T, h: T) -> T {
    mul_add::<T, FMA>(a0, bk, mul_add::<T, FMA>(ak, b0, h))
}

/// `a b + d` at order `k`.
#[inline(always)]
pub fn mul_plus<T: Coefficient, const FMA: bool>(a0: T, ak: T, b0: T, bk: T, dk: T, h: T) -> T {
    product::<T, FMA>(a0, ak, b0, bk, h) + dk
}

/// `a b - d` at order `k`.
#[inline(always)]
pub fn mul_minus<T: Coefficient, const FMA: bool>(a0: T, ak: T, b0: T, bk: T, dk: T, h: T) -> T {
    product::<T, FMA>(a0, ak, b0, bk, h) - dk
}

/// `d - a b` at order `k`.
#[inline(always)]
pub fn minus_mul<T: Coefficient, const FMA: bool>(dk: T, a0: T, ak: T, b0: T, bk: T, h: T) -> T {
    dk - product::<T, FMA>(a0, ak, b0, bk, h)
}

/// `a b + d e` at order `k` (`h`: the history of both products).
#[inline(always)]
pub fn dot_add<T: Coefficient, const FMA: bool>(
    [a0, ak, b0, bk]: [T; 4],
    [d0, dk, e0, ek]: [T; 4],
    h: T,
) -> T {
    product::<T, FMA>(a0, ak, b0, bk, product::<T, FMA>(d0, dk, e0, ek, h))
}

/// `a b - d e` at order `k` (`h`: the history of both products, the second with `-d`).
#[inline(always)]
pub fn dot_sub<T: Coefficient, const FMA: bool>(
    [a0, ak, b0, bk]: [T; 4],
    [d0, dk, e0, ek]: [T; 4],
    h: T,
) -> T {
    product::<T, FMA>(a0, ak, b0, bk, product::<T, FMA>(-d0, -dk, e0, ek, h))
}

/// `w = a / b` at order `k`: `(a^[k] - (b^[k] w^[0] + h)) (1 / b^[0])`, `h = sum_{j=1..k-1}
/// b^[j] w^[k-j]`. A product by the reciprocal rather than a quotient: `1 / b^[0]` does not
/// wait for the chain of the order, so the chain waits for a multiplication instead of a
/// division (three quotients in a row on the Routh sphere's tape: 8 Taylor lanes 1.035x
/// faster at 1e-12, BENCHMARKS.md, "Sweeps"; the order 0 is the field's own division).
#[inline(always)]
pub fn quotient<T: Coefficient, const FMA: bool>(ak: T, b0: T, bk: T, w0: T, h: T) -> T {
    (ak - mul_add::<T, FMA>(bk, w0, h)) * b0.recip()
}

/// `w = c / b` (`c` constant) at order `k`: `-(b^[k] w^[0] + h) (1 / b^[0])` (as [`quotient`]).
#[inline(always)]
pub fn reciprocal<T: Coefficient, const FMA: bool>(b0: T, bk: T, w0: T, h: T) -> T {
    -mul_add::<T, FMA>(bk, w0, h) * b0.recip()
}

/// `w = sqrt(a)` at order `k`: `(a^[k] - h) / (2 w^[0])`, `h = sum_{j=1..k-1} w^[j] w^[k-j]`.
#[inline(always)]
pub fn square_root<T: Coefficient>(ak: T, w0: T, h: T) -> T {
    (ak - h) / (w0 * 2.0)
}
