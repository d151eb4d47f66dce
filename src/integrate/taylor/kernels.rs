//! Generated Taylor kernels: the pass of order `k >= 1` through the tapes of the model
//! families in straight-line code (see [`super::codegen`]). Generated: do not edit;
//! rewrite with `ROUTH_REGENERATE=1 cargo test --release --lib generated_kernels_are_up_to_date`.

use super::convolution::{self, at};
use super::recurrence;
use super::tape::Coefficient;

/// The name and the shape ([`super::codegen::shape`]) of each kernel, by number.
pub(super) const SHAPES: [(&str, &str); 6] = [
    ("routh", "n 6 first 7\nadd_c 2 #\ndot_add 0 0 1 1\nmul 7 7\nadd 8 9\nadd_c 10 #\nadd_c 10 #\ndiv 8 11\ndiv 9 12\nadd 13 14\ndot_add 0 3 1 4\nmul 5 7\ndiv 16 11\ndiv 17 12\nadd 18 19\nc_sub 15 #\ndiv 20 21\nmul_plus 0 22 3\ndiv 23 11\nmul_plus 1 22 4\ndiv 25 11\nmul_plus 7 22 5\ndiv 27 12\ndot_sub 1 28 2 26\ndot_sub 2 24 0 28\ndot_sub 0 26 1 24\nmul_c 31 #\nmul_c 1 #\nmul_c 0 #\nc_sub 34 #\ndot_sub 4 28 5 26\ndot_sub 5 24 3 28\ndot_sub 3 26 4 24\nadd 33 36\nmul_plus 24 32 39\nadd 35 37\nmul_plus 26 32 41\nmul_plus 28 32 38\n"),
    ("routh_free", "n 6 first 7\nadd_c 2 #\ndot_add 0 0 1 1\nmul 7 7\nadd 8 9\nadd_c 10 #\nadd_c 10 #\ndiv 8 11\ndiv 9 12\nadd 13 14\ndot_add 0 3 1 4\nmul 5 7\ndiv 16 11\ndiv 17 12\nadd 18 19\nc_sub 15 #\ndiv 20 21\nmul_plus 0 22 3\ndiv 23 11\nmul_plus 1 22 4\ndiv 25 11\nmul_plus 7 22 5\ndiv 27 12\ndot_sub 1 28 2 26\ndot_sub 2 24 0 28\ndot_sub 0 26 1 24\nmul_c 31 #\ndot_sub 4 28 5 26\ndot_sub 5 24 3 28\ndot_sub 3 26 4 24\nmul_plus 24 32 33\nmul_plus 26 32 34\nmul_plus 28 32 35\n"),
    ("routh_general", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 7 7 8 8\nmul 10 10\nadd 11 12\nmul_c 13 #\nadd_c 14 #\nadd_c 14 #\ndiv 11 15\ndiv 12 16\nadd 17 18\ndot_add 3 7 4 8\nmul 5 10\ndiv 20 15\ndiv 21 16\nadd 22 23\nmul_c 24 #\nmul_c 19 #\nc_sub 26 #\ndiv 25 27\nmul_plus 7 28 3\ndiv 29 15\nmul_plus 8 28 4\ndiv 31 15\nmul_plus 10 28 5\ndiv 33 16\ndot_sub 1 34 2 32\ndot_sub 2 30 0 34\ndot_sub 0 32 1 30\nmul_c 37 #\nmul_c 1 #\nmul_c 0 #\nc_sub 40 #\ndot_sub 4 34 5 32\ndot_sub 5 30 3 34\ndot_sub 3 32 4 30\nadd 39 42\nmul_plus 30 38 45\nadd 41 43\nmul_plus 32 38 47\nmul_plus 34 38 44\n"),
    ("routh_general_free", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 7 7 8 8\nmul 10 10\nadd 11 12\nmul_c 13 #\nadd_c 14 #\nadd_c 14 #\ndiv 11 15\ndiv 12 16\nadd 17 18\ndot_add 3 7 4 8\nmul 5 10\ndiv 20 15\ndiv 21 16\nadd 22 23\nmul_c 24 #\nmul_c 19 #\nc_sub 26 #\ndiv 25 27\nmul_plus 7 28 3\ndiv 29 15\nmul_plus 8 28 4\ndiv 31 15\nmul_plus 10 28 5\ndiv 33 16\ndot_sub 1 34 2 32\ndot_sub 2 30 0 34\ndot_sub 0 32 1 30\nmul_c 37 #\ndot_sub 4 34 5 32\ndot_sub 5 30 3 34\ndot_sub 3 32 4 30\nmul_plus 30 38 39\nmul_plus 32 38 40\nmul_plus 34 38 41\n"),
    ("chaplygin", "n 6 first 7\nmul 0 0\nmul 1 1\nmul 2 2\nadd 7 8\nadd 9 10\nadd_c 11 #\nadd_c 11 #\nadd_c 11 #\ndiv 7 12\ndiv 8 13\ndiv 9 14\nadd 15 16\nadd 17 18\nmul 0 3\nmul 1 4\nmul 2 5\ndiv 20 12\ndiv 21 13\ndiv 22 14\nadd 23 24\nadd 25 26\nc_sub 19 #\ndiv 27 28\nmul_plus 0 29 3\ndiv 30 12\nmul_plus 1 29 4\ndiv 32 13\nmul_plus 2 29 5\ndiv 34 14\ndot_sub 1 35 2 33\ndot_sub 2 31 0 35\ndot_sub 0 33 1 31\ndot_sub 4 35 5 33\ndot_sub 5 31 3 35\ndot_sub 3 33 4 31\n"),
    ("ball", "n 6 first 7\nmul_c 0 #\nadd_c 7 #\nmul_c 1 #\nadd_c 9 #\nmul_c 2 #\nadd_c 11 #\nmul 8 8\nmul 10 10\nmul 12 12\nadd 13 14\nadd 15 16\nmul_c 17 #\nadd_c 18 #\nadd_c 18 #\nadd_c 18 #\ndiv 13 19\ndiv 14 20\ndiv 15 21\nadd 22 23\nadd 24 25\nmul 3 8\nmul 4 10\nmul 5 12\ndiv 27 19\ndiv 28 20\ndiv 29 21\nadd 30 31\nadd 32 33\nmul_c 34 #\nmul_c 26 #\nc_sub 36 #\ndiv 35 37\nmul_plus 8 38 3\ndiv 39 19\nmul_plus 10 38 4\ndiv 41 20\nmul_plus 12 38 5\ndiv 43 21\ndot_sub 1 44 2 42\ndot_sub 2 40 0 44\ndot_sub 0 42 1 40\nmul_c 45 #\nmul_c 46 #\nadd 48 49\nmul_c 47 #\nadd 50 51\nmul_c 1 #\nmul_c 2 #\nsub 53 54\nmul_c 2 #\nmul_c 0 #\nsub 56 57\nmul_c 0 #\nmul_c 1 #\nsub 59 60\ndot_sub 4 44 5 42\ndot_sub 5 40 3 44\ndot_sub 3 42 4 40\nadd 55 62\nmul_plus 40 52 65\nadd 58 63\nmul_plus 42 52 67\nadd 61 64\nmul_plus 44 52 69\n"),
];

/// The pass of order `k >= 1` through the tape of shape `SHAPES[kernel]`, in slots of
/// `s` coefficients (order 0 of each `PAD` places into its slot), with the histories `h`
/// ([`super::convolution`]) and the inline constants `q` ([`super::codegen::constants`]).
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
            q.try_into().expect("the constants of the shape"),
        ),
        1 => routh_free::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the constants of the shape"),
        ),
        2 => routh_general::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the constants of the shape"),
        ),
        3 => routh_general_free::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the constants of the shape"),
        ),
        4 => chaplygin::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the constants of the shape"),
        ),
        5 => ball::<T, FMA>(
            c,
            s,
            k,
            h.try_into().expect("the histories of the shape"),
            q.try_into().expect("the constants of the shape"),
        ),
        _ => unreachable!("a kernel of SHAPES"),
    }
}

/// Order 0 of the tape of shape `SHAPES[kernel]`, in slots of `s` coefficients: the
/// field's own operations, with the inline constants `z` ([`super::codegen::constants`]).
#[inline(always)]
pub(super) fn zero<T: Coefficient>(kernel: usize, c: &mut [T], s: usize, z: &[f64]) {
    match kernel {
        0 => routh_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
        1 => routh_free_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
        2 => routh_general_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
        3 => routh_general_free_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
        4 => chaplygin_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
        5 => ball_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
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
    h: &[T; 24],
    q: &[f64; 8],
) {
    let v7 = c[2 * s + 4 + k];
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[4], c[4 + k]], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[7 * s + 4], v7, h[1]);
    c[9 * s + 4 + k] = v9;
    let v10 = v8 + v9;
    c[10 * s + 4 + k] = v10;
    let v11 = v10;
    c[11 * s + 4 + k] = v11;
    let v12 = v10;
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::quotient::<T, FMA>(v8, c[11 * s + 4], v11, c[13 * s + 4], h[2]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::quotient::<T, FMA>(v9, c[12 * s + 4], v12, c[14 * s + 4], h[3]);
    c[14 * s + 4 + k] = v14;
    let v15 = v13 + v14;
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[3 * s + 4], c[3 * s + 4 + k]], [c[s + 4], c[s + 4 + k], c[4 * s + 4], c[4 * s + 4 + k]], h[4]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[7 * s + 4], v7, h[5]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::quotient::<T, FMA>(v16, c[11 * s + 4], v11, c[18 * s + 4], h[6]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::quotient::<T, FMA>(v17, c[12 * s + 4], v12, c[19 * s + 4], h[7]);
    c[19 * s + 4 + k] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4 + k] = v20;
    let v21 = -v15;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::quotient::<T, FMA>(v20, c[21 * s + 4], v21, c[22 * s + 4], h[8]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[22 * s + 4], v22, c[3 * s + 4 + k], h[9]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::quotient::<T, FMA>(v23, c[11 * s + 4], v11, c[24 * s + 4], h[10]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[s + 4], c[s + 4 + k], c[22 * s + 4], v22, c[4 * s + 4 + k], h[11]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::quotient::<T, FMA>(v25, c[11 * s + 4], v11, c[26 * s + 4], h[12]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[22 * s + 4], v22, c[5 * s + 4 + k], h[13]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::quotient::<T, FMA>(v27, c[12 * s + 4], v12, c[28 * s + 4], h[14]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[28 * s + 4], v28], [c[2 * s + 4], c[2 * s + 4 + k], c[26 * s + 4], v26], h[15]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[24 * s + 4], v24], [c[4], c[4 + k], c[28 * s + 4], v28], h[16]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[26 * s + 4], v26], [c[s + 4], c[s + 4 + k], c[24 * s + 4], v24], h[17]);
    c[31 * s + 4 + k] = v31;
    let v32 = v31 * q[4];
    c[32 * s + 4 + k] = v32;
    let v33 = c[s + 4 + k] * q[5];
    c[33 * s + 4 + k] = v33;
    let v34 = c[4 + k] * q[6];
    c[34 * s + 4 + k] = v34;
    let v35 = -v34;
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[28 * s + 4], v28], [c[5 * s + 4], c[5 * s + 4 + k], c[26 * s + 4], v26], h[18]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[24 * s + 4], v24], [c[3 * s + 4], c[3 * s + 4 + k], c[28 * s + 4], v28], h[19]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[26 * s + 4], v26], [c[4 * s + 4], c[4 * s + 4 + k], c[24 * s + 4], v24], h[20]);
    c[38 * s + 4 + k] = v38;
    let v39 = v33 + v36;
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::mul_plus::<T, FMA>(c[24 * s + 4], v24, c[32 * s + 4], v32, v39, h[21]);
    c[40 * s + 4 + k] = v40;
    let v41 = v35 + v37;
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::mul_plus::<T, FMA>(c[26 * s + 4], v26, c[32 * s + 4], v32, v41, h[22]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::mul_plus::<T, FMA>(c[28 * s + 4], v28, c[32 * s + 4], v32, v38, h[23]);
    c[43 * s + 4 + k] = v43;
}

/// Order 0 of the kernel `routh`.
#[inline(always)]
fn routh_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 8]) {
    let v7 = c[2 * s + 4] + z[0];
    c[7 * s + 4] = v7;
    let v8 = c[4] * c[4] + c[s + 4] * c[s + 4];
    c[8 * s + 4] = v8;
    let v9 = v7 * v7;
    c[9 * s + 4] = v9;
    let v10 = v8 + v9;
    c[10 * s + 4] = v10;
    let v11 = v10 + z[1];
    c[11 * s + 4] = v11;
    let v12 = v10 + z[2];
    c[12 * s + 4] = v12;
    let v13 = v8 / v11;
    c[13 * s + 4] = v13;
    let v14 = v9 / v12;
    c[14 * s + 4] = v14;
    let v15 = v13 + v14;
    c[15 * s + 4] = v15;
    let v16 = c[4] * c[3 * s + 4] + c[s + 4] * c[4 * s + 4];
    c[16 * s + 4] = v16;
    let v17 = c[5 * s + 4] * v7;
    c[17 * s + 4] = v17;
    let v18 = v16 / v11;
    c[18 * s + 4] = v18;
    let v19 = v17 / v12;
    c[19 * s + 4] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4] = v20;
    let v21 = T::from_f64(z[3]) - v15;
    c[21 * s + 4] = v21;
    let v22 = v20 / v21;
    c[22 * s + 4] = v22;
    let v23 = c[4] * v22 + c[3 * s + 4];
    c[23 * s + 4] = v23;
    let v24 = v23 / v11;
    c[24 * s + 4] = v24;
    let v25 = c[s + 4] * v22 + c[4 * s + 4];
    c[25 * s + 4] = v25;
    let v26 = v25 / v11;
    c[26 * s + 4] = v26;
    let v27 = v7 * v22 + c[5 * s + 4];
    c[27 * s + 4] = v27;
    let v28 = v27 / v12;
    c[28 * s + 4] = v28;
    let v29 = c[s + 4] * v28 - c[2 * s + 4] * v26;
    c[29 * s + 4] = v29;
    let v30 = c[2 * s + 4] * v24 - c[4] * v28;
    c[30 * s + 4] = v30;
    let v31 = c[4] * v26 - c[s + 4] * v24;
    c[31 * s + 4] = v31;
    let v32 = v31 * z[4];
    c[32 * s + 4] = v32;
    let v33 = c[s + 4] * z[5];
    c[33 * s + 4] = v33;
    let v34 = c[4] * z[6];
    c[34 * s + 4] = v34;
    let v35 = T::from_f64(z[7]) - v34;
    c[35 * s + 4] = v35;
    let v36 = c[4 * s + 4] * v28 - c[5 * s + 4] * v26;
    c[36 * s + 4] = v36;
    let v37 = c[5 * s + 4] * v24 - c[3 * s + 4] * v28;
    c[37 * s + 4] = v37;
    let v38 = c[3 * s + 4] * v26 - c[4 * s + 4] * v24;
    c[38 * s + 4] = v38;
    let v39 = v33 + v36;
    c[39 * s + 4] = v39;
    let v40 = v24 * v32 + v39;
    c[40 * s + 4] = v40;
    let v41 = v35 + v37;
    c[41 * s + 4] = v41;
    let v42 = v26 * v32 + v41;
    c[42 * s + 4] = v42;
    let v43 = v28 * v32 + v38;
    c[43 * s + 4] = v43;
}

/// The histories of the kernels `routh`, `routh_free` at order `k >= 1` ([`histories`]).
#[inline(always)]
fn routh_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 24],
    g: &mut [T; 24],
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
        // Histories [0, 1, 8, 9, 11, 13].
        let (mut s0, mut s1, mut s8, mut s9, mut s11, mut s13) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, a2, b2, a21, b22) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 21 * s + 4 + j), at(c, 22 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a0, b0, s0);
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
            s1 = convolution::mul_add::<T, FMA>(a2, b2, s1);
            s8 = convolution::mul_add::<T, FMA>(a21, b22, s8);
            s9 = convolution::mul_add::<T, FMA>(a0, b22, s9);
            s11 = convolution::mul_add::<T, FMA>(a1, b22, s11);
            s13 = convolution::mul_add::<T, FMA>(a2, b22, s13);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), s0);
                s1 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s1);
                s8 = convolution::mul_add::<T, FMA>(at(c, 21 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 21 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s8);
                s9 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 22 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 22 * s + 4 + 1), s9);
                s11 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 22 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 22 * s + 4 + 1), s11);
                s13 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s13);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[8] = s8;
        h[9] = s9;
        h[11] = s11;
        h[13] = s13;
        // Histories [2, 3, 6, 7, 10, 12].
        let (mut s2, mut s3, mut s6, mut s7, mut s10, mut s12) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a10, b13, b14, b18, b19, b24, b26) = unsafe { (at(c, 10 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 14 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a10, b13, s2);
            s3 = convolution::mul_add::<T, FMA>(a10, b14, s3);
            s6 = convolution::mul_add::<T, FMA>(a10, b18, s6);
            s7 = convolution::mul_add::<T, FMA>(a10, b19, s7);
            s10 = convolution::mul_add::<T, FMA>(a10, b24, s10);
            s12 = convolution::mul_add::<T, FMA>(a10, b26, s12);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s2 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), s2);
                s3 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), s3);
                s6 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), s6);
                s7 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), s7);
                s10 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), s10);
                s12 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s12);
            }
        }
        h[2] = s2;
        h[3] = s3;
        h[6] = s6;
        h[7] = s7;
        h[10] = s10;
        h[12] = s12;
        // Histories [4, 5, 14, 17, 20, 21].
        let (mut s4, mut s5, mut s14, mut s17, mut s20, mut s21) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, b2, a3, b3, a4, b4, a5, a10, a24, b24, b26, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 3 * s + 4 + k - j), at(c, 4 * s + 4 + j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + j), at(c, 10 * s + 4 + j), at(c, 24 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s4 = convolution::mul_add::<T, FMA>(a0, b3, s4);
            s4 = convolution::mul_add::<T, FMA>(a1, b4, s4);
            s5 = convolution::mul_add::<T, FMA>(a5, b2, s5);
            s14 = convolution::mul_add::<T, FMA>(a10, b28, s14);
            s17 = convolution::mul_add::<T, FMA>(a0, b26, s17);
            s17 = convolution::mul_add::<T, FMA>(-a1, b24, s17);
            s20 = convolution::mul_add::<T, FMA>(a3, b26, s20);
            s20 = convolution::mul_add::<T, FMA>(-a4, b24, s20);
            s21 = convolution::mul_add::<T, FMA>(a24, b32, s21);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s4 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s5);
                s14 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s14);
                s17 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 26 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 24 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 26 * s + 4 + 1), s17);
                s17 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 24 * s + 4 + 1), s17);
                s20 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), s20);
                s21 = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s21);
            }
        }
        h[4] = s4;
        h[5] = s5;
        h[14] = s14;
        h[17] = s17;
        h[20] = s20;
        h[21] = s21;
        // Histories [15, 16, 18, 19, 22, 23].
        let (mut s15, mut s16, mut s18, mut s19, mut s22, mut s23) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b24, a26, b26, a28, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s15 = convolution::mul_add::<T, FMA>(a1, b28, s15);
            s15 = convolution::mul_add::<T, FMA>(-a2, b26, s15);
            s16 = convolution::mul_add::<T, FMA>(a2, b24, s16);
            s16 = convolution::mul_add::<T, FMA>(-a0, b28, s16);
            s18 = convolution::mul_add::<T, FMA>(a4, b28, s18);
            s18 = convolution::mul_add::<T, FMA>(-a5, b26, s18);
            s19 = convolution::mul_add::<T, FMA>(a5, b24, s19);
            s19 = convolution::mul_add::<T, FMA>(-a3, b28, s19);
            s22 = convolution::mul_add::<T, FMA>(a26, b32, s22);
            s23 = convolution::mul_add::<T, FMA>(a28, b32, s23);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s15 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 28 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 28 * s + 4 + 1), s15);
                s15 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s15);
                s16 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 28 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), s16);
                s16 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 28 * s + 4 + 1), s16);
                s18 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), s18);
                s19 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s19);
                s22 = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s22);
                s23 = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s23);
            }
        }
        h[15] = s15;
        h[16] = s16;
        h[18] = s18;
        h[19] = s19;
        h[22] = s22;
        h[23] = s23;
    } else if even {
        // Histories [0, 1, 8, 9, 11, 13]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s8, mut t8, mut s9, mut t9, mut s11, mut t11, mut s13, mut t13) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p0, mut p1, mut p2, mut p22) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, a2, b2, a21, b22) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 21 * s + 4 + j), at(c, 22 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a0, b0, s0);
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
            s1 = convolution::mul_add::<T, FMA>(a2, b2, s1);
            s8 = convolution::mul_add::<T, FMA>(a21, b22, s8);
            s9 = convolution::mul_add::<T, FMA>(a0, b22, s9);
            s11 = convolution::mul_add::<T, FMA>(a1, b22, s11);
            s13 = convolution::mul_add::<T, FMA>(a2, b22, s13);
            (b0, b1, b2, b22)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, a2, b2, a21, b22) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 21 * s + 4 + j), at(c, 22 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a0, b0, s0);
            s0 = convolution::mul_add::<T, FMA>(a1, b1, s0);
            s1 = convolution::mul_add::<T, FMA>(a2, b2, s1);
            s8 = convolution::mul_add::<T, FMA>(a21, b22, s8);
            s9 = convolution::mul_add::<T, FMA>(a0, b22, s9);
            s11 = convolution::mul_add::<T, FMA>(a1, b22, s11);
            s13 = convolution::mul_add::<T, FMA>(a2, b22, s13);
            t0 = convolution::mul_add::<T, FMA>(a0, p0, t0);
            t0 = convolution::mul_add::<T, FMA>(a1, p1, t0);
            t1 = convolution::mul_add::<T, FMA>(a2, p2, t1);
            t8 = convolution::mul_add::<T, FMA>(a21, p22, t8);
            t9 = convolution::mul_add::<T, FMA>(a0, p22, t9);
            t11 = convolution::mul_add::<T, FMA>(a1, p22, t11);
            t13 = convolution::mul_add::<T, FMA>(a2, p22, t13);
            (p0, p1, p2, p22) = (b0, b1, b2, b22);
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[8] = s8;
        g[8] = t8;
        h[9] = s9;
        g[9] = t9;
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        // Histories [2, 3, 6, 7, 10, 12]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s2, mut t2, mut s3, mut t3, mut s6, mut t6, mut s7, mut t7, mut s10, mut t10, mut s12, mut t12) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p13, mut p14, mut p18, mut p19, mut p24, mut p26) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a10, b13, b14, b18, b19, b24, b26) = unsafe { (at(c, 10 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 14 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a10, b13, s2);
            s3 = convolution::mul_add::<T, FMA>(a10, b14, s3);
            s6 = convolution::mul_add::<T, FMA>(a10, b18, s6);
            s7 = convolution::mul_add::<T, FMA>(a10, b19, s7);
            s10 = convolution::mul_add::<T, FMA>(a10, b24, s10);
            s12 = convolution::mul_add::<T, FMA>(a10, b26, s12);
            (b13, b14, b18, b19, b24, b26)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a10, b13, b14, b18, b19, b24, b26) = unsafe { (at(c, 10 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 14 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 19 * s + 4 + k - j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a10, b13, s2);
            s3 = convolution::mul_add::<T, FMA>(a10, b14, s3);
            s6 = convolution::mul_add::<T, FMA>(a10, b18, s6);
            s7 = convolution::mul_add::<T, FMA>(a10, b19, s7);
            s10 = convolution::mul_add::<T, FMA>(a10, b24, s10);
            s12 = convolution::mul_add::<T, FMA>(a10, b26, s12);
            t2 = convolution::mul_add::<T, FMA>(a10, p13, t2);
            t3 = convolution::mul_add::<T, FMA>(a10, p14, t3);
            t6 = convolution::mul_add::<T, FMA>(a10, p18, t6);
            t7 = convolution::mul_add::<T, FMA>(a10, p19, t7);
            t10 = convolution::mul_add::<T, FMA>(a10, p24, t10);
            t12 = convolution::mul_add::<T, FMA>(a10, p26, t12);
            (p13, p14, p18, p19, p24, p26) = (b13, b14, b18, b19, b24, b26);
        }
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        // Histories [4, 5, 14, 17, 20, 21]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s4, mut t4, mut s5, mut t5, mut s14, mut t14, mut s17, mut t17, mut s20, mut t20, mut s21, mut t21) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p2, mut p3, mut p4, mut p24, mut p26, mut p28, mut p32) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, b2, a3, b3, a4, b4, a5, a10, a24, b24, b26, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 3 * s + 4 + k - j), at(c, 4 * s + 4 + j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + j), at(c, 10 * s + 4 + j), at(c, 24 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s4 = convolution::mul_add::<T, FMA>(a0, b3, s4);
            s4 = convolution::mul_add::<T, FMA>(a1, b4, s4);
            s5 = convolution::mul_add::<T, FMA>(a5, b2, s5);
            s14 = convolution::mul_add::<T, FMA>(a10, b28, s14);
            s17 = convolution::mul_add::<T, FMA>(a0, b26, s17);
            s17 = convolution::mul_add::<T, FMA>(-a1, b24, s17);
            s20 = convolution::mul_add::<T, FMA>(a3, b26, s20);
            s20 = convolution::mul_add::<T, FMA>(-a4, b24, s20);
            s21 = convolution::mul_add::<T, FMA>(a24, b32, s21);
            (b2, b3, b4, b24, b26, b28, b32)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, b2, a3, b3, a4, b4, a5, a10, a24, b24, b26, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + j), at(c, 3 * s + 4 + k - j), at(c, 4 * s + 4 + j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + j), at(c, 10 * s + 4 + j), at(c, 24 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s4 = convolution::mul_add::<T, FMA>(a0, b3, s4);
            s4 = convolution::mul_add::<T, FMA>(a1, b4, s4);
            s5 = convolution::mul_add::<T, FMA>(a5, b2, s5);
            s14 = convolution::mul_add::<T, FMA>(a10, b28, s14);
            s17 = convolution::mul_add::<T, FMA>(a0, b26, s17);
            s17 = convolution::mul_add::<T, FMA>(-a1, b24, s17);
            s20 = convolution::mul_add::<T, FMA>(a3, b26, s20);
            s20 = convolution::mul_add::<T, FMA>(-a4, b24, s20);
            s21 = convolution::mul_add::<T, FMA>(a24, b32, s21);
            t4 = convolution::mul_add::<T, FMA>(a0, p3, t4);
            t4 = convolution::mul_add::<T, FMA>(a1, p4, t4);
            t5 = convolution::mul_add::<T, FMA>(a5, p2, t5);
            t14 = convolution::mul_add::<T, FMA>(a10, p28, t14);
            t17 = convolution::mul_add::<T, FMA>(a0, p26, t17);
            t17 = convolution::mul_add::<T, FMA>(-a1, p24, t17);
            t20 = convolution::mul_add::<T, FMA>(a3, p26, t20);
            t20 = convolution::mul_add::<T, FMA>(-a4, p24, t20);
            t21 = convolution::mul_add::<T, FMA>(a24, p32, t21);
            (p2, p3, p4, p24, p26, p28, p32) = (b2, b3, b4, b24, b26, b28, b32);
        }
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[14] = s14;
        g[14] = t14;
        h[17] = s17;
        g[17] = t17;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
        // Histories [15, 16, 18, 19, 22, 23]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s15, mut t15, mut s16, mut t16, mut s18, mut t18, mut s19, mut t19, mut s22, mut t22, mut s23, mut t23) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p24, mut p26, mut p28, mut p32) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b24, a26, b26, a28, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s15 = convolution::mul_add::<T, FMA>(a1, b28, s15);
            s15 = convolution::mul_add::<T, FMA>(-a2, b26, s15);
            s16 = convolution::mul_add::<T, FMA>(a2, b24, s16);
            s16 = convolution::mul_add::<T, FMA>(-a0, b28, s16);
            s18 = convolution::mul_add::<T, FMA>(a4, b28, s18);
            s18 = convolution::mul_add::<T, FMA>(-a5, b26, s18);
            s19 = convolution::mul_add::<T, FMA>(a5, b24, s19);
            s19 = convolution::mul_add::<T, FMA>(-a3, b28, s19);
            s22 = convolution::mul_add::<T, FMA>(a26, b32, s22);
            s23 = convolution::mul_add::<T, FMA>(a28, b32, s23);
            (b24, b26, b28, b32)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b24, a26, b26, a28, b28, b32) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 24 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 26 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s15 = convolution::mul_add::<T, FMA>(a1, b28, s15);
            s15 = convolution::mul_add::<T, FMA>(-a2, b26, s15);
            s16 = convolution::mul_add::<T, FMA>(a2, b24, s16);
            s16 = convolution::mul_add::<T, FMA>(-a0, b28, s16);
            s18 = convolution::mul_add::<T, FMA>(a4, b28, s18);
            s18 = convolution::mul_add::<T, FMA>(-a5, b26, s18);
            s19 = convolution::mul_add::<T, FMA>(a5, b24, s19);
            s19 = convolution::mul_add::<T, FMA>(-a3, b28, s19);
            s22 = convolution::mul_add::<T, FMA>(a26, b32, s22);
            s23 = convolution::mul_add::<T, FMA>(a28, b32, s23);
            t15 = convolution::mul_add::<T, FMA>(a1, p28, t15);
            t15 = convolution::mul_add::<T, FMA>(-a2, p26, t15);
            t16 = convolution::mul_add::<T, FMA>(a2, p24, t16);
            t16 = convolution::mul_add::<T, FMA>(-a0, p28, t16);
            t18 = convolution::mul_add::<T, FMA>(a4, p28, t18);
            t18 = convolution::mul_add::<T, FMA>(-a5, p26, t18);
            t19 = convolution::mul_add::<T, FMA>(a5, p24, t19);
            t19 = convolution::mul_add::<T, FMA>(-a3, p28, t19);
            t22 = convolution::mul_add::<T, FMA>(a26, p32, t22);
            t23 = convolution::mul_add::<T, FMA>(a28, p32, t23);
            (p24, p26, p28, p32) = (b24, b26, b28, b32);
        }
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 19 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 19 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 21 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 21 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 26 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 26 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 24 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[23] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh_free`.
#[inline(always)]
fn routh_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 24],
    q: &[f64; 5],
) {
    let v7 = c[2 * s + 4 + k];
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[4], c[4 + k]], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[7 * s + 4], v7, h[1]);
    c[9 * s + 4 + k] = v9;
    let v10 = v8 + v9;
    c[10 * s + 4 + k] = v10;
    let v11 = v10;
    c[11 * s + 4 + k] = v11;
    let v12 = v10;
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::quotient::<T, FMA>(v8, c[11 * s + 4], v11, c[13 * s + 4], h[2]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::quotient::<T, FMA>(v9, c[12 * s + 4], v12, c[14 * s + 4], h[3]);
    c[14 * s + 4 + k] = v14;
    let v15 = v13 + v14;
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[3 * s + 4], c[3 * s + 4 + k]], [c[s + 4], c[s + 4 + k], c[4 * s + 4], c[4 * s + 4 + k]], h[4]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[7 * s + 4], v7, h[5]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::quotient::<T, FMA>(v16, c[11 * s + 4], v11, c[18 * s + 4], h[6]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::quotient::<T, FMA>(v17, c[12 * s + 4], v12, c[19 * s + 4], h[7]);
    c[19 * s + 4 + k] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4 + k] = v20;
    let v21 = -v15;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::quotient::<T, FMA>(v20, c[21 * s + 4], v21, c[22 * s + 4], h[8]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[22 * s + 4], v22, c[3 * s + 4 + k], h[9]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::quotient::<T, FMA>(v23, c[11 * s + 4], v11, c[24 * s + 4], h[10]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[s + 4], c[s + 4 + k], c[22 * s + 4], v22, c[4 * s + 4 + k], h[11]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::quotient::<T, FMA>(v25, c[11 * s + 4], v11, c[26 * s + 4], h[12]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[22 * s + 4], v22, c[5 * s + 4 + k], h[13]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::quotient::<T, FMA>(v27, c[12 * s + 4], v12, c[28 * s + 4], h[14]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[28 * s + 4], v28], [c[2 * s + 4], c[2 * s + 4 + k], c[26 * s + 4], v26], h[15]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[24 * s + 4], v24], [c[4], c[4 + k], c[28 * s + 4], v28], h[16]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[26 * s + 4], v26], [c[s + 4], c[s + 4 + k], c[24 * s + 4], v24], h[17]);
    c[31 * s + 4 + k] = v31;
    let v32 = v31 * q[4];
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[28 * s + 4], v28], [c[5 * s + 4], c[5 * s + 4 + k], c[26 * s + 4], v26], h[18]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[24 * s + 4], v24], [c[3 * s + 4], c[3 * s + 4 + k], c[28 * s + 4], v28], h[19]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[26 * s + 4], v26], [c[4 * s + 4], c[4 * s + 4 + k], c[24 * s + 4], v24], h[20]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::mul_plus::<T, FMA>(c[24 * s + 4], v24, c[32 * s + 4], v32, v33, h[21]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::mul_plus::<T, FMA>(c[26 * s + 4], v26, c[32 * s + 4], v32, v34, h[22]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::mul_plus::<T, FMA>(c[28 * s + 4], v28, c[32 * s + 4], v32, v35, h[23]);
    c[38 * s + 4 + k] = v38;
}

/// Order 0 of the kernel `routh_free`.
#[inline(always)]
fn routh_free_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 5]) {
    let v7 = c[2 * s + 4] + z[0];
    c[7 * s + 4] = v7;
    let v8 = c[4] * c[4] + c[s + 4] * c[s + 4];
    c[8 * s + 4] = v8;
    let v9 = v7 * v7;
    c[9 * s + 4] = v9;
    let v10 = v8 + v9;
    c[10 * s + 4] = v10;
    let v11 = v10 + z[1];
    c[11 * s + 4] = v11;
    let v12 = v10 + z[2];
    c[12 * s + 4] = v12;
    let v13 = v8 / v11;
    c[13 * s + 4] = v13;
    let v14 = v9 / v12;
    c[14 * s + 4] = v14;
    let v15 = v13 + v14;
    c[15 * s + 4] = v15;
    let v16 = c[4] * c[3 * s + 4] + c[s + 4] * c[4 * s + 4];
    c[16 * s + 4] = v16;
    let v17 = c[5 * s + 4] * v7;
    c[17 * s + 4] = v17;
    let v18 = v16 / v11;
    c[18 * s + 4] = v18;
    let v19 = v17 / v12;
    c[19 * s + 4] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4] = v20;
    let v21 = T::from_f64(z[3]) - v15;
    c[21 * s + 4] = v21;
    let v22 = v20 / v21;
    c[22 * s + 4] = v22;
    let v23 = c[4] * v22 + c[3 * s + 4];
    c[23 * s + 4] = v23;
    let v24 = v23 / v11;
    c[24 * s + 4] = v24;
    let v25 = c[s + 4] * v22 + c[4 * s + 4];
    c[25 * s + 4] = v25;
    let v26 = v25 / v11;
    c[26 * s + 4] = v26;
    let v27 = v7 * v22 + c[5 * s + 4];
    c[27 * s + 4] = v27;
    let v28 = v27 / v12;
    c[28 * s + 4] = v28;
    let v29 = c[s + 4] * v28 - c[2 * s + 4] * v26;
    c[29 * s + 4] = v29;
    let v30 = c[2 * s + 4] * v24 - c[4] * v28;
    c[30 * s + 4] = v30;
    let v31 = c[4] * v26 - c[s + 4] * v24;
    c[31 * s + 4] = v31;
    let v32 = v31 * z[4];
    c[32 * s + 4] = v32;
    let v33 = c[4 * s + 4] * v28 - c[5 * s + 4] * v26;
    c[33 * s + 4] = v33;
    let v34 = c[5 * s + 4] * v24 - c[3 * s + 4] * v28;
    c[34 * s + 4] = v34;
    let v35 = c[3 * s + 4] * v26 - c[4 * s + 4] * v24;
    c[35 * s + 4] = v35;
    let v36 = v24 * v32 + v33;
    c[36 * s + 4] = v36;
    let v37 = v26 * v32 + v34;
    c[37 * s + 4] = v37;
    let v38 = v28 * v32 + v35;
    c[38 * s + 4] = v38;
}

/// The pass of order `k >= 1` of the kernel `routh_general`.
#[inline(always)]
fn routh_general<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 24],
    q: &[f64; 14],
) {
    let v7 = c[4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = c[s + 4 + k] * q[1];
    c[8 * s + 4 + k] = v8;
    let v9 = c[2 * s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[7 * s + 4], v7], [c[8 * s + 4], v8, c[8 * s + 4], v8], h[0]);
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[1]);
    c[12 * s + 4 + k] = v12;
    let v13 = v11 + v12;
    c[13 * s + 4 + k] = v13;
    let v14 = v13 * q[4];
    c[14 * s + 4 + k] = v14;
    let v15 = v14;
    c[15 * s + 4 + k] = v15;
    let v16 = v14;
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::quotient::<T, FMA>(v11, c[15 * s + 4], v15, c[17 * s + 4], h[2]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::quotient::<T, FMA>(v12, c[16 * s + 4], v16, c[18 * s + 4], h[3]);
    c[18 * s + 4 + k] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::dot_add::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[7 * s + 4], v7], [c[4 * s + 4], c[4 * s + 4 + k], c[8 * s + 4], v8], h[4]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[10 * s + 4], v10, h[5]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::quotient::<T, FMA>(v20, c[15 * s + 4], v15, c[22 * s + 4], h[6]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::quotient::<T, FMA>(v21, c[16 * s + 4], v16, c[23 * s + 4], h[7]);
    c[23 * s + 4 + k] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4 + k] = v24;
    let v25 = v24 * q[7];
    c[25 * s + 4 + k] = v25;
    let v26 = v19 * q[8];
    c[26 * s + 4 + k] = v26;
    let v27 = -v26;
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::quotient::<T, FMA>(v25, c[27 * s + 4], v27, c[28 * s + 4], h[8]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[28 * s + 4], v28, c[3 * s + 4 + k], h[9]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::quotient::<T, FMA>(v29, c[15 * s + 4], v15, c[30 * s + 4], h[10]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[28 * s + 4], v28, c[4 * s + 4 + k], h[11]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::quotient::<T, FMA>(v31, c[15 * s + 4], v15, c[32 * s + 4], h[12]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[28 * s + 4], v28, c[5 * s + 4 + k], h[13]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::quotient::<T, FMA>(v33, c[16 * s + 4], v16, c[34 * s + 4], h[14]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[34 * s + 4], v34], [c[2 * s + 4], c[2 * s + 4 + k], c[32 * s + 4], v32], h[15]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[30 * s + 4], v30], [c[4], c[4 + k], c[34 * s + 4], v34], h[16]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[32 * s + 4], v32], [c[s + 4], c[s + 4 + k], c[30 * s + 4], v30], h[17]);
    c[37 * s + 4 + k] = v37;
    let v38 = v37 * q[10];
    c[38 * s + 4 + k] = v38;
    let v39 = c[s + 4 + k] * q[11];
    c[39 * s + 4 + k] = v39;
    let v40 = c[4 + k] * q[12];
    c[40 * s + 4 + k] = v40;
    let v41 = -v40;
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[34 * s + 4], v34], [c[5 * s + 4], c[5 * s + 4 + k], c[32 * s + 4], v32], h[18]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[30 * s + 4], v30], [c[3 * s + 4], c[3 * s + 4 + k], c[34 * s + 4], v34], h[19]);
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[32 * s + 4], v32], [c[4 * s + 4], c[4 * s + 4 + k], c[30 * s + 4], v30], h[20]);
    c[44 * s + 4 + k] = v44;
    let v45 = v39 + v42;
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::mul_plus::<T, FMA>(c[30 * s + 4], v30, c[38 * s + 4], v38, v45, h[21]);
    c[46 * s + 4 + k] = v46;
    let v47 = v41 + v43;
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::mul_plus::<T, FMA>(c[32 * s + 4], v32, c[38 * s + 4], v38, v47, h[22]);
    c[48 * s + 4 + k] = v48;
    let v49 = recurrence::mul_plus::<T, FMA>(c[34 * s + 4], v34, c[38 * s + 4], v38, v44, h[23]);
    c[49 * s + 4 + k] = v49;
}

/// Order 0 of the kernel `routh_general`.
#[inline(always)]
fn routh_general_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 14]) {
    let v7 = c[4] * z[0];
    c[7 * s + 4] = v7;
    let v8 = c[s + 4] * z[1];
    c[8 * s + 4] = v8;
    let v9 = c[2 * s + 4] * z[2];
    c[9 * s + 4] = v9;
    let v10 = v9 + z[3];
    c[10 * s + 4] = v10;
    let v11 = v7 * v7 + v8 * v8;
    c[11 * s + 4] = v11;
    let v12 = v10 * v10;
    c[12 * s + 4] = v12;
    let v13 = v11 + v12;
    c[13 * s + 4] = v13;
    let v14 = v13 * z[4];
    c[14 * s + 4] = v14;
    let v15 = v14 + z[5];
    c[15 * s + 4] = v15;
    let v16 = v14 + z[6];
    c[16 * s + 4] = v16;
    let v17 = v11 / v15;
    c[17 * s + 4] = v17;
    let v18 = v12 / v16;
    c[18 * s + 4] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4] = v19;
    let v20 = c[3 * s + 4] * v7 + c[4 * s + 4] * v8;
    c[20 * s + 4] = v20;
    let v21 = c[5 * s + 4] * v10;
    c[21 * s + 4] = v21;
    let v22 = v20 / v15;
    c[22 * s + 4] = v22;
    let v23 = v21 / v16;
    c[23 * s + 4] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4] = v24;
    let v25 = v24 * z[7];
    c[25 * s + 4] = v25;
    let v26 = v19 * z[8];
    c[26 * s + 4] = v26;
    let v27 = T::from_f64(z[9]) - v26;
    c[27 * s + 4] = v27;
    let v28 = v25 / v27;
    c[28 * s + 4] = v28;
    let v29 = v7 * v28 + c[3 * s + 4];
    c[29 * s + 4] = v29;
    let v30 = v29 / v15;
    c[30 * s + 4] = v30;
    let v31 = v8 * v28 + c[4 * s + 4];
    c[31 * s + 4] = v31;
    let v32 = v31 / v15;
    c[32 * s + 4] = v32;
    let v33 = v10 * v28 + c[5 * s + 4];
    c[33 * s + 4] = v33;
    let v34 = v33 / v16;
    c[34 * s + 4] = v34;
    let v35 = c[s + 4] * v34 - c[2 * s + 4] * v32;
    c[35 * s + 4] = v35;
    let v36 = c[2 * s + 4] * v30 - c[4] * v34;
    c[36 * s + 4] = v36;
    let v37 = c[4] * v32 - c[s + 4] * v30;
    c[37 * s + 4] = v37;
    let v38 = v37 * z[10];
    c[38 * s + 4] = v38;
    let v39 = c[s + 4] * z[11];
    c[39 * s + 4] = v39;
    let v40 = c[4] * z[12];
    c[40 * s + 4] = v40;
    let v41 = T::from_f64(z[13]) - v40;
    c[41 * s + 4] = v41;
    let v42 = c[4 * s + 4] * v34 - c[5 * s + 4] * v32;
    c[42 * s + 4] = v42;
    let v43 = c[5 * s + 4] * v30 - c[3 * s + 4] * v34;
    c[43 * s + 4] = v43;
    let v44 = c[3 * s + 4] * v32 - c[4 * s + 4] * v30;
    c[44 * s + 4] = v44;
    let v45 = v39 + v42;
    c[45 * s + 4] = v45;
    let v46 = v30 * v38 + v45;
    c[46 * s + 4] = v46;
    let v47 = v41 + v43;
    c[47 * s + 4] = v47;
    let v48 = v32 * v38 + v47;
    c[48 * s + 4] = v48;
    let v49 = v34 * v38 + v44;
    c[49 * s + 4] = v49;
}

/// The histories of the kernels `routh_general`, `routh_general_free` at order `k >= 1` ([`histories`]).
#[inline(always)]
fn routh_general_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 24],
    g: &mut [T; 24],
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
        // Histories [0, 1, 8, 9, 11, 13].
        let (mut s0, mut s1, mut s8, mut s9, mut s11, mut s13) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, b7, a8, b8, a9, b9, a27, b28) = unsafe { (at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 27 * s + 4 + j), at(c, 28 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a7, b7, s0);
            s0 = convolution::mul_add::<T, FMA>(a8, b8, s0);
            s1 = convolution::mul_add::<T, FMA>(a9, b9, s1);
            s8 = convolution::mul_add::<T, FMA>(a27, b28, s8);
            s9 = convolution::mul_add::<T, FMA>(a7, b28, s9);
            s11 = convolution::mul_add::<T, FMA>(a8, b28, s11);
            s13 = convolution::mul_add::<T, FMA>(a9, b28, s13);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), s0);
                s1 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s1);
                s8 = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s8);
                s9 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s9);
                s11 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s11);
                s13 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s13);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[8] = s8;
        h[9] = s9;
        h[11] = s11;
        h[13] = s13;
        // Histories [2, 3, 6, 7, 10, 12].
        let (mut s2, mut s3, mut s6, mut s7, mut s10, mut s12) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a14, b17, b18, b22, b23, b30, b32) = unsafe { (at(c, 14 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a14, b17, s2);
            s3 = convolution::mul_add::<T, FMA>(a14, b18, s3);
            s6 = convolution::mul_add::<T, FMA>(a14, b22, s6);
            s7 = convolution::mul_add::<T, FMA>(a14, b23, s7);
            s10 = convolution::mul_add::<T, FMA>(a14, b30, s10);
            s12 = convolution::mul_add::<T, FMA>(a14, b32, s12);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s2 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s2);
                s3 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), s3);
                s6 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s6);
                s7 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), s7);
                s10 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s10);
                s12 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s12);
            }
        }
        h[2] = s2;
        h[3] = s3;
        h[6] = s6;
        h[7] = s7;
        h[10] = s10;
        h[12] = s12;
        // Histories [4, 5, 14, 17, 20, 21].
        let (mut s4, mut s5, mut s14, mut s17, mut s20, mut s21) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b7, b8, b9, a14, a30, b30, b32, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 30 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s4 = convolution::mul_add::<T, FMA>(a3, b7, s4);
            s4 = convolution::mul_add::<T, FMA>(a4, b8, s4);
            s5 = convolution::mul_add::<T, FMA>(a5, b9, s5);
            s14 = convolution::mul_add::<T, FMA>(a14, b34, s14);
            s17 = convolution::mul_add::<T, FMA>(a0, b32, s17);
            s17 = convolution::mul_add::<T, FMA>(-a1, b30, s17);
            s20 = convolution::mul_add::<T, FMA>(a3, b32, s20);
            s20 = convolution::mul_add::<T, FMA>(-a4, b30, s20);
            s21 = convolution::mul_add::<T, FMA>(a30, b38, s21);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s4 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s5);
                s14 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s14);
                s17 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 32 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 30 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 32 * s + 4 + 1), s17);
                s17 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 30 * s + 4 + 1), s17);
                s20 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s20);
                s21 = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s21);
            }
        }
        h[4] = s4;
        h[5] = s5;
        h[14] = s14;
        h[17] = s17;
        h[20] = s20;
        h[21] = s21;
        // Histories [15, 16, 18, 19, 22, 23].
        let (mut s15, mut s16, mut s18, mut s19, mut s22, mut s23) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b30, a32, b32, a34, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + j), at(c, 32 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s15 = convolution::mul_add::<T, FMA>(a1, b34, s15);
            s15 = convolution::mul_add::<T, FMA>(-a2, b32, s15);
            s16 = convolution::mul_add::<T, FMA>(a2, b30, s16);
            s16 = convolution::mul_add::<T, FMA>(-a0, b34, s16);
            s18 = convolution::mul_add::<T, FMA>(a4, b34, s18);
            s18 = convolution::mul_add::<T, FMA>(-a5, b32, s18);
            s19 = convolution::mul_add::<T, FMA>(a5, b30, s19);
            s19 = convolution::mul_add::<T, FMA>(-a3, b34, s19);
            s22 = convolution::mul_add::<T, FMA>(a32, b38, s22);
            s23 = convolution::mul_add::<T, FMA>(a34, b38, s23);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s15 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 34 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 34 * s + 4 + 1), s15);
                s15 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s15);
                s16 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 34 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s16);
                s16 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 34 * s + 4 + 1), s16);
                s18 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s18);
                s18 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s18);
                s19 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s19);
                s22 = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s22);
                s23 = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s23);
            }
        }
        h[15] = s15;
        h[16] = s16;
        h[18] = s18;
        h[19] = s19;
        h[22] = s22;
        h[23] = s23;
    } else if even {
        // Histories [0, 1, 8, 9, 11, 13]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s8, mut t8, mut s9, mut t9, mut s11, mut t11, mut s13, mut t13) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p8, mut p9, mut p28) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, b7, a8, b8, a9, b9, a27, b28) = unsafe { (at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 27 * s + 4 + j), at(c, 28 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a7, b7, s0);
            s0 = convolution::mul_add::<T, FMA>(a8, b8, s0);
            s1 = convolution::mul_add::<T, FMA>(a9, b9, s1);
            s8 = convolution::mul_add::<T, FMA>(a27, b28, s8);
            s9 = convolution::mul_add::<T, FMA>(a7, b28, s9);
            s11 = convolution::mul_add::<T, FMA>(a8, b28, s11);
            s13 = convolution::mul_add::<T, FMA>(a9, b28, s13);
            (b7, b8, b9, b28)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, b7, a8, b8, a9, b9, a27, b28) = unsafe { (at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 27 * s + 4 + j), at(c, 28 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a7, b7, s0);
            s0 = convolution::mul_add::<T, FMA>(a8, b8, s0);
            s1 = convolution::mul_add::<T, FMA>(a9, b9, s1);
            s8 = convolution::mul_add::<T, FMA>(a27, b28, s8);
            s9 = convolution::mul_add::<T, FMA>(a7, b28, s9);
            s11 = convolution::mul_add::<T, FMA>(a8, b28, s11);
            s13 = convolution::mul_add::<T, FMA>(a9, b28, s13);
            t0 = convolution::mul_add::<T, FMA>(a7, p7, t0);
            t0 = convolution::mul_add::<T, FMA>(a8, p8, t0);
            t1 = convolution::mul_add::<T, FMA>(a9, p9, t1);
            t8 = convolution::mul_add::<T, FMA>(a27, p28, t8);
            t9 = convolution::mul_add::<T, FMA>(a7, p28, t9);
            t11 = convolution::mul_add::<T, FMA>(a8, p28, t11);
            t13 = convolution::mul_add::<T, FMA>(a9, p28, t13);
            (p7, p8, p9, p28) = (b7, b8, b9, b28);
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[8] = s8;
        g[8] = t8;
        h[9] = s9;
        g[9] = t9;
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        // Histories [2, 3, 6, 7, 10, 12]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s2, mut t2, mut s3, mut t3, mut s6, mut t6, mut s7, mut t7, mut s10, mut t10, mut s12, mut t12) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p17, mut p18, mut p22, mut p23, mut p30, mut p32) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a14, b17, b18, b22, b23, b30, b32) = unsafe { (at(c, 14 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a14, b17, s2);
            s3 = convolution::mul_add::<T, FMA>(a14, b18, s3);
            s6 = convolution::mul_add::<T, FMA>(a14, b22, s6);
            s7 = convolution::mul_add::<T, FMA>(a14, b23, s7);
            s10 = convolution::mul_add::<T, FMA>(a14, b30, s10);
            s12 = convolution::mul_add::<T, FMA>(a14, b32, s12);
            (b17, b18, b22, b23, b30, b32)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a14, b17, b18, b22, b23, b30, b32) = unsafe { (at(c, 14 * s + 4 + j), at(c, 17 * s + 4 + k - j), at(c, 18 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a14, b17, s2);
            s3 = convolution::mul_add::<T, FMA>(a14, b18, s3);
            s6 = convolution::mul_add::<T, FMA>(a14, b22, s6);
            s7 = convolution::mul_add::<T, FMA>(a14, b23, s7);
            s10 = convolution::mul_add::<T, FMA>(a14, b30, s10);
            s12 = convolution::mul_add::<T, FMA>(a14, b32, s12);
            t2 = convolution::mul_add::<T, FMA>(a14, p17, t2);
            t3 = convolution::mul_add::<T, FMA>(a14, p18, t3);
            t6 = convolution::mul_add::<T, FMA>(a14, p22, t6);
            t7 = convolution::mul_add::<T, FMA>(a14, p23, t7);
            t10 = convolution::mul_add::<T, FMA>(a14, p30, t10);
            t12 = convolution::mul_add::<T, FMA>(a14, p32, t12);
            (p17, p18, p22, p23, p30, p32) = (b17, b18, b22, b23, b30, b32);
        }
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        // Histories [4, 5, 14, 17, 20, 21]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s4, mut t4, mut s5, mut t5, mut s14, mut t14, mut s17, mut t17, mut s20, mut t20, mut s21, mut t21) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p8, mut p9, mut p30, mut p32, mut p34, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b7, b8, b9, a14, a30, b30, b32, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 30 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s4 = convolution::mul_add::<T, FMA>(a3, b7, s4);
            s4 = convolution::mul_add::<T, FMA>(a4, b8, s4);
            s5 = convolution::mul_add::<T, FMA>(a5, b9, s5);
            s14 = convolution::mul_add::<T, FMA>(a14, b34, s14);
            s17 = convolution::mul_add::<T, FMA>(a0, b32, s17);
            s17 = convolution::mul_add::<T, FMA>(-a1, b30, s17);
            s20 = convolution::mul_add::<T, FMA>(a3, b32, s20);
            s20 = convolution::mul_add::<T, FMA>(-a4, b30, s20);
            s21 = convolution::mul_add::<T, FMA>(a30, b38, s21);
            (b7, b8, b9, b30, b32, b34, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b7, b8, b9, a14, a30, b30, b32, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 30 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s4 = convolution::mul_add::<T, FMA>(a3, b7, s4);
            s4 = convolution::mul_add::<T, FMA>(a4, b8, s4);
            s5 = convolution::mul_add::<T, FMA>(a5, b9, s5);
            s14 = convolution::mul_add::<T, FMA>(a14, b34, s14);
            s17 = convolution::mul_add::<T, FMA>(a0, b32, s17);
            s17 = convolution::mul_add::<T, FMA>(-a1, b30, s17);
            s20 = convolution::mul_add::<T, FMA>(a3, b32, s20);
            s20 = convolution::mul_add::<T, FMA>(-a4, b30, s20);
            s21 = convolution::mul_add::<T, FMA>(a30, b38, s21);
            t4 = convolution::mul_add::<T, FMA>(a3, p7, t4);
            t4 = convolution::mul_add::<T, FMA>(a4, p8, t4);
            t5 = convolution::mul_add::<T, FMA>(a5, p9, t5);
            t14 = convolution::mul_add::<T, FMA>(a14, p34, t14);
            t17 = convolution::mul_add::<T, FMA>(a0, p32, t17);
            t17 = convolution::mul_add::<T, FMA>(-a1, p30, t17);
            t20 = convolution::mul_add::<T, FMA>(a3, p32, t20);
            t20 = convolution::mul_add::<T, FMA>(-a4, p30, t20);
            t21 = convolution::mul_add::<T, FMA>(a30, p38, t21);
            (p7, p8, p9, p30, p32, p34, p38) = (b7, b8, b9, b30, b32, b34, b38);
        }
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[14] = s14;
        g[14] = t14;
        h[17] = s17;
        g[17] = t17;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
        // Histories [15, 16, 18, 19, 22, 23]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s15, mut t15, mut s16, mut t16, mut s18, mut t18, mut s19, mut t19, mut s22, mut t22, mut s23, mut t23) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p30, mut p32, mut p34, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b30, a32, b32, a34, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + j), at(c, 32 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s15 = convolution::mul_add::<T, FMA>(a1, b34, s15);
            s15 = convolution::mul_add::<T, FMA>(-a2, b32, s15);
            s16 = convolution::mul_add::<T, FMA>(a2, b30, s16);
            s16 = convolution::mul_add::<T, FMA>(-a0, b34, s16);
            s18 = convolution::mul_add::<T, FMA>(a4, b34, s18);
            s18 = convolution::mul_add::<T, FMA>(-a5, b32, s18);
            s19 = convolution::mul_add::<T, FMA>(a5, b30, s19);
            s19 = convolution::mul_add::<T, FMA>(-a3, b34, s19);
            s22 = convolution::mul_add::<T, FMA>(a32, b38, s22);
            s23 = convolution::mul_add::<T, FMA>(a34, b38, s23);
            (b30, b32, b34, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b30, a32, b32, a34, b34, b38) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 32 * s + 4 + j), at(c, 32 * s + 4 + k - j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s15 = convolution::mul_add::<T, FMA>(a1, b34, s15);
            s15 = convolution::mul_add::<T, FMA>(-a2, b32, s15);
            s16 = convolution::mul_add::<T, FMA>(a2, b30, s16);
            s16 = convolution::mul_add::<T, FMA>(-a0, b34, s16);
            s18 = convolution::mul_add::<T, FMA>(a4, b34, s18);
            s18 = convolution::mul_add::<T, FMA>(-a5, b32, s18);
            s19 = convolution::mul_add::<T, FMA>(a5, b30, s19);
            s19 = convolution::mul_add::<T, FMA>(-a3, b34, s19);
            s22 = convolution::mul_add::<T, FMA>(a32, b38, s22);
            s23 = convolution::mul_add::<T, FMA>(a34, b38, s23);
            t15 = convolution::mul_add::<T, FMA>(a1, p34, t15);
            t15 = convolution::mul_add::<T, FMA>(-a2, p32, t15);
            t16 = convolution::mul_add::<T, FMA>(a2, p30, t16);
            t16 = convolution::mul_add::<T, FMA>(-a0, p34, t16);
            t18 = convolution::mul_add::<T, FMA>(a4, p34, t18);
            t18 = convolution::mul_add::<T, FMA>(-a5, p32, t18);
            t19 = convolution::mul_add::<T, FMA>(a5, p30, t19);
            t19 = convolution::mul_add::<T, FMA>(-a3, p34, t19);
            t22 = convolution::mul_add::<T, FMA>(a32, p38, t22);
            t23 = convolution::mul_add::<T, FMA>(a34, p38, t23);
            (p30, p32, p34, p38) = (b30, b32, b34, b38);
        }
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 27 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 30 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 32 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[23] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh_general_free`.
#[inline(always)]
fn routh_general_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 24],
    q: &[f64; 11],
) {
    let v7 = c[4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = c[s + 4 + k] * q[1];
    c[8 * s + 4 + k] = v8;
    let v9 = c[2 * s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[7 * s + 4], v7], [c[8 * s + 4], v8, c[8 * s + 4], v8], h[0]);
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[1]);
    c[12 * s + 4 + k] = v12;
    let v13 = v11 + v12;
    c[13 * s + 4 + k] = v13;
    let v14 = v13 * q[4];
    c[14 * s + 4 + k] = v14;
    let v15 = v14;
    c[15 * s + 4 + k] = v15;
    let v16 = v14;
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::quotient::<T, FMA>(v11, c[15 * s + 4], v15, c[17 * s + 4], h[2]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::quotient::<T, FMA>(v12, c[16 * s + 4], v16, c[18 * s + 4], h[3]);
    c[18 * s + 4 + k] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::dot_add::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[7 * s + 4], v7], [c[4 * s + 4], c[4 * s + 4 + k], c[8 * s + 4], v8], h[4]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[10 * s + 4], v10, h[5]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::quotient::<T, FMA>(v20, c[15 * s + 4], v15, c[22 * s + 4], h[6]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::quotient::<T, FMA>(v21, c[16 * s + 4], v16, c[23 * s + 4], h[7]);
    c[23 * s + 4 + k] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4 + k] = v24;
    let v25 = v24 * q[7];
    c[25 * s + 4 + k] = v25;
    let v26 = v19 * q[8];
    c[26 * s + 4 + k] = v26;
    let v27 = -v26;
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::quotient::<T, FMA>(v25, c[27 * s + 4], v27, c[28 * s + 4], h[8]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[28 * s + 4], v28, c[3 * s + 4 + k], h[9]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::quotient::<T, FMA>(v29, c[15 * s + 4], v15, c[30 * s + 4], h[10]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[28 * s + 4], v28, c[4 * s + 4 + k], h[11]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::quotient::<T, FMA>(v31, c[15 * s + 4], v15, c[32 * s + 4], h[12]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[28 * s + 4], v28, c[5 * s + 4 + k], h[13]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::quotient::<T, FMA>(v33, c[16 * s + 4], v16, c[34 * s + 4], h[14]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[34 * s + 4], v34], [c[2 * s + 4], c[2 * s + 4 + k], c[32 * s + 4], v32], h[15]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[30 * s + 4], v30], [c[4], c[4 + k], c[34 * s + 4], v34], h[16]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[32 * s + 4], v32], [c[s + 4], c[s + 4 + k], c[30 * s + 4], v30], h[17]);
    c[37 * s + 4 + k] = v37;
    let v38 = v37 * q[10];
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[34 * s + 4], v34], [c[5 * s + 4], c[5 * s + 4 + k], c[32 * s + 4], v32], h[18]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[30 * s + 4], v30], [c[3 * s + 4], c[3 * s + 4 + k], c[34 * s + 4], v34], h[19]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[32 * s + 4], v32], [c[4 * s + 4], c[4 * s + 4 + k], c[30 * s + 4], v30], h[20]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::mul_plus::<T, FMA>(c[30 * s + 4], v30, c[38 * s + 4], v38, v39, h[21]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::mul_plus::<T, FMA>(c[32 * s + 4], v32, c[38 * s + 4], v38, v40, h[22]);
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::mul_plus::<T, FMA>(c[34 * s + 4], v34, c[38 * s + 4], v38, v41, h[23]);
    c[44 * s + 4 + k] = v44;
}

/// Order 0 of the kernel `routh_general_free`.
#[inline(always)]
fn routh_general_free_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 11]) {
    let v7 = c[4] * z[0];
    c[7 * s + 4] = v7;
    let v8 = c[s + 4] * z[1];
    c[8 * s + 4] = v8;
    let v9 = c[2 * s + 4] * z[2];
    c[9 * s + 4] = v9;
    let v10 = v9 + z[3];
    c[10 * s + 4] = v10;
    let v11 = v7 * v7 + v8 * v8;
    c[11 * s + 4] = v11;
    let v12 = v10 * v10;
    c[12 * s + 4] = v12;
    let v13 = v11 + v12;
    c[13 * s + 4] = v13;
    let v14 = v13 * z[4];
    c[14 * s + 4] = v14;
    let v15 = v14 + z[5];
    c[15 * s + 4] = v15;
    let v16 = v14 + z[6];
    c[16 * s + 4] = v16;
    let v17 = v11 / v15;
    c[17 * s + 4] = v17;
    let v18 = v12 / v16;
    c[18 * s + 4] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4] = v19;
    let v20 = c[3 * s + 4] * v7 + c[4 * s + 4] * v8;
    c[20 * s + 4] = v20;
    let v21 = c[5 * s + 4] * v10;
    c[21 * s + 4] = v21;
    let v22 = v20 / v15;
    c[22 * s + 4] = v22;
    let v23 = v21 / v16;
    c[23 * s + 4] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4] = v24;
    let v25 = v24 * z[7];
    c[25 * s + 4] = v25;
    let v26 = v19 * z[8];
    c[26 * s + 4] = v26;
    let v27 = T::from_f64(z[9]) - v26;
    c[27 * s + 4] = v27;
    let v28 = v25 / v27;
    c[28 * s + 4] = v28;
    let v29 = v7 * v28 + c[3 * s + 4];
    c[29 * s + 4] = v29;
    let v30 = v29 / v15;
    c[30 * s + 4] = v30;
    let v31 = v8 * v28 + c[4 * s + 4];
    c[31 * s + 4] = v31;
    let v32 = v31 / v15;
    c[32 * s + 4] = v32;
    let v33 = v10 * v28 + c[5 * s + 4];
    c[33 * s + 4] = v33;
    let v34 = v33 / v16;
    c[34 * s + 4] = v34;
    let v35 = c[s + 4] * v34 - c[2 * s + 4] * v32;
    c[35 * s + 4] = v35;
    let v36 = c[2 * s + 4] * v30 - c[4] * v34;
    c[36 * s + 4] = v36;
    let v37 = c[4] * v32 - c[s + 4] * v30;
    c[37 * s + 4] = v37;
    let v38 = v37 * z[10];
    c[38 * s + 4] = v38;
    let v39 = c[4 * s + 4] * v34 - c[5 * s + 4] * v32;
    c[39 * s + 4] = v39;
    let v40 = c[5 * s + 4] * v30 - c[3 * s + 4] * v34;
    c[40 * s + 4] = v40;
    let v41 = c[3 * s + 4] * v32 - c[4 * s + 4] * v30;
    c[41 * s + 4] = v41;
    let v42 = v30 * v38 + v39;
    c[42 * s + 4] = v42;
    let v43 = v32 * v38 + v40;
    c[43 * s + 4] = v43;
    let v44 = v34 * v38 + v41;
    c[44 * s + 4] = v44;
}

/// The pass of order `k >= 1` of the kernel `chaplygin`.
#[inline(always)]
fn chaplygin<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 25],
    _q: &[f64; 4],
) {
    let v7 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[4], c[4 + k], h[0]);
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k], h[1]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::product::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[2 * s + 4], c[2 * s + 4 + k], h[2]);
    c[9 * s + 4 + k] = v9;
    let v10 = v7 + v8;
    c[10 * s + 4 + k] = v10;
    let v11 = v9 + v10;
    c[11 * s + 4 + k] = v11;
    let v12 = v11;
    c[12 * s + 4 + k] = v12;
    let v13 = v11;
    c[13 * s + 4 + k] = v13;
    let v14 = v11;
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::quotient::<T, FMA>(v7, c[12 * s + 4], v12, c[15 * s + 4], h[3]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::quotient::<T, FMA>(v8, c[13 * s + 4], v13, c[16 * s + 4], h[4]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::quotient::<T, FMA>(v9, c[14 * s + 4], v14, c[17 * s + 4], h[5]);
    c[17 * s + 4 + k] = v17;
    let v18 = v15 + v16;
    c[18 * s + 4 + k] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[3 * s + 4], c[3 * s + 4 + k], h[6]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[4 * s + 4], c[4 * s + 4 + k], h[7]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[5 * s + 4], c[5 * s + 4 + k], h[8]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::quotient::<T, FMA>(v20, c[12 * s + 4], v12, c[23 * s + 4], h[9]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::quotient::<T, FMA>(v21, c[13 * s + 4], v13, c[24 * s + 4], h[10]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::quotient::<T, FMA>(v22, c[14 * s + 4], v14, c[25 * s + 4], h[11]);
    c[25 * s + 4 + k] = v25;
    let v26 = v23 + v24;
    c[26 * s + 4 + k] = v26;
    let v27 = v25 + v26;
    c[27 * s + 4 + k] = v27;
    let v28 = -v19;
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::quotient::<T, FMA>(v27, c[28 * s + 4], v28, c[29 * s + 4], h[12]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[29 * s + 4], v29, c[3 * s + 4 + k], h[13]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v30, c[12 * s + 4], v12, c[31 * s + 4], h[14]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[s + 4], c[s + 4 + k], c[29 * s + 4], v29, c[4 * s + 4 + k], h[15]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::quotient::<T, FMA>(v32, c[13 * s + 4], v13, c[33 * s + 4], h[16]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::mul_plus::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[29 * s + 4], v29, c[5 * s + 4 + k], h[17]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::quotient::<T, FMA>(v34, c[14 * s + 4], v14, c[35 * s + 4], h[18]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[35 * s + 4], v35], [c[2 * s + 4], c[2 * s + 4 + k], c[33 * s + 4], v33], h[19]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[31 * s + 4], v31], [c[4], c[4 + k], c[35 * s + 4], v35], h[20]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[33 * s + 4], v33], [c[s + 4], c[s + 4 + k], c[31 * s + 4], v31], h[21]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[35 * s + 4], v35], [c[5 * s + 4], c[5 * s + 4 + k], c[33 * s + 4], v33], h[22]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[31 * s + 4], v31], [c[3 * s + 4], c[3 * s + 4 + k], c[35 * s + 4], v35], h[23]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[33 * s + 4], v33], [c[4 * s + 4], c[4 * s + 4 + k], c[31 * s + 4], v31], h[24]);
    c[41 * s + 4 + k] = v41;
}

/// Order 0 of the kernel `chaplygin`.
#[inline(always)]
fn chaplygin_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 4]) {
    let v7 = c[4] * c[4];
    c[7 * s + 4] = v7;
    let v8 = c[s + 4] * c[s + 4];
    c[8 * s + 4] = v8;
    let v9 = c[2 * s + 4] * c[2 * s + 4];
    c[9 * s + 4] = v9;
    let v10 = v7 + v8;
    c[10 * s + 4] = v10;
    let v11 = v9 + v10;
    c[11 * s + 4] = v11;
    let v12 = v11 + z[0];
    c[12 * s + 4] = v12;
    let v13 = v11 + z[1];
    c[13 * s + 4] = v13;
    let v14 = v11 + z[2];
    c[14 * s + 4] = v14;
    let v15 = v7 / v12;
    c[15 * s + 4] = v15;
    let v16 = v8 / v13;
    c[16 * s + 4] = v16;
    let v17 = v9 / v14;
    c[17 * s + 4] = v17;
    let v18 = v15 + v16;
    c[18 * s + 4] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4] = v19;
    let v20 = c[4] * c[3 * s + 4];
    c[20 * s + 4] = v20;
    let v21 = c[s + 4] * c[4 * s + 4];
    c[21 * s + 4] = v21;
    let v22 = c[2 * s + 4] * c[5 * s + 4];
    c[22 * s + 4] = v22;
    let v23 = v20 / v12;
    c[23 * s + 4] = v23;
    let v24 = v21 / v13;
    c[24 * s + 4] = v24;
    let v25 = v22 / v14;
    c[25 * s + 4] = v25;
    let v26 = v23 + v24;
    c[26 * s + 4] = v26;
    let v27 = v25 + v26;
    c[27 * s + 4] = v27;
    let v28 = T::from_f64(z[3]) - v19;
    c[28 * s + 4] = v28;
    let v29 = v27 / v28;
    c[29 * s + 4] = v29;
    let v30 = c[4] * v29 + c[3 * s + 4];
    c[30 * s + 4] = v30;
    let v31 = v30 / v12;
    c[31 * s + 4] = v31;
    let v32 = c[s + 4] * v29 + c[4 * s + 4];
    c[32 * s + 4] = v32;
    let v33 = v32 / v13;
    c[33 * s + 4] = v33;
    let v34 = c[2 * s + 4] * v29 + c[5 * s + 4];
    c[34 * s + 4] = v34;
    let v35 = v34 / v14;
    c[35 * s + 4] = v35;
    let v36 = c[s + 4] * v35 - c[2 * s + 4] * v33;
    c[36 * s + 4] = v36;
    let v37 = c[2 * s + 4] * v31 - c[4] * v35;
    c[37 * s + 4] = v37;
    let v38 = c[4] * v33 - c[s + 4] * v31;
    c[38 * s + 4] = v38;
    let v39 = c[4 * s + 4] * v35 - c[5 * s + 4] * v33;
    c[39 * s + 4] = v39;
    let v40 = c[5 * s + 4] * v31 - c[3 * s + 4] * v35;
    c[40 * s + 4] = v40;
    let v41 = c[3 * s + 4] * v33 - c[4 * s + 4] * v31;
    c[41 * s + 4] = v41;
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
    assert!(k + 4 <= s && c.len() >= 36 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 6, 12, 13, 15].
        let (mut s0, mut s6, mut s12, mut s13, mut s15) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b3, a28, b29) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 3 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 29 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a0, b0, s0);
            s6 = convolution::mul_add::<T, FMA>(a0, b3, s6);
            s12 = convolution::mul_add::<T, FMA>(a28, b29, s12);
            s13 = convolution::mul_add::<T, FMA>(a0, b29, s13);
            s15 = convolution::mul_add::<T, FMA>(a1, b29, s15);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), s0);
                s6 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), s6);
                s12 = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), s12);
                s13 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 29 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 29 * s + 4 + 1), s13);
                s15 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 29 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 29 * s + 4 + 1), s15);
            }
        }
        h[0] = s0;
        h[6] = s6;
        h[12] = s12;
        h[13] = s13;
        h[15] = s15;
        // Histories [1, 2, 7, 8, 17].
        let (mut s1, mut s2, mut s7, mut s8, mut s17) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1, a2, b2, b4, b5, b29) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s1 = convolution::mul_add::<T, FMA>(a1, b1, s1);
            s2 = convolution::mul_add::<T, FMA>(a2, b2, s2);
            s7 = convolution::mul_add::<T, FMA>(a1, b4, s7);
            s8 = convolution::mul_add::<T, FMA>(a2, b5, s8);
            s17 = convolution::mul_add::<T, FMA>(a2, b29, s17);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s1 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), s1);
                s2 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s2);
                s7 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), s7);
                s8 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 5 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 5 * s + 4 + 1), s8);
                s17 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), s17);
            }
        }
        h[1] = s1;
        h[2] = s2;
        h[7] = s7;
        h[8] = s8;
        h[17] = s17;
        // Histories [3, 4, 5, 9, 10].
        let (mut s3, mut s4, mut s5, mut s9, mut s10) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a11, b15, b16, b17, b23, b24) = unsafe { (at(c, 11 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 16 * s + 4 + k - j), at(c, 17 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 24 * s + 4 + k - j)) };
            s3 = convolution::mul_add::<T, FMA>(a11, b15, s3);
            s4 = convolution::mul_add::<T, FMA>(a11, b16, s4);
            s5 = convolution::mul_add::<T, FMA>(a11, b17, s5);
            s9 = convolution::mul_add::<T, FMA>(a11, b23, s9);
            s10 = convolution::mul_add::<T, FMA>(a11, b24, s10);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s3 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), s3);
                s4 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 16 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 16 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), s5);
                s9 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), s9);
                s10 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), s10);
            }
        }
        h[3] = s3;
        h[4] = s4;
        h[5] = s5;
        h[9] = s9;
        h[10] = s10;
        // Histories [11, 14, 16, 18, 19].
        let (mut s11, mut s14, mut s16, mut s18, mut s19) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a11, b25, b31, b33, b35) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 35 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a11, b25, s11);
            s14 = convolution::mul_add::<T, FMA>(a11, b31, s14);
            s16 = convolution::mul_add::<T, FMA>(a11, b33, s16);
            s18 = convolution::mul_add::<T, FMA>(a11, b35, s18);
            s19 = convolution::mul_add::<T, FMA>(a1, b35, s19);
            s19 = convolution::mul_add::<T, FMA>(-a2, b33, s19);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s11 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s11);
                s14 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s14);
                s16 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s16);
                s18 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), s18);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 35 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 35 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s19);
            }
        }
        h[11] = s11;
        h[14] = s14;
        h[16] = s16;
        h[18] = s18;
        h[19] = s19;
        // Histories [20, 21, 22, 23, 24].
        let (mut s20, mut s21, mut s22, mut s23, mut s24) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b31, b33, b35) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 35 * s + 4 + k - j)) };
            s20 = convolution::mul_add::<T, FMA>(a2, b31, s20);
            s20 = convolution::mul_add::<T, FMA>(-a0, b35, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b33, s21);
            s21 = convolution::mul_add::<T, FMA>(-a1, b31, s21);
            s22 = convolution::mul_add::<T, FMA>(a4, b35, s22);
            s22 = convolution::mul_add::<T, FMA>(-a5, b33, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b31, s23);
            s23 = convolution::mul_add::<T, FMA>(-a3, b35, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b33, s24);
            s24 = convolution::mul_add::<T, FMA>(-a4, b31, s24);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 35 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 35 * s + 4 + 1), s20);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 33 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 31 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 33 * s + 4 + 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 31 * s + 4 + 1), s21);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s22);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), s23);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s24);
            }
        }
        h[20] = s20;
        h[21] = s21;
        h[22] = s22;
        h[23] = s23;
        h[24] = s24;
    } else if even {
        // Histories [0, 6, 12, 13, 15]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s6, mut t6, mut s12, mut t12, mut s13, mut t13, mut s15, mut t15) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p0, mut p3, mut p29) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b3, a28, b29) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 3 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 29 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a0, b0, s0);
            s6 = convolution::mul_add::<T, FMA>(a0, b3, s6);
            s12 = convolution::mul_add::<T, FMA>(a28, b29, s12);
            s13 = convolution::mul_add::<T, FMA>(a0, b29, s13);
            s15 = convolution::mul_add::<T, FMA>(a1, b29, s15);
            (b0, b3, b29)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b3, a28, b29) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, 3 * s + 4 + k - j), at(c, 28 * s + 4 + j), at(c, 29 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a0, b0, s0);
            s6 = convolution::mul_add::<T, FMA>(a0, b3, s6);
            s12 = convolution::mul_add::<T, FMA>(a28, b29, s12);
            s13 = convolution::mul_add::<T, FMA>(a0, b29, s13);
            s15 = convolution::mul_add::<T, FMA>(a1, b29, s15);
            t0 = convolution::mul_add::<T, FMA>(a0, p0, t0);
            t6 = convolution::mul_add::<T, FMA>(a0, p3, t6);
            t12 = convolution::mul_add::<T, FMA>(a28, p29, t12);
            t13 = convolution::mul_add::<T, FMA>(a0, p29, t13);
            t15 = convolution::mul_add::<T, FMA>(a1, p29, t15);
            (p0, p3, p29) = (b0, b3, b29);
        }
        h[0] = s0;
        g[0] = t0;
        h[6] = s6;
        g[6] = t6;
        h[12] = s12;
        g[12] = t12;
        h[13] = s13;
        g[13] = t13;
        h[15] = s15;
        g[15] = t15;
        // Histories [1, 2, 7, 8, 17]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s1, mut t1, mut s2, mut t2, mut s7, mut t7, mut s8, mut t8, mut s17, mut t17) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p1, mut p2, mut p4, mut p5, mut p29) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1, a2, b2, b4, b5, b29) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s1 = convolution::mul_add::<T, FMA>(a1, b1, s1);
            s2 = convolution::mul_add::<T, FMA>(a2, b2, s2);
            s7 = convolution::mul_add::<T, FMA>(a1, b4, s7);
            s8 = convolution::mul_add::<T, FMA>(a2, b5, s8);
            s17 = convolution::mul_add::<T, FMA>(a2, b29, s17);
            (b1, b2, b4, b5, b29)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, b1, a2, b2, b4, b5, b29) = unsafe { (at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + k - j), at(c, 29 * s + 4 + k - j)) };
            s1 = convolution::mul_add::<T, FMA>(a1, b1, s1);
            s2 = convolution::mul_add::<T, FMA>(a2, b2, s2);
            s7 = convolution::mul_add::<T, FMA>(a1, b4, s7);
            s8 = convolution::mul_add::<T, FMA>(a2, b5, s8);
            s17 = convolution::mul_add::<T, FMA>(a2, b29, s17);
            t1 = convolution::mul_add::<T, FMA>(a1, p1, t1);
            t2 = convolution::mul_add::<T, FMA>(a2, p2, t2);
            t7 = convolution::mul_add::<T, FMA>(a1, p4, t7);
            t8 = convolution::mul_add::<T, FMA>(a2, p5, t8);
            t17 = convolution::mul_add::<T, FMA>(a2, p29, t17);
            (p1, p2, p4, p5, p29) = (b1, b2, b4, b5, b29);
        }
        h[1] = s1;
        g[1] = t1;
        h[2] = s2;
        g[2] = t2;
        h[7] = s7;
        g[7] = t7;
        h[8] = s8;
        g[8] = t8;
        h[17] = s17;
        g[17] = t17;
        // Histories [3, 4, 5, 9, 10]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s3, mut t3, mut s4, mut t4, mut s5, mut t5, mut s9, mut t9, mut s10, mut t10) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p15, mut p16, mut p17, mut p23, mut p24) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a11, b15, b16, b17, b23, b24) = unsafe { (at(c, 11 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 16 * s + 4 + k - j), at(c, 17 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 24 * s + 4 + k - j)) };
            s3 = convolution::mul_add::<T, FMA>(a11, b15, s3);
            s4 = convolution::mul_add::<T, FMA>(a11, b16, s4);
            s5 = convolution::mul_add::<T, FMA>(a11, b17, s5);
            s9 = convolution::mul_add::<T, FMA>(a11, b23, s9);
            s10 = convolution::mul_add::<T, FMA>(a11, b24, s10);
            (b15, b16, b17, b23, b24)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a11, b15, b16, b17, b23, b24) = unsafe { (at(c, 11 * s + 4 + j), at(c, 15 * s + 4 + k - j), at(c, 16 * s + 4 + k - j), at(c, 17 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 24 * s + 4 + k - j)) };
            s3 = convolution::mul_add::<T, FMA>(a11, b15, s3);
            s4 = convolution::mul_add::<T, FMA>(a11, b16, s4);
            s5 = convolution::mul_add::<T, FMA>(a11, b17, s5);
            s9 = convolution::mul_add::<T, FMA>(a11, b23, s9);
            s10 = convolution::mul_add::<T, FMA>(a11, b24, s10);
            t3 = convolution::mul_add::<T, FMA>(a11, p15, t3);
            t4 = convolution::mul_add::<T, FMA>(a11, p16, t4);
            t5 = convolution::mul_add::<T, FMA>(a11, p17, t5);
            t9 = convolution::mul_add::<T, FMA>(a11, p23, t9);
            t10 = convolution::mul_add::<T, FMA>(a11, p24, t10);
            (p15, p16, p17, p23, p24) = (b15, b16, b17, b23, b24);
        }
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[9] = s9;
        g[9] = t9;
        h[10] = s10;
        g[10] = t10;
        // Histories [11, 14, 16, 18, 19]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s11, mut t11, mut s14, mut t14, mut s16, mut t16, mut s18, mut t18, mut s19, mut t19) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p25, mut p31, mut p33, mut p35) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a11, b25, b31, b33, b35) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 35 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a11, b25, s11);
            s14 = convolution::mul_add::<T, FMA>(a11, b31, s14);
            s16 = convolution::mul_add::<T, FMA>(a11, b33, s16);
            s18 = convolution::mul_add::<T, FMA>(a11, b35, s18);
            s19 = convolution::mul_add::<T, FMA>(a1, b35, s19);
            s19 = convolution::mul_add::<T, FMA>(-a2, b33, s19);
            (b25, b31, b33, b35)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a11, b25, b31, b33, b35) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 35 * s + 4 + k - j)) };
            s11 = convolution::mul_add::<T, FMA>(a11, b25, s11);
            s14 = convolution::mul_add::<T, FMA>(a11, b31, s14);
            s16 = convolution::mul_add::<T, FMA>(a11, b33, s16);
            s18 = convolution::mul_add::<T, FMA>(a11, b35, s18);
            s19 = convolution::mul_add::<T, FMA>(a1, b35, s19);
            s19 = convolution::mul_add::<T, FMA>(-a2, b33, s19);
            t11 = convolution::mul_add::<T, FMA>(a11, p25, t11);
            t14 = convolution::mul_add::<T, FMA>(a11, p31, t14);
            t16 = convolution::mul_add::<T, FMA>(a11, p33, t16);
            t18 = convolution::mul_add::<T, FMA>(a11, p35, t18);
            t19 = convolution::mul_add::<T, FMA>(a1, p35, t19);
            t19 = convolution::mul_add::<T, FMA>(-a2, p33, t19);
            (p25, p31, p33, p35) = (b25, b31, b33, b35);
        }
        h[11] = s11;
        g[11] = t11;
        h[14] = s14;
        g[14] = t14;
        h[16] = s16;
        g[16] = t16;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        // Histories [20, 21, 22, 23, 24]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s20, mut t20, mut s21, mut t21, mut s22, mut t22, mut s23, mut t23, mut s24, mut t24) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p31, mut p33, mut p35) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b31, b33, b35) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 35 * s + 4 + k - j)) };
            s20 = convolution::mul_add::<T, FMA>(a2, b31, s20);
            s20 = convolution::mul_add::<T, FMA>(-a0, b35, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b33, s21);
            s21 = convolution::mul_add::<T, FMA>(-a1, b31, s21);
            s22 = convolution::mul_add::<T, FMA>(a4, b35, s22);
            s22 = convolution::mul_add::<T, FMA>(-a5, b33, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b31, s23);
            s23 = convolution::mul_add::<T, FMA>(-a3, b35, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b33, s24);
            s24 = convolution::mul_add::<T, FMA>(-a4, b31, s24);
            (b31, b33, b35)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b31, b33, b35) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 35 * s + 4 + k - j)) };
            s20 = convolution::mul_add::<T, FMA>(a2, b31, s20);
            s20 = convolution::mul_add::<T, FMA>(-a0, b35, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b33, s21);
            s21 = convolution::mul_add::<T, FMA>(-a1, b31, s21);
            s22 = convolution::mul_add::<T, FMA>(a4, b35, s22);
            s22 = convolution::mul_add::<T, FMA>(-a5, b33, s22);
            s23 = convolution::mul_add::<T, FMA>(a5, b31, s23);
            s23 = convolution::mul_add::<T, FMA>(-a3, b35, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b33, s24);
            s24 = convolution::mul_add::<T, FMA>(-a4, b31, s24);
            t20 = convolution::mul_add::<T, FMA>(a2, p31, t20);
            t20 = convolution::mul_add::<T, FMA>(-a0, p35, t20);
            t21 = convolution::mul_add::<T, FMA>(a0, p33, t21);
            t21 = convolution::mul_add::<T, FMA>(-a1, p31, t21);
            t22 = convolution::mul_add::<T, FMA>(a4, p35, t22);
            t22 = convolution::mul_add::<T, FMA>(-a5, p33, t22);
            t23 = convolution::mul_add::<T, FMA>(a5, p31, t23);
            t23 = convolution::mul_add::<T, FMA>(-a3, p35, t23);
            t24 = convolution::mul_add::<T, FMA>(a3, p33, t24);
            t24 = convolution::mul_add::<T, FMA>(-a4, p31, t24);
            (p31, p33, p35) = (b31, b33, b35);
        }
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
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 15 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 15 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 16 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 16 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 17 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 17 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 5 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 5 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 28 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 29 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 29 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 35 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 35 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
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
    q: &[f64; 22],
) {
    let v7 = c[4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = v7;
    c[8 * s + 4 + k] = v8;
    let v9 = c[s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = v9;
    c[10 * s + 4 + k] = v10;
    let v11 = c[2 * s + 4 + k] * q[4];
    c[11 * s + 4 + k] = v11;
    let v12 = v11;
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[8 * s + 4], v8, h[0]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[1]);
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[12 * s + 4], v12, c[12 * s + 4], v12, h[2]);
    c[15 * s + 4 + k] = v15;
    let v16 = v13 + v14;
    c[16 * s + 4 + k] = v16;
    let v17 = v15 + v16;
    c[17 * s + 4 + k] = v17;
    let v18 = v17 * q[6];
    c[18 * s + 4 + k] = v18;
    let v19 = v18;
    c[19 * s + 4 + k] = v19;
    let v20 = v18;
    c[20 * s + 4 + k] = v20;
    let v21 = v18;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::quotient::<T, FMA>(v13, c[19 * s + 4], v19, c[22 * s + 4], h[3]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::quotient::<T, FMA>(v14, c[20 * s + 4], v20, c[23 * s + 4], h[4]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::quotient::<T, FMA>(v15, c[21 * s + 4], v21, c[24 * s + 4], h[5]);
    c[24 * s + 4 + k] = v24;
    let v25 = v22 + v23;
    c[25 * s + 4 + k] = v25;
    let v26 = v24 + v25;
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[8 * s + 4], v8, h[6]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[10 * s + 4], v10, h[7]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[12 * s + 4], v12, h[8]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::quotient::<T, FMA>(v27, c[19 * s + 4], v19, c[30 * s + 4], h[9]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v28, c[20 * s + 4], v20, c[31 * s + 4], h[10]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::quotient::<T, FMA>(v29, c[21 * s + 4], v21, c[32 * s + 4], h[11]);
    c[32 * s + 4 + k] = v32;
    let v33 = v30 + v31;
    c[33 * s + 4 + k] = v33;
    let v34 = v32 + v33;
    c[34 * s + 4 + k] = v34;
    let v35 = v34 * q[10];
    c[35 * s + 4 + k] = v35;
    let v36 = v26 * q[11];
    c[36 * s + 4 + k] = v36;
    let v37 = -v36;
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::quotient::<T, FMA>(v35, c[37 * s + 4], v37, c[38 * s + 4], h[12]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[38 * s + 4], v38, c[3 * s + 4 + k], h[13]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::quotient::<T, FMA>(v39, c[19 * s + 4], v19, c[40 * s + 4], h[14]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[38 * s + 4], v38, c[4 * s + 4 + k], h[15]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::quotient::<T, FMA>(v41, c[20 * s + 4], v20, c[42 * s + 4], h[16]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::mul_plus::<T, FMA>(c[12 * s + 4], v12, c[38 * s + 4], v38, c[5 * s + 4 + k], h[17]);
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::quotient::<T, FMA>(v43, c[21 * s + 4], v21, c[44 * s + 4], h[18]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[44 * s + 4], v44], [c[2 * s + 4], c[2 * s + 4 + k], c[42 * s + 4], v42], h[19]);
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[40 * s + 4], v40], [c[4], c[4 + k], c[44 * s + 4], v44], h[20]);
    c[46 * s + 4 + k] = v46;
    let v47 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[42 * s + 4], v42], [c[s + 4], c[s + 4 + k], c[40 * s + 4], v40], h[21]);
    c[47 * s + 4 + k] = v47;
    let v48 = v45 * q[13];
    c[48 * s + 4 + k] = v48;
    let v49 = v46 * q[14];
    c[49 * s + 4 + k] = v49;
    let v50 = v48 + v49;
    c[50 * s + 4 + k] = v50;
    let v51 = v47 * q[15];
    c[51 * s + 4 + k] = v51;
    let v52 = v50 + v51;
    c[52 * s + 4 + k] = v52;
    let v53 = c[s + 4 + k] * q[16];
    c[53 * s + 4 + k] = v53;
    let v54 = c[2 * s + 4 + k] * q[17];
    c[54 * s + 4 + k] = v54;
    let v55 = v53 - v54;
    c[55 * s + 4 + k] = v55;
    let v56 = c[2 * s + 4 + k] * q[18];
    c[56 * s + 4 + k] = v56;
    let v57 = c[4 + k] * q[19];
    c[57 * s + 4 + k] = v57;
    let v58 = v56 - v57;
    c[58 * s + 4 + k] = v58;
    let v59 = c[4 + k] * q[20];
    c[59 * s + 4 + k] = v59;
    let v60 = c[s + 4 + k] * q[21];
    c[60 * s + 4 + k] = v60;
    let v61 = v59 - v60;
    c[61 * s + 4 + k] = v61;
    let v62 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[44 * s + 4], v44], [c[5 * s + 4], c[5 * s + 4 + k], c[42 * s + 4], v42], h[22]);
    c[62 * s + 4 + k] = v62;
    let v63 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[40 * s + 4], v40], [c[3 * s + 4], c[3 * s + 4 + k], c[44 * s + 4], v44], h[23]);
    c[63 * s + 4 + k] = v63;
    let v64 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[42 * s + 4], v42], [c[4 * s + 4], c[4 * s + 4 + k], c[40 * s + 4], v40], h[24]);
    c[64 * s + 4 + k] = v64;
    let v65 = v55 + v62;
    c[65 * s + 4 + k] = v65;
    let v66 = recurrence::mul_plus::<T, FMA>(c[40 * s + 4], v40, c[52 * s + 4], v52, v65, h[25]);
    c[66 * s + 4 + k] = v66;
    let v67 = v58 + v63;
    c[67 * s + 4 + k] = v67;
    let v68 = recurrence::mul_plus::<T, FMA>(c[42 * s + 4], v42, c[52 * s + 4], v52, v67, h[26]);
    c[68 * s + 4 + k] = v68;
    let v69 = v61 + v64;
    c[69 * s + 4 + k] = v69;
    let v70 = recurrence::mul_plus::<T, FMA>(c[44 * s + 4], v44, c[52 * s + 4], v52, v69, h[27]);
    c[70 * s + 4 + k] = v70;
}

/// Order 0 of the kernel `ball`.
#[inline(always)]
fn ball_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 22]) {
    let v7 = c[4] * z[0];
    c[7 * s + 4] = v7;
    let v8 = v7 + z[1];
    c[8 * s + 4] = v8;
    let v9 = c[s + 4] * z[2];
    c[9 * s + 4] = v9;
    let v10 = v9 + z[3];
    c[10 * s + 4] = v10;
    let v11 = c[2 * s + 4] * z[4];
    c[11 * s + 4] = v11;
    let v12 = v11 + z[5];
    c[12 * s + 4] = v12;
    let v13 = v8 * v8;
    c[13 * s + 4] = v13;
    let v14 = v10 * v10;
    c[14 * s + 4] = v14;
    let v15 = v12 * v12;
    c[15 * s + 4] = v15;
    let v16 = v13 + v14;
    c[16 * s + 4] = v16;
    let v17 = v15 + v16;
    c[17 * s + 4] = v17;
    let v18 = v17 * z[6];
    c[18 * s + 4] = v18;
    let v19 = v18 + z[7];
    c[19 * s + 4] = v19;
    let v20 = v18 + z[8];
    c[20 * s + 4] = v20;
    let v21 = v18 + z[9];
    c[21 * s + 4] = v21;
    let v22 = v13 / v19;
    c[22 * s + 4] = v22;
    let v23 = v14 / v20;
    c[23 * s + 4] = v23;
    let v24 = v15 / v21;
    c[24 * s + 4] = v24;
    let v25 = v22 + v23;
    c[25 * s + 4] = v25;
    let v26 = v24 + v25;
    c[26 * s + 4] = v26;
    let v27 = c[3 * s + 4] * v8;
    c[27 * s + 4] = v27;
    let v28 = c[4 * s + 4] * v10;
    c[28 * s + 4] = v28;
    let v29 = c[5 * s + 4] * v12;
    c[29 * s + 4] = v29;
    let v30 = v27 / v19;
    c[30 * s + 4] = v30;
    let v31 = v28 / v20;
    c[31 * s + 4] = v31;
    let v32 = v29 / v21;
    c[32 * s + 4] = v32;
    let v33 = v30 + v31;
    c[33 * s + 4] = v33;
    let v34 = v32 + v33;
    c[34 * s + 4] = v34;
    let v35 = v34 * z[10];
    c[35 * s + 4] = v35;
    let v36 = v26 * z[11];
    c[36 * s + 4] = v36;
    let v37 = T::from_f64(z[12]) - v36;
    c[37 * s + 4] = v37;
    let v38 = v35 / v37;
    c[38 * s + 4] = v38;
    let v39 = v8 * v38 + c[3 * s + 4];
    c[39 * s + 4] = v39;
    let v40 = v39 / v19;
    c[40 * s + 4] = v40;
    let v41 = v10 * v38 + c[4 * s + 4];
    c[41 * s + 4] = v41;
    let v42 = v41 / v20;
    c[42 * s + 4] = v42;
    let v43 = v12 * v38 + c[5 * s + 4];
    c[43 * s + 4] = v43;
    let v44 = v43 / v21;
    c[44 * s + 4] = v44;
    let v45 = c[s + 4] * v44 - c[2 * s + 4] * v42;
    c[45 * s + 4] = v45;
    let v46 = c[2 * s + 4] * v40 - c[4] * v44;
    c[46 * s + 4] = v46;
    let v47 = c[4] * v42 - c[s + 4] * v40;
    c[47 * s + 4] = v47;
    let v48 = v45 * z[13];
    c[48 * s + 4] = v48;
    let v49 = v46 * z[14];
    c[49 * s + 4] = v49;
    let v50 = v48 + v49;
    c[50 * s + 4] = v50;
    let v51 = v47 * z[15];
    c[51 * s + 4] = v51;
    let v52 = v50 + v51;
    c[52 * s + 4] = v52;
    let v53 = c[s + 4] * z[16];
    c[53 * s + 4] = v53;
    let v54 = c[2 * s + 4] * z[17];
    c[54 * s + 4] = v54;
    let v55 = v53 - v54;
    c[55 * s + 4] = v55;
    let v56 = c[2 * s + 4] * z[18];
    c[56 * s + 4] = v56;
    let v57 = c[4] * z[19];
    c[57 * s + 4] = v57;
    let v58 = v56 - v57;
    c[58 * s + 4] = v58;
    let v59 = c[4] * z[20];
    c[59 * s + 4] = v59;
    let v60 = c[s + 4] * z[21];
    c[60 * s + 4] = v60;
    let v61 = v59 - v60;
    c[61 * s + 4] = v61;
    let v62 = c[4 * s + 4] * v44 - c[5 * s + 4] * v42;
    c[62 * s + 4] = v62;
    let v63 = c[5 * s + 4] * v40 - c[3 * s + 4] * v44;
    c[63 * s + 4] = v63;
    let v64 = c[3 * s + 4] * v42 - c[4 * s + 4] * v40;
    c[64 * s + 4] = v64;
    let v65 = v55 + v62;
    c[65 * s + 4] = v65;
    let v66 = v40 * v52 + v65;
    c[66 * s + 4] = v66;
    let v67 = v58 + v63;
    c[67 * s + 4] = v67;
    let v68 = v42 * v52 + v67;
    c[68 * s + 4] = v68;
    let v69 = v61 + v64;
    c[69 * s + 4] = v69;
    let v70 = v44 * v52 + v69;
    c[70 * s + 4] = v70;
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
    assert!(k + 4 <= s && c.len() >= 53 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 6, 12, 13, 15].
        let (mut s0, mut s1, mut s6, mut s12, mut s13, mut s15) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a7, b7, a9, b9, a37, b38) = unsafe { (at(c, 3 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 37 * s + 4 + j), at(c, 38 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a7, b7, s0);
            s1 = convolution::mul_add::<T, FMA>(a9, b9, s1);
            s6 = convolution::mul_add::<T, FMA>(a3, b7, s6);
            s12 = convolution::mul_add::<T, FMA>(a37, b38, s12);
            s13 = convolution::mul_add::<T, FMA>(a7, b38, s13);
            s15 = convolution::mul_add::<T, FMA>(a9, b38, s15);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s0);
                s0 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s0);
                s1 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s1);
                s1 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s1);
                s6 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s6);
                s6 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s6);
                s12 = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s12);
                s12 = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s12);
                s13 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s13);
                s13 = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s13);
                s15 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s15);
                s15 = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s15);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[6] = s6;
        h[12] = s12;
        h[13] = s13;
        h[15] = s15;
        // Histories [2, 3, 4, 5, 8, 17].
        let (mut s2, mut s3, mut s4, mut s5, mut s8, mut s17) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a11, b11, a18, b22, b23, b24, b38) = unsafe { (at(c, 5 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 24 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a11, b11, s2);
            s3 = convolution::mul_add::<T, FMA>(a18, b22, s3);
            s4 = convolution::mul_add::<T, FMA>(a18, b23, s4);
            s5 = convolution::mul_add::<T, FMA>(a18, b24, s5);
            s8 = convolution::mul_add::<T, FMA>(a5, b11, s8);
            s17 = convolution::mul_add::<T, FMA>(a11, b38, s17);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s2 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s2);
                s2 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s2);
                s3 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s3);
                s3 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s3);
                s4 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), s4);
                s4 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), s4);
                s5 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), s5);
                s5 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), s5);
                s8 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s8);
                s8 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s8);
                s17 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), s17);
                s17 = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), s17);
            }
        }
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[5] = s5;
        h[8] = s8;
        h[17] = s17;
        // Histories [7, 9, 10, 11, 14, 16].
        let (mut s7, mut s9, mut s10, mut s11, mut s14, mut s16) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a4, b9, a18, b30, b31, b32, b40, b42) = unsafe { (at(c, 4 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 40 * s + 4 + k - j), at(c, 42 * s + 4 + k - j)) };
            s7 = convolution::mul_add::<T, FMA>(a4, b9, s7);
            s9 = convolution::mul_add::<T, FMA>(a18, b30, s9);
            s10 = convolution::mul_add::<T, FMA>(a18, b31, s10);
            s11 = convolution::mul_add::<T, FMA>(a18, b32, s11);
            s14 = convolution::mul_add::<T, FMA>(a18, b40, s14);
            s16 = convolution::mul_add::<T, FMA>(a18, b42, s16);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s7 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s7);
                s7 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s7);
                s9 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s9);
                s9 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s9);
                s10 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s10);
                s10 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s10);
                s11 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), s11);
                s11 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), s11);
                s14 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), s14);
                s14 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), s14);
                s16 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), s16);
                s16 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), s16);
            }
        }
        h[7] = s7;
        h[9] = s9;
        h[10] = s10;
        h[11] = s11;
        h[14] = s14;
        h[16] = s16;
        // Histories [18, 19, 22, 25, 26, 27].
        let (mut s18, mut s19, mut s22, mut s25, mut s26, mut s27) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a4, a5, a18, a40, a42, b42, a44, b44, b52) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 18 * s + 4 + j), at(c, 40 * s + 4 + j), at(c, 42 * s + 4 + j), at(c, 42 * s + 4 + k - j), at(c, 44 * s + 4 + j), at(c, 44 * s + 4 + k - j), at(c, 52 * s + 4 + k - j)) };
            s18 = convolution::mul_add::<T, FMA>(a18, b44, s18);
            s19 = convolution::mul_add::<T, FMA>(a1, b44, s19);
            s19 = convolution::mul_add::<T, FMA>(-a2, b42, s19);
            s22 = convolution::mul_add::<T, FMA>(a4, b44, s22);
            s22 = convolution::mul_add::<T, FMA>(-a5, b42, s22);
            s25 = convolution::mul_add::<T, FMA>(a40, b52, s25);
            s26 = convolution::mul_add::<T, FMA>(a42, b52, s26);
            s27 = convolution::mul_add::<T, FMA>(a44, b52, s27);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s18 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), s18);
                s18 = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), s18);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 44 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), s19);
                s19 = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 44 * s + 4 + 1), s19);
                s19 = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), s19);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), s22);
                s22 = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), s22);
                s22 = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), s22);
                s25 = convolution::mul_add::<T, FMA>(at(c, 40 * s + 4 + 1), at(c, 52 * s + 4 + k - 1), s25);
                s25 = convolution::mul_add::<T, FMA>(at(c, 40 * s + 4 + k - 1), at(c, 52 * s + 4 + 1), s25);
                s26 = convolution::mul_add::<T, FMA>(at(c, 42 * s + 4 + 1), at(c, 52 * s + 4 + k - 1), s26);
                s26 = convolution::mul_add::<T, FMA>(at(c, 42 * s + 4 + k - 1), at(c, 52 * s + 4 + 1), s26);
                s27 = convolution::mul_add::<T, FMA>(at(c, 44 * s + 4 + 1), at(c, 52 * s + 4 + k - 1), s27);
                s27 = convolution::mul_add::<T, FMA>(at(c, 44 * s + 4 + k - 1), at(c, 52 * s + 4 + 1), s27);
            }
        }
        h[18] = s18;
        h[19] = s19;
        h[22] = s22;
        h[25] = s25;
        h[26] = s26;
        h[27] = s27;
        // Histories [20, 21, 23, 24].
        let (mut s20, mut s21, mut s23, mut s24) = (zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b40, b42, b44) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 40 * s + 4 + k - j), at(c, 42 * s + 4 + k - j), at(c, 44 * s + 4 + k - j)) };
            s20 = convolution::mul_add::<T, FMA>(a2, b40, s20);
            s20 = convolution::mul_add::<T, FMA>(-a0, b44, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b42, s21);
            s21 = convolution::mul_add::<T, FMA>(-a1, b40, s21);
            s23 = convolution::mul_add::<T, FMA>(a5, b40, s23);
            s23 = convolution::mul_add::<T, FMA>(-a3, b44, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b42, s24);
            s24 = convolution::mul_add::<T, FMA>(-a4, b40, s24);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 44 * s + 4 + k - 1), s20);
                s20 = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), s20);
                s20 = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 44 * s + 4 + 1), s20);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 42 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 40 * s + 4 + k - 1), s21);
                s21 = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 42 * s + 4 + 1), s21);
                s21 = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 40 * s + 4 + 1), s21);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), s23);
                s23 = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), s23);
                s23 = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), s23);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), s24);
                s24 = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), s24);
                s24 = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), s24);
            }
        }
        h[20] = s20;
        h[21] = s21;
        h[23] = s23;
        h[24] = s24;
    } else if even {
        // Histories [0, 1, 6, 12, 13, 15]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s6, mut t6, mut s12, mut t12, mut s13, mut t13, mut s15, mut t15) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p9, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a7, b7, a9, b9, a37, b38) = unsafe { (at(c, 3 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 37 * s + 4 + j), at(c, 38 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a7, b7, s0);
            s1 = convolution::mul_add::<T, FMA>(a9, b9, s1);
            s6 = convolution::mul_add::<T, FMA>(a3, b7, s6);
            s12 = convolution::mul_add::<T, FMA>(a37, b38, s12);
            s13 = convolution::mul_add::<T, FMA>(a7, b38, s13);
            s15 = convolution::mul_add::<T, FMA>(a9, b38, s15);
            (b7, b9, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a7, b7, a9, b9, a37, b38) = unsafe { (at(c, 3 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 37 * s + 4 + j), at(c, 38 * s + 4 + k - j)) };
            s0 = convolution::mul_add::<T, FMA>(a7, b7, s0);
            s1 = convolution::mul_add::<T, FMA>(a9, b9, s1);
            s6 = convolution::mul_add::<T, FMA>(a3, b7, s6);
            s12 = convolution::mul_add::<T, FMA>(a37, b38, s12);
            s13 = convolution::mul_add::<T, FMA>(a7, b38, s13);
            s15 = convolution::mul_add::<T, FMA>(a9, b38, s15);
            t0 = convolution::mul_add::<T, FMA>(a7, p7, t0);
            t1 = convolution::mul_add::<T, FMA>(a9, p9, t1);
            t6 = convolution::mul_add::<T, FMA>(a3, p7, t6);
            t12 = convolution::mul_add::<T, FMA>(a37, p38, t12);
            t13 = convolution::mul_add::<T, FMA>(a7, p38, t13);
            t15 = convolution::mul_add::<T, FMA>(a9, p38, t15);
            (p7, p9, p38) = (b7, b9, b38);
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[6] = s6;
        g[6] = t6;
        h[12] = s12;
        g[12] = t12;
        h[13] = s13;
        g[13] = t13;
        h[15] = s15;
        g[15] = t15;
        // Histories [2, 3, 4, 5, 8, 17]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s5, mut t5, mut s8, mut t8, mut s17, mut t17) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p11, mut p22, mut p23, mut p24, mut p38) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a11, b11, a18, b22, b23, b24, b38) = unsafe { (at(c, 5 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 24 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a11, b11, s2);
            s3 = convolution::mul_add::<T, FMA>(a18, b22, s3);
            s4 = convolution::mul_add::<T, FMA>(a18, b23, s4);
            s5 = convolution::mul_add::<T, FMA>(a18, b24, s5);
            s8 = convolution::mul_add::<T, FMA>(a5, b11, s8);
            s17 = convolution::mul_add::<T, FMA>(a11, b38, s17);
            (b11, b22, b23, b24, b38)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a5, a11, b11, a18, b22, b23, b24, b38) = unsafe { (at(c, 5 * s + 4 + j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 22 * s + 4 + k - j), at(c, 23 * s + 4 + k - j), at(c, 24 * s + 4 + k - j), at(c, 38 * s + 4 + k - j)) };
            s2 = convolution::mul_add::<T, FMA>(a11, b11, s2);
            s3 = convolution::mul_add::<T, FMA>(a18, b22, s3);
            s4 = convolution::mul_add::<T, FMA>(a18, b23, s4);
            s5 = convolution::mul_add::<T, FMA>(a18, b24, s5);
            s8 = convolution::mul_add::<T, FMA>(a5, b11, s8);
            s17 = convolution::mul_add::<T, FMA>(a11, b38, s17);
            t2 = convolution::mul_add::<T, FMA>(a11, p11, t2);
            t3 = convolution::mul_add::<T, FMA>(a18, p22, t3);
            t4 = convolution::mul_add::<T, FMA>(a18, p23, t4);
            t5 = convolution::mul_add::<T, FMA>(a18, p24, t5);
            t8 = convolution::mul_add::<T, FMA>(a5, p11, t8);
            t17 = convolution::mul_add::<T, FMA>(a11, p38, t17);
            (p11, p22, p23, p24, p38) = (b11, b22, b23, b24, b38);
        }
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[8] = s8;
        g[8] = t8;
        h[17] = s17;
        g[17] = t17;
        // Histories [7, 9, 10, 11, 14, 16]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s7, mut t7, mut s9, mut t9, mut s10, mut t10, mut s11, mut t11, mut s14, mut t14, mut s16, mut t16) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p9, mut p30, mut p31, mut p32, mut p40, mut p42) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a4, b9, a18, b30, b31, b32, b40, b42) = unsafe { (at(c, 4 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 40 * s + 4 + k - j), at(c, 42 * s + 4 + k - j)) };
            s7 = convolution::mul_add::<T, FMA>(a4, b9, s7);
            s9 = convolution::mul_add::<T, FMA>(a18, b30, s9);
            s10 = convolution::mul_add::<T, FMA>(a18, b31, s10);
            s11 = convolution::mul_add::<T, FMA>(a18, b32, s11);
            s14 = convolution::mul_add::<T, FMA>(a18, b40, s14);
            s16 = convolution::mul_add::<T, FMA>(a18, b42, s16);
            (b9, b30, b31, b32, b40, b42)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a4, b9, a18, b30, b31, b32, b40, b42) = unsafe { (at(c, 4 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 18 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 32 * s + 4 + k - j), at(c, 40 * s + 4 + k - j), at(c, 42 * s + 4 + k - j)) };
            s7 = convolution::mul_add::<T, FMA>(a4, b9, s7);
            s9 = convolution::mul_add::<T, FMA>(a18, b30, s9);
            s10 = convolution::mul_add::<T, FMA>(a18, b31, s10);
            s11 = convolution::mul_add::<T, FMA>(a18, b32, s11);
            s14 = convolution::mul_add::<T, FMA>(a18, b40, s14);
            s16 = convolution::mul_add::<T, FMA>(a18, b42, s16);
            t7 = convolution::mul_add::<T, FMA>(a4, p9, t7);
            t9 = convolution::mul_add::<T, FMA>(a18, p30, t9);
            t10 = convolution::mul_add::<T, FMA>(a18, p31, t10);
            t11 = convolution::mul_add::<T, FMA>(a18, p32, t11);
            t14 = convolution::mul_add::<T, FMA>(a18, p40, t14);
            t16 = convolution::mul_add::<T, FMA>(a18, p42, t16);
            (p9, p30, p31, p32, p40, p42) = (b9, b30, b31, b32, b40, b42);
        }
        h[7] = s7;
        g[7] = t7;
        h[9] = s9;
        g[9] = t9;
        h[10] = s10;
        g[10] = t10;
        h[11] = s11;
        g[11] = t11;
        h[14] = s14;
        g[14] = t14;
        h[16] = s16;
        g[16] = t16;
        // Histories [18, 19, 22, 25, 26, 27]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s18, mut t18, mut s19, mut t19, mut s22, mut t22, mut s25, mut t25, mut s26, mut t26, mut s27, mut t27) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p42, mut p44, mut p52) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a4, a5, a18, a40, a42, b42, a44, b44, b52) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 18 * s + 4 + j), at(c, 40 * s + 4 + j), at(c, 42 * s + 4 + j), at(c, 42 * s + 4 + k - j), at(c, 44 * s + 4 + j), at(c, 44 * s + 4 + k - j), at(c, 52 * s + 4 + k - j)) };
            s18 = convolution::mul_add::<T, FMA>(a18, b44, s18);
            s19 = convolution::mul_add::<T, FMA>(a1, b44, s19);
            s19 = convolution::mul_add::<T, FMA>(-a2, b42, s19);
            s22 = convolution::mul_add::<T, FMA>(a4, b44, s22);
            s22 = convolution::mul_add::<T, FMA>(-a5, b42, s22);
            s25 = convolution::mul_add::<T, FMA>(a40, b52, s25);
            s26 = convolution::mul_add::<T, FMA>(a42, b52, s26);
            s27 = convolution::mul_add::<T, FMA>(a44, b52, s27);
            (b42, b44, b52)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a4, a5, a18, a40, a42, b42, a44, b44, b52) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 18 * s + 4 + j), at(c, 40 * s + 4 + j), at(c, 42 * s + 4 + j), at(c, 42 * s + 4 + k - j), at(c, 44 * s + 4 + j), at(c, 44 * s + 4 + k - j), at(c, 52 * s + 4 + k - j)) };
            s18 = convolution::mul_add::<T, FMA>(a18, b44, s18);
            s19 = convolution::mul_add::<T, FMA>(a1, b44, s19);
            s19 = convolution::mul_add::<T, FMA>(-a2, b42, s19);
            s22 = convolution::mul_add::<T, FMA>(a4, b44, s22);
            s22 = convolution::mul_add::<T, FMA>(-a5, b42, s22);
            s25 = convolution::mul_add::<T, FMA>(a40, b52, s25);
            s26 = convolution::mul_add::<T, FMA>(a42, b52, s26);
            s27 = convolution::mul_add::<T, FMA>(a44, b52, s27);
            t18 = convolution::mul_add::<T, FMA>(a18, p44, t18);
            t19 = convolution::mul_add::<T, FMA>(a1, p44, t19);
            t19 = convolution::mul_add::<T, FMA>(-a2, p42, t19);
            t22 = convolution::mul_add::<T, FMA>(a4, p44, t22);
            t22 = convolution::mul_add::<T, FMA>(-a5, p42, t22);
            t25 = convolution::mul_add::<T, FMA>(a40, p52, t25);
            t26 = convolution::mul_add::<T, FMA>(a42, p52, t26);
            t27 = convolution::mul_add::<T, FMA>(a44, p52, t27);
            (p42, p44, p52) = (b42, b44, b52);
        }
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[22] = s22;
        g[22] = t22;
        h[25] = s25;
        g[25] = t25;
        h[26] = s26;
        g[26] = t26;
        h[27] = s27;
        g[27] = t27;
        // Histories [20, 21, 23, 24]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s20, mut t20, mut s21, mut t21, mut s23, mut t23, mut s24, mut t24) = (zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p40, mut p42, mut p44) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b40, b42, b44) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 40 * s + 4 + k - j), at(c, 42 * s + 4 + k - j), at(c, 44 * s + 4 + k - j)) };
            s20 = convolution::mul_add::<T, FMA>(a2, b40, s20);
            s20 = convolution::mul_add::<T, FMA>(-a0, b44, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b42, s21);
            s21 = convolution::mul_add::<T, FMA>(-a1, b40, s21);
            s23 = convolution::mul_add::<T, FMA>(a5, b40, s23);
            s23 = convolution::mul_add::<T, FMA>(-a3, b44, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b42, s24);
            s24 = convolution::mul_add::<T, FMA>(-a4, b40, s24);
            (b40, b42, b44)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b40, b42, b44) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 40 * s + 4 + k - j), at(c, 42 * s + 4 + k - j), at(c, 44 * s + 4 + k - j)) };
            s20 = convolution::mul_add::<T, FMA>(a2, b40, s20);
            s20 = convolution::mul_add::<T, FMA>(-a0, b44, s20);
            s21 = convolution::mul_add::<T, FMA>(a0, b42, s21);
            s21 = convolution::mul_add::<T, FMA>(-a1, b40, s21);
            s23 = convolution::mul_add::<T, FMA>(a5, b40, s23);
            s23 = convolution::mul_add::<T, FMA>(-a3, b44, s23);
            s24 = convolution::mul_add::<T, FMA>(a3, b42, s24);
            s24 = convolution::mul_add::<T, FMA>(-a4, b40, s24);
            t20 = convolution::mul_add::<T, FMA>(a2, p40, t20);
            t20 = convolution::mul_add::<T, FMA>(-a0, p44, t20);
            t21 = convolution::mul_add::<T, FMA>(a0, p42, t21);
            t21 = convolution::mul_add::<T, FMA>(-a1, p40, t21);
            t23 = convolution::mul_add::<T, FMA>(a5, p40, t23);
            t23 = convolution::mul_add::<T, FMA>(-a3, p44, t23);
            t24 = convolution::mul_add::<T, FMA>(a3, p42, t24);
            t24 = convolution::mul_add::<T, FMA>(-a4, p40, t24);
            (p40, p42, p44) = (b40, b42, b44);
        }
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
        h[23] = s23;
        g[23] = t23;
        h[24] = s24;
        g[24] = t24;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 23 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 23 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 24 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 24 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 32 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 32 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 37 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 38 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 38 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 18 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = convolution::mul_add::<T, FMA>(at(c, 4 + 1), at(c, 42 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 42 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 42 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 42 * s + 4 + 1), e);
        e = convolution::mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        h[24] = e;
        let mut e = g[25];
        e = convolution::mul_add::<T, FMA>(at(c, 40 * s + 4 + 1), at(c, 52 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 40 * s + 4 + k - 1), at(c, 52 * s + 4 + 1), e);
        h[25] = e;
        let mut e = g[26];
        e = convolution::mul_add::<T, FMA>(at(c, 42 * s + 4 + 1), at(c, 52 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 42 * s + 4 + k - 1), at(c, 52 * s + 4 + 1), e);
        h[26] = e;
        let mut e = g[27];
        e = convolution::mul_add::<T, FMA>(at(c, 44 * s + 4 + 1), at(c, 52 * s + 4 + k - 1), e);
        e = convolution::mul_add::<T, FMA>(at(c, 44 * s + 4 + k - 1), at(c, 52 * s + 4 + 1), e);
        h[27] = e;
        }
    }
}
