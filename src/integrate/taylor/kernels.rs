//! Generated Taylor kernels: the pass of order `k >= 1` through the tapes of the model
//! families in straight-line code (see [`super::codegen`]). Generated: do not edit;
//! rewrite with `ROUTH_REGENERATE=1 cargo test --release --lib generated_kernels_are_up_to_date`.

use super::convolution::{self, at};
use super::recurrence;
use super::tape::Coefficient;

/// The name and the shape ([`super::codegen::shape`]) of each kernel, by number.
pub(super) const SHAPES: [(&str, &str); 6] = [
    ("routh", "n 6 first 7\nadd_c 2 #\ndot_add 7 7 1 1\nmul_plus 0 0 8\nadd_c 9 #\nc_div 10 #\nadd_c 9 #\nc_div 12 #\nmul 0 11\nmul 1 11\nmul 7 13\nmul 3 11\nmul 4 11\nmul 5 13\ndot_add 7 19 1 18\nmul_plus 0 17 20\ndot_add 7 16 1 15\nmul_plus 0 14 22\nc_sub 23 #\ndiv 21 24\nmul_plus 14 25 17\nmul_plus 15 25 18\nmul_plus 16 25 19\ndot_sub 1 28 2 27\ndot_sub 2 26 0 28\ndot_sub 0 27 1 26\nmul_c 31 #\nmul_c 1 #\nmul_c 0 #\nc_sub 34 #\ndot_sub 4 28 5 27\ndot_sub 5 26 3 28\ndot_sub 3 27 4 26\nadd 33 36\nmul_plus 26 32 39\nadd 35 37\nmul_plus 27 32 41\nmul_plus 28 32 38\n"),
    ("routh_free", "n 6 first 7\nadd_c 2 #\ndot_add 7 7 1 1\nmul_plus 0 0 8\nadd_c 9 #\nc_div 10 #\nadd_c 9 #\nc_div 12 #\nmul 0 11\nmul 1 11\nmul 7 13\nmul 3 11\nmul 4 11\nmul 5 13\ndot_add 7 19 1 18\nmul_plus 0 17 20\ndot_add 7 16 1 15\nmul_plus 0 14 22\nc_sub 23 #\ndiv 21 24\nmul_plus 14 25 17\nmul_plus 15 25 18\nmul_plus 16 25 19\ndot_sub 1 28 2 27\ndot_sub 2 26 0 28\ndot_sub 0 27 1 26\nmul_c 31 #\ndot_sub 4 28 5 27\ndot_sub 5 26 3 28\ndot_sub 3 27 4 26\nmul_plus 26 32 33\nmul_plus 27 32 34\nmul_plus 28 32 35\n"),
    ("routh_general", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 10 10 8 8\nmul_plus 7 7 11\nmul_c 12 #\nadd_c 13 #\nc_div 14 #\nadd_c 13 #\nc_div 16 #\nmul 7 15\nmul 8 15\nmul 10 17\nmul 3 15\nmul 4 15\nmul 5 17\ndot_add 10 23 8 22\nmul_plus 7 21 24\nmul_c 25 #\ndot_add 10 20 8 19\nmul_plus 7 18 27\nmul_c 28 #\nc_sub 29 #\ndiv 26 30\nmul_plus 18 31 21\nmul_plus 19 31 22\nmul_plus 20 31 23\ndot_sub 1 34 2 33\ndot_sub 2 32 0 34\ndot_sub 0 33 1 32\nmul_c 37 #\nmul_c 1 #\nmul_c 0 #\nc_sub 40 #\ndot_sub 4 34 5 33\ndot_sub 5 32 3 34\ndot_sub 3 33 4 32\nadd 39 42\nmul_plus 32 38 45\nadd 41 43\nmul_plus 33 38 47\nmul_plus 34 38 44\n"),
    ("routh_general_free", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 10 10 8 8\nmul_plus 7 7 11\nmul_c 12 #\nadd_c 13 #\nc_div 14 #\nadd_c 13 #\nc_div 16 #\nmul 7 15\nmul 8 15\nmul 10 17\nmul 3 15\nmul 4 15\nmul 5 17\ndot_add 10 23 8 22\nmul_plus 7 21 24\nmul_c 25 #\ndot_add 10 20 8 19\nmul_plus 7 18 27\nmul_c 28 #\nc_sub 29 #\ndiv 26 30\nmul_plus 18 31 21\nmul_plus 19 31 22\nmul_plus 20 31 23\ndot_sub 1 34 2 33\ndot_sub 2 32 0 34\ndot_sub 0 33 1 32\nmul_c 37 #\ndot_sub 4 34 5 33\ndot_sub 5 32 3 34\ndot_sub 3 33 4 32\nmul_plus 32 38 39\nmul_plus 33 38 40\nmul_plus 34 38 41\n"),
    ("chaplygin", "n 6 first 7\ndot_add 2 2 1 1\nmul_plus 0 0 7\nadd_c 8 #\nc_div 9 #\nadd_c 8 #\nc_div 11 #\nadd_c 8 #\nc_div 13 #\nmul 0 10\nmul 1 12\nmul 2 14\nmul 3 10\nmul 4 12\nmul 5 14\ndot_add 2 20 1 19\nmul_plus 0 18 21\ndot_add 2 17 1 16\nmul_plus 0 15 23\nc_sub 24 #\ndiv 22 25\nmul_plus 15 26 18\nmul_plus 16 26 19\nmul_plus 17 26 20\ndot_sub 1 29 2 28\ndot_sub 2 27 0 29\ndot_sub 0 28 1 27\ndot_sub 4 29 5 28\ndot_sub 5 27 3 29\ndot_sub 3 28 4 27\n"),
    ("ball", "n 6 first 7\nmul_c 0 #\nadd_c 7 #\nmul_c 1 #\nadd_c 9 #\nmul_c 2 #\nadd_c 11 #\ndot_add 12 12 10 10\nmul_plus 8 8 13\nmul_c 14 #\nadd_c 15 #\nc_div 16 #\nadd_c 15 #\nc_div 18 #\nadd_c 15 #\nc_div 20 #\nmul 8 17\nmul 10 19\nmul 12 21\nmul 3 17\nmul 4 19\nmul 5 21\ndot_add 12 27 10 26\nmul_plus 8 25 28\nmul_c 29 #\ndot_add 12 24 10 23\nmul_plus 8 22 31\nmul_c 32 #\nc_sub 33 #\ndiv 30 34\nmul_plus 22 35 25\nmul_plus 23 35 26\nmul_plus 24 35 27\ndot_sub 1 38 2 37\ndot_sub 2 36 0 38\ndot_sub 0 37 1 36\nmul_c 39 #\nmul_c 40 #\nadd 42 43\nmul_c 41 #\nadd 44 45\nmul_c 1 #\nmul_c 2 #\nsub 47 48\nmul_c 2 #\nmul_c 0 #\nsub 50 51\nmul_c 0 #\nmul_c 1 #\nsub 53 54\ndot_sub 4 38 5 37\ndot_sub 5 36 3 38\ndot_sub 3 37 4 36\nadd 49 56\nmul_plus 36 46 59\nadd 52 57\nmul_plus 37 46 61\nadd 55 58\nmul_plus 38 46 63\n"),
];

/// The pass of order `k >= 1` through the tape of shape `SHAPES[kernel]`, in slots of
/// `s` coefficients (order 0 of each `PAD` places into its slot), with the histories `h`
/// ([`super::convolution`]) and the factors `q` ([`super::codegen::factors`]).
#[inline(always)]
pub(super) fn pass<T: Coefficient, const FMA: bool>(
    kernel: usize,
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T],
    q: &[f64],
) {
    match kernel {
        0 => routh::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the factors of the shape"),
        ),
        1 => routh_free::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the factors of the shape"),
        ),
        2 => routh_general::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the factors of the shape"),
        ),
        3 => routh_general_free::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the factors of the shape"),
        ),
        4 => chaplygin::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the factors of the shape"),
        ),
        5 => ball::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the factors of the shape"),
        ),
        _ => unreachable!("a kernel of SHAPES"),
    }
}

/// The histories ([`super::convolution`]) at order `k >= 1` of the tape of shape
/// `SHAPES[kernel]` into `h`, in slots of `s` coefficients: bitwise
/// [`super::convolution::histories`] of the tape's list, in groups that load each
/// coefficient once for all the products of the group that read it.
#[inline(always)]
pub(super) fn histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    kernel: usize,
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T],
    g: &mut [T],
) {
    match kernel {
        0 => routh_histories::<T, FMA, WIDE>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            g.try_into().expect("the histories of the shape"),
        ),
        1 => routh_histories::<T, FMA, WIDE>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            g.try_into().expect("the histories of the shape"),
        ),
        2 => routh_general_histories::<T, FMA, WIDE>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            g.try_into().expect("the histories of the shape"),
        ),
        3 => routh_general_histories::<T, FMA, WIDE>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            g.try_into().expect("the histories of the shape"),
        ),
        4 => chaplygin_histories::<T, FMA, WIDE>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            g.try_into().expect("the histories of the shape"),
        ),
        5 => ball_histories::<T, FMA, WIDE>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            g.try_into().expect("the histories of the shape"),
        ),
        _ => unreachable!("a kernel of SHAPES"),
    }
}

/// The pass of order `k >= 1` of the kernel `routh`.
#[inline(always)]
fn routh<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 27],
    q: &[f64; 3],
) {
    let v7 = c[2 * s + 4 + k];
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[7 * s + 4], v7], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[4], c[4 + k], v8, h[1]);
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::reciprocal::<T, FMA>(c[10 * s + 4], v10, c[11 * s + 4], h[2]);
    c[11 * s + 4 + k] = v11;
    let v12 = v9;
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::reciprocal::<T, FMA>(c[12 * s + 4], v12, c[13 * s + 4], h[3]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[11 * s + 4], v11, h[4]);
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[11 * s + 4], v11, h[5]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[13 * s + 4], v13, h[6]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[11 * s + 4], v11, h[7]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[11 * s + 4], v11, h[8]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[13 * s + 4], v13, h[9]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[19 * s + 4], v19], [c[s + 4], c[s + 4 + k], c[18 * s + 4], v18], h[10]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[17 * s + 4], v17, v20, h[11]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[16 * s + 4], v16], [c[s + 4], c[s + 4 + k], c[15 * s + 4], v15], h[12]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[14 * s + 4], v14, v22, h[13]);
    c[23 * s + 4 + k] = v23;
    let v24 = -v23;
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::quotient::<T, FMA>(v21, c[24 * s + 4], v24, c[25 * s + 4], h[14]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::mul_plus::<T, FMA>(c[14 * s + 4], v14, c[25 * s + 4], v25, v17, h[15]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::mul_plus::<T, FMA>(c[15 * s + 4], v15, c[25 * s + 4], v25, v18, h[16]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[16 * s + 4], v16, c[25 * s + 4], v25, v19, h[17]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[28 * s + 4], v28], [c[2 * s + 4], c[2 * s + 4 + k], c[27 * s + 4], v27], h[18]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[26 * s + 4], v26], [c[4], c[4 + k], c[28 * s + 4], v28], h[19]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[27 * s + 4], v27], [c[s + 4], c[s + 4 + k], c[26 * s + 4], v26], h[20]);
    c[31 * s + 4 + k] = v31;
    let v32 = v31 * q[0];
    c[32 * s + 4 + k] = v32;
    let v33 = c[s + 4 + k] * q[1];
    c[33 * s + 4 + k] = v33;
    let v34 = c[4 + k] * q[2];
    c[34 * s + 4 + k] = v34;
    let v35 = -v34;
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[28 * s + 4], v28], [c[5 * s + 4], c[5 * s + 4 + k], c[27 * s + 4], v27], h[21]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[26 * s + 4], v26], [c[3 * s + 4], c[3 * s + 4 + k], c[28 * s + 4], v28], h[22]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[27 * s + 4], v27], [c[4 * s + 4], c[4 * s + 4 + k], c[26 * s + 4], v26], h[23]);
    c[38 * s + 4 + k] = v38;
    let v39 = v33 + v36;
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::mul_plus::<T, FMA>(c[26 * s + 4], v26, c[32 * s + 4], v32, v39, h[24]);
    c[40 * s + 4 + k] = v40;
    let v41 = v35 + v37;
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::mul_plus::<T, FMA>(c[27 * s + 4], v27, c[32 * s + 4], v32, v41, h[25]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::mul_plus::<T, FMA>(c[28 * s + 4], v28, c[32 * s + 4], v32, v38, h[26]);
    c[43 * s + 4 + k] = v43;
}

/// The histories of the kernels `routh`, `routh_free` at order `k >= 1` ([`histories`]).
#[inline(always)]
fn routh_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 27],
    g: &mut [T; 27],
) {
    assert!(k + 4 <= s && c.len() >= 33 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8].
        let (mut s0, mut s1, mut s2, mut s3, mut s4, mut s5, mut s6, mut s7, mut s8) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, a2, b2, a3, a4, a9, b11, b13) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 13 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a2, b2, s0);
            s1 = convolution::mul_add::<T, FMA>(a0, b0, s1);
            s2 = convolution::mul_add::<T, FMA>(a9, b11, s2);
            s3 = convolution::mul_add::<T, FMA>(a9, b13, s3);
            s4 = convolution::mul_add::<T, FMA>(a0, b11, s4);
            s5 = convolution::mul_add::<T, FMA>(a1, b11, s5);
            s6 = convolution::mul_add::<T, FMA>(a2, b13, s6);
            s7 = convolution::mul_add::<T, FMA>(a3, b11, s7);
            s8 = convolution::mul_add::<T, FMA>(a4, b11, s8);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), s0);
                s1 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), s1);
                s2 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s2);
                s3 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), s3);
                s4 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 11 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 11 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 11 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 11 * s + 4 + 1), s5);
                s6 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), s6);
                s7 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s7);
                s8 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s8);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[5] = s5;
        h[6] = s6;
        h[7] = s7;
        h[8] = s8;
        // Histories [9, 11, 13, 14, 15, 16, 17, 24, 25].
        let (mut s9, mut s11, mut s13, mut s14, mut s15, mut s16, mut s17, mut s24, mut s25) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a5, b13, a14, b14, a15, a16, b17, a24, b25, a26, a27, b32) = unsafe { (at(c, 4 + j), at(c, 5 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 14 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 16 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 24 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 27 * s + 4 + j), at(c, 32 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a5, b13, s9);
            s11 = convolution::mul_add::<T, FMA>(a0, b17, s11);
            s13 = convolution::mul_add::<T, FMA>(a0, b14, s13);
            s14 = convolution::mul_add::<T, FMA>(a24, b25, s14);
            s15 = convolution::mul_add::<T, FMA>(a14, b25, s15);
            s16 = convolution::mul_add::<T, FMA>(a15, b25, s16);
            s17 = convolution::mul_add::<T, FMA>(a16, b25, s17);
            s24 = convolution::mul_add::<T, FMA>(a26, b32, s24);
            s25 = convolution::mul_add::<T, FMA>(a27, b32, s25);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s9 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), s9);
                s11 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 17 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 17 * s + 4 + 1), s11);
                s13 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 14 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 14 * s + 4 + 1), s13);
                s14 = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s14);
                s15 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s15);
                s16 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s16);
                s17 = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s17);
                s24 = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s24);
                s25 = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s25);
                s25 = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s25);
            }
        }
        h[9] = s9;
        h[11] = s11;
        h[13] = s13;
        h[14] = s14;
        h[15] = s15;
        h[16] = s16;
        h[17] = s17;
        h[24] = s24;
        h[25] = s25;
        // Histories [10, 12, 18, 19, 20, 21, 22, 23, 26].
        let (mut s10, mut s12, mut s18, mut s19, mut s20, mut s21, mut s22, mut s23, mut s26) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b16, b19, b26, b27, a28, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a2, b19, s10);
            s12 = convolution::mul_add::<T, FMA>(a2, b16, s12);
            s18 = convolution::mul_add::<T, FMA>(a1, b28, s18);
            s19 = convolution::mul_add::<T, FMA>(a2, b26, s19);
            s20 = convolution::mul_add::<T, FMA>(a0, b27, s20);
            s21 = convolution::mul_add::<T, FMA>(a4, b28, s21);
            s22 = convolution::mul_add::<T, FMA>(a5, b26, s22);
            s23 = convolution::mul_add::<T, FMA>(a3, b27, s23);
            s26 = convolution::mul_add::<T, FMA>(a28, b32, s26);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b15, b18, b26, b27, b28) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a1, b18, s10);
            s12 = convolution::mul_add::<T, FMA>(a1, b15, s12);
            s18 = convolution::mul_add::<T, FMA>(-a2, b27, s18);
            s19 = convolution::mul_add::<T, FMA>(-a0, b28, s19);
            s20 = convolution::mul_add::<T, FMA>(-a1, b26, s20);
            s21 = convolution::mul_add::<T, FMA>(-a5, b27, s21);
            s22 = convolution::mul_add::<T, FMA>(-a3, b28, s22);
            s23 = convolution::mul_add::<T, FMA>(-a4, b26, s23);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s10 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 18 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 18 * s + 4 + 1), s10);
                s12 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 16 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 16 * s + 4 + 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 15 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 15 * s + 4 + 1), s12);
                s18 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 28 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 28 * s + 4 + 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s18);
                s19 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 28 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 28 * s + 4 + 1), s19);
                s20 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 27 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 27 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 26 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 26 * s + 4 + 1), s20);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s21);
                s22 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s22);
                s23 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s23);
                s26 = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s26);
                s26 = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s26);
            }
        }
        h[10] = s10;
        h[12] = s12;
        h[18] = s18;
        h[19] = s19;
        h[20] = s20;
        h[21] = s21;
        h[22] = s22;
        h[23] = s23;
        h[26] = s26;
    } else if even {
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s5, mut t5, mut s6, mut t6, mut s7, mut t7, mut s8, mut t8) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p0, mut p2, mut p11, mut p13) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, a2, b2, a3, a4, a9, b11, b13) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 13 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a2, b2, s0);
            s1 = convolution::mul_add::<T, FMA>(a0, b0, s1);
            s2 = convolution::mul_add::<T, FMA>(a9, b11, s2);
            s3 = convolution::mul_add::<T, FMA>(a9, b13, s3);
            s4 = convolution::mul_add::<T, FMA>(a0, b11, s4);
            s5 = convolution::mul_add::<T, FMA>(a1, b11, s5);
            s6 = convolution::mul_add::<T, FMA>(a2, b13, s6);
            s7 = convolution::mul_add::<T, FMA>(a3, b11, s7);
            s8 = convolution::mul_add::<T, FMA>(a4, b11, s8);
            (b0, b2, b11, b13)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, a2, b2, a3, a4, a9, b11, b13) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 13 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a2, b2, s0);
            s1 = convolution::mul_add::<T, FMA>(a0, b0, s1);
            s2 = convolution::mul_add::<T, FMA>(a9, b11, s2);
            s3 = convolution::mul_add::<T, FMA>(a9, b13, s3);
            s4 = convolution::mul_add::<T, FMA>(a0, b11, s4);
            s5 = convolution::mul_add::<T, FMA>(a1, b11, s5);
            s6 = convolution::mul_add::<T, FMA>(a2, b13, s6);
            s7 = convolution::mul_add::<T, FMA>(a3, b11, s7);
            s8 = convolution::mul_add::<T, FMA>(a4, b11, s8);
            t0 = convolution::mul_add::<T, FMA>(a2, p2, t0);
            t1 = convolution::mul_add::<T, FMA>(a0, p0, t1);
            t2 = convolution::mul_add::<T, FMA>(a9, p11, t2);
            t3 = convolution::mul_add::<T, FMA>(a9, p13, t3);
            t4 = convolution::mul_add::<T, FMA>(a0, p11, t4);
            t5 = convolution::mul_add::<T, FMA>(a1, p11, t5);
            t6 = convolution::mul_add::<T, FMA>(a2, p13, t6);
            t7 = convolution::mul_add::<T, FMA>(a3, p11, t7);
            t8 = convolution::mul_add::<T, FMA>(a4, p11, t8);
            (p0, p2, p11, p13) = (b0, b2, b11, b13);
        }
        let mut p1 = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
            b1
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
            t0 = convolution::mul_add::<T, FMA>(a1, p1, t0);
            p1 = b1;
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[8] = s8;
        g[8] = t8;
        // Histories [9, 11, 13, 14, 15, 16, 17, 24, 25]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s9, mut t9, mut s11, mut t11, mut s13, mut t13, mut s14, mut t14, mut s15, mut t15, mut s16, mut t16, mut s17, mut t17, mut s24, mut t24, mut s25, mut t25) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p13, mut p14, mut p17, mut p25, mut p32) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a5, b13, a14, b14, a15, a16, b17, a24, b25, a26, a27, b32) = unsafe { (at(c, 4 + j), at(c, 5 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 14 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 16 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 24 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 27 * s + 4 + j), at(c, 32 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a5, b13, s9);
            s11 = convolution::mul_add::<T, FMA>(a0, b17, s11);
            s13 = convolution::mul_add::<T, FMA>(a0, b14, s13);
            s14 = convolution::mul_add::<T, FMA>(a24, b25, s14);
            s15 = convolution::mul_add::<T, FMA>(a14, b25, s15);
            s16 = convolution::mul_add::<T, FMA>(a15, b25, s16);
            s17 = convolution::mul_add::<T, FMA>(a16, b25, s17);
            s24 = convolution::mul_add::<T, FMA>(a26, b32, s24);
            s25 = convolution::mul_add::<T, FMA>(a27, b32, s25);
            (b13, b14, b17, b25, b32)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a5, b13, a14, b14, a15, a16, b17, a24, b25, a26, a27, b32) = unsafe { (at(c, 4 + j), at(c, 5 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 14 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 16 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 24 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 27 * s + 4 + j), at(c, 32 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a5, b13, s9);
            s11 = convolution::mul_add::<T, FMA>(a0, b17, s11);
            s13 = convolution::mul_add::<T, FMA>(a0, b14, s13);
            s14 = convolution::mul_add::<T, FMA>(a24, b25, s14);
            s15 = convolution::mul_add::<T, FMA>(a14, b25, s15);
            s16 = convolution::mul_add::<T, FMA>(a15, b25, s16);
            s17 = convolution::mul_add::<T, FMA>(a16, b25, s17);
            s24 = convolution::mul_add::<T, FMA>(a26, b32, s24);
            s25 = convolution::mul_add::<T, FMA>(a27, b32, s25);
            t9 = convolution::mul_add::<T, FMA>(a5, p13, t9);
            t11 = convolution::mul_add::<T, FMA>(a0, p17, t11);
            t13 = convolution::mul_add::<T, FMA>(a0, p14, t13);
            t14 = convolution::mul_add::<T, FMA>(a24, p25, t14);
            t15 = convolution::mul_add::<T, FMA>(a14, p25, t15);
            t16 = convolution::mul_add::<T, FMA>(a15, p25, t16);
            t17 = convolution::mul_add::<T, FMA>(a16, p25, t17);
            t24 = convolution::mul_add::<T, FMA>(a26, p32, t24);
            t25 = convolution::mul_add::<T, FMA>(a27, p32, t25);
            (p13, p14, p17, p25, p32) = (b13, b14, b17, b25, b32);
        }
        h[9] = s9;
        g[9] = t9;
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        h[14] = s14;
        g[14] = t14;
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[17] = s17;
        g[17] = t17;
        h[24] = s24;
        g[24] = t24;
        h[25] = s25;
        g[25] = t25;
        // Histories [10, 12, 18, 19, 20, 21, 22, 23, 26]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s10, mut t10, mut s12, mut t12, mut s18, mut t18, mut s19, mut t19, mut s20, mut t20, mut s21, mut t21, mut s22, mut t22, mut s23, mut t23, mut s26, mut t26) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p16, mut p19, mut p26, mut p27, mut p28, mut p32) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b16, b19, b26, b27, a28, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a2, b19, s10);
            s12 = convolution::mul_add::<T, FMA>(a2, b16, s12);
            s18 = convolution::mul_add::<T, FMA>(a1, b28, s18);
            s19 = convolution::mul_add::<T, FMA>(a2, b26, s19);
            s20 = convolution::mul_add::<T, FMA>(a0, b27, s20);
            s21 = convolution::mul_add::<T, FMA>(a4, b28, s21);
            s22 = convolution::mul_add::<T, FMA>(a5, b26, s22);
            s23 = convolution::mul_add::<T, FMA>(a3, b27, s23);
            s26 = convolution::mul_add::<T, FMA>(a28, b32, s26);
            (b16, b19, b26, b27, b28, b32)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b16, b19, b26, b27, a28, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a2, b19, s10);
            s12 = convolution::mul_add::<T, FMA>(a2, b16, s12);
            s18 = convolution::mul_add::<T, FMA>(a1, b28, s18);
            s19 = convolution::mul_add::<T, FMA>(a2, b26, s19);
            s20 = convolution::mul_add::<T, FMA>(a0, b27, s20);
            s21 = convolution::mul_add::<T, FMA>(a4, b28, s21);
            s22 = convolution::mul_add::<T, FMA>(a5, b26, s22);
            s23 = convolution::mul_add::<T, FMA>(a3, b27, s23);
            s26 = convolution::mul_add::<T, FMA>(a28, b32, s26);
            t10 = convolution::mul_add::<T, FMA>(a2, p19, t10);
            t12 = convolution::mul_add::<T, FMA>(a2, p16, t12);
            t18 = convolution::mul_add::<T, FMA>(a1, p28, t18);
            t19 = convolution::mul_add::<T, FMA>(a2, p26, t19);
            t20 = convolution::mul_add::<T, FMA>(a0, p27, t20);
            t21 = convolution::mul_add::<T, FMA>(a4, p28, t21);
            t22 = convolution::mul_add::<T, FMA>(a5, p26, t22);
            t23 = convolution::mul_add::<T, FMA>(a3, p27, t23);
            t26 = convolution::mul_add::<T, FMA>(a28, p32, t26);
            (p16, p19, p26, p27, p28, p32) = (b16, b19, b26, b27, b28, b32);
        }
        let (mut p15, mut p18, mut p26, mut p27, mut p28) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b15, b18, b26, b27, b28) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a1, b18, s10);
            s12 = convolution::mul_add::<T, FMA>(a1, b15, s12);
            s18 = convolution::mul_add::<T, FMA>(-a2, b27, s18);
            s19 = convolution::mul_add::<T, FMA>(-a0, b28, s19);
            s20 = convolution::mul_add::<T, FMA>(-a1, b26, s20);
            s21 = convolution::mul_add::<T, FMA>(-a5, b27, s21);
            s22 = convolution::mul_add::<T, FMA>(-a3, b28, s22);
            s23 = convolution::mul_add::<T, FMA>(-a4, b26, s23);
            (b15, b18, b26, b27, b28)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b15, b18, b26, b27, b28) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a1, b18, s10);
            s12 = convolution::mul_add::<T, FMA>(a1, b15, s12);
            s18 = convolution::mul_add::<T, FMA>(-a2, b27, s18);
            s19 = convolution::mul_add::<T, FMA>(-a0, b28, s19);
            s20 = convolution::mul_add::<T, FMA>(-a1, b26, s20);
            s21 = convolution::mul_add::<T, FMA>(-a5, b27, s21);
            s22 = convolution::mul_add::<T, FMA>(-a3, b28, s22);
            s23 = convolution::mul_add::<T, FMA>(-a4, b26, s23);
            t10 = convolution::mul_add::<T, FMA>(a1, p18, t10);
            t12 = convolution::mul_add::<T, FMA>(a1, p15, t12);
            t18 = convolution::mul_add::<T, FMA>(-a2, p27, t18);
            t19 = convolution::mul_add::<T, FMA>(-a0, p28, t19);
            t20 = convolution::mul_add::<T, FMA>(-a1, p26, t20);
            t21 = convolution::mul_add::<T, FMA>(-a5, p27, t21);
            t22 = convolution::mul_add::<T, FMA>(-a3, p28, t22);
            t23 = convolution::mul_add::<T, FMA>(-a4, p26, t23);
            (p15, p18, p26, p27, p28) = (b15, b18, b26, b27, b28);
        }
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
        h[26] = s26;
        g[26] = t26;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 18 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 18 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 16 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 16 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 14 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 14 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[24] = e;
        let mut e = g[25];
        e = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[25] = e;
        let mut e = g[26];
        e = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[26] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh_free`.
#[inline(always)]
fn routh_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 27],
    q: &[f64; 1],
) {
    let v7 = c[2 * s + 4 + k];
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[7 * s + 4], v7], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[4], c[4 + k], v8, h[1]);
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::reciprocal::<T, FMA>(c[10 * s + 4], v10, c[11 * s + 4], h[2]);
    c[11 * s + 4 + k] = v11;
    let v12 = v9;
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::reciprocal::<T, FMA>(c[12 * s + 4], v12, c[13 * s + 4], h[3]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[11 * s + 4], v11, h[4]);
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[11 * s + 4], v11, h[5]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[13 * s + 4], v13, h[6]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[11 * s + 4], v11, h[7]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[11 * s + 4], v11, h[8]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[13 * s + 4], v13, h[9]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[19 * s + 4], v19], [c[s + 4], c[s + 4 + k], c[18 * s + 4], v18], h[10]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[17 * s + 4], v17, v20, h[11]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[16 * s + 4], v16], [c[s + 4], c[s + 4 + k], c[15 * s + 4], v15], h[12]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[14 * s + 4], v14, v22, h[13]);
    c[23 * s + 4 + k] = v23;
    let v24 = -v23;
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::quotient::<T, FMA>(v21, c[24 * s + 4], v24, c[25 * s + 4], h[14]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::mul_plus::<T, FMA>(c[14 * s + 4], v14, c[25 * s + 4], v25, v17, h[15]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::mul_plus::<T, FMA>(c[15 * s + 4], v15, c[25 * s + 4], v25, v18, h[16]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[16 * s + 4], v16, c[25 * s + 4], v25, v19, h[17]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[28 * s + 4], v28], [c[2 * s + 4], c[2 * s + 4 + k], c[27 * s + 4], v27], h[18]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[26 * s + 4], v26], [c[4], c[4 + k], c[28 * s + 4], v28], h[19]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[27 * s + 4], v27], [c[s + 4], c[s + 4 + k], c[26 * s + 4], v26], h[20]);
    c[31 * s + 4 + k] = v31;
    let v32 = v31 * q[0];
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[28 * s + 4], v28], [c[5 * s + 4], c[5 * s + 4 + k], c[27 * s + 4], v27], h[21]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[26 * s + 4], v26], [c[3 * s + 4], c[3 * s + 4 + k], c[28 * s + 4], v28], h[22]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[27 * s + 4], v27], [c[4 * s + 4], c[4 * s + 4 + k], c[26 * s + 4], v26], h[23]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::mul_plus::<T, FMA>(c[26 * s + 4], v26, c[32 * s + 4], v32, v33, h[24]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::mul_plus::<T, FMA>(c[27 * s + 4], v27, c[32 * s + 4], v32, v34, h[25]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::mul_plus::<T, FMA>(c[28 * s + 4], v28, c[32 * s + 4], v32, v35, h[26]);
    c[38 * s + 4 + k] = v38;
}

/// The pass of order `k >= 1` of the kernel `routh_general`.
#[inline(always)]
fn routh_general<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 27],
    q: &[f64; 9],
) {
    let v7 = c[4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = c[s + 4 + k] * q[1];
    c[8 * s + 4 + k] = v8;
    let v9 = c[2 * s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[10 * s + 4], v10], [c[8 * s + 4], v8, c[8 * s + 4], v8], h[0]);
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[7 * s + 4], v7, v11, h[1]);
    c[12 * s + 4 + k] = v12;
    let v13 = v12 * q[3];
    c[13 * s + 4 + k] = v13;
    let v14 = v13;
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::reciprocal::<T, FMA>(c[14 * s + 4], v14, c[15 * s + 4], h[2]);
    c[15 * s + 4 + k] = v15;
    let v16 = v13;
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::reciprocal::<T, FMA>(c[16 * s + 4], v16, c[17 * s + 4], h[3]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[15 * s + 4], v15, h[4]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[15 * s + 4], v15, h[5]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[17 * s + 4], v17, h[6]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[15 * s + 4], v15, h[7]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[15 * s + 4], v15, h[8]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[17 * s + 4], v17, h[9]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[23 * s + 4], v23], [c[8 * s + 4], v8, c[22 * s + 4], v22], h[10]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[21 * s + 4], v21, v24, h[11]);
    c[25 * s + 4 + k] = v25;
    let v26 = v25 * q[4];
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[20 * s + 4], v20], [c[8 * s + 4], v8, c[19 * s + 4], v19], h[12]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[18 * s + 4], v18, v27, h[13]);
    c[28 * s + 4 + k] = v28;
    let v29 = v28 * q[5];
    c[29 * s + 4 + k] = v29;
    let v30 = -v29;
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v26, c[30 * s + 4], v30, c[31 * s + 4], h[14]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[18 * s + 4], v18, c[31 * s + 4], v31, v21, h[15]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::mul_plus::<T, FMA>(c[19 * s + 4], v19, c[31 * s + 4], v31, v22, h[16]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::mul_plus::<T, FMA>(c[20 * s + 4], v20, c[31 * s + 4], v31, v23, h[17]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[34 * s + 4], v34], [c[2 * s + 4], c[2 * s + 4 + k], c[33 * s + 4], v33], h[18]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[32 * s + 4], v32], [c[4], c[4 + k], c[34 * s + 4], v34], h[19]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[33 * s + 4], v33], [c[s + 4], c[s + 4 + k], c[32 * s + 4], v32], h[20]);
    c[37 * s + 4 + k] = v37;
    let v38 = v37 * q[6];
    c[38 * s + 4 + k] = v38;
    let v39 = c[s + 4 + k] * q[7];
    c[39 * s + 4 + k] = v39;
    let v40 = c[4 + k] * q[8];
    c[40 * s + 4 + k] = v40;
    let v41 = -v40;
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[34 * s + 4], v34], [c[5 * s + 4], c[5 * s + 4 + k], c[33 * s + 4], v33], h[21]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[32 * s + 4], v32], [c[3 * s + 4], c[3 * s + 4 + k], c[34 * s + 4], v34], h[22]);
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[33 * s + 4], v33], [c[4 * s + 4], c[4 * s + 4 + k], c[32 * s + 4], v32], h[23]);
    c[44 * s + 4 + k] = v44;
    let v45 = v39 + v42;
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::mul_plus::<T, FMA>(c[32 * s + 4], v32, c[38 * s + 4], v38, v45, h[24]);
    c[46 * s + 4 + k] = v46;
    let v47 = v41 + v43;
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::mul_plus::<T, FMA>(c[33 * s + 4], v33, c[38 * s + 4], v38, v47, h[25]);
    c[48 * s + 4 + k] = v48;
    let v49 = recurrence::mul_plus::<T, FMA>(c[34 * s + 4], v34, c[38 * s + 4], v38, v44, h[26]);
    c[49 * s + 4 + k] = v49;
}

/// The histories of the kernels `routh_general`, `routh_general_free` at order `k >= 1` ([`histories`]).
#[inline(always)]
fn routh_general_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 27],
    g: &mut [T; 27],
) {
    assert!(k + 4 <= s && c.len() >= 39 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8].
        let (mut s0, mut s1, mut s2, mut s3, mut s4, mut s5, mut s6, mut s7, mut s8) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a7, b7, a8, a9, b9, a13, b15, b17) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 13 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 17 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a9, b9, s0);
            s1 = convolution::mul_add::<T, FMA>(a7, b7, s1);
            s2 = convolution::mul_add::<T, FMA>(a13, b15, s2);
            s3 = convolution::mul_add::<T, FMA>(a13, b17, s3);
            s4 = convolution::mul_add::<T, FMA>(a7, b15, s4);
            s5 = convolution::mul_add::<T, FMA>(a8, b15, s5);
            s6 = convolution::mul_add::<T, FMA>(a9, b17, s6);
            s7 = convolution::mul_add::<T, FMA>(a3, b15, s7);
            s8 = convolution::mul_add::<T, FMA>(a4, b15, s8);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a8, b8) = unsafe { (at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a8, b8, s0);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), s0);
                s1 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s1);
                s2 = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), s2);
                s3 = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s3);
                s4 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), s5);
                s6 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s6);
                s7 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), s7);
                s8 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), s8);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[5] = s5;
        h[6] = s6;
        h[7] = s7;
        h[8] = s8;
        // Histories [9, 11, 13, 14, 15, 16, 17, 24, 25].
        let (mut s9, mut s11, mut s13, mut s14, mut s15, mut s16, mut s17, mut s24, mut s25) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a7, b17, a18, b18, a19, a20, b21, a30, b31, a32, a33, b38) = unsafe { (at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 19 * s + 4 + j), at(c, 20 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 30 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 32 * s + 4 + j), at(c, 33 * s + 4 + j), at(c, 38 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a5, b17, s9);
            s11 = convolution::mul_add::<T, FMA>(a7, b21, s11);
            s13 = convolution::mul_add::<T, FMA>(a7, b18, s13);
            s14 = convolution::mul_add::<T, FMA>(a30, b31, s14);
            s15 = convolution::mul_add::<T, FMA>(a18, b31, s15);
            s16 = convolution::mul_add::<T, FMA>(a19, b31, s16);
            s17 = convolution::mul_add::<T, FMA>(a20, b31, s17);
            s24 = convolution::mul_add::<T, FMA>(a32, b38, s24);
            s25 = convolution::mul_add::<T, FMA>(a33, b38, s25);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s9 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s9);
                s11 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), s11);
                s13 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), s13);
                s14 = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s14);
                s15 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s15);
                s16 = convolution::mul_add::<T, FMA>(at(c, 19 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 19 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s16);
                s17 = convolution::mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s17);
                s24 = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s24);
                s25 = convolution::mul_add::<T, FMA>(at(c, 33 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s25);
                s25 = convolution::mul_add::<T, FMA>(at(c, 33 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s25);
            }
        }
        h[9] = s9;
        h[11] = s11;
        h[13] = s13;
        h[14] = s14;
        h[15] = s15;
        h[16] = s16;
        h[17] = s17;
        h[24] = s24;
        h[25] = s25;
        // Histories [10, 12, 18, 19, 20, 21, 22, 23, 26].
        let (mut s10, mut s12, mut s18, mut s19, mut s20, mut s21, mut s22, mut s23, mut s26) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a9, b20, b23, b32, b33, a34, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 20 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a9, b23, s10);
            s12 = convolution::mul_add::<T, FMA>(a9, b20, s12);
            s18 = convolution::mul_add::<T, FMA>(a1, b34, s18);
            s19 = convolution::mul_add::<T, FMA>(a2, b32, s19);
            s20 = convolution::mul_add::<T, FMA>(a0, b33, s20);
            s21 = convolution::mul_add::<T, FMA>(a4, b34, s21);
            s22 = convolution::mul_add::<T, FMA>(a5, b32, s22);
            s23 = convolution::mul_add::<T, FMA>(a3, b33, s23);
            s26 = convolution::mul_add::<T, FMA>(a34, b38, s26);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a8, b19, b22, b32, b33, b34) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 19 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 34 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a8, b22, s10);
            s12 = convolution::mul_add::<T, FMA>(a8, b19, s12);
            s18 = convolution::mul_add::<T, FMA>(-a2, b33, s18);
            s19 = convolution::mul_add::<T, FMA>(-a0, b34, s19);
            s20 = convolution::mul_add::<T, FMA>(-a1, b32, s20);
            s21 = convolution::mul_add::<T, FMA>(-a5, b33, s21);
            s22 = convolution::mul_add::<T, FMA>(-a3, b34, s22);
            s23 = convolution::mul_add::<T, FMA>(-a4, b32, s23);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s10 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s10);
                s12 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 20 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 20 * s + 4 + 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), s12);
                s18 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 34 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 34 * s + 4 + 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s18);
                s19 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 34 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 34 * s + 4 + 1), s19);
                s20 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 33 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 33 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 32 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 32 * s + 4 + 1), s20);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s21);
                s22 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s22);
                s23 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s23);
                s26 = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s26);
                s26 = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s26);
            }
        }
        h[10] = s10;
        h[12] = s12;
        h[18] = s18;
        h[19] = s19;
        h[20] = s20;
        h[21] = s21;
        h[22] = s22;
        h[23] = s23;
        h[26] = s26;
    } else if even {
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s5, mut t5, mut s6, mut t6, mut s7, mut t7, mut s8, mut t8) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p9, mut p15, mut p17) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a7, b7, a8, a9, b9, a13, b15, b17) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 13 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 17 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a9, b9, s0);
            s1 = convolution::mul_add::<T, FMA>(a7, b7, s1);
            s2 = convolution::mul_add::<T, FMA>(a13, b15, s2);
            s3 = convolution::mul_add::<T, FMA>(a13, b17, s3);
            s4 = convolution::mul_add::<T, FMA>(a7, b15, s4);
            s5 = convolution::mul_add::<T, FMA>(a8, b15, s5);
            s6 = convolution::mul_add::<T, FMA>(a9, b17, s6);
            s7 = convolution::mul_add::<T, FMA>(a3, b15, s7);
            s8 = convolution::mul_add::<T, FMA>(a4, b15, s8);
            (b7, b9, b15, b17)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a7, b7, a8, a9, b9, a13, b15, b17) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 13 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 17 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a9, b9, s0);
            s1 = convolution::mul_add::<T, FMA>(a7, b7, s1);
            s2 = convolution::mul_add::<T, FMA>(a13, b15, s2);
            s3 = convolution::mul_add::<T, FMA>(a13, b17, s3);
            s4 = convolution::mul_add::<T, FMA>(a7, b15, s4);
            s5 = convolution::mul_add::<T, FMA>(a8, b15, s5);
            s6 = convolution::mul_add::<T, FMA>(a9, b17, s6);
            s7 = convolution::mul_add::<T, FMA>(a3, b15, s7);
            s8 = convolution::mul_add::<T, FMA>(a4, b15, s8);
            t0 = convolution::mul_add::<T, FMA>(a9, p9, t0);
            t1 = convolution::mul_add::<T, FMA>(a7, p7, t1);
            t2 = convolution::mul_add::<T, FMA>(a13, p15, t2);
            t3 = convolution::mul_add::<T, FMA>(a13, p17, t3);
            t4 = convolution::mul_add::<T, FMA>(a7, p15, t4);
            t5 = convolution::mul_add::<T, FMA>(a8, p15, t5);
            t6 = convolution::mul_add::<T, FMA>(a9, p17, t6);
            t7 = convolution::mul_add::<T, FMA>(a3, p15, t7);
            t8 = convolution::mul_add::<T, FMA>(a4, p15, t8);
            (p7, p9, p15, p17) = (b7, b9, b15, b17);
        }
        let mut p8 = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a8, b8) = unsafe { (at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a8, b8, s0);
            b8
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a8, b8) = unsafe { (at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a8, b8, s0);
            t0 = convolution::mul_add::<T, FMA>(a8, p8, t0);
            p8 = b8;
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[8] = s8;
        g[8] = t8;
        // Histories [9, 11, 13, 14, 15, 16, 17, 24, 25]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s9, mut t9, mut s11, mut t11, mut s13, mut t13, mut s14, mut t14, mut s15, mut t15, mut s16, mut t16, mut s17, mut t17, mut s24, mut t24, mut s25, mut t25) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p17, mut p18, mut p21, mut p31, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a7, b17, a18, b18, a19, a20, b21, a30, b31, a32, a33, b38) = unsafe { (at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 19 * s + 4 + j), at(c, 20 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 30 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 32 * s + 4 + j), at(c, 33 * s + 4 + j), at(c, 38 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a5, b17, s9);
            s11 = convolution::mul_add::<T, FMA>(a7, b21, s11);
            s13 = convolution::mul_add::<T, FMA>(a7, b18, s13);
            s14 = convolution::mul_add::<T, FMA>(a30, b31, s14);
            s15 = convolution::mul_add::<T, FMA>(a18, b31, s15);
            s16 = convolution::mul_add::<T, FMA>(a19, b31, s16);
            s17 = convolution::mul_add::<T, FMA>(a20, b31, s17);
            s24 = convolution::mul_add::<T, FMA>(a32, b38, s24);
            s25 = convolution::mul_add::<T, FMA>(a33, b38, s25);
            (b17, b18, b21, b31, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a7, b17, a18, b18, a19, a20, b21, a30, b31, a32, a33, b38) = unsafe { (at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 19 * s + 4 + j), at(c, 20 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 30 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 32 * s + 4 + j), at(c, 33 * s + 4 + j), at(c, 38 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a5, b17, s9);
            s11 = convolution::mul_add::<T, FMA>(a7, b21, s11);
            s13 = convolution::mul_add::<T, FMA>(a7, b18, s13);
            s14 = convolution::mul_add::<T, FMA>(a30, b31, s14);
            s15 = convolution::mul_add::<T, FMA>(a18, b31, s15);
            s16 = convolution::mul_add::<T, FMA>(a19, b31, s16);
            s17 = convolution::mul_add::<T, FMA>(a20, b31, s17);
            s24 = convolution::mul_add::<T, FMA>(a32, b38, s24);
            s25 = convolution::mul_add::<T, FMA>(a33, b38, s25);
            t9 = convolution::mul_add::<T, FMA>(a5, p17, t9);
            t11 = convolution::mul_add::<T, FMA>(a7, p21, t11);
            t13 = convolution::mul_add::<T, FMA>(a7, p18, t13);
            t14 = convolution::mul_add::<T, FMA>(a30, p31, t14);
            t15 = convolution::mul_add::<T, FMA>(a18, p31, t15);
            t16 = convolution::mul_add::<T, FMA>(a19, p31, t16);
            t17 = convolution::mul_add::<T, FMA>(a20, p31, t17);
            t24 = convolution::mul_add::<T, FMA>(a32, p38, t24);
            t25 = convolution::mul_add::<T, FMA>(a33, p38, t25);
            (p17, p18, p21, p31, p38) = (b17, b18, b21, b31, b38);
        }
        h[9] = s9;
        g[9] = t9;
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        h[14] = s14;
        g[14] = t14;
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[17] = s17;
        g[17] = t17;
        h[24] = s24;
        g[24] = t24;
        h[25] = s25;
        g[25] = t25;
        // Histories [10, 12, 18, 19, 20, 21, 22, 23, 26]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s10, mut t10, mut s12, mut t12, mut s18, mut t18, mut s19, mut t19, mut s20, mut t20, mut s21, mut t21, mut s22, mut t22, mut s23, mut t23, mut s26, mut t26) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p20, mut p23, mut p32, mut p33, mut p34, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a9, b20, b23, b32, b33, a34, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 20 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a9, b23, s10);
            s12 = convolution::mul_add::<T, FMA>(a9, b20, s12);
            s18 = convolution::mul_add::<T, FMA>(a1, b34, s18);
            s19 = convolution::mul_add::<T, FMA>(a2, b32, s19);
            s20 = convolution::mul_add::<T, FMA>(a0, b33, s20);
            s21 = convolution::mul_add::<T, FMA>(a4, b34, s21);
            s22 = convolution::mul_add::<T, FMA>(a5, b32, s22);
            s23 = convolution::mul_add::<T, FMA>(a3, b33, s23);
            s26 = convolution::mul_add::<T, FMA>(a34, b38, s26);
            (b20, b23, b32, b33, b34, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a9, b20, b23, b32, b33, a34, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 20 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a9, b23, s10);
            s12 = convolution::mul_add::<T, FMA>(a9, b20, s12);
            s18 = convolution::mul_add::<T, FMA>(a1, b34, s18);
            s19 = convolution::mul_add::<T, FMA>(a2, b32, s19);
            s20 = convolution::mul_add::<T, FMA>(a0, b33, s20);
            s21 = convolution::mul_add::<T, FMA>(a4, b34, s21);
            s22 = convolution::mul_add::<T, FMA>(a5, b32, s22);
            s23 = convolution::mul_add::<T, FMA>(a3, b33, s23);
            s26 = convolution::mul_add::<T, FMA>(a34, b38, s26);
            t10 = convolution::mul_add::<T, FMA>(a9, p23, t10);
            t12 = convolution::mul_add::<T, FMA>(a9, p20, t12);
            t18 = convolution::mul_add::<T, FMA>(a1, p34, t18);
            t19 = convolution::mul_add::<T, FMA>(a2, p32, t19);
            t20 = convolution::mul_add::<T, FMA>(a0, p33, t20);
            t21 = convolution::mul_add::<T, FMA>(a4, p34, t21);
            t22 = convolution::mul_add::<T, FMA>(a5, p32, t22);
            t23 = convolution::mul_add::<T, FMA>(a3, p33, t23);
            t26 = convolution::mul_add::<T, FMA>(a34, p38, t26);
            (p20, p23, p32, p33, p34, p38) = (b20, b23, b32, b33, b34, b38);
        }
        let (mut p19, mut p22, mut p32, mut p33, mut p34) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a8, b19, b22, b32, b33, b34) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 19 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 34 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a8, b22, s10);
            s12 = convolution::mul_add::<T, FMA>(a8, b19, s12);
            s18 = convolution::mul_add::<T, FMA>(-a2, b33, s18);
            s19 = convolution::mul_add::<T, FMA>(-a0, b34, s19);
            s20 = convolution::mul_add::<T, FMA>(-a1, b32, s20);
            s21 = convolution::mul_add::<T, FMA>(-a5, b33, s21);
            s22 = convolution::mul_add::<T, FMA>(-a3, b34, s22);
            s23 = convolution::mul_add::<T, FMA>(-a4, b32, s23);
            (b19, b22, b32, b33, b34)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a8, b19, b22, b32, b33, b34) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 19 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 34 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a8, b22, s10);
            s12 = convolution::mul_add::<T, FMA>(a8, b19, s12);
            s18 = convolution::mul_add::<T, FMA>(-a2, b33, s18);
            s19 = convolution::mul_add::<T, FMA>(-a0, b34, s19);
            s20 = convolution::mul_add::<T, FMA>(-a1, b32, s20);
            s21 = convolution::mul_add::<T, FMA>(-a5, b33, s21);
            s22 = convolution::mul_add::<T, FMA>(-a3, b34, s22);
            s23 = convolution::mul_add::<T, FMA>(-a4, b32, s23);
            t10 = convolution::mul_add::<T, FMA>(a8, p22, t10);
            t12 = convolution::mul_add::<T, FMA>(a8, p19, t12);
            t18 = convolution::mul_add::<T, FMA>(-a2, p33, t18);
            t19 = convolution::mul_add::<T, FMA>(-a0, p34, t19);
            t20 = convolution::mul_add::<T, FMA>(-a1, p32, t20);
            t21 = convolution::mul_add::<T, FMA>(-a5, p33, t21);
            t22 = convolution::mul_add::<T, FMA>(-a3, p34, t22);
            t23 = convolution::mul_add::<T, FMA>(-a4, p32, t23);
            (p19, p22, p32, p33, p34) = (b19, b22, b32, b33, b34);
        }
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
        h[26] = s26;
        g[26] = t26;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 13 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 20 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 20 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 19 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 19 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[24] = e;
        let mut e = g[25];
        e = convolution::mul_add::<T, FMA>(at(c, 33 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 33 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[25] = e;
        let mut e = g[26];
        e = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[26] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh_general_free`.
#[inline(always)]
fn routh_general_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 27],
    q: &[f64; 7],
) {
    let v7 = c[4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = c[s + 4 + k] * q[1];
    c[8 * s + 4 + k] = v8;
    let v9 = c[2 * s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[10 * s + 4], v10], [c[8 * s + 4], v8, c[8 * s + 4], v8], h[0]);
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[7 * s + 4], v7, v11, h[1]);
    c[12 * s + 4 + k] = v12;
    let v13 = v12 * q[3];
    c[13 * s + 4 + k] = v13;
    let v14 = v13;
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::reciprocal::<T, FMA>(c[14 * s + 4], v14, c[15 * s + 4], h[2]);
    c[15 * s + 4 + k] = v15;
    let v16 = v13;
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::reciprocal::<T, FMA>(c[16 * s + 4], v16, c[17 * s + 4], h[3]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[15 * s + 4], v15, h[4]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[15 * s + 4], v15, h[5]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[17 * s + 4], v17, h[6]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[15 * s + 4], v15, h[7]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[15 * s + 4], v15, h[8]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[17 * s + 4], v17, h[9]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[23 * s + 4], v23], [c[8 * s + 4], v8, c[22 * s + 4], v22], h[10]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[21 * s + 4], v21, v24, h[11]);
    c[25 * s + 4 + k] = v25;
    let v26 = v25 * q[4];
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[20 * s + 4], v20], [c[8 * s + 4], v8, c[19 * s + 4], v19], h[12]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[18 * s + 4], v18, v27, h[13]);
    c[28 * s + 4 + k] = v28;
    let v29 = v28 * q[5];
    c[29 * s + 4 + k] = v29;
    let v30 = -v29;
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v26, c[30 * s + 4], v30, c[31 * s + 4], h[14]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[18 * s + 4], v18, c[31 * s + 4], v31, v21, h[15]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::mul_plus::<T, FMA>(c[19 * s + 4], v19, c[31 * s + 4], v31, v22, h[16]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::mul_plus::<T, FMA>(c[20 * s + 4], v20, c[31 * s + 4], v31, v23, h[17]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[34 * s + 4], v34], [c[2 * s + 4], c[2 * s + 4 + k], c[33 * s + 4], v33], h[18]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[32 * s + 4], v32], [c[4], c[4 + k], c[34 * s + 4], v34], h[19]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[33 * s + 4], v33], [c[s + 4], c[s + 4 + k], c[32 * s + 4], v32], h[20]);
    c[37 * s + 4 + k] = v37;
    let v38 = v37 * q[6];
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[34 * s + 4], v34], [c[5 * s + 4], c[5 * s + 4 + k], c[33 * s + 4], v33], h[21]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[32 * s + 4], v32], [c[3 * s + 4], c[3 * s + 4 + k], c[34 * s + 4], v34], h[22]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[33 * s + 4], v33], [c[4 * s + 4], c[4 * s + 4 + k], c[32 * s + 4], v32], h[23]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::mul_plus::<T, FMA>(c[32 * s + 4], v32, c[38 * s + 4], v38, v39, h[24]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::mul_plus::<T, FMA>(c[33 * s + 4], v33, c[38 * s + 4], v38, v40, h[25]);
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::mul_plus::<T, FMA>(c[34 * s + 4], v34, c[38 * s + 4], v38, v41, h[26]);
    c[44 * s + 4 + k] = v44;
}

/// The pass of order `k >= 1` of the kernel `chaplygin`.
#[inline(always)]
fn chaplygin<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 25],
    _q: &[f64; 0],
) {
    let v7 = recurrence::dot_add::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[2 * s + 4], c[2 * s + 4 + k]], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[4], c[4 + k], v7, h[1]);
    c[8 * s + 4 + k] = v8;
    let v9 = v8;
    c[9 * s + 4 + k] = v9;
    let v10 = recurrence::reciprocal::<T, FMA>(c[9 * s + 4], v9, c[10 * s + 4], h[2]);
    c[10 * s + 4 + k] = v10;
    let v11 = v8;
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::reciprocal::<T, FMA>(c[11 * s + 4], v11, c[12 * s + 4], h[3]);
    c[12 * s + 4 + k] = v12;
    let v13 = v8;
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::reciprocal::<T, FMA>(c[13 * s + 4], v13, c[14 * s + 4], h[4]);
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[10 * s + 4], v10, h[5]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[12 * s + 4], v12, h[6]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[14 * s + 4], v14, h[7]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[10 * s + 4], v10, h[8]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[12 * s + 4], v12, h[9]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[14 * s + 4], v14, h[10]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::dot_add::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[20 * s + 4], v20], [c[s + 4], c[s + 4 + k], c[19 * s + 4], v19], h[11]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[18 * s + 4], v18, v21, h[12]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::dot_add::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[17 * s + 4], v17], [c[s + 4], c[s + 4 + k], c[16 * s + 4], v16], h[13]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[15 * s + 4], v15, v23, h[14]);
    c[24 * s + 4 + k] = v24;
    let v25 = -v24;
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::quotient::<T, FMA>(v22, c[25 * s + 4], v25, c[26 * s + 4], h[15]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::mul_plus::<T, FMA>(c[15 * s + 4], v15, c[26 * s + 4], v26, v18, h[16]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[16 * s + 4], v16, c[26 * s + 4], v26, v19, h[17]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::mul_plus::<T, FMA>(c[17 * s + 4], v17, c[26 * s + 4], v26, v20, h[18]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[29 * s + 4], v29], [c[2 * s + 4], c[2 * s + 4 + k], c[28 * s + 4], v28], h[19]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[27 * s + 4], v27], [c[4], c[4 + k], c[29 * s + 4], v29], h[20]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[28 * s + 4], v28], [c[s + 4], c[s + 4 + k], c[27 * s + 4], v27], h[21]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[29 * s + 4], v29], [c[5 * s + 4], c[5 * s + 4 + k], c[28 * s + 4], v28], h[22]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[27 * s + 4], v27], [c[3 * s + 4], c[3 * s + 4 + k], c[29 * s + 4], v29], h[23]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[28 * s + 4], v28], [c[4 * s + 4], c[4 * s + 4 + k], c[27 * s + 4], v27], h[24]);
    c[35 * s + 4 + k] = v35;
}

/// The histories of the kernels `chaplygin` at order `k >= 1` ([`histories`]).
#[inline(always)]
fn chaplygin_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 25],
    g: &mut [T; 25],
) {
    assert!(k + 4 <= s && c.len() >= 30 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8].
        let (mut s0, mut s1, mut s2, mut s3, mut s4, mut s5, mut s6, mut s7, mut s8) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, a2, b2, a3, a8, b10, b12, b14) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a2, b2, s0);
            s1 = convolution::mul_add::<T, FMA>(a0, b0, s1);
            s2 = convolution::mul_add::<T, FMA>(a8, b10, s2);
            s3 = convolution::mul_add::<T, FMA>(a8, b12, s3);
            s4 = convolution::mul_add::<T, FMA>(a8, b14, s4);
            s5 = convolution::mul_add::<T, FMA>(a0, b10, s5);
            s6 = convolution::mul_add::<T, FMA>(a1, b12, s6);
            s7 = convolution::mul_add::<T, FMA>(a2, b14, s7);
            s8 = convolution::mul_add::<T, FMA>(a3, b10, s8);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), s0);
                s1 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), s1);
                s2 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), s2);
                s3 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), s3);
                s4 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 10 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 10 * s + 4 + 1), s5);
                s6 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 12 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 12 * s + 4 + 1), s6);
                s7 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), s7);
                s8 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), s8);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[5] = s5;
        h[6] = s6;
        h[7] = s7;
        h[8] = s8;
        // Histories [9, 10, 12, 14, 15, 16, 17, 18, 21].
        let (mut s9, mut s10, mut s12, mut s14, mut s15, mut s16, mut s17, mut s18, mut s21) = (zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a4, a5, b12, b14, a15, b15, a16, a17, b18, a25, b26, b28) = unsafe { (at(c, 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 16 * s + 4 + j), at(c, 17 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 25 * s + 4 + j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a4, b12, s9);
            s10 = convolution::mul_add::<T, FMA>(a5, b14, s10);
            s12 = convolution::mul_add::<T, FMA>(a0, b18, s12);
            s14 = convolution::mul_add::<T, FMA>(a0, b15, s14);
            s15 = convolution::mul_add::<T, FMA>(a25, b26, s15);
            s16 = convolution::mul_add::<T, FMA>(a15, b26, s16);
            s17 = convolution::mul_add::<T, FMA>(a16, b26, s17);
            s18 = convolution::mul_add::<T, FMA>(a17, b26, s18);
            s21 = convolution::mul_add::<T, FMA>(a0, b28, s21);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b27) = unsafe { (at(c, s + 4 + j), at(c, 27 * s + 4 + k - j)) };
            s21 = convolution::mul_add::<T, FMA>(-a1, b27, s21);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s9 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), s9);
                s10 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), s10);
                s12 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 18 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 18 * s + 4 + 1), s12);
                s14 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 15 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 15 * s + 4 + 1), s14);
                s15 = convolution::mul_add::<T, FMA>(at(c, 25 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, 25 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s15);
                s16 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s16);
                s17 = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s17);
                s18 = convolution::mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s18);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 28 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 28 * s + 4 + 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 27 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 27 * s + 4 + 1), s21);
            }
        }
        h[9] = s9;
        h[10] = s10;
        h[12] = s12;
        h[14] = s14;
        h[15] = s15;
        h[16] = s16;
        h[17] = s17;
        h[18] = s18;
        h[21] = s21;
        // Histories [11, 13, 19, 20, 22, 23, 24].
        let (mut s11, mut s13, mut s19, mut s20, mut s22, mut s23, mut s24) = (zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a3, a4, a5, b17, b20, b27, b28, b29) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 20 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a2, b20, s11);
            s13 = convolution::mul_add::<T, FMA>(a2, b17, s13);
            s19 = convolution::mul_add::<T, FMA>(a1, b29, s19);
            s20 = convolution::mul_add::<T, FMA>(a2, b27, s20);
            s22 = convolution::mul_add::<T, FMA>(a4, b29, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b27, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b28, s24);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b16, b19, b27, b28, b29) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a1, b19, s11);
            s13 = convolution::mul_add::<T, FMA>(a1, b16, s13);
            s19 = convolution::mul_add::<T, FMA>(-a2, b28, s19);
            s20 = convolution::mul_add::<T, FMA>(-a0, b29, s20);
            s22 = convolution::mul_add::<T, FMA>(-a5, b28, s22);
            s23 = convolution::mul_add::<T, FMA>(-a3, b29, s23);
            s24 = convolution::mul_add::<T, FMA>(-a4, b27, s24);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s11 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 20 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 20 * s + 4 + 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 19 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 19 * s + 4 + 1), s11);
                s13 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 16 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 16 * s + 4 + 1), s13);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 29 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 29 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s19);
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 29 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 29 * s + 4 + 1), s20);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s22);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), s23);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s24);
            }
        }
        h[11] = s11;
        h[13] = s13;
        h[19] = s19;
        h[20] = s20;
        h[22] = s22;
        h[23] = s23;
        h[24] = s24;
    } else if even {
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s5, mut t5, mut s6, mut t6, mut s7, mut t7, mut s8, mut t8) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p0, mut p2, mut p10, mut p12, mut p14) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, a2, b2, a3, a8, b10, b12, b14) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a2, b2, s0);
            s1 = convolution::mul_add::<T, FMA>(a0, b0, s1);
            s2 = convolution::mul_add::<T, FMA>(a8, b10, s2);
            s3 = convolution::mul_add::<T, FMA>(a8, b12, s3);
            s4 = convolution::mul_add::<T, FMA>(a8, b14, s4);
            s5 = convolution::mul_add::<T, FMA>(a0, b10, s5);
            s6 = convolution::mul_add::<T, FMA>(a1, b12, s6);
            s7 = convolution::mul_add::<T, FMA>(a2, b14, s7);
            s8 = convolution::mul_add::<T, FMA>(a3, b10, s8);
            (b0, b2, b10, b12, b14)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, a2, b2, a3, a8, b10, b12, b14) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a2, b2, s0);
            s1 = convolution::mul_add::<T, FMA>(a0, b0, s1);
            s2 = convolution::mul_add::<T, FMA>(a8, b10, s2);
            s3 = convolution::mul_add::<T, FMA>(a8, b12, s3);
            s4 = convolution::mul_add::<T, FMA>(a8, b14, s4);
            s5 = convolution::mul_add::<T, FMA>(a0, b10, s5);
            s6 = convolution::mul_add::<T, FMA>(a1, b12, s6);
            s7 = convolution::mul_add::<T, FMA>(a2, b14, s7);
            s8 = convolution::mul_add::<T, FMA>(a3, b10, s8);
            t0 = convolution::mul_add::<T, FMA>(a2, p2, t0);
            t1 = convolution::mul_add::<T, FMA>(a0, p0, t1);
            t2 = convolution::mul_add::<T, FMA>(a8, p10, t2);
            t3 = convolution::mul_add::<T, FMA>(a8, p12, t3);
            t4 = convolution::mul_add::<T, FMA>(a8, p14, t4);
            t5 = convolution::mul_add::<T, FMA>(a0, p10, t5);
            t6 = convolution::mul_add::<T, FMA>(a1, p12, t6);
            t7 = convolution::mul_add::<T, FMA>(a2, p14, t7);
            t8 = convolution::mul_add::<T, FMA>(a3, p10, t8);
            (p0, p2, p10, p12, p14) = (b0, b2, b10, b12, b14);
        }
        let mut p1 = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
            b1
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
            t0 = convolution::mul_add::<T, FMA>(a1, p1, t0);
            p1 = b1;
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[8] = s8;
        g[8] = t8;
        // Histories [9, 10, 12, 14, 15, 16, 17, 18, 21]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s9, mut t9, mut s10, mut t10, mut s12, mut t12, mut s14, mut t14, mut s15, mut t15, mut s16, mut t16, mut s17, mut t17, mut s18, mut t18, mut s21, mut t21) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p12, mut p14, mut p15, mut p18, mut p26, mut p28) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a4, a5, b12, b14, a15, b15, a16, a17, b18, a25, b26, b28) = unsafe { (at(c, 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 16 * s + 4 + j), at(c, 17 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 25 * s + 4 + j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a4, b12, s9);
            s10 = convolution::mul_add::<T, FMA>(a5, b14, s10);
            s12 = convolution::mul_add::<T, FMA>(a0, b18, s12);
            s14 = convolution::mul_add::<T, FMA>(a0, b15, s14);
            s15 = convolution::mul_add::<T, FMA>(a25, b26, s15);
            s16 = convolution::mul_add::<T, FMA>(a15, b26, s16);
            s17 = convolution::mul_add::<T, FMA>(a16, b26, s17);
            s18 = convolution::mul_add::<T, FMA>(a17, b26, s18);
            s21 = convolution::mul_add::<T, FMA>(a0, b28, s21);
            (b12, b14, b15, b18, b26, b28)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a4, a5, b12, b14, a15, b15, a16, a17, b18, a25, b26, b28) = unsafe { (at(c, 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 16 * s + 4 + j), at(c, 17 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 25 * s + 4 + j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + k - j)) };
            s9 = convolution::mul_add::<T, FMA>(a4, b12, s9);
            s10 = convolution::mul_add::<T, FMA>(a5, b14, s10);
            s12 = convolution::mul_add::<T, FMA>(a0, b18, s12);
            s14 = convolution::mul_add::<T, FMA>(a0, b15, s14);
            s15 = convolution::mul_add::<T, FMA>(a25, b26, s15);
            s16 = convolution::mul_add::<T, FMA>(a15, b26, s16);
            s17 = convolution::mul_add::<T, FMA>(a16, b26, s17);
            s18 = convolution::mul_add::<T, FMA>(a17, b26, s18);
            s21 = convolution::mul_add::<T, FMA>(a0, b28, s21);
            t9 = convolution::mul_add::<T, FMA>(a4, p12, t9);
            t10 = convolution::mul_add::<T, FMA>(a5, p14, t10);
            t12 = convolution::mul_add::<T, FMA>(a0, p18, t12);
            t14 = convolution::mul_add::<T, FMA>(a0, p15, t14);
            t15 = convolution::mul_add::<T, FMA>(a25, p26, t15);
            t16 = convolution::mul_add::<T, FMA>(a15, p26, t16);
            t17 = convolution::mul_add::<T, FMA>(a16, p26, t17);
            t18 = convolution::mul_add::<T, FMA>(a17, p26, t18);
            t21 = convolution::mul_add::<T, FMA>(a0, p28, t21);
            (p12, p14, p15, p18, p26, p28) = (b12, b14, b15, b18, b26, b28);
        }
        let mut p27 = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b27) = unsafe { (at(c, s + 4 + j), at(c, 27 * s + 4 + k - j)) };
            s21 = convolution::mul_add::<T, FMA>(-a1, b27, s21);
            b27
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b27) = unsafe { (at(c, s + 4 + j), at(c, 27 * s + 4 + k - j)) };
            s21 = convolution::mul_add::<T, FMA>(-a1, b27, s21);
            t21 = convolution::mul_add::<T, FMA>(-a1, p27, t21);
            p27 = b27;
        }
        h[9] = s9;
        g[9] = t9;
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        h[14] = s14;
        g[14] = t14;
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[17] = s17;
        g[17] = t17;
        h[18] = s18;
        g[18] = t18;
        h[21] = s21;
        g[21] = t21;
        // Histories [11, 13, 19, 20, 22, 23, 24]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s11, mut t11, mut s13, mut t13, mut s19, mut t19, mut s20, mut t20, mut s22, mut t22, mut s23, mut t23, mut s24, mut t24) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p17, mut p20, mut p27, mut p28, mut p29) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a3, a4, a5, b17, b20, b27, b28, b29) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 20 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a2, b20, s11);
            s13 = convolution::mul_add::<T, FMA>(a2, b17, s13);
            s19 = convolution::mul_add::<T, FMA>(a1, b29, s19);
            s20 = convolution::mul_add::<T, FMA>(a2, b27, s20);
            s22 = convolution::mul_add::<T, FMA>(a4, b29, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b27, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b28, s24);
            (b17, b20, b27, b28, b29)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a3, a4, a5, b17, b20, b27, b28, b29) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 20 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a2, b20, s11);
            s13 = convolution::mul_add::<T, FMA>(a2, b17, s13);
            s19 = convolution::mul_add::<T, FMA>(a1, b29, s19);
            s20 = convolution::mul_add::<T, FMA>(a2, b27, s20);
            s22 = convolution::mul_add::<T, FMA>(a4, b29, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b27, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b28, s24);
            t11 = convolution::mul_add::<T, FMA>(a2, p20, t11);
            t13 = convolution::mul_add::<T, FMA>(a2, p17, t13);
            t19 = convolution::mul_add::<T, FMA>(a1, p29, t19);
            t20 = convolution::mul_add::<T, FMA>(a2, p27, t20);
            t22 = convolution::mul_add::<T, FMA>(a4, p29, t22);
            t23 = convolution::mul_add::<T, FMA>(a5, p27, t23);
            t24 = convolution::mul_add::<T, FMA>(a3, p28, t24);
            (p17, p20, p27, p28, p29) = (b17, b20, b27, b28, b29);
        }
        let (mut p16, mut p19, mut p27, mut p28, mut p29) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b16, b19, b27, b28, b29) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a1, b19, s11);
            s13 = convolution::mul_add::<T, FMA>(a1, b16, s13);
            s19 = convolution::mul_add::<T, FMA>(-a2, b28, s19);
            s20 = convolution::mul_add::<T, FMA>(-a0, b29, s20);
            s22 = convolution::mul_add::<T, FMA>(-a5, b28, s22);
            s23 = convolution::mul_add::<T, FMA>(-a3, b29, s23);
            s24 = convolution::mul_add::<T, FMA>(-a4, b27, s24);
            (b16, b19, b27, b28, b29)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b16, b19, b27, b28, b29) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a1, b19, s11);
            s13 = convolution::mul_add::<T, FMA>(a1, b16, s13);
            s19 = convolution::mul_add::<T, FMA>(-a2, b28, s19);
            s20 = convolution::mul_add::<T, FMA>(-a0, b29, s20);
            s22 = convolution::mul_add::<T, FMA>(-a5, b28, s22);
            s23 = convolution::mul_add::<T, FMA>(-a3, b29, s23);
            s24 = convolution::mul_add::<T, FMA>(-a4, b27, s24);
            t11 = convolution::mul_add::<T, FMA>(a1, p19, t11);
            t13 = convolution::mul_add::<T, FMA>(a1, p16, t13);
            t19 = convolution::mul_add::<T, FMA>(-a2, p28, t19);
            t20 = convolution::mul_add::<T, FMA>(-a0, p29, t20);
            t22 = convolution::mul_add::<T, FMA>(-a5, p28, t22);
            t23 = convolution::mul_add::<T, FMA>(-a3, p29, t23);
            t24 = convolution::mul_add::<T, FMA>(-a4, p27, t24);
            (p16, p19, p27, p28, p29) = (b16, b19, b27, b28, b29);
        }
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
        h[24] = s24;
        g[24] = t24;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 10 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 10 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 12 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 12 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 20 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 20 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 19 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 19 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 18 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 18 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 16 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 16 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, 25 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 25 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 16 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        h[24] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `ball`.
#[inline(always)]
fn ball<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 28],
    q: &[f64; 15],
) {
    let v7 = c[4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = v7;
    c[8 * s + 4 + k] = v8;
    let v9 = c[s + 4 + k] * q[1];
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = c[2 * s + 4 + k] * q[2];
    c[11 * s + 4 + k] = v11;
    let v12 = v11;
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::dot_add::<T, FMA>([c[12 * s + 4], v12, c[12 * s + 4], v12], [c[10 * s + 4], v10, c[10 * s + 4], v10], h[0]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[8 * s + 4], v8, v13, h[1]);
    c[14 * s + 4 + k] = v14;
    let v15 = v14 * q[3];
    c[15 * s + 4 + k] = v15;
    let v16 = v15;
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::reciprocal::<T, FMA>(c[16 * s + 4], v16, c[17 * s + 4], h[2]);
    c[17 * s + 4 + k] = v17;
    let v18 = v15;
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::reciprocal::<T, FMA>(c[18 * s + 4], v18, c[19 * s + 4], h[3]);
    c[19 * s + 4 + k] = v19;
    let v20 = v15;
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::reciprocal::<T, FMA>(c[20 * s + 4], v20, c[21 * s + 4], h[4]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[17 * s + 4], v17, h[5]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[19 * s + 4], v19, h[6]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::product::<T, FMA>(c[12 * s + 4], v12, c[21 * s + 4], v21, h[7]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[17 * s + 4], v17, h[8]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[19 * s + 4], v19, h[9]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[21 * s + 4], v21, h[10]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::dot_add::<T, FMA>([c[12 * s + 4], v12, c[27 * s + 4], v27], [c[10 * s + 4], v10, c[26 * s + 4], v26], h[11]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[25 * s + 4], v25, v28, h[12]);
    c[29 * s + 4 + k] = v29;
    let v30 = v29 * q[4];
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_add::<T, FMA>([c[12 * s + 4], v12, c[24 * s + 4], v24], [c[10 * s + 4], v10, c[23 * s + 4], v23], h[13]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[22 * s + 4], v22, v31, h[14]);
    c[32 * s + 4 + k] = v32;
    let v33 = v32 * q[5];
    c[33 * s + 4 + k] = v33;
    let v34 = -v33;
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::quotient::<T, FMA>(v30, c[34 * s + 4], v34, c[35 * s + 4], h[15]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::mul_plus::<T, FMA>(c[22 * s + 4], v22, c[35 * s + 4], v35, v25, h[16]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::mul_plus::<T, FMA>(c[23 * s + 4], v23, c[35 * s + 4], v35, v26, h[17]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::mul_plus::<T, FMA>(c[24 * s + 4], v24, c[35 * s + 4], v35, v27, h[18]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[38 * s + 4], v38], [c[2 * s + 4], c[2 * s + 4 + k], c[37 * s + 4], v37], h[19]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[36 * s + 4], v36], [c[4], c[4 + k], c[38 * s + 4], v38], h[20]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[37 * s + 4], v37], [c[s + 4], c[s + 4 + k], c[36 * s + 4], v36], h[21]);
    c[41 * s + 4 + k] = v41;
    let v42 = v39 * q[6];
    c[42 * s + 4 + k] = v42;
    let v43 = v40 * q[7];
    c[43 * s + 4 + k] = v43;
    let v44 = v42 + v43;
    c[44 * s + 4 + k] = v44;
    let v45 = v41 * q[8];
    c[45 * s + 4 + k] = v45;
    let v46 = v44 + v45;
    c[46 * s + 4 + k] = v46;
    let v47 = c[s + 4 + k] * q[9];
    c[47 * s + 4 + k] = v47;
    let v48 = c[2 * s + 4 + k] * q[10];
    c[48 * s + 4 + k] = v48;
    let v49 = v47 - v48;
    c[49 * s + 4 + k] = v49;
    let v50 = c[2 * s + 4 + k] * q[11];
    c[50 * s + 4 + k] = v50;
    let v51 = c[4 + k] * q[12];
    c[51 * s + 4 + k] = v51;
    let v52 = v50 - v51;
    c[52 * s + 4 + k] = v52;
    let v53 = c[4 + k] * q[13];
    c[53 * s + 4 + k] = v53;
    let v54 = c[s + 4 + k] * q[14];
    c[54 * s + 4 + k] = v54;
    let v55 = v53 - v54;
    c[55 * s + 4 + k] = v55;
    let v56 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[38 * s + 4], v38], [c[5 * s + 4], c[5 * s + 4 + k], c[37 * s + 4], v37], h[22]);
    c[56 * s + 4 + k] = v56;
    let v57 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[36 * s + 4], v36], [c[3 * s + 4], c[3 * s + 4 + k], c[38 * s + 4], v38], h[23]);
    c[57 * s + 4 + k] = v57;
    let v58 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[37 * s + 4], v37], [c[4 * s + 4], c[4 * s + 4 + k], c[36 * s + 4], v36], h[24]);
    c[58 * s + 4 + k] = v58;
    let v59 = v49 + v56;
    c[59 * s + 4 + k] = v59;
    let v60 = recurrence::mul_plus::<T, FMA>(c[36 * s + 4], v36, c[46 * s + 4], v46, v59, h[25]);
    c[60 * s + 4 + k] = v60;
    let v61 = v52 + v57;
    c[61 * s + 4 + k] = v61;
    let v62 = recurrence::mul_plus::<T, FMA>(c[37 * s + 4], v37, c[46 * s + 4], v46, v61, h[26]);
    c[62 * s + 4 + k] = v62;
    let v63 = v55 + v58;
    c[63 * s + 4 + k] = v63;
    let v64 = recurrence::mul_plus::<T, FMA>(c[38 * s + 4], v38, c[46 * s + 4], v46, v63, h[27]);
    c[64 * s + 4 + k] = v64;
}

/// The histories of the kernels `ball` at order `k >= 1` ([`histories`]).
#[inline(always)]
fn ball_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 28],
    g: &mut [T; 28],
) {
    assert!(k + 4 <= s && c.len() >= 47 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8, 9].
        let (mut s0, mut s1, mut s2, mut s3, mut s4, mut s5, mut s6, mut s7, mut s8, mut s9) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a7, b7, a9, a11, b11, a15, b17, b19, b21) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 21 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a11, b11, s0);
            s1 = convolution::mul_add::<T, FMA>(a7, b7, s1);
            s2 = convolution::mul_add::<T, FMA>(a15, b17, s2);
            s3 = convolution::mul_add::<T, FMA>(a15, b19, s3);
            s4 = convolution::mul_add::<T, FMA>(a15, b21, s4);
            s5 = convolution::mul_add::<T, FMA>(a7, b17, s5);
            s6 = convolution::mul_add::<T, FMA>(a9, b19, s6);
            s7 = convolution::mul_add::<T, FMA>(a11, b21, s7);
            s8 = convolution::mul_add::<T, FMA>(a3, b17, s8);
            s9 = convolution::mul_add::<T, FMA>(a4, b19, s9);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a9, b9) = unsafe { (at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a9, b9, s0);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s0);
                s1 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s1);
                s2 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s2);
                s3 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), s3);
                s4 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s5);
                s6 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), s6);
                s7 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), s7);
                s8 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s8);
                s9 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), s9);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[5] = s5;
        h[6] = s6;
        h[7] = s7;
        h[8] = s8;
        h[9] = s9;
        // Histories [10, 12, 14, 15, 16, 17, 18, 25, 26, 27].
        let (mut s10, mut s12, mut s14, mut s15, mut s16, mut s17, mut s18, mut s25, mut s26, mut s27) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a7, b21, a22, b22, a23, a24, b25, a34, b35, a36, a37, a38, b46) = unsafe { (at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 22 * s + 4 + j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + j), at(c, 24 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 35 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 37 * s + 4 + j), at(c, 38 * s + 4 + j), at(c, 46 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a5, b21, s10);
            s12 = convolution::mul_add::<T, FMA>(a7, b25, s12);
            s14 = convolution::mul_add::<T, FMA>(a7, b22, s14);
            s15 = convolution::mul_add::<T, FMA>(a34, b35, s15);
            s16 = convolution::mul_add::<T, FMA>(a22, b35, s16);
            s17 = convolution::mul_add::<T, FMA>(a23, b35, s17);
            s18 = convolution::mul_add::<T, FMA>(a24, b35, s18);
            s25 = convolution::mul_add::<T, FMA>(a36, b46, s25);
            s26 = convolution::mul_add::<T, FMA>(a37, b46, s26);
            s27 = convolution::mul_add::<T, FMA>(a38, b46, s27);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s10 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), s10);
                s12 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s12);
                s14 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s14);
                s15 = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), s15);
                s16 = convolution::mul_add::<T, FMA>(at(c, 22 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 22 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), s16);
                s17 = convolution::mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), s17);
                s18 = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), s18);
                s25 = convolution::mul_add::<T, FMA>(at(c, 36 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), s25);
                s25 = convolution::mul_add::<T, FMA>(at(c, 36 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), s25);
                s26 = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), s26);
                s26 = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), s26);
                s27 = convolution::mul_add::<T, FMA>(at(c, 38 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), s27);
                s27 = convolution::mul_add::<T, FMA>(at(c, 38 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), s27);
            }
        }
        h[10] = s10;
        h[12] = s12;
        h[14] = s14;
        h[15] = s15;
        h[16] = s16;
        h[17] = s17;
        h[18] = s18;
        h[25] = s25;
        h[26] = s26;
        h[27] = s27;
        // Histories [11, 13, 19, 20, 21, 22, 23, 24].
        let (mut s11, mut s13, mut s19, mut s20, mut s21, mut s22, mut s23, mut s24) = (zero, zero, zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a11, b24, b27, b36, b37, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 37 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a11, b27, s11);
            s13 = convolution::mul_add::<T, FMA>(a11, b24, s13);
            s19 = convolution::mul_add::<T, FMA>(a1, b38, s19);
            s20 = convolution::mul_add::<T, FMA>(a2, b36, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b37, s21);
            s22 = convolution::mul_add::<T, FMA>(a4, b38, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b36, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b37, s24);
        }
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a9, b23, b26, b36, b37, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 23 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 37 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a9, b26, s11);
            s13 = convolution::mul_add::<T, FMA>(a9, b23, s13);
            s19 = convolution::mul_add::<T, FMA>(-a2, b37, s19);
            s20 = convolution::mul_add::<T, FMA>(-a0, b38, s20);
            s21 = convolution::mul_add::<T, FMA>(-a1, b36, s21);
            s22 = convolution::mul_add::<T, FMA>(-a5, b37, s22);
            s23 = convolution::mul_add::<T, FMA>(-a3, b38, s23);
            s24 = convolution::mul_add::<T, FMA>(-a4, b36, s24);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s11 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s11);
                s13 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), s13);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 38 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 38 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 37 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 37 * s + 4 + 1), s19);
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 38 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 38 * s + 4 + 1), s20);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 37 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 37 * s + 4 + 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 36 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 36 * s + 4 + 1), s21);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 37 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 37 * s + 4 + 1), s22);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s23);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 37 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 37 * s + 4 + 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s24);
            }
        }
        h[11] = s11;
        h[13] = s13;
        h[19] = s19;
        h[20] = s20;
        h[21] = s21;
        h[22] = s22;
        h[23] = s23;
        h[24] = s24;
    } else if even {
        // Histories [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s5, mut t5, mut s6, mut t6, mut s7, mut t7, mut s8, mut t8, mut s9, mut t9) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p11, mut p17, mut p19, mut p21) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a7, b7, a9, a11, b11, a15, b17, b19, b21) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 21 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a11, b11, s0);
            s1 = convolution::mul_add::<T, FMA>(a7, b7, s1);
            s2 = convolution::mul_add::<T, FMA>(a15, b17, s2);
            s3 = convolution::mul_add::<T, FMA>(a15, b19, s3);
            s4 = convolution::mul_add::<T, FMA>(a15, b21, s4);
            s5 = convolution::mul_add::<T, FMA>(a7, b17, s5);
            s6 = convolution::mul_add::<T, FMA>(a9, b19, s6);
            s7 = convolution::mul_add::<T, FMA>(a11, b21, s7);
            s8 = convolution::mul_add::<T, FMA>(a3, b17, s8);
            s9 = convolution::mul_add::<T, FMA>(a4, b19, s9);
            (b7, b11, b17, b19, b21)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a7, b7, a9, a11, b11, a15, b17, b19, b21) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 15 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 21 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a11, b11, s0);
            s1 = convolution::mul_add::<T, FMA>(a7, b7, s1);
            s2 = convolution::mul_add::<T, FMA>(a15, b17, s2);
            s3 = convolution::mul_add::<T, FMA>(a15, b19, s3);
            s4 = convolution::mul_add::<T, FMA>(a15, b21, s4);
            s5 = convolution::mul_add::<T, FMA>(a7, b17, s5);
            s6 = convolution::mul_add::<T, FMA>(a9, b19, s6);
            s7 = convolution::mul_add::<T, FMA>(a11, b21, s7);
            s8 = convolution::mul_add::<T, FMA>(a3, b17, s8);
            s9 = convolution::mul_add::<T, FMA>(a4, b19, s9);
            t0 = convolution::mul_add::<T, FMA>(a11, p11, t0);
            t1 = convolution::mul_add::<T, FMA>(a7, p7, t1);
            t2 = convolution::mul_add::<T, FMA>(a15, p17, t2);
            t3 = convolution::mul_add::<T, FMA>(a15, p19, t3);
            t4 = convolution::mul_add::<T, FMA>(a15, p21, t4);
            t5 = convolution::mul_add::<T, FMA>(a7, p17, t5);
            t6 = convolution::mul_add::<T, FMA>(a9, p19, t6);
            t7 = convolution::mul_add::<T, FMA>(a11, p21, t7);
            t8 = convolution::mul_add::<T, FMA>(a3, p17, t8);
            t9 = convolution::mul_add::<T, FMA>(a4, p19, t9);
            (p7, p11, p17, p19, p21) = (b7, b11, b17, b19, b21);
        }
        let mut p9 = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a9, b9) = unsafe { (at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a9, b9, s0);
            b9
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a9, b9) = unsafe { (at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a9, b9, s0);
            t0 = convolution::mul_add::<T, FMA>(a9, p9, t0);
            p9 = b9;
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[8] = s8;
        g[8] = t8;
        h[9] = s9;
        g[9] = t9;
        // Histories [10, 12, 14, 15, 16, 17, 18, 25, 26, 27]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s10, mut t10, mut s12, mut t12, mut s14, mut t14, mut s15, mut t15, mut s16, mut t16, mut s17, mut t17, mut s18, mut t18, mut s25, mut t25, mut s26, mut t26, mut s27, mut t27) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p21, mut p22, mut p25, mut p35, mut p46) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a7, b21, a22, b22, a23, a24, b25, a34, b35, a36, a37, a38, b46) = unsafe { (at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 22 * s + 4 + j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + j), at(c, 24 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 35 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 37 * s + 4 + j), at(c, 38 * s + 4 + j), at(c, 46 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a5, b21, s10);
            s12 = convolution::mul_add::<T, FMA>(a7, b25, s12);
            s14 = convolution::mul_add::<T, FMA>(a7, b22, s14);
            s15 = convolution::mul_add::<T, FMA>(a34, b35, s15);
            s16 = convolution::mul_add::<T, FMA>(a22, b35, s16);
            s17 = convolution::mul_add::<T, FMA>(a23, b35, s17);
            s18 = convolution::mul_add::<T, FMA>(a24, b35, s18);
            s25 = convolution::mul_add::<T, FMA>(a36, b46, s25);
            s26 = convolution::mul_add::<T, FMA>(a37, b46, s26);
            s27 = convolution::mul_add::<T, FMA>(a38, b46, s27);
            (b21, b22, b25, b35, b46)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a7, b21, a22, b22, a23, a24, b25, a34, b35, a36, a37, a38, b46) = unsafe { (at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 22 * s + 4 + j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + j), at(c, 24 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 35 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 37 * s + 4 + j), at(c, 38 * s + 4 + j), at(c, 46 * s + 4 + k - j)) };
            s10 = convolution::mul_add::<T, FMA>(a5, b21, s10);
            s12 = convolution::mul_add::<T, FMA>(a7, b25, s12);
            s14 = convolution::mul_add::<T, FMA>(a7, b22, s14);
            s15 = convolution::mul_add::<T, FMA>(a34, b35, s15);
            s16 = convolution::mul_add::<T, FMA>(a22, b35, s16);
            s17 = convolution::mul_add::<T, FMA>(a23, b35, s17);
            s18 = convolution::mul_add::<T, FMA>(a24, b35, s18);
            s25 = convolution::mul_add::<T, FMA>(a36, b46, s25);
            s26 = convolution::mul_add::<T, FMA>(a37, b46, s26);
            s27 = convolution::mul_add::<T, FMA>(a38, b46, s27);
            t10 = convolution::mul_add::<T, FMA>(a5, p21, t10);
            t12 = convolution::mul_add::<T, FMA>(a7, p25, t12);
            t14 = convolution::mul_add::<T, FMA>(a7, p22, t14);
            t15 = convolution::mul_add::<T, FMA>(a34, p35, t15);
            t16 = convolution::mul_add::<T, FMA>(a22, p35, t16);
            t17 = convolution::mul_add::<T, FMA>(a23, p35, t17);
            t18 = convolution::mul_add::<T, FMA>(a24, p35, t18);
            t25 = convolution::mul_add::<T, FMA>(a36, p46, t25);
            t26 = convolution::mul_add::<T, FMA>(a37, p46, t26);
            t27 = convolution::mul_add::<T, FMA>(a38, p46, t27);
            (p21, p22, p25, p35, p46) = (b21, b22, b25, b35, b46);
        }
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        h[14] = s14;
        g[14] = t14;
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[17] = s17;
        g[17] = t17;
        h[18] = s18;
        g[18] = t18;
        h[25] = s25;
        g[25] = t25;
        h[26] = s26;
        g[26] = t26;
        h[27] = s27;
        g[27] = t27;
        // Histories [11, 13, 19, 20, 21, 22, 23, 24]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s11, mut t11, mut s13, mut t13, mut s19, mut t19, mut s20, mut t20, mut s21, mut t21, mut s22, mut t22, mut s23, mut t23, mut s24, mut t24) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p24, mut p27, mut p36, mut p37, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a11, b24, b27, b36, b37, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 37 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a11, b27, s11);
            s13 = convolution::mul_add::<T, FMA>(a11, b24, s13);
            s19 = convolution::mul_add::<T, FMA>(a1, b38, s19);
            s20 = convolution::mul_add::<T, FMA>(a2, b36, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b37, s21);
            s22 = convolution::mul_add::<T, FMA>(a4, b38, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b36, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b37, s24);
            (b24, b27, b36, b37, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a11, b24, b27, b36, b37, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 37 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a11, b27, s11);
            s13 = convolution::mul_add::<T, FMA>(a11, b24, s13);
            s19 = convolution::mul_add::<T, FMA>(a1, b38, s19);
            s20 = convolution::mul_add::<T, FMA>(a2, b36, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b37, s21);
            s22 = convolution::mul_add::<T, FMA>(a4, b38, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b36, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b37, s24);
            t11 = convolution::mul_add::<T, FMA>(a11, p27, t11);
            t13 = convolution::mul_add::<T, FMA>(a11, p24, t13);
            t19 = convolution::mul_add::<T, FMA>(a1, p38, t19);
            t20 = convolution::mul_add::<T, FMA>(a2, p36, t20);
            t21 = convolution::mul_add::<T, FMA>(a0, p37, t21);
            t22 = convolution::mul_add::<T, FMA>(a4, p38, t22);
            t23 = convolution::mul_add::<T, FMA>(a5, p36, t23);
            t24 = convolution::mul_add::<T, FMA>(a3, p37, t24);
            (p24, p27, p36, p37, p38) = (b24, b27, b36, b37, b38);
        }
        let (mut p23, mut p26, mut p36, mut p37, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a9, b23, b26, b36, b37, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 23 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 37 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a9, b26, s11);
            s13 = convolution::mul_add::<T, FMA>(a9, b23, s13);
            s19 = convolution::mul_add::<T, FMA>(-a2, b37, s19);
            s20 = convolution::mul_add::<T, FMA>(-a0, b38, s20);
            s21 = convolution::mul_add::<T, FMA>(-a1, b36, s21);
            s22 = convolution::mul_add::<T, FMA>(-a5, b37, s22);
            s23 = convolution::mul_add::<T, FMA>(-a3, b38, s23);
            s24 = convolution::mul_add::<T, FMA>(-a4, b36, s24);
            (b23, b26, b36, b37, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, a9, b23, b26, b36, b37, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 23 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 37 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a9, b26, s11);
            s13 = convolution::mul_add::<T, FMA>(a9, b23, s13);
            s19 = convolution::mul_add::<T, FMA>(-a2, b37, s19);
            s20 = convolution::mul_add::<T, FMA>(-a0, b38, s20);
            s21 = convolution::mul_add::<T, FMA>(-a1, b36, s21);
            s22 = convolution::mul_add::<T, FMA>(-a5, b37, s22);
            s23 = convolution::mul_add::<T, FMA>(-a3, b38, s23);
            s24 = convolution::mul_add::<T, FMA>(-a4, b36, s24);
            t11 = convolution::mul_add::<T, FMA>(a9, p26, t11);
            t13 = convolution::mul_add::<T, FMA>(a9, p23, t13);
            t19 = convolution::mul_add::<T, FMA>(-a2, p37, t19);
            t20 = convolution::mul_add::<T, FMA>(-a0, p38, t20);
            t21 = convolution::mul_add::<T, FMA>(-a1, p36, t21);
            t22 = convolution::mul_add::<T, FMA>(-a5, p37, t22);
            t23 = convolution::mul_add::<T, FMA>(-a3, p38, t23);
            t24 = convolution::mul_add::<T, FMA>(-a4, p36, t24);
            (p23, p26, p36, p37, p38) = (b23, b26, b36, b37, b38);
        }
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
        h[24] = s24;
        g[24] = t24;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 15 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 22 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 22 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 37 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 37 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 37 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 37 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 37 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 37 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 37 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 37 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[24] = e;
        let mut e = g[25];
        e = convolution::mul_add::<T, FMA>(at(c, 36 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 36 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), e);
        h[25] = e;
        let mut e = g[26];
        e = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), e);
        h[26] = e;
        let mut e = g[27];
        e = convolution::mul_add::<T, FMA>(at(c, 38 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 38 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), e);
        h[27] = e;
        }
    }
}
