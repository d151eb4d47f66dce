//! Generated Taylor kernels: the pass of order `k >= 1` through the tapes of the model
//! families in straight-line code (see [`super::codegen`]). Generated: do not edit;
//! rewrite with `ROUTH_REGENERATE=1 cargo test --release --lib generated_kernels_are_up_to_date`.

use super::recurrence;
use super::tape::Coefficient;

/// The name and the shape ([`super::codegen::shape`]) of each kernel, by number.
pub(super) const SHAPES: [(&str, &str); 6] = [
    ("routh", "n 6 first 7\nadd_c 2 #\ndot_add 7 7 1 1\nmul_plus 0 0 8\nadd_c 9 #\nadd_c 9 #\nmul 10 11\nmul 10 10\nmul 10 12\nmul 0 12\nmul 1 12\nmul 7 13\nmul 3 12\nmul 4 12\nmul 5 13\ndot_add 7 17 1 16\nmul_plus 0 15 21\nsub 14 22\ndot_add 7 20 1 19\nmul_plus 0 18 24\nmul 14 23\nc_div 26 #\ndot_add 15 25 18 23\nmul 27 28\ndot_add 16 25 19 23\nmul 27 30\ndot_add 17 25 20 23\nmul 27 32\ndot_sub 1 33 2 31\ndot_sub 2 29 0 33\ndot_sub 0 31 1 29\nmul_c 36 #\nmul_c 1 #\nmul_c 0 #\nc_sub 39 #\ndot_sub 4 33 5 31\ndot_sub 5 29 3 33\ndot_sub 3 31 4 29\nadd 38 41\nmul_plus 29 37 44\nadd 40 42\nmul_plus 31 37 46\nmul_plus 33 37 43\n"),
    ("routh_free", "n 6 first 7\nadd_c 2 #\ndot_add 7 7 1 1\nmul_plus 0 0 8\nadd_c 9 #\nadd_c 9 #\nmul 10 11\nmul 10 10\nmul 10 12\nmul 0 12\nmul 1 12\nmul 7 13\nmul 3 12\nmul 4 12\nmul 5 13\ndot_add 7 17 1 16\nmul_plus 0 15 21\nsub 14 22\ndot_add 7 20 1 19\nmul_plus 0 18 24\nmul 14 23\nc_div 26 #\ndot_add 15 25 18 23\nmul 27 28\ndot_add 16 25 19 23\nmul 27 30\ndot_add 17 25 20 23\nmul 27 32\ndot_sub 1 33 2 31\ndot_sub 2 29 0 33\ndot_sub 0 31 1 29\nmul_c 36 #\ndot_sub 4 33 5 31\ndot_sub 5 29 3 33\ndot_sub 3 31 4 29\nmul_plus 29 37 38\nmul_plus 31 37 39\nmul_plus 33 37 40\n"),
    ("routh_general", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 10 10 8 8\nmul_plus 7 7 11\nmul_c 12 #\nadd_c 13 #\nadd_c 13 #\nmul 14 15\nmul 14 14\nmul 14 16\nmul 7 16\nmul 8 16\nmul 10 17\nmul 3 16\nmul 4 16\nmul 5 17\ndot_add 10 21 8 20\nmul_plus 7 19 25\nmul_c 26 #\nsub 18 27\ndot_add 10 24 8 23\nmul_plus 7 22 29\nmul_c 30 #\nmul 18 28\nc_div 32 #\ndot_add 19 31 22 28\nmul 33 34\ndot_add 20 31 23 28\nmul 33 36\ndot_add 21 31 24 28\nmul 33 38\ndot_sub 1 39 2 37\ndot_sub 2 35 0 39\ndot_sub 0 37 1 35\nmul_c 42 #\nmul_c 1 #\nmul_c 0 #\nc_sub 45 #\ndot_sub 4 39 5 37\ndot_sub 5 35 3 39\ndot_sub 3 37 4 35\nadd 44 47\nmul_plus 35 43 50\nadd 46 48\nmul_plus 37 43 52\nmul_plus 39 43 49\n"),
    ("routh_general_free", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 10 10 8 8\nmul_plus 7 7 11\nmul_c 12 #\nadd_c 13 #\nadd_c 13 #\nmul 14 15\nmul 14 14\nmul 14 16\nmul 7 16\nmul 8 16\nmul 10 17\nmul 3 16\nmul 4 16\nmul 5 17\ndot_add 10 21 8 20\nmul_plus 7 19 25\nmul_c 26 #\nsub 18 27\ndot_add 10 24 8 23\nmul_plus 7 22 29\nmul_c 30 #\nmul 18 28\nc_div 32 #\ndot_add 19 31 22 28\nmul 33 34\ndot_add 20 31 23 28\nmul 33 36\ndot_add 21 31 24 28\nmul 33 38\ndot_sub 1 39 2 37\ndot_sub 2 35 0 39\ndot_sub 0 37 1 35\nmul_c 42 #\ndot_sub 4 39 5 37\ndot_sub 5 35 3 39\ndot_sub 3 37 4 35\nmul_plus 35 43 44\nmul_plus 37 43 45\nmul_plus 39 43 46\n"),
    ("chaplygin", "n 6 first 7\ndot_add 2 2 1 1\nmul_plus 0 0 7\nadd_c 8 #\nadd_c 8 #\nadd_c 8 #\nmul 10 11\nmul 9 11\nmul 9 10\nmul 9 12\nmul 0 12\nmul 1 13\nmul 2 14\nmul 3 12\nmul 4 13\nmul 5 14\ndot_add 2 18 1 17\nmul_plus 0 16 22\nsub 15 23\ndot_add 2 21 1 20\nmul_plus 0 19 25\nmul 15 24\nc_div 27 #\ndot_add 16 26 19 24\nmul 28 29\ndot_add 17 26 20 24\nmul 28 31\ndot_add 18 26 21 24\nmul 28 33\ndot_sub 1 34 2 32\ndot_sub 2 30 0 34\ndot_sub 0 32 1 30\ndot_sub 4 34 5 32\ndot_sub 5 30 3 34\ndot_sub 3 32 4 30\n"),
    ("ball", "n 6 first 7\nmul_c 0 #\nadd_c 7 #\nmul_c 1 #\nadd_c 9 #\nmul_c 2 #\nadd_c 11 #\ndot_add 12 12 10 10\nmul_plus 8 8 13\nmul_c 14 #\nadd_c 15 #\nadd_c 15 #\nadd_c 15 #\nmul 17 18\nmul 16 18\nmul 16 17\nmul 16 19\nmul 8 19\nmul 10 20\nmul 12 21\nmul 3 19\nmul 4 20\nmul 5 21\ndot_add 12 25 10 24\nmul_plus 8 23 29\nmul_c 30 #\nsub 22 31\ndot_add 12 28 10 27\nmul_plus 8 26 33\nmul_c 34 #\nmul 22 32\nc_div 36 #\ndot_add 23 35 26 32\nmul 37 38\ndot_add 24 35 27 32\nmul 37 40\ndot_add 25 35 28 32\nmul 37 42\ndot_sub 1 43 2 41\ndot_sub 2 39 0 43\ndot_sub 0 41 1 39\nmul_c 44 #\nmul_c 45 #\nadd 47 48\nmul_c 46 #\nadd 49 50\nmul_c 1 #\nmul_c 2 #\nsub 52 53\nmul_c 2 #\nmul_c 0 #\nsub 55 56\nmul_c 0 #\nmul_c 1 #\nsub 58 59\ndot_sub 4 43 5 41\ndot_sub 5 39 3 43\ndot_sub 3 41 4 39\nadd 54 61\nmul_plus 39 51 64\nadd 57 62\nmul_plus 41 51 66\nadd 60 63\nmul_plus 43 51 68\n"),
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

/// The pass of order `k >= 1` of the kernel `routh`.
#[inline(always)]
fn routh<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 32],
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
    let v11 = v9;
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[11 * s + 4], v11, h[2]);
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[3]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[12 * s + 4], v12, h[4]);
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[12 * s + 4], v12, h[5]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[12 * s + 4], v12, h[6]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[13 * s + 4], v13, h[7]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[12 * s + 4], v12, h[8]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[12 * s + 4], v12, h[9]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[13 * s + 4], v13, h[10]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[17 * s + 4], v17], [c[s + 4], c[s + 4 + k], c[16 * s + 4], v16], h[11]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[15 * s + 4], v15, v21, h[12]);
    c[22 * s + 4 + k] = v22;
    let v23 = v14 - v22;
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[20 * s + 4], v20], [c[s + 4], c[s + 4 + k], c[19 * s + 4], v19], h[13]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[18 * s + 4], v18, v24, h[14]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[23 * s + 4], v23, h[15]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::reciprocal::<T, FMA>(c[26 * s + 4], v26, c[27 * s + 4], h[16]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::dot_add::<T, FMA>([c[15 * s + 4], v15, c[25 * s + 4], v25], [c[18 * s + 4], v18, c[23 * s + 4], v23], h[17]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::product::<T, FMA>(c[27 * s + 4], v27, c[28 * s + 4], v28, h[18]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::dot_add::<T, FMA>([c[16 * s + 4], v16, c[25 * s + 4], v25], [c[19 * s + 4], v19, c[23 * s + 4], v23], h[19]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::product::<T, FMA>(c[27 * s + 4], v27, c[30 * s + 4], v30, h[20]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::dot_add::<T, FMA>([c[17 * s + 4], v17, c[25 * s + 4], v25], [c[20 * s + 4], v20, c[23 * s + 4], v23], h[21]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::product::<T, FMA>(c[27 * s + 4], v27, c[32 * s + 4], v32, h[22]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[33 * s + 4], v33], [c[2 * s + 4], c[2 * s + 4 + k], c[31 * s + 4], v31], h[23]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[29 * s + 4], v29], [c[4], c[4 + k], c[33 * s + 4], v33], h[24]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[31 * s + 4], v31], [c[s + 4], c[s + 4 + k], c[29 * s + 4], v29], h[25]);
    c[36 * s + 4 + k] = v36;
    let v37 = v36 * q[0];
    c[37 * s + 4 + k] = v37;
    let v38 = c[s + 4 + k] * q[1];
    c[38 * s + 4 + k] = v38;
    let v39 = c[4 + k] * q[2];
    c[39 * s + 4 + k] = v39;
    let v40 = -v39;
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[33 * s + 4], v33], [c[5 * s + 4], c[5 * s + 4 + k], c[31 * s + 4], v31], h[26]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[29 * s + 4], v29], [c[3 * s + 4], c[3 * s + 4 + k], c[33 * s + 4], v33], h[27]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[31 * s + 4], v31], [c[4 * s + 4], c[4 * s + 4 + k], c[29 * s + 4], v29], h[28]);
    c[43 * s + 4 + k] = v43;
    let v44 = v38 + v41;
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::mul_plus::<T, FMA>(c[29 * s + 4], v29, c[37 * s + 4], v37, v44, h[29]);
    c[45 * s + 4 + k] = v45;
    let v46 = v40 + v42;
    c[46 * s + 4 + k] = v46;
    let v47 = recurrence::mul_plus::<T, FMA>(c[31 * s + 4], v31, c[37 * s + 4], v37, v46, h[30]);
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::mul_plus::<T, FMA>(c[33 * s + 4], v33, c[37 * s + 4], v37, v43, h[31]);
    c[48 * s + 4 + k] = v48;
}

/// The pass of order `k >= 1` of the kernel `routh_free`.
#[inline(always)]
fn routh_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 32],
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
    let v11 = v9;
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[11 * s + 4], v11, h[2]);
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[3]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[12 * s + 4], v12, h[4]);
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[12 * s + 4], v12, h[5]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[12 * s + 4], v12, h[6]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[13 * s + 4], v13, h[7]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[12 * s + 4], v12, h[8]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[12 * s + 4], v12, h[9]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[13 * s + 4], v13, h[10]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[17 * s + 4], v17], [c[s + 4], c[s + 4 + k], c[16 * s + 4], v16], h[11]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[15 * s + 4], v15, v21, h[12]);
    c[22 * s + 4 + k] = v22;
    let v23 = v14 - v22;
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[20 * s + 4], v20], [c[s + 4], c[s + 4 + k], c[19 * s + 4], v19], h[13]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[18 * s + 4], v18, v24, h[14]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[23 * s + 4], v23, h[15]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::reciprocal::<T, FMA>(c[26 * s + 4], v26, c[27 * s + 4], h[16]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::dot_add::<T, FMA>([c[15 * s + 4], v15, c[25 * s + 4], v25], [c[18 * s + 4], v18, c[23 * s + 4], v23], h[17]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::product::<T, FMA>(c[27 * s + 4], v27, c[28 * s + 4], v28, h[18]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::dot_add::<T, FMA>([c[16 * s + 4], v16, c[25 * s + 4], v25], [c[19 * s + 4], v19, c[23 * s + 4], v23], h[19]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::product::<T, FMA>(c[27 * s + 4], v27, c[30 * s + 4], v30, h[20]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::dot_add::<T, FMA>([c[17 * s + 4], v17, c[25 * s + 4], v25], [c[20 * s + 4], v20, c[23 * s + 4], v23], h[21]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::product::<T, FMA>(c[27 * s + 4], v27, c[32 * s + 4], v32, h[22]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[33 * s + 4], v33], [c[2 * s + 4], c[2 * s + 4 + k], c[31 * s + 4], v31], h[23]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[29 * s + 4], v29], [c[4], c[4 + k], c[33 * s + 4], v33], h[24]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[31 * s + 4], v31], [c[s + 4], c[s + 4 + k], c[29 * s + 4], v29], h[25]);
    c[36 * s + 4 + k] = v36;
    let v37 = v36 * q[0];
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[33 * s + 4], v33], [c[5 * s + 4], c[5 * s + 4 + k], c[31 * s + 4], v31], h[26]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[29 * s + 4], v29], [c[3 * s + 4], c[3 * s + 4 + k], c[33 * s + 4], v33], h[27]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[31 * s + 4], v31], [c[4 * s + 4], c[4 * s + 4 + k], c[29 * s + 4], v29], h[28]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::mul_plus::<T, FMA>(c[29 * s + 4], v29, c[37 * s + 4], v37, v38, h[29]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::mul_plus::<T, FMA>(c[31 * s + 4], v31, c[37 * s + 4], v37, v39, h[30]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::mul_plus::<T, FMA>(c[33 * s + 4], v33, c[37 * s + 4], v37, v40, h[31]);
    c[43 * s + 4 + k] = v43;
}

/// The pass of order `k >= 1` of the kernel `routh_general`.
#[inline(always)]
fn routh_general<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 32],
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
    let v15 = v13;
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[15 * s + 4], v15, h[2]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[14 * s + 4], v14, h[3]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[16 * s + 4], v16, h[4]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[16 * s + 4], v16, h[5]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[16 * s + 4], v16, h[6]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[17 * s + 4], v17, h[7]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[16 * s + 4], v16, h[8]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[16 * s + 4], v16, h[9]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[17 * s + 4], v17, h[10]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[21 * s + 4], v21], [c[8 * s + 4], v8, c[20 * s + 4], v20], h[11]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[19 * s + 4], v19, v25, h[12]);
    c[26 * s + 4 + k] = v26;
    let v27 = v26 * q[4];
    c[27 * s + 4 + k] = v27;
    let v28 = v18 - v27;
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[24 * s + 4], v24], [c[8 * s + 4], v8, c[23 * s + 4], v23], h[13]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[22 * s + 4], v22, v29, h[14]);
    c[30 * s + 4 + k] = v30;
    let v31 = v30 * q[5];
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::product::<T, FMA>(c[18 * s + 4], v18, c[28 * s + 4], v28, h[15]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::reciprocal::<T, FMA>(c[32 * s + 4], v32, c[33 * s + 4], h[16]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::dot_add::<T, FMA>([c[19 * s + 4], v19, c[31 * s + 4], v31], [c[22 * s + 4], v22, c[28 * s + 4], v28], h[17]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::product::<T, FMA>(c[33 * s + 4], v33, c[34 * s + 4], v34, h[18]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_add::<T, FMA>([c[20 * s + 4], v20, c[31 * s + 4], v31], [c[23 * s + 4], v23, c[28 * s + 4], v28], h[19]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::product::<T, FMA>(c[33 * s + 4], v33, c[36 * s + 4], v36, h[20]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_add::<T, FMA>([c[21 * s + 4], v21, c[31 * s + 4], v31], [c[24 * s + 4], v24, c[28 * s + 4], v28], h[21]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::product::<T, FMA>(c[33 * s + 4], v33, c[38 * s + 4], v38, h[22]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[39 * s + 4], v39], [c[2 * s + 4], c[2 * s + 4 + k], c[37 * s + 4], v37], h[23]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[35 * s + 4], v35], [c[4], c[4 + k], c[39 * s + 4], v39], h[24]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[37 * s + 4], v37], [c[s + 4], c[s + 4 + k], c[35 * s + 4], v35], h[25]);
    c[42 * s + 4 + k] = v42;
    let v43 = v42 * q[6];
    c[43 * s + 4 + k] = v43;
    let v44 = c[s + 4 + k] * q[7];
    c[44 * s + 4 + k] = v44;
    let v45 = c[4 + k] * q[8];
    c[45 * s + 4 + k] = v45;
    let v46 = -v45;
    c[46 * s + 4 + k] = v46;
    let v47 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[39 * s + 4], v39], [c[5 * s + 4], c[5 * s + 4 + k], c[37 * s + 4], v37], h[26]);
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[35 * s + 4], v35], [c[3 * s + 4], c[3 * s + 4 + k], c[39 * s + 4], v39], h[27]);
    c[48 * s + 4 + k] = v48;
    let v49 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[37 * s + 4], v37], [c[4 * s + 4], c[4 * s + 4 + k], c[35 * s + 4], v35], h[28]);
    c[49 * s + 4 + k] = v49;
    let v50 = v44 + v47;
    c[50 * s + 4 + k] = v50;
    let v51 = recurrence::mul_plus::<T, FMA>(c[35 * s + 4], v35, c[43 * s + 4], v43, v50, h[29]);
    c[51 * s + 4 + k] = v51;
    let v52 = v46 + v48;
    c[52 * s + 4 + k] = v52;
    let v53 = recurrence::mul_plus::<T, FMA>(c[37 * s + 4], v37, c[43 * s + 4], v43, v52, h[30]);
    c[53 * s + 4 + k] = v53;
    let v54 = recurrence::mul_plus::<T, FMA>(c[39 * s + 4], v39, c[43 * s + 4], v43, v49, h[31]);
    c[54 * s + 4 + k] = v54;
}

/// The pass of order `k >= 1` of the kernel `routh_general_free`.
#[inline(always)]
fn routh_general_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 32],
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
    let v15 = v13;
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[15 * s + 4], v15, h[2]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[14 * s + 4], v14, h[3]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[14 * s + 4], v14, c[16 * s + 4], v16, h[4]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[16 * s + 4], v16, h[5]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[16 * s + 4], v16, h[6]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[17 * s + 4], v17, h[7]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[16 * s + 4], v16, h[8]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[16 * s + 4], v16, h[9]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[17 * s + 4], v17, h[10]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[21 * s + 4], v21], [c[8 * s + 4], v8, c[20 * s + 4], v20], h[11]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[19 * s + 4], v19, v25, h[12]);
    c[26 * s + 4 + k] = v26;
    let v27 = v26 * q[4];
    c[27 * s + 4 + k] = v27;
    let v28 = v18 - v27;
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[24 * s + 4], v24], [c[8 * s + 4], v8, c[23 * s + 4], v23], h[13]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[22 * s + 4], v22, v29, h[14]);
    c[30 * s + 4 + k] = v30;
    let v31 = v30 * q[5];
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::product::<T, FMA>(c[18 * s + 4], v18, c[28 * s + 4], v28, h[15]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::reciprocal::<T, FMA>(c[32 * s + 4], v32, c[33 * s + 4], h[16]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::dot_add::<T, FMA>([c[19 * s + 4], v19, c[31 * s + 4], v31], [c[22 * s + 4], v22, c[28 * s + 4], v28], h[17]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::product::<T, FMA>(c[33 * s + 4], v33, c[34 * s + 4], v34, h[18]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_add::<T, FMA>([c[20 * s + 4], v20, c[31 * s + 4], v31], [c[23 * s + 4], v23, c[28 * s + 4], v28], h[19]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::product::<T, FMA>(c[33 * s + 4], v33, c[36 * s + 4], v36, h[20]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_add::<T, FMA>([c[21 * s + 4], v21, c[31 * s + 4], v31], [c[24 * s + 4], v24, c[28 * s + 4], v28], h[21]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::product::<T, FMA>(c[33 * s + 4], v33, c[38 * s + 4], v38, h[22]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[39 * s + 4], v39], [c[2 * s + 4], c[2 * s + 4 + k], c[37 * s + 4], v37], h[23]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[35 * s + 4], v35], [c[4], c[4 + k], c[39 * s + 4], v39], h[24]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[37 * s + 4], v37], [c[s + 4], c[s + 4 + k], c[35 * s + 4], v35], h[25]);
    c[42 * s + 4 + k] = v42;
    let v43 = v42 * q[6];
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[39 * s + 4], v39], [c[5 * s + 4], c[5 * s + 4 + k], c[37 * s + 4], v37], h[26]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[35 * s + 4], v35], [c[3 * s + 4], c[3 * s + 4 + k], c[39 * s + 4], v39], h[27]);
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[37 * s + 4], v37], [c[4 * s + 4], c[4 * s + 4 + k], c[35 * s + 4], v35], h[28]);
    c[46 * s + 4 + k] = v46;
    let v47 = recurrence::mul_plus::<T, FMA>(c[35 * s + 4], v35, c[43 * s + 4], v43, v44, h[29]);
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::mul_plus::<T, FMA>(c[37 * s + 4], v37, c[43 * s + 4], v43, v45, h[30]);
    c[48 * s + 4 + k] = v48;
    let v49 = recurrence::mul_plus::<T, FMA>(c[39 * s + 4], v39, c[43 * s + 4], v43, v46, h[31]);
    c[49 * s + 4 + k] = v49;
}

/// The pass of order `k >= 1` of the kernel `chaplygin`.
#[inline(always)]
fn chaplygin<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 30],
    _q: &[f64; 0],
) {
    let v7 = recurrence::dot_add::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[2 * s + 4], c[2 * s + 4 + k]], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[4], c[4 + k], v7, h[1]);
    c[8 * s + 4 + k] = v8;
    let v9 = v8;
    c[9 * s + 4 + k] = v9;
    let v10 = v8;
    c[10 * s + 4 + k] = v10;
    let v11 = v8;
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[11 * s + 4], v11, h[2]);
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::product::<T, FMA>(c[9 * s + 4], v9, c[11 * s + 4], v11, h[3]);
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::product::<T, FMA>(c[9 * s + 4], v9, c[10 * s + 4], v10, h[4]);
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[9 * s + 4], v9, c[12 * s + 4], v12, h[5]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[12 * s + 4], v12, h[6]);
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[13 * s + 4], v13, h[7]);
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[14 * s + 4], v14, h[8]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[12 * s + 4], v12, h[9]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[13 * s + 4], v13, h[10]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[14 * s + 4], v14, h[11]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::dot_add::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[18 * s + 4], v18], [c[s + 4], c[s + 4 + k], c[17 * s + 4], v17], h[12]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[16 * s + 4], v16, v22, h[13]);
    c[23 * s + 4 + k] = v23;
    let v24 = v15 - v23;
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::dot_add::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[21 * s + 4], v21], [c[s + 4], c[s + 4 + k], c[20 * s + 4], v20], h[14]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[19 * s + 4], v19, v25, h[15]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::product::<T, FMA>(c[15 * s + 4], v15, c[24 * s + 4], v24, h[16]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::reciprocal::<T, FMA>(c[27 * s + 4], v27, c[28 * s + 4], h[17]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_add::<T, FMA>([c[16 * s + 4], v16, c[26 * s + 4], v26], [c[19 * s + 4], v19, c[24 * s + 4], v24], h[18]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::product::<T, FMA>(c[28 * s + 4], v28, c[29 * s + 4], v29, h[19]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_add::<T, FMA>([c[17 * s + 4], v17, c[26 * s + 4], v26], [c[20 * s + 4], v20, c[24 * s + 4], v24], h[20]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::product::<T, FMA>(c[28 * s + 4], v28, c[31 * s + 4], v31, h[21]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::dot_add::<T, FMA>([c[18 * s + 4], v18, c[26 * s + 4], v26], [c[21 * s + 4], v21, c[24 * s + 4], v24], h[22]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::product::<T, FMA>(c[28 * s + 4], v28, c[33 * s + 4], v33, h[23]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[34 * s + 4], v34], [c[2 * s + 4], c[2 * s + 4 + k], c[32 * s + 4], v32], h[24]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[30 * s + 4], v30], [c[4], c[4 + k], c[34 * s + 4], v34], h[25]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[32 * s + 4], v32], [c[s + 4], c[s + 4 + k], c[30 * s + 4], v30], h[26]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[34 * s + 4], v34], [c[5 * s + 4], c[5 * s + 4 + k], c[32 * s + 4], v32], h[27]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[30 * s + 4], v30], [c[3 * s + 4], c[3 * s + 4 + k], c[34 * s + 4], v34], h[28]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[32 * s + 4], v32], [c[4 * s + 4], c[4 * s + 4 + k], c[30 * s + 4], v30], h[29]);
    c[40 * s + 4 + k] = v40;
}

/// The pass of order `k >= 1` of the kernel `ball`.
#[inline(always)]
fn ball<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 33],
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
    let v17 = v15;
    c[17 * s + 4 + k] = v17;
    let v18 = v15;
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[17 * s + 4], v17, c[18 * s + 4], v18, h[2]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[16 * s + 4], v16, c[18 * s + 4], v18, h[3]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[16 * s + 4], v16, c[17 * s + 4], v17, h[4]);
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[16 * s + 4], v16, c[19 * s + 4], v19, h[5]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[19 * s + 4], v19, h[6]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[20 * s + 4], v20, h[7]);
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::product::<T, FMA>(c[12 * s + 4], v12, c[21 * s + 4], v21, h[8]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[19 * s + 4], v19, h[9]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[20 * s + 4], v20, h[10]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[21 * s + 4], v21, h[11]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::dot_add::<T, FMA>([c[12 * s + 4], v12, c[25 * s + 4], v25], [c[10 * s + 4], v10, c[24 * s + 4], v24], h[12]);
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[23 * s + 4], v23, v29, h[13]);
    c[30 * s + 4 + k] = v30;
    let v31 = v30 * q[4];
    c[31 * s + 4 + k] = v31;
    let v32 = v22 - v31;
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::dot_add::<T, FMA>([c[12 * s + 4], v12, c[28 * s + 4], v28], [c[10 * s + 4], v10, c[27 * s + 4], v27], h[14]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[26 * s + 4], v26, v33, h[15]);
    c[34 * s + 4 + k] = v34;
    let v35 = v34 * q[5];
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::product::<T, FMA>(c[22 * s + 4], v22, c[32 * s + 4], v32, h[16]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::reciprocal::<T, FMA>(c[36 * s + 4], v36, c[37 * s + 4], h[17]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_add::<T, FMA>([c[23 * s + 4], v23, c[35 * s + 4], v35], [c[26 * s + 4], v26, c[32 * s + 4], v32], h[18]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::product::<T, FMA>(c[37 * s + 4], v37, c[38 * s + 4], v38, h[19]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_add::<T, FMA>([c[24 * s + 4], v24, c[35 * s + 4], v35], [c[27 * s + 4], v27, c[32 * s + 4], v32], h[20]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::product::<T, FMA>(c[37 * s + 4], v37, c[40 * s + 4], v40, h[21]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_add::<T, FMA>([c[25 * s + 4], v25, c[35 * s + 4], v35], [c[28 * s + 4], v28, c[32 * s + 4], v32], h[22]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::product::<T, FMA>(c[37 * s + 4], v37, c[42 * s + 4], v42, h[23]);
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[43 * s + 4], v43], [c[2 * s + 4], c[2 * s + 4 + k], c[41 * s + 4], v41], h[24]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[39 * s + 4], v39], [c[4], c[4 + k], c[43 * s + 4], v43], h[25]);
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[41 * s + 4], v41], [c[s + 4], c[s + 4 + k], c[39 * s + 4], v39], h[26]);
    c[46 * s + 4 + k] = v46;
    let v47 = v44 * q[6];
    c[47 * s + 4 + k] = v47;
    let v48 = v45 * q[7];
    c[48 * s + 4 + k] = v48;
    let v49 = v47 + v48;
    c[49 * s + 4 + k] = v49;
    let v50 = v46 * q[8];
    c[50 * s + 4 + k] = v50;
    let v51 = v49 + v50;
    c[51 * s + 4 + k] = v51;
    let v52 = c[s + 4 + k] * q[9];
    c[52 * s + 4 + k] = v52;
    let v53 = c[2 * s + 4 + k] * q[10];
    c[53 * s + 4 + k] = v53;
    let v54 = v52 - v53;
    c[54 * s + 4 + k] = v54;
    let v55 = c[2 * s + 4 + k] * q[11];
    c[55 * s + 4 + k] = v55;
    let v56 = c[4 + k] * q[12];
    c[56 * s + 4 + k] = v56;
    let v57 = v55 - v56;
    c[57 * s + 4 + k] = v57;
    let v58 = c[4 + k] * q[13];
    c[58 * s + 4 + k] = v58;
    let v59 = c[s + 4 + k] * q[14];
    c[59 * s + 4 + k] = v59;
    let v60 = v58 - v59;
    c[60 * s + 4 + k] = v60;
    let v61 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[43 * s + 4], v43], [c[5 * s + 4], c[5 * s + 4 + k], c[41 * s + 4], v41], h[27]);
    c[61 * s + 4 + k] = v61;
    let v62 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[39 * s + 4], v39], [c[3 * s + 4], c[3 * s + 4 + k], c[43 * s + 4], v43], h[28]);
    c[62 * s + 4 + k] = v62;
    let v63 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[41 * s + 4], v41], [c[4 * s + 4], c[4 * s + 4 + k], c[39 * s + 4], v39], h[29]);
    c[63 * s + 4 + k] = v63;
    let v64 = v54 + v61;
    c[64 * s + 4 + k] = v64;
    let v65 = recurrence::mul_plus::<T, FMA>(c[39 * s + 4], v39, c[51 * s + 4], v51, v64, h[30]);
    c[65 * s + 4 + k] = v65;
    let v66 = v57 + v62;
    c[66 * s + 4 + k] = v66;
    let v67 = recurrence::mul_plus::<T, FMA>(c[41 * s + 4], v41, c[51 * s + 4], v51, v66, h[31]);
    c[67 * s + 4 + k] = v67;
    let v68 = v60 + v63;
    c[68 * s + 4 + k] = v68;
    let v69 = recurrence::mul_plus::<T, FMA>(c[43 * s + 4], v43, c[51 * s + 4], v51, v68, h[32]);
    c[69 * s + 4 + k] = v69;
}
