//! The part of each convolution of a Taylor pass that the pass does not change: for an
//! operation with a product, quotient or square root, the sum over the orders `1 .. k-1` of
//! its operands (its **history** at order `k`), computed for all operations of the tape at once
//! before the pass of order `k` runs through the tape.
//!
//! At order `k` the convolution of a product `w = a b` is
//! `w^[k] = sum_{j=0..k} a^[j] b^[k-j]`: only its two end terms `a^[0] b^[k]` and
//! `a^[k] b^[0]` need the order `k` of the operands, which the pass computes operation after
//! operation; the `k - 1` terms between them use orders computed by earlier passes. The
//! histories are therefore independent of each other: they can be summed side by side, and
//! the generated histories of the model families ([`super::codegen`]) sum those that read the
//! same coefficients in one loop, which loads each coefficient once for all of them.
//!
//! The order of the arithmetic, the same for every [`Coefficient`] type, instruction set and
//! way of running: a history is one sum, zero to start with, of its terms, each added as
//! `s <- a^[j] b^[k-j] + s` (a fused multiply-add if the pass fuses); a second product
//! (`a b ± d e`) adds its term `(±d^[j]) e^[k-j]` to the same sum right after the first's
//! term of the same `j`, with `-d` for a difference (exact; so one loop over `j` sums both
//! products, instead of a second loop that would wait for the first's sum). The orders `j`
//! come in this order:
//! * at an even order `k` (and at `k = 1`, no term): `j = 1, ..., k-1`;
//! * at an odd order `k >= 3`: first `j = 2, ..., k-2`, then the end terms `j = 1, k-1`.
//!
//! The odd orders are so ordered for the generated histories ([`super::codegen`]), which sum
//! the terms of two orders in one loop: at an even order `k` the loop loads `a^[j]` and
//! `b^[k-j]` for the terms of order `k`, and the `b^[k+1-j]` it loaded one `j` before makes
//! the term `a^[j] b^[k+1-j]` of order `k + 1` (`j >= 2`): two terms for every two loads, half
//! the loads of a loop over one order. The end terms of order `k + 1` need the order `k`,
//! which the pass of order `k` computes after the loop: the pass of order `k + 1` adds them.
//! A lane of [`Lanes`](crate::batch::Lanes) therefore computes bitwise the `f64` history, and
//! the generated histories bitwise [`histories`].

use super::coefficient::Coefficient;

/// The history of one operation: `sum_{j=1..k-1} a^[j] b^[k-j]`, plus or minus
/// `sum_{j=1..k-1} d^[j] e^[k-j]` if `second`. Operands are the offsets of the coefficient of
/// order 0 of their slots (as in the tape's instructions).
#[derive(Debug, Clone, Copy)]
pub struct History {
    pub a: u32,
    pub b: u32,
    /// The second product `(d, e, minus)`.
    pub second: Option<(u32, u32, bool)>,
}

/// The histories of `list` at order `k >= 1` into `out` (`out.len() >= list.len()`), in the
/// arithmetic of the module documentation, products fused if `FMA`: the interpreter's (the
/// tapes without a generated kernel).
#[inline(always)]
pub fn histories<T: Coefficient, const FMA: bool>(
    c: &[T],
    list: &[History],
    k: usize,
    out: &mut [T],
) {
    for (h, v) in list.iter().zip(out.iter_mut()) {
        let zero = T::from_f64(0.0);
        *v = if k % 2 == 0 || k < 3 {
            products::<T, FMA>(c, h, k, 1..k, zero)
        } else {
            let middle = products::<T, FMA>(c, h, k, 2..k - 1, zero);
            products::<T, FMA>(c, h, k, [1, k - 1], middle)
        };
    }
}

/// `s` plus, for each `j` of `js` in order (each in `1 ..= k-1`), the term `a^[j] b^[k-j]` of
/// the first product of `h`, then the term `(±d^[j]) e^[k-j]` of its second.
#[inline(always)]
fn products<T: Coefficient, const FMA: bool>(
    c: &[T],
    h: &History,
    k: usize,
    js: impl IntoIterator<Item = usize>,
    mut s: T,
) -> T {
    let (a, b) = (h.a as usize, h.b as usize);
    for j in js {
        s = mul_add::<T, FMA>(c[a + j], c[b + k - j], s);
        if let Some((d, e, minus)) = h.second {
            let x = c[d as usize + j];
            s = mul_add::<T, FMA>(if minus { -x } else { x }, c[e as usize + k - j], s);
        }
    }
    s
}

/// `c[i]` without a bounds check (the generated histories: one check of the whole layout
/// before their loops instead of one per load).
///
/// # Safety
/// `i < c.len()`.
#[inline(always)]
pub unsafe fn at<T: Copy>(c: &[T], i: usize) -> T {
    debug_assert!(i < c.len());
    // SAFETY: the caller's.
    unsafe { *c.get_unchecked(i) }
}

/// `x y + z`: one rounding (fused) if `FMA`, else two.
#[inline(always)]
pub fn mul_add<T: Coefficient, const FMA: bool>(x: T, y: T, z: T) -> T {
    if FMA {
        x.fused_mul_add(y, z)
    } else {
        x * y + z
    }
}
