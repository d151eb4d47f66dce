//! The part of each convolution of a Taylor pass that the pass does not change: for an
//! operation with a product, quotient or square root, the sum over the orders `1 .. k-1` of
//! its operands (its **history** at order `k`), computed for all operations of the tape at once
//! before the pass of order `k` runs through the tape.
//!
//! At order `k` the convolution of a product `w = a b` is
//! `w^[k] = sum_{j=0..k} a^[j] b^[k-j]`: only its two end terms `a^[0] b^[k]` and
//! `a^[k] b^[0]` need the order `k` of the operands, which the pass computes operation after
//! operation; the `k - 1` terms between them use orders computed by earlier passes. The
//! histories are therefore independent of each other: one loop over a flat list of them, with
//! no dispatch, and (for `f64` with AVX2 and FMA) four of them reduced together, instead of a
//! dot product with its set-up and reduction inside every operation of the pass.
//!
//! The order of the arithmetic, the same for every [`Coefficient`] type and instruction set:
//! a history sums its terms `j = 1, ..., k-1` in four partial sums `s_0 .. s_3` (zero to start
//! with): with `t = (k - 1) mod 4`, the terms `j = 1 .. t` go to the sums `0 .. t-1`, then term
//! `j = t + 1 + 4 i + l` to sum `l`, each as `s_l <- x y + s_l` (a fused multiply-add if the
//! pass fuses); a second product (`a b ± d e`) adds its terms to the same sums after the
//! first's, with `-d` for a difference (exact); the history is `(s_0 + s_1) + (s_2 + s_3)`. A
//! lane of [`Lanes`](crate::batch::Lanes) therefore computes bitwise the `f64` history.

use super::tape::Coefficient;

/// `$body` with `$k` a constant for the orders of the usual tolerances (2 to 24: order 20 at
/// `eps = 1e-12` and at `eps = 2.2e-16`, [`taylor_order`](super::taylor_order)), so that the
/// compiler lays the terms of a history out in full for each of them (no loop counters, no
/// partial chunk: the Taylor lanes run 9 % faster, BENCHMARKS.md); a variable `$k` above.
/// The same operations in the same order either way.
macro_rules! at_constant_order {
    ($k:ident, $body:expr) => {
        at_constant_order!(@ $k, $body, 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24)
    };
    (@ $k:ident, $body:expr, $($n:literal)*) => {
        match $k {
            $($n => {
                let $k = $n;
                $body
            })*
            _ => $body,
        }
    };
}

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
/// arithmetic of the module documentation, products fused if `FMA`.
#[inline(always)]
pub fn histories<T: Coefficient, const FMA: bool>(
    c: &[T],
    list: &[History],
    k: usize,
    out: &mut [T],
) {
    if FMA {
        at_constant_order!(k, histories_at::<T, FMA>(c, list, k, out))
    } else {
        histories_at::<T, FMA>(c, list, k, out)
    }
}

/// [`histories`] (`k` a constant where [`at_constant_order!`] makes it one).
#[inline(always)]
fn histories_at<T: Coefficient, const FMA: bool>(
    c: &[T],
    list: &[History],
    k: usize,
    out: &mut [T],
) {
    for (h, v) in list.iter().zip(out.iter_mut()) {
        let mut s = [T::from_f64(0.0); 4];
        terms::<T, FMA>(c, h.a as usize, h.b as usize, k, false, &mut s);
        if let Some((d, e, minus)) = h.second {
            terms::<T, FMA>(c, d as usize, e as usize, k, minus, &mut s);
        }
        *v = (s[0] + s[1]) + (s[2] + s[3]);
    }
}

/// Adds the terms `(±a^[j]) b^[k-j]`, `j = 1 .. k-1`, to the partial sums `s`.
#[inline(always)]
fn terms<T: Coefficient, const FMA: bool>(
    c: &[T],
    a: usize,
    b: usize,
    k: usize,
    minus: bool,
    s: &mut [T; 4],
) {
    if minus {
        terms_signed::<T, FMA, true>(c, a, b, k, s);
    } else {
        terms_signed::<T, FMA, false>(c, a, b, k, s);
    }
}

/// [`terms`] with `-a` if `MINUS`.
#[inline(always)]
fn terms_signed<T: Coefficient, const FMA: bool, const MINUS: bool>(
    c: &[T],
    a: usize,
    b: usize,
    k: usize,
    s: &mut [T; 4],
) {
    if k < 2 {
        return;
    }
    // Orders 1 .. k-1 of `a` and of `b`: term `j` is `x[j-1] y[k-1-j]`.
    let (xs, ys) = (&c[a + 1..a + k], &c[b + 1..b + k]);
    let t = (k - 1) % 4;
    let (head, xs) = xs.split_at(t);
    let (ys, tail) = ys.split_at(ys.len() - t);
    // Constant indices into `s` (a variable one would keep the sums in memory).
    for l in 0..3 {
        if l < t {
            s[l] = mul_add::<T, FMA>(signed::<T, MINUS>(head[l]), tail[t - 1 - l], s[l]);
        }
    }
    for (u, v) in xs.chunks_exact(4).zip(ys.rchunks_exact(4)) {
        for l in 0..4 {
            s[l] = mul_add::<T, FMA>(signed::<T, MINUS>(u[l]), v[3 - l], s[l]);
        }
    }
}

/// `-v` if `MINUS`, else `v` (a function, not a closure: closures do not inherit the target
/// features of the function they are written in).
#[inline(always)]
fn signed<T: Coefficient, const MINUS: bool>(v: T) -> T {
    if MINUS {
        -v
    } else {
        v
    }
}

/// `x y + z`: one rounding (fused) if `FMA`, else two.
#[inline(always)]
pub(super) fn mul_add<T: Coefficient, const FMA: bool>(x: T, y: T, z: T) -> T {
    if FMA {
        x.fused_mul_add(y, z)
    } else {
        x * y + z
    }
}

/// [`histories`] for `f64` with AVX2 and FMA: the four partial sums of a history in one
/// register, four histories reduced together. The same operations as [`histories`] with
/// `FMA`, bit for bit: lane `l` of the register is the partial sum `s_l`, the first `t` terms
/// are fused into the lanes below `t` only (the others kept by a blend), and the reduction
/// `(s_0 + s_1) + (s_2 + s_3)` is a horizontal add of pairs and a sum of the halves.
///
/// # Safety
/// The CPU must have AVX2 and FMA; every operand of `list` must be the offset of order 0 of a
/// slot of `c` with at least 4 places before it and `k + 3` after it (the tape's layout
/// for `k <= max_order`).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
pub unsafe fn histories_avx2(c: &[f64], list: &[History], k: usize, out: &mut [f64]) {
    use std::arch::x86_64::*;
    if k < 2 {
        out[..list.len()].fill(0.0);
        return;
    }
    let t = (k - 1) % 4;
    let tail = _mm256_castsi256_pd(_mm256_setr_epi64x(
        -i64::from(t > 0),
        -i64::from(t > 1),
        -i64::from(t > 2),
        0,
    ));
    let p = c.as_ptr();
    let mut groups = list.chunks_exact(4);
    let mut at = 0;
    for g in &mut groups {
        let s0 = history_avx2(p, &g[0], k, t, tail);
        let s1 = history_avx2(p, &g[1], k, t, tail);
        let s2 = history_avx2(p, &g[2], k, t, tail);
        let s3 = history_avx2(p, &g[3], k, t, tail);
        let (h01, h23) = (_mm256_hadd_pd(s0, s1), _mm256_hadd_pd(s2, s3));
        let sums = _mm256_add_pd(
            _mm256_permute2f128_pd::<0x20>(h01, h23),
            _mm256_permute2f128_pd::<0x31>(h01, h23),
        );
        _mm256_storeu_pd(out[at..at + 4].as_mut_ptr(), sums);
        at += 4;
    }
    for h in groups.remainder() {
        let mut s = [0.0; 4];
        _mm256_storeu_pd(s.as_mut_ptr(), history_avx2(p, h, k, t, tail));
        out[at] = (s[0] + s[1]) + (s[2] + s[3]);
        at += 1;
    }
}

/// The partial sums of one history ([`histories_avx2`]; `t = (k - 1) mod 4`, `tail` the
/// lanes below `t`).
///
/// # Safety
/// As [`histories_avx2`]'s, with `k >= 2`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
unsafe fn history_avx2(
    p: *const f64,
    h: &History,
    k: usize,
    t: usize,
    tail: std::arch::x86_64::__m256d,
) -> std::arch::x86_64::__m256d {
    use std::arch::x86_64::*;
    let mut s = run_avx2(
        p,
        h.a as usize,
        h.b as usize,
        k,
        t,
        tail,
        false,
        _mm256_setzero_pd(),
    );
    if let Some((d, e, minus)) = h.second {
        s = run_avx2(p, d as usize, e as usize, k, t, tail, minus, s);
    }
    s
}

/// The terms `(±a^[j]) b^[k-j]`, `j = 1 .. k-1`, fused into the partial sums `s`
/// ([`histories_avx2`]).
///
/// # Safety
/// As [`history_avx2`]'s.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
#[allow(clippy::too_many_arguments)]
unsafe fn run_avx2(
    p: *const f64,
    a: usize,
    b: usize,
    k: usize,
    t: usize,
    tail: std::arch::x86_64::__m256d,
    minus: bool,
    mut s: std::arch::x86_64::__m256d,
) -> std::arch::x86_64::__m256d {
    use std::arch::x86_64::*;
    let negate = _mm256_set1_pd(if minus { -0.0 } else { 0.0 });
    if t > 0 {
        s = _mm256_blendv_pd(s, step_avx2(p, a, b, k, 1, negate, s), tail);
    }
    for j0 in (1 + t..k).step_by(4) {
        s = step_avx2(p, a, b, k, j0, negate, s);
    }
    s
}

/// `(±a^[j0 .. j0+4]) * (b^[k-j0], ..., b^[k-j0-3])` fused into `s` (`negate`: `-0.0` in
/// each lane for `-a`, else `0.0`).
///
/// # Safety
/// As [`history_avx2`]'s, with `1 <= j0 <= k - 1`: the loads read orders `j0 .. j0+3 <= k+2`
/// of `a` and `k-j0-3 >= -4 .. k-j0` of `b`, within the slots' places.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
unsafe fn step_avx2(
    p: *const f64,
    a: usize,
    b: usize,
    k: usize,
    j0: usize,
    negate: std::arch::x86_64::__m256d,
    s: std::arch::x86_64::__m256d,
) -> std::arch::x86_64::__m256d {
    use std::arch::x86_64::*;
    let x = _mm256_loadu_pd(p.add(a + j0));
    let y = _mm256_permute4x64_pd::<0b00_01_10_11>(_mm256_loadu_pd(p.add(b + k - j0 - 3)));
    _mm256_fmadd_pd(_mm256_xor_pd(x, negate), y, s)
}
