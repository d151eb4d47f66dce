//! The model families with generated Taylor kernels ([`crate::kernels`]): one ball of each,
//! whose tape's shape (the operations, with the constants left out: `0` and `1` kept) the
//! kernel serves for every ball of the family. `cargo xtask kernels` records their tapes
//! through the one generic field ([`crate::field`]) and writes `kernels.rs`; the test
//! `generated_kernels_are_up_to_date` checks that the file is what it would write.

use crate::ball::Ball;
use crate::kernels::BallKernels;
use crate::simulate::ReducedSystem;
use routh_integrate::taylor::{codegen, Tape};

/// The command that rewrites `kernels.rs`, named in its header.
pub const REGENERATE: &str = "cargo xtask kernels";

/// The path of the generated kernels in the crate.
pub const KERNELS: &str = "src/kernels.rs";

/// The families: the Routh sphere of the default case (m = R = 1; the case "tilted" of the
/// work-precision benchmark is of this family) and of a general body (no parameter 0 or 1),
/// each with and without gravity; the Chaplygin ball (the centre of mass at the centre, three
/// moments); a general ball (three moments, the centre of mass off the axis). omega is
/// computed in the body's unit of inertia k ([`Ball::inertia_unit`]), whose products by
/// `1 / k` the tape folds when k = 1: the general bodies come twice, with k = 4 (m R^2 = 4.5)
/// and with k = 1 (`_unit`: m R^2 = 0.98), two shapes; the default body and the Chaplygin
/// ball of the family have k = 1.
pub fn families() -> Vec<(&'static str, Ball)> {
    let ball = |m, r, inertia, com, gravity| {
        Ball::new(m, r, inertia, com, gravity).expect("a valid ball of the family")
    };
    let routh = |gravity| ball(1.0, 1.0, [0.4, 0.4, 0.5], [0.0, 0.0, -0.3], gravity);
    let general = |gravity| ball(2.0, 1.5, [0.7, 0.7, 1.1], [0.0, 0.0, 0.3], gravity);
    let general_unit = |gravity| ball(2.0, 0.7, [0.3, 0.3, 0.45], [0.0, 0.0, 0.25], gravity);
    vec![
        ("routh", routh(9.81)),
        ("routh_free", routh(0.0)),
        ("routh_general", general(9.81)),
        ("routh_general_free", general(0.0)),
        ("routh_general_unit", general_unit(9.81)),
        ("routh_general_unit_free", general_unit(0.0)),
        ("chaplygin", ball(1.0, 1.0, [0.3, 0.4, 0.5], [0.0; 3], 0.0)),
        (
            "ball",
            ball(2.0, 1.5, [0.7, 0.9, 1.1], [0.1, -0.2, 0.3], 9.81),
        ),
        (
            "ball_unit",
            ball(2.0, 0.7, [0.3, 0.35, 0.45], [0.1, -0.2, 0.25], 9.81),
        ),
    ]
}

/// The source of `kernels.rs`: the kernels of the tapes of [`families`] as the type
/// `BallKernels`.
pub fn kernels_source() -> String {
    source_of(families())
}

/// The source of the kernels of `families`' tapes, recorded through the generic field (the
/// generator reads the tapes' code, never the kernel a tape found).
fn source_of(families: Vec<(&'static str, Ball)>) -> String {
    let tapes: Vec<(&str, Tape<6, f64, BallKernels>)> = families
        .into_iter()
        .map(|(name, ball)| {
            let tape = Tape::record(&ReducedSystem(&ball), 2).expect("the reduced field records");
            (name, tape)
        })
        .collect();
    let named: Vec<_> = tapes.iter().map(|(name, tape)| (*name, tape)).collect();
    codegen::source("BallKernels", &named, REGENERATE)
}

#[cfg(test)]
mod tests {
    use super::{families, kernels_source, KERNELS, REGENERATE};
    use crate::ball::Ball;
    use crate::kernels::BallKernels;
    use crate::simulate::ReducedSystem;
    use routh_integrate::batch::Lanes;
    use routh_integrate::taylor::coefficient::Coefficient;
    use routh_integrate::taylor::tape::{Isa, PAD, STRIDE};
    use routh_integrate::taylor::{Kernels, Tape};

    /// The checked-in kernels are what the generator makes of the tapes of [`families`],
    /// recorded from the generic field: text equality (`cargo xtask kernels` rewrites the
    /// file). Negative control: the source generated without one family differs.
    #[test]
    fn generated_kernels_are_up_to_date() {
        let generated = kernels_source();
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(KERNELS);
        let checked_in = std::fs::read_to_string(&path).expect("reads the kernels");
        assert!(
            checked_in == generated,
            "{KERNELS} is out of date: rewrite it with `{REGENERATE}`"
        );
        let without_one = super::source_of(families().split_off(1));
        assert_ne!(without_one, checked_in);
    }

    /// A tape's coefficients `y^[0..=p]` in lane `l` after an expansion, as bits.
    fn series_bits<T: Coefficient, K: Kernels>(
        tape: &Tape<6, T, K>,
        p: usize,
        l: usize,
    ) -> Vec<u64> {
        (0..6)
            .flat_map(|i| (0..=p).map(move |k| tape.state_coefficient(i, k).lane(l).to_bits()))
            .collect()
    }

    /// Every instruction set this CPU has, in `f64` and in 8 lanes, kernel and interpreter:
    /// bitwise the same coefficients as the detected set's for the sets that fuse (AVX2 with
    /// FMA, AVX-512: the same operations in registers of 1, 4 or 8 doubles), and
    /// for the baseline (products and sums apart) the same in `f64` and in lanes, different
    /// from the fused ones (the negative control: the comparison sees the rounding).
    #[test]
    fn every_instruction_set_gives_the_same_coefficients() {
        let p = 20;
        let (_, ball) = families()[0];
        let tape = Tape::record(&ReducedSystem(&ball), p).expect("records");
        let tilt = std::f64::consts::PI / 12.0;
        let y = [tilt.sin(), 0.0, tilt.cos(), 0.5, 0.2, 8.0];
        let detected = tape.isa();
        let sets = [Isa::Baseline, Isa::Avx2Fma, Isa::Avx512];
        let run = |isa: Isa, interpreted: bool| {
            let tape = if interpreted {
                tape.interpreted()
            } else {
                tape.clone()
            }
            .with_isa(isa);
            let mut single = tape.clone();
            single.expand(0.5, &y, p);
            let mut lanes: Tape<6, Lanes<8>, BallKernels> = tape.with_coefficients();
            lanes.expand(Lanes::splat(0.5), &y.map(Lanes::splat), p);
            (series_bits(&single, p, 0), series_bits(&lanes, p, 5))
        };
        let fused = run(detected, false);
        assert_eq!(fused.0, fused.1);
        for isa in sets.into_iter().filter(|s| s.available()) {
            for interpreted in [false, true] {
                let (single, lanes) = run(isa, interpreted);
                assert_eq!(single, lanes, "{isa:?}");
                if isa == Isa::Baseline {
                    assert_ne!(single, fused.0, "{isa:?}");
                } else {
                    assert_eq!(single, fused.0, "{isa:?}");
                }
            }
        }
    }

    /// The generated kernels against the interpreter, in `f64` and in 4 and 8 lanes: bitwise
    /// equal coefficients (tolerance zero: the kernels make the interpreter's calls, with the
    /// same values, in its order) at every order up to 20 and up to 30 (a tape of order 20 has
    /// the constant stride of `tape::STRIDE`, one of order 30 a longer one, which the
    /// generated code takes as a variable),
    /// from 40 random states for each of three bodies of each family (the parameters scaled,
    /// keeping the zeros, the ones and the equal moments: the same shape, the kernel found by
    /// its shape). Negative control: the kernel's coefficients from another state differ.
    #[test]
    fn kernels_are_bitwise_the_interpreter() {
        kernels_are_bitwise_the_interpreter_to(20);
        kernels_are_bitwise_the_interpreter_to(30);
    }

    /// [`kernels_are_bitwise_the_interpreter`] for tapes of order `p`.
    fn kernels_are_bitwise_the_interpreter_to(p: usize) {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut uniform = |lo: f64, hi: f64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            lo + (hi - lo) * (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for (name, family) in families() {
            for draw in 0..3 {
                let ball = if draw > 0 {
                    let f = uniform(0.8, 1.2);
                    Ball::new(
                        family.m(),
                        family.radius(),
                        family.inertia().map(|i| if i == 1.0 { i } else { i * f }),
                        family.com().map(|c| c * uniform(0.5, 0.9)),
                        family.gravity() * uniform(0.5, 2.0),
                    )
                    .expect("a valid body")
                } else {
                    family
                };
                let kernel = Tape::record(&ReducedSystem(&ball), p).expect("records");
                assert_eq!(kernel.kernel(), Some(name), "{name}: found by its shape");
                // Order 20 runs the kernels at the constant stride, order 30 at a variable one.
                assert_eq!(
                    kernel.stride() == STRIDE,
                    p + 1 + 2 * PAD <= STRIDE,
                    "order {p}"
                );
                let interpreter = kernel.interpreted();
                assert_eq!(interpreter.kernel(), None);
                let mut lanes: [Tape<6, Lanes<8>, BallKernels>; 2] =
                    [kernel.with_coefficients(), interpreter.with_coefficients()];
                let mut fours: [Tape<6, Lanes<4>, BallKernels>; 2] =
                    [kernel.with_coefficients(), interpreter.with_coefficients()];
                let mut single = [kernel, interpreter];
                let states: Vec<[f64; 6]> = (0..40)
                    .map(|_| {
                        let (u, v) = (uniform(0.0, std::f64::consts::PI), uniform(-3.0, 3.0));
                        [u.sin() * v.cos(), u.sin() * v.sin(), u.cos()]
                            .into_iter()
                            .chain((0..3).map(|_| uniform(-5.0, 5.0)))
                            .collect::<Vec<_>>()
                            .try_into()
                            .expect("six numbers")
                    })
                    .collect();
                for (n, y) in states.iter().enumerate() {
                    let t = uniform(-10.0, 10.0);
                    for tape in &mut single {
                        tape.expand(t, y, p);
                    }
                    let [a, b] = &single;
                    assert_eq!(
                        series_bits(a, p, 0),
                        series_bits(b, p, 0),
                        "{name}, state {n}"
                    );
                    let other = states[(n + 1) % states.len()];
                    let mut control = a.clone();
                    control.expand(t, &other, p);
                    assert_ne!(series_bits(&control, p, 0), series_bits(b, p, 0));
                    let group = (0..8).map(|l| states[(n + l) % states.len()]);
                    let y8: [Lanes<8>; 6] = std::array::from_fn(|i| {
                        Lanes(std::array::from_fn(|l| states[(n + l) % states.len()][i]))
                    });
                    let y4: [Lanes<4>; 6] =
                        std::array::from_fn(|i| Lanes(std::array::from_fn(|l| y8[i].0[l])));
                    for tape in &mut lanes {
                        tape.expand(Lanes::splat(t), &y8, p);
                    }
                    for tape in &mut fours {
                        tape.expand(Lanes::splat(t), &y4, p);
                    }
                    for (l, y) in group.enumerate() {
                        let mut one = a.clone();
                        one.expand(t, &y, p);
                        let want = series_bits(&one, p, 0);
                        for tape in &lanes {
                            assert_eq!(series_bits(tape, p, l), want, "{name}, 8 lanes, lane {l}");
                        }
                        if l < 4 {
                            for tape in &fours {
                                assert_eq!(series_bits(tape, p, l), want, "{name}, 4 lanes");
                            }
                        }
                    }
                }
            }
        }
    }
}
