//! Generated Taylor kernels: the passes through the tapes of the model families in
//! straight-line code (`routh_integrate::taylor::codegen`). Generated: do not edit;
//! rewrite with `cargo xtask kernels`.

use routh_integrate::taylor::kernels::{
    at, mul_add, recurrence, Coefficient, Kernels,
};

/// The generated kernels of the model families (by shape: [`Kernels::SHAPES`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct BallKernels;

impl Kernels for BallKernels {
    const SHAPES: &'static [(&'static str, &'static str)] = &[
        ("routh", "n 6 first 7\nadd_c 2 #\ndot_add 0 0 1 1\nmul 7 7\ndot_add 0 3 1 4\nmul 5 7\nadd 8 9\nadd 10 11\nmul_c 10 #\nmul_c 11 #\nadd 14 15\nmul_plus 12 13 16\nmul_c 8 #\nmul_c 9 #\nadd 18 19\nadd_c 20 #\ndiv 17 21\nmul_plus 0 22 3\nadd_c 12 #\ndiv 23 24\nmul_plus 1 22 4\ndiv 26 24\nmul_plus 7 22 5\nadd_c 12 #\ndiv 28 29\ndot_sub 1 30 2 27\ndot_sub 2 25 0 30\ndot_sub 0 27 1 25\nmul_c 33 #\nmul_c 1 #\nmul_c 0 #\nc_sub 36 #\ndot_sub 4 30 5 27\ndot_sub 5 25 3 30\ndot_sub 3 27 4 25\nadd 35 38\nmul_plus 25 34 41\nadd 37 39\nmul_plus 27 34 43\nmul_plus 30 34 40\n"),
        ("routh_free", "n 6 first 7\nadd_c 2 #\ndot_add 0 0 1 1\nmul 7 7\ndot_add 0 3 1 4\nmul 5 7\nadd 8 9\nadd 10 11\nmul_c 10 #\nmul_c 11 #\nadd 14 15\nmul_plus 12 13 16\nmul_c 8 #\nmul_c 9 #\nadd 18 19\nadd_c 20 #\ndiv 17 21\nmul_plus 0 22 3\nadd_c 12 #\ndiv 23 24\nmul_plus 1 22 4\ndiv 26 24\nmul_plus 7 22 5\nadd_c 12 #\ndiv 28 29\ndot_sub 1 30 2 27\ndot_sub 2 25 0 30\ndot_sub 0 27 1 25\nmul_c 33 #\ndot_sub 4 30 5 27\ndot_sub 5 25 3 30\ndot_sub 3 27 4 25\nmul_plus 25 34 35\nmul_plus 27 34 36\nmul_plus 30 34 37\n"),
        ("routh_general", "n 6 first 7\nmul_c 3 #\nmul_c 4 #\nmul_c 5 #\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 12 #\ndot_add 10 10 11 11\nmul_c 14 #\nmul 13 13\nmul_c 16 #\ndot_add 7 10 8 11\nmul 9 13\nadd 15 17\nadd 18 19\nmul_c 18 #\nmul_c 19 #\nadd 22 23\nmul_plus 20 21 24\nmul_c 25 #\nmul_c 15 #\nmul_c 17 #\nadd 27 28\nadd_c 29 #\ndiv 26 30\nmul_plus 10 31 7\nadd_c 20 #\ndiv 32 33\nmul_plus 11 31 8\ndiv 35 33\nmul_plus 13 31 9\nadd_c 20 #\ndiv 37 38\ndot_sub 1 39 2 36\ndot_sub 2 34 0 39\ndot_sub 0 36 1 34\nmul_c 42 #\nmul_c 1 #\nmul_c 0 #\nc_sub 45 #\ndot_sub 4 39 5 36\ndot_sub 5 34 3 39\ndot_sub 3 36 4 34\nadd 44 47\nmul_plus 34 43 50\nadd 46 48\nmul_plus 36 43 52\nmul_plus 39 43 49\n"),
        ("routh_general_free", "n 6 first 7\nmul_c 3 #\nmul_c 4 #\nmul_c 5 #\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 12 #\ndot_add 10 10 11 11\nmul_c 14 #\nmul 13 13\nmul_c 16 #\ndot_add 7 10 8 11\nmul 9 13\nadd 15 17\nadd 18 19\nmul_c 18 #\nmul_c 19 #\nadd 22 23\nmul_plus 20 21 24\nmul_c 25 #\nmul_c 15 #\nmul_c 17 #\nadd 27 28\nadd_c 29 #\ndiv 26 30\nmul_plus 10 31 7\nadd_c 20 #\ndiv 32 33\nmul_plus 11 31 8\ndiv 35 33\nmul_plus 13 31 9\nadd_c 20 #\ndiv 37 38\ndot_sub 1 39 2 36\ndot_sub 2 34 0 39\ndot_sub 0 36 1 34\nmul_c 42 #\ndot_sub 4 39 5 36\ndot_sub 5 34 3 39\ndot_sub 3 36 4 34\nmul_plus 34 43 44\nmul_plus 36 43 45\nmul_plus 39 43 46\n"),
        ("routh_general_unit", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 7 7 8 8\nmul_c 11 #\nmul 10 10\nmul_c 13 #\ndot_add 3 7 4 8\nmul 5 10\nadd 12 14\nadd 15 16\nmul_c 15 #\nmul_c 16 #\nadd 19 20\nmul_plus 17 18 21\nmul_c 22 #\nmul_c 12 #\nmul_c 14 #\nadd 24 25\nadd_c 26 #\ndiv 23 27\nmul_plus 7 28 3\nadd_c 17 #\ndiv 29 30\nmul_plus 8 28 4\ndiv 32 30\nmul_plus 10 28 5\nadd_c 17 #\ndiv 34 35\ndot_sub 1 36 2 33\ndot_sub 2 31 0 36\ndot_sub 0 33 1 31\nmul_c 39 #\nmul_c 1 #\nmul_c 0 #\nc_sub 42 #\ndot_sub 4 36 5 33\ndot_sub 5 31 3 36\ndot_sub 3 33 4 31\nadd 41 44\nmul_plus 31 40 47\nadd 43 45\nmul_plus 33 40 49\nmul_plus 36 40 46\n"),
        ("routh_general_unit_free", "n 6 first 7\nmul_c 0 #\nmul_c 1 #\nmul_c 2 #\nadd_c 9 #\ndot_add 7 7 8 8\nmul_c 11 #\nmul 10 10\nmul_c 13 #\ndot_add 3 7 4 8\nmul 5 10\nadd 12 14\nadd 15 16\nmul_c 15 #\nmul_c 16 #\nadd 19 20\nmul_plus 17 18 21\nmul_c 22 #\nmul_c 12 #\nmul_c 14 #\nadd 24 25\nadd_c 26 #\ndiv 23 27\nmul_plus 7 28 3\nadd_c 17 #\ndiv 29 30\nmul_plus 8 28 4\ndiv 32 30\nmul_plus 10 28 5\nadd_c 17 #\ndiv 34 35\ndot_sub 1 36 2 33\ndot_sub 2 31 0 36\ndot_sub 0 33 1 31\nmul_c 39 #\ndot_sub 4 36 5 33\ndot_sub 5 31 3 36\ndot_sub 3 33 4 31\nmul_plus 31 40 41\nmul_plus 33 40 42\nmul_plus 36 40 43\n"),
        ("chaplygin", "n 6 first 7\nmul 0 0\nmul 1 1\nmul 2 2\nmul 0 3\nmul 1 4\nmul 2 5\nadd 7 8\nadd 9 13\nadd 10 11\nadd 12 15\nmul_c 10 #\nmul_c 11 #\nadd 17 18\nmul_c 12 #\nadd 19 20\nmul_plus 14 16 21\nmul_c 10 #\nmul_c 11 #\nadd 23 24\nmul_c 12 #\nadd 25 26\nmul_plus 14 22 27\nmul_c 7 #\nmul_c 8 #\nadd 29 30\nmul_c 9 #\nadd 31 32\nmul_c 7 #\nmul_c 8 #\nadd 34 35\nmul_c 9 #\nadd 36 37\nmul_plus 14 33 38\nadd_c 39 #\ndiv 28 40\nmul_plus 0 41 3\nadd_c 14 #\ndiv 42 43\nmul_plus 1 41 4\nadd_c 14 #\ndiv 45 46\nmul_plus 2 41 5\nadd_c 14 #\ndiv 48 49\ndot_sub 1 50 2 47\ndot_sub 2 44 0 50\ndot_sub 0 47 1 44\ndot_sub 4 50 5 47\ndot_sub 5 44 3 50\ndot_sub 3 47 4 44\n"),
        ("ball", "n 6 first 7\nmul_c 3 #\nmul_c 4 #\nmul_c 5 #\nmul_c 0 #\nadd_c 10 #\nmul_c 1 #\nadd_c 12 #\nmul_c 2 #\nadd_c 14 #\nmul 11 11\nmul_c 16 #\nmul 13 13\nmul_c 18 #\nmul 15 15\nmul_c 20 #\nmul 7 11\nmul 8 13\nmul 9 15\nadd 17 19\nadd 21 25\nadd 22 23\nadd 24 27\nmul_c 22 #\nmul_c 23 #\nadd 29 30\nmul_c 24 #\nadd 31 32\nmul_plus 26 28 33\nmul_c 22 #\nmul_c 23 #\nadd 35 36\nmul_c 24 #\nadd 37 38\nmul_plus 26 34 39\nmul_c 40 #\nmul_c 17 #\nmul_c 19 #\nadd 42 43\nmul_c 21 #\nadd 44 45\nmul_c 17 #\nmul_c 19 #\nadd 47 48\nmul_c 21 #\nadd 49 50\nmul_plus 26 46 51\nadd_c 52 #\ndiv 41 53\nmul_plus 11 54 7\nadd_c 26 #\ndiv 55 56\nmul_plus 13 54 8\nadd_c 26 #\ndiv 58 59\nmul_plus 15 54 9\nadd_c 26 #\ndiv 61 62\ndot_sub 1 63 2 60\ndot_sub 2 57 0 63\ndot_sub 0 60 1 57\nmul_c 64 #\nmul_c 65 #\nadd 67 68\nmul_c 66 #\nadd 69 70\nmul_c 1 #\nmul_c 2 #\nsub 72 73\nmul_c 2 #\nmul_c 0 #\nsub 75 76\nmul_c 0 #\nmul_c 1 #\nsub 78 79\ndot_sub 4 63 5 60\ndot_sub 5 57 3 63\ndot_sub 3 60 4 57\nadd 74 81\nmul_plus 57 71 84\nadd 77 82\nmul_plus 60 71 86\nadd 80 83\nmul_plus 63 71 88\n"),
        ("ball_unit", "n 6 first 7\nmul_c 0 #\nadd_c 7 #\nmul_c 1 #\nadd_c 9 #\nmul_c 2 #\nadd_c 11 #\nmul 8 8\nmul_c 13 #\nmul 10 10\nmul_c 15 #\nmul 12 12\nmul_c 17 #\nmul 3 8\nmul 4 10\nmul 5 12\nadd 14 16\nadd 18 22\nadd 19 20\nadd 21 24\nmul_c 19 #\nmul_c 20 #\nadd 26 27\nmul_c 21 #\nadd 28 29\nmul_plus 23 25 30\nmul_c 19 #\nmul_c 20 #\nadd 32 33\nmul_c 21 #\nadd 34 35\nmul_plus 23 31 36\nmul_c 37 #\nmul_c 14 #\nmul_c 16 #\nadd 39 40\nmul_c 18 #\nadd 41 42\nmul_c 14 #\nmul_c 16 #\nadd 44 45\nmul_c 18 #\nadd 46 47\nmul_plus 23 43 48\nadd_c 49 #\ndiv 38 50\nmul_plus 8 51 3\nadd_c 23 #\ndiv 52 53\nmul_plus 10 51 4\nadd_c 23 #\ndiv 55 56\nmul_plus 12 51 5\nadd_c 23 #\ndiv 58 59\ndot_sub 1 60 2 57\ndot_sub 2 54 0 60\ndot_sub 0 57 1 54\nmul_c 61 #\nmul_c 62 #\nadd 64 65\nmul_c 63 #\nadd 66 67\nmul_c 1 #\nmul_c 2 #\nsub 69 70\nmul_c 2 #\nmul_c 0 #\nsub 72 73\nmul_c 0 #\nmul_c 1 #\nsub 75 76\ndot_sub 4 60 5 57\ndot_sub 5 54 3 60\ndot_sub 3 57 4 54\nadd 71 78\nmul_plus 54 68 81\nadd 74 79\nmul_plus 57 68 83\nadd 77 80\nmul_plus 60 68 85\n"),
    ];

    #[inline(always)]
    fn pass<T: Coefficient, const FMA: bool>(
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
            4 => routh_general_unit::<T, FMA>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                q.try_into().expect("the constants of the shape"),
            ),
            5 => routh_general_unit_free::<T, FMA>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                q.try_into().expect("the constants of the shape"),
            ),
            6 => chaplygin::<T, FMA>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                q.try_into().expect("the constants of the shape"),
            ),
            7 => ball::<T, FMA>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                q.try_into().expect("the constants of the shape"),
            ),
            8 => ball_unit::<T, FMA>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                q.try_into().expect("the constants of the shape"),
            ),
            _ => unreachable!("a kernel of SHAPES"),
        }
    }

    #[inline(always)]
    fn zero<T: Coefficient>(kernel: usize, c: &mut [T], s: usize, z: &[f64]) {
        match kernel {
            0 => routh_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            1 => routh_free_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            2 => routh_general_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            3 => routh_general_free_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            4 => routh_general_unit_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            5 => routh_general_unit_free_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            6 => chaplygin_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            7 => ball_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            8 => ball_unit_zero::<T>(c, s, z.try_into().expect("the constants of the shape")),
            _ => unreachable!("a kernel of SHAPES"),
        }
    }

    #[inline(always)]
    fn histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
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
            4 => routh_general_unit_histories::<T, FMA, WIDE>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                g.try_into().expect("the histories of the shape"),
            ),
            5 => routh_general_unit_histories::<T, FMA, WIDE>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                g.try_into().expect("the histories of the shape"),
            ),
            6 => chaplygin_histories::<T, FMA, WIDE>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                g.try_into().expect("the histories of the shape"),
            ),
            7 => ball_histories::<T, FMA, WIDE>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                g.try_into().expect("the histories of the shape"),
            ),
            8 => ball_unit_histories::<T, FMA, WIDE>(
                c,
                s,
                k,
                h.try_into().expect("the histories of the shape"),
                g.try_into().expect("the histories of the shape"),
            ),
            _ => unreachable!("a kernel of SHAPES"),
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh`.
#[inline(always)]
fn routh<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 21],
    q: &[f64; 12],
) {
    let v7 = c[2 * s + 4 + k];
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[4], c[4 + k]], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[7 * s + 4], v7, h[1]);
    c[9 * s + 4 + k] = v9;
    let v10 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[3 * s + 4], c[3 * s + 4 + k]], [c[s + 4], c[s + 4 + k], c[4 * s + 4], c[4 * s + 4 + k]], h[2]);
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[7 * s + 4], v7, h[3]);
    c[11 * s + 4 + k] = v11;
    let v12 = v8 + v9;
    c[12 * s + 4 + k] = v12;
    let v13 = v10 + v11;
    c[13 * s + 4 + k] = v13;
    let v14 = v10 * q[1];
    c[14 * s + 4 + k] = v14;
    let v15 = v11 * q[2];
    c[15 * s + 4 + k] = v15;
    let v16 = v14 + v15;
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::mul_plus::<T, FMA>(c[12 * s + 4], v12, c[13 * s + 4], v13, v16, h[4]);
    c[17 * s + 4 + k] = v17;
    let v18 = v8 * q[3];
    c[18 * s + 4 + k] = v18;
    let v19 = v9 * q[4];
    c[19 * s + 4 + k] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4 + k] = v20;
    let v21 = v20;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::quotient::<T, FMA>(v17, c[21 * s + 4], v21, c[22 * s + 4], h[5]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[22 * s + 4], v22, c[3 * s + 4 + k], h[6]);
    c[23 * s + 4 + k] = v23;
    let v24 = v12;
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::quotient::<T, FMA>(v23, c[24 * s + 4], v24, c[25 * s + 4], h[7]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::mul_plus::<T, FMA>(c[s + 4], c[s + 4 + k], c[22 * s + 4], v22, c[4 * s + 4 + k], h[8]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::quotient::<T, FMA>(v26, c[24 * s + 4], v24, c[27 * s + 4], h[9]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[22 * s + 4], v22, c[5 * s + 4 + k], h[10]);
    c[28 * s + 4 + k] = v28;
    let v29 = v12;
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::quotient::<T, FMA>(v28, c[29 * s + 4], v29, c[30 * s + 4], h[11]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[30 * s + 4], v30], [c[2 * s + 4], c[2 * s + 4 + k], c[27 * s + 4], v27], h[12]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[25 * s + 4], v25], [c[4], c[4 + k], c[30 * s + 4], v30], h[13]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[27 * s + 4], v27], [c[s + 4], c[s + 4 + k], c[25 * s + 4], v25], h[14]);
    c[33 * s + 4 + k] = v33;
    let v34 = v33 * q[8];
    c[34 * s + 4 + k] = v34;
    let v35 = c[s + 4 + k] * q[9];
    c[35 * s + 4 + k] = v35;
    let v36 = c[4 + k] * q[10];
    c[36 * s + 4 + k] = v36;
    let v37 = -v36;
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[30 * s + 4], v30], [c[5 * s + 4], c[5 * s + 4 + k], c[27 * s + 4], v27], h[15]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[25 * s + 4], v25], [c[3 * s + 4], c[3 * s + 4 + k], c[30 * s + 4], v30], h[16]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[27 * s + 4], v27], [c[4 * s + 4], c[4 * s + 4 + k], c[25 * s + 4], v25], h[17]);
    c[40 * s + 4 + k] = v40;
    let v41 = v35 + v38;
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::mul_plus::<T, FMA>(c[25 * s + 4], v25, c[34 * s + 4], v34, v41, h[18]);
    c[42 * s + 4 + k] = v42;
    let v43 = v37 + v39;
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::mul_plus::<T, FMA>(c[27 * s + 4], v27, c[34 * s + 4], v34, v43, h[19]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::mul_plus::<T, FMA>(c[30 * s + 4], v30, c[34 * s + 4], v34, v40, h[20]);
    c[45 * s + 4 + k] = v45;
}

/// Order 0 of the kernel `routh`.
#[inline(always)]
fn routh_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 12]) {
    let v7 = c[2 * s + 4] + z[0];
    c[7 * s + 4] = v7;
    let v8 = c[4] * c[4] + c[s + 4] * c[s + 4];
    c[8 * s + 4] = v8;
    let v9 = v7 * v7;
    c[9 * s + 4] = v9;
    let v10 = c[4] * c[3 * s + 4] + c[s + 4] * c[4 * s + 4];
    c[10 * s + 4] = v10;
    let v11 = c[5 * s + 4] * v7;
    c[11 * s + 4] = v11;
    let v12 = v8 + v9;
    c[12 * s + 4] = v12;
    let v13 = v10 + v11;
    c[13 * s + 4] = v13;
    let v14 = v10 * z[1];
    c[14 * s + 4] = v14;
    let v15 = v11 * z[2];
    c[15 * s + 4] = v15;
    let v16 = v14 + v15;
    c[16 * s + 4] = v16;
    let v17 = v12 * v13 + v16;
    c[17 * s + 4] = v17;
    let v18 = v8 * z[3];
    c[18 * s + 4] = v18;
    let v19 = v9 * z[4];
    c[19 * s + 4] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4] = v20;
    let v21 = v20 + z[5];
    c[21 * s + 4] = v21;
    let v22 = v17 / v21;
    c[22 * s + 4] = v22;
    let v23 = c[4] * v22 + c[3 * s + 4];
    c[23 * s + 4] = v23;
    let v24 = v12 + z[6];
    c[24 * s + 4] = v24;
    let v25 = v23 / v24;
    c[25 * s + 4] = v25;
    let v26 = c[s + 4] * v22 + c[4 * s + 4];
    c[26 * s + 4] = v26;
    let v27 = v26 / v24;
    c[27 * s + 4] = v27;
    let v28 = v7 * v22 + c[5 * s + 4];
    c[28 * s + 4] = v28;
    let v29 = v12 + z[7];
    c[29 * s + 4] = v29;
    let v30 = v28 / v29;
    c[30 * s + 4] = v30;
    let v31 = c[s + 4] * v30 - c[2 * s + 4] * v27;
    c[31 * s + 4] = v31;
    let v32 = c[2 * s + 4] * v25 - c[4] * v30;
    c[32 * s + 4] = v32;
    let v33 = c[4] * v27 - c[s + 4] * v25;
    c[33 * s + 4] = v33;
    let v34 = v33 * z[8];
    c[34 * s + 4] = v34;
    let v35 = c[s + 4] * z[9];
    c[35 * s + 4] = v35;
    let v36 = c[4] * z[10];
    c[36 * s + 4] = v36;
    let v37 = T::from_f64(z[11]) - v36;
    c[37 * s + 4] = v37;
    let v38 = c[4 * s + 4] * v30 - c[5 * s + 4] * v27;
    c[38 * s + 4] = v38;
    let v39 = c[5 * s + 4] * v25 - c[3 * s + 4] * v30;
    c[39 * s + 4] = v39;
    let v40 = c[3 * s + 4] * v27 - c[4 * s + 4] * v25;
    c[40 * s + 4] = v40;
    let v41 = v35 + v38;
    c[41 * s + 4] = v41;
    let v42 = v25 * v34 + v41;
    c[42 * s + 4] = v42;
    let v43 = v37 + v39;
    c[43 * s + 4] = v43;
    let v44 = v27 * v34 + v43;
    c[44 * s + 4] = v44;
    let v45 = v30 * v34 + v40;
    c[45 * s + 4] = v45;
}

/// The histories of the kernels `routh`, `routh_free` at order `k >= 1` ([`Kernels::histories`]).
#[inline(always)]
fn routh_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 21],
    g: &mut [T; 21],
) {
    assert!(k + 4 <= s && c.len() >= 35 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 5, 6, 8, 10].
        let (mut s0, mut s1, mut s5, mut s6, mut s8, mut s10) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, a2, b2, a20, b22) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 20 * s + 4 + j), at(c, 22 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a0, b0, s0);
            s0 = mul_add::<T, FMA>(a1, b1, s0);
            s1 = mul_add::<T, FMA>(a2, b2, s1);
            s5 = mul_add::<T, FMA>(a20, b22, s5);
            s6 = mul_add::<T, FMA>(a0, b22, s6);
            s8 = mul_add::<T, FMA>(a1, b22, s8);
            s10 = mul_add::<T, FMA>(a2, b22, s10);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), s0);
                s0 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), s0);
                s1 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s1);
                s1 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s1);
                s5 = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s5);
                s5 = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s5);
                s6 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 22 * s + 4 + k - 1), s6);
                s6 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 22 * s + 4 + 1), s6);
                s8 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 22 * s + 4 + k - 1), s8);
                s8 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 22 * s + 4 + 1), s8);
                s10 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s10);
                s10 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s10);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[5] = s5;
        h[6] = s6;
        h[8] = s8;
        h[10] = s10;
        // Histories [2, 3, 4, 7, 9, 11].
        let (mut s2, mut s3, mut s4, mut s7, mut s9, mut s11) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, b2, b3, b4, a5, a12, b13, b25, b27, b30) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + j), at(c, 12 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a0, b3, s2);
            s2 = mul_add::<T, FMA>(a1, b4, s2);
            s3 = mul_add::<T, FMA>(a5, b2, s3);
            s4 = mul_add::<T, FMA>(a12, b13, s4);
            s7 = mul_add::<T, FMA>(a12, b25, s7);
            s9 = mul_add::<T, FMA>(a12, b27, s9);
            s11 = mul_add::<T, FMA>(a12, b30, s11);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s2 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), s2);
                s2 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), s2);
                s3 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s3);
                s3 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s3);
                s4 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), s4);
                s4 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), s4);
                s7 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s7);
                s7 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s7);
                s9 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s9);
                s9 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s9);
                s11 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s11);
                s11 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s11);
            }
        }
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[7] = s7;
        h[9] = s9;
        h[11] = s11;
        // Histories [12, 13, 15, 18, 19, 20].
        let (mut s12, mut s13, mut s15, mut s18, mut s19, mut s20) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a25, b25, a27, b27, a30, b30, b34) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 25 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 34 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b30, s12);
            s12 = mul_add::<T, FMA>(-a2, b27, s12);
            s13 = mul_add::<T, FMA>(a2, b25, s13);
            s13 = mul_add::<T, FMA>(-a0, b30, s13);
            s15 = mul_add::<T, FMA>(a4, b30, s15);
            s15 = mul_add::<T, FMA>(-a5, b27, s15);
            s18 = mul_add::<T, FMA>(a25, b34, s18);
            s19 = mul_add::<T, FMA>(a27, b34, s19);
            s20 = mul_add::<T, FMA>(a30, b34, s20);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s12 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 30 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 30 * s + 4 + 1), s12);
                s12 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s12);
                s13 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 30 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s13);
                s13 = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 30 * s + 4 + 1), s13);
                s15 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s15);
                s15 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s15);
                s18 = mul_add::<T, FMA>(at(c, 25 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(at(c, 25 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s18);
                s19 = mul_add::<T, FMA>(at(c, 27 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(at(c, 27 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s19);
                s20 = mul_add::<T, FMA>(at(c, 30 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(at(c, 30 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s20);
            }
        }
        h[12] = s12;
        h[13] = s13;
        h[15] = s15;
        h[18] = s18;
        h[19] = s19;
        h[20] = s20;
        // Histories [14, 16, 17].
        let (mut s14, mut s16, mut s17) = (zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b25, b27, b30) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b27, s14);
            s14 = mul_add::<T, FMA>(-a1, b25, s14);
            s16 = mul_add::<T, FMA>(a5, b25, s16);
            s16 = mul_add::<T, FMA>(-a3, b30, s16);
            s17 = mul_add::<T, FMA>(a3, b27, s17);
            s17 = mul_add::<T, FMA>(-a4, b25, s17);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s14 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 27 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 25 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 27 * s + 4 + 1), s14);
                s14 = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 25 * s + 4 + 1), s14);
                s16 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), s16);
                s17 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s17);
            }
        }
        h[14] = s14;
        h[16] = s16;
        h[17] = s17;
    } else if even {
        // Histories [0, 1, 5, 6, 8, 10]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s5, mut t5, mut s6, mut t6, mut s8, mut t8, mut s10, mut t10) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p0, mut p1, mut p2, mut p22) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, a2, b2, a20, b22) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 20 * s + 4 + j), at(c, 22 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a0, b0, s0);
            s0 = mul_add::<T, FMA>(a1, b1, s0);
            s1 = mul_add::<T, FMA>(a2, b2, s1);
            s5 = mul_add::<T, FMA>(a20, b22, s5);
            s6 = mul_add::<T, FMA>(a0, b22, s6);
            s8 = mul_add::<T, FMA>(a1, b22, s8);
            s10 = mul_add::<T, FMA>(a2, b22, s10);
            (b0, b1, b2, b22)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, a2, b2, a20, b22) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 20 * s + 4 + j), at(c, 22 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a0, b0, s0);
            s0 = mul_add::<T, FMA>(a1, b1, s0);
            s1 = mul_add::<T, FMA>(a2, b2, s1);
            s5 = mul_add::<T, FMA>(a20, b22, s5);
            s6 = mul_add::<T, FMA>(a0, b22, s6);
            s8 = mul_add::<T, FMA>(a1, b22, s8);
            s10 = mul_add::<T, FMA>(a2, b22, s10);
            t0 = mul_add::<T, FMA>(a0, p0, t0);
            t0 = mul_add::<T, FMA>(a1, p1, t0);
            t1 = mul_add::<T, FMA>(a2, p2, t1);
            t5 = mul_add::<T, FMA>(a20, p22, t5);
            t6 = mul_add::<T, FMA>(a0, p22, t6);
            t8 = mul_add::<T, FMA>(a1, p22, t8);
            t10 = mul_add::<T, FMA>(a2, p22, t10);
            (p0, p1, p2, p22) = (b0, b1, b2, b22);
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[8] = s8;
        g[8] = t8;
        h[10] = s10;
        g[10] = t10;
        // Histories [2, 3, 4, 7, 9, 11]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s7, mut t7, mut s9, mut t9, mut s11, mut t11) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p2, mut p3, mut p4, mut p13, mut p25, mut p27, mut p30) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, b2, b3, b4, a5, a12, b13, b25, b27, b30) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + j), at(c, 12 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a0, b3, s2);
            s2 = mul_add::<T, FMA>(a1, b4, s2);
            s3 = mul_add::<T, FMA>(a5, b2, s3);
            s4 = mul_add::<T, FMA>(a12, b13, s4);
            s7 = mul_add::<T, FMA>(a12, b25, s7);
            s9 = mul_add::<T, FMA>(a12, b27, s9);
            s11 = mul_add::<T, FMA>(a12, b30, s11);
            (b2, b3, b4, b13, b25, b27, b30)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, b2, b3, b4, a5, a12, b13, b25, b27, b30) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 3 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + j), at(c, 12 * s + 4 + j), at(c, 13 * s + 4 + k - j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a0, b3, s2);
            s2 = mul_add::<T, FMA>(a1, b4, s2);
            s3 = mul_add::<T, FMA>(a5, b2, s3);
            s4 = mul_add::<T, FMA>(a12, b13, s4);
            s7 = mul_add::<T, FMA>(a12, b25, s7);
            s9 = mul_add::<T, FMA>(a12, b27, s9);
            s11 = mul_add::<T, FMA>(a12, b30, s11);
            t2 = mul_add::<T, FMA>(a0, p3, t2);
            t2 = mul_add::<T, FMA>(a1, p4, t2);
            t3 = mul_add::<T, FMA>(a5, p2, t3);
            t4 = mul_add::<T, FMA>(a12, p13, t4);
            t7 = mul_add::<T, FMA>(a12, p25, t7);
            t9 = mul_add::<T, FMA>(a12, p27, t9);
            t11 = mul_add::<T, FMA>(a12, p30, t11);
            (p2, p3, p4, p13, p25, p27, p30) = (b2, b3, b4, b13, b25, b27, b30);
        }
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[7] = s7;
        g[7] = t7;
        h[9] = s9;
        g[9] = t9;
        h[11] = s11;
        g[11] = t11;
        // Histories [12, 13, 15, 18, 19, 20]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s12, mut t12, mut s13, mut t13, mut s15, mut t15, mut s18, mut t18, mut s19, mut t19, mut s20, mut t20) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p25, mut p27, mut p30, mut p34) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a25, b25, a27, b27, a30, b30, b34) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 25 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 34 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b30, s12);
            s12 = mul_add::<T, FMA>(-a2, b27, s12);
            s13 = mul_add::<T, FMA>(a2, b25, s13);
            s13 = mul_add::<T, FMA>(-a0, b30, s13);
            s15 = mul_add::<T, FMA>(a4, b30, s15);
            s15 = mul_add::<T, FMA>(-a5, b27, s15);
            s18 = mul_add::<T, FMA>(a25, b34, s18);
            s19 = mul_add::<T, FMA>(a27, b34, s19);
            s20 = mul_add::<T, FMA>(a30, b34, s20);
            (b25, b27, b30, b34)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a25, b25, a27, b27, a30, b30, b34) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 25 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + j), at(c, 30 * s + 4 + k - j), at(c, 34 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b30, s12);
            s12 = mul_add::<T, FMA>(-a2, b27, s12);
            s13 = mul_add::<T, FMA>(a2, b25, s13);
            s13 = mul_add::<T, FMA>(-a0, b30, s13);
            s15 = mul_add::<T, FMA>(a4, b30, s15);
            s15 = mul_add::<T, FMA>(-a5, b27, s15);
            s18 = mul_add::<T, FMA>(a25, b34, s18);
            s19 = mul_add::<T, FMA>(a27, b34, s19);
            s20 = mul_add::<T, FMA>(a30, b34, s20);
            t12 = mul_add::<T, FMA>(a1, p30, t12);
            t12 = mul_add::<T, FMA>(-a2, p27, t12);
            t13 = mul_add::<T, FMA>(a2, p25, t13);
            t13 = mul_add::<T, FMA>(-a0, p30, t13);
            t15 = mul_add::<T, FMA>(a4, p30, t15);
            t15 = mul_add::<T, FMA>(-a5, p27, t15);
            t18 = mul_add::<T, FMA>(a25, p34, t18);
            t19 = mul_add::<T, FMA>(a27, p34, t19);
            t20 = mul_add::<T, FMA>(a30, p34, t20);
            (p25, p27, p30, p34) = (b25, b27, b30, b34);
        }
        h[12] = s12;
        g[12] = t12;
        h[13] = s13;
        g[13] = t13;
        h[15] = s15;
        g[15] = t15;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        // Histories [14, 16, 17]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s14, mut t14, mut s16, mut t16, mut s17, mut t17) = (zero, zero, zero, zero, zero, zero);
        let (mut p25, mut p27, mut p30) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b25, b27, b30) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b27, s14);
            s14 = mul_add::<T, FMA>(-a1, b25, s14);
            s16 = mul_add::<T, FMA>(a5, b25, s16);
            s16 = mul_add::<T, FMA>(-a3, b30, s16);
            s17 = mul_add::<T, FMA>(a3, b27, s17);
            s17 = mul_add::<T, FMA>(-a4, b25, s17);
            (b25, b27, b30)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b25, b27, b30) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 27 * s + 4 + k - j), at(c, 30 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b27, s14);
            s14 = mul_add::<T, FMA>(-a1, b25, s14);
            s16 = mul_add::<T, FMA>(a5, b25, s16);
            s16 = mul_add::<T, FMA>(-a3, b30, s16);
            s17 = mul_add::<T, FMA>(a3, b27, s17);
            s17 = mul_add::<T, FMA>(-a4, b25, s17);
            t14 = mul_add::<T, FMA>(a0, p27, t14);
            t14 = mul_add::<T, FMA>(-a1, p25, t14);
            t16 = mul_add::<T, FMA>(a5, p25, t16);
            t16 = mul_add::<T, FMA>(-a3, p30, t16);
            t17 = mul_add::<T, FMA>(a3, p27, t17);
            t17 = mul_add::<T, FMA>(-a4, p25, t17);
            (p25, p27, p30) = (b25, b27, b30);
        }
        h[14] = s14;
        g[14] = t14;
        h[16] = s16;
        g[16] = t16;
        h[17] = s17;
        g[17] = t17;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 13 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 13 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 30 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 30 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 27 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 27 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = mul_add::<T, FMA>(at(c, 25 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 25 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = mul_add::<T, FMA>(at(c, 27 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 27 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = mul_add::<T, FMA>(at(c, 30 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 30 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[20] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh_free`.
#[inline(always)]
fn routh_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 21],
    q: &[f64; 9],
) {
    let v7 = c[2 * s + 4 + k];
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[4], c[4 + k]], [c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k]], h[0]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[7 * s + 4], v7, h[1]);
    c[9 * s + 4 + k] = v9;
    let v10 = recurrence::dot_add::<T, FMA>([c[4], c[4 + k], c[3 * s + 4], c[3 * s + 4 + k]], [c[s + 4], c[s + 4 + k], c[4 * s + 4], c[4 * s + 4 + k]], h[2]);
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[7 * s + 4], v7, h[3]);
    c[11 * s + 4 + k] = v11;
    let v12 = v8 + v9;
    c[12 * s + 4 + k] = v12;
    let v13 = v10 + v11;
    c[13 * s + 4 + k] = v13;
    let v14 = v10 * q[1];
    c[14 * s + 4 + k] = v14;
    let v15 = v11 * q[2];
    c[15 * s + 4 + k] = v15;
    let v16 = v14 + v15;
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::mul_plus::<T, FMA>(c[12 * s + 4], v12, c[13 * s + 4], v13, v16, h[4]);
    c[17 * s + 4 + k] = v17;
    let v18 = v8 * q[3];
    c[18 * s + 4 + k] = v18;
    let v19 = v9 * q[4];
    c[19 * s + 4 + k] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4 + k] = v20;
    let v21 = v20;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::quotient::<T, FMA>(v17, c[21 * s + 4], v21, c[22 * s + 4], h[5]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[22 * s + 4], v22, c[3 * s + 4 + k], h[6]);
    c[23 * s + 4 + k] = v23;
    let v24 = v12;
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::quotient::<T, FMA>(v23, c[24 * s + 4], v24, c[25 * s + 4], h[7]);
    c[25 * s + 4 + k] = v25;
    let v26 = recurrence::mul_plus::<T, FMA>(c[s + 4], c[s + 4 + k], c[22 * s + 4], v22, c[4 * s + 4 + k], h[8]);
    c[26 * s + 4 + k] = v26;
    let v27 = recurrence::quotient::<T, FMA>(v26, c[24 * s + 4], v24, c[27 * s + 4], h[9]);
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[22 * s + 4], v22, c[5 * s + 4 + k], h[10]);
    c[28 * s + 4 + k] = v28;
    let v29 = v12;
    c[29 * s + 4 + k] = v29;
    let v30 = recurrence::quotient::<T, FMA>(v28, c[29 * s + 4], v29, c[30 * s + 4], h[11]);
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[30 * s + 4], v30], [c[2 * s + 4], c[2 * s + 4 + k], c[27 * s + 4], v27], h[12]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[25 * s + 4], v25], [c[4], c[4 + k], c[30 * s + 4], v30], h[13]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[27 * s + 4], v27], [c[s + 4], c[s + 4 + k], c[25 * s + 4], v25], h[14]);
    c[33 * s + 4 + k] = v33;
    let v34 = v33 * q[8];
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[30 * s + 4], v30], [c[5 * s + 4], c[5 * s + 4 + k], c[27 * s + 4], v27], h[15]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[25 * s + 4], v25], [c[3 * s + 4], c[3 * s + 4 + k], c[30 * s + 4], v30], h[16]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[27 * s + 4], v27], [c[4 * s + 4], c[4 * s + 4 + k], c[25 * s + 4], v25], h[17]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::mul_plus::<T, FMA>(c[25 * s + 4], v25, c[34 * s + 4], v34, v35, h[18]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::mul_plus::<T, FMA>(c[27 * s + 4], v27, c[34 * s + 4], v34, v36, h[19]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::mul_plus::<T, FMA>(c[30 * s + 4], v30, c[34 * s + 4], v34, v37, h[20]);
    c[40 * s + 4 + k] = v40;
}

/// Order 0 of the kernel `routh_free`.
#[inline(always)]
fn routh_free_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 9]) {
    let v7 = c[2 * s + 4] + z[0];
    c[7 * s + 4] = v7;
    let v8 = c[4] * c[4] + c[s + 4] * c[s + 4];
    c[8 * s + 4] = v8;
    let v9 = v7 * v7;
    c[9 * s + 4] = v9;
    let v10 = c[4] * c[3 * s + 4] + c[s + 4] * c[4 * s + 4];
    c[10 * s + 4] = v10;
    let v11 = c[5 * s + 4] * v7;
    c[11 * s + 4] = v11;
    let v12 = v8 + v9;
    c[12 * s + 4] = v12;
    let v13 = v10 + v11;
    c[13 * s + 4] = v13;
    let v14 = v10 * z[1];
    c[14 * s + 4] = v14;
    let v15 = v11 * z[2];
    c[15 * s + 4] = v15;
    let v16 = v14 + v15;
    c[16 * s + 4] = v16;
    let v17 = v12 * v13 + v16;
    c[17 * s + 4] = v17;
    let v18 = v8 * z[3];
    c[18 * s + 4] = v18;
    let v19 = v9 * z[4];
    c[19 * s + 4] = v19;
    let v20 = v18 + v19;
    c[20 * s + 4] = v20;
    let v21 = v20 + z[5];
    c[21 * s + 4] = v21;
    let v22 = v17 / v21;
    c[22 * s + 4] = v22;
    let v23 = c[4] * v22 + c[3 * s + 4];
    c[23 * s + 4] = v23;
    let v24 = v12 + z[6];
    c[24 * s + 4] = v24;
    let v25 = v23 / v24;
    c[25 * s + 4] = v25;
    let v26 = c[s + 4] * v22 + c[4 * s + 4];
    c[26 * s + 4] = v26;
    let v27 = v26 / v24;
    c[27 * s + 4] = v27;
    let v28 = v7 * v22 + c[5 * s + 4];
    c[28 * s + 4] = v28;
    let v29 = v12 + z[7];
    c[29 * s + 4] = v29;
    let v30 = v28 / v29;
    c[30 * s + 4] = v30;
    let v31 = c[s + 4] * v30 - c[2 * s + 4] * v27;
    c[31 * s + 4] = v31;
    let v32 = c[2 * s + 4] * v25 - c[4] * v30;
    c[32 * s + 4] = v32;
    let v33 = c[4] * v27 - c[s + 4] * v25;
    c[33 * s + 4] = v33;
    let v34 = v33 * z[8];
    c[34 * s + 4] = v34;
    let v35 = c[4 * s + 4] * v30 - c[5 * s + 4] * v27;
    c[35 * s + 4] = v35;
    let v36 = c[5 * s + 4] * v25 - c[3 * s + 4] * v30;
    c[36 * s + 4] = v36;
    let v37 = c[3 * s + 4] * v27 - c[4 * s + 4] * v25;
    c[37 * s + 4] = v37;
    let v38 = v25 * v34 + v35;
    c[38 * s + 4] = v38;
    let v39 = v27 * v34 + v36;
    c[39 * s + 4] = v39;
    let v40 = v30 * v34 + v37;
    c[40 * s + 4] = v40;
}

/// The pass of order `k >= 1` of the kernel `routh_general`.
#[inline(always)]
fn routh_general<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 21],
    q: &[f64; 21],
) {
    let v7 = c[3 * s + 4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = c[4 * s + 4 + k] * q[1];
    c[8 * s + 4 + k] = v8;
    let v9 = c[5 * s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = c[4 + k] * q[3];
    c[10 * s + 4 + k] = v10;
    let v11 = c[s + 4 + k] * q[4];
    c[11 * s + 4 + k] = v11;
    let v12 = c[2 * s + 4 + k] * q[5];
    c[12 * s + 4 + k] = v12;
    let v13 = v12;
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[10 * s + 4], v10], [c[11 * s + 4], v11, c[11 * s + 4], v11], h[0]);
    c[14 * s + 4 + k] = v14;
    let v15 = v14 * q[7];
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[13 * s + 4], v13, c[13 * s + 4], v13, h[1]);
    c[16 * s + 4 + k] = v16;
    let v17 = v16 * q[8];
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[10 * s + 4], v10], [c[8 * s + 4], v8, c[11 * s + 4], v11], h[2]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[9 * s + 4], v9, c[13 * s + 4], v13, h[3]);
    c[19 * s + 4 + k] = v19;
    let v20 = v15 + v17;
    c[20 * s + 4 + k] = v20;
    let v21 = v18 + v19;
    c[21 * s + 4 + k] = v21;
    let v22 = v18 * q[9];
    c[22 * s + 4 + k] = v22;
    let v23 = v19 * q[10];
    c[23 * s + 4 + k] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[20 * s + 4], v20, c[21 * s + 4], v21, v24, h[4]);
    c[25 * s + 4 + k] = v25;
    let v26 = v25 * q[11];
    c[26 * s + 4 + k] = v26;
    let v27 = v15 * q[12];
    c[27 * s + 4 + k] = v27;
    let v28 = v17 * q[13];
    c[28 * s + 4 + k] = v28;
    let v29 = v27 + v28;
    c[29 * s + 4 + k] = v29;
    let v30 = v29;
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v26, c[30 * s + 4], v30, c[31 * s + 4], h[5]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[31 * s + 4], v31, v7, h[6]);
    c[32 * s + 4 + k] = v32;
    let v33 = v20;
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::quotient::<T, FMA>(v32, c[33 * s + 4], v33, c[34 * s + 4], h[7]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::mul_plus::<T, FMA>(c[11 * s + 4], v11, c[31 * s + 4], v31, v8, h[8]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::quotient::<T, FMA>(v35, c[33 * s + 4], v33, c[36 * s + 4], h[9]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::mul_plus::<T, FMA>(c[13 * s + 4], v13, c[31 * s + 4], v31, v9, h[10]);
    c[37 * s + 4 + k] = v37;
    let v38 = v20;
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::quotient::<T, FMA>(v37, c[38 * s + 4], v38, c[39 * s + 4], h[11]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[39 * s + 4], v39], [c[2 * s + 4], c[2 * s + 4 + k], c[36 * s + 4], v36], h[12]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[34 * s + 4], v34], [c[4], c[4 + k], c[39 * s + 4], v39], h[13]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[36 * s + 4], v36], [c[s + 4], c[s + 4 + k], c[34 * s + 4], v34], h[14]);
    c[42 * s + 4 + k] = v42;
    let v43 = v42 * q[17];
    c[43 * s + 4 + k] = v43;
    let v44 = c[s + 4 + k] * q[18];
    c[44 * s + 4 + k] = v44;
    let v45 = c[4 + k] * q[19];
    c[45 * s + 4 + k] = v45;
    let v46 = -v45;
    c[46 * s + 4 + k] = v46;
    let v47 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[39 * s + 4], v39], [c[5 * s + 4], c[5 * s + 4 + k], c[36 * s + 4], v36], h[15]);
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[34 * s + 4], v34], [c[3 * s + 4], c[3 * s + 4 + k], c[39 * s + 4], v39], h[16]);
    c[48 * s + 4 + k] = v48;
    let v49 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[36 * s + 4], v36], [c[4 * s + 4], c[4 * s + 4 + k], c[34 * s + 4], v34], h[17]);
    c[49 * s + 4 + k] = v49;
    let v50 = v44 + v47;
    c[50 * s + 4 + k] = v50;
    let v51 = recurrence::mul_plus::<T, FMA>(c[34 * s + 4], v34, c[43 * s + 4], v43, v50, h[18]);
    c[51 * s + 4 + k] = v51;
    let v52 = v46 + v48;
    c[52 * s + 4 + k] = v52;
    let v53 = recurrence::mul_plus::<T, FMA>(c[36 * s + 4], v36, c[43 * s + 4], v43, v52, h[19]);
    c[53 * s + 4 + k] = v53;
    let v54 = recurrence::mul_plus::<T, FMA>(c[39 * s + 4], v39, c[43 * s + 4], v43, v49, h[20]);
    c[54 * s + 4 + k] = v54;
}

/// Order 0 of the kernel `routh_general`.
#[inline(always)]
fn routh_general_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 21]) {
    let v7 = c[3 * s + 4] * z[0];
    c[7 * s + 4] = v7;
    let v8 = c[4 * s + 4] * z[1];
    c[8 * s + 4] = v8;
    let v9 = c[5 * s + 4] * z[2];
    c[9 * s + 4] = v9;
    let v10 = c[4] * z[3];
    c[10 * s + 4] = v10;
    let v11 = c[s + 4] * z[4];
    c[11 * s + 4] = v11;
    let v12 = c[2 * s + 4] * z[5];
    c[12 * s + 4] = v12;
    let v13 = v12 + z[6];
    c[13 * s + 4] = v13;
    let v14 = v10 * v10 + v11 * v11;
    c[14 * s + 4] = v14;
    let v15 = v14 * z[7];
    c[15 * s + 4] = v15;
    let v16 = v13 * v13;
    c[16 * s + 4] = v16;
    let v17 = v16 * z[8];
    c[17 * s + 4] = v17;
    let v18 = v7 * v10 + v8 * v11;
    c[18 * s + 4] = v18;
    let v19 = v9 * v13;
    c[19 * s + 4] = v19;
    let v20 = v15 + v17;
    c[20 * s + 4] = v20;
    let v21 = v18 + v19;
    c[21 * s + 4] = v21;
    let v22 = v18 * z[9];
    c[22 * s + 4] = v22;
    let v23 = v19 * z[10];
    c[23 * s + 4] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4] = v24;
    let v25 = v20 * v21 + v24;
    c[25 * s + 4] = v25;
    let v26 = v25 * z[11];
    c[26 * s + 4] = v26;
    let v27 = v15 * z[12];
    c[27 * s + 4] = v27;
    let v28 = v17 * z[13];
    c[28 * s + 4] = v28;
    let v29 = v27 + v28;
    c[29 * s + 4] = v29;
    let v30 = v29 + z[14];
    c[30 * s + 4] = v30;
    let v31 = v26 / v30;
    c[31 * s + 4] = v31;
    let v32 = v10 * v31 + v7;
    c[32 * s + 4] = v32;
    let v33 = v20 + z[15];
    c[33 * s + 4] = v33;
    let v34 = v32 / v33;
    c[34 * s + 4] = v34;
    let v35 = v11 * v31 + v8;
    c[35 * s + 4] = v35;
    let v36 = v35 / v33;
    c[36 * s + 4] = v36;
    let v37 = v13 * v31 + v9;
    c[37 * s + 4] = v37;
    let v38 = v20 + z[16];
    c[38 * s + 4] = v38;
    let v39 = v37 / v38;
    c[39 * s + 4] = v39;
    let v40 = c[s + 4] * v39 - c[2 * s + 4] * v36;
    c[40 * s + 4] = v40;
    let v41 = c[2 * s + 4] * v34 - c[4] * v39;
    c[41 * s + 4] = v41;
    let v42 = c[4] * v36 - c[s + 4] * v34;
    c[42 * s + 4] = v42;
    let v43 = v42 * z[17];
    c[43 * s + 4] = v43;
    let v44 = c[s + 4] * z[18];
    c[44 * s + 4] = v44;
    let v45 = c[4] * z[19];
    c[45 * s + 4] = v45;
    let v46 = T::from_f64(z[20]) - v45;
    c[46 * s + 4] = v46;
    let v47 = c[4 * s + 4] * v39 - c[5 * s + 4] * v36;
    c[47 * s + 4] = v47;
    let v48 = c[5 * s + 4] * v34 - c[3 * s + 4] * v39;
    c[48 * s + 4] = v48;
    let v49 = c[3 * s + 4] * v36 - c[4 * s + 4] * v34;
    c[49 * s + 4] = v49;
    let v50 = v44 + v47;
    c[50 * s + 4] = v50;
    let v51 = v34 * v43 + v50;
    c[51 * s + 4] = v51;
    let v52 = v46 + v48;
    c[52 * s + 4] = v52;
    let v53 = v36 * v43 + v52;
    c[53 * s + 4] = v53;
    let v54 = v39 * v43 + v49;
    c[54 * s + 4] = v54;
}

/// The histories of the kernels `routh_general`, `routh_general_free` at order `k >= 1` ([`Kernels::histories`]).
#[inline(always)]
fn routh_general_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 21],
    g: &mut [T; 21],
) {
    assert!(k + 4 <= s && c.len() >= 44 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 5, 6, 8, 10].
        let (mut s0, mut s1, mut s5, mut s6, mut s8, mut s10) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a10, b10, a11, b11, a12, b12, a29, b31) = unsafe { (at(c, 10 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 12 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 29 * s + 4 + j), at(c, 31 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a10, b10, s0);
            s0 = mul_add::<T, FMA>(a11, b11, s0);
            s1 = mul_add::<T, FMA>(a12, b12, s1);
            s5 = mul_add::<T, FMA>(a29, b31, s5);
            s6 = mul_add::<T, FMA>(a10, b31, s6);
            s8 = mul_add::<T, FMA>(a11, b31, s8);
            s10 = mul_add::<T, FMA>(a12, b31, s10);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s0);
                s1 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), s1);
                s1 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), s1);
                s5 = mul_add::<T, FMA>(at(c, 29 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s5);
                s5 = mul_add::<T, FMA>(at(c, 29 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s5);
                s6 = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s6);
                s6 = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s6);
                s8 = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s8);
                s8 = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s8);
                s10 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s10);
                s10 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s10);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[5] = s5;
        h[6] = s6;
        h[8] = s8;
        h[10] = s10;
        // Histories [2, 3, 4, 7, 9, 11].
        let (mut s2, mut s3, mut s4, mut s7, mut s9, mut s11) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, a8, a9, b10, b11, b12, a20, b21, b34, b36, b39) = unsafe { (at(c, 7 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 11 * s + 4 + k - j), at(c, 12 * s + 4 + k - j), at(c, 20 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a7, b10, s2);
            s2 = mul_add::<T, FMA>(a8, b11, s2);
            s3 = mul_add::<T, FMA>(a9, b12, s3);
            s4 = mul_add::<T, FMA>(a20, b21, s4);
            s7 = mul_add::<T, FMA>(a20, b34, s7);
            s9 = mul_add::<T, FMA>(a20, b36, s9);
            s11 = mul_add::<T, FMA>(a20, b39, s11);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s2 = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s2);
                s3 = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), s3);
                s3 = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), s3);
                s4 = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), s4);
                s4 = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), s4);
                s7 = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s7);
                s7 = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s7);
                s9 = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s9);
                s9 = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s9);
                s11 = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 39 * s + 4 + k - 1), s11);
                s11 = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 39 * s + 4 + 1), s11);
            }
        }
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[7] = s7;
        h[9] = s9;
        h[11] = s11;
        // Histories [12, 13, 15, 18, 19, 20].
        let (mut s12, mut s13, mut s15, mut s18, mut s19, mut s20) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a34, b34, a36, b36, a39, b39, b43) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + j), at(c, 39 * s + 4 + k - j), at(c, 43 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b39, s12);
            s12 = mul_add::<T, FMA>(-a2, b36, s12);
            s13 = mul_add::<T, FMA>(a2, b34, s13);
            s13 = mul_add::<T, FMA>(-a0, b39, s13);
            s15 = mul_add::<T, FMA>(a4, b39, s15);
            s15 = mul_add::<T, FMA>(-a5, b36, s15);
            s18 = mul_add::<T, FMA>(a34, b43, s18);
            s19 = mul_add::<T, FMA>(a36, b43, s19);
            s20 = mul_add::<T, FMA>(a39, b43, s20);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s12 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 39 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 39 * s + 4 + 1), s12);
                s12 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s12);
                s13 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 39 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s13);
                s13 = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 39 * s + 4 + 1), s13);
                s15 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 39 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 39 * s + 4 + 1), s15);
                s15 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s15);
                s18 = mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), s18);
                s19 = mul_add::<T, FMA>(at(c, 36 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(at(c, 36 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), s19);
                s20 = mul_add::<T, FMA>(at(c, 39 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(at(c, 39 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), s20);
            }
        }
        h[12] = s12;
        h[13] = s13;
        h[15] = s15;
        h[18] = s18;
        h[19] = s19;
        h[20] = s20;
        // Histories [14, 16, 17].
        let (mut s14, mut s16, mut s17) = (zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b34, b36, b39) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b36, s14);
            s14 = mul_add::<T, FMA>(-a1, b34, s14);
            s16 = mul_add::<T, FMA>(a5, b34, s16);
            s16 = mul_add::<T, FMA>(-a3, b39, s16);
            s17 = mul_add::<T, FMA>(a3, b36, s17);
            s17 = mul_add::<T, FMA>(-a4, b34, s17);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s14 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 36 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 34 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 36 * s + 4 + 1), s14);
                s14 = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 34 * s + 4 + 1), s14);
                s16 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 39 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 39 * s + 4 + 1), s16);
                s17 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s17);
            }
        }
        h[14] = s14;
        h[16] = s16;
        h[17] = s17;
    } else if even {
        // Histories [0, 1, 5, 6, 8, 10]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s5, mut t5, mut s6, mut t6, mut s8, mut t8, mut s10, mut t10) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p10, mut p11, mut p12, mut p31) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a10, b10, a11, b11, a12, b12, a29, b31) = unsafe { (at(c, 10 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 12 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 29 * s + 4 + j), at(c, 31 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a10, b10, s0);
            s0 = mul_add::<T, FMA>(a11, b11, s0);
            s1 = mul_add::<T, FMA>(a12, b12, s1);
            s5 = mul_add::<T, FMA>(a29, b31, s5);
            s6 = mul_add::<T, FMA>(a10, b31, s6);
            s8 = mul_add::<T, FMA>(a11, b31, s8);
            s10 = mul_add::<T, FMA>(a12, b31, s10);
            (b10, b11, b12, b31)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a10, b10, a11, b11, a12, b12, a29, b31) = unsafe { (at(c, 10 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 12 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 29 * s + 4 + j), at(c, 31 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a10, b10, s0);
            s0 = mul_add::<T, FMA>(a11, b11, s0);
            s1 = mul_add::<T, FMA>(a12, b12, s1);
            s5 = mul_add::<T, FMA>(a29, b31, s5);
            s6 = mul_add::<T, FMA>(a10, b31, s6);
            s8 = mul_add::<T, FMA>(a11, b31, s8);
            s10 = mul_add::<T, FMA>(a12, b31, s10);
            t0 = mul_add::<T, FMA>(a10, p10, t0);
            t0 = mul_add::<T, FMA>(a11, p11, t0);
            t1 = mul_add::<T, FMA>(a12, p12, t1);
            t5 = mul_add::<T, FMA>(a29, p31, t5);
            t6 = mul_add::<T, FMA>(a10, p31, t6);
            t8 = mul_add::<T, FMA>(a11, p31, t8);
            t10 = mul_add::<T, FMA>(a12, p31, t10);
            (p10, p11, p12, p31) = (b10, b11, b12, b31);
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[8] = s8;
        g[8] = t8;
        h[10] = s10;
        g[10] = t10;
        // Histories [2, 3, 4, 7, 9, 11]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s7, mut t7, mut s9, mut t9, mut s11, mut t11) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p10, mut p11, mut p12, mut p21, mut p34, mut p36, mut p39) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, a8, a9, b10, b11, b12, a20, b21, b34, b36, b39) = unsafe { (at(c, 7 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 11 * s + 4 + k - j), at(c, 12 * s + 4 + k - j), at(c, 20 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a7, b10, s2);
            s2 = mul_add::<T, FMA>(a8, b11, s2);
            s3 = mul_add::<T, FMA>(a9, b12, s3);
            s4 = mul_add::<T, FMA>(a20, b21, s4);
            s7 = mul_add::<T, FMA>(a20, b34, s7);
            s9 = mul_add::<T, FMA>(a20, b36, s9);
            s11 = mul_add::<T, FMA>(a20, b39, s11);
            (b10, b11, b12, b21, b34, b36, b39)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, a8, a9, b10, b11, b12, a20, b21, b34, b36, b39) = unsafe { (at(c, 7 * s + 4 + j), at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 11 * s + 4 + k - j), at(c, 12 * s + 4 + k - j), at(c, 20 * s + 4 + j), at(c, 21 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a7, b10, s2);
            s2 = mul_add::<T, FMA>(a8, b11, s2);
            s3 = mul_add::<T, FMA>(a9, b12, s3);
            s4 = mul_add::<T, FMA>(a20, b21, s4);
            s7 = mul_add::<T, FMA>(a20, b34, s7);
            s9 = mul_add::<T, FMA>(a20, b36, s9);
            s11 = mul_add::<T, FMA>(a20, b39, s11);
            t2 = mul_add::<T, FMA>(a7, p10, t2);
            t2 = mul_add::<T, FMA>(a8, p11, t2);
            t3 = mul_add::<T, FMA>(a9, p12, t3);
            t4 = mul_add::<T, FMA>(a20, p21, t4);
            t7 = mul_add::<T, FMA>(a20, p34, t7);
            t9 = mul_add::<T, FMA>(a20, p36, t9);
            t11 = mul_add::<T, FMA>(a20, p39, t11);
            (p10, p11, p12, p21, p34, p36, p39) = (b10, b11, b12, b21, b34, b36, b39);
        }
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[7] = s7;
        g[7] = t7;
        h[9] = s9;
        g[9] = t9;
        h[11] = s11;
        g[11] = t11;
        // Histories [12, 13, 15, 18, 19, 20]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s12, mut t12, mut s13, mut t13, mut s15, mut t15, mut s18, mut t18, mut s19, mut t19, mut s20, mut t20) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p34, mut p36, mut p39, mut p43) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a34, b34, a36, b36, a39, b39, b43) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + j), at(c, 39 * s + 4 + k - j), at(c, 43 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b39, s12);
            s12 = mul_add::<T, FMA>(-a2, b36, s12);
            s13 = mul_add::<T, FMA>(a2, b34, s13);
            s13 = mul_add::<T, FMA>(-a0, b39, s13);
            s15 = mul_add::<T, FMA>(a4, b39, s15);
            s15 = mul_add::<T, FMA>(-a5, b36, s15);
            s18 = mul_add::<T, FMA>(a34, b43, s18);
            s19 = mul_add::<T, FMA>(a36, b43, s19);
            s20 = mul_add::<T, FMA>(a39, b43, s20);
            (b34, b36, b39, b43)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a34, b34, a36, b36, a39, b39, b43) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 34 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + j), at(c, 39 * s + 4 + k - j), at(c, 43 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b39, s12);
            s12 = mul_add::<T, FMA>(-a2, b36, s12);
            s13 = mul_add::<T, FMA>(a2, b34, s13);
            s13 = mul_add::<T, FMA>(-a0, b39, s13);
            s15 = mul_add::<T, FMA>(a4, b39, s15);
            s15 = mul_add::<T, FMA>(-a5, b36, s15);
            s18 = mul_add::<T, FMA>(a34, b43, s18);
            s19 = mul_add::<T, FMA>(a36, b43, s19);
            s20 = mul_add::<T, FMA>(a39, b43, s20);
            t12 = mul_add::<T, FMA>(a1, p39, t12);
            t12 = mul_add::<T, FMA>(-a2, p36, t12);
            t13 = mul_add::<T, FMA>(a2, p34, t13);
            t13 = mul_add::<T, FMA>(-a0, p39, t13);
            t15 = mul_add::<T, FMA>(a4, p39, t15);
            t15 = mul_add::<T, FMA>(-a5, p36, t15);
            t18 = mul_add::<T, FMA>(a34, p43, t18);
            t19 = mul_add::<T, FMA>(a36, p43, t19);
            t20 = mul_add::<T, FMA>(a39, p43, t20);
            (p34, p36, p39, p43) = (b34, b36, b39, b43);
        }
        h[12] = s12;
        g[12] = t12;
        h[13] = s13;
        g[13] = t13;
        h[15] = s15;
        g[15] = t15;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        // Histories [14, 16, 17]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s14, mut t14, mut s16, mut t16, mut s17, mut t17) = (zero, zero, zero, zero, zero, zero);
        let (mut p34, mut p36, mut p39) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b34, b36, b39) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b36, s14);
            s14 = mul_add::<T, FMA>(-a1, b34, s14);
            s16 = mul_add::<T, FMA>(a5, b34, s16);
            s16 = mul_add::<T, FMA>(-a3, b39, s16);
            s17 = mul_add::<T, FMA>(a3, b36, s17);
            s17 = mul_add::<T, FMA>(-a4, b34, s17);
            (b34, b36, b39)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b34, b36, b39) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 34 * s + 4 + k - j), at(c, 36 * s + 4 + k - j), at(c, 39 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b36, s14);
            s14 = mul_add::<T, FMA>(-a1, b34, s14);
            s16 = mul_add::<T, FMA>(a5, b34, s16);
            s16 = mul_add::<T, FMA>(-a3, b39, s16);
            s17 = mul_add::<T, FMA>(a3, b36, s17);
            s17 = mul_add::<T, FMA>(-a4, b34, s17);
            t14 = mul_add::<T, FMA>(a0, p36, t14);
            t14 = mul_add::<T, FMA>(-a1, p34, t14);
            t16 = mul_add::<T, FMA>(a5, p34, t16);
            t16 = mul_add::<T, FMA>(-a3, p39, t16);
            t17 = mul_add::<T, FMA>(a3, p36, t17);
            t17 = mul_add::<T, FMA>(-a4, p34, t17);
            (p34, p36, p39) = (b34, b36, b39);
        }
        h[14] = s14;
        g[14] = t14;
        h[16] = s16;
        g[16] = t16;
        h[17] = s17;
        g[17] = t17;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 21 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 21 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = mul_add::<T, FMA>(at(c, 29 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 29 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + 1), at(c, 39 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 20 * s + 4 + k - 1), at(c, 39 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 39 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 39 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 39 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 39 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 39 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 39 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 39 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 39 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = mul_add::<T, FMA>(at(c, 34 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 34 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = mul_add::<T, FMA>(at(c, 36 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 36 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = mul_add::<T, FMA>(at(c, 39 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 39 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), e);
        h[20] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh_general_free`.
#[inline(always)]
fn routh_general_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 21],
    q: &[f64; 18],
) {
    let v7 = c[3 * s + 4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = c[4 * s + 4 + k] * q[1];
    c[8 * s + 4 + k] = v8;
    let v9 = c[5 * s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = c[4 + k] * q[3];
    c[10 * s + 4 + k] = v10;
    let v11 = c[s + 4 + k] * q[4];
    c[11 * s + 4 + k] = v11;
    let v12 = c[2 * s + 4 + k] * q[5];
    c[12 * s + 4 + k] = v12;
    let v13 = v12;
    c[13 * s + 4 + k] = v13;
    let v14 = recurrence::dot_add::<T, FMA>([c[10 * s + 4], v10, c[10 * s + 4], v10], [c[11 * s + 4], v11, c[11 * s + 4], v11], h[0]);
    c[14 * s + 4 + k] = v14;
    let v15 = v14 * q[7];
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[13 * s + 4], v13, c[13 * s + 4], v13, h[1]);
    c[16 * s + 4 + k] = v16;
    let v17 = v16 * q[8];
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::dot_add::<T, FMA>([c[7 * s + 4], v7, c[10 * s + 4], v10], [c[8 * s + 4], v8, c[11 * s + 4], v11], h[2]);
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[9 * s + 4], v9, c[13 * s + 4], v13, h[3]);
    c[19 * s + 4 + k] = v19;
    let v20 = v15 + v17;
    c[20 * s + 4 + k] = v20;
    let v21 = v18 + v19;
    c[21 * s + 4 + k] = v21;
    let v22 = v18 * q[9];
    c[22 * s + 4 + k] = v22;
    let v23 = v19 * q[10];
    c[23 * s + 4 + k] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4 + k] = v24;
    let v25 = recurrence::mul_plus::<T, FMA>(c[20 * s + 4], v20, c[21 * s + 4], v21, v24, h[4]);
    c[25 * s + 4 + k] = v25;
    let v26 = v25 * q[11];
    c[26 * s + 4 + k] = v26;
    let v27 = v15 * q[12];
    c[27 * s + 4 + k] = v27;
    let v28 = v17 * q[13];
    c[28 * s + 4 + k] = v28;
    let v29 = v27 + v28;
    c[29 * s + 4 + k] = v29;
    let v30 = v29;
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v26, c[30 * s + 4], v30, c[31 * s + 4], h[5]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[31 * s + 4], v31, v7, h[6]);
    c[32 * s + 4 + k] = v32;
    let v33 = v20;
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::quotient::<T, FMA>(v32, c[33 * s + 4], v33, c[34 * s + 4], h[7]);
    c[34 * s + 4 + k] = v34;
    let v35 = recurrence::mul_plus::<T, FMA>(c[11 * s + 4], v11, c[31 * s + 4], v31, v8, h[8]);
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::quotient::<T, FMA>(v35, c[33 * s + 4], v33, c[36 * s + 4], h[9]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::mul_plus::<T, FMA>(c[13 * s + 4], v13, c[31 * s + 4], v31, v9, h[10]);
    c[37 * s + 4 + k] = v37;
    let v38 = v20;
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::quotient::<T, FMA>(v37, c[38 * s + 4], v38, c[39 * s + 4], h[11]);
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[39 * s + 4], v39], [c[2 * s + 4], c[2 * s + 4 + k], c[36 * s + 4], v36], h[12]);
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[34 * s + 4], v34], [c[4], c[4 + k], c[39 * s + 4], v39], h[13]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[36 * s + 4], v36], [c[s + 4], c[s + 4 + k], c[34 * s + 4], v34], h[14]);
    c[42 * s + 4 + k] = v42;
    let v43 = v42 * q[17];
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[39 * s + 4], v39], [c[5 * s + 4], c[5 * s + 4 + k], c[36 * s + 4], v36], h[15]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[34 * s + 4], v34], [c[3 * s + 4], c[3 * s + 4 + k], c[39 * s + 4], v39], h[16]);
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[36 * s + 4], v36], [c[4 * s + 4], c[4 * s + 4 + k], c[34 * s + 4], v34], h[17]);
    c[46 * s + 4 + k] = v46;
    let v47 = recurrence::mul_plus::<T, FMA>(c[34 * s + 4], v34, c[43 * s + 4], v43, v44, h[18]);
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::mul_plus::<T, FMA>(c[36 * s + 4], v36, c[43 * s + 4], v43, v45, h[19]);
    c[48 * s + 4 + k] = v48;
    let v49 = recurrence::mul_plus::<T, FMA>(c[39 * s + 4], v39, c[43 * s + 4], v43, v46, h[20]);
    c[49 * s + 4 + k] = v49;
}

/// Order 0 of the kernel `routh_general_free`.
#[inline(always)]
fn routh_general_free_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 18]) {
    let v7 = c[3 * s + 4] * z[0];
    c[7 * s + 4] = v7;
    let v8 = c[4 * s + 4] * z[1];
    c[8 * s + 4] = v8;
    let v9 = c[5 * s + 4] * z[2];
    c[9 * s + 4] = v9;
    let v10 = c[4] * z[3];
    c[10 * s + 4] = v10;
    let v11 = c[s + 4] * z[4];
    c[11 * s + 4] = v11;
    let v12 = c[2 * s + 4] * z[5];
    c[12 * s + 4] = v12;
    let v13 = v12 + z[6];
    c[13 * s + 4] = v13;
    let v14 = v10 * v10 + v11 * v11;
    c[14 * s + 4] = v14;
    let v15 = v14 * z[7];
    c[15 * s + 4] = v15;
    let v16 = v13 * v13;
    c[16 * s + 4] = v16;
    let v17 = v16 * z[8];
    c[17 * s + 4] = v17;
    let v18 = v7 * v10 + v8 * v11;
    c[18 * s + 4] = v18;
    let v19 = v9 * v13;
    c[19 * s + 4] = v19;
    let v20 = v15 + v17;
    c[20 * s + 4] = v20;
    let v21 = v18 + v19;
    c[21 * s + 4] = v21;
    let v22 = v18 * z[9];
    c[22 * s + 4] = v22;
    let v23 = v19 * z[10];
    c[23 * s + 4] = v23;
    let v24 = v22 + v23;
    c[24 * s + 4] = v24;
    let v25 = v20 * v21 + v24;
    c[25 * s + 4] = v25;
    let v26 = v25 * z[11];
    c[26 * s + 4] = v26;
    let v27 = v15 * z[12];
    c[27 * s + 4] = v27;
    let v28 = v17 * z[13];
    c[28 * s + 4] = v28;
    let v29 = v27 + v28;
    c[29 * s + 4] = v29;
    let v30 = v29 + z[14];
    c[30 * s + 4] = v30;
    let v31 = v26 / v30;
    c[31 * s + 4] = v31;
    let v32 = v10 * v31 + v7;
    c[32 * s + 4] = v32;
    let v33 = v20 + z[15];
    c[33 * s + 4] = v33;
    let v34 = v32 / v33;
    c[34 * s + 4] = v34;
    let v35 = v11 * v31 + v8;
    c[35 * s + 4] = v35;
    let v36 = v35 / v33;
    c[36 * s + 4] = v36;
    let v37 = v13 * v31 + v9;
    c[37 * s + 4] = v37;
    let v38 = v20 + z[16];
    c[38 * s + 4] = v38;
    let v39 = v37 / v38;
    c[39 * s + 4] = v39;
    let v40 = c[s + 4] * v39 - c[2 * s + 4] * v36;
    c[40 * s + 4] = v40;
    let v41 = c[2 * s + 4] * v34 - c[4] * v39;
    c[41 * s + 4] = v41;
    let v42 = c[4] * v36 - c[s + 4] * v34;
    c[42 * s + 4] = v42;
    let v43 = v42 * z[17];
    c[43 * s + 4] = v43;
    let v44 = c[4 * s + 4] * v39 - c[5 * s + 4] * v36;
    c[44 * s + 4] = v44;
    let v45 = c[5 * s + 4] * v34 - c[3 * s + 4] * v39;
    c[45 * s + 4] = v45;
    let v46 = c[3 * s + 4] * v36 - c[4 * s + 4] * v34;
    c[46 * s + 4] = v46;
    let v47 = v34 * v43 + v44;
    c[47 * s + 4] = v47;
    let v48 = v36 * v43 + v45;
    c[48 * s + 4] = v48;
    let v49 = v39 * v43 + v46;
    c[49 * s + 4] = v49;
}

/// The pass of order `k >= 1` of the kernel `routh_general_unit`.
#[inline(always)]
fn routh_general_unit<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 21],
    q: &[f64; 18],
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
    let v12 = v11 * q[4];
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[1]);
    c[13 * s + 4 + k] = v13;
    let v14 = v13 * q[5];
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::dot_add::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[7 * s + 4], v7], [c[4 * s + 4], c[4 * s + 4 + k], c[8 * s + 4], v8], h[2]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[10 * s + 4], v10, h[3]);
    c[16 * s + 4 + k] = v16;
    let v17 = v12 + v14;
    c[17 * s + 4 + k] = v17;
    let v18 = v15 + v16;
    c[18 * s + 4 + k] = v18;
    let v19 = v15 * q[6];
    c[19 * s + 4 + k] = v19;
    let v20 = v16 * q[7];
    c[20 * s + 4 + k] = v20;
    let v21 = v19 + v20;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::mul_plus::<T, FMA>(c[17 * s + 4], v17, c[18 * s + 4], v18, v21, h[4]);
    c[22 * s + 4 + k] = v22;
    let v23 = v22 * q[8];
    c[23 * s + 4 + k] = v23;
    let v24 = v12 * q[9];
    c[24 * s + 4 + k] = v24;
    let v25 = v14 * q[10];
    c[25 * s + 4 + k] = v25;
    let v26 = v24 + v25;
    c[26 * s + 4 + k] = v26;
    let v27 = v26;
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::quotient::<T, FMA>(v23, c[27 * s + 4], v27, c[28 * s + 4], h[5]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[28 * s + 4], v28, c[3 * s + 4 + k], h[6]);
    c[29 * s + 4 + k] = v29;
    let v30 = v17;
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v29, c[30 * s + 4], v30, c[31 * s + 4], h[7]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[28 * s + 4], v28, c[4 * s + 4 + k], h[8]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::quotient::<T, FMA>(v32, c[30 * s + 4], v30, c[33 * s + 4], h[9]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[28 * s + 4], v28, c[5 * s + 4 + k], h[10]);
    c[34 * s + 4 + k] = v34;
    let v35 = v17;
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::quotient::<T, FMA>(v34, c[35 * s + 4], v35, c[36 * s + 4], h[11]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[36 * s + 4], v36], [c[2 * s + 4], c[2 * s + 4 + k], c[33 * s + 4], v33], h[12]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[31 * s + 4], v31], [c[4], c[4 + k], c[36 * s + 4], v36], h[13]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[33 * s + 4], v33], [c[s + 4], c[s + 4 + k], c[31 * s + 4], v31], h[14]);
    c[39 * s + 4 + k] = v39;
    let v40 = v39 * q[14];
    c[40 * s + 4 + k] = v40;
    let v41 = c[s + 4 + k] * q[15];
    c[41 * s + 4 + k] = v41;
    let v42 = c[4 + k] * q[16];
    c[42 * s + 4 + k] = v42;
    let v43 = -v42;
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[36 * s + 4], v36], [c[5 * s + 4], c[5 * s + 4 + k], c[33 * s + 4], v33], h[15]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[31 * s + 4], v31], [c[3 * s + 4], c[3 * s + 4 + k], c[36 * s + 4], v36], h[16]);
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[33 * s + 4], v33], [c[4 * s + 4], c[4 * s + 4 + k], c[31 * s + 4], v31], h[17]);
    c[46 * s + 4 + k] = v46;
    let v47 = v41 + v44;
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::mul_plus::<T, FMA>(c[31 * s + 4], v31, c[40 * s + 4], v40, v47, h[18]);
    c[48 * s + 4 + k] = v48;
    let v49 = v43 + v45;
    c[49 * s + 4 + k] = v49;
    let v50 = recurrence::mul_plus::<T, FMA>(c[33 * s + 4], v33, c[40 * s + 4], v40, v49, h[19]);
    c[50 * s + 4 + k] = v50;
    let v51 = recurrence::mul_plus::<T, FMA>(c[36 * s + 4], v36, c[40 * s + 4], v40, v46, h[20]);
    c[51 * s + 4 + k] = v51;
}

/// Order 0 of the kernel `routh_general_unit`.
#[inline(always)]
fn routh_general_unit_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 18]) {
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
    let v12 = v11 * z[4];
    c[12 * s + 4] = v12;
    let v13 = v10 * v10;
    c[13 * s + 4] = v13;
    let v14 = v13 * z[5];
    c[14 * s + 4] = v14;
    let v15 = c[3 * s + 4] * v7 + c[4 * s + 4] * v8;
    c[15 * s + 4] = v15;
    let v16 = c[5 * s + 4] * v10;
    c[16 * s + 4] = v16;
    let v17 = v12 + v14;
    c[17 * s + 4] = v17;
    let v18 = v15 + v16;
    c[18 * s + 4] = v18;
    let v19 = v15 * z[6];
    c[19 * s + 4] = v19;
    let v20 = v16 * z[7];
    c[20 * s + 4] = v20;
    let v21 = v19 + v20;
    c[21 * s + 4] = v21;
    let v22 = v17 * v18 + v21;
    c[22 * s + 4] = v22;
    let v23 = v22 * z[8];
    c[23 * s + 4] = v23;
    let v24 = v12 * z[9];
    c[24 * s + 4] = v24;
    let v25 = v14 * z[10];
    c[25 * s + 4] = v25;
    let v26 = v24 + v25;
    c[26 * s + 4] = v26;
    let v27 = v26 + z[11];
    c[27 * s + 4] = v27;
    let v28 = v23 / v27;
    c[28 * s + 4] = v28;
    let v29 = v7 * v28 + c[3 * s + 4];
    c[29 * s + 4] = v29;
    let v30 = v17 + z[12];
    c[30 * s + 4] = v30;
    let v31 = v29 / v30;
    c[31 * s + 4] = v31;
    let v32 = v8 * v28 + c[4 * s + 4];
    c[32 * s + 4] = v32;
    let v33 = v32 / v30;
    c[33 * s + 4] = v33;
    let v34 = v10 * v28 + c[5 * s + 4];
    c[34 * s + 4] = v34;
    let v35 = v17 + z[13];
    c[35 * s + 4] = v35;
    let v36 = v34 / v35;
    c[36 * s + 4] = v36;
    let v37 = c[s + 4] * v36 - c[2 * s + 4] * v33;
    c[37 * s + 4] = v37;
    let v38 = c[2 * s + 4] * v31 - c[4] * v36;
    c[38 * s + 4] = v38;
    let v39 = c[4] * v33 - c[s + 4] * v31;
    c[39 * s + 4] = v39;
    let v40 = v39 * z[14];
    c[40 * s + 4] = v40;
    let v41 = c[s + 4] * z[15];
    c[41 * s + 4] = v41;
    let v42 = c[4] * z[16];
    c[42 * s + 4] = v42;
    let v43 = T::from_f64(z[17]) - v42;
    c[43 * s + 4] = v43;
    let v44 = c[4 * s + 4] * v36 - c[5 * s + 4] * v33;
    c[44 * s + 4] = v44;
    let v45 = c[5 * s + 4] * v31 - c[3 * s + 4] * v36;
    c[45 * s + 4] = v45;
    let v46 = c[3 * s + 4] * v33 - c[4 * s + 4] * v31;
    c[46 * s + 4] = v46;
    let v47 = v41 + v44;
    c[47 * s + 4] = v47;
    let v48 = v31 * v40 + v47;
    c[48 * s + 4] = v48;
    let v49 = v43 + v45;
    c[49 * s + 4] = v49;
    let v50 = v33 * v40 + v49;
    c[50 * s + 4] = v50;
    let v51 = v36 * v40 + v46;
    c[51 * s + 4] = v51;
}

/// The histories of the kernels `routh_general_unit`, `routh_general_unit_free` at order `k >= 1` ([`Kernels::histories`]).
#[inline(always)]
fn routh_general_unit_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 21],
    g: &mut [T; 21],
) {
    assert!(k + 4 <= s && c.len() >= 41 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 5, 6, 8, 10].
        let (mut s0, mut s1, mut s5, mut s6, mut s8, mut s10) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, b7, a8, b8, a9, b9, a26, b28) = unsafe { (at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 28 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a7, b7, s0);
            s0 = mul_add::<T, FMA>(a8, b8, s0);
            s1 = mul_add::<T, FMA>(a9, b9, s1);
            s5 = mul_add::<T, FMA>(a26, b28, s5);
            s6 = mul_add::<T, FMA>(a7, b28, s6);
            s8 = mul_add::<T, FMA>(a8, b28, s8);
            s10 = mul_add::<T, FMA>(a9, b28, s10);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), s0);
                s1 = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s1);
                s1 = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s1);
                s5 = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s5);
                s5 = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s5);
                s6 = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s6);
                s6 = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s6);
                s8 = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s8);
                s8 = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s8);
                s10 = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s10);
                s10 = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s10);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[5] = s5;
        h[6] = s6;
        h[8] = s8;
        h[10] = s10;
        // Histories [2, 3, 4, 7, 9, 11].
        let (mut s2, mut s3, mut s4, mut s7, mut s9, mut s11) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a5, b7, b8, b9, a17, b18, b31, b33, b36) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + k - j), at(c, 17 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a3, b7, s2);
            s2 = mul_add::<T, FMA>(a4, b8, s2);
            s3 = mul_add::<T, FMA>(a5, b9, s3);
            s4 = mul_add::<T, FMA>(a17, b18, s4);
            s7 = mul_add::<T, FMA>(a17, b31, s7);
            s9 = mul_add::<T, FMA>(a17, b33, s9);
            s11 = mul_add::<T, FMA>(a17, b36, s11);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s2 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), s2);
                s3 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s3);
                s3 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s3);
                s4 = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), s4);
                s4 = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), s4);
                s7 = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s7);
                s7 = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s7);
                s9 = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s9);
                s9 = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s9);
                s11 = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s11);
                s11 = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s11);
            }
        }
        h[2] = s2;
        h[3] = s3;
        h[4] = s4;
        h[7] = s7;
        h[9] = s9;
        h[11] = s11;
        // Histories [12, 13, 15, 18, 19, 20].
        let (mut s12, mut s13, mut s15, mut s18, mut s19, mut s20) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a31, b31, a33, b33, a36, b36, b40) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 36 * s + 4 + k - j), at(c, 40 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b36, s12);
            s12 = mul_add::<T, FMA>(-a2, b33, s12);
            s13 = mul_add::<T, FMA>(a2, b31, s13);
            s13 = mul_add::<T, FMA>(-a0, b36, s13);
            s15 = mul_add::<T, FMA>(a4, b36, s15);
            s15 = mul_add::<T, FMA>(-a5, b33, s15);
            s18 = mul_add::<T, FMA>(a31, b40, s18);
            s19 = mul_add::<T, FMA>(a33, b40, s19);
            s20 = mul_add::<T, FMA>(a36, b40, s20);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s12 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 36 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 36 * s + 4 + 1), s12);
                s12 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s12);
                s13 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 36 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s13);
                s13 = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 36 * s + 4 + 1), s13);
                s15 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s15);
                s15 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s15);
                s18 = mul_add::<T, FMA>(at(c, 31 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(at(c, 31 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), s18);
                s19 = mul_add::<T, FMA>(at(c, 33 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(at(c, 33 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), s19);
                s20 = mul_add::<T, FMA>(at(c, 36 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(at(c, 36 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), s20);
            }
        }
        h[12] = s12;
        h[13] = s13;
        h[15] = s15;
        h[18] = s18;
        h[19] = s19;
        h[20] = s20;
        // Histories [14, 16, 17].
        let (mut s14, mut s16, mut s17) = (zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b31, b33, b36) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b33, s14);
            s14 = mul_add::<T, FMA>(-a1, b31, s14);
            s16 = mul_add::<T, FMA>(a5, b31, s16);
            s16 = mul_add::<T, FMA>(-a3, b36, s16);
            s17 = mul_add::<T, FMA>(a3, b33, s17);
            s17 = mul_add::<T, FMA>(-a4, b31, s17);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s14 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 33 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 31 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 33 * s + 4 + 1), s14);
                s14 = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 31 * s + 4 + 1), s14);
                s16 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), s16);
                s17 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s17);
            }
        }
        h[14] = s14;
        h[16] = s16;
        h[17] = s17;
    } else if even {
        // Histories [0, 1, 5, 6, 8, 10]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s5, mut t5, mut s6, mut t6, mut s8, mut t8, mut s10, mut t10) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p8, mut p9, mut p28) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, b7, a8, b8, a9, b9, a26, b28) = unsafe { (at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 28 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a7, b7, s0);
            s0 = mul_add::<T, FMA>(a8, b8, s0);
            s1 = mul_add::<T, FMA>(a9, b9, s1);
            s5 = mul_add::<T, FMA>(a26, b28, s5);
            s6 = mul_add::<T, FMA>(a7, b28, s6);
            s8 = mul_add::<T, FMA>(a8, b28, s8);
            s10 = mul_add::<T, FMA>(a9, b28, s10);
            (b7, b8, b9, b28)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, b7, a8, b8, a9, b9, a26, b28) = unsafe { (at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 26 * s + 4 + j), at(c, 28 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a7, b7, s0);
            s0 = mul_add::<T, FMA>(a8, b8, s0);
            s1 = mul_add::<T, FMA>(a9, b9, s1);
            s5 = mul_add::<T, FMA>(a26, b28, s5);
            s6 = mul_add::<T, FMA>(a7, b28, s6);
            s8 = mul_add::<T, FMA>(a8, b28, s8);
            s10 = mul_add::<T, FMA>(a9, b28, s10);
            t0 = mul_add::<T, FMA>(a7, p7, t0);
            t0 = mul_add::<T, FMA>(a8, p8, t0);
            t1 = mul_add::<T, FMA>(a9, p9, t1);
            t5 = mul_add::<T, FMA>(a26, p28, t5);
            t6 = mul_add::<T, FMA>(a7, p28, t6);
            t8 = mul_add::<T, FMA>(a8, p28, t8);
            t10 = mul_add::<T, FMA>(a9, p28, t10);
            (p7, p8, p9, p28) = (b7, b8, b9, b28);
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[8] = s8;
        g[8] = t8;
        h[10] = s10;
        g[10] = t10;
        // Histories [2, 3, 4, 7, 9, 11]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s2, mut t2, mut s3, mut t3, mut s4, mut t4, mut s7, mut t7, mut s9, mut t9, mut s11, mut t11) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p8, mut p9, mut p18, mut p31, mut p33, mut p36) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a5, b7, b8, b9, a17, b18, b31, b33, b36) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + k - j), at(c, 17 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a3, b7, s2);
            s2 = mul_add::<T, FMA>(a4, b8, s2);
            s3 = mul_add::<T, FMA>(a5, b9, s3);
            s4 = mul_add::<T, FMA>(a17, b18, s4);
            s7 = mul_add::<T, FMA>(a17, b31, s7);
            s9 = mul_add::<T, FMA>(a17, b33, s9);
            s11 = mul_add::<T, FMA>(a17, b36, s11);
            (b7, b8, b9, b18, b31, b33, b36)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a4, a5, b7, b8, b9, a17, b18, b31, b33, b36) = unsafe { (at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 8 * s + 4 + k - j), at(c, 9 * s + 4 + k - j), at(c, 17 * s + 4 + j), at(c, 18 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a3, b7, s2);
            s2 = mul_add::<T, FMA>(a4, b8, s2);
            s3 = mul_add::<T, FMA>(a5, b9, s3);
            s4 = mul_add::<T, FMA>(a17, b18, s4);
            s7 = mul_add::<T, FMA>(a17, b31, s7);
            s9 = mul_add::<T, FMA>(a17, b33, s9);
            s11 = mul_add::<T, FMA>(a17, b36, s11);
            t2 = mul_add::<T, FMA>(a3, p7, t2);
            t2 = mul_add::<T, FMA>(a4, p8, t2);
            t3 = mul_add::<T, FMA>(a5, p9, t3);
            t4 = mul_add::<T, FMA>(a17, p18, t4);
            t7 = mul_add::<T, FMA>(a17, p31, t7);
            t9 = mul_add::<T, FMA>(a17, p33, t9);
            t11 = mul_add::<T, FMA>(a17, p36, t11);
            (p7, p8, p9, p18, p31, p33, p36) = (b7, b8, b9, b18, b31, b33, b36);
        }
        h[2] = s2;
        g[2] = t2;
        h[3] = s3;
        g[3] = t3;
        h[4] = s4;
        g[4] = t4;
        h[7] = s7;
        g[7] = t7;
        h[9] = s9;
        g[9] = t9;
        h[11] = s11;
        g[11] = t11;
        // Histories [12, 13, 15, 18, 19, 20]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s12, mut t12, mut s13, mut t13, mut s15, mut t15, mut s18, mut t18, mut s19, mut t19, mut s20, mut t20) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p31, mut p33, mut p36, mut p40) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a31, b31, a33, b33, a36, b36, b40) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 36 * s + 4 + k - j), at(c, 40 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b36, s12);
            s12 = mul_add::<T, FMA>(-a2, b33, s12);
            s13 = mul_add::<T, FMA>(a2, b31, s13);
            s13 = mul_add::<T, FMA>(-a0, b36, s13);
            s15 = mul_add::<T, FMA>(a4, b36, s15);
            s15 = mul_add::<T, FMA>(-a5, b33, s15);
            s18 = mul_add::<T, FMA>(a31, b40, s18);
            s19 = mul_add::<T, FMA>(a33, b40, s19);
            s20 = mul_add::<T, FMA>(a36, b40, s20);
            (b31, b33, b36, b40)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a4, a5, a31, b31, a33, b33, a36, b36, b40) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + j), at(c, 36 * s + 4 + k - j), at(c, 40 * s + 4 + k - j)) };
            s12 = mul_add::<T, FMA>(a1, b36, s12);
            s12 = mul_add::<T, FMA>(-a2, b33, s12);
            s13 = mul_add::<T, FMA>(a2, b31, s13);
            s13 = mul_add::<T, FMA>(-a0, b36, s13);
            s15 = mul_add::<T, FMA>(a4, b36, s15);
            s15 = mul_add::<T, FMA>(-a5, b33, s15);
            s18 = mul_add::<T, FMA>(a31, b40, s18);
            s19 = mul_add::<T, FMA>(a33, b40, s19);
            s20 = mul_add::<T, FMA>(a36, b40, s20);
            t12 = mul_add::<T, FMA>(a1, p36, t12);
            t12 = mul_add::<T, FMA>(-a2, p33, t12);
            t13 = mul_add::<T, FMA>(a2, p31, t13);
            t13 = mul_add::<T, FMA>(-a0, p36, t13);
            t15 = mul_add::<T, FMA>(a4, p36, t15);
            t15 = mul_add::<T, FMA>(-a5, p33, t15);
            t18 = mul_add::<T, FMA>(a31, p40, t18);
            t19 = mul_add::<T, FMA>(a33, p40, t19);
            t20 = mul_add::<T, FMA>(a36, p40, t20);
            (p31, p33, p36, p40) = (b31, b33, b36, b40);
        }
        h[12] = s12;
        g[12] = t12;
        h[13] = s13;
        g[13] = t13;
        h[15] = s15;
        g[15] = t15;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        // Histories [14, 16, 17]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s14, mut t14, mut s16, mut t16, mut s17, mut t17) = (zero, zero, zero, zero, zero, zero);
        let (mut p31, mut p33, mut p36) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b31, b33, b36) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b33, s14);
            s14 = mul_add::<T, FMA>(-a1, b31, s14);
            s16 = mul_add::<T, FMA>(a5, b31, s16);
            s16 = mul_add::<T, FMA>(-a3, b36, s16);
            s17 = mul_add::<T, FMA>(a3, b33, s17);
            s17 = mul_add::<T, FMA>(-a4, b31, s17);
            (b31, b33, b36)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a3, a4, a5, b31, b33, b36) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 31 * s + 4 + k - j), at(c, 33 * s + 4 + k - j), at(c, 36 * s + 4 + k - j)) };
            s14 = mul_add::<T, FMA>(a0, b33, s14);
            s14 = mul_add::<T, FMA>(-a1, b31, s14);
            s16 = mul_add::<T, FMA>(a5, b31, s16);
            s16 = mul_add::<T, FMA>(-a3, b36, s16);
            s17 = mul_add::<T, FMA>(a3, b33, s17);
            s17 = mul_add::<T, FMA>(-a4, b31, s17);
            t14 = mul_add::<T, FMA>(a0, p33, t14);
            t14 = mul_add::<T, FMA>(-a1, p31, t14);
            t16 = mul_add::<T, FMA>(a5, p31, t16);
            t16 = mul_add::<T, FMA>(-a3, p36, t16);
            t17 = mul_add::<T, FMA>(a3, p33, t17);
            t17 = mul_add::<T, FMA>(-a4, p31, t17);
            (p31, p33, p36) = (b31, b33, b36);
        }
        h[14] = s14;
        g[14] = t14;
        h[16] = s16;
        g[16] = t16;
        h[17] = s17;
        g[17] = t17;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 8 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 8 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 18 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 18 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 17 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 36 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 36 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = mul_add::<T, FMA>(at(c, 31 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 31 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = mul_add::<T, FMA>(at(c, 33 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 33 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = mul_add::<T, FMA>(at(c, 36 * s + 4 + 1), at(c, 40 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 36 * s + 4 + k - 1), at(c, 40 * s + 4 + 1), e);
        h[20] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `routh_general_unit_free`.
#[inline(always)]
fn routh_general_unit_free<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 21],
    q: &[f64; 15],
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
    let v12 = v11 * q[4];
    c[12 * s + 4 + k] = v12;
    let v13 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[1]);
    c[13 * s + 4 + k] = v13;
    let v14 = v13 * q[5];
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::dot_add::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[7 * s + 4], v7], [c[4 * s + 4], c[4 * s + 4 + k], c[8 * s + 4], v8], h[2]);
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[10 * s + 4], v10, h[3]);
    c[16 * s + 4 + k] = v16;
    let v17 = v12 + v14;
    c[17 * s + 4 + k] = v17;
    let v18 = v15 + v16;
    c[18 * s + 4 + k] = v18;
    let v19 = v15 * q[6];
    c[19 * s + 4 + k] = v19;
    let v20 = v16 * q[7];
    c[20 * s + 4 + k] = v20;
    let v21 = v19 + v20;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::mul_plus::<T, FMA>(c[17 * s + 4], v17, c[18 * s + 4], v18, v21, h[4]);
    c[22 * s + 4 + k] = v22;
    let v23 = v22 * q[8];
    c[23 * s + 4 + k] = v23;
    let v24 = v12 * q[9];
    c[24 * s + 4 + k] = v24;
    let v25 = v14 * q[10];
    c[25 * s + 4 + k] = v25;
    let v26 = v24 + v25;
    c[26 * s + 4 + k] = v26;
    let v27 = v26;
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::quotient::<T, FMA>(v23, c[27 * s + 4], v27, c[28 * s + 4], h[5]);
    c[28 * s + 4 + k] = v28;
    let v29 = recurrence::mul_plus::<T, FMA>(c[7 * s + 4], v7, c[28 * s + 4], v28, c[3 * s + 4 + k], h[6]);
    c[29 * s + 4 + k] = v29;
    let v30 = v17;
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::quotient::<T, FMA>(v29, c[30 * s + 4], v30, c[31 * s + 4], h[7]);
    c[31 * s + 4 + k] = v31;
    let v32 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[28 * s + 4], v28, c[4 * s + 4 + k], h[8]);
    c[32 * s + 4 + k] = v32;
    let v33 = recurrence::quotient::<T, FMA>(v32, c[30 * s + 4], v30, c[33 * s + 4], h[9]);
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[28 * s + 4], v28, c[5 * s + 4 + k], h[10]);
    c[34 * s + 4 + k] = v34;
    let v35 = v17;
    c[35 * s + 4 + k] = v35;
    let v36 = recurrence::quotient::<T, FMA>(v34, c[35 * s + 4], v35, c[36 * s + 4], h[11]);
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[36 * s + 4], v36], [c[2 * s + 4], c[2 * s + 4 + k], c[33 * s + 4], v33], h[12]);
    c[37 * s + 4 + k] = v37;
    let v38 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[31 * s + 4], v31], [c[4], c[4 + k], c[36 * s + 4], v36], h[13]);
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[33 * s + 4], v33], [c[s + 4], c[s + 4 + k], c[31 * s + 4], v31], h[14]);
    c[39 * s + 4 + k] = v39;
    let v40 = v39 * q[14];
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[36 * s + 4], v36], [c[5 * s + 4], c[5 * s + 4 + k], c[33 * s + 4], v33], h[15]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[31 * s + 4], v31], [c[3 * s + 4], c[3 * s + 4 + k], c[36 * s + 4], v36], h[16]);
    c[42 * s + 4 + k] = v42;
    let v43 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[33 * s + 4], v33], [c[4 * s + 4], c[4 * s + 4 + k], c[31 * s + 4], v31], h[17]);
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::mul_plus::<T, FMA>(c[31 * s + 4], v31, c[40 * s + 4], v40, v41, h[18]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::mul_plus::<T, FMA>(c[33 * s + 4], v33, c[40 * s + 4], v40, v42, h[19]);
    c[45 * s + 4 + k] = v45;
    let v46 = recurrence::mul_plus::<T, FMA>(c[36 * s + 4], v36, c[40 * s + 4], v40, v43, h[20]);
    c[46 * s + 4 + k] = v46;
}

/// Order 0 of the kernel `routh_general_unit_free`.
#[inline(always)]
fn routh_general_unit_free_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 15]) {
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
    let v12 = v11 * z[4];
    c[12 * s + 4] = v12;
    let v13 = v10 * v10;
    c[13 * s + 4] = v13;
    let v14 = v13 * z[5];
    c[14 * s + 4] = v14;
    let v15 = c[3 * s + 4] * v7 + c[4 * s + 4] * v8;
    c[15 * s + 4] = v15;
    let v16 = c[5 * s + 4] * v10;
    c[16 * s + 4] = v16;
    let v17 = v12 + v14;
    c[17 * s + 4] = v17;
    let v18 = v15 + v16;
    c[18 * s + 4] = v18;
    let v19 = v15 * z[6];
    c[19 * s + 4] = v19;
    let v20 = v16 * z[7];
    c[20 * s + 4] = v20;
    let v21 = v19 + v20;
    c[21 * s + 4] = v21;
    let v22 = v17 * v18 + v21;
    c[22 * s + 4] = v22;
    let v23 = v22 * z[8];
    c[23 * s + 4] = v23;
    let v24 = v12 * z[9];
    c[24 * s + 4] = v24;
    let v25 = v14 * z[10];
    c[25 * s + 4] = v25;
    let v26 = v24 + v25;
    c[26 * s + 4] = v26;
    let v27 = v26 + z[11];
    c[27 * s + 4] = v27;
    let v28 = v23 / v27;
    c[28 * s + 4] = v28;
    let v29 = v7 * v28 + c[3 * s + 4];
    c[29 * s + 4] = v29;
    let v30 = v17 + z[12];
    c[30 * s + 4] = v30;
    let v31 = v29 / v30;
    c[31 * s + 4] = v31;
    let v32 = v8 * v28 + c[4 * s + 4];
    c[32 * s + 4] = v32;
    let v33 = v32 / v30;
    c[33 * s + 4] = v33;
    let v34 = v10 * v28 + c[5 * s + 4];
    c[34 * s + 4] = v34;
    let v35 = v17 + z[13];
    c[35 * s + 4] = v35;
    let v36 = v34 / v35;
    c[36 * s + 4] = v36;
    let v37 = c[s + 4] * v36 - c[2 * s + 4] * v33;
    c[37 * s + 4] = v37;
    let v38 = c[2 * s + 4] * v31 - c[4] * v36;
    c[38 * s + 4] = v38;
    let v39 = c[4] * v33 - c[s + 4] * v31;
    c[39 * s + 4] = v39;
    let v40 = v39 * z[14];
    c[40 * s + 4] = v40;
    let v41 = c[4 * s + 4] * v36 - c[5 * s + 4] * v33;
    c[41 * s + 4] = v41;
    let v42 = c[5 * s + 4] * v31 - c[3 * s + 4] * v36;
    c[42 * s + 4] = v42;
    let v43 = c[3 * s + 4] * v33 - c[4 * s + 4] * v31;
    c[43 * s + 4] = v43;
    let v44 = v31 * v40 + v41;
    c[44 * s + 4] = v44;
    let v45 = v33 * v40 + v42;
    c[45 * s + 4] = v45;
    let v46 = v36 * v40 + v43;
    c[46 * s + 4] = v46;
}

/// The pass of order `k >= 1` of the kernel `chaplygin`.
#[inline(always)]
fn chaplygin<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 22],
    q: &[f64; 16],
) {
    let v7 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[4], c[4 + k], h[0]);
    c[7 * s + 4 + k] = v7;
    let v8 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[s + 4], c[s + 4 + k], h[1]);
    c[8 * s + 4 + k] = v8;
    let v9 = recurrence::product::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[2 * s + 4], c[2 * s + 4 + k], h[2]);
    c[9 * s + 4 + k] = v9;
    let v10 = recurrence::product::<T, FMA>(c[4], c[4 + k], c[3 * s + 4], c[3 * s + 4 + k], h[3]);
    c[10 * s + 4 + k] = v10;
    let v11 = recurrence::product::<T, FMA>(c[s + 4], c[s + 4 + k], c[4 * s + 4], c[4 * s + 4 + k], h[4]);
    c[11 * s + 4 + k] = v11;
    let v12 = recurrence::product::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[5 * s + 4], c[5 * s + 4 + k], h[5]);
    c[12 * s + 4 + k] = v12;
    let v13 = v7 + v8;
    c[13 * s + 4 + k] = v13;
    let v14 = v9 + v13;
    c[14 * s + 4 + k] = v14;
    let v15 = v10 + v11;
    c[15 * s + 4 + k] = v15;
    let v16 = v12 + v15;
    c[16 * s + 4 + k] = v16;
    let v17 = v10 * q[0];
    c[17 * s + 4 + k] = v17;
    let v18 = v11 * q[1];
    c[18 * s + 4 + k] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4 + k] = v19;
    let v20 = v12 * q[2];
    c[20 * s + 4 + k] = v20;
    let v21 = v19 + v20;
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::mul_plus::<T, FMA>(c[14 * s + 4], v14, c[16 * s + 4], v16, v21, h[6]);
    c[22 * s + 4 + k] = v22;
    let v23 = v10 * q[3];
    c[23 * s + 4 + k] = v23;
    let v24 = v11 * q[4];
    c[24 * s + 4 + k] = v24;
    let v25 = v23 + v24;
    c[25 * s + 4 + k] = v25;
    let v26 = v12 * q[5];
    c[26 * s + 4 + k] = v26;
    let v27 = v25 + v26;
    c[27 * s + 4 + k] = v27;
    let v28 = recurrence::mul_plus::<T, FMA>(c[14 * s + 4], v14, c[22 * s + 4], v22, v27, h[7]);
    c[28 * s + 4 + k] = v28;
    let v29 = v7 * q[6];
    c[29 * s + 4 + k] = v29;
    let v30 = v8 * q[7];
    c[30 * s + 4 + k] = v30;
    let v31 = v29 + v30;
    c[31 * s + 4 + k] = v31;
    let v32 = v9 * q[8];
    c[32 * s + 4 + k] = v32;
    let v33 = v31 + v32;
    c[33 * s + 4 + k] = v33;
    let v34 = v7 * q[9];
    c[34 * s + 4 + k] = v34;
    let v35 = v8 * q[10];
    c[35 * s + 4 + k] = v35;
    let v36 = v34 + v35;
    c[36 * s + 4 + k] = v36;
    let v37 = v9 * q[11];
    c[37 * s + 4 + k] = v37;
    let v38 = v36 + v37;
    c[38 * s + 4 + k] = v38;
    let v39 = recurrence::mul_plus::<T, FMA>(c[14 * s + 4], v14, c[33 * s + 4], v33, v38, h[8]);
    c[39 * s + 4 + k] = v39;
    let v40 = v39;
    c[40 * s + 4 + k] = v40;
    let v41 = recurrence::quotient::<T, FMA>(v28, c[40 * s + 4], v40, c[41 * s + 4], h[9]);
    c[41 * s + 4 + k] = v41;
    let v42 = recurrence::mul_plus::<T, FMA>(c[4], c[4 + k], c[41 * s + 4], v41, c[3 * s + 4 + k], h[10]);
    c[42 * s + 4 + k] = v42;
    let v43 = v14;
    c[43 * s + 4 + k] = v43;
    let v44 = recurrence::quotient::<T, FMA>(v42, c[43 * s + 4], v43, c[44 * s + 4], h[11]);
    c[44 * s + 4 + k] = v44;
    let v45 = recurrence::mul_plus::<T, FMA>(c[s + 4], c[s + 4 + k], c[41 * s + 4], v41, c[4 * s + 4 + k], h[12]);
    c[45 * s + 4 + k] = v45;
    let v46 = v14;
    c[46 * s + 4 + k] = v46;
    let v47 = recurrence::quotient::<T, FMA>(v45, c[46 * s + 4], v46, c[47 * s + 4], h[13]);
    c[47 * s + 4 + k] = v47;
    let v48 = recurrence::mul_plus::<T, FMA>(c[2 * s + 4], c[2 * s + 4 + k], c[41 * s + 4], v41, c[5 * s + 4 + k], h[14]);
    c[48 * s + 4 + k] = v48;
    let v49 = v14;
    c[49 * s + 4 + k] = v49;
    let v50 = recurrence::quotient::<T, FMA>(v48, c[49 * s + 4], v49, c[50 * s + 4], h[15]);
    c[50 * s + 4 + k] = v50;
    let v51 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[50 * s + 4], v50], [c[2 * s + 4], c[2 * s + 4 + k], c[47 * s + 4], v47], h[16]);
    c[51 * s + 4 + k] = v51;
    let v52 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[44 * s + 4], v44], [c[4], c[4 + k], c[50 * s + 4], v50], h[17]);
    c[52 * s + 4 + k] = v52;
    let v53 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[47 * s + 4], v47], [c[s + 4], c[s + 4 + k], c[44 * s + 4], v44], h[18]);
    c[53 * s + 4 + k] = v53;
    let v54 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[50 * s + 4], v50], [c[5 * s + 4], c[5 * s + 4 + k], c[47 * s + 4], v47], h[19]);
    c[54 * s + 4 + k] = v54;
    let v55 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[44 * s + 4], v44], [c[3 * s + 4], c[3 * s + 4 + k], c[50 * s + 4], v50], h[20]);
    c[55 * s + 4 + k] = v55;
    let v56 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[47 * s + 4], v47], [c[4 * s + 4], c[4 * s + 4 + k], c[44 * s + 4], v44], h[21]);
    c[56 * s + 4 + k] = v56;
}

/// Order 0 of the kernel `chaplygin`.
#[inline(always)]
fn chaplygin_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 16]) {
    let v7 = c[4] * c[4];
    c[7 * s + 4] = v7;
    let v8 = c[s + 4] * c[s + 4];
    c[8 * s + 4] = v8;
    let v9 = c[2 * s + 4] * c[2 * s + 4];
    c[9 * s + 4] = v9;
    let v10 = c[4] * c[3 * s + 4];
    c[10 * s + 4] = v10;
    let v11 = c[s + 4] * c[4 * s + 4];
    c[11 * s + 4] = v11;
    let v12 = c[2 * s + 4] * c[5 * s + 4];
    c[12 * s + 4] = v12;
    let v13 = v7 + v8;
    c[13 * s + 4] = v13;
    let v14 = v9 + v13;
    c[14 * s + 4] = v14;
    let v15 = v10 + v11;
    c[15 * s + 4] = v15;
    let v16 = v12 + v15;
    c[16 * s + 4] = v16;
    let v17 = v10 * z[0];
    c[17 * s + 4] = v17;
    let v18 = v11 * z[1];
    c[18 * s + 4] = v18;
    let v19 = v17 + v18;
    c[19 * s + 4] = v19;
    let v20 = v12 * z[2];
    c[20 * s + 4] = v20;
    let v21 = v19 + v20;
    c[21 * s + 4] = v21;
    let v22 = v14 * v16 + v21;
    c[22 * s + 4] = v22;
    let v23 = v10 * z[3];
    c[23 * s + 4] = v23;
    let v24 = v11 * z[4];
    c[24 * s + 4] = v24;
    let v25 = v23 + v24;
    c[25 * s + 4] = v25;
    let v26 = v12 * z[5];
    c[26 * s + 4] = v26;
    let v27 = v25 + v26;
    c[27 * s + 4] = v27;
    let v28 = v14 * v22 + v27;
    c[28 * s + 4] = v28;
    let v29 = v7 * z[6];
    c[29 * s + 4] = v29;
    let v30 = v8 * z[7];
    c[30 * s + 4] = v30;
    let v31 = v29 + v30;
    c[31 * s + 4] = v31;
    let v32 = v9 * z[8];
    c[32 * s + 4] = v32;
    let v33 = v31 + v32;
    c[33 * s + 4] = v33;
    let v34 = v7 * z[9];
    c[34 * s + 4] = v34;
    let v35 = v8 * z[10];
    c[35 * s + 4] = v35;
    let v36 = v34 + v35;
    c[36 * s + 4] = v36;
    let v37 = v9 * z[11];
    c[37 * s + 4] = v37;
    let v38 = v36 + v37;
    c[38 * s + 4] = v38;
    let v39 = v14 * v33 + v38;
    c[39 * s + 4] = v39;
    let v40 = v39 + z[12];
    c[40 * s + 4] = v40;
    let v41 = v28 / v40;
    c[41 * s + 4] = v41;
    let v42 = c[4] * v41 + c[3 * s + 4];
    c[42 * s + 4] = v42;
    let v43 = v14 + z[13];
    c[43 * s + 4] = v43;
    let v44 = v42 / v43;
    c[44 * s + 4] = v44;
    let v45 = c[s + 4] * v41 + c[4 * s + 4];
    c[45 * s + 4] = v45;
    let v46 = v14 + z[14];
    c[46 * s + 4] = v46;
    let v47 = v45 / v46;
    c[47 * s + 4] = v47;
    let v48 = c[2 * s + 4] * v41 + c[5 * s + 4];
    c[48 * s + 4] = v48;
    let v49 = v14 + z[15];
    c[49 * s + 4] = v49;
    let v50 = v48 / v49;
    c[50 * s + 4] = v50;
    let v51 = c[s + 4] * v50 - c[2 * s + 4] * v47;
    c[51 * s + 4] = v51;
    let v52 = c[2 * s + 4] * v44 - c[4] * v50;
    c[52 * s + 4] = v52;
    let v53 = c[4] * v47 - c[s + 4] * v44;
    c[53 * s + 4] = v53;
    let v54 = c[4 * s + 4] * v50 - c[5 * s + 4] * v47;
    c[54 * s + 4] = v54;
    let v55 = c[5 * s + 4] * v44 - c[3 * s + 4] * v50;
    c[55 * s + 4] = v55;
    let v56 = c[3 * s + 4] * v47 - c[4 * s + 4] * v44;
    c[56 * s + 4] = v56;
}

/// The histories of the kernels `chaplygin` at order `k >= 1` ([`Kernels::histories`]).
#[inline(always)]
fn chaplygin_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 22],
    g: &mut [T; 22],
) {
    assert!(k + 4 <= s && c.len() >= 51 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 1, 3, 9, 10, 12].
        let (mut s0, mut s1, mut s3, mut s9, mut s10, mut s12) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, b3, a39, b41) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 3 * s + 4 + k - j), at(c, 39 * s + 4 + j), at(c, 41 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a0, b0, s0);
            s1 = mul_add::<T, FMA>(a1, b1, s1);
            s3 = mul_add::<T, FMA>(a0, b3, s3);
            s9 = mul_add::<T, FMA>(a39, b41, s9);
            s10 = mul_add::<T, FMA>(a0, b41, s10);
            s12 = mul_add::<T, FMA>(a1, b41, s12);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), s0);
                s1 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), s1);
                s1 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), s1);
                s3 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), s3);
                s3 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), s3);
                s9 = mul_add::<T, FMA>(at(c, 39 * s + 4 + 1), at(c, 41 * s + 4 + k - 1), s9);
                s9 = mul_add::<T, FMA>(at(c, 39 * s + 4 + k - 1), at(c, 41 * s + 4 + 1), s9);
                s10 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 41 * s + 4 + k - 1), s10);
                s10 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 41 * s + 4 + 1), s10);
                s12 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 41 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 41 * s + 4 + 1), s12);
            }
        }
        h[0] = s0;
        h[1] = s1;
        h[3] = s3;
        h[9] = s9;
        h[10] = s10;
        h[12] = s12;
        // Histories [2, 4, 5, 6, 7, 14].
        let (mut s2, mut s4, mut s5, mut s6, mut s7, mut s14) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, b2, b4, b5, a14, b16, b22, b41) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 41 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a2, b2, s2);
            s4 = mul_add::<T, FMA>(a1, b4, s4);
            s5 = mul_add::<T, FMA>(a2, b5, s5);
            s6 = mul_add::<T, FMA>(a14, b16, s6);
            s7 = mul_add::<T, FMA>(a14, b22, s7);
            s14 = mul_add::<T, FMA>(a2, b41, s14);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s2 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), s2);
                s4 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), s4);
                s4 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), s4);
                s5 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 5 * s + 4 + k - 1), s5);
                s5 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 5 * s + 4 + 1), s5);
                s6 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 16 * s + 4 + k - 1), s6);
                s6 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 16 * s + 4 + 1), s6);
                s7 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), s7);
                s7 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), s7);
                s14 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 41 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 41 * s + 4 + 1), s14);
            }
        }
        h[2] = s2;
        h[4] = s4;
        h[5] = s5;
        h[6] = s6;
        h[7] = s7;
        h[14] = s14;
        // Histories [8, 11, 13, 15, 16, 19].
        let (mut s8, mut s11, mut s13, mut s15, mut s16, mut s19) = (zero, zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a4, a5, a14, b33, b44, b47, b50) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 14 * s + 4 + j), at(c, 33 * s + 4 + k - j), at(c, 44 * s + 4 + k - j), at(c, 47 * s + 4 + k - j), at(c, 50 * s + 4 + k - j)) };
            s8 = mul_add::<T, FMA>(a14, b33, s8);
            s11 = mul_add::<T, FMA>(a14, b44, s11);
            s13 = mul_add::<T, FMA>(a14, b47, s13);
            s15 = mul_add::<T, FMA>(a14, b50, s15);
            s16 = mul_add::<T, FMA>(a1, b50, s16);
            s16 = mul_add::<T, FMA>(-a2, b47, s16);
            s19 = mul_add::<T, FMA>(a4, b50, s19);
            s19 = mul_add::<T, FMA>(-a5, b47, s19);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s8 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), s8);
                s8 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), s8);
                s11 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), s11);
                s11 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), s11);
                s13 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), s13);
                s15 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 50 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 50 * s + 4 + 1), s15);
                s16 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 50 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 50 * s + 4 + 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), s16);
                s19 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 50 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 50 * s + 4 + 1), s19);
                s19 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), s19);
            }
        }
        h[8] = s8;
        h[11] = s11;
        h[13] = s13;
        h[15] = s15;
        h[16] = s16;
        h[19] = s19;
        // Histories [17, 18, 20, 21].
        let (mut s17, mut s18, mut s20, mut s21) = (zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b44, b47, b50) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 44 * s + 4 + k - j), at(c, 47 * s + 4 + k - j), at(c, 50 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b44, s17);
            s17 = mul_add::<T, FMA>(-a0, b50, s17);
            s18 = mul_add::<T, FMA>(a0, b47, s18);
            s18 = mul_add::<T, FMA>(-a1, b44, s18);
            s20 = mul_add::<T, FMA>(a5, b44, s20);
            s20 = mul_add::<T, FMA>(-a3, b50, s20);
            s21 = mul_add::<T, FMA>(a3, b47, s21);
            s21 = mul_add::<T, FMA>(-a4, b44, s21);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s17 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 50 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 50 * s + 4 + 1), s17);
                s18 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 47 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 44 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 47 * s + 4 + 1), s18);
                s18 = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 44 * s + 4 + 1), s18);
                s20 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 50 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), s20);
                s20 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 50 * s + 4 + 1), s20);
                s21 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), s21);
                s21 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), s21);
                s21 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), s21);
                s21 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), s21);
            }
        }
        h[17] = s17;
        h[18] = s18;
        h[20] = s20;
        h[21] = s21;
    } else if even {
        // Histories [0, 1, 3, 9, 10, 12]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s1, mut t1, mut s3, mut t3, mut s9, mut t9, mut s10, mut t10, mut s12, mut t12) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p0, mut p1, mut p3, mut p41) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, b3, a39, b41) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 3 * s + 4 + k - j), at(c, 39 * s + 4 + j), at(c, 41 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a0, b0, s0);
            s1 = mul_add::<T, FMA>(a1, b1, s1);
            s3 = mul_add::<T, FMA>(a0, b3, s3);
            s9 = mul_add::<T, FMA>(a39, b41, s9);
            s10 = mul_add::<T, FMA>(a0, b41, s10);
            s12 = mul_add::<T, FMA>(a1, b41, s12);
            (b0, b1, b3, b41)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, b0, a1, b1, b3, a39, b41) = unsafe { (at(c, 4 + j), at(c, 4 + k - j), at(c, s + 4 + j), at(c, s + 4 + k - j), at(c, 3 * s + 4 + k - j), at(c, 39 * s + 4 + j), at(c, 41 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a0, b0, s0);
            s1 = mul_add::<T, FMA>(a1, b1, s1);
            s3 = mul_add::<T, FMA>(a0, b3, s3);
            s9 = mul_add::<T, FMA>(a39, b41, s9);
            s10 = mul_add::<T, FMA>(a0, b41, s10);
            s12 = mul_add::<T, FMA>(a1, b41, s12);
            t0 = mul_add::<T, FMA>(a0, p0, t0);
            t1 = mul_add::<T, FMA>(a1, p1, t1);
            t3 = mul_add::<T, FMA>(a0, p3, t3);
            t9 = mul_add::<T, FMA>(a39, p41, t9);
            t10 = mul_add::<T, FMA>(a0, p41, t10);
            t12 = mul_add::<T, FMA>(a1, p41, t12);
            (p0, p1, p3, p41) = (b0, b1, b3, b41);
        }
        h[0] = s0;
        g[0] = t0;
        h[1] = s1;
        g[1] = t1;
        h[3] = s3;
        g[3] = t3;
        h[9] = s9;
        g[9] = t9;
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        // Histories [2, 4, 5, 6, 7, 14]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s2, mut t2, mut s4, mut t4, mut s5, mut t5, mut s6, mut t6, mut s7, mut t7, mut s14, mut t14) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p2, mut p4, mut p5, mut p16, mut p22, mut p41) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, b2, b4, b5, a14, b16, b22, b41) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 41 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a2, b2, s2);
            s4 = mul_add::<T, FMA>(a1, b4, s4);
            s5 = mul_add::<T, FMA>(a2, b5, s5);
            s6 = mul_add::<T, FMA>(a14, b16, s6);
            s7 = mul_add::<T, FMA>(a14, b22, s7);
            s14 = mul_add::<T, FMA>(a2, b41, s14);
            (b2, b4, b5, b16, b22, b41)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, b2, b4, b5, a14, b16, b22, b41) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 2 * s + 4 + k - j), at(c, 4 * s + 4 + k - j), at(c, 5 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 16 * s + 4 + k - j), at(c, 22 * s + 4 + k - j), at(c, 41 * s + 4 + k - j)) };
            s2 = mul_add::<T, FMA>(a2, b2, s2);
            s4 = mul_add::<T, FMA>(a1, b4, s4);
            s5 = mul_add::<T, FMA>(a2, b5, s5);
            s6 = mul_add::<T, FMA>(a14, b16, s6);
            s7 = mul_add::<T, FMA>(a14, b22, s7);
            s14 = mul_add::<T, FMA>(a2, b41, s14);
            t2 = mul_add::<T, FMA>(a2, p2, t2);
            t4 = mul_add::<T, FMA>(a1, p4, t4);
            t5 = mul_add::<T, FMA>(a2, p5, t5);
            t6 = mul_add::<T, FMA>(a14, p16, t6);
            t7 = mul_add::<T, FMA>(a14, p22, t7);
            t14 = mul_add::<T, FMA>(a2, p41, t14);
            (p2, p4, p5, p16, p22, p41) = (b2, b4, b5, b16, b22, b41);
        }
        h[2] = s2;
        g[2] = t2;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[14] = s14;
        g[14] = t14;
        // Histories [8, 11, 13, 15, 16, 19]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s8, mut t8, mut s11, mut t11, mut s13, mut t13, mut s15, mut t15, mut s16, mut t16, mut s19, mut t19) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p33, mut p44, mut p47, mut p50) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a4, a5, a14, b33, b44, b47, b50) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 14 * s + 4 + j), at(c, 33 * s + 4 + k - j), at(c, 44 * s + 4 + k - j), at(c, 47 * s + 4 + k - j), at(c, 50 * s + 4 + k - j)) };
            s8 = mul_add::<T, FMA>(a14, b33, s8);
            s11 = mul_add::<T, FMA>(a14, b44, s11);
            s13 = mul_add::<T, FMA>(a14, b47, s13);
            s15 = mul_add::<T, FMA>(a14, b50, s15);
            s16 = mul_add::<T, FMA>(a1, b50, s16);
            s16 = mul_add::<T, FMA>(-a2, b47, s16);
            s19 = mul_add::<T, FMA>(a4, b50, s19);
            s19 = mul_add::<T, FMA>(-a5, b47, s19);
            (b33, b44, b47, b50)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a4, a5, a14, b33, b44, b47, b50) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 14 * s + 4 + j), at(c, 33 * s + 4 + k - j), at(c, 44 * s + 4 + k - j), at(c, 47 * s + 4 + k - j), at(c, 50 * s + 4 + k - j)) };
            s8 = mul_add::<T, FMA>(a14, b33, s8);
            s11 = mul_add::<T, FMA>(a14, b44, s11);
            s13 = mul_add::<T, FMA>(a14, b47, s13);
            s15 = mul_add::<T, FMA>(a14, b50, s15);
            s16 = mul_add::<T, FMA>(a1, b50, s16);
            s16 = mul_add::<T, FMA>(-a2, b47, s16);
            s19 = mul_add::<T, FMA>(a4, b50, s19);
            s19 = mul_add::<T, FMA>(-a5, b47, s19);
            t8 = mul_add::<T, FMA>(a14, p33, t8);
            t11 = mul_add::<T, FMA>(a14, p44, t11);
            t13 = mul_add::<T, FMA>(a14, p47, t13);
            t15 = mul_add::<T, FMA>(a14, p50, t15);
            t16 = mul_add::<T, FMA>(a1, p50, t16);
            t16 = mul_add::<T, FMA>(-a2, p47, t16);
            t19 = mul_add::<T, FMA>(a4, p50, t19);
            t19 = mul_add::<T, FMA>(-a5, p47, t19);
            (p33, p44, p47, p50) = (b33, b44, b47, b50);
        }
        h[8] = s8;
        g[8] = t8;
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[19] = s19;
        g[19] = t19;
        // Histories [17, 18, 20, 21]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s17, mut t17, mut s18, mut t18, mut s20, mut t20, mut s21, mut t21) = (zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p44, mut p47, mut p50) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b44, b47, b50) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 44 * s + 4 + k - j), at(c, 47 * s + 4 + k - j), at(c, 50 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b44, s17);
            s17 = mul_add::<T, FMA>(-a0, b50, s17);
            s18 = mul_add::<T, FMA>(a0, b47, s18);
            s18 = mul_add::<T, FMA>(-a1, b44, s18);
            s20 = mul_add::<T, FMA>(a5, b44, s20);
            s20 = mul_add::<T, FMA>(-a3, b50, s20);
            s21 = mul_add::<T, FMA>(a3, b47, s21);
            s21 = mul_add::<T, FMA>(-a4, b44, s21);
            (b44, b47, b50)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b44, b47, b50) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 44 * s + 4 + k - j), at(c, 47 * s + 4 + k - j), at(c, 50 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b44, s17);
            s17 = mul_add::<T, FMA>(-a0, b50, s17);
            s18 = mul_add::<T, FMA>(a0, b47, s18);
            s18 = mul_add::<T, FMA>(-a1, b44, s18);
            s20 = mul_add::<T, FMA>(a5, b44, s20);
            s20 = mul_add::<T, FMA>(-a3, b50, s20);
            s21 = mul_add::<T, FMA>(a3, b47, s21);
            s21 = mul_add::<T, FMA>(-a4, b44, s21);
            t17 = mul_add::<T, FMA>(a2, p44, t17);
            t17 = mul_add::<T, FMA>(-a0, p50, t17);
            t18 = mul_add::<T, FMA>(a0, p47, t18);
            t18 = mul_add::<T, FMA>(-a1, p44, t18);
            t20 = mul_add::<T, FMA>(a5, p44, t20);
            t20 = mul_add::<T, FMA>(-a3, p50, t20);
            t21 = mul_add::<T, FMA>(a3, p47, t21);
            t21 = mul_add::<T, FMA>(-a4, p44, t21);
            (p44, p47, p50) = (b44, b47, b50);
        }
        h[17] = s17;
        g[17] = t17;
        h[18] = s18;
        g[18] = t18;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 2 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 2 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 3 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 3 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 4 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 4 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 5 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 5 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 16 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 16 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 22 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 22 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 33 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 33 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = mul_add::<T, FMA>(at(c, 39 * s + 4 + 1), at(c, 41 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 39 * s + 4 + k - 1), at(c, 41 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 41 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 41 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 41 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 41 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 41 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 41 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 50 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 50 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 50 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 50 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 50 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 50 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 47 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 47 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 50 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 50 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 50 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 50 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 47 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 44 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 47 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 44 * s + 4 + 1), e);
        h[21] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `ball`.
#[inline(always)]
fn ball<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 25],
    q: &[f64; 38],
) {
    let v7 = c[3 * s + 4 + k] * q[0];
    c[7 * s + 4 + k] = v7;
    let v8 = c[4 * s + 4 + k] * q[1];
    c[8 * s + 4 + k] = v8;
    let v9 = c[5 * s + 4 + k] * q[2];
    c[9 * s + 4 + k] = v9;
    let v10 = c[4 + k] * q[3];
    c[10 * s + 4 + k] = v10;
    let v11 = v10;
    c[11 * s + 4 + k] = v11;
    let v12 = c[s + 4 + k] * q[5];
    c[12 * s + 4 + k] = v12;
    let v13 = v12;
    c[13 * s + 4 + k] = v13;
    let v14 = c[2 * s + 4 + k] * q[7];
    c[14 * s + 4 + k] = v14;
    let v15 = v14;
    c[15 * s + 4 + k] = v15;
    let v16 = recurrence::product::<T, FMA>(c[11 * s + 4], v11, c[11 * s + 4], v11, h[0]);
    c[16 * s + 4 + k] = v16;
    let v17 = v16 * q[9];
    c[17 * s + 4 + k] = v17;
    let v18 = recurrence::product::<T, FMA>(c[13 * s + 4], v13, c[13 * s + 4], v13, h[1]);
    c[18 * s + 4 + k] = v18;
    let v19 = v18 * q[10];
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[15 * s + 4], v15, c[15 * s + 4], v15, h[2]);
    c[20 * s + 4 + k] = v20;
    let v21 = v20 * q[11];
    c[21 * s + 4 + k] = v21;
    let v22 = recurrence::product::<T, FMA>(c[7 * s + 4], v7, c[11 * s + 4], v11, h[3]);
    c[22 * s + 4 + k] = v22;
    let v23 = recurrence::product::<T, FMA>(c[8 * s + 4], v8, c[13 * s + 4], v13, h[4]);
    c[23 * s + 4 + k] = v23;
    let v24 = recurrence::product::<T, FMA>(c[9 * s + 4], v9, c[15 * s + 4], v15, h[5]);
    c[24 * s + 4 + k] = v24;
    let v25 = v17 + v19;
    c[25 * s + 4 + k] = v25;
    let v26 = v21 + v25;
    c[26 * s + 4 + k] = v26;
    let v27 = v22 + v23;
    c[27 * s + 4 + k] = v27;
    let v28 = v24 + v27;
    c[28 * s + 4 + k] = v28;
    let v29 = v22 * q[12];
    c[29 * s + 4 + k] = v29;
    let v30 = v23 * q[13];
    c[30 * s + 4 + k] = v30;
    let v31 = v29 + v30;
    c[31 * s + 4 + k] = v31;
    let v32 = v24 * q[14];
    c[32 * s + 4 + k] = v32;
    let v33 = v31 + v32;
    c[33 * s + 4 + k] = v33;
    let v34 = recurrence::mul_plus::<T, FMA>(c[26 * s + 4], v26, c[28 * s + 4], v28, v33, h[6]);
    c[34 * s + 4 + k] = v34;
    let v35 = v22 * q[15];
    c[35 * s + 4 + k] = v35;
    let v36 = v23 * q[16];
    c[36 * s + 4 + k] = v36;
    let v37 = v35 + v36;
    c[37 * s + 4 + k] = v37;
    let v38 = v24 * q[17];
    c[38 * s + 4 + k] = v38;
    let v39 = v37 + v38;
    c[39 * s + 4 + k] = v39;
    let v40 = recurrence::mul_plus::<T, FMA>(c[26 * s + 4], v26, c[34 * s + 4], v34, v39, h[7]);
    c[40 * s + 4 + k] = v40;
    let v41 = v40 * q[18];
    c[41 * s + 4 + k] = v41;
    let v42 = v17 * q[19];
    c[42 * s + 4 + k] = v42;
    let v43 = v19 * q[20];
    c[43 * s + 4 + k] = v43;
    let v44 = v42 + v43;
    c[44 * s + 4 + k] = v44;
    let v45 = v21 * q[21];
    c[45 * s + 4 + k] = v45;
    let v46 = v44 + v45;
    c[46 * s + 4 + k] = v46;
    let v47 = v17 * q[22];
    c[47 * s + 4 + k] = v47;
    let v48 = v19 * q[23];
    c[48 * s + 4 + k] = v48;
    let v49 = v47 + v48;
    c[49 * s + 4 + k] = v49;
    let v50 = v21 * q[24];
    c[50 * s + 4 + k] = v50;
    let v51 = v49 + v50;
    c[51 * s + 4 + k] = v51;
    let v52 = recurrence::mul_plus::<T, FMA>(c[26 * s + 4], v26, c[46 * s + 4], v46, v51, h[8]);
    c[52 * s + 4 + k] = v52;
    let v53 = v52;
    c[53 * s + 4 + k] = v53;
    let v54 = recurrence::quotient::<T, FMA>(v41, c[53 * s + 4], v53, c[54 * s + 4], h[9]);
    c[54 * s + 4 + k] = v54;
    let v55 = recurrence::mul_plus::<T, FMA>(c[11 * s + 4], v11, c[54 * s + 4], v54, v7, h[10]);
    c[55 * s + 4 + k] = v55;
    let v56 = v26;
    c[56 * s + 4 + k] = v56;
    let v57 = recurrence::quotient::<T, FMA>(v55, c[56 * s + 4], v56, c[57 * s + 4], h[11]);
    c[57 * s + 4 + k] = v57;
    let v58 = recurrence::mul_plus::<T, FMA>(c[13 * s + 4], v13, c[54 * s + 4], v54, v8, h[12]);
    c[58 * s + 4 + k] = v58;
    let v59 = v26;
    c[59 * s + 4 + k] = v59;
    let v60 = recurrence::quotient::<T, FMA>(v58, c[59 * s + 4], v59, c[60 * s + 4], h[13]);
    c[60 * s + 4 + k] = v60;
    let v61 = recurrence::mul_plus::<T, FMA>(c[15 * s + 4], v15, c[54 * s + 4], v54, v9, h[14]);
    c[61 * s + 4 + k] = v61;
    let v62 = v26;
    c[62 * s + 4 + k] = v62;
    let v63 = recurrence::quotient::<T, FMA>(v61, c[62 * s + 4], v62, c[63 * s + 4], h[15]);
    c[63 * s + 4 + k] = v63;
    let v64 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[63 * s + 4], v63], [c[2 * s + 4], c[2 * s + 4 + k], c[60 * s + 4], v60], h[16]);
    c[64 * s + 4 + k] = v64;
    let v65 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[57 * s + 4], v57], [c[4], c[4 + k], c[63 * s + 4], v63], h[17]);
    c[65 * s + 4 + k] = v65;
    let v66 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[60 * s + 4], v60], [c[s + 4], c[s + 4 + k], c[57 * s + 4], v57], h[18]);
    c[66 * s + 4 + k] = v66;
    let v67 = v64 * q[29];
    c[67 * s + 4 + k] = v67;
    let v68 = v65 * q[30];
    c[68 * s + 4 + k] = v68;
    let v69 = v67 + v68;
    c[69 * s + 4 + k] = v69;
    let v70 = v66 * q[31];
    c[70 * s + 4 + k] = v70;
    let v71 = v69 + v70;
    c[71 * s + 4 + k] = v71;
    let v72 = c[s + 4 + k] * q[32];
    c[72 * s + 4 + k] = v72;
    let v73 = c[2 * s + 4 + k] * q[33];
    c[73 * s + 4 + k] = v73;
    let v74 = v72 - v73;
    c[74 * s + 4 + k] = v74;
    let v75 = c[2 * s + 4 + k] * q[34];
    c[75 * s + 4 + k] = v75;
    let v76 = c[4 + k] * q[35];
    c[76 * s + 4 + k] = v76;
    let v77 = v75 - v76;
    c[77 * s + 4 + k] = v77;
    let v78 = c[4 + k] * q[36];
    c[78 * s + 4 + k] = v78;
    let v79 = c[s + 4 + k] * q[37];
    c[79 * s + 4 + k] = v79;
    let v80 = v78 - v79;
    c[80 * s + 4 + k] = v80;
    let v81 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[63 * s + 4], v63], [c[5 * s + 4], c[5 * s + 4 + k], c[60 * s + 4], v60], h[19]);
    c[81 * s + 4 + k] = v81;
    let v82 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[57 * s + 4], v57], [c[3 * s + 4], c[3 * s + 4 + k], c[63 * s + 4], v63], h[20]);
    c[82 * s + 4 + k] = v82;
    let v83 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[60 * s + 4], v60], [c[4 * s + 4], c[4 * s + 4 + k], c[57 * s + 4], v57], h[21]);
    c[83 * s + 4 + k] = v83;
    let v84 = v74 + v81;
    c[84 * s + 4 + k] = v84;
    let v85 = recurrence::mul_plus::<T, FMA>(c[57 * s + 4], v57, c[71 * s + 4], v71, v84, h[22]);
    c[85 * s + 4 + k] = v85;
    let v86 = v77 + v82;
    c[86 * s + 4 + k] = v86;
    let v87 = recurrence::mul_plus::<T, FMA>(c[60 * s + 4], v60, c[71 * s + 4], v71, v86, h[23]);
    c[87 * s + 4 + k] = v87;
    let v88 = v80 + v83;
    c[88 * s + 4 + k] = v88;
    let v89 = recurrence::mul_plus::<T, FMA>(c[63 * s + 4], v63, c[71 * s + 4], v71, v88, h[24]);
    c[89 * s + 4 + k] = v89;
}

/// Order 0 of the kernel `ball`.
#[inline(always)]
fn ball_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 38]) {
    let v7 = c[3 * s + 4] * z[0];
    c[7 * s + 4] = v7;
    let v8 = c[4 * s + 4] * z[1];
    c[8 * s + 4] = v8;
    let v9 = c[5 * s + 4] * z[2];
    c[9 * s + 4] = v9;
    let v10 = c[4] * z[3];
    c[10 * s + 4] = v10;
    let v11 = v10 + z[4];
    c[11 * s + 4] = v11;
    let v12 = c[s + 4] * z[5];
    c[12 * s + 4] = v12;
    let v13 = v12 + z[6];
    c[13 * s + 4] = v13;
    let v14 = c[2 * s + 4] * z[7];
    c[14 * s + 4] = v14;
    let v15 = v14 + z[8];
    c[15 * s + 4] = v15;
    let v16 = v11 * v11;
    c[16 * s + 4] = v16;
    let v17 = v16 * z[9];
    c[17 * s + 4] = v17;
    let v18 = v13 * v13;
    c[18 * s + 4] = v18;
    let v19 = v18 * z[10];
    c[19 * s + 4] = v19;
    let v20 = v15 * v15;
    c[20 * s + 4] = v20;
    let v21 = v20 * z[11];
    c[21 * s + 4] = v21;
    let v22 = v7 * v11;
    c[22 * s + 4] = v22;
    let v23 = v8 * v13;
    c[23 * s + 4] = v23;
    let v24 = v9 * v15;
    c[24 * s + 4] = v24;
    let v25 = v17 + v19;
    c[25 * s + 4] = v25;
    let v26 = v21 + v25;
    c[26 * s + 4] = v26;
    let v27 = v22 + v23;
    c[27 * s + 4] = v27;
    let v28 = v24 + v27;
    c[28 * s + 4] = v28;
    let v29 = v22 * z[12];
    c[29 * s + 4] = v29;
    let v30 = v23 * z[13];
    c[30 * s + 4] = v30;
    let v31 = v29 + v30;
    c[31 * s + 4] = v31;
    let v32 = v24 * z[14];
    c[32 * s + 4] = v32;
    let v33 = v31 + v32;
    c[33 * s + 4] = v33;
    let v34 = v26 * v28 + v33;
    c[34 * s + 4] = v34;
    let v35 = v22 * z[15];
    c[35 * s + 4] = v35;
    let v36 = v23 * z[16];
    c[36 * s + 4] = v36;
    let v37 = v35 + v36;
    c[37 * s + 4] = v37;
    let v38 = v24 * z[17];
    c[38 * s + 4] = v38;
    let v39 = v37 + v38;
    c[39 * s + 4] = v39;
    let v40 = v26 * v34 + v39;
    c[40 * s + 4] = v40;
    let v41 = v40 * z[18];
    c[41 * s + 4] = v41;
    let v42 = v17 * z[19];
    c[42 * s + 4] = v42;
    let v43 = v19 * z[20];
    c[43 * s + 4] = v43;
    let v44 = v42 + v43;
    c[44 * s + 4] = v44;
    let v45 = v21 * z[21];
    c[45 * s + 4] = v45;
    let v46 = v44 + v45;
    c[46 * s + 4] = v46;
    let v47 = v17 * z[22];
    c[47 * s + 4] = v47;
    let v48 = v19 * z[23];
    c[48 * s + 4] = v48;
    let v49 = v47 + v48;
    c[49 * s + 4] = v49;
    let v50 = v21 * z[24];
    c[50 * s + 4] = v50;
    let v51 = v49 + v50;
    c[51 * s + 4] = v51;
    let v52 = v26 * v46 + v51;
    c[52 * s + 4] = v52;
    let v53 = v52 + z[25];
    c[53 * s + 4] = v53;
    let v54 = v41 / v53;
    c[54 * s + 4] = v54;
    let v55 = v11 * v54 + v7;
    c[55 * s + 4] = v55;
    let v56 = v26 + z[26];
    c[56 * s + 4] = v56;
    let v57 = v55 / v56;
    c[57 * s + 4] = v57;
    let v58 = v13 * v54 + v8;
    c[58 * s + 4] = v58;
    let v59 = v26 + z[27];
    c[59 * s + 4] = v59;
    let v60 = v58 / v59;
    c[60 * s + 4] = v60;
    let v61 = v15 * v54 + v9;
    c[61 * s + 4] = v61;
    let v62 = v26 + z[28];
    c[62 * s + 4] = v62;
    let v63 = v61 / v62;
    c[63 * s + 4] = v63;
    let v64 = c[s + 4] * v63 - c[2 * s + 4] * v60;
    c[64 * s + 4] = v64;
    let v65 = c[2 * s + 4] * v57 - c[4] * v63;
    c[65 * s + 4] = v65;
    let v66 = c[4] * v60 - c[s + 4] * v57;
    c[66 * s + 4] = v66;
    let v67 = v64 * z[29];
    c[67 * s + 4] = v67;
    let v68 = v65 * z[30];
    c[68 * s + 4] = v68;
    let v69 = v67 + v68;
    c[69 * s + 4] = v69;
    let v70 = v66 * z[31];
    c[70 * s + 4] = v70;
    let v71 = v69 + v70;
    c[71 * s + 4] = v71;
    let v72 = c[s + 4] * z[32];
    c[72 * s + 4] = v72;
    let v73 = c[2 * s + 4] * z[33];
    c[73 * s + 4] = v73;
    let v74 = v72 - v73;
    c[74 * s + 4] = v74;
    let v75 = c[2 * s + 4] * z[34];
    c[75 * s + 4] = v75;
    let v76 = c[4] * z[35];
    c[76 * s + 4] = v76;
    let v77 = v75 - v76;
    c[77 * s + 4] = v77;
    let v78 = c[4] * z[36];
    c[78 * s + 4] = v78;
    let v79 = c[s + 4] * z[37];
    c[79 * s + 4] = v79;
    let v80 = v78 - v79;
    c[80 * s + 4] = v80;
    let v81 = c[4 * s + 4] * v63 - c[5 * s + 4] * v60;
    c[81 * s + 4] = v81;
    let v82 = c[5 * s + 4] * v57 - c[3 * s + 4] * v63;
    c[82 * s + 4] = v82;
    let v83 = c[3 * s + 4] * v60 - c[4 * s + 4] * v57;
    c[83 * s + 4] = v83;
    let v84 = v74 + v81;
    c[84 * s + 4] = v84;
    let v85 = v57 * v71 + v84;
    c[85 * s + 4] = v85;
    let v86 = v77 + v82;
    c[86 * s + 4] = v86;
    let v87 = v60 * v71 + v86;
    c[87 * s + 4] = v87;
    let v88 = v80 + v83;
    c[88 * s + 4] = v88;
    let v89 = v63 * v71 + v88;
    c[89 * s + 4] = v89;
}

/// The histories of the kernels `ball` at order `k >= 1` ([`Kernels::histories`]).
#[inline(always)]
fn ball_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 25],
    g: &mut [T; 25],
) {
    assert!(k + 4 <= s && c.len() >= 72 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 3, 9, 10, 12].
        let (mut s0, mut s3, mut s9, mut s10, mut s12) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, a10, b10, a12, a52, b54) = unsafe { (at(c, 7 * s + 4 + j), at(c, 10 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 12 * s + 4 + j), at(c, 52 * s + 4 + j), at(c, 54 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a10, b10, s0);
            s3 = mul_add::<T, FMA>(a7, b10, s3);
            s9 = mul_add::<T, FMA>(a52, b54, s9);
            s10 = mul_add::<T, FMA>(a10, b54, s10);
            s12 = mul_add::<T, FMA>(a12, b54, s12);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), s0);
                s3 = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), s3);
                s3 = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), s3);
                s9 = mul_add::<T, FMA>(at(c, 52 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s9);
                s9 = mul_add::<T, FMA>(at(c, 52 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s9);
                s10 = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s10);
                s10 = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s10);
                s12 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s12);
            }
        }
        h[0] = s0;
        h[3] = s3;
        h[9] = s9;
        h[10] = s10;
        h[12] = s12;
        // Histories [1, 2, 4, 5, 14].
        let (mut s1, mut s2, mut s4, mut s5, mut s14) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a8, a9, a12, b12, a14, b14, b54) = unsafe { (at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 12 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 14 * s + 4 + k - j), at(c, 54 * s + 4 + k - j)) };
            s1 = mul_add::<T, FMA>(a12, b12, s1);
            s2 = mul_add::<T, FMA>(a14, b14, s2);
            s4 = mul_add::<T, FMA>(a8, b12, s4);
            s5 = mul_add::<T, FMA>(a9, b14, s5);
            s14 = mul_add::<T, FMA>(a14, b54, s14);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s1 = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), s1);
                s1 = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), s1);
                s2 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), s2);
                s4 = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), s4);
                s4 = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), s4);
                s5 = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), s5);
                s5 = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), s5);
                s14 = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s14);
            }
        }
        h[1] = s1;
        h[2] = s2;
        h[4] = s4;
        h[5] = s5;
        h[14] = s14;
        // Histories [6, 7, 8, 11, 13].
        let (mut s6, mut s7, mut s8, mut s11, mut s13) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a26, b28, b34, b46, b57, b60) = unsafe { (at(c, 26 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 46 * s + 4 + k - j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j)) };
            s6 = mul_add::<T, FMA>(a26, b28, s6);
            s7 = mul_add::<T, FMA>(a26, b34, s7);
            s8 = mul_add::<T, FMA>(a26, b46, s8);
            s11 = mul_add::<T, FMA>(a26, b57, s11);
            s13 = mul_add::<T, FMA>(a26, b60, s13);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s6 = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), s6);
                s6 = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), s6);
                s7 = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), s7);
                s7 = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), s7);
                s8 = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), s8);
                s8 = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), s8);
                s11 = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s11);
                s11 = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s11);
                s13 = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), s13);
            }
        }
        h[6] = s6;
        h[7] = s7;
        h[8] = s8;
        h[11] = s11;
        h[13] = s13;
        // Histories [15, 16, 22, 23, 24].
        let (mut s15, mut s16, mut s22, mut s23, mut s24) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a26, a57, a60, b60, a63, b63, b71) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 26 * s + 4 + j), at(c, 57 * s + 4 + j), at(c, 60 * s + 4 + j), at(c, 60 * s + 4 + k - j), at(c, 63 * s + 4 + j), at(c, 63 * s + 4 + k - j), at(c, 71 * s + 4 + k - j)) };
            s15 = mul_add::<T, FMA>(a26, b63, s15);
            s16 = mul_add::<T, FMA>(a1, b63, s16);
            s16 = mul_add::<T, FMA>(-a2, b60, s16);
            s22 = mul_add::<T, FMA>(a57, b71, s22);
            s23 = mul_add::<T, FMA>(a60, b71, s23);
            s24 = mul_add::<T, FMA>(a63, b71, s24);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s15 = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 63 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 63 * s + 4 + 1), s15);
                s16 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 63 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 63 * s + 4 + 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), s16);
                s22 = mul_add::<T, FMA>(at(c, 57 * s + 4 + 1), at(c, 71 * s + 4 + k - 1), s22);
                s22 = mul_add::<T, FMA>(at(c, 57 * s + 4 + k - 1), at(c, 71 * s + 4 + 1), s22);
                s23 = mul_add::<T, FMA>(at(c, 60 * s + 4 + 1), at(c, 71 * s + 4 + k - 1), s23);
                s23 = mul_add::<T, FMA>(at(c, 60 * s + 4 + k - 1), at(c, 71 * s + 4 + 1), s23);
                s24 = mul_add::<T, FMA>(at(c, 63 * s + 4 + 1), at(c, 71 * s + 4 + k - 1), s24);
                s24 = mul_add::<T, FMA>(at(c, 63 * s + 4 + k - 1), at(c, 71 * s + 4 + 1), s24);
            }
        }
        h[15] = s15;
        h[16] = s16;
        h[22] = s22;
        h[23] = s23;
        h[24] = s24;
        // Histories [17, 18, 19, 20, 21].
        let (mut s17, mut s18, mut s19, mut s20, mut s21) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b57, b60, b63) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j), at(c, 63 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b57, s17);
            s17 = mul_add::<T, FMA>(-a0, b63, s17);
            s18 = mul_add::<T, FMA>(a0, b60, s18);
            s18 = mul_add::<T, FMA>(-a1, b57, s18);
            s19 = mul_add::<T, FMA>(a4, b63, s19);
            s19 = mul_add::<T, FMA>(-a5, b60, s19);
            s20 = mul_add::<T, FMA>(a5, b57, s20);
            s20 = mul_add::<T, FMA>(-a3, b63, s20);
            s21 = mul_add::<T, FMA>(a3, b60, s21);
            s21 = mul_add::<T, FMA>(-a4, b57, s21);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s17 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 63 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 63 * s + 4 + 1), s17);
                s18 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 60 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 57 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 60 * s + 4 + 1), s18);
                s18 = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 57 * s + 4 + 1), s18);
                s19 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 63 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 63 * s + 4 + 1), s19);
                s19 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), s19);
                s20 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 63 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s20);
                s20 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 63 * s + 4 + 1), s20);
                s21 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), s21);
                s21 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s21);
                s21 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), s21);
                s21 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s21);
            }
        }
        h[17] = s17;
        h[18] = s18;
        h[19] = s19;
        h[20] = s20;
        h[21] = s21;
    } else if even {
        // Histories [0, 3, 9, 10, 12]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s3, mut t3, mut s9, mut t9, mut s10, mut t10, mut s12, mut t12) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p10, mut p54) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, a10, b10, a12, a52, b54) = unsafe { (at(c, 7 * s + 4 + j), at(c, 10 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 12 * s + 4 + j), at(c, 52 * s + 4 + j), at(c, 54 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a10, b10, s0);
            s3 = mul_add::<T, FMA>(a7, b10, s3);
            s9 = mul_add::<T, FMA>(a52, b54, s9);
            s10 = mul_add::<T, FMA>(a10, b54, s10);
            s12 = mul_add::<T, FMA>(a12, b54, s12);
            (b10, b54)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a7, a10, b10, a12, a52, b54) = unsafe { (at(c, 7 * s + 4 + j), at(c, 10 * s + 4 + j), at(c, 10 * s + 4 + k - j), at(c, 12 * s + 4 + j), at(c, 52 * s + 4 + j), at(c, 54 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a10, b10, s0);
            s3 = mul_add::<T, FMA>(a7, b10, s3);
            s9 = mul_add::<T, FMA>(a52, b54, s9);
            s10 = mul_add::<T, FMA>(a10, b54, s10);
            s12 = mul_add::<T, FMA>(a12, b54, s12);
            t0 = mul_add::<T, FMA>(a10, p10, t0);
            t3 = mul_add::<T, FMA>(a7, p10, t3);
            t9 = mul_add::<T, FMA>(a52, p54, t9);
            t10 = mul_add::<T, FMA>(a10, p54, t10);
            t12 = mul_add::<T, FMA>(a12, p54, t12);
            (p10, p54) = (b10, b54);
        }
        h[0] = s0;
        g[0] = t0;
        h[3] = s3;
        g[3] = t3;
        h[9] = s9;
        g[9] = t9;
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        // Histories [1, 2, 4, 5, 14]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s1, mut t1, mut s2, mut t2, mut s4, mut t4, mut s5, mut t5, mut s14, mut t14) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p12, mut p14, mut p54) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a8, a9, a12, b12, a14, b14, b54) = unsafe { (at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 12 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 14 * s + 4 + k - j), at(c, 54 * s + 4 + k - j)) };
            s1 = mul_add::<T, FMA>(a12, b12, s1);
            s2 = mul_add::<T, FMA>(a14, b14, s2);
            s4 = mul_add::<T, FMA>(a8, b12, s4);
            s5 = mul_add::<T, FMA>(a9, b14, s5);
            s14 = mul_add::<T, FMA>(a14, b54, s14);
            (b12, b14, b54)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a8, a9, a12, b12, a14, b14, b54) = unsafe { (at(c, 8 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 12 * s + 4 + j), at(c, 12 * s + 4 + k - j), at(c, 14 * s + 4 + j), at(c, 14 * s + 4 + k - j), at(c, 54 * s + 4 + k - j)) };
            s1 = mul_add::<T, FMA>(a12, b12, s1);
            s2 = mul_add::<T, FMA>(a14, b14, s2);
            s4 = mul_add::<T, FMA>(a8, b12, s4);
            s5 = mul_add::<T, FMA>(a9, b14, s5);
            s14 = mul_add::<T, FMA>(a14, b54, s14);
            t1 = mul_add::<T, FMA>(a12, p12, t1);
            t2 = mul_add::<T, FMA>(a14, p14, t2);
            t4 = mul_add::<T, FMA>(a8, p12, t4);
            t5 = mul_add::<T, FMA>(a9, p14, t5);
            t14 = mul_add::<T, FMA>(a14, p54, t14);
            (p12, p14, p54) = (b12, b14, b54);
        }
        h[1] = s1;
        g[1] = t1;
        h[2] = s2;
        g[2] = t2;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[14] = s14;
        g[14] = t14;
        // Histories [6, 7, 8, 11, 13]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s6, mut t6, mut s7, mut t7, mut s8, mut t8, mut s11, mut t11, mut s13, mut t13) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p28, mut p34, mut p46, mut p57, mut p60) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a26, b28, b34, b46, b57, b60) = unsafe { (at(c, 26 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 46 * s + 4 + k - j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j)) };
            s6 = mul_add::<T, FMA>(a26, b28, s6);
            s7 = mul_add::<T, FMA>(a26, b34, s7);
            s8 = mul_add::<T, FMA>(a26, b46, s8);
            s11 = mul_add::<T, FMA>(a26, b57, s11);
            s13 = mul_add::<T, FMA>(a26, b60, s13);
            (b28, b34, b46, b57, b60)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a26, b28, b34, b46, b57, b60) = unsafe { (at(c, 26 * s + 4 + j), at(c, 28 * s + 4 + k - j), at(c, 34 * s + 4 + k - j), at(c, 46 * s + 4 + k - j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j)) };
            s6 = mul_add::<T, FMA>(a26, b28, s6);
            s7 = mul_add::<T, FMA>(a26, b34, s7);
            s8 = mul_add::<T, FMA>(a26, b46, s8);
            s11 = mul_add::<T, FMA>(a26, b57, s11);
            s13 = mul_add::<T, FMA>(a26, b60, s13);
            t6 = mul_add::<T, FMA>(a26, p28, t6);
            t7 = mul_add::<T, FMA>(a26, p34, t7);
            t8 = mul_add::<T, FMA>(a26, p46, t8);
            t11 = mul_add::<T, FMA>(a26, p57, t11);
            t13 = mul_add::<T, FMA>(a26, p60, t13);
            (p28, p34, p46, p57, p60) = (b28, b34, b46, b57, b60);
        }
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[8] = s8;
        g[8] = t8;
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        // Histories [15, 16, 22, 23, 24]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s15, mut t15, mut s16, mut t16, mut s22, mut t22, mut s23, mut t23, mut s24, mut t24) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p60, mut p63, mut p71) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a26, a57, a60, b60, a63, b63, b71) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 26 * s + 4 + j), at(c, 57 * s + 4 + j), at(c, 60 * s + 4 + j), at(c, 60 * s + 4 + k - j), at(c, 63 * s + 4 + j), at(c, 63 * s + 4 + k - j), at(c, 71 * s + 4 + k - j)) };
            s15 = mul_add::<T, FMA>(a26, b63, s15);
            s16 = mul_add::<T, FMA>(a1, b63, s16);
            s16 = mul_add::<T, FMA>(-a2, b60, s16);
            s22 = mul_add::<T, FMA>(a57, b71, s22);
            s23 = mul_add::<T, FMA>(a60, b71, s23);
            s24 = mul_add::<T, FMA>(a63, b71, s24);
            (b60, b63, b71)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a26, a57, a60, b60, a63, b63, b71) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 26 * s + 4 + j), at(c, 57 * s + 4 + j), at(c, 60 * s + 4 + j), at(c, 60 * s + 4 + k - j), at(c, 63 * s + 4 + j), at(c, 63 * s + 4 + k - j), at(c, 71 * s + 4 + k - j)) };
            s15 = mul_add::<T, FMA>(a26, b63, s15);
            s16 = mul_add::<T, FMA>(a1, b63, s16);
            s16 = mul_add::<T, FMA>(-a2, b60, s16);
            s22 = mul_add::<T, FMA>(a57, b71, s22);
            s23 = mul_add::<T, FMA>(a60, b71, s23);
            s24 = mul_add::<T, FMA>(a63, b71, s24);
            t15 = mul_add::<T, FMA>(a26, p63, t15);
            t16 = mul_add::<T, FMA>(a1, p63, t16);
            t16 = mul_add::<T, FMA>(-a2, p60, t16);
            t22 = mul_add::<T, FMA>(a57, p71, t22);
            t23 = mul_add::<T, FMA>(a60, p71, t23);
            t24 = mul_add::<T, FMA>(a63, p71, t24);
            (p60, p63, p71) = (b60, b63, b71);
        }
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
        h[24] = s24;
        g[24] = t24;
        // Histories [17, 18, 19, 20, 21]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s17, mut t17, mut s18, mut t18, mut s19, mut t19, mut s20, mut t20, mut s21, mut t21) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p57, mut p60, mut p63) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b57, b60, b63) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j), at(c, 63 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b57, s17);
            s17 = mul_add::<T, FMA>(-a0, b63, s17);
            s18 = mul_add::<T, FMA>(a0, b60, s18);
            s18 = mul_add::<T, FMA>(-a1, b57, s18);
            s19 = mul_add::<T, FMA>(a4, b63, s19);
            s19 = mul_add::<T, FMA>(-a5, b60, s19);
            s20 = mul_add::<T, FMA>(a5, b57, s20);
            s20 = mul_add::<T, FMA>(-a3, b63, s20);
            s21 = mul_add::<T, FMA>(a3, b60, s21);
            s21 = mul_add::<T, FMA>(-a4, b57, s21);
            (b57, b60, b63)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b57, b60, b63) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j), at(c, 63 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b57, s17);
            s17 = mul_add::<T, FMA>(-a0, b63, s17);
            s18 = mul_add::<T, FMA>(a0, b60, s18);
            s18 = mul_add::<T, FMA>(-a1, b57, s18);
            s19 = mul_add::<T, FMA>(a4, b63, s19);
            s19 = mul_add::<T, FMA>(-a5, b60, s19);
            s20 = mul_add::<T, FMA>(a5, b57, s20);
            s20 = mul_add::<T, FMA>(-a3, b63, s20);
            s21 = mul_add::<T, FMA>(a3, b60, s21);
            s21 = mul_add::<T, FMA>(-a4, b57, s21);
            t17 = mul_add::<T, FMA>(a2, p57, t17);
            t17 = mul_add::<T, FMA>(-a0, p63, t17);
            t18 = mul_add::<T, FMA>(a0, p60, t18);
            t18 = mul_add::<T, FMA>(-a1, p57, t18);
            t19 = mul_add::<T, FMA>(a4, p63, t19);
            t19 = mul_add::<T, FMA>(-a5, p60, t19);
            t20 = mul_add::<T, FMA>(a5, p57, t20);
            t20 = mul_add::<T, FMA>(-a3, p63, t20);
            t21 = mul_add::<T, FMA>(a3, p60, t21);
            t21 = mul_add::<T, FMA>(-a4, p57, t21);
            (p57, p60, p63) = (b57, b60, b63);
        }
        h[17] = s17;
        g[17] = t17;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 10 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 10 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + 1), at(c, 12 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 8 * s + 4 + k - 1), at(c, 12 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 14 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 14 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 28 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 28 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 34 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 34 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 46 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 46 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = mul_add::<T, FMA>(at(c, 52 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 52 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 10 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 12 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 14 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + 1), at(c, 63 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 26 * s + 4 + k - 1), at(c, 63 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 63 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 63 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 63 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 63 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 63 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 63 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 63 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 63 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = mul_add::<T, FMA>(at(c, 57 * s + 4 + 1), at(c, 71 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 57 * s + 4 + k - 1), at(c, 71 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = mul_add::<T, FMA>(at(c, 60 * s + 4 + 1), at(c, 71 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 60 * s + 4 + k - 1), at(c, 71 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = mul_add::<T, FMA>(at(c, 63 * s + 4 + 1), at(c, 71 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 63 * s + 4 + k - 1), at(c, 71 * s + 4 + 1), e);
        h[24] = e;
        }
    }
}

/// The pass of order `k >= 1` of the kernel `ball_unit`.
#[inline(always)]
fn ball_unit<T: Coefficient, const FMA: bool>(
    c: &mut [T],
    s: usize,
    k: usize,
    h: &[T; 25],
    q: &[f64; 35],
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
    let v14 = v13 * q[6];
    c[14 * s + 4 + k] = v14;
    let v15 = recurrence::product::<T, FMA>(c[10 * s + 4], v10, c[10 * s + 4], v10, h[1]);
    c[15 * s + 4 + k] = v15;
    let v16 = v15 * q[7];
    c[16 * s + 4 + k] = v16;
    let v17 = recurrence::product::<T, FMA>(c[12 * s + 4], v12, c[12 * s + 4], v12, h[2]);
    c[17 * s + 4 + k] = v17;
    let v18 = v17 * q[8];
    c[18 * s + 4 + k] = v18;
    let v19 = recurrence::product::<T, FMA>(c[3 * s + 4], c[3 * s + 4 + k], c[8 * s + 4], v8, h[3]);
    c[19 * s + 4 + k] = v19;
    let v20 = recurrence::product::<T, FMA>(c[4 * s + 4], c[4 * s + 4 + k], c[10 * s + 4], v10, h[4]);
    c[20 * s + 4 + k] = v20;
    let v21 = recurrence::product::<T, FMA>(c[5 * s + 4], c[5 * s + 4 + k], c[12 * s + 4], v12, h[5]);
    c[21 * s + 4 + k] = v21;
    let v22 = v14 + v16;
    c[22 * s + 4 + k] = v22;
    let v23 = v18 + v22;
    c[23 * s + 4 + k] = v23;
    let v24 = v19 + v20;
    c[24 * s + 4 + k] = v24;
    let v25 = v21 + v24;
    c[25 * s + 4 + k] = v25;
    let v26 = v19 * q[9];
    c[26 * s + 4 + k] = v26;
    let v27 = v20 * q[10];
    c[27 * s + 4 + k] = v27;
    let v28 = v26 + v27;
    c[28 * s + 4 + k] = v28;
    let v29 = v21 * q[11];
    c[29 * s + 4 + k] = v29;
    let v30 = v28 + v29;
    c[30 * s + 4 + k] = v30;
    let v31 = recurrence::mul_plus::<T, FMA>(c[23 * s + 4], v23, c[25 * s + 4], v25, v30, h[6]);
    c[31 * s + 4 + k] = v31;
    let v32 = v19 * q[12];
    c[32 * s + 4 + k] = v32;
    let v33 = v20 * q[13];
    c[33 * s + 4 + k] = v33;
    let v34 = v32 + v33;
    c[34 * s + 4 + k] = v34;
    let v35 = v21 * q[14];
    c[35 * s + 4 + k] = v35;
    let v36 = v34 + v35;
    c[36 * s + 4 + k] = v36;
    let v37 = recurrence::mul_plus::<T, FMA>(c[23 * s + 4], v23, c[31 * s + 4], v31, v36, h[7]);
    c[37 * s + 4 + k] = v37;
    let v38 = v37 * q[15];
    c[38 * s + 4 + k] = v38;
    let v39 = v14 * q[16];
    c[39 * s + 4 + k] = v39;
    let v40 = v16 * q[17];
    c[40 * s + 4 + k] = v40;
    let v41 = v39 + v40;
    c[41 * s + 4 + k] = v41;
    let v42 = v18 * q[18];
    c[42 * s + 4 + k] = v42;
    let v43 = v41 + v42;
    c[43 * s + 4 + k] = v43;
    let v44 = v14 * q[19];
    c[44 * s + 4 + k] = v44;
    let v45 = v16 * q[20];
    c[45 * s + 4 + k] = v45;
    let v46 = v44 + v45;
    c[46 * s + 4 + k] = v46;
    let v47 = v18 * q[21];
    c[47 * s + 4 + k] = v47;
    let v48 = v46 + v47;
    c[48 * s + 4 + k] = v48;
    let v49 = recurrence::mul_plus::<T, FMA>(c[23 * s + 4], v23, c[43 * s + 4], v43, v48, h[8]);
    c[49 * s + 4 + k] = v49;
    let v50 = v49;
    c[50 * s + 4 + k] = v50;
    let v51 = recurrence::quotient::<T, FMA>(v38, c[50 * s + 4], v50, c[51 * s + 4], h[9]);
    c[51 * s + 4 + k] = v51;
    let v52 = recurrence::mul_plus::<T, FMA>(c[8 * s + 4], v8, c[51 * s + 4], v51, c[3 * s + 4 + k], h[10]);
    c[52 * s + 4 + k] = v52;
    let v53 = v23;
    c[53 * s + 4 + k] = v53;
    let v54 = recurrence::quotient::<T, FMA>(v52, c[53 * s + 4], v53, c[54 * s + 4], h[11]);
    c[54 * s + 4 + k] = v54;
    let v55 = recurrence::mul_plus::<T, FMA>(c[10 * s + 4], v10, c[51 * s + 4], v51, c[4 * s + 4 + k], h[12]);
    c[55 * s + 4 + k] = v55;
    let v56 = v23;
    c[56 * s + 4 + k] = v56;
    let v57 = recurrence::quotient::<T, FMA>(v55, c[56 * s + 4], v56, c[57 * s + 4], h[13]);
    c[57 * s + 4 + k] = v57;
    let v58 = recurrence::mul_plus::<T, FMA>(c[12 * s + 4], v12, c[51 * s + 4], v51, c[5 * s + 4 + k], h[14]);
    c[58 * s + 4 + k] = v58;
    let v59 = v23;
    c[59 * s + 4 + k] = v59;
    let v60 = recurrence::quotient::<T, FMA>(v58, c[59 * s + 4], v59, c[60 * s + 4], h[15]);
    c[60 * s + 4 + k] = v60;
    let v61 = recurrence::dot_sub::<T, FMA>([c[s + 4], c[s + 4 + k], c[60 * s + 4], v60], [c[2 * s + 4], c[2 * s + 4 + k], c[57 * s + 4], v57], h[16]);
    c[61 * s + 4 + k] = v61;
    let v62 = recurrence::dot_sub::<T, FMA>([c[2 * s + 4], c[2 * s + 4 + k], c[54 * s + 4], v54], [c[4], c[4 + k], c[60 * s + 4], v60], h[17]);
    c[62 * s + 4 + k] = v62;
    let v63 = recurrence::dot_sub::<T, FMA>([c[4], c[4 + k], c[57 * s + 4], v57], [c[s + 4], c[s + 4 + k], c[54 * s + 4], v54], h[18]);
    c[63 * s + 4 + k] = v63;
    let v64 = v61 * q[26];
    c[64 * s + 4 + k] = v64;
    let v65 = v62 * q[27];
    c[65 * s + 4 + k] = v65;
    let v66 = v64 + v65;
    c[66 * s + 4 + k] = v66;
    let v67 = v63 * q[28];
    c[67 * s + 4 + k] = v67;
    let v68 = v66 + v67;
    c[68 * s + 4 + k] = v68;
    let v69 = c[s + 4 + k] * q[29];
    c[69 * s + 4 + k] = v69;
    let v70 = c[2 * s + 4 + k] * q[30];
    c[70 * s + 4 + k] = v70;
    let v71 = v69 - v70;
    c[71 * s + 4 + k] = v71;
    let v72 = c[2 * s + 4 + k] * q[31];
    c[72 * s + 4 + k] = v72;
    let v73 = c[4 + k] * q[32];
    c[73 * s + 4 + k] = v73;
    let v74 = v72 - v73;
    c[74 * s + 4 + k] = v74;
    let v75 = c[4 + k] * q[33];
    c[75 * s + 4 + k] = v75;
    let v76 = c[s + 4 + k] * q[34];
    c[76 * s + 4 + k] = v76;
    let v77 = v75 - v76;
    c[77 * s + 4 + k] = v77;
    let v78 = recurrence::dot_sub::<T, FMA>([c[4 * s + 4], c[4 * s + 4 + k], c[60 * s + 4], v60], [c[5 * s + 4], c[5 * s + 4 + k], c[57 * s + 4], v57], h[19]);
    c[78 * s + 4 + k] = v78;
    let v79 = recurrence::dot_sub::<T, FMA>([c[5 * s + 4], c[5 * s + 4 + k], c[54 * s + 4], v54], [c[3 * s + 4], c[3 * s + 4 + k], c[60 * s + 4], v60], h[20]);
    c[79 * s + 4 + k] = v79;
    let v80 = recurrence::dot_sub::<T, FMA>([c[3 * s + 4], c[3 * s + 4 + k], c[57 * s + 4], v57], [c[4 * s + 4], c[4 * s + 4 + k], c[54 * s + 4], v54], h[21]);
    c[80 * s + 4 + k] = v80;
    let v81 = v71 + v78;
    c[81 * s + 4 + k] = v81;
    let v82 = recurrence::mul_plus::<T, FMA>(c[54 * s + 4], v54, c[68 * s + 4], v68, v81, h[22]);
    c[82 * s + 4 + k] = v82;
    let v83 = v74 + v79;
    c[83 * s + 4 + k] = v83;
    let v84 = recurrence::mul_plus::<T, FMA>(c[57 * s + 4], v57, c[68 * s + 4], v68, v83, h[23]);
    c[84 * s + 4 + k] = v84;
    let v85 = v77 + v80;
    c[85 * s + 4 + k] = v85;
    let v86 = recurrence::mul_plus::<T, FMA>(c[60 * s + 4], v60, c[68 * s + 4], v68, v85, h[24]);
    c[86 * s + 4 + k] = v86;
}

/// Order 0 of the kernel `ball_unit`.
#[inline(always)]
fn ball_unit_zero<T: Coefficient>(c: &mut [T], s: usize, z: &[f64; 35]) {
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
    let v14 = v13 * z[6];
    c[14 * s + 4] = v14;
    let v15 = v10 * v10;
    c[15 * s + 4] = v15;
    let v16 = v15 * z[7];
    c[16 * s + 4] = v16;
    let v17 = v12 * v12;
    c[17 * s + 4] = v17;
    let v18 = v17 * z[8];
    c[18 * s + 4] = v18;
    let v19 = c[3 * s + 4] * v8;
    c[19 * s + 4] = v19;
    let v20 = c[4 * s + 4] * v10;
    c[20 * s + 4] = v20;
    let v21 = c[5 * s + 4] * v12;
    c[21 * s + 4] = v21;
    let v22 = v14 + v16;
    c[22 * s + 4] = v22;
    let v23 = v18 + v22;
    c[23 * s + 4] = v23;
    let v24 = v19 + v20;
    c[24 * s + 4] = v24;
    let v25 = v21 + v24;
    c[25 * s + 4] = v25;
    let v26 = v19 * z[9];
    c[26 * s + 4] = v26;
    let v27 = v20 * z[10];
    c[27 * s + 4] = v27;
    let v28 = v26 + v27;
    c[28 * s + 4] = v28;
    let v29 = v21 * z[11];
    c[29 * s + 4] = v29;
    let v30 = v28 + v29;
    c[30 * s + 4] = v30;
    let v31 = v23 * v25 + v30;
    c[31 * s + 4] = v31;
    let v32 = v19 * z[12];
    c[32 * s + 4] = v32;
    let v33 = v20 * z[13];
    c[33 * s + 4] = v33;
    let v34 = v32 + v33;
    c[34 * s + 4] = v34;
    let v35 = v21 * z[14];
    c[35 * s + 4] = v35;
    let v36 = v34 + v35;
    c[36 * s + 4] = v36;
    let v37 = v23 * v31 + v36;
    c[37 * s + 4] = v37;
    let v38 = v37 * z[15];
    c[38 * s + 4] = v38;
    let v39 = v14 * z[16];
    c[39 * s + 4] = v39;
    let v40 = v16 * z[17];
    c[40 * s + 4] = v40;
    let v41 = v39 + v40;
    c[41 * s + 4] = v41;
    let v42 = v18 * z[18];
    c[42 * s + 4] = v42;
    let v43 = v41 + v42;
    c[43 * s + 4] = v43;
    let v44 = v14 * z[19];
    c[44 * s + 4] = v44;
    let v45 = v16 * z[20];
    c[45 * s + 4] = v45;
    let v46 = v44 + v45;
    c[46 * s + 4] = v46;
    let v47 = v18 * z[21];
    c[47 * s + 4] = v47;
    let v48 = v46 + v47;
    c[48 * s + 4] = v48;
    let v49 = v23 * v43 + v48;
    c[49 * s + 4] = v49;
    let v50 = v49 + z[22];
    c[50 * s + 4] = v50;
    let v51 = v38 / v50;
    c[51 * s + 4] = v51;
    let v52 = v8 * v51 + c[3 * s + 4];
    c[52 * s + 4] = v52;
    let v53 = v23 + z[23];
    c[53 * s + 4] = v53;
    let v54 = v52 / v53;
    c[54 * s + 4] = v54;
    let v55 = v10 * v51 + c[4 * s + 4];
    c[55 * s + 4] = v55;
    let v56 = v23 + z[24];
    c[56 * s + 4] = v56;
    let v57 = v55 / v56;
    c[57 * s + 4] = v57;
    let v58 = v12 * v51 + c[5 * s + 4];
    c[58 * s + 4] = v58;
    let v59 = v23 + z[25];
    c[59 * s + 4] = v59;
    let v60 = v58 / v59;
    c[60 * s + 4] = v60;
    let v61 = c[s + 4] * v60 - c[2 * s + 4] * v57;
    c[61 * s + 4] = v61;
    let v62 = c[2 * s + 4] * v54 - c[4] * v60;
    c[62 * s + 4] = v62;
    let v63 = c[4] * v57 - c[s + 4] * v54;
    c[63 * s + 4] = v63;
    let v64 = v61 * z[26];
    c[64 * s + 4] = v64;
    let v65 = v62 * z[27];
    c[65 * s + 4] = v65;
    let v66 = v64 + v65;
    c[66 * s + 4] = v66;
    let v67 = v63 * z[28];
    c[67 * s + 4] = v67;
    let v68 = v66 + v67;
    c[68 * s + 4] = v68;
    let v69 = c[s + 4] * z[29];
    c[69 * s + 4] = v69;
    let v70 = c[2 * s + 4] * z[30];
    c[70 * s + 4] = v70;
    let v71 = v69 - v70;
    c[71 * s + 4] = v71;
    let v72 = c[2 * s + 4] * z[31];
    c[72 * s + 4] = v72;
    let v73 = c[4] * z[32];
    c[73 * s + 4] = v73;
    let v74 = v72 - v73;
    c[74 * s + 4] = v74;
    let v75 = c[4] * z[33];
    c[75 * s + 4] = v75;
    let v76 = c[s + 4] * z[34];
    c[76 * s + 4] = v76;
    let v77 = v75 - v76;
    c[77 * s + 4] = v77;
    let v78 = c[4 * s + 4] * v60 - c[5 * s + 4] * v57;
    c[78 * s + 4] = v78;
    let v79 = c[5 * s + 4] * v54 - c[3 * s + 4] * v60;
    c[79 * s + 4] = v79;
    let v80 = c[3 * s + 4] * v57 - c[4 * s + 4] * v54;
    c[80 * s + 4] = v80;
    let v81 = v71 + v78;
    c[81 * s + 4] = v81;
    let v82 = v54 * v68 + v81;
    c[82 * s + 4] = v82;
    let v83 = v74 + v79;
    c[83 * s + 4] = v83;
    let v84 = v57 * v68 + v83;
    c[84 * s + 4] = v84;
    let v85 = v77 + v80;
    c[85 * s + 4] = v85;
    let v86 = v60 * v68 + v85;
    c[86 * s + 4] = v86;
}

/// The histories of the kernels `ball_unit` at order `k >= 1` ([`Kernels::histories`]).
#[inline(always)]
fn ball_unit_histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
    c: &[T],
    s: usize,
    k: usize,
    h: &mut [T; 25],
    g: &mut [T; 25],
) {
    assert!(k + 4 <= s && c.len() >= 69 * s, "the layout of the shape");
    let zero = T::from_f64(0.0);
    if k == 1 {
        h.fill(zero);
        return;
    }
    let even = k % 2 == 0;
    if !WIDE {
        let (lo, hi) = if even { (1, k) } else { (2, k - 1) };
        // Histories [0, 3, 9, 10, 12].
        let (mut s0, mut s3, mut s9, mut s10, mut s12) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a7, b7, a9, a49, b51) = unsafe { (at(c, 3 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 49 * s + 4 + j), at(c, 51 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a7, b7, s0);
            s3 = mul_add::<T, FMA>(a3, b7, s3);
            s9 = mul_add::<T, FMA>(a49, b51, s9);
            s10 = mul_add::<T, FMA>(a7, b51, s10);
            s12 = mul_add::<T, FMA>(a9, b51, s12);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s0 = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s0);
                s0 = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s0);
                s3 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), s3);
                s3 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), s3);
                s9 = mul_add::<T, FMA>(at(c, 49 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), s9);
                s9 = mul_add::<T, FMA>(at(c, 49 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), s9);
                s10 = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), s10);
                s10 = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), s10);
                s12 = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), s12);
                s12 = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), s12);
            }
        }
        h[0] = s0;
        h[3] = s3;
        h[9] = s9;
        h[10] = s10;
        h[12] = s12;
        // Histories [1, 2, 4, 5, 14].
        let (mut s1, mut s2, mut s4, mut s5, mut s14) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a4, a5, a9, b9, a11, b11, b51) = unsafe { (at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 51 * s + 4 + k - j)) };
            s1 = mul_add::<T, FMA>(a9, b9, s1);
            s2 = mul_add::<T, FMA>(a11, b11, s2);
            s4 = mul_add::<T, FMA>(a4, b9, s4);
            s5 = mul_add::<T, FMA>(a5, b11, s5);
            s14 = mul_add::<T, FMA>(a11, b51, s14);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s1 = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s1);
                s1 = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s1);
                s2 = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s2);
                s2 = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s2);
                s4 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), s4);
                s4 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), s4);
                s5 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), s5);
                s5 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), s5);
                s14 = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), s14);
                s14 = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), s14);
            }
        }
        h[1] = s1;
        h[2] = s2;
        h[4] = s4;
        h[5] = s5;
        h[14] = s14;
        // Histories [6, 7, 8, 11, 13].
        let (mut s6, mut s7, mut s8, mut s11, mut s13) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a23, b25, b31, b43, b54, b57) = unsafe { (at(c, 23 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 43 * s + 4 + k - j), at(c, 54 * s + 4 + k - j), at(c, 57 * s + 4 + k - j)) };
            s6 = mul_add::<T, FMA>(a23, b25, s6);
            s7 = mul_add::<T, FMA>(a23, b31, s7);
            s8 = mul_add::<T, FMA>(a23, b43, s8);
            s11 = mul_add::<T, FMA>(a23, b54, s11);
            s13 = mul_add::<T, FMA>(a23, b57, s13);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s6 = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), s6);
                s6 = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), s6);
                s7 = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), s7);
                s7 = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), s7);
                s8 = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), s8);
                s8 = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), s8);
                s11 = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s11);
                s11 = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s11);
                s13 = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s13);
                s13 = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s13);
            }
        }
        h[6] = s6;
        h[7] = s7;
        h[8] = s8;
        h[11] = s11;
        h[13] = s13;
        // Histories [15, 16, 22, 23, 24].
        let (mut s15, mut s16, mut s22, mut s23, mut s24) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a23, a54, a57, b57, a60, b60, b68) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 23 * s + 4 + j), at(c, 54 * s + 4 + j), at(c, 57 * s + 4 + j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + j), at(c, 60 * s + 4 + k - j), at(c, 68 * s + 4 + k - j)) };
            s15 = mul_add::<T, FMA>(a23, b60, s15);
            s16 = mul_add::<T, FMA>(a1, b60, s16);
            s16 = mul_add::<T, FMA>(-a2, b57, s16);
            s22 = mul_add::<T, FMA>(a54, b68, s22);
            s23 = mul_add::<T, FMA>(a57, b68, s23);
            s24 = mul_add::<T, FMA>(a60, b68, s24);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s15 = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), s15);
                s15 = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), s15);
                s16 = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 60 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s16);
                s16 = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 60 * s + 4 + 1), s16);
                s16 = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s16);
                s22 = mul_add::<T, FMA>(at(c, 54 * s + 4 + 1), at(c, 68 * s + 4 + k - 1), s22);
                s22 = mul_add::<T, FMA>(at(c, 54 * s + 4 + k - 1), at(c, 68 * s + 4 + 1), s22);
                s23 = mul_add::<T, FMA>(at(c, 57 * s + 4 + 1), at(c, 68 * s + 4 + k - 1), s23);
                s23 = mul_add::<T, FMA>(at(c, 57 * s + 4 + k - 1), at(c, 68 * s + 4 + 1), s23);
                s24 = mul_add::<T, FMA>(at(c, 60 * s + 4 + 1), at(c, 68 * s + 4 + k - 1), s24);
                s24 = mul_add::<T, FMA>(at(c, 60 * s + 4 + k - 1), at(c, 68 * s + 4 + 1), s24);
            }
        }
        h[15] = s15;
        h[16] = s16;
        h[22] = s22;
        h[23] = s23;
        h[24] = s24;
        // Histories [17, 18, 19, 20, 21].
        let (mut s17, mut s18, mut s19, mut s20, mut s21) = (zero, zero, zero, zero, zero);
        for j in lo..hi {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b54, b57, b60) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 54 * s + 4 + k - j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b54, s17);
            s17 = mul_add::<T, FMA>(-a0, b60, s17);
            s18 = mul_add::<T, FMA>(a0, b57, s18);
            s18 = mul_add::<T, FMA>(-a1, b54, s18);
            s19 = mul_add::<T, FMA>(a4, b60, s19);
            s19 = mul_add::<T, FMA>(-a5, b57, s19);
            s20 = mul_add::<T, FMA>(a5, b54, s20);
            s20 = mul_add::<T, FMA>(-a3, b60, s20);
            s21 = mul_add::<T, FMA>(a3, b57, s21);
            s21 = mul_add::<T, FMA>(-a4, b54, s21);
        }
        if !even {
            // SAFETY: the assertion above, with `1 <= k - 1`.
            unsafe {
                s17 = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 60 * s + 4 + k - 1), s17);
                s17 = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s17);
                s17 = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 60 * s + 4 + 1), s17);
                s18 = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 57 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 54 * s + 4 + k - 1), s18);
                s18 = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 57 * s + 4 + 1), s18);
                s18 = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 54 * s + 4 + 1), s18);
                s19 = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s19);
                s19 = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), s19);
                s19 = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s19);
                s20 = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), s20);
                s20 = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s20);
                s20 = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), s20);
                s21 = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), s21);
                s21 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), s21);
                s21 = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), s21);
                s21 = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), s21);
            }
        }
        h[17] = s17;
        h[18] = s18;
        h[19] = s19;
        h[20] = s20;
        h[21] = s21;
    } else if even {
        // Histories [0, 3, 9, 10, 12]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s0, mut t0, mut s3, mut t3, mut s9, mut t9, mut s10, mut t10, mut s12, mut t12) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p7, mut p51) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a7, b7, a9, a49, b51) = unsafe { (at(c, 3 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 49 * s + 4 + j), at(c, 51 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a7, b7, s0);
            s3 = mul_add::<T, FMA>(a3, b7, s3);
            s9 = mul_add::<T, FMA>(a49, b51, s9);
            s10 = mul_add::<T, FMA>(a7, b51, s10);
            s12 = mul_add::<T, FMA>(a9, b51, s12);
            (b7, b51)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a3, a7, b7, a9, a49, b51) = unsafe { (at(c, 3 * s + 4 + j), at(c, 7 * s + 4 + j), at(c, 7 * s + 4 + k - j), at(c, 9 * s + 4 + j), at(c, 49 * s + 4 + j), at(c, 51 * s + 4 + k - j)) };
            s0 = mul_add::<T, FMA>(a7, b7, s0);
            s3 = mul_add::<T, FMA>(a3, b7, s3);
            s9 = mul_add::<T, FMA>(a49, b51, s9);
            s10 = mul_add::<T, FMA>(a7, b51, s10);
            s12 = mul_add::<T, FMA>(a9, b51, s12);
            t0 = mul_add::<T, FMA>(a7, p7, t0);
            t3 = mul_add::<T, FMA>(a3, p7, t3);
            t9 = mul_add::<T, FMA>(a49, p51, t9);
            t10 = mul_add::<T, FMA>(a7, p51, t10);
            t12 = mul_add::<T, FMA>(a9, p51, t12);
            (p7, p51) = (b7, b51);
        }
        h[0] = s0;
        g[0] = t0;
        h[3] = s3;
        g[3] = t3;
        h[9] = s9;
        g[9] = t9;
        h[10] = s10;
        g[10] = t10;
        h[12] = s12;
        g[12] = t12;
        // Histories [1, 2, 4, 5, 14]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s1, mut t1, mut s2, mut t2, mut s4, mut t4, mut s5, mut t5, mut s14, mut t14) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p9, mut p11, mut p51) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a4, a5, a9, b9, a11, b11, b51) = unsafe { (at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 51 * s + 4 + k - j)) };
            s1 = mul_add::<T, FMA>(a9, b9, s1);
            s2 = mul_add::<T, FMA>(a11, b11, s2);
            s4 = mul_add::<T, FMA>(a4, b9, s4);
            s5 = mul_add::<T, FMA>(a5, b11, s5);
            s14 = mul_add::<T, FMA>(a11, b51, s14);
            (b9, b11, b51)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a4, a5, a9, b9, a11, b11, b51) = unsafe { (at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 9 * s + 4 + j), at(c, 9 * s + 4 + k - j), at(c, 11 * s + 4 + j), at(c, 11 * s + 4 + k - j), at(c, 51 * s + 4 + k - j)) };
            s1 = mul_add::<T, FMA>(a9, b9, s1);
            s2 = mul_add::<T, FMA>(a11, b11, s2);
            s4 = mul_add::<T, FMA>(a4, b9, s4);
            s5 = mul_add::<T, FMA>(a5, b11, s5);
            s14 = mul_add::<T, FMA>(a11, b51, s14);
            t1 = mul_add::<T, FMA>(a9, p9, t1);
            t2 = mul_add::<T, FMA>(a11, p11, t2);
            t4 = mul_add::<T, FMA>(a4, p9, t4);
            t5 = mul_add::<T, FMA>(a5, p11, t5);
            t14 = mul_add::<T, FMA>(a11, p51, t14);
            (p9, p11, p51) = (b9, b11, b51);
        }
        h[1] = s1;
        g[1] = t1;
        h[2] = s2;
        g[2] = t2;
        h[4] = s4;
        g[4] = t4;
        h[5] = s5;
        g[5] = t5;
        h[14] = s14;
        g[14] = t14;
        // Histories [6, 7, 8, 11, 13]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s6, mut t6, mut s7, mut t7, mut s8, mut t8, mut s11, mut t11, mut s13, mut t13) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p25, mut p31, mut p43, mut p54, mut p57) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a23, b25, b31, b43, b54, b57) = unsafe { (at(c, 23 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 43 * s + 4 + k - j), at(c, 54 * s + 4 + k - j), at(c, 57 * s + 4 + k - j)) };
            s6 = mul_add::<T, FMA>(a23, b25, s6);
            s7 = mul_add::<T, FMA>(a23, b31, s7);
            s8 = mul_add::<T, FMA>(a23, b43, s8);
            s11 = mul_add::<T, FMA>(a23, b54, s11);
            s13 = mul_add::<T, FMA>(a23, b57, s13);
            (b25, b31, b43, b54, b57)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a23, b25, b31, b43, b54, b57) = unsafe { (at(c, 23 * s + 4 + j), at(c, 25 * s + 4 + k - j), at(c, 31 * s + 4 + k - j), at(c, 43 * s + 4 + k - j), at(c, 54 * s + 4 + k - j), at(c, 57 * s + 4 + k - j)) };
            s6 = mul_add::<T, FMA>(a23, b25, s6);
            s7 = mul_add::<T, FMA>(a23, b31, s7);
            s8 = mul_add::<T, FMA>(a23, b43, s8);
            s11 = mul_add::<T, FMA>(a23, b54, s11);
            s13 = mul_add::<T, FMA>(a23, b57, s13);
            t6 = mul_add::<T, FMA>(a23, p25, t6);
            t7 = mul_add::<T, FMA>(a23, p31, t7);
            t8 = mul_add::<T, FMA>(a23, p43, t8);
            t11 = mul_add::<T, FMA>(a23, p54, t11);
            t13 = mul_add::<T, FMA>(a23, p57, t13);
            (p25, p31, p43, p54, p57) = (b25, b31, b43, b54, b57);
        }
        h[6] = s6;
        g[6] = t6;
        h[7] = s7;
        g[7] = t7;
        h[8] = s8;
        g[8] = t8;
        h[11] = s11;
        g[11] = t11;
        h[13] = s13;
        g[13] = t13;
        // Histories [15, 16, 22, 23, 24]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s15, mut t15, mut s16, mut t16, mut s22, mut t22, mut s23, mut t23, mut s24, mut t24) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p57, mut p60, mut p68) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a23, a54, a57, b57, a60, b60, b68) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 23 * s + 4 + j), at(c, 54 * s + 4 + j), at(c, 57 * s + 4 + j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + j), at(c, 60 * s + 4 + k - j), at(c, 68 * s + 4 + k - j)) };
            s15 = mul_add::<T, FMA>(a23, b60, s15);
            s16 = mul_add::<T, FMA>(a1, b60, s16);
            s16 = mul_add::<T, FMA>(-a2, b57, s16);
            s22 = mul_add::<T, FMA>(a54, b68, s22);
            s23 = mul_add::<T, FMA>(a57, b68, s23);
            s24 = mul_add::<T, FMA>(a60, b68, s24);
            (b57, b60, b68)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a1, a2, a23, a54, a57, b57, a60, b60, b68) = unsafe { (at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 23 * s + 4 + j), at(c, 54 * s + 4 + j), at(c, 57 * s + 4 + j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + j), at(c, 60 * s + 4 + k - j), at(c, 68 * s + 4 + k - j)) };
            s15 = mul_add::<T, FMA>(a23, b60, s15);
            s16 = mul_add::<T, FMA>(a1, b60, s16);
            s16 = mul_add::<T, FMA>(-a2, b57, s16);
            s22 = mul_add::<T, FMA>(a54, b68, s22);
            s23 = mul_add::<T, FMA>(a57, b68, s23);
            s24 = mul_add::<T, FMA>(a60, b68, s24);
            t15 = mul_add::<T, FMA>(a23, p60, t15);
            t16 = mul_add::<T, FMA>(a1, p60, t16);
            t16 = mul_add::<T, FMA>(-a2, p57, t16);
            t22 = mul_add::<T, FMA>(a54, p68, t22);
            t23 = mul_add::<T, FMA>(a57, p68, t23);
            t24 = mul_add::<T, FMA>(a60, p68, t24);
            (p57, p60, p68) = (b57, b60, b68);
        }
        h[15] = s15;
        g[15] = t15;
        h[16] = s16;
        g[16] = t16;
        h[22] = s22;
        g[22] = t22;
        h[23] = s23;
        g[23] = t23;
        h[24] = s24;
        g[24] = t24;
        // Histories [17, 18, 19, 20, 21]: `s` of order `k`, `t` of order `k + 1`.
        let (mut s17, mut t17, mut s18, mut t18, mut s19, mut t19, mut s20, mut t20, mut s21, mut t21) = (zero, zero, zero, zero, zero, zero, zero, zero, zero, zero);
        let (mut p54, mut p57, mut p60) = {
            let j = 1;
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b54, b57, b60) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 54 * s + 4 + k - j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b54, s17);
            s17 = mul_add::<T, FMA>(-a0, b60, s17);
            s18 = mul_add::<T, FMA>(a0, b57, s18);
            s18 = mul_add::<T, FMA>(-a1, b54, s18);
            s19 = mul_add::<T, FMA>(a4, b60, s19);
            s19 = mul_add::<T, FMA>(-a5, b57, s19);
            s20 = mul_add::<T, FMA>(a5, b54, s20);
            s20 = mul_add::<T, FMA>(-a3, b60, s20);
            s21 = mul_add::<T, FMA>(a3, b57, s21);
            s21 = mul_add::<T, FMA>(-a4, b54, s21);
            (b54, b57, b60)
        };
        for j in 2..k {
            // SAFETY: the assertion above, with `1 <= j, k - j <= k - 1`.
            let (a0, a1, a2, a3, a4, a5, b54, b57, b60) = unsafe { (at(c, 4 + j), at(c, s + 4 + j), at(c, 2 * s + 4 + j), at(c, 3 * s + 4 + j), at(c, 4 * s + 4 + j), at(c, 5 * s + 4 + j), at(c, 54 * s + 4 + k - j), at(c, 57 * s + 4 + k - j), at(c, 60 * s + 4 + k - j)) };
            s17 = mul_add::<T, FMA>(a2, b54, s17);
            s17 = mul_add::<T, FMA>(-a0, b60, s17);
            s18 = mul_add::<T, FMA>(a0, b57, s18);
            s18 = mul_add::<T, FMA>(-a1, b54, s18);
            s19 = mul_add::<T, FMA>(a4, b60, s19);
            s19 = mul_add::<T, FMA>(-a5, b57, s19);
            s20 = mul_add::<T, FMA>(a5, b54, s20);
            s20 = mul_add::<T, FMA>(-a3, b60, s20);
            s21 = mul_add::<T, FMA>(a3, b57, s21);
            s21 = mul_add::<T, FMA>(-a4, b54, s21);
            t17 = mul_add::<T, FMA>(a2, p54, t17);
            t17 = mul_add::<T, FMA>(-a0, p60, t17);
            t18 = mul_add::<T, FMA>(a0, p57, t18);
            t18 = mul_add::<T, FMA>(-a1, p54, t18);
            t19 = mul_add::<T, FMA>(a4, p60, t19);
            t19 = mul_add::<T, FMA>(-a5, p57, t19);
            t20 = mul_add::<T, FMA>(a5, p54, t20);
            t20 = mul_add::<T, FMA>(-a3, p60, t20);
            t21 = mul_add::<T, FMA>(a3, p57, t21);
            t21 = mul_add::<T, FMA>(-a4, p54, t21);
            (p54, p57, p60) = (b54, b57, b60);
        }
        h[17] = s17;
        g[17] = t17;
        h[18] = s18;
        g[18] = t18;
        h[19] = s19;
        g[19] = t19;
        h[20] = s20;
        g[20] = t20;
        h[21] = s21;
        g[21] = t21;
    } else {
        // SAFETY: the assertion above, with `1 <= k - 1`.
        unsafe {
        let mut e = g[0];
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        h[0] = e;
        let mut e = g[1];
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[1] = e;
        let mut e = g[2];
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[2] = e;
        let mut e = g[3];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 7 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 7 * s + 4 + 1), e);
        h[3] = e;
        let mut e = g[4];
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 9 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 9 * s + 4 + 1), e);
        h[4] = e;
        let mut e = g[5];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 11 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 11 * s + 4 + 1), e);
        h[5] = e;
        let mut e = g[6];
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 25 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 25 * s + 4 + 1), e);
        h[6] = e;
        let mut e = g[7];
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 31 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 31 * s + 4 + 1), e);
        h[7] = e;
        let mut e = g[8];
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 43 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 43 * s + 4 + 1), e);
        h[8] = e;
        let mut e = g[9];
        e = mul_add::<T, FMA>(at(c, 49 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 49 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), e);
        h[9] = e;
        let mut e = g[10];
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 7 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), e);
        h[10] = e;
        let mut e = g[11];
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        h[11] = e;
        let mut e = g[12];
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 9 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), e);
        h[12] = e;
        let mut e = g[13];
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        h[13] = e;
        let mut e = g[14];
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + 1), at(c, 51 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 11 * s + 4 + k - 1), at(c, 51 * s + 4 + 1), e);
        h[14] = e;
        let mut e = g[15];
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 23 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        h[15] = e;
        let mut e = g[16];
        e = mul_add::<T, FMA>(at(c, s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 2 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        h[16] = e;
        let mut e = g[17];
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 2 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        h[17] = e;
        let mut e = g[18];
        e = mul_add::<T, FMA>(at(c, 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        h[18] = e;
        let mut e = g[19];
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 4 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 5 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        h[19] = e;
        let mut e = g[20];
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + 1), at(c, 60 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 5 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 3 * s + 4 + k - 1), at(c, 60 * s + 4 + 1), e);
        h[20] = e;
        let mut e = g[21];
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + 1), at(c, 57 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + 1), at(c, 54 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 3 * s + 4 + k - 1), at(c, 57 * s + 4 + 1), e);
        e = mul_add::<T, FMA>(-at(c, 4 * s + 4 + k - 1), at(c, 54 * s + 4 + 1), e);
        h[21] = e;
        let mut e = g[22];
        e = mul_add::<T, FMA>(at(c, 54 * s + 4 + 1), at(c, 68 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 54 * s + 4 + k - 1), at(c, 68 * s + 4 + 1), e);
        h[22] = e;
        let mut e = g[23];
        e = mul_add::<T, FMA>(at(c, 57 * s + 4 + 1), at(c, 68 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 57 * s + 4 + k - 1), at(c, 68 * s + 4 + 1), e);
        h[23] = e;
        let mut e = g[24];
        e = mul_add::<T, FMA>(at(c, 60 * s + 4 + 1), at(c, 68 * s + 4 + k - 1), e);
        e = mul_add::<T, FMA>(at(c, 60 * s + 4 + k - 1), at(c, 68 * s + 4 + 1), e);
        h[24] = e;
        }
    }
}
